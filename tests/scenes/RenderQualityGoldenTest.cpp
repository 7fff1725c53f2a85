// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The interactive renderer's texture filters and the anti-alias style,
// compared with tests/golden (tolerance: tests/golden/README.md):
//   texture_filter_fast, _mid, _best: a plane of a mipmapped checkerboard
//     seen at a grazing angle under RAVE's Fast (nearest), Mid (bilinear) and
//     Best (trilinear over the mipmap's levels) filters;
//   antialias_wireframe: a box, a torus and a line under the wireframe
//     renderer with the edges mode; antialias_filled: the same lit by the
//     interactive renderer with edges and filled modes.
// Facts a golden blessed from a wrong picture would not pass are checked by
// reading pixels: towards the horizon the trilinear image varies far less
// than the nearest one (its far texels are the levels' averages); the
// anti-aliased images hold shades between an edge and what is behind it that
// their aliased twins do not, and come out the same twice.
// Per-pixel formulas: tests/api/TextureFilterRenderTest.cpp and
// tests/api/AntiAliasRenderTest.cpp.

#include "Golden.h"
#include "SceneRender.h"
#include "SessionTest.h"
#include "QuadMesh.h"

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
#include <set>
#include <vector>

namespace {

constexpr int kWidth = 160, kHeight = 120;

class RenderQualityGoldenTest : public q3test::SessionTest<> {
protected:

    // Renders `submit` in perspective from `eye` towards `target` with the
    // renderer `type` (RAVE texture filter `filter` for the interactive
    // one), lit by an ambient and a directional light.
    q3test::RgbaImage render(const TQ3Point3D& eye, const TQ3Point3D& target, TQ3ObjectType type,
                             unsigned long filter, const std::function<void(TQ3ViewObject)>& submit)
    {
        q3test::SceneSetup setup = q3test::sceneLookingAt(kWidth, kHeight, {1.0f, 0.08f, 0.1f, 0.16f}, eye, target);
        setup.hither = 0.2f;
        setup.yon = 100.0f;
        setup.fov = 0.9f;
        setup.renderer = type;
        if (type == kQ3RendererTypeInteractive)
            setup.textureFilter = filter;
        return q3test::renderScene(setup, submit);
    }

    // The variance of the green channel over rows y0..y1, pixels of the
    // clear colour's blue (41) left out.
    static double variance(const q3test::RgbaImage& image, int y0, int y1)
    {
        double sum = 0, squares = 0;
        int n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < image.width; ++x) {
                if (image.at(x, y)[2] == 41)
                    continue;
                const double g = image.at(x, y)[1];
                sum += g;
                squares += g * g;
                ++n;
            }
        const double mean = sum / n;
        return squares / n - mean * mean;
    }
};

// The checkerboard's colours (8 x 8 texel squares on a 64 x 64 image).
constexpr unsigned char kLight[3] = {240, 220, 120};
constexpr unsigned char kDark[3] = {30, 60, 150};

// A 64 x 64 checkerboard mipmap (RGB24) whose every image is the one before
// it averaged over 2 x 2 texels, rounded, down to 1 x 1.
struct CheckerMipmap {
    std::vector<unsigned char> bytes;
    TQ3Mipmap mipmap{};

    CheckerMipmap()
    {
        std::vector<unsigned char> level;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const unsigned char* c = ((x / 8) + (y / 8)) % 2 == 0 ? kLight : kDark;
                level.insert(level.end(), c, c + 3);
            }
        mipmap.useMipmapping = kQ3True;
        mipmap.pixelType = kQ3PixelTypeRGB24;
        mipmap.bitOrder = kQ3EndianBig;
        mipmap.byteOrder = kQ3EndianBig;
        unsigned long side = 64;
        for (int i = 0; side >= 1; ++i) {
            mipmap.mipmaps[i] = TQ3MipmapImage{side, side, 3 * side, (unsigned long)bytes.size()};
            bytes.insert(bytes.end(), level.begin(), level.end());
            if (side == 1)
                break;
            std::vector<unsigned char> half;
            const unsigned long next = side / 2;
            for (unsigned long y = 0; y < next; ++y)
                for (unsigned long x = 0; x < next; ++x)
                    for (int k = 0; k < 3; ++k) {
                        const auto at = [&](unsigned long xx, unsigned long yy) { return int(level[(yy * side + xx) * 3 + k]); };
                        half.push_back(
                            (unsigned char)((at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) +
                                             at(2 * x + 1, 2 * y + 1) + 2) / 4));
                    }
            level = half;
            side = next;
        }
    }
};

// A long plane (x -4..4, z 3..-45) with the checkerboard repeated 12 times
// along it and 2 times across, seen from just above it.
q3test::RgbaImage drawPlane(
    unsigned long filter,
    const std::function<q3test::RgbaImage(unsigned long, const std::function<void(TQ3ViewObject)>&)>& render)
{
    CheckerMipmap checker;
    TQ3StorageObject storage = Q3MemoryStorage_New(checker.bytes.data(), (unsigned long)checker.bytes.size());
    checker.mipmap.image = storage;
    TQ3TextureObject texture = Q3MipmapTexture_New(&checker.mipmap);
    EXPECT_NE(texture, nullptr);
    TQ3ShaderObject shader = Q3TextureShader_New(texture);
    const q3test::QuadMesh quad({{-4, 0, 3}, {4, 0, 3}, {4, 0, -45}, {-4, 0, -45}}, {{0, 0}, {2, 0}, {2, 12}, {0, 12}});
    TQ3GeometryObject plane = quad.create();
    q3test::RgbaImage image = render(filter, [&](TQ3ViewObject view) {
        Q3Shader_Submit(shader, view);
        Q3Geometry_Submit(plane, view);
    });
    Q3Object_Dispose(plane);
    Q3Object_Dispose(shader);
    Q3Object_Dispose(texture);
    Q3Object_Dispose(storage);
    return image;
}

TEST_F(RenderQualityGoldenTest, AMipmappedPlaneAtAGrazingAngleUnderEachFilter)
{
    const auto render = [&](unsigned long filter, const std::function<void(TQ3ViewObject)>& submit) {
        return this->render({0.0f, 0.7f, 3.5f}, {0.0f, 0.0f, -20.0f}, kQ3RendererTypeInteractive, filter, submit);
    };
    const q3test::RgbaImage fast = drawPlane(0, render);
    const q3test::RgbaImage mid = drawPlane(1, render);
    const q3test::RgbaImage best = drawPlane(2, render);
    EXPECT_TRUE(q3test::matchesGolden("texture_filter_fast", fast));
    EXPECT_TRUE(q3test::matchesGolden("texture_filter_mid", mid));
    EXPECT_TRUE(q3test::matchesGolden("texture_filter_best", best));
    // The far band, just below the horizon: nearest sampling keeps both
    // checker colours there, trilinear filtering their mean.
    int top = -1;
    for (int y = 0; y < kHeight && top < 0; ++y)
        if (fast.at(kWidth / 2, y)[2] != 41) // the clear colour's blue: 0.16 * 255
            top = y;
    ASSERT_GE(top, 0);
    const double farFast = variance(fast, top + 1, top + 6), farBest = variance(best, top + 1, top + 6);
    EXPECT_LT(farBest, farFast / 3) << "far band variance: fast " << farFast << ", best " << farBest;
    // Near the camera the texture is magnified: mid and best agree there.
    int same = 0;
    for (int x = 0; x < kWidth; ++x)
        same += mid.at(x, kHeight - 2)[1] == best.at(x, kHeight - 2)[1] ? 1 : 0;
    EXPECT_GT(same, kWidth * 9 / 10);
}

// A box, a torus and a line under the anti-alias style's edges mode, or
// edges and filled, or none.
void submitScene(TQ3ViewObject view, TQ3AntiAliasMode mode, bool smooth)
{
    if (smooth) {
        const TQ3AntiAliasStyleData style{kQ3On, mode, 1.0f};
        Q3AntiAliasStyle_Submit(&style, view);
    }
    TQ3ShaderObject lambert = Q3LambertIllumination_New();
    Q3Shader_Submit(lambert, view);
    Q3Object_Dispose(lambert);
    TQ3AttributeSet orange = Q3AttributeSet_New();
    const TQ3ColorRGB orangeColour{1.0f, 0.55f, 0.1f};
    Q3AttributeSet_Add(orange, kQ3AttributeTypeDiffuseColor, &orangeColour);
    TQ3BoxData box{{-1.6f, -0.6f, -0.5f}, {1.1f, 0.3f, 0.0f}, {0.0f, 1.2f, 0.0f}, {-0.4f, 0.0f, 1.0f}, nullptr, orange};
    Q3Box_Submit(&box, view);
    TQ3AttributeSet teal = Q3AttributeSet_New();
    const TQ3ColorRGB tealColour{0.1f, 0.75f, 0.7f};
    Q3AttributeSet_Add(teal, kQ3AttributeTypeDiffuseColor, &tealColour);
    TQ3TorusData torus{{0.9f, 0.2f, 0.0f}, {0.0f, 0.25f, 0.15f}, {0.8f, 0.0f, 0.0f}, {0.0f, -0.45f, 0.75f}, 1.0f,
                       0.0f, 1.0f, 0.0f, 1.0f, kQ3EndCapNone, nullptr, teal};
    TQ3SubdivisionStyleData subdivision{kQ3SubdivisionMethodConstant, 20.0f, 10.0f};
    Q3SubdivisionStyle_Submit(&subdivision, view);
    Q3Torus_Submit(&torus, view);
    TQ3AttributeSet white = Q3AttributeSet_New();
    const TQ3ColorRGB whiteColour{1.0f, 1.0f, 1.0f};
    Q3AttributeSet_Add(white, kQ3AttributeTypeDiffuseColor, &whiteColour);
    TQ3LineData line{{{{-2.2f, -1.1f, 0.4f}, nullptr}, {{2.3f, 1.3f, -0.2f}, nullptr}}, white};
    Q3Line_Submit(&line, view);
    Q3Object_Dispose(orange);
    Q3Object_Dispose(teal);
    Q3Object_Dispose(white);
}

// Pixels of a colour the aliased image does not hold at all.
int newShades(const q3test::RgbaImage& smoothed, const q3test::RgbaImage& aliased)
{
    std::set<unsigned> colours;
    for (int y = 0; y < aliased.height; ++y)
        for (int x = 0; x < aliased.width; ++x) {
            const unsigned char* p = aliased.at(x, y);
            colours.insert(unsigned(p[0]) << 16 | unsigned(p[1]) << 8 | p[2]);
        }
    int n = 0;
    for (int y = 0; y < smoothed.height; ++y)
        for (int x = 0; x < smoothed.width; ++x) {
            const unsigned char* p = smoothed.at(x, y);
            n += colours.count(unsigned(p[0]) << 16 | unsigned(p[1]) << 8 | p[2]) == 0 ? 1 : 0;
        }
    return n;
}

TEST_F(RenderQualityGoldenTest, AnAntiAliasedWireframeAndFilledScene)
{
    const TQ3Point3D eye{0.6f, 1.2f, 5.0f}, target{0.0f, 0.0f, 0.0f};
    const auto draw = [&](TQ3ObjectType type, TQ3AntiAliasMode mode, bool smooth) {
        return render(eye, target, type, 0, [&](TQ3ViewObject view) { submitScene(view, mode, smooth); });
    };
    const TQ3AntiAliasMode both = kQ3AntiAliasModeMaskEdges | kQ3AntiAliasModeMaskFilled;
    const q3test::RgbaImage wireframe = draw(kQ3RendererTypeWireFrame, kQ3AntiAliasModeMaskEdges, true);
    const q3test::RgbaImage filled = draw(kQ3RendererTypeInteractive, both, true);
    EXPECT_TRUE(q3test::matchesGolden("antialias_wireframe", wireframe));
    EXPECT_TRUE(q3test::matchesGolden("antialias_filled", filled));
    // Shades between an edge and its background that aliased drawing never
    // makes: the wireframe's lines are single colours on the clear colour.
    EXPECT_GT(newShades(wireframe, draw(kQ3RendererTypeWireFrame, 0, false)), 200);
    // The same pixels every time.
    EXPECT_EQ(filled.pixels, draw(kQ3RendererTypeInteractive, both, true).pixels);
    EXPECT_EQ(wireframe.pixels, draw(kQ3RendererTypeWireFrame, kQ3AntiAliasModeMaskEdges, true).pixels);
}

} // namespace
