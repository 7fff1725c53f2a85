// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Interpolation and least-squares approximation of points (see Fitting.h for the
// choices of parameters and knots).
//
// The lecture (6.5) interpolates N points with a cubic by requiring
// R(u_j) = sum_i R_i B_{i,4}(u_j) = P_j (eq. 6.26), a banded system. Here the same
// equations are set up for any order and any number n <= N of control points; with
// R_0 = P_0 and R_{n-1} = P_{N-1} fixed (a clamped curve passes through its end
// control points) the remaining n - 2 unknowns minimise
//   sum_j |P_j - N_0(u_j) P_0 - N_{n-1}(u_j) P_{N-1} - sum_{i=1}^{n-2} N_i(u_j) R_i|^2
// over the points j = 1 .. N-2, which is Piegl & Tiller's formulation (The NURBS
// Book, section 9.4.1). Each row has at most k nonzero entries, in consecutive
// columns that never move left from one row to the next (the parameters increase),
// so a Givens rotation folds each row into an upper triangular band of width k.
// With n = N the system is square and the least-squares solution interpolates.
//
// The rows and their solution are BandedLeastSquares'.

#include "geometry/nurbs/Fitting.h"

#include "geometry/nurbs/BandedLeastSquares.h"
#include "geometry/nurbs/CurveAccess.h"
#include "geometry/nurbs/Knots.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace q3::nurbs {
namespace {

Point3 pointAt(const float* xyz, std::size_t i)
{
    return Point3{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
}

} // namespace

ToolResult<bool> checkFitSizes(unsigned long order, std::size_t numPoints, std::size_t numControlPoints)
{
    if (order < kMinOrder || order > kMaxOrder)
        return toolFailure<bool>(ToolError::kOutOfRange,
                                 formatMessage("order %lu is outside %u..%u", order, kMinOrder, kMaxOrder));
    if (numPoints < order)
        return toolFailure<bool>(ToolError::kTooFewPoints,
                                 formatMessage("%zu points is fewer than the order %lu", numPoints, order));
    if (numPoints > kMaxToolPoints)
        return toolFailure<bool>(ToolError::kOutOfRange,
                                 formatMessage("%zu points is more than Q3's limit of %zu", numPoints, kMaxToolPoints));
    if (numControlPoints < order || numControlPoints > numPoints)
        return toolFailure<bool>(ToolError::kOutOfRange,
                                 formatMessage("%zu control points is outside the order %lu to the number of "
                                               "points %zu",
                                               numControlPoints, order, numPoints));
    return toolValue(true);
}

ToolResult<HomogeneousCurve> fitPoints(unsigned order, const float* xyz, std::size_t numPoints,
                                       std::size_t numControlPoints, Parameterization how)
{
    const std::size_t N = numPoints;
    const std::size_t n = numControlPoints;
    const ToolResult<bool> sizes = checkFitSizes(order, N, n);
    if (!sizes.ok())
        return toolFailure<HomogeneousCurve>(sizes);
    for (std::size_t i = 0; i < 3 * N; ++i)
        if (!std::isfinite(xyz[i]))
            return toolFailure<HomogeneousCurve>(
                ToolError::kNotFinite,
                formatMessage("point %zu has a coordinate that is %g; points must be finite", i / 3, double(xyz[i])));

    // Parameters.
    std::vector<double> u(N, 0.0);
    for (std::size_t i = 1; i < N; ++i) {
        const double chord = access::length3(access::sub3(pointAt(xyz, i), pointAt(xyz, i - 1)));
        if (chord == 0.0)
            return toolFailure<HomogeneousCurve>(
                ToolError::kInvalidArgument,
                formatMessage("points %zu and %zu are both (%g, %g, %g); consecutive points must differ", i - 1, i,
                              double(xyz[3 * i]), double(xyz[3 * i + 1]), double(xyz[3 * i + 2])));
        u[i] = u[i - 1] + (how == Parameterization::kCentripetal ? std::sqrt(chord) : chord);
    }
    const double total = u[N - 1];
    for (std::size_t i = 1; i < N; ++i) {
        u[i] = i + 1 == N ? 1.0 : u[i] / total;
        if (!(u[i] > u[i - 1]))
            return toolFailure<HomogeneousCurve>(
                ToolError::kDegenerate,
                formatMessage("points %zu and %zu are too close together, compared with the whole polyline, for "
                              "their parameters to differ",
                              i - 1, i));
    }

    // Knots, rounded to float.
    const unsigned p = order - 1;
    HomogeneousCurve curve;
    curve.order = order;
    curve.knots.assign(order, 0.0);
    const double step = double(N - order + 1) / double(n - order + 1);
    for (std::size_t m = 1; m + order <= n; ++m) {
        const double s = 0.5 * double(order - 2) + double(m) * step;
        const std::size_t i = std::min(std::size_t(s), N - 2);
        const double f = s - double(i);
        const double value = f == 0.0 ? u[i] : (1.0 - f) * u[i] + f * u[i + 1];
        const double rounded = double(float(value));
        if (!(rounded > curve.knots.back() && rounded < 1.0))
            return toolFailure<HomogeneousCurve>(
                ToolError::kDegenerate,
                formatMessage("interior knots %zu and %zu of the fitted curve would both be %.9g in float; the points "
                              "are too unevenly spaced for %zu control points",
                              m - 1, m, rounded, n));
        curve.knots.push_back(rounded);
    }
    curve.knots.resize(n + order, 1.0);

    // The banded system for R_1 .. R_{n-2}.
    const Point3 first = pointAt(xyz, 0);
    const Point3 last = pointAt(xyz, N - 1);
    const double firstValue[3] = {first.x, first.y, first.z};
    const double lastValue[3] = {last.x, last.y, last.z};
    BandedLeastSquares system(n - 2, order, 3);
    double basis[kMaxOrder];
    std::size_t l = p;
    for (std::size_t j = 1; j + 1 < N; ++j) {
        while (l + 1 < n && !(u[j] < curve.knots[l + 1]))
            ++l;
        basisFunctionsOnSpan(curve.knots, l, p, u[j], basis);
        const Point3 d = pointAt(xyz, j);
        const double value[3] = {d.x, d.y, d.z};
        system.addCurveRow(l, p, basis, n, value, firstValue, lastValue);
    }
    std::vector<double> inner;
    if (!system.solve(inner))
        return toolFailure<HomogeneousCurve>(
            ToolError::kDegenerate,
            formatMessage("the %zu points do not determine a curve with %zu control points (the system is "
                          "numerically singular)",
                          N, n));
    curve.points.assign(n, Point4{});
    curve.points[0] = Point4{first.x, first.y, first.z, 1.0};
    for (std::size_t i = 1; i + 1 < n; ++i)
        curve.points[i] = Point4{inner[3 * (i - 1)], inner[3 * (i - 1) + 1], inner[3 * (i - 1) + 2], 1.0};
    curve.points[n - 1] = Point4{last.x, last.y, last.z, 1.0};
    return toolValue(std::move(curve));
}

} // namespace q3::nurbs
