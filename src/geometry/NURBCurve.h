// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "geometry/CurveCache.h"
#include "geometry/DataGeometry.h"
#include "geometry/nurbs/Curve.h"

namespace q3 {

extern const ClassInfo kNURBCurveClass;

/// Checks a caller's TQ3NURBCurveData against the article's rules; the one
/// routine behind Q3NURBCurve_New, _SetData and immediate-mode _Submit. Throws
/// kQ3ErrorNULLParameter (data or an array is NULL), kQ3ErrorParameterOutOfRange
/// (order outside 2-16, numPoints above kQ3GeometryMaxArrayCount),
/// kQ3ErrorGeometryInsufficientNumberOfPoints (numPoints < order) or
/// kQ3ErrorInvalidData (any other rule), with a message naming the rule, the
/// index and the value. Does not look at the attribute set.
void validateNURBCurveData(const TQ3NURBCurveData* data);

/// The curve part of valid data, as the NURBS math takes it.
nurbs::CurveRef curveRefOf(const TQ3NURBCurveData& data);

/// A NURB curve. Invariant: its order, control points and knots always
/// satisfy validateNURBCurveData; every edit is checked on a copy first and
/// bumps the edit index only once it has been applied. It keeps no
/// tessellation (CurveCache): each pass subdivides it again.
class NURBCurve final : public DataGeometry<NURBCurve, TQ3NURBCurveData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeNURBCurve;
    static constexpr const char* kName = "curve";
    static constexpr const char* kDataName = "curveData";
    static constexpr TQ3AttributeSet TQ3NURBCurveData::*kOwnSet = &TQ3NURBCurveData::curveAttributeSet;

    static void check(const TQ3NURBCurveData& data) { validateNURBCurveData(&data); }

    using DataGeometry::DataGeometry;

    const ClassInfo& classInfo() const override { return kNURBCurveClass; }
    /// The polyline the context's subdivision gives (one point for a curve
    /// that subdivides to a single point).
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;
    /// The control points projected to 3D (x/w, y/w, z/w): the article's
    /// bound, which the curve never leaves (convex hull property).
    void bound(const DecomposeContext& context, std::vector<glm::dvec3>& points) const override;
    /// The polyline as a PolyLine with the curve's attribute set; a curve that
    /// subdivides to one point gives two equal vertices.
    Ref<Geometry> decomposed(const DecomposeContext& context) const override;

    TQ3RationalPoint4D controlPoint(unsigned long index) const;
    void setControlPoint(unsigned long index, const TQ3RationalPoint4D& point);
    float knot(unsigned long index) const;
    void setKnot(unsigned long index, float value);

    nurbs::CurveRef curve() const { return curveRefOf(data()); }
    CurveCache& cache() const { return m_cache; }

private:
    mutable CurveCache m_cache;
};

} // namespace q3
