// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "geometry/Geometry.h"

namespace q3 {

extern const ClassInfo kPointClass;

/// Checks a caller's TQ3PointData against the rules in QD3DGeometry.h:
/// kQ3ErrorNULLParameter (data is NULL), kQ3ErrorInvalidData (a coordinate is
/// not finite). The one routine behind Q3Point_New, _SetData and _Submit; the
/// attribute set handle is checked when the point resolves it.
void validatePointData(const TQ3PointData* data);

/// A retained point. Invariant: its position is finite (its attribute set is
/// held by Geometry).
class Point final : public Geometry {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypePoint;

    /// Copies valid data (validate first). Throws kQ3ErrorInvalidObject or
    /// kQ3ErrorInvalidObjectType for a bad attribute set handle.
    explicit Point(const TQ3PointData& data);

    const ClassInfo& classInfo() const override { return kPointClass; }
    Object* duplicate() const override;
    void accept(ShapeVisitor& visitor) const override;

    /// Fills `out` with the position and a new reference to the attribute set.
    void getData(TQ3PointData& out) const;
    void setData(const TQ3PointData& data);
    /// Releases the reference getData handed out and sets it to NULL.
    static void emptyData(TQ3PointData& data);

    const TQ3Point3D& point() const { return m_point; }
    /// Moves the point; kQ3ErrorInvalidData (and no change) when a coordinate
    /// is not finite, as for TQ3PointData.
    void setPosition(const TQ3Point3D& position);

private:
    Point(const TQ3Point3D& point, Ref<AttributeSet> attributes);

    TQ3Point3D m_point;
};

} // namespace q3
