// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// evaluateGrid, the constant method's vector kernel: on random patches
// (orders 2 to 11, rational, repeated interior knots, a collapsed edge) every
// vertex equals, bit for bit, the scalar row evaluator's under each
// instruction set, and lies on the surface given by a recursive Cox-de Boor
// sum written here. Reusing a TessellatedSurface (the grid path overwrites
// the arrays without clearing them) gives what a fresh one gives.

#include "geometry/nurbs/SurfaceGrid.h"

#include "geometry/nurbs/Bezier.h"
#include "geometry/nurbs/SurfaceHull.h"
#include "geometry/nurbs/SurfaceTessellate.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace q3::nurbs {
namespace {

struct RandomPatch {
    unsigned uOrder = 2, vOrder = 2;
    std::size_t columns = 2, rows = 2;
    std::vector<float> points, uKnots, vKnots;

    SurfaceRef ref() const
    {
        return SurfaceRef{uOrder, vOrder, columns, rows, points.data(), uKnots.data(), vKnots.data()};
    }
};

std::vector<float> randomKnots(std::mt19937& rng, std::size_t count, unsigned order)
{
    // Clamped, a quarter of the interior knots repeated order - 1 times.
    std::vector<float> knots(order, 0.0f);
    const std::size_t interiorEnd = count - order;
    float t = 0.0f;
    std::uniform_real_distribution<float> step(0.2f, 1.5f);
    while (knots.size() < interiorEnd) {
        t += step(rng);
        const std::size_t run = std::min<std::size_t>(rng() % 4 == 0 ? order - 1 : 1, interiorEnd - knots.size());
        knots.insert(knots.end(), run, t);
    }
    t += step(rng);
    knots.insert(knots.end(), order, t);
    return knots;
}

RandomPatch randomPatch(std::mt19937& rng, bool collapseFirstRow, unsigned maxOrder = 11)
{
    std::uniform_int_distribution<unsigned> order(2, maxOrder);
    std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f), weight(0.3f, 3.0f);
    RandomPatch p;
    p.uOrder = order(rng);
    p.vOrder = order(rng);
    p.columns = p.uOrder + std::uniform_int_distribution<std::size_t>(0, 6)(rng);
    p.rows = p.vOrder + std::uniform_int_distribution<std::size_t>(0, 6)(rng);
    p.uKnots = randomKnots(rng, p.columns + p.uOrder, p.uOrder);
    p.vKnots = randomKnots(rng, p.rows + p.vOrder, p.vOrder);
    for (std::size_t r = 0; r < p.rows; ++r)
        for (std::size_t c = 0; c < p.columns; ++c) {
            const float w = weight(rng);
            float x = coordinate(rng), y = coordinate(rng), z = coordinate(rng);
            if (collapseFirstRow && r == 0)
                x = y = z = 0.5f; // a pole: du vanishes along v = v0
            for (float value : {x * w, y * w, z * w, w})
                p.points.push_back(value);
        }
    return p;
}

// N_{i,k}(t) by the article's recursion, 0/0 as 0, right-continuous except at
// the domain's end (the last span is closed).
double basis(const std::vector<float>& x, std::size_t i, unsigned k, double t, double end)
{
    if (k == 1) {
        if (x[i] < x[i + 1] && ((x[i] <= t && t < x[i + 1]) || (t == end && x[i + 1] == end)))
            return 1.0;
        return 0.0;
    }
    double sum = 0.0;
    if (x[i + k - 1] > x[i])
        sum += (t - x[i]) / (x[i + k - 1] - x[i]) * basis(x, i, k - 1, t, end);
    if (x[i + k] > x[i + 1])
        sum += (x[i + k] - t) / (x[i + k] - x[i + 1]) * basis(x, i + 1, k - 1, t, end);
    return sum;
}

void referencePoint(const RandomPatch& p, double u, double v, double out[3])
{
    const double uEnd = p.uKnots[p.columns], vEnd = p.vKnots[p.rows];
    double h[4] = {};
    for (std::size_t r = 0; r < p.rows; ++r) {
        const double bv = basis(p.vKnots, r, p.vOrder, v, vEnd);
        if (bv == 0.0)
            continue;
        for (std::size_t c = 0; c < p.columns; ++c) {
            const double b = bv * basis(p.uKnots, c, p.uOrder, u, uEnd);
            for (int k = 0; k < 4; ++k)
                h[k] += b * p.points[4 * (r * p.columns + c) + k];
        }
    }
    for (int k = 0; k < 3; ++k)
        out[k] = h[k] / h[3];
}

std::vector<double> samples(const std::vector<float>& knots, std::size_t count, unsigned order, unsigned perSpan)
{
    std::vector<double> t;
    for (std::size_t i = order - 1; i < count; ++i)
        if (knots[i] < knots[i + 1])
            for (unsigned j = 0; j < perSpan; ++j)
                t.push_back(knots[i] + (double(knots[i + 1]) - knots[i]) * j / perSpan);
    t.push_back(knots[count]);
    return t;
}

TEST(SurfaceGrid, EqualsTheScalarEvaluatorBitForBitAndLiesOnTheSurface)
{
    std::mt19937 rng(20261124);
    const KernelIsa original = activeKernelIsa();
    std::vector<KernelIsa> isas{KernelIsa::kBaseline};
    if (supportedKernelIsa() == KernelIsa::kAvx2)
        isas.push_back(KernelIsa::kAvx2);
    for (int trial = 0; trial < 60; ++trial) {
        const RandomPatch p = randomPatch(rng, trial % 5 == 0);
        const SurfaceRef s = p.ref();
        const std::vector<double> us = samples(p.uKnots, p.columns, p.uOrder, 3);
        const std::vector<double> vs = samples(p.vKnots, p.rows, p.vOrder, 2);
        const std::size_t count = us.size() * vs.size();
        // The scalar path, vertex by vertex.
        std::vector<float> expectedPositions, expectedNormals;
        SurfaceRowEvaluator row(s);
        for (double v : vs) {
            row.setV(v, true);
            for (double u : us) {
                const SurfacePoint q = row.pointWithNormal(u);
                for (double value : {q.point.x, q.point.y, q.point.z})
                    expectedPositions.push_back(float(value));
                for (double value : {q.normal.x, q.normal.y, q.normal.z})
                    expectedNormals.push_back(float(value));
            }
        }
        for (KernelIsa isa : isas) {
            ASSERT_TRUE(forceKernelIsa(isa));
            std::vector<float> positions(3 * count, -7.0f), normals(3 * count, -7.0f);
            evaluateGrid(s, us.data(), us.size(), vs.data(), vs.size(), positions.data(), normals.data());
            ASSERT_EQ(0, std::memcmp(positions.data(), expectedPositions.data(), positions.size() * sizeof(float)))
                << "trial " << trial << " isa " << int(isa);
            ASSERT_EQ(0, std::memcmp(normals.data(), expectedNormals.data(), normals.size() * sizeof(float)))
                << "trial " << trial << " isa " << int(isa);
        }
        // On the surface: the recursive sum, at a few vertices.
        for (std::size_t k = 0; k < count; k += 7) {
            const double u = us[k % us.size()], v = vs[k / us.size()];
            double reference[3];
            referencePoint(p, u, v, reference);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(expectedPositions[3 * k + c], reference[c], 1e-5 * (1.0 + std::fabs(reference[c])))
                    << "trial " << trial << " u " << u << " v " << v;
        }
    }
    forceKernelIsa(original);
}

TEST(SurfaceGrid, AReusedResultEqualsAFreshOne)
{
    std::mt19937 rng(7);
    const RandomPatch big = randomPatch(rng, false), small = randomPatch(rng, true);
    PatchRef bigPatch, smallPatch;
    bigPatch.surface = big.ref();
    smallPatch.surface = small.ref();
    TessellationOptions fine, coarse;
    fine.c1 = fine.c2 = 9;
    coarse.c1 = 2;
    coarse.c2 = 3;
    TessellatedSurface reused;
    tessellateSurface(bigPatch, fine, reused);
    tessellateSurface(smallPatch, coarse, reused);
    TessellatedSurface fresh;
    tessellateSurface(smallPatch, coarse, fresh);
    EXPECT_EQ(reused.positions, fresh.positions);
    EXPECT_EQ(reused.normals, fresh.normals);
    EXPECT_EQ(reused.uvs, fresh.uvs);
    EXPECT_EQ(reused.parameters, fresh.parameters);
    EXPECT_EQ(reused.triangles, fresh.triangles);
    EXPECT_EQ(reused.uSegments, 2u);
    EXPECT_EQ(reused.vSegments, 3u);
}

// SurfaceHull never calls a piece outside the view volume when a point of it
// (the recursive sum above, on a 6 x 6 grid over the rectangle) is inside
// the plane: on random patches, random projective maps and random
// rectangles; and it does call some pieces outside.
TEST(SurfaceHull, APieceCalledOutsideHasEveryPointOutsideOnePlaneAndOneCalledInsideNone)
{
    std::mt19937 rng(424242);
    std::uniform_real_distribution<double> unit(0.0, 1.0), entry(-1.0, 1.0);
    std::size_t outsideCount = 0, insideCount = 0, total = 0;
    for (int trial = 0; trial < 30; ++trial) {
        // Orders up to 6: the recursive sum costs 2^order per basis function.
        const RandomPatch p = randomPatch(rng, false, 6);
        std::array<double, 16> clip;
        for (double& value : clip)
            value = entry(rng);
        clip[15] += 2.0;
        const SurfaceHull hull(p.ref(), clip);
        const double uLo = p.uKnots[p.uOrder - 1], uHi = p.uKnots[p.columns];
        const double vLo = p.vKnots[p.vOrder - 1], vHi = p.vKnots[p.rows];
        for (int r = 0; r < 30; ++r) {
            double u0 = uLo + (uHi - uLo) * unit(rng), u1 = uLo + (uHi - uLo) * unit(rng);
            double v0 = vLo + (vHi - vLo) * unit(rng), v1 = vLo + (vHi - vLo) * unit(rng);
            if (r % 2 == 0) { // small rectangles too
                u1 = u0 + (u1 - u0) * 0.05;
                v1 = v0 + (v1 - v0) * 0.05;
            }
            if (u1 < u0)
                std::swap(u0, u1);
            if (v1 < v0)
                std::swap(v0, v1);
            // The five clip-plane values (inside where >= 0) of the surface
            // point at sample (i, j) of a 6 x 6 grid over the rectangle.
            const auto planeValues = [&](int i, int j) {
                double point[3];
                referencePoint(p, u0 + (u1 - u0) * i / 5.0, v0 + (v1 - v0) * j / 5.0, point);
                double f[4];
                for (int k = 0; k < 4; ++k)
                    f[k] = clip[4 * k] * point[0] + clip[4 * k + 1] * point[1] + clip[4 * k + 2] * point[2] +
                           clip[4 * k + 3];
                return std::array<double, 5>{f[3] + f[0], f[3] - f[0], f[3] + f[1], f[3] - f[1], -f[2]};
            };
            ++total;
            if (hull.inside(u0, u1, v0, v1)) {
                // Every point of the piece inside every plane, and so no
                // part of it outside one.
                ++insideCount;
                EXPECT_FALSE(hull.outside(u0, u1, v0, v1)) << "trial " << trial << " rectangle " << r;
                for (int i = 0; i <= 5; ++i)
                    for (int j = 0; j <= 5; ++j)
                        for (double value : planeValues(i, j))
                            EXPECT_GE(value, -1e-9) << "trial " << trial << " rectangle " << r;
            }
            if (!hull.outside(u0, u1, v0, v1))
                continue;
            ++outsideCount;
            unsigned common = 31u;
            for (int i = 0; i <= 5; ++i)
                for (int j = 0; j <= 5; ++j) {
                    const std::array<double, 5> values = planeValues(i, j);
                    for (unsigned plane = 0; plane < 5; ++plane)
                        if (!(values[plane] < 0.0))
                            common &= ~(1u << plane);
                }
            EXPECT_NE(common, 0u) << "trial " << trial << " rectangle " << r;
        }
    }
    EXPECT_GT(outsideCount, total / 20);
    EXPECT_LT(outsideCount, total);
    EXPECT_GT(insideCount, total / 20);
}

} // namespace
} // namespace q3::nurbs
