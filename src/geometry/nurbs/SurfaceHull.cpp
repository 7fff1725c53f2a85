// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The view-volume test of a patch piece by its Bezier control points.
//
// In one variable, the Bezier points of a span's polynomial over [a, b] are
// the blossoms f(a^(k-1-m), b^m). Two triangles give them (Bezier.cpp's
// spanToBezier with a and b inside the span instead of its ends): de Boor's
// triangle at a, whose right edge is f(a^(k-1-m), x_(l+1) .. x_(l+m)), then
// the knots x_(l+1) .. x_(l+m) replaced by b one at a time, each step an
// affine combination in one blossom argument. Applied to the columns of a
// span pair in v and then to the resulting rows in u, this gives the
// uOrder x vOrder homogeneous Bezier points of the piece over a rectangle.
// Their frustum images are linear in them, and the weights are positive, so
// a plane all of them are outside of bounds the whole piece.

#include "geometry/nurbs/SurfaceHull.h"

#include <algorithm>
#include <cmath>

namespace q3::nurbs {
namespace {

// Bezier points over [a, b] of the order-k spline with knots x, span l, its
// k control points in d (4 doubles each), in place. a < x[l + 1], a <= b.
void toBezier(const float* x, std::size_t l, unsigned k, double a, double b, double (*d)[4])
{
    double right[kMaxPatchOrder][4];
    double work[kMaxPatchOrder][4];
    std::copy(&d[0][0], &d[0][0] + 4 * k, &work[0][0]);
    std::copy(work[k - 1], work[k - 1] + 4, right[k - 1]);
    for (unsigned r = 1; r < k; ++r) {
        for (unsigned i = k - 1; i >= r; --i) {
            const std::size_t j = l + 1 + i - k;
            const double x0 = x[j], x1 = x[j + k - r];
            const double alpha = x1 > x0 ? (a - x0) / (x1 - x0) : 0.0;
            for (int c = 0; c < 4; ++c)
                work[i][c] = (1.0 - alpha) * work[i - 1][c] + alpha * work[i][c];
        }
        std::copy(work[k - 1], work[k - 1] + 4, right[k - 1 - r]);
    }
    const unsigned deg = k - 1;
    for (unsigned s = 1; s <= deg; ++s)
        for (unsigned m = deg; m >= s; --m) {
            const double xm = x[l + m - s + 1];
            const double beta = xm > a ? (b - a) / (xm - a) : 0.0;
            for (int c = 0; c < 4; ++c)
                right[m][c] = (1.0 - beta) * right[m - 1][c] + beta * right[m][c];
        }
    std::copy(&right[0][0], &right[0][0] + 4 * k, &d[0][0]);
}

} // namespace

SurfaceHull::SurfaceHull(const SurfaceRef& surface, const std::array<double, 16>& clip)
    : m_s(surface), m_clip(clip), m_uSpans(uSpans(surface)), m_vSpans(vSpans(surface))
{
}

void SurfaceHull::planes(double x, double y, double z, double out[5]) const
{
    double f[4];
    for (int i = 0; i < 4; ++i)
        f[i] = m_clip[4 * i] * x + m_clip[4 * i + 1] * y + m_clip[4 * i + 2] * z + m_clip[4 * i + 3];
    out[0] = f[3] + f[0];
    out[1] = f[3] - f[0];
    out[2] = f[3] + f[1];
    out[3] = f[3] - f[1];
    out[4] = -f[2];
}

unsigned SurfaceHull::outsidePlanes(std::size_t su, std::size_t sv, double u0, double u1, double v0, double v1,
                                    bool* straddles) const
{
    if (straddles != nullptr)
        *straddles = false;
    const unsigned ku = m_s.uOrder, kv = m_s.vOrder;
    const std::size_t firstColumn = su + 1 - ku, firstRow = sv + 1 - kv;
    // Columns to Bezier form in v: grid[column][m].
    double grid[kMaxPatchOrder][kMaxPatchOrder][4];
    for (unsigned c = 0; c < ku; ++c) {
        double d[kMaxPatchOrder][4];
        for (unsigned r = 0; r < kv; ++r) {
            const float* p = m_s.points + 4 * ((firstRow + r) * m_s.numColumns + firstColumn + c);
            for (int q = 0; q < 4; ++q)
                d[r][q] = p[q];
        }
        toBezier(m_s.vKnots, sv, kv, v0, v1, d);
        for (unsigned m = 0; m < kv; ++m)
            std::copy(d[m], d[m] + 4, grid[c][m]);
    }
    unsigned mask = 31u;
    for (unsigned m = 0; m < kv && (mask != 0 || straddles != nullptr); ++m) {
        double d[kMaxPatchOrder][4];
        for (unsigned c = 0; c < ku; ++c)
            std::copy(grid[c][m], grid[c][m] + 4, d[c]);
        toBezier(m_s.uKnots, su, ku, u0, u1, d);
        for (unsigned c = 0; c < ku && (mask != 0 || straddles != nullptr); ++c) {
            const double* h = d[c];
            double f[4];
            for (int i = 0; i < 4; ++i)
                f[i] = m_clip[4 * i] * h[0] + m_clip[4 * i + 1] * h[1] + m_clip[4 * i + 2] * h[2] +
                       m_clip[4 * i + 3] * h[3];
            const double values[5] = {f[3] + f[0], f[3] - f[0], f[3] + f[1], f[3] - f[1], -f[2]};
            const double margin = 1e-6 * (std::fabs(f[0]) + std::fabs(f[1]) + std::fabs(f[2]) + std::fabs(f[3]));
            for (unsigned plane = 0; plane < 5; ++plane) {
                if (!(values[plane] < -margin))
                    mask &= ~(1u << plane);
                if (straddles != nullptr && !(values[plane] >= 0.0))
                    *straddles = true;
            }
        }
    }
    return mask;
}

template <class F>
bool SurfaceHull::forEachPiece(double u0, double u1, double v0, double v1, F&& f) const
{
    if (!(u0 <= u1) || !(v0 <= v1))
        return false;
    // Spans with start <= hi and end >= lo; a piece of zero width at a span's
    // end belongs to the next span (or, at the domain's end, to the last).
    auto pieces = [](const std::vector<Span>& spans, double lo, double hi, std::vector<std::size_t>& out) {
        out.clear();
        auto it = std::upper_bound(spans.begin(), spans.end(), lo,
                                   [](double t, const Span& s) { return t < s.end; });
        if (it == spans.end())
            it = spans.end() - 1;
        for (; it != spans.end() && it->start <= hi; ++it) {
            out.push_back(std::size_t(it - spans.begin()));
            if (hi <= it->end)
                break;
        }
    };
    std::vector<std::size_t> us, vs;
    pieces(m_uSpans, u0, u1, us);
    pieces(m_vSpans, v0, v1, vs);
    bool any = false;
    for (std::size_t i : us)
        for (std::size_t j : vs) {
            const Span& su = m_uSpans[i];
            const Span& sv = m_vSpans[j];
            const double a = std::max(u0, su.start), b = std::min(u1, su.end);
            const double c = std::max(v0, sv.start), d = std::min(v1, sv.end);
            if (!(a <= b) || !(c <= d) || !(a < su.end || su.end == m_uSpans.back().end) ||
                !(c < sv.end || sv.end == m_vSpans.back().end))
                return false;
            any = true;
            if (!f(su.knotIndex, sv.knotIndex, a, b, c, d))
                return false;
        }
    return any;
}

bool SurfaceHull::outside(double u0, double u1, double v0, double v1) const
{
    unsigned mask = 31u;
    const bool all = forEachPiece(u0, u1, v0, v1, [&](std::size_t su, std::size_t sv, double a, double b, double c,
                                                      double d) {
        mask &= outsidePlanes(su, sv, a, b, c, d);
        return mask != 0;
    });
    return all && mask != 0;
}

bool SurfaceHull::inside(double u0, double u1, double v0, double v1) const
{
    return forEachPiece(u0, u1, v0, v1, [&](std::size_t su, std::size_t sv, double a, double b, double c, double d) {
        bool straddles = false;
        outsidePlanes(su, sv, a, b, c, d, &straddles);
        return !straddles;
    });
}

} // namespace q3::nurbs
