// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
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

} // namespace q3
