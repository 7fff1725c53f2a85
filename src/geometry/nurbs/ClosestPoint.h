// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"
#include "geometry/nurbs/ToolResult.h"

#include <cstddef>

namespace q3::nurbs {

/// The point of a curve nearest to another point.
struct ClosestPoint {
    double t = 0.0;
    Point3 point;
    double distance = 0.0;
};

/// The tolerance of closestPoint, relative to the diagonal of the bounding box of
/// the curve's control points (x/w, y/w, z/w).
constexpr double kClosestPointTolerance = 1e-9;
/// The most pieces one closestPoint call splits in two.
constexpr std::size_t kMaxClosestPointSplits = 4096;

/// The point of a valid curve nearest to target, by branch and bound over the
/// Bezier pieces of its non-empty spans with a safeguarded Newton iteration in each
/// piece that may hold a nearer point (see ClosestPoint.cpp). Every span end (corners
/// and the domain's ends included) is a candidate. The distance returned exceeds the
/// distance from target to the curve by at most kClosestPointTolerance times the
/// diagonal of the control points' bounding box, unless the search ran out of its
/// kMaxClosestPointSplits splits, which takes a stretch of curve whose points are all
/// that nearly equally near (target close to a centre of curvature, as at the centre
/// of a circular arc); then the result is the nearest point found by then. Among equally near points the smallest t seen wins.
/// target must be finite (kNotFinite).
/// Cost: O(order^2) per Newton step; a few dozen pieces for a target not close to a
/// centre of curvature, at most kMaxClosestPointSplits; memory O(spans * order).
ToolResult<ClosestPoint> closestPoint(const CurveRef& curve, const Point3& target);

} // namespace q3::nurbs
