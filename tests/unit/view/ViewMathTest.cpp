// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The small conversions the view layer is built on: pane rounding, frustum
// to pane pixels, frustum to OpenGL clip space, matrix order and layout.

#include "view/CurveTessellation.h"
#include "view/DrawContext.h"
#include "base/Matrix.h"
#include "view/RenderPass.h"

#include <gtest/gtest.h>

namespace q3 {
namespace {

TEST(ViewMath, PaneEdgesRoundToTheNearestPixelBoundary)
{
    const PixelRect exact = paneRect(TQ3Area{{10, 20}, {110, 70}});
    EXPECT_EQ(exact.x, 10);
    EXPECT_EQ(exact.y, 20);
    EXPECT_EQ(exact.width, 100);
    EXPECT_EQ(exact.height, 50);
    const PixelRect rounded = paneRect(TQ3Area{{9.6f, 20.4f}, {110.4f, 70.6f}});
    EXPECT_EQ(rounded.x, 10);
    EXPECT_EQ(rounded.y, 20);
    EXPECT_EQ(rounded.width, 100);
    EXPECT_EQ(rounded.height, 51);
    // A sliver still covers one pixel; huge coordinates are clamped, not overflowed.
    const PixelRect sliver = paneRect(TQ3Area{{3.1f, 3.1f}, {3.2f, 3.2f}});
    EXPECT_EQ(sliver.width, 1);
    EXPECT_EQ(sliver.height, 1);
    const PixelRect huge = paneRect(TQ3Area{{-1e30f, 0}, {1e30f, 1}});
    // Edges clamp to +-2^29 so that the width, max - min, still fits an int.
    EXPECT_EQ(huge.x, -(1 << 29));
    EXPECT_EQ(huge.width, 1 << 30);
}

TEST(ViewMath, FrustumCornersMapToThePaneCorners)
{
    const PixelRect pane{20, 10, 200, 100};
    const glm::dvec2 topLeft = frustumToPane(pane, -1, 1);
    EXPECT_DOUBLE_EQ(topLeft.x, 20);
    EXPECT_DOUBLE_EQ(topLeft.y, 10);
    const glm::dvec2 bottomRight = frustumToPane(pane, 1, -1);
    EXPECT_DOUBLE_EQ(bottomRight.x, 220);
    EXPECT_DOUBLE_EQ(bottomRight.y, 110);
}

TEST(ViewMath, FrustumDepthMapsOntoOpenGLClipDepth)
{
    // Frustum z 0 (hither) is clip z -w, z -1 (yon) is +w.
    const Matrix m = frustumToClip();
    const glm::dvec4 hither = m * glm::dvec4(0.3, -0.2, 0.0, 2.0);
    EXPECT_DOUBLE_EQ(hither.z, -2.0);
    EXPECT_DOUBLE_EQ(hither.x, 0.3);
    EXPECT_DOUBLE_EQ(hither.w, 2.0);
    const glm::dvec4 yon = m * glm::dvec4(0.0, 0.0, -2.0, 2.0);
    EXPECT_DOUBLE_EQ(yon.z, 2.0);
}

TEST(ViewMath, MatricesShareQuickDraw3DsLayoutAndOrder)
{
    TQ3Matrix4x4 translate{};
    for (int i = 0; i < 4; ++i)
        translate.value[i][i] = 1;
    translate.value[3][0] = 5; // row-vector translation by x = 5
    TQ3Matrix4x4 scale{};
    scale.value[0][0] = 2;
    scale.value[1][1] = scale.value[2][2] = scale.value[3][3] = 1;
    // then(a, b): a first. Scale then translate sends x = 1 to 7.
    const glm::dvec4 p = transformPoint(then(fromQ3(scale), fromQ3(translate)), glm::dvec3(1, 0, 0));
    EXPECT_DOUBLE_EQ(p.x, 7);
    const glm::dvec4 q = transformPoint(then(fromQ3(translate), fromQ3(scale)), glm::dvec3(1, 0, 0));
    EXPECT_DOUBLE_EQ(q.x, 12);
    const TQ3Matrix4x4 back = toQ3(fromQ3(translate));
    EXPECT_EQ(back.value[3][0], 5.0f);
    const Matrix m = fromQ3(translate);
    EXPECT_EQ((&m[0][0])[3 * 4 + 0], 5.0); // element [row 3][column 0] in row-major memory
}

} // namespace
} // namespace q3
