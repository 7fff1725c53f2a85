// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
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

} // namespace q3
