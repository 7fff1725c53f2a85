// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/Quadric.h"

namespace q3 {

extern const ClassInfo kDiskClass;

/// A disk (an elliptic one), possibly partial in u and v. Invariant: its
/// data obeys the TQ3DiskData rules of QD3DGeometry.h.
class Disk final : public QuadricGeometry<Disk, TQ3DiskData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeDisk;
    static constexpr const char* kName = "disk";
    static constexpr const char* kDataName = "diskData";
    static constexpr TQ3AttributeSet TQ3DiskData::*kOwnSet = &TQ3DiskData::diskAttributeSet;

    /// The TQ3DiskData rules of QD3DGeometry.h, in their order.
    static void check(const TQ3DiskData& data);
    /// The tolerated degenerate case of the data (Quadric.h), or "".
    static std::string degeneracy(const TQ3DiskData& data);
    static quadric::Patches patches(const TQ3DiskData& data);
    /// The ellipse's box.
    static void boundPoints(const TQ3DiskData& data, std::vector<glm::dvec3>& points);

    using QuadricGeometry::QuadricGeometry;

    const ClassInfo& classInfo() const override { return kDiskClass; }
    std::vector<const AttributeSet*> partSets() const { return {}; }
};

// The data description (core/DataLayout.h), with the 3DMF form its reader
// and writer come from (io/SimpleGeometryIO.cpp).
namespace layout {
template <> struct Describe<TQ3DiskData> {
    static auto fields()
    {
        using D = TQ3DiskData;
        return std::make_tuple(finite("origin", &D::origin), finite("majorRadius", &D::majorRadius),
                               finite("minorRadius", &D::minorRadius), finite("uMin", &D::uMin), finite("uMax", &D::uMax),
                               finite("vMin", &D::vMin), finite("vMax", &D::vMax),
                               handle<AttributeSet>("diskAttributeSet", &D::diskAttributeSet));
    }
    // MF3D's 1.0 disk stops at the origin; the QD3D 1.5.4 book's adds the ranges.
    static auto fileFields()
    {
        using D = TQ3DiskData;
        return std::make_tuple(vector3D(&D::majorRadius, {1, 0, 0}), vector3D(&D::minorRadius, {0, 1, 0}),
                               point3D(&D::origin, {0, 0, 0}),
                               trailing(float32(&D::uMin, 0), float32(&D::uMax, 1), float32(&D::vMin, 0),
                                        float32(&D::vMax, 1)));
    }
    static auto fileParts() { return std::make_tuple(ownSetPart(&TQ3DiskData::diskAttributeSet)); }
};
} // namespace layout

} // namespace q3
