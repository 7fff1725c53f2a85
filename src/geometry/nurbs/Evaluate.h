// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"

#include <cstddef>

namespace q3::nurbs {

/// A point on a curve: the homogeneous sum and its projection.
struct CurvePoint {
    Point4 homogeneous;
    Point3 point;
};

/// A point and the first derivative with respect to t.
struct CurvePointDerivative {
    Point4 homogeneous;
    Point4 homogeneousDerivative;
    Point3 point;
    Point3 tangent;  ///< d(point)/dt, the derivative of the projected (rational) curve
};

/// Evaluates a valid curve at t with de Boor's algorithm on the homogeneous control
/// points, in double. t is clamped to the domain (NaN counts as its start); at a
/// knot the span to the right is used, at the domain end the last span.
/// Cost O(order^2), no allocation. Errors: none; requires a valid curve.
CurvePoint evaluate(const CurveRef& curve, double t);
CurvePoint evaluate(const HomogeneousCurve& curve, double t);

/// As evaluate(), plus the derivative. At a knot where the curve is not C1 this is
/// the right-hand derivative (the left-hand one at the domain end).
CurvePointDerivative evaluateWithDerivative(const CurveRef& curve, double t);

/// The B-spline basis function N_{i,k}(t) by the Cox-de Boor recursion, with
/// 0/0 taken as 0. The order-1 functions are 1 on [x_i, x_{i+1}); so that the
/// functions sum to 1 on the whole closed domain, at t == x_n (the domain end) only the
/// order-1 function of the last non-empty span is 1 (the limit from the left).
/// Requires a valid knot vector of numPoints + order knots and i < numPoints.
/// Cost O(order^2).
double basisFunction(const float* knots, std::size_t numPoints, unsigned order, std::size_t i, double t);

} // namespace q3::nurbs
