// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Choosing the rendering backend (Q3_RENDER_BACKEND), and the two backends
// against each other: OSMesa and EGL on llvmpipe draw the same scene into
// the same bytes, in one process, even with their frames interleaved on one
// thread.

#include "render/OffscreenRenderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace q3 {
namespace {

// Sets (or with null unsets) an environment variable for one test.
class ScopedEnvironment {
public:
    ScopedEnvironment(const char* name, const char* value) : m_name(name)
    {
        const char* old = std::getenv(name);
        m_had = old != nullptr;
        if (m_had)
            m_old = old;
        if (value != nullptr)
            setenv(name, value, 1);
        else
            unsetenv(name);
    }
    ~ScopedEnvironment()
    {
        if (m_had)
            setenv(m_name, m_old.c_str(), 1);
        else
            unsetenv(m_name);
    }

private:
    const char* m_name;
    bool m_had = false;
    std::string m_old;
};

TEST(RenderBackend, UnsetOrEmptyPrefersOsMesaAndFallsBackToEgl)
{
    for (const char* value : {static_cast<const char*>(nullptr), ""}) {
        GlBackendChoice both = chooseGlBackend(value, true, true);
        EXPECT_TRUE(both.result);
        EXPECT_EQ(both.backend, GlBackend::kOsMesa);
        GlBackendChoice eglOnly = chooseGlBackend(value, false, true);
        EXPECT_TRUE(eglOnly.result);
        EXPECT_EQ(eglOnly.backend, GlBackend::kEgl);
        GlBackendChoice osmesaOnly = chooseGlBackend(value, true, false);
        EXPECT_TRUE(osmesaOnly.result);
        EXPECT_EQ(osmesaOnly.backend, GlBackend::kOsMesa);
        GlBackendChoice none = chooseGlBackend(value, false, false);
        EXPECT_EQ(none.result.status, RenderStatus::kContextFailure);
        EXPECT_NE(none.result.message.find("libOSMesa.so.8"), std::string::npos) << none.result.message;
        EXPECT_NE(none.result.message.find("libEGL.so.1"), std::string::npos) << none.result.message;
    }
}

TEST(RenderBackend, ANamedBackendIsTakenOrRefusedNeverReplaced)
{
    GlBackendChoice egl = chooseGlBackend("egl", true, true);
    EXPECT_TRUE(egl.result);
    EXPECT_EQ(egl.backend, GlBackend::kEgl);
    GlBackendChoice osmesa = chooseGlBackend("osmesa", true, true);
    EXPECT_TRUE(osmesa.result);
    EXPECT_EQ(osmesa.backend, GlBackend::kOsMesa);

    GlBackendChoice missingEgl = chooseGlBackend("egl", true, false);
    EXPECT_EQ(missingEgl.result.status, RenderStatus::kContextFailure);
    EXPECT_NE(missingEgl.result.message.find("libEGL.so.1"), std::string::npos) << missingEgl.result.message;
    GlBackendChoice missingOsMesa = chooseGlBackend("osmesa", false, true);
    EXPECT_EQ(missingOsMesa.result.status, RenderStatus::kContextFailure);
    EXPECT_NE(missingOsMesa.result.message.find("libOSMesa.so.8"), std::string::npos)
        << missingOsMesa.result.message;
}

TEST(RenderBackend, AnUnknownValueIsAnErrorNamingTheValidOnes)
{
    for (const char* value : {"EGL", "gl", "osmesa ", "vulkan"}) {
        GlBackendChoice choice = chooseGlBackend(value, true, true);
        EXPECT_EQ(choice.result.status, RenderStatus::kContextFailure) << value;
        EXPECT_NE(choice.result.message.find(std::string("'") + value + "'"), std::string::npos)
            << choice.result.message;
        EXPECT_NE(choice.result.message.find("osmesa or egl"), std::string::npos) << choice.result.message;
    }
    EXPECT_STREQ(glBackendName(GlBackend::kOsMesa), "osmesa");
    EXPECT_STREQ(glBackendName(GlBackend::kEgl), "egl");
}

TEST(RenderBackend, TheRendererHonoursTheEnvironmentVariable)
{
    {
        ScopedEnvironment variable("Q3_RENDER_BACKEND", "bogus");
        OffscreenRenderer renderer;
        RenderResult begun = renderer.beginFrame(4, 4, RgbaColor{0, 0, 0, 1}, PixelRect{0, 0, 4, 4});
        EXPECT_EQ(begun.status, RenderStatus::kContextFailure);
        EXPECT_NE(begun.message.find("Q3_RENDER_BACKEND='bogus'"), std::string::npos) << begun.message;
        EXPECT_FALSE(renderer.inFrame());
    }
    for (GlBackend backend : {GlBackend::kOsMesa, GlBackend::kEgl}) {
        ScopedEnvironment variable("Q3_RENDER_BACKEND", glBackendName(backend));
        GlBackendChoice choice = chooseGlBackendFromEnvironment();
        EXPECT_EQ(choice.backend, backend);
        EXPECT_EQ(bool(choice.result), glBackendAvailable(backend)) << choice.result.message;
    }
}

TEST(RenderBackend, AnUnknownEglDeviceKindIsAnError)
{
    if (!glBackendAvailable(GlBackend::kEgl))
        GTEST_SKIP() << "EGL is not available";
    ScopedEnvironment variable("Q3_EGL_DEVICE", "fastest");
    OffscreenRenderer renderer(GlBackend::kEgl);
    RenderResult begun = renderer.beginFrame(4, 4, RgbaColor{0, 0, 0, 1}, PixelRect{0, 0, 4, 4});
    EXPECT_EQ(begun.status, RenderStatus::kContextFailure);
    EXPECT_NE(begun.message.find("Q3_EGL_DEVICE='fastest'"), std::string::npos) << begun.message;
}

// A 4 x 4 RGB24 texture of distinct texels.
std::vector<std::uint8_t> texels()
{
    std::vector<std::uint8_t> bytes;
    for (int i = 0; i < 16; ++i)
        bytes.insert(bytes.end(), {std::uint8_t(i * 16), std::uint8_t(255 - i * 13), std::uint8_t(i * 7 + 40)});
    return bytes;
}

// One frame of every kind of drawing, in a pane inset in the image: random
// line strips under two matrices, wide points, depth-tested triangles,
// Phong-lit triangles per vertex and per pixel under three lights, a
// textured square, a bitmap. `midway` runs after setLighting has flushed
// the first half to OpenGL.
void drawScene(OffscreenRenderer& renderer, int width, int height, const std::function<void()>& midway = {})
{
    const PixelRect pane{5, 3, width - 9, height - 7};
    ASSERT_TRUE(renderer.beginFrame(std::uint32_t(width), std::uint32_t(height), RgbaColor{0.2f, 0.3f, 0.4f, 1.0f},
                                    pane, FrameOptions{true}));
    std::uint32_t seed = 2026;
    auto next = [&seed]() {
        seed = seed * 1664525u + 1013904223u;
        return float(seed >> 8) / float(1u << 24);
    };
    const std::array<float, 16> identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const std::array<float, 16> tilted{0.8f, 0.3f, 0, 0, -0.3f, 0.8f, 0, 0, 0, 0, 1, 0, 0.05f, -0.1f, 0, 1.2f};
    std::vector<float> xyz;
    for (int strip = 0; strip < 40; ++strip) {
        xyz.clear();
        for (int i = 0; i < 3 * 25; ++i)
            xyz.push_back(next() * 2.2f - 1.1f);
        ASSERT_TRUE(renderer.setMatrix((strip % 2 ? tilted : identity).data()));
        ASSERT_TRUE(renderer.drawLineStrip(xyz.data(), 25, RgbColor{next(), next(), next()}));
    }
    ASSERT_TRUE(renderer.setMatrix(identity.data()));
    xyz.clear();
    for (int i = 0; i < 3 * 12; ++i)
        xyz.push_back(next() * 2.0f - 1.0f);
    ASSERT_TRUE(renderer.drawTriangles(xyz.data(), 12, RgbColor{0.3f, 0.7f, 0.1f}));
    ASSERT_TRUE(renderer.drawPoints(xyz.data(), 12, RgbColor{1.0f, 1.0f, 0.0f}, 3.5f));

    LightingSetup lighting;
    RenderLight ambient;
    ambient.color[0] = ambient.color[1] = ambient.color[2] = 0.2f;
    RenderLight directional;
    directional.kind = RenderLight::Kind::kDirectional;
    directional.color[0] = 0.9f, directional.color[1] = 0.8f, directional.color[2] = 0.7f;
    directional.direction[0] = 0.3f, directional.direction[1] = -0.4f;
    directional.direction[2] = -std::sqrt(1.0f - 0.25f);
    RenderLight point;
    point.kind = RenderLight::Kind::kPoint;
    point.color[0] = 0.5f, point.color[1] = 0.6f, point.color[2] = 1.0f;
    point.position[0] = -0.5f, point.position[1] = 0.5f, point.position[2] = 1.0f;
    point.attenuation = 1;
    lighting.lights = {ambient, directional, point};
    lighting.eye[2] = 3.0f;
    ASSERT_TRUE(renderer.setLighting(lighting));
    if (midway)
        midway();

    // A bumpy grid, lit per vertex (left) and per pixel (right).
    constexpr int kGrid = 9;
    std::vector<float> grid, normals, rgb;
    std::vector<std::uint32_t> indices;
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i) {
            const float u = float(i) / (kGrid - 1), v = float(j) / (kGrid - 1);
            const float z = 0.15f * std::sin(6.0f * u) * std::cos(5.0f * v);
            grid.insert(grid.end(), {u * 0.9f - 0.95f, v * 1.6f - 0.8f, z});
            const float nx = -0.15f * 6.0f * std::cos(6.0f * u) * std::cos(5.0f * v);
            const float ny = 0.15f * 5.0f * std::sin(6.0f * u) * std::sin(5.0f * v);
            const float length = std::sqrt(nx * nx + ny * ny + 1.0f);
            normals.insert(normals.end(), {nx / length, ny / length, 1.0f / length});
            rgb.insert(rgb.end(), {u, 0.5f, 1.0f - v});
        }
    for (int j = 0; j + 1 < kGrid; ++j)
        for (int i = 0; i + 1 < kGrid; ++i) {
            const std::uint32_t a = std::uint32_t(j * kGrid + i), b = a + 1, c = a + kGrid, d = c + 1;
            indices.insert(indices.end(), {a, b, d, a, d, c});
        }
    SurfaceShading phong;
    phong.illumination = 2;
    phong.specularControl = 12.0f;
    phong.interpolation = 1;
    ASSERT_TRUE(renderer.drawLitTriangles(grid.data(), normals.data(), rgb.data(), kGrid * kGrid, indices.data(),
                                          indices.size(), RgbColor{}, phong));
    for (std::size_t k = 0; k < grid.size(); k += 3)
        grid[k] += 1.0f;
    phong.interpolation = 2;
    ASSERT_TRUE(renderer.drawLitTriangles(grid.data(), normals.data(), rgb.data(), kGrid * kGrid, indices.data(),
                                          indices.size(), RgbColor{}, phong));

    // A textured square in front, tilted in depth.
    const std::vector<std::uint8_t> bytes = texels();
    TextureImage texture;
    texture.pixels = bytes.data();
    texture.layout.width = 4;
    texture.layout.height = 4;
    texture.layout.rowBytes = 12;
    texture.layout.pixelType = PixelType::kRGB24;
    texture.layout.byteOrder = ByteOrder::kBig;
    ASSERT_TRUE(renderer.setTexture(&texture));
    const float square[12] = {-0.4f, 0.3f, -0.5f, 0.35f, 0.4f, -0.2f, 0.3f, -0.45f, 0.1f, -0.45f, -0.3f, -0.3f};
    const float st[8] = {0, 0, 1.5f, 0, 1.5f, 1.25f, 0, 1.25f};
    const std::uint32_t quad[6] = {0, 1, 2, 0, 2, 3};
    ASSERT_TRUE(renderer.drawElements(DrawMode::kTriangles, square, nullptr, 4, quad, 6, RgbColor{1, 0.9f, 0.8f},
                                      true, st));
    ASSERT_TRUE(renderer.setTexture(nullptr));

    const unsigned char bits[4] = {0xF0, 0x99, 0x0F, 0x66};
    BitmapImage bitmap;
    bitmap.bits = bits;
    bitmap.width = 8;
    bitmap.height = 4;
    bitmap.rowBytes = 1;
    const float anchor[3] = {0.1f, 0.6f, -0.9f};
    ASSERT_TRUE(renderer.drawBitmap(anchor, bitmap, RgbColor{1, 0, 1}));
    RenderResult ended = renderer.endFrame();
    ASSERT_TRUE(ended) << ended.message;
}

std::vector<std::uint8_t> imageOf(const OffscreenRenderer& renderer)
{
    return std::vector<std::uint8_t>(renderer.pixels(), renderer.pixels() + renderer.rowBytes() * renderer.height());
}

// Counts the pixels that differ, and the distinct colours of the image (so
// that a blank picture cannot pass).
struct Comparison {
    std::size_t differing = 0;
    std::size_t colours = 0;
};

Comparison compare(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b)
{
    Comparison result;
    std::vector<std::uint32_t> seen;
    for (std::size_t i = 0; i + 3 < a.size() && i + 3 < b.size(); i += 4) {
        if (a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2] || a[i + 3] != b[i + 3])
            ++result.differing;
        seen.push_back(std::uint32_t(a[i]) << 24 | std::uint32_t(a[i + 1]) << 16 | std::uint32_t(a[i + 2]) << 8 |
                       a[i + 3]);
    }
    std::sort(seen.begin(), seen.end());
    result.colours = std::size_t(std::unique(seen.begin(), seen.end()) - seen.begin());
    return result;
}

bool bothBackends()
{
    return glBackendAvailable(GlBackend::kOsMesa) && glBackendAvailable(GlBackend::kEgl);
}

TEST(RenderBackend, OsMesaAndEglDrawTheSameBytes)
{
    if (!bothBackends())
        GTEST_SKIP() << "needs both OSMesa and EGL";
    for (const std::array<int, 2> size : {std::array<int, 2>{97, 61}, std::array<int, 2>{64, 128}}) {
        OffscreenRenderer osmesa(GlBackend::kOsMesa);
        OffscreenRenderer egl(GlBackend::kEgl);
        drawScene(osmesa, size[0], size[1]);
        drawScene(egl, size[0], size[1]);
        ASSERT_EQ(osmesa.rowBytes(), egl.rowBytes());
        ASSERT_EQ(osmesa.height(), egl.height());
        const Comparison c = compare(imageOf(osmesa), imageOf(egl));
        EXPECT_EQ(c.differing, 0u) << size[0] << " x " << size[1];
        EXPECT_GT(c.colours, 200u) << "the scene should draw many colours";
    }
}

TEST(RenderBackend, FramesOfBothBackendsInterleavedOnOneThreadMatchSeparateOnes)
{
    if (!bothBackends())
        GTEST_SKIP() << "needs both OSMesa and EGL";
    OffscreenRenderer reference(GlBackend::kOsMesa);
    drawScene(reference, 80, 60);
    const std::vector<std::uint8_t> expected = imageOf(reference);

    // One backend's frame is flushed halfway (its context made current and
    // the previous one restored), the other backend draws a whole frame,
    // then the first one finishes: each leaves the thread's contexts as it
    // found them, so neither disturbs the other.
    OffscreenRenderer osmesa(GlBackend::kOsMesa), egl(GlBackend::kEgl);
    for (int round = 0; round < 2; ++round) {
        drawScene(osmesa, 80, 60, [&] { drawScene(egl, 80, 60); });
        EXPECT_EQ(compare(imageOf(osmesa), expected).differing, 0u) << round;
        EXPECT_EQ(compare(imageOf(egl), expected).differing, 0u) << round;
        drawScene(egl, 80, 60, [&] { drawScene(osmesa, 80, 60); });
        EXPECT_EQ(compare(imageOf(osmesa), expected).differing, 0u) << round;
        EXPECT_EQ(compare(imageOf(egl), expected).differing, 0u) << round;
    }
}

} // namespace
} // namespace q3
