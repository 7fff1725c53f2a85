// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Knot-vector rules and span bookkeeping.
//
// The validity rules are the list in the article's section "NURB CURVES IN
// QUICKDRAW 3D" (order 2..16, at least `order` control points, n + k knots,
// nondecreasing knots, at most k-1 equal knots except k at either end, positive w).
// Two rules the article takes for granted are made explicit: every value is finite,
// and the domain [x_{k-1}, x_n] is not empty ("the curve begins at the k th knot
// from the beginning of the knot vector and ends at the k th knot from the end",
// section "DEFINING THE BASIS FUNCTIONS").
//
// Span search is the usual binary search over the domain knots (Piegl & Tiller,
// The NURBS Book, algorithm A2.1), with the end-of-domain case sent to the last
// non-empty span so that evaluation is defined on the closed domain.

#include "geometry/nurbs/Knots.h"
#include "geometry/nurbs/ToolResult.h"

#include <cmath>
#include <cstdio>

namespace q3::nurbs {
namespace {

CurveValidation fail(CurveRule rule, std::size_t index, std::string message)
{
    CurveValidation result;
    result.rule = rule;
    result.index = index;
    result.message = std::move(message);
    return result;
}

// Shared by the float view and the double curve; `knot(i)` returns a double.
template <typename KnotAt>
std::size_t findSpanIn(unsigned order, std::size_t numPoints, KnotAt knot, double t)
{
    const std::size_t first = order - 1;
    const double start = knot(first);
    const double end = knot(numPoints);
    std::size_t lo = first;
    std::size_t hi = numPoints;
    if (!(t > start)) {
        t = start;
    }
    if (t >= end) {
        // Last non-empty span: largest lo with knot(lo) < end.
        while (hi - lo > 1) {
            const std::size_t mid = lo + (hi - lo) / 2;
            if (knot(mid) < end) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return lo;
    }
    // Invariant: knot(lo) <= t < knot(hi).
    while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (t < knot(mid)) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    return lo;
}

} // namespace

CurveProblem CurveValidation::problem() const
{
    switch (rule) {
    case CurveRule::kValid:
        return CurveProblem::kNone;
    case CurveRule::kOrderOutOfRange:
        return CurveProblem::kOrderOutOfRange;
    case CurveRule::kTooFewPoints:
        return CurveProblem::kTooFewPoints;
    default:
        return CurveProblem::kBadContent;
    }
}

CurveValidation validateCurve(const CurveRef& curve)
{
    const unsigned k = curve.order;
    const std::size_t n = curve.numPoints;
    if (k < kMinOrder || k > kMaxOrder) {
        return fail(CurveRule::kOrderOutOfRange, 0,
                    formatMessage("order %u is outside %u..%u", k, kMinOrder, kMaxOrder));
    }
    if (n < k) {
        return fail(CurveRule::kTooFewPoints, 0,
                    formatMessage("%zu control points is fewer than the order %u", n, k));
    }
    if (curve.points == nullptr || curve.knots == nullptr) {
        return fail(CurveRule::kMissingArray, 0,
                    curve.points == nullptr ? "the control point array is null"
                                            : "the knot array is null");
    }

    const std::size_t numKnots = n + k;
    const float* x = curve.knots;
    for (std::size_t i = 0; i < numKnots; ++i) {
        if (!std::isfinite(x[i])) {
            return fail(CurveRule::kKnotNotFinite, i,
                        formatMessage("knot %zu is %g; knots must be finite", i, double(x[i])));
        }
    }
    for (std::size_t i = 1; i < numKnots; ++i) {
        if (x[i] < x[i - 1]) {
            return fail(CurveRule::kKnotDecreasing, i,
                        formatMessage("knot %zu (%g) is less than knot %zu (%g); knots must be nondecreasing",
                                      i, double(x[i]), i - 1, double(x[i - 1])));
        }
    }
    for (std::size_t start = 0; start < numKnots;) {
        std::size_t stop = start + 1;
        while (stop < numKnots && x[stop] == x[start]) {
            ++stop;
        }
        const std::size_t length = stop - start;
        const bool atEnd = start == 0 || stop == numKnots;
        const std::size_t limit = atEnd ? k : k - 1;
        if (length > limit) {
            return fail(CurveRule::kKnotRunTooLong, start,
                        formatMessage("knots %zu..%zu are all %g: %zu equal knots where at most %zu are "
                                      "allowed (order - 1 inside the vector, order at either end)",
                                      start, stop - 1, double(x[start]), length, limit));
        }
        start = stop;
    }

    const float* p = curve.points;
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 4; ++c) {
            if (!std::isfinite(p[4 * i + c])) {
                return fail(CurveRule::kPointNotFinite, i,
                            formatMessage("control point %zu has a component that is %g; "
                                          "control points must be finite",
                                          i, double(p[4 * i + c])));
            }
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!(p[4 * i + 3] > 0.0f)) {
            return fail(CurveRule::kWeightNotPositive, i,
                        formatMessage("control point %zu has w = %g; w must be positive",
                                      i, double(p[4 * i + 3])));
        }
    }
    if (!(x[k - 1] < x[n])) {
        return fail(CurveRule::kEmptyDomain, k - 1,
                    formatMessage("knot %u and knot %zu are both %g, so the curve's domain is empty",
                                  k - 1, n, double(x[n])));
    }
    return CurveValidation{};
}

Domain curveDomain(const CurveRef& curve)
{
    return Domain{curve.knots[curve.order - 1], curve.knots[curve.numPoints]};
}

double clampToDomain(const Domain& domain, double t)
{
    if (!(t > domain.start)) {
        return domain.start;
    }
    return t < domain.end ? t : domain.end;
}

std::vector<Span> nonEmptySpans(const CurveRef& curve)
{
    std::vector<Span> spans;
    spans.reserve(countNonEmptySpans(curve));
    for (std::size_t i = curve.order - 1; i < curve.numPoints; ++i) {
        const double a = curve.knots[i];
        const double b = curve.knots[i + 1];
        if (a < b) {
            spans.push_back(Span{i, a, b});
        }
    }
    return spans;
}

std::size_t countNonEmptySpans(const CurveRef& curve)
{
    std::size_t count = 0;
    for (std::size_t i = curve.order - 1; i < curve.numPoints; ++i) {
        count += curve.knots[i] < curve.knots[i + 1] ? 1 : 0;
    }
    return count;
}

std::size_t findSpan(const CurveRef& curve, double t)
{
    const float* x = curve.knots;
    return findSpanIn(curve.order, curve.numPoints, [x](std::size_t i) { return double(x[i]); }, t);
}

std::size_t findSpan(const HomogeneousCurve& curve, double t)
{
    const double* x = curve.knots.data();
    return findSpanIn(curve.order, curve.points.size(), [x](std::size_t i) { return x[i]; }, t);
}

} // namespace q3::nurbs
