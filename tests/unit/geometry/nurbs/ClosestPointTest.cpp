// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/ClosestPoint.h"

#include "CurveToolsTestSupport.h"
#include "GoldenSection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

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

// The tolerance closestPoint promises: kClosestPointTolerance times the diagonal of
// the bounding box of the projected control points.
double promisedTolerance(const TestCurve& curve)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY};
    double hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (std::size_t i = 0; i < curve.numPoints(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double v = double(curve.points[4 * i + c]) / double(curve.points[4 * i + 3]);
            lo[c] = std::min(lo[c], v);
            hi[c] = std::max(hi[c], v);
        }
    return kClosestPointTolerance *
           std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                     (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

// An independent oracle for the least distance: the reference (Cox-de Boor)
// evaluator at perSpan + 1 evenly spaced parameters of every non-empty span, then
// golden-section search over the two intervals around every sample no farther than
// its neighbours in the same span (span ends included, so corners are seen).
double oracleDistance(const TestCurve& curve, const Point3& target, int perSpan)
{
    const auto f = [&](double t) { return test::distance3(test::referencePoint3(curve, t), target); };
    double best = INFINITY;
    for (std::size_t l = curve.order - 1; l < curve.numPoints(); ++l) {
        const double a = curve.knots[l];
        const double b = curve.knots[l + 1];
        if (!(a < b))
            continue;
        std::vector<double> ts(perSpan + 1), fs(perSpan + 1);
        for (int i = 0; i <= perSpan; ++i) {
            ts[i] = i == perSpan ? b : a + (b - a) * i / perSpan;
            fs[i] = f(ts[i]);
            best = std::min(best, fs[i]);
        }
        for (int i = 0; i <= perSpan; ++i) {
            if ((i > 0 && fs[i - 1] < fs[i]) || (i < perSpan && fs[i + 1] < fs[i]))
                continue;
            double lo = ts[std::max(i - 1, 0)];
            double hi = ts[std::min(i + 1, perSpan)];
            best = std::min(best, q3test::goldenSectionMinimum(f, lo, hi, 80));
        }
    }
    return best;
}

void expectAgreesWithTheOracle(const TestCurve& curve, const Point3& target, int perSpan, const char* what,
                               int trial)
{
    const ToolResult<ClosestPoint> found = closestPoint(curve.ref(), target);
    ASSERT_TRUE(found.ok()) << found.message;
    const double tolerance = promisedTolerance(curve);
    // The oracle's distance is that of a curve point, so no nearer than the least
    // distance: the promise is found <= oracle + tolerance. The other side checks
    // that the oracle is fine enough to be a measure.
    double oracle = oracleDistance(curve, target, perSpan);
    // Nearer than the oracle: either it sampled too coarsely (then 16 times finer
    // sampling finds the point too) or closestPoint handed out a wrong distance.
    if (found.value.distance < oracle - tolerance)
        oracle = oracleDistance(curve, target, 16 * perSpan);
    EXPECT_LE(found.value.distance, oracle + tolerance) << what << " trial " << trial << " order " << curve.order;
    EXPECT_GE(found.value.distance, oracle - tolerance) << what << " trial " << trial << " order " << curve.order;
    EXPECT_NEAR(test::distance3(test::referencePoint3(curve, found.value.t), target), found.value.distance,
                1e-9 * test::curveScale(curve));
}

TEST(NurbsClosestPoint, MatchesADenseOracleOnThousandsOfRandomQueries)
{
    // Interior knots repeat often, up to multiplicity order - 1 (corners); half the
    // targets are near the curve, where the nearest point is decided by the knots.
    std::mt19937 rng(2026);
    std::uniform_real_distribution<double> coordinate(-15.0, 15.0);
    std::uniform_real_distribution<double> offset(-0.5, 0.5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int queries = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 3 != 0, 0.6, 4});
        for (int q = 0; q < 10; ++q, ++queries) {
            Point3 target{coordinate(rng), coordinate(rng), coordinate(rng)};
            if (q % 2 == 1) {
                const double t = curve.domainStart() + unit(rng) * (curve.domainEnd() - curve.domainStart());
                const Point3 on = test::referencePoint3(curve, t);
                target = Point3{on.x + offset(rng), on.y + offset(rng), on.z + offset(rng)};
            }
            expectAgreesWithTheOracle(curve, target, 6 * int(k), "random", trial);
        }
    }
    EXPECT_EQ(queries, 3000);
}

TEST(NurbsClosestPoint, FindsACornerOfMultiplicityOrderMinusOne)
{
    // A cubic V: the knot 1 of multiplicity 3 makes the curve only C0 at (0, 0).
    const TestCurve v = test::makeCurve(4,
                                        {-1, 1, 0, 1, -2.f / 3, 2.f / 3, 0, 1, -1.f / 3, 1.f / 3, 0, 1, 0, 0, 0, 1,
                                         1.f / 3, 1.f / 3, 0, 1, 2.f / 3, 2.f / 3, 0, 1, 1, 1, 0, 1},
                                        {0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2});
    const ToolResult<ClosestPoint> below = closestPoint(v.ref(), Point3{0.0, -1.0, 0.0});
    ASSERT_TRUE(below.ok());
    EXPECT_NEAR(below.value.t, 1.0, 1e-12);
    EXPECT_NEAR(below.value.distance, 1.0, 1e-12);
    for (double x = -2.0; x <= 2.0; x += 0.125)
        for (double y = -1.0; y <= 2.0; y += 0.125)
            expectAgreesWithTheOracle(v, Point3{x, y, 0.25}, 200, "V", 0);
}

// Bernstein coefficients of the polynomial sum a_j t^j of degree n (b_i = sum over
// j <= i of C(i, j) / C(n, j) a_j).
std::vector<double> powerToBernstein(const std::vector<double>& a)
{
    const std::size_t n = a.size() - 1;
    const auto binomial = [](std::size_t m, std::size_t j) {
        double r = 1.0;
        for (std::size_t i = 1; i <= j; ++i)
            r = r * double(m - j + i) / double(i);
        return r;
    };
    std::vector<double> b(n + 1, 0.0);
    for (std::size_t i = 0; i <= n; ++i)
        for (std::size_t j = 0; j <= i; ++j)
            b[i] += binomial(i, j) / binomial(n, j) * a[j];
    return b;
}

TEST(NurbsClosestPoint, TellsApartTwoMinimaCloserThanAnyCoarseSampling)
{
    // x = t, y = A ((t - h)^2 - d^2)^2 + s (t - h) on [0, 1]: two dips d either side
    // of h, d down to a hundredth of the span (a fifth of the old 4k + 1 sampling's
    // step), tilted by s so that one is nearer a target below them.
    int trial = 0;
    for (double h : {0.5, 0.4731, 0.5382}) {
        for (double d : {0.1, 0.03, 0.01}) {
            for (double s : {-1e-3, -1e-5, 0.0, 1e-5, 1e-3}) {
                const double A = 1.0 / (d * d);
                // ((t - h)^2 - d^2)^2 expanded in powers of t.
                const double c0 = h * h - d * d;  // (t - h)^2 - d^2 = t^2 - 2 h t + c0
                std::vector<double> y = {A * c0 * c0 - s * h, A * (-4 * h * c0) + s, A * (4 * h * h + 2 * c0),
                                         A * (-4 * h), A};
                const std::vector<double> by = powerToBernstein(y);
                std::vector<float> points;
                for (std::size_t i = 0; i < by.size(); ++i)
                    for (double v : {double(i) / 4.0, by[i], 0.0, 1.0})
                        points.push_back(float(v));
                const TestCurve curve = test::makeCurve(5, points, {0, 0, 0, 0, 0, 1, 1, 1, 1, 1});
                for (double dx : {-0.5 * d, -0.1 * d, 0.0, 0.1 * d, 0.5 * d})
                    for (double below : {0.001, 0.05, 0.5})
                        expectAgreesWithTheOracle(curve, Point3{h + dx, -below, 0.0}, 1000, "dips", trial++);
            }
        }
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

TEST(NurbsClosestPoint, AtTheCentreOfAnArcEndsWithinItsBudgetAtTheRadius)
{
    // Every point of the arc is equally near its centre: the one case the search
    // may spend its kMaxClosestPointSplits on; any point of the arc is an answer.
    const float w = float(std::sqrt(0.5));
    const TestCurve quarter =
        test::makeCurve(3, {1, 0, 0, 1, w, w, 0, w, 0, 1, 0, 1}, {0, 0, 0, 1, 1, 1});
    for (double z : {0.0, 0.5}) {
        const ToolResult<ClosestPoint> found = closestPoint(quarter.ref(), Point3{0.0, 0.0, z});
        ASSERT_TRUE(found.ok());
        EXPECT_NEAR(found.value.distance, std::sqrt(1.0 + z * z), 1e-7);
        EXPECT_GE(found.value.t, 0.0);
        EXPECT_LE(found.value.t, 1.0);
    }
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
