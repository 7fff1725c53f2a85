// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Tensor-product NURB surfaces (lecture 6, section 6.7.2 and eq. 6.46):
//
//   S(u, v) = sum_r sum_c N_{r,kv}(v) N_{c,ku}(u) w_rc P_rc / sum_r sum_c N_{r,kv}(v) N_{c,ku}(u) w_rc
//
// evaluated on the homogeneous points (w_rc P_rc, w_rc) as the article does
// for curves ("RATIONAL CURVES"), then divided by w. Only the ku x kv points of
// the span pair holding (u, v) contribute (local support, lecture 6.7.2).
//
// The basis functions come from the article's recursion ("DEFINING THE BASIS
// FUNCTIONS", lecture eqs. 6.5-6.6), built bottom-up for the k functions that
// are non-zero on the span; their derivatives from lecture eqs. 6.23-6.24
// written for a single basis function (the derivative of the curve sum with
// one control point set to 1). The partial derivatives of the rational
// surface follow from the quotient rule: with S_h = (X, Y, Z, W) the
// homogeneous sum, dS/du = (dX/du - S dW/du) / W, and likewise for v.
//
// Knot checks are the curve rules of the article's "NURB CURVES IN QUICKDRAW
// 3D" (Knots.cpp), applied to one knot vector at a time.

#include "geometry/nurbs/Surface.h"

#include "geometry/nurbs/Evaluate.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace q3::nurbs {

KnotCheck checkKnots(const float* knots, std::size_t numPoints, unsigned order)
{
    const std::size_t count = numPoints + order;
    KnotCheck result;
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isfinite(knots[i])) {
            result.rule = KnotRule::kNotFinite;
            result.index = i;
            return result;
        }
    for (std::size_t i = 1; i < count; ++i)
        if (knots[i] < knots[i - 1]) {
            result.rule = KnotRule::kDecreasing;
            result.index = i;
            return result;
        }
    for (std::size_t start = 0; start < count;) {
        std::size_t stop = start + 1;
        while (stop < count && knots[stop] == knots[start])
            ++stop;
        const bool atEnd = start == 0 || stop == count;
        const std::size_t limit = atEnd ? order : order - 1;
        if (stop - start > limit) {
            result.rule = KnotRule::kRunTooLong;
            result.index = start;
            result.run = stop - start;
            result.limit = limit;
            return result;
        }
        start = stop;
    }
    if (!(knots[order - 1] < knots[numPoints])) {
        result.rule = KnotRule::kEmptyDomain;
        result.index = order - 1;
    }
    return result;
}

SurfaceDomain surfaceDomain(const SurfaceRef& s)
{
    return SurfaceDomain{s.uKnots[s.uOrder - 1], s.uKnots[s.numColumns], s.vKnots[s.vOrder - 1],
                         s.vKnots[s.numRows]};
}

namespace {

std::vector<Span> spansOf(const float* knots, std::size_t numPoints, unsigned order)
{
    std::vector<Span> spans;
    for (std::size_t i = order - 1; i < numPoints; ++i)
        if (knots[i] < knots[i + 1])
            spans.push_back(Span{i, knots[i], knots[i + 1]});
    return spans;
}

double clampTo(double t, double lo, double hi)
{
    if (!(t > lo))
        return lo;
    return t < hi ? t : hi;
}

// The homogeneous sum and (optionally) its two partial derivatives.
struct Homogeneous {
    Point4 s;
    Point4 du;
    Point4 dv;
};

Homogeneous sum(const SurfaceRef& surface, double u, double v, bool derivatives)
{
    const SurfaceDomain d = surfaceDomain(surface);
    u = clampTo(u, d.u0, d.u1);
    v = clampTo(v, d.v0, d.v1);
    const unsigned ku = surface.uOrder;
    const unsigned kv = surface.vOrder;
    const std::size_t su = findKnotSpan(surface.uKnots, surface.numColumns, ku, u);
    const std::size_t sv = findKnotSpan(surface.vKnots, surface.numRows, kv, v);
    double nu[kMaxPatchOrder], dnu[kMaxPatchOrder], nv[kMaxPatchOrder], dnv[kMaxPatchOrder];
    basisWithDerivative(surface.uKnots, su, ku, u, nu, derivatives ? dnu : nullptr);
    basisWithDerivative(surface.vKnots, sv, kv, v, nv, derivatives ? dnv : nullptr);
    Homogeneous h;
    const std::size_t firstColumn = su + 1 - ku;
    const std::size_t firstRow = sv + 1 - kv;
    for (unsigned r = 0; r < kv; ++r) {
        // The row's curve at u, and its u-derivative.
        const float* row = surface.points + 4 * ((firstRow + r) * surface.numColumns + firstColumn);
        Point4 c, cu;
        for (unsigned j = 0; j < ku; ++j) {
            const float* p = row + 4 * j;
            c.x += nu[j] * p[0];
            c.y += nu[j] * p[1];
            c.z += nu[j] * p[2];
            c.w += nu[j] * p[3];
            if (derivatives) {
                cu.x += dnu[j] * p[0];
                cu.y += dnu[j] * p[1];
                cu.z += dnu[j] * p[2];
                cu.w += dnu[j] * p[3];
            }
        }
        h.s.x += nv[r] * c.x;
        h.s.y += nv[r] * c.y;
        h.s.z += nv[r] * c.z;
        h.s.w += nv[r] * c.w;
        if (derivatives) {
            h.du.x += nv[r] * cu.x;
            h.du.y += nv[r] * cu.y;
            h.du.z += nv[r] * cu.z;
            h.du.w += nv[r] * cu.w;
            h.dv.x += dnv[r] * c.x;
            h.dv.y += dnv[r] * c.y;
            h.dv.z += dnv[r] * c.z;
            h.dv.w += dnv[r] * c.w;
        }
    }
    return h;
}

Point3 quotientDerivative(const Point3& s, const Point4& d, double inverseW)
{
    return Point3{(d.x - s.x * d.w) * inverseW, (d.y - s.y * d.w) * inverseW, (d.z - s.z * d.w) * inverseW};
}

// The unit normal from the partials, or false when it is not well defined:
// |du x dv| is zero, or below 1e-10 |du| |dv| (lost to rounding).
bool unitNormal(const Point3& du, const Point3& dv, Point3& normal)
{
    const Point3 n{du.y * dv.z - du.z * dv.y, du.z * dv.x - du.x * dv.z, du.x * dv.y - du.y * dv.x};
    const double n2 = n.x * n.x + n.y * n.y + n.z * n.z;
    const double du2 = du.x * du.x + du.y * du.y + du.z * du.z;
    const double dv2 = dv.x * dv.x + dv.y * dv.y + dv.z * dv.z;
    if (!(n2 > 1e-20 * du2 * dv2) || !(n2 < std::numeric_limits<double>::infinity()))
        return false;
    const double inverse = 1.0 / std::sqrt(n2);
    normal = Point3{n.x * inverse, n.y * inverse, n.z * inverse};
    return true;
}

// The rational point and partials from the homogeneous ones.
void finish(const Point4& h, const Point4& hu, const Point4& hv, SurfacePoint& out)
{
    const double inverseW = 1.0 / h.w;
    out.point = Point3{h.x * inverseW, h.y * inverseW, h.z * inverseW};
    out.du = quotientDerivative(out.point, hu, inverseW);
    out.dv = quotientDerivative(out.point, hv, inverseW);
}

} // namespace

std::vector<Span> uSpans(const SurfaceRef& s)
{
    return spansOf(s.uKnots, s.numColumns, s.uOrder);
}

std::vector<Span> vSpans(const SurfaceRef& s)
{
    return spansOf(s.vKnots, s.numRows, s.vOrder);
}

std::size_t findKnotSpan(const float* knots, std::size_t numPoints, unsigned order, double t)
{
    CurveRef ref;
    ref.order = order;
    ref.numPoints = numPoints;
    ref.knots = knots;
    return findSpan(ref, t);
}

void basisWithDerivative(const float* knots, std::size_t span, unsigned order, double t, double* value,
                         double* derivative)
{
    // Two buffers take turns: `lower` holds N_{span-m+2+j, m-1}(t), the
    // functions of the order below, `level` receives N_{span-m+1+j, m}(t).
    double a[kMaxOrder + 1];
    double b[kMaxOrder + 1];
    double* lower = a;
    double* level = b;
    lower[0] = 1.0;
    for (unsigned m = 2; m <= order; ++m) {
        for (unsigned j = 0; j < m; ++j) {
            const std::size_t i = span + 1 + j - m; // N_{i,m}
            double sum = 0.0;
            if (j > 0) {
                // (t - x_i) / (x_{i+m-1} - x_i) N_{i,m-1}
                const double x0 = knots[i], x1 = knots[i + m - 1];
                if (x1 > x0)
                    sum += (t - x0) / (x1 - x0) * lower[j - 1];
            }
            if (j + 1 < m) {
                // (x_{i+m} - t) / (x_{i+m} - x_{i+1}) N_{i+1,m-1}
                const double x0 = knots[i + 1], x1 = knots[i + m];
                if (x1 > x0)
                    sum += (x1 - t) / (x1 - x0) * lower[j];
            }
            level[j] = sum;
        }
        if (m < order)
            std::swap(lower, level);
    }
    if (order < 2) {
        value[0] = 1.0;
        if (derivative != nullptr)
            derivative[0] = 0.0;
        return;
    }
    for (unsigned j = 0; j < order; ++j)
        value[j] = level[j];
    if (derivative == nullptr)
        return;
    // The order - 1 functions are still in `lower` (N_{span-order+2+j, order-1}).
    const double k1 = double(order - 1);
    for (unsigned j = 0; j < order; ++j) {
        const std::size_t i = span + 1 + j - order;
        double d = 0.0;
        if (j > 0) {
            const double x0 = knots[i], x1 = knots[i + order - 1];
            if (x1 > x0)
                d += lower[j - 1] / (x1 - x0);
        }
        if (j + 1 < order) {
            const double x0 = knots[i + 1], x1 = knots[i + order];
            if (x1 > x0)
                d -= lower[j] / (x1 - x0);
        }
        derivative[j] = k1 * d;
    }
}

Point3 evaluateSurface(const SurfaceRef& surface, double u, double v)
{
    return project(sum(surface, u, v, false).s);
}

SurfacePoint evaluateWithNormal(const SurfaceRef& surface, double u, double v)
{
    const SurfaceDomain d = surfaceDomain(surface);
    u = clampTo(u, d.u0, d.u1);
    v = clampTo(v, d.v0, d.v1);
    const Homogeneous h = sum(surface, u, v, true);
    SurfacePoint result;
    finish(h.s, h.du, h.dv, result);
    if (unitNormal(result.du, result.dv, result.normal))
        return result;
    // Towards the centre of the domain, farther and farther.
    const double cu = 0.5 * (d.u0 + d.u1), cv = 0.5 * (d.v0 + d.v1);
    const double width = d.u1 - d.u0, height = d.v1 - d.v0;
    for (double step : {1e-6, 1e-4, 1e-2}) {
        const double nu = u + (u < cu ? step : u > cu ? -step : 0.0) * width;
        const double nv = v + (v < cv ? step : v > cv ? -step : 0.0) * height;
        const Homogeneous near = sum(surface, nu, nv, true);
        SurfacePoint nearby;
        finish(near.s, near.du, near.dv, nearby);
        if (unitNormal(nearby.du, nearby.dv, result.normal))
            return result;
    }
    result.normal = Point3{};
    return result;
}

SurfaceRowEvaluator::SurfaceRowEvaluator(const SurfaceRef& surface)
    : m_s(surface), m_domain(surfaceDomain(surface)), m_columns(surface.numColumns),
      m_derivatives(surface.numColumns)
{
}

void SurfaceRowEvaluator::setV(double v, bool derivatives)
{
    v = clampTo(v, m_domain.v0, m_domain.v1);
    m_v = v;
    const std::size_t span = findKnotSpan(m_s.vKnots, m_s.numRows, m_s.vOrder, v);
    double n[kMaxPatchOrder], dn[kMaxPatchOrder];
    basisWithDerivative(m_s.vKnots, span, m_s.vOrder, v, n, derivatives ? dn : nullptr);
    const std::size_t firstRow = span + 1 - m_s.vOrder;
    const std::size_t columns = m_s.numColumns;
    for (std::size_t c = 0; c < columns; ++c) {
        Point4 q, dq;
        for (unsigned r = 0; r < m_s.vOrder; ++r) {
            const float* p = m_s.points + 4 * ((firstRow + r) * columns + c);
            q.x += n[r] * p[0];
            q.y += n[r] * p[1];
            q.z += n[r] * p[2];
            q.w += n[r] * p[3];
            if (derivatives) {
                dq.x += dn[r] * p[0];
                dq.y += dn[r] * p[1];
                dq.z += dn[r] * p[2];
                dq.w += dn[r] * p[3];
            }
        }
        m_columns[c] = q;
        m_derivatives[c] = dq;
    }
}

Point3 SurfaceRowEvaluator::point(double u) const
{
    u = clampTo(u, m_domain.u0, m_domain.u1);
    const std::size_t span = findKnotSpan(m_s.uKnots, m_s.numColumns, m_s.uOrder, u);
    double n[kMaxPatchOrder];
    basisWithDerivative(m_s.uKnots, span, m_s.uOrder, u, n, nullptr);
    Point4 h;
    const Point4* q = m_columns.data() + (span + 1 - m_s.uOrder);
    for (unsigned j = 0; j < m_s.uOrder; ++j) {
        h.x += n[j] * q[j].x;
        h.y += n[j] * q[j].y;
        h.z += n[j] * q[j].z;
        h.w += n[j] * q[j].w;
    }
    return project(h);
}

SurfacePoint SurfaceRowEvaluator::pointWithNormal(double u) const
{
    u = clampTo(u, m_domain.u0, m_domain.u1);
    const std::size_t span = findKnotSpan(m_s.uKnots, m_s.numColumns, m_s.uOrder, u);
    double n[kMaxPatchOrder], dn[kMaxPatchOrder];
    basisWithDerivative(m_s.uKnots, span, m_s.uOrder, u, n, dn);
    return pointWithNormal(u, span, n, dn);
}

SurfacePoint SurfaceRowEvaluator::pointWithNormal(double u, std::size_t span, const double* n, const double* dn) const
{
    Point4 h, hu, hv;
    const std::size_t first = span + 1 - m_s.uOrder;
    const Point4* q = m_columns.data() + first;
    const Point4* dq = m_derivatives.data() + first;
    for (unsigned j = 0; j < m_s.uOrder; ++j) {
        h.x += n[j] * q[j].x;
        h.y += n[j] * q[j].y;
        h.z += n[j] * q[j].z;
        h.w += n[j] * q[j].w;
        hu.x += dn[j] * q[j].x;
        hu.y += dn[j] * q[j].y;
        hu.z += dn[j] * q[j].z;
        hu.w += dn[j] * q[j].w;
        hv.x += n[j] * dq[j].x;
        hv.y += n[j] * dq[j].y;
        hv.z += n[j] * dq[j].z;
        hv.w += n[j] * dq[j].w;
    }
    SurfacePoint result;
    finish(h, hu, hv, result);
    if (!unitNormal(result.du, result.dv, result.normal))
        result.normal = evaluateWithNormal(m_s, u, m_v).normal;
    return result;
}

PlanarCurve::PlanarCurve(const TrimCurveRef& trim) : order(trim.order)
{
    points.resize(4 * trim.numPoints);
    for (std::size_t i = 0; i < trim.numPoints; ++i) {
        points[4 * i] = trim.points[3 * i];
        points[4 * i + 1] = trim.points[3 * i + 1];
        points[4 * i + 2] = 0.0f;
        points[4 * i + 3] = trim.points[3 * i + 2];
    }
    knots.assign(trim.knots, trim.knots + trim.numPoints + trim.order);
}

CurveRef PlanarCurve::ref() const
{
    CurveRef r;
    r.order = order;
    r.numPoints = points.size() / 4;
    r.points = points.data();
    r.knots = knots.data();
    return r;
}

TrimEnds trimCurveEnds(const TrimCurveRef& trim)
{
    const PlanarCurve planar(trim);
    const CurveRef ref = planar.ref();
    const Domain domain = curveDomain(ref);
    const Point3 a = evaluate(ref, domain.start).point;
    const Point3 b = evaluate(ref, domain.end).point;
    return TrimEnds{a.x, a.y, b.x, b.y};
}

} // namespace q3::nurbs
