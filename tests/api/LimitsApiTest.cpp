// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Inputs at the limits: a curve of a million control points of the highest
// order, a world-space c1 a million times smaller than the curve, and a
// perspective camera inside the curve. Each must be created, drawn, bounded
// and decomposed to completion with output bounded by
// kQ3SubdivisionMaxSegmentsPerCurve (QD3DStyle.h), posting
// kQ3WarningParameterOutOfRange exactly where the subdivision gave in.
// These tests assert no times: speed belongs to the benchmarks.

#include "RenderTestSupport.h"

#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace {

using namespace q3test;

constexpr unsigned long kCap = kQ3SubdivisionMaxSegmentsPerCurve;

/// A clamped uniform curve: order, a knot vector 0 .. spans with end knots
/// repeated `order` times, and `count` control points from `at`.
struct BigCurve {
    std::vector<TQ3RationalPoint4D> points;
    std::vector<float> knots;
    unsigned long order;

    template <class At>
    BigCurve(unsigned long count, unsigned long curveOrder, At at) : order(curveOrder)
    {
        points.reserve(count);
        for (unsigned long i = 0; i < count; ++i)
            points.push_back(at(i));
        const unsigned long spans = count - order + 1;
        knots.reserve(count + order);
        for (unsigned long i = 0; i < count + order; ++i)
            knots.push_back(float(std::min(i < order ? 0 : i - order + 1, spans)));
    }

    TQ3NURBCurveData data() { return TQ3NURBCurveData{order, points.size(), points.data(), knots.data(), nullptr}; }
};

class LimitsApiTest : public Q3ApiTest {
protected:
    /// The number of vertices of the polyline `curve` decomposes into in the
    /// current state of `view` (0 on failure).
    unsigned long decomposedVertices(TQ3GeometryObject curve, TQ3ViewObject view, bool expectCapWarning)
    {
        TQ3GeometryObject polyLine = nullptr;
        if (expectCapWarning)
            EXPECT_Q3_WARNING(polyLine = Q3Geometry_GetDecomposed(curve, view), kQ3WarningParameterOutOfRange);
        else
            polyLine = Q3Geometry_GetDecomposed(curve, view);
        EXPECT_NE(polyLine, nullptr);
        if (polyLine == nullptr)
            return 0;
        TQ3PolyLineData data{};
        EXPECT_EQ(Q3PolyLine_GetData(polyLine, &data), kQ3Success);
        const unsigned long count = data.numVertices;
        bool finite = true;
        for (unsigned long i = 0; i < count; ++i)
            finite = finite && std::isfinite(data.vertices[i].point.x) && std::isfinite(data.vertices[i].point.y) &&
                     std::isfinite(data.vertices[i].point.z);
        EXPECT_TRUE(finite) << "the decomposed polyline has a vertex that is not finite";
        Q3PolyLine_EmptyData(&data);
        Q3Object_Dispose(polyLine);
        return count;
    }

    /// Draws `curve` (retained) and the same data in immediate mode, in one
    /// rendering loop of `view` under `style`.
    void render(TestView& view, TQ3GeometryObject curve, TQ3NURBCurveData& data,
                const TQ3SubdivisionStyleData& style, bool expectCapWarning)
    {
        ASSERT_EQ(Q3View_StartRendering(view.view()), kQ3Success);
        EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, view.view()), kQ3Success);
        if (expectCapWarning) {
            EXPECT_Q3_WARNING(EXPECT_EQ(Q3Geometry_Submit(curve, view.view()), kQ3Success),
                              kQ3WarningParameterOutOfRange);
            EXPECT_Q3_WARNING(EXPECT_EQ(Q3NURBCurve_Submit(&data, view.view()), kQ3Success),
                              kQ3WarningParameterOutOfRange);
        } else {
            EXPECT_EQ(Q3Geometry_Submit(curve, view.view()), kQ3Success);
            EXPECT_EQ(Q3NURBCurve_Submit(&data, view.view()), kQ3Success);
        }
        EXPECT_EQ(Q3View_EndRendering(view.view()), kQ3ViewStatusDone);
    }
};

/// How many pixels of an image are lit.
std::size_t litPixels(const Pixmap& image)
{
    std::size_t lit = 0;
    for (unsigned long y = 0; y < image.height(); ++y)
        for (unsigned long x = 0; x < image.width(); ++x)
            lit += image.lit(x, y) ? 1 : 0;
    return lit;
}

// 10^6 control points of order 16: 999,985 spans, just under the segment
// cap, so one constant segment per span fits and draws without a warning.
// The points follow 20,000 periods of a sine across the image, so the curve
// is about 1.8 million pixels long: screen-space subdivision to a pixel would
// need more segments than the cap allows and gives in.
TEST_F(LimitsApiTest, AMillionControlPointsOfOrderSixteenAreCreatedDrawnBoundedAndDecomposed)
{
    constexpr unsigned long kPoints = 1000000;
    BigCurve big(kPoints, 16, [](unsigned long i) {
        const float x = -1.0f + 2.0f * float(i) / float(kPoints - 1);
        const float y = 0.9f * float(std::sin(2.0 * 3.14159265358979 * double(i % 50) / 50.0));
        return TQ3RationalPoint4D{x, y, 0.0f, 1.0f};
    });
    float lowY = 0.0f, highY = 0.0f;
    for (const TQ3RationalPoint4D& p : big.points) {
        lowY = std::min(lowY, p.y);
        highY = std::max(highY, p.y);
    }
    TQ3NURBCurveData data = big.data();
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    ASSERT_NE(curve, nullptr);

    Pixmap image(64, 64);
    TQ3OrthographicCameraData cameraData = listing1OrthographicCamera();
    cameraData.cameraData.placement = {{0.0f, 0.0f, 10.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
    cameraData.left = -1.25f;
    cameraData.right = 1.25f;
    cameraData.top = 1.25f;
    cameraData.bottom = -1.25f;
    TQ3CameraObject camera = Q3OrthographicCamera_New(&cameraData);
    TestView view(image.pixmap(), kQ3RendererTypeInteractive, camera);
    Q3Object_Dispose(camera);

    const TQ3SubdivisionStyleData constant{kQ3SubdivisionMethodConstant, 1.0f, 1.0f};
    render(view, curve, data, constant, false);
    EXPECT_GT(litPixels(image), 64u * 32u) << "the zigzag should cover most of the image";
    ASSERT_EQ(Q3View_StartRendering(view.view()), kQ3Success);
    Q3SubdivisionStyle_Submit(&constant, view.view());
    const unsigned long constantVertices = decomposedVertices(curve, view.view(), false);
    EXPECT_EQ(Q3View_EndRendering(view.view()), kQ3ViewStatusDone);
    EXPECT_LE(constantVertices, kCap + 1);
    EXPECT_GE(constantVertices, kPoints - 15);

    const TQ3SubdivisionStyleData screen{kQ3SubdivisionMethodScreenSpace, 1.0f, 1.0f};
    render(view, curve, data, screen, true);
    ASSERT_EQ(Q3View_StartRendering(view.view()), kQ3Success);
    Q3SubdivisionStyle_Submit(&screen, view.view());
    const unsigned long screenVertices = decomposedVertices(curve, view.view(), true);
    EXPECT_EQ(Q3View_EndRendering(view.view()), kQ3ViewStatusDone);
    EXPECT_LE(screenVertices, kCap + 1);
    EXPECT_GE(screenVertices, 2u);

    // The box bounds the control points (the curve lies in their hull).
    TQ3BoundingBox box{};
    ASSERT_EQ(Q3View_StartBoundingBox(view.view(), kQ3ComputeBoundsExact), kQ3Success);
    EXPECT_EQ(Q3Geometry_Submit(curve, view.view()), kQ3Success);
    ASSERT_EQ(Q3View_EndBoundingBox(view.view(), &box), kQ3ViewStatusDone);
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_FLOAT_EQ(box.min.x, -1.0f);
    EXPECT_FLOAT_EQ(box.max.x, 1.0f);
    EXPECT_FLOAT_EQ(box.min.y, lowY);
    EXPECT_FLOAT_EQ(box.max.y, highY);
    TQ3BoundingSphere sphere{};
    ASSERT_EQ(Q3View_StartBoundingSphere(view.view(), kQ3ComputeBoundsApproximate), kQ3Success);
    EXPECT_EQ(Q3NURBCurve_Submit(&data, view.view()), kQ3Success);
    ASSERT_EQ(Q3View_EndBoundingSphere(view.view(), &sphere), kQ3ViewStatusDone);
    EXPECT_GE(sphere.radius, std::hypot(1.0f, highY));

    Q3Object_Dispose(curve);
}

// c1 a millionth of Listing 1's length: segments that short would take 1.03
// million of them (with Q3's padding), more than the view's cap leaves for
// placing them, so a longer length is used and the warning posted. The image is
// still the curve.
TEST_F(LimitsApiTest, AWorldSpaceC1AMillionTimesSmallerThanTheCurveIsCapped)
{
    double length = 0.0;
    for (int i = 1; i <= 100000; ++i) {
        const Point3 a = listing1At((i - 1) / 100000.0), b = listing1At(i / 100000.0);
        length += std::hypot(b.x - a.x, b.y - a.y);
    }
    Listing1 listing;
    TQ3NURBCurveData data = listing.data();
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    ASSERT_NE(curve, nullptr);
    Pixmap image(64, 64);
    TestView view(image.pixmap());

    const float c1 = float(length / 1e6);
    const TQ3SubdivisionStyleData tiny{kQ3SubdivisionMethodWorldSpace, c1, c1};
    render(view, curve, data, tiny, true);
    const CurveImageReport report = checkCurveImage(image, orthographicProjection(0, 0, 64, 64), 0, 0, 64, 64);
    EXPECT_EQ(report.strayPixels, 0u) << report.firstProblem;
    EXPECT_EQ(report.missedSamples, 0u) << report.firstProblem;
    ASSERT_EQ(Q3View_StartRendering(view.view()), kQ3Success);
    Q3SubdivisionStyle_Submit(&tiny, view.view());
    const unsigned long vertices = decomposedVertices(curve, view.view(), true);
    EXPECT_EQ(Q3View_EndRendering(view.view()), kQ3ViewStatusDone);
    // In a 64 x 64 view the cap is the view's (QD3DStyle.h,
    // kQ3SubdivisionViewSegmentsPerPixel), far below kCap.
    const unsigned long viewCap = kQ3SubdivisionViewSegmentsPerPixel * (64 + 64);
    EXPECT_LE(vertices, viewCap + 1);
    EXPECT_GE(vertices, viewCap / 2) << "capped, but it should still come close to the cap";

    // The smallest positive c1 of all: the same, not worse.
    const TQ3SubdivisionStyleData least{kQ3SubdivisionMethodWorldSpace, std::numeric_limits<float>::denorm_min(),
                                        1.0f};
    ASSERT_EQ(Q3View_StartRendering(view.view()), kQ3Success);
    Q3SubdivisionStyle_Submit(&least, view.view());
    EXPECT_LE(decomposedVertices(curve, view.view(), true), kCap + 1);
    EXPECT_EQ(Q3View_EndRendering(view.view()), kQ3ViewStatusDone);
    Q3Object_Dispose(curve);
}

// A helix of radius 2 around the eye of a perspective camera, running from
// 5 units behind it to 5 units in front of it: part of the curve has no image
// at all, and the part near the eye's plane projects to enormous pixel
// lengths. Screen-space subdivision to a pixel still fits under the view's
// cap (no warning); to an eighth of a pixel, the finest allowed, it does not,
// and gives in with the warning. A line through the eye itself (its midpoint, where the
// subdivision probes it, is the eye) is seen end on: one point, nothing to
// light, and no trouble.
TEST_F(LimitsApiTest, APerspectiveCameraInsideTheCurveDrawsAndDecomposesIt)
{
    BigCurve helix(400, 4, [](unsigned long i) {
        const float t = float(i) * 0.3f;
        return TQ3RationalPoint4D{2.0f * std::cos(t), 2.0f * std::sin(t), 5.0f - 0.025f * float(i), 1.0f};
    });
    TQ3NURBCurveData helixData = helix.data();
    TQ3GeometryObject helixCurve = Q3NURBCurve_New(&helixData);
    ASSERT_NE(helixCurve, nullptr);
    BigCurve through(2, 2, [](unsigned long i) {
        return i == 0 ? TQ3RationalPoint4D{-1.0f, 0.5f, 4.0f, 1.0f} : TQ3RationalPoint4D{1.0f, -0.5f, -4.0f, 1.0f};
    });
    TQ3NURBCurveData throughData = through.data();
    TQ3GeometryObject throughCurve = Q3NURBCurve_New(&throughData);
    ASSERT_NE(throughCurve, nullptr);

    TQ3ViewAngleAspectCameraData cameraData{};
    cameraData.cameraData.placement = {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, {0.0f, 1.0f, 0.0f}};
    cameraData.cameraData.range = {0.001f, 100.0f};
    cameraData.cameraData.viewPort = {{-1.0f, 1.0f}, 2.0f, 2.0f};
    cameraData.fov = 1.5f;
    cameraData.aspectRatioXToY = 1.0f;
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&cameraData);
    ASSERT_NE(camera, nullptr);
    Pixmap image(64, 64);
    TestView view(image.pixmap(), kQ3RendererTypeInteractive, camera);
    Q3Object_Dispose(camera);

    const TQ3SubdivisionStyleData pixel{kQ3SubdivisionMethodScreenSpace, 1.0f, 1.0f};
    render(view, helixCurve, helixData, pixel, false);
    EXPECT_GT(litPixels(image), 64u);
    render(view, throughCurve, throughData, pixel, false);
    EXPECT_EQ(litPixels(image), 0u) << "a line through the eye is seen as a point";

    // The finest screen-space c1 (a smaller one is replaced by it).
    const TQ3SubdivisionStyleData eighth{kQ3SubdivisionMethodScreenSpace, kQ3SubdivisionMinScreenSpaceC1,
                                         kQ3SubdivisionMinScreenSpaceC1};
    render(view, helixCurve, helixData, eighth, true);
    EXPECT_GT(litPixels(image), 64u);
    render(view, throughCurve, throughData, eighth, false);

    for (const TQ3SubdivisionStyleData& style : {pixel, eighth}) {
        ASSERT_EQ(Q3View_StartRendering(view.view()), kQ3Success);
        Q3SubdivisionStyle_Submit(&style, view.view());
        const unsigned long helixVertices = decomposedVertices(helixCurve, view.view(), style.c1 < 1.0f);
        EXPECT_GE(helixVertices, 2u);
        EXPECT_LE(helixVertices, kCap + 1);
        const unsigned long throughVertices = decomposedVertices(throughCurve, view.view(), false);
        EXPECT_GE(throughVertices, 2u);
        EXPECT_LE(throughVertices, kCap + 1);
        EXPECT_EQ(Q3View_EndRendering(view.view()), kQ3ViewStatusDone);
    }

    Q3Object_Dispose(helixCurve);
    Q3Object_Dispose(throughCurve);
}

} // namespace
