// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The geometric tests of picking (view/PickMath.h), each checked against an
// evaluator written here by another method: ray against triangle by
// intersecting the plane and solving for barycentric weights with Cramer's
// rule; closest approaches by dense sampling of the parameters; clipping by
// checking the depth range of the result; the rectangle overlap by sampling
// the shape and the rectangle's edges.

#include "view/PickMath.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace q3::pickmath {
namespace {

using glm::dvec2;
using glm::dvec3;
using glm::dvec4;

// The independent evaluator: where the ray meets the plane of abc, then the
// weights from the 2x2 system of dot products (Cramer's rule).
struct Reference {
    bool hit = false;
    double t = 0.0;
    double margin = 0.0; // how far inside (smallest weight), to skip edge cases
};

Reference reference(const dvec3& o, const dvec3& d, const dvec3& a, const dvec3& b, const dvec3& c)
{
    Reference r;
    const dvec3 n = glm::cross(b - a, c - a);
    const double denom = glm::dot(n, d);
    if (std::abs(denom) < 1e-9)
        return r;
    r.t = glm::dot(n, a - o) / denom;
    const dvec3 p = o + r.t * d;
    const dvec3 v0 = b - a, v1 = c - a, v2 = p - a;
    const double d00 = glm::dot(v0, v0), d01 = glm::dot(v0, v1), d11 = glm::dot(v1, v1);
    const double d20 = glm::dot(v2, v0), d21 = glm::dot(v2, v1);
    const double det = d00 * d11 - d01 * d01;
    const double u = (d11 * d20 - d01 * d21) / det;
    const double v = (d00 * d21 - d01 * d20) / det;
    r.margin = std::min({u, v, 1.0 - u - v});
    r.hit = r.margin >= 0.0 && r.t >= 0.0;
    return r;
}

TEST(PickMath, RayTriangleAgreesWithPlaneAndCramerEvaluator)
{
    std::mt19937 rng(1234);
    std::uniform_real_distribution<double> coord(-2.0, 2.0);
    int hits = 0, misses = 0;
    for (int i = 0; i < 5000; ++i) {
        const dvec3 a(coord(rng), coord(rng), coord(rng));
        const dvec3 b(coord(rng), coord(rng), coord(rng));
        const dvec3 c(coord(rng), coord(rng), coord(rng));
        const dvec3 o(coord(rng), coord(rng), coord(rng) + 4.0);
        // Half the rays aim near the triangle, so both outcomes are common.
        const dvec3 aim = (a + b + c) / 3.0 + 0.4 * dvec3(coord(rng), coord(rng), coord(rng));
        const dvec3 d = i % 2 == 0 ? glm::normalize(dvec3(coord(rng), coord(rng), -2.0 + 0.5 * coord(rng)))
                                   : glm::normalize(aim - o);
        const Reference want = reference(o, d, a, b, c);
        // Grazing cases are decided by rounding either way.
        if (std::abs(want.margin) < 1e-6 || std::abs(want.t) < 1e-6 ||
            glm::length(glm::cross(b - a, c - a)) < 1e-3)
            continue;
        const std::optional<TriangleHit> got = rayTriangle(o, d, a, b, c);
        ASSERT_EQ(got.has_value(), want.hit) << "case " << i;
        if (got) {
            ++hits;
            EXPECT_NEAR(got->t, want.t, 1e-7 * (1.0 + std::abs(want.t)));
            const dvec3 p = (1.0 - got->u - got->v) * a + got->u * b + got->v * c;
            EXPECT_LT(glm::distance(p, o + got->t * d), 1e-7);
        } else {
            ++misses;
        }
    }
    EXPECT_GT(hits, 500);
    EXPECT_GT(misses, 500);
}

TEST(PickMath, RayTriangleMissesBehindTheOriginAndParallel)
{
    const dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    EXPECT_FALSE(rayTriangle(dvec3(0.2, 0.2, 1), dvec3(0, 0, 1), a, b, c));
    EXPECT_TRUE(rayTriangle(dvec3(0.2, 0.2, 1), dvec3(0, 0, -1), a, b, c));
    EXPECT_FALSE(rayTriangle(dvec3(0.2, 0.2, 0), dvec3(1, 0, 0), a, b, c));
    EXPECT_FALSE(rayTriangle(dvec3(0.2, 0.2, 1), dvec3(0, 0, -1), a, a, c)); // no area
    // The edges count as inside.
    EXPECT_TRUE(rayTriangle(dvec3(0.5, 0.0, 1), dvec3(0, 0, -1), a, b, c));
}

TEST(PickMath, RayAndSegmentApproachMatchesSampling)
{
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> coord(-3.0, 3.0);
    for (int i = 0; i < 300; ++i) {
        const dvec3 o(coord(rng), coord(rng), coord(rng));
        const dvec3 d = glm::normalize(dvec3(coord(rng), coord(rng), coord(rng)));
        const dvec3 a(coord(rng), coord(rng), coord(rng));
        const dvec3 b(coord(rng), coord(rng), coord(rng));
        // Sampling: s over the segment, and for each s the exact best t >= 0.
        double best = 1e300;
        for (int k = 0; k <= 4000; ++k) {
            const dvec3 q = a + (k / 4000.0) * (b - a);
            const double t = std::max(0.0, glm::dot(q - o, d));
            best = std::min(best, glm::distance(o + t * d, q));
        }
        const Approach got = raySegment(o, d, a, b);
        EXPECT_LE(got.distance, best + 1e-9) << "case " << i;
        EXPECT_NEAR(got.distance, best, 2e-3) << "case " << i;
        EXPECT_GE(got.t, 0.0);
        EXPECT_GE(got.s, 0.0);
        EXPECT_LE(got.s, 1.0);
        EXPECT_NEAR(glm::distance(o + got.t * d, a + got.s * (b - a)), got.distance, 1e-9);

        const Approach point = rayPoint(o, d, a);
        double pointBest = 1e300;
        for (int k = 0; k <= 4000; ++k)
            pointBest = std::min(pointBest, glm::distance(o + (k / 400.0) * d, a));
        EXPECT_LE(point.distance, pointBest + 1e-9);
        EXPECT_NEAR(point.distance, pointBest, 2e-3);
    }
}

TEST(PickMath, PointSegmentDistanceIn2D)
{
    EXPECT_DOUBLE_EQ(pointSegment2D(dvec2(5, 3), dvec2(0, 0), dvec2(10, 0)).distance, 3.0);
    EXPECT_DOUBLE_EQ(pointSegment2D(dvec2(5, 3), dvec2(0, 0), dvec2(10, 0)).s, 0.5);
    EXPECT_DOUBLE_EQ(pointSegment2D(dvec2(-3, 4), dvec2(0, 0), dvec2(10, 0)).distance, 5.0);
    EXPECT_DOUBLE_EQ(pointSegment2D(dvec2(-3, 4), dvec2(0, 0), dvec2(10, 0)).s, 0.0);
    EXPECT_DOUBLE_EQ(pointSegment2D(dvec2(1, 1), dvec2(2, 2), dvec2(2, 2)).distance, std::sqrt(2.0));
}

TEST(PickMath, ClippedSegmentStaysInTheDepthRangeAndOnTheLine)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-2.0, 2.0);
    int kept = 0, dropped = 0;
    for (int i = 0; i < 2000; ++i) {
        const dvec4 a(coord(rng), coord(rng), coord(rng), 1.0 + 0.5 * coord(rng));
        const dvec4 b(coord(rng), coord(rng), coord(rng), 1.0 + 0.5 * coord(rng));
        ClipVertex ca{a, 0.0}, cb{b, 1.0};
        // Reference: sample the segment for a point inside the region.
        bool anyInside = false;
        for (int k = 0; k <= 1000 && !anyInside; ++k) {
            const dvec4 p = a + (k / 1000.0) * (b - a);
            anyInside = p.w > 1e-9 && p.z <= 0.0 && p.z >= -p.w;
        }
        const bool got = clipSegment(ca, cb);
        if (anyInside)
            EXPECT_TRUE(got) << "case " << i;
        if (!got) {
            ++dropped;
            continue;
        }
        ++kept;
        for (const ClipVertex& v : {ca, cb}) {
            EXPECT_GT(v.clip.w, 0.0);
            EXPECT_LE(v.clip.z, 1e-12);
            EXPECT_GE(v.clip.z + v.clip.w, -1e-12);
            const dvec4 on = a + v.s * (b - a);
            EXPECT_LT(glm::length(on - v.clip), 1e-9);
        }
    }
    EXPECT_GT(kept, 100);
    EXPECT_GT(dropped, 100);
}

TEST(PickMath, ClippedPolygonLiesInTheDepthRange)
{
    std::vector<dvec4> triangle = {dvec4(0, 0, 0.5, 1), dvec4(1, 0, -0.5, 1), dvec4(0, 1, -2.0, 1)};
    clipPolygon(triangle);
    ASSERT_GE(triangle.size(), 3u);
    for (const dvec4& v : triangle) {
        EXPECT_LE(v.z, 1e-12);
        EXPECT_GE(v.z + v.w, -1e-12);
    }
    std::vector<dvec4> behind = {dvec4(0, 0, 0.5, 1), dvec4(1, 0, 0.5, 1), dvec4(0, 1, 0.5, 1)};
    clipPolygon(behind);
    EXPECT_TRUE(behind.empty());
}

TEST(PickMath, ScreenParameterMapsToTheHomogeneousPoint)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        const dvec4 a(unit(rng), unit(rng), -unit(rng), 0.5 + unit(rng));
        const dvec4 b(unit(rng), unit(rng), -unit(rng), 0.5 + unit(rng));
        const double sigma = unit(rng);
        const dvec2 sa(a.x / a.w, a.y / a.w), sb(b.x / b.w, b.y / b.w);
        const dvec2 screen = sa + sigma * (sb - sa);
        const double s = screenToHomogeneous(sigma, a.w, b.w);
        const dvec4 h = a + s * (b - a);
        EXPECT_NEAR(h.x / h.w, screen.x, 1e-12);
        EXPECT_NEAR(h.y / h.w, screen.y, 1e-12);
    }
}

// Reference overlap: a point of the shape (sampled densely over its area or
// length) in the rectangle, or a rectangle corner inside the shape.
bool sampledOverlap(const std::vector<dvec2>& shape, const dvec2& lo, const dvec2& hi)
{
    auto inRect = [&](const dvec2& p) { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; };
    const int n = 120;
    if (shape.size() == 3) {
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const dvec2 p = shape[0] + (i / double(n)) * (shape[1] - shape[0]) +
                                (j / double(n)) * (shape[2] - shape[0]);
                if (inRect(p))
                    return true;
            }
        return false;
    }
    for (int i = 0; i <= 10 * n; ++i)
        if (inRect(shape[0] + (i / (10.0 * n)) * (shape.back() - shape[0])))
            return true;
    return false;
}

TEST(PickMath, ConvexOverlapAgreesWithSampling)
{
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> coord(0.0, 10.0);
    int overlaps = 0, separate = 0;
    for (int i = 0; i < 1500; ++i) {
        const std::size_t count = 2 + i % 2;
        std::vector<dvec2> shape;
        for (std::size_t k = 0; k < count; ++k)
            shape.emplace_back(coord(rng), coord(rng));
        dvec2 lo(coord(rng), coord(rng));
        dvec2 hi = lo + dvec2(0.5 + 0.2 * coord(rng), 0.5 + 0.2 * coord(rng));
        const bool want = sampledOverlap(shape, lo, hi);
        const bool got = convexOverlapsRect(shape.data(), shape.size(), lo, hi);
        // Sampling can miss a sliver of overlap, never invent one.
        if (want)
            EXPECT_TRUE(got) << "case " << i;
        else if (got) {
            // Shrunk by a margin, a true overlap the samples missed is gone.
            const dvec2 margin(0.2, 0.2);
            EXPECT_FALSE(convexOverlapsRect(shape.data(), shape.size(), lo + margin, hi - margin)) << "case " << i;
        }
        (got ? overlaps : separate) += 1;
    }
    EXPECT_GT(overlaps, 100);
    EXPECT_GT(separate, 100);
    const dvec2 point(3, 3);
    EXPECT_TRUE(convexOverlapsRect(&point, 1, dvec2(3, 3), dvec2(4, 4)));
    EXPECT_FALSE(convexOverlapsRect(&point, 1, dvec2(3.1, 3), dvec2(4, 4)));
}

} // namespace
} // namespace q3::pickmath
