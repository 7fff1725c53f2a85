// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"
#include "geometry/nurbs/ToolResult.h"

#include <cstddef>

namespace q3::nurbs {

/// The most interval bisections one arc-length call makes beyond one interval per
/// knot span. When the tolerance has not been met by then, the call still returns
/// its best value, with a warning giving the estimated error. Each bisection costs
/// 32 evaluations of the speed, so the cap bounds a call to about 0.1 s at order 16
/// (less at lower orders); spent worst interval first, 4096 bisections take the
/// length of a curve with a cusp to about 1e-14 of itself.
constexpr std::size_t kMaxArcLengthBisections = std::size_t(1) << 12;

/// The length of a valid curve between parameters t0 <= t1, to within `tolerance`
/// (an absolute length, by the quadrature's own error estimate).
/// t0 and t1 must be finite (kNotFinite), inside the closed domain (kOutOfRange) and
/// in order (kInvalidArgument); tolerance must be finite (kNotFinite) and greater
/// than 0 (kInvalidArgument).
///
/// The length is the integral of the speed |C'(t)| (Derivatives.h) over each knot
/// span in the range, where the speed is smooth, by adaptive Gauss-Legendre
/// quadrature: an interval's 8-point estimate is compared with the sum over its two
/// halves; within its share of the tolerance (in proportion to its width) the sum is
/// kept, otherwise each half is treated the same way.
ToolResult<double> arcLength(const CurveRef& curve, double t0, double t1, double tolerance);

/// The parameter t >= t0 at which the length from t0 reaches `length`, so that
/// |arcLength(t0, t) - length| <= tolerance. length must be finite (kNotFinite) and
/// between 0 and the length from t0 to the domain's end (kOutOfRange: a length longer
/// than the rest of the curve by more than the tolerance; within it, the end is
/// returned). t0 and tolerance as for arcLength. Spans are measured one after
/// another until the one holding the length; inside it the parameter is found by
/// Newton's method on L(t) - length (L' is the speed), kept inside a shrinking
/// bracket by bisection, at most 100 steps.
ToolResult<double> parameterAtLength(const CurveRef& curve, double t0, double length, double tolerance);

} // namespace q3::nurbs
