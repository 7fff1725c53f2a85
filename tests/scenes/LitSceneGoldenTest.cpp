// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Every lit scene of samples/lighting and the frames of the Box sample
// (samples/box) compared with tests/golden/lit_NAME.png and
// box_frame_N.png (tolerance: tests/golden/README.md), and facts about the
// pictures checked by reading pixels, so that a golden blessed from a wrong
// picture would not pass. Exact lighting values against the book's equations
// are checked in tests/api/LightingRenderTest.cpp.

#include "Golden.h"
#include "SessionTest.h"

#include "QD3D.h"
#include "QD3DErrors.h"
#include "box_document.h"
#include "lit_scenes.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace {

constexpr int kWidth = Q3SCENE_WIDTH;
constexpr int kHeight = Q3SCENE_HEIGHT;
constexpr unsigned long kBoxFrames = 4;

class LitSceneTest : public q3test::SessionTest<> {
protected:

    static q3test::RgbaImage render(const char* name)
    {
        q3test::RgbaImage image(kWidth, kHeight);
        const Q3LitScene* scene = q3litscene_find(name);
        EXPECT_NE(scene, nullptr) << name;
        if (scene != nullptr)
            EXPECT_EQ(q3litscene_render(scene, kWidth, kHeight, image.pixels.data()), 0) << name;
        return image;
    }
};

class LitSceneGolden : public LitSceneTest, public ::testing::WithParamInterface<unsigned long> {};

TEST_P(LitSceneGolden, MatchesTheGolden)
{
    const Q3LitScene* scene = q3litscene_get(GetParam());
    ASSERT_NE(scene, nullptr);
    const q3test::RgbaImage image = render(scene->scene.name);
    EXPECT_TRUE(q3test::matchesGolden(std::string("lit_") + scene->scene.name, image));
}

INSTANTIATE_TEST_SUITE_P(LitScenes, LitSceneGolden, ::testing::Range(0UL, q3litscene_count()),
                         [](const ::testing::TestParamInfo<unsigned long>& info) {
                             return std::string(q3litscene_get(info.param)->scene.name);
                         });

class BoxFrameGolden : public LitSceneTest, public ::testing::WithParamInterface<unsigned long> {};

TEST_P(BoxFrameGolden, MatchesTheGolden)
{
    BoxDocument* document = box_document_new(kWidth, kHeight);
    ASSERT_NE(document, nullptr);
    q3test::RgbaImage image(kWidth, kHeight);
    EXPECT_EQ(box_document_draw(document, GetParam(), image.pixels.data()), 0);
    box_document_dispose(document);
    EXPECT_TRUE(q3test::matchesGolden("box_frame_" + std::to_string(GetParam()), image));
}

INSTANTIATE_TEST_SUITE_P(BoxSample, BoxFrameGolden, ::testing::Range(0UL, kBoxFrames));

// ---- Facts about the pictures --------------------------------------------

struct Pixel {
    int r, g, b;
    bool operator<(const Pixel& o) const { return r != o.r ? r < o.r : g != o.g ? g < o.g : b < o.b; }
};

Pixel at(const q3test::RgbaImage& image, int x, int y)
{
    const unsigned char* p = image.at(x, y);
    return Pixel{p[0], p[1], p[2]};
}

int byteOf(float value)
{
    return int(value * 255.0f + 0.5f);
}

bool near(const Pixel& p, float r, float g, float b, int tolerance = 2)
{
    return std::abs(p.r - byteOf(r)) <= tolerance && std::abs(p.g - byteOf(g)) <= tolerance &&
           std::abs(p.b - byteOf(b)) <= tolerance;
}

// The scenes' background, lit_scenes.c's DARK.
bool isBackground(const Pixel& p)
{
    return near(p, 0.1f, 0.1f, 0.13f, 1);
}

template <typename F>
int count(const q3test::RgbaImage& image, F&& predicate, int x0 = 0, int x1 = kWidth)
{
    int n = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = x0; x < x1; ++x)
            n += predicate(at(image, x, y)) ? 1 : 0;
    return n;
}

int drawn(const q3test::RgbaImage& image, int x0 = 0, int x1 = kWidth)
{
    return count(image, [](const Pixel& p) { return !isBackground(p); }, x0, x1);
}

// Lit by an ambient light alone (brightness 0.7, ambient coefficient 1),
// every surface is its diffuse colour times 0.7, the same at every pixel.
TEST_F(LitSceneTest, AnAmbientLightAloneGivesEachSurfaceOneFlatColour)
{
    const q3test::RgbaImage image = render("light_ambient");
    const float k = 0.7f;
    const float colours[4][3] = {{0.8f, 0.8f, 0.8f}, {0.9f, 0.25f, 0.2f}, {0.25f, 0.4f, 0.9f}, {0.3f, 0.8f, 0.35f}};
    const int all = drawn(image);
    const int flat = count(image, [&](const Pixel& p) {
        for (const auto& c : colours)
            if (near(p, k * c[0], k * c[1], k * c[2]))
                return true;
        return false;
    });
    EXPECT_GT(all, 20000);
    EXPECT_EQ(flat, all);
}

// Outside the spot light's outer angle only the ambient light (0.1) reaches
// the grey floor; under the hot angle the floor is lit far brighter.
TEST_F(LitSceneTest, TheSpotLightLeavesTheFloorOutsideItsConeAtTheAmbientLevel)
{
    const q3test::RgbaImage image = render("light_spot");
    EXPECT_GT(count(image, [](const Pixel& p) { return near(p, 0.08f, 0.08f, 0.08f); }), 5000);
    EXPECT_GT(count(image, [](const Pixel& p) { return p.r > 200 && p.g > 200 && p.b > 200; }), 200);
}

// NULL illumination draws the diffuse colours, whatever the lights.
TEST_F(LitSceneTest, NullIlluminationDrawsTheDiffuseColours)
{
    const q3test::RgbaImage image = render("illumination_null");
    const int all = drawn(image);
    EXPECT_GT(all, 10000);
    EXPECT_EQ(count(image, [](const Pixel& p) {
                  return near(p, 0.85f, 0.85f, 0.85f) || near(p, 0.95f, 0.5f, 0.15f);
              }),
              all);
}

// Phong is Lambert plus a specular term: never darker, and where the
// highlights are (white on orange), much bluer.
TEST_F(LitSceneTest, PhongAddsHighlightsToLambert)
{
    const q3test::RgbaImage lambert = render("illumination_lambert");
    const q3test::RgbaImage phong = render("illumination_phong");
    int darker = 0, highlights = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const Pixel l = at(lambert, x, y), p = at(phong, x, y);
            darker += (p.r < l.r - 1 || p.g < l.g - 1 || p.b < l.b - 1) ? 1 : 0;
            highlights += p.b > l.b + 40 ? 1 : 0;
        }
    EXPECT_EQ(darker, 0);
    EXPECT_GT(highlights, 100);
}

// Edges draw fewer pixels than filled triangles, points fewer than edges.
TEST_F(LitSceneTest, FillStylesDrawFacesEdgesOrPoints)
{
    const int filled = drawn(render("fill_filled"));
    const int edges = drawn(render("fill_edges"));
    const int points = drawn(render("fill_points"));
    EXPECT_GT(points, 100);
    EXPECT_GT(edges, 2 * points);
    EXPECT_GT(filled, 2 * edges);
}

// Removing back faces leaves the open cylinder's inside undrawn; flipping
// draws the same pixels as both, lit differently (the inside's normals
// turned towards the viewer).
TEST_F(LitSceneTest, BackfacingStylesDrawRemoveOrFlipTheInside)
{
    const q3test::RgbaImage both = render("backfacing_both");
    const q3test::RgbaImage removed = render("backfacing_remove");
    const q3test::RgbaImage flipped = render("backfacing_flip");
    int sameCoverage = 0, differentColour = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const Pixel b = at(both, x, y), f = at(flipped, x, y);
            sameCoverage += isBackground(b) == isBackground(f) ? 1 : 0;
            differentColour += (std::abs(b.r - f.r) + std::abs(b.g - f.g) + std::abs(b.b - f.b)) > 30 ? 1 : 0;
        }
    EXPECT_EQ(sameCoverage, kWidth * kHeight);
    EXPECT_GT(differentColour, 2000);
    EXPECT_LT(drawn(removed) + 2000, drawn(both));
}

// Flat shading gives each triangle one colour: far fewer distinct colours
// than vertex interpolation; pixel interpolation differs from vertex.
TEST_F(LitSceneTest, InterpolationStylesShadeFlatByVertexOrByPixel)
{
    auto colours = [](const q3test::RgbaImage& image) {
        std::set<Pixel> distinct;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x)
                distinct.insert(at(image, x, y));
        return distinct.size();
    };
    const q3test::RgbaImage flat = render("interpolation_none");
    const q3test::RgbaImage vertex = render("interpolation_vertex");
    const q3test::RgbaImage pixel = render("interpolation_pixel");
    EXPECT_LE(colours(flat), 12u * 8u + 2u); // at most one per triangle, and the background
    EXPECT_GT(colours(vertex), 4 * colours(flat));
    int differ = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const Pixel v = at(vertex, x, y), p = at(pixel, x, y);
            differ += (std::abs(v.r - p.r) + std::abs(v.g - p.g) + std::abs(v.b - p.b)) > 6 ? 1 : 0;
        }
    EXPECT_GT(differ, 1000);
}

// [box, move right, red, sphere]: unordered, the box stays at the left in
// the default white; ordered, the move comes first and nothing is left at
// the left, and the colour comes first and both are red.
TEST_F(LitSceneTest, AnOrderedGroupAppliesTransformsAndAttributesFirst)
{
    const q3test::RgbaImage unordered = render("group_unordered");
    const q3test::RgbaImage ordered = render("group_ordered");
    const int left = kWidth / 4;
    auto grey = [](const Pixel& p) { return !isBackground(p) && std::abs(p.r - p.g) < 8 && std::abs(p.g - p.b) < 8; };
    auto red = [](const Pixel& p) { return p.r > 2 * p.g + 10 && p.r > 2 * p.b + 10; };
    EXPECT_GT(drawn(unordered, 0, left), 1500);
    EXPECT_EQ(drawn(ordered, 0, left), 0);
    EXPECT_GT(count(unordered, grey), 3000);
    EXPECT_EQ(count(ordered, grey), 0);
    EXPECT_GT(count(ordered, red), count(unordered, red) + 1000);
}

// The Box sample: an orange box (red over green over blue in every drawn
// pixel), lit differently on its faces, turning from frame to frame.
TEST_F(LitSceneTest, TheBoxSampleDrawsAnOrangeBoxThatTurns)
{
    BoxDocument* document = box_document_new(kWidth, kHeight);
    ASSERT_NE(document, nullptr);
    q3test::RgbaImage first(kWidth, kHeight), second(kWidth, kHeight);
    ASSERT_EQ(box_document_draw(document, 0, first.pixels.data()), 0);
    ASSERT_EQ(box_document_draw(document, 1, second.pixels.data()), 0);
    box_document_dispose(document);
    const Pixel background = at(first, 0, 0);
    std::set<Pixel> shades;
    int box = 0, orange = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const Pixel p = at(first, x, y);
            if (p.r == background.r && p.g == background.g && p.b == background.b)
                continue;
            ++box;
            orange += (p.r >= p.g && p.g >= p.b) ? 1 : 0;
            shades.insert(p);
        }
    EXPECT_GT(box, 8000);
    EXPECT_GT(orange, box * 99 / 100);
    EXPECT_GE(shades.size(), 3u); // three faces towards the camera, lit differently
    EXPECT_NE(first.pixels, second.pixels);
}

// The trimmed patch: down the middle column the plain patch is one run of
// drawn pixels, the trimmed one is cut by the hole; at the middle row of the
// run beyond the hole (the island), the hole's background lies on both
// sides, and the patch again beyond it.
TEST_F(LitSceneTest, TheTrimmedPatchHasAHoleWithAnIslandInIt)
{
    const q3test::RgbaImage plain = render("patch_plain");
    const q3test::RgbaImage trimmed = render("patch_trimmed");
    auto runs = [](const q3test::RgbaImage& image, int x) {
        std::vector<std::pair<int, int>> found;
        for (int y = 0; y < kHeight; ++y)
            if (!isBackground(at(image, x, y))) {
                if (found.empty() || found.back().second != y - 1)
                    found.push_back({y, y});
                else
                    found.back().second = y;
            }
        return found;
    };
    const int middle = kWidth / 2;
    ASSERT_EQ(runs(plain, middle).size(), 1u);
    const auto cut = runs(trimmed, middle);
    ASSERT_GE(cut.size(), 2u);
    const int y = (cut[0].first + cut[0].second) / 2;
    for (int step : {-1, 1}) {
        int x = middle;
        while (x > 0 && x < kWidth - 1 && !isBackground(at(trimmed, x, y)))
            x += step;
        const int island = std::abs(x - middle);
        while (x > 0 && x < kWidth - 1 && isBackground(at(trimmed, x, y)))
            x += step;
        EXPECT_GT(island, 5) << "the island";
        EXPECT_TRUE(x > 0 && x < kWidth - 1) << "no patch beyond the hole at row " << y;
    }
}

} // namespace
