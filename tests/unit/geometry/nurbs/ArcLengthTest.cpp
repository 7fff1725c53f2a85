// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/ArcLength.h"

#include "CurveToolsTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>

namespace q3::nurbs {
namespace {

using test::TestCurve;

// The reference length: polylines through the reference evaluator with m and 2m
// segments per span, Richardson-extrapolated (a polyline's error falls as h^2 on
// smooth spans, so 4 P(2m)/3 - P(m)/3 is accurate to O(h^4)).
double polylineLength(const TestCurve& c, double t0, double t1, int perSpan)
{
    double length = 0.0;
    for (std::size_t l = c.order - 1; l < c.numPoints(); ++l) {
        const double a = std::max(double(c.knots[l]), t0);
        const double b = std::min(double(c.knots[l + 1]), t1);
        if (!(a < b))
            continue;
        Point3 previous = test::referencePoint3(c, a);
        for (int s = 1; s <= perSpan; ++s) {
            const Point3 next = test::referencePoint3(c, a + (b - a) * s / perSpan);
            length += test::distance3(previous, next);
            previous = next;
        }
    }
    return length;
}

double referenceLength(const TestCurve& c, double t0, double t1)
{
    const double coarse = polylineLength(c, t0, t1, 400);
    const double fine = polylineLength(c, t0, t1, 800);
    return fine + (fine - coarse) / 3.0;
}

TEST(NurbsArcLength, MatchesAFinePolylineWithinTheTolerance)
{
    std::mt19937 rng(71);
    for (int trial = 0; trial < 60; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.2, 4});
        std::uniform_real_distribution<double> in(curve.domainStart(), curve.domainEnd());
        double t0 = in(rng);
        double t1 = in(rng);
        if (t0 > t1)
            std::swap(t0, t1);
        if (trial % 4 == 0) {
            t0 = curve.domainStart();
            t1 = curve.domainEnd();
        }
        const double reference = referenceLength(curve, t0, t1);
        const double tolerance = 1e-6 * reference;
        const ToolResult<double> length = arcLength(curve.ref(), t0, t1, tolerance);
        ASSERT_TRUE(length.ok()) << length.message;
        EXPECT_TRUE(length.warning.empty()) << length.warning;
        EXPECT_NEAR(length.value, reference, tolerance) << "order " << k;
    }
}

TEST(NurbsArcLength, AQuarterCircleHasLengthPiROverTwo)
{
    // Lecture 6.8.2's quarter circle: (R, 0), (R, R) with weight sqrt(2)/2, (0, R).
    const double R = 2.0;
    const float w = float(std::sqrt(0.5));
    const TestCurve arc = test::makeCurve(3, {float(R), 0, 0, 1, float(R) * w, float(R) * w, 0, w, 0, float(R), 0, 1},
                                          {0, 0, 0, 1, 1, 1});
    const ToolResult<double> length = arcLength(arc.ref(), 0.0, 1.0, 1e-10);
    ASSERT_TRUE(length.ok());
    // The float weight moves the arc off the circle by ~1e-8 of R.
    EXPECT_NEAR(length.value, std::acos(-1.0) * R / 2.0, 1e-7);
}

TEST(NurbsArcLength, ParameterAtLengthInvertsArcLength)
{
    std::mt19937 rng(73);
    for (int trial = 0; trial < 60; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.2, 6});
        const double t0 = trial % 3 == 0 ? curve.domainStart()
                                         : std::uniform_real_distribution<double>(curve.domainStart(),
                                                                                  curve.domainEnd())(rng);
        const double total = arcLength(curve.ref(), t0, curve.domainEnd(), 1e-9).value;
        const double tolerance = 1e-6 * (total + 1.0);
        for (double fraction : {0.0, 0.1, 0.5, 0.9, 1.0}) {
            const double wanted = fraction * total;
            const ToolResult<double> t = parameterAtLength(curve.ref(), t0, wanted, tolerance);
            ASSERT_TRUE(t.ok()) << t.message;
            EXPECT_TRUE(t.warning.empty()) << t.warning;
            EXPECT_GE(t.value, t0);
            EXPECT_LE(t.value, curve.domainEnd());
            EXPECT_NEAR(arcLength(curve.ref(), t0, t.value, 1e-3 * tolerance).value, wanted, 1.01 * tolerance)
                << "order " << k << " fraction " << fraction;
        }
        EXPECT_EQ(parameterAtLength(curve.ref(), t0, total + 2 * tolerance + 1e-9 * total, tolerance).error,
                  ToolError::kOutOfRange);
    }
}

TEST(NurbsArcLength, RejectsBadRangesAndTolerances)
{
    const TestCurve curve = test::listingOneCurve();
    EXPECT_EQ(arcLength(curve.ref(), 0.5, 0.25, 1e-6).error, ToolError::kInvalidArgument);
    EXPECT_EQ(arcLength(curve.ref(), -0.5, 0.25, 1e-6).error, ToolError::kOutOfRange);
    EXPECT_EQ(arcLength(curve.ref(), 0.0, 1.5, 1e-6).error, ToolError::kOutOfRange);
    EXPECT_EQ(arcLength(curve.ref(), std::nan(""), 1.0, 1e-6).error, ToolError::kNotFinite);
    EXPECT_EQ(arcLength(curve.ref(), 0.0, 1.0, 0.0).error, ToolError::kInvalidArgument);
    EXPECT_EQ(arcLength(curve.ref(), 0.0, 1.0, -1.0).error, ToolError::kInvalidArgument);
    EXPECT_EQ(arcLength(curve.ref(), 0.0, 1.0, INFINITY).error, ToolError::kNotFinite);
    EXPECT_EQ(arcLength(curve.ref(), 0.5, 0.5, 1e-6).value, 0.0);
    EXPECT_EQ(parameterAtLength(curve.ref(), 0.0, -1.0, 1e-6).error, ToolError::kOutOfRange);
    EXPECT_EQ(parameterAtLength(curve.ref(), 0.0, std::nan(""), 1e-6).error, ToolError::kNotFinite);
    EXPECT_EQ(parameterAtLength(curve.ref(), 0.0, 100.0, 1e-6).error, ToolError::kOutOfRange);
    EXPECT_EQ(parameterAtLength(curve.ref(), 0.3, 0.0, 1e-6).value, 0.3);
}

TEST(NurbsArcLength, ChecksBothParametersForBeingFiniteBeforeEitherForTheDomain)
{
    // The header's order: t0 or t1 not finite, then t0 or t1 outside, then the tolerance.
    const TestCurve curve = test::listingOneCurve();
    EXPECT_EQ(arcLength(curve.ref(), -0.5, std::nan(""), 1e-6).error, ToolError::kNotFinite);
    EXPECT_EQ(arcLength(curve.ref(), 1.5, INFINITY, 1e-6).error, ToolError::kNotFinite);
    EXPECT_EQ(arcLength(curve.ref(), std::nan(""), 1.5, 1e-6).error, ToolError::kNotFinite);
    EXPECT_EQ(arcLength(curve.ref(), -0.5, 1.0, std::nan("")).error, ToolError::kOutOfRange);
    EXPECT_EQ(arcLength(curve.ref(), 0.0, 1.5, 0.0).error, ToolError::kOutOfRange);
}

TEST(NurbsArcLength, AnUnreachableToleranceEndsAtTheCapWithAWarning)
{
    // A cubic with a cusp at t = 0.5: C'(t) = 3((1 - 2t)^2, 1 - 2t). Its speed has a
    // kink there, which no bisection of [0, 0.9] lands on, so 1e-300 is out of reach.
    const TestCurve cusp =
        test::makeCurve(4, {0, 0, 0, 1, 1, 1, 0, 1, 0, 1, 0, 1, 1, 0, 0, 1}, {0, 0, 0, 0, 1, 1, 1, 1});
    const ToolResult<double> length = arcLength(cusp.ref(), 0.0, 0.9, 1e-300);
    ASSERT_TRUE(length.ok());
    EXPECT_FALSE(length.warning.empty());
    EXPECT_NEAR(length.value, arcLength(cusp.ref(), 0.0, 0.9, 1e-9).value, 1e-8);
}

} // namespace
} // namespace q3::nurbs
