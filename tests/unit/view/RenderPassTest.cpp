// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The rendering pass drawn into a NullRenderTarget (base/NullRenderTarget.h):
// the pass reaches the pixels only through base/RenderTarget.h, so it runs
// without any rendering backend, and the calls it makes can be read back.

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "base/NullRenderTarget.h"
#include "geometry/Geometry.h"
#include "view/RenderPass.h"

#include <gtest/gtest.h>

namespace q3 {
namespace {

class RenderPassTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_EQ(Q3Initialize(), kQ3Success);
        const TQ3TriangleData triangle{{{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{0, 1, 0}, nullptr}}, nullptr};
        m_triangle = Q3Triangle_New(&triangle);
        const TQ3PointData point{{0.5f, 0.5f, 0.0f}, nullptr};
        m_point = Q3Point_New(&point);
        ASSERT_TRUE(m_triangle && m_point);
        ASSERT_TRUE(m_target.beginFrame(8, 8, RgbaColor{}, PixelRect{0, 0, 8, 8}).ok());
    }

    void TearDown() override
    {
        Q3Object_Dispose(m_triangle);
        Q3Object_Dispose(m_point);
        Q3Exit();
    }

    /// Draws both geometries in one pass of a renderer that fills or not.
    void drawAll(bool fill)
    {
        RenderStyle style;
        style.fillTriangles = fill;
        RenderPass pass(m_target, Window{Matrix(1.0), PixelRect{0, 0, 8, 8}}, defaultAttributes(nullptr), style);
        pass.visitGeometry(geometry(m_triangle));
        pass.visitGeometry(geometry(m_point));
    }

    static const Geometry& geometry(TQ3GeometryObject handle)
    {
        return static_cast<const Geometry&>(*static_cast<Object*>(handle));
    }

    NullRenderTarget m_target;
    TQ3GeometryObject m_triangle = nullptr;
    TQ3GeometryObject m_point = nullptr;
};

TEST_F(RenderPassTest, FilledTrianglesAndPointsReachTheTargetThroughTheInterface)
{
    drawAll(true);
    ASSERT_TRUE(m_target.endFrame().ok());
    const std::vector<std::string>& calls = m_target.calls();
    ASSERT_GE(calls.size(), 4u);
    EXPECT_EQ(calls.front(), "beginFrame");
    EXPECT_EQ(calls[1], "setMatrix");
    EXPECT_EQ(calls.back(), "endFrame");
    // The matrix is handed over once: both geometries share it.
    EXPECT_EQ(m_target.count("setMatrix"), 1u);
    EXPECT_EQ(m_target.count("setFaceOptions"), 1u);
    // Anti-aliasing is off by default: the target is never told about it.
    EXPECT_EQ(m_target.count("setAntiAlias"), 0u);
    // One draw per mesh: the triangle filled, then the point.
    const std::vector<NullRenderTarget::DrawRecord>& draws = m_target.draws();
    ASSERT_EQ(draws.size(), 2u);
    EXPECT_EQ(draws[0].triangles, 1u);
    EXPECT_EQ(draws[0].fill, Shading::Fill::kFilled);
    EXPECT_FALSE(draws[0].edgesAlone);
    EXPECT_EQ(draws[1].triangles, 0u);
    EXPECT_EQ(draws[1].points, 1u);
    ASSERT_NE(m_target.pixels(), nullptr);
    EXPECT_EQ(m_target.rowBytes(), 32u);
}

TEST_F(RenderPassTest, TheWireframeRendererAsksForATrianglesEdges)
{
    drawAll(false);
    const std::vector<NullRenderTarget::DrawRecord>& draws = m_target.draws();
    ASSERT_EQ(draws.size(), 2u);
    EXPECT_EQ(draws[0].triangles, 1u);
    EXPECT_EQ(draws[0].fill, Shading::Fill::kEdges);
    EXPECT_TRUE(draws[0].edgesAlone);
    EXPECT_EQ(m_target.count("setFaceOptions"), 0u);
    EXPECT_EQ(draws[1].points, 1u);
}

TEST_F(RenderPassTest, TheTransparencyColourReachesTheTargetChannelByChannel)
{
    // The triangle's set: transparency (0.2, 0.9, 0.3); its first vertex's
    // own: (1, 0, 0.5); the other two take the triangle's. Out-of-range
    // channels are clamped to 0..1 one by one.
    const TQ3ColorRGB shared{0.2f, 0.9f, 0.3f}, own{1.5f, -1.0f, 0.5f};
    TQ3AttributeSet set = Q3AttributeSet_New();
    TQ3AttributeSet first = Q3AttributeSet_New();
    ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeTransparencyColor, &shared), kQ3Success);
    ASSERT_EQ(Q3AttributeSet_Add(first, kQ3AttributeTypeTransparencyColor, &own), kQ3Success);
    const TQ3TriangleData data{{{{0, 0, 0}, first}, {{1, 0, 0}, nullptr}, {{0, 1, 0}, nullptr}}, set};
    TQ3GeometryObject tinted = Q3Triangle_New(&data);
    ASSERT_NE(tinted, nullptr);
    {
        RenderStyle style;
        style.fillTriangles = true;
        RenderPass pass(m_target, Window{Matrix(1.0), PixelRect{0, 0, 8, 8}}, defaultAttributes(nullptr), style);
        pass.visitGeometry(geometry(tinted));
        pass.visitGeometry(geometry(m_triangle));
    }
    Q3Object_Dispose(tinted);
    Q3Object_Dispose(first);
    Q3Object_Dispose(set);
    const std::vector<NullRenderTarget::DrawRecord>& draws = m_target.draws();
    ASSERT_EQ(draws.size(), 2u);
    EXPECT_FLOAT_EQ(draws[0].opacity.r, 0.2f);
    EXPECT_FLOAT_EQ(draws[0].opacity.g, 0.9f);
    EXPECT_FLOAT_EQ(draws[0].opacity.b, 0.3f);
    ASSERT_EQ(draws[0].opacityRgb.size(), 9u);
    const float expected[9] = {1.0f, 0.0f, 0.5f, 0.2f, 0.9f, 0.3f, 0.2f, 0.9f, 0.3f};
    for (int i = 0; i < 9; ++i)
        EXPECT_FLOAT_EQ(draws[0].opacityRgb[std::size_t(i)], expected[i]) << "value " << i;
    // Without a transparency colour: opaque, no array.
    EXPECT_FLOAT_EQ(draws[1].opacity.r, 1.0f);
    EXPECT_FLOAT_EQ(draws[1].opacity.g, 1.0f);
    EXPECT_FLOAT_EQ(draws[1].opacity.b, 1.0f);
    EXPECT_TRUE(draws[1].opacityRgb.empty());
}

} // namespace
} // namespace q3
