// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"
#include "geometry/nurbs/ToolResult.h"

#include <cstddef>

namespace q3::nurbs {

/// Piece `index` of a valid curve's Bezier decomposition: the rational Bezier curve
/// (order k, k control points, knots a repeated k times then b repeated k times)
/// that equals the curve on its index-th non-empty knot span [a, b], pieces counted
/// from 0 in increasing t. kOutOfRange when index >= countNonEmptySpans(curve).
/// Cost O(n + k^2) (finding the span, then spanToBezier).
ToolResult<HomogeneousCurve> bezierPiece(const CurveRef& curve, std::size_t index);

/// The two halves of a curve cut at a parameter.
struct SplitCurves {
    HomogeneousCurve left;   ///< the curve on [start, t], same parameters
    HomogeneousCurve right;  ///< the curve on [t, end]
};

/// Cuts a curve at t: t is inserted until it occurs order - 1 times (article,
/// "EVALUATING NURB CURVES": the control point then made lies on the curve at t),
/// and the control points and knots are shared out, each half receiving one more
/// copy of t so that it occurs order times at the cut end (Piegl & Tiller, section
/// 5.3, curve splitting). t must be finite (kNotFinite) and strictly inside the
/// domain (kOutOfRange). Cost O((n + k) k).
ToolResult<SplitCurves> splitAt(const HomogeneousCurve& curve, double t);

} // namespace q3::nurbs
