// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// A deliberately plain NURB evaluator for tests, independent of Q3's: the
// article's basis-function recursion ("DEFINING THE BASIS FUNCTIONS",
// Cox-de Boor, 0/0 taken as 0) summed as the article's rational formula
// ("RATIONAL CURVES") on homogeneous control points, in double precision.
// Exponential in the order, which is fine for the orders the tests use.

#include "QD3DGeometry.h"

#include <cstddef>

namespace q3test {

struct RefPoint {
    double x = 0.0, y = 0.0, z = 0.0;
};

/// The curve's domain [x(k-1), x(n)] (order k, n control points).
inline double referenceDomainStart(const TQ3NURBCurveData& c) { return c.knots[c.order - 1]; }
inline double referenceDomainEnd(const TQ3NURBCurveData& c) { return c.knots[c.numPoints]; }

/// N(i,k)(t) for a knot vector of `count` knots. The order-1 functions are 1
/// on [x(i), x(i+1)); at t == `end` (the domain end) the last non-empty span
/// ending there counts instead, so that the functions sum to 1 on the whole
/// closed domain.
inline double referenceBasis(const float* x, std::size_t count, std::size_t i, unsigned long k,
                             double t, double end)
{
    if (k == 1) {
        if (t == end) {
            // The last non-empty span [x(s), x(s+1)] with x(s+1) == end.
            std::size_t s = count;
            for (std::size_t j = 0; j + 1 < count; ++j) {
                if (double(x[j]) < double(x[j + 1]) && double(x[j + 1]) == end)
                    s = j;
            }
            return i == s ? 1.0 : 0.0;
        }
        return (double(x[i]) <= t && t < double(x[i + 1])) ? 1.0 : 0.0;
    }
    double value = 0.0;
    const double leftWidth = double(x[i + k - 1]) - double(x[i]);
    const double rightWidth = double(x[i + k]) - double(x[i + 1]);
    if (leftWidth != 0.0)
        value += (t - double(x[i])) / leftWidth * referenceBasis(x, count, i, k - 1, t, end);
    if (rightWidth != 0.0)
        value += (double(x[i + k]) - t) / rightWidth * referenceBasis(x, count, i + 1, k - 1, t, end);
    return value;
}

/// Q(t) = sum(N(i,k)(t) * (X, Y, Z)_i) / sum(N(i,k)(t) * W_i), t in the domain.
inline RefPoint referenceEvaluate(const TQ3NURBCurveData& c, double t)
{
    const std::size_t count = c.numPoints + c.order;
    const double end = referenceDomainEnd(c);
    double x = 0.0, y = 0.0, z = 0.0, w = 0.0;
    for (std::size_t i = 0; i < c.numPoints; ++i) {
        const double n = referenceBasis(c.knots, count, i, c.order, t, end);
        x += n * c.controlPoints[i].x;
        y += n * c.controlPoints[i].y;
        z += n * c.controlPoints[i].z;
        w += n * c.controlPoints[i].w;
    }
    return RefPoint{x / w, y / w, z / w};
}

} // namespace q3test
