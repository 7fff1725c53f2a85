// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Knot refinement (many insertions at once) and knot removal.
//
// Refinement is Boehm's insertion (article, "KNOT INSERTION"; lecture 6, section
// 6.6.2) applied to all new knots in one sweep from the right, as Piegl & Tiller's
// algorithm A5.4 organises it: control points left of the first new knot's span and
// right of the last one's are copied, and every other point is produced once, by the
// article's rule B^_j = (1 - a_j) B_{j-1} + a_j B_j with a_j computed on the knot
// vector as it stands after the insertions to the right. Only knots around the
// inserted ones are read, so it holds for unclamped knot vectors as well, and it
// costs O((n + r) k) instead of the O(n r) of r separate insertions.
//
// Removal of c copies of a knot u works on a window of the knot vector around u:
// the reduced curve's points there, all but the p next to u fixed at the original
// values, are refined with c copies of u again (refine is linear in the points, so
// refining unit vectors gives the columns of the insertion matrix), and the p free
// points are chosen by least squares so that the refined window matches the original
// points (BandedLeastSquares). Outside the window nothing changes, so the proof of
// KnotRefinement.h needs only the window as well.

#include "geometry/nurbs/KnotRefinement.h"

#include "geometry/nurbs/BandedLeastSquares.h"
#include "geometry/nurbs/CurveAccess.h"
#include "geometry/nurbs/Knots.h"

#include <algorithm>
#include <cmath>

namespace q3::nurbs {
namespace {

std::size_t multiplicityOf(const std::vector<double>& knots, double value)
{
    const auto range = std::equal_range(knots.begin(), knots.end(), value);
    return std::size_t(range.second - range.first);
}

bool finiteInFloat(const Point4& p)
{
    return std::isfinite(float(p.x)) && std::isfinite(float(p.y)) && std::isfinite(float(p.z)) &&
           std::isfinite(float(p.w)) && float(p.w) > 0.0f;
}

// The reduced curve near the removed knot, and how its refinement lines up with the
// original: local point j is reduced point lo + j, local refined point r is original
// point lo + r.
struct RemovalWindow {
    HomogeneousCurve local;  // knots y[lo .. hi], their control points
    std::size_t lo = 0;
    std::size_t firstFree = 0;  // local index of the first of the p free points
};

// The largest-distance bound of KnotRefinement.h between the original points and the
// window refined back (same indices), or infinity when a weight is not positive.
double deviationBound(const HomogeneousCurve& original, std::size_t lo, const HomogeneousCurve& back)
{
    double pointDifference = 0.0;
    double weightDifference = 0.0;
    double radius = 0.0;
    double smallestWeight = INFINITY;
    for (std::size_t r = 0; r < back.points.size(); ++r) {
        const Point4& a = back.points[r];
        const Point4& b = original.points[lo + r];
        if (!(a.w > 0.0) || !std::isfinite(a.x + a.y + a.z + a.w))
            return INFINITY;
        pointDifference = std::max(pointDifference, access::length3(Point3{a.x - b.x, a.y - b.y, a.z - b.z}));
        weightDifference = std::max(weightDifference, std::fabs(a.w - b.w));
        radius = std::max(radius, access::length3(Point3{a.x / a.w, a.y / a.w, a.z / a.w}));
        smallestWeight = std::min(smallestWeight, b.w);
    }
    return (pointDifference + radius * weightDifference) / smallestWeight;
}

// Tries to take `count` copies of x[first] out; returns the reduced curve when the
// bound holds, else an empty curve.
HomogeneousCurve tryRemoval(const HomogeneousCurve& curve, std::size_t first, std::size_t count, double tolerance)
{
    const unsigned k = curve.order;
    const std::size_t p = k - 1;
    const double u = curve.knots[first];
    std::vector<double> y = curve.knots;
    y.erase(y.begin() + std::ptrdiff_t(first), y.begin() + std::ptrdiff_t(first + count));
    const std::size_t g = first;  // where u's run starts (or would) in y; g >= p + 1
    const std::size_t lo = g > 2 * k ? g - 2 * k : 0;
    const std::size_t hi = std::min(y.size() - 1, g + 2 * k);

    HomogeneousCurve local;
    local.order = k;
    local.knots.assign(y.begin() + std::ptrdiff_t(lo), y.begin() + std::ptrdiff_t(hi + 1));
    const std::size_t localPoints = local.knots.size() - k;
    const std::size_t firstFree = g - p - lo;
    // Fixed points: original left of the free ones, shifted by count right of them.
    local.points.resize(localPoints);
    for (std::size_t j = 0; j < localPoints; ++j) {
        const std::size_t reduced = lo + j;
        local.points[j] = reduced < g - p ? curve.points[reduced] : Point4{};
        if (reduced >= g)
            local.points[j] = curve.points[reduced + count];
    }
    const std::vector<double> copies(count, u);
    const HomogeneousCurve base = refine(local, copies);
    const std::size_t rows = base.points.size();
    std::vector<std::vector<double>> columns(p);
    for (std::size_t c = 0; c < p; ++c) {
        HomogeneousCurve unit = local;
        std::fill(unit.points.begin(), unit.points.end(), Point4{});
        unit.points[firstFree + c] = Point4{1.0, 0.0, 0.0, 0.0};
        const HomogeneousCurve refined = refine(unit, copies);
        columns[c].resize(rows);
        for (std::size_t r = 0; r < rows; ++r)
            columns[c][r] = refined.points[r].x;
    }
    BandedLeastSquares system(p, unsigned(p), 4);
    for (std::size_t r = 0; r < rows; ++r) {
        double a[kMaxOrder] = {};
        for (std::size_t c = 0; c < p; ++c)
            a[c] = columns[c][r];
        const Point4 target = access::sub(curve.points[lo + r], base.points[r]);
        double rhs[4] = {target.x, target.y, target.z, target.w};
        system.addRow(0, a, rhs);
    }
    std::vector<double> free;
    if (!system.solve(free))
        return HomogeneousCurve{};
    for (std::size_t c = 0; c < p; ++c) {
        const Point4 q{free[4 * c], free[4 * c + 1], free[4 * c + 2], free[4 * c + 3]};
        if (!finiteInFloat(q))
            return HomogeneousCurve{};
        local.points[firstFree + c] = Point4{double(float(q.x)), double(float(q.y)), double(float(q.z)),
                                             double(float(q.w))};
    }
    if (deviationBound(curve, lo, refine(local, copies)) > tolerance)
        return HomogeneousCurve{};

    HomogeneousCurve result;
    result.order = k;
    result.knots = std::move(y);
    result.points.reserve(curve.points.size() - count);
    result.points.insert(result.points.end(), curve.points.begin(), curve.points.begin() + std::ptrdiff_t(lo));
    result.points.insert(result.points.end(), local.points.begin(), local.points.end());
    result.points.insert(result.points.end(), curve.points.begin() + std::ptrdiff_t(lo + localPoints + count),
                         curve.points.end());
    return result;
}

} // namespace

HomogeneousCurve refine(const HomogeneousCurve& curve, const std::vector<double>& knots)
{
    if (knots.empty())
        return curve;
    const std::size_t p = curve.order - 1;
    const std::size_t n = curve.points.size();
    const std::size_t r = knots.size();
    const std::vector<double>& x = curve.knots;
    const std::vector<Point4>& P = curve.points;
    const std::size_t a = findSpan(curve, knots.front());
    const std::size_t b = findSpan(curve, knots.back()) + 1;

    HomogeneousCurve result;
    result.order = curve.order;
    result.knots.assign(x.size() + r, 0.0);
    result.points.assign(n + r, Point4{});
    std::vector<double>& y = result.knots;
    std::vector<Point4>& Q = result.points;
    for (std::size_t j = 0; j <= a - p; ++j)
        Q[j] = P[j];
    for (std::size_t j = b - 1; j < n; ++j)
        Q[j + r] = P[j];
    for (std::size_t j = 0; j <= a; ++j)
        y[j] = x[j];
    for (std::size_t j = b + p; j < x.size(); ++j)
        y[j + r] = x[j];

    // i walks the old knots, slot the new ones, both from the right.
    std::size_t i = b + p - 1;
    std::size_t slot = b + p + r - 1;
    for (std::size_t j = r; j-- > 0;) {
        const double t = knots[j];
        while (t <= x[i] && i > a) {
            Q[slot - p - 1] = P[i - p - 1];
            y[slot] = x[i];
            --slot;
            --i;
        }
        Q[slot - p - 1] = Q[slot - p];
        for (std::size_t l = 1; l <= p; ++l) {
            const std::size_t index = slot - p + l;
            const double right = y[slot + l];
            if (right == t) {
                Q[index - 1] = Q[index];
            } else {
                const double alpha = (right - t) / (right - x[i - p + l]);
                Q[index - 1] = access::lerp(Q[index], Q[index - 1], alpha);
            }
        }
        y[slot] = t;
        --slot;
    }
    return result;
}

ToolResult<HomogeneousCurve> insertKnotTimes(const HomogeneousCurve& curve, double t, std::size_t times)
{
    const ToolResult<double> checked = checkParameter(t, domainOf(curve), true, "the knot");
    if (!checked.ok())
        return toolFailure<HomogeneousCurve>(checked);
    const std::size_t limit = curve.order - 1;
    const std::size_t existing = multiplicityOf(curve.knots, t);
    if (times > limit - existing)
        return toolFailure<HomogeneousCurve>(
            ToolError::kOutOfRange,
            formatMessage("inserting the knot %.9g %zu times would make it occur %s times; at most "
                          "order - 1 = %zu equal knots are allowed inside the knot vector",
                          t, times, times > limit ? "more than order - 1" : std::to_string(existing + times).c_str(),
                          limit));
    if (curve.points.size() + times > kMaxToolPoints)
        return toolFailure<HomogeneousCurve>(
            ToolError::kOutOfRange,
            formatMessage("the result would have %zu control points, more than Q3's limit of %zu",
                          curve.points.size() + times, kMaxToolPoints));
    return toolValue(refine(curve, std::vector<double>(times, t)));
}

ToolResult<HomogeneousCurve> refineKnots(const HomogeneousCurve& curve, std::vector<double> knots)
{
    if (knots.size() > kMaxToolPoints || curve.points.size() + knots.size() > kMaxToolPoints)
        return toolFailure<HomogeneousCurve>(
            ToolError::kOutOfRange,
            formatMessage("inserting %zu knots would give more than Q3's limit of %zu control points",
                          knots.size(), kMaxToolPoints));
    const Domain domain = domainOf(curve);
    for (std::size_t i = 0; i < knots.size(); ++i) {
        const std::string name = formatMessage("knots[%zu]", i);
        const ToolResult<double> checked = checkParameter(knots[i], domain, true, name.c_str());
        if (!checked.ok())
            return toolFailure<HomogeneousCurve>(checked);
    }
    std::sort(knots.begin(), knots.end());
    const std::size_t limit = curve.order - 1;
    for (std::size_t start = 0; start < knots.size();) {
        std::size_t stop = start + 1;
        while (stop < knots.size() && knots[stop] == knots[start])
            ++stop;
        const std::size_t existing = multiplicityOf(curve.knots, knots[start]);
        if (existing + (stop - start) > limit)
            return toolFailure<HomogeneousCurve>(
                ToolError::kInvalidArgument,
                formatMessage("the knot value %.9g would occur %zu times (%zu new, %zu already); at most "
                              "order - 1 = %zu equal knots are allowed inside the knot vector",
                              knots[start], existing + (stop - start), stop - start, existing, limit));
        start = stop;
    }
    return toolValue(refine(curve, knots));
}

ToolResult<KnotRemoval> removeKnot(const HomogeneousCurve& curve, std::size_t knotIndex, std::size_t times,
                                   double tolerance)
{
    const std::vector<double>& x = curve.knots;
    if (knotIndex >= x.size())
        return toolFailure<KnotRemoval>(
            ToolError::kOutOfRange,
            formatMessage("knot index %zu is past the last knot (index %zu)", knotIndex, x.size() - 1));
    const Domain domain = domainOf(curve);
    const double u = x[knotIndex];
    if (!(domain.start < u && u < domain.end))
        return toolFailure<KnotRemoval>(
            ToolError::kOutOfRange,
            formatMessage("knot %zu (%.9g) is not inside the domain (%.9g, %.9g); only interior knots "
                          "can be removed",
                          knotIndex, u, domain.start, domain.end));
    const std::size_t multiplicity = multiplicityOf(x, u);
    if (times > multiplicity)
        return toolFailure<KnotRemoval>(
            ToolError::kOutOfRange,
            formatMessage("cannot remove knot %zu (%.9g) %zu times: it occurs %zu times", knotIndex, u,
                          times, multiplicity));
    if (!std::isfinite(tolerance))
        return toolFailure<KnotRemoval>(
            ToolError::kNotFinite, formatMessage("the tolerance is %g; it must be a finite number", tolerance));
    if (!(tolerance > 0.0))
        return toolFailure<KnotRemoval>(
            ToolError::kInvalidArgument,
            formatMessage("the tolerance is %g; it must be greater than 0", tolerance));

    std::size_t first = knotIndex;
    while (first > 0 && x[first - 1] == u)
        --first;
    for (std::size_t count = times; count > 0; --count) {
        HomogeneousCurve reduced = tryRemoval(curve, first, count, tolerance);
        if (!reduced.points.empty())
            return toolValue(KnotRemoval{std::move(reduced), count});
    }
    return toolValue(KnotRemoval{curve, 0});
}

} // namespace q3::nurbs
