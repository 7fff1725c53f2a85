// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The OSMesa backend's opacity and fog calls (RenderTarget::setOpacity,
// setFog): their argument checks, and pixels against the formulas evaluated
// here: a translucent pixel is a C + (1 - a) B, a fogged one f C + (1 - f) F.

#include "render/OffscreenRenderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace q3 {
namespace {

constexpr int kSize = 16;
const RgbaColor kClear{0.0f, 0.0f, 0.0f, 1.0f};
const RgbColor kBehind{0.2f, 0.6f, 1.0f};
const RgbColor kFront{1.0f, 0.4f, 0.0f};

// Pixel coordinates of the pane (y down) to clip space; z is kept.
std::array<float, 16> pixelOrtho()
{
    return {2.0f / kSize, 0, 0, 0, 0, -2.0f / kSize, 0, 0, 0, 0, 1, 0, -1, 1, 0, 1};
}

// Two triangles covering columns x0..x1 of every row at depth z.
std::vector<float> quad(float x0, float x1, float z)
{
    return {x0, 0, z, x1, 0, z, x1, float(kSize), z, x0, 0, z, x1, float(kSize), z, x0, float(kSize), z};
}

int byteOf(double v)
{
    return int(std::lround(std::min(1.0, std::max(0.0, v)) * 255.0));
}

// Every pixel of columns x0..x1 (ends excluded) within 1 of the colour.
void expectColumns(const OffscreenRenderer& renderer, int x0, int x1, double r, double g, double b,
                   const char* what)
{
    int wrong = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::uint8_t* p = renderer.pixels() + renderer.rowBytes() * std::size_t(y) + std::size_t(x) * 4;
            wrong += std::abs(p[0] - byteOf(r)) > 1 || std::abs(p[1] - byteOf(g)) > 1 || std::abs(p[2] - byteOf(b)) > 1;
        }
    EXPECT_EQ(wrong, 0) << what;
}

double blend(double front, double behind, double a)
{
    return a * front + (1 - a) * behind;
}

TEST(OffscreenTranslucency, StateCallsOutsideAFrameReportWrongState)
{
    OffscreenRenderer renderer;
    EXPECT_EQ(renderer.setFog(FogSetup{}).status, RenderStatus::kWrongState);
    EXPECT_EQ(renderer.setOpacity(OpacitySetup{}).status, RenderStatus::kWrongState);
}

TEST(OffscreenTranslucency, BadFogIsRefusedAndTheFogInForceStays)
{
    OffscreenRenderer renderer;
    ASSERT_TRUE(renderer.beginFrame(kSize, kSize, kClear, PixelRect{0, 0, kSize, kSize}));
    const std::array<float, 16> m = pixelOrtho();
    ASSERT_TRUE(renderer.setMatrix(m.data()));
    // The eye distance is the clip z: linear from 0 to 1 keeps half at 0.5.
    FogSetup fog;
    fog.mode = FogSetup::Mode::kLinear;
    fog.start = 0.0f;
    fog.end = 1.0f;
    fog.color[0] = 1.0f;
    fog.color[1] = 1.0f;
    fog.color[2] = 1.0f;
    fog.depthPlane[2] = 1.0f;
    ASSERT_TRUE(renderer.setFog(fog));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    FogSetup bad = fog;
    bad.start = nan;
    EXPECT_EQ(renderer.setFog(bad).status, RenderStatus::kInvalidArgument);
    bad = fog;
    bad.wPlane[3] = std::numeric_limits<float>::infinity();
    EXPECT_EQ(renderer.setFog(bad).status, RenderStatus::kInvalidArgument);
    bad = fog;
    bad.density = -1.0f;
    EXPECT_EQ(renderer.setFog(bad).status, RenderStatus::kInvalidArgument);
    bad = fog;
    bad.end = bad.start;
    EXPECT_EQ(renderer.setFog(bad).status, RenderStatus::kInvalidArgument);
    const std::vector<float> all = quad(0, kSize, 0.5f);
    ASSERT_TRUE(renderer.drawTriangles(all.data(), 6, kFront));
    ASSERT_TRUE(renderer.endFrame());
    expectColumns(renderer, 0, kSize, blend(kFront.r, 1, 0.5), blend(kFront.g, 1, 0.5), blend(kFront.b, 1, 0.5),
                  "linear fog, half way");
}

TEST(OffscreenTranslucency, BadOpacityIsRefused)
{
    OffscreenRenderer renderer;
    ASSERT_TRUE(renderer.beginFrame(kSize, kSize, kClear, PixelRect{0, 0, kSize, kSize}));
    for (float uniform : {-0.1f, 1.5f, std::numeric_limits<float>::quiet_NaN()}) {
        EXPECT_EQ(renderer.setOpacity(OpacitySetup{nullptr, 0, RgbColor{uniform, 1, 1}}).status,
                  RenderStatus::kInvalidArgument);
        EXPECT_EQ(renderer.setOpacity(OpacitySetup{nullptr, 0, RgbColor{1, 1, uniform}}).status,
                  RenderStatus::kInvalidArgument);
    }
    // An array of the wrong length fails the draw, which draws nothing.
    const float rgb[9] = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f};
    ASSERT_TRUE(renderer.setOpacity(OpacitySetup{rgb, 3, RgbColor{1, 1, 1}}));
    const std::array<float, 16> m = pixelOrtho();
    ASSERT_TRUE(renderer.setMatrix(m.data()));
    const std::vector<float> all = quad(0, kSize, 0.0f);
    EXPECT_EQ(renderer.drawTriangles(all.data(), 6, kFront).status, RenderStatus::kInvalidArgument);
    ASSERT_TRUE(renderer.endFrame());
    expectColumns(renderer, 0, kSize, 0, 0, 0, "nothing drawn");
}

// Starts a depth-tested frame over the whole kSize x kSize image, drawn in
// pixel coordinates.
bool beginDepthTestedFrame(OffscreenRenderer& renderer)
{
    FrameOptions options;
    options.depthTest = true;
    const std::array<float, 16> m = pixelOrtho();
    return renderer.beginFrame(kSize, kSize, kClear, PixelRect{0, 0, kSize, kSize}, options) &&
           renderer.setMatrix(m.data());
}

TEST(OffscreenTranslucency, TranslucentTrianglesWaitForTheEndOfTheFrameAcrossAFlush)
{
    OffscreenRenderer renderer;
    ASSERT_TRUE(beginDepthTestedFrame(renderer));
    // Nearer (z -0.5) and translucent, submitted first; setLighting flushes
    // the batch before the opaque one behind it (z 0.5) comes.
    ASSERT_TRUE(renderer.setOpacity(OpacitySetup{nullptr, 0, RgbColor{0.25f, 0.25f, 0.25f}}));
    const std::vector<float> front = quad(0, kSize, -0.5f);
    ASSERT_TRUE(renderer.drawTriangles(front.data(), 6, kFront));
    ASSERT_TRUE(renderer.setOpacity(OpacitySetup{}));
    ASSERT_TRUE(renderer.setLighting(LightingSetup{}));
    const std::vector<float> back = quad(0, kSize, 0.5f);
    ASSERT_TRUE(renderer.drawTriangles(back.data(), 6, kBehind));
    ASSERT_TRUE(renderer.endFrame());
    expectColumns(renderer, 0, kSize, blend(kFront.r, kBehind.r, 0.25), blend(kFront.g, kBehind.g, 0.25),
                  blend(kFront.b, kBehind.b, 0.25), "a quarter of the front over the back");
}

TEST(OffscreenTranslucency, OneDrawSplitsIntoOpaqueAndTranslucentTriangles)
{
    OffscreenRenderer renderer;
    ASSERT_TRUE(beginDepthTestedFrame(renderer));
    const std::vector<float> back = quad(0, kSize, 0.5f);
    ASSERT_TRUE(renderer.drawTriangles(back.data(), 6, kBehind));
    // The left half's two triangles opaque, the right half's at 0.5.
    std::vector<float> front = quad(0, kSize / 2, -0.5f);
    const std::vector<float> right = quad(kSize / 2, kSize, -0.5f);
    front.insert(front.end(), right.begin(), right.end());
    std::vector<float> rgb(3 * 12, 1.0f);
    std::fill(rgb.begin() + 3 * 6, rgb.end(), 0.5f);
    std::vector<std::uint32_t> indices(12);
    for (std::uint32_t i = 0; i < 12; ++i)
        indices[i] = i;
    ASSERT_TRUE(renderer.setOpacity(OpacitySetup{rgb.data(), 12, RgbColor{1, 1, 1}}));
    ASSERT_TRUE(renderer.drawElements(DrawMode::kTriangles, front.data(), nullptr, 12, indices.data(), 12, kFront,
                                      false));
    ASSERT_TRUE(renderer.endFrame());
    expectColumns(renderer, 0, kSize / 2, kFront.r, kFront.g, kFront.b, "opaque half");
    expectColumns(renderer, kSize / 2, kSize, blend(kFront.r, kBehind.r, 0.5), blend(kFront.g, kBehind.g, 0.5),
                  blend(kFront.b, kBehind.b, 0.5), "translucent half");
}

// A full-image quad at one depth, in one colour.
struct Layer {
    float depth;
    RgbColor color;
};

// Draws `layers` in their order as translucent quads (opacity 0.5) over an
// opaque back, then expects each pixel to be every quad blended over the
// one behind, farthest first, quads at one depth in submission order: that
// rule evaluated here (rounded to bytes after each blend, as the image
// stores it).
void expectFarthestFirst(const std::vector<Layer>& layers, const std::string& what)
{
    OffscreenRenderer renderer;
    ASSERT_TRUE(beginDepthTestedFrame(renderer));
    const std::vector<float> back = quad(0, kSize, 0.99f);
    ASSERT_TRUE(renderer.drawTriangles(back.data(), 6, kBehind));
    ASSERT_TRUE(renderer.setOpacity(OpacitySetup{nullptr, 0, RgbColor{0.5f, 0.5f, 0.5f}}));
    for (const Layer& layer : layers) {
        const std::vector<float> triangles = quad(0, kSize, layer.depth);
        ASSERT_TRUE(renderer.drawTriangles(triangles.data(), 6, layer.color));
    }
    ASSERT_TRUE(renderer.endFrame());

    std::vector<Layer> order = layers;
    std::stable_sort(order.begin(), order.end(), [](const Layer& a, const Layer& b) { return a.depth > b.depth; });
    int expected[3] = {byteOf(kBehind.r), byteOf(kBehind.g), byteOf(kBehind.b)};
    for (const Layer& layer : order) {
        const float channels[3] = {layer.color.r, layer.color.g, layer.color.b};
        for (int c = 0; c < 3; ++c)
            expected[c] = int(std::lround(0.5 * channels[c] * 255.0 + 0.5 * expected[c]));
    }
    int wrong = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const std::uint8_t* p = renderer.pixels() + renderer.rowBytes() * std::size_t(y) + std::size_t(x) * 4;
            for (int c = 0; c < 3; ++c)
                wrong += std::abs(p[c] - expected[c]) > 2;
        }
    EXPECT_EQ(wrong, 0) << what << ": expected " << expected[0] << " " << expected[1] << " " << expected[2];
}

// Quads submitted in a scrambled order: 60 at random depths behind 0, and
// in front of them the ones that decide the colour, at 0 and below,
// several at one depth.
TEST(OffscreenTranslucency, TranslucentTrianglesBlendFarthestFirstAndTiesInSubmissionOrder)
{
    std::vector<Layer> layers;
    const float fixedDepths[] = {0.0f, -0.25f, 0.0f, -0.75f, 0.0f, -0.25f, 0.0f};
    std::uint32_t seed = 12345u;
    const auto next = [&seed] {
        seed = seed * 1664525u + 1013904223u;
        return float(seed >> 8) / float(1u << 24);
    };
    for (int i = 0; i < 60; ++i)
        layers.push_back({0.05f + 0.9f * next(), RgbColor{next(), next(), next()}});
    for (std::size_t i = 0; i < std::size(fixedDepths); ++i)
        layers.insert(layers.begin() + std::ptrdiff_t(9 * i), Layer{fixedDepths[i], RgbColor{next(), next(), next()}});
    expectFarthestFirst(layers, "random depths");
}

// Depths a float step or a few apart, whose sort keys share their upper
// 32 bits (the sort orders such runs on its own: by insertion up to 16
// keys, by a merge sort above): a run of 40 quads and one of 6, each
// scrambled, with ties, in a frame of its own.
TEST(OffscreenTranslucency, DepthsAFloatStepApartBlendFarthestFirst)
{
    std::uint32_t seed = 777u;
    const auto next = [&seed] {
        seed = seed * 1664525u + 1013904223u;
        return seed >> 8;
    };
    for (const int length : {40, 6}) {
        std::vector<Layer> layers;
        float depth = -0.75f;
        for (int k = 0; k < length; ++k) {
            // Every fifth a tie with the one before.
            if (k % 5 != 4)
                depth = std::nextafter(depth, 1.0f);
            layers.push_back({depth, RgbColor{float(next() % 256) / 255.0f, float(next() % 256) / 255.0f,
                                              float(next() % 256) / 255.0f}});
        }
        for (std::size_t k = layers.size(); k > 1; --k)
            std::swap(layers[k - 1], layers[next() % k]);
        expectFarthestFirst(layers, "a run of " + std::to_string(length));
    }
}

} // namespace
} // namespace q3
