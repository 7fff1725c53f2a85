// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The process's OpenGL contexts, lent by renderers between their frames
// (OffscreenRenderer.cpp, GlResources and ContextPool): renderers drawn one
// after another share one context, a frame begun while another is open gets
// a context of its own, and what a shared context keeps (textures,
// compared byte for byte) never shows one renderer another's image.

#include "render/OffscreenRenderer.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace q3 {
namespace {

constexpr int kSide = 8;

// A 2 x 2 RGB24 texture (row 0 the top).
using Texels = std::array<std::uint8_t, 12>;
const Texels kFirst = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
const Texels kSecond = {255, 255, 255, 0, 0, 255, 0, 255, 0, 255, 0, 0};

TextureImage textureOf(const Texels& texels)
{
    TextureImage image;
    image.pixels = texels.data();
    image.layout.width = 2;
    image.layout.height = 2;
    image.layout.rowBytes = 6;
    image.layout.pixelType = PixelType::kRGB24;
    image.layout.byteOrder = ByteOrder::kBig;
    return image;
}

// One frame of a size x size image: a square over the whole pane in
// `color`, textured with `texels` unless null (uv 0..1 from the top left).
bool drawFrame(OffscreenRenderer& renderer, const Texels* texels, const RgbColor& color, int size = kSide)
{
    if (!renderer.beginFrame(std::uint32_t(size), std::uint32_t(size), RgbaColor{0, 0, 0, 1},
                             PixelRect{0, 0, size, size}))
        return false;
    const float xyz[12] = {-1, 1, 0, 1, 1, 0, 1, -1, 0, -1, -1, 0};
    const float st[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    const std::uint32_t indices[6] = {0, 1, 2, 0, 2, 3};
    if (texels != nullptr) {
        const TextureImage image = textureOf(*texels);
        if (!renderer.setTexture(&image))
            return false;
    }
    if (!renderer.drawElements(DrawMode::kTriangles, xyz, nullptr, 4, indices, 6, color, texels != nullptr,
                               texels != nullptr ? st : nullptr))
        return false;
    return bool(renderer.endFrame());
}

// Whether every pixel is what the frame above draws: under nearest
// sampling, pixel (x, y) of the 8 x 8 image shows texel (x / 4, y / 4)
// times white; untextured, `color` as bytes.
bool showsFrame(const OffscreenRenderer& renderer, const Texels* texels, const RgbColor& color)
{
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const std::uint8_t* p = renderer.pixels() + renderer.rowBytes() * std::size_t(y) + std::size_t(x) * 4;
            std::uint8_t want[3];
            if (texels != nullptr) {
                const std::uint8_t* texel = texels->data() + 6 * (y / (kSide / 2)) + 3 * (x / (kSide / 2));
                for (int c = 0; c < 3; ++c)
                    want[c] = texel[c];
            } else {
                const float channels[3] = {color.r, color.g, color.b};
                for (int c = 0; c < 3; ++c)
                    want[c] = std::uint8_t(channels[c] * 255.0f + 0.5f);
            }
            if (p[0] != want[0] || p[1] != want[1] || p[2] != want[2] || p[3] != 255)
                return false;
        }
    return true;
}

const RgbColor kWhite{1, 1, 1};

TEST(OffscreenContextPool, RenderersDrawnInTurnShareOneContext)
{
    // A size no other test of this file draws, so that no idle context of
    // it exists before.
    constexpr int kSize = 37;
    const std::uint64_t before = OffscreenRenderer::contextsMade();
    {
        OffscreenRenderer renderers[3];
        const RgbColor colors[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (int round = 0; round < 3; ++round)
            for (int i = 0; i < 3; ++i)
                ASSERT_TRUE(drawFrame(renderers[i], nullptr, colors[i], kSize));
        EXPECT_EQ(OffscreenRenderer::contextsMade() - before, 1u);
        for (int i = 0; i < 3; ++i) {
            const std::uint8_t* p = renderers[i].pixels() + renderers[i].rowBytes() * 20 + 4 * 20;
            EXPECT_EQ(p[0], i == 0 ? 255 : 0);
            EXPECT_EQ(p[1], i == 1 ? 255 : 0);
            EXPECT_EQ(p[2], i == 2 ? 255 : 0);
        }

        // A frame begun while another is open: a second context.
        const PixelRect pane{0, 0, kSize, kSize};
        ASSERT_TRUE(renderers[0].beginFrame(kSize, kSize, RgbaColor{0, 0, 0, 1}, pane));
        ASSERT_TRUE(renderers[1].beginFrame(kSize, kSize, RgbaColor{0, 0, 0, 1}, pane));
        EXPECT_EQ(OffscreenRenderer::contextsMade() - before, 2u);
        ASSERT_TRUE(renderers[1].endFrame());
        ASSERT_TRUE(renderers[0].endFrame());

        // Both are idle now: frames in turn make none.
        for (int round = 0; round < 2; ++round)
            for (int i = 0; i < 3; ++i)
                ASSERT_TRUE(drawFrame(renderers[i], nullptr, colors[i], kSize));
        EXPECT_EQ(OffscreenRenderer::contextsMade() - before, 2u);
    }
    // Kept after the renderers are gone, for the next one.
    OffscreenRenderer later;
    ASSERT_TRUE(drawFrame(later, nullptr, kWhite, kSize));
    EXPECT_EQ(OffscreenRenderer::contextsMade() - before, 2u);
}

TEST(OffscreenContextPool, TexturesStayEachRenderersOwnInASharedContext)
{
    const std::uint64_t before = OffscreenRenderer::contextsMade();
    auto a = std::make_unique<OffscreenRenderer>();
    OffscreenRenderer b;
    OffscreenRenderer c;
    // c's texture starts with a's bytes, in memory of its own.
    Texels mine = kFirst;
    for (int round = 0; round < 4; ++round) {
        ASSERT_TRUE(drawFrame(*a, &kFirst, kWhite));
        EXPECT_TRUE(showsFrame(*a, &kFirst, kWhite)) << "round " << round;
        ASSERT_TRUE(drawFrame(b, &kSecond, kWhite));
        EXPECT_TRUE(showsFrame(b, &kSecond, kWhite)) << "round " << round;
        ASSERT_TRUE(drawFrame(c, &mine, kWhite));
        EXPECT_TRUE(showsFrame(c, &mine, kWhite)) << "round " << round;
        ASSERT_TRUE(drawFrame(b, nullptr, RgbColor{0, 1, 0}));
        EXPECT_TRUE(showsFrame(b, nullptr, RgbColor{0, 1, 0})) << "round " << round;
        // Edited in place: a new texture for c, and a's unchanged.
        mine[3 * (round % 4)] ^= 0xFF;
    }
    // a goes, with the textures it drew last (c may still draw its bytes).
    a.reset();
    for (int round = 0; round < 2; ++round) {
        ASSERT_TRUE(drawFrame(c, &kFirst, kWhite));
        EXPECT_TRUE(showsFrame(c, &kFirst, kWhite)) << "round " << round;
        ASSERT_TRUE(drawFrame(b, &kSecond, kWhite));
        EXPECT_TRUE(showsFrame(b, &kSecond, kWhite)) << "round " << round;
    }
    EXPECT_LE(OffscreenRenderer::contextsMade() - before, 1u);
}

TEST(OffscreenContextPool, ACancelledFrameGivesItsContextBack)
{
    OffscreenRenderer a;
    OffscreenRenderer b;
    ASSERT_TRUE(drawFrame(a, &kFirst, kWhite));
    ASSERT_TRUE(drawFrame(b, &kSecond, kWhite));
    const std::uint64_t before = OffscreenRenderer::contextsMade();

    ASSERT_TRUE(a.beginFrame(kSide, kSide, RgbaColor{0, 0, 0, 1}, PixelRect{0, 0, kSide, kSide}));
    const TextureImage image = textureOf(kSecond);
    ASSERT_TRUE(a.setTexture(&image));
    a.cancelFrame();

    ASSERT_TRUE(drawFrame(b, &kFirst, kWhite));
    EXPECT_TRUE(showsFrame(b, &kFirst, kWhite));
    ASSERT_TRUE(drawFrame(a, &kSecond, kWhite));
    EXPECT_TRUE(showsFrame(a, &kSecond, kWhite));
    EXPECT_EQ(OffscreenRenderer::contextsMade(), before);
}

} // namespace
} // namespace q3
