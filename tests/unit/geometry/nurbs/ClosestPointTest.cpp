// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/ClosestPoint.h"

#include "CurveToolsTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>

namespace q3::nurbs {
namespace {

using test::TestCurve;

TEST(NurbsClosestPoint, IsNoFartherThanAnySampledPoint)
{
    std::mt19937 rng(79);
    std::uniform_real_distribution<double> coordinate(-15.0, 15.0);
    for (int trial = 0; trial < 150; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.3, 8});
        const Point3 target{coordinate(rng), coordinate(rng), coordinate(rng)};
        const ToolResult<ClosestPoint> found = closestPoint(curve.ref(), target);
        ASSERT_TRUE(found.ok()) << found.message;
        EXPECT_GE(found.value.t, curve.domainStart());
        EXPECT_LE(found.value.t, curve.domainEnd());
        const Point3 on = test::referencePoint3(curve, found.value.t);
        EXPECT_LE(test::distance3(on, found.value.point), 1e-9 * test::curveScale(curve));
        EXPECT_NEAR(test::distance3(on, target), found.value.distance, 1e-9 * test::curveScale(curve));
        double nearestSample = INFINITY;
        const int samples = 3000;
        for (int s = 0; s <= samples; ++s) {
            const double t = curve.domainStart() + (curve.domainEnd() - curve.domainStart()) * s / samples;
            nearestSample = std::min(nearestSample, test::distance3(test::referencePoint3(curve, t), target));
        }
        EXPECT_LE(found.value.distance, nearestSample + 1e-9 * test::curveScale(curve)) << "order " << k;
    }
}

TEST(NurbsClosestPoint, FindsTheFootOfThePerpendicularOnACircle)
{
    const float w = float(std::sqrt(0.5));
    const TestCurve quarter =
        test::makeCurve(3, {1, 0, 0, 1, w, w, 0, w, 0, 1, 0, 1}, {0, 0, 0, 1, 1, 1});
    const ToolResult<ClosestPoint> found = closestPoint(quarter.ref(), Point3{3.0, 3.0, 0.5});
    ASSERT_TRUE(found.ok());
    EXPECT_NEAR(found.value.point.x, std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(found.value.point.y, std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(found.value.t, 0.5, 1e-6);
    // Beyond the arc's end the end point is nearest.
    EXPECT_EQ(closestPoint(quarter.ref(), Point3{5.0, -1.0, 0.0}).value.t, 0.0);
    EXPECT_EQ(closestPoint(quarter.ref(), Point3{-1.0, 5.0, 0.0}).value.t, 1.0);
}

TEST(NurbsClosestPoint, RejectsATargetThatIsNotFinite)
{
    const TestCurve curve = test::listingOneCurve();
    EXPECT_EQ(closestPoint(curve.ref(), Point3{std::nan(""), 0, 0}).error, ToolError::kNotFinite);
    EXPECT_EQ(closestPoint(curve.ref(), Point3{0, INFINITY, 0}).error, ToolError::kNotFinite);
    EXPECT_EQ(closestPoint(curve.ref(), Point3{0, 0, -INFINITY}).error, ToolError::kNotFinite);
}

} // namespace
} // namespace q3::nurbs
