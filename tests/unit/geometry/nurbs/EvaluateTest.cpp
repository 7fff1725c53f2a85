// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/Evaluate.h"

#include "NurbsTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace q3::nurbs {
namespace {

using test::makeCurve;
using test::TestCurve;

constexpr double kPi = 3.14159265358979323846;

// The article's circular arc ("CONIC SECTIONS"): order 3, knots 0,0,0,1,1,1, end points
// on the unit circle at angles -theta and +theta, the inner point where the end
// tangents meet, weight cos(theta). Homogeneous form: the inner xyz is multiplied by w.
HomogeneousCurve arc(double theta)
{
    const double w = std::cos(theta);
    HomogeneousCurve curve;
    curve.order = 3;
    curve.knots = {0, 0, 0, 1, 1, 1};
    curve.points = {Point4{std::cos(theta), -std::sin(theta), 0, 1},
                    Point4{(1.0 / w) * w, 0, 0, w},
                    Point4{std::cos(theta), std::sin(theta), 0, 1}};
    return curve;
}

// A full circle as one curve of four 90-degree arcs (article, Figure 21).
HomogeneousCurve fourArcCircle()
{
    const double w = std::sqrt(0.5);
    const double corner[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    HomogeneousCurve curve;
    curve.order = 3;
    curve.knots = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    for (int i = 0; i < 9; ++i) {
        const double weight = i % 2 == 1 ? w : 1.0;
        curve.points.push_back(Point4{corner[i][0] * weight, corner[i][1] * weight, 0, weight});
    }
    return curve;
}

// x and y of an evaluated point, each to EXPECT_DOUBLE_EQ's four ulps.
void expectXY(const CurvePoint& p, double x, double y)
{
    EXPECT_DOUBLE_EQ(p.point.x, x);
    EXPECT_DOUBLE_EQ(p.point.y, y);
}

double radius(const Point3& p)
{
    return std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
}

TEST(NurbsEvaluate, ListingOneBezierMidpointIsHandComputedValue)
{
    // Bernstein weights at 1/2 are 1/8, 3/8, 3/8, 1/8:
    // x = (0 + 3*1 + 3*2 + 3) / 8 = 1.5, y = (0 + 3*1 + 0 + 1) / 8 = 0.5.
    const TestCurve curve = test::listingOneCurve();
    const CurvePoint p = evaluate(curve.ref(), 0.5);
    expectXY(p, 1.5, 0.5);
    EXPECT_DOUBLE_EQ(p.point.z, 0.0);
    EXPECT_DOUBLE_EQ(p.homogeneous.w, 1.0);
}

TEST(NurbsEvaluate, ListingOneBezierQuarterPointIsHandComputedValue)
{
    // Weights at 1/4: 27/64, 27/64, 9/64, 1/64: x = (27 + 18 + 3) / 64, y = (27 + 1) / 64.
    const CurvePoint p = evaluate(test::listingOneCurve().ref(), 0.25);
    expectXY(p, 48.0 / 64.0, 28.0 / 64.0);
}

TEST(NurbsEvaluate, ClampedCurveStartsAndEndsAtEndControlPoints)
{
    const TestCurve curve = test::listingOneCurve();
    const CurvePoint start = evaluate(curve.ref(), 0.0);
    const CurvePoint end = evaluate(curve.ref(), 1.0);
    EXPECT_EQ(start.point.x, 0.0);
    EXPECT_EQ(start.point.y, 0.0);
    EXPECT_EQ(end.point.x, 3.0);
    EXPECT_EQ(end.point.y, 1.0);
}

TEST(NurbsEvaluate, OrderTwoCurveIsThePolylineThroughItsPoints)
{
    const TestCurve curve = makeCurve(2, {0, 0, 0, 1, 2, 0, 0, 1, 2, 2, 0, 1, 5, 2, 4, 1}, {0, 0, 1, 2, 3, 3});
    const CurveRef ref = curve.ref();
    EXPECT_DOUBLE_EQ(evaluate(ref, 1.0).point.x, 2.0);
    EXPECT_DOUBLE_EQ(evaluate(ref, 2.0).point.y, 2.0);
    const CurvePoint mid = evaluate(ref, 2.5);
    expectXY(mid, 3.5, 2.0);
    EXPECT_DOUBLE_EQ(mid.point.z, 2.0);
}

TEST(NurbsEvaluate, TripleStartKnotPutsCurveOnFirstControlPoint)
{
    // Article, Figures 12-13: order 3, knots {0,0,0,3,4,5,6,7}.
    const TestCurve curve = makeCurve(
        3, {1, 1, 0, 1, 2, 3, 0, 1, 4, 3, 0, 1, 5, 1, 0, 1, 7, 2, 0, 1}, {0, 0, 0, 3, 4, 5, 6, 7});
    const CurvePoint p = evaluate(curve.ref(), 0.0);
    expectXY(p, 1.0, 1.0);
}

TEST(NurbsEvaluate, DoubleInteriorKnotPutsQuadraticOnControlPoint)
{
    // Article, Figures 14-15: knots {0,1,2,3,3,5,6,7}; at t = 3 only N_{2,3} is non-zero.
    const TestCurve curve = makeCurve(
        3, {1, 1, 0, 1, 2, 3, 0, 1, 4, 3, 0, 2, 5, 1, 0, 1, 7, 2, 0, 1}, {0, 1, 2, 3, 3, 5, 6, 7});
    const CurvePoint p = evaluate(curve.ref(), 3.0);
    expectXY(p, 2.0, 1.5);
    EXPECT_DOUBLE_EQ(basisFunction(curve.knots.data(), 5, 3, 2, 3.0), 1.0);
}

TEST(NurbsEvaluate, CircularArcsStayOnUnitCircleInDouble)
{
    for (double degrees : {10.0, 30.0, 45.0, 60.0, 80.0, 89.0}) {
        const HomogeneousCurve curve = arc(degrees * kPi / 180.0);
        for (int i = 0; i <= 1000; ++i) {
            const CurvePoint p = evaluate(curve, i / 1000.0);
            EXPECT_NEAR(radius(p.point), 1.0, 1e-12) << degrees << " degrees, t = " << i / 1000.0;
        }
    }
}

TEST(NurbsEvaluate, ArcOfSixtyDegreeHalfAngleSpansOneThirdOfCircle)
{
    // Figure 19: an equilateral control triangle, theta = 60 degrees, w = 0.5, a 120-degree arc.
    const HomogeneousCurve curve = arc(kPi / 3.0);
    EXPECT_NEAR(curve.points[1].w, 0.5, 1e-15);
    const CurvePoint mid = evaluate(curve, 0.5);
    EXPECT_NEAR(mid.point.x, 1.0, 1e-15);
    EXPECT_NEAR(mid.point.y, 0.0, 1e-15);
    const CurvePoint start = evaluate(curve, 0.0);
    EXPECT_NEAR(std::atan2(start.point.y, start.point.x), -kPi / 3.0, 1e-15);
}

TEST(NurbsEvaluate, FourArcCircleStaysOnUnitCircle)
{
    const HomogeneousCurve curve = fourArcCircle();
    for (int i = 0; i <= 4000; ++i) {
        EXPECT_NEAR(radius(evaluate(curve, i / 1000.0).point), 1.0, 1e-12);
    }
}

TEST(NurbsEvaluate, FloatArcStaysOnCircleToFloatPrecision)
{
    // The same arc through the float QuickDraw 3D layout: cos and sin of the angle are
    // rounded to float, which moves the curve by up to a few float ulps (1e-7).
    const double theta = kPi / 4.0;
    const float c = float(std::cos(theta));
    const float s = float(std::sin(theta));
    const TestCurve curve = makeCurve(3, {c, -s, 0, 1, 1.0f, 0, 0, c, c, s, 0, 1}, {0, 0, 0, 1, 1, 1});
    for (int i = 0; i <= 100; ++i) {
        EXPECT_NEAR(radius(evaluate(curve.ref(), i / 100.0).point), 1.0, 1e-6);
    }
}

TEST(NurbsEvaluate, BasisMatchesHandComputedUniformValues)
{
    const float knots[] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    // Order 2 hat on [0, 2].
    EXPECT_DOUBLE_EQ(basisFunction(knots, 7, 2, 0, 0.5), 0.5);
    EXPECT_DOUBLE_EQ(basisFunction(knots, 7, 2, 0, 1.0), 1.0);
    EXPECT_DOUBLE_EQ(basisFunction(knots, 7, 2, 0, 1.5), 0.5);
    // Uniform quadratic: t^2/2 on [0,1), (-2t^2 + 6t - 3)/2 on [1,2).
    EXPECT_DOUBLE_EQ(basisFunction(knots, 6, 3, 0, 0.5), 0.125);
    EXPECT_DOUBLE_EQ(basisFunction(knots, 6, 3, 0, 1.5), 0.75);
    // Uniform cubic peak: 2/3 at its centre.
    EXPECT_DOUBLE_EQ(basisFunction(knots, 5, 4, 0, 2.0), 2.0 / 3.0);
    EXPECT_DOUBLE_EQ(basisFunction(knots, 5, 4, 0, 1.0), 1.0 / 6.0);
}

TEST(NurbsEvaluate, BasisFunctionsArePartitionOfUnityOnRandomKnots)
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 3 != 0, 0.3, 12});
        const std::size_t n = curve.numPoints();
        for (int s = 0; s <= 20; ++s) {
            double t = curve.domainStart() + (curve.domainEnd() - curve.domainStart()) * s / 20.0;
            if (s == 20) {
                t = curve.domainEnd();
            }
            if (s % 7 == 3) {
                t = curve.knots[k - 1 + std::size_t(s) % (n - k + 1)];
            }
            double sum = 0.0;
            for (std::size_t i = 0; i < n; ++i) {
                const double N = basisFunction(curve.knots.data(), n, k, i, t);
                EXPECT_GE(N, 0.0);
                if (t < curve.knots[i] || t > curve.knots[i + k]) {
                    EXPECT_EQ(N, 0.0) << "local support";
                }
                sum += N;
            }
            EXPECT_NEAR(sum, 1.0, 1e-13) << "order " << k << " t " << t;
        }
    }
}

TEST(NurbsEvaluate, DeBoorMatchesCoxDeBoorReferenceOnRandomCurves)
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.3, 12});
        const double scale = test::curveScale(curve);
        const HomogeneousCurve homogeneous = toHomogeneous(curve.ref());
        for (int s = 0; s <= 30; ++s) {
            const double t = s == 30 ? curve.domainEnd()
                                     : curve.domainStart() + (curve.domainEnd() - curve.domainStart()) * unit(rng);
            const Point3 expected = test::referencePoint3(curve, t);
            const CurvePoint p = evaluate(curve.ref(), t);
            EXPECT_LE(test::distance3(p.point, expected), 1e-12 * scale) << "order " << k << " t " << t;
            const CurvePoint q = evaluate(homogeneous, t);
            EXPECT_LE(test::distance3(q.point, expected), 1e-12 * scale);
        }
    }
}

TEST(NurbsEvaluate, ClampsParameterToDomain)
{
    const TestCurve curve = test::listingOneCurve();
    const CurveRef ref = curve.ref();
    EXPECT_EQ(evaluate(ref, -5.0).point.x, 0.0);
    EXPECT_EQ(evaluate(ref, 7.0).point.x, 3.0);
    EXPECT_EQ(evaluate(ref, std::numeric_limits<double>::quiet_NaN()).point.x, 0.0);
    EXPECT_EQ(evaluate(ref, std::numeric_limits<double>::infinity()).point.x, 3.0);
}

TEST(NurbsEvaluate, ListingOneDerivativeIsHandComputedValue)
{
    // Q'(t) = 3 * sum (P_{i+1} - P_i) B_{i,2}(t); the differences are (1,1), (1,-1), (1,1).
    const TestCurve curve = test::listingOneCurve();
    const CurveRef ref = curve.ref();
    const CurvePointDerivative mid = evaluateWithDerivative(ref, 0.5);
    EXPECT_DOUBLE_EQ(mid.tangent.x, 3.0);
    EXPECT_NEAR(mid.tangent.y, 0.0, 1e-15);
    const CurvePointDerivative start = evaluateWithDerivative(ref, 0.0);
    EXPECT_DOUBLE_EQ(start.tangent.x, 3.0);
    EXPECT_DOUBLE_EQ(start.tangent.y, 3.0);
}

TEST(NurbsEvaluate, DerivativeMatchesCentralDifferenceOnRandomCurves)
{
    std::mt19937 rng(5);
    for (int trial = 0; trial < 200; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.2, 8});
        const CurveRef ref = curve.ref();
        for (const Span& span : nonEmptySpans(ref)) {
            // Away from the span's ends, where the central difference would straddle a knot.
            const double t =
                span.start + (span.end - span.start) * std::uniform_real_distribution<double>(0.05, 0.95)(rng);
            const double h = 1e-5 * (span.end - span.start);
            const CurvePointDerivative d = evaluateWithDerivative(ref, t);
            const Point3 ahead = test::referencePoint3(curve, t + h);
            const Point3 behind = test::referencePoint3(curve, t - h);
            const Point3 difference{(ahead.x - behind.x) / (2 * h), (ahead.y - behind.y) / (2 * h),
                                    (ahead.z - behind.z) / (2 * h)};
            const double size = 1.0 + std::sqrt(d.tangent.x * d.tangent.x + d.tangent.y * d.tangent.y +
                                                d.tangent.z * d.tangent.z);
            EXPECT_LE(test::distance3(d.tangent, difference), 1e-4 * size) << "order " << k;
            EXPECT_LE(test::distance3(d.point, test::referencePoint3(curve, t)), 1e-12 * test::curveScale(curve));
        }
    }
}

} // namespace
} // namespace q3::nurbs
