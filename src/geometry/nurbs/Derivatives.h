// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"
#include "geometry/nurbs/ToolResult.h"

namespace q3::nurbs {

/// The point of a curve and its first two derivatives with respect to t, of the
/// projected (rational) curve.
struct CurveDerivatives {
    Point3 point;
    Point3 first;
    Point3 second;
    /// The size of the rounding error first carries: below about 1e-12 of this, a
    /// first derivative cannot be told from zero (order times the largest local control
    /// point coordinate over the span's width).
    double firstScale = 0.0;
};

/// Evaluates a valid curve and its first two derivatives at t, in double. t is
/// clamped to the domain (NaN counts as its start). At a knot the span to the right
/// is used (right-hand derivatives), at the domain end the last span (left-hand).
/// Cost O(order^2), no allocation. Errors: none; requires a valid curve.
CurveDerivatives evaluateDerivatives(const CurveRef& curve, double t);
CurveDerivatives evaluateDerivatives(const HomogeneousCurve& curve, double t);

/// The checked forms behind the C calls: t must be finite (kNotFinite) and inside
/// the closed domain (kOutOfRange). Tangent and curvature also fail with
/// kZeroDerivative where the first derivative is zero (below 1e-12 of firstScale).
ToolResult<Point3> positionAt(const CurveRef& curve, double t);
ToolResult<CurveDerivatives> derivativesAt(const CurveRef& curve, double t);
/// The unit tangent C'/|C'|.
ToolResult<Point3> tangentAt(const CurveRef& curve, double t);
/// The curvature |C' x C''| / |C'|^3 (1/radius of the osculating circle).
ToolResult<double> curvatureAt(const CurveRef& curve, double t);

} // namespace q3::nurbs
