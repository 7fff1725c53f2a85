// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Curves the NURB curve API tests own: the arrays of a TQ3NURBCurveData,
// so that each test can break one thing, and the article's curves.

#include "QD3DGeometry.h"

#include <cstring>
#include <vector>

namespace q3test {

struct CurveArrays {
    std::vector<TQ3RationalPoint4D> points;
    std::vector<float> knots;
    unsigned long order;
    TQ3AttributeSet attributes = nullptr;

    TQ3NURBCurveData data()
    {
        return TQ3NURBCurveData{order, points.size(), points.data(), knots.data(), attributes};
    }
    /// The same order, knots and points (the attribute set aside).
    bool operator==(const CurveArrays& o) const
    {
        return order == o.order && knots == o.knots && points.size() == o.points.size() &&
               std::memcmp(points.data(), o.points.data(), points.size() * sizeof(TQ3RationalPoint4D)) == 0;
    }
};

/// The article's Listing 1: a cubic Bezier curve on [0, 1].
inline CurveArrays listing1()
{
    return {{{0, 0, 0, 1}, {1, 1, 0, 1}, {2, 0, 0, 1}, {3, 1, 0, 1}}, {0, 0, 0, 0, 1, 1, 1, 1}, 4};
}

/// A quadratic with six points and interior knots 1, 2, 3 (domain [0, 4]),
/// the article's Figure 13 shape.
inline CurveArrays sixPointQuadratic()
{
    return {{{0, 0, 0, 1}, {1, 2, 0, 1}, {2, 0, 0, 1}, {3, 2, 0, 1}, {4, 0, 0, 1}, {5, 2, 0, 1}},
            {0, 0, 0, 1, 2, 3, 4, 4, 4},
            3};
}

} // namespace q3test
