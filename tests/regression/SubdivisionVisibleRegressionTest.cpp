// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Work bounded by what the pane can show (docs/subdivision.md, "What a view
// can show"): in a rendering loop, knot spans that cannot be seen are drawn
// with one segment each, yet every segment with a part inside the view volume
// still obeys c1. Random curves much larger than the view, under orthographic
// and perspective cameras, are decomposed with Q3Geometry_GetDecomposed in a
// 128 x 128 rendering loop; the polylines are checked with
// SubdivisionReference.h (its own camera model and view volume, no Q3 code).
//
// Tolerances: a segment "has a part inside" when it reaches at least 1e-5
// view-port units inside every side and past the hither plane (float
// vertices and float camera data move the boundary by about 1e-7 of the
// scene, so a chord that Q3 proved outside cannot appear inside by more).
// A visible segment may exceed c1 by 1e-4 c1 plus 1e-4 pixels (screen) or
// 1e-6 of the curve's size (world): the float rounding of its end points,
// about 1e-7 of the scene, is far below either.

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
#include <random>
#include <string>
#include <vector>

namespace {

using namespace q3test::subdivision;

constexpr unsigned long kSide = 128;
constexpr int kCurves = 60;
constexpr Real kMargin = 1e-5L;

struct Scene : SceneCamera {
    Curve curve;

    Scene() { pane = {{0, 0}, {float(kSide), float(kSide)}}; }
};

// A curve of extent 10 seen through a view a few times narrower than it, so
// that most of it is outside; every point at least 1.5 radii in front of the
// eye.
Scene makeScene(std::mt19937& rng, int index)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Scene scene;
    RandomCurveOptions options;
    options.order = 2 + unsigned(index % 7);
    options.clamped = index % 3 != 0;
    options.extraPoints = 16;
    scene.curve = randomCurve(rng, options);
    scene.perspective = index % 2 == 1;

    const Real radius = ControlBox(scene.curve.points).radius();
    // Look at a curve point near the middle, from a random direction.
    const Vec3 target = evaluate(scene.curve, scene.curve.domainStart() +
                                                  (0.3L + 0.4L * Real(u(rng))) *
                                                      (scene.curve.domainEnd() - scene.curve.domainStart()));
    std::normal_distribution<double> normal;
    Vec3 direction{normal(rng), normal(rng), normal(rng)};
    direction = unit(direction);
    Vec3 up{0, 1, 0};
    if (norm(cross(up, direction)) < 0.3L)
        up = Vec3{1, 0, 0};
    // Every curve point is within 2 radii of the target, so at least half a
    // radius in front of the eye.
    const Real away = radius * (2.5L + 2.0L * Real(u(rng)));
    const TQ3CameraData camera =
        lookAt(target + away * direction, target, up, 0.05L * radius, 100 * (away + radius));
    if (scene.perspective) {
        const Real fov = 0.15 + 0.3 * u(rng);
        scene.setPerspective(camera, fov, 1);
    } else {
        const Real half = radius * (0.25L + 0.35L * Real(u(rng)));
        scene.setOrthographic(camera, half, half);
    }
    return scene;
}

class SubdivisionVisibleRegressionTest : public q3test::PixmapViewTest {
protected:
    SubdivisionVisibleRegressionTest() : PixmapViewTest(kSide, kSide) {}

    /// The polyline Q3Geometry_GetDecomposed gives for `curve` under `style`
    /// inside a rendering loop (a warning, if `warns`, is expected once per
    /// pass).
    std::vector<Vec3> decompose(TQ3GeometryObject curve, const TQ3SubdivisionStyleData& style, bool warns = false)
    {
        std::vector<Vec3> result;
        EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        TQ3ViewStatus status;
        do {
            EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, m_view), kQ3Success);
            TQ3GeometryObject polyLine = nullptr;
            if (warns)
                EXPECT_Q3_WARNING(polyLine = Q3Geometry_GetDecomposed(curve, m_view), kQ3WarningParameterOutOfRange);
            else
                polyLine = Q3Geometry_GetDecomposed(curve, m_view);
            EXPECT_NE(polyLine, nullptr);
            result.clear();
            if (polyLine != nullptr) {
                TQ3PolyLineData data{};
                EXPECT_EQ(Q3PolyLine_GetData(polyLine, &data), kQ3Success);
                for (unsigned long v = 0; v < data.numVertices; ++v)
                    result.push_back(toVec(data.vertices[v].point));
                Q3PolyLine_EmptyData(&data);
                Q3Object_Dispose(polyLine);
            }
            status = Q3View_EndRendering(m_view);
        } while (status == kQ3ViewStatusRetraverse);
        EXPECT_EQ(status, kQ3ViewStatusDone);
        return result;
    }
};

Real pixelDistance(const ScreenMap& map, const Vec3& a, const Vec3& b)
{
    Real ax = 0, ay = 0, bx = 0, by = 0;
    EXPECT_TRUE(map.map(a, ax, ay));
    EXPECT_TRUE(map.map(b, bx, by));
    return std::hypot(bx - ax, by - ay);
}

TEST_F(SubdivisionVisibleRegressionTest, VisibleSegmentsObeyC1WhileHiddenSpansGetOneSegment)
{
    std::mt19937 rng(20261124u);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::size_t visibleChecked[3] = {0, 0, 0};
    std::size_t hiddenLong[3] = {0, 0, 0}; // invisible segments longer than c1 (or than 1/m of a span)
    std::size_t constantFewer = 0;
    for (int index = 0; index < kCurves && !HasFailure(); ++index) {
        const Scene scene = makeScene(rng, index);
        const ScreenMap map = scene.screen();
        const Curve& c = scene.curve;
        const std::string what = "curve " + std::to_string(index) + (scene.perspective ? " perspective" : " orthographic");
        // Lengths of the whole curve from dense samples (a lower bound).
        const DenseSamples samples = denseSamples(c, 64);
        Real worldLength = 0, pixelLength = 0;
        for (std::size_t i = 1; i < samples.local.size(); ++i) {
            worldLength += distance(samples.local[i - 1], samples.local[i]);
            pixelLength += pixelDistance(map, samples.local[i - 1], samples.local[i]);
        }
        // Both adaptive counts stay far below the view's cap (4096 for this
        // pane), so no c1 is replaced and the guarantee must hold.
        const float screenC1 = float(std::max<Real>(1.0L + 3.0L * Real(u(rng)), pixelLength / 2500));
        const float worldC1 = float(worldLength / (30 + 270 * u(rng)));
        const TQ3SubdivisionStyleData screen{kQ3SubdivisionMethodScreenSpace, screenC1, screenC1};
        const TQ3SubdivisionStyleData world{kQ3SubdivisionMethodWorldSpace, worldC1, worldC1};
        const TQ3SubdivisionStyleData constant{kQ3SubdivisionMethodConstant, 16, 16};

        Curve copy = c;
        TQ3NURBCurveData data = copy.data();
        TQ3GeometryObject curve = Q3NURBCurve_New(&data);
        ASSERT_NE(curve, nullptr);
        useCamera(scene.newObject());
        const std::vector<Vec3> byScreen = decompose(curve, screen);
        const std::vector<Vec3> byWorld = decompose(curve, world);
        const std::vector<Vec3> byConstant = decompose(curve, constant);
        Q3Object_Dispose(curve);

        const auto check = [&](const std::vector<Vec3>& v, int kind, Real c1, const char* name) {
            ASSERT_GE(v.size(), 2u) << what << " " << name;
            for (std::size_t i = 1; i < v.size(); ++i) {
                const bool visible = map.segmentVisible(v[i - 1], v[i], scene.hither(), kMargin);
                const Real length = kind == 0 ? pixelDistance(map, v[i - 1], v[i]) : distance(v[i - 1], v[i]);
                const Real allowed = kind == 0 ? c1 * (1 + 1e-4L) + 1e-4L : c1 * (1 + 1e-4L) + 1e-6L * c.scale();
                if (visible) {
                    ++visibleChecked[kind];
                    EXPECT_LE(length, allowed) << what << " " << name << " visible segment " << i - 1 << " of "
                                               << v.size() - 1 << " c1 " << double(c1);
                } else if (length > allowed) {
                    ++hiddenLong[kind];
                }
            }
        };
        check(byScreen, 0, screenC1, "screen space");
        check(byWorld, 1, worldC1, "world space");
        // Constant: 16 segments per span, one for a span that cannot be seen.
        const std::size_t spans = c.spans().size();
        EXPECT_GE(byConstant.size(), spans + 1) << what;
        EXPECT_LE(byConstant.size(), 16 * spans + 1) << what;
        if (byConstant.size() < 16 * spans + 1)
            ++constantFewer;
    }
    // The scenes are built so that culling happens: not a vacuous pass.
    EXPECT_GT(visibleChecked[0], 1000u);
    EXPECT_GT(visibleChecked[1], 100u);
    EXPECT_GT(hiddenLong[0], 20u);
    EXPECT_GT(hiddenLong[1], 20u);
    EXPECT_GT(constantFewer, 10u);
}

// A screen-space c1 under kQ3SubdivisionMinScreenSpaceC1 is replaced by it,
// with the article's warning, by every call that takes a style.
TEST_F(SubdivisionVisibleRegressionTest, ScreenSpaceBelowTheFloorIsReplacedWithAWarning)
{
    EXPECT_EQ(kQ3SubdivisionMinScreenSpaceC1, 0.125f);
    const TQ3SubdivisionStyleData tiny{kQ3SubdivisionMethodScreenSpace, 1e-6f, 0.01f};
    TQ3StyleObject style = nullptr;
    EXPECT_Q3_WARNING(style = Q3SubdivisionStyle_New(&tiny), kQ3WarningParameterOutOfRange);
    ASSERT_NE(style, nullptr);
    TQ3SubdivisionStyleData got{};
    ASSERT_EQ(Q3SubdivisionStyle_GetData(style, &got), kQ3Success);
    EXPECT_EQ(got.c1, kQ3SubdivisionMinScreenSpaceC1);
    EXPECT_EQ(got.c2, kQ3SubdivisionMinScreenSpaceC1);
    const TQ3SubdivisionStyleData half{kQ3SubdivisionMethodScreenSpace, 0.5f, 0.124f};
    EXPECT_Q3_WARNING(Q3SubdivisionStyle_SetData(style, &half), kQ3WarningParameterOutOfRange);
    ASSERT_EQ(Q3SubdivisionStyle_GetData(style, &got), kQ3Success);
    EXPECT_EQ(got.c1, 0.5f);
    EXPECT_EQ(got.c2, kQ3SubdivisionMinScreenSpaceC1);
    // At the floor, and world space below it: nothing replaced.
    const TQ3SubdivisionStyleData floor{kQ3SubdivisionMethodScreenSpace, 0.125f, 0.125f};
    EXPECT_EQ(Q3SubdivisionStyle_SetData(style, &floor), kQ3Success);
    const TQ3SubdivisionStyleData world{kQ3SubdivisionMethodWorldSpace, 1e-6f, 1e-6f};
    EXPECT_EQ(Q3SubdivisionStyle_SetData(style, &world), kQ3Success);
    ASSERT_EQ(Q3SubdivisionStyle_GetData(style, &got), kQ3Success);
    EXPECT_EQ(got.c1, 1e-6f);
    Q3Object_Dispose(style);

    // Submitted in a loop: the state says what curves are drawn with.
    const TQ3OrthographicCameraData ortho = q3test::orthographicCameraAt(0, 0, 2, 2);
    useCamera(Q3OrthographicCamera_New(&ortho));
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    TQ3ViewStatus status;
    do {
        EXPECT_Q3_WARNING(EXPECT_EQ(Q3SubdivisionStyle_Submit(&tiny, m_view), kQ3Success),
                          kQ3WarningParameterOutOfRange);
        EXPECT_EQ(Q3View_GetSubdivisionStyleState(m_view, &got), kQ3Success);
        EXPECT_EQ(got.c1, kQ3SubdivisionMinScreenSpaceC1);
        status = Q3View_EndRendering(m_view);
    } while (status == kQ3ViewStatusRetraverse);
    EXPECT_EQ(status, kQ3ViewStatusDone);
}

// A world- or screen-space curve in a view gets at most
// kQ3SubdivisionViewSegmentsPerPixel * (width + height) segments; one that
// would need more is drawn with longer ones and warns. The constant method
// keeps its own limit (kQ3SubdivisionMaxConstantSegments per span).
TEST_F(SubdivisionVisibleRegressionTest, TheViewCapsAdaptiveSegmentsWithAWarning)
{
    EXPECT_EQ(kQ3SubdivisionViewSegmentsPerPixel, 16);
    const std::size_t cap = std::size_t(kQ3SubdivisionViewSegmentsPerPixel) * (kSide + kSide);
    const TQ3OrthographicCameraData ortho = q3test::orthographicCameraAt(0, 0, 2, 2);
    useCamera(Q3OrthographicCamera_New(&ortho));
    // A cubic Bezier inside the view, about 4 units (128 pixels) long.
    TQ3RationalPoint4D points[4] = {{-1.8f, -1, 0, 1}, {-0.6f, 1.5f, 0, 1}, {0.6f, -1.5f, 0, 1}, {1.8f, 1, 0, 1}};
    float knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    TQ3NURBCurveData data{4, 4, points, knots, nullptr};
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    ASSERT_NE(curve, nullptr);

    const TQ3SubdivisionStyleData world{kQ3SubdivisionMethodWorldSpace, 1e-6f, 1e-6f};
    const std::vector<Vec3> byWorld = decompose(curve, world, true);
    EXPECT_LE(byWorld.size() - 1, cap);
    EXPECT_GT(byWorld.size() - 1, cap / 2);
    const TQ3SubdivisionStyleData screen{kQ3SubdivisionMethodScreenSpace, 0.125f, 0.125f};
    // About 200 pixels / 0.125: within the cap, no warning.
    const std::vector<Vec3> byScreen = decompose(curve, screen);
    EXPECT_GT(byScreen.size() - 1, 1000u);
    EXPECT_LE(byScreen.size() - 1, cap);
    const TQ3SubdivisionStyleData constant{kQ3SubdivisionMethodConstant, 1024, 1024};
    EXPECT_EQ(decompose(curve, constant).size(), 1025u);
    Q3Object_Dispose(curve);
}

} // namespace
