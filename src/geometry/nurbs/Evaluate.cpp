// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Point evaluation by de Boor's algorithm and the basis functions by Cox-de Boor.
//
// de Boor: lecture 6, eqs. 6.27-6.30. For t in span [x_l, x_{l+1}) only the k
// control points P_{l-k+1} .. P_l are involved; starting from P_i^0 = P_i (6.28) the
// recursion P_i^j = (1 - a_i^j) P_{i-1}^{j-1} + a_i^j P_i^{j-1} with
// a_i^j = (t - x_i) / (x_{i+k-j} - x_i) (6.29-6.30) runs k-1 levels and leaves the
// curve point. It is applied to the homogeneous (x, y, z, w) points, so the rational
// curve is the projection of the result (article, "RATIONAL CURVES").
//
// The derivative comes from the same triangle: the last step is a linear
// interpolation between the two level-(k-2) points over [x_l, x_{l+1}], and the
// derivative of the homogeneous curve is (k-1) times their difference over
// x_{l+1} - x_l, which is lecture eqs. 6.23-6.24 applied to the de Boor points of
// the span. The rational tangent follows from the quotient rule.
//
// The basis function is the article's recursion (section "DEFINING THE BASIS
// FUNCTIONS", also lecture eqs. 6.5-6.6), computed bottom-up as a triangle.

#include "geometry/nurbs/Evaluate.h"

#include "geometry/nurbs/Knots.h"

namespace q3::nurbs {
namespace {

inline Point4 lerp(const Point4& a, const Point4& b, double alpha)
{
    const double beta = 1.0 - alpha;
    return Point4{beta * a.x + alpha * b.x, beta * a.y + alpha * b.y,
                  beta * a.z + alpha * b.z, beta * a.w + alpha * b.w};
}

// Runs de Boor's triangle for span l at t and returns the curve point. When
// lastLeft is given, the two points the final step interpolates between (level k-2)
// are stored in lastLeft and lastRight.
template <typename KnotAt, typename PointAt>
Point4 deBoor(unsigned k, std::size_t l, KnotAt knot, PointAt point, double t,
              Point4* lastLeft, Point4* lastRight)
{
    Point4 d[kMaxOrder];
    const unsigned deg = k - 1;
    for (unsigned j = 0; j <= deg; ++j) {
        d[j] = point(l - deg + j);
    }
    for (unsigned r = 1; r <= deg; ++r) {
        if (r == deg && lastLeft != nullptr) {
            *lastLeft = d[deg - 1];
            *lastRight = d[deg];
        }
        for (unsigned j = deg; j >= r; --j) {
            const double lo = knot(l - deg + j);
            const double hi = knot(l + 1 + j - r);
            d[j] = lerp(d[j - 1], d[j], (t - lo) / (hi - lo));
        }
    }
    return d[deg];
}

CurvePoint finish(const Point4& h)
{
    return CurvePoint{h, project(h)};
}

} // namespace

CurvePoint evaluate(const CurveRef& curve, double t)
{
    t = clampToDomain(curveDomain(curve), t);
    const std::size_t l = findSpan(curve, t);
    const float* x = curve.knots;
    const float* p = curve.points;
    return finish(deBoor(
        curve.order, l, [x](std::size_t i) { return double(x[i]); },
        [p](std::size_t i) { return Point4{p[4 * i], p[4 * i + 1], p[4 * i + 2], p[4 * i + 3]}; }, t,
        nullptr, nullptr));
}

CurvePoint evaluate(const HomogeneousCurve& curve, double t)
{
    const std::size_t n = curve.points.size();
    t = clampToDomain(Domain{curve.knots[curve.order - 1], curve.knots[n]}, t);
    const std::size_t l = findSpan(curve, t);
    const double* x = curve.knots.data();
    const Point4* p = curve.points.data();
    return finish(deBoor(
        curve.order, l, [x](std::size_t i) { return x[i]; }, [p](std::size_t i) { return p[i]; }, t,
        nullptr, nullptr));
}

CurvePointDerivative evaluateWithDerivative(const CurveRef& curve, double t)
{
    t = clampToDomain(curveDomain(curve), t);
    const std::size_t l = findSpan(curve, t);
    const float* x = curve.knots;
    const float* p = curve.points;
    Point4 left;
    Point4 right;
    const Point4 h = deBoor(
        curve.order, l, [x](std::size_t i) { return double(x[i]); },
        [p](std::size_t i) { return Point4{p[4 * i], p[4 * i + 1], p[4 * i + 2], p[4 * i + 3]}; }, t,
        &left, &right);
    const double scale = double(curve.order - 1) / (double(x[l + 1]) - double(x[l]));
    const Point4 dh{scale * (right.x - left.x), scale * (right.y - left.y),
                    scale * (right.z - left.z), scale * (right.w - left.w)};
    CurvePointDerivative result;
    result.homogeneous = h;
    result.homogeneousDerivative = dh;
    result.point = project(h);
    result.tangent = Point3{(dh.x - result.point.x * dh.w) / h.w, (dh.y - result.point.y * dh.w) / h.w,
                            (dh.z - result.point.z * dh.w) / h.w};
    return result;
}

double basisFunction(const float* knots, std::size_t numPoints, unsigned order, std::size_t i, double t)
{
    // N[j] holds N_{i+j, level}; the order-1 functions first.
    double N[kMaxOrder + 1];
    const double end = knots[numPoints];
    std::size_t lastSpan = numPoints - 1;
    while (!(double(knots[lastSpan]) < end)) {
        --lastSpan;
    }
    for (unsigned j = 0; j < order; ++j) {
        const std::size_t m = i + j;
        const bool inside = double(knots[m]) <= t && t < double(knots[m + 1]);
        N[j] = (t == end ? m == lastSpan : inside) ? 1.0 : 0.0;
    }
    for (unsigned level = 2; level <= order; ++level) {
        for (unsigned j = 0; j + level <= order; ++j) {
            const std::size_t m = i + j;
            const double a0 = knots[m];
            const double a1 = knots[m + level - 1];
            const double b0 = knots[m + 1];
            const double b1 = knots[m + level];
            const double left = a1 > a0 ? (t - a0) / (a1 - a0) * N[j] : 0.0;
            const double right = b1 > b0 ? (b1 - t) / (b1 - b0) * N[j + 1] : 0.0;
            N[j] = left + right;
        }
    }
    return N[0];
}

} // namespace q3::nurbs
