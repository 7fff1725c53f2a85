// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Textured scenes drawn by the interactive renderer and compared with
// tests/golden/texture_NAME.png (tolerance: tests/golden/README.md): a
// checkerboard on a TriMesh seen in perspective (unlit, wrapping twice),
// on a box lit per pixel (Lambert) and on a NURB patch lit per vertex
// (Phong, highlights added over the texture); and attribute_texture.png,
// a model whose texture shaders are kept in attribute sets (a TriMesh's own
// set, a box's face sets, a polygon's vertex sets). Facts that a golden blessed
// from a wrong picture would not pass are checked by reading pixels: both
// checker colours show, the lit ones darker where the light falls less.
// Exact texels against uv are checked in tests/api/TextureRenderTest.cpp.

#include "Golden.h"
#include "MemoryFile.h"
#include "SceneRender.h"
#include "SessionTest.h"
#include "QuadMesh.h"

#include "QD3D.h"
#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DErrors.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DIO.h"
#include "QD3DLight.h"
#include "QD3DMath.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"
#include "QD3DStyle.h"
#include "QD3DView.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <vector>

namespace {

constexpr int kWidth = 160, kHeight = 120;

// The objects written to a 3DMF file in memory in `mode` and read back.
std::vector<TQ3Object> throughFile(const std::vector<TQ3Object>& objects, TQ3FileMode mode)
{
    const std::vector<unsigned char> bytes = q3test::writeMemoryFile(
        mode,
        [&](TQ3ViewObject view) {
            for (TQ3Object object : objects)
                EXPECT_EQ(Q3Object_Submit(object, view), kQ3Success);
        },
        [](bool ok, const char* what) { EXPECT_TRUE(ok) << what; });
    TQ3StorageObject storage = Q3MemoryStorage_New(bytes.data(), static_cast<unsigned long>(bytes.size()));
    TQ3FileObject file = Q3File_New();
    Q3File_SetStorage(file, storage);
    std::vector<TQ3Object> read;
    TQ3FileMode opened = 0;
    if (Q3File_OpenRead(file, &opened) == kQ3Success) {
        while (Q3File_IsEndOfFile(file) == kQ3False) {
            TQ3Object object = Q3File_ReadObject(file);
            if (object == nullptr)
                break;
            read.push_back(object);
        }
        Q3File_Close(file);
    }
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
    return read;
}
// The checkerboard's two colours.
constexpr unsigned char kLight[3] = {230, 180, 60};
constexpr unsigned char kDark[3] = {40, 90, 200};

class TextureGoldenTest : public q3test::SessionTest<> {
protected:
    void SetUp() override
    {
        SessionTest::SetUp();
        // An 8 x 8 checkerboard, ARGB32 big-endian.
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) {
                const unsigned char* c = (x + y) % 2 == 0 ? kLight : kDark;
                m_texels.insert(m_texels.end(), {255, c[0], c[1], c[2]});
            }
        m_storage = Q3MemoryStorage_New(m_texels.data(), static_cast<unsigned long>(m_texels.size()));
        const TQ3StoragePixmap pixmap{m_storage, 8, 8, 32, 32, kQ3PixelTypeARGB32, kQ3EndianBig, kQ3EndianBig};
        m_texture = Q3PixmapTexture_New(&pixmap);
        m_shader = Q3TextureShader_New(m_texture);
        ASSERT_NE(m_shader, nullptr);
    }
    void TearDown() override
    {
        Q3Object_Dispose(m_shader);
        Q3Object_Dispose(m_texture);
        Q3Object_Dispose(m_storage);
        SessionTest::TearDown();
    }

    // Renders `submit` in perspective from `eye` towards the origin, with an
    // ambient light (0.3) and a directional light (0.8) when lit.
    q3test::RgbaImage render(const TQ3Point3D& eye, bool lit, const std::function<void(TQ3ViewObject)>& submit)
    {
        q3test::SceneSetup setup = q3test::sceneLookingAt(kWidth, kHeight, {1.0f, 0.1f, 0.1f, 0.12f}, eye);
        setup.ambient = lit ? 0.3f : 0.0f;
        setup.sun = lit;
        return q3test::renderScene(setup, submit);
    }

    // How many pixels are (within `slack`) a scaled copy of the colour:
    // channel ratios to it all within 0.1 of one another and of no more than
    // `maxScale`.
    static int pixelsLike(const q3test::RgbaImage& image, const unsigned char* colour, double minScale,
                          double maxScale)
    {
        int n = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const unsigned char* p = image.at(x, y);
                double lo = 10.0, hi = -1.0;
                for (int k = 0; k < 3; ++k) {
                    const double ratio = double(p[k]) / colour[k];
                    lo = std::min(lo, ratio);
                    hi = std::max(hi, ratio);
                }
                if (hi - lo < 0.1 && lo >= minScale && hi <= maxScale)
                    ++n;
            }
        return n;
    }

    // The image matches the golden `name`, and each checker colour (scaled
    // by minScale..maxScale) shows in more than `atLeast` pixels.
    static void expectGoldenWithBothColours(const char* name, const q3test::RgbaImage& image, double minScale,
                                            double maxScale, int atLeast)
    {
        EXPECT_TRUE(q3test::matchesGolden(name, image));
        EXPECT_GT(pixelsLike(image, kLight, minScale, maxScale), atLeast) << "light";
        EXPECT_GT(pixelsLike(image, kDark, minScale, maxScale), atLeast) << "dark";
    }

    std::vector<unsigned char> m_texels;
    TQ3StorageObject m_storage = nullptr;
    TQ3TextureObject m_texture = nullptr;
    TQ3ShaderObject m_shader = nullptr;
};

TEST_F(TextureGoldenTest, TriMeshInPerspectiveWrapsTheCheckerboardTwice)
{
    const q3test::QuadMesh quad({{-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}}, {{0, 2}, {2, 2}, {2, 0}, {0, 0}}, true);
    TQ3GeometryObject mesh = quad.create();
    ASSERT_NE(mesh, nullptr);
    const q3test::RgbaImage image = render({0.5f, 2.5f, 4.0f}, false, [&](TQ3ViewObject v) {
        Q3Shader_Submit(m_shader, v);
        Q3Geometry_Submit(mesh, v);
    });
    Q3Object_Dispose(mesh);
    // Unlit: the texels' own colours, both of them, over large areas.
    expectGoldenWithBothColours("texture_trimesh_perspective", image, 0.99, 1.01, 2000);
}

TEST_F(TextureGoldenTest, BoxLitPerPixelShowsTheCheckerboardOnEachFace)
{
    const TQ3BoxData data{{-1, -1, -1}, {0, 2, 0}, {0, 0, 2}, {2, 0, 0}, nullptr, nullptr};
    TQ3GeometryObject box = Q3Box_New(&data);
    ASSERT_NE(box, nullptr);
    TQ3ShaderObject lambert = Q3LambertIllumination_New();
    TQ3StyleObject pixel = Q3InterpolationStyle_New(kQ3InterpolationStylePixel);
    const q3test::RgbaImage image = render({3.0f, 2.5f, 4.0f}, true, [&](TQ3ViewObject v) {
        Q3Shader_Submit(lambert, v);
        Q3Style_Submit(pixel, v);
        Q3Shader_Submit(m_shader, v);
        Q3Geometry_Submit(box, v);
    });
    Q3Object_Dispose(pixel);
    Q3Object_Dispose(lambert);
    Q3Object_Dispose(box);
    // Lit: scaled checker colours, never brighter than 1.1 times the texel
    // (0.3 ambient + 0.8 at most), and both colours show.
    expectGoldenWithBothColours("texture_box_lit", image, 0.25, 1.11, 1000);
}

TEST_F(TextureGoldenTest, PatchLitPerVertexWithPhongHighlights)
{
    TQ3RationalPoint4D points[16];
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column) {
            const float x = -1.5f + column, z = 1.5f - row;
            const float y = (row == 1 || row == 2) && (column == 1 || column == 2) ? 1.2f : 0.0f;
            points[row * 4 + column] = TQ3RationalPoint4D{x, y, z, 1.0f};
        }
    float knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    TQ3NURBPatchData data{4, 4, 4, 4, points, knots, knots, 0, nullptr, nullptr};
    TQ3GeometryObject patch = Q3NURBPatch_New(&data);
    ASSERT_NE(patch, nullptr);
    TQ3ShaderObject phong = Q3PhongIllumination_New();
    TQ3SubdivisionStyleData subdivision{kQ3SubdivisionMethodConstant, 16, 16};
    TQ3StyleObject style = Q3SubdivisionStyle_New(&subdivision);
    const q3test::RgbaImage image = render({0.5f, 3.0f, 4.0f}, true, [&](TQ3ViewObject v) {
        Q3Shader_Submit(phong, v);
        Q3Style_Submit(style, v);
        Q3Shader_Submit(m_shader, v);
        Q3Geometry_Submit(patch, v);
    });
    Q3Object_Dispose(style);
    Q3Object_Dispose(phong);
    Q3Object_Dispose(patch);
    expectGoldenWithBothColours("texture_patch_phong", image, 0.25, 1.11, 500);
}

TEST_F(TextureGoldenTest, ShadersInGeometryFaceAndVertexSets)
{
    // Stripes (red and white columns) and a two-colour board (green and
    // magenta), ARGB32 big-endian like the checkerboard.
    constexpr unsigned char kRed[3] = {210, 40, 40};
    constexpr unsigned char kWhite[3] = {240, 240, 240};
    constexpr unsigned char kGreen[3] = {40, 190, 70};
    constexpr unsigned char kMagenta[3] = {200, 50, 200};
    std::vector<unsigned char> stripes, board;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            const unsigned char* s = x % 2 == 0 ? kRed : kWhite;
            stripes.insert(stripes.end(), {255, s[0], s[1], s[2]});
        }
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            const unsigned char* b = (x + y) % 2 == 0 ? kGreen : kMagenta;
            board.insert(board.end(), {255, b[0], b[1], b[2]});
        }
    std::vector<TQ3Object> owned;
    const auto shaderOf = [&](std::vector<unsigned char>& texels, unsigned long side) {
        TQ3StorageObject storage = Q3MemoryStorage_New(texels.data(), static_cast<unsigned long>(texels.size()));
        const TQ3StoragePixmap pixmap{storage, side, side, side * 4, 32, kQ3PixelTypeARGB32, kQ3EndianBig,
                                      kQ3EndianBig};
        TQ3TextureObject texture = Q3PixmapTexture_New(&pixmap);
        TQ3ShaderObject shader = Q3TextureShader_New(texture);
        owned.insert(owned.end(), {storage, texture, shader});
        return shader;
    };
    TQ3ShaderObject striped = shaderOf(stripes, 4);
    TQ3ShaderObject boarded = shaderOf(board, 2);
    const auto setWith = [&](TQ3ShaderObject shader) {
        TQ3AttributeSet set = Q3AttributeSet_New();
        Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, &shader);
        owned.push_back(set);
        return set;
    };

    // The floor: a TriMesh with the checkerboard in its own set.
    q3test::QuadMesh floorQuad({{-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}}, {{0, 2}, {2, 2}, {2, 0}, {0, 0}}, true);
    floorQuad.data.triMeshAttributeSet = setWith(m_shader);
    TQ3GeometryObject floor = floorQuad.create();
    // A box with the stripes in the face sets of its top and of the two
    // sides facing the eye, the board on the others.
    TQ3AttributeSet stripedFace = setWith(striped), boardedFace = setWith(boarded);
    TQ3AttributeSet faces[6] = {boardedFace, stripedFace, stripedFace, boardedFace, stripedFace, boardedFace};
    const TQ3BoxData boxData{{-1.6f, 0, -1.2f}, {0, 1.2f, 0}, {0, 0, 1.2f}, {1.2f, 0, 0}, faces, nullptr};
    TQ3GeometryObject box = Q3Box_New(&boxData);
    // A standing polygon with the board in every vertex set.
    TQ3Vertex3D vertices[4] = {{{0.3f, 0, 0.2f}, nullptr},
                               {{1.8f, 0, -0.4f}, nullptr},
                               {{1.8f, 1.5f, -0.4f}, nullptr},
                               {{0.3f, 1.5f, 0.2f}, nullptr}};
    const TQ3Param2D corners[4] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    for (int i = 0; i < 4; ++i) {
        vertices[i].attributeSet = setWith(boarded);
        Q3AttributeSet_Add(vertices[i].attributeSet, kQ3AttributeTypeSurfaceUV, &corners[i]);
    }
    const TQ3PolygonData polygonData{4, vertices, nullptr};
    TQ3GeometryObject polygon = Q3Polygon_New(&polygonData);
    ASSERT_NE(floor, nullptr);
    ASSERT_NE(box, nullptr);
    ASSERT_NE(polygon, nullptr);
    owned.insert(owned.end(), {floor, box, polygon});

    TQ3ShaderObject lambert = Q3LambertIllumination_New();
    owned.push_back(lambert);
    const q3test::RgbaImage image = render({1.0f, 3.0f, 5.0f}, true, [&](TQ3ViewObject v) {
        Q3Shader_Submit(lambert, v);
        Q3Geometry_Submit(floor, v);
        Q3Geometry_Submit(box, v);
        Q3Geometry_Submit(polygon, v);
    });
    // Through 3DMF, text and binary: the shaders in the sets come back and
    // the picture is the same, pixel for pixel.
    for (TQ3FileMode mode : {TQ3FileMode{kQ3FileModeNormal}, TQ3FileMode{kQ3FileModeText}}) {
        SCOPED_TRACE(mode);
        const std::vector<TQ3Object> copies = throughFile({floor, box, polygon}, mode);
        ASSERT_EQ(copies.size(), 3u);
        const q3test::RgbaImage again = render({1.0f, 3.0f, 5.0f}, true, [&](TQ3ViewObject v) {
            Q3Shader_Submit(lambert, v);
            for (TQ3Object copy : copies)
                Q3Object_Submit(copy, v);
        });
        EXPECT_TRUE(again.pixels == image.pixels) << "the copy read from the file draws another picture";
        for (TQ3Object copy : copies)
            Q3Object_Dispose(copy);
    }
    for (TQ3Object object : owned)
        Q3Object_Dispose(object);
    // Every texture shows, lit (0.3 ambient + 0.8 at most).
    expectGoldenWithBothColours("attribute_texture", image, 0.25, 1.11, 300);
    EXPECT_GT(pixelsLike(image, kRed, 0.25, 1.11), 100);
    EXPECT_GT(pixelsLike(image, kGreen, 0.25, 1.11), 100);
    EXPECT_GT(pixelsLike(image, kMagenta, 0.25, 1.11), 100);
}

} // namespace
