// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "geometry/DataGeometry.h"

namespace q3 {

extern const ClassInfo kPolyhedronClass;

/// A polyhedron: triangles over shared vertices, with optional edges.
/// Invariant: its data obeys the TQ3PolyhedronData rules of QD3DGeometry.h
/// (every index in range, every edge flag within kQ3PolyhedronEdgeAll).
class Polyhedron final : public DataGeometry<Polyhedron, TQ3PolyhedronData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypePolyhedron;
    static constexpr const char* kName = "polyhedron";
    static constexpr const char* kDataName = "polyhedronData";
    static constexpr TQ3AttributeSet TQ3PolyhedronData::*kOwnSet = &TQ3PolyhedronData::polyhedronAttributeSet;

    /// The TQ3PolyhedronData rules of QD3DGeometry.h, in their order.
    static void check(const TQ3PolyhedronData& data);

    using DataGeometry::DataGeometry;

    const ClassInfo& classInfo() const override { return kPolyhedronClass; }
    /// Each triangle with three vertices of its own (a vertex's attributes,
    /// then its triangle's); the wireframe: the sides each edgeFlag names,
    /// then every listed edge (its endpoints' attributes, then its own).
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;

    const TQ3Vertex3D& vertex(unsigned long index) const;
    void setVertexPosition(unsigned long index, const TQ3Point3D& position);
    void setVertexAttributeSet(unsigned long index, Ref<AttributeSet> attributes);

    /// A copy of triangle `index` with a new reference to its set.
    TQ3PolyhedronTriangleData triangle(unsigned long index) const;
    /// Replaces triangle `index` after checking it; the set is retained.
    void setTriangle(unsigned long index, const TQ3PolyhedronTriangleData& triangle);
    TQ3PolyhedronEdgeData edge(unsigned long index) const;
    void setEdge(unsigned long index, const TQ3PolyhedronEdgeData& edge);
};

} // namespace q3
