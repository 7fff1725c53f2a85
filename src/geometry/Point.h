// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/DataGeometry.h"

namespace q3 {

extern const ClassInfo kPointClass;

/// A point. Invariant: its position is finite (the TQ3PointData rule).
class Point final : public DataGeometry<Point, TQ3PointData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypePoint;
    static constexpr const char* kName = "point";
    static constexpr const char* kDataName = "pointData";
    static constexpr TQ3AttributeSet TQ3PointData::*kOwnSet = &TQ3PointData::pointAttributeSet;

    // The TQ3PointData rules of QD3DGeometry.h are all in the description below.

    using DataGeometry::DataGeometry;

    const ClassInfo& classInfo() const override { return kPointClass; }
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;
    bool isPrimitive() const override { return true; }

    const TQ3Point3D& point() const { return data().point; }
    /// Moves the point; kQ3ErrorInvalidData (and no change) when a coordinate
    /// is not finite.
    void setPosition(const TQ3Point3D& position);
};

// The data description (core/DataLayout.h), with the 3DMF form its reader
// and writer come from (io/SimpleGeometryIO.cpp).
namespace layout {
template <>
struct Describe<TQ3PointData> {
    static auto fields()
    {
        return std::make_tuple(finite("point", &TQ3PointData::point),
                               handle<AttributeSet>("pointAttributeSet", &TQ3PointData::pointAttributeSet));
    }
    static auto fileFields() { return std::make_tuple(point3D(&TQ3PointData::point)); }
    static auto fileParts() { return std::make_tuple(ownSetPart(&TQ3PointData::pointAttributeSet)); }
};
} // namespace layout

} // namespace q3
