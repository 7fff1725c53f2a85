// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
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

    // The TQ3PolygonData rules of QD3DGeometry.h are all in the description below.

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

// The data description (core/DataLayout.h), with the 3DMF form its reader
// and writer come from (io/SimpleGeometryIO.cpp).
namespace layout {
template <>
struct Describe<TQ3PolygonData> {
    static auto fields()
    {
        return std::make_tuple(
            atLeast("numVertices", &TQ3PolygonData::numVertices, 3),
            requiredArray("vertices", &TQ3PolygonData::vertices, countOf(&TQ3PolygonData::numVertices)),
            handle<AttributeSet>("polygonAttributeSet", &TQ3PolygonData::polygonAttributeSet));
    }
    static auto fileFields()
    {
        return std::make_tuple(vertexPoints(&TQ3PolygonData::numVertices, &TQ3PolygonData::vertices));
    }
    static auto fileParts()
    {
        using D = TQ3PolygonData;
        return std::make_tuple(ownSetPart(&D::polygonAttributeSet), vertexSetsPart(&D::numVertices, &D::vertices));
    }
};
} // namespace layout

} // namespace q3
