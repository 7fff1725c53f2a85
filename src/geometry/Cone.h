// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/Quadric.h"

namespace q3 {

extern const ClassInfo kConeClass;

/// A cone, possibly partial in u and v, with its caps. Invariant: its data
/// obeys the TQ3ConeData rules of QD3DGeometry.h.
class Cone final : public QuadricGeometry<Cone, TQ3ConeData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeCone;
    static constexpr const char* kName = "cone";
    static constexpr const char* kDataName = "coneData";
    static constexpr TQ3AttributeSet TQ3ConeData::*kOwnSet = &TQ3ConeData::coneAttributeSet;

    /// The TQ3ConeData rules of QD3DGeometry.h, in their order.
    static void check(const TQ3ConeData& data) { checkRevolvedData(data); }
    /// The tolerated degenerate case of the data (Quadric.h), or "".
    static std::string degeneracy(const TQ3ConeData& data) { return revolvedDegeneracy(data); }
    static quadric::Patches patches(const TQ3ConeData& data) { return quadric::conePatches(revolvedShape(data)); }
    /// The base ellipse's box and the apex.
    static void boundPoints(const TQ3ConeData& data, std::vector<glm::dvec3>& points);

    using QuadricGeometry::QuadricGeometry;

    const ClassInfo& classInfo() const override { return kConeClass; }
    std::vector<const AttributeSet*> partSets() const;
};

// The data description (core/DataLayout.h), with the 3DMF form its reader
// and writer come from (io/SimpleGeometryIO.cpp).
namespace layout {
template <> struct Describe<TQ3ConeData> {
    static auto fields()
    {
        using D = TQ3ConeData;
        return std::make_tuple(finite("origin", &D::origin), finite("orientation", &D::orientation),
                               finite("majorRadius", &D::majorRadius), finite("minorRadius", &D::minorRadius),
                               finite("uMin", &D::uMin), finite("uMax", &D::uMax), finite("vMin", &D::vMin),
                               finite("vMax", &D::vMax), value("caps", &D::caps),
                               handle<AttributeSet>("interiorAttributeSet", &D::interiorAttributeSet),
                               handle<AttributeSet>("faceAttributeSet", &D::faceAttributeSet),
                               handle<AttributeSet>("bottomAttributeSet", &D::bottomAttributeSet),
                               handle<AttributeSet>("coneAttributeSet", &D::coneAttributeSet));
    }
    // As Quesa reads it; an object with no data is MF3D's default (docs/3dmf.md).
    static auto fileFields()
    {
        using D = TQ3ConeData;
        return std::make_tuple(vector3D(&D::orientation, {1, 0, 0}), vector3D(&D::majorRadius, {0, 1, 0}),
                               vector3D(&D::minorRadius, {0, 0, 1}), point3D(&D::origin, {0, 0, 0}),
                               trailing(float32(&D::uMin, 0), float32(&D::uMax, 1), float32(&D::vMin, 0),
                                        float32(&D::vMax, 1)));
    }
    static auto fileParts()
    {
        using D = TQ3ConeData;
        return std::make_tuple(endCapsPart(&D::caps), capSetPart(CapPart::kInterior, &D::interiorAttributeSet),
                               capSetPart(CapPart::kFace, &D::faceAttributeSet),
                               capSetPart(CapPart::kBottom, &D::bottomAttributeSet), ownSetPart(&D::coneAttributeSet));
    }
};
} // namespace layout

} // namespace q3
