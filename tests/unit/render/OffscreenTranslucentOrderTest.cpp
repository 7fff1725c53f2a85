// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Translucent meshes drawn unsorted (OffscreenRenderer.cpp, placeInOrder;
// render/SingleCover.h): a retained mesh whose triangles can cover no
// sample twice, alone in its part of the image, is drawn in its own order
// with the very pixels the back-to-front order gives; a mesh that folds
// over itself, one that winds over itself without folding, one that
// reaches outside the view volume, and one that shares pixels with another
// mesh are still sorted, and their pixels are checked against back-to-front
// blending evaluated here.

#include "render/OffscreenRenderer.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace q3 {
namespace {

constexpr int kSize = 32;
const RgbaColor kClear{0.0f, 0.0f, 0.0f, 1.0f};
const RgbColor kBehind{0.2f, 0.6f, 1.0f};
const RgbColor kNear{1.0f, 0.4f, 0.0f};
const RgbColor kFar{0.1f, 1.0f, 0.3f};
constexpr float kOpacity = 0.5f;

// Pixel coordinates of the image (y down) to clip space; z is kept.
std::array<float, 16> pixelOrtho()
{
    return {2.0f / kSize, 0, 0, 0, 0, -2.0f / kSize, 0, 0, 0, 0, 1, 0, -1, 1, 0, 1};
}

// A mesh of its own arrays, with a serial.
struct TestMesh {
    std::vector<float> positions;
    std::vector<float> colors;
    std::vector<std::uint32_t> triangles;
    std::uint64_t serial = Mesh::newSerial();

    std::uint32_t add(float x, float y, float z, const RgbColor& color)
    {
        positions.insert(positions.end(), {x, y, z});
        colors.insert(colors.end(), {color.r, color.g, color.b});
        return std::uint32_t(positions.size() / 3 - 1);
    }
    MeshView view(bool withSerial = true) const
    {
        MeshView mesh;
        mesh.positions = positions.data();
        mesh.vertexCount = positions.size() / 3;
        mesh.triangles = triangles.data();
        mesh.triangleCount = triangles.size() / 3;
        mesh.serial = withSerial ? serial : 0;
        return mesh;
    }
};

// Unlit, translucent at kOpacity, each triangle the colour of its last
// corner (flat) or the corners' colours interpolated.
Shading translucent(const TestMesh& mesh, bool smooth)
{
    Shading shading;
    shading.rgb = mesh.colors.data();
    shading.smooth = smooth;
    shading.opacity = OpacitySetup{nullptr, 0, RgbColor{kOpacity, kOpacity, kOpacity}};
    return shading;
}

// A depth-tested frame: an opaque back over the whole image at z 0.99,
// then `draw`, with `matrix`, its triangles multisampled if `antiAlias`.
template <class Draw>
std::vector<std::uint8_t> frame(OffscreenRenderer& renderer, Draw&& draw,
                                const std::array<float, 16>& matrix = pixelOrtho(), bool antiAlias = false)
{
    FrameOptions options;
    options.depthTest = true;
    const std::array<float, 16> ortho = pixelOrtho();
    EXPECT_TRUE(renderer.beginFrame(kSize, kSize, kClear, PixelRect{0, 0, kSize, kSize}, options).ok());
    AntiAliasOptions smoothing;
    smoothing.triangles = antiAlias;
    EXPECT_TRUE(renderer.setAntiAlias(smoothing).ok());
    EXPECT_TRUE(renderer.setMatrix(ortho.data()).ok());
    const float back[] = {0, 0, 0.99f, kSize, 0, 0.99f, kSize, kSize, 0.99f,
                          0, 0, 0.99f, kSize, kSize, 0.99f, 0, kSize, 0.99f};
    EXPECT_TRUE(renderer.drawTriangles(back, 6, kBehind).ok());
    EXPECT_TRUE(renderer.setMatrix(matrix.data()).ok());
    draw();
    EXPECT_TRUE(renderer.endFrame().ok());
    return std::vector<std::uint8_t>(renderer.pixels(), renderer.pixels() + std::size_t(kSize) * kSize * 4);
}

// One channel blended at kOpacity over `behind` (a byte), rounded to a
// byte as the image stores it.
int over(float front, int behind)
{
    return int(std::lround(kOpacity * front * 255.0 + (1.0 - kOpacity) * behind));
}

// kNear over kFar over kBehind: the back-to-front order where the near and
// the far triangles overlap.
std::array<int, 3> nearOverFar()
{
    const float near[3] = {kNear.r, kNear.g, kNear.b};
    const float far[3] = {kFar.r, kFar.g, kFar.b};
    const float behind[3] = {kBehind.r, kBehind.g, kBehind.b};
    std::array<int, 3> expected;
    for (int c = 0; c < 3; ++c)
        expected[c] = over(near[c], over(far[c], int(std::lround(behind[c] * 255.0))));
    return expected;
}

// Pixel (x, y) within 2 of `expected` in every channel.
void expectPixel(const std::vector<std::uint8_t>& image, int x, int y, const std::array<int, 3>& expected)
{
    const std::uint8_t* p = image.data() + 4 * (std::size_t(y) * kSize + std::size_t(x));
    for (int c = 0; c < 3; ++c)
        EXPECT_LE(std::abs(int(p[c]) - expected[c]), 2)
            << "pixel " << x << ", " << y << " channel " << c << ": " << int(p[c]) << " for " << expected[c];
}

// A 9 x 9 grid over pixels 4..28 whose depth waves (so that its triangles'
// back-to-front order is not their order), its colours varying.
TestMesh wavyGrid(float x0, float x1)
{
    TestMesh mesh;
    constexpr std::uint32_t n = 9;
    for (std::uint32_t j = 0; j < n; ++j)
        for (std::uint32_t i = 0; i < n; ++i) {
            const float u = float(i) / float(n - 1), v = float(j) / float(n - 1);
            mesh.add(x0 + (x1 - x0) * u, 4.0f + 24.0f * v, 0.5f + 0.3f * std::sin(7.0f * u) * std::cos(5.0f * v),
                     RgbColor{u, v, 1.0f - u * v});
        }
    for (std::uint32_t j = 0; j + 1 < n; ++j)
        for (std::uint32_t i = 0; i + 1 < n; ++i) {
            const std::uint32_t a = j * n + i;
            mesh.triangles.insert(mesh.triangles.end(), {a, a + 1, a + n + 1, a, a + n + 1, a + n});
        }
    return mesh;
}

TEST(OffscreenTranslucentOrder, AMeshThatCoversEachSampleOnceIsDrawnUnsortedWithTheSortedPixels)
{
    const TestMesh grid = wavyGrid(4.0f, 28.0f);
    // A perspective divide as well: w grows with z.
    std::array<float, 16> perspective = pixelOrtho();
    perspective[11] = 0.4f;
    perspective[15] = 1.0f;
    // Multisampled too: the argument holds at every sample point.
    for (const bool antiAlias : {false, true})
        for (const std::array<float, 16>& matrix : {pixelOrtho(), perspective}) {
            SCOPED_TRACE(antiAlias ? "multisampled" : "one sample a pixel");
            OffscreenRenderer sorted, unsorted;
            const std::vector<std::uint8_t> expected = frame(
                sorted, [&] { ASSERT_TRUE(sorted.draw(grid.view(false), translucent(grid, true)).ok()); }, matrix,
                antiAlias);
            const std::vector<std::uint8_t> image = frame(
                unsorted, [&] { ASSERT_TRUE(unsorted.draw(grid.view(), translucent(grid, true)).ok()); }, matrix,
                antiAlias);
            EXPECT_EQ(sorted.translucentInOrder(), 0u);
            EXPECT_EQ(unsorted.translucentInOrder(), grid.triangles.size() / 3);
            EXPECT_EQ(image, expected);
        }
}

// Random grids, jittered so that some fold over themselves and some do
// not, each triangle its own colour, under random perspective matrices:
// wherever a grid is drawn unsorted, its image is the sorted one.
TEST(OffscreenTranslucentOrder, RandomGridsDrawnUnsortedGiveTheSortedPixels)
{
    std::uint32_t seed = 2026u;
    const auto next = [&seed] {
        seed = seed * 1664525u + 1013904223u;
        return float(seed >> 8) / float(1u << 24);
    };
    int unsortedGrids = 0, sortedGrids = 0;
    for (int trial = 0; trial < 24; ++trial) {
        TestMesh grid;
        constexpr std::uint32_t n = 7;
        const float jitter = 4.0f * next(); // up to most of a cell (4 px)
        for (std::uint32_t j = 0; j < n; ++j)
            for (std::uint32_t i = 0; i < n; ++i)
                grid.add(4.0f + 4.0f * float(i) + jitter * (next() - 0.5f),
                         4.0f + 4.0f * float(j) + jitter * (next() - 0.5f), 0.1f + 0.8f * next(),
                         RgbColor{next(), next(), next()});
        for (std::uint32_t j = 0; j + 1 < n; ++j)
            for (std::uint32_t i = 0; i + 1 < n; ++i) {
                const std::uint32_t a = j * n + i;
                grid.triangles.insert(grid.triangles.end(), {a, a + 1, a + n + 1, a, a + n + 1, a + n});
            }
        std::array<float, 16> matrix = pixelOrtho();
        matrix[11] = 0.5f * next(); // w = 1 + that z
        OffscreenRenderer sorted, unsorted;
        const std::vector<std::uint8_t> expected = frame(
            sorted, [&] { ASSERT_TRUE(sorted.draw(grid.view(false), translucent(grid, false)).ok()); }, matrix);
        const std::vector<std::uint8_t> image = frame(
            unsorted, [&] { ASSERT_TRUE(unsorted.draw(grid.view(), translucent(grid, false)).ok()); }, matrix);
        EXPECT_EQ(image, expected) << "trial " << trial << ", jitter " << jitter;
        ++(unsorted.translucentInOrder() > 0 ? unsortedGrids : sortedGrids);
    }
    // Both kinds were met.
    EXPECT_GT(unsortedGrids, 0);
    EXPECT_GT(sortedGrids, 0);
}

TEST(OffscreenTranslucentOrder, AMeshFoldedOverItselfIsSorted)
{
    // A big triangle, near, and a second one folded back over it from its
    // right side (their shared edge used each way, so the boundary is one
    // simple dart-shaped loop), far: they turn opposite ways on the screen.
    TestMesh mesh;
    const std::uint32_t a = mesh.add(4, 28, 0.2f, kNear), b = mesh.add(28, 28, 0.2f, kNear),
                        c = mesh.add(16, 4, 0.2f, kNear), d = mesh.add(16, 20, 0.8f, kFar);
    mesh.triangles = {a, b, c, c, b, d}; // each its last corner's colour
    OffscreenRenderer renderer;
    const std::vector<std::uint8_t> image =
        frame(renderer, [&] { ASSERT_TRUE(renderer.draw(mesh.view(), translucent(mesh, false)).ok()); });
    EXPECT_EQ(renderer.translucentInOrder(), 0u);
    // Inside the folded triangle (28, 28), (16, 20), (16, 4).
    for (const auto& [x, y] : {std::array<int, 2>{19, 17}, {20, 19}, {18, 14}})
        expectPixel(image, x, y, nearOverFar());
}

TEST(OffscreenTranslucentOrder, AMeshWindingOverItselfWithoutFoldingIsSorted)
{
    // A ring strip round the image's centre, from radius 6 to 14, through
    // one and a quarter turns, every triangle turning the same way; its
    // depth grows along it, so that the last quarter lies behind the first.
    TestMesh mesh;
    constexpr int kSteps = 25; // 18 degrees each
    const float pi = std::acos(-1.0f);
    for (int k = 0; k <= kSteps; ++k) {
        const float angle = float(k) * 2.0f * pi / 20.0f;
        const float z = 0.1f + 0.8f * float(k) / float(kSteps);
        const RgbColor& color = k <= 10 ? kNear : kFar;
        mesh.add(16.0f + 6.0f * std::cos(angle), 16.0f + 6.0f * std::sin(angle), z, color);
        mesh.add(16.0f + 14.0f * std::cos(angle), 16.0f + 14.0f * std::sin(angle), z, color);
    }
    for (std::uint32_t k = 0; k < kSteps; ++k) {
        const std::uint32_t in0 = 2 * k, out0 = in0 + 1, in1 = in0 + 2, out1 = in0 + 3;
        mesh.triangles.insert(mesh.triangles.end(), {in0, out0, out1, in0, out1, in1});
    }
    OffscreenRenderer renderer;
    const std::vector<std::uint8_t> image =
        frame(renderer, [&] { ASSERT_TRUE(renderer.draw(mesh.view(), translucent(mesh, false)).ok()); });
    EXPECT_EQ(renderer.translucentInOrder(), 0u);
    // At 45 degrees, radius 10: the first quarter (near) over the last.
    expectPixel(image, 23, 23, nearOverFar());
    expectPixel(image, 16 + 9, 16 + 2, nearOverFar()); // about 13 degrees, radius 9
}

TEST(OffscreenTranslucentOrder, MeshesSharingPixelsAreSortedTogether)
{
    // Each mesh alone would be drawn unsorted; together they overlap.
    TestMesh near, far;
    for (TestMesh* mesh : {&near, &far}) {
        const float z = mesh == &near ? 0.3f : 0.7f;
        const RgbColor& color = mesh == &near ? kNear : kFar;
        const float x0 = mesh == &near ? 4.0f : 12.0f;
        const std::uint32_t a = mesh->add(x0, 4, z, color), b = mesh->add(x0 + 16, 4, z, color),
                            c = mesh->add(x0 + 16, 28, z, color), d = mesh->add(x0, 28, z, color);
        mesh->triangles = {a, b, c, a, c, d};
    }
    OffscreenRenderer renderer;
    const std::vector<std::uint8_t> image = frame(renderer, [&] {
        ASSERT_TRUE(renderer.draw(near.view(), translucent(near, false)).ok());
        ASSERT_TRUE(renderer.draw(far.view(), translucent(far, false)).ok());
    });
    EXPECT_EQ(renderer.translucentInOrder(), 0u);
    for (const auto& [x, y] : {std::array<int, 2>{14, 10}, {18, 20}})
        expectPixel(image, x, y, nearOverFar());
}

TEST(OffscreenTranslucentOrder, AMeshReachingOutsideTheViewIsSorted)
{
    // Wider than the image: clipped, its triangles' vertices are not its own.
    const TestMesh wide = wavyGrid(-10.0f, 40.0f);
    OffscreenRenderer sorted, renderer;
    const std::vector<std::uint8_t> expected =
        frame(sorted, [&] { ASSERT_TRUE(sorted.draw(wide.view(false), translucent(wide, true)).ok()); });
    const std::vector<std::uint8_t> image =
        frame(renderer, [&] { ASSERT_TRUE(renderer.draw(wide.view(), translucent(wide, true)).ok()); });
    EXPECT_EQ(renderer.translucentInOrder(), 0u);
    EXPECT_EQ(image, expected);
}

} // namespace
} // namespace q3
