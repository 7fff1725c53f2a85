// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/KnotRefinement.h"

#include "CurveToolsTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace q3::nurbs {
namespace {

using test::TestCurve;

// Shapes must agree to 1e-6 of the curve's size (the bound); in double the
// insertions are exact to about 1e-13.
constexpr double kShapeTolerance = 1e-6;

double uniformIn(std::mt19937& rng, double a, double b)
{
    return std::uniform_real_distribution<double>(a, b)(rng);
}

std::size_t multiplicity(const std::vector<double>& knots, double value)
{
    return std::size_t(std::count(knots.begin(), knots.end(), value));
}

TEST(NurbsKnotRefinement, InsertingAKnotRepeatedlyLeavesRandomCurvesUnchanged)
{
    std::mt19937 rng(5);
    for (int trial = 0; trial < 300; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.3, 10});
        const HomogeneousCurve h = test::asHomogeneous(curve);
        // Half the time an existing interior knot, else a random value.
        double t = uniformIn(rng, curve.domainStart(), curve.domainEnd());
        if (trial % 2 == 1) {
            for (std::size_t i = k; i < curve.numPoints(); ++i)
                if (curve.knots[i] > curve.domainStart() && curve.knots[i] < curve.domainEnd())
                    t = curve.knots[i];
        }
        const std::size_t room = (k - 1) - multiplicity(h.knots, t);
        const ToolResult<HomogeneousCurve> inserted = insertKnotTimes(h, t, room);
        ASSERT_TRUE(inserted.ok()) << inserted.message;
        EXPECT_EQ(inserted.value.points.size(), curve.numPoints() + room);
        EXPECT_EQ(inserted.value.knots.size(), inserted.value.points.size() + k);
        EXPECT_TRUE(std::is_sorted(inserted.value.knots.begin(), inserted.value.knots.end()));
        EXPECT_EQ(multiplicity(inserted.value.knots, t), k - 1);
        EXPECT_LE(test::maxDeviation(curve, inserted.value, curve.domainStart(), curve.domainEnd()),
                  kShapeTolerance * test::curveScale(curve))
            << "order " << k << " t " << t;
        EXPECT_EQ(insertKnotTimes(h, t, room + 1).error, ToolError::kOutOfRange);
    }
}

TEST(NurbsKnotRefinement, RefiningWithManyKnotsAtOnceLeavesRandomCurvesUnchanged)
{
    std::mt19937 rng(17);
    for (int trial = 0; trial < 300; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 3 != 0, 0.25, 10});
        const HomogeneousCurve h = test::asHomogeneous(curve);
        std::vector<double> knots;
        const int count = 1 + int(rng() % 40);
        for (int i = 0; i < count; ++i) {
            const double t = uniformIn(rng, curve.domainStart(), curve.domainEnd());
            // Repeat some values, within the multiplicity limit.
            const std::size_t copies = 1 + rng() % 3;
            for (std::size_t c = 0; c < copies; ++c)
                if (multiplicity(h.knots, t) + std::size_t(std::count(knots.begin(), knots.end(), t)) < k - 1 &&
                    t > curve.domainStart())
                    knots.push_back(t);
        }
        std::shuffle(knots.begin(), knots.end(), rng);
        const ToolResult<HomogeneousCurve> refined = refineKnots(h, knots);
        ASSERT_TRUE(refined.ok()) << refined.message;
        EXPECT_EQ(refined.value.points.size(), curve.numPoints() + knots.size());
        EXPECT_TRUE(std::is_sorted(refined.value.knots.begin(), refined.value.knots.end()));
        EXPECT_LE(test::maxDeviation(curve, refined.value, curve.domainStart(), curve.domainEnd()),
                  kShapeTolerance * test::curveScale(curve))
            << "order " << k << " with " << knots.size() << " knots";
    }
}

TEST(NurbsKnotRefinement, RefinementMatchesTheArticlesListingTwoOnFigure22)
{
    // Figure 9's curve with t = 3.6 inserted (article, "KNOT INSERTION"): i = 3,
    // alpha_2 = (3.6 - 2) / (4 - 2) = 0.8, alpha_3 = (3.6 - 3) / (5 - 3) = 0.3.
    const TestCurve curve = test::makeCurve(3, {0, 0.5f, 0, 1, 1.5f, 3.5f, 0, 1, 3, 0.5f, 0, 1, 4.5f, 3, 0, 1, 6, 1, 0, 1},
                                            {0, 1, 2, 3, 4, 5, 6, 7});
    const ToolResult<HomogeneousCurve> r = insertKnotTimes(test::asHomogeneous(curve), 3.6f, 1);
    ASSERT_TRUE(r.ok());
    const std::vector<double> knots{0, 1, 2, 3, double(3.6f), 4, 5, 6, 7};
    EXPECT_EQ(r.value.knots, knots);
    const double alpha2 = (double(3.6f) - 2.0) / 2.0;
    const double alpha3 = (double(3.6f) - 3.0) / 2.0;
    EXPECT_DOUBLE_EQ(r.value.points[2].x, (1 - alpha2) * 1.5 + alpha2 * 3.0);
    EXPECT_DOUBLE_EQ(r.value.points[3].x, (1 - alpha3) * 3.0 + alpha3 * 4.5);
    EXPECT_DOUBLE_EQ(r.value.points[1].x, 1.5);
    EXPECT_DOUBLE_EQ(r.value.points[4].x, 4.5);
}

TEST(NurbsKnotRefinement, RejectsKnotsOutsideTheOpenDomainAndTooManyCopies)
{
    const HomogeneousCurve h = test::asHomogeneous(test::listingOneCurve());
    EXPECT_EQ(insertKnotTimes(h, 0.0, 1).error, ToolError::kOutOfRange);
    EXPECT_EQ(insertKnotTimes(h, 1.0, 1).error, ToolError::kOutOfRange);
    EXPECT_EQ(insertKnotTimes(h, std::nan(""), 1).error, ToolError::kNotFinite);
    EXPECT_EQ(insertKnotTimes(h, INFINITY, 1).error, ToolError::kNotFinite);
    EXPECT_EQ(insertKnotTimes(h, 0.5, 4).error, ToolError::kOutOfRange);
    EXPECT_EQ(insertKnotTimes(h, 0.5, std::size_t(-1)).error, ToolError::kOutOfRange);
    EXPECT_TRUE(insertKnotTimes(h, 0.5, 3).ok());
    EXPECT_EQ(insertKnotTimes(h, 0.5, 0).value.points.size(), 4u);
    EXPECT_EQ(refineKnots(h, {0.5, 0.5, 0.5, 0.5}).error, ToolError::kInvalidArgument);
    EXPECT_EQ(refineKnots(h, {0.5, -0.5}).error, ToolError::kOutOfRange);
    EXPECT_EQ(refineKnots(h, {0.5, std::nan("")}).error, ToolError::kNotFinite);
    EXPECT_FALSE(refineKnots(h, {0.5, std::nan("")}).message.empty());
    EXPECT_TRUE(refineKnots(h, {}).ok());
}

TEST(NurbsKnotRemoval, AnInsertedKnotComesOutAgainAndTheShapeStays)
{
    std::mt19937 rng(23);
    for (int trial = 0; trial < 300; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.2, 8});
        const double t = double(float(uniformIn(rng, curve.domainStart(), curve.domainEnd())));
        const std::size_t room = (k - 1) - multiplicity(test::asHomogeneous(curve).knots, t);
        if (room == 0 || t <= curve.domainStart())
            continue;
        const std::size_t copies = 1 + rng() % room;
        HomogeneousCurve inserted = insertKnotTimes(test::asHomogeneous(curve), t, copies).value;
        roundToFloat(inserted);
        const std::size_t index = std::size_t(std::find(inserted.knots.begin(), inserted.knots.end(), t) -
                                              inserted.knots.begin());
        const double tolerance = 1e-4 * test::curveScale(curve);
        const ToolResult<KnotRemoval> removal = removeKnot(inserted, index, copies, tolerance);
        ASSERT_TRUE(removal.ok()) << removal.message;
        EXPECT_EQ(removal.value.removed, copies) << "order " << k;
        EXPECT_EQ(removal.value.curve.points.size(), inserted.points.size() - removal.value.removed);
        EXPECT_LE(test::maxDeviation(curve, removal.value.curve, curve.domainStart(), curve.domainEnd()),
                  tolerance);
    }
}

TEST(NurbsKnotRemoval, RemovalHappensOnlyWithinTheTolerance)
{
    // Removing a knot of a random curve changes it; whatever count the call accepts,
    // the curve moves by no more than the tolerance.
    std::mt19937 rng(29);
    int removedSome = 0;
    int refused = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.4, 8});
        const HomogeneousCurve h = test::asHomogeneous(curve);
        std::vector<std::size_t> interior;
        for (std::size_t i = 0; i < h.knots.size(); ++i)
            if (h.knots[i] > curve.domainStart() && h.knots[i] < curve.domainEnd())
                interior.push_back(i);
        if (interior.empty())
            continue;
        const std::size_t index = interior[rng() % interior.size()];
        const std::size_t times = multiplicity(h.knots, h.knots[index]);
        const double tolerance = test::curveScale(curve) * std::pow(10.0, uniformIn(rng, -4.0, 2.0));
        const ToolResult<KnotRemoval> removal = removeKnot(h, index, times, tolerance);
        ASSERT_TRUE(removal.ok()) << removal.message;
        if (removal.value.removed == 0) {
            ++refused;
            EXPECT_EQ(removal.value.curve.points.size(), h.points.size());
            continue;
        }
        ++removedSome;
        EXPECT_LE(test::maxDeviation(curve, removal.value.curve, curve.domainStart(), curve.domainEnd(), 400),
                  tolerance)
            << "order " << k << " removed " << removal.value.removed;
        for (const Point4& p : removal.value.curve.points)
            EXPECT_GT(p.w, 0.0);
    }
    EXPECT_GT(removedSome, 20);
    EXPECT_GT(refused, 20);
}

TEST(NurbsKnotRemoval, RejectsBadIndicesCountsAndTolerances)
{
    // Listing 1 with 0.5 inserted twice: knots 0 0 0 0 .5 .5 1 1 1 1.
    const HomogeneousCurve h =
        insertKnotTimes(test::asHomogeneous(test::listingOneCurve()), 0.5, 2).value;
    EXPECT_EQ(removeKnot(h, 0, 1, 1e-3).error, ToolError::kOutOfRange);   // domain start
    EXPECT_EQ(removeKnot(h, 3, 1, 1e-3).error, ToolError::kOutOfRange);
    EXPECT_EQ(removeKnot(h, 9, 1, 1e-3).error, ToolError::kOutOfRange);   // last knot
    EXPECT_EQ(removeKnot(h, 10, 1, 1e-3).error, ToolError::kOutOfRange);  // one past
    EXPECT_EQ(removeKnot(h, std::size_t(-1), 1, 1e-3).error, ToolError::kOutOfRange);
    EXPECT_EQ(removeKnot(h, 4, 3, 1e-3).error, ToolError::kOutOfRange);   // occurs twice
    EXPECT_EQ(removeKnot(h, 4, 1, 0.0).error, ToolError::kInvalidArgument);
    EXPECT_EQ(removeKnot(h, 4, 1, -1.0).error, ToolError::kInvalidArgument);
    EXPECT_EQ(removeKnot(h, 4, 1, std::nan("")).error, ToolError::kNotFinite);
    EXPECT_EQ(removeKnot(h, 4, 1, INFINITY).error, ToolError::kNotFinite);
    const ToolResult<KnotRemoval> none = removeKnot(h, 5, 0, 1e-3);
    ASSERT_TRUE(none.ok());
    EXPECT_EQ(none.value.removed, 0u);
    const ToolResult<KnotRemoval> both = removeKnot(h, 5, 2, 1e-6);
    ASSERT_TRUE(both.ok());
    EXPECT_EQ(both.value.removed, 2u);
    EXPECT_EQ(both.value.curve.knots, (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
}

} // namespace
} // namespace q3::nurbs
