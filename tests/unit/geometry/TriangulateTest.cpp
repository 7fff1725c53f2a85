// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// geometry/mesh/Triangulate: triangulate() checked against an independent
// description of the region written here. For input whose contours do not
// cross: every triangle is counterclockwise with positive area, its corners
// are input points, the areas add up to the even-odd area of the contours
// (shoelace per contour, signed by its nesting depth), every centroid is
// inside the region, random sample points inside are covered by exactly one
// triangle and those outside by none, and the count is n + 2h - 2 (n
// vertices, h holes, Euler's formula for a triangulation without extra
// points). Random star-shaped polygons with star-shaped holes and islands
// (fixed seeds) drive a property test; hand-made cases cover convex
// polygons, repeated points, collinear runs, spikes and crossing input.

#include "geometry/mesh/Triangulate.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace q3::mesh {
namespace {

using glm::dvec2;
using glm::dvec3;
using Ring = std::vector<dvec2>;

double signedArea(const Ring& ring)
{
    double twice = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const dvec2& a = ring[i];
        const dvec2& b = ring[(i + 1) % ring.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return twice / 2;
}

// Even-odd crossing test for one ring.
bool insideRing(const Ring& ring, const dvec2& p)
{
    bool inside = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const dvec2& a = ring[i];
        const dvec2& b = ring[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside;
}

// A region as the caller describes it: contours, and the nesting depth of
// each (known by construction: 0 an outline, 1 a hole, 2 an island...).
struct Region {
    std::vector<Ring> contours;
    std::vector<int> depths;

    void add(Ring ring, int depth)
    {
        contours.push_back(std::move(ring));
        depths.push_back(depth);
    }

    bool contains(const dvec2& p) const
    {
        bool inside = false;
        for (const Ring& ring : contours)
            inside = inside != insideRing(ring, p);
        return inside;
    }

    double area() const
    {
        double sum = 0;
        for (std::size_t i = 0; i < contours.size(); ++i)
            sum += (depths[i] % 2 == 0 ? 1 : -1) * std::abs(signedArea(contours[i]));
        return sum;
    }

    /// n + 2h - 2 per outline with its holes: the triangle count of any
    /// triangulation without extra points.
    std::size_t eulerCount() const
    {
        std::size_t count = 0;
        for (std::size_t i = 0; i < contours.size(); ++i)
            count += depths[i] % 2 == 0 ? contours[i].size() - 2 : contours[i].size() + 2;
        return count;
    }

    std::vector<dvec2> points() const
    {
        std::vector<dvec2> all;
        for (const Ring& ring : contours)
            all.insert(all.end(), ring.begin(), ring.end());
        return all;
    }

    std::vector<std::size_t> starts() const
    {
        std::vector<std::size_t> starts;
        std::size_t at = 0;
        for (const Ring& ring : contours) {
            starts.push_back(at);
            at += ring.size();
        }
        return starts;
    }
};

double cross(const dvec2& o, const dvec2& a, const dvec2& b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

struct Expectation {
    bool exactCount = true; // n + 2h - 2 (general position)
    std::size_t samples = 200;
};

// Runs triangulate() on the region and checks everything the header
// promises for contours that do not cross.
void checkTriangulation(const Region& region, std::mt19937& rng, const Expectation& expect = {})
{
    const std::vector<dvec2> points = region.points();
    const std::vector<std::uint32_t> triangles = triangulate(points, region.starts());
    ASSERT_EQ(triangles.size() % 3, 0u);
    const std::size_t count = triangles.size() / 3;
    if (expect.exactCount)
        EXPECT_EQ(count, region.eulerCount());
    else
        EXPECT_LE(count, region.eulerCount());

    dvec2 low(1e300), high(-1e300);
    for (const dvec2& p : points) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    const double scale = std::max(high.x - low.x, high.y - low.y);
    double sum = 0;
    for (std::size_t t = 0; t < count; ++t) {
        for (int k = 0; k < 3; ++k)
            ASSERT_LT(triangles[3 * t + k], points.size());
        const dvec2& a = points[triangles[3 * t]];
        const dvec2& b = points[triangles[3 * t + 1]];
        const dvec2& c = points[triangles[3 * t + 2]];
        const double twice = cross(a, b, c);
        ASSERT_GT(twice, 0.0) << "triangle " << t << " is clockwise or degenerate";
        sum += twice / 2;
        const dvec2 centroid = (a + b + c) / 3.0;
        EXPECT_TRUE(region.contains(centroid)) << "triangle " << t << "'s centroid is outside";
    }
    EXPECT_NEAR(sum, region.area(), 1e-9 * scale * scale);

    // Random points: inside the region covered once, outside never (points
    // within a hair of a triangle side are skipped).
    std::uniform_real_distribution<double> ux(low.x, high.x), uy(low.y, high.y);
    const double hair = 1e-9 * scale;
    for (std::size_t s = 0; s < expect.samples; ++s) {
        const dvec2 p(ux(rng), uy(rng));
        int covering = 0;
        bool onSide = false;
        for (std::size_t t = 0; t < count && !onSide; ++t) {
            const dvec2& a = points[triangles[3 * t]];
            const dvec2& b = points[triangles[3 * t + 1]];
            const dvec2& c = points[triangles[3 * t + 2]];
            const double e[3] = {cross(a, b, p) / glm::length(b - a), cross(b, c, p) / glm::length(c - b),
                                 cross(c, a, p) / glm::length(a - c)};
            if (std::abs(e[0]) < hair || std::abs(e[1]) < hair || std::abs(e[2]) < hair)
                onSide = true;
            else if (e[0] > 0 && e[1] > 0 && e[2] > 0)
                ++covering;
        }
        if (onSide)
            continue;
        EXPECT_EQ(covering, region.contains(p) ? 1 : 0) << "at (" << p.x << ", " << p.y << ")";
    }
}

// ---- Random star-shaped regions ---------------------------------------------------------

struct Star {
    Ring ring;
    dvec2 centre;
    double core; // the disk of this radius about the centre is inside the ring
};

// A polygon star-shaped about `centre`: n vertices at jittered, increasing
// angles (each gap below pi, so the centre is inside) and random radii in
// [rmin, rmax]; started at a random vertex and in a random direction.
Star randomStar(std::mt19937& rng, const dvec2& centre, std::size_t n, double rmin, double rmax)
{
    std::uniform_real_distribution<double> jitter(-0.2, 0.2), radius(rmin, rmax), phase(0, 2 * M_PI);
    const double start = phase(rng);
    Star star{{}, centre, 1e300};
    for (std::size_t i = 0; i < n; ++i) {
        const double angle = start + 2 * M_PI * (double(i) + jitter(rng)) / double(n);
        const double r = radius(rng);
        star.ring.push_back(centre + r * dvec2(std::cos(angle), std::sin(angle)));
    }
    // The largest disk about the centre inside the ring: its distance to the
    // nearest side (the centre sees every side, the polygon being star-shaped).
    for (std::size_t i = 0; i < n; ++i) {
        const dvec2 a = star.ring[i], b = star.ring[(i + 1) % n];
        const double t = std::clamp(glm::dot(centre - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
        star.core = std::min(star.core, glm::length(a + t * (b - a) - centre));
    }
    std::rotate(star.ring.begin(), star.ring.begin() + std::uniform_int_distribution<std::size_t>(0, n - 1)(rng),
                star.ring.end());
    if (std::uniform_int_distribution<int>(0, 1)(rng) == 1)
        std::reverse(star.ring.begin(), star.ring.end());
    return star;
}

// An outline with up to three holes placed in disjoint disks inside its core,
// and in some holes an island inside the hole's core.
Region randomRegion(std::mt19937& rng, int maxHoles)
{
    std::uniform_int_distribution<std::size_t> vertices(3, 40);
    std::uniform_real_distribution<double> offset(-100, 100);
    Region region;
    const dvec2 centre(offset(rng), offset(rng));
    const Star outline = randomStar(rng, centre, vertices(rng), 10, 30);
    region.add(outline.ring, 0);
    const int holes = std::uniform_int_distribution<int>(0, maxHoles)(rng);
    const double phase = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
    for (int h = 0; h < holes; ++h) {
        // Hole disks: at distance rho from the centre, radius room, disjoint
        // from each other and inside the core.
        const double rho = holes == 1 ? 0.0 : 0.5 * outline.core;
        const double room = 0.9 * (holes == 1 ? 0.9 * outline.core
                                              : std::min(0.45 * outline.core, rho * std::sin(M_PI / holes)));
        const double angle = phase + 2 * M_PI * h / holes;
        const dvec2 at = centre + rho * dvec2(std::cos(angle), std::sin(angle));
        const Star hole = randomStar(rng, at, vertices(rng), 0.4 * room, room);
        region.add(hole.ring, 1);
        if (std::uniform_int_distribution<int>(0, 1)(rng) == 1) {
            const Star island = randomStar(rng, at, vertices(rng), 0.3 * hole.core, 0.8 * hole.core);
            region.add(island.ring, 2);
        }
    }
    // The contours in a random order: the depth comes from containment, not position.
    std::vector<std::size_t> order(region.contours.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    Region shuffled;
    for (std::size_t i : order)
        shuffled.add(region.contours[i], region.depths[i]);
    return shuffled;
}

TEST(Triangulate, RandomSimpleStarPolygons)
{
    std::mt19937 rng(20261124);
    for (int i = 0; i < 300; ++i) {
        SCOPED_TRACE("polygon " + std::to_string(i));
        checkTriangulation(randomRegion(rng, 0), rng);
        if (::testing::Test::HasFailure())
            return;
    }
}

TEST(Triangulate, RandomPolygonsWithHolesAndIslands)
{
    std::mt19937 rng(11);
    for (int i = 0; i < 300; ++i) {
        SCOPED_TRACE("region " + std::to_string(i));
        checkTriangulation(randomRegion(rng, 3), rng);
        if (::testing::Test::HasFailure())
            return;
    }
}

// ---- Hand-made cases ----------------------------------------------------------------------

TEST(Triangulate, ConvexPolygonsGiveNMinusTwoTriangles)
{
    std::mt19937 rng(3);
    for (std::size_t n = 3; n <= 64; ++n) {
        Region region;
        Ring ring;
        for (std::size_t i = 0; i < n; ++i) {
            const double angle = 2 * M_PI * double(i) / double(n);
            ring.push_back(dvec2(5 + 2 * std::cos(angle), -3 + std::sin(angle))); // an ellipse
        }
        region.add(ring, 0);
        SCOPED_TRACE("n = " + std::to_string(n));
        checkTriangulation(region, rng);
        std::reverse(region.contours[0].begin(), region.contours[0].end()); // clockwise input
        checkTriangulation(region, rng);
    }
}

TEST(Triangulate, SquareWithAHoleAndAnIslandInIt)
{
    std::mt19937 rng(4);
    Region region;
    region.add({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, 0);
    region.add({{2, 2}, {8, 2}, {8, 8}, {2, 8}}, 1); // counterclockwise too: Q3 reorients
    region.add({{4, 4}, {6, 4}, {6, 6}, {4, 6}}, 2);
    EXPECT_DOUBLE_EQ(region.area(), 100.0 - 36.0 + 4.0);
    EXPECT_EQ(region.eulerCount(), 10u);
    checkTriangulation(region, rng, {true, 2000});
}

TEST(Triangulate, TwoHolesBridgedToTheSameOutlineVertex)
{
    // Hole A's bridge runs from (14, -8) to the outline's corner (20, 7).
    // Hole B's ray to +x meets that bridge first, so its bridge goes to the
    // same corner, which is in the outline twice by then: only one copy's
    // wedge faces B (the other bridge would cross A's).
    std::mt19937 rng(12);
    Region region;
    region.add({{-16, 3}, {16, -18}, {20, 7}}, 0);
    region.add({{12, -8}, {14, -8}, {14, -6}, {12, -6}}, 1);
    region.add({{7, -2}, {9, -2}, {9, -1}, {7, -1}}, 1);
    EXPECT_DOUBLE_EQ(region.area(), 436.0);
    checkTriangulation(region, rng, {true, 2000});
}

TEST(Triangulate, SeparateOutlinesAreEachTriangulated)
{
    std::mt19937 rng(5);
    Region region;
    region.add({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0);
    region.add({{3, 0}, {3, 1}, {2, 1}, {2, 0}}, 0); // clockwise
    region.add({{0, 3}, {2, 3}, {1, 5}}, 0);
    checkTriangulation(region, rng, {true, 1000});
}

TEST(Triangulate, RepeatedPointsAreTolerated)
{
    std::mt19937 rng(6);
    // A concave L with every corner given twice or three times, and the
    // first point repeated at the end (an explicitly closed contour).
    const Ring ell{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
    Ring repeated;
    for (std::size_t i = 0; i < ell.size(); ++i)
        for (std::size_t k = 0; k <= i % 3; ++k)
            repeated.push_back(ell[i]);
    repeated.push_back(ell[0]);
    const std::vector<std::uint32_t> triangles = triangulate(repeated, {0});
    Region region;
    region.add(ell, 0);
    ASSERT_EQ(triangles.size(), 3 * (ell.size() - 2));
    double sum = 0;
    for (std::size_t t = 0; t < triangles.size(); t += 3) {
        const double twice = cross(repeated[triangles[t]], repeated[triangles[t + 1]], repeated[triangles[t + 2]]);
        EXPECT_GT(twice, 0.0);
        sum += twice / 2;
        EXPECT_TRUE(region.contains(
            (repeated[triangles[t]] + repeated[triangles[t + 1]] + repeated[triangles[t + 2]]) / 3.0));
    }
    EXPECT_DOUBLE_EQ(sum, 5.0);
}

TEST(Triangulate, CollinearRunsAndSpikesAreTolerated)
{
    std::mt19937 rng(7);
    // A square with extra points along every side.
    Region runs;
    runs.add({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1.5}, {3, 3}, {2, 3}, {0.5, 3}, {0, 3}, {0, 2}, {0, 1}}, 0);
    checkTriangulation(runs, rng, {false, 500});
    // The same with a hole whose sides have collinear runs too.
    runs.add({{1, 1}, {1, 1.5}, {1, 2}, {2, 2}, {2, 1}, {1.5, 1}}, 1);
    checkTriangulation(runs, rng, {false, 500});
    // A needle going out from the top side and back along itself: no area.
    const Ring spike{{0, 0}, {2, 0}, {2, 2}, {1, 2}, {1, 3}, {1, 2}, {0, 2}};
    const std::vector<std::uint32_t> triangles = triangulate(spike, {0});
    EXPECT_LE(triangles.size() / 3, spike.size() - 2);
    double sum = 0;
    for (std::size_t t = 0; t < triangles.size(); t += 3) {
        const double twice = cross(spike[triangles[t]], spike[triangles[t + 1]], spike[triangles[t + 2]]);
        EXPECT_GT(twice, 0.0);
        sum += twice / 2;
    }
    EXPECT_DOUBLE_EQ(sum, 4.0);
}

TEST(Triangulate, ContoursWithoutAreaAddNothing)
{
    EXPECT_TRUE(triangulate({}, {}).empty());
    EXPECT_TRUE(triangulate({{0, 0}, {1, 1}}, {0}).empty());
    EXPECT_TRUE(triangulate({{0, 0}, {1, 1}, {2, 2}, {3, 3}}, {0}).empty()); // collinear
    EXPECT_TRUE(triangulate({{1, 1}, {1, 1}, {1, 1}}, {0}).empty());        // one point
    // A square with a degenerate "hole" (two points, then a flat one) is the square.
    const std::vector<dvec2> points{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {2, 2}, {1, 2}, {1, 2}, {1, 3}};
    const std::vector<std::uint32_t> triangles = triangulate(points, {0, 4, 6});
    ASSERT_EQ(triangles.size(), 6u);
    for (std::uint32_t index : triangles)
        EXPECT_LT(index, 4u);
}

TEST(Triangulate, CrossingInputTerminatesWithAtMostNMinusTwoTriangles)
{
    // A bowtie, a pentagram drawn as one line, and random points in random order.
    const Ring bowtie{{0, 0}, {2, 2}, {2, 0}, {0, 2}};
    EXPECT_LE(triangulate(bowtie, {0}).size() / 3, 2u);
    Ring pentagram;
    for (int i = 0; i < 5; ++i)
        pentagram.push_back(dvec2(std::cos(M_PI / 2 + i * 4 * M_PI / 5), std::sin(M_PI / 2 + i * 4 * M_PI / 5)));
    EXPECT_LE(triangulate(pentagram, {0}).size() / 3, 3u);
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> coordinate(-1, 1);
    for (int i = 0; i < 300; ++i) {
        const std::size_t n = std::uniform_int_distribution<std::size_t>(3, 60)(rng);
        Ring ring(n);
        for (dvec2& p : ring)
            p = dvec2(coordinate(rng), coordinate(rng));
        const std::vector<std::uint32_t> triangles = triangulate(ring, {0});
        ASSERT_EQ(triangles.size() % 3, 0u);
        EXPECT_LE(triangles.size() / 3, n - 2) << "case " << i;
        for (std::uint32_t index : triangles)
            ASSERT_LT(index, n);
    }
}

// ---- Newell normal and projection -------------------------------------------------------

TEST(NewellNormal, IsTheUnitNormalFromWhichTheOutlineRunsCounterclockwise)
{
    const dvec3 square[4] = {{0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}};
    const dvec3 up = newellNormal(square, 4);
    EXPECT_NEAR(up.x, 0, 1e-15);
    EXPECT_NEAR(up.y, 0, 1e-15);
    EXPECT_NEAR(up.z, 1, 1e-15);
    const dvec3 reversed[4] = {square[3], square[2], square[1], square[0]};
    EXPECT_NEAR(newellNormal(reversed, 4).z, -1, 1e-15);
    // A tilted triangle: the normalized cross product of two sides.
    const dvec3 tri[3] = {{1, 0, 0}, {0, 2, 0}, {0, 0, 3}};
    const dvec3 expected = glm::normalize(glm::cross(tri[1] - tri[0], tri[2] - tri[0]));
    const dvec3 n = newellNormal(tri, 3);
    EXPECT_NEAR(n.x, expected.x, 1e-15);
    EXPECT_NEAR(n.y, expected.y, 1e-15);
    EXPECT_NEAR(n.z, expected.z, 1e-15);
    // No area: zero.
    const dvec3 line[3] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    EXPECT_EQ(newellNormal(line, 3), dvec3(0.0));
}

TEST(ProjectToPlane, IsAnIsometryThatKeepsCounterclockwiseOutlinesCounterclockwise)
{
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 50; ++i) {
        // A random plane and a star-shaped outline in it, counterclockwise about n.
        dvec3 n(u(rng), u(rng), u(rng));
        if (glm::length(n) < 0.1)
            continue;
        n = glm::normalize(n);
        if (i % 3 == 0) // axis-aligned normals too, either way
            n = dvec3(i % 2 ? 1.0 : -1.0, 0, 0);
        const dvec3 helper = std::abs(n.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
        const dvec3 e1 = glm::normalize(glm::cross(n, helper)), e2 = glm::cross(n, e1);
        const Star star = randomStar(rng, dvec2(0), 12, 1, 3);
        Ring ccw = star.ring;
        if (signedArea(ccw) < 0)
            std::reverse(ccw.begin(), ccw.end());
        const dvec3 origin(u(rng) * 10, u(rng) * 10, u(rng) * 10);
        std::vector<dvec3> outline;
        for (const dvec2& p : ccw)
            outline.push_back(origin + p.x * e1 + p.y * e2); // (e1, e2, n) is right-handed
        const std::vector<dvec2> flat = projectToPlane(outline.data(), outline.size(), n);
        ASSERT_EQ(flat.size(), outline.size());
        EXPECT_GT(signedArea(flat), 0.0);
        EXPECT_NEAR(signedArea(flat), signedArea(ccw), 1e-9);
        for (std::size_t a = 0; a < outline.size(); ++a)
            for (std::size_t b = a + 1; b < outline.size(); ++b)
                EXPECT_NEAR(glm::distance(flat[a], flat[b]), glm::distance(outline[a], outline[b]), 1e-9);
    }
}

// triangulateEvenOdd over contours that cross: a sample point is covered by
// exactly one triangle where an odd number of contours surround it (each
// contour's own crossing count, insideRing, which is even-odd for a
// self-intersecting ring too) and by none elsewhere; every triangle is
// counterclockwise; every added point lies on the side it names.
void expectEvenOdd(const std::vector<Ring>& contours, const std::string& what)
{
    std::vector<dvec2> points;
    std::vector<std::size_t> starts;
    for (const Ring& ring : contours) {
        starts.push_back(points.size());
        points.insert(points.end(), ring.begin(), ring.end());
    }
    const Triangulation result = triangulateEvenOdd(points, starts);
    std::vector<dvec2> all = points;
    for (const EdgePoint& e : result.added) {
        ASSERT_LT(e.a, points.size()) << what;
        ASSERT_LT(e.b, points.size()) << what;
        // Strictly inside in exact arithmetic; a crossing's level may round
        // to within an ulp of a vertex's.
        EXPECT_GE(e.t, 0.0) << what;
        EXPECT_LE(e.t, 1.0) << what;
        all.push_back(points[e.a] + (points[e.b] - points[e.a]) * e.t);
    }
    ASSERT_EQ(result.triangles.size() % 3, 0u) << what;
    for (std::size_t t = 0; t < result.triangles.size(); t += 3) {
        ASSERT_LT(result.triangles[t + 2], all.size()) << what;
        const dvec2 &a = all[result.triangles[t]], &b = all[result.triangles[t + 1]], &c = all[result.triangles[t + 2]];
        EXPECT_GT((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x), 0.0) << what << ": triangle " << t / 3;
    }
    double minX = 1e300, maxX = -1e300, minY = 1e300, maxY = -1e300;
    for (const dvec2& p : points) {
        minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
        minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
    }
    int inside = 0, wrong = 0;
    for (int i = 0; i < 97; ++i)
        for (int j = 0; j < 89; ++j) {
            // Off-grid samples (irrational steps), so none lies on a side.
            const dvec2 p(minX + (maxX - minX) * (i + 0.5 * std::sqrt(2.0) - 0.2) / 97.0,
                          minY + (maxY - minY) * (j + 0.5 * std::sqrt(3.0) - 0.4) / 89.0);
            bool in = false;
            for (const Ring& ring : contours)
                in = in != insideRing(ring, p);
            int covered = 0;
            for (std::size_t t = 0; t < result.triangles.size(); t += 3) {
                const dvec2 &a = all[result.triangles[t]], &b = all[result.triangles[t + 1]],
                            &c = all[result.triangles[t + 2]];
                const auto side = [&](const dvec2& u, const dvec2& v) {
                    return (v.x - u.x) * (p.y - u.y) - (v.y - u.y) * (p.x - u.x);
                };
                covered += side(a, b) > 0 && side(b, c) > 0 && side(c, a) > 0 ? 1 : 0;
            }
            inside += in ? 1 : 0;
            if (covered != (in ? 1 : 0) && wrong++ < 3)
                ADD_FAILURE() << what << ": sample (" << p.x << ", " << p.y << ") is covered " << covered
                              << " times, " << (in ? "inside" : "outside") << " by the even-odd rule";
        }
    EXPECT_GT(inside, 100) << what;
}

TEST(TriangulateEvenOdd, APentagramLeavesItsCentreEmpty)
{
    Ring star;
    for (int k = 0; k < 5; ++k) {
        const double angle = M_PI / 2 + k * 4 * M_PI / 5; // every second point of a pentagon
        star.push_back(dvec2(std::cos(angle), std::sin(angle)));
    }
    expectEvenOdd({star}, "pentagram");
    // The centre is inside the star's outline but crossed twice: a hole.
    std::vector<dvec2> points(star.begin(), star.end());
    const Triangulation result = triangulateEvenOdd(points, {0});
    EXPECT_FALSE(result.added.empty());
}

TEST(TriangulateEvenOdd, ABowTieFillsBothLoops)
{
    expectEvenOdd({{{0, 0}, {2, 1}, {2, 0}, {0, 1}}}, "bow tie");
}

TEST(TriangulateEvenOdd, OverlappingContoursCutTheirOverlapOut)
{
    expectEvenOdd({{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}}, "two squares");
    // Wound the other way round, the same region: the rule ignores direction.
    expectEvenOdd({{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{1, 3}, {3, 3}, {3, 1}, {1, 1}}}, "two squares, one reversed");
    // Three overlapping triangles: the part inside all three is filled again.
    expectEvenOdd({{{0, 0}, {4, 0}, {2, 3}}, {{0, 2}, {4, 2}, {2, -1}}, {{1, -1}, {3, -1}, {2, 4}}}, "three triangles");
}

TEST(TriangulateEvenOdd, ContoursThatDoNotCrossAreTriangulatedWithoutAddedPoints)
{
    const std::vector<dvec2> points = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {1, 3}, {3, 3}, {3, 1}};
    const Triangulation result = triangulateEvenOdd(points, {0, 4});
    EXPECT_TRUE(result.added.empty());
    EXPECT_EQ(result.triangles, triangulate(points, {0, 4}));
    expectEvenOdd({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {1, 3}, {3, 3}, {3, 1}}}, "square with a hole");
}

} // namespace
} // namespace q3::mesh
