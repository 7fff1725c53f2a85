// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/DegreeElevation.h"

#include "CurveToolsTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace q3::nurbs {
namespace {

using test::TestCurve;

// Interior knot values (strictly inside [start, end]) and how often each occurs.
std::map<double, std::size_t> interiorMultiplicities(const std::vector<double>& knots, double start, double end)
{
    std::map<double, std::size_t> result;
    for (double x : knots)
        if (x > start && x < end)
            ++result[x];
    return result;
}

TEST(NurbsDegreeElevation, ElevationLeavesRandomCurvesOfEveryOrderUnchanged)
{
    // The joint knots are removed by exact formulas; in double the shapes agree to
    // about 1e-11 of the curve's size even at order 16, well inside 1e-6.
    std::mt19937 rng(41);
    for (int trial = 0; trial < 300; ++trial) {
        const unsigned k = 2 + trial % 14;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.3, 10});
        const std::size_t times = 1 + rng() % (kMaxOrder - k);
        const ToolResult<HomogeneousCurve> elevated = elevateDegree(curve.ref(), times);
        ASSERT_TRUE(elevated.ok()) << elevated.message;
        const HomogeneousCurve& e = elevated.value;
        EXPECT_EQ(e.order, k + times);
        EXPECT_EQ(e.knots.size(), e.points.size() + e.order);
        EXPECT_TRUE(std::is_sorted(e.knots.begin(), e.knots.end()));
        // Clamped at the domain's ends, every interior multiplicity raised by times.
        EXPECT_EQ(std::count(e.knots.begin(), e.knots.end(), curve.domainStart()), std::ptrdiff_t(e.order));
        EXPECT_EQ(std::count(e.knots.begin(), e.knots.end(), curve.domainEnd()), std::ptrdiff_t(e.order));
        std::map<double, std::size_t> expected =
            interiorMultiplicities(test::asHomogeneous(curve).knots, curve.domainStart(), curve.domainEnd());
        for (auto& entry : expected)
            entry.second += times;
        EXPECT_EQ(interiorMultiplicities(e.knots, curve.domainStart(), curve.domainEnd()), expected);
        EXPECT_LE(test::maxDeviation(curve, e, curve.domainStart(), curve.domainEnd()),
                  1e-6 * test::curveScale(curve))
            << "order " << k << " + " << times;
        for (const Point4& p : e.points)
            EXPECT_GT(p.w, 0.0);
    }
}

TEST(NurbsDegreeElevation, ElevationByZeroClampsAndKeepsAClampedCurveAsItIs)
{
    std::mt19937 rng(43);
    for (int trial = 0; trial < 100; ++trial) {
        const unsigned k = 2 + trial % 15;
        const bool clamped = trial % 2 == 0;
        const TestCurve curve = test::randomCurve(rng, k, {clamped, 0.3, 10});
        const ToolResult<HomogeneousCurve> same = elevateDegree(curve.ref(), 0);
        ASSERT_TRUE(same.ok()) << same.message;
        const HomogeneousCurve& e = same.value;
        const HomogeneousCurve original = test::asHomogeneous(curve);
        EXPECT_EQ(e.order, k);
        EXPECT_EQ(std::count(e.knots.begin(), e.knots.end(), curve.domainStart()), std::ptrdiff_t(k));
        EXPECT_EQ(std::count(e.knots.begin(), e.knots.end(), curve.domainEnd()), std::ptrdiff_t(k));
        EXPECT_EQ(interiorMultiplicities(e.knots, curve.domainStart(), curve.domainEnd()),
                  interiorMultiplicities(original.knots, curve.domainStart(), curve.domainEnd()));
        if (clamped) {
            EXPECT_EQ(e.knots, original.knots);
            ASSERT_EQ(e.points.size(), original.points.size());
            for (std::size_t i = 0; i < e.points.size(); ++i) {
                EXPECT_EQ(e.points[i].x, original.points[i].x);
                EXPECT_EQ(e.points[i].w, original.points[i].w);
            }
        }
        EXPECT_LE(test::maxDeviation(curve, e, curve.domainStart(), curve.domainEnd()),
                  1e-6 * test::curveScale(curve))
            << "order " << k;
    }
}

TEST(NurbsDegreeElevation, ABezierCurveIsElevatedByTheBernsteinFormula)
{
    // Listing 1's cubic raised to a quartic: Q_i = i/4 P_{i-1} + (1 - i/4) P_i.
    const ToolResult<HomogeneousCurve> e = elevateDegree(test::listingOneCurve().ref(), 1);
    ASSERT_TRUE(e.ok());
    ASSERT_EQ(e.value.points.size(), 5u);
    const double x[5] = {0, 0.75, 1.5, 2.25, 3};
    const double y[5] = {0, 0.75, 0.5, 0.25, 1};
    for (int i = 0; i < 5; ++i) {
        EXPECT_NEAR(e.value.points[i].x, x[i], 1e-14);
        EXPECT_NEAR(e.value.points[i].y, y[i], 1e-14);
        EXPECT_NEAR(e.value.points[i].w, 1.0, 1e-14);
    }
}

TEST(NurbsDegreeElevation, TheOrderStopsAtSixteen)
{
    const TestCurve curve = test::listingOneCurve();
    EXPECT_TRUE(elevateDegree(curve.ref(), 12).ok());
    EXPECT_EQ(elevateDegree(curve.ref(), 13).error, ToolError::kOutOfRange);
    EXPECT_EQ(elevateDegree(curve.ref(), std::size_t(-1)).error, ToolError::kOutOfRange);
    const ToolResult<HomogeneousCurve> copy = elevateDegree(curve.ref(), 0);
    ASSERT_TRUE(copy.ok());
    EXPECT_EQ(copy.value.order, 4u);
    EXPECT_EQ(copy.value.points.size(), 4u);
}

} // namespace
} // namespace q3::nurbs
