// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The other geometries the view draws and bounds: polylines, lines and
// points, with their colours; and two views drawing one retained curve on
// two threads at once.

#include "RenderTestSupport.h"

#include "QD3DSet.h"

#include <thread>

namespace {

using namespace q3test;

class RenderPrimitivesTest : public Q3ApiTest {
protected:
    // Pixels of the 200 x 150 orthographic scene (RenderTestSupport.h).
    static Point3 pixelOf(double x, double y) { return orthographicProjection(0, 0, 200, 150)({x, y, 0}); }

    static bool litNear(const Pixmap& image, const Point3& p)
    {
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if (image.lit(unsigned(p.x) + dx, unsigned(p.y) + dy))
                    return true;
        return false;
    }

    static std::size_t litCount(const Pixmap& image)
    {
        std::size_t n = 0;
        for (unsigned long y = 0; y < image.height(); ++y)
            for (unsigned long x = 0; x < image.width(); ++x)
                n += image.lit(x, y) ? 1 : 0;
        return n;
    }

    TQ3AttributeSet colorSet(float r, float g, float b)
    {
        TQ3AttributeSet set = Q3AttributeSet_New();
        const TQ3ColorRGB color = {r, g, b};
        Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color);
        return set;
    }
};

TEST_F(RenderPrimitivesTest, PolylineLineAndPointAreDrawnWhereTheyAre)
{
    TQ3Vertex3D vertices[3] = {{{0, 0, 0}, nullptr}, {{1, 1, 0}, nullptr}, {{2, 0, 0}, nullptr}};
    const TQ3PolyLineData polyLine = {3, vertices, nullptr, nullptr};
    const TQ3LineData line = {{{{3, -0.5f, 0}, nullptr}, {{3, 1.5f, 0}, nullptr}}, nullptr};
    const TQ3PointData point = {{-0.25f, 1.49f, 0}, nullptr}; // at a pixel centre
    Pixmap image(200, 150);
    {
        TestView view(image.pixmap(), kQ3RendererTypeWireFrame);
        EXPECT_EQ(view.render([&](TQ3ViewObject v) {
                      EXPECT_EQ(Q3PolyLine_Submit(&polyLine, v), kQ3Success);
                      EXPECT_EQ(Q3Line_Submit(&line, v), kQ3Success);
                      EXPECT_EQ(Q3Point_Submit(&point, v), kQ3Success);
                  }),
                  kQ3ViewStatusDone);
    }
    EXPECT_TRUE(litNear(image, pixelOf(0.5, 0.5)));  // first polyline segment
    EXPECT_TRUE(litNear(image, pixelOf(1.5, 0.5)));  // second one
    EXPECT_FALSE(litNear(image, pixelOf(1.0, 0.2))); // not between them
    EXPECT_TRUE(litNear(image, pixelOf(3.0, 0.0)));  // the line
    EXPECT_TRUE(litNear(image, pixelOf(3.0, 1.2)));
    const Point3 p = pixelOf(-0.25, 1.49);
    EXPECT_TRUE(image.lit(unsigned(p.x), unsigned(p.y))); // the point
    EXPECT_LT(litCount(image), 400u);
}

TEST_F(RenderPrimitivesTest, SegmentColorsWinOverThePolylineColor)
{
    TQ3AttributeSet red = colorSet(1, 0, 0);
    TQ3AttributeSet green = colorSet(0, 1, 0);
    TQ3Vertex3D vertices[3] = {{{0, 0, 0}, nullptr}, {{1, 1, 0}, nullptr}, {{2, 0, 0}, nullptr}};
    TQ3AttributeSet segments[2] = {green, nullptr};
    const TQ3PolyLineData polyLine = {3, vertices, segments, red};
    TQ3GeometryObject object = Q3PolyLine_New(&polyLine);
    Pixmap image(200, 150);
    {
        TestView view(image.pixmap());
        view.render([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(object, v), kQ3Success); });
    }
    auto colorNear = [&](const Point3& p) { return image.litNear(unsigned(p.x), unsigned(p.y)); };
    const Rgba first = colorNear(pixelOf(0.5, 0.5));
    const Rgba second = colorNear(pixelOf(1.5, 0.5));
    EXPECT_EQ(first.g, 255);
    EXPECT_EQ(first.r, 0);
    EXPECT_EQ(second.r, 255);
    EXPECT_EQ(second.g, 0);
    Q3Object_Dispose(object);
    Q3Object_Dispose(red);
    Q3Object_Dispose(green);
}

TEST_F(RenderPrimitivesTest, LinesAndPointsTakeTheirOwnOrTheStateColor)
{
    TQ3AttributeSet blue = colorSet(0, 0, 1);
    TQ3AttributeSet green = colorSet(0, 1, 0);
    const TQ3LineData line = {{{{1, -0.5f, 0}, nullptr}, {{1, 1.5f, 0}, nullptr}}, blue};
    const TQ3PointData point = {{2.01f, 0.49f, 0}, nullptr}; // at a pixel centre
    Pixmap image(200, 150);
    {
        TestView view(image.pixmap());
        view.render([&](TQ3ViewObject v) {
            Q3AttributeSet_Submit(green, v);
            Q3Line_Submit(&line, v);
            Q3Point_Submit(&point, v);
        });
    }
    const Point3 onLine = pixelOf(1, 0.5);
    bool blueFound = false;
    for (int dx = -1; dx <= 1; ++dx) {
        const Rgba c = image.at(unsigned(onLine.x) + dx, unsigned(onLine.y));
        blueFound = blueFound || (c.b == 255 && c.r == 0 && c.g == 0);
    }
    EXPECT_TRUE(blueFound);
    const Point3 p = pixelOf(2.01, 0.49);
    const Rgba c = image.at(unsigned(p.x), unsigned(p.y));
    EXPECT_EQ(c.g, 255);
    EXPECT_EQ(c.r + c.b, 0);
    Q3Object_Dispose(blue);
    Q3Object_Dispose(green);
}

TEST_F(RenderPrimitivesTest, PolylinesLinesAndPointsAreBoundedByTheirVertices)
{
    TQ3Vertex3D vertices[3] = {{{0, 0, 0}, nullptr}, {{1, 5, 0}, nullptr}, {{2, 0, -1}, nullptr}};
    const TQ3PolyLineData polyLine = {3, vertices, nullptr, nullptr};
    const TQ3LineData line = {{{{-3, 0, 0}, nullptr}, {{0, 0, 0}, nullptr}}, nullptr};
    const TQ3PointData point = {{0, 0, 4}, nullptr};
    TQ3ViewObject view = Q3View_New();
    ASSERT_EQ(Q3View_StartBoundingBox(view, kQ3ComputeBoundsExact), kQ3Success);
    Q3PolyLine_Submit(&polyLine, view);
    Q3Line_Submit(&line, view);
    Q3Point_Submit(&point, view);
    TQ3BoundingBox box{};
    ASSERT_EQ(Q3View_EndBoundingBox(view, &box), kQ3ViewStatusDone);
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_EQ(box.min.x, -3.0f);
    EXPECT_EQ(box.min.z, -1.0f);
    EXPECT_EQ(box.max.y, 5.0f);
    EXPECT_EQ(box.max.z, 4.0f);
    // A lone point is a bound of zero size, not an empty one.
    ASSERT_EQ(Q3View_StartBoundingSphere(view, kQ3ComputeBoundsApproximate), kQ3Success);
    Q3Point_Submit(&point, view);
    TQ3BoundingSphere sphere{};
    ASSERT_EQ(Q3View_EndBoundingSphere(view, &sphere), kQ3ViewStatusDone);
    EXPECT_EQ(sphere.isEmpty, kQ3False);
    EXPECT_EQ(sphere.origin.z, 4.0f);
    EXPECT_EQ(sphere.radius, 0.0f);
    Q3Object_Dispose(view);
}

TEST_F(RenderPrimitivesTest, TwoThreadsDrawOneRetainedCurveAtOnce)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    Pixmap reference(200, 150);
    {
        TestView view(reference.pixmap());
        view.render([&](TQ3ViewObject v) { Q3Geometry_Submit(curve, v); });
    }
    Pixmap images[2] = {Pixmap(200, 150), Pixmap(200, 150)};
    std::thread threads[2];
    for (int t = 0; t < 2; ++t)
        threads[t] = std::thread([&, t] {
            TestView view(images[t].pixmap());
            for (int frame = 0; frame < 10; ++frame) {
                // Alternate styles so that the shared cache is rebuilt under contention.
                const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodScreenSpace, frame % 2 ? 20.0f : 3.0f,
                                                       20.0f};
                view.render([&](TQ3ViewObject v) {
                    Q3SubdivisionStyle_Submit(&style, v);
                    Q3Geometry_Submit(curve, v);
                });
            }
        });
    for (std::thread& thread : threads)
        thread.join();
    // The last frame of each used the default c1 of 20: the reference image.
    EXPECT_EQ(images[0].bytes(), reference.bytes());
    EXPECT_EQ(images[1].bytes(), reference.bytes());
    Q3Object_Dispose(curve);
}

} // namespace
