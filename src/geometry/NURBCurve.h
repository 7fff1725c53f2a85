// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/DataGeometry.h"
#include "geometry/Decompose.h"
#include "geometry/nurbs/Curve.h"

#include <atomic>
#include <cstdint>

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
/// tessellation, only a count: a retained curve may hold at most 4 times its
/// data (issue 16), and even a 4-point Bezier's 65-vertex polyline (780
/// bytes) is 8 times its 96 data bytes, so every pass subdivides it again
/// into the view's scratch buffer (SubdivisionMeasure::curveScratch), which
/// the renderer copies into its batch.
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
    /// that subdivides to a single point); kQ3WarningParameterOutOfRange when
    /// a cap (kQ3SubdivisionMaxSegmentsPerCurve, or in a view for world and
    /// screen space kQ3SubdivisionViewSegmentsPerPixel) made it coarser.
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
    /// How many times this retained curve has been subdivided (once per pass
    /// that drew or decomposed it); tests and benchmarks read it.
    std::uint64_t tessellations() const { return m_tessellations.load(std::memory_order_relaxed); }

private:
    /// Tessellates under the context's subdivision into its scratch (or
    /// `own`), counts it, and returns the polyline; the caller posts the
    /// warning (warnIfShort) once it has used it.
    const nurbs::TessellatedCurve& tessellate(const SubdivisionMeasure& measure, bool count,
                                              nurbs::TessellatedCurve& own) const;

    /// Atomic because views on several threads may draw the same retained
    /// curve; a copy (Duplicate) starts from the original's count.
    struct Counter : std::atomic<std::uint64_t> {
        Counter() : std::atomic<std::uint64_t>(0) {}
        Counter(const Counter& other) : std::atomic<std::uint64_t>(other.load(std::memory_order_relaxed)) {}
        Counter& operator=(const Counter& other)
        {
            store(other.load(std::memory_order_relaxed), std::memory_order_relaxed);
            return *this;
        }
    };
    mutable Counter m_tessellations;
};

// The data description (core/DataLayout.h).
namespace layout {
template <>
struct Describe<TQ3NURBCurveData> {
    static auto fields()
    {
        using D = TQ3NURBCurveData;
        return std::make_tuple(value("order", &D::order), value("numPoints", &D::numPoints),
                               array("controlPoints", &D::controlPoints, countOf(&D::numPoints)),
                               array("knots", &D::knots, countSum(&D::order, &D::numPoints)),
                               handle<AttributeSet>("curveAttributeSet", &D::curveAttributeSet));
    }
};
} // namespace layout

} // namespace q3
