// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// RenderTarget::draw on the OpenGL backend: a mesh and its Shading give the
// very image of the primitive calls they stand for (drawn in a second frame
// of the same renderer), and bad meshes are refused.

#include "render/OffscreenRenderer.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace q3 {
namespace {

constexpr std::uint32_t kSize = 16;

// Row-vector matrix taking pixel coordinates (y down) of the image to clip
// space.
const std::array<float, 16> kPixels = {2.0f / kSize, 0, 0, 0, 0, -2.0f / kSize, 0, 0, 0, 0, 1, 0, -1, 1, 0, 1};

// A square of 4 vertices from (3, 3) to (12, 12), two triangles, its
// outline as 4 edges, a diagonal line and one point.
const float kSquare[] = {3.5f, 3.5f, 0, 12.5f, 3.5f, 0, 12.5f, 12.5f, 0, 3.5f, 12.5f, 0, 8.5f, 1.5f, 0};
const std::uint32_t kTriangles[] = {0, 1, 2, 0, 2, 3};
const std::uint32_t kEdges[] = {0, 1, 1, 2, 2, 3, 3, 0};
const std::uint32_t kLine[] = {0, 2};
const std::uint32_t kPoint[] = {4};
const float kColors[] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0, 0, 1, 1};

MeshView square()
{
    MeshView mesh;
    mesh.positions = kSquare;
    mesh.vertexCount = 5;
    mesh.triangles = kTriangles;
    mesh.triangleCount = 2;
    mesh.edges = kEdges;
    mesh.edgeCount = 4;
    mesh.lines = kLine;
    mesh.lineCount = 1;
    mesh.points = kPoint;
    mesh.pointCount = 1;
    return mesh;
}

class OffscreenMeshDraw : public ::testing::Test {
protected:
    // The image of one frame whose draws `body` makes.
    std::vector<std::uint8_t> frame(const std::function<void()>& body)
    {
        EXPECT_TRUE(m_renderer.beginFrame(kSize, kSize, RgbaColor{0, 0, 0, 1}, PixelRect{0, 0, kSize, kSize}).ok());
        EXPECT_TRUE(m_renderer.setMatrix(kPixels.data()).ok());
        body();
        EXPECT_TRUE(m_renderer.endFrame().ok());
        return std::vector<std::uint8_t>(m_renderer.pixels(), m_renderer.pixels() + kSize * kSize * 4);
    }

    static bool anyLit(const std::vector<std::uint8_t>& image)
    {
        for (std::size_t i = 0; i < image.size(); i += 4)
            if (image[i] != 0 || image[i + 1] != 0 || image[i + 2] != 0)
                return true;
        return false;
    }

    OffscreenRenderer m_renderer;
};

TEST_F(OffscreenMeshDraw, FilledMeshIsItsTrianglesThenItsLineThenItsPoint)
{
    Shading shading;
    shading.rgb = kColors;
    const MeshView mesh = square();
    const std::vector<std::uint8_t> drawn = frame([&] { ASSERT_TRUE(m_renderer.draw(mesh, shading).ok()); });
    const std::vector<std::uint8_t> expected = frame([&] {
        ASSERT_TRUE(m_renderer.drawElements(DrawMode::kTriangles, kSquare, kColors, 5, kTriangles, 6, shading.color,
                                            true)
                        .ok());
        ASSERT_TRUE(m_renderer.drawElements(DrawMode::kLines, kSquare, kColors, 5, kLine, 2, shading.color, true).ok());
        ASSERT_TRUE(m_renderer.drawElements(DrawMode::kPoints, kSquare, kColors, 5, kPoint, 1, shading.color, false).ok());
    });
    ASSERT_TRUE(anyLit(expected));
    EXPECT_EQ(drawn, expected);
}

TEST_F(OffscreenMeshDraw, EdgesFillDrawsTheMeshOutlineInItsColour)
{
    Shading shading;
    shading.fill = Shading::Fill::kEdges;
    shading.color = RgbColor{1, 1, 0};
    MeshView mesh = square();
    mesh.lineCount = 0;
    mesh.pointCount = 0;
    const std::vector<std::uint8_t> drawn = frame([&] { ASSERT_TRUE(m_renderer.draw(mesh, shading).ok()); });
    std::vector<float> segments;
    for (std::uint32_t index : kEdges)
        segments.insert(segments.end(), kSquare + 3 * index, kSquare + 3 * index + 3);
    const std::vector<std::uint8_t> expected =
        frame([&] { ASSERT_TRUE(m_renderer.drawLines(segments.data(), 8, shading.color).ok()); });
    ASSERT_TRUE(anyLit(expected));
    EXPECT_EQ(drawn, expected);
    // Inside the outline nothing is drawn.
    const std::size_t centre = (8 * kSize + 8) * 4;
    EXPECT_EQ(drawn[centre], 0);
    EXPECT_EQ(drawn[centre + 1], 0);
}

TEST_F(OffscreenMeshDraw, PointsFillDrawsEveryVertex)
{
    Shading shading;
    shading.fill = Shading::Fill::kPoints;
    MeshView mesh = square();
    mesh.lineCount = 0;
    mesh.pointCount = 0;
    const std::vector<std::uint8_t> drawn = frame([&] { ASSERT_TRUE(m_renderer.draw(mesh, shading).ok()); });
    const std::vector<std::uint8_t> expected =
        frame([&] { ASSERT_TRUE(m_renderer.drawPoints(kSquare, 5, shading.color).ok()); });
    EXPECT_EQ(drawn, expected);
}

TEST_F(OffscreenMeshDraw, EdgesOfAMeshWithoutTrianglesAreDrawnOnlyWhenAlone)
{
    MeshView mesh = square();
    mesh.triangles = nullptr;
    mesh.triangleCount = 0;
    mesh.lineCount = 0;
    mesh.pointCount = 0;
    Shading shading;
    EXPECT_FALSE(anyLit(frame([&] { ASSERT_TRUE(m_renderer.draw(mesh, shading).ok()); })));
    shading.edgesAlone = true;
    EXPECT_TRUE(anyLit(frame([&] { ASSERT_TRUE(m_renderer.draw(mesh, shading).ok()); })));
}

TEST_F(OffscreenMeshDraw, BadMeshesAreRefused)
{
    Shading shading;
    EXPECT_EQ(m_renderer.draw(square(), shading).status, RenderStatus::kWrongState);
    frame([&] {
        MeshView noPositions = square();
        noPositions.positions = nullptr;
        EXPECT_EQ(m_renderer.draw(noPositions, shading).status, RenderStatus::kInvalidArgument);

        const std::uint32_t pastTheEnd[] = {0, 5};
        MeshView badLine = square();
        badLine.triangleCount = 0;
        badLine.lines = pastTheEnd;
        EXPECT_EQ(m_renderer.draw(badLine, shading).status, RenderStatus::kInvalidArgument);

        const std::uint32_t badPoint[] = {UINT32_MAX};
        MeshView point = square();
        point.triangleCount = 0;
        point.lineCount = 0;
        point.points = badPoint;
        EXPECT_EQ(m_renderer.draw(point, shading).status, RenderStatus::kInvalidArgument);

        const Strip longStrip{3, 3};
        MeshView strip = square();
        strip.triangleCount = 0;
        strip.lineCount = 0;
        strip.pointCount = 0;
        strip.strips = &longStrip;
        strip.stripCount = 1;
        EXPECT_EQ(m_renderer.draw(strip, shading).status, RenderStatus::kInvalidArgument);

        // Lit flat, so every corner is copied: the opacity array must have
        // one r g b per vertex.
        const float rgb[] = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f};
        Shading lit;
        lit.lit = true;
        lit.surface.interpolation = 0;
        lit.opacity.rgb = rgb;
        lit.opacity.count = 2;
        EXPECT_EQ(m_renderer.draw(square(), lit).status, RenderStatus::kInvalidArgument);

        Shading textured;
        const float st[10] = {};
        textured.st = st;
        textured.texture = 7;
        EXPECT_EQ(m_renderer.draw(square(), textured).status, RenderStatus::kInvalidArgument);
    });
}

// Textures are kept on the GPU from frame to frame only while their bytes
// stay the same: an image changed in place, in the same buffer, is drawn
// with its new texels, and the old one again when it comes back.
TEST_F(OffscreenMeshDraw, ATextureChangedBetweenFramesIsDrawnAsItIsNow)
{
    // One ARGB32 texel, big-endian: A, R, G, B in memory.
    std::uint8_t texel[4] = {255, 200, 10, 20};
    TextureImage image;
    image.pixels = texel;
    image.layout.width = 1;
    image.layout.height = 1;
    image.layout.rowBytes = 4;
    const float st[10] = {};
    const auto drawTextured = [&] {
        return frame([&] {
            std::uint32_t id = kNoTexture;
            ASSERT_TRUE(m_renderer.addTexture(image, id).ok());
            Shading shading;
            shading.st = st;
            shading.texture = id;
            MeshView mesh = square();
            mesh.lineCount = 0;
            mesh.pointCount = 0;
            ASSERT_TRUE(m_renderer.draw(mesh, shading).ok());
        });
    };
    const std::size_t centre = (8 * kSize + 8) * 4;
    const auto centreOf = [&](const std::vector<std::uint8_t>& pixels) {
        return std::array<int, 3>{pixels[centre], pixels[centre + 1], pixels[centre + 2]};
    };
    EXPECT_EQ(centreOf(drawTextured()), (std::array<int, 3>{200, 10, 20}));
    EXPECT_EQ(centreOf(drawTextured()), (std::array<int, 3>{200, 10, 20}));
    texel[1] = 30;
    texel[3] = 90;
    EXPECT_EQ(centreOf(drawTextured()), (std::array<int, 3>{30, 10, 90}));
    texel[1] = 200;
    texel[3] = 20;
    EXPECT_EQ(centreOf(drawTextured()), (std::array<int, 3>{200, 10, 20}));
    // Clamped instead of repeated is another texture (its wrap mode).
    image.clampS = true;
    EXPECT_EQ(centreOf(drawTextured()), (std::array<int, 3>{200, 10, 20}));
}

} // namespace
} // namespace q3
