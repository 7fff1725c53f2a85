// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The anti-alias style drawn by multisampling (4 samples a pixel), checked
// against the coverage of OpenGL's standard 4-sample pattern computed here.
//
// A red quad on black spans world x 0.046875..2.046875 and y -0.5..1.5; the
// orthographic camera puts 16 pixels in a world unit with x = -0.5 at the
// left edge and y = 2 at the top, so its top and bottom edges lie on pixel
// rows 8 and 40 exactly and its left and right edges three quarters of the
// way across pixel columns 8 and 40: x = 8.75 and 40.75 pixels. The four
// samples of a pixel lie at x 0.125, 0.375, 0.625 and 0.875 of it (and y
// 0.625, 0.125, 0.875, 0.375 in the same order: the standard pattern, one
// sample per row and per column of a 4 x 4 grid). So column 8 is covered by
// the one sample right of 0.75, column 40 by the three left of it: red 255/4
// and 3 * 255/4, the mean of the samples. Without the filled mode (or with the
// style off) those pixels are covered wholly or not at all by their centre
// (0.5): column 8 black, column 40 red.

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"
#include "RenderTestSupport.h"

#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DShader.h"
#include "QD3DStyle.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace {

using namespace q3test;

constexpr int kWidth = 64, kHeight = 48;
constexpr float kLeft = 0.046875f, kRight = 2.046875f, kBottom = -0.5f, kTop = 1.5f;

class AntiAliasRenderTest : public OwningApiTest {
protected:
    TQ3GeometryObject redQuad()
    {
        TQ3Vertex3D vertices[4] = {{{kLeft, kBottom, 0}, nullptr},
                                   {{kRight, kBottom, 0}, nullptr},
                                   {{kRight, kTop, 0}, nullptr},
                                   {{kLeft, kTop, 0}, nullptr}};
        TQ3PolygonData data{4, vertices, own(colorSet(1, 0, 0))};
        TQ3GeometryObject polygon = own(Q3Polygon_New(&data));
        EXPECT_NE(polygon, nullptr);
        return polygon;
    }

    Pixmap render(const std::function<void(TQ3ViewObject)>& submit,
                  TQ3ObjectType renderer = kQ3RendererTypeInteractive)
    {
        Pixmap image(kWidth, kHeight);
        TestView view(image.pixmap(), renderer);
        EXPECT_EQ(view.render(submit), kQ3ViewStatusDone);
        return image;
    }

    // Row `row` of the quad: column 7 black, 8 a quarter red, 9..39 red, 40
    // three quarters, 41 black, within `tolerance`.
    void expectRow(const Pixmap& image, int row, double quarter8, double quarter40, const std::string& what)
    {
        for (int px = 6; px <= 42; ++px) {
            double coverage = px < 8 || px > 40 ? 0.0 : 1.0;
            if (px == 8)
                coverage = quarter8;
            if (px == 40)
                coverage = quarter40;
            const Rgba got = image.at(px, row);
            EXPECT_NEAR(got.r, 255.0 * coverage, 1.0) << what << ": pixel (" << px << ", " << row << ")";
            EXPECT_EQ(got.g, 0) << what;
            EXPECT_EQ(got.b, 0) << what;
        }
    }
};

TEST_F(AntiAliasRenderTest, FilledModeCoversEdgePixelsByTheirSamples)
{
    TQ3GeometryObject quad = redQuad();
    const TQ3AntiAliasStyleData style{kQ3On, kQ3AntiAliasModeMaskFilled, 1.0f};
    const Pixmap image = render([&](TQ3ViewObject v) {
        EXPECT_EQ(Q3AntiAliasStyle_Submit(&style, v), kQ3Success);
        EXPECT_EQ(Q3Geometry_Submit(quad, v), kQ3Success);
    });
    for (int row : {8, 20, 39})
        expectRow(image, row, 0.25, 0.75, "filled, anti-aliased");
    // The rows on the quad's top and bottom edges: wholly in or out.
    EXPECT_EQ(image.at(20, 7).r, 0);
    EXPECT_EQ(image.at(20, 40).r, 0);
}

TEST_F(AntiAliasRenderTest, EveryQualityDrawsWithTheSameFourSamples)
{
    TQ3GeometryObject quad = redQuad();
    for (float quality : {0.0f, 0.3f, 1.0f}) {
        const TQ3AntiAliasStyleData style{kQ3On, kQ3AntiAliasModeMaskFilled, quality};
        const Pixmap image = render([&](TQ3ViewObject v) {
            Q3AntiAliasStyle_Submit(&style, v);
            Q3Geometry_Submit(quad, v);
        });
        expectRow(image, 20, 0.25, 0.75, "quality " + std::to_string(quality));
    }
}

TEST_F(AntiAliasRenderTest, WithoutTheFilledModeOrOffSurfacesAreAliased)
{
    TQ3GeometryObject quad = redQuad();
    const auto drawWith = [&](const TQ3AntiAliasStyleData* style) {
        return render([&](TQ3ViewObject v) {
            if (style != nullptr)
                Q3AntiAliasStyle_Submit(style, v);
            Q3Geometry_Submit(quad, v);
        });
    };
    const Pixmap plain = drawWith(nullptr);
    expectRow(plain, 20, 0.0, 1.0, "no style");
    const TQ3AntiAliasStyleData edges{kQ3On, kQ3AntiAliasModeMaskEdges, 1.0f};
    const Pixmap edgesOnly = drawWith(&edges);
    expectRow(edgesOnly, 20, 0.0, 1.0, "edges mode");
    const TQ3AntiAliasStyleData off{kQ3Off, kQ3AntiAliasModeMaskFilled | kQ3AntiAliasModeMaskEdges, 1.0f};
    const Pixmap offImage = drawWith(&off);
    // Off: the very pixels of no style at all.
    EXPECT_EQ(offImage.bytes(), plain.bytes());
}

TEST_F(AntiAliasRenderTest, EdgesModeSmoothsLinesAndIsTheSameEveryRun)
{
    // A shallow line: aliased, every pixel is the line's red or black;
    // smoothed, pixels along it take shares of red in between.
    TQ3LineData line{{{{0.0f, 0.0f, 0.0f}, nullptr}, {{3.0f, 0.7f, 0.0f}, nullptr}}, own(colorSet(1, 0, 0))};
    TQ3GeometryObject geometry = own(Q3Line_New(&line));
    const TQ3AntiAliasStyleData style{kQ3On, kQ3AntiAliasModeMaskEdges, 1.0f};
    const auto draw = [&](bool smooth) {
        return render([&](TQ3ViewObject v) {
            if (smooth)
                Q3AntiAliasStyle_Submit(&style, v);
            Q3Geometry_Submit(geometry, v);
        });
    };
    const auto partial = [](const Pixmap& image) {
        int n = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x)
                n += image.at(x, y).r > 0 && image.at(x, y).r < 255 ? 1 : 0;
        return n;
    };
    const Pixmap aliased = draw(false);
    const Pixmap smoothed = draw(true);
    EXPECT_EQ(partial(aliased), 0);
    EXPECT_GT(partial(smoothed), 20);
    const Pixmap again = draw(true);
    EXPECT_EQ(smoothed.bytes(), again.bytes());
}

TEST_F(AntiAliasRenderTest, AStyleSubmittedAfterOtherDrawingKeepsThatDrawing)
{
    // The red quad drawn before the style, unlit; then a blue one behind it,
    // lit by a full ambient light, whose lights make the target draw what it
    // holds so far into the image, and whose style makes the rest of the
    // frame multisampled. The red quad keeps its aliased pixels, and the
    // depth it wrote still hides the blue one behind it.
    TQ3GeometryObject quad = redQuad();
    TQ3Vertex3D behind[4] = {{{1.0f, -1.0f, -1.0f}, nullptr},
                             {{3.0f, -1.0f, -1.0f}, nullptr},
                             {{3.0f, 1.0f, -1.0f}, nullptr},
                             {{1.0f, 1.0f, -1.0f}, nullptr}};
    TQ3PolygonData data{4, behind, own(colorSet(0, 0, 1))};
    TQ3GeometryObject blue = own(Q3Polygon_New(&data));
    const TQ3LightData light{kQ3True, 1.0f, {1, 1, 1}};
    TQ3GroupObject lights = own(Q3LightGroup_New());
    Q3Group_AddObject(lights, own(Q3AmbientLight_New(&light)));
    TQ3ShaderObject lambert = own(Q3LambertIllumination_New());
    const TQ3AntiAliasStyleData style{kQ3On, kQ3AntiAliasModeMaskFilled, 1.0f};
    Pixmap image(kWidth, kHeight);
    {
        TestView view(image.pixmap(), kQ3RendererTypeInteractive);
        ASSERT_EQ(Q3View_SetLightGroup(view.view(), lights), kQ3Success);
        EXPECT_EQ(view.render([&](TQ3ViewObject v) {
            Q3Geometry_Submit(quad, v);
            Q3AntiAliasStyle_Submit(&style, v);
            Q3Shader_Submit(lambert, v);
            Q3Geometry_Submit(blue, v);
        }),
                  kQ3ViewStatusDone);
    }
    expectRow(image, 10, 0.0, 1.0, "drawn before the style"); // above the blue quad
    EXPECT_EQ(image.at(30, 30).r, 255);
    EXPECT_EQ(image.at(30, 30).b, 0);
    EXPECT_EQ(image.at(50, 30).r, 0);
    EXPECT_EQ(image.at(50, 30).b, 255);
    // The blue quad's right edge, at x = 3 (pixel 56 exactly), and its left
    // one, hidden: full pixels; its top edge is on a pixel boundary too.
    EXPECT_EQ(image.at(55, 30).b, 255);
    EXPECT_EQ(image.at(56, 30).b, 0);
}

} // namespace

TEST_F(AntiAliasRenderTest, OnlyWhatIsDrawnUnderTheStyleIsSmoothed)
{
    // Left of the red quad a blue triangle, right of it a green one, both
    // with slanted edges, and a yellow quad behind the red one (z -1)
    // reaching out below and right of it: the blue drawn before the style,
    // the red under it (filled mode), the yellow and green after a style
    // that turns it off. Only the red quad's side edges, columns 8 and 40,
    // may differ from the same frame drawn without any anti-aliasing
    // (the yellow quad's pixels on column 40 depend on the depth of one of
    // the pixel's samples); everything else is the very same bytes, and the
    // red quad still hides the yellow one drawn after it.
    TQ3GeometryObject quad = redQuad();
    const auto triangle = [&](TQ3Point3D a, TQ3Point3D b, TQ3Point3D c, float r, float g, float bl) {
        const TQ3TriangleData data{{{a, nullptr}, {b, nullptr}, {c, nullptr}}, own(colorSet(r, g, bl))};
        return own(Q3Triangle_New(&data));
    };
    TQ3GeometryObject blue = triangle({-0.45f, -0.9f, 0}, {-0.1f, 1.9f, 0}, {-0.45f, 1.9f, 0}, 0, 0, 1);
    TQ3GeometryObject green = triangle({2.6f, 0.6f, 0}, {3.4f, 0.6f, 0}, {3.4f, 1.9f, 0}, 0, 1, 0);
    TQ3Vertex3D behind[4] = {{{1.5f, -0.9f, -1.0f}, nullptr},
                             {{2.6f, -0.9f, -1.0f}, nullptr},
                             {{2.6f, 0.5f, -1.0f}, nullptr},
                             {{1.5f, 0.5f, -1.0f}, nullptr}};
    TQ3PolygonData data{4, behind, own(colorSet(1, 1, 0))};
    TQ3GeometryObject yellow = own(Q3Polygon_New(&data));
    const TQ3AntiAliasStyleData on{kQ3On, kQ3AntiAliasModeMaskFilled, 1.0f};
    const TQ3AntiAliasStyleData off{kQ3Off, kQ3AntiAliasModeMaskFilled, 1.0f};
    const auto draw = [&](bool smooth) {
        return render([&](TQ3ViewObject v) {
            Q3Geometry_Submit(blue, v);
            if (smooth)
                Q3AntiAliasStyle_Submit(&on, v);
            Q3Geometry_Submit(quad, v);
            if (smooth)
                Q3AntiAliasStyle_Submit(&off, v);
            Q3Geometry_Submit(yellow, v);
            Q3Geometry_Submit(green, v);
        });
    };
    const Pixmap aliased = draw(false);
    const Pixmap mixed = draw(true);
    // The red quad's edges smoothed: the shares of its samples.
    for (int row : {8, 20})
        expectRow(mixed, row, 0.25, 0.75, "the anti-aliased quad");
    expectRow(aliased, 20, 0.0, 1.0, "the same quad aliased");
    int differing = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const Rgba a = aliased.at(x, y), m = mixed.at(x, y);
            const bool same = a.r == m.r && a.g == m.g && a.b == m.b && a.a == m.a;
            if ((x == 8 || x == 40) && y >= 8 && y < 40)
                continue;
            differing += same ? 0 : 1;
            EXPECT_TRUE(same) << "pixel (" << x << ", " << y << ") differs from the aliased frame";
            if (differing > 5)
                FAIL() << "more differing pixels";
        }
    // The triangles are drawn (their slanted edges, aliased, are among the
    // pixels compared above).
    EXPECT_EQ(mixed.at(2, 2).b, 255);
    EXPECT_EQ(mixed.at(60, 12).g, 255);
    // The yellow quad: hidden by the red one, seen right of it.
    EXPECT_EQ(mixed.at(30, 36).r, 255);
    EXPECT_EQ(mixed.at(30, 36).g, 0);
    EXPECT_EQ(mixed.at(45, 36).r, 255);
    EXPECT_EQ(mixed.at(45, 36).g, 255);
    // The same pixels every time.
    EXPECT_EQ(mixed.bytes(), draw(true).bytes());
}

TEST_F(AntiAliasRenderTest, LinesAndTranslucentTrianglesKeepTheMarkTheyWereDrawnUnder)
{
    // A line under the edges mode, then, under a kQ3Off style, another line
    // and a half-transparent triangle (translucent triangles are drawn at
    // the end of the frame, after the style is long gone); then a
    // half-transparent quad under the filled mode. Only the first line and
    // the translucent quad's side edges are smoothed: every other pixel is
    // that of the frame drawn without the style.
    const auto lineOf = [&](TQ3Point3D a, TQ3Point3D b) {
        TQ3LineData data{{{a, nullptr}, {b, nullptr}}, own(colorSet(1, 1, 1))};
        return own(Q3Line_New(&data));
    };
    TQ3GeometryObject smoothLine = lineOf({-0.4f, 1.8f, 0}, {3.4f, 1.65f, 0});
    TQ3GeometryObject plainLine = lineOf({-0.4f, -0.6f, 0}, {3.4f, -0.85f, 0});
    TQ3AttributeSet half = own(colorSet(0, 0, 1));
    const TQ3ColorRGB halfT{0.5f, 0.5f, 0.5f};
    ASSERT_EQ(Q3AttributeSet_Add(half, kQ3AttributeTypeTransparencyColor, &halfT), kQ3Success);
    const TQ3TriangleData triangleData{{{{2.3f, -0.4f, 0}, nullptr}, {{3.4f, -0.4f, 0}, nullptr},
                                        {{3.4f, 1.4f, 0}, nullptr}},
                                       half};
    TQ3GeometryObject triangle = own(Q3Triangle_New(&triangleData));
    TQ3AttributeSet redHalf = own(colorSet(1, 0, 0));
    ASSERT_EQ(Q3AttributeSet_Add(redHalf, kQ3AttributeTypeTransparencyColor, &halfT), kQ3Success);
    TQ3Vertex3D corners[4] = {{{kLeft, kBottom, 0}, nullptr},
                              {{kRight, kBottom, 0}, nullptr},
                              {{kRight, kTop, 0}, nullptr},
                              {{kLeft, kTop, 0}, nullptr}};
    TQ3PolygonData quadData{4, corners, redHalf};
    TQ3GeometryObject quad = own(Q3Polygon_New(&quadData));
    const TQ3AntiAliasStyleData edges{kQ3On, kQ3AntiAliasModeMaskEdges, 1.0f};
    const TQ3AntiAliasStyleData filled{kQ3On, kQ3AntiAliasModeMaskFilled, 1.0f};
    const TQ3AntiAliasStyleData off{kQ3Off, kQ3AntiAliasModeMaskEdges, 1.0f};
    const auto draw = [&](bool smooth) {
        return render([&](TQ3ViewObject v) {
            if (smooth)
                Q3AntiAliasStyle_Submit(&edges, v);
            Q3Geometry_Submit(smoothLine, v);
            if (smooth)
                Q3AntiAliasStyle_Submit(&off, v);
            Q3Geometry_Submit(plainLine, v);
            Q3Geometry_Submit(triangle, v);
            if (smooth)
                Q3AntiAliasStyle_Submit(&filled, v);
            Q3Geometry_Submit(quad, v);
        });
    };
    const Pixmap aliased = draw(false);
    const Pixmap mixed = draw(true);
    // The first line (rows 2 to 6) has shades between white and black; the
    // second one none.
    int shadedFirst = 0, shadedSecond = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const Rgba p = mixed.at(x, y);
            const bool shaded = p.r == p.g && p.g == p.b && p.r > 0 && p.r < 255;
            (y < 8 ? shadedFirst : shadedSecond) += shaded ? 1 : 0;
        }
    EXPECT_GT(shadedFirst, 20);
    EXPECT_EQ(shadedSecond, 0);
    // The translucent quad's side columns: half red over black, by its
    // samples' shares (a quarter and three quarters).
    EXPECT_NEAR(mixed.at(8, 20).r, 0.25 * 127.5, 1.5);
    EXPECT_NEAR(mixed.at(40, 20).r, 0.75 * 127.5, 1.5);
    int differing = 0;
    for (int y = 8; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if ((x == 8 || x == 40) && y < 40)
                continue;
            const Rgba a = aliased.at(x, y), m = mixed.at(x, y);
            const bool same = a.r == m.r && a.g == m.g && a.b == m.b && a.a == m.a;
            differing += same ? 0 : 1;
            EXPECT_TRUE(same) << "pixel (" << x << ", " << y << ") differs from the aliased frame";
            if (differing > 5)
                FAIL() << "more differing pixels";
        }
    EXPECT_EQ(mixed.bytes(), draw(true).bytes());
}
