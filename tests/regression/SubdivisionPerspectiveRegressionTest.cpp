// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Screen-space subdivision of curves that reach the eye of a perspective
// camera: behind it, through it, across the plane it stands in. Such curves
// must be subdivided and drawn in bounded work, with a segment count set by
// what the camera can show (the curve beyond the hither plane) and not by how
// close to the eye the subdivision happens to probe; and what is drawn must be
// the visible part of the curve, not a wrapped-around image of the part
// behind the eye. Checked against SubdivisionReference.h's projection and
// evaluator. docs/subdivision.md describes the behaviour.

#include "PixmapViewTest.h"
#include "Q3ApiTest.h"
#include "SubdivisionReference.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DRenderer.h"
#include "QD3DStyle.h"
#include "QD3DView.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace q3test::subdivision;

constexpr unsigned long kWidth = 128;
constexpr unsigned long kHeight = 96;
constexpr float kHither = 0.5f;
constexpr unsigned kSeed = 20260414u;

/// Tessellate.h's probes: max(order, 8) per span. Where a probe interval has
/// an end without an image it becomes one unmeasured segment.
std::size_t probesPerSpan(unsigned long order)
{
    return std::max<std::size_t>(order, 8);
}

/// Random curve `index` around the eye: every order in turn, clamped every
/// other one, knots repeated with probability 0.3, extent 4.
RandomCurveOptions aroundTheEye(int index)
{
    RandomCurveOptions options;
    options.order = 2 + unsigned(index % 15);
    options.clamped = index % 2 == 0;
    options.repeatProbability = 0.3L;
    options.extent = 4;
    return options;
}

class SubdivisionPerspectiveRegressionTest : public q3test::PixmapViewTest {
protected:
    SubdivisionPerspectiveRegressionTest() : PixmapViewTest(kWidth, kHeight) {}

    void SetUp() override
    {
        PixmapViewTest::SetUp();
        m_camera = eyeAtOrigin(kHither);
        useCamera(Q3ViewAngleAspectCamera_New(&m_camera));
    }

    ScreenMap screen() const { return ScreenMap(m_camera, {{0, 0}, {float(kWidth), float(kHeight)}}); }

    /// Draws the curve (retained and immediate) and decomposes it, in one
    /// rendering loop under screen-space subdivision with c1.
    std::vector<Vec3> render(Curve& curve, float c1)
    {
        const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodScreenSpace, c1, c1};
        TQ3NURBCurveData data = curve.data();
        TQ3GeometryObject object = Q3NURBCurve_New(&data);
        EXPECT_NE(object, nullptr);
        std::vector<Vec3> out;
        EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, m_view), kQ3Success);
        EXPECT_EQ(Q3Geometry_Submit(object, m_view), kQ3Success);
        EXPECT_EQ(Q3NURBCurve_Submit(&data, m_view), kQ3Success);
        TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(object, m_view);
        EXPECT_NE(polyLine, nullptr);
        if (polyLine != nullptr) {
            TQ3PolyLineData lines{};
            EXPECT_EQ(Q3PolyLine_GetData(polyLine, &lines), kQ3Success);
            for (unsigned long i = 0; i < lines.numVertices; ++i)
                out.push_back(toVec(lines.vertices[i].point));
            Q3PolyLine_EmptyData(&lines);
            Q3Object_Dispose(polyLine);
        }
        EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
        Q3Object_Dispose(object);
        return out;
    }

    /// The most segments a screen-space polyline of `curve` may have: 1.2
    /// times its pixel length beyond the hither plane over c1 (the near-
    /// minimal bound the property test uses), plus per span one segment per
    /// probe interval that cannot be measured and twice that again for the
    /// runs they split the span into and for march steps that meet a point
    /// without an image.
    std::size_t segmentBound(const Curve& curve, float c1) const
    {
        const ScreenMap map = screen();
        const DenseSamples samples = denseSamples(curve, 512);
        Real visible = 0;
        for (std::size_t i = 1; i < samples.local.size(); ++i) {
            const Vec3& a = samples.local[i - 1];
            const Vec3& b = samples.local[i];
            Real ax, ay, bx, by;
            if (map.depth(a) >= kHither && map.depth(b) >= kHither && map.map(a, ax, ay) && map.map(b, bx, by))
                visible += std::hypot(bx - ax, by - ay);
        }
        const std::size_t spans = curve.spans().size();
        return std::size_t(1.2L * visible / c1) + spans * (3 * probesPerSpan(curve.order) + 1);
    }

    /// Every vertex on the curve, the domain ends first and last.
    static void expectOnCurve(const Curve& curve, const std::vector<Vec3>& v, const std::string& what)
    {
        ASSERT_GE(v.size(), 2u) << what;
        const Real size = curve.scale();
        const DenseSamples samples = denseSamples(curve, 64);
        CurveLocator locator(curve, samples, 1e-6L * size);
        EXPECT_LE(distance(v.front(), evaluate(curve, curve.domainStart())), 1e-6L * size) << what;
        EXPECT_LE(distance(v.back(), evaluate(curve, curve.domainEnd())), 1e-6L * size) << what;
        for (std::size_t i = 0; i < v.size(); ++i)
            EXPECT_LE(locator.distanceOf(v[i]), 1e-6L * size) << what << " vertex " << i;
    }

    bool lit(unsigned long x, unsigned long y) const
    {
        const unsigned char* p = &m_memory[(y * kWidth + x) * 4];
        return p[1] > 127 || p[2] > 127 || p[3] > 127;
    }

    std::size_t litPixels() const
    {
        std::size_t count = 0;
        for (unsigned long y = 0; y < kHeight; ++y)
            for (unsigned long x = 0; x < kWidth; ++x)
                count += lit(x, y) ? 1 : 0;
        return count;
    }

    TQ3ViewAngleAspectCameraData m_camera{};
};

Curve line(const Vec3& from, const Vec3& to)
{
    Curve c;
    c.order = 2;
    c.clamped = true;
    c.points = {{float(from.x), float(from.y), float(from.z), 1}, {float(to.x), float(to.y), float(to.z), 1}};
    c.knots = {0, 0, 1, 1};
    return c;
}

// Random curves of every order with all their control points behind the
// eye: nothing has an image, so every probe interval is one unmeasured
// segment and nothing is drawn.
TEST_F(SubdivisionPerspectiveRegressionTest, ACurveBehindTheEyeGetsOneSegmentPerProbeIntervalAndDrawsNothing)
{
    std::mt19937 rng(kSeed);
    for (unsigned long order = 2; order <= 16; ++order) {
        RandomCurveOptions options;
        options.order = order;
        options.clamped = order % 2 == 0;
        options.repeatProbability = 0.3L;
        options.extent = 3;
        Curve curve = randomCurve(rng, options);
        for (TQ3RationalPoint4D& p : curve.points)
            p.z = std::fabs(p.z) + 0.5f * p.w; // z / w >= 0.5: behind the eye
        const std::vector<Vec3> v = render(curve, 1.0f);
        const std::size_t spans = curve.spans().size();
        EXPECT_LE(v.size(), spans * probesPerSpan(order) + 1) << "order " << order;
        expectOnCurve(curve, v, "order " + std::to_string(order));
        EXPECT_EQ(litPixels(), 0u) << "order " << order;
    }
}

// A line from 5 units in front of the eye to 5 units behind it, whose
// midpoint (where the subdivision probes an order-2 span) is a small distance
// `gap` in front of the eye plane, well inside the hither distance. Its image
// there is about 70 / gap pixels from the centre: measuring that part would
// take 10^3 to 10^7 segments of 2 pixels, all of them clipped away, and past
// kQ3SubdivisionMaxSegmentsPerCurve a warning and coarser segments on the
// visible part too. Beyond the hither plane the line is about 130 pixels
// long (partly outside the image), which is all it should cost.
TEST_F(SubdivisionPerspectiveRegressionTest, ALineCrossingTheEyePlaneCostsWhatItsVisiblePartCosts)
{
    for (const float gap : {1e-2f, 1e-4f, 1e-6f}) {
        Curve crossing = line({1.0L, 0.3L, -5.0L}, {1.0L, 0.3L, 5.0L - 2.0L * gap});
        const std::vector<Vec3> v = render(crossing, 2.0f);
        const std::string what = "gap " + std::to_string(gap);
        EXPECT_LE(v.size(), segmentBound(crossing, 2.0f) + 1) << what;
        expectOnCurve(crossing, v, what);
    }
}

// The same line drawn: its part beyond the hither plane appears exactly (an
// order-2 curve is its own polyline), clipped where it meets that plane, and
// nothing else: the part behind the eye must not wrap around onto the image.
TEST_F(SubdivisionPerspectiveRegressionTest, ALineCrossingTheEyePlaneDrawsOnlyItsVisiblePart)
{
    Curve crossing = line({1.0L, 0.3L, -5.0L}, {-0.2L, -0.4L, 5.0L});
    render(crossing, 20.0f);
    const ScreenMap map = screen();
    std::vector<std::pair<Real, Real>> visible;
    for (int i = 0; i <= 4000; ++i) {
        const Vec3 p = evaluate(crossing, Real(i) / 4000);
        Real x, y;
        if (map.depth(p) >= kHither && map.map(p, x, y))
            visible.emplace_back(x, y);
    }
    ASSERT_GE(visible.size(), 2u);
    std::size_t litCount = 0, stray = 0, missed = 0;
    for (unsigned long y = 0; y < kHeight; ++y)
        for (unsigned long x = 0; x < kWidth; ++x) {
            if (!lit(x, y))
                continue;
            ++litCount;
            Real best = 1e30L;
            for (const auto& s : visible)
                best = std::min(best, std::hypot(s.first - (x + 0.5L), s.second - (y + 0.5L)));
            // A 1-pixel line lights pixels whose centres are within a pixel
            // of it; 1.5 allows for the rasteriser's diagonal steps.
            if (best > 1.5L)
                ++stray;
        }
    for (const auto& s : visible) {
        const long px = long(std::floor(s.first)), py = long(std::floor(s.second));
        if (px < 0 || py < 0 || px >= long(kWidth) || py >= long(kHeight))
            continue;
        bool found = false;
        for (long dy = -1; dy <= 1 && !found; ++dy)
            for (long dx = -1; dx <= 1 && !found; ++dx) {
                const long qx = px + dx, qy = py + dy;
                found = qx >= 0 && qy >= 0 && qx < long(kWidth) && qy < long(kHeight) && lit(qx, qy);
            }
        missed += found ? 0 : 1;
    }
    EXPECT_GT(litCount, 20u);
    EXPECT_EQ(stray, 0u) << "pixels lit away from the visible part of the line";
    EXPECT_EQ(missed, 0u) << "points of the visible part with no lit pixel near them";
}

// Curves through the eye itself: an order-2 polyline with a vertex at the
// eye (a span end, so the subdivision probes it), and a cubic that
// interpolates the eye at a knot of multiplicity order - 1.
TEST_F(SubdivisionPerspectiveRegressionTest, CurvesThroughTheEyeFinishWithBoundedOutput)
{
    Curve polyline;
    polyline.order = 2;
    polyline.points = {{-2, 0.5f, -6, 1}, {0, 0, 0, 1}, {2, 1, 6, 1}, {3, -1, -4, 1}};
    polyline.knots = {0, 0, 1, 2, 3, 3};
    Curve cubic;
    cubic.order = 4;
    cubic.points = {{-3, 1, -8, 1}, {-1, 0.5f, -2, 2}, {-1, 0, -1, 1}, {0, 0, 0, 1},
                    {1, 0, 1, 1},   {2, -1, 4, 0.5f},  {1, -2, -6, 1}};
    cubic.knots = {0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2};
    for (Curve* curve : {&polyline, &cubic}) {
        for (const float c1 : {0.5f, 20.0f}) {
            const std::string what = "order " + std::to_string(curve->order) + " c1 " + std::to_string(c1);
            const std::vector<Vec3> v = render(*curve, c1);
            EXPECT_LE(v.size(), segmentBound(*curve, c1) + 1) << what;
            expectOnCurve(*curve, v, what);
        }
    }
}

// Random curves of every order wound around the eye, at c1 from half a
// pixel to 20 pixels: some pass behind it, some through the space between
// the eye and the hither plane, some close by. Each finishes without a
// warning, with every vertex on the curve and the count within segmentBound.
TEST_F(SubdivisionPerspectiveRegressionTest, RandomCurvesAroundTheEyeStayBounded)
{
    std::mt19937 rng(kSeed + 1);
    std::size_t largest = 0;
    for (int index = 0; index < 60; ++index) {
        Curve curve = randomCurve(rng, aroundTheEye(index));
        const float c1 = index % 3 == 0 ? 0.5f : index % 3 == 1 ? 4.0f : 20.0f;
        const std::string what = "curve " + std::to_string(index) + " order " + std::to_string(curve.order);
        const std::vector<Vec3> v = render(curve, c1);
        EXPECT_LE(v.size(), segmentBound(curve, c1) + 1) << what;
        expectOnCurve(curve, v, what);
        largest = std::max(largest, v.size());
        if (HasFailure())
            break;
    }
    std::printf("[ subdivision ] curves around the eye: at most %zu vertices\n", largest);
}

// The part of every polyline segment that lies beyond the hither plane (what
// is drawn of it) is at most c1 pixels long, also for a segment that crosses
// the plane: the subdivision finds where the curve leaves the visible side
// and measures up to there, so the unmeasured segment beyond starts on the
// plane itself. Curves are random (every order, around and through the eye)
// plus a cubic arc that crosses the plane mid-span, where the probes alone
// would leave a long visible chord.
TEST_F(SubdivisionPerspectiveRegressionTest, TheVisiblePieceOfEverySegmentIsAtMostC1)
{
    std::vector<Curve> curves;
    Curve arc;
    arc.order = 4;
    arc.points = {{-2.0f, 0.6f, -1.5f, 1}, {-0.7f, -0.8f, 0.9f, 1}, {0.8f, 0.7f, 0.9f, 1}, {2.1f, -0.4f, -1.6f, 1}};
    arc.knots = {0, 0, 0, 0, 1, 1, 1, 1};
    curves.push_back(arc);
    std::mt19937 rng(kSeed + 2);
    for (int index = 0; index < 400; ++index) {
        curves.push_back(randomCurve(rng, aroundTheEye(index)));
    }
    const ScreenMap map = screen();
    std::size_t crossing = 0;
    for (std::size_t index = 0; index < curves.size(); ++index) {
        const float c1 = index % 2 == 0 ? 3.0f : 12.0f;
        const std::vector<Vec3> v = render(curves[index], c1);
        const std::string what = "curve " + std::to_string(index) + " order " + std::to_string(curves[index].order);
        for (std::size_t i = 1; i < v.size(); ++i) {
            Vec3 a = v[i - 1], b = v[i];
            const Real da = map.depth(a), db = map.depth(b);
            if ((da < kHither) != (db < kHither))
                ++crossing;
            // A rendering loop draws a span outside the view as one segment
            // (docs/subdivision.md, "What a view can show"): only segments
            // reaching 1e-5 view-port units into the view volume count.
            if (!map.segmentVisible(a, b, kHither, 1e-5L))
                continue;
            if (da < kHither || db < kHither) {
                // Clip the straight segment at the hither plane.
                const Real t = (kHither - da) / (db - da);
                const Vec3 onPlane = a + t * (b - a);
                (da < kHither ? a : b) = onPlane;
            }
            Real ax, ay, bx, by;
            ASSERT_TRUE(map.map(a, ax, ay) && map.map(b, bx, by)) << what;
            // Vertices are floats: each end may move by its rounding error.
            const Real slack = map.pixelError(a, 1e-6L * curves[index].scale()) +
                               map.pixelError(b, 1e-6L * curves[index].scale()) + 1e-3L;
            EXPECT_LE(std::hypot(bx - ax, by - ay), c1 + slack) << what << ", segment " << i << ", depths " << double(da) << " and " << double(db);
        }
        if (HasFailure())
            break;
    }
    EXPECT_GT(crossing, 10u) << "the curves should cross the hither plane";
}

} // namespace
