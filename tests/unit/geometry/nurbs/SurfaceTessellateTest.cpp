// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The surface tessellator on its own (no view): the mesh it makes is a valid
// triangulation of the kept part of the domain (every triangle
// counterclockwise in (u, v), every interior edge shared by exactly two
// triangles, the triangles' parameter area equal to the region's), edges obey
// the bound, the constant method's counts, trim loops that cross are refused.
// The full guarantees are checked through the public API against a reference
// evaluator in tests/regression/NURBPatchPropertyRegressionTest.cpp.

#include "geometry/nurbs/SurfaceTessellate.h"

#include "geometry/nurbs/Evaluate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace q3::nurbs {
namespace {

// A patch owning its arrays.
struct TestPatch {
    unsigned uOrder = 2, vOrder = 2;
    std::size_t columns = 2, rows = 2;
    std::vector<float> points;
    std::vector<float> uKnots, vKnots;
    std::vector<std::vector<std::vector<float>>> loopPoints; // per loop, per curve: x y w
    std::vector<std::vector<std::vector<float>>> loopKnots;
    std::vector<std::vector<unsigned>> loopOrders;

    PatchRef ref() const
    {
        PatchRef r;
        r.surface = SurfaceRef{uOrder, vOrder, columns, rows, points.data(), uKnots.data(), vKnots.data()};
        for (std::size_t l = 0; l < loopPoints.size(); ++l) {
            r.loops.emplace_back();
            for (std::size_t c = 0; c < loopPoints[l].size(); ++c)
                r.loops.back().push_back(TrimCurveRef{loopOrders[l][c], loopPoints[l][c].size() / 3,
                                                      loopPoints[l][c].data(), loopKnots[l][c].data()});
        }
        return r;
    }

    // A closed polygon as a loop of straight (order 2) curves, one per side.
    void addPolygon(const std::vector<std::pair<float, float>>& corners)
    {
        loopPoints.emplace_back();
        loopKnots.emplace_back();
        loopOrders.emplace_back();
        for (std::size_t i = 0; i < corners.size(); ++i) {
            const auto& a = corners[i];
            const auto& b = corners[(i + 1) % corners.size()];
            loopPoints.back().push_back({a.first, a.second, 1, b.first, b.second, 1});
            loopKnots.back().push_back({0, 0, 1, 1});
            loopOrders.back().push_back(2);
        }
    }

    // A circle of radius r around (cx, cy) as one rational quadratic curve of
    // four quarter arcs (w = sqrt(2)/2 at the corners), counterclockwise
    // unless `clockwise`.
    void addCircle(float cx, float cy, float r, bool clockwise)
    {
        const float s = 0.70710678f;
        std::vector<std::pair<float, float>> pts = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1},
                                                    {1, -1}, {1, 0}};
        if (clockwise)
            std::reverse(pts.begin(), pts.end());
        std::vector<float> xyw;
        for (std::size_t i = 0; i < pts.size(); ++i) {
            const float w = i % 2 == 1 ? s : 1.0f;
            xyw.insert(xyw.end(), {(cx + r * pts[i].first) * w, (cy + r * pts[i].second) * w, w});
        }
        loopPoints.push_back({xyw});
        loopKnots.push_back({{0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4}});
        loopOrders.push_back({3});
    }
};

// A bilinear-in-knots bicubic bump over [0, 1]^2, 4 x 4 control points.
TestPatch bump()
{
    TestPatch p;
    p.uOrder = p.vOrder = 4;
    p.columns = p.rows = 4;
    for (std::size_t r = 0; r < 4; ++r)
        for (std::size_t c = 0; c < 4; ++c) {
            const float z = (r == 1 || r == 2) && (c == 1 || c == 2) ? 1.5f : 0.0f;
            p.points.insert(p.points.end(), {float(c), float(r), z, 1.0f});
        }
    p.uKnots = {0, 0, 0, 0, 1, 1, 1, 1};
    p.vKnots = {0, 0, 0, 0, 1, 1, 1, 1};
    return p;
}

const PointMapping kIdentity = [](const Point3& p, Point3& out) {
    out = p;
    return true;
};

// The patch tessellated adaptively to world-space edges of at most c1 (the
// identity mapping).
TessellatedSurface adaptive(const TestPatch& p, double c1)
{
    TessellationOptions how;
    how.method = Method::kAdaptive;
    how.c1 = c1;
    how.customMapping = kIdentity;
    TessellatedSurface s;
    tessellateSurface(p.ref(), how, s);
    return s;
}

double length(const TessellatedSurface& s, std::uint32_t a, std::uint32_t b)
{
    const float* p = &s.positions[3 * a];
    const float* q = &s.positions[3 * b];
    return std::sqrt(double(p[0] - q[0]) * (p[0] - q[0]) + double(p[1] - q[1]) * (p[1] - q[1]) +
                     double(p[2] - q[2]) * (p[2] - q[2]));
}

// Valid triangulation: counterclockwise in (u, v), each directed edge once,
// each undirected edge in at most two triangles. Returns the (u, v) area.
double expectValidMesh(const TessellatedSurface& s)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    double area = 0.0;
    for (std::size_t t = 0; t < s.triangleCount(); ++t) {
        const std::uint32_t* v = &s.triangles[3 * t];
        const double* a = &s.parameters[2 * v[0]];
        const double* b = &s.parameters[2 * v[1]];
        const double* c = &s.parameters[2 * v[2]];
        const double twice = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        EXPECT_GT(twice, -1e-12) << "triangle " << t << " is clockwise in (u, v)";
        area += twice / 2;
        for (int k = 0; k < 3; ++k) {
            const std::pair<std::uint32_t, std::uint32_t> edge(v[k], v[(k + 1) % 3]);
            EXPECT_EQ(++directed[edge], 1) << "directed edge used twice";
        }
    }
    return area;
}

TEST(SurfaceTessellate, ConstantGivesTwoTrianglesPerCellAndCoversTheDomain)
{
    const TestPatch p = bump();
    TessellationOptions how;
    how.c1 = 7;
    how.c2 = 5;
    TessellatedSurface s;
    tessellateSurface(p.ref(), how, s);
    EXPECT_EQ(s.triangleCount(), 2u * 7 * 5);
    EXPECT_EQ(s.vertexCount(), 8u * 6);
    EXPECT_NEAR(expectValidMesh(s), 1.0, 1e-12);
    EXPECT_FALSE(s.substituted);
}

TEST(SurfaceTessellate, WorldSpaceEdgesAreWithinTheBound)
{
    const TestPatch p = bump();
    const TessellatedSurface s = adaptive(p, 0.1);
    EXPECT_NEAR(expectValidMesh(s), 1.0, 1e-12);
    double longest = 0.0;
    for (std::size_t t = 0; t < s.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k)
            longest = std::max(longest, length(s, s.triangles[3 * t + k], s.triangles[3 * t + (k + 1) % 3]));
    EXPECT_LE(longest, 0.1 * (1 + 1e-6));
    EXPECT_FALSE(s.capped);
    double area = 0.0;
    std::vector<int> histogram(10, 0);
    for (std::size_t t = 0; t < s.triangleCount(); ++t) {
        const float* a = &s.positions[3 * s.triangles[3 * t]];
        const float* b = &s.positions[3 * s.triangles[3 * t + 1]];
        const float* c = &s.positions[3 * s.triangles[3 * t + 2]];
        const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double x = ab[1] * ac[2] - ab[2] * ac[1], y = ab[2] * ac[0] - ab[0] * ac[2], z = ab[0] * ac[1] - ab[1] * ac[0];
        area += 0.5 * std::sqrt(x * x + y * y + z * z);
        for (int k = 0; k < 3; ++k)
            histogram[std::min(9, int(10 * length(s, s.triangles[3 * t + k], s.triangles[3 * t + (k + 1) % 3]) / 0.1))]++;
    }
    std::printf("[ patches ] bump, c1 = 0.1: %zu triangles, %zu vertices, longest edge %.5f, ratio %.3f\n", s.triangleCount(),
                s.vertexCount(), longest, s.triangleCount() / (area / (0.4330127 * 0.01)));
    for (int h : histogram) std::printf(" %d", h);
    std::printf("\n");
}

TEST(SurfaceTessellate, AHoleAndAnIslandKeepTheRightArea)
{
    TestPatch p = bump();
    p.addPolygon({{0.1f, 0.1f}, {0.9f, 0.1f}, {0.9f, 0.9f}, {0.1f, 0.9f}}); // outer, counterclockwise
    p.addCircle(0.5f, 0.5f, 0.3f, true);                                    // hole
    p.addCircle(0.5f, 0.5f, 0.1f, false);                                   // island
    const TessellatedSurface s = adaptive(p, 0.05);
    ASSERT_FALSE(s.crossing);
    const double pi = 3.14159265358979;
    const double expected = 0.64 - pi * 0.09 + pi * 0.01;
    EXPECT_NEAR(expectValidMesh(s), expected, 0.01);
    std::printf("[ patches ] trimmed bump: %zu triangles\n", s.triangleCount());
}

TEST(SurfaceTessellate, ALoneClockwiseLoopCutsAHole)
{
    TestPatch p = bump();
    p.addPolygon({{0.25f, 0.25f}, {0.25f, 0.75f}, {0.75f, 0.75f}, {0.75f, 0.25f}});
    TessellationOptions how;
    how.c1 = how.c2 = 8;
    TessellatedSurface s;
    tessellateSurface(p.ref(), how, s);
    EXPECT_NEAR(expectValidMesh(s), 0.75, 1e-9);
}

TEST(SurfaceTessellate, CrossingLoopsAreRefused)
{
    TestPatch p = bump();
    p.addPolygon({{0.1f, 0.1f}, {0.6f, 0.1f}, {0.6f, 0.6f}, {0.1f, 0.6f}});
    p.addPolygon({{0.4f, 0.4f}, {0.9f, 0.4f}, {0.9f, 0.9f}, {0.4f, 0.9f}});
    TessellationOptions how;
    how.c1 = how.c2 = 4;
    TessellatedSurface s;
    tessellateSurface(p.ref(), how, s);
    EXPECT_TRUE(s.crossing);
    EXPECT_EQ(s.triangleCount(), 0u);
}

} // namespace
} // namespace q3::nurbs
