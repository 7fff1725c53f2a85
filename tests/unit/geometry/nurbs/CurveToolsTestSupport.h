// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Helpers for the curve-tool tests: a double-precision reference evaluator for the
// library's HomogeneousCurve results (the same literal Cox-de Boor recursion as
// NurbsTestSupport.h's, sharing no code with the library), finite differences of
// it, and shape comparisons by dense sampling.

#include "NurbsTestSupport.h"

#include "geometry/nurbs/Curve.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace q3::nurbs::test {

/// The homogeneous point of (order, knots, points) at t, t in the domain (left limit
/// at its end), by the Cox-de Boor recursion over every basis function.
inline Point4 referenceHomogeneous(unsigned k, const std::vector<double>& x, const std::vector<Point4>& P,
                                   double t)
{
    const std::size_t n = P.size();
    std::size_t span = k - 1;
    for (std::size_t i = k - 1; i < n; ++i)
        if (x[i] < x[i + 1] && x[i] <= t)
            span = i;
    std::vector<double> N(x.size() - 1, 0.0);
    N[span] = 1.0;
    for (unsigned level = 2; level <= k; ++level) {
        for (std::size_t i = 0; i + level < x.size(); ++i) {
            double value = 0.0;
            if (x[i + level - 1] != x[i])
                value += (t - x[i]) / (x[i + level - 1] - x[i]) * N[i];
            if (x[i + level] != x[i + 1])
                value += (x[i + level] - t) / (x[i + level] - x[i + 1]) * N[i + 1];
            N[i] = value;
        }
    }
    Point4 sum;
    for (std::size_t i = 0; i < n; ++i) {
        sum.x += N[i] * P[i].x;
        sum.y += N[i] * P[i].y;
        sum.z += N[i] * P[i].z;
        sum.w += N[i] * P[i].w;
    }
    return sum;
}

inline Point3 referencePoint3(const HomogeneousCurve& c, double t)
{
    const Point4 h = referenceHomogeneous(c.order, c.knots, c.points, t);
    return Point3{h.x / h.w, h.y / h.w, h.z / h.w};
}

/// The test curve as double arrays (plain copies, no library code).
inline HomogeneousCurve asHomogeneous(const TestCurve& curve)
{
    HomogeneousCurve h;
    h.order = curve.order;
    h.knots.assign(curve.knots.begin(), curve.knots.end());
    for (std::size_t i = 0; i < curve.numPoints(); ++i)
        h.points.push_back(Point4{curve.points[4 * i], curve.points[4 * i + 1], curve.points[4 * i + 2],
                                  curve.points[4 * i + 3]});
    return h;
}

/// The largest distance between the two curves at `samples` + 1 evenly spaced
/// parameters of [start, end] and at every knot of either inside it.
inline double maxDeviation(const TestCurve& original, const HomogeneousCurve& result, double start, double end,
                           int samples = 200)
{
    std::vector<double> ts;
    for (int s = 0; s <= samples; ++s)
        ts.push_back(start + (end - start) * s / samples);
    for (double knot : original.knots)
        if (knot >= start && knot <= end)
            ts.push_back(knot);
    for (double knot : result.knots)
        if (knot >= start && knot <= end)
            ts.push_back(knot);
    double worst = 0.0;
    for (double t : ts)
        worst = std::max(worst, distance3(referencePoint3(original, t), referencePoint3(result, t)));
    return worst;
}

/// Fourth-order central differences of the reference curve: the first and second
/// derivatives at t with step h.
inline void referenceDerivatives(const TestCurve& c, double t, double h, Point3& first, Point3& second)
{
    const Point3 m2 = referencePoint3(c, t - 2 * h);
    const Point3 m1 = referencePoint3(c, t - h);
    const Point3 p0 = referencePoint3(c, t);
    const Point3 p1 = referencePoint3(c, t + h);
    const Point3 p2 = referencePoint3(c, t + 2 * h);
    const auto d1 = [h](double a, double b, double p, double q) { return (a - 8 * b + 8 * p - q) / (12 * h); };
    const auto d2 = [h](double a, double b, double m, double p, double q) {
        return (-a + 16 * b - 30 * m + 16 * p - q) / (12 * h * h);
    };
    first = Point3{d1(m2.x, m1.x, p1.x, p2.x), d1(m2.y, m1.y, p1.y, p2.y), d1(m2.z, m1.z, p1.z, p2.z)};
    second = Point3{d2(m2.x, m1.x, p0.x, p1.x, p2.x), d2(m2.y, m1.y, p0.y, p1.y, p2.y),
                    d2(m2.z, m1.z, p0.z, p1.z, p2.z)};
}

/// A random parameter well inside a random non-empty span: (t, span start, span end).
struct SpanParameter {
    double t, a, b;
};
inline SpanParameter randomInsideSpan(std::mt19937& rng, const TestCurve& c, double margin = 0.1)
{
    std::vector<std::size_t> spans;
    for (std::size_t i = c.order - 1; i < c.numPoints(); ++i)
        if (c.knots[i] < c.knots[i + 1])
            spans.push_back(i);
    const std::size_t l = spans[std::uniform_int_distribution<std::size_t>(0, spans.size() - 1)(rng)];
    const double a = c.knots[l];
    const double b = c.knots[l + 1];
    const double f = std::uniform_real_distribution<double>(margin, 1.0 - margin)(rng);
    return SpanParameter{a + (b - a) * f, a, b};
}

} // namespace q3::nurbs::test
