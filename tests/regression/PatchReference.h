// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The second computation the NURB patch regression tests compare Q3 with,
// written from QD3DGeometry.h's definitions and the lecture's formulas and
// sharing no code with src/ (SubdivisionReference.h supplies the
// transforms, the cameras and the curve evaluator, used here for the trim
// curves with z = 0):
//   - a patch evaluator: the tensor product of two Cox-de Boor sums over the
//     non-empty spans holding (u, v), on homogeneous points, in long double;
//     its partial derivatives by one-sided differences (forward, backward at
//     the domain's far end), so the normal is the span's to the right and
//     above, as QD3DGeometry.h says for a vertex on a crease;
//   - the distance from a point to the surface (Gauss-Newton from a guess);
//   - random valid patches (orders 2-11 in each direction, clamped or not,
//     interior knots repeated, weights 0.25 to 4) and random non-crossing
//     trim loops (nested star-shaped loops, one to three rational curves of
//     orders 2-5 each), with the region they keep decided by the even-odd
//     count over finely sampled loops (plus one for the domain itself when
//     no outermost loop runs counterclockwise).

#include "GoldenSection.h"
#include "SubdivisionReference.h"

#include "QD3DGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace q3test::patches {

using subdivision::Real;
using subdivision::Vec3;

struct TrimCurve {
    unsigned long order = 2;
    std::vector<TQ3RationalPoint3D> points;
    std::vector<float> knots;

    /// The same curve in the (u, v) plane (z = 0) as a reference curve.
    subdivision::Curve asCurve() const
    {
        subdivision::Curve c;
        c.order = order;
        for (const TQ3RationalPoint3D& q : points)
            c.points.push_back({q.x, q.y, 0.0f, q.w});
        c.knots = knots;
        return c;
    }
};

/// A patch that owns its arrays.
struct Patch {
    unsigned long uOrder = 2, vOrder = 2, numRows = 2, numColumns = 2;
    std::vector<TQ3RationalPoint4D> points;
    std::vector<float> uKnots, vKnots;
    std::vector<std::vector<TrimCurve>> loops;
    std::vector<bool> loopCounterclockwise;

    std::vector<TQ3NURBPatchTrimLoopData> loopData;
    std::vector<std::vector<TQ3NURBPatchTrimCurveData>> curveData;

    TQ3NURBPatchData data()
    {
        loopData.clear();
        curveData.assign(loops.size(), {});
        for (std::size_t l = 0; l < loops.size(); ++l) {
            for (TrimCurve& c : loops[l])
                curveData[l].push_back({c.order, c.points.size(), c.points.data(), c.knots.data()});
            loopData.push_back({curveData[l].size(), curveData[l].data()});
        }
        return TQ3NURBPatchData{uOrder,        vOrder,        numRows,       numColumns,
                                points.data(), uKnots.data(), vKnots.data(), loopData.size(),
                                loopData.empty() ? nullptr : loopData.data(), nullptr};
    }

    Real u0() const { return uKnots[uOrder - 1]; }
    Real u1() const { return uKnots[numColumns]; }
    Real v0() const { return vKnots[vOrder - 1]; }
    Real v1() const { return vKnots[numRows]; }

    /// Knot indices s with knots[s] < knots[s + 1] inside the domain.
    static std::vector<std::size_t> spansOf(const std::vector<float>& knots, unsigned long order, unsigned long n)
    {
        std::vector<std::size_t> spans;
        for (std::size_t s = order - 1; s < n; ++s)
            if (knots[s] < knots[s + 1])
                spans.push_back(s);
        return spans;
    }
    std::vector<std::size_t> uSpans() const { return spansOf(uKnots, uOrder, numColumns); }
    std::vector<std::size_t> vSpans() const { return spansOf(vKnots, vOrder, numRows); }

    /// The control points' extent (bounding-box diagonal or largest
    /// coordinate, whichever is larger): no surface coordinate exceeds it.
    Real size() const { return subdivision::ControlBox(points).extent(); }
};

/// The order-k basis functions non-zero on the span holding t (the last span
/// starting at or before t; the first for t before the domain): N[j] is
/// N_{span-k+1+j,k}(t). Returns the span.
inline std::size_t basis(const std::vector<float>& x, unsigned long k, unsigned long n, Real t, Real* N)
{
    std::size_t s = n;
    for (std::size_t i = k - 1; i < n; ++i)
        if (x[i] < x[i + 1] && (s == n || Real(x[i]) <= t))
            s = i;
    Real level[kQ3NURBCurveMaxOrder + 1] = {};
    level[k - 1] = 1; // N_{s,1}; entries hold N_{s-(k-1)+j, m}
    for (std::size_t m = 2; m <= k; ++m)
        for (std::size_t j = 0; j < k; ++j) {
            const std::size_t i = s - (k - 1) + j;
            const Real xi = x[i], xim1 = x[i + m - 1], xi1 = x[i + 1], xim = x[i + m];
            Real value = 0;
            if (xim1 != xi)
                value += (t - xi) / (xim1 - xi) * level[j];
            if (xim != xi1)
                value += (xim - t) / (xim - xi1) * level[j + 1];
            level[j] = value;
        }
    for (std::size_t j = 0; j < k; ++j)
        N[j] = level[j];
    return s;
}

/// The surface at (u, v), clamped into the domain.
inline Vec3 evaluate(const Patch& p, Real u, Real v)
{
    u = std::clamp(u, p.u0(), p.u1());
    v = std::clamp(v, p.v0(), p.v1());
    Real nu[kQ3NURBPatchMaxOrder], nv[kQ3NURBPatchMaxOrder];
    const std::size_t su = basis(p.uKnots, p.uOrder, p.numColumns, u, nu);
    const std::size_t sv = basis(p.vKnots, p.vOrder, p.numRows, v, nv);
    Real x = 0, y = 0, z = 0, w = 0;
    for (std::size_t r = 0; r < p.vOrder; ++r)
        for (std::size_t c = 0; c < p.uOrder; ++c) {
            const TQ3RationalPoint4D& q = p.points[(sv - (p.vOrder - 1) + r) * p.numColumns + (su - (p.uOrder - 1) + c)];
            const Real b = nv[r] * nu[c];
            x += b * q.x;
            y += b * q.y;
            z += b * q.z;
            w += b * q.w;
        }
    return {x / w, y / w, z / w};
}

/// dS/du and dS/dv at (u, v) by one-sided differences of step h (a
/// millionth of the domain's side), forward unless that leaves the domain.
inline void partials(const Patch& p, Real u, Real v, Vec3& du, Vec3& dv)
{
    const Real hu = (p.u1() - p.u0()) * 1e-7L, hv = (p.v1() - p.v0()) * 1e-7L;
    const Vec3 s = evaluate(p, u, v);
    const Real su = u + hu <= p.u1() ? hu : -hu;
    const Real sv = v + hv <= p.v1() ? hv : -hv;
    du = (1 / su) * (evaluate(p, u + su, v) - s);
    dv = (1 / sv) * (evaluate(p, u, v + sv) - s);
}

/// The unit normal (du x dv); `wellDefined` false where |du x dv| is below
/// 1e-6 |du| |dv| (a pole, a cusp: there the direction means little).
inline Vec3 normal(const Patch& p, Real u, Real v, bool& wellDefined)
{
    Vec3 du, dv;
    partials(p, u, v, du, dv);
    const Vec3 n = subdivision::cross(du, dv);
    const Real length = subdivision::norm(n);
    wellDefined = length > 1e-6L * subdivision::norm(du) * subdivision::norm(dv);
    return length > 0 ? (1 / length) * n : n;
}

/// The distance from q to the surface near (u, v): Gauss-Newton on
/// |S(u, v) - q|^2 with the difference partials, kept in the domain; the
/// parameters found are left in u and v.
inline Real distanceToSurface(const Patch& p, const Vec3& q, Real& u, Real& v, Real goodEnough = 0)
{
    Real best = subdivision::distance(evaluate(p, u, v), q);
    for (int iteration = 0; iteration < 12 && best > goodEnough; ++iteration) {
        Vec3 du, dv;
        partials(p, u, v, du, dv);
        const Vec3 r = evaluate(p, u, v) - q;
        const Real a = subdivision::dot(du, du), b = subdivision::dot(du, dv), c = subdivision::dot(dv, dv);
        const Real g1 = subdivision::dot(du, r), g2 = subdivision::dot(dv, r);
        const Real det = a * c - b * b;
        if (!(det > 0))
            break;
        const Real nu = std::clamp(u - (c * g1 - b * g2) / det, p.u0(), p.u1());
        const Real nv = std::clamp(v - (a * g2 - b * g1) / det, p.v0(), p.v1());
        const Real d = subdivision::distance(evaluate(p, nu, nv), q);
        if (!(d < best))
            break;
        best = d;
        u = nu;
        v = nv;
    }
    return best;
}

struct PatchOptions {
    unsigned long uOrder = 4, vOrder = 4;
    bool clamped = true;
    Real repeatProbability = 0;
    unsigned long extraPoints = 5;
};

inline std::vector<float> randomKnots(std::mt19937& rng, unsigned long k, unsigned long n, bool clamped,
                                      Real repeatProbability)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (;;) {
        std::vector<float> knots;
        double value = std::floor(8 * unit(rng) - 4);
        unsigned long run = 1;
        knots.push_back(float(value));
        for (unsigned long i = 1; i < n + k; ++i) {
            const bool endRun = clamped && (i < k || i > n);
            const bool firstOfEndRun = clamped && i == n;
            const bool repeat =
                endRun || (!firstOfEndRun && run < k - 1 && unit(rng) < double(repeatProbability));
            if (repeat) {
                ++run;
            } else {
                value += 0.125 + 1.5 * unit(rng);
                run = 1;
            }
            knots.push_back(float(value));
        }
        if (knots[k - 1] < knots[n])
            return knots;
    }
}

/// A random patch obeying every TQ3NURBPatchData rule: control points on a
/// wavy grid (column c, row r at about (c, r)) with random heights and
/// jitter, weights 0.25 to 4.
inline Patch randomPatch(std::mt19937& rng, const PatchOptions& o)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_real_distribution<double> logWeight(std::log(0.25), std::log(4.0));
    std::uniform_int_distribution<unsigned long> extra(0, o.extraPoints);
    Patch p;
    p.uOrder = o.uOrder;
    p.vOrder = o.vOrder;
    p.numColumns = o.uOrder + extra(rng);
    p.numRows = o.vOrder + extra(rng);
    const double height = 0.3 + 2.0 * unit(rng);
    for (unsigned long r = 0; r < p.numRows; ++r)
        for (unsigned long c = 0; c < p.numColumns; ++c) {
            const double w = std::exp(logWeight(rng));
            const double x = double(c) + 0.6 * (unit(rng) - 0.5);
            const double y = double(r) + 0.6 * (unit(rng) - 0.5);
            const double z = height * (unit(rng) - 0.5);
            p.points.push_back({float(x * w), float(y * w), float(z * w), float(w)});
        }
    p.uKnots = randomKnots(rng, p.uOrder, p.numColumns, o.clamped, o.repeatProbability);
    p.vKnots = randomKnots(rng, p.vOrder, p.numRows, o.clamped, o.repeatProbability);
    return p;
}

/// A star-shaped loop around (cu, cv): radius between lo and hi (times the
/// half-axes au, av), `curves` rational curves of random orders 2-5 sharing
/// their end points exactly, counterclockwise or clockwise.
inline std::vector<TrimCurve> starLoop(std::mt19937& rng, Real cu, Real cv, Real au, Real av, Real lo, Real hi,
                                       int curves, bool counterclockwise)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_real_distribution<double> logWeight(std::log(0.5), std::log(2.0));
    std::vector<TrimCurve> loop;
    // Corner angles where one curve hands over to the next.
    const double start = 6.283185307 * unit(rng);
    std::vector<TQ3RationalPoint3D> corners;
    auto pointAt = [&](double angle, double radius, double w) {
        const double u = double(cu) + radius * double(au) * std::cos(angle);
        const double v = double(cv) + radius * double(av) * std::sin(angle);
        return TQ3RationalPoint3D{float(u * w), float(v * w), float(w)};
    };
    for (int i = 0; i < curves; ++i) {
        const double a = start + 6.283185307 * i / curves;
        corners.push_back(pointAt(a, double(lo + (hi - lo) * Real(unit(rng))), std::exp(logWeight(rng))));
    }
    for (int i = 0; i < curves; ++i) {
        TrimCurve curve;
        curve.order = 2 + (unsigned long)(unit(rng) * 4) % 4;
        // At least 8 points per loop overall and order points per curve.
        const unsigned long n = std::max<unsigned long>(curve.order, 8 / curves + 1 + (unsigned long)(3 * unit(rng)));
        const double a0 = start + 6.283185307 * i / curves;
        const double a1 = start + 6.283185307 * (i + 1) / curves;
        for (unsigned long j = 0; j < n; ++j) {
            if (j == 0) {
                curve.points.push_back(corners[i]);
            } else if (j + 1 == n) {
                curve.points.push_back(corners[(i + 1) % curves]);
            } else {
                const double a = a0 + (a1 - a0) * double(j) / double(n - 1);
                curve.points.push_back(pointAt(a, double(lo + (hi - lo) * Real(unit(rng))), std::exp(logWeight(rng))));
            }
        }
        curve.knots.clear();
        for (unsigned long j = 0; j < curve.order; ++j)
            curve.knots.push_back(0.0f);
        for (unsigned long j = 1; j + curve.order <= n; ++j)
            curve.knots.push_back(float(j));
        for (unsigned long j = 0; j < curve.order; ++j)
            curve.knots.push_back(float(n - curve.order + 1));
        loop.push_back(std::move(curve));
    }
    if (!counterclockwise) {
        // Reverse the loop: the curves in reverse order, each reversed
        // (its knots mirrored).
        std::reverse(loop.begin(), loop.end());
        for (TrimCurve& c : loop) {
            std::reverse(c.points.begin(), c.points.end());
            const float end = c.knots.back();
            std::reverse(c.knots.begin(), c.knots.end());
            for (float& k : c.knots)
                k = end - k;
        }
    }
    return loop;
}

/// Dense polygons of a patch's loops in (u, v), `perSpan` samples per span
/// of every trim curve, by SubdivisionReference.h's curve evaluator.
inline std::vector<std::vector<std::pair<Real, Real>>> densePolygons(const Patch& p, int perSpan)
{
    std::vector<std::vector<std::pair<Real, Real>>> out;
    for (const std::vector<TrimCurve>& loop : p.loops) {
        out.emplace_back();
        for (const TrimCurve& t : loop) {
            const subdivision::DenseSamples samples = subdivision::denseSamples(t.asCurve(), perSpan);
            for (std::size_t i = 0; i + 1 < samples.local.size(); ++i)
                out.back().emplace_back(samples.local[i].x, samples.local[i].y);
        }
    }
    return out;
}

/// Segments in (u, v) bucketed in a uniform grid, for nearest-segment
/// queries by rings of cells around the query point.
class SegmentGrid {
public:
    struct Segment {
        Real u0, v0, u1, v1;
        std::size_t tag;
    };

    void build(std::vector<Segment> segments)
    {
        m_segments = std::move(segments);
        m_lo = {1e30L, 1e30L};
        m_hi = {-1e30L, -1e30L};
        for (const Segment& s : m_segments) {
            m_lo = {std::min({m_lo.first, s.u0, s.u1}), std::min({m_lo.second, s.v0, s.v1})};
            m_hi = {std::max({m_hi.first, s.u0, s.u1}), std::max({m_hi.second, s.v0, s.v1})};
        }
        m_n = std::max<int>(1, int(std::sqrt(double(m_segments.size())) / 2));
        m_cell = std::max((m_hi.first - m_lo.first) / m_n, (m_hi.second - m_lo.second) / m_n);
        if (!(m_cell > 0))
            m_cell = 1;
        m_cells.assign(std::size_t(m_n) * m_n, {});
        for (std::size_t i = 0; i < m_segments.size(); ++i) {
            const Segment& s = m_segments[i];
            for (int y = cellOf(std::min(s.v0, s.v1), m_lo.second); y <= cellOf(std::max(s.v0, s.v1), m_lo.second); ++y)
                for (int x = cellOf(std::min(s.u0, s.u1), m_lo.first); x <= cellOf(std::max(s.u0, s.u1), m_lo.first); ++x)
                    m_cells[std::size_t(y) * m_n + x].push_back(i);
        }
    }

    /// The distance to the nearest segment; `tag` receives its tag.
    Real nearest(Real u, Real v, std::size_t* tag = nullptr) const
    {
        Real best2 = std::numeric_limits<Real>::infinity();
        const int cx = cellOf(u, m_lo.first), cy = cellOf(v, m_lo.second);
        for (int ring = 0; ring <= 2 * m_n; ++ring) {
            // Every cell in this ring is at least (ring - 1) cells away.
            const Real reach = (ring - 1) * m_cell;
            if (ring > 1 && reach * reach > best2 && insideGrid(u, v))
                break;
            for (int y = cy - ring; y <= cy + ring; ++y)
                for (int x = cx - ring; x <= cx + ring; ++x) {
                    if (std::max(std::abs(x - cx), std::abs(y - cy)) != ring || x < 0 || y < 0 || x >= m_n || y >= m_n)
                        continue;
                    for (std::size_t i : m_cells[std::size_t(y) * m_n + x]) {
                        const Segment& s = m_segments[i];
                        const Real ex = s.u1 - s.u0, ey = s.v1 - s.v0;
                        const Real len2 = ex * ex + ey * ey;
                        const Real t = len2 > 0 ? std::clamp(((u - s.u0) * ex + (v - s.v0) * ey) / len2, Real(0), Real(1)) : 0;
                        const Real dx = s.u0 + t * ex - u, dy = s.v0 + t * ey - v;
                        const Real d2 = dx * dx + dy * dy;
                        if (d2 < best2) {
                            best2 = d2;
                            if (tag != nullptr)
                                *tag = s.tag;
                        }
                    }
                }
        }
        return std::sqrt(best2);
    }

private:
    int cellOf(Real value, Real lo) const { return std::clamp(int((value - lo) / m_cell), 0, m_n - 1); }
    bool insideGrid(Real u, Real v) const
    {
        return u >= m_lo.first && u <= m_hi.first && v >= m_lo.second && v <= m_hi.second;
    }

    std::vector<Segment> m_segments;
    std::vector<std::vector<std::size_t>> m_cells;
    std::pair<Real, Real> m_lo, m_hi;
    Real m_cell = 1;
    int m_n = 1;
};

/// The distance in (u, v) from a point to a patch's trim curves: the nearest
/// of `perSpan` samples per span, then a golden-section search on the curve
/// parameter around it (the curve evaluator of SubdivisionReference.h).
class TrimLocator {
public:
    TrimLocator(const Patch& p, int perSpan)
    {
        for (const std::vector<TrimCurve>& loop : p.loops)
            for (const TrimCurve& t : loop) {
                subdivision::Curve c = t.asCurve();
                m_samples.push_back(subdivision::denseSamples(c, perSpan));
                m_curves.push_back(std::move(c));
            }
        std::vector<SegmentGrid::Segment> segments;
        for (std::size_t c = 0; c < m_samples.size(); ++c)
            for (std::size_t i = 0; i + 1 < m_samples[c].local.size(); ++i) {
                const Vec3& a = m_samples[c].local[i];
                const Vec3& b = m_samples[c].local[i + 1];
                segments.push_back({a.x, a.y, b.x, b.y, (std::size_t(c) << 32) | i});
            }
        m_grid.build(std::move(segments));
    }

    Real distance(Real u, Real v) const
    {
        // The nearest chord between samples, then a golden-section search on
        // the curve parameter over the two sample intervals around it.
        std::size_t tag = 0;
        Real best = m_grid.nearest(u, v, &tag);
        const std::size_t c = tag >> 32, i = tag & 0xFFFFFFFFu;
        const subdivision::DenseSamples& s = m_samples[c];
        Real lo = s.t[i == 0 ? 0 : i - 1];
        Real hi = s.t[std::min(i + 2, s.t.size() - 1)];
        auto at = [&](Real t) {
            const Vec3 q = subdivision::evaluate(m_curves[c], t);
            return std::hypot(q.x - u, q.y - v);
        };
        return std::min(best, q3test::goldenSectionMinimum(at, lo, hi, 50));
    }

private:
    std::vector<subdivision::Curve> m_curves;
    std::vector<subdivision::DenseSamples> m_samples;
    SegmentGrid m_grid;
};

/// Whether (u, v) is kept: odd count of loops around it, plus one when every
/// loop that no other loop surrounds is clockwise (QD3DGeometry.h's rule for
/// properly nested loops).
class Region {
public:
    Region(const Patch& p, int perSpan) : m_polygons(densePolygons(p, perSpan))
    {
        for (const auto& polygon : m_polygons) {
            Box b{1e30L, -1e30L, 1e30L, -1e30L};
            for (const auto& q : polygon) {
                b.u0 = std::min(b.u0, q.first);
                b.u1 = std::max(b.u1, q.first);
                b.v0 = std::min(b.v0, q.second);
                b.v1 = std::max(b.v1, q.second);
            }
            m_boxes.push_back(b);
        }
        std::vector<SegmentGrid::Segment> segments;
        for (const auto& polygon : m_polygons)
            for (std::size_t i = 0, n = polygon.size(); i < n; ++i)
                segments.push_back({polygon[i].first, polygon[i].second, polygon[(i + 1) % n].first,
                                    polygon[(i + 1) % n].second, 0});
        m_grid.build(std::move(segments));
        m_outerCounts = p.loops.empty();
        bool anyOuterCounterclockwise = false;
        for (std::size_t l = 0; l < m_polygons.size(); ++l) {
            bool outermost = true;
            for (std::size_t m = 0; m < m_polygons.size(); ++m)
                if (m != l && inside(m_polygons[m], m_polygons[l][0].first, m_polygons[l][0].second))
                    outermost = false;
            if (outermost && p.loopCounterclockwise[l])
                anyOuterCounterclockwise = true;
        }
        m_outerCounts = !anyOuterCounterclockwise;
    }

    bool kept(Real u, Real v) const
    {
        int count = m_outerCounts ? 1 : 0;
        for (std::size_t i = 0; i < m_polygons.size(); ++i) {
            const Box& b = m_boxes[i];
            if (u < b.u0 || u > b.u1 || v < b.v0 || v > b.v1)
                continue;
            count += inside(m_polygons[i], u, v) ? 1 : 0;
        }
        return count % 2 == 1;
    }

    /// The distance in (u, v) from a point to the nearest loop.
    Real distanceToLoops(Real u, Real v) const { return m_grid.nearest(u, v); }

    /// The kept area in (u, v) (shoelace areas with the even-odd signs).
    Real area(Real domainArea) const
    {
        Real total = m_outerCounts ? domainArea : 0;
        for (const auto& polygon : m_polygons) {
            Real a = 0;
            for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
                const auto& p = polygon[i];
                const auto& q = polygon[(i + 1) % n];
                a += p.first * q.second - q.first * p.second;
            }
            a = std::fabs(a) / 2;
            total += (depth(polygon) + (m_outerCounts ? 1 : 0)) % 2 == 0 ? a : -a;
        }
        return total;
    }

private:
    static bool inside(const std::vector<std::pair<Real, Real>>& polygon, Real u, Real v)
    {
        bool in = false;
        for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
            const auto& a = polygon[i];
            const auto& b = polygon[j];
            if ((a.second > v) != (b.second > v) &&
                u < (b.first - a.first) * (v - a.second) / (b.second - a.second) + a.first)
                in = !in;
        }
        return in;
    }

    int depth(const std::vector<std::pair<Real, Real>>& polygon) const
    {
        int d = 0;
        for (const auto& other : m_polygons)
            if (&other != &polygon && inside(other, polygon[0].first, polygon[0].second))
                ++d;
        return d;
    }

    struct Box {
        Real u0, u1, v0, v1;
    };
    std::vector<std::vector<std::pair<Real, Real>>> m_polygons;
    std::vector<Box> m_boxes;
    SegmentGrid m_grid;
    bool m_outerCounts = true;
};

/// Random trim loops for p: 0 none; 1 an outer counterclockwise loop with a
/// clockwise hole holding a counterclockwise island; 2 a lone clockwise hole;
/// 3 an outer loop with two holes side by side.
inline void addRandomTrims(std::mt19937& rng, Patch& p, int kind)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto curves = [&] { return 1 + int(3 * unit(rng)) % 3; };
    const Real cu = (p.u0() + p.u1()) / 2 + (p.u1() - p.u0()) * Real(0.04 * (unit(rng) - 0.5));
    const Real cv = (p.v0() + p.v1()) / 2 + (p.v1() - p.v0()) * Real(0.04 * (unit(rng) - 0.5));
    const Real au = (p.u1() - p.u0()) * 0.45L, av = (p.v1() - p.v0()) * 0.45L;
    auto add = [&](std::vector<TrimCurve> loop, bool ccw) {
        p.loops.push_back(std::move(loop));
        p.loopCounterclockwise.push_back(ccw);
    };
    switch (kind) {
    case 1:
        add(starLoop(rng, cu, cv, au, av, 0.85L, 1.0L, curves(), true), true);
        add(starLoop(rng, cu, cv, au, av, 0.45L, 0.6L, curves(), false), false);
        add(starLoop(rng, cu, cv, au, av, 0.1L, 0.25L, curves(), true), true);
        break;
    case 2:
        add(starLoop(rng, cu, cv, au, av, 0.3L, 0.6L, curves(), false), false);
        break;
    case 3:
        add(starLoop(rng, cu, cv, au, av, 0.85L, 1.0L, curves(), true), true);
        add(starLoop(rng, cu - au * 0.4L, cv, au, av, 0.15L, 0.3L, curves(), false), false);
        add(starLoop(rng, cu + au * 0.4L, cv, au, av, 0.15L, 0.3L, curves(), false), false);
        break;
    default:
        break;
    }
}

} // namespace q3test::patches
