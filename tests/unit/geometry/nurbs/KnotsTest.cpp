// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/Knots.h"

#include "NurbsTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace q3::nurbs {
namespace {

using test::makeCurve;
using test::TestCurve;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A curve of the given order with n unit-weight points and the given knots.
TestCurve curveWithKnots(unsigned order, std::size_t n, std::vector<float> knots)
{
    std::vector<float> points;
    for (std::size_t i = 0; i < n; ++i) {
        points.insert(points.end(), {float(i), float(i % 2), 0.0f, 1.0f});
    }
    return makeCurve(order, std::move(points), std::move(knots));
}

// Uniform knots 0, 1, 2, ...
std::vector<float> uniformKnots(std::size_t count)
{
    std::vector<float> knots(count);
    for (std::size_t i = 0; i < count; ++i) {
        knots[i] = float(i);
    }
    return knots;
}

TEST(NurbsKnots, AcceptsListingOneCurve)
{
    const TestCurve curve = test::listingOneCurve();
    const CurveValidation result = validateCurve(curve.ref());
    EXPECT_TRUE(result.ok());
    EXPECT_EQ(result.problem(), CurveProblem::kNone);
    EXPECT_TRUE(result.message.empty());
}

TEST(NurbsKnots, AcceptsOrdersTwoThroughSixteen)
{
    for (unsigned k = kMinOrder; k <= kMaxOrder; ++k) {
        const TestCurve curve = curveWithKnots(k, k, uniformKnots(2 * k));
        EXPECT_TRUE(validateCurve(curve.ref()).ok()) << "order " << k;
    }
}

TEST(NurbsKnots, RejectsOrderOutOfRange)
{
    for (unsigned k : {0u, 1u, 17u, 100u, 0xFFFFFFFFu}) {
        CurveRef ref = curveWithKnots(4, 4, uniformKnots(8)).ref();
        ref.order = k;
        const CurveValidation result = validateCurve(ref);
        EXPECT_EQ(result.rule, CurveRule::kOrderOutOfRange) << k;
        EXPECT_EQ(result.problem(), CurveProblem::kOrderOutOfRange);
        EXPECT_FALSE(result.message.empty());
    }
}

TEST(NurbsKnots, RejectsFewerPointsThanOrder)
{
    const TestCurve curve = curveWithKnots(4, 3, uniformKnots(7));
    const CurveValidation result = validateCurve(curve.ref());
    EXPECT_EQ(result.rule, CurveRule::kTooFewPoints);
    EXPECT_EQ(result.problem(), CurveProblem::kTooFewPoints);

    CurveRef none = curve.ref();
    none.numPoints = 0;
    EXPECT_EQ(validateCurve(none).rule, CurveRule::kTooFewPoints);
}

TEST(NurbsKnots, AcceptsPointCountEqualToOrder)
{
    EXPECT_TRUE(validateCurve(curveWithKnots(3, 3, {0, 0, 0, 1, 1, 1}).ref()).ok());
}

TEST(NurbsKnots, RejectsNullArrays)
{
    const TestCurve curve = test::listingOneCurve();
    CurveRef ref = curve.ref();
    ref.points = nullptr;
    EXPECT_EQ(validateCurve(ref).rule, CurveRule::kMissingArray);
    EXPECT_EQ(validateCurve(ref).problem(), CurveProblem::kBadContent);
    ref = curve.ref();
    ref.knots = nullptr;
    EXPECT_EQ(validateCurve(ref).rule, CurveRule::kMissingArray);
}

TEST(NurbsKnots, RejectsNonFiniteKnotAndReportsItsIndex)
{
    for (float bad : {kNaN, kInf, -kInf}) {
        for (std::size_t index : {std::size_t{0}, std::size_t{3}, std::size_t{7}}) {
            TestCurve curve = test::listingOneCurve();
            curve.knots[index] = bad;
            const CurveValidation result = validateCurve(curve.ref());
            EXPECT_EQ(result.rule, CurveRule::kKnotNotFinite);
            EXPECT_EQ(result.index, index);
            EXPECT_EQ(result.problem(), CurveProblem::kBadContent);
        }
    }
}

TEST(NurbsKnots, RejectsDecreasingKnotAndReportsItsIndex)
{
    const TestCurve curve = curveWithKnots(3, 5, {0, 0, 0, 2, 1, 3, 3, 3});
    const CurveValidation result = validateCurve(curve.ref());
    EXPECT_EQ(result.rule, CurveRule::kKnotDecreasing);
    EXPECT_EQ(result.index, 4u);
    EXPECT_NE(result.message.find("nondecreasing"), std::string::npos);
}

TEST(NurbsKnots, AcceptsInteriorRunOfOrderMinusOne)
{
    // Order 4: three equal interior knots.
    EXPECT_TRUE(validateCurve(curveWithKnots(4, 7, {0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2}).ref()).ok());
}

TEST(NurbsKnots, RejectsInteriorRunOfOrder)
{
    const TestCurve curve = curveWithKnots(4, 8, {0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2});
    const CurveValidation result = validateCurve(curve.ref());
    EXPECT_EQ(result.rule, CurveRule::kKnotRunTooLong);
    EXPECT_EQ(result.index, 4u);
    EXPECT_EQ(result.problem(), CurveProblem::kBadContent);
}

TEST(NurbsKnots, AcceptsRunOfOrderAtEitherEnd)
{
    EXPECT_TRUE(validateCurve(curveWithKnots(4, 5, {0, 0, 0, 0, 1, 2, 3, 4, 5}).ref()).ok());
    EXPECT_TRUE(validateCurve(curveWithKnots(4, 5, {0, 1, 2, 3, 4, 5, 5, 5, 5}).ref()).ok());
    EXPECT_TRUE(validateCurve(curveWithKnots(2, 2, {0, 0, 1, 1}).ref()).ok());
}

TEST(NurbsKnots, RejectsRunLongerThanOrderAtEitherEnd)
{
    const CurveValidation start = validateCurve(curveWithKnots(3, 5, {0, 0, 0, 0, 1, 2, 3, 4}).ref());
    EXPECT_EQ(start.rule, CurveRule::kKnotRunTooLong);
    EXPECT_EQ(start.index, 0u);
    const CurveValidation end = validateCurve(curveWithKnots(3, 5, {0, 1, 2, 3, 4, 4, 4, 4}).ref());
    EXPECT_EQ(end.rule, CurveRule::kKnotRunTooLong);
    EXPECT_EQ(end.index, 4u);
}

TEST(NurbsKnots, OrderTwoAllowsNoRepeatedInteriorKnot)
{
    EXPECT_EQ(validateCurve(curveWithKnots(2, 4, {0, 0, 1, 1, 2, 2}).ref()).rule, CurveRule::kKnotRunTooLong);
    EXPECT_TRUE(validateCurve(curveWithKnots(2, 4, {0, 0, 1, 2, 3, 3}).ref()).ok());
}

TEST(NurbsKnots, RejectsNonFinitePointAndReportsItsIndex)
{
    for (float bad : {kNaN, kInf, -kInf}) {
        for (int component = 0; component < 4; ++component) {
            TestCurve curve = test::listingOneCurve();
            curve.points[4 * 2 + component] = bad;
            const CurveValidation result = validateCurve(curve.ref());
            EXPECT_EQ(result.rule, CurveRule::kPointNotFinite) << component;
            EXPECT_EQ(result.index, 2u);
        }
    }
}

TEST(NurbsKnots, RejectsZeroAndNegativeWeight)
{
    for (float w : {0.0f, -0.0f, -1.0f, -1e-30f}) {
        TestCurve curve = test::listingOneCurve();
        curve.points[4 * 3 + 3] = w;
        const CurveValidation result = validateCurve(curve.ref());
        EXPECT_EQ(result.rule, CurveRule::kWeightNotPositive) << w;
        EXPECT_EQ(result.index, 3u);
        EXPECT_EQ(result.problem(), CurveProblem::kBadContent);
    }
}

TEST(NurbsKnots, AcceptsTinyPositiveWeight)
{
    TestCurve curve = test::listingOneCurve();
    curve.points[4 * 1 + 3] = std::numeric_limits<float>::denorm_min();
    EXPECT_TRUE(validateCurve(curve.ref()).ok());
}

TEST(NurbsKnots, RejectsEmptyDomain)
{
    // Order 4, 4 points: domain [knots[3], knots[4]] = [3, 3], a legal run of two.
    const CurveValidation result = validateCurve(curveWithKnots(4, 4, {0, 1, 2, 3, 3, 4, 5, 6}).ref());
    EXPECT_EQ(result.rule, CurveRule::kEmptyDomain);
    EXPECT_EQ(result.problem(), CurveProblem::kBadContent);
}

TEST(NurbsKnots, ReportsTheFirstRuleInCheckingOrder)
{
    TestCurve curve = curveWithKnots(3, 5, {0, 0, 0, 2, 1, 3, 3, 3});
    curve.points[3] = -1.0f;
    EXPECT_EQ(validateCurve(curve.ref()).rule, CurveRule::kKnotDecreasing);
}

TEST(NurbsKnots, DomainRunsFromKnotOrderMinusOneToKnotN)
{
    // The article: an order-4 curve with knots 0..7 only goes from t = 3 to t = 4.
    const TestCurve curve = curveWithKnots(4, 4, uniformKnots(8));
    const Domain domain = curveDomain(curve.ref());
    EXPECT_EQ(domain.start, 3.0);
    EXPECT_EQ(domain.end, 4.0);
}

TEST(NurbsKnots, ListsOnlyNonEmptySpansInsideDomain)
{
    const TestCurve curve = curveWithKnots(3, 7, {0, 0, 0, 1, 1, 2, 4, 5, 5, 5});
    const std::vector<Span> spans = nonEmptySpans(curve.ref());
    // Knots 3 and 4 are both 1, so span 3 is empty.
    ASSERT_EQ(spans.size(), 4u);
    EXPECT_EQ(countNonEmptySpans(curve.ref()), 4u);
    EXPECT_EQ(spans[0].knotIndex, 2u);
    EXPECT_EQ(spans[0].start, 0.0);
    EXPECT_EQ(spans[0].end, 1.0);
    EXPECT_EQ(spans[1].knotIndex, 4u);
    EXPECT_EQ(spans[1].start, 1.0);
    EXPECT_EQ(spans[1].end, 2.0);
    EXPECT_EQ(spans[2].knotIndex, 5u);
    EXPECT_EQ(spans[3].knotIndex, 6u);
    EXPECT_EQ(spans[3].end, 5.0);
}

TEST(NurbsKnots, FindSpanReturnsHalfOpenSpanAndLastSpanAtEnd)
{
    const TestCurve curve = curveWithKnots(3, 7, {0, 0, 0, 1, 1, 2, 4, 5, 5, 5});
    const CurveRef ref = curve.ref();
    EXPECT_EQ(findSpan(ref, 0.0), 2u);
    EXPECT_EQ(findSpan(ref, 0.5), 2u);
    EXPECT_EQ(findSpan(ref, 1.0), 4u);  // knots 3 and 4 are both 1: span 3 is empty
    EXPECT_EQ(findSpan(ref, 1.999), 4u);
    EXPECT_EQ(findSpan(ref, 2.0), 5u);
    EXPECT_EQ(findSpan(ref, 4.5), 6u);
    EXPECT_EQ(findSpan(ref, 5.0), 6u);
}

TEST(NurbsKnots, FindSpanClampsOutsideDomainAndNaN)
{
    const TestCurve curve = curveWithKnots(4, 6, uniformKnots(10));
    const CurveRef ref = curve.ref();
    EXPECT_EQ(findSpan(ref, -100.0), 3u);
    EXPECT_EQ(findSpan(ref, 100.0), 5u);
    EXPECT_EQ(findSpan(ref, std::numeric_limits<double>::quiet_NaN()), 3u);
    EXPECT_EQ(findSpan(ref, -std::numeric_limits<double>::infinity()), 3u);
    EXPECT_EQ(findSpan(ref, std::numeric_limits<double>::infinity()), 5u);
}

TEST(NurbsKnots, FindSpanAgreesWithLinearScanOnRandomCurves)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.4, 20});
        const CurveRef ref = curve.ref();
        const HomogeneousCurve homogeneous = toHomogeneous(ref);
        for (int s = 0; s < 20; ++s) {
            double t = curve.domainStart() + (curve.domainEnd() - curve.domainStart()) * unit(rng);
            if (s == 0) {
                t = curve.domainStart();
            }
            if (s < 5 && s > 0) {
                t = curve.knots[k - 1 + std::size_t(s) % (curve.numPoints() - k + 1)];
            }
            // The half-open span holding t, or at the domain end the last non-empty one.
            std::size_t expected = 0;
            for (std::size_t i = k - 1; i < curve.numPoints(); ++i) {
                if (curve.knots[i] <= t && t < curve.knots[i + 1]) {
                    expected = i;
                }
                if (t == curve.domainEnd() && curve.knots[i] < curve.knots[i + 1]) {
                    expected = i;
                }
            }
            EXPECT_EQ(findSpan(ref, t), expected);
            EXPECT_EQ(findSpan(homogeneous, t), expected);
        }
    }
}

} // namespace
} // namespace q3::nurbs
