// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The article's Listing 1 curve rendered through the public API and checked
// against the cubic Bezier formula (RenderTestSupport.h): every lit pixel
// within 1.5 pixels of the curve and the curve's whole length lit. The
// tolerance: a 1-pixel aliased line lights pixels whose centres lie within
// about 0.71 px of it (half a pixel diagonal), and the default screen-space
// subdivision (segments of at most 20 px) strays from this curve by at most
// about 0.5 px (chord sagitta L^2 / 8R with the curve's smallest radius of
// curvature, about 106 px here), so 1.5 px leaves a margin without letting a
// misplaced curve pass.

#include "RenderTestSupport.h"

#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"
#include "q3png.h"

#include <cmath>
#include <string>

namespace {

using namespace q3test;
using RenderCurveTest = Q3ApiTest;

constexpr unsigned long kWidth = 200;
constexpr unsigned long kHeight = 150;

// Writes the image next to the test's other output, for a failure message.
std::string saveImage(const Pixmap& image, const std::string& name)
{
    const std::string path = ::testing::TempDir() + "q3_" + name + ".png";
    const std::vector<unsigned char> rgba = image.rgba();
    q3png_write_rgba8(path.c_str(), rgba.data(), int(image.width()), int(image.height()),
                      int(image.width() * 4));
    return path;
}

void expectCurve(const Pixmap& image, const Projection& project, int x0, int y0, int x1, int y1,
                 const std::string& name)
{
    const CurveImageReport report = checkCurveImage(image, project, x0, y0, x1, y1);
    EXPECT_GT(report.litPixels, 100u) << name;
    EXPECT_EQ(report.strayPixels, 0u) << name << ": " << report.firstProblem;
    EXPECT_EQ(report.missedSamples, 0u) << name << ": " << report.firstProblem;
    if (report.strayPixels != 0 || report.missedSamples != 0 || report.litPixels <= 100)
        ADD_FAILURE() << "image saved to " << saveImage(image, name);
}

void submitRetained(TQ3ViewObject view, TQ3GeometryObject curve)
{
    EXPECT_EQ(Q3Geometry_Submit(curve, view), kQ3Success);
}

TEST_F(RenderCurveTest, RetainedListing1IsDrawnAlongTheCurve)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    Pixmap image(kWidth, kHeight);
    {
        TestView view(image.pixmap());
        EXPECT_EQ(view.render([&](TQ3ViewObject v) { submitRetained(v, curve); }), kQ3ViewStatusDone);
    }
    expectCurve(image, orthographicProjection(0, 0, kWidth, kHeight), 0, 0, kWidth, kHeight, "retained");
    Q3Object_Dispose(curve);
}

TEST_F(RenderCurveTest, ImmediateModeDrawsTheSameImageAsRetainedMode)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    Pixmap retained(kWidth, kHeight), immediate(kWidth, kHeight);
    {
        TestView view(retained.pixmap());
        EXPECT_EQ(view.render([&](TQ3ViewObject v) { submitRetained(v, curve); }), kQ3ViewStatusDone);
    }
    {
        TestView view(immediate.pixmap());
        EXPECT_EQ(view.render([&](TQ3ViewObject v) { EXPECT_EQ(Q3NURBCurve_Submit(&data, v), kQ3Success); }),
                  kQ3ViewStatusDone);
    }
    expectCurve(immediate, orthographicProjection(0, 0, kWidth, kHeight), 0, 0, kWidth, kHeight,
                "immediate");
    EXPECT_EQ(retained.bytes(), immediate.bytes());
    Q3Object_Dispose(curve);
}

TEST_F(RenderCurveTest, EveryPixelTypeAndByteOrderShowsTheCurve)
{
    const TQ3PixelType types[] = {kQ3PixelTypeRGB32,  kQ3PixelTypeARGB32,    kQ3PixelTypeRGB16,
                                  kQ3PixelTypeARGB16, kQ3PixelTypeRGB16_565, kQ3PixelTypeRGB24};
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    for (TQ3PixelType type : types)
        for (TQ3Endian order : {kQ3EndianBig, kQ3EndianLittle}) {
            const std::string name =
                std::string(nameOf(type)) + (order == kQ3EndianBig ? "_big" : "_little");
            SCOPED_TRACE(name);
            // Rows padded by 3 bytes: rowBytes is not a multiple of the pixel size.
            Pixmap image(kWidth, kHeight, type, order, 3);
            {
                TestView view(image.pixmap());
                EXPECT_EQ(view.render([&](TQ3ViewObject v) { Q3NURBCurve_Submit(&data, v); }),
                          kQ3ViewStatusDone);
            }
            expectCurve(image, orthographicProjection(0, 0, kWidth, kHeight), 0, 0, kWidth, kHeight, name);
            // The clear reached every pixel: black, opaque where there is alpha.
            const Rgba corner = image.at(0, 0);
            EXPECT_EQ(corner.r + corner.g + corner.b, 0);
            EXPECT_EQ(corner.a, 255);
            // The padding at the row ends is the caller's and stays untouched.
            const unsigned long rowBytes = image.pixmap().rowBytes;
            for (unsigned long y = 0; y < kHeight; ++y)
                for (unsigned long i = rowBytes - 3; i < rowBytes; ++i)
                    ASSERT_EQ(image.bytes()[y * rowBytes + i], Pixmap::kSentinel) << "row " << y;
        }
}

TEST_F(RenderCurveTest, LitPixelsAreWhiteWithOpaqueAlphaInEveryFormat)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    for (TQ3PixelType type : {kQ3PixelTypeARGB32, kQ3PixelTypeARGB16, kQ3PixelTypeRGB16_565}) {
        SCOPED_TRACE(nameOf(type));
        Pixmap image(kWidth, kHeight, type, kQ3EndianLittle);
        {
            TestView view(image.pixmap());
            view.render([&](TQ3ViewObject v) { Q3NURBCurve_Submit(&data, v); });
        }
        // The curve's first point, (0, 0), is at pixel (25, 100).
        bool foundWhite = false;
        for (int y = 98; y <= 101; ++y)
            for (int x = 24; x <= 27; ++x) {
                const Rgba c = image.at(x, y);
                foundWhite = foundWhite || (c.r == 255 && c.g == 255 && c.b == 255 && c.a == 255);
            }
        EXPECT_TRUE(foundWhite);
    }
}

TEST_F(RenderCurveTest, WireFrameRendererDrawsTheCurve)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    Pixmap wireFrame(kWidth, kHeight), interactive(kWidth, kHeight);
    {
        TestView view(wireFrame.pixmap(), kQ3RendererTypeWireFrame);
        EXPECT_EQ(view.render([&](TQ3ViewObject v) { Q3NURBCurve_Submit(&data, v); }), kQ3ViewStatusDone);
    }
    {
        TestView view(interactive.pixmap(), kQ3RendererTypeInteractive);
        EXPECT_EQ(view.render([&](TQ3ViewObject v) { Q3NURBCurve_Submit(&data, v); }), kQ3ViewStatusDone);
    }
    expectCurve(wireFrame, orthographicProjection(0, 0, kWidth, kHeight), 0, 0, kWidth, kHeight,
                "wireframe");
    EXPECT_EQ(wireFrame.bytes(), interactive.bytes());
}

// A view angle aspect camera looking down at the curve from in front and
// above, so perspective foreshortens it; the expected positions come from a
// look-at frame and pinhole projection written out in RenderTestSupport.h.
TEST_F(RenderCurveTest, PerspectiveCameraDrawsTheProjectedCurve)
{
    const Point3 eye = {1.5, -1.5, 1.8}, target = {1.5, 0.5, 0.0}, up = {0, 0, 1};
    const double fov = 1.0, aspect = double(kWidth) / kHeight;
    const TQ3ViewAngleAspectCameraData cameraData = viewAngleCamera(eye, target, up, fov, aspect);
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&cameraData);
    ASSERT_NE(camera, nullptr);
    const Projection project = perspectiveProjection(eye, target, up, fov, aspect, kWidth, kHeight);

    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    Pixmap image(kWidth, kHeight);
    {
        TestView view(image.pixmap(), kQ3RendererTypeInteractive, camera);
        EXPECT_EQ(view.render([&](TQ3ViewObject v) { Q3NURBCurve_Submit(&data, v); }), kQ3ViewStatusDone);
    }
    expectCurve(image, project, 0, 0, kWidth, kHeight, "perspective");
    Q3Object_Dispose(camera);
}

TEST_F(RenderCurveTest, PaneConfinesDrawingAndClearingAndTakesTheViewPort)
{
    // A 4:3 pane keeps the camera's aspect, so the curve is the whole-pixmap
    // drawing scaled by 0.8 and moved to the pane.
    const int paneX = 20, paneY = 15, paneW = 160, paneH = 120;
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    Pixmap image(kWidth, kHeight);
    {
        TestView view(image.pixmap());
        const TQ3Area pane = {{float(paneX), float(paneY)}, {float(paneX + paneW), float(paneY + paneH)}};
        ASSERT_EQ(Q3DrawContext_SetPane(view.context(), &pane), kQ3Success);
        ASSERT_EQ(Q3DrawContext_SetPaneState(view.context(), kQ3True), kQ3Success);
        EXPECT_EQ(view.render([&](TQ3ViewObject v) { Q3NURBCurve_Submit(&data, v); }), kQ3ViewStatusDone);
    }
    expectCurve(image, orthographicProjection(paneX, paneY, paneW, paneH), paneX, paneY, paneX + paneW,
                paneY + paneH, "pane");
    // Outside the pane nothing was written; inside, the clear reached.
    const unsigned long rowBytes = image.pixmap().rowBytes;
    for (unsigned long y = 0; y < kHeight; ++y)
        for (unsigned long x = 0; x < kWidth; ++x) {
            const bool inside = int(x) >= paneX && int(x) < paneX + paneW && int(y) >= paneY &&
                                int(y) < paneY + paneH;
            const unsigned char* p = image.bytes().data() + y * rowBytes + 4 * x;
            if (!inside)
                ASSERT_TRUE(p[0] == Pixmap::kSentinel && p[1] == Pixmap::kSentinel &&
                            p[2] == Pixmap::kSentinel && p[3] == Pixmap::kSentinel)
                    << "pixel (" << x << ", " << y << ") outside the pane was written";
            else
                ASSERT_EQ(image.at(x, y).a, 255) << "pixel (" << x << ", " << y << ") was not cleared";
        }
}

TEST_F(RenderCurveTest, ClearMethodNoneKeepsEveryPixelTheCurveDoesNotCover)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    Pixmap image(kWidth, kHeight);
    {
        TestView view(image.pixmap());
        ASSERT_EQ(Q3DrawContext_SetClearImageMethod(view.context(), kQ3ClearMethodNone), kQ3Success);
        EXPECT_EQ(view.render([&](TQ3ViewObject v) { Q3NURBCurve_Submit(&data, v); }), kQ3ViewStatusDone);
    }
    std::size_t kept = 0, drawn = 0;
    for (unsigned long y = 0; y < kHeight; ++y)
        for (unsigned long x = 0; x < kWidth; ++x) {
            if (image.word(x, y) == 0x5A5A5A5Au) {
                ++kept;
            } else {
                ++drawn;
                EXPECT_EQ(image.word(x, y), 0xFFFFFFFFu) << x << ", " << y;
            }
        }
    EXPECT_GT(drawn, 100u);
    EXPECT_EQ(kept + drawn, kWidth * kHeight);
}

TEST_F(RenderCurveTest, ConstantSubdivisionDrawsTheCurveToo)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, 32, 32};
    Pixmap image(kWidth, kHeight);
    {
        TestView view(image.pixmap());
        view.render([&](TQ3ViewObject v) {
            EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, v), kQ3Success);
            EXPECT_EQ(Q3NURBCurve_Submit(&data, v), kQ3Success);
        });
    }
    expectCurve(image, orthographicProjection(0, 0, kWidth, kHeight), 0, 0, kWidth, kHeight, "constant");
}

TEST_F(RenderCurveTest, TransformsMoveTheCurve)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    const TQ3Vector3D offset = {0.25f, -0.5f, 0.0f};
    Pixmap image(kWidth, kHeight);
    {
        TestView view(image.pixmap());
        view.render([&](TQ3ViewObject v) {
            EXPECT_EQ(Q3TranslateTransform_Submit(&offset, v), kQ3Success);
            EXPECT_EQ(Q3NURBCurve_Submit(&data, v), kQ3Success);
        });
    }
    const Projection plain = orthographicProjection(0, 0, kWidth, kHeight);
    expectCurve(image,
                [&](const Point3& p) { return plain(Point3{p.x + 0.25, p.y - 0.5, p.z}); }, 0, 0, kWidth,
                kHeight, "translated");
}

// ---- Colour -----------------------------------------------------------------

class RenderColorTest : public Q3ApiTest {
protected:
    // The colour of the lit pixels; fails unless they all share one.
    Rgba renderedColor(const std::function<void(TQ3ViewObject)>& submit)
    {
        Pixmap image(kWidth, kHeight);
        {
            TestView view(image.pixmap());
            EXPECT_EQ(view.render(submit), kQ3ViewStatusDone);
        }
        Rgba color{};
        std::size_t lit = 0;
        for (unsigned long y = 0; y < kHeight; ++y)
            for (unsigned long x = 0; x < kWidth; ++x) {
                if (!image.lit(x, y))
                    continue;
                const Rgba c = image.at(x, y);
                if (lit++ == 0)
                    color = c;
                EXPECT_TRUE(c.r == color.r && c.g == color.g && c.b == color.b) << x << ", " << y;
            }
        EXPECT_GT(lit, 100u);
        return color;
    }

    // The colour of Listing 1's curve (carrying curveSet) drawn after
    // submitting the attribute state.
    Rgba curveColorAfter(const std::function<void(TQ3ViewObject)>& state, TQ3AttributeSet curveSet = nullptr)
    {
        Listing1 listing;
        const TQ3NURBCurveData data = listing.data(curveSet);
        return renderedColor([&](TQ3ViewObject v) {
            state(v);
            Q3NURBCurve_Submit(&data, v);
        });
    }

    // Every channel exactly: 255 where the colour is on, 0 where it is off.
    static void expectColor(const Rgba& c, int r, int g, int b, const char* what = "")
    {
        EXPECT_EQ(c.r, r) << what;
        EXPECT_EQ(c.g, g) << what;
        EXPECT_EQ(c.b, b) << what;
    }

    TQ3AttributeSet colorSet(float r, float g, float b)
    {
        TQ3AttributeSet set = Q3AttributeSet_New();
        const TQ3ColorRGB color = {r, g, b};
        EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color), kQ3Success);
        return set;
    }
};

TEST_F(RenderColorTest, DefaultDiffuseColorIsWhite)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    const Rgba c = renderedColor([&](TQ3ViewObject v) { Q3NURBCurve_Submit(&data, v); });
    expectColor(c, 255, 255, 255);
}

TEST_F(RenderColorTest, CurveAttributeSetColorsTheCurve)
{
    TQ3AttributeSet red = colorSet(1, 0, 0);
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data(red);
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    const Rgba retained = renderedColor([&](TQ3ViewObject v) { Q3Geometry_Submit(curve, v); });
    expectColor(retained, 255, 0, 0, "retained");
    const Rgba immediate = renderedColor([&](TQ3ViewObject v) { Q3NURBCurve_Submit(&data, v); });
    expectColor(immediate, 255, 0, 0, "immediate");
    Q3Object_Dispose(curve);
    Q3Object_Dispose(red);
}

TEST_F(RenderColorTest, SubmittedAttributeStateColorsACurveWithoutItsOwn)
{
    TQ3AttributeSet green = colorSet(0, 1, 0);
    expectColor(curveColorAfter([&](TQ3ViewObject v) { EXPECT_EQ(Q3AttributeSet_Submit(green, v), kQ3Success); }),
                0, 255, 0);
    Q3Object_Dispose(green);
}

TEST_F(RenderColorTest, CurveOwnColorWinsOverTheAttributeState)
{
    TQ3AttributeSet green = colorSet(0, 1, 0);
    TQ3AttributeSet blue = colorSet(0, 0, 1);
    expectColor(curveColorAfter([&](TQ3ViewObject v) { Q3AttributeSet_Submit(green, v); }, blue), 0, 0, 255);
    Q3Object_Dispose(green);
    Q3Object_Dispose(blue);
}

TEST_F(RenderColorTest, PopRestoresTheAttributeStateOfThePush)
{
    TQ3AttributeSet green = colorSet(0, 1, 0);
    const Rgba c = curveColorAfter([&](TQ3ViewObject v) {
        EXPECT_EQ(Q3Push_Submit(v), kQ3Success);
        Q3AttributeSet_Submit(green, v);
        EXPECT_EQ(Q3Pop_Submit(v), kQ3Success);
    });
    expectColor(c, 255, 255, 255);
    Q3Object_Dispose(green);
}

TEST_F(RenderColorTest, AnAttributeSetWithoutDiffuseColorLeavesTheStateAlone)
{
    TQ3AttributeSet green = colorSet(0, 1, 0);
    TQ3AttributeSet other = Q3AttributeSet_New();
    const float ambient = 0.5f;
    Q3AttributeSet_Add(other, kQ3AttributeTypeAmbientCoefficient, &ambient);
    const Rgba c = curveColorAfter([&](TQ3ViewObject v) {
        Q3AttributeSet_Submit(green, v);
        Q3AttributeSet_Submit(other, v);
    });
    expectColor(c, 0, 255, 0);
    Q3Object_Dispose(green);
    Q3Object_Dispose(other);
}

} // namespace
