// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/Quadric.h"

namespace q3 {

extern const ClassInfo kEllipsoidClass;

/// An ellipsoid, possibly partial in u and v, with its caps. Invariant: its
/// data obeys the TQ3EllipsoidData rules of QD3DGeometry.h.
class Ellipsoid final : public QuadricGeometry<Ellipsoid, TQ3EllipsoidData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeEllipsoid;
    static constexpr const char* kName = "ellipsoid";
    static constexpr const char* kDataName = "ellipsoidData";
    static constexpr TQ3AttributeSet TQ3EllipsoidData::*kOwnSet = &TQ3EllipsoidData::ellipsoidAttributeSet;

    /// The TQ3EllipsoidData rules of QD3DGeometry.h, in their order.
    static void check(const TQ3EllipsoidData& data) { checkRevolvedData(data); }
    /// The tolerated degenerate case of the data (Quadric.h), or "".
    static std::string degeneracy(const TQ3EllipsoidData& data) { return revolvedDegeneracy(data); }
    static quadric::Patches patches(const TQ3EllipsoidData& data)
    {
        return quadric::ellipsoidPatches(revolvedShape(data));
    }
    /// The ellipsoid's exact box: half-extents sqrt(x_i^2 + y_i^2 + z_i^2).
    static void boundPoints(const TQ3EllipsoidData& data, std::vector<glm::dvec3>& points);

    using QuadricGeometry::QuadricGeometry;

    const ClassInfo& classInfo() const override { return kEllipsoidClass; }
    /// Every part but the surface takes interiorAttributeSet.
    std::vector<const AttributeSet*> partSets() const;
};

// The data description (core/DataLayout.h), with the 3DMF form its reader
// and writer come from (io/SimpleGeometryIO.cpp).
namespace layout {
template <> struct Describe<TQ3EllipsoidData> {
    static auto fields()
    {
        using D = TQ3EllipsoidData;
        return std::make_tuple(finite("origin", &D::origin), finite("orientation", &D::orientation),
                               finite("majorRadius", &D::majorRadius), finite("minorRadius", &D::minorRadius),
                               finite("uMin", &D::uMin), finite("uMax", &D::uMax), finite("vMin", &D::vMin),
                               finite("vMax", &D::vMax), value("caps", &D::caps),
                               handle<AttributeSet>("interiorAttributeSet", &D::interiorAttributeSet),
                               handle<AttributeSet>("ellipsoidAttributeSet", &D::ellipsoidAttributeSet));
    }
    // As Quesa reads it; an object with no data is MF3D's default (docs/3dmf.md).
    static auto fileFields()
    {
        using D = TQ3EllipsoidData;
        return std::make_tuple(vector3D(&D::orientation, {1, 0, 0}), vector3D(&D::majorRadius, {0, 1, 0}),
                               vector3D(&D::minorRadius, {0, 0, 1}), point3D(&D::origin, {0, 0, 0}),
                               trailing(float32(&D::uMin, 0), float32(&D::uMax, 1), float32(&D::vMin, 0),
                                        float32(&D::vMax, 1)));
    }
    static auto fileParts()
    {
        using D = TQ3EllipsoidData;
        return std::make_tuple(endCapsPart(&D::caps), capSetPart(CapPart::kInterior, &D::interiorAttributeSet),
                               ownSetPart(&D::ellipsoidAttributeSet));
    }
};
} // namespace layout

} // namespace q3
