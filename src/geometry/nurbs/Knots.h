// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"

#include <cstddef>
#include <string>
#include <vector>

namespace q3::nurbs {

/// The rule a curve breaks, in the order validateCurve() checks them.
enum class CurveRule {
    kValid,
    kOrderOutOfRange,     ///< order outside 2..16
    kTooFewPoints,        ///< numPoints < order
    kMissingArray,        ///< points or knots is null
    kKnotNotFinite,       ///< a knot is NaN or infinite; index = knot
    kKnotDecreasing,      ///< knots[index] < knots[index - 1]
    kKnotRunTooLong,      ///< too many equal knots; index = first knot of the run
    kPointNotFinite,      ///< a control point component is NaN or infinite; index = point
    kWeightNotPositive,   ///< a control point has w <= 0; index = point
    kEmptyDomain,         ///< knots[order - 1] == knots[numPoints]; index = order - 1
};

/// Coarse grouping of CurveRule, so a caller can pick an error code without
/// listing every rule.
enum class CurveProblem {
    kNone,
    kOrderOutOfRange,
    kTooFewPoints,
    kBadContent,          ///< every rule from kMissingArray on
};

/// Outcome of validateCurve().
struct CurveValidation {
    CurveRule rule = CurveRule::kValid;
    std::size_t index = 0;  ///< knot or control point index the rule names; 0 when it names none
    std::string message;    ///< one English sentence for a warning or error post; empty when valid

    bool ok() const { return rule == CurveRule::kValid; }
    CurveProblem problem() const;
};

/// Checks a curve against the rules of the article's "NURB CURVES IN QUICKDRAW 3D"
/// section, plus the two it leaves implicit (finite values, a non-empty domain).
/// Rules are checked in CurveRule order; within one rule the lowest index is reported.
/// A run of equal knots may be order - 1 long, or order long when it starts at the
/// first knot or ends at the last.
/// Reads order, numPoints and, when those pass, 4 * numPoints point floats and
/// numPoints + order knots.
/// Errors: none raised; the result names the first broken rule (problem() groups them
/// as the C layer's error codes need). Ownership: reads the caller's arrays only.
CurveValidation validateCurve(const CurveRef& curve);

/// The parameter range [knots[k-1], knots[n]] on which the curve is defined.
struct Domain {
    double start = 0.0;
    double end = 0.0;
};
Domain curveDomain(const CurveRef& curve);

/// A non-empty knot interval [start, end) = [knots[knotIndex], knots[knotIndex + 1])
/// inside the domain: one polynomial piece of the curve.
struct Span {
    std::size_t knotIndex = 0;
    double start = 0.0;
    double end = 0.0;
};

/// The non-empty spans of a valid curve, in increasing order; knotIndex runs over
/// order-1 .. numPoints-1.
std::vector<Span> nonEmptySpans(const CurveRef& curve);
std::size_t countNonEmptySpans(const CurveRef& curve);

/// The knot index i of the span holding t: knots[i] <= t < knots[i+1], order-1 <= i <= numPoints-1.
/// t is first clamped to the domain (NaN counts as the domain start); at the domain
/// end the last non-empty span is returned, so the curve is closed at both ends.
/// Binary search, O(log n). Requires a valid curve.
std::size_t findSpan(const CurveRef& curve, double t);
std::size_t findSpan(const HomogeneousCurve& curve, double t);

/// Clamps t to [start, end]; NaN becomes start.
double clampToDomain(const Domain& domain, double t);

} // namespace q3::nurbs
