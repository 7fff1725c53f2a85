// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The pure-math quadric tessellation (src/geometry/quadric) without a view:
// constant grids of known size, the measured method's edge bound under a
// mapping with and without a half-space that has no image, the triangle and
// segment caps, and the ellipse's polyline. The API-level properties (every
// shape, random frames, cameras) are in tests/regression/QuadricPropertyTest.

#include "geometry/quadric/Shapes.h"
#include "geometry/quadric/Tessellate.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace q3::quadric {
namespace {

constexpr double kTwoPi = 6.283185307179586;

RevolvedShape unitSphere()
{
    RevolvedShape s;
    s.origin = Vec3(0.0);
    s.orientation = Vec3(0, 0, 1);
    s.majorRadius = Vec3(1, 0, 0);
    s.minorRadius = Vec3(0, 1, 0);
    return s;
}

Subdivision constant(double c1, double c2)
{
    Subdivision s;
    s.method = Method::kConstant;
    s.c1 = c1;
    s.c2 = c2;
    return s;
}

Subdivision measured(double c1, Mapping map = [](const Vec3& p, Vec3& out) {
    out = p;
    return true;
})
{
    Subdivision s;
    s.method = Method::kMeasured;
    s.c1 = c1;
    s.map = std::move(map);
    return s;
}

template <class EdgeCheck>
void forEachEdge(const Tessellation& t, EdgeCheck check)
{
    for (std::size_t k = 0; k < t.triangles.size(); k += 3)
        for (int e = 0; e < 3; ++e)
            check(t.positions[t.triangles[k + e]], t.positions[t.triangles[k + (e + 1) % 3]]);
}

double longestEdge(const Tessellation& t)
{
    double longest = 0.0;
    forEachEdge(t, [&](const Vec3& a, const Vec3& b) { longest = std::max(longest, glm::distance(a, b)); });
    return longest;
}

void expectOnUnitSphere(const Tessellation& t)
{
    ASSERT_EQ(t.normals.size(), t.positions.size());
    for (std::size_t i = 0; i < t.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(t.positions[i]), 1.0, 1e-12);
        EXPECT_NEAR(glm::distance(t.normals[i], t.positions[i]), 0.0, 1e-9);
    }
}

// Constant: c1 segments around, c2 from pole to pole; the rows at the poles
// are single points, so the polar bands are fans: 8 x 2 quads (two
// triangles each) between the inner rows and 8 triangles at each pole.
TEST(QuadricTessellate, ConstantSphereIsAGridWithPolarFans)
{
    const Tessellation t = tessellate(ellipsoidPatches(unitSphere()), constant(8, 4));
    EXPECT_EQ(t.triangleCount(), 8u * 2u * 2u + 2u * 8u);
    EXPECT_FALSE(t.reduced);
    expectOnUnitSphere(t);
    // Counterclockwise seen from outside: every triangle's normal points out.
    for (std::size_t k = 0; k < t.triangles.size(); k += 3) {
        const Vec3 a = t.positions[t.triangles[k]], b = t.positions[t.triangles[k + 1]],
                   c = t.positions[t.triangles[k + 2]];
        EXPECT_GT(glm::dot(glm::cross(b - a, c - a), a + b + c), 0.0);
    }
}

TEST(QuadricTessellate, ConstantBoxIsTwelveTriangles)
{
    BoxShape box{Vec3(0.0), Vec3(0, 0, 2), Vec3(3, 0, 0), Vec3(0, 1, 0)};
    const Tessellation t = tessellate(boxPatches(box), constant(50, 50));
    EXPECT_EQ(t.triangleCount(), 12u);
    for (std::size_t i = 0; i < t.parts.size(); ++i)
        EXPECT_TRUE(t.parts[i] >= 0 && t.parts[i] < 6);
}

TEST(QuadricTessellate, MeasuredEdgesAreAtMostC1)
{
    for (double c1 : {1.5, 0.4, 0.05}) {
        const Tessellation t = tessellate(ellipsoidPatches(unitSphere()), measured(c1));
        EXPECT_LE(longestEdge(t), c1) << c1;
        EXPECT_EQ(t.unresolved, 0u);
        expectOnUnitSphere(t);
    }
    // However large c1 is, one segment per quarter turn: no triangle spans
    // more than a right angle of the sphere.
    const Tessellation coarse = tessellate(ellipsoidPatches(unitSphere()), measured(100.0));
    EXPECT_LE(longestEdge(coarse), std::sqrt(2.0) + 1e-9);
}

// Points with local z > 0.3 have no image. An edge with both ends imaged
// is at most c1; an edge with one end imaged, its imaged part (from that end
// to the plane) is; the part without an image is drawn coarsely.
TEST(QuadricTessellate, MeasuredEdgesCrossingTheHalfSpaceWithoutAnImage)
{
    const double c1 = 0.1;
    const Mapping map = [](const Vec3& p, Vec3& out) {
        out = p;
        return p.z <= 0.3;
    };
    const Tessellation t = tessellate(ellipsoidPatches(unitSphere()), measured(c1, map));
    forEachEdge(t, [&](const Vec3& a, const Vec3& b) {
        if (a.z <= 0.3 && b.z <= 0.3)
            EXPECT_LE(glm::distance(a, b), c1 * (1 + 1e-9));
        else if (a.z <= 0.3 || b.z <= 0.3) {
            const Vec3& in = a.z <= 0.3 ? a : b;
            const Vec3& out = a.z <= 0.3 ? b : a;
            const double s = (0.3 - in.z) / (out.z - in.z);
            EXPECT_LE(s * glm::distance(a, b), c1 * (1 + 1e-6));
        }
    });
    const Tessellation whole = tessellate(ellipsoidPatches(unitSphere()), measured(c1));
    EXPECT_LT(t.triangleCount(), whole.triangleCount() * 3 / 4);
    expectOnUnitSphere(t);
}

TEST(QuadricTessellate, TheTriangleCapCoarsensAndSaysSo)
{
    Subdivision fine = measured(1e-4);
    fine.maxTriangles = 4000;
    const Tessellation t = tessellate(ellipsoidPatches(unitSphere()), fine);
    EXPECT_TRUE(t.reduced);
    EXPECT_LE(t.triangleCount(), 4000u);
    EXPECT_GT(t.triangleCount(), 1000u);
    EXPECT_GT(t.effectiveC1, 1e-4);
    EXPECT_LE(longestEdge(t), t.effectiveC1 * (1 + 1e-9));

    Subdivision dense = constant(1024, 1024);
    dense.maxTriangles = 1000;
    const Tessellation c = tessellate(ellipsoidPatches(unitSphere()), dense);
    EXPECT_TRUE(c.reduced);
    EXPECT_LE(c.triangleCount(), 1000u);
    EXPECT_LT(c.effectiveC1, 1024.0);

    // A cap below the coarsest tessellation gives the coarsest. The measured
    // method gets there after at most kMaxDoublings doublings of c1 (each
    // attempt that runs over costs a whole cap), then one attempt at the
    // coarsest under the cap and the coarsest without it.
    for (Subdivision tiny : {measured(1e-3), constant(64, 64)}) {
        tiny.maxTriangles = 2;
        const Tessellation coarsest = tessellate(ellipsoidPatches(unitSphere()), tiny);
        EXPECT_TRUE(coarsest.reduced);
        EXPECT_GT(coarsest.triangleCount(), 2u);
        EXPECT_LE(coarsest.triangleCount(), 24u);
        if (tiny.method == Method::kMeasured)
            EXPECT_LE(coarsest.overruns, kMaxDoublings + 2);
    }

    const Tessellation plain = tessellate(ellipsoidPatches(unitSphere()), constant(16, 8));
    EXPECT_FALSE(plain.reduced);
    EXPECT_EQ(plain.effectiveC1, 16.0);
}

TEST(QuadricTessellate, AngularRangesWrapThroughZero)
{
    const Range wrapped = angularRange(0.75, 0.25);
    EXPECT_DOUBLE_EQ(wrapped.min, 0.75);
    EXPECT_DOUBLE_EQ(wrapped.max, 1.25);
    EXPECT_FALSE(wrapped.full());
    EXPECT_TRUE(angularRange(0.0, 1.0).full());
    // A half disk through angle 0: every point has x >= 0.
    DiskShape disk{Vec3(0.0), Vec3(1, 0, 0), Vec3(0, 1, 0), wrapped, Range{}};
    const Tessellation t = tessellate(diskPatches(disk), constant(16, 2));
    bool reachesBothEnds[2] = {false, false};
    for (const Vec3& p : t.positions) {
        EXPECT_GE(p.x, -1e-12);
        EXPECT_NEAR(p.z, 0.0, 1e-15);
        if (std::abs(p.x) < 1e-12 && std::abs(std::abs(p.y) - 1.0) < 1e-12)
            reachesBothEnds[p.y > 0.0] = true;
    }
    EXPECT_TRUE(reachesBothEnds[0] && reachesBothEnds[1]);
}

TEST(QuadricTessellate, EllipsePolylines)
{
    const EllipseShape circle{Vec3(0.0), Vec3(1, 0, 0), Vec3(0, 1, 0), Range{}};
    const auto curve = [&](double u) { return ellipsePoint(circle, u); };
    const Polyline constantLine = tessellateCurve(curve, 0.0, 1.0, true, constant(10, 1), 1 << 20);
    ASSERT_GE(constantLine.points.size(), 10u);
    EXPECT_EQ(constantLine.points.size(), 11u); // closed: the last point is the first
    EXPECT_NEAR(glm::distance(constantLine.points.front(), constantLine.points.back()), 0.0, 1e-12);

    const double c1 = 0.1;
    const Polyline measuredLine = tessellateCurve(curve, 0.0, 1.0, true, measured(c1), 1 << 20);
    const std::size_t segments = measuredLine.points.size() - 1;
    EXPECT_GE(segments, std::size_t(std::ceil(kTwoPi / c1)));
    EXPECT_LE(segments, std::size_t(std::ceil(kTwoPi / (c1 * (1 - kCurveTolerance)))) + 1);
    for (std::size_t i = 0; i < segments; ++i) {
        const double length = glm::distance(measuredLine.points[i], measuredLine.points[i + 1]);
        EXPECT_LE(length, c1 * (1 + 1e-9));
        if (i + 1 < segments)
            EXPECT_GE(length, c1 * (1 - kCurveTolerance) * (1 - 1e-9));
    }

    const Polyline capped = tessellateCurve(curve, 0.0, 1.0, true, measured(1e-6), 16);
    EXPECT_TRUE(capped.reduced);
    EXPECT_LE(capped.points.size(), 17u);
}

} // namespace
} // namespace q3::quadric
