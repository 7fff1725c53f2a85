// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "geometry/DataGeometry.h"

namespace q3 {

extern const ClassInfo kPolygonClass;

/// A simple polygon. Invariant: at least three vertices, all finite.
class Polygon final : public DataGeometry<Polygon, TQ3PolygonData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypePolygon;
    static constexpr const char* kName = "polygon";
    static constexpr const char* kDataName = "polygonData";
    static constexpr TQ3AttributeSet TQ3PolygonData::*kOwnSet = &TQ3PolygonData::polygonAttributeSet;

    /// The TQ3PolygonData rules of QD3DGeometry.h, in their order:
    /// kQ3ErrorNULLParameter (vertices is NULL),
    /// kQ3ErrorGeometryInsufficientNumberOfPoints (numVertices < 3),
    /// kQ3ErrorParameterOutOfRange (numVertices above kQ3GeometryMaxArrayCount),
    /// kQ3ErrorInvalidData (a coordinate is not finite).
    static void check(const TQ3PolygonData& data);

    using DataGeometry::DataGeometry;

    const ClassInfo& classInfo() const override { return kPolygonClass; }
    /// The polygon's area as triangles (mesh/Triangulate.h, in the plane that
    /// fits its outline best; concave outlines too), its outline as the
    /// wireframe; each vertex with its own attributes.
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;

    std::size_t vertexCount() const { return data().numVertices; }
    const TQ3Vertex3D& vertex(std::size_t index) const;
    void setVertexPosition(std::size_t index, const TQ3Point3D& position);
    void setVertexAttributeSet(std::size_t index, Ref<AttributeSet> attributes);
};

} // namespace q3
