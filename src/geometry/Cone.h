// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
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

} // namespace q3
