// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/Derivatives.h"

#include "CurveToolsTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace q3::nurbs {
namespace {

using test::TestCurve;

double norm(const Point3& p)
{
    return std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
}

double difference(const Point3& a, const Point3& b)
{
    return test::distance3(a, b);
}

// A circular arc of radius r and angle 2 theta as the article builds it (section
// "CONIC SECTIONS", Listing 3's knots): isosceles control triangle, inner weight
// cos(theta), stored homogeneous.
TestCurve circularArc(double r, double theta)
{
    const double w = std::cos(theta);
    const double apex = r / std::cos(theta);
    return test::makeCurve(3,
                           {float(r * std::cos(-theta)), float(r * std::sin(-theta)), 0, 1,
                            float(apex * w), 0, 0, float(w),
                            float(r * std::cos(theta)), float(r * std::sin(theta)), 0, 1},
                           {0, 0, 0, 1, 1, 1});
}

TEST(NurbsDerivatives, MatchFiniteDifferencesOfTheReferenceOnRandomCurvesOfEveryOrder)
{
    // Fourth-order differences with h = 1e-3 of the span width are accurate to about
    // 1e-11 of the derivatives' size for these curves; 1e-6 leaves a wide margin.
    std::mt19937 rng(61);
    for (int trial = 0; trial < 300; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 3 != 0, 0.3, 8});
        const test::SpanParameter at = test::randomInsideSpan(rng, curve);
        const double h = 1e-3 * (at.b - at.a);
        Point3 first, second;
        test::referenceDerivatives(curve, at.t, h, first, second);
        const CurveDerivatives d = evaluateDerivatives(curve.ref(), at.t);
        EXPECT_LE(difference(d.point, test::referencePoint3(curve, at.t)), 1e-12 * test::curveScale(curve));
        EXPECT_LE(difference(d.first, first), 1e-6 * (norm(first) + test::curveScale(curve)))
            << "order " << k << " t " << at.t;
        EXPECT_LE(difference(d.second, second), 1e-5 * (norm(second) + norm(first) + test::curveScale(curve)))
            << "order " << k << " t " << at.t;
    }
}

TEST(NurbsDerivatives, CurvatureOfTheArticlesCircularArcsIsOneOverTheRadius)
{
    for (double r : {0.5, 1.0, 3.0, 100.0}) {
        for (double degrees : {30.0, 45.0, 60.0, 80.0}) {
            const TestCurve arc = circularArc(r, degrees * std::acos(-1.0) / 180.0);
            for (int s = 0; s <= 20; ++s) {
                const double t = s / 20.0;
                const ToolResult<double> kappa = curvatureAt(arc.ref(), t);
                ASSERT_TRUE(kappa.ok()) << kappa.message;
                // The float control points put the arc within ~1e-7 of a true circle.
                EXPECT_NEAR(kappa.value * r, 1.0, 2e-6) << "r " << r << " angle " << degrees << " t " << t;
                const ToolResult<Point3> tangent = tangentAt(arc.ref(), t);
                ASSERT_TRUE(tangent.ok());
                EXPECT_NEAR(norm(tangent.value), 1.0, 1e-12);
                const Point3 p = evaluateDerivatives(arc.ref(), t).point;
                EXPECT_NEAR(p.x * tangent.value.x + p.y * tangent.value.y, 0.0, 1e-6 * r)
                    << "a circle's tangent is perpendicular to its radius";
            }
        }
    }
}

TEST(NurbsDerivatives, DerivativesAtKnotsAreOneSided)
{
    // Figure 15's kink: order 3 with the knot 3 doubled; left of it the curve heads
    // into B2, right of it away.
    const TestCurve curve = test::makeCurve(
        3, {0, 0.5f, 0, 1, 1.5f, 3.5f, 0, 1, 3, 0.5f, 0, 1, 4.5f, 3, 0, 1, 6, 1, 0, 1}, {0, 1, 2, 3, 3, 5, 6, 7});
    const CurveDerivatives at = evaluateDerivatives(curve.ref(), 3.0);
    const CurveDerivatives after = evaluateDerivatives(curve.ref(), 3.0 + 1e-9);
    EXPECT_LE(difference(at.first, after.first), 1e-6 * norm(at.first));
    const CurveDerivatives atEnd = evaluateDerivatives(curve.ref(), 5.0);
    const CurveDerivatives before = evaluateDerivatives(curve.ref(), 5.0 - 1e-9);
    EXPECT_LE(difference(atEnd.first, before.first), 1e-6 * norm(atEnd.first));
}

TEST(NurbsDerivatives, CheckedFormsRejectBadParametersAndZeroDerivatives)
{
    const TestCurve curve = test::listingOneCurve();
    EXPECT_EQ(positionAt(curve.ref(), std::nan("")).error, ToolError::kNotFinite);
    EXPECT_EQ(derivativesAt(curve.ref(), INFINITY).error, ToolError::kNotFinite);
    EXPECT_EQ(tangentAt(curve.ref(), -INFINITY).error, ToolError::kNotFinite);
    EXPECT_EQ(curvatureAt(curve.ref(), 1.0000001).error, ToolError::kOutOfRange);
    EXPECT_EQ(positionAt(curve.ref(), -1e-9).error, ToolError::kOutOfRange);
    EXPECT_TRUE(positionAt(curve.ref(), 0.0).ok());
    EXPECT_TRUE(positionAt(curve.ref(), 1.0).ok());

    // Two equal control points at the start: the cubic starts with zero speed.
    const TestCurve stalled =
        test::makeCurve(4, {0, 0, 0, 1, 0, 0, 0, 1, 2, 0, 0, 1, 3, 1, 0, 1}, {0, 0, 0, 0, 1, 1, 1, 1});
    EXPECT_EQ(tangentAt(stalled.ref(), 0.0).error, ToolError::kZeroDerivative);
    EXPECT_EQ(curvatureAt(stalled.ref(), 0.0).error, ToolError::kZeroDerivative);
    EXPECT_FALSE(tangentAt(stalled.ref(), 0.0).message.empty());
    EXPECT_TRUE(tangentAt(stalled.ref(), 0.5).ok());
}

} // namespace
} // namespace q3::nurbs
