// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Every scene of samples/scenes rendered at the sample's size and compared
// with tests/golden/scene_NAME.png (tolerance: tests/golden/README.md), and a
// few facts about the pictures checked by reading pixels, so that a golden
// blessed from a wrong picture would not pass.

#include "Golden.h"
#include "SessionTest.h"

#include "QD3D.h"
#include "QD3DErrors.h"
#include "scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

class SceneTest : public q3test::SessionTest<::testing::TestWithParam<unsigned long>> {
protected:

    static q3test::RgbaImage render(const Q3Scene* scene)
    {
        q3test::RgbaImage image(Q3SCENE_WIDTH, Q3SCENE_HEIGHT);
        EXPECT_EQ(q3scene_render(scene, Q3SCENE_WIDTH, Q3SCENE_HEIGHT, image.pixels.data()), 0) << scene->name;
        return image;
    }

    // The scenes NAME_interactive and NAME_wireframe and their images; the
    // images stay empty when either scene is missing.
    struct FilledAndOutlined {
        const Q3Scene* filled = nullptr;
        const Q3Scene* outlined = nullptr;
        q3test::RgbaImage a, b;
    };
    static FilledAndOutlined renderBoth(const std::string& name)
    {
        FilledAndOutlined both;
        both.filled = q3scene_find((name + "_interactive").c_str());
        both.outlined = q3scene_find((name + "_wireframe").c_str());
        if (both.filled != nullptr && both.outlined != nullptr) {
            both.a = render(both.filled);
            both.b = render(both.outlined);
        }
        return both;
    }
};

struct Pixel {
    int r, g, b;
};

Pixel at(const q3test::RgbaImage& image, int x, int y)
{
    const unsigned char* p = image.at(x, y);
    return Pixel{p[0], p[1], p[2]};
}

bool isBackground(const q3test::RgbaImage& image, int x, int y, const TQ3ColorRGB& background)
{
    const Pixel p = at(image, x, y);
    auto near = [](int channel, float value) { return std::abs(channel - int(value * 255.0f + 0.5f)) <= 1; };
    return near(p.r, background.r) && near(p.g, background.g) && near(p.b, background.b);
}

TEST_P(SceneTest, MatchesTheGolden)
{
    const Q3Scene* scene = q3scene_get(GetParam());
    ASSERT_NE(scene, nullptr);
    const q3test::RgbaImage image = render(scene);
    EXPECT_TRUE(q3test::matchesGolden(std::string("scene_") + scene->name, image));
}

INSTANTIATE_TEST_SUITE_P(Scenes, SceneTest, ::testing::Range(0UL, q3scene_count()),
                         [](const ::testing::TestParamInfo<unsigned long>& info) {
                             return std::string(q3scene_get(info.param)->name);
                         });

using ScenePixels = SceneTest;

// The hexagon's centre vertex is near-white and its colours blend towards
// the rim: filled, the middle of the image is lit; in wireframe it is not.
TEST_F(ScenePixels, TheInteractiveRendererFillsWhatTheWireframeOutlines)
{
    const FilledAndOutlined both = renderBoth("trimesh");
    const auto& [filled, outlined, a, b] = both;
    ASSERT_TRUE(filled != nullptr && outlined != nullptr);
    int filledCount = 0, outlinedCount = 0;
    for (int y = 0; y < Q3SCENE_HEIGHT; ++y)
        for (int x = 0; x < Q3SCENE_WIDTH; ++x) {
            filledCount += !isBackground(a, x, y, filled->background);
            outlinedCount += !isBackground(b, x, y, outlined->background);
        }
    EXPECT_GT(filledCount, 8 * outlinedCount);
    EXPECT_GT(outlinedCount, 300); // six rim sides and six spokes are drawn
}

// Blue (near, submitted first) wins wherever the two triangles overlap: the
// picture has blue pixels and orange ones, and around the image centre,
// where both triangles lie, blue.
TEST_F(ScenePixels, TheNearerTriangleHidesTheFartherOne)
{
    const Q3Scene* scene = q3scene_find("hidden_triangle");
    ASSERT_NE(scene, nullptr);
    const q3test::RgbaImage image = render(scene);
    const Pixel centre = at(image, Q3SCENE_WIDTH / 2, Q3SCENE_HEIGHT / 2);
    EXPECT_GT(centre.b, 200);
    EXPECT_LT(centre.r, 80);
    int orange = 0;
    for (int y = 0; y < Q3SCENE_HEIGHT; ++y)
        for (int x = 0; x < Q3SCENE_WIDTH; ++x) {
            const Pixel p = at(image, x, y);
            orange += p.r > 200 && p.b < 60;
        }
    EXPECT_GT(orange, 1000);
}

// Along the zigzag the colour goes from red to blue: the lit pixels in the
// leftmost tenth are reddish, those in the rightmost tenth bluish.
TEST_F(ScenePixels, ThePolylineRunsFromRedToBlue)
{
    const Q3Scene* scene = q3scene_find("polyline_red_to_blue");
    ASSERT_NE(scene, nullptr);
    const q3test::RgbaImage image = render(scene);
    long leftRed = 0, leftBlue = 0, rightRed = 0, rightBlue = 0;
    for (int y = 0; y < Q3SCENE_HEIGHT; ++y)
        for (int x = 0; x < Q3SCENE_WIDTH; ++x) {
            if (isBackground(image, x, y, scene->background))
                continue;
            const Pixel p = at(image, x, y);
            if (x < Q3SCENE_WIDTH / 4) {
                leftRed += p.r;
                leftBlue += p.b;
            } else if (x > 3 * Q3SCENE_WIDTH / 4) {
                rightRed += p.r;
                rightBlue += p.b;
            }
        }
    EXPECT_GT(leftRed, 2 * leftBlue);
    EXPECT_GT(rightBlue, 2 * rightRed);
}

int countNear(const q3test::RgbaImage& image, int r, int g, int b)
{
    int count = 0;
    for (int y = 0; y < Q3SCENE_HEIGHT; ++y)
        for (int x = 0; x < Q3SCENE_WIDTH; ++x) {
            const Pixel p = at(image, x, y);
            count += std::abs(p.r - r) <= 8 && std::abs(p.g - g) <= 8 && std::abs(p.b - b) <= 8;
        }
    return count;
}

// The two boxes between them show all six face colours, each on a sizeable
// face (the colours of scenes.c's box_face_sets, in 0..255).
TEST_F(ScenePixels, TheBoxesShowAllSixFaceColours)
{
    const Q3Scene* scene = q3scene_find("box_faces");
    ASSERT_NE(scene, nullptr);
    const q3test::RgbaImage image = render(scene);
    const int faces[6][3] = {{230, 51, 51},  {51, 204, 77},  {51, 102, 242},
                             {242, 217, 51}, {51, 217, 230}, {217, 77, 217}};
    for (const auto& face : faces)
        EXPECT_GT(countNear(image, face[0], face[1], face[2]), 400) << face[0] << " " << face[1] << " " << face[2];
}

// Seen from below, the cones' bottoms (blue) and the cut's faces (green)
// show besides their sides (orange).
TEST_F(ScenePixels, TheConesShowTheirBottomsAndTheCut)
{
    const Q3Scene* scene = q3scene_find("cone_bottom");
    ASSERT_NE(scene, nullptr);
    const q3test::RgbaImage image = render(scene);
    EXPECT_GT(countNear(image, 242, 140, 38), 2000);
    EXPECT_GT(countNear(image, 51, 102, 242), 2000);
    EXPECT_GT(countNear(image, 64, 204, 77), 800);
}

// The holed face: orange around a hole that shows the background, filled
// and outlined alike; the folded face's shared corner magenta (its corner
// set), not the vertex's yellow; the shared edge white in the wireframe.
TEST_F(ScenePixels, TheMeshShowsItsHoleCornerAndSharedEdge)
{
    const FilledAndOutlined both = renderBoth("mesh");
    const auto& [filled, outlined, a, b] = both;
    ASSERT_TRUE(filled != nullptr && outlined != nullptr);
    EXPECT_TRUE(isBackground(a, 109, 120, filled->background));
    EXPECT_TRUE(isBackground(b, 109, 120, outlined->background));
    EXPECT_GT(countNear(a, 242, 140, 38), 12000);
    const Pixel corner = at(a, 176, 50);
    EXPECT_GT(corner.r, 180);
    EXPECT_GT(corner.b, 150);
    EXPECT_LT(corner.g, 120);
    EXPECT_GT(countNear(b, 255, 255, 255), 100);
    EXPECT_EQ(countNear(a, 255, 255, 255), 0);
}

// The camera of the flat scenes (eye on +z at 5, 0.75 rad along y): the
// pixel column and row a point of the plane z = 0 projects to.
int columnOf(float x)
{
    const double halfHeight = 5.0 * std::tan(0.375);
    return int(std::floor(Q3SCENE_WIDTH / 2.0 + x / (halfHeight * Q3SCENE_WIDTH / Q3SCENE_HEIGHT) * Q3SCENE_WIDTH / 2.0));
}
int rowOf(float y)
{
    const double halfHeight = 5.0 * std::tan(0.375);
    return int(std::floor(Q3SCENE_HEIGHT / 2.0 - y / halfHeight * Q3SCENE_HEIGHT / 2.0));
}

// Even-odd: the square's ring and the island inside its hole are orange, the
// hole between them is the background; the star's triangular hole too.
TEST_F(ScenePixels, TheGeneralPolygonsFillOnlyInsideAnOddNumberOfContours)
{
    const Q3Scene* scene = q3scene_find("general_polygons");
    ASSERT_NE(scene, nullptr);
    const q3test::RgbaImage image = render(scene);
    auto orange = [&](float x, float y) {
        const Pixel p = at(image, columnOf(x), rowOf(y));
        return p.r > 200 && p.g > 100 && p.g < 180 && p.b < 80;
    };
    EXPECT_TRUE(orange(-1.3f, 0.0f));           // the island
    EXPECT_TRUE(orange(-1.3f + 0.8f, 0.0f));    // the ring, right
    EXPECT_TRUE(orange(-1.3f, -0.8f));          // the ring, below
    for (const float d : {0.42f, -0.42f}) {     // the hole, either side
        EXPECT_TRUE(isBackground(image, columnOf(-1.3f + d), rowOf(0.0f), scene->background));
        EXPECT_TRUE(isBackground(image, columnOf(-1.3f), rowOf(d), scene->background));
    }
    EXPECT_TRUE(isBackground(image, columnOf(1.42f), rowOf(-0.08f), scene->background)); // the star's hole
    EXPECT_FALSE(isBackground(image, columnOf(1.4f), rowOf(0.4f), scene->background));  // the star
}

// Every set bit of each visible marker is one pixel of its colour: the
// crosses have 28 set bits, the bar 36; the yellow cross behind the
// triangle is hidden.
TEST_F(ScenePixels, MarkersDrawTheirBitsInScreenSpace)
{
    const Q3Scene* scene = q3scene_find("markers");
    ASSERT_NE(scene, nullptr);
    const q3test::RgbaImage image = render(scene);
    EXPECT_EQ(countNear(image, 242, 51, 51), 28);   // red
    EXPECT_EQ(countNear(image, 51, 230, 77), 28);   // green
    EXPECT_EQ(countNear(image, 77, 128, 255), 36);  // blue
    EXPECT_EQ(countNear(image, 255, 255, 255), 28); // white
    EXPECT_EQ(countNear(image, 255, 230, 51), 0);   // yellow, hidden
    // The red cross is centred on the triangle's left corner: its middle
    // rows span columns corner - 4 to corner + 3.
    const int x = columnOf(-1.5f), y = rowOf(-1.0f);
    const Pixel left = at(image, x - 4, y - 1), right = at(image, x + 3, y);
    EXPECT_GT(left.r, 200);
    EXPECT_LT(left.g, 80);
    EXPECT_GT(right.r, 200);
    EXPECT_LT(right.g, 80);
}

} // namespace
