// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The figures' numbers, not just their pictures: the circles of Figures 19
// to 21 lie on the circle, Figure 22's curve is unchanged by the knot
// insertion, Figure 13's curve starts at its first control point, the basis
// plots are the basis functions, and the article's other claims about the
// figures hold. Positions come both from the tests' own evaluator
// (ReferenceNurbs.h) and from the line segments Q3 draws
// (Q3Geometry_GetDecomposed inside a rendering loop).

#include "Q3ApiTest.h"
#include "ReferenceNurbs.h"

#include "QD3DGeometry.h"
#include "QD3DStyle.h"
#include "QD3DView.h"
#include "figures.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using q3test::RefPoint;

constexpr double kPi = 3.14159265358979323846;

/// Tessellated vertices are floats, and so are the control points, which
/// round exact values such as sqrt(3) and sqrt(2)/2 to 24 bits (relative
/// error <= 2^-24, about 6e-8). Moving a control point or weight by a
/// relative 6e-8 moves a rational quadratic's points by at most about as
/// much relative to the circle's size, and rounding the double-precision
/// result to float adds at most 6e-8 per coordinate. So a float vertex of
/// an exact circle of radius 1 lies within a few 1e-7 of it; 1e-6 relative
/// is the bound asked for and still far below a wrong weight's error (a
/// weight of 0.7 instead of sqrt(2)/2 moves the curve by about 3e-3).
constexpr double kCircleTolerance = 1e-6;

/// The segments per span used to decompose the figures' curves.
constexpr float kSegmentsPerSpan = 64.0f;

class ArticleFigureGeometry : public q3test::Q3ApiTest {
protected:
    static Q3Figure figure(int number)
    {
        Q3Figure f;
        EXPECT_EQ(q3fig_find(number, &f), 0) << "no Figure " << number;
        return f;
    }

    /// The vertices Q3 draws for a curve with kSegmentsPerSpan segments per
    /// span: a rendering loop in a view, a retained curve, and
    /// Q3Geometry_GetDecomposed on the loop's first pass.
    std::vector<TQ3Point3D> decompose(Q3FigCurve& curve)
    {
        std::vector<TQ3Point3D> vertices;
        const Q3FigRect frame = {-3.0f, -3.0f, 8.0f, 5.0f};
        Q3FigCanvas canvas;
        if (q3fig_canvas_open(&canvas, 64, 48, &frame, 1, q3fig_background()) != 0) {
            ADD_FAILURE() << "cannot open a canvas";
            return vertices;
        }
        TQ3NURBCurveData data = q3fig_curve_data(&curve);
        TQ3GeometryObject object = Q3NURBCurve_New(&data);
        EXPECT_NE(object, nullptr);
        if (object != nullptr && Q3View_StartRendering(canvas.view) == kQ3Success) {
            bool first = true;
            do {
                TQ3SubdivisionStyleData style{kQ3SubdivisionMethodConstant, kSegmentsPerSpan,
                                              kSegmentsPerSpan};
                EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, canvas.view), kQ3Success);
                if (first) {
                    TQ3GeometryObject polyline = Q3Geometry_GetDecomposed(object, canvas.view);
                    EXPECT_NE(polyline, nullptr);
                    TQ3PolyLineData lineData;
                    if (polyline != nullptr && Q3PolyLine_GetData(polyline, &lineData) == kQ3Success) {
                        for (unsigned long i = 0; i < lineData.numVertices; ++i)
                            vertices.push_back(lineData.vertices[i].point);
                        Q3PolyLine_EmptyData(&lineData);
                    }
                    if (polyline != nullptr)
                        Q3Object_Dispose(polyline);
                    first = false;
                }
                EXPECT_EQ(Q3Geometry_Submit(object, canvas.view), kQ3Success);
            } while (Q3View_EndRendering(canvas.view) == kQ3ViewStatusRetraverse);
        }
        if (object != nullptr)
            Q3Object_Dispose(object);
        q3fig_canvas_close(&canvas);
        return vertices;
    }

    /// Checks that Q3's vertices for a curve lie on the unit circle about the
    /// origin, go counterclockwise, and sweep `sweep` radians; the curve
    /// has `spans` knot spans.
    void expectOnUnitCircle(Q3FigCurve& curve, int spans, double sweep)
    {
        const std::vector<TQ3Point3D> vertices = decompose(curve);
        ASSERT_EQ(vertices.size(), std::size_t(spans) * std::size_t(kSegmentsPerSpan) + 1);
        double swept = 0.0;
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            const double x = vertices[i].x, y = vertices[i].y;
            EXPECT_NEAR(std::hypot(x, y), 1.0, kCircleTolerance) << "vertex " << i;
            EXPECT_EQ(vertices[i].z, 0.0f);
            if (i > 0) {
                const double px = vertices[i - 1].x, py = vertices[i - 1].y;
                double step = std::atan2(y, x) - std::atan2(py, px);
                if (step < -kPi)
                    step += 2 * kPi;
                EXPECT_GT(step, 0.0) << "vertex " << i << " does not go counterclockwise";
                swept += step;
            }
        }
        EXPECT_NEAR(swept, sweep, 1e-5);

        // The curve itself (the tests' evaluator, in double), densely.
        const TQ3NURBCurveData data = q3fig_curve_data(&curve);
        const double t0 = q3test::referenceDomainStart(data), t1 = q3test::referenceDomainEnd(data);
        for (int j = 0; j <= 1000; ++j) {
            const RefPoint p = q3test::referenceEvaluate(data, t0 + (t1 - t0) * j / 1000.0);
            EXPECT_NEAR(std::hypot(p.x, p.y), 1.0, kCircleTolerance) << "t index " << j;
        }
    }
};

TEST_F(ArticleFigureGeometry, EveryFigureCurveIsValidQ3Data)
{
    for (unsigned long index = 0; index < q3fig_count(); ++index) {
        Q3Figure f;
        ASSERT_EQ(q3fig_build(index, &f), 0);
        for (unsigned long c = 0; c < f.numCurves; ++c) {
            TQ3NURBCurveData data = q3fig_curve_data(&f.curves[c]);
            TQ3GeometryObject object = Q3NURBCurve_New(&data);
            EXPECT_NE(object, nullptr) << f.name << " curve " << c;
            if (object != nullptr)
                Q3Object_Dispose(object);
        }
    }
}

TEST_F(ArticleFigureGeometry, Figure19ArcLiesOnTheUnitCircle)
{
    Q3Figure f = figure(19);
    Q3FigCurve& arc = f.curves[f.numCurves - 1];
    ASSERT_EQ(arc.numPoints, 3u);
    // The construction: equilateral control triangle, inner weight cos 60.
    const double side01 = std::hypot(arc.points[1].x / arc.points[1].w - arc.points[0].x,
                                     arc.points[1].y / arc.points[1].w - arc.points[0].y);
    const double side02 =
        std::hypot(arc.points[2].x - arc.points[0].x, arc.points[2].y - arc.points[0].y);
    EXPECT_NEAR(side01, side02, 1e-6);
    EXPECT_EQ(arc.points[1].w, 0.5f);
    expectOnUnitCircle(arc, 1, 2 * kPi / 3);
    // And the guide circle drawn behind it is Figure 21's.
    expectOnUnitCircle(f.curves[0], 4, 2 * kPi);
}

TEST_F(ArticleFigureGeometry, Figure20IsOneCurveMakingTheWholeCircle)
{
    Q3Figure f = figure(20);
    ASSERT_EQ(f.numCurves, 1u);
    ASSERT_EQ(f.curves[0].numPoints, 7u);
    const float knots[10] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 3};
    EXPECT_TRUE(std::equal(knots, knots + 10, f.curves[0].knots));
    expectOnUnitCircle(f.curves[0], 3, 2 * kPi);
}

TEST_F(ArticleFigureGeometry, Figure21IsOneCurveMakingTheWholeCircle)
{
    Q3Figure f = figure(21);
    ASSERT_EQ(f.numCurves, 1u);
    ASSERT_EQ(f.curves[0].numPoints, 9u);
    const float knots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    EXPECT_TRUE(std::equal(knots, knots + 12, f.curves[0].knots));
    EXPECT_EQ(f.curves[0].points[1].w, float(std::sqrt(2.0) / 2.0));
    expectOnUnitCircle(f.curves[0], 4, 2 * kPi);
}

TEST_F(ArticleFigureGeometry, Figure22KnotInsertionLeavesTheCurveUnchanged)
{
    Q3Figure f = figure(22);
    ASSERT_EQ(f.numCurves, 2u);
    Q3FigCurve& before = f.curves[0];
    Q3FigCurve& after = f.curves[1];
    ASSERT_EQ(after.numPoints, before.numPoints + 1);
    const float knots[9] = {0, 1, 2, 3, 3.6f, 4, 5, 6, 7};
    EXPECT_TRUE(std::equal(knots, knots + 9, after.knots));

    // Evaluated directly: the same curve. The new control points are double
    // blends rounded to float (coordinates <= 6, so within 4e-7 each).
    const TQ3NURBCurveData a = q3fig_curve_data(&before);
    const TQ3NURBCurveData b = q3fig_curve_data(&after);
    for (int j = 0; j <= 1000; ++j) {
        const double t = 2.0 + 3.0 * j / 1000.0;
        const RefPoint p = q3test::referenceEvaluate(a, t), q = q3test::referenceEvaluate(b, t);
        EXPECT_LT(std::hypot(p.x - q.x, p.y - q.y), 2e-6) << "t = " << t;
    }

    // As Q3 draws it: the new curve's vertices (spans 2-3, 3-3.6, 3.6-4 and
    // 4-5, evenly divided) lie on the old curve.
    const std::vector<TQ3Point3D> vertices = decompose(after);
    const int perSpan = int(kSegmentsPerSpan);
    ASSERT_EQ(vertices.size(), std::size_t(4 * perSpan + 1));
    const double spanStarts[5] = {2.0, 3.0, double(3.6f), 4.0, 5.0};
    for (int span = 0; span < 4; ++span) {
        for (int s = 0; s <= perSpan; ++s) {
            const double t = spanStarts[span] + (spanStarts[span + 1] - spanStarts[span]) * s / perSpan;
            const TQ3Point3D& v = vertices[std::size_t(span * perSpan + s)];
            const RefPoint p = q3test::referenceEvaluate(a, t);
            EXPECT_LT(std::hypot(v.x - p.x, v.y - p.y), 4e-6) << "t = " << t;
        }
    }

    // The article's picture: the two moved points sit on the old polygon's
    // legs B1-B2 and B2-B3; the others are the old points.
    using P = TQ3RationalPoint4D;
    auto cross = [](const P& o, const P& p, const P& q) {
        return (double(p.x) - o.x) * (double(q.y) - o.y) - (double(p.y) - o.y) * (double(q.x) - o.x);
    };
    EXPECT_NEAR(cross(before.points[1], before.points[2], after.points[2]), 0.0, 1e-5);
    EXPECT_NEAR(cross(before.points[2], before.points[3], after.points[3]), 0.0, 1e-5);
    for (int j : {0, 1}) {
        EXPECT_EQ(after.points[j].x, before.points[j].x);
        EXPECT_EQ(after.points[j].y, before.points[j].y);
    }
    for (int j : {4, 5}) {
        EXPECT_EQ(after.points[j].x, before.points[j - 1].x);
        EXPECT_EQ(after.points[j].y, before.points[j - 1].y);
    }
}

// x and y of `got` within `tolerance` of `want`'s.
template <class Got, class Want>
void expectNearXY(const Got& got, const Want& want, double tolerance)
{
    EXPECT_NEAR(got.x, want.x, tolerance);
    EXPECT_NEAR(got.y, want.y, tolerance);
}

TEST_F(ArticleFigureGeometry, Figure13CurveStartsAtItsFirstControlPoint)
{
    Q3Figure f = figure(13);
    const TQ3RationalPoint4D& b0 = f.curves[0].points[0];
    expectNearXY(q3test::referenceEvaluate(q3fig_curve_data(&f.curves[0]), 0.0), b0, 1e-12);
    const std::vector<TQ3Point3D> vertices = decompose(f.curves[0]);
    ASSERT_FALSE(vertices.empty());
    // A float vertex of the exact start (coordinates <= 1).
    expectNearXY(vertices.front(), b0, 1e-7);

    // Figure 9's uniform curve, by contrast, starts halfway along B0-B1.
    Q3Figure uniform = figure(9);
    const std::vector<TQ3Point3D> floating = decompose(uniform.curves[0]);
    ASSERT_FALSE(floating.empty());
    const TQ3RationalPoint4D& b1 = uniform.curves[0].points[1];
    EXPECT_NEAR(floating.front().x, 0.5 * (b0.x + b1.x), 1e-6);
    EXPECT_NEAR(floating.front().y, 0.5 * (b0.y + b1.y), 1e-6);
}

TEST_F(ArticleFigureGeometry, Figure15CurvePassesThroughB2AtTheDoubleKnot)
{
    Q3Figure f = figure(15);
    const TQ3RationalPoint4D& b2 = f.curves[0].points[2];
    expectNearXY(q3test::referenceEvaluate(q3fig_curve_data(&f.curves[0]), 3.0), b2, 1e-12);
    // t = 3 ends the first span (2 to 3): vertex kSegmentsPerSpan.
    const std::vector<TQ3Point3D> vertices = decompose(f.curves[0]);
    ASSERT_EQ(vertices.size(), std::size_t(2 * kSegmentsPerSpan + 1));
    const TQ3Point3D& v = vertices[std::size_t(kSegmentsPerSpan)];
    expectNearXY(v, b2, 1e-6);
}

/// The closest the curve comes to a point, over 2001 parameters.
double closestApproach(Q3FigCurve& curve, const TQ3RationalPoint4D& point)
{
    const TQ3NURBCurveData data = q3fig_curve_data(&curve);
    const double t0 = q3test::referenceDomainStart(data), t1 = q3test::referenceDomainEnd(data);
    const double px = point.x / point.w, py = point.y / point.w;
    double closest = 1e300;
    for (int j = 0; j <= 2000; ++j) {
        const RefPoint p = q3test::referenceEvaluate(data, t0 + (t1 - t0) * j / 2000.0);
        closest = std::min(closest, std::hypot(p.x - px, p.y - py));
    }
    return closest;
}

TEST_F(ArticleFigureGeometry, Figure11And16PullTheCurveTowardsTheirControlPoints)
{
    Q3Figure uniform = figure(9), nonuniform = figure(11), weighted = figure(16);
    const TQ3RationalPoint4D* b = q3fig_free_form_points();
    // Narrow knot intervals pull Figure 11 towards B2 and B3.
    EXPECT_LT(closestApproach(nonuniform.curves[0], b[2]), closestApproach(uniform.curves[0], b[2]));
    EXPECT_LT(closestApproach(nonuniform.curves[0], b[3]), closestApproach(uniform.curves[0], b[3]));
    // Raising B2's weight pulls Figure 16's curve (its second) towards B2.
    ASSERT_EQ(weighted.numCurves, 2u);
    EXPECT_GT(weighted.curves[1].points[2].w, 1.0f);
    EXPECT_LT(closestApproach(weighted.curves[1], b[2]), closestApproach(uniform.curves[0], b[2]));
}

TEST_F(ArticleFigureGeometry, Figure18ArcsRiseWithTheInnerWeight)
{
    Q3Figure f = figure(18);
    ASSERT_EQ(f.numCurves, 3u);
    double previous = 0.0;
    for (unsigned long c = 0; c < 3; ++c) {
        const TQ3NURBCurveData data = q3fig_curve_data(&f.curves[c]);
        const double w = f.curves[c].points[1].w;
        // At t = 1/2 the quadratic basis is (1/4, 1/2, 1/4), so the apex
        // of the arc over (0, 0), (1.5, 2.5), (3, 0) is at y = 2.5 w / (1 + w).
        const RefPoint apex = q3test::referenceEvaluate(data, 0.5);
        EXPECT_NEAR(apex.y, 2.5 * w / (1.0 + w), 1e-6);
        EXPECT_GT(apex.y, previous);
        previous = apex.y;
    }
}

TEST_F(ArticleFigureGeometry, BasisPlotsAreTheBasisFunctions)
{
    for (int number : {7, 10, 12, 14}) {
        Q3Figure plot = figure(number);
        ASSERT_EQ(plot.numCurves, 5u);
        // The article's knot vector: Figure 7 goes with Figure 9, and so on.
        Q3Figure curveFigure = figure(number == 7 ? 9 : number + 1);
        const float* knots = curveFigure.curves[0].knots;
        for (unsigned long i = 0; i < 5; ++i) {
            const TQ3NURBCurveData data = q3fig_curve_data(&plot.curves[i]);
            const double t0 = q3test::referenceDomainStart(data), t1 = q3test::referenceDomainEnd(data);
            EXPECT_EQ(t0, knots[0]);
            EXPECT_EQ(t1, knots[7]);
            for (int j = 0; j <= 280; ++j) {
                const double t = t0 + (t1 - t0) * j / 280.0;
                const RefPoint p = q3test::referenceEvaluate(data, t);
                // The Greville abscissae reproduce t (linear precision)...
                EXPECT_NEAR(p.x, t, 1e-9) << "Figure " << number << " N" << i << " t = " << t;
                // ...and the height is N(i,3)(t) of the article's knots.
                const double expected = q3test::referenceBasis(knots, 8, i, 3, t, knots[7] + 1.0);
                EXPECT_NEAR(p.y, expected, 1e-9) << "Figure " << number << " N" << i << " t = " << t;
            }
        }
    }
}

} // namespace
