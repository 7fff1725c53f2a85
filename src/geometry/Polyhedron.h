// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
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

// The data description (core/DataLayout.h).
namespace layout {
template <>
struct Describe<TQ3PolyhedronEdgeData> {
    static auto fields()
    {
        using E = TQ3PolyhedronEdgeData;
        return std::make_tuple(value("vertexIndices", &E::vertexIndices), value("triangleIndices", &E::triangleIndices),
                               handle<AttributeSet>("edgeAttributeSet", &E::edgeAttributeSet));
    }
};

template <>
struct Describe<TQ3PolyhedronTriangleData> {
    static auto fields()
    {
        using T = TQ3PolyhedronTriangleData;
        return std::make_tuple(value("vertexIndices", &T::vertexIndices), value("edgeFlag", &T::edgeFlag),
                               handle<AttributeSet>("triangleAttributeSet", &T::triangleAttributeSet));
    }
};

template <>
struct Describe<TQ3PolyhedronData> {
    static auto fields()
    {
        using D = TQ3PolyhedronData;
        return std::make_tuple(atLeast("numVertices", &D::numVertices, 3),
                               requiredArray("vertices", &D::vertices, countOf(&D::numVertices)),
                               value("numEdges", &D::numEdges),
                               array("edges", &D::edges, countOf(&D::numEdges)),
                               atLeast("numTriangles", &D::numTriangles, 1),
                               requiredArray("triangles", &D::triangles, countOf(&D::numTriangles)),
                               handle<AttributeSet>("polyhedronAttributeSet", &D::polyhedronAttributeSet));
    }
};
} // namespace layout

} // namespace q3
