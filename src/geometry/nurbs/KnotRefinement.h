// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"
#include "geometry/nurbs/ToolResult.h"

#include <cstddef>
#include <vector>

namespace q3::nurbs {

/// Inserts every value of `knots` (nondecreasing, each strictly inside the domain,
/// no value then occurring more than order - 1 times) into a curve that obeys the
/// validateCurve() rules, in one pass: the same curve with knots.size() more knots
/// and control points. Cost O((n + r) * order) for r new knots.
/// Errors: none (unchecked; see refineKnots). Ownership: returns a new curve.
HomogeneousCurve refine(const HomogeneousCurve& curve, const std::vector<double>& knots);

/// Inserts the knot t `times` times (0 gives a copy). t must be finite (kNotFinite)
/// and strictly inside the domain (kOutOfRange); t may already be a knot, but the
/// insertions may not make it occur more than order - 1 times (kOutOfRange) or the
/// curve have more than kMaxToolPoints control points (kOutOfRange).
ToolResult<HomogeneousCurve> insertKnotTimes(const HomogeneousCurve& curve, double t, std::size_t times);

/// Inserts the given knots, in any order (sorted first). Each must be finite
/// (kNotFinite), strictly inside the domain (kOutOfRange), and no value may end up
/// occurring more than order - 1 times (kInvalidArgument); the result may have at
/// most kMaxToolPoints control points (kOutOfRange).
ToolResult<HomogeneousCurve> refineKnots(const HomogeneousCurve& curve, std::vector<double> knots);

/// The outcome of removeKnot: the curve with `removed` copies of the knot taken out.
struct KnotRemoval {
    HomogeneousCurve curve;
    std::size_t removed = 0;
};

/// Removes the knot knots[knotIndex] up to `times` times (0 gives a copy), as often
/// as the curve allows while it moves by no more than `tolerance` (a distance, in the
/// curve's units) anywhere: the largest count c <= times whose result is proven
/// within tolerance. The result's values are rounded to float before the proof, so
/// the promise holds for the float curve the C layer hands out.
///
/// Removing c copies of u leaves the control points away from u as they are and
/// chooses the p = order - 1 points next to it so that inserting u back c times
/// comes as close as possible, in the least-squares sense, to the original points
/// (Lyche & Morken, "Knot removal for parametric B-spline curves and surfaces",
/// CAGD 4, 1987, use the same best approximation). When u is removable the fit is
/// exact, whatever the order; a knot that is not removable is approximated as well
/// as the reduced knot vector allows.
///
/// Proof: the removed knot is inserted back c times, which gives a curve on the
/// original knot vector with homogeneous points (A_i, v_i) next to the original
/// (B_i, w_i). On one knot vector the homogeneous curves differ by no more than their
/// control points (convex hull property), so with C = A/v and D = B/w,
///   |C - D| = |(A - B) + C (w - v)| / w <= (max |A_i - B_i| + R max |v_i - w_i|) / w_min,
/// where R bounds |C| (the largest distance of a projected control point from the
/// origin) and w_min is the smallest original weight, both over the points near u.
/// Piegl & Tiller (The NURBS Book, section 5.4) turn a distance into a homogeneous
/// tolerance the same way.
///
/// knotIndex must name a knot strictly inside the domain (kOutOfRange, also for an
/// index past the end); times may not exceed that knot's multiplicity (kOutOfRange);
/// tolerance must be finite (kNotFinite) and greater than 0 (kInvalidArgument).
/// Cost O(n + times * order^3).
ToolResult<KnotRemoval> removeKnot(const HomogeneousCurve& curve, std::size_t knotIndex, std::size_t times,
                                   double tolerance);

} // namespace q3::nurbs
