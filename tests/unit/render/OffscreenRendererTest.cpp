// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "render/OffscreenRenderer.h"
#include "render/GlContext.h"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>
#include <vector>

namespace q3 {
namespace {

using Pixel = std::array<std::uint8_t, 4>;

// Channel values k / 255 convert to exactly k, with no rounding tie.
constexpr float level(int k)
{
    return float(k) / 255.0f;
}

const RgbaColor kClear{level(51), level(102), level(204), 1.0f};
const Pixel kClearPixel{51, 102, 204, 255};
const RgbColor kWhite{1.0f, 1.0f, 1.0f};
const Pixel kWhitePixel{255, 255, 255, 255};
const Pixel kOutside{0, 0, 0, 0};

// Row-vector matrix (p' = p * M, m[row * 4 + column]) taking pixel
// coordinates of a width x height pane, y downwards, to clip space.
std::array<float, 16> pixelOrtho(int width, int height)
{
    return {2.0f / float(width), 0, 0, 0, //
            0, -2.0f / float(height), 0, 0, //
            0, 0, 1, 0, //
            -1, 1, 0, 1};
}

// Starts a frame of width x height pixels, all of it the pane, drawn in
// pixel coordinates.
bool beginPixelFrame(OffscreenRenderer& renderer, int width, int height)
{
    return renderer.beginFrame(width, height, kClear, PixelRect{0, 0, width, height}) &&
           renderer.setMatrix(pixelOrtho(width, height).data());
}

Pixel pixelAt(const OffscreenRenderer& renderer, int x, int y)
{
    const std::uint8_t* p = renderer.pixels() + renderer.rowBytes() * std::size_t(y) + std::size_t(x) * 4;
    return {p[0], p[1], p[2], p[3]};
}

std::vector<std::uint8_t> imageOf(const OffscreenRenderer& renderer)
{
    return std::vector<std::uint8_t>(renderer.pixels(),
                                     renderer.pixels() + renderer.rowBytes() * renderer.height());
}

// Expects every pixel of the image to be `inside` within rect and `outside`
// elsewhere, except the listed exceptions; reports the first few mismatches.
void expectImage(const OffscreenRenderer& renderer, const PixelRect& rect, const Pixel& inside,
                 const Pixel& outside, const std::vector<std::pair<std::array<int, 2>, Pixel>>& exceptions = {})
{
    int mismatches = 0;
    for (int y = 0; y < int(renderer.height()); ++y) {
        for (int x = 0; x < int(renderer.width()); ++x) {
            const bool in = x >= rect.x && x < rect.x + rect.width && y >= rect.y && y < rect.y + rect.height;
            Pixel expected = in ? inside : outside;
            for (const auto& exception : exceptions)
                if (exception.first[0] == x && exception.first[1] == y)
                    expected = exception.second;
            const Pixel actual = pixelAt(renderer, x, y);
            if (actual != expected && ++mismatches <= 8)
                ADD_FAILURE() << "pixel (" << x << ", " << y << ") is " << int(actual[0]) << ","
                              << int(actual[1]) << "," << int(actual[2]) << "," << int(actual[3])
                              << " expected " << int(expected[0]) << "," << int(expected[1]) << ","
                              << int(expected[2]) << "," << int(expected[3]);
        }
    }
    EXPECT_EQ(mismatches, 0);
}

// A deterministic scene exercising every primitive: strips, segments,
// triangles and wide points, under two matrices, with coordinates that are
// not on any pixel grid.
void drawScene(OffscreenRenderer& renderer, int variant)
{
    std::uint32_t seed = 12345u + std::uint32_t(variant) * 7919u;
    auto next = [&seed]() {
        seed = seed * 1664525u + 1013904223u;
        return float(seed >> 8) / float(1u << 24);
    };
    std::vector<float> xyz;
    const std::array<float, 16> identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const std::array<float, 16> tilted{0.8f, 0.3f, 0, 0, -0.3f, 0.8f, 0, 0, 0, 0, 1, 0, 0.05f, -0.1f, 0, 1.2f};
    for (int strip = 0; strip < 60; ++strip) {
        xyz.clear();
        for (int i = 0; i < 33; ++i) {
            xyz.push_back(next() * 2.2f - 1.1f);
            xyz.push_back(next() * 2.2f - 1.1f);
            xyz.push_back(next() * 2.0f - 1.0f);
        }
        ASSERT_TRUE(renderer.setMatrix((strip % 2 ? tilted : identity).data()));
        ASSERT_TRUE(renderer.drawLineStrip(xyz.data(), 33, RgbColor{next(), next(), next()}));
    }
    xyz.clear();
    for (int i = 0; i < 30; ++i)
        xyz.push_back(next() * 2.0f - 1.0f);
    ASSERT_TRUE(renderer.drawTriangles(xyz.data(), 6, RgbColor{0.3f, 0.7f, 0.1f}));
    ASSERT_TRUE(renderer.drawLines(xyz.data(), 10, RgbColor{0.9f, 0.2f, 0.4f}));
    ASSERT_TRUE(renderer.drawPoints(xyz.data(), 10, RgbColor{1.0f, 1.0f, 0.0f}, 3.5f));
}

void renderScene(OffscreenRenderer& renderer, int variant, std::uint32_t width = 96, std::uint32_t height = 72)
{
    ASSERT_TRUE(renderer.beginFrame(width, height, kClear, PixelRect{0, 0, int(width), int(height)}));
    drawScene(renderer, variant);
    RenderResult ended = renderer.endFrame();
    ASSERT_TRUE(ended) << ended.message;
}

TEST(RenderOffscreen, DrawsHorizontalLineAtExpectedRow)
{
    OffscreenRenderer renderer;
    ASSERT_TRUE(beginPixelFrame(renderer, 24, 16));
    // From the centre of pixel (2, 5) to the centre of pixel (12, 5): the
    // diamond-exit rule lights the first pixel and not the last.
    const float line[] = {2.5f, 5.5f, 0.0f, 12.5f, 5.5f, 0.0f};
    ASSERT_TRUE(renderer.drawLineStrip(line, 2, kWhite));
    ASSERT_TRUE(renderer.endFrame());
    std::vector<std::pair<std::array<int, 2>, Pixel>> lit;
    for (int x = 2; x <= 11; ++x)
        lit.push_back({{x, 5}, kWhitePixel});
    expectImage(renderer, PixelRect{0, 0, 24, 16}, kClearPixel, kOutside, lit);
}

TEST(RenderOffscreen, DrawsVerticalLineAtExpectedColumnTopDown)
{
    OffscreenRenderer renderer;
    ASSERT_TRUE(beginPixelFrame(renderer, 16, 20));
    // Down the image from the centre of pixel (7, 1) to that of (7, 9). The
    // diamond-exit rule would light rows 1..8; llvmpipe leaves out the first
    // row of this y-major line, which OpenGL allows (the fragment count may
    // differ by one). Pinned here so that a rasterizer change shows up.
    const float line[] = {7.5f, 1.5f, 0.0f, 7.5f, 9.5f, 0.0f};
    ASSERT_TRUE(renderer.drawLineStrip(line, 2, kWhite));
    ASSERT_TRUE(renderer.endFrame());
    std::vector<std::pair<std::array<int, 2>, Pixel>> lit;
    for (int y = 2; y <= 8; ++y)
        lit.push_back({{7, y}, kWhitePixel});
    expectImage(renderer, PixelRect{0, 0, 16, 20}, kClearPixel, kOutside, lit);
}

TEST(RenderOffscreen, DoubleMatrixGivesSameImageAsFloatMatrix)
{
    const std::array<float, 16> single = pixelOrtho(24, 16);
    double twice[16];
    for (int i = 0; i < 16; ++i)
        twice[i] = single[i];
    const float strip[] = {1.5f, 1.5f, 0.0f, 20.5f, 13.5f, 0.0f, 3.5f, 12.5f, 0.0f};

    OffscreenRenderer a;
    ASSERT_TRUE(a.beginFrame(24, 16, kClear, PixelRect{0, 0, 24, 16}));
    ASSERT_TRUE(a.setMatrix(single.data()));
    ASSERT_TRUE(a.drawLineStrip(strip, 3, kWhite));
    ASSERT_TRUE(a.endFrame());
    OffscreenRenderer b;
    ASSERT_TRUE(b.beginFrame(24, 16, kClear, PixelRect{0, 0, 24, 16}));
    ASSERT_TRUE(b.setMatrix(twice));
    ASSERT_TRUE(b.drawLineStrip(strip, 3, kWhite));
    ASSERT_TRUE(b.endFrame());
    EXPECT_EQ(imageOf(a), imageOf(b));
    EXPECT_EQ(pixelAt(a, 1, 1), kWhitePixel);
}

TEST(RenderOffscreen, ClearColorFillsPaneOnly)
{
    OffscreenRenderer renderer;
    const PixelRect pane{10, 20, 30, 15};
    ASSERT_TRUE(renderer.beginFrame(64, 48, kClear, pane));
    ASSERT_TRUE(renderer.endFrame());
    EXPECT_EQ(renderer.width(), 64u);
    EXPECT_EQ(renderer.height(), 48u);
    EXPECT_EQ(renderer.rowBytes(), 64u * 4);
    expectImage(renderer, pane, kClearPixel, kOutside);
}

TEST(RenderOffscreen, PaneSmallerThanImageReceivesClipSpace)
{
    OffscreenRenderer renderer;
    const PixelRect pane{8, 4, 20, 10};
    ASSERT_TRUE(renderer.beginFrame(40, 30, kClear, pane));
    ASSERT_TRUE(renderer.setMatrix(pixelOrtho(pane.width, pane.height).data()));
    // Pane-local pixel centres (3, 2) .. (9, 2), and a line far wider than
    // the pane on its row 7: it is clipped to the pane.
    const float inside[] = {3.5f, 2.5f, 0.0f, 10.5f, 2.5f, 0.0f};
    const float wide[] = {-50.5f, 7.5f, 0.0f, 70.5f, 7.5f, 0.0f};
    ASSERT_TRUE(renderer.drawLineStrip(inside, 2, kWhite));
    ASSERT_TRUE(renderer.drawLines(wide, 2, kWhite));
    // A wide point on the pane's corner stays inside the pane.
    const float corner[] = {0.0f, 0.0f, 0.0f};
    ASSERT_TRUE(renderer.drawPoints(corner, 1, kWhite, 6.0f));
    ASSERT_TRUE(renderer.endFrame());

    std::vector<std::pair<std::array<int, 2>, Pixel>> lit;
    for (int x = 3; x <= 9; ++x)
        lit.push_back({{pane.x + x, pane.y + 2}, kWhitePixel});
    for (int x = 0; x < pane.width; ++x)
        lit.push_back({{pane.x + x, pane.y + 7}, kWhitePixel});
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x)
            lit.push_back({{pane.x + x, pane.y + y}, kWhitePixel});
    expectImage(renderer, pane, kClearPixel, kOutside, lit);
}

TEST(RenderOffscreen, PaneReachingOutsideImageKeepsItsMapping)
{
    OffscreenRenderer renderer;
    const PixelRect pane{-6, -3, 20, 12};
    ASSERT_TRUE(renderer.beginFrame(16, 16, kClear, pane));
    ASSERT_TRUE(renderer.setMatrix(pixelOrtho(pane.width, pane.height).data()));
    const float line[] = {8.5f, 5.5f, 0.0f, 12.5f, 5.5f, 0.0f};
    ASSERT_TRUE(renderer.drawLineStrip(line, 2, kWhite));
    ASSERT_TRUE(renderer.endFrame());
    std::vector<std::pair<std::array<int, 2>, Pixel>> lit;
    for (int x = 8; x <= 11; ++x)
        lit.push_back({{x - 6, 5 - 3}, kWhitePixel});
    expectImage(renderer, PixelRect{0, 0, 14, 9}, kClearPixel, kOutside, lit);
}

TEST(RenderOffscreen, FillsTrianglesAndPointsOnExactPixels)
{
    OffscreenRenderer renderer;
    ASSERT_TRUE(beginPixelFrame(renderer, 32, 24));
    // Two triangles covering [2, 6) x [3, 8) with edges on pixel boundaries.
    const float quad[] = {2, 3, 0, 6, 3, 0, 6, 8, 0, 2, 3, 0, 6, 8, 0, 2, 8, 0};
    ASSERT_TRUE(renderer.drawTriangles(quad, 6, kWhite));
    const float points[] = {20.5f, 10.5f, 0.0f, 25.5f, 15.5f, 0.0f};
    ASSERT_TRUE(renderer.drawPoints(points, 1, kWhite));
    ASSERT_TRUE(renderer.drawPoints(points + 3, 1, RgbColor{1.0f, 0.0f, 0.0f}, 3.0f));
    ASSERT_TRUE(renderer.endFrame());

    std::vector<std::pair<std::array<int, 2>, Pixel>> lit;
    for (int y = 3; y < 8; ++y)
        for (int x = 2; x < 6; ++x)
            lit.push_back({{x, y}, kWhitePixel});
    lit.push_back({{20, 10}, kWhitePixel});
    for (int y = 14; y <= 16; ++y)
        for (int x = 24; x <= 26; ++x)
            lit.push_back({{x, y}, Pixel{255, 0, 0, 255}});
    expectImage(renderer, PixelRect{0, 0, 32, 24}, kClearPixel, kOutside, lit);
}

TEST(RenderOffscreen, LaterPrimitivesPaintOverEarlierOnes)
{
    OffscreenRenderer renderer;
    ASSERT_TRUE(beginPixelFrame(renderer, 16, 16));
    const float line[] = {1.5f, 4.5f, 0.0f, 9.5f, 4.5f, 0.0f};
    const float quad[] = {0, 0, 0, 16, 0, 0, 16, 16, 0, 0, 0, 0, 16, 16, 0, 0, 16, 0};
    ASSERT_TRUE(renderer.drawLineStrip(line, 2, kWhite));
    ASSERT_TRUE(renderer.drawTriangles(quad, 6, RgbColor{0.0f, 1.0f, 0.0f}));
    ASSERT_TRUE(renderer.drawLineStrip(line, 2, RgbColor{1.0f, 0.0f, 0.0f}));
    ASSERT_TRUE(renderer.endFrame());
    EXPECT_EQ(pixelAt(renderer, 3, 4), (Pixel{255, 0, 0, 255}));
    EXPECT_EQ(pixelAt(renderer, 3, 5), (Pixel{0, 255, 0, 255}));
}

// Single-coloured draws are batched apart from draws with per-vertex
// colours (positions only, the colour set once per run): each keeps its
// own colour whichever kind it follows, in one batch and in order.
TEST(RenderOffscreen, SingleColouredAndPerVertexColouredDrawsKeepTheirColours)
{
    OffscreenRenderer renderer;
    ASSERT_TRUE(beginPixelFrame(renderer, 16, 16));
    const float row1[] = {1.5f, 1.5f, 0.0f, 9.5f, 1.5f, 0.0f};
    const float row3[] = {1.5f, 3.5f, 0.0f, 9.5f, 3.5f, 0.0f};
    const float row5[] = {1.5f, 5.5f, 0.0f, 9.5f, 5.5f, 0.0f};
    const float row7[] = {1.5f, 7.5f, 0.0f, 9.5f, 7.5f, 0.0f};
    const float green[] = {0.0f, 1.0f, 0.0f, 0.0f, 1.0f, 0.0f};
    const float points[] = {12.5f, 1.5f, 0.0f, 12.5f, 3.5f, 0.0f};
    // Per-vertex green, then single red and blue strips, then per-vertex
    // green over the blue strip's start (drawn later), then two point draws
    // of different colours that must not merge into one.
    ASSERT_TRUE(renderer.drawArrays(DrawMode::kLineStrip, row1, green, 2, kWhite, false));
    ASSERT_TRUE(renderer.drawLineStrip(row3, 2, RgbColor{1.0f, 0.0f, 0.0f}));
    ASSERT_TRUE(renderer.drawLineStrip(row5, 2, RgbColor{0.0f, 0.0f, 1.0f}));
    const float over[] = {1.5f, 5.5f, 0.0f, 4.5f, 5.5f, 0.0f};
    ASSERT_TRUE(renderer.drawArrays(DrawMode::kLineStrip, over, green, 2, kWhite, false));
    ASSERT_TRUE(renderer.drawLineStrip(row7, 2, RgbColor{1.0f, 0.0f, 0.0f}));
    ASSERT_TRUE(renderer.drawPoints(points, 1, RgbColor{1.0f, 1.0f, 0.0f}));
    ASSERT_TRUE(renderer.drawPoints(points + 3, 1, RgbColor{0.0f, 1.0f, 1.0f}));
    ASSERT_TRUE(renderer.endFrame());
    EXPECT_EQ(pixelAt(renderer, 5, 1), (Pixel{0, 255, 0, 255}));
    EXPECT_EQ(pixelAt(renderer, 5, 3), (Pixel{255, 0, 0, 255}));
    EXPECT_EQ(pixelAt(renderer, 2, 5), (Pixel{0, 255, 0, 255}));
    EXPECT_EQ(pixelAt(renderer, 6, 5), (Pixel{0, 0, 255, 255}));
    EXPECT_EQ(pixelAt(renderer, 5, 7), (Pixel{255, 0, 0, 255}));
    EXPECT_EQ(pixelAt(renderer, 12, 1), (Pixel{255, 255, 0, 255}));
    EXPECT_EQ(pixelAt(renderer, 12, 3), (Pixel{0, 255, 255, 255}));
}

TEST(RenderOffscreen, RepeatedFramesAreBitIdentical)
{
    OffscreenRenderer renderer;
    renderScene(renderer, 0);
    const std::vector<std::uint8_t> first = imageOf(renderer);
    renderScene(renderer, 0);
    EXPECT_EQ(imageOf(renderer), first);
    renderScene(renderer, 1);
    EXPECT_NE(imageOf(renderer), first);
    renderScene(renderer, 0);
    EXPECT_EQ(imageOf(renderer), first);

    OffscreenRenderer fresh;
    renderScene(fresh, 0);
    EXPECT_EQ(imageOf(fresh), first);
}

TEST(RenderOffscreen, ResizingBetweenFramesMatchesFreshRenderers)
{
    OffscreenRenderer reference;
    renderScene(reference, 2, 50, 40);
    const std::vector<std::uint8_t> small = imageOf(reference);
    OffscreenRenderer other;
    renderScene(other, 2, 130, 70);
    const std::vector<std::uint8_t> large = imageOf(other);

    OffscreenRenderer renderer;
    for (int i = 0; i < 3; ++i) {
        renderScene(renderer, 2, 50, 40);
        EXPECT_EQ(imageOf(renderer), small);
        renderScene(renderer, 2, 130, 70);
        EXPECT_EQ(imageOf(renderer), large);
    }
}

TEST(RenderOffscreen, TwoThreadsMatchSequentialRendering)
{
    // Same size on purpose: older OSMesa shared one buffer between contexts
    // of equal size, which this would catch.
    std::vector<std::uint8_t> expected[2];
    for (int variant = 0; variant < 2; ++variant) {
        OffscreenRenderer renderer;
        renderScene(renderer, variant + 3);
        expected[variant] = imageOf(renderer);
    }
    ASSERT_NE(expected[0], expected[1]);

    constexpr int kFrames = 25;
    std::atomic<int> ready{0};
    std::atomic<int> mismatches[2] = {{0}, {0}};
    std::atomic<int> failures{0};
    auto work = [&](int variant) {
        OffscreenRenderer renderer;
        ready.fetch_add(1);
        while (ready.load() < 2) {
        }
        for (int frame = 0; frame < kFrames; ++frame) {
            if (!renderer.beginFrame(96, 72, kClear, PixelRect{0, 0, 96, 72})) {
                failures.fetch_add(1);
                return;
            }
            drawScene(renderer, variant + 3);
            if (!renderer.endFrame()) {
                failures.fetch_add(1);
                return;
            }
            if (imageOf(renderer) != expected[variant])
                mismatches[variant].fetch_add(1);
        }
    };
    std::thread first(work, 0);
    std::thread second(work, 1);
    first.join();
    second.join();
    EXPECT_EQ(failures.load(), 0);
    EXPECT_EQ(mismatches[0].load(), 0);
    EXPECT_EQ(mismatches[1].load(), 0);
}

// FrameOptions::bgraImage: each backend delivers the frame straight into
// the caller's image (rows padded here, the padding left alone), B, G, R,
// A, the very pixels an ordinary frame gives; with a pane that is not the
// whole image it is left untouched and the frame drawn as usual.
TEST(RenderOffscreen, AFrameOfferedTheCallersImageDrawsTheSamePixelsThere)
{
    constexpr std::uint32_t kWidth = 96, kHeight = 72, kRowPixels = kWidth + 3;
    for (const GlBackend backend : {GlBackend::kOsMesa, GlBackend::kEgl}) {
        if (!glBackendAvailable(backend))
            continue;
        OffscreenRenderer reference(backend);
        ASSERT_TRUE(reference.beginFrame(kWidth, kHeight, kClear, PixelRect{0, 0, int(kWidth), int(kHeight)}));
        drawScene(reference, 7);
        ASSERT_TRUE(reference.endFrame());
        EXPECT_FALSE(reference.drewInPlace());
        const std::vector<std::uint8_t> expected = imageOf(reference);

        for (const bool wholePane : {true, false}) {
            std::vector<std::uint8_t> bgra(std::size_t(kRowPixels) * 4 * kHeight, 0x5A);
            OffscreenRenderer renderer(backend);
            FrameOptions options;
            options.bgraImage = bgra.data();
            options.bgraRowBytes = std::size_t(kRowPixels) * 4;
            const PixelRect pane = wholePane ? PixelRect{0, 0, int(kWidth), int(kHeight)}
                                             : PixelRect{0, 0, int(kWidth), int(kHeight) - 1};
            ASSERT_TRUE(renderer.beginFrame(kWidth, kHeight, kClear, pane, options));
            drawScene(renderer, 7);
            ASSERT_TRUE(renderer.endFrame());
            const bool inPlace = wholePane;
            EXPECT_EQ(renderer.drewInPlace(), inPlace) << glBackendName(backend) << " whole pane " << wholePane;
            std::size_t wrong = 0, padding = 0, untouched = 0;
            for (std::uint32_t y = 0; y < kHeight; ++y)
                for (std::uint32_t x = 0; x < kRowPixels; ++x)
                    for (int c = 0; c < 4; ++c) {
                        const std::uint8_t got = bgra[(std::size_t(y) * kRowPixels + x) * 4 + std::size_t(c)];
                        if (!inPlace || x >= kWidth) {
                            (x >= kWidth ? padding : untouched) += got != 0x5A;
                            continue;
                        }
                        const int rgba = c == 3 ? 3 : 2 - c; // B, G, R, A from R, G, B, A
                        wrong += got != expected[(std::size_t(y) * kWidth + x) * 4 + std::size_t(rgba)];
                    }
            EXPECT_EQ(wrong, 0u) << glBackendName(backend);
            EXPECT_EQ(padding, 0u) << glBackendName(backend);
            EXPECT_EQ(untouched, 0u) << glBackendName(backend);
            if (!inPlace && wholePane)
                EXPECT_EQ(imageOf(renderer), expected) << glBackendName(backend);
        }
    }
}

TEST(RenderOffscreen, InterleavedFramesOnOneThreadStaySeparate)
{
    OffscreenRenderer reference[2];
    renderScene(reference[0], 5);
    renderScene(reference[1], 6);

    OffscreenRenderer a;
    OffscreenRenderer b;
    ASSERT_TRUE(a.beginFrame(96, 72, kClear, PixelRect{0, 0, 96, 72}));
    ASSERT_TRUE(b.beginFrame(96, 72, kClear, PixelRect{0, 0, 96, 72}));
    drawScene(a, 5);
    drawScene(b, 6);
    ASSERT_TRUE(b.endFrame());
    ASSERT_TRUE(a.endFrame());
    EXPECT_EQ(imageOf(a), imageOf(reference[0]));
    EXPECT_EQ(imageOf(b), imageOf(reference[1]));
}

TEST(RenderOffscreen, LargeBatchFlushedMidFrameGivesSameImage)
{
    OffscreenRenderer reference;
    renderScene(reference, 7);

    // 1.2 million points behind the far plane are clipped away but force the
    // batch through OpenGL in the middle of the frame.
    std::vector<float> hidden(std::size_t(1200000) * 3, 0.0f);
    for (std::size_t i = 2; i < hidden.size(); i += 3)
        hidden[i] = 5.0f;
    OffscreenRenderer renderer;
    ASSERT_TRUE(renderer.beginFrame(96, 72, kClear, PixelRect{0, 0, 96, 72}));
    const float first[] = {-1.0f, -1.0f, 0.0f, 1.0f, 1.0f, 0.0f};
    ASSERT_TRUE(renderer.drawLineStrip(first, 2, RgbColor{1.0f, 0.0f, 1.0f}));
    ASSERT_TRUE(renderer.drawPoints(hidden.data(), hidden.size() / 3, kWhite));
    ASSERT_TRUE(renderer.drawPoints(hidden.data(), hidden.size() / 3, kWhite));
    drawScene(renderer, 7);
    ASSERT_TRUE(renderer.endFrame());

    OffscreenRenderer withDiagonal;
    ASSERT_TRUE(withDiagonal.beginFrame(96, 72, kClear, PixelRect{0, 0, 96, 72}));
    ASSERT_TRUE(withDiagonal.drawLineStrip(first, 2, RgbColor{1.0f, 0.0f, 1.0f}));
    drawScene(withDiagonal, 7);
    ASSERT_TRUE(withDiagonal.endFrame());
    EXPECT_EQ(imageOf(renderer), imageOf(withDiagonal));
    EXPECT_NE(imageOf(renderer), imageOf(reference));
}

TEST(RenderOffscreen, CallsOutsideAFrameReportWrongState)
{
    OffscreenRenderer renderer;
    const float xyz[] = {0, 0, 0, 1, 1, 0};
    const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    EXPECT_EQ(renderer.drawLineStrip(xyz, 2, kWhite).status, RenderStatus::kWrongState);
    EXPECT_EQ(renderer.setMatrix(identity).status, RenderStatus::kWrongState);
    EXPECT_EQ(renderer.endFrame().status, RenderStatus::kWrongState);
    EXPECT_EQ(renderer.pixels(), nullptr);

    ASSERT_TRUE(renderer.beginFrame(8, 8, kClear, PixelRect{0, 0, 8, 8}));
    EXPECT_TRUE(renderer.inFrame());
    RenderResult twice = renderer.beginFrame(8, 8, kClear, PixelRect{0, 0, 8, 8});
    EXPECT_EQ(twice.status, RenderStatus::kWrongState);
    EXPECT_FALSE(twice.message.empty());
    renderer.cancelFrame();
    EXPECT_FALSE(renderer.inFrame());
    EXPECT_EQ(renderer.drawLines(xyz, 2, kWhite).status, RenderStatus::kWrongState);
    EXPECT_TRUE(renderer.beginFrame(8, 8, kClear, PixelRect{0, 0, 8, 8}));
    EXPECT_TRUE(renderer.endFrame());
}

TEST(RenderOffscreen, BadFrameParametersAreRejected)
{
    OffscreenRenderer renderer;
    const PixelRect pane{0, 0, 8, 8};
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(renderer.beginFrame(0, 8, kClear, pane).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.beginFrame(8, 0, kClear, pane).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.beginFrame(16385, 8, kClear, pane).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.beginFrame(8, UINT32_MAX, kClear, pane).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.beginFrame(8, 8, kClear, PixelRect{0, 0, 0, 8}).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.beginFrame(8, 8, kClear, PixelRect{0, 0, 8, -1}).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.beginFrame(8, 8, kClear, PixelRect{0, 0, 16385, 8}).status,
              RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.beginFrame(8, 8, kClear, PixelRect{INT32_MIN, 0, 8, 8}).status,
              RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.beginFrame(8, 8, RgbaColor{nan, 0, 0, 1}, pane).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.beginFrame(8, 8, RgbaColor{0, 0, 0, INFINITY}, pane).status,
              RenderStatus::kInvalidArgument);
    EXPECT_FALSE(renderer.inFrame());
}

TEST(RenderOffscreen, BadDrawArgumentsAreRejectedAndDrawNothing)
{
    OffscreenRenderer renderer;
    ASSERT_TRUE(renderer.beginFrame(16, 16, kClear, PixelRect{0, 0, 16, 16}));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const float goodThenNan[] = {-1, 0, 0, 1, 0, 0, 0, nan, 0};
    const float withInf[] = {-1, 0, 0, 1, inf, 0};
    const float three[] = {-1, 0, 0, 1, 0, 0, 0, 1, 0};
    const float badMatrix[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, nan, 1};
    const double hugeMatrix[16] = {1e300, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

    EXPECT_EQ(renderer.drawLineStrip(nullptr, 2, kWhite).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.drawLineStrip(goodThenNan, 3, kWhite).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.drawLines(withInf, 2, kWhite).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.drawLines(three, 3, kWhite).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.drawTriangles(three, 2, kWhite).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.drawLineStrip(three, 2, RgbColor{nan, 0, 0}).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.drawPoints(three, 1, kWhite, 0.0f).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.drawPoints(three, 1, kWhite, nan).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.drawPoints(three, 1, kWhite, -inf).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.setMatrix(badMatrix).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.setMatrix(hugeMatrix).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(renderer.setMatrix(static_cast<const float*>(nullptr)).status, RenderStatus::kInvalidArgument);
    // Empty calls and a one-point strip are valid and draw nothing.
    EXPECT_TRUE(renderer.drawLineStrip(nullptr, 0, kWhite));
    EXPECT_TRUE(renderer.drawLineStrip(three, 1, kWhite));
    ASSERT_TRUE(renderer.endFrame());
    expectImage(renderer, PixelRect{0, 0, 16, 16}, kClearPixel, kOutside);
}

// A bitmap lands pixel for pixel: its top left at the anchor's pixel plus
// the offsets, most significant bit first (or least), clipped at the pane's
// edge, whatever the matrix does to lengths; a later draw still uses the
// caller's matrix.
TEST(RenderOffscreen, DrawBitmapPlacesEachSetBitOnOnePixel)
{
    OffscreenRenderer renderer;
    ASSERT_TRUE(beginPixelFrame(renderer, 24, 16));
    const unsigned char bits[] = {0xA0, 0x00, 0x40, 0x01}; // 9 x 2, two bytes a row
    BitmapImage image;
    image.bits = bits;
    image.rowBytes = 2;
    image.width = 9;
    image.height = 2;
    image.xOffset = -1;
    image.yOffset = 2;
    const float anchor[] = {5.5f, 3.5f, 0.0f}; // pixel (5, 3)
    ASSERT_TRUE(renderer.drawBitmap(anchor, image, kWhite));
    image.lsbFirst = true;
    const float corner[] = {17.5f, 0.5f, 0.0f}; // pixel (17, 0): columns past 23 are clipped
    image.xOffset = 0;
    image.yOffset = 0;
    ASSERT_TRUE(renderer.drawBitmap(corner, image, kWhite));
    const float line[] = {0.5f, 12.5f, 0.0f, 3.5f, 12.5f, 0.0f};
    ASSERT_TRUE(renderer.drawLineStrip(line, 2, kWhite));
    ASSERT_TRUE(renderer.endFrame());
    expectImage(renderer, PixelRect{0, 0, 24, 16}, kClearPixel, kOutside,
                {{{4, 5}, kWhitePixel}, {{6, 5}, kWhitePixel}, {{5, 6}, kWhitePixel}, // 0xA0; 0x40 (0x01: past 9)
                 {{22, 0}, kWhitePixel}, {{23, 1}, kWhitePixel}, // lsb first: 5 (7 clipped); 6 (8 clipped)
                 {{0, 12}, kWhitePixel}, {{1, 12}, kWhitePixel}, {{2, 12}, kWhitePixel}}); // the line
}

TEST(RenderOffscreen, DrawBitmapChecksItsArgumentsAndSkipsAnchorsOutsideTheDepthRange)
{
    OffscreenRenderer renderer;
    const unsigned char bits[] = {0xFF};
    BitmapImage image;
    image.bits = bits;
    image.rowBytes = 1;
    image.width = 8;
    image.height = 1;
    const float anchor[] = {4.5f, 4.5f, 0.0f};
    EXPECT_EQ(renderer.drawBitmap(anchor, image, kWhite).status, RenderStatus::kWrongState);
    ASSERT_TRUE(beginPixelFrame(renderer, 16, 16));
    EXPECT_EQ(renderer.drawBitmap(nullptr, image, kWhite).status, RenderStatus::kInvalidArgument);
    image.width = 9;
    EXPECT_EQ(renderer.drawBitmap(anchor, image, kWhite).status, RenderStatus::kInvalidArgument);
    image.width = 8;
    image.bits = nullptr;
    EXPECT_EQ(renderer.drawBitmap(anchor, image, kWhite).status, RenderStatus::kInvalidArgument);
    image.bits = bits;
    const float nan[] = {std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f};
    EXPECT_EQ(renderer.drawBitmap(nan, image, kWhite).status, RenderStatus::kInvalidArgument);
    const float far[] = {4.5f, 4.5f, 2.0f}; // clip z 2 > w 1
    EXPECT_TRUE(renderer.drawBitmap(far, image, kWhite));
    image.xOffset = 1L << 30; // wholly off the pane
    EXPECT_TRUE(renderer.drawBitmap(anchor, image, kWhite));
    ASSERT_TRUE(renderer.endFrame());
    expectImage(renderer, PixelRect{0, 0, 16, 16}, kClearPixel, kOutside);
}

} // namespace
} // namespace q3
