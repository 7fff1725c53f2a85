// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Translucency, fog and highlighting drawn by the interactive renderer and
// compared with tests/golden/NAME.png (tolerance: tests/golden/README.md):
// a translucent box over an opaque one (grey, and tinted), a row of spheres each under another
// fog mode, a texture with alpha cut-outs over a box, and a highlighted
// box beside a plain one. Exact pixels against the formulas are checked in
// tests/api/TranslucencyFogRenderTest.cpp; here a few facts a golden blessed
// from a wrong picture would not pass are checked too.

#include "Golden.h"
#include "SceneRender.h"
#include "SessionTest.h"

#include "QD3D.h"
#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DErrors.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DMath.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"
#include "QD3DStyle.h"
#include "QD3DView.h"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

namespace {

constexpr int kWidth = 160, kHeight = 120;

class TranslucencyGoldenTest : public q3test::SessionTest<> {
protected:
    void TearDown() override
    {
        for (TQ3Object object : m_owned)
            Q3Object_Dispose(object);
        SessionTest::TearDown();
    }

    template <class T>
    T own(T object)
    {
        EXPECT_NE(object, nullptr);
        m_owned.push_back(object);
        return object;
    }

    TQ3AttributeSet colors(TQ3ColorRGB diffuse, const TQ3ColorRGB* transparency = nullptr)
    {
        TQ3AttributeSet set = own(Q3AttributeSet_New());
        Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &diffuse);
        if (transparency != nullptr)
            Q3AttributeSet_Add(set, kQ3AttributeTypeTransparencyColor, transparency);
        return set;
    }

    TQ3GeometryObject box(TQ3Point3D origin, float size, TQ3AttributeSet set)
    {
        const TQ3BoxData data{origin, {0, size, 0}, {0, 0, size}, {size, 0, 0}, nullptr, set};
        return own(Q3Box_New(&data));
    }

    TQ3GeometryObject sphere(TQ3Point3D centre, float radius, TQ3AttributeSet set)
    {
        TQ3EllipsoidData data{};
        data.origin = centre;
        data.orientation = {0, 0, radius};
        data.majorRadius = {radius, 0, 0};
        data.minorRadius = {0, radius, 0};
        data.uMax = 1;
        data.vMax = 1;
        data.ellipsoidAttributeSet = set;
        return own(Q3Ellipsoid_New(&data));
    }

    // Renders `submit` in perspective from `eye` towards `target`, lit by an
    // ambient light (0.35) and a directional light (0.8), Phong shaded.
    q3test::RgbaImage render(const TQ3Point3D& eye, const TQ3Point3D& target,
                             const std::function<void(TQ3ViewObject)>& submit)
    {
        q3test::SceneSetup setup = q3test::sceneLookingAt(kWidth, kHeight, {1.0f, 0.15f, 0.15f, 0.2f}, eye, target);
        setup.yon = 60.0f;
        setup.phong = true;
        setup.keepAlpha = true;
        return q3test::renderScene(setup, submit);
    }

    std::vector<TQ3Object> m_owned;
};

TEST_F(TranslucencyGoldenTest, TranslucentBoxOverAnOpaqueOne)
{
    const TQ3ColorRGB glass{0.4f, 0.4f, 0.4f};
    TQ3GeometryObject opaque = box({-1.2f, -0.8f, -1.5f}, 1.6f, colors({0.9f, 0.3f, 0.2f}));
    TQ3GeometryObject translucent = box({-0.6f, -1.0f, -0.2f}, 1.8f, colors({0.2f, 0.5f, 1.0f}, &glass));
    const q3test::RgbaImage image = render({2.0f, 2.5f, 6.0f}, {0, 0, 0}, [&](TQ3ViewObject v) {
        Q3Geometry_Submit(translucent, v);
        Q3Geometry_Submit(opaque, v);
    });
    EXPECT_TRUE(q3test::matchesGolden("translucent_box_over_opaque", image));
    // Somewhere the red box shows through the blue one: both red and blue
    // well above the background's.
    int through = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const unsigned char* p = image.at(x, y);
            through += p[0] > 90 && p[2] > 90;
        }
    EXPECT_GT(through, 200);
}

TEST_F(TranslucencyGoldenTest, TintedTranslucentBoxOverAnOpaqueOne)
{
    // Green glass: transparency (0.2, 0.9, 0.3) lets the red box's red
    // channel through and takes the glass's own green (the QD3D Book's
    // per-channel rule).
    const TQ3ColorRGB glass{0.2f, 0.9f, 0.3f};
    TQ3GeometryObject opaque = box({-1.2f, -0.8f, -1.5f}, 1.6f, colors({0.9f, 0.3f, 0.2f}));
    TQ3GeometryObject translucent = box({-0.6f, -1.0f, -0.2f}, 1.8f, colors({0.3f, 0.9f, 0.4f}, &glass));
    const q3test::RgbaImage image = render({2.0f, 2.5f, 6.0f}, {0, 0, 0}, [&](TQ3ViewObject v) {
        Q3Geometry_Submit(translucent, v);
        Q3Geometry_Submit(opaque, v);
    });
    EXPECT_TRUE(q3test::matchesGolden("translucent_box_tinted", image));
    // Somewhere the red box shows through the green glass: red well above
    // the background's and above the glass's own green share of it.
    int through = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const unsigned char* p = image.at(x, y);
            through += p[0] > 90 && p[1] > 90;
        }
    EXPECT_GT(through, 200);
}

TEST_F(TranslucencyGoldenTest, RowOfSpheresOneFogModeEach)
{
    // Left to right: linear, exponential, exponential-squared, alpha (a
    // half-transparent sphere); each row recedes from the eye.
    const TQ3FogMode modes[4] = {kQ3FogModeLinear, kQ3FogModeExponential, kQ3FogModeExponentialSquared,
                                 kQ3FogModeAlpha};
    const TQ3ColorRGB half{0.5f, 0.5f, 0.5f};
    const TQ3SubdivisionStyleData subdivision{kQ3SubdivisionMethodConstant, 24.0f, 12.0f};
    const q3test::RgbaImage image = render({0.0f, 1.0f, 9.0f}, {0, 0, 0}, [&](TQ3ViewObject v) {
        Q3SubdivisionStyle_Submit(&subdivision, v);
        for (int m = 0; m < 4; ++m) {
            Q3Push_Submit(v);
            const TQ3FogStyleData fog{kQ3On, modes[m], 6.0f, 16.0f, modes[m] == kQ3FogModeExponential ? 0.09f : 0.07f,
                                      {1.0f, 0.75f, 0.8f, 0.85f}};
            Q3FogStyle_Submit(&fog, v);
            for (int k = 0; k < 3; ++k) {
                const float x = -3.0f + 2.0f * m + 0.4f * k, z = 1.5f - 4.0f * k;
                Q3Geometry_Submit(sphere({x, -0.8f + 0.9f * k, z}, 0.7f,
                                         colors({0.95f, 0.35f, 0.1f}, modes[m] == kQ3FogModeAlpha ? &half : nullptr)),
                                  v);
            }
            Q3Pop_Submit(v);
        }
    });
    EXPECT_TRUE(q3test::matchesGolden("fog_spheres_modes", image));
}

TEST_F(TranslucencyGoldenTest, TextureWithAlphaCutOuts)
{
    // A 16 x 16 ARGB32 texture: an opaque frame and cross, transparent holes
    // between them, and a half-transparent middle square.
    std::vector<unsigned char> texels;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const bool frame = x < 2 || x > 13 || y < 2 || y > 13 || x == 7 || x == 8 || y == 7 || y == 8;
            const bool middle = x >= 5 && x <= 10 && y >= 5 && y <= 10;
            const unsigned char a = frame ? 255 : middle ? 128 : 0;
            texels.insert(texels.end(), {a, (unsigned char)(frame ? 240 : 220), (unsigned char)(frame ? 200 : 60),
                                         (unsigned char)(frame ? 40 : 200)});
        }
    TQ3StorageObject storage = own(Q3MemoryStorage_New(texels.data(), static_cast<unsigned long>(texels.size())));
    const TQ3StoragePixmap pixmap{storage, 16, 16, 64, 32, kQ3PixelTypeARGB32, kQ3EndianBig, kQ3EndianBig};
    TQ3TextureObject texture = own(Q3PixmapTexture_New(&pixmap));
    TQ3ShaderObject shader = own(Q3TextureShader_New(texture));
    TQ3Param2D uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const TQ3Point3D corners[4] = {{-1.6f, -1.2f, 0.8f}, {1.6f, -1.2f, 0.8f}, {1.6f, 1.6f, 0.8f}, {-1.6f, 1.6f, 0.8f}};
    std::vector<TQ3Vertex3D> vertices(4);
    for (int k = 0; k < 4; ++k) {
        TQ3AttributeSet set = own(Q3AttributeSet_New());
        Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceUV, &uvs[k]);
        vertices[k] = TQ3Vertex3D{corners[k], set};
    }
    const TQ3PolygonData data{4, vertices.data(), nullptr};
    TQ3GeometryObject plane = own(Q3Polygon_New(&data));
    TQ3GeometryObject behind = box({-1.0f, -1.0f, -1.5f}, 1.5f, colors({0.3f, 0.8f, 0.4f}));
    const q3test::RgbaImage image = render({1.0f, 1.5f, 6.0f}, {0, 0, 0}, [&](TQ3ViewObject v) {
        Q3Push_Submit(v);
        Q3Shader_Submit(shader, v);
        Q3Geometry_Submit(plane, v);
        Q3Pop_Submit(v);
        Q3Geometry_Submit(behind, v);
    });
    EXPECT_TRUE(q3test::matchesGolden("texture_alpha_cutouts", image));
}

TEST_F(TranslucencyGoldenTest, HighlightedBoxBesideAPlainOne)
{
    TQ3AttributeSet highlight = own(Q3AttributeSet_New());
    const TQ3ColorRGB yellow{1.0f, 0.9f, 0.1f};
    Q3AttributeSet_Add(highlight, kQ3AttributeTypeDiffuseColor, &yellow);
    TQ3StyleObject style = own(Q3HighlightStyle_New(highlight));
    TQ3AttributeSet on = colors({0.2f, 0.4f, 0.9f});
    const TQ3Switch state = kQ3On;
    Q3AttributeSet_Add(on, kQ3AttributeTypeHighlightState, &state);
    TQ3GeometryObject highlighted = box({0.3f, -0.8f, -0.8f}, 1.6f, on);
    TQ3GeometryObject plain = box({-2.1f, -0.8f, -0.8f}, 1.6f, colors({0.2f, 0.4f, 0.9f}));
    const q3test::RgbaImage image = render({1.0f, 2.5f, 6.5f}, {0, 0, 0}, [&](TQ3ViewObject v) {
        Q3Style_Submit(style, v);
        Q3Geometry_Submit(plain, v);
        Q3Geometry_Submit(highlighted, v);
    });
    EXPECT_TRUE(q3test::matchesGolden("highlight_object", image));
    // The highlighted box (right half) is yellow, the plain one (left) blue.
    int yellowRight = 0, yellowLeft = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const unsigned char* p = image.at(x, y);
            const bool isYellow = p[0] > 120 && p[1] > 100 && p[2] < 60;
            (x < kWidth / 2 ? yellowLeft : yellowRight) += isYellow;
        }
    EXPECT_GT(yellowRight, 500);
    EXPECT_EQ(yellowLeft, 0);
}

} // namespace
