// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// OffscreenRenderer::setTexture, addTexture, useTexture and textured
// triangles: the contract's errors, a texel per pixel under nearest
// sampling, wrap against clamp, the texture kept across a batch flushed
// mid-frame, textures of a frame used again after others, and untextured
// draws left as they were.

#include "render/OffscreenRenderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace q3 {
namespace {

using Pixel = std::array<std::uint8_t, 4>;

Pixel pixelAt(const OffscreenRenderer& renderer, int x, int y)
{
    const std::uint8_t* p = renderer.pixels() + renderer.rowBytes() * std::size_t(y) + std::size_t(x) * 4;
    return {p[0], p[1], p[2], p[3]};
}

// A 2 x 2 RGB24 texture: red, green / blue, white (row 0 the top).
const std::uint8_t kTexels[12] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
const Pixel kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255}, kBlue{0, 0, 255, 255}, kWhite{255, 255, 255, 255};

TextureImage texture(bool clamp = false)
{
    TextureImage image;
    image.pixels = kTexels;
    image.layout.width = 2;
    image.layout.height = 2;
    image.layout.rowBytes = 6;
    image.layout.pixelType = PixelType::kRGB24;
    image.layout.byteOrder = ByteOrder::kBig;
    image.clampS = clamp;
    image.clampT = clamp;
    return image;
}

// A square filling an 8 x 8 pane (identity matrix: clip space), its
// texture coordinates from (s0, t0) at the top left to (s1, t1).
void drawSquare(OffscreenRenderer& renderer, float s0, float t0, float s1, float t1)
{
    const float xyz[12] = {-1, 1, 0, 1, 1, 0, 1, -1, 0, -1, -1, 0};
    const float st[8] = {s0, t0, s1, t0, s1, t1, s0, t1};
    const std::uint32_t indices[6] = {0, 1, 2, 0, 2, 3};
    ASSERT_TRUE(renderer.drawElements(DrawMode::kTriangles, xyz, nullptr, 4, indices, 6, RgbColor{1, 1, 1}, true, st));
}

void begin(OffscreenRenderer& renderer)
{
    ASSERT_TRUE(renderer.beginFrame(8, 8, RgbaColor{0, 0, 0, 1}, PixelRect{0, 0, 8, 8}));
}

TEST(OffscreenTexture, SetTextureRefusesOutsideAFrameAndBadImages)
{
    OffscreenRenderer renderer;
    TextureImage image = texture();
    EXPECT_EQ(renderer.setTexture(&image).status, RenderStatus::kWrongState);
    begin(renderer);
    TextureImage noPixels = image;
    noPixels.pixels = nullptr;
    EXPECT_EQ(renderer.setTexture(&noPixels).status, RenderStatus::kInvalidArgument);
    TextureImage narrowRows = image;
    narrowRows.layout.rowBytes = 5;
    EXPECT_EQ(renderer.setTexture(&narrowRows).status, RenderStatus::kInvalidArgument);
    TextureImage empty = image;
    empty.layout.width = 0;
    EXPECT_EQ(renderer.setTexture(&empty).status, RenderStatus::kInvalidArgument);
    EXPECT_TRUE(renderer.setTexture(nullptr));
    // A non-finite texture coordinate is refused once a texture is set.
    ASSERT_TRUE(renderer.setTexture(&image));
    const float xyz[9] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};
    const float st[6] = {0, 0, 1, 0, std::numeric_limits<float>::quiet_NaN(), 1};
    const std::uint32_t indices[3] = {0, 1, 2};
    EXPECT_EQ(renderer.drawElements(DrawMode::kTriangles, xyz, nullptr, 3, indices, 3, RgbColor{1, 1, 1}, true, st)
                  .status,
              RenderStatus::kInvalidArgument);
    EXPECT_TRUE(renderer.endFrame());
}

TEST(OffscreenTexture, EachQuarterOfTheSquareShowsItsTexel)
{
    OffscreenRenderer renderer;
    begin(renderer);
    TextureImage image = texture();
    ASSERT_TRUE(renderer.setTexture(&image));
    drawSquare(renderer, 0, 0, 1, 1);
    ASSERT_TRUE(renderer.endFrame());
    EXPECT_EQ(pixelAt(renderer, 1, 1), kRed);
    EXPECT_EQ(pixelAt(renderer, 6, 1), kGreen);
    EXPECT_EQ(pixelAt(renderer, 1, 6), kBlue);
    EXPECT_EQ(pixelAt(renderer, 6, 6), kWhite);
}

TEST(OffscreenTexture, WrapRepeatsAndClampKeepsTheEdge)
{
    // s and t from -1 to 1: wrapped, each quarter of the pane is the whole
    // texture again; clamped, the texture fills the bottom right quarter and
    // the rest repeats its edge texels: the top left quarter its corner
    // (red), the top right its top row, the bottom left its left column.
    for (bool clamp : {false, true}) {
        OffscreenRenderer renderer;
        begin(renderer);
        TextureImage image = texture(clamp);
        ASSERT_TRUE(renderer.setTexture(&image));
        drawSquare(renderer, -1, -1, 1, 1);
        ASSERT_TRUE(renderer.endFrame());
        if (!clamp) {
            EXPECT_EQ(pixelAt(renderer, 0, 0), kRed);
            EXPECT_EQ(pixelAt(renderer, 3, 3), kWhite);
            EXPECT_EQ(pixelAt(renderer, 4, 0), kRed);
            EXPECT_EQ(pixelAt(renderer, 7, 7), kWhite);
        } else {
            EXPECT_EQ(pixelAt(renderer, 0, 0), kRed);
            EXPECT_EQ(pixelAt(renderer, 3, 3), kRed);
            EXPECT_EQ(pixelAt(renderer, 5, 0), kRed);
            EXPECT_EQ(pixelAt(renderer, 7, 0), kGreen);
            EXPECT_EQ(pixelAt(renderer, 7, 7), kWhite);
            EXPECT_EQ(pixelAt(renderer, 0, 5), kRed);
            EXPECT_EQ(pixelAt(renderer, 0, 7), kBlue);
        }
    }
}

TEST(OffscreenTexture, WithoutCoordinatesOrTextureTrianglesKeepTheirColour)
{
    OffscreenRenderer renderer;
    begin(renderer);
    const float xyz[12] = {-1, 1, 0, 1, 1, 0, 1, -1, 0, -1, -1, 0};
    const std::uint32_t indices[6] = {0, 1, 2, 0, 2, 3};
    // Coordinates but no texture: plain.
    const float st[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    ASSERT_TRUE(renderer.drawElements(DrawMode::kTriangles, xyz, nullptr, 4, indices, 6, RgbColor{0, 0, 1}, false, st));
    ASSERT_TRUE(renderer.endFrame());
    EXPECT_EQ(pixelAt(renderer, 4, 4), kBlue);
    // A texture but no coordinates: plain too.
    begin(renderer);
    TextureImage image = texture();
    ASSERT_TRUE(renderer.setTexture(&image));
    ASSERT_TRUE(renderer.drawElements(DrawMode::kTriangles, xyz, nullptr, 4, indices, 6, RgbColor{0, 1, 0}, false));
    ASSERT_TRUE(renderer.endFrame());
    EXPECT_EQ(pixelAt(renderer, 1, 1), kGreen);
    EXPECT_EQ(pixelAt(renderer, 6, 6), kGreen);
}

TEST(OffscreenTexture, TheTextureOutlivesABatchFlushedForNewLights)
{
    // setLighting flushes the batch drawn so far; the texture set before
    // still textures what is drawn after.
    OffscreenRenderer renderer;
    begin(renderer);
    TextureImage image = texture();
    ASSERT_TRUE(renderer.setTexture(&image));
    drawSquare(renderer, 0, 0, 1, 1);
    ASSERT_TRUE(renderer.setLighting(LightingSetup{}));
    drawSquare(renderer, 1, 0, 0, 1); // mirrored left to right
    ASSERT_TRUE(renderer.endFrame());
    EXPECT_EQ(pixelAt(renderer, 1, 1), kGreen);
    EXPECT_EQ(pixelAt(renderer, 6, 6), kBlue);
}

// The same 2 x 2 texture with each row's texels swapped: green, red /
// white, blue.
const std::uint8_t kSwapped[12] = {0, 255, 0, 255, 0, 0, 255, 255, 255, 0, 0, 255};

TEST(OffscreenTexture, AddTextureAndUseTextureRefuseOutsideAFrameAndUnknownIds)
{
    OffscreenRenderer renderer;
    TextureImage image = texture();
    std::uint32_t id = 7;
    EXPECT_EQ(renderer.addTexture(image, id).status, RenderStatus::kWrongState);
    EXPECT_EQ(renderer.useTexture(OffscreenRenderer::kNoTexture).status, RenderStatus::kWrongState);
    EXPECT_EQ(id, 7u);
    begin(renderer);
    TextureImage noPixels = image;
    noPixels.pixels = nullptr;
    EXPECT_EQ(renderer.addTexture(noPixels, id).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(id, 7u);
    EXPECT_EQ(renderer.useTexture(0).status, RenderStatus::kInvalidArgument);
    ASSERT_TRUE(renderer.addTexture(image, id));
    EXPECT_EQ(id, 0u);
    EXPECT_TRUE(renderer.useTexture(id));
    EXPECT_EQ(renderer.useTexture(1).status, RenderStatus::kInvalidArgument);
    EXPECT_TRUE(renderer.useTexture(OffscreenRenderer::kNoTexture));
    ASSERT_TRUE(renderer.endFrame());
    // A new frame starts without the last one's textures.
    begin(renderer);
    EXPECT_EQ(renderer.useTexture(id).status, RenderStatus::kInvalidArgument);
    ASSERT_TRUE(renderer.endFrame());
}

TEST(OffscreenTexture, TexturesAddedOnceAreUsedAgainAfterOthersAndAfterAFlush)
{
    // Two textures, drawn A, B, then A again after a flush: the left half
    // and the right half of the pane each show the last texture drawn there.
    OffscreenRenderer renderer;
    begin(renderer);
    TextureImage a = texture();
    TextureImage b = texture();
    b.pixels = kSwapped;
    std::uint32_t idA = 0, idB = 0;
    ASSERT_TRUE(renderer.addTexture(a, idA));
    ASSERT_TRUE(renderer.addTexture(b, idB));
    EXPECT_NE(idA, idB);
    const float left[12] = {-1, 1, 0, 0, 1, 0, 0, -1, 0, -1, -1, 0};
    const float right[12] = {0, 1, 0, 1, 1, 0, 1, -1, 0, 0, -1, 0};
    const float st[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    const std::uint32_t indices[6] = {0, 1, 2, 0, 2, 3};
    const auto draw = [&](const float* xyz) {
        ASSERT_TRUE(
            renderer.drawElements(DrawMode::kTriangles, xyz, nullptr, 4, indices, 6, RgbColor{1, 1, 1}, true, st));
    };
    ASSERT_TRUE(renderer.useTexture(idA));
    draw(left);
    ASSERT_TRUE(renderer.useTexture(idB));
    draw(right);
    ASSERT_TRUE(renderer.setLighting(LightingSetup{})); // flushes
    ASSERT_TRUE(renderer.useTexture(idA));
    draw(right);
    ASSERT_TRUE(renderer.useTexture(OffscreenRenderer::kNoTexture));
    ASSERT_TRUE(renderer.endFrame());
    // Each half maps the whole texture: its top left quarter is the
    // texel at row 0, column 0.
    EXPECT_EQ(pixelAt(renderer, 0, 0), kRed);
    EXPECT_EQ(pixelAt(renderer, 3, 7), kWhite);
    EXPECT_EQ(pixelAt(renderer, 4, 0), kRed);
    EXPECT_EQ(pixelAt(renderer, 7, 7), kWhite);
    // B (drawn on the right first) shows nowhere: A was drawn over it.
    EXPECT_EQ(pixelAt(renderer, 6, 0), kGreen);
}

TEST(OffscreenTexture, AddTextureRefusesABrokenMipmapChainOrFilter)
{
    OffscreenRenderer renderer;
    begin(renderer);
    // The 2 x 2 image's chain is one 1 x 1 image.
    const std::uint8_t grey[3] = {128, 128, 128};
    TextureLevel level;
    level.pixels = grey;
    level.layout.width = 1;
    level.layout.height = 1;
    level.layout.rowBytes = 3;
    level.layout.pixelType = PixelType::kRGB24;
    TextureImage image = texture();
    image.filter = TextureFilter::kTrilinear;
    image.mipmaps = {level};
    std::uint32_t id = 77;
    EXPECT_TRUE(renderer.addTexture(image, id));
    EXPECT_EQ(id, 0u);
    TextureImage tooMany = image;
    tooMany.mipmaps = {level, level};
    id = 77;
    EXPECT_EQ(renderer.addTexture(tooMany, id).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(id, 77u);
    TextureImage wrongSize = image;
    wrongSize.mipmaps[0].layout.width = 2;
    wrongSize.mipmaps[0].layout.rowBytes = 6;
    EXPECT_EQ(renderer.addTexture(wrongSize, id).status, RenderStatus::kInvalidArgument);
    TextureImage noPixels = image;
    noPixels.mipmaps[0].pixels = nullptr;
    EXPECT_EQ(renderer.addTexture(noPixels, id).status, RenderStatus::kInvalidArgument);
    TextureImage badLayout = image;
    badLayout.mipmaps[0].layout.rowBytes = 2;
    EXPECT_EQ(renderer.addTexture(badLayout, id).status, RenderStatus::kInvalidArgument);
    // A 4 x 2 image's chain is 2 x 1, then 1 x 1; stopping early is refused.
    const std::uint8_t wide[24] = {};
    TextureImage four = image;
    four.pixels = wide;
    four.layout.width = 4;
    four.layout.rowBytes = 12;
    TextureLevel twoByOne = level;
    twoByOne.pixels = wide;
    twoByOne.layout.width = 2;
    twoByOne.layout.rowBytes = 6;
    four.mipmaps = {twoByOne};
    EXPECT_EQ(renderer.addTexture(four, id).status, RenderStatus::kInvalidArgument);
    four.mipmaps = {twoByOne, level};
    EXPECT_TRUE(renderer.addTexture(four, id));
    EXPECT_EQ(id, 1u);
    // A filter outside the enumeration, as a caller's bytes might hold.
    TextureImage badFilter = texture();
    const int seven = 7;
    std::memcpy(&badFilter.filter, &seven, sizeof seven);
    EXPECT_EQ(renderer.addTexture(badFilter, id).status, RenderStatus::kInvalidArgument);
    EXPECT_TRUE(renderer.endFrame());
}

TEST(OffscreenTexture, BilinearFilteringMixesNeighbouringTexels)
{
    // The 2 x 2 texture over the 8 x 8 pane: pixel (x, y) samples s = (x +
    // 1/2) / 8, so texel coordinate a = s * 2 - 1/2 = (x - 1.5) / 4, clamped
    // at the edges: pixel 3 is 3/8 of the way from column 0 to column 1.
    OffscreenRenderer renderer;
    begin(renderer);
    TextureImage image = texture(true);
    image.filter = TextureFilter::kBilinear;
    ASSERT_TRUE(renderer.setTexture(&image));
    drawSquare(renderer, 0, 0, 1, 1);
    ASSERT_TRUE(renderer.endFrame());
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const double fa = std::min(std::max((x - 1.5) / 4.0, 0.0), 1.0);
            const double fb = std::min(std::max((y - 1.5) / 4.0, 0.0), 1.0);
            const Pixel top[2] = {kRed, kGreen}, bottom[2] = {kBlue, kWhite};
            const Pixel got = pixelAt(renderer, x, y);
            for (int k = 0; k < 3; ++k) {
                const double upper = top[0][k] + (top[1][k] - top[0][k]) * fa;
                const double lower = bottom[0][k] + (bottom[1][k] - bottom[0][k]) * fa;
                EXPECT_NEAR(got[k], upper + (lower - upper) * fb, 2.0) << "pixel " << x << ", " << y << " channel " << k;
            }
        }
}

} // namespace
} // namespace q3
