// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The retained-mode curve cache as the view uses it: an unchanged re-render
// tessellates nothing; every change the polyline depends on (edit, style,
// transform, camera, pane size) rebuilds it once; changes it does not depend
// on do not. The scene is set up through the C API and the cache is read
// through the core (CurveCache::tessellations, CurveCache::bezier).

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DRenderer.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"
#include "QD3DView.h"
#include "geometry/NURBCurve.h"
#include "geometry/nurbs/Bezier.h"
#include "geometry/nurbs/Tessellate.h"
#include "view/CurveTessellation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace q3 {
namespace {

class CurveCacheTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_EQ(Q3Initialize(), kQ3Success);
        m_liveAtStart = Q3Memory_CountLiveObjects();
        m_memory.assign(kWidth * kHeight * 4, 0);
        TQ3PixmapDrawContextData contextData{};
        contextData.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
        contextData.drawContextData.clearImageColor = {1, 0, 0, 0};
        contextData.pixmap = {m_memory.data(), kWidth, kHeight, kWidth * 4, 32, kQ3PixelTypeARGB32,
                              kQ3EndianBig, kQ3EndianBig};
        m_context = Q3PixmapDrawContext_New(&contextData);
        m_camera = Q3OrthographicCamera_New(&m_cameraData);
        m_view = Q3View_New();
        Q3View_SetDrawContext(m_view, m_context);
        Q3View_SetCamera(m_view, m_camera);
        Q3View_SetRendererByType(m_view, kQ3RendererTypeInteractive);
        const TQ3NURBCurveData data{4, 4, m_points, m_knots, nullptr};
        m_curve = Q3NURBCurve_New(&data);
        ASSERT_TRUE(m_context && m_camera && m_view && m_curve);
    }

    void TearDown() override
    {
        for (TQ3Object object : {m_curve, m_view, m_camera, m_context})
            Q3Object_Dispose(object);
        EXPECT_EQ(Q3Memory_CountLiveObjects(), m_liveAtStart);
        Q3Exit();
    }

    CurveCache& cache() { return lookup<NURBCurve>(m_curve, "curve").cache(); }

    // One frame: `before` runs first inside the loop, then the curve is submitted.
    void render(const std::function<void(TQ3ViewObject)>& before = {})
    {
        ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        if (before)
            before(m_view);
        ASSERT_EQ(Q3Geometry_Submit(m_curve, m_view), kQ3Success);
        ASSERT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
    }

    static constexpr unsigned long kWidth = 120;
    static constexpr unsigned long kHeight = 90;
    unsigned long m_liveAtStart = 0;
    std::vector<unsigned char> m_memory;
    TQ3RationalPoint4D m_points[4] = {{0, 0, 0, 1}, {1, 1, 0, 1}, {2, 0, 0, 1}, {3, 1, 0, 1}};
    float m_knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    TQ3OrthographicCameraData m_cameraData{
        {{{1.5f, 0.5f, 10}, {1.5f, 0.5f, 0}, {0, 1, 0}}, {1, 100}, {{-1, 1}, 2, 2}}, -2, 1.5f, 2, -1.5f};
    TQ3DrawContextObject m_context = nullptr;
    TQ3CameraObject m_camera = nullptr;
    TQ3ViewObject m_view = nullptr;
    TQ3GeometryObject m_curve = nullptr;
};

TEST_F(CurveCacheTest, AnUnchangedRerenderTessellatesNothing)
{
    EXPECT_EQ(cache().tessellations, 0u);
    render();
    EXPECT_EQ(cache().tessellations, 1u);
    EXPECT_TRUE(cache().valid);
    const std::vector<float> first = cache().polyline;
    for (int frame = 0; frame < 4; ++frame)
        render();
    EXPECT_EQ(cache().tessellations, 1u);
    EXPECT_EQ(cache().polyline, first);
}

TEST_F(CurveCacheTest, DecomposingReusesTheRenderedPolyline)
{
    render();
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(m_curve, m_view);
    ASSERT_NE(polyLine, nullptr);
    ASSERT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
    EXPECT_EQ(cache().tessellations, 1u);
    TQ3PolyLineData data{};
    Q3PolyLine_GetData(polyLine, &data);
    ASSERT_EQ(data.numVertices * 3, cache().polyline.size());
    for (unsigned long i = 0; i < data.numVertices; ++i) {
        EXPECT_EQ(data.vertices[i].point.x, cache().polyline[3 * i]);
        EXPECT_EQ(data.vertices[i].point.y, cache().polyline[3 * i + 1]);
    }
    Q3PolyLine_EmptyData(&data);
    Q3Object_Dispose(polyLine);
}

TEST_F(CurveCacheTest, AnEditRebuildsTheBezierFormAndThePolyline)
{
    render();
    ASSERT_TRUE(cache().bezier);
    const TQ3RationalPoint4D moved = {1, 2, 0, 1};
    ASSERT_EQ(Q3NURBCurve_SetControlPoint(m_curve, 1, &moved), kQ3Success);
    EXPECT_FALSE(cache().valid);
    EXPECT_FALSE(cache().bezier);
    render();
    EXPECT_EQ(cache().tessellations, 2u);
    EXPECT_TRUE(cache().bezier);
    // Q3Shared_Edited counts as an edit too.
    ASSERT_EQ(Q3Shared_Edited(m_curve), kQ3Success);
    render();
    EXPECT_EQ(cache().tessellations, 3u);
    render();
    EXPECT_EQ(cache().tessellations, 3u);
}

TEST_F(CurveCacheTest, TheBezierFormIsBuiltOncePerEditWhateverTheStyle)
{
    render();
    const nurbs::BezierForm* form = cache().bezier.get();
    const TQ3SubdivisionStyleData styles[] = {{kQ3SubdivisionMethodConstant, 4, 4},
                                              {kQ3SubdivisionMethodWorldSpace, 0.1f, 0.1f},
                                              {kQ3SubdivisionMethodScreenSpace, 3, 3}};
    for (const TQ3SubdivisionStyleData& style : styles)
        render([&](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&style, v); });
    EXPECT_EQ(cache().tessellations, 4u);
    EXPECT_EQ(cache().bezier.get(), form);
}

TEST_F(CurveCacheTest, AStyleChangeRebuildsOnce)
{
    const TQ3SubdivisionStyleData constant = {kQ3SubdivisionMethodConstant, 6, 6};
    const TQ3SubdivisionStyleData finer = {kQ3SubdivisionMethodConstant, 7, 7};
    auto with = [](const TQ3SubdivisionStyleData& s) {
        return [&s](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&s, v); };
    };
    render(with(constant));
    render(with(constant));
    EXPECT_EQ(cache().tessellations, 1u);
    EXPECT_EQ(cache().polyline.size(), 7u * 3);
    render(with(finer));
    EXPECT_EQ(cache().tessellations, 2u);
    EXPECT_EQ(cache().polyline.size(), 8u * 3);
    // c2 does not matter to a curve.
    const TQ3SubdivisionStyleData otherC2 = {kQ3SubdivisionMethodConstant, 7, 99};
    render(with(otherC2));
    EXPECT_EQ(cache().tessellations, 2u);
    // The cache holds one polyline: going back rebuilds.
    render(with(constant));
    EXPECT_EQ(cache().tessellations, 3u);
}

TEST_F(CurveCacheTest, ATransformRebuildsOnlyWhenTheMethodMeasuresThroughIt)
{
    const TQ3Vector3D offset = {0.25f, 0, 0};
    const TQ3Vector3D scale = {1.5f, 1.5f, 1.5f};
    // Screen space (the default) measures through the transform.
    render();
    render([&](TQ3ViewObject v) { Q3ScaleTransform_Submit(&scale, v); });
    EXPECT_EQ(cache().tessellations, 2u);
    render([&](TQ3ViewObject v) { Q3ScaleTransform_Submit(&scale, v); });
    EXPECT_EQ(cache().tessellations, 2u);
    // World space too.
    const TQ3SubdivisionStyleData world = {kQ3SubdivisionMethodWorldSpace, 0.2f, 0.2f};
    render([&](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&world, v); });
    EXPECT_EQ(cache().tessellations, 3u);
    render([&](TQ3ViewObject v) {
        Q3SubdivisionStyle_Submit(&world, v);
        Q3TranslateTransform_Submit(&offset, v);
    });
    EXPECT_EQ(cache().tessellations, 4u);
    // Constant subdivision does not.
    const TQ3SubdivisionStyleData constant = {kQ3SubdivisionMethodConstant, 5, 5};
    render([&](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&constant, v); });
    EXPECT_EQ(cache().tessellations, 5u);
    render([&](TQ3ViewObject v) {
        Q3SubdivisionStyle_Submit(&constant, v);
        Q3ScaleTransform_Submit(&scale, v);
    });
    EXPECT_EQ(cache().tessellations, 5u);
}

TEST_F(CurveCacheTest, ACameraChangeRebuildsScreenSpaceOnly)
{
    render();
    TQ3OrthographicCameraData zoomed = m_cameraData;
    zoomed.left = -1;
    zoomed.right = 1;
    ASSERT_EQ(Q3OrthographicCamera_SetData(m_camera, &zoomed), kQ3Success);
    render();
    EXPECT_EQ(cache().tessellations, 2u);
    render();
    EXPECT_EQ(cache().tessellations, 2u);
    // World space does not look at the camera.
    const TQ3SubdivisionStyleData world = {kQ3SubdivisionMethodWorldSpace, 0.2f, 0.2f};
    render([&](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&world, v); });
    EXPECT_EQ(cache().tessellations, 3u);
    ASSERT_EQ(Q3OrthographicCamera_SetData(m_camera, &m_cameraData), kQ3Success);
    render([&](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&world, v); });
    EXPECT_EQ(cache().tessellations, 3u);
}

TEST_F(CurveCacheTest, APaneOfAnotherSizeRebuildsAMovedOneDoesNot)
{
    render();
    const TQ3Area pane = {{0, 0}, {60, 45}};
    ASSERT_EQ(Q3DrawContext_SetPane(m_context, &pane), kQ3Success);
    ASSERT_EQ(Q3DrawContext_SetPaneState(m_context, kQ3True), kQ3Success);
    render();
    EXPECT_EQ(cache().tessellations, 2u);
    // The same size elsewhere: lengths in pixels are unchanged.
    const TQ3Area moved = {{30, 20}, {90, 65}};
    ASSERT_EQ(Q3DrawContext_SetPane(m_context, &moved), kQ3Success);
    render();
    EXPECT_EQ(cache().tessellations, 2u);
    // With the pane off the view draws into the whole image: another size.
    ASSERT_EQ(Q3DrawContext_SetPaneState(m_context, kQ3False), kQ3Success);
    render();
    EXPECT_EQ(cache().tessellations, 3u);
}

TEST_F(CurveCacheTest, ImmediateModeLeavesRetainedCachesAlone)
{
    render();
    const TQ3NURBCurveData data{4, 4, m_points, m_knots, nullptr};
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    for (int i = 0; i < 3; ++i)
        ASSERT_EQ(Q3NURBCurve_Submit(&data, m_view), kQ3Success);
    ASSERT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
    EXPECT_EQ(cache().tessellations, 1u);
}

// A clamped uniform curve of the given order with `spans` non-empty spans: a
// wiggle in x-y with weights between 0.5 and 2.
struct UniformCurve {
    unsigned order = 0;
    std::vector<float> points;
    std::vector<float> knots;

    UniformCurve(unsigned k, std::size_t spans) : order(k)
    {
        const std::size_t n = spans + k - 1;
        for (std::size_t i = 0; i < n; ++i) {
            const double w = 1.25 + 0.75 * std::sin(0.7 * double(i));
            const double x = double(i) / double(n);
            const double y = std::sin(37.0 * x) + 0.1 * std::cos(5.0 * double(i));
            points.insert(points.end(), {float(x * w), float(y * w), 0.0f, float(w)});
        }
        for (std::size_t i = 0; i < n + k; ++i)
            knots.push_back(float(std::min(std::max<std::size_t>(i, k - 1), n) - (k - 1)));
    }
    nurbs::CurveRef ref() const { return nurbs::CurveRef{order, points.size() / 4, points.data(), knots.data()}; }
};

TEST(CurveCacheMemory, TheWholeFormLimitCountsBezierPoints)
{
    // Order 16: 2^18 / 16 spans is exactly the limit.
    const std::size_t spans = nurbs::kWholeFormLimit / 16;
    EXPECT_TRUE(nurbs::fitsWholeBezierForm(UniformCurve(16, spans).ref()));
    EXPECT_FALSE(nurbs::fitsWholeBezierForm(UniformCurve(16, spans + 1).ref()));
    EXPECT_TRUE(nurbs::fitsWholeBezierForm(UniformCurve(4, spans * 4).ref()));
}

TEST(CurveCacheMemory, ALargeRetainedCurveKeepsOnlyItsPolylineAndDrawsTheSame)
{
    const UniformCurve large(16, nurbs::kWholeFormLimit / 16 + 7);
    const nurbs::CurveRef ref = large.ref();
    CurveCache cache;
    TessellationSetting setting;
    setting.style = {kQ3SubdivisionMethodConstant, 3.0f, 0.0f};
    std::vector<float> drawn;
    const PolylineUser keep = [&](const float* xyz, std::size_t count) { drawn.assign(xyz, xyz + 3 * count); };
    withCurvePolyline(ref, &cache, setting, keep);
    EXPECT_EQ(cache.bezier, nullptr);
    EXPECT_EQ(cache.tessellations, 1u);
    EXPECT_EQ(cache.polyline, drawn);
    // Span-by-span conversion is the same arithmetic as the whole form's.
    EXPECT_EQ(drawn, nurbs::tessellateConstant(nurbs::BezierForm(ref), 3).vertices);

    // A style change rebuilds the polyline, still without a form; c1 holds.
    const float c1 = 0.002f;
    setting.style = {kQ3SubdivisionMethodWorldSpace, c1, 0.0f};
    withCurvePolyline(ref, &cache, setting, keep);
    EXPECT_EQ(cache.bezier, nullptr);
    EXPECT_EQ(cache.tessellations, 2u);
    ASSERT_GT(drawn.size(), 6u);
    double longest = 0.0;
    for (std::size_t v = 3; v < drawn.size(); v += 3)
        longest = std::max(longest, double(std::hypot(drawn[v] - drawn[v - 3], drawn[v + 1] - drawn[v - 2])));
    // Chords are measured exactly in double; the float vertices (coordinates up to
    // about 2) move each end by half an ulp.
    EXPECT_LE(longest, c1 + 4.0 * std::numeric_limits<float>::epsilon());
    EXPECT_GT(longest, 0.9 * c1);
}

TEST(CurveCacheMemory, ASmallRetainedCurveKeepsItsBezierForm)
{
    const UniformCurve small(16, 50);
    CurveCache cache;
    TessellationSetting setting;
    setting.style = {kQ3SubdivisionMethodConstant, 3.0f, 0.0f};
    withCurvePolyline(small.ref(), &cache, setting, [](const float*, std::size_t) {});
    ASSERT_NE(cache.bezier, nullptr);
    EXPECT_EQ(cache.bezier->spanCount(), 50u);
}

} // namespace
} // namespace q3
