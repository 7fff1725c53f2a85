// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
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

} // namespace q3
