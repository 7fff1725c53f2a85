// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/Limits.h"
#include "geometry/nurbs/Curve.h"
#include "geometry/nurbs/Knots.h"

#include <cstddef>
#include <vector>

// NURB surfaces (tensor-product patches) and the two-dimensional rational
// curves that trim them: plain values in, plain values out.
namespace q3::nurbs {

/// Smallest and largest patch order in u and in v (kQ3NURBPatchMaxOrder).
constexpr unsigned kMinPatchOrder = limits::kMinPatchOrder;
constexpr unsigned kMaxPatchOrder = limits::kMaxPatchOrder;

/// A non-owning view of a patch in QuickDraw 3D's layout (TQ3NURBPatchData
/// without trim loops and attribute set): numRows rows of numColumns
/// homogeneous points, point (row, column) at 4 * (row * numColumns + column);
/// u runs along a row, v across rows. Functions taking a SurfaceRef require
/// checkSurface(surface).ok() unless their comment says otherwise.
struct SurfaceRef {
    unsigned uOrder = 0;
    unsigned vOrder = 0;
    std::size_t numColumns = 0;      ///< control points in u, >= uOrder
    std::size_t numRows = 0;         ///< control points in v, >= vOrder
    const float* points = nullptr;   ///< 4 * numRows * numColumns floats: x, y, z, w (homogeneous)
    const float* uKnots = nullptr;   ///< uOrder + numColumns floats
    const float* vKnots = nullptr;   ///< vOrder + numRows floats
};

/// The rule a knot vector breaks (the article's knot rules, as for curves).
enum class KnotRule {
    kValid,
    kNotFinite,   ///< knots[index] is NaN or infinite
    kDecreasing,  ///< knots[index] < knots[index - 1]
    kRunTooLong,  ///< knots[index .. index + run - 1] are equal, run > limit
    kEmptyDomain, ///< knots[order - 1] == knots[numPoints]
};

/// Outcome of checkKnots(): the first rule broken, at the lowest index.
struct KnotCheck {
    KnotRule rule = KnotRule::kValid;
    std::size_t index = 0;  ///< the knot the rule names (the first of a run)
    std::size_t run = 0;    ///< kRunTooLong: how many equal knots
    std::size_t limit = 0;  ///< kRunTooLong: how many are allowed there
    bool ok() const { return rule == KnotRule::kValid; }
};

/// Checks numPoints + order knots, in KnotRule order: finite, nondecreasing,
/// runs of equal knots at most order - 1 long (order at either end of the
/// vector), knots[order - 1] < knots[numPoints]. Requires order >= 2,
/// numPoints >= order and the array. O(numPoints + order).
KnotCheck checkKnots(const float* knots, std::size_t numPoints, unsigned order);

/// The parameter rectangle a valid patch is defined on.
struct SurfaceDomain {
    double u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;
};
SurfaceDomain surfaceDomain(const SurfaceRef& surface);

/// The non-empty spans of a patch in u (over uKnots) and in v (over vKnots).
std::vector<Span> uSpans(const SurfaceRef& surface);
std::vector<Span> vSpans(const SurfaceRef& surface);

/// A surface point with its first partial derivatives and unit normal, all in
/// the patch's own coordinates.
struct SurfacePoint {
    Point3 point;
    Point3 du;      ///< dS/du of the rational surface
    Point3 dv;      ///< dS/dv
    Point3 normal;  ///< (du x dv) / |du x dv|; see evaluateWithNormal for where that vanishes
};

/// The surface at (u, v) by the tensor-product Cox-de Boor sum on the
/// homogeneous points, in double, divided by w. u and v are clamped to the
/// domain (NaN counts as its start); at a knot the span to the right (above)
/// is used, at the domain end the last one. O(uOrder^2 + vOrder^2 +
/// uOrder * vOrder), no allocation.
Point3 evaluateSurface(const SurfaceRef& surface, double u, double v);

/// As evaluateSurface, plus the exact first partial derivatives (the
/// quotient rule on the homogeneous sums and their derivatives) and the unit
/// normal. Where du x dv vanishes or is lost to rounding (a pole, a collapsed
/// edge, a cusp), the normal is the one a short step inside the domain
/// (1e-6 of the domain's width and height towards its centre, then 1e-4,
/// then 1e-2), so that vertices there still get the limit of their
/// neighbours' normals; if every step fails too the normal is (0, 0, 0).
SurfacePoint evaluateWithNormal(const SurfaceRef& surface, double u, double v);

/// The surface along one line of constant v: the columns' homogeneous
/// control points collapsed at v (and their v derivatives), so that each
/// point along the line costs one curve sum of uOrder terms instead of a
/// tensor sum. Tessellation evaluates rows of vertices this way.
/// Invariant: after setV, columns() holds numColumns points (and
/// columnDerivatives() too when derivatives were asked for).
class SurfaceRowEvaluator {
public:
    explicit SurfaceRowEvaluator(const SurfaceRef& surface);

    /// Collapses the columns at v (clamped to the domain). O(numColumns * vOrder).
    void setV(double v, bool derivatives);
    double v() const { return m_v; }

    /// The surface at (u, v), u clamped to the domain. O(uOrder^2).
    Point3 point(double u) const;
    /// The same with partials and unit normal, as evaluateWithNormal gives
    /// them (requires setV with derivatives).
    SurfacePoint pointWithNormal(double u) const;
    /// The same from the basis functions of u already computed: span is the
    /// knot span, n and dn the uOrder values and derivatives.
    SurfacePoint pointWithNormal(double u, std::size_t span, const double* n, const double* dn) const;

    const SurfaceRef& surface() const { return m_s; }

private:
    SurfaceRef m_s;
    SurfaceDomain m_domain;
    double m_v = 0.0;
    std::vector<Point4> m_columns;
    std::vector<Point4> m_derivatives;
};

/// The values and first derivatives of the order-k B-spline basis functions
/// that are not zero on span `span` (knots[span] <= t < knots[span + 1]):
/// value[j] = N_{span-k+1+j,k}(t) and derivative[j] its derivative, for
/// j = 0 .. k-1. Built level by level from the article's recursion (0/0
/// taken as 0); the derivative is lecture eq. 6.23-6.24 applied to the
/// functions: N'_{i,k} = (k-1) (N_{i,k-1} / (x_{i+k-1} - x_i) -
/// N_{i+1,k-1} / (x_{i+k} - x_{i+1})). derivative may be null. O(k^2).
void basisWithDerivative(const float* knots, std::size_t span, unsigned order, double t, double* value,
                         double* derivative);

/// The knot index of the span of a valid knot vector holding t, clamped to
/// the domain as findSpan does for curves.
std::size_t findKnotSpan(const float* knots, std::size_t numPoints, unsigned order, double t);

/// A trim curve: a NURB curve in a patch's (u, v) plane, its control points
/// (x, y, w) homogeneous (the point is (x/w, y/w)), as TQ3NURBPatchTrimCurveData
/// holds it.
struct TrimCurveRef {
    unsigned order = 0;
    std::size_t numPoints = 0;
    const float* points = nullptr;  ///< 3 * numPoints floats: x, y, w
    const float* knots = nullptr;   ///< numPoints + order floats
};

/// The same curve as a three-dimensional one with z = 0, so the curve
/// machinery (evaluation, subdivision) applies to it. Owns its arrays.
struct PlanarCurve {
    unsigned order = 0;
    std::vector<float> points;  ///< x, y, 0, w per point
    std::vector<float> knots;

    explicit PlanarCurve(const TrimCurveRef& trim);
    CurveRef ref() const;
};

/// Where a valid trim curve starts and ends (its points at the ends of its
/// domain), in double.
struct TrimEnds {
    double startU = 0.0, startV = 0.0, endU = 0.0, endV = 0.0;
};
TrimEnds trimCurveEnds(const TrimCurveRef& trim);

} // namespace q3::nurbs
