// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/Split.h"

#include "geometry/nurbs/Knots.h"

#include "CurveToolsTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace q3::nurbs {
namespace {

using test::TestCurve;

TEST(NurbsSplit, BothHalvesFollowTheCurveAndMeetAtTheCut)
{
    std::mt19937 rng(43);
    for (int trial = 0; trial < 300; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.3, 10});
        double t = std::uniform_real_distribution<double>(curve.domainStart(), curve.domainEnd())(rng);
        if (trial % 3 == 0)
            t = curve.knots[(k - 1 + curve.numPoints()) / 2];  // often an existing knot
        if (!(t > curve.domainStart() && t < curve.domainEnd()))
            continue;
        const ToolResult<SplitCurves> split = splitAt(test::asHomogeneous(curve), t);
        ASSERT_TRUE(split.ok()) << split.message;
        const HomogeneousCurve& left = split.value.left;
        const HomogeneousCurve& right = split.value.right;
        const double scale = test::curveScale(curve);
        EXPECT_EQ(left.knots.size(), left.points.size() + k);
        EXPECT_EQ(right.knots.size(), right.points.size() + k);
        EXPECT_EQ(left.knots[left.points.size()], t);
        EXPECT_EQ(right.knots[k - 1], t);
        EXPECT_EQ(std::count(left.knots.end() - k, left.knots.end(), t), std::ptrdiff_t(k));
        EXPECT_EQ(std::count(right.knots.begin(), right.knots.begin() + k, t), std::ptrdiff_t(k));
        EXPECT_LE(test::maxDeviation(curve, left, curve.domainStart(), t), 1e-6 * scale) << "order " << k;
        EXPECT_LE(test::maxDeviation(curve, right, t, curve.domainEnd()), 1e-6 * scale) << "order " << k;
        const Point3 cut = test::referencePoint3(curve, t);
        EXPECT_LE(test::distance3(project(left.points.back()), cut), 1e-9 * scale);
        EXPECT_LE(test::distance3(project(right.points.front()), cut), 1e-9 * scale);
    }
}

TEST(NurbsSplit, RejectsCutsOutsideTheOpenDomain)
{
    const HomogeneousCurve h = test::asHomogeneous(test::listingOneCurve());
    EXPECT_EQ(splitAt(h, 0.0).error, ToolError::kOutOfRange);
    EXPECT_EQ(splitAt(h, 1.0).error, ToolError::kOutOfRange);
    EXPECT_EQ(splitAt(h, std::nan("")).error, ToolError::kNotFinite);
    EXPECT_TRUE(splitAt(h, 0.25).ok());
}

TEST(NurbsBezierPieces, EachPieceFollowsTheCurveOnItsSpan)
{
    std::mt19937 rng(47);
    for (int trial = 0; trial < 200; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.3, 10});
        const std::vector<Span> spans = nonEmptySpans(curve.ref());
        for (std::size_t s = 0; s < spans.size(); ++s) {
            const ToolResult<HomogeneousCurve> piece = bezierPiece(curve.ref(), s);
            ASSERT_TRUE(piece.ok()) << piece.message;
            EXPECT_EQ(piece.value.points.size(), k);
            EXPECT_EQ(piece.value.knots.front(), spans[s].start);
            EXPECT_EQ(piece.value.knots.back(), spans[s].end);
            EXPECT_LE(test::maxDeviation(curve, piece.value, spans[s].start, spans[s].end, 50),
                      1e-6 * test::curveScale(curve));
        }
        EXPECT_EQ(bezierPiece(curve.ref(), spans.size()).error, ToolError::kOutOfRange);
        EXPECT_EQ(bezierPiece(curve.ref(), std::size_t(-1)).error, ToolError::kOutOfRange);
    }
}

} // namespace
} // namespace q3::nurbs
