// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Triangles, polygons and trimeshes as the renderers draw them, checked
// pixel by pixel against geometry computed here: the interactive renderer
// fills exactly the inside (concave outlines too) and hides what is behind;
// the wireframe renderer draws only edges, in submit order; per-vertex
// colours are interpolated; the attribute inheritance order; TriMesh edge
// colours; and Q3Geometry_GetDecomposed for the three new types.

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"
#include "RenderTestSupport.h"

#include "QD3DSet.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace {

using namespace q3test;

constexpr unsigned long kWidth = 200, kHeight = 150;

// The scene of listing1OrthographicCamera in a 200 x 150 pixmap: 50 pixels
// per unit, world x -0.5..3.5 left to right and y 2..-1 top to bottom.
struct Pixel {
    double x, y;
};
Pixel pixelOf(double x, double y)
{
    const Point3 p = orthographicProjection(0, 0, kWidth, kHeight)({x, y, 0});
    return {p.x, p.y};
}
// The world point at the centre of pixel (px, py), inverting pixelOf.
Pixel worldAt(unsigned long px, unsigned long py)
{
    return {(px + 0.5) / 50.0 - 0.5, 2.0 - (py + 0.5) / 50.0};
}

struct Segment {
    double ax, ay, bx, by; // world coordinates (pixels once inspect() has converted them)
};

// The distance in pixels from p to a segment given in pixels.
double pixelDistance(const Pixel& p, const Segment& s)
{
    const Pixel a{s.ax, s.ay}, b{s.bx, s.by};
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    const double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
}

// The closed outline of a polygon as segments.
std::vector<Segment> outline(const std::vector<Pixel>& corners)
{
    std::vector<Segment> sides;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const Pixel& a = corners[i];
        const Pixel& b = corners[(i + 1) % corners.size()];
        sides.push_back({a.x, a.y, b.x, b.y});
    }
    return sides;
}

// Even-odd point in polygon (world coordinates), written independently of Q3.
bool insidePolygon(const std::vector<Pixel>& corners, double x, double y)
{
    bool inside = false;
    for (std::size_t i = 0, j = corners.size() - 1; i < corners.size(); j = i++) {
        const Pixel& a = corners[i];
        const Pixel& b = corners[j];
        if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside;
}

// What an image shows of a region: among pixels whose centre is more than
// `margin` pixels from every drawn segment, how many inside and outside the
// region are lit; and how many samples along the segments have no lit pixel
// around them.
struct RegionReport {
    std::size_t insideLit = 0, insideDark = 0, outsideLit = 0, outsideDark = 0, missedEdgeSamples = 0;
    std::string first;
};

RegionReport inspect(const Pixmap& image, const std::function<bool(double, double)>& inside,
                     const std::vector<Segment>& segments, double margin = 2.0)
{
    RegionReport report;
    std::vector<Segment> inPixels;
    for (const Segment& s : segments) {
        const Pixel a = pixelOf(s.ax, s.ay), b = pixelOf(s.bx, s.by);
        inPixels.push_back({a.x, a.y, b.x, b.y});
    }
    for (unsigned long py = 0; py < image.height(); ++py)
        for (unsigned long px = 0; px < image.width(); ++px) {
            const Pixel centre{px + 0.5, py + 0.5};
            double nearest = 1e9;
            for (const Segment& s : inPixels)
                nearest = std::min(nearest, pixelDistance(centre, s));
            if (nearest <= margin)
                continue;
            const Pixel world = worldAt(px, py);
            const bool in = inside(world.x, world.y);
            const bool lit = image.lit(px, py);
            (in ? (lit ? report.insideLit : report.insideDark) : (lit ? report.outsideLit : report.outsideDark))++;
            if (report.first.empty() && lit != in)
                report.first = "pixel (" + std::to_string(px) + ", " + std::to_string(py) + ") is " +
                               (lit ? "lit" : "dark") + " " + (in ? "inside" : "outside");
        }
    for (const Segment& s : segments) {
        const Pixel a = pixelOf(s.ax, s.ay), b = pixelOf(s.bx, s.by);
        const int samples = int(std::hypot(b.x - a.x, b.y - a.y)) * 2;
        for (int i = 2; i + 2 < samples; ++i) { // the ends may be clipped by a neighbour
            const double t = double(i) / samples;
            const int cx = int(a.x + t * (b.x - a.x)), cy = int(a.y + t * (b.y - a.y));
            bool found = false;
            for (int dy = -1; dy <= 1 && !found; ++dy)
                for (int dx = -1; dx <= 1 && !found; ++dx)
                    found = image.lit(unsigned(cx + dx), unsigned(cy + dy));
            report.missedEdgeSamples += found ? 0 : 1;
        }
    }
    return report;
}

class RenderSurfacesTest : public OwningApiTest {
protected:
    /// Renders `submit` with a renderer of that type into a fresh pixmap.
    static Pixmap render(TQ3ObjectType renderer, const std::function<void(TQ3ViewObject)>& submit)
    {
        Pixmap image(kWidth, kHeight);
        TestView view(image.pixmap(), renderer);
        EXPECT_EQ(view.render(submit), kQ3ViewStatusDone);
        return image;
    }

    static Rgba colorAt(const Pixmap& image, double x, double y)
    {
        const Pixel p = pixelOf(x, y);
        return image.at(unsigned(p.x), unsigned(p.y));
    }

    static void expectColor(const Rgba& c, int r, int g, int b, int tolerance, const std::string& what)
    {
        EXPECT_NEAR(c.r, r, tolerance) << what;
        EXPECT_NEAR(c.g, g, tolerance) << what;
        EXPECT_NEAR(c.b, b, tolerance) << what;
    }

    TQ3AttributeSet color(float r, float g, float b) { return own(colorSet(r, g, b)); }

    // A large triangle, a concave L and a 5-pointed star, in world x/y.
    const std::vector<Pixel> m_triangle{{0.1, -0.6}, {3.2, -0.3}, {1.4, 1.8}};
    const std::vector<Pixel> m_ell{{0, -0.7}, {3, -0.7}, {3, 0.2}, {1, 0.2}, {1, 1.8}, {0, 1.8}};
};

std::vector<Pixel> star(double cx, double cy, double outer, double inner)
{
    std::vector<Pixel> corners;
    for (int i = 0; i < 10; ++i) {
        const double angle = M_PI / 2 + i * M_PI / 5;
        const double r = i % 2 == 0 ? outer : inner;
        corners.push_back({cx + r * std::cos(angle), cy + r * std::sin(angle)});
    }
    return corners;
}

std::vector<TQ3Vertex3D> verticesOf(const std::vector<Pixel>& corners, float z = 0)
{
    std::vector<TQ3Vertex3D> vertices;
    for (const Pixel& c : corners)
        vertices.push_back({{float(c.x), float(c.y), z}, nullptr});
    return vertices;
}

// ---- Filled or outlined -------------------------------------------------------------

TEST_F(RenderSurfacesTest, TheInteractiveRendererFillsATriangleAndTheWireframeRendererDrawsItsSides)
{
    const std::vector<TQ3Vertex3D> v = verticesOf(m_triangle);
    const TQ3TriangleData data{{v[0], v[1], v[2]}, nullptr};
    TQ3GeometryObject triangle = own(Q3Triangle_New(&data));
    auto inside = [&](double x, double y) { return insidePolygon(m_triangle, x, y); };
    for (bool retained : {false, true}) {
        SCOPED_TRACE(retained ? "retained" : "immediate");
        auto submit = [&](TQ3ViewObject view) {
            EXPECT_EQ(retained ? Q3Geometry_Submit(triangle, view) : Q3Triangle_Submit(&data, view), kQ3Success);
        };
        const RegionReport filled = inspect(render(kQ3RendererTypeInteractive, submit), inside, outline(m_triangle));
        EXPECT_GT(filled.insideLit, 3000u);
        EXPECT_EQ(filled.insideDark, 0u) << filled.first;
        EXPECT_EQ(filled.outsideLit, 0u) << filled.first;
        const RegionReport wire = inspect(render(kQ3RendererTypeWireFrame, submit), inside, outline(m_triangle));
        EXPECT_EQ(wire.insideLit, 0u) << wire.first;
        EXPECT_EQ(wire.outsideLit, 0u);
        EXPECT_EQ(wire.missedEdgeSamples, 0u);
    }
}

TEST_F(RenderSurfacesTest, AConcavePolygonFillsExactlyItsInsideAndItsWireframeIsItsOutline)
{
    for (const std::vector<Pixel>& corners : {m_ell, star(1.5, 0.5, 1.4, 0.55)}) {
        std::vector<TQ3Vertex3D> v = verticesOf(corners);
        const TQ3PolygonData data{(unsigned long)v.size(), v.data(), nullptr};
        auto inside = [&](double x, double y) { return insidePolygon(corners, x, y); };
        auto submit = [&](TQ3ViewObject view) { EXPECT_EQ(Q3Polygon_Submit(&data, view), kQ3Success); };
        const Pixmap filledImage = render(kQ3RendererTypeInteractive, submit);
        const RegionReport filled = inspect(filledImage, inside, outline(corners));
        SCOPED_TRACE(corners.size() == 6 ? "L" : "star");
        EXPECT_GT(filled.insideLit, 1500u);
        EXPECT_EQ(filled.insideDark, 0u) << filled.first;
        EXPECT_EQ(filled.outsideLit, 0u) << filled.first;
        const RegionReport wire = inspect(render(kQ3RendererTypeWireFrame, submit), inside, outline(corners));
        EXPECT_EQ(wire.insideLit, 0u) << wire.first; // no triangulation diagonals
        EXPECT_EQ(wire.outsideLit, 0u);
        EXPECT_EQ(wire.missedEdgeSamples, 0u);
    }
    // The notch of the L, sampled directly: clear.
    std::vector<TQ3Vertex3D> v = verticesOf(m_ell);
    const TQ3PolygonData data{(unsigned long)v.size(), v.data(), nullptr};
    const Pixmap image =
        render(kQ3RendererTypeInteractive, [&](TQ3ViewObject view) { Q3Polygon_Submit(&data, view); });
    for (const Pixel& notch : std::vector<Pixel>{{2, 1}, {2.8, 1.6}, {1.2, 0.4}, {2.5, 0.5}})
        EXPECT_FALSE(image.lit(unsigned(pixelOf(notch.x, notch.y).x), unsigned(pixelOf(notch.x, notch.y).y)))
            << notch.x << ", " << notch.y;
    EXPECT_TRUE(image.lit(unsigned(pixelOf(0.5, 1.5).x), unsigned(pixelOf(0.5, 1.5).y)));
}

TEST_F(RenderSurfacesTest, AClockwisePolygonOutOfTheXYPlaneIsFilledToo)
{
    // The L reversed (clockwise) and tilted: z = 0.3 x - 0.2 y. The
    // orthographic camera looks down z, so the image is the same region.
    std::vector<Pixel> corners(m_ell.rbegin(), m_ell.rend());
    std::vector<TQ3Vertex3D> v = verticesOf(corners);
    for (TQ3Vertex3D& vertex : v)
        vertex.point.z = 0.3f * vertex.point.x - 0.2f * vertex.point.y;
    const TQ3PolygonData data{(unsigned long)v.size(), v.data(), nullptr};
    const RegionReport filled =
        inspect(render(kQ3RendererTypeInteractive, [&](TQ3ViewObject view) { Q3Polygon_Submit(&data, view); }),
                [&](double x, double y) { return insidePolygon(corners, x, y); }, outline(corners));
    EXPECT_GT(filled.insideLit, 1500u);
    EXPECT_EQ(filled.insideDark, 0u) << filled.first;
    EXPECT_EQ(filled.outsideLit, 0u) << filled.first;
}

TEST_F(RenderSurfacesTest, ATriMeshIsFilledOrDrawnAsEveryTriangleSide)
{
    // An L of four triangles over six points; the wireframe shows the inner
    // diagonals too (every side of every triangle).
    std::vector<TQ3Point3D> points;
    for (const Pixel& c : m_ell)
        points.push_back({float(c.x), float(c.y), 0});
    // Corners 0..5 of the L: (0,-0.7) (3,-0.7) (3,0.2) (1,0.2) (1,1.8) (0,1.8).
    std::vector<TQ3TriMeshTriangleData> triangles{{{0, 1, 2}}, {{0, 2, 3}}, {{0, 3, 4}}, {{0, 4, 5}}};
    TQ3TriMeshData data{};
    data.numTriangles = triangles.size();
    data.triangles = triangles.data();
    data.numPoints = points.size();
    data.points = points.data();
    std::vector<Segment> sides;
    for (const TQ3TriMeshTriangleData& t : triangles)
        for (int k = 0; k < 3; ++k) {
            const TQ3Point3D& a = points[t.pointIndices[k]];
            const TQ3Point3D& b = points[t.pointIndices[(k + 1) % 3]];
            sides.push_back({a.x, a.y, b.x, b.y});
        }
    auto inside = [&](double x, double y) { return insidePolygon(m_ell, x, y); };
    TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
    for (bool retained : {false, true}) {
        SCOPED_TRACE(retained ? "retained" : "immediate");
        auto submit = [&](TQ3ViewObject view) {
            EXPECT_EQ(retained ? Q3Geometry_Submit(triMesh, view) : Q3TriMesh_Submit(&data, view), kQ3Success);
        };
        const RegionReport filled = inspect(render(kQ3RendererTypeInteractive, submit), inside, sides);
        EXPECT_GT(filled.insideLit, 1500u);
        EXPECT_EQ(filled.insideDark, 0u) << filled.first;
        EXPECT_EQ(filled.outsideLit, 0u) << filled.first;
        const RegionReport wire = inspect(render(kQ3RendererTypeWireFrame, submit), inside, sides);
        EXPECT_EQ(wire.insideLit, 0u) << wire.first;
        EXPECT_EQ(wire.outsideLit, 0u);
        EXPECT_EQ(wire.missedEdgeSamples, 0u);
    }
}

// A renderer keeps a retained mesh's vertex data from frame to frame
// (render/OffscreenRenderer.cpp, StaticKey); an edit of the geometry's
// points, or of the attribute set that colours it, after frames that kept it
// is drawn at once.
TEST_F(RenderSurfacesTest, ARetainedTriMeshEditedAfterFramesThatKeptItIsDrawnAsEdited)
{
    std::vector<TQ3Point3D> points;
    for (const Pixel& c : m_triangle)
        points.push_back({float(c.x), float(c.y), 0});
    TQ3TriMeshTriangleData triangle{{0, 1, 2}};
    TQ3AttributeSet red = color(1, 0, 0);
    TQ3TriMeshData data{};
    data.numTriangles = 1;
    data.triangles = &triangle;
    data.numPoints = points.size();
    data.points = points.data();
    data.triMeshAttributeSet = red;
    TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
    Pixmap image(kWidth, kHeight);
    TestView view(image.pixmap());
    // Frames of the mesh, checked against the triangle `corners` in `r g b`.
    const auto frames = [&](const std::vector<Pixel>& corners, int r, int g, int b, const std::string& what) {
        SCOPED_TRACE(what);
        for (int f = 0; f < 3; ++f) {
            ASSERT_EQ(view.render([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(triMesh, v), kQ3Success); }),
                      kQ3ViewStatusDone);
            const RegionReport report = inspect(
                image, [&](double x, double y) { return insidePolygon(corners, x, y); }, outline(corners));
            EXPECT_GT(report.insideLit, 1500u) << "frame " << f;
            EXPECT_EQ(report.insideDark, 0u) << "frame " << f << ": " << report.first;
            EXPECT_EQ(report.outsideLit, 0u) << "frame " << f << ": " << report.first;
            double cx = 0, cy = 0;
            for (const Pixel& c : corners) {
                cx += c.x / 3;
                cy += c.y / 3;
            }
            expectColor(colorAt(image, cx, cy), r, g, b, 1, "frame " + std::to_string(f));
        }
    };
    frames(m_triangle, 255, 0, 0, "as made");
    // The points moved down and left by a fifth of a unit.
    std::vector<Pixel> moved;
    for (TQ3Point3D& p : points) {
        p.x -= 0.2f;
        p.y -= 0.2f;
        moved.push_back({p.x, p.y});
    }
    ASSERT_EQ(Q3TriMesh_SetData(triMesh, &data), kQ3Success);
    frames(moved, 255, 0, 0, "moved");
    // The set the geometry holds made green.
    TQ3AttributeSet held = nullptr;
    ASSERT_EQ(Q3Geometry_GetAttributeSet(triMesh, &held), kQ3Success);
    ASSERT_NE(held, nullptr);
    const TQ3ColorRGB green{0, 1, 0};
    ASSERT_EQ(Q3AttributeSet_Add(held, kQ3AttributeTypeDiffuseColor, &green), kQ3Success);
    Q3Object_Dispose(held);
    frames(moved, 0, 255, 0, "green");
}

// ---- Depth ----------------------------------------------------------------------------

TEST_F(RenderSurfacesTest, TheNearerTriangleHidesTheFartherOneWhateverTheOrderButWireframeFollowsTheOrder)
{
    // The camera looks down -z from z = 10: z = 1 is nearer than z = -1.
    // The near red triangle has a horizontal side along the pixel row at
    // y = -0.01, the far green one a vertical side along the pixel column
    // at x = 1.51; they cross at pixel (100, 100).
    TQ3AttributeSet red = color(1, 0, 0), green = color(0, 1, 0);
    const TQ3TriangleData nearRed{{{{0.2f, -0.01f, 1}, nullptr}, {{3.2f, -0.01f, 1}, nullptr}, {{1.7f, 1.8f, 1}, nullptr}},
                                  red};
    const TQ3TriangleData farGreen{
        {{{1.51f, -0.9f, -1}, nullptr}, {{1.51f, 1.6f, -1}, nullptr}, {{-0.3f, 0.4f, -1}, nullptr}}, green};
    ASSERT_NEAR(pixelOf(1.51, -0.01).x, 100.5, 1e-9);
    ASSERT_NEAR(pixelOf(1.51, -0.01).y, 100.5, 1e-9);
    for (bool nearFirst : {true, false}) {
        SCOPED_TRACE(nearFirst ? "near first" : "far first");
        auto submit = [&](TQ3ViewObject view) {
            Q3Triangle_Submit(nearFirst ? &nearRed : &farGreen, view);
            Q3Triangle_Submit(nearFirst ? &farGreen : &nearRed, view);
        };
        const Pixmap filled = render(kQ3RendererTypeInteractive, submit);
        // Inside both (left of x = 1.51, above y = -0.01, inside each triangle).
        for (const Pixel& both : std::vector<Pixel>{{1.2, 0.3}, {1.4, 0.8}, {0.9, 0.35}})
            expectColor(colorAt(filled, both.x, both.y), 255, 0, 0, 0, "overlap");
        expectColor(colorAt(filled, 0.3, -0.5), 0, 0, 0, 0, "neither"); // below the red one, left of the green one
        expectColor(colorAt(filled, 1.3, -0.5), 0, 255, 0, 0, "green only");
        expectColor(colorAt(filled, 2.5, 0.3), 255, 0, 0, 0, "red only");

        const Pixmap wire = render(kQ3RendererTypeWireFrame, submit);
        const Rgba crossing = wire.at(100, 100);
        if (nearFirst)
            expectColor(crossing, 0, 255, 0, 0, "the later, farther side is drawn over");
        else
            expectColor(crossing, 255, 0, 0, 0, "the later side is drawn over");
        expectColor(colorAt(wire, 1.2, 0.3), 0, 0, 0, 0, "wireframe interior");
    }
}

// ---- Colours ------------------------------------------------------------------------

TEST_F(RenderSurfacesTest, VertexColorsAreInterpolatedAcrossATriangle)
{
    TQ3AttributeSet red = color(1, 0, 0), green = color(0, 1, 0), blue = color(0, 0, 1);
    const std::vector<TQ3Vertex3D> v = verticesOf(m_triangle);
    const TQ3TriangleData data{{{v[0].point, red}, {v[1].point, green}, {v[2].point, blue}}, nullptr};
    const Pixmap image = render(kQ3RendererTypeInteractive, [&](TQ3ViewObject view) { Q3Triangle_Submit(&data, view); });
    // Barycentric coordinates of a world point, written out here.
    const Pixel a = m_triangle[0], b = m_triangle[1], c = m_triangle[2];
    auto weights = [&](double x, double y) {
        const double d = (b.y - c.y) * (a.x - c.x) + (c.x - b.x) * (a.y - c.y);
        const double wa = ((b.y - c.y) * (x - c.x) + (c.x - b.x) * (y - c.y)) / d;
        const double wb = ((c.y - a.y) * (x - c.x) + (a.x - c.x) * (y - c.y)) / d;
        return std::array<double, 3>{wa, wb, 1 - wa - wb};
    };
    // The centroid's pixel: near the average colour.
    const Pixel centroid{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
    const Pixel cp = pixelOf(centroid.x, centroid.y);
    const Rgba middle = image.at(unsigned(cp.x), unsigned(cp.y));
    expectColor(middle, 85, 85, 85, 5, "centroid");
    // Every pixel well inside: the interpolation at its centre, within 3 of 255.
    std::size_t checked = 0;
    for (unsigned long py = 0; py < kHeight; ++py)
        for (unsigned long px = 0; px < kWidth; ++px) {
            const Pixel w = worldAt(px, py);
            const std::array<double, 3> bary = weights(w.x, w.y);
            if (std::min({bary[0], bary[1], bary[2]}) < 0.05)
                continue;
            const Rgba got = image.at(px, py);
            ASSERT_NEAR(got.r, 255 * bary[0], 3) << px << ", " << py;
            ASSERT_NEAR(got.g, 255 * bary[1], 3) << px << ", " << py;
            ASSERT_NEAR(got.b, 255 * bary[2], 3) << px << ", " << py;
            ++checked;
        }
    EXPECT_GT(checked, 2000u);
}

TEST_F(RenderSurfacesTest, VertexColorsAreInterpolatedAlongALineAndAPolyLine)
{
    TQ3AttributeSet red = color(1, 0, 0), green = color(0, 1, 0), blue = color(0, 0, 1);
    // Along pixel rows (y at pixel centres), so each column has one pixel.
    const float lineY = 2.0f - 20.5f / 50, polyY = 2.0f - 120.5f / 50;
    const TQ3LineData line{{{{0, lineY, 0}, red}, {{3, lineY, 0}, blue}}, nullptr};
    TQ3Vertex3D vertices[3] = {{{0, polyY, 0}, red}, {{1.5f, polyY, 0}, green}, {{3, polyY, 0}, blue}};
    const TQ3PolyLineData polyLine{3, vertices, nullptr, nullptr};
    for (TQ3ObjectType renderer : {kQ3RendererTypeWireFrame, kQ3RendererTypeInteractive}) {
        const Pixmap image = render(renderer, [&](TQ3ViewObject view) {
            Q3Line_Submit(&line, view);
            Q3PolyLine_Submit(&polyLine, view);
        });
        // The line's midpoint: half red, half blue; a quarter of the way: 3/4 red.
        expectColor(colorAt(image, 1.5 + 0.01, lineY), 128, 0, 128, 6, "line middle");
        expectColor(colorAt(image, 0.75 + 0.01, lineY), 191, 0, 64, 6, "line quarter");
        // The polyline's segments: red to green, then green to blue.
        expectColor(colorAt(image, 0.75 + 0.01, polyY), 128, 128, 0, 6, "first segment middle");
        expectColor(colorAt(image, 2.25 + 0.01, polyY), 0, 128, 128, 6, "second segment middle");
    }
}

TEST_F(RenderSurfacesTest, VertexBeatsFaceBeatsGeometryBeatsStateColorInATriMesh)
{
    // Four separate triangles side by side, each over its own three points:
    //   0: its points have vertex colours (red), its triangle colour is green;
    //   1: no vertex colour, triangle colour green;
    //   2: no vertex colour, no triangle colour: the triMeshAttributeSet's blue;
    //   3: the same, in a second trimesh without a set: the state's yellow.
    std::vector<TQ3Point3D> points;
    std::vector<TQ3TriMeshTriangleData> triangles;
    for (int t = 0; t < 3; ++t) {
        const float x = -0.3f + 1.1f * float(t);
        const unsigned long first = points.size();
        points.insert(points.end(), {{x, -0.8f, 0}, {x + 0.9f, -0.8f, 0}, {x + 0.45f, 0.5f, 0}});
        triangles.push_back({{first, first + 1, first + 2}});
    }
    std::vector<TQ3ColorRGB> pointColors(points.size(), TQ3ColorRGB{1, 0, 0});
    std::vector<char> pointUse{1, 1, 1, 0, 0, 0, 0, 0, 0};
    std::vector<TQ3ColorRGB> triangleColors(3, TQ3ColorRGB{0, 1, 0});
    std::vector<char> triangleUse{1, 1, 0};
    TQ3TriMeshAttributeData vertexAttributes[1] = {
        {kQ3AttributeTypeDiffuseColor, pointColors.data(), pointUse.data()}};
    TQ3TriMeshAttributeData triangleAttributes[1] = {
        {kQ3AttributeTypeDiffuseColor, triangleColors.data(), triangleUse.data()}};
    // A blue set, the triangles with one attribute array, no edges, the
    // points with one.
    TQ3TriMeshData data{color(0, 0, 1), static_cast<unsigned long>(triangles.size()), triangles.data(), 1,
                        triangleAttributes, 0, nullptr, 0, nullptr, static_cast<unsigned long>(points.size()),
                        points.data(), 1, vertexAttributes, TQ3BoundingBox{}};

    std::vector<TQ3Point3D> lonePoints{{0.5f, 0.8f, 0}, {1.5f, 0.8f, 0}, {1.0f, 1.8f, 0}};
    TQ3TriMeshTriangleData lone[1] = {{{0, 1, 2}}};
    const TQ3TriMeshData bare{nullptr, 1, lone, 0, nullptr, 0, nullptr, 0, nullptr, 3, lonePoints.data(), 0, nullptr,
                              TQ3BoundingBox{}};
    TQ3AttributeSet yellow = color(1, 1, 0);
    TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
    for (bool retained : {false, true}) {
        SCOPED_TRACE(retained ? "retained" : "immediate");
        const Pixmap image = render(kQ3RendererTypeInteractive, [&](TQ3ViewObject view) {
            EXPECT_EQ(Q3AttributeSet_Submit(yellow, view), kQ3Success);
            EXPECT_EQ(retained ? Q3Geometry_Submit(triMesh, view) : Q3TriMesh_Submit(&data, view), kQ3Success);
            EXPECT_EQ(Q3TriMesh_Submit(&bare, view), kQ3Success);
        });
        auto centreOf = [&](const TQ3Point3D* p) {
            return colorAt(image, (p[0].x + p[1].x + p[2].x) / 3, (p[0].y + p[1].y + p[2].y) / 3);
        };
        expectColor(centreOf(&points[0]), 255, 0, 0, 0, "vertex colour");
        expectColor(centreOf(&points[3]), 0, 255, 0, 0, "triangle colour");
        expectColor(centreOf(&points[6]), 0, 0, 255, 0, "trimesh set colour");
        expectColor(centreOf(lonePoints.data()), 255, 255, 0, 0, "state colour");
    }
}

TEST_F(RenderSurfacesTest, VertexBeatsFaceBeatsStateColorInATriangleAndAPolygon)
{
    TQ3AttributeSet red = color(1, 0, 0), green = color(0, 1, 0), yellow = color(1, 1, 0);
    // Left: a triangle whose vertices are red and whose own set is green.
    // Middle: the same without vertex colours. Right: a polygon with neither.
    const TQ3TriangleData withVertexColors{
        {{{-0.3f, -0.8f, 0}, red}, {{0.7f, -0.8f, 0}, red}, {{0.2f, 0.8f, 0}, red}}, green};
    const TQ3TriangleData withFaceColor{
        {{{0.8f, -0.8f, 0}, nullptr}, {{1.8f, -0.8f, 0}, nullptr}, {{1.3f, 0.8f, 0}, nullptr}}, green};
    TQ3Vertex3D square[4] = {{{2.0f, -0.8f, 0}, nullptr}, {{3.3f, -0.8f, 0}, nullptr}, {{3.3f, 0.8f, 0}, nullptr},
                             {{2.0f, 0.8f, 0}, nullptr}};
    const TQ3PolygonData plain{4, square, nullptr};
    TQ3Vertex3D colored[4] = {{{2.0f, 1.0f, 0}, red}, {{3.3f, 1.0f, 0}, red}, {{3.3f, 1.9f, 0}, red},
                              {{2.0f, 1.9f, 0}, red}};
    const TQ3PolygonData vertexColored{4, colored, green};
    const Pixmap image = render(kQ3RendererTypeInteractive, [&](TQ3ViewObject view) {
        Q3AttributeSet_Submit(yellow, view);
        Q3Triangle_Submit(&withVertexColors, view);
        Q3Triangle_Submit(&withFaceColor, view);
        Q3Polygon_Submit(&plain, view);
        Q3Polygon_Submit(&vertexColored, view);
    });
    expectColor(colorAt(image, 0.2, -0.3), 255, 0, 0, 0, "triangle vertex colours");
    expectColor(colorAt(image, 1.3, -0.3), 0, 255, 0, 0, "triangle colour");
    expectColor(colorAt(image, 2.6, 0.0), 255, 255, 0, 0, "state colour");
    expectColor(colorAt(image, 2.6, 1.5), 255, 0, 0, 0, "polygon vertex colours");
}

TEST_F(RenderSurfacesTest, ARetainedSurfaceIsRedrawnAfterItsVertexSetsOrItsDataChange)
{
    // The retained triangle and polygon cache their decomposition; editing a
    // vertex's attribute set, replacing it, or moving a vertex must show.
    TQ3AttributeSet set = color(1, 0, 0);
    TQ3AttributeSet other = color(0, 0, 1);
    const TQ3TriangleData triangleData{
        {{{-0.3f, -0.8f, 0}, set}, {{1.2f, -0.8f, 0}, set}, {{0.45f, 1.5f, 0}, set}}, nullptr};
    TQ3Vertex3D square[4] = {{{1.8f, -0.8f, 0}, set}, {{3.3f, -0.8f, 0}, set}, {{3.3f, 1.5f, 0}, set},
                             {{1.8f, 1.5f, 0}, set}};
    const TQ3PolygonData polygonData{4, square, nullptr};
    TQ3GeometryObject triangle = own(Q3Triangle_New(&triangleData));
    TQ3GeometryObject polygon = own(Q3Polygon_New(&polygonData));
    auto draw = [&] {
        return render(kQ3RendererTypeInteractive, [&](TQ3ViewObject view) {
            EXPECT_EQ(Q3Geometry_Submit(triangle, view), kQ3Success);
            EXPECT_EQ(Q3Geometry_Submit(polygon, view), kQ3Success);
        });
    };
    Pixmap image = draw();
    expectColor(colorAt(image, 0.45, 0), 255, 0, 0, 0, "triangle, red");
    expectColor(colorAt(image, 2.5, 0), 255, 0, 0, 0, "polygon, red");

    const TQ3ColorRGB green{0, 1, 0};
    ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &green), kQ3Success);
    image = draw();
    expectColor(colorAt(image, 0.45, 0), 0, 255, 0, 0, "triangle, the set edited");
    expectColor(colorAt(image, 2.5, 0), 0, 255, 0, 0, "polygon, the set edited");

    for (unsigned long i = 0; i < 3; ++i)
        ASSERT_EQ(Q3Triangle_SetVertexAttributeSet(triangle, i, other), kQ3Success);
    for (unsigned long i = 0; i < 4; ++i)
        ASSERT_EQ(Q3Polygon_SetVertexAttributeSet(polygon, i, other), kQ3Success);
    image = draw();
    expectColor(colorAt(image, 0.45, 0), 0, 0, 255, 0, "triangle, the sets replaced");
    expectColor(colorAt(image, 2.5, 0), 0, 0, 255, 0, "polygon, the sets replaced");

    const TQ3Point3D away{0.45f, 1.9f, 0};
    ASSERT_EQ(Q3Triangle_SetVertexPosition(triangle, 0, &away), kQ3Success);
    image = draw();
    expectColor(colorAt(image, 0.0, -0.7), 0, 0, 0, 0, "the moved corner's old place");
}

TEST_F(RenderSurfacesTest, TriMeshEdgeColorsShowInTheWireframe)
{
    // One triangle; its three sides listed as edges, the first two coloured
    // (red, then blue) and the third switched off by the use array.
    std::vector<TQ3Point3D> points{{0, -0.7f, 0}, {3, -0.7f, 0}, {1.5f, 1.7f, 0}};
    TQ3TriMeshTriangleData triangles[1] = {{{0, 1, 2}}};
    TQ3TriMeshEdgeData edges[3] = {{{0, 1}, {0, (unsigned long)kQ3ArrayIndexNULL}},
                                   {{1, 2}, {0, (unsigned long)kQ3ArrayIndexNULL}},
                                   {{2, 0}, {0, (unsigned long)kQ3ArrayIndexNULL}}};
    TQ3ColorRGB edgeColors[3] = {{1, 0, 0}, {0, 0, 1}, {1, 0, 1}};
    char edgeUse[3] = {1, 1, 0};
    TQ3TriMeshAttributeData edgeAttributes[1] = {{kQ3AttributeTypeDiffuseColor, edgeColors, edgeUse}};
    const TQ3TriMeshData data{nullptr, 1, triangles, 0, nullptr, 3, edges, 1, edgeAttributes, 3, points.data(), 0,
                              nullptr, TQ3BoundingBox{}};
    TQ3AttributeSet green = color(0, 1, 0);
    auto submit = [&](TQ3ViewObject view) {
        Q3AttributeSet_Submit(green, view);
        EXPECT_EQ(Q3TriMesh_Submit(&data, view), kQ3Success);
    };
    const Pixmap wire = render(kQ3RendererTypeWireFrame, submit);
    auto colorNear = [&](double x, double y) {
        const Pixel p = pixelOf(x, y);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if (wire.lit(unsigned(p.x) + dx, unsigned(p.y) + dy))
                    return wire.at(unsigned(p.x) + dx, unsigned(p.y) + dy);
        return Rgba{};
    };
    expectColor(colorNear(1.5, -0.7), 255, 0, 0, 0, "edge 0");
    expectColor(colorNear(2.25, 0.5), 0, 0, 255, 0, "edge 1");
    expectColor(colorNear(0.75, 0.5), 0, 255, 0, 0, "edge 2 has no colour in use: the state's");
    // The interactive renderer fills: the state colour inside, no edges.
    const Pixmap filled = render(kQ3RendererTypeInteractive, submit);
    expectColor(colorAt(filled, 1.5, 0.2), 0, 255, 0, 0, "fill");
    expectColor(colorAt(filled, 1.5, -0.6), 0, 255, 0, 0, "fill near edge 0");
}

// ---- Q3Geometry_GetDecomposed ---------------------------------------------------------

class DecomposeSurfacesTest : public OwningApiTest {
protected:
    /// Q3Geometry_GetDecomposed inside a bounding loop.
    TQ3GeometryObject decomposed(TQ3GeometryObject geometry)
    {
        TQ3GeometryObject result = nullptr;
        boundsOf([&](TQ3ViewObject v) {
            if (result == nullptr)
                result = Q3Geometry_GetDecomposed(geometry, v);
        });
        return result;
    }
};

struct Vec {
    double x, y, z;
};
Vec operator-(const Vec& a, const Vec& b)
{
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Vec cross(const Vec& a, const Vec& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(const Vec& a, const Vec& b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
Vec vec(const TQ3Point3D& p)
{
    return {p.x, p.y, p.z};
}

TEST_F(DecomposeSurfacesTest, TrianglesAndTriMeshesAreNotDecomposed)
{
    const TQ3TriangleData triangleData{{{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{0, 1, 0}, nullptr}}, nullptr};
    TQ3Point3D points[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    TQ3TriMeshTriangleData triangles[1] = {{{0, 1, 2}}};
    const TQ3TriMeshData triMeshData{nullptr, 1, triangles, 0, nullptr, 0, nullptr, 0, nullptr, 3, points, 0, nullptr,
                                     TQ3BoundingBox{}};
    for (TQ3GeometryObject geometry : {own(Q3Triangle_New(&triangleData)), own(Q3TriMesh_New(&triMeshData))}) {
        ASSERT_NE(geometry, nullptr);
        EXPECT_EQ(decomposed(geometry), nullptr);
        EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNone);
    }
}

TEST_F(DecomposeSurfacesTest, APolygonDecomposesIntoATriMeshCoveringItExactly)
{
    // A concave polygon (the star) in a tilted plane, with some vertex colours.
    const std::vector<Pixel> corners = star(0, 0, 2.0, 0.8);
    // A rotation about x by 40 degrees and about z by 25 degrees, then a shift.
    const double ax = 40 * M_PI / 180, az = 25 * M_PI / 180;
    std::vector<TQ3Vertex3D> vertices;
    for (const Pixel& c : corners) {
        const double y1 = c.y * std::cos(ax), z1 = c.y * std::sin(ax);
        const double x2 = c.x * std::cos(az) - y1 * std::sin(az), y2 = c.x * std::sin(az) + y1 * std::cos(az);
        vertices.push_back({{float(x2 + 1), float(y2 - 2), float(z1 + 3)}, nullptr});
    }
    const std::size_t n = vertices.size();
    // The polygon's area and normal (Newell, independently of Q3).
    Vec newell{0, 0, 0};
    for (std::size_t i = 0; i < n; ++i) {
        const Vec c = cross(vec(vertices[i].point), vec(vertices[(i + 1) % n].point));
        newell = {newell.x + c.x, newell.y + c.y, newell.z + c.z};
    }
    const double area = std::sqrt(dot(newell, newell)) / 2;

    TQ3AttributeSet red = own(colorSet(1, 0, 0));
    TQ3AttributeSet polygonSet = own(colorSet(0, 0, 1));
    for (int colors = 0; colors < 3; ++colors) { // none, some, all vertices coloured
        SCOPED_TRACE("colour case " + std::to_string(colors));
        for (std::size_t i = 0; i < n; ++i)
            vertices[i].attributeSet = colors == 2 || (colors == 1 && i % 3 == 0) ? red : nullptr;
        const TQ3PolygonData data{(unsigned long)n, vertices.data(), polygonSet};
        TQ3GeometryObject polygon = own(Q3Polygon_New(&data));
        TQ3GeometryObject result = decomposed(polygon);
        ASSERT_NE(result, nullptr);
        own(result);
        EXPECT_EQ(Q3Geometry_GetType(result), kQ3GeometryTypeTriMesh);
        TQ3TriMeshData mesh{};
        ASSERT_EQ(Q3TriMesh_GetData(result, &mesh), kQ3Success);
        EXPECT_EQ(mesh.triMeshAttributeSet, polygonSet);

        // Every triangle's corners are polygon vertices; its winding follows
        // the polygon's; its centroid (mapped back to the star's own plane
        // through the vertices) is inside the star.
        double sum = 0;
        EXPECT_EQ(mesh.numTriangles, n - 2);
        for (unsigned long t = 0; t < mesh.numTriangles; ++t) {
            Vec corner[3];
            Pixel flat{0, 0};
            for (int k = 0; k < 3; ++k) {
                const unsigned long p = mesh.triangles[t].pointIndices[k];
                ASSERT_LT(p, mesh.numPoints);
                corner[k] = vec(mesh.points[p]);
                std::size_t vertex = n;
                for (std::size_t i = 0; i < n; ++i)
                    if (samePoint(vertices[i].point, mesh.points[p]))
                        vertex = i;
                ASSERT_LT(vertex, n) << "triangle " << t << " corner " << k << " is not a polygon vertex";
                flat = {flat.x + corners[vertex].x / 3, flat.y + corners[vertex].y / 3};
            }
            EXPECT_TRUE(insidePolygon(corners, flat.x, flat.y)) << "triangle " << t;
            const Vec normal = cross(corner[1] - corner[0], corner[2] - corner[0]);
            EXPECT_GT(dot(normal, newell), 0.0) << "triangle " << t << " is wound against the polygon";
            sum += std::sqrt(dot(normal, normal)) / 2;
        }
        EXPECT_NEAR(sum, area, 1e-5 * area);

        // Colours: an array exactly when some vertex had one; a use array
        // exactly when not all did.
        const TQ3TriMeshAttributeData* colorEntry = nullptr;
        for (unsigned long i = 0; i < mesh.numVertexAttributeTypes; ++i)
            if (mesh.vertexAttributeTypes[i].attributeType == kQ3AttributeTypeDiffuseColor)
                colorEntry = &mesh.vertexAttributeTypes[i];
        if (colors == 0) {
            EXPECT_EQ(colorEntry, nullptr);
        } else {
            ASSERT_NE(colorEntry, nullptr);
            EXPECT_EQ(colorEntry->attributeUseArray != nullptr, colors == 1);
            for (unsigned long p = 0; p < mesh.numPoints; ++p) {
                std::size_t vertex = n;
                for (std::size_t i = 0; i < n; ++i)
                    if (samePoint(vertices[i].point, mesh.points[p]))
                        vertex = i;
                ASSERT_LT(vertex, n);
                const bool has = vertices[vertex].attributeSet != nullptr;
                if (colorEntry->attributeUseArray != nullptr)
                    EXPECT_EQ(colorEntry->attributeUseArray[p] != 0, has) << "point " << p;
                if (has) {
                    const TQ3ColorRGB c = static_cast<const TQ3ColorRGB*>(colorEntry->data)[p];
                    EXPECT_EQ(c.r, 1.0f);
                    EXPECT_EQ(c.g, 0.0f);
                }
            }
        }
        Q3TriMesh_EmptyData(&mesh);
    }
}

TEST_F(DecomposeSurfacesTest, ADegeneratePolygonDecomposesIntoNoTriangles)
{
    // Collinear vertices enclose no area: a TriMesh without triangles.
    TQ3Vertex3D vertices[4] = {{{0, 0, 0}, nullptr}, {{1, 1, 1}, nullptr}, {{2, 2, 2}, nullptr}, {{3, 3, 3}, nullptr}};
    const TQ3PolygonData data{4, vertices, nullptr};
    TQ3GeometryObject polygon = own(Q3Polygon_New(&data));
    TQ3GeometryObject result = decomposed(polygon);
    ASSERT_NE(result, nullptr);
    own(result);
    TQ3TriMeshData mesh{};
    ASSERT_EQ(Q3TriMesh_GetData(result, &mesh), kQ3Success);
    EXPECT_EQ(mesh.numTriangles, 0u);
    Q3TriMesh_EmptyData(&mesh);
}

} // namespace
