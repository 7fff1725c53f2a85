// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Test-only helpers: random curves and a reference evaluator that shares no code
// with the library (a literal bottom-up Cox-de Boor recursion over the whole knot
// vector, with its own span search).

#include "geometry/nurbs/Curve.h"
#include "geometry/nurbs/Knots.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace q3::nurbs::test {

/// Owns the arrays a CurveRef points at.
struct TestCurve {
    unsigned order = 0;
    std::vector<float> points;  // 4 per point, homogeneous
    std::vector<float> knots;

    std::size_t numPoints() const { return points.size() / 4; }
    CurveRef ref() const { return CurveRef{order, numPoints(), points.data(), knots.data()}; }
    double domainStart() const { return knots[order - 1]; }
    double domainEnd() const { return knots[numPoints()]; }
};

inline TestCurve makeCurve(unsigned order, std::vector<float> points, std::vector<float> knots)
{
    return TestCurve{order, std::move(points), std::move(knots)};
}

/// Listing 1 of the article: the cubic Bezier curve (0,0),(1,1),(2,0),(3,1).
inline TestCurve listingOneCurve()
{
    return makeCurve(4, {0, 0, 0, 1, 1, 1, 0, 1, 2, 0, 0, 1, 3, 1, 0, 1}, {0, 0, 0, 0, 1, 1, 1, 1});
}

struct RandomCurveOptions {
    bool clamped = true;
    double repeatProbability = 0.0;  // chance that an interior knot repeats its predecessor
    std::size_t extraPoints = 12;    // numPoints is order + uniform(0, extraPoints)
};

/// A random valid curve: coordinates in [-10, 10], weights in [0.25, 4], knot runs at
/// most order-1 inside and order at clamped ends.
inline TestCurve randomCurve(std::mt19937& rng, unsigned order, const RandomCurveOptions& options)
{
    std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
    std::uniform_real_distribution<double> logWeight(std::log(0.25), std::log(4.0));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<std::size_t> extra(0, options.extraPoints);
    for (;;) {
        TestCurve curve;
        curve.order = order;
        const std::size_t n = order + extra(rng);
        for (std::size_t i = 0; i < n; ++i) {
            const double w = std::exp(logWeight(rng));
            curve.points.push_back(float(coordinate(rng) * w));
            curve.points.push_back(float(coordinate(rng) * w));
            curve.points.push_back(float(coordinate(rng) * w));
            curve.points.push_back(float(w));
        }
        const std::size_t numKnots = n + order;
        std::vector<double> x(numKnots);
        double value = std::floor(coordinate(rng));
        std::size_t run = 1;
        x[0] = value;
        for (std::size_t i = 1; i < numKnots; ++i) {
            const bool clampedEnd = options.clamped && (i < order || i > n);
            const bool startsEnd = options.clamped && i == n;
            const bool repeat =
                clampedEnd || (!startsEnd && run < order - 1 && unit(rng) < options.repeatProbability);
            if (repeat) {
                ++run;
            } else {
                value += 0.125 + 1.5 * unit(rng);
                run = 1;
            }
            x[i] = value;
        }
        for (double v : x) {
            curve.knots.push_back(float(v));
        }
        if (validateCurve(curve.ref()).ok()) {
            return curve;
        }
    }
}

/// The homogeneous curve point by the Cox-de Boor recursion over every basis function.
/// t must lie in the domain; at its end the left limit is taken.
inline Point4 referencePoint(const TestCurve& curve, double t)
{
    const unsigned k = curve.order;
    const std::size_t n = curve.numPoints();
    const std::size_t count = n + k;
    std::vector<double> x(curve.knots.begin(), curve.knots.end());
    std::size_t span = 0;
    bool found = false;
    for (std::size_t i = k - 1; i < n; ++i) {
        if (x[i] <= t && t < x[i + 1]) {
            span = i;
            found = true;
        }
    }
    if (!found) {
        for (std::size_t i = k - 1; i < n; ++i) {
            if (x[i] < x[i + 1]) {
                span = i;
            }
        }
    }
    std::vector<double> N(count - 1, 0.0);
    N[span] = 1.0;
    for (unsigned level = 2; level <= k; ++level) {
        for (std::size_t i = 0; i + level < count; ++i) {
            double value = 0.0;
            if (x[i + level - 1] != x[i]) {
                value += (t - x[i]) / (x[i + level - 1] - x[i]) * N[i];
            }
            if (x[i + level] != x[i + 1]) {
                value += (x[i + level] - t) / (x[i + level] - x[i + 1]) * N[i + 1];
            }
            N[i] = value;
        }
    }
    Point4 sum;
    for (std::size_t i = 0; i < n; ++i) {
        const float* p = &curve.points[4 * i];
        sum.x += N[i] * p[0];
        sum.y += N[i] * p[1];
        sum.z += N[i] * p[2];
        sum.w += N[i] * p[3];
    }
    return sum;
}

inline Point3 referencePoint3(const TestCurve& curve, double t)
{
    const Point4 h = referencePoint(curve, t);
    return Point3{h.x / h.w, h.y / h.w, h.z / h.w};
}

/// Largest absolute projected control point coordinate: the scale errors are relative to.
inline double curveScale(const TestCurve& curve)
{
    double scale = 1.0;
    for (std::size_t i = 0; i < curve.numPoints(); ++i) {
        const float* p = &curve.points[4 * i];
        for (int c = 0; c < 3; ++c) {
            scale = std::max(scale, std::fabs(double(p[c]) / double(p[3])));
        }
    }
    return scale;
}

inline double distance3(const Point3& a, const Point3& b)
{
    return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

} // namespace q3::nurbs::test
