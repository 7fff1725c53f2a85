// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The article's code, run as printed: Listing 1 (retained mode), the
// immediate-mode and subdivision-style loops, Listing 2 (InsertKnot) and
// Listing 3 (BezierToNURBCurve), each compiled from the article's text by a
// C wrapper (ListingWrappers.h) and checked here by its pixels, a golden
// image and, for Listings 2 and 3, the numbers it produces.

#include "Golden.h"
#include "Q3ApiTest.h"
#include "ReferenceNurbs.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DView.h"
#include "figures.h"

#if Q3_HAVE_LISTINGS
#include "ListingWrappers.h"
#endif

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <vector>

namespace {

using q3test::RefPoint;
using q3test::RgbaImage;

constexpr unsigned long kWidth = 320;
constexpr unsigned long kHeight = 240;
constexpr TQ3ColorRGB kDark = {0.10f, 0.12f, 0.16f};

// Listing 1's curve (its numbers, written out here as the curveData the
// immediate-mode and subdivision-style fragments expect to exist).
TQ3RationalPoint4D gListing1Points[4] = {{0, 0, 0, 1}, {1, 1, 0, 1}, {2, 0, 0, 1}, {3, 1, 0, 1}};
float gListing1Knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
// Listing 1's control points span x 0 to 3, y 0 to 1.
constexpr Q3FigRect kListing1Frame = {-0.25f, -0.5f, 3.25f, 1.5f};

TQ3NURBCurveData listing1Curve()
{
    return TQ3NURBCurveData{4, 4, gListing1Points, gListing1Knots, nullptr};
}

/// An image and where the plane lands in it.
struct Rendered {
    RgbaImage image;
    Q3FigCanvas mapping{};  // frame and size only; the view is gone

    void pixelOf(double x, double y, float* px, float* py) const
    {
        q3fig_canvas_pixel(&mapping, float(x), float(y), px, py);
    }
};

/// Opens a dark canvas on frame, lets draw() run its own rendering loop in
/// the canvas's view, and returns the pixels.
Rendered renderWith(const Q3FigRect& frame, const std::function<void(TQ3ViewObject)>& draw)
{
    Rendered result;
    result.image = RgbaImage(int(kWidth), int(kHeight));
    Q3FigCanvas canvas;
    if (q3fig_canvas_open(&canvas, kWidth, kHeight, &frame, 1, kDark) != 0) {
        ADD_FAILURE() << "cannot open a canvas";
        return result;
    }
    draw(canvas.view);
    q3fig_canvas_rgba(&canvas, result.image.pixels.data());
    result.mapping = canvas;
    result.mapping.view = nullptr;
    result.mapping.argb = nullptr;
    q3fig_canvas_close(&canvas);
    return result;
}

/// The usual loop around a submit function; expects it to finish.
void renderingLoop(TQ3ViewObject view, const std::function<void(int pass)>& submit)
{
    ASSERT_EQ(Q3View_StartRendering(view), kQ3Success);
    TQ3ViewStatus status;
    int pass = 0;
    do {
        submit(pass++);
        status = Q3View_EndRendering(view);
    } while (status == kQ3ViewStatusRetraverse);
    EXPECT_EQ(status, kQ3ViewStatusDone);
}

bool isWhite(const unsigned char* p) { return p[0] == 255 && p[1] == 255 && p[2] == 255; }

bool sameColor(const unsigned char* a, const unsigned char* b) { return std::memcmp(a, b, 4) == 0; }

/// Whether a pixel within `radius` of (px, py) satisfies pred.
bool anyNear(const RgbaImage& image, float px, float py, int radius,
             const std::function<bool(const unsigned char*)>& pred)
{
    const int cx = int(std::floor(px)), cy = int(std::floor(py));
    for (int y = cy - radius; y <= cy + radius; ++y) {
        for (int x = cx - radius; x <= cx + radius; ++x) {
            if (x >= 0 && y >= 0 && x < image.width && y < image.height && pred(image.at(x, y)))
                return true;
        }
    }
    return false;
}

/// Pixels unlike the background (the top-left corner's colour).
long inkPixels(const RgbaImage& image)
{
    long count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            count += sameColor(image.at(x, y), image.at(0, 0)) ? 0 : 1;
    return count;
}

/// Ink pixels of a with no ink pixel of b in their 3 x 3 neighbourhood.
long inkWithoutNeighbour(const RgbaImage& a, const RgbaImage& b)
{
    long count = 0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            if (sameColor(a.at(x, y), a.at(0, 0)))
                continue;
            const bool matched = anyNear(b, float(x), float(y), 1, [&](const unsigned char* p) {
                return !sameColor(p, b.at(0, 0));
            });
            count += matched ? 0 : 1;
        }
    }
    return count;
}

/// A figure of one curve, framed on its control points, drawn with the
/// figures' look (blue curve; with controls, gray polygon and red markers).
Q3Figure figureOf(const TQ3NURBCurveData& data, bool controls)
{
    Q3Figure figure;
    std::memset(&figure, 0, sizeof figure);
    figure.numCurves = 1;
    Q3FigCurve& curve = figure.curves[0];
    EXPECT_LE(data.numPoints, static_cast<unsigned long>(Q3FIG_MAX_POINTS));
    curve.order = data.order;
    curve.numPoints = std::min<unsigned long>(data.numPoints, Q3FIG_MAX_POINTS);
    std::copy(data.controlPoints, data.controlPoints + curve.numPoints, curve.points);
    std::copy(data.knots, data.knots + curve.numPoints + curve.order, curve.knots);
    curve.drawCurve = 1;
    curve.drawControls = controls ? 1 : 0;
    curve.curveColor = {0.08f, 0.24f, 0.62f};
    curve.polygonColor = {0.60f, 0.60f, 0.60f};
    curve.pointColor = {0.82f, 0.08f, 0.08f};
    float xMin = 1e30f, xMax = -1e30f, yMin = 1e30f, yMax = -1e30f;
    for (unsigned long i = 0; i < curve.numPoints; ++i) {
        const float x = curve.points[i].x / curve.points[i].w;
        const float y = curve.points[i].y / curve.points[i].w;
        xMin = std::min(xMin, x);
        xMax = std::max(xMax, x);
        yMin = std::min(yMin, y);
        yMax = std::max(yMax, y);
    }
    figure.frame = Q3FigRect{xMin - 0.5f, yMin - 0.5f, xMax + 0.5f, yMax + 0.5f};
    return figure;
}

RgbaImage renderFigure(const Q3Figure& figure)
{
    RgbaImage image(static_cast<int>(kWidth), static_cast<int>(kHeight));
    EXPECT_EQ(q3fig_render(&figure, kWidth, kHeight, image.pixels.data()), 0);
    return image;
}

double distance(const RefPoint& a, const RefPoint& b)
{
    return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

/// The largest distance between two curves over n + 1 parameters spread
/// evenly across the domain of a (which b must share).
double largestDistance(const TQ3NURBCurveData& a, const TQ3NURBCurveData& b, int n)
{
    const double t0 = q3test::referenceDomainStart(a), t1 = q3test::referenceDomainEnd(a);
    double largest = 0.0;
    for (int j = 0; j <= n; ++j) {
        const double t = t0 + (t1 - t0) * j / n;
        const RefPoint p = q3test::referenceEvaluate(a, t), q = q3test::referenceEvaluate(b, t);
        largest = std::max(largest, distance(p, q));
    }
    return largest;
}

/// A Bezier curve by de Casteljau's construction (independent of B-splines).
RefPoint deCasteljau(std::vector<RefPoint> points, double t)
{
    for (std::size_t level = points.size() - 1; level > 0; --level)
        for (std::size_t i = 0; i < level; ++i)
            points[i] = RefPoint{(1 - t) * points[i].x + t * points[i + 1].x,
                                 (1 - t) * points[i].y + t * points[i + 1].y,
                                 (1 - t) * points[i].z + t * points[i + 1].z};
    return points[0];
}

class ArticleListing : public q3test::Q3ApiTest {
protected:
    void SetUp() override
    {
        Q3ApiTest::SetUp();
#if !Q3_HAVE_LISTINGS
        GTEST_SKIP() << "the article's listings are not in " << Q3_LISTINGS_DIR_TEXT
                     << " (configure with -DQ3_LISTINGS_DIR=...)";
#endif
    }
};

#if Q3_HAVE_LISTINGS

/// Listing 1 on a dark canvas (it draws with the default white).
Rendered renderListing1()
{
    return renderWith(kListing1Frame, [](TQ3ViewObject view) { q3listing1_retained(view); });
}

/// Checks that an image shows Listing 1's curve, white on the background:
/// near every one of 21 points of the curve (within 2 pixels: the default
/// screen-space subdivision of 20-pixel segments strays less than a pixel
/// from this curve) there is a white pixel; two points 0.4 units (about 36
/// pixels) off the curve are background; nothing but white is drawn; and
/// the ink is about one pixel per pixel of arc length (the curve is about
/// 3.6 units, 330 pixels, long).
void expectListing1Curve(const Rendered& r)
{
    const TQ3NURBCurveData curve = listing1Curve();
    for (int j = 0; j <= 20; ++j) {
        const RefPoint p = q3test::referenceEvaluate(curve, j / 20.0);
        float px, py;
        r.pixelOf(p.x, p.y, &px, &py);
        EXPECT_TRUE(anyNear(r.image, px, py, 2, isWhite)) << "no curve near t = " << j / 20.0;
    }
    for (double y : {0.1, 0.9}) {
        float px, py;
        r.pixelOf(1.5, y, &px, &py);
        EXPECT_FALSE(anyNear(r.image, px, py, 2, [&](const unsigned char* p) {
            return !sameColor(p, r.image.at(0, 0));
        })) << "ink at (1.5, " << y << "), off the curve";
    }
    long white = 0, other = 0;
    for (int y = 0; y < r.image.height; ++y) {
        for (int x = 0; x < r.image.width; ++x) {
            const unsigned char* p = r.image.at(x, y);
            if (isWhite(p))
                ++white;
            else if (!sameColor(p, r.image.at(0, 0)))
                ++other;
        }
    }
    EXPECT_EQ(other, 0);
    EXPECT_GT(white, 250);
    EXPECT_LT(white, 600);
}

TEST_F(ArticleListing, Listing1DrawsTheCurveInRetainedMode)
{
    const Rendered r = renderListing1();
    expectListing1Curve(r);
    EXPECT_TRUE(q3test::matchesGolden("listing1", r.image));
}

TEST_F(ArticleListing, ImmediateModeLoopDrawsWhatListing1Draws)
{
    const TQ3NURBCurveData curve = listing1Curve();
    const Rendered immediate =
        renderWith(kListing1Frame, [&](TQ3ViewObject view) { q3listing_immediate_mode(view, &curve); });
    expectListing1Curve(immediate);
    // QD3DGeometry.h: immediate mode draws exactly what retained mode draws.
    EXPECT_EQ(q3test::countDifferingPixels(immediate.image, renderListing1().image), 0);
    EXPECT_TRUE(q3test::matchesGolden("immediate_mode", immediate.image));
}

TEST_F(ArticleListing, SubdivisionStyleLoopDrawsFiveSegmentsPerSpan)
{
    TQ3NURBCurveData curve = listing1Curve();
    const Rendered listing = renderWith(
        kListing1Frame, [&](TQ3ViewObject view) { q3listing_subdivision_style(view, &curve); });

    // The segments a five-per-span style gives: one span, so six vertices at
    // t = 0, 0.2, ..., 1. Drawn as a plain polyline they must give exactly
    // the listing's pixels.
    TQ3GeometryObject retained = Q3NURBCurve_New(&curve);
    ASSERT_NE(retained, nullptr);
    std::vector<TQ3Point3D> vertices;
    const Rendered polyline = renderWith(kListing1Frame, [&](TQ3ViewObject view) {
        renderingLoop(view, [&](int) {
            TQ3SubdivisionStyleData style{kQ3SubdivisionMethodConstant, 5.0f, 5.0f};
            ASSERT_EQ(Q3SubdivisionStyle_Submit(&style, view), kQ3Success);
            TQ3GeometryObject decomposed = Q3Geometry_GetDecomposed(retained, view);
            ASSERT_NE(decomposed, nullptr);
            EXPECT_EQ(Q3Geometry_Submit(decomposed, view), kQ3Success);
            TQ3PolyLineData data;
            ASSERT_EQ(Q3PolyLine_GetData(decomposed, &data), kQ3Success);
            vertices.clear();
            for (unsigned long i = 0; i < data.numVertices; ++i)
                vertices.push_back(data.vertices[i].point);
            Q3PolyLine_EmptyData(&data);
            Q3Object_Dispose(decomposed);
        });
    });
    Q3Object_Dispose(retained);

    ASSERT_EQ(vertices.size(), 6u);
    for (std::size_t j = 0; j < vertices.size(); ++j) {
        const RefPoint p = q3test::referenceEvaluate(curve, j / 5.0);
        // Vertices are floats: rounding one coordinate of size <= 3 errs by
        // at most 3 * 2^-24, about 2e-7.
        EXPECT_NEAR(vertices[j].x, p.x, 1e-6) << "vertex " << j;
        EXPECT_NEAR(vertices[j].y, p.y, 1e-6) << "vertex " << j;
    }
    EXPECT_EQ(q3test::countDifferingPixels(listing.image, polyline.image), 0);

    // The pixels tell segment counts apart: six per span looks different.
    const Rendered six = renderWith(kListing1Frame, [&](TQ3ViewObject view) {
        renderingLoop(view, [&](int) {
            TQ3SubdivisionStyleData style{kQ3SubdivisionMethodConstant, 6.0f, 6.0f};
            Q3SubdivisionStyle_Submit(&style, view);
            Q3NURBCurve_Submit(&curve, view);
        });
    });
    EXPECT_GT(q3test::countDifferingPixels(listing.image, six.image), 20);
    EXPECT_TRUE(q3test::matchesGolden("subdivision_style", listing.image));
}

/// Figure 9's curve: order 3, five points, knots {0, ..., 7}.
Q3Figure figure9()
{
    Q3Figure figure;
    EXPECT_EQ(q3fig_find(9, &figure), 0);
    return figure;
}

/// What Listing 2 returns, freed with q3listing_free_curve.
using ListingCurve = std::unique_ptr<TQ3NURBCurveData, void (*)(TQ3NURBCurveData*)>;

/// Listing 2's knot insertion of tNew into `curve`.
ListingCurve listing2InsertKnot(TQ3NURBCurveData& curve, float tNew)
{
    return ListingCurve(q3listing2_insert_knot(&curve, tNew), q3listing_free_curve);
}

TEST_F(ArticleListing, Listing2InsertKnotKeepsTheCurveUnchanged)
{
    Q3Figure figure = figure9();
    TQ3NURBCurveData before = q3fig_curve_data(&figure.curves[0]);
    for (float tNew : {3.6f, 2.5f, 3.0f, 4.75f}) {
        SCOPED_TRACE(tNew);
        const ListingCurve after = listing2InsertKnot(before, tNew);
        ASSERT_NE(after.get(), nullptr);
        EXPECT_EQ(after->order, 3u);
        ASSERT_EQ(after->numPoints, 6u);
        std::vector<float> expectedKnots(before.knots, before.knots + 8);
        expectedKnots.insert(std::upper_bound(expectedKnots.begin(), expectedKnots.end(), tNew), tNew);
        EXPECT_EQ(std::vector<float>(after->knots, after->knots + 9), expectedKnots);
        EXPECT_EQ(after->curveAttributeSet, nullptr);

        // A valid curve: Q3 accepts it (the fixture fails on any error).
        TQ3GeometryObject object = Q3NURBCurve_New(after.get());
        EXPECT_NE(object, nullptr);
        if (object != nullptr)
            Q3Object_Dispose(object);

        // The same shape. The listing blends float control points with a
        // float alpha: each new coordinate (size <= 6) carries a few
        // roundings of 6 * 2^-24 = 4e-7; 1e-5 leaves a wide margin while a
        // wrong blend moves the curve by tenths.
        EXPECT_LT(largestDistance(before, *after, 600), 1e-5);
    }
}

TEST_F(ArticleListing, Listing2AgreesWithTheFiguresKnotInsertion)
{
    Q3Figure figure = figure9();
    TQ3NURBCurveData before = q3fig_curve_data(&figure.curves[0]);
    const ListingCurve listing = listing2InsertKnot(before, 3.6f);
    ASSERT_NE(listing.get(), nullptr);
    Q3FigCurve ours;
    ASSERT_EQ(q3fig_insert_knot(&figure.curves[0], 3.6f, &ours), 0);
    ASSERT_EQ(ours.numPoints, listing->numPoints);
    for (unsigned long j = 0; j < ours.numPoints; ++j) {
        // Ours blends in double, the listing in float: within a few float
        // roundings of coordinates <= 6 (about 4e-7 each).
        EXPECT_NEAR(ours.points[j].x, listing->controlPoints[j].x, 2e-6) << j;
        EXPECT_NEAR(ours.points[j].y, listing->controlPoints[j].y, 2e-6) << j;
        EXPECT_NEAR(ours.points[j].w, listing->controlPoints[j].w, 2e-6) << j;
    }
    for (unsigned long j = 0; j < ours.numPoints + ours.order; ++j)
        EXPECT_EQ(ours.knots[j], listing->knots[j]) << j;
}

TEST_F(ArticleListing, Listing2ResultRendersLikeTheOriginal)
{
    Q3Figure figure = figure9();
    TQ3NURBCurveData before = q3fig_curve_data(&figure.curves[0]);
    const ListingCurve after = listing2InsertKnot(before, 3.6f);
    ASSERT_NE(after.get(), nullptr);

    // Same curve, different polylines (the new knot splits a span, so the
    // vertices fall elsewhere): each curve pixel of one image must have one
    // of the other within one pixel, both ways.
    Q3Figure plainBefore = figureOf(before, false);
    Q3Figure plainAfter = figureOf(*after, false);
    plainAfter.frame = plainBefore.frame;
    const RgbaImage a = renderFigure(plainBefore);
    const RgbaImage b = renderFigure(plainAfter);
    EXPECT_GT(inkPixels(a), 150);
    EXPECT_EQ(inkWithoutNeighbour(a, b), 0);
    EXPECT_EQ(inkWithoutNeighbour(b, a), 0);

    // The golden: the new curve with its six control points.
    Q3Figure withControls = figureOf(*after, true);
    withControls.frame = plainBefore.frame;
    EXPECT_TRUE(q3test::matchesGolden("listing2_insert_knot", renderFigure(withControls)));
}

TEST_F(ArticleListing, Listing2DuplicatesTheAttributeSet)
{
    Q3Figure figure = figure9();
    TQ3NURBCurveData before = q3fig_curve_data(&figure.curves[0]);
    before.curveAttributeSet = Q3AttributeSet_New();
    ASSERT_NE(before.curveAttributeSet, nullptr);
    const TQ3ColorRGB fuchsia = {1.0f, 0.0f, 1.0f};
    ASSERT_EQ(Q3AttributeSet_Add(before.curveAttributeSet, kQ3AttributeTypeDiffuseColor, &fuchsia),
              kQ3Success);

    const ListingCurve after = listing2InsertKnot(before, 3.6f);
    ASSERT_NE(after.get(), nullptr);
    ASSERT_NE(after->curveAttributeSet, nullptr);
    EXPECT_NE(after->curveAttributeSet, before.curveAttributeSet);
    TQ3ColorRGB color{};
    EXPECT_EQ(Q3AttributeSet_Get(after->curveAttributeSet, kQ3AttributeTypeDiffuseColor, &color),
              kQ3Success);
    EXPECT_EQ(color.r, 1.0f);
    EXPECT_EQ(color.g, 0.0f);
    EXPECT_EQ(color.b, 1.0f);
    Q3Object_Dispose(before.curveAttributeSet);
}

/// Runs Listing 3 on a Bezier curve and checks its NURB data: the Bezier
/// points with w = 1, order = number of points, knots k zeros then k ones,
/// no attribute set; and that it evaluates to the Bezier curve.
void expectBezierConversion(const std::vector<RefPoint>& bezier, const char* golden)
{
    std::vector<float> xyz;
    for (const RefPoint& p : bezier) {
        xyz.push_back(float(p.x));
        xyz.push_back(float(p.y));
        xyz.push_back(float(p.z));
    }
    const unsigned k = unsigned(bezier.size());
    TQ3NURBCurveData* nurb = q3listing3_bezier_to_nurb(k, xyz.data());
    ASSERT_NE(nurb, nullptr);
    EXPECT_EQ(nurb->order, k);
    ASSERT_EQ(nurb->numPoints, k);
    for (unsigned i = 0; i < k; ++i) {
        EXPECT_EQ(nurb->controlPoints[i].x, xyz[3 * i]);
        EXPECT_EQ(nurb->controlPoints[i].y, xyz[3 * i + 1]);
        EXPECT_EQ(nurb->controlPoints[i].z, xyz[3 * i + 2]);
        EXPECT_EQ(nurb->controlPoints[i].w, 1.0f);
    }
    for (unsigned i = 0; i < 2 * k; ++i)
        EXPECT_EQ(nurb->knots[i], i < k ? 0.0f : 1.0f) << "knot " << i;
    EXPECT_EQ(nurb->curveAttributeSet, nullptr);

    // Same curve as de Casteljau's (points exact in float, so only the
    // double evaluation's rounding separates them).
    for (int j = 0; j <= 100; ++j)
        EXPECT_LT(distance(q3test::referenceEvaluate(*nurb, j / 100.0), deCasteljau(bezier, j / 100.0)),
                  1e-12);

    TQ3GeometryObject object = Q3NURBCurve_New(nurb);
    EXPECT_NE(object, nullptr);
    if (object != nullptr)
        Q3Object_Dispose(object);

    const Q3Figure figure = figureOf(*nurb, true);
    const RgbaImage image = renderFigure(figure);
    Q3FigCanvas mapping;
    std::memset(&mapping, 0, sizeof mapping);
    mapping.width = kWidth;
    mapping.height = kHeight;
    q3fig_fit_frame(&figure.frame, kWidth, kHeight, &mapping.frame);
    const unsigned char curveBlue[3] = {20, 61, 158};  // 0.08, 0.24, 0.62 rounded
    for (double t : {0.25, 0.5, 0.75}) {
        const RefPoint p = deCasteljau(bezier, t);
        float px, py;
        q3fig_canvas_pixel(&mapping, float(p.x), float(p.y), &px, &py);
        EXPECT_TRUE(anyNear(image, px, py, 1, [&](const unsigned char* q) {
            return std::memcmp(q, curveBlue, 3) == 0;
        })) << "no curve pixel near the Bezier point at t = " << t;
    }
    EXPECT_TRUE(q3test::matchesGolden(golden, image));
    q3listing_free_curve(nurb);
}

TEST_F(ArticleListing, Listing3ConvertsACubicBezierCurve)
{
    expectBezierConversion({{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}}, "listing3_bezier_cubic");
}

TEST_F(ArticleListing, Listing3ConvertsAQuadraticBezierCurve)
{
    expectBezierConversion({{0, 0, 0}, {2, 3, 0}, {4, 0.5, 0}}, "listing3_bezier_quadratic");
}

#else // !Q3_HAVE_LISTINGS: the same tests, each reporting SKIPPED from SetUp.

TEST_F(ArticleListing, Listing1DrawsTheCurveInRetainedMode) {}
TEST_F(ArticleListing, ImmediateModeLoopDrawsWhatListing1Draws) {}
TEST_F(ArticleListing, SubdivisionStyleLoopDrawsFiveSegmentsPerSpan) {}
TEST_F(ArticleListing, Listing2InsertKnotKeepsTheCurveUnchanged) {}
TEST_F(ArticleListing, Listing2AgreesWithTheFiguresKnotInsertion) {}
TEST_F(ArticleListing, Listing2ResultRendersLikeTheOriginal) {}
TEST_F(ArticleListing, Listing2DuplicatesTheAttributeSet) {}
TEST_F(ArticleListing, Listing3ConvertsACubicBezierCurve) {}
TEST_F(ArticleListing, Listing3ConvertsAQuadraticBezierCurve) {}

#endif

} // namespace
