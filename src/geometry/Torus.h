// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/Quadric.h"

namespace q3 {

extern const ClassInfo kTorusClass;

/// A torus, possibly partial in u and v, with the faces of its cuts.
/// Invariant: its data obeys the TQ3TorusData rules of QD3DGeometry.h.
class Torus final : public QuadricGeometry<Torus, TQ3TorusData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeTorus;
    static constexpr const char* kName = "torus";
    static constexpr const char* kDataName = "torusData";
    static constexpr TQ3AttributeSet TQ3TorusData::*kOwnSet = &TQ3TorusData::torusAttributeSet;

    /// The TQ3TorusData rules of QD3DGeometry.h, in their order.
    static void check(const TQ3TorusData& data);
    /// The tolerated degenerate case of the data (Quadric.h), or "".
    static std::string degeneracy(const TQ3TorusData& data);
    static quadric::Patches patches(const TQ3TorusData& data);
    /// A box holding the ring's box grown by the tube's reach along each
    /// axis.
    static void boundPoints(const TQ3TorusData& data, std::vector<glm::dvec3>& points);

    using QuadricGeometry::QuadricGeometry;

    const ClassInfo& classInfo() const override { return kTorusClass; }
    std::vector<const AttributeSet*> partSets() const;
};

// The data description (core/DataLayout.h), with the 3DMF form its reader
// and writer come from (io/SimpleGeometryIO.cpp).
namespace layout {
template <> struct Describe<TQ3TorusData> {
    static auto fields()
    {
        using D = TQ3TorusData;
        return std::make_tuple(finite("origin", &D::origin), finite("orientation", &D::orientation),
                               finite("majorRadius", &D::majorRadius), finite("minorRadius", &D::minorRadius),
                               finite("ratio", &D::ratio), finite("uMin", &D::uMin), finite("uMax", &D::uMax),
                               finite("vMin", &D::vMin), finite("vMax", &D::vMax), value("caps", &D::caps),
                               handle<AttributeSet>("interiorAttributeSet", &D::interiorAttributeSet),
                               handle<AttributeSet>("torusAttributeSet", &D::torusAttributeSet));
    }
    // As Quesa reads it; an object with no data is MF3D's default (docs/3dmf.md).
    static auto fileFields()
    {
        using D = TQ3TorusData;
        return std::make_tuple(vector3D(&D::orientation, {1, 0, 0}), vector3D(&D::majorRadius, {0, 1, 0}),
                               vector3D(&D::minorRadius, {0, 0, 1}), point3D(&D::origin, {0, 0, 0}),
                               float32(&D::ratio, 1),
                               trailing(float32(&D::uMin, 0), float32(&D::uMax, 1), float32(&D::vMin, 0),
                                        float32(&D::vMax, 1)));
    }
    static auto fileParts()
    {
        using D = TQ3TorusData;
        return std::make_tuple(endCapsPart(&D::caps), capSetPart(CapPart::kInterior, &D::interiorAttributeSet),
                               ownSetPart(&D::torusAttributeSet));
    }
};
} // namespace layout

} // namespace q3
