// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"
#include "geometry/nurbs/ToolResult.h"

#include <cstddef>

namespace q3::nurbs {

/// Raises a valid curve's order by `times` (0 gives a clamped curve:
/// the curve itself if it is clamped already) without
/// changing its shape on the domain. The result is clamped: its knot vector starts
/// and ends with order + times copies of the domain's ends; each interior knot of
/// multiplicity m comes out with multiplicity m + times, so the curve keeps its
/// continuity at every knot. The order may not exceed kMaxOrder (kOutOfRange), nor
/// the result have more than kMaxToolPoints control points (kOutOfRange).
/// Cost O(result * order^2) time, O(result * order) memory.
ToolResult<HomogeneousCurve> elevateDegree(const CurveRef& curve, std::size_t times);

} // namespace q3::nurbs
