// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/DataGeometry.h"

namespace q3 {

extern const ClassInfo kGeneralPolygonClass;

/// A general polygon: contours filled under the even-odd rule. Invariant: its
/// data obeys the TQ3GeneralPolygonData rules of QD3DGeometry.h (at least one
/// contour, each of at least three finite vertices, a shape hint of the
/// enumeration, at most kQ3GeometryMaxArrayCount vertices in all).
class GeneralPolygon final : public DataGeometry<GeneralPolygon, TQ3GeneralPolygonData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeGeneralPolygon;
    static constexpr const char* kName = "general polygon";
    static constexpr const char* kDataName = "generalPolygonData";
    static constexpr TQ3AttributeSet TQ3GeneralPolygonData::*kOwnSet =
        &TQ3GeneralPolygonData::generalPolygonAttributeSet;

    /// The TQ3GeneralPolygonData rules of QD3DGeometry.h, in their order.
    static void check(const TQ3GeneralPolygonData& data);
    /// kQ3ErrorInvalidParameter unless hint is one of the enumeration's.
    static void checkShapeHint(const TQ3GeneralPolygonShapeHint& hint, TQ3Error code);

    using DataGeometry::DataGeometry;

    const ClassInfo& classInfo() const override { return kGeneralPolygonClass; }
    /// Every contour's vertices (with their own attributes), the region
    /// inside an odd number of contours as triangles (mesh/Triangulate.h, in
    /// the plane that fits all the vertices best) and every contour's
    /// outline as the wireframe.
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;

    const TQ3Vertex3D& vertex(unsigned long contour, unsigned long index) const;
    void setVertexPosition(unsigned long contour, unsigned long index, const TQ3Point3D& position);
    void setVertexAttributeSet(unsigned long contour, unsigned long index, Ref<AttributeSet> attributes);
    TQ3GeneralPolygonShapeHint shapeHint() const { return data().shapeHint; }
    void setShapeHint(const TQ3GeneralPolygonShapeHint& hint);

private:
    const TQ3GeneralPolygonContourData& contour(unsigned long index) const;
};

// The data description (core/DataLayout.h).
namespace layout {
template <>
struct Describe<TQ3GeneralPolygonContourData> {
    static auto fields()
    {
        using C = TQ3GeneralPolygonContourData;
        return std::make_tuple(atLeast("numVertices", &C::numVertices, 3),
                               requiredArray("vertices", &C::vertices, countOf(&C::numVertices)));
    }
};

template <>
struct Describe<TQ3GeneralPolygonData> {
    static auto fields()
    {
        using D = TQ3GeneralPolygonData;
        return std::make_tuple(atLeast("numContours", &D::numContours, 1),
                               requiredArray("contours", &D::contours, countOf(&D::numContours)),
                               value("shapeHint", &D::shapeHint),
                               handle<AttributeSet>("generalPolygonAttributeSet", &D::generalPolygonAttributeSet));
    }
};
} // namespace layout

} // namespace q3
