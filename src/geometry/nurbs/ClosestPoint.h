// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"
#include "geometry/nurbs/ToolResult.h"

namespace q3::nurbs {

/// The point of a curve nearest to another point.
struct ClosestPoint {
    double t = 0.0;
    Point3 point;
    double distance = 0.0;
};

/// Samples each non-empty span of a valid curve at 4 * order + 1 evenly spaced
/// parameters; around every sample nearer than both its neighbours (the domain's
/// ends included) the squared distance is minimised by golden-section search over
/// the two neighbouring sample intervals, to the resolution of a double; the nearest
/// point found wins, so the result is never farther than any sample. target must
/// be finite (kNotFinite).
/// Cost O(spans * order^3) evaluations in the worst case, no allocation.
ToolResult<ClosestPoint> closestPoint(const CurveRef& curve, const Point3& target);

} // namespace q3::nurbs
