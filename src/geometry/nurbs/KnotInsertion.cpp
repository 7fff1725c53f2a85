// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Single-knot insertion (Boehm's algorithm).
//
// The formula is the article's, section "KNOT INSERTION" / "THE ALGORITHM": for
// x_i < x_new <= x_{i+1} the new control points are
//   B^_j = (1 - a_j) B_{j-1} + a_j B_j,
//   a_j = 1                                      for j <= i - k + 1,
//   a_j = (x_new - x_j) / (x_{j+k-1} - x_j)      for i - k + 2 <= j <= i,
//   a_j = 0                                      for j >= i + 1,
// and the new knot vector is the old one with x_new placed after x_i. The same
// scheme is lecture 6, section 6.6.2. It is applied to homogeneous points, so the
// rational curve is unchanged as well.

#include "geometry/nurbs/KnotInsertion.h"

#include <cstddef>

namespace q3::nurbs {

std::optional<HomogeneousCurve> insertKnot(const HomogeneousCurve& curve, double tNew)
{
    const unsigned k = curve.order;
    const std::size_t n = curve.points.size();
    const std::vector<double>& x = curve.knots;
    if (!(x[k - 1] < tNew && tNew < x[n])) {
        return std::nullopt;
    }
    // i: x_i < tNew <= x_{i+1}; tNew is inside the domain so k-2 <= i <= n-1.
    std::size_t i = k - 1;
    {
        std::size_t lo = k - 1;  // x[lo] < tNew
        std::size_t hi = n;      // tNew <= x[hi]
        while (hi - lo > 1) {
            const std::size_t mid = lo + (hi - lo) / 2;
            if (x[mid] < tNew) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        i = lo;
    }
    std::size_t equal = 0;
    for (std::size_t j = i + 1; j < x.size() && x[j] == tNew; ++j) {
        ++equal;
    }
    if (equal + 1 > k - 1) {
        return std::nullopt;
    }

    HomogeneousCurve result;
    result.order = k;
    result.knots.reserve(x.size() + 1);
    result.knots.insert(result.knots.end(), x.begin(), x.begin() + std::ptrdiff_t(i + 1));
    result.knots.push_back(tNew);
    result.knots.insert(result.knots.end(), x.begin() + std::ptrdiff_t(i + 1), x.end());

    result.points.resize(n + 1);
    const std::vector<Point4>& b = curve.points;
    for (std::size_t j = 0; j <= n; ++j) {
        if (j + k <= i + 1) {
            result.points[j] = b[j];
        } else if (j >= i + 1) {
            result.points[j] = b[j - 1];
        } else {
            const double alpha = (tNew - x[j]) / (x[j + k - 1] - x[j]);
            const double beta = 1.0 - alpha;
            const Point4& p = b[j - 1];
            const Point4& q = b[j];
            result.points[j] = Point4{beta * p.x + alpha * q.x, beta * p.y + alpha * q.y,
                                      beta * p.z + alpha * q.z, beta * p.w + alpha * q.w};
        }
    }
    return result;
}

} // namespace q3::nurbs
