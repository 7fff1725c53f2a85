// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Static vertex data (OffscreenRenderer.cpp, StaticKey): a mesh with a
// serial drawn again the same way is drawn from what the context kept, with
// exactly the image the usual path gives; a mesh drawn another way (colour,
// uv transform, lighting), a translucent one and one without a serial are
// not; many meshes, more than the kept buffers first hold, still draw
// right while the buffers are emptied and grown; and at the buffers' limit,
// meshes no longer drawn give their room to the meshes drawn now.

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
std::array<float, 16> pixelsToClip(std::uint32_t size)
{
    const float s = float(size);
    return {2.0f / s, 0, 0, 0, 0, -2.0f / s, 0, 0, 0, 0, 1, 0, -1, 1, 0, 1};
}

// A square from (3, 3) to (12, 12) in two triangles, a colour, a normal
// and a uv per vertex.
const float kSquare[] = {3.5f, 3.5f, 0, 12.5f, 3.5f, 0, 12.5f, 12.5f, 0, 3.5f, 12.5f, 0};
const std::uint32_t kTriangles[] = {0, 1, 2, 0, 2, 3};
const float kColors[] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0};
const float kNormals[] = {0, 0, 1, 0, 0.6f, 0.8f, 0, 0, 1, 0.6f, 0, 0.8f};
const float kSt[] = {0, 0, 1, 0, 1, 1, 0, 1};
const float kStScaled[] = {0, 0, 2, 0, 2, 2, 0, 2};

// A 2 x 2 RGB24 texture (row 0 the top).
const std::array<std::uint8_t, 12> kTexels = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};

MeshView square(std::uint64_t serial)
{
    MeshView mesh;
    mesh.positions = kSquare;
    mesh.vertexCount = 4;
    mesh.triangles = kTriangles;
    mesh.triangleCount = 2;
    mesh.normals = kNormals;
    mesh.serial = serial;
    return mesh;
}

class OffscreenKeptMesh : public ::testing::Test {
protected:
    // The image of one frame of `renderer` whose draws `body` makes, lit by
    // one directional light, the texture above given as `texture`.
    static std::vector<std::uint8_t> frame(OffscreenRenderer& renderer, const std::function<void(std::uint32_t)>& body,
                                           std::uint32_t size = kSize)
    {
        EXPECT_TRUE(renderer.beginFrame(size, size, RgbaColor{0, 0, 0, 1}, PixelRect{0, 0, int(size), int(size)}).ok());
        const std::array<float, 16> matrix = pixelsToClip(size);
        EXPECT_TRUE(renderer.setMatrix(matrix.data()).ok());
        LightingSetup lighting;
        lighting.lights.push_back(RenderLight{});
        lighting.lights.back().kind = RenderLight::Kind::kDirectional;
        lighting.lights.back().color[0] = lighting.lights.back().color[1] = lighting.lights.back().color[2] = 0.8f;
        lighting.lights.back().direction[2] = -1.0f;
        lighting.lights.push_back(RenderLight{});
        lighting.lights.back().color[0] = lighting.lights.back().color[1] = lighting.lights.back().color[2] = 0.2f;
        lighting.eye[2] = 10.0f;
        EXPECT_TRUE(renderer.setLighting(lighting).ok());
        TextureImage image;
        image.pixels = kTexels.data();
        image.layout.width = 2;
        image.layout.height = 2;
        image.layout.rowBytes = 6;
        image.layout.pixelType = PixelType::kRGB24;
        image.layout.byteOrder = ByteOrder::kBig;
        std::uint32_t texture = kNoTexture;
        EXPECT_TRUE(renderer.addTexture(image, texture).ok());
        body(texture);
        EXPECT_TRUE(renderer.endFrame().ok());
        return std::vector<std::uint8_t>(renderer.pixels(), renderer.pixels() + std::size_t(size) * size * 4);
    }

    static bool anyLit(const std::vector<std::uint8_t>& image)
    {
        for (std::size_t i = 0; i < image.size(); i += 4)
            if (image[i] != 0 || image[i + 1] != 0 || image[i + 2] != 0)
                return true;
        return false;
    }

    // Shadings of the square: lit (Phong) and textured, lit with per-vertex
    // colours, unlit with per-vertex colours.
    static Shading litTextured(std::uint32_t texture, const float* st = kSt)
    {
        Shading shading;
        shading.lit = true;
        shading.surface.illumination = 2;
        shading.surface.specularControl = 8.0f;
        shading.st = st;
        shading.texture = texture;
        return shading;
    }
    static Shading litColoured()
    {
        Shading shading;
        shading.lit = true;
        shading.rgb = kColors;
        return shading;
    }
    static Shading unlitColoured()
    {
        Shading shading;
        shading.rgb = kColors;
        return shading;
    }
};

TEST_F(OffscreenKeptMesh, AMeshDrawnAgainTheSameWayIsDrawnFromKeptDataWithTheSameImage)
{
    OffscreenRenderer reference;
    OffscreenRenderer renderer;
    const std::function<Shading(std::uint32_t)> shadings[] = {
        [](std::uint32_t texture) { return litTextured(texture); }, [](std::uint32_t) { return litColoured(); },
        [](std::uint32_t) { return unlitColoured(); }};
    std::uint64_t serial = 100;
    for (const auto& shadingOf : shadings) {
        ++serial;
        SCOPED_TRACE("serial " + std::to_string(serial));
        // The usual path: a mesh without a serial is never kept.
        const std::vector<std::uint8_t> expected = frame(reference, [&](std::uint32_t texture) {
            ASSERT_TRUE(reference.draw(square(0), shadingOf(texture)).ok());
        });
        ASSERT_TRUE(anyLit(expected));
        const std::uint64_t before = renderer.keptDraws();
        // Seen in the first frame, kept from the second's batch, drawn from
        // what was kept from the third on.
        for (int f = 0; f < 5; ++f) {
            const std::vector<std::uint8_t> drawn = frame(renderer, [&](std::uint32_t texture) {
                ASSERT_TRUE(renderer.draw(square(serial), shadingOf(texture)).ok());
            });
            EXPECT_EQ(drawn, expected) << "frame " << f;
            EXPECT_EQ(renderer.keptDraws() - before, std::uint64_t(f < 2 ? 0 : f - 1)) << "frame " << f;
        }
    }
    EXPECT_EQ(reference.keptDraws(), 0u);
}

TEST_F(OffscreenKeptMesh, AMeshDrawnAnotherWayIsNotDrawnFromWhatWasKeptForTheFirst)
{
    // Pairs of shadings of the square that differ in one thing: the
    // colour, the uv transform (its texture coordinates with it), the
    // winding of the front (the face normals of a mesh without normals),
    // the interpolation.
    using ShadingOf = std::function<Shading(std::uint32_t)>;
    const auto coloured = [](float r, float g, float b) {
        return [=](std::uint32_t) {
            Shading shading = litColoured();
            shading.rgb = nullptr;
            shading.color = RgbColor{r, g, b};
            return shading;
        };
    };
    const auto flat = [](bool clockwise) {
        return [=](std::uint32_t) {
            Shading shading = litColoured();
            shading.surface.interpolation = 0;
            shading.clockwiseFront = clockwise;
            return shading;
        };
    };
    struct Pair {
        ShadingOf first, second;
        bool normals;
    };
    const Pair pairs[] = {
        {coloured(0.9f, 0.2f, 0.1f), coloured(0.2f, 0.9f, 0.4f), true},
        {[](std::uint32_t texture) { return litTextured(texture); },
         [](std::uint32_t texture) {
             Shading shading = litTextured(texture, kStScaled);
             shading.stTransform[0] = shading.stTransform[3] = 2.0f;
             return shading;
         },
         true},
        {flat(false), flat(true), false},
        {[](std::uint32_t) { return litColoured(); }, flat(false), true},
    };
    std::uint64_t serial = 200;
    for (const Pair& pair : pairs) {
        ++serial;
        SCOPED_TRACE("serial " + std::to_string(serial));
        const ShadingOf& first = pair.first;
        const ShadingOf& second = pair.second;
        const auto mesh = [&](std::uint64_t number) {
            MeshView view = square(number);
            if (!pair.normals)
                view.normals = nullptr;
            return view;
        };
        OffscreenRenderer reference;
        OffscreenRenderer renderer;
        for (int f = 0; f < 3; ++f)
            frame(renderer,
                  [&](std::uint32_t texture) { ASSERT_TRUE(renderer.draw(mesh(serial), first(texture)).ok()); });
        const std::uint64_t kept = renderer.keptDraws();
        ASSERT_EQ(kept, 1u);
        const std::vector<std::uint8_t> before = frame(reference, [&](std::uint32_t texture) {
            ASSERT_TRUE(reference.draw(mesh(0), first(texture)).ok());
        });
        const std::vector<std::uint8_t> expected = frame(reference, [&](std::uint32_t texture) {
            ASSERT_TRUE(reference.draw(mesh(0), second(texture)).ok());
        });
        ASSERT_NE(expected, before);
        const std::vector<std::uint8_t> drawn = frame(renderer, [&](std::uint32_t texture) {
            ASSERT_TRUE(renderer.draw(mesh(serial), second(texture)).ok());
        });
        EXPECT_EQ(drawn, expected);
        EXPECT_EQ(renderer.keptDraws(), kept);
    }
}

TEST_F(OffscreenKeptMesh, LightingAtEveryPixelDrawsTheVerticesKeptForLightingAtTheVertices)
{
    // The two interpolations that light smoothly give the same vertices;
    // only the program differs, chosen per draw.
    OffscreenRenderer reference;
    OffscreenRenderer renderer;
    Shading perPixel = litColoured();
    perPixel.surface.illumination = 2;
    perPixel.surface.interpolation = 2;
    Shading perVertex = perPixel;
    perVertex.surface.interpolation = 1;
    const std::vector<std::uint8_t> expected =
        frame(reference, [&](std::uint32_t) { ASSERT_TRUE(reference.draw(square(0), perPixel).ok()); });
    const std::vector<std::uint8_t> vertexLit =
        frame(reference, [&](std::uint32_t) { ASSERT_TRUE(reference.draw(square(0), perVertex).ok()); });
    ASSERT_NE(expected, vertexLit);
    for (int f = 0; f < 3; ++f)
        frame(renderer, [&](std::uint32_t) { ASSERT_TRUE(renderer.draw(square(301), perVertex).ok()); });
    const std::uint64_t kept = renderer.keptDraws();
    ASSERT_EQ(kept, 1u);
    const std::vector<std::uint8_t> drawn =
        frame(renderer, [&](std::uint32_t) { ASSERT_TRUE(renderer.draw(square(301), perPixel).ok()); });
    EXPECT_EQ(drawn, expected);
    EXPECT_EQ(renderer.keptDraws(), kept + 1);
}

TEST_F(OffscreenKeptMesh, UvsGivenWithTheirTransformDrawAsTheCoordinatesComputedFromThem)
{
    // Shading::uvs: the renderer puts them through stTransform itself. The
    // same square given the coordinates computed here (the formula of
    // RenderTarget.h) draws the same image, streamed (no serial) and from
    // kept data (a serial, from the third frame on).
    const float transform[6] = {1.5f, 0.25f, -0.5f, 2.0f, 0.25f, -0.125f};
    const float uvs[8] = {0.0f, 1.0f, 1.0f, 1.0f, 1.0f, 0.0f, 0.0f, 0.0f};
    float st[8];
    for (int i = 0; i < 4; ++i) {
        const float u = uvs[2 * i], v = uvs[2 * i + 1];
        st[2 * i] = u * transform[0] + v * transform[2] + transform[4];
        st[2 * i + 1] = 1.0f - (u * transform[1] + v * transform[3] + transform[5]);
    }
    const auto draw = [&](OffscreenRenderer& renderer, std::uint64_t serial, bool fromUvs) {
        return frame(renderer, [&](std::uint32_t texture) {
            Shading shading = litTextured(texture, fromUvs ? nullptr : st);
            if (fromUvs)
                shading.uvs = uvs;
            std::copy(std::begin(transform), std::end(transform), std::begin(shading.stTransform));
            ASSERT_TRUE(renderer.draw(square(serial), shading).ok());
        });
    };
    OffscreenRenderer reference;
    const std::vector<std::uint8_t> expected = draw(reference, 0, false);
    ASSERT_TRUE(anyLit(expected));
    OffscreenRenderer streamed;
    EXPECT_EQ(draw(streamed, 0, true), expected);
    OffscreenRenderer renderer;
    const std::uint64_t serial = Mesh::newSerial();
    for (int f = 0; f < 4; ++f)
        EXPECT_EQ(draw(renderer, serial, true), expected) << "frame " << f;
    EXPECT_EQ(renderer.keptDraws(), 2u);
    // A texture given neither coordinates nor uvs leaves the square
    // untextured.
    const std::vector<std::uint8_t> untextured = frame(reference, [&](std::uint32_t texture) {
        Shading shading = litTextured(texture, nullptr);
        ASSERT_TRUE(reference.draw(square(0), shading).ok());
    });
    EXPECT_NE(untextured, expected);
}

TEST_F(OffscreenKeptMesh, TranslucentMeshesAndMeshesWithoutASerialAreNeverKept)
{
    OffscreenRenderer reference;
    OffscreenRenderer renderer;
    Shading translucent = litColoured();
    translucent.opacity.uniform = RgbColor{0.5f, 0.5f, 0.5f};
    const std::vector<std::uint8_t> expected =
        frame(reference, [&](std::uint32_t) { ASSERT_TRUE(reference.draw(square(0), translucent).ok()); });
    for (int f = 0; f < 4; ++f) {
        const std::vector<std::uint8_t> drawn = frame(renderer, [&](std::uint32_t) {
            ASSERT_TRUE(renderer.draw(square(9), translucent).ok());
            ASSERT_TRUE(renderer.draw(square(0), litColoured()).ok());
        });
        const std::vector<std::uint8_t> alone = frame(reference, [&](std::uint32_t) {
            ASSERT_TRUE(reference.draw(square(0), translucent).ok());
            ASSERT_TRUE(reference.draw(square(0), litColoured()).ok());
        });
        EXPECT_EQ(drawn, alone);
    }
    EXPECT_EQ(renderer.keptDraws(), 0u);
    EXPECT_TRUE(anyLit(expected));
}

TEST_F(OffscreenKeptMesh, MoreMeshesThanTheKeptBuffersFirstHoldStillDrawRight)
{
    // 40 grids of 32 x 32 vertices (40,960 vertices, 230,640 indices: more
    // than the kept buffers' first 32,768 and 65,536), each in its own 8 x 8
    // cell of a 64 x 64 image in its own colour, drawn for 6 frames: the
    // buffers run out, are emptied and grown, and every frame is the image
    // of the usual path.
    constexpr std::uint32_t kImage = 64;
    constexpr int kGrid = 32, kMeshes = 40;
    std::vector<std::vector<float>> positions(kMeshes);
    std::vector<std::uint32_t> triangles;
    for (int y = 0; y + 1 < kGrid; ++y)
        for (int x = 0; x + 1 < kGrid; ++x) {
            const std::uint32_t v = std::uint32_t(y * kGrid + x);
            for (std::uint32_t index : {v, v + 1, v + kGrid + 1, v, v + kGrid + 1, v + kGrid})
                triangles.push_back(index);
        }
    for (int m = 0; m < kMeshes; ++m) {
        const float left = float(8 * (m % 8)) + 0.5f, top = float(8 * (m / 8)) + 0.5f;
        for (int y = 0; y < kGrid; ++y)
            for (int x = 0; x < kGrid; ++x)
                for (float value : {left + 7.0f * float(x) / (kGrid - 1), top + 7.0f * float(y) / (kGrid - 1), 0.0f})
                    positions[std::size_t(m)].push_back(value);
    }
    const auto draw = [&](OffscreenRenderer& renderer, bool serials) {
        return frame(
            renderer,
            [&](std::uint32_t) {
                for (int m = 0; m < kMeshes; ++m) {
                    MeshView mesh;
                    mesh.positions = positions[std::size_t(m)].data();
                    mesh.vertexCount = std::size_t(kGrid) * kGrid;
                    mesh.triangles = triangles.data();
                    mesh.triangleCount = triangles.size() / 3;
                    mesh.serial = serials ? std::uint64_t(1000 + m) : 0;
                    Shading shading;
                    shading.color = RgbColor{float(m % 5) / 4.0f, float(m % 7) / 6.0f, float(m) / (kMeshes - 1)};
                    shading.smooth = true;
                    ASSERT_TRUE(renderer.draw(mesh, shading).ok());
                }
            },
            kImage);
    };
    OffscreenRenderer reference;
    const std::vector<std::uint8_t> expected = draw(reference, false);
    ASSERT_TRUE(anyLit(expected));
    OffscreenRenderer renderer;
    for (int f = 0; f < 6; ++f)
        EXPECT_EQ(draw(renderer, true), expected) << "frame " << f;
    EXPECT_GE(renderer.keptDraws(), std::uint64_t(kMeshes));
}

TEST_F(OffscreenKeptMesh, MeshesForgottenAtTheLimitLeaveTheirRoomToTheMeshesDrawnNow)
{
    // The kept buffers limited to four squares. Four squares are kept; then
    // only four others are drawn. Once the first four are forgotten (no frame
    // drew them for 64 frames: at most 128 frames later), the buffers, as
    // large as they get, are emptied for the four drawn now, which are then
    // kept, and every frame is still the image of the usual path.
    // An image size no other test uses, so that the renderers take a context
    // of their own from the process's pool, and serials no other mesh has.
    constexpr int kSquares = 4;
    constexpr std::uint32_t kImage = 19;
    using Serials = std::array<std::uint64_t, kSquares>;
    const Serials none{};
    Serials first, second;
    for (Serials* serials : {&first, &second})
        for (std::uint64_t& serial : *serials)
            serial = Mesh::newSerial();
    const auto draw = [&](OffscreenRenderer& renderer, const Serials& serials) {
        return frame(
            renderer,
            [&](std::uint32_t) {
                for (std::uint64_t serial : serials)
                    ASSERT_TRUE(renderer.draw(square(serial), litColoured()).ok());
            },
            kImage);
    };
    OffscreenRenderer reference;
    const std::vector<std::uint8_t> expected = draw(reference, none);
    ASSERT_TRUE(anyLit(expected));
    OffscreenRenderer renderer;
    renderer.setKeptLimits(4 * kSquares, 6 * kSquares);
    for (int f = 0; f < 3; ++f)
        EXPECT_EQ(draw(renderer, first), expected);
    ASSERT_EQ(renderer.keptDraws(), std::uint64_t(kSquares)) << "the first four are kept at the third frame";
    int framesUntilKept = -1;
    for (int f = 0; f < 140; ++f) {
        const std::uint64_t before = renderer.keptDraws();
        EXPECT_EQ(draw(renderer, second), expected) << "frame " << f;
        if (renderer.keptDraws() - before == std::uint64_t(kSquares)) {
            framesUntilKept = f;
            break;
        }
        EXPECT_EQ(renderer.keptDraws(), before) << "frame " << f;
    }
    EXPECT_GT(framesUntilKept, 60) << "the first four are not forgotten before 64 frames";
    EXPECT_LT(framesUntilKept, 140) << "the four drawn now are never kept";
    const std::uint64_t kept = renderer.keptDraws();
    EXPECT_EQ(draw(renderer, second), expected);
    EXPECT_EQ(renderer.keptDraws(), kept + kSquares);
}

} // namespace
} // namespace q3
