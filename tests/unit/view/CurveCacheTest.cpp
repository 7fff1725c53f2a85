// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// A retained curve as the view draws it: it keeps no tessellation
// (geometry/NURBCurve.h), so every pass subdivides it once, into the view's
// one curve buffer; every change (edit, style) is drawn at the next frame and
// an unchanged re-render draws the same pixels. The scene is set up through
// the C API and the counter read through the core
// (NURBCurve::tessellations, View::curveScratchBytes).

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
#include "view/View.h"

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

    std::uint64_t subdivisions() { return lookup<NURBCurve>(m_curve, "curve").tessellations(); }
    std::size_t scratchBytes() { return lookup<View>(m_view, "view").curveScratchBytes(); }

    // One frame: `before` runs first inside the loop, then `curve` (m_curve
    // by default) is submitted. Returns the image.
    std::vector<unsigned char> render(const std::function<void(TQ3ViewObject)>& before = {},
                                      TQ3GeometryObject curve = nullptr)
    {
        EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        if (before)
            before(m_view);
        EXPECT_EQ(Q3Geometry_Submit(curve != nullptr ? curve : m_curve, m_view), kQ3Success);
        EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
        return m_memory;
    }

    // The vertices Q3Geometry_GetDecomposed gives under `before`.
    std::vector<TQ3Point3D> decomposed(const std::function<void(TQ3ViewObject)>& before = {})
    {
        std::vector<TQ3Point3D> out;
        EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        if (before)
            before(m_view);
        TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(m_curve, m_view);
        EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
        TQ3PolyLineData data{};
        if (polyLine != nullptr && Q3PolyLine_GetData(polyLine, &data) == kQ3Success) {
            for (unsigned long i = 0; i < data.numVertices; ++i)
                out.push_back(data.vertices[i].point);
            Q3PolyLine_EmptyData(&data);
        }
        if (polyLine != nullptr)
            Q3Object_Dispose(polyLine);
        return out;
    }

    static std::size_t lit(const std::vector<unsigned char>& image)
    {
        std::size_t count = 0;
        for (std::size_t i = 0; i < image.size(); i += 4)
            count += image[i + 1] > 127 || image[i + 2] > 127 || image[i + 3] > 127 ? 1 : 0;
        return count;
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

TEST_F(CurveCacheTest, EveryPassSubdividesOnceAndAnUnchangedFrameDrawsTheSamePixels)
{
    EXPECT_EQ(subdivisions(), 0u);
    const std::vector<unsigned char> first = render();
    EXPECT_GT(lit(first), 0u);
    EXPECT_EQ(subdivisions(), 1u);
    for (int frame = 0; frame < 4; ++frame)
        EXPECT_EQ(render(), first) << "frame " << frame;
    EXPECT_EQ(subdivisions(), 5u);
    EXPECT_FALSE(decomposed().empty());
    EXPECT_EQ(subdivisions(), 6u);
}

TEST_F(CurveCacheTest, TheViewSubdividesIntoOneBufferThatStopsGrowing)
{
    EXPECT_EQ(scratchBytes(), 0u);
    render();
    const std::size_t bytes = scratchBytes();
    // At least the polyline: 12 bytes of vertex and 8 of parameter each.
    EXPECT_GE(bytes, decomposed().size() * 20);
    for (int frame = 0; frame < 3; ++frame)
        render();
    EXPECT_EQ(scratchBytes(), bytes);
    // A finer style needs more room: the buffer grows once.
    const TQ3SubdivisionStyleData fine = {kQ3SubdivisionMethodConstant, 1000, 1000};
    render([&](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&fine, v); });
    EXPECT_GE(scratchBytes(), 1001u * 20);
    const std::size_t grown = scratchBytes();
    render();
    EXPECT_EQ(scratchBytes(), grown);
}

TEST_F(CurveCacheTest, AnEditIsDrawnAtTheNextFrame)
{
    const std::vector<unsigned char> before = render();
    const TQ3RationalPoint4D moved = {1, 2, 0, 1};
    ASSERT_EQ(Q3NURBCurve_SetControlPoint(m_curve, 1, &moved), kQ3Success);
    const std::vector<unsigned char> after = render();
    EXPECT_NE(after, before);
    // The same pixels as a curve that was never drawn, made with the new data.
    TQ3RationalPoint4D points[4] = {m_points[0], moved, m_points[2], m_points[3]};
    const TQ3NURBCurveData data{4, 4, points, m_knots, nullptr};
    TQ3GeometryObject fresh = Q3NURBCurve_New(&data);
    ASSERT_NE(fresh, nullptr);
    EXPECT_EQ(render({}, fresh), after);
    Q3Object_Dispose(fresh);
    // Setting the old point back draws the first image again.
    ASSERT_EQ(Q3NURBCurve_SetControlPoint(m_curve, 1, &m_points[1]), kQ3Success);
    EXPECT_EQ(render(), before);
}

TEST_F(CurveCacheTest, AStyleChangeIsDrawnAtTheNextFrameAndGoingBackToo)
{
    const TQ3SubdivisionStyleData constant = {kQ3SubdivisionMethodConstant, 6, 6};
    const TQ3SubdivisionStyleData finer = {kQ3SubdivisionMethodConstant, 7, 7};
    auto with = [](const TQ3SubdivisionStyleData& s) {
        return [&s](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&s, v); };
    };
    EXPECT_EQ(decomposed(with(constant)).size(), 7u);
    EXPECT_EQ(decomposed(with(finer)).size(), 8u);
    EXPECT_EQ(decomposed(with(constant)).size(), 7u);
    const std::vector<unsigned char> six = render(with(constant));
    const std::vector<unsigned char> seven = render(with(finer));
    EXPECT_EQ(render(with(constant)), six);
    EXPECT_EQ(render(with(finer)), seven);
}

TEST_F(CurveCacheTest, ACameraChangeIsDrawnAtTheNextFrame)
{
    const std::vector<unsigned char> wide = render();
    TQ3OrthographicCameraData zoomed = m_cameraData;
    zoomed.left = -1;
    zoomed.right = 1;
    ASSERT_EQ(Q3OrthographicCamera_SetData(m_camera, &zoomed), kQ3Success);
    const std::vector<unsigned char> narrow = render();
    EXPECT_NE(narrow, wide);
    ASSERT_EQ(Q3OrthographicCamera_SetData(m_camera, &m_cameraData), kQ3Success);
    EXPECT_EQ(render(), wide);
}

TEST_F(CurveCacheTest, ImmediateModeLeavesRetainedCountersAlone)
{
    render();
    const TQ3NURBCurveData data{4, 4, m_points, m_knots, nullptr};
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    for (int i = 0; i < 3; ++i)
        ASSERT_EQ(Q3NURBCurve_Submit(&data, m_view), kQ3Success);
    ASSERT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
    EXPECT_EQ(subdivisions(), 1u);
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

// What a pass does with a curve (NURBCurve::decompose): tessellate under the
// options the setting resolves to, into the buffer given.
const std::vector<float>& subdivide(const nurbs::CurveRef& ref, const TessellationSetting& setting,
                                    nurbs::TessellatedCurve& into)
{
    nurbs::tessellate(ref, measureFor(setting).options, into);
    return into.vertices;
}

TEST(CurveCacheMemory, ALargeCurveDrawsFromTheScratchWhatItsWholeFormGives)
{
    const UniformCurve large(16, nurbs::kWholeFormLimit / 16 + 7);
    const nurbs::CurveRef ref = large.ref();
    nurbs::TessellatedCurve scratch;
    TessellationSetting setting;
    setting.style = {kQ3SubdivisionMethodConstant, 3.0f, 0.0f};
    std::vector<float> drawn = subdivide(ref, setting, scratch);
    // Span-by-span conversion is the same arithmetic as the whole form's.
    nurbs::TessellationOptions three;
    three.c1 = 3;
    nurbs::TessellatedCurve fromForm;
    nurbs::tessellate(nurbs::BezierForm(ref), three, fromForm);
    EXPECT_EQ(drawn, fromForm.vertices);

    // Another style, the same buffer; c1 holds.
    const float c1 = 0.002f;
    setting.style = {kQ3SubdivisionMethodWorldSpace, c1, 0.0f};
    drawn = subdivide(ref, setting, scratch);
    ASSERT_GT(drawn.size(), 6u);
    double longest = 0.0;
    for (std::size_t v = 3; v < drawn.size(); v += 3)
        longest = std::max(longest, double(std::hypot(drawn[v] - drawn[v - 3], drawn[v + 1] - drawn[v - 2])));
    // Chords are measured exactly in double; the float vertices (coordinates up to
    // about 2) move each end by half an ulp.
    EXPECT_LE(longest, c1 + 4.0 * std::numeric_limits<float>::epsilon());
    EXPECT_GT(longest, 0.9 * c1);
}

TEST(CurveCacheMemory, WithoutAScratchACallUsesItsOwnBufferAndDrawsTheSame)
{
    const UniformCurve small(16, 50);
    TessellationSetting setting;
    setting.style = {kQ3SubdivisionMethodConstant, 3.0f, 0.0f};
    nurbs::TessellatedCurve fresh;
    const std::vector<float> own = subdivide(small.ref(), setting, fresh);
    nurbs::TessellatedCurve scratch;
    subdivide(UniformCurve(4, 9).ref(), setting, scratch); // a buffer used before
    const std::vector<float> scratched = subdivide(small.ref(), setting, scratch);
    EXPECT_EQ(own.size(), (50u * 3 + 1) * 3);
    EXPECT_EQ(own, scratched);
}

// The view's buffer keeps the constant method's Bernstein table between
// curves: reusing it, or replacing it for another order or count, gives the
// vertices a fresh result gives, bit for bit.
TEST(CurveCacheMemory, AReusedResultGivesWhatAFreshOneGives)
{
    const UniformCurve cubicA(4, 7);
    const UniformCurve cubicB(4, 3);
    const UniformCurve quintic(6, 5);
    nurbs::TessellatedCurve reused;
    const struct {
        const UniformCurve* curve;
        std::uint32_t segments;
    } runs[] = {{&cubicA, 64}, {&cubicB, 64}, {&quintic, 64}, {&cubicA, 9}, {&cubicB, 64}};
    for (const auto& run : runs) {
        nurbs::TessellationOptions options;
        options.c1 = run.segments;
        nurbs::tessellate(run.curve->ref(), options, reused);
        nurbs::TessellatedCurve fresh;
        nurbs::tessellate(run.curve->ref(), options, fresh);
        EXPECT_EQ(reused.vertices, fresh.vertices) << "order " << run.curve->order << ", " << run.segments;
        EXPECT_EQ(reused.parameters, fresh.parameters);
        EXPECT_EQ(reused.table.order(), run.curve->order);
        EXPECT_EQ(reused.table.segments(), run.segments);
    }
}

} // namespace
} // namespace q3
