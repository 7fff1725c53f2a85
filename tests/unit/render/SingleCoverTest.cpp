// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The tests that let a translucent mesh be drawn unsorted
// (render/SingleCover.h): a mesh's boundary as one loop, a triangle's turn
// and a polygon's simplicity, each with the slack the rasterizer's rounding
// asks for, against values worked out here.

#include "render/SingleCover.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace q3 {
namespace {

// An n x n grid of points, row by row, and its squares' two triangles each,
// counter-clockwise with y up.
std::vector<std::uint32_t> gridTriangles(std::uint32_t n)
{
    std::vector<std::uint32_t> corners;
    for (std::uint32_t y = 0; y + 1 < n; ++y)
        for (std::uint32_t x = 0; x + 1 < n; ++x) {
            const std::uint32_t a = y * n + x;
            corners.insert(corners.end(), {a, a + 1, a + n + 1, a, a + n + 1, a + n});
        }
    return corners;
}

TEST(SingleCover, AGridsBoundaryIsItsRimOnceRoundCounterClockwise)
{
    const std::uint32_t n = 5;
    const std::vector<std::uint32_t> corners = gridTriangles(n);
    std::vector<std::uint32_t> loop;
    ASSERT_TRUE(boundaryLoop(corners.data(), corners.size() / 3, n * n, loop));
    ASSERT_EQ(loop.size(), std::size_t(4 * (n - 1)));
    // Every rim point once, and each step one grid edge along the rim.
    const std::set<std::uint32_t> visited(loop.begin(), loop.end());
    EXPECT_EQ(visited.size(), loop.size());
    double doubledArea = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const std::uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
        const int ax = int(a % n), ay = int(a / n), bx = int(b % n), by = int(b / n);
        EXPECT_TRUE(ax == 0 || ay == 0 || ax == int(n - 1) || ay == int(n - 1)) << a;
        EXPECT_EQ(std::abs(ax - bx) + std::abs(ay - by), 1) << a << " to " << b;
        doubledArea += double(ax) * by - double(bx) * ay;
    }
    // The shoelace formula: the grid's area, positive (counter-clockwise,
    // as its triangles turn).
    EXPECT_EQ(doubledArea, 2.0 * (n - 1) * (n - 1));
}

TEST(SingleCover, MeshesWithoutOneLoopHaveNone)
{
    std::vector<std::uint32_t> loop{7};
    const auto none = [&](const std::vector<std::uint32_t>& corners, std::size_t vertexCount, const char* what) {
        loop.assign(1, 7);
        EXPECT_FALSE(boundaryLoop(corners.data(), corners.size() / 3, vertexCount, loop)) << what;
        EXPECT_TRUE(loop.empty()) << what;
    };
    none({}, 3, "no triangle");
    none({0, 1, 3}, 3, "an index one past the end");
    none({0, 1, std::numeric_limits<std::uint32_t>::max()}, 3, "an index at UINT32_MAX");
    none({0, 1, 1}, 3, "two equal corners");
    none({0, 1, 2, 3, 4, 5}, 6, "two triangles apart: two loops");
    none({0, 1, 2, 2, 3, 4}, 5, "two triangles meeting at a corner: loops sharing a vertex");
    none({0, 1, 2, 0, 1, 2}, 3, "one triangle twice: each edge left over twice one way");
    none({0, 1, 2, 0, 3, 1, 1, 3, 2, 2, 3, 0}, 4, "a closed tetrahedron: no boundary");
    // A ring of 4 squares around a square hole: an outer and an inner loop.
    std::vector<std::uint32_t> ring;
    for (std::uint32_t k = 0; k < 4; ++k) {
        const std::uint32_t o0 = k, o1 = (k + 1) % 4, i0 = 4 + k, i1 = 4 + (k + 1) % 4;
        ring.insert(ring.end(), {o0, o1, i1, o0, i1, i0});
    }
    none(ring, 8, "a ring");
    const std::vector<std::uint32_t> one{0, 1, 2};
    ASSERT_TRUE(boundaryLoop(one.data(), 1, 3, loop));
    EXPECT_EQ(loop.size(), 3u);
}

TEST(SingleCover, ATriangleTurnsOnlyWhereItsSlackCannotFlattenIt)
{
    const double slack = 0.25;
    const WindowPoint a{0.0, 0.0}, b{10.0, 0.0};
    // a, b, (0, h): doubled area 10 h; the corners moved by the slack
    // change it by at most 2 slack (10 + h) + 8 slack^2 (SingleCover.h).
    const auto bound = [&](double h) { return 2.0 * slack * (10.0 + h) + 8.0 * slack * slack; };
    // 10 h = 2 s (10 + h) + 8 s^2: h = (20 s + 8 s^2) / (10 - 2 s).
    const double edge = (20.0 * slack + 8.0 * slack * slack) / (10.0 - 2.0 * slack);
    ASSERT_NEAR(10.0 * edge, bound(edge), 1e-12);
    EXPECT_EQ(turnWithSlack(a, b, WindowPoint{0.0, edge * 1.001}, slack), 1);
    EXPECT_EQ(turnWithSlack(a, b, WindowPoint{0.0, edge * 0.999}, slack), 0);
    EXPECT_EQ(turnWithSlack(a, b, WindowPoint{0.0, -edge * 1.001}, slack), -1);
    EXPECT_EQ(turnWithSlack(a, b, WindowPoint{0.0, -edge * 0.999}, slack), 0);
    EXPECT_EQ(turnWithSlack(b, a, WindowPoint{0.0, 5.0}, slack), -1);
    EXPECT_EQ(turnWithSlack(a, b, WindowPoint{20.0, 0.0}, 0.0), 0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(turnWithSlack(a, b, WindowPoint{nan, 5.0}, slack), 0);
    EXPECT_EQ(turnWithSlack(a, b, WindowPoint{0.0, inf}, slack), 0);
}

// Whether the polygon through `points` in order stays simple.
bool simple(const std::vector<WindowPoint>& points, double slack)
{
    std::vector<std::uint32_t> loop;
    for (std::uint32_t i = 0; i < points.size(); ++i)
        loop.push_back(i);
    LoopScratch scratch;
    return simpleWithSlack(points.data(), 0, loop, slack, scratch);
}

TEST(SingleCover, APolygonIsSimpleOnlyWithItsSidesMoreThanThreeSlacksApart)
{
    const double slack = 0.1;
    EXPECT_TRUE(simple({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, slack));
    EXPECT_TRUE(simple({{0, 0}, {10, 0}, {0, 10}}, slack));
    EXPECT_FALSE(simple({{0, 0}, {10, 10}, {10, 0}, {0, 10}}, slack)) << "a figure eight";
    EXPECT_FALSE(simple({{0, 0}, {10, 0}}, slack)) << "two corners";
    EXPECT_FALSE(simple({{0, 0}, {10, 0}, {5, 0}, {5, 5}}, slack)) << "a side doubling back on the one before";
    // A U whose arms' inner sides (x = 4 and x = 4 + gap) do not touch:
    // simple only while the gap is more than 3 slack.
    const auto u = [](double gap) {
        return std::vector<WindowPoint>{{0, 0}, {8 + gap, 0}, {8 + gap, 10}, {4 + gap, 10},
                                        {4 + gap, 2}, {4, 2},       {4, 10},      {0, 10}};
    };
    EXPECT_TRUE(simple(u(3.0 * slack * 1.01), slack));
    EXPECT_FALSE(simple(u(3.0 * slack * 0.99), slack));
    // Two consecutive sides at a sharp corner: the polygon (0, 0), (10, 0),
    // (0, d) keeps (0, d) d from the first side's line, so it is simple
    // while d > 3 slack (each side's far end kept off the other).
    EXPECT_TRUE(simple({{0, 0}, {10, 0}, {0, 3.0 * slack * 1.01}}, slack));
    EXPECT_FALSE(simple({{0, 0}, {10, 0}, {0, 3.0 * slack * 0.99}}, slack));
    // A corner visited twice.
    EXPECT_FALSE(simple({{0, 0}, {10, 0}, {5, 5}, {10, 10}, {0, 10}, {5, 5}}, slack));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(simple({{0, 0}, {10, 0}, {nan, 10}, {0, 10}}, slack));
    // The points taken from `offset` on.
    const std::vector<WindowPoint> points{{99, 99}, {0, 0}, {10, 0}, {10, 10}, {0, 10}};
    LoopScratch scratch;
    EXPECT_TRUE(simpleWithSlack(points.data(), 1, {0, 1, 2, 3}, slack, scratch));
    EXPECT_FALSE(simpleWithSlack(points.data(), 0, {0, 1, 2, 3}, slack, scratch)) << "(99, 99) first: folded onto itself";
}

} // namespace
} // namespace q3
