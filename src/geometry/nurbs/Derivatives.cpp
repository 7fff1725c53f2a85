// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// First and second derivatives of a curve.
//
// The derivative of a B-spline of order k is a B-spline of order k-1 on the same
// knots (lecture 6, eqs. 6.23-6.24): P'(t) = sum_i d_i N_{i,k-1}(t) with
// d_i = (k-1) (P_i - P_{i-1}) / (x_{i+k-1} - x_i). Applying the rule twice on the k
// control points of the span holding t gives the k-1 first-derivative and k-2
// second-derivative control points of that span; de Boor's algorithm (lecture eqs.
// 6.28-6.30, with the order lowered accordingly) evaluates all three. Every
// denominator is at least the span's width, so nothing divides by zero.
//
// The rules apply to the homogeneous curve A(t) = (wx, wy, wz, w). The rational
// curve C = A/w then follows from the quotient rule (Piegl & Tiller, The NURBS
// Book, eq. 4.8): C' = (A' - w' C) / w and C'' = (A'' - 2 w' C' - w'' C) / w.
// Curvature is |C' x C''| / |C'|^3.

#include "geometry/nurbs/Derivatives.h"

#include "geometry/nurbs/CurveAccess.h"
#include "geometry/nurbs/Evaluate.h"
#include "geometry/nurbs/Knots.h"

#include <algorithm>
#include <cmath>

namespace q3::nurbs {
namespace {

// de Boor on q + 1 local points of degree q, Q[j] standing for index l - q + j, at t
// in span l. Overwrites Q; returns the curve point.
template <class Curve>
Point4 deBoorLocal(const Curve& c, Point4* Q, unsigned q, std::size_t l, double t)
{
    for (unsigned r = 1; r <= q; ++r) {
        for (unsigned j = q; j >= r; --j) {
            const std::size_t i = l - q + j;
            const double lo = access::knot(c, i);
            const double hi = access::knot(c, i + q + 1 - r);
            Q[j] = access::lerp(Q[j - 1], Q[j], (t - lo) / (hi - lo));
        }
    }
    return Q[q];
}

template <class Curve>
CurveDerivatives derivativesOf(const Curve& c, double t)
{
    const unsigned k = access::order(c);
    const unsigned p = k - 1;
    const std::size_t n = access::count(c);
    t = clampToDomain(Domain{access::knot(c, k - 1), access::knot(c, n)}, t);
    const std::size_t l = findSpan(c, t);

    Point4 P[kMaxOrder];
    Point4 D[kMaxOrder];
    Point4 E[kMaxOrder];
    double largest = 0.0;
    for (unsigned j = 0; j <= p; ++j) {
        P[j] = access::point(c, l - p + j);
        largest = std::max({largest, std::fabs(P[j].x / P[j].w), std::fabs(P[j].y / P[j].w),
                            std::fabs(P[j].z / P[j].w)});
    }
    // First-derivative points d_i, i = l-p+1 .. l, in D[0 .. p-1].
    for (unsigned j = 0; j < p; ++j) {
        const std::size_t i = l - p + 1 + j;
        const double width = access::knot(c, i + p) - access::knot(c, i);
        D[j] = access::scale(access::sub(P[j + 1], P[j]), double(p) / width);
    }
    // Second-derivative points, i = l-p+2 .. l, in E[0 .. p-2].
    for (unsigned j = 0; j + 1 < p; ++j) {
        const std::size_t i = l - p + 2 + j;
        const double width = access::knot(c, i + p - 1) - access::knot(c, i);
        E[j] = access::scale(access::sub(D[j + 1], D[j]), double(p - 1) / width);
    }
    const Point4 a0 = deBoorLocal(c, P, p, l, t);
    const Point4 a1 = deBoorLocal(c, D, p - 1, l, t);
    const Point4 a2 = p >= 2 ? deBoorLocal(c, E, p - 2, l, t) : Point4{};

    CurveDerivatives result;
    const double w = a0.w;
    result.point = Point3{a0.x / w, a0.y / w, a0.z / w};
    const Point3& C = result.point;
    result.first = Point3{(a1.x - a1.w * C.x) / w, (a1.y - a1.w * C.y) / w, (a1.z - a1.w * C.z) / w};
    const Point3& C1 = result.first;
    result.second = Point3{(a2.x - 2.0 * a1.w * C1.x - a2.w * C.x) / w,
                           (a2.y - 2.0 * a1.w * C1.y - a2.w * C.y) / w,
                           (a2.z - 2.0 * a1.w * C1.z - a2.w * C.z) / w};
    result.firstScale = double(p) * largest / (access::knot(c, l + 1) - access::knot(c, l));
    return result;
}

bool isZeroDerivative(const CurveDerivatives& d)
{
    return !(access::length3(d.first) > 1e-12 * d.firstScale);
}

std::string zeroDerivativeMessage(double t)
{
    return formatMessage("the first derivative at t = %.9g is zero, so the curve has no tangent "
                         "direction there",
                         t);
}

} // namespace

CurveDerivatives evaluateDerivatives(const CurveRef& curve, double t)
{
    return derivativesOf(curve, t);
}

CurveDerivatives evaluateDerivatives(const HomogeneousCurve& curve, double t)
{
    return derivativesOf(curve, t);
}

ToolResult<Point3> positionAt(const CurveRef& curve, double t)
{
    const ToolResult<double> checked = checkParameter(t, curveDomain(curve), false, "t");
    if (!checked.ok())
        return toolFailure<Point3>(checked);
    return toolValue(evaluate(curve, t).point);
}

ToolResult<CurveDerivatives> derivativesAt(const CurveRef& curve, double t)
{
    const ToolResult<double> checked = checkParameter(t, curveDomain(curve), false, "t");
    if (!checked.ok())
        return toolFailure<CurveDerivatives>(checked);
    return toolValue(evaluateDerivatives(curve, t));
}

ToolResult<Point3> tangentAt(const CurveRef& curve, double t)
{
    const ToolResult<CurveDerivatives> d = derivativesAt(curve, t);
    if (!d.ok())
        return toolFailure<Point3>(d);
    if (isZeroDerivative(d.value))
        return toolFailure<Point3>(ToolError::kZeroDerivative, zeroDerivativeMessage(t));
    const Point3& v = d.value.first;
    const double length = access::length3(v);
    return toolValue(Point3{v.x / length, v.y / length, v.z / length});
}

ToolResult<double> curvatureAt(const CurveRef& curve, double t)
{
    const ToolResult<CurveDerivatives> d = derivativesAt(curve, t);
    if (!d.ok())
        return toolFailure<double>(d);
    if (isZeroDerivative(d.value))
        return toolFailure<double>(ToolError::kZeroDerivative, zeroDerivativeMessage(t));
    const double speed = access::length3(d.value.first);
    return toolValue(access::length3(access::cross3(d.value.first, d.value.second)) /
                     (speed * speed * speed));
}

} // namespace q3::nurbs
