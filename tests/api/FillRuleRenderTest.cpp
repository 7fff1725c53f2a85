// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The even-odd rule of the QD3D Book's "General Polygons" ("contours may
// overlap or be disjoint ... the even-odd rule is used to determine which
// parts are inside the polygon") for contours that cross: each pixel of a
// drawn general polygon, polygon or mesh face against a crossing count
// computed here at the pixel's centre (pixels within a tenth of a pixel of a
// side are skipped: there rasterization, not the rule, decides).

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"
#include "RenderTestSupport.h"

#include "QD3DGeometry.h"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace {

using namespace q3test;

// 64 x 48 pixels under listing1OrthographicCamera: world x -0.5..3.5 and y
// 2..-1, 16 pixels a unit.
constexpr int kWidth = 64, kHeight = 48;

struct P {
    double x, y;
};
using Ring = std::vector<P>;

bool evenOdd(const std::vector<Ring>& contours, double x, double y)
{
    bool inside = false;
    for (const Ring& ring : contours)
        for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
            const P &a = ring[i], &b = ring[j];
            if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x)
                inside = !inside;
        }
    return inside;
}

double distanceToSides(const std::vector<Ring>& contours, double x, double y)
{
    double best = 1e300;
    for (const Ring& ring : contours)
        for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
            const P &a = ring[i], &b = ring[j];
            const double dx = b.x - a.x, dy = b.y - a.y;
            double t = ((x - a.x) * dx + (y - a.y) * dy) / (dx * dx + dy * dy);
            t = std::min(std::max(t, 0.0), 1.0);
            best = std::min(best, std::hypot(x - a.x - t * dx, y - a.y - t * dy));
        }
    return best;
}

Ring pentagram()
{
    Ring star;
    for (int k = 0; k < 5; ++k) {
        const double angle = M_PI / 2 + k * 4 * M_PI / 5;
        star.push_back(P{1.5 + 1.4 * std::cos(angle), 0.5 + 1.4 * std::sin(angle)});
    }
    return star;
}

class FillRuleRenderTest : public OwningApiTest {
protected:
    Pixmap render(TQ3GeometryObject geometry)
    {
        Pixmap image(kWidth, kHeight);
        TestView view(image.pixmap(), kQ3RendererTypeInteractive);
        EXPECT_EQ(view.render([&](TQ3ViewObject v) { Q3Geometry_Submit(geometry, v); }), kQ3ViewStatusDone);
        return image;
    }

    // Every pixel red inside by the rule, black outside; returns how many
    // were inside.
    int expectEvenOdd(const Pixmap& image, const std::vector<Ring>& contours, const std::string& what)
    {
        int inside = 0, wrong = 0;
        for (int py = 0; py < kHeight; ++py)
            for (int px = 0; px < kWidth; ++px) {
                const double x = -0.5 + (px + 0.5) / 16.0, y = 2.0 - (py + 0.5) / 16.0;
                if (distanceToSides(contours, x, y) < 0.1 / 16.0)
                    continue;
                const bool in = evenOdd(contours, x, y);
                inside += in ? 1 : 0;
                const Rgba c = image.at(px, py);
                if ((c.r == (in ? 255 : 0) && c.g == 0 && c.b == 0) || wrong++ >= 3)
                    continue;
                ADD_FAILURE() << what << ": pixel (" << px << ", " << py << ") is " << c.r << " " << c.g << " "
                              << c.b << ", " << (in ? "inside" : "outside") << " by the even-odd rule";
            }
        EXPECT_EQ(wrong, 0) << what;
        return inside;
    }

    std::vector<TQ3Vertex3D> vertices(const Ring& ring)
    {
        std::vector<TQ3Vertex3D> out;
        for (const P& p : ring)
            out.push_back(TQ3Vertex3D{{float(p.x), float(p.y), 0.0f}, nullptr});
        return out;
    }

    TQ3GeometryObject generalPolygon(const std::vector<Ring>& contours)
    {
        std::vector<std::vector<TQ3Vertex3D>> lists;
        std::vector<TQ3GeneralPolygonContourData> data;
        for (const Ring& ring : contours)
            lists.push_back(vertices(ring));
        for (auto& list : lists)
            data.push_back(TQ3GeneralPolygonContourData{(unsigned long)list.size(), list.data()});
        TQ3GeneralPolygonData polygon{(unsigned long)data.size(), data.data(), kQ3GeneralPolygonShapeHintComplex,
                                      own(colorSet(1, 0, 0))};
        TQ3GeometryObject geometry = own(Q3GeneralPolygon_New(&polygon));
        EXPECT_NE(geometry, nullptr);
        return geometry;
    }
};

TEST_F(FillRuleRenderTest, AGeneralPolygonPentagramLeavesItsCentreEmpty)
{
    const std::vector<Ring> star = {pentagram()};
    const Pixmap image = render(generalPolygon(star));
    EXPECT_GT(expectEvenOdd(image, star, "pentagram"), 300);
    // The centre: inside the outline, crossed twice, empty.
    EXPECT_EQ(image.at(32, 24).r, 0);
}

TEST_F(FillRuleRenderTest, OverlappingContoursCutTheirOverlapOut)
{
    const std::vector<Ring> squares = {{{0.0, -0.5}, {2.0, -0.5}, {2.0, 1.2}, {0.0, 1.2}},
                                       {{1.0, 0.2}, {3.2, 0.2}, {3.2, 1.8}, {1.0, 1.8}}};
    EXPECT_GT(expectEvenOdd(render(generalPolygon(squares)), squares, "two squares"), 500);
    // A bow tie in one contour: both loops filled.
    const std::vector<Ring> bowTie = {{{0.0, -0.5}, {3.0, 1.5}, {3.0, -0.5}, {0.0, 1.5}}};
    EXPECT_GT(expectEvenOdd(render(generalPolygon(bowTie)), bowTie, "bow tie"), 300);
}

TEST_F(FillRuleRenderTest, ASelfCrossingSimplePolygonTakesTheSameRule)
{
    const Ring star = pentagram();
    std::vector<TQ3Vertex3D> list = vertices(star);
    TQ3PolygonData data{(unsigned long)list.size(), list.data(), own(colorSet(1, 0, 0))};
    TQ3GeometryObject polygon = own(Q3Polygon_New(&data));
    ASSERT_NE(polygon, nullptr);
    EXPECT_GT(expectEvenOdd(render(polygon), {star}, "simple pentagram"), 300);
}

TEST_F(FillRuleRenderTest, AMeshFaceWhoseContoursOverlapTakesTheSameRule)
{
    const std::vector<Ring> squares = {{{0.0, -0.5}, {2.0, -0.5}, {2.0, 1.2}, {0.0, 1.2}},
                                       {{1.0, 0.2}, {3.2, 0.2}, {3.2, 1.8}, {1.0, 1.8}}};
    TQ3GeometryObject mesh = own(Q3Mesh_New());
    ASSERT_NE(mesh, nullptr);
    std::vector<TQ3MeshFace> faces;
    for (const Ring& ring : squares) {
        std::vector<TQ3MeshVertex> corners;
        for (const TQ3Vertex3D& v : vertices(ring))
            corners.push_back(Q3Mesh_VertexNew(mesh, &v));
        faces.push_back(Q3Mesh_FaceNew(mesh, (unsigned long)corners.size(), corners.data(), own(colorSet(1, 0, 0))));
        ASSERT_NE(faces.back(), nullptr);
    }
    ASSERT_NE(Q3Mesh_FaceToContour(mesh, faces[0], faces[1]), nullptr);
    EXPECT_GT(expectEvenOdd(render(mesh), squares, "mesh face"), 500);
}

} // namespace
