// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "geometry/Quadric.h"

namespace q3 {

extern const ClassInfo kCylinderClass;

/// A cylinder, possibly partial in u and v, with its caps. Invariant: its
/// data obeys the TQ3CylinderData rules of QD3DGeometry.h.
class Cylinder final : public QuadricGeometry<Cylinder, TQ3CylinderData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeCylinder;
    static constexpr const char* kName = "cylinder";
    static constexpr const char* kDataName = "cylinderData";
    static constexpr TQ3AttributeSet TQ3CylinderData::*kOwnSet = &TQ3CylinderData::cylinderAttributeSet;

    /// The TQ3CylinderData rules of QD3DGeometry.h, in their order.
    static void check(const TQ3CylinderData& data) { checkRevolvedData(data); }
    /// The tolerated degenerate case of the data (Quadric.h), or "".
    static std::string degeneracy(const TQ3CylinderData& data) { return revolvedDegeneracy(data); }
    static quadric::Patches patches(const TQ3CylinderData& data)
    {
        return quadric::cylinderPatches(revolvedShape(data));
    }
    /// The boxes of the bottom and top ellipses.
    static void boundPoints(const TQ3CylinderData& data, std::vector<glm::dvec3>& points);

    using QuadricGeometry::QuadricGeometry;

    const ClassInfo& classInfo() const override { return kCylinderClass; }
    std::vector<const AttributeSet*> partSets() const;
};

} // namespace q3
