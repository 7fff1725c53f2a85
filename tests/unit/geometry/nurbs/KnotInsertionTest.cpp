// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/KnotInsertion.h"

#include "geometry/nurbs/Evaluate.h"

#include "NurbsTestSupport.h"

#include <gtest/gtest.h>

#include <limits>

namespace q3::nurbs {
namespace {

using test::TestCurve;

double pointDistance(const Point3& a, const Point3& b)
{
    return test::distance3(a, b);
}

TEST(NurbsKnotInsertion, ListingOneMidpointInsertionMatchesArticleAlphas)
{
    // Cubic Bezier, insert 0.5: i = 3 (x_3 = 0 < 0.5 <= x_4 = 1).
    // alpha_1..3 = (0.5 - 0) / (1 - 0) = 0.5, so the new inner points are midpoints:
    // B^ = P0, (P0+P1)/2, (P1+P2)/2, (P2+P3)/2, P3.
    const TestCurve curve = test::listingOneCurve();
    const std::optional<HomogeneousCurve> inserted = insertKnot(toHomogeneous(curve.ref()), 0.5);
    ASSERT_TRUE(inserted.has_value());
    ASSERT_EQ(inserted->points.size(), 5u);
    const std::vector<double> knots{0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    EXPECT_EQ(inserted->knots, knots);
    const double expected[5][2] = {{0, 0}, {0.5, 0.5}, {1.5, 0.5}, {2.5, 0.5}, {3, 1}};
    for (int j = 0; j < 5; ++j) {
        EXPECT_DOUBLE_EQ(inserted->points[j].x, expected[j][0]) << j;
        EXPECT_DOUBLE_EQ(inserted->points[j].y, expected[j][1]) << j;
        EXPECT_DOUBLE_EQ(inserted->points[j].w, 1.0);
    }
}

TEST(NurbsKnotInsertion, InsertionLeavesRandomCurvesUnchanged)
{
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.3, 10});
        const double scale = test::curveScale(curve);
        HomogeneousCurve refined = toHomogeneous(curve.ref());
        // Several insertions, including at existing knots.
        for (int insertion = 0; insertion < 4; ++insertion) {
            double t = curve.domainStart() + (curve.domainEnd() - curve.domainStart()) * unit(rng);
            if (insertion == 3) {
                t = refined.knots[k + (refined.points.size() - k) / 2];
            }
            std::optional<HomogeneousCurve> next = insertKnot(refined, t);
            if (next) {
                EXPECT_EQ(next->points.size(), refined.points.size() + 1);
                EXPECT_EQ(next->knots.size(), next->points.size() + k);
                refined = std::move(*next);
            }
        }
        EXPECT_GT(refined.points.size(), curve.numPoints());
        for (int s = 0; s <= 50; ++s) {
            const double t = curve.domainStart() + (curve.domainEnd() - curve.domainStart()) * s / 50.0;
            const Point3 expected = test::referencePoint3(curve, t);
            EXPECT_LE(pointDistance(evaluate(refined, t).point, expected), 1e-12 * scale)
                << "order " << k << " t " << t;
        }
    }
}

TEST(NurbsKnotInsertion, InsertingOrderMinusOneTimesPutsControlPointOnCurve)
{
    // Article, "EVALUATING NURB CURVES": after k-1 insertions of t, the newest control
    // point is Q(t). Cross-checks de Boor against repeated Boehm insertion.
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> unit(0.05, 0.95);
    for (int trial = 0; trial < 150; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.0, 6});
        const double t = curve.domainStart() + (curve.domainEnd() - curve.domainStart()) * unit(rng);
        HomogeneousCurve refined = toHomogeneous(curve.ref());
        bool alreadyKnot = false;
        for (double knot : refined.knots) {
            alreadyKnot = alreadyKnot || knot == t;
        }
        if (alreadyKnot) {
            continue;
        }
        for (unsigned r = 0; r + 1 < k; ++r) {
            std::optional<HomogeneousCurve> next = insertKnot(refined, t);
            ASSERT_TRUE(next.has_value());
            refined = std::move(*next);
        }
        EXPECT_FALSE(insertKnot(refined, t).has_value()) << "a k-th interior copy must be refused";
        // The point whose neighbouring knots are the k-1 copies of t.
        std::size_t first = 0;
        while (refined.knots[first] != t) {
            ++first;
        }
        const Point3 onCurve = project(refined.points[first - 1]);
        EXPECT_LE(pointDistance(onCurve, evaluate(curve.ref(), t).point), 1e-12 * test::curveScale(curve))
            << "order " << k;
    }
}

TEST(NurbsKnotInsertion, RefusesParameterOutsideOpenDomain)
{
    const HomogeneousCurve curve = toHomogeneous(test::listingOneCurve().ref());
    EXPECT_FALSE(insertKnot(curve, 0.0).has_value());
    EXPECT_FALSE(insertKnot(curve, 1.0).has_value());
    EXPECT_FALSE(insertKnot(curve, -1.0).has_value());
    EXPECT_FALSE(insertKnot(curve, 2.0).has_value());
    EXPECT_FALSE(insertKnot(curve, std::numeric_limits<double>::quiet_NaN()).has_value());
    EXPECT_FALSE(insertKnot(curve, std::numeric_limits<double>::infinity()).has_value());
    EXPECT_FALSE(insertKnot(curve, -std::numeric_limits<double>::infinity()).has_value());
}

} // namespace
} // namespace q3::nurbs
