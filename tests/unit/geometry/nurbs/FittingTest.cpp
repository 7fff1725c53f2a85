// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/Fitting.h"

#include "CurveToolsTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace q3::nurbs {
namespace {

// Random points along a wandering path (consecutive points apart).
std::vector<float> randomPoints(std::mt19937& rng, std::size_t count)
{
    std::uniform_real_distribution<double> step(-1.0, 1.0);
    std::vector<float> xyz;
    double x = 0, y = 0, z = 0;
    for (std::size_t i = 0; i < count; ++i) {
        x += 0.2 + step(rng);
        y += step(rng);
        z += 0.3 * step(rng);
        xyz.insert(xyz.end(), {float(x), float(y), float(z)});
    }
    return xyz;
}

// The parameters Fitting.h promises, computed here from the points.
std::vector<double> parameters(const std::vector<float>& xyz, Parameterization how)
{
    const std::size_t count = xyz.size() / 3;
    std::vector<double> u(count, 0.0);
    for (std::size_t i = 1; i < count; ++i) {
        const double dx = double(xyz[3 * i]) - xyz[3 * i - 3];
        const double dy = double(xyz[3 * i + 1]) - xyz[3 * i - 2];
        const double dz = double(xyz[3 * i + 2]) - xyz[3 * i - 1];
        const double chord = std::sqrt(dx * dx + dy * dy + dz * dz);
        u[i] = u[i - 1] + (how == Parameterization::kCentripetal ? std::sqrt(chord) : chord);
    }
    for (double& v : u)
        v /= u.back();
    return u;
}

double pointScale(const std::vector<float>& xyz)
{
    double scale = 1.0;
    for (float v : xyz)
        scale = std::max(scale, double(std::fabs(v)));
    return scale;
}

double squaredResidual(const HomogeneousCurve& curve, const std::vector<float>& xyz, const std::vector<double>& u)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i) {
        const Point3 p = test::referencePoint3(curve, u[i]);
        const Point3 d{p.x - xyz[3 * i], p.y - xyz[3 * i + 1], p.z - xyz[3 * i + 2]};
        sum += d.x * d.x + d.y * d.y + d.z * d.z;
    }
    return sum;
}

TEST(NurbsFitting, InterpolationPassesThroughEveryPointForEveryOrder)
{
    // The solve is backward stable; the interpolant of wandering points has control
    // points within a few times the points' size, so the residual at each point is a
    // few ulps of that size. 1e-9 is far inside the 1e-6.
    std::mt19937 rng(53);
    for (int trial = 0; trial < 150; ++trial) {
        const unsigned k = 2 + trial % 15;
        const std::size_t count = k + rng() % 30;
        const std::vector<float> xyz = randomPoints(rng, count);
        const Parameterization how = trial % 2 ? Parameterization::kCentripetal : Parameterization::kChordLength;
        const ToolResult<HomogeneousCurve> fit = fitPoints(k, xyz.data(), count, count, how);
        ASSERT_TRUE(fit.ok()) << fit.message;
        ASSERT_EQ(fit.value.points.size(), count);
        const std::vector<double> u = parameters(xyz, how);
        for (std::size_t i = 0; i < count; ++i) {
            const Point3 p = test::referencePoint3(fit.value, u[i]);
            EXPECT_NEAR(p.x, xyz[3 * i], 1e-9 * pointScale(xyz)) << "order " << k << " point " << i;
            EXPECT_NEAR(p.y, xyz[3 * i + 1], 1e-9 * pointScale(xyz));
            EXPECT_NEAR(p.z, xyz[3 * i + 2], 1e-9 * pointScale(xyz));
        }
        for (std::size_t i = 0; i < fit.value.knots.size(); ++i)
            EXPECT_EQ(fit.value.knots[i], double(float(fit.value.knots[i])));
    }
}

TEST(NurbsFitting, CubicKnotsAreTheLecturesParameters)
{
    // Lecture 6.5: T = {u1 x4, u3, ..., u_{N-2}, uN x4} (1-based), chord length.
    std::mt19937 rng(59);
    const std::vector<float> xyz = randomPoints(rng, 9);
    const ToolResult<HomogeneousCurve> fit = fitPoints(4, xyz.data(), 9, 9, Parameterization::kChordLength);
    ASSERT_TRUE(fit.ok());
    const std::vector<double> u = parameters(xyz, Parameterization::kChordLength);
    ASSERT_EQ(fit.value.knots.size(), 13u);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(fit.value.knots[i], 0.0);
        EXPECT_EQ(fit.value.knots[9 + i], 1.0);
    }
    for (int m = 0; m < 5; ++m)
        EXPECT_NEAR(fit.value.knots[4 + m], u[2 + m], 1e-7) << m;  // u_3 .. u_7, 1-based
}

TEST(NurbsFitting, LeastSquaresKeepsTheEndsAndMinimisesTheResidual)
{
    std::mt19937 rng(67);
    for (int trial = 0; trial < 120; ++trial) {
        const unsigned k = 2 + trial % 15;
        const std::size_t count = k + 5 + rng() % 40;
        const std::size_t controls = k + rng() % (count - k + 1);
        const std::vector<float> xyz = randomPoints(rng, count);
        const ToolResult<HomogeneousCurve> fit =
            fitPoints(k, xyz.data(), count, controls, Parameterization::kChordLength);
        ASSERT_TRUE(fit.ok()) << fit.message;
        const HomogeneousCurve& c = fit.value;
        ASSERT_EQ(c.points.size(), controls);
        EXPECT_EQ(c.points.front().x, xyz[0]);
        EXPECT_EQ(c.points.back().z, xyz[3 * count - 1]);
        const std::vector<double> u = parameters(xyz, Parameterization::kChordLength);
        const double best = squaredResidual(c, xyz, u);
        // Moving any inner control point makes the fit worse.
        for (int probe = 0; probe < 4 && controls > 2; ++probe) {
            HomogeneousCurve moved = c;
            const std::size_t i = 1 + rng() % (controls - 2);
            const double delta = 1e-3 * pointScale(xyz);
            (probe % 2 ? moved.points[i].x : moved.points[i].y) += probe < 2 ? delta : -delta;
            EXPECT_GE(squaredResidual(moved, xyz, u), best * (1 - 1e-12)) << "order " << k;
        }
    }
}

TEST(NurbsFitting, RejectsBadCountsAndPoints)
{
    const std::vector<float> xyz{0, 0, 0, 1, 0, 0, 2, 1, 0, 3, 0, 0, 4, 1, 0};
    const auto fit = [&](unsigned order, std::size_t count, std::size_t controls) {
        return fitPoints(order, xyz.data(), count, controls, Parameterization::kChordLength).error;
    };
    EXPECT_EQ(fit(1, 5, 5), ToolError::kOutOfRange);
    EXPECT_EQ(fit(17, 5, 5), ToolError::kOutOfRange);
    EXPECT_EQ(fit(4, 3, 3), ToolError::kTooFewPoints);
    EXPECT_EQ(fit(4, 5, 3), ToolError::kOutOfRange);
    EXPECT_EQ(fit(4, 5, 6), ToolError::kOutOfRange);
    EXPECT_EQ(fit(4, 5, std::size_t(-1)), ToolError::kOutOfRange);
    EXPECT_EQ(fit(4, kMaxToolPoints + 1, 5), ToolError::kOutOfRange);
    EXPECT_EQ(fit(4, 5, 4), ToolError::kNone);
    EXPECT_EQ(fit(2, 5, 2), ToolError::kNone);

    std::vector<float> repeated = xyz;
    repeated[6] = 1;
    repeated[7] = 0;
    EXPECT_EQ(fitPoints(3, repeated.data(), 5, 5, Parameterization::kCentripetal).error, ToolError::kInvalidArgument);
    std::vector<float> infinite = xyz;
    infinite[4] = INFINITY;
    EXPECT_EQ(fitPoints(3, infinite.data(), 5, 5, Parameterization::kCentripetal).error, ToolError::kNotFinite);
}

} // namespace
} // namespace q3::nurbs
