// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"
#include "geometry/nurbs/ToolResult.h"

#include <cstddef>

namespace q3::nurbs {

/// How the fitted curve's parameter at each point follows the polyline through the
/// points: in proportion to the length of each leg (chord length, lecture 6,
/// section 6.5), or to its square root (centripetal, E. T. Y. Lee 1989), which
/// follows sharp turns more tightly.
enum class Parameterization { kChordLength, kCentripetal };

/// Fits a non-rational curve of `order` with `numControlPoints` control points to
/// `numPoints` points (xyz: x, y, z floats per point, the TQ3Point3D layout)
/// by least squares, with the first and last control points fixed at the first and
/// last points. With numControlPoints == numPoints the fit is exact: the curve
/// interpolates every point (lecture 6, section 6.5, generalised to any order).
///
/// Parameters u_0 = 0 < ... < u_{N-1} = 1 as `how` says. The knot vector is clamped
/// on [0, 1]; its n - k interior knots are the parameter sequence read at the
/// fractional positions s_m = (k - 2)/2 + m (N - k + 1)/(n - k + 1), m = 1 .. n - k,
/// interpolating linearly between neighbours. For interpolation (n = N) that is
/// u_{m + (k-2)/2}: for cubics exactly the lecture's choice (the parameters with
/// u_2 and u_{N-1} left out), for even degrees the midpoints of neighbouring
/// parameters; for n < N the knots spread evenly over the parameters. Either way
/// every knot span holds parameters enough for the Schoenberg-Whitney condition,
/// so the system has one solution. The knots are rounded to float before the system
/// is set up, so that the float curve handed out is the one that was fitted. The
/// banded least-squares system is solved by Givens rotations, one row per point
/// (sequential accumulation of a banded matrix, Lawson & Hanson, "Solving Least
/// Squares Problems"), in O(N k^2) time and O(n k) memory.
///
/// Errors: order outside 2..16, numPoints or numControlPoints above kMaxToolPoints,
/// numControlPoints outside order .. numPoints (kOutOfRange); numPoints < order
/// (kTooFewPoints); a coordinate that is not finite (kNotFinite); two consecutive
/// points that coincide (kInvalidArgument); points so close together that the
/// parameters or the float knots cannot tell them apart, or a system that is
/// numerically singular (kDegenerate).
ToolResult<HomogeneousCurve> fitPoints(unsigned order, const float* xyz, std::size_t numPoints,
                                       std::size_t numControlPoints, Parameterization how);

/// The size checks fitPoints makes first, in its order, without reading any point;
/// for callers that must check something else between them and the points.
ToolResult<bool> checkFitSizes(unsigned long order, std::size_t numPoints, std::size_t numControlPoints);

} // namespace q3::nurbs
