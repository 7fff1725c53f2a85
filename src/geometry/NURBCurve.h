// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "geometry/CurveCache.h"
#include "geometry/Geometry.h"
#include "geometry/nurbs/Curve.h"

#include <vector>

namespace q3 {

extern const ClassInfo kNURBCurveClass;

/// Checks a caller's TQ3NURBCurveData against the article's rules; the one
/// routine behind Q3NURBCurve_New, _SetData and immediate-mode _Submit. Throws
/// kQ3ErrorNULLParameter (data or an array is NULL), kQ3ErrorParameterOutOfRange
/// (order outside 2-16), kQ3ErrorGeometryInsufficientNumberOfPoints
/// (numPoints < order) or kQ3ErrorInvalidData (any other rule), with a message
/// naming the rule, the index and the value. Does not look at the attribute set.
void validateNURBCurveData(const TQ3NURBCurveData* data);

/// The curve part of valid data, as the NURBS math takes it.
nurbs::CurveRef curveRefOf(const TQ3NURBCurveData& data);

/// A retained NURB curve. Invariant: its order, control points and knots
/// always satisfy validateNURBCurveData; every edit is checked on a copy first
/// and bumps the edit index (dropping the cached tessellation) only once it
/// has been applied.
class NURBCurve final : public Geometry {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeNURBCurve;

    /// Copies valid data (validate first). Throws as attributeSetFromHandle.
    explicit NURBCurve(const TQ3NURBCurveData& data);

    const ClassInfo& classInfo() const override { return kNURBCurveClass; }
    Object* duplicate() const override;
    void accept(ShapeVisitor& visitor) const override;

    /// Fills `out` with freshly malloc'ed copies and a new reference to the
    /// attribute set (see emptyData).
    void getData(TQ3NURBCurveData& out) const;
    void setData(const TQ3NURBCurveData& data);
    /// Frees what getData allocated and releases the attribute set reference.
    static void emptyData(TQ3NURBCurveData& data);

    TQ3RationalPoint4D controlPoint(unsigned long index) const;
    void setControlPoint(unsigned long index, const TQ3RationalPoint4D& point);
    float knot(unsigned long index) const;
    void setKnot(unsigned long index, float value);

    nurbs::CurveRef curve() const;
    CurveCache& cache() const { return m_cache; }

protected:
    void onEdited() override { m_cache.invalidate(); }

private:
    NURBCurve() = default;
    void assign(const TQ3NURBCurveData& data, Ref<AttributeSet> attributes);

    unsigned long m_order = 0;
    std::vector<TQ3RationalPoint4D> m_points;
    std::vector<float> m_knots;
    mutable CurveCache m_cache;
};

} // namespace q3
