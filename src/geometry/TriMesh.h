// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "geometry/DataGeometry.h"

namespace q3 {

extern const ClassInfo kTriMeshClass;

/// A triangle mesh. Invariant: its data obeys the TQ3TriMeshData rules of
/// QD3DGeometry.h (every index in range, every point and attribute value
/// finite, every attribute type a standard one Q3 stores).
class TriMesh final : public DataGeometry<TriMesh, TQ3TriMeshData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeTriMesh;
    static constexpr const char* kName = "triMesh";
    static constexpr const char* kDataName = "triMeshData";
    static constexpr TQ3AttributeSet TQ3TriMeshData::*kOwnSet = &TQ3TriMeshData::triMeshAttributeSet;

    /// The TQ3TriMeshData rules of QD3DGeometry.h, in their order.
    static void check(const TQ3TriMeshData& data);

    using DataGeometry::DataGeometry;

    /// A TriMesh of a decomposition: the mesh's triangles over its vertices,
    /// with the per-vertex attributes it has as vertex attribute arrays (an
    /// attributeUseArray where only some vertices have one), the triangles'
    /// own surface shaders as a kQ3AttributeTypeSurfaceShader triangle
    /// attribute array, and `own` (may be null) as its triMeshAttributeSet.
    static Ref<TriMesh> fromMesh(const Mesh& mesh, const AttributeSet* own);

    const ClassInfo& classInfo() const override { return kTriMeshClass; }
    /// The triangles over the points with their vertex attributes; triangle
    /// attributes apply to their own three corners (a vertex's own still
    /// win), so a mesh with any gives every triangle its own vertices. The
    /// wireframe is every distinct triangle side, then each edge of the edge
    /// array that has a colour, in that colour.
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;
    bool isPrimitive() const override { return true; }
    /// Every point, used by a triangle or not: the box GetData reports as
    /// bBox (the default, the drawn vertices, would leave out the unused
    /// points only when the mesh has triangle attributes).
    void bound(const DecomposeContext& context, std::vector<glm::dvec3>& points) const override;

    /// As DataGeometry::getData, with bBox the box of the points (the
    /// caller's bBox is not kept: Q3 computes it).
    void getData(TQ3TriMeshData& out) const;
};

} // namespace q3
