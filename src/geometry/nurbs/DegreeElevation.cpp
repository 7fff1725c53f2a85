// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Degree elevation by interpolation in the bigger spline space.
//
// A piecewise polynomial of degree p that is C^{p-m} at a knot of multiplicity m is
// also a piecewise polynomial of degree p + t that is C^{p-m} there, i.e. a B-spline
// of order k + t on the knot vector in which every interior knot occurs m + t times
// (the spline spaces are nested: the Curry-Schoenberg theorem, de Boor, "A
// Practical Guide to Splines").
// So the elevated control points are those of the one spline in that space that
// agrees with the curve at as many points as it has control points. The points are
// the Greville abscissae of the new knot vector, tau_j = (y_{j+1} + ... + y_{j+p+t})
// / (p + t), which satisfy the Schoenberg-Whitney condition (y_j < tau_j < y_{j+p+t+1})
// whatever the multiplicities, so the banded collocation system has one solution,
// and that solution reproduces the curve exactly up to rounding. The conditions are
// set up on the homogeneous curve, a polynomial spline, so rational curves are
// elevated exactly as well.
//
// Piegl & Tiller's algorithm A5.9 reaches the same control points by converting to
// Bezier form, elevating each piece and removing the joint knots again; the removal
// divides by small interpolation ratios, and at orders near 16 it loses up to 1e-5 of
// the curve's size, where this solve (stable Givens rotations on a well-conditioned
// totally positive matrix) keeps about 1e-10.

#include "geometry/nurbs/DegreeElevation.h"

#include "geometry/nurbs/BandedLeastSquares.h"
#include "geometry/nurbs/Evaluate.h"
#include "geometry/nurbs/Knots.h"

namespace q3::nurbs {

ToolResult<HomogeneousCurve> elevateDegree(const CurveRef& curve, std::size_t times)
{
    const unsigned k = curve.order;
    if (times > kMaxOrder - k)
        return toolFailure<HomogeneousCurve>(
            ToolError::kOutOfRange,
            formatMessage("raising the order %u by %zu would exceed the highest order, %u", k, times, kMaxOrder));
    // By 0 a clamped curve comes back as it is; an unclamped one goes through the
    // collocation below, which clamps it as for any other times.
    const std::size_t n = curve.numPoints;
    if (times == 0 && curve.knots[0] == curve.knots[k - 1] && curve.knots[n] == curve.knots[n + k - 1])
        return toolValue(toHomogeneous(curve));
    const unsigned newOrder = k + unsigned(times);
    const unsigned degree = newOrder - 1;

    // The new knot vector: clamped ends, every interior value times more often.
    const Domain domain = curveDomain(curve);
    std::size_t count = newOrder;
    for (std::size_t i = k; i < curve.numPoints; ++i)
        if (domain.start < curve.knots[i] && curve.knots[i] < domain.end)
            count += 1 + (curve.knots[i] != curve.knots[i - 1] ? times : 0);
    if (count > kMaxToolPoints)
        return toolFailure<HomogeneousCurve>(
            ToolError::kOutOfRange,
            formatMessage("the elevated curve would have %zu control points, more than Q3's limit of %zu", count,
                          kMaxToolPoints));
    HomogeneousCurve result;
    result.order = newOrder;
    std::vector<double>& y = result.knots;
    y.reserve(count + newOrder);
    y.assign(newOrder, domain.start);
    for (std::size_t i = k; i < curve.numPoints; ++i) {
        const double x = curve.knots[i];
        if (domain.start < x && x < domain.end)
            y.insert(y.end(), 1 + (x != double(curve.knots[i - 1]) ? times : 0), x);
    }
    y.insert(y.end(), newOrder, domain.end);

    // Collocation at the Greville abscissae, ends fixed (a clamped curve starts and
    // ends at its end control points).
    const Point4 start = evaluate(curve, domain.start).homogeneous;
    const Point4 end = evaluate(curve, domain.end).homogeneous;
    const double first[4] = {start.x, start.y, start.z, start.w};
    const double last[4] = {end.x, end.y, end.z, end.w};
    BandedLeastSquares system(count - 2, newOrder, 4);
    double basis[kMaxOrder];
    std::size_t l = degree;
    for (std::size_t j = 1; j + 1 < count; ++j) {
        double sum = 0.0;
        for (unsigned i = 1; i <= degree; ++i)
            sum += y[j + i];
        const double tau = sum / degree;
        while (l + 1 < count && !(tau < y[l + 1]))
            ++l;
        basisFunctionsOnSpan(y, l, degree, tau, basis);
        const Point4 a = evaluate(curve, tau).homogeneous;
        const double value[4] = {a.x, a.y, a.z, a.w};
        system.addCurveRow(l, degree, basis, count, value, first, last);
    }
    std::vector<double> inner;
    if (!system.solve(inner))
        return toolFailure<HomogeneousCurve>(ToolError::kDegenerate,
                                             "the elevated curve's collocation system is numerically singular");
    result.points.assign(count, start);
    for (std::size_t i = 1; i + 1 < count; ++i)
        result.points[i] = Point4{inner[4 * (i - 1)], inner[4 * (i - 1) + 1], inner[4 * (i - 1) + 2],
                                  inner[4 * (i - 1) + 3]};
    result.points[count - 1] = end;
    return toolValue(std::move(result));
}

} // namespace q3::nurbs
