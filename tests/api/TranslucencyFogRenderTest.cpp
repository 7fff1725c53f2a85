// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Translucency and fog in the interactive renderer, pixel by pixel against
// formulas evaluated here (not by Q3).
//
// Translucency (the QD3D Book, "Transparency": a transparency colour of
// (1, 1, 1) is opaque, (0, 0, 0) wholly transparent; QuickDraw 3D multiplies
// it by the object's colour). A translucent surface of colour C and
// transparency colour T over what lies behind it, B, gives, channel by
// channel,
//     pixel.c = T.c C.c + (1 - T.c) B.c      for c = r, g, b
// with T times the texel's alpha under a texture. Translucent surfaces are
// drawn after the opaque ones, farthest first.
//
// Fog (QD3DStyle.h): at eye distance z (along the viewing direction), the
// fraction f of the pixel's own colour kept is (end - z) / (end - start),
// exp(-density z), exp(-(density z)^2) or the pixel's alpha, clamped to
// 0..1, and pixel = f colour + (1 - f) fog colour.

#include "OwningApiTest.h"
#include "RenderTestSupport.h"

#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"
#include "QD3DStyle.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace {

using q3test::Pixmap;
using q3test::Rgba;

constexpr unsigned long kSize = 64; // pixels each way
constexpr double kHalf = 2.0;       // the camera shows x and y in [-2, 2]

struct Color {
    double r, g, b;
};

Color mix(const Color& front, const Color& behind, double a)
{
    return {a * front.r + (1 - a) * behind.r, a * front.g + (1 - a) * behind.g, a * front.b + (1 - a) * behind.b};
}

// The book's rule channel by channel: transparency colour t.
Color mix(const Color& front, const Color& behind, const Color& t)
{
    return {t.r * front.r + (1 - t.r) * behind.r, t.g * front.g + (1 - t.g) * behind.g,
            t.b * front.b + (1 - t.b) * behind.b};
}

int toByte(double v)
{
    return int(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

// The world x and y at the centre of pixel (i, j) (orthographic camera).
double worldX(unsigned long i)
{
    return q3test::pixelCentre(i, kSize, kHalf);
}

class TranslucencyFogRenderTest : public q3test::OwningApiTest {
protected:
    /// A polygon filling x and y -2..2 at z = 1, the texture's (0, 0) to
    /// (1, 1) across it (a uv on each corner).
    // The square x, y in -2..2 at z = 1 with uv 0..1 across it, and `set`
    // (may be null) as its own.
    TQ3GeometryObject texturedSquare(TQ3AttributeSet set = nullptr)
    {
        const TQ3Param2D uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        const TQ3Point3D corners[4] = {{-2, -2, 1}, {2, -2, 1}, {2, 2, 1}, {-2, 2, 1}};
        std::vector<TQ3Vertex3D> v(4);
        for (int k = 0; k < 4; ++k) {
            TQ3AttributeSet set = own(Q3AttributeSet_New());
            EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceUV, &uvs[k]), kQ3Success);
            v[k] = TQ3Vertex3D{corners[k], set};
        }
        const TQ3PolygonData data{4, v.data(), set};
        return own(Q3Polygon_New(&data));
    }

    // A texture shader of the 2 x 2 ARGB32 texture the alpha tests use:
    // opaque red, alpha 0, alpha 128 green, opaque blue (top row first).
    TQ3ShaderObject alphaTextureShader()
    {
        m_alphaTexels = {255, 255, 0, 0, 0, 255, 255, 255, 128, 0, 255, 0, 255, 0, 0, 255};
        TQ3StorageObject storage =
            own(Q3MemoryStorage_New(m_alphaTexels.data(), static_cast<unsigned long>(m_alphaTexels.size())));
        const TQ3StoragePixmap pixmap{storage, 2, 2, 8, 32, kQ3PixelTypeARGB32, kQ3EndianBig, kQ3EndianBig};
        return own(Q3TextureShader_New(own(Q3PixmapTexture_New(&pixmap))));
    }

    // The square of texturedSquare with `squareSet`, under the alpha
    // texture shader, then behind it (z = 0.5) a wider rectangle of
    // diffuse colour `behind`, drawn after it.
    Pixmap renderAlphaTextureOver(TQ3AttributeSet squareSet, const Color& behind)
    {
        TQ3ShaderObject shader = alphaTextureShader();
        TQ3GeometryObject textured = texturedSquare(squareSet);
        TQ3GeometryObject between = rect(-3, 3, -3, 3, 0.5, 0.5, colorSet(behind));
        return render([&](TQ3ViewObject v) {
            Q3Push_Submit(v);
            Q3Shader_Submit(shader, v);
            Q3Geometry_Submit(textured, v);
            Q3Pop_Submit(v);
            Q3Geometry_Submit(between, v);
        });
    }

    // Every pixel of the image's quadrant at (i0, j0), but its border,
    // against `expected` within 1 per channel.
    void expectQuadrant(const Pixmap& image, unsigned long i0, unsigned long j0, const Color& expected,
                        const std::string& what)
    {
        int wrong = 0;
        for (unsigned long j = j0 + 1; j < j0 + kSize / 2 - 1; ++j)
            for (unsigned long i = i0 + 1; i < i0 + kSize / 2 - 1; ++i) {
                const Rgba got = image.at(i, j);
                wrong += std::abs(got.r - toByte(expected.r)) > 1 || std::abs(got.g - toByte(expected.g)) > 1 ||
                         std::abs(got.b - toByte(expected.b)) > 1;
            }
        EXPECT_EQ(wrong, 0) << what;
    }

    std::vector<unsigned char> m_alphaTexels;

    TQ3CameraObject orthographic()
    {
        const TQ3OrthographicCameraData data = q3test::orthographicCameraAt(0, 0, float(kHalf), float(kHalf));
        return own(Q3OrthographicCamera_New(&data));
    }

    TQ3AttributeSet colorSet(const Color& diffuse, const Color* transparency = nullptr)
    {
        TQ3AttributeSet set = own(Q3AttributeSet_New());
        const TQ3ColorRGB d{float(diffuse.r), float(diffuse.g), float(diffuse.b)};
        EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &d), kQ3Success);
        if (transparency != nullptr) {
            const TQ3ColorRGB t{float(transparency->r), float(transparency->g), float(transparency->b)};
            EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeTransparencyColor, &t), kQ3Success);
        }
        return set;
    }

    // A rectangle x0..x1 by y0..y1 in the plane z (or z0 at x = -2 rising to
    // z1 at x = 2), facing +z, with its own set and optional vertex sets.
    TQ3GeometryObject rect(double x0, double x1, double y0, double y1, double z0, double z1, TQ3AttributeSet set,
                           TQ3AttributeSet vertexSet = nullptr)
    {
        const auto zAt = [&](double x) { return float(z0 + (z1 - z0) * (x + kHalf) / (2 * kHalf)); };
        std::vector<TQ3Vertex3D> v{{{float(x0), float(y0), zAt(x0)}, vertexSet},
                                   {{float(x1), float(y0), zAt(x1)}, vertexSet},
                                   {{float(x1), float(y1), zAt(x1)}, vertexSet},
                                   {{float(x0), float(y1), zAt(x0)}, vertexSet}};
        const TQ3PolygonData data{4, v.data(), set};
        return own(Q3Polygon_New(&data));
    }

    Pixmap render(const std::function<void(TQ3ViewObject)>& submit, TQ3CameraObject camera = nullptr,
                  bool ambientLight = false)
    {
        Pixmap image(kSize, kSize);
        q3test::TestView view(image.pixmap(), kQ3RendererTypeInteractive, camera != nullptr ? camera : orthographic());
        if (ambientLight) {
            TQ3GroupObject group = own(Q3LightGroup_New());
            const TQ3LightData data{kQ3True, 1.0f, {1.0f, 1.0f, 1.0f}};
            EXPECT_NE(Q3Group_AddObject(group, own(Q3AmbientLight_New(&data))), nullptr);
            EXPECT_EQ(Q3View_SetLightGroup(view.view(), group), kQ3Success);
        }
        EXPECT_EQ(view.render(submit), kQ3ViewStatusDone);
        return image;
    }

    // `geometries` submitted in this order, lit by Lambert under an ambient
    // light of 1 (so each lit colour is the diffuse one), with `interpolation`.
    Pixmap renderLambert(TQ3InterpolationStyle interpolation, const std::vector<TQ3GeometryObject>& geometries)
    {
        TQ3ShaderObject lambert = own(Q3LambertIllumination_New());
        return render(
            [&](TQ3ViewObject v) {
                Q3InterpolationStyle_Submit(interpolation, v);
                Q3Shader_Submit(lambert, v);
                for (TQ3GeometryObject geometry : geometries)
                    Q3Geometry_Submit(geometry, v);
            },
            nullptr, true);
    }

    // Every pixel in columns i0..i1 (ends excluded) and every row, against
    // expected(i), within `tolerance` per channel.
    void expectColumns(const Pixmap& image, unsigned long i0, unsigned long i1,
                       const std::function<Color(unsigned long)>& expected, const std::string& what,
                       int tolerance = 1)
    {
        int wrong = 0;
        std::string first;
        for (unsigned long j = 0; j < kSize; ++j)
            for (unsigned long i = i0; i < i1; ++i) {
                const Color e = expected(i);
                const Rgba got = image.at(i, j);
                if (std::abs(got.r - toByte(e.r)) > tolerance || std::abs(got.g - toByte(e.g)) > tolerance ||
                    std::abs(got.b - toByte(e.b)) > tolerance) {
                    if (wrong++ == 0)
                        first = "(" + std::to_string(i) + ", " + std::to_string(j) + "): got " +
                                std::to_string(got.r) + " " + std::to_string(got.g) + " " + std::to_string(got.b) +
                                ", expected " + std::to_string(toByte(e.r)) + " " + std::to_string(toByte(e.g)) +
                                " " + std::to_string(toByte(e.b));
                }
            }
        EXPECT_EQ(wrong, 0) << what << ": first wrong pixel " << first;
    }
};

const Color kBehind{0.2, 0.6, 0.9};
const Color kFront{0.9, 0.3, 0.1};

TEST_F(TranslucencyFogRenderTest, TranslucentSurfaceBlendsOverTheOpaqueOneWhateverTheOrder)
{
    const Color grey{0.25, 0.25, 0.25};
    const Color tinted{0.2, 0.5, 0.8};
    TQ3GeometryObject back = rect(-3, 3, -3, 3, 0, 0, colorSet(kBehind));
    TQ3GeometryObject left = rect(-3, 0, -3, 3, 1, 1, colorSet(kFront, &grey));
    TQ3GeometryObject right = rect(0, 3, -3, 3, 1, 1, colorSet(kFront, &tinted));
    for (bool translucentFirst : {false, true}) {
        const Pixmap image = render([&](TQ3ViewObject v) {
            if (!translucentFirst)
                Q3Geometry_Submit(back, v);
            Q3Geometry_Submit(left, v);
            Q3Geometry_Submit(right, v);
            if (translucentFirst)
                Q3Geometry_Submit(back, v);
        });
        const std::string order = translucentFirst ? "translucent first" : "opaque first";
        expectColumns(image, 0, kSize / 2, [&](unsigned long) { return mix(kFront, kBehind, 0.25); },
                      "grey transparency, " + order);
        expectColumns(image, kSize / 2, kSize, [&](unsigned long) { return mix(kFront, kBehind, tinted); },
                      "tinted transparency, " + order);
    }
}

TEST_F(TranslucencyFogRenderTest, TintedTransparencyBlendsEachChannelByItsOwnOpacity)
{
    // Green passing only green, and an orange tint, unlit and lit (Lambert
    // under an ambient light of 1, so the lit colour is the diffuse one).
    const Color green{0, 1, 0};
    const Color orange{1, 0.5, 0.25};
    const Color front{0.8, 0.4, 0.6};
    TQ3ShaderObject lambert = own(Q3LambertIllumination_New());
    TQ3GeometryObject back = rect(-3, 3, -3, 3, 0, 0, colorSet(kBehind));
    TQ3GeometryObject left = rect(-3, 0, -3, 3, 1, 1, colorSet(front, &green));
    TQ3GeometryObject right = rect(0, 3, -3, 3, 1, 1, colorSet(front, &orange));
    for (bool lit : {false, true}) {
        const Pixmap image = render(
            [&](TQ3ViewObject v) {
                if (lit)
                    Q3Shader_Submit(lambert, v);
                Q3Geometry_Submit(left, v);
                Q3Geometry_Submit(right, v);
                Q3Geometry_Submit(back, v);
            },
            nullptr, lit);
        const std::string how = lit ? "lit" : "unlit";
        // (0, 1, 0): red and blue are what lies behind, green the front's.
        expectColumns(image, 0, kSize / 2, [&](unsigned long) { return Color{kBehind.r, front.g, kBehind.b}; },
                      "green tint, " + how);
        expectColumns(image, kSize / 2, kSize, [&](unsigned long) { return mix(front, kBehind, orange); },
                      "orange tint, " + how);
    }
}

TEST_F(TranslucencyFogRenderTest, PerVertexTintsAreInterpolatedChannelByChannel)
{
    // Transparency (1, 0, 0.5) at the left edge (x = -2), (0, 1, 0.5) at the
    // right (x = 2): across the square each channel's opacity is linear in x.
    const Color leftT{1, 0, 0.5}, rightT{0, 1, 0.5};
    const Color front{0.9, 0.8, 0.1};
    TQ3AttributeSet leftSet = own(Q3AttributeSet_New());
    TQ3AttributeSet rightSet = own(Q3AttributeSet_New());
    const TQ3ColorRGB l{float(leftT.r), float(leftT.g), float(leftT.b)};
    const TQ3ColorRGB r{float(rightT.r), float(rightT.g), float(rightT.b)};
    ASSERT_EQ(Q3AttributeSet_Add(leftSet, kQ3AttributeTypeTransparencyColor, &l), kQ3Success);
    ASSERT_EQ(Q3AttributeSet_Add(rightSet, kQ3AttributeTypeTransparencyColor, &r), kQ3Success);
    std::vector<TQ3Vertex3D> v{{{-2.0f, -2.0f, 1.0f}, leftSet},
                               {{2.0f, -2.0f, 1.0f}, rightSet},
                               {{2.0f, 2.0f, 1.0f}, rightSet},
                               {{-2.0f, 2.0f, 1.0f}, leftSet}};
    const TQ3PolygonData data{4, v.data(), colorSet(front)};
    TQ3GeometryObject square = own(Q3Polygon_New(&data));
    TQ3GeometryObject back = rect(-3, 3, -3, 3, 0, 0, colorSet(kBehind));
    const Pixmap image = render([&](TQ3ViewObject view) {
        Q3Geometry_Submit(back, view);
        Q3Geometry_Submit(square, view);
    });
    expectColumns(
        image, 0, kSize,
        [&](unsigned long i) {
            const double f = (worldX(i) + kHalf) / (2 * kHalf);
            const Color t{leftT.r + f * (rightT.r - leftT.r), leftT.g + f * (rightT.g - leftT.g),
                          leftT.b + f * (rightT.b - leftT.b)};
            return mix(front, kBehind, t);
        },
        "interpolated tint");
}

TEST_F(TranslucencyFogRenderTest, TranslucentSurfacesAreBlendedFarthestFirst)
{
    const Color half{0.5, 0.5, 0.5};
    const Color quarter{0.25, 0.25, 0.25};
    const Color nearColor{0.1, 0.9, 0.2};
    TQ3GeometryObject back = rect(-3, 3, -3, 3, 0, 0, colorSet(kBehind));
    TQ3GeometryObject nearer = rect(-3, 3, -3, 3, 2, 2, colorSet(nearColor, &quarter));
    TQ3GeometryObject farther = rect(-3, 3, -3, 3, 1, 1, colorSet(kFront, &half));
    // The nearer one submitted first: drawn last all the same.
    const Pixmap image = render([&](TQ3ViewObject v) {
        Q3Geometry_Submit(nearer, v);
        Q3Geometry_Submit(farther, v);
        Q3Geometry_Submit(back, v);
    });
    expectColumns(image, 0, kSize, [&](unsigned long) { return mix(nearColor, mix(kFront, kBehind, 0.5), 0.25); },
                  "two translucent layers");
}

TEST_F(TranslucencyFogRenderTest, VertexTransparencyOverridesTheGeometrysWhichOverridesTheViews)
{
    const Color view{0.5, 0.5, 0.5}, geometry{0.25, 0.25, 0.25}, vertex{0.75, 0.75, 0.75};
    TQ3AttributeSet viewSet = own(Q3AttributeSet_New());
    const TQ3ColorRGB viewT{0.5f, 0.5f, 0.5f};
    ASSERT_EQ(Q3AttributeSet_Add(viewSet, kQ3AttributeTypeTransparencyColor, &viewT), kQ3Success);
    TQ3AttributeSet vertexSet = own(Q3AttributeSet_New());
    const TQ3ColorRGB vertexT{0.75f, 0.75f, 0.75f};
    ASSERT_EQ(Q3AttributeSet_Add(vertexSet, kQ3AttributeTypeTransparencyColor, &vertexT), kQ3Success);
    TQ3GeometryObject back = rect(-3, 3, -3, 3, 0, 0, colorSet(kBehind));
    // Column by column: the view's, the geometry's, the vertices' own.
    TQ3GeometryObject first = rect(-3, -1, -3, 3, 1, 1, colorSet(kFront));
    TQ3GeometryObject second = rect(-1, 1, -3, 3, 1, 1, colorSet(kFront, &geometry));
    TQ3GeometryObject third = rect(1, 3, -3, 3, 1, 1, colorSet(kFront, &geometry), vertexSet);
    const Pixmap image = render([&](TQ3ViewObject v) {
        Q3Geometry_Submit(back, v);
        Q3Push_Submit(v);
        Q3AttributeSet_Submit(viewSet, v);
        Q3Geometry_Submit(first, v);
        Q3Geometry_Submit(second, v);
        Q3Geometry_Submit(third, v);
        Q3Pop_Submit(v);
    });
    expectColumns(image, 1, 15, [&](unsigned long) { return mix(kFront, kBehind, view.r); }, "view state");
    expectColumns(image, 17, 47, [&](unsigned long) { return mix(kFront, kBehind, geometry.r); }, "geometry");
    expectColumns(image, 49, 63, [&](unsigned long) { return mix(kFront, kBehind, vertex.r); }, "vertex");
}

TEST_F(TranslucencyFogRenderTest, HighlightSetsColourAndTransparencyOverTheVertices)
{
    // The highlight style's set (diffuse green, transparency 0.5) over a
    // geometry whose highlight state is on, whose vertices are opaque red.
    TQ3AttributeSet highlight = own(Q3AttributeSet_New());
    const TQ3ColorRGB green{0, 1, 0}, halfT{0.5f, 0.5f, 0.5f}, opaque{1, 1, 1}, red{1, 0, 0};
    ASSERT_EQ(Q3AttributeSet_Add(highlight, kQ3AttributeTypeDiffuseColor, &green), kQ3Success);
    ASSERT_EQ(Q3AttributeSet_Add(highlight, kQ3AttributeTypeTransparencyColor, &halfT), kQ3Success);
    TQ3StyleObject style = own(Q3HighlightStyle_New(highlight));
    TQ3AttributeSet vertexSet = own(Q3AttributeSet_New());
    ASSERT_EQ(Q3AttributeSet_Add(vertexSet, kQ3AttributeTypeDiffuseColor, &red), kQ3Success);
    ASSERT_EQ(Q3AttributeSet_Add(vertexSet, kQ3AttributeTypeTransparencyColor, &opaque), kQ3Success);
    TQ3AttributeSet on = colorSet(kFront);
    const TQ3Switch state = kQ3On;
    ASSERT_EQ(Q3AttributeSet_Add(on, kQ3AttributeTypeHighlightState, &state), kQ3Success);
    TQ3GeometryObject back = rect(-3, 3, -3, 3, 0, 0, colorSet(kBehind));
    TQ3GeometryObject left = rect(-3, 0, -3, 3, 1, 1, on, vertexSet);
    TQ3GeometryObject right = rect(0, 3, -3, 3, 1, 1, colorSet(kFront), vertexSet);
    const Pixmap image = render([&](TQ3ViewObject v) {
        Q3Style_Submit(style, v);
        Q3Geometry_Submit(back, v);
        Q3Geometry_Submit(left, v);
        Q3Geometry_Submit(right, v);
    });
    expectColumns(image, 0, kSize / 2, [&](unsigned long) { return mix(Color{0, 1, 0}, kBehind, 0.5); },
                  "highlighted");
    expectColumns(image, kSize / 2, kSize, [&](unsigned long) { return Color{1, 0, 0}; }, "not highlighted");
}

TEST_F(TranslucencyFogRenderTest, LitTranslucentSurfaceBlendsItsLitColour)
{
    // Lambert under an ambient light of 1: the lit colour is the diffuse one.
    const Color grey{0.25, 0.25, 0.25};
    TQ3GeometryObject back = rect(-3, 3, -3, 3, 0, 0, colorSet(kBehind));
    TQ3GeometryObject front = rect(-3, 3, -3, 3, 1, 1, colorSet(kFront, &grey));
    for (TQ3InterpolationStyle interpolation : {kQ3InterpolationStyleVertex, kQ3InterpolationStylePixel}) {
        const Pixmap image = renderLambert(interpolation, {front, back});
        expectColumns(image, 0, kSize, [&](unsigned long) { return mix(kFront, kBehind, 0.25); },
                      "lit, interpolation " + std::to_string(int(interpolation)));
    }
}

TEST_F(TranslucencyFogRenderTest, LitLayersOfOneGreyOpacityAndOfTintsBlendEachByTheBooksRuleInOneFrame)
{
    // Three layers, lit (Lambert under an ambient light of 1, so each lit
    // colour is the diffuse one), submitted in no particular order: the
    // opaque back at z = 0, a tinted layer at z = 0.5, and at z = 1 a grey
    // one: on the left half its geometry's transparency (one grey opacity for
    // the whole draw), on the right half the same grey on every vertex.
    // Q3 draws the two grey halves and the tint by different programs and
    // blend functions (SurfaceFinish.h); every pixel must be the book's rule
    // applied layer by layer, farthest first.
    const Color tint{0.2, 0.9, 0.5};
    const Color grey{0.4, 0.4, 0.4};
    const Color middle{0.7, 0.1, 0.5};
    TQ3AttributeSet greyVertex = own(Q3AttributeSet_New());
    const TQ3ColorRGB g{float(grey.r), float(grey.g), float(grey.b)};
    ASSERT_EQ(Q3AttributeSet_Add(greyVertex, kQ3AttributeTypeTransparencyColor, &g), kQ3Success);
    TQ3GeometryObject back = rect(-3, 3, -3, 3, 0, 0, colorSet(kBehind));
    TQ3GeometryObject tinted = rect(-3, 3, -3, 3, 0.5, 0.5, colorSet(middle, &tint));
    TQ3GeometryObject left = rect(-3, 0, -3, 3, 1, 1, colorSet(kFront, &grey));
    TQ3GeometryObject right = rect(0, 3, -3, 3, 1, 1, colorSet(kFront), greyVertex);
    const Color expected = mix(kFront, mix(middle, kBehind, tint), grey.r);
    for (TQ3InterpolationStyle interpolation : {kQ3InterpolationStyleVertex, kQ3InterpolationStylePixel}) {
        const Pixmap image = renderLambert(interpolation, {left, tinted, back, right});
        const std::string how = "interpolation " + std::to_string(int(interpolation));
        expectColumns(image, 0, kSize / 2, [&](unsigned long) { return expected; }, "grey geometry, " + how);
        expectColumns(image, kSize / 2, kSize, [&](unsigned long) { return expected; }, "grey vertices, " + how);
    }
}

TEST_F(TranslucencyFogRenderTest, LitAlphaTextureUnderGreyTransparencyBlendsByTheirProduct)
{
    // The 2 x 2 ARGB32 alpha texture (opaque red, alpha 0, alpha 128 green,
    // opaque blue) on a lit square (Lambert under an ambient light of 1: the
    // texel is the lit colour) whose transparency is grey 0.6: each texel's
    // opacity is 0.6 times its alpha. The grey rectangle behind is drawn
    // after it.
    const double t = 0.6;
    const Color grey{t, t, t};
    const Color middle{0.3, 0.3, 0.3};
    TQ3ShaderObject lambert = own(Q3LambertIllumination_New());
    TQ3ShaderObject shader = alphaTextureShader();
    TQ3GeometryObject textured = texturedSquare(colorSet(Color{1, 1, 1}, &grey));
    TQ3GeometryObject between = rect(-3, 3, -3, 3, 0.5, 0.5, colorSet(middle));
    const Pixmap image = render(
        [&](TQ3ViewObject v) {
            Q3Shader_Submit(lambert, v);
            Q3Push_Submit(v);
            Q3Shader_Submit(shader, v);
            Q3Geometry_Submit(textured, v);
            Q3Pop_Submit(v);
            Q3Geometry_Submit(between, v);
        },
        nullptr, true);
    const Color red{1, 0, 0}, green{0, 1, 0}, blue{0, 0, 1};
    const double a = 128.0 / 255.0;
    expectQuadrant(image, 0, 0, mix(red, middle, t), "opaque red texel");
    expectQuadrant(image, kSize / 2, 0, middle, "alpha 0");
    expectQuadrant(image, 0, kSize / 2, mix(green, middle, t * a), "alpha 128 green texel");
    expectQuadrant(image, kSize / 2, kSize / 2, mix(blue, middle, t), "opaque blue texel");
}

TEST_F(TranslucencyFogRenderTest, TextureAlphaCutsOutAndOpaqueTexelsHideWhatIsBehind)
{
    // A 2 x 2 ARGB32 texture: opaque red, alpha 0, alpha 128 green, opaque
    // blue (top row first), over the whole view, nearest; behind it a
    // square drawn after it, and the opaque background.
    const Color middle{0.3, 0.3, 0.3};
    const Pixmap image = renderAlphaTextureOver(nullptr, middle);
    const Color red{1, 0, 0}, green{0, 1, 0}, blue{0, 0, 1};
    const double a = 128.0 / 255.0;
    expectQuadrant(image, 0, 0, red, "opaque texel");
    expectQuadrant(image, kSize / 2, 0, middle, "alpha 0: what lies behind, drawn later");
    expectQuadrant(image, 0, kSize / 2, mix(green, middle, a), "alpha 128: blended");
    expectQuadrant(image, kSize / 2, kSize / 2, blue, "opaque texel hides what is behind");
}

TEST_F(TranslucencyFogRenderTest, TintTimesTexelAlphaChannelByChannel)
{
    // The 2 x 2 ARGB32 texture of the test above (opaque red, alpha 0,
    // alpha 128 green, opaque blue) on a square whose transparency colour
    // is (0, 1, 0.5): each channel's opacity is that channel of T times the
    // texel's alpha. The grey rectangle behind is drawn after it.
    const Color tint{0, 1, 0.5};
    const Color middle{0.3, 0.3, 0.3};
    const Pixmap image = renderAlphaTextureOver(colorSet(Color{1, 1, 1}, &tint), middle);
    const auto times = [](const Color& t, double a) { return Color{t.r * a, t.g * a, t.b * a}; };
    const Color red{1, 0, 0}, green{0, 1, 0}, blue{0, 0, 1};
    const double a = 128.0 / 255.0;
    expectQuadrant(image, 0, 0, mix(red, middle, tint), "opaque red texel");
    expectQuadrant(image, kSize / 2, 0, middle, "alpha 0");
    expectQuadrant(image, 0, kSize / 2, mix(green, middle, times(tint, a)), "alpha 128 green texel");
    expectQuadrant(image, kSize / 2, kSize / 2, mix(blue, middle, tint), "opaque blue texel");
}

TEST_F(TranslucencyFogRenderTest, Argb16AlphaBitCutsOut)
{
    // Two ARGB16 texels, big-endian: red with the alpha bit, green without.
    std::vector<unsigned char> texels{0xFC, 0x00, 0x03, 0xE0};
    TQ3StorageObject storage = own(Q3MemoryStorage_New(texels.data(), static_cast<unsigned long>(texels.size())));
    const TQ3StoragePixmap pixmap{storage, 2, 1, 4, 16, kQ3PixelTypeARGB16, kQ3EndianBig, kQ3EndianBig};
    TQ3ShaderObject shader = own(Q3TextureShader_New(own(Q3PixmapTexture_New(&pixmap))));
    TQ3GeometryObject textured = texturedSquare();
    TQ3GeometryObject back = rect(-3, 3, -3, 3, 0, 0, colorSet(kBehind));
    const Pixmap image = render([&](TQ3ViewObject v) {
        Q3Geometry_Submit(back, v);
        Q3Push_Submit(v);
        Q3Shader_Submit(shader, v);
        Q3Geometry_Submit(textured, v);
        Q3Pop_Submit(v);
    });
    expectColumns(image, 1, kSize / 2 - 1, [&](unsigned long) { return Color{1, 0, 0}; }, "alpha bit set");
    expectColumns(image, kSize / 2 + 1, kSize - 1, [&](unsigned long) { return kBehind; }, "alpha bit clear");
}

// Fog on a plane that rises from z = -4 at x = -2 to z = 4 at x = 2, seen by
// the orthographic camera at z = 10: eye distance 10 - z.
class FogModeTest : public TranslucencyFogRenderTest,
                    public ::testing::WithParamInterface<std::tuple<TQ3FogMode, bool>> {};

TEST_P(FogModeTest, EachPixelIsTheFogFormulaOfItsEyeDistance)
{
    const TQ3FogMode mode = std::get<0>(GetParam());
    const bool lit = std::get<1>(GetParam());
    const TQ3FogStyleData fog{kQ3On, mode, 5.0f, 15.0f, mode == kQ3FogModeExponential ? 0.1f : 0.08f,
                              {1.0f, 0.8f, 0.85f, 0.9f}};
    const Color fogColor{0.8, 0.85, 0.9};
    const Color half{0.5, 0.5, 0.5};
    const bool translucent = mode == kQ3FogModeAlpha;
    TQ3GeometryObject plane = rect(-3, 3, -3, 3, -4, 4, colorSet(kFront, translucent ? &half : nullptr));
    TQ3ShaderObject lambert = own(Q3LambertIllumination_New());
    const Pixmap image = render(
        [&](TQ3ViewObject v) {
            if (lit)
                Q3Shader_Submit(lambert, v);
            Q3FogStyle_Submit(&fog, v);
            Q3Geometry_Submit(plane, v);
        },
        nullptr, lit);
    const Color background{0, 0, 0}; // the test views clear to black
    expectColumns(
        image, 0, kSize,
        [&](unsigned long i) {
            const double z = 10.0 - 2.0 * worldX(i);
            double f = 0;
            switch (mode) {
            case kQ3FogModeLinear: f = (15.0 - z) / (15.0 - 5.0); break;
            case kQ3FogModeExponential: f = std::exp(-0.1 * z); break;
            case kQ3FogModeExponentialSquared: f = std::exp(-(0.08 * z) * (0.08 * z)); break;
            default: f = 0.5; break;
            }
            f = std::clamp(f, 0.0, 1.0);
            const Color fogged = mix(kFront, fogColor, f);
            return translucent ? mix(fogged, background, 0.5) : fogged;
        },
        "fog mode " + std::to_string(int(mode)) + (lit ? ", lit" : ", unlit"), 2);
}

INSTANTIATE_TEST_SUITE_P(Modes, FogModeTest,
                         ::testing::Combine(::testing::Values(kQ3FogModeLinear, kQ3FogModeExponential,
                                                              kQ3FogModeExponentialSquared, kQ3FogModeAlpha),
                                            ::testing::Bool()));

TEST_F(TranslucencyFogRenderTest, FogUsesTheEyeDepthNotTheDistanceToTheEye)
{
    // A perspective camera at z = 10 facing a plane at z = 0: every pixel
    // is at eye depth 10, wherever it lies off the axis.
    TQ3ViewAngleAspectCameraData data{};
    data.cameraData.placement = {{0, 0, 10}, {0, 0, 0}, {0, 1, 0}};
    data.cameraData.range = {1.0f, 100.0f};
    data.cameraData.viewPort = {{-1.0f, 1.0f}, 2.0f, 2.0f};
    data.fov = 1.2f;
    data.aspectRatioXToY = 1.0f;
    TQ3CameraObject camera = own(Q3ViewAngleAspectCamera_New(&data));
    const TQ3FogStyleData fog{kQ3On, kQ3FogModeLinear, 0.0f, 20.0f, 1.0f, {1.0f, 1.0f, 1.0f, 1.0f}};
    TQ3GeometryObject plane = rect(-20, 20, -20, 20, 0, 0, colorSet(kFront));
    const Pixmap image = render(
        [&](TQ3ViewObject v) {
            Q3FogStyle_Submit(&fog, v);
            Q3Geometry_Submit(plane, v);
        },
        camera);
    expectColumns(image, 0, kSize, [&](unsigned long) { return mix(kFront, Color{1, 1, 1}, 0.5); },
                  "perspective, eye depth 10 of 20", 2);
}

TEST_F(TranslucencyFogRenderTest, FogIsPoppedWithTheViewState)
{
    const TQ3FogStyleData fog{kQ3On, kQ3FogModeLinear, 0.0f, 20.0f, 1.0f, {1.0f, 1.0f, 1.0f, 1.0f}};
    TQ3GeometryObject left = rect(-3, 0, -3, 3, 0, 0, colorSet(kFront));
    TQ3GeometryObject right = rect(0, 3, -3, 3, 0, 0, colorSet(kFront));
    const Pixmap image = render([&](TQ3ViewObject v) {
        Q3Push_Submit(v);
        Q3FogStyle_Submit(&fog, v);
        Q3Geometry_Submit(left, v);
        Q3Pop_Submit(v);
        Q3Geometry_Submit(right, v);
    });
    expectColumns(image, 0, kSize / 2, [&](unsigned long) { return mix(kFront, Color{1, 1, 1}, 0.5); }, "fogged",
                  2);
    expectColumns(image, kSize / 2, kSize, [&](unsigned long) { return kFront; }, "after the pop");
}

} // namespace
