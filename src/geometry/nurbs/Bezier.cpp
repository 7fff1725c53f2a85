// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Rational Bezier form of each span, and the fast sampling kernel built on it.
//
// Conversion. The article's section "CONVERTING NURB TO BEZIER CURVES" describes
// the method: insert knots at both ends of a span until each end has k-1 equal
// knots; the k control points that then govern the span are its Bezier points.
// Repeated Boehm insertion of the same knot (article, "KNOT INSERTION") at the span
// start a = x_l is exactly de Boor's triangle evaluated at t = a (lecture eqs.
// 6.28-6.30): its right edge P_l^0, P_l^1, ..., P_l^{k-1} are the control points of
// the curve with a inserted k-1 times (lecture 6.6.1 notes the triangle "permits the
// splitting of the segment"). A second triangle then inserts b = x_{l+1} k-1 times
// into those points; in blossom terms it turns f(a^{k-1-m}, x_{l+1} .. x_{l+m}) into
// f(a^{k-1-m}, b^m) with the step weight (b - a) / (x_{l+m-s+1} - a). Both triangles
// only ever form convex combinations, so the conversion is as stable as de Boor
// itself. Each span is converted independently (O(k^2) per span) rather than
// sweeping the knot vector as Piegl & Tiller's algorithm A5.6 does, so a tessellator
// can convert spans one at a time without storing the whole form.
//
// Sampling. On a Bezier span the homogeneous point is sum_r B_{r,k-1}(u) P_r
// (Bernstein basis). For uniform samples u_j = j/m the weights B_{r,k-1}(u_j) do not
// depend on the span, so they are tabulated once per (order, m) and each sample is
// k multiply-adds per coordinate plus one division by w; two samples share each
// vector instruction. The weights are built by the de Casteljau-style recurrence
// B_{r,d}(u) = (1-u) B_{r,d-1}(u) + u B_{r-1,d-1}(u), which makes the end samples exact.
//
// Single points at arbitrary u use the Bernstein form with Horner's rule in
// s = u/(1-u) (or (1-u)/u past the midpoint, so |s| <= 1), O(k) per point.

#include "geometry/nurbs/Bezier.h"

#include <algorithm>
#include <cstring>

namespace q3::nurbs {
namespace {

struct Binomials {
    double value[kMaxOrder][kMaxOrder] = {};
    constexpr Binomials()
    {
        for (unsigned n = 0; n < kMaxOrder; ++n) {
            value[n][0] = 1.0;
            for (unsigned r = 1; r <= n; ++r) {
                value[n][r] = value[n - 1][r - 1] + (r < n ? value[n - 1][r] : 0.0);
            }
        }
    }
};
constexpr Binomials kBinomials;

inline Point4 lerp(const Point4& a, const Point4& b, double alpha)
{
    const double beta = 1.0 - alpha;
    return Point4{beta * a.x + alpha * b.x, beta * a.y + alpha * b.y,
                  beta * a.z + alpha * b.z, beta * a.w + alpha * b.w};
}

#if defined(__GNUC__)
// Two samples per step in one SSE2 register pair: the weights of consecutive samples
// are adjacent in a table column, so one load feeds both, and one division serves two w.
typedef double Double2 __attribute__((vector_size(16)));

inline Double2 load2(const double* p)
{
    Double2 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
#endif

template <unsigned K, typename Out>
void sampleFixed(const Point4* points, const BernsteinTable& table, std::uint32_t first,
                 std::uint32_t count, Out* xyz)
{
    double px[K];
    double py[K];
    double pz[K];
    double pw[K];
    const double* column[K];
    for (unsigned r = 0; r < K; ++r) {
        px[r] = points[r].x;
        py[r] = points[r].y;
        pz[r] = points[r].z;
        pw[r] = points[r].w;
        column[r] = table.column(r) + first;
    }
    std::uint32_t j = 0;
#if defined(__GNUC__)
    // The control points broadcast once, so the loop multiplies by memory operands.
    Double2 cx[K], cy[K], cz[K], cw[K];
    for (unsigned r = 0; r < K; ++r) {
        cx[r] = Double2{px[r], px[r]};
        cy[r] = Double2{py[r], py[r]};
        cz[r] = Double2{pz[r], pz[r]};
        cw[r] = Double2{pw[r], pw[r]};
    }
    for (; j + 4 <= count; j += 4) {
        Double2 x0 = {0.0, 0.0}, x1 = {0.0, 0.0};
        Double2 y0 = {0.0, 0.0}, y1 = {0.0, 0.0};
        Double2 z0 = {0.0, 0.0}, z1 = {0.0, 0.0};
        Double2 w0 = {0.0, 0.0}, w1 = {0.0, 0.0};
        for (unsigned r = 0; r < K; ++r) {
            const Double2 b0 = load2(column[r] + j);
            const Double2 b1 = load2(column[r] + j + 2);
            x0 += b0 * cx[r];
            x1 += b1 * cx[r];
            y0 += b0 * cy[r];
            y1 += b1 * cy[r];
            z0 += b0 * cz[r];
            z1 += b1 * cz[r];
            w0 += b0 * cw[r];
            w1 += b1 * cw[r];
        }
        const Double2 inv0 = 1.0 / w0;
        const Double2 inv1 = 1.0 / w1;
        x0 *= inv0;
        y0 *= inv0;
        z0 *= inv0;
        x1 *= inv1;
        y1 *= inv1;
        z1 *= inv1;
        Out* out = xyz + 3 * std::size_t(j);
        out[0] = Out(x0[0]);
        out[1] = Out(y0[0]);
        out[2] = Out(z0[0]);
        out[3] = Out(x0[1]);
        out[4] = Out(y0[1]);
        out[5] = Out(z0[1]);
        out[6] = Out(x1[0]);
        out[7] = Out(y1[0]);
        out[8] = Out(z1[0]);
        out[9] = Out(x1[1]);
        out[10] = Out(y1[1]);
        out[11] = Out(z1[1]);
    }
    for (; j + 2 <= count; j += 2) {
        Double2 x = {0.0, 0.0};
        Double2 y = {0.0, 0.0};
        Double2 z = {0.0, 0.0};
        Double2 w = {0.0, 0.0};
        for (unsigned r = 0; r < K; ++r) {
            const Double2 b = load2(column[r] + j);
            x += b * px[r];
            y += b * py[r];
            z += b * pz[r];
            w += b * pw[r];
        }
        const Double2 inv = 1.0 / w;
        x *= inv;
        y *= inv;
        z *= inv;
        Out* out = xyz + 3 * std::size_t(j);
        out[0] = Out(x[0]);
        out[1] = Out(y[0]);
        out[2] = Out(z[0]);
        out[3] = Out(x[1]);
        out[4] = Out(y[1]);
        out[5] = Out(z[1]);
    }
#endif
    for (; j < count; ++j) {
        double x = 0.0;
        double y = 0.0;
        double z = 0.0;
        double w = 0.0;
        for (unsigned r = 0; r < K; ++r) {
            const double b = column[r][j];
            x += b * px[r];
            y += b * py[r];
            z += b * pz[r];
            w += b * pw[r];
        }
        const double inv = 1.0 / w;
        Out* out = xyz + 3 * std::size_t(j);
        out[0] = Out(x * inv);
        out[1] = Out(y * inv);
        out[2] = Out(z * inv);
    }
}

template <typename Out>
void sampleDispatch(const Point4* points, const BernsteinTable& table, std::uint32_t first,
                    std::uint32_t count, Out* xyz)
{
    switch (table.order()) {
    case 2: sampleFixed<2>(points, table, first, count, xyz); break;
    case 3: sampleFixed<3>(points, table, first, count, xyz); break;
    case 4: sampleFixed<4>(points, table, first, count, xyz); break;
    case 5: sampleFixed<5>(points, table, first, count, xyz); break;
    case 6: sampleFixed<6>(points, table, first, count, xyz); break;
    case 7: sampleFixed<7>(points, table, first, count, xyz); break;
    case 8: sampleFixed<8>(points, table, first, count, xyz); break;
    case 9: sampleFixed<9>(points, table, first, count, xyz); break;
    case 10: sampleFixed<10>(points, table, first, count, xyz); break;
    case 11: sampleFixed<11>(points, table, first, count, xyz); break;
    case 12: sampleFixed<12>(points, table, first, count, xyz); break;
    case 13: sampleFixed<13>(points, table, first, count, xyz); break;
    case 14: sampleFixed<14>(points, table, first, count, xyz); break;
    case 15: sampleFixed<15>(points, table, first, count, xyz); break;
    case 16: sampleFixed<16>(points, table, first, count, xyz); break;
    default: break;
    }
}

} // namespace

BernsteinTable::BernsteinTable(unsigned order, std::uint32_t segments)
{
    if (order < kMinOrder || order > kMaxOrder || segments == 0) {
        return;  // an empty table; the kernels write nothing with it
    }
    m_order = order;
    m_segments = segments;
    m_weights.assign((std::size_t(segments) + 1) * order, 0.0);
    const std::size_t stride = std::size_t(segments) + 1;
    double b[kMaxOrder];
    for (std::uint32_t j = 0; j <= segments; ++j) {
        const double u = double(j) / double(segments);
        const double v = 1.0 - u;
        b[0] = 1.0;
        for (unsigned degree = 1; degree < order; ++degree) {
            b[degree] = u * b[degree - 1];
            for (unsigned r = degree - 1; r > 0; --r) {
                b[r] = v * b[r] + u * b[r - 1];
            }
            b[0] = v * b[0];
        }
        for (unsigned r = 0; r < order; ++r) {
            m_weights[r * stride + j] = b[r];
        }
    }
}

void spanToBezier(const CurveRef& curve, std::size_t l, Point4* out)
{
    const unsigned deg = curve.order - 1;
    const float* x = curve.knots;
    const float* p = curve.points;
    const double a = x[l];
    const double b = x[l + 1];

    // First triangle: de Boor at t = a; its right edge becomes out[deg], ..., out[0].
    Point4 d[kMaxOrder];
    for (unsigned j = 0; j <= deg; ++j) {
        const float* q = p + 4 * (l - deg + j);
        d[j] = Point4{q[0], q[1], q[2], q[3]};
    }
    out[deg] = d[deg];
    for (unsigned r = 1; r <= deg; ++r) {
        for (unsigned j = deg; j >= r; --j) {
            const double lo = x[l - deg + j];
            const double hi = x[l + 1 + j - r];
            d[j] = lerp(d[j - 1], d[j], (a - lo) / (hi - lo));
        }
        out[deg - r] = d[deg];
    }

    // Second triangle: replace the right-hand knots x_{l+1} .. x_{l+m} by b.
    for (unsigned s = 1; s <= deg; ++s) {
        for (unsigned m = deg; m >= s; --m) {
            const double xm = x[l + m - s + 1];
            out[m] = lerp(out[m - 1], out[m], (b - a) / (xm - a));
        }
    }
}

namespace {

// The span's left-clamped polygon f(a^{p-m}, x_{l+1} .. x_{l+m}): de Boor's
// triangle at a = x_l (the first triangle of spanToBezier).
void leftClamped(const CurveRef& curve, std::size_t l, Point4* out)
{
    const unsigned deg = curve.order - 1;
    const float* x = curve.knots;
    const float* p = curve.points;
    const double a = x[l];
    Point4 d[kMaxOrder];
    for (unsigned j = 0; j <= deg; ++j) {
        const float* q = p + 4 * (l - deg + j);
        d[j] = Point4{q[0], q[1], q[2], q[3]};
    }
    out[deg] = d[deg];
    for (unsigned r = 1; r <= deg; ++r) {
        for (unsigned j = deg; j >= r; --j) {
            const double lo = x[l - deg + j];
            const double hi = x[l + 1 + j - r];
            d[j] = lerp(d[j - 1], d[j], (a - lo) / (hi - lo));
        }
        out[deg - r] = d[deg];
    }
}

} // namespace

void BezierSweep::convert(std::size_t l, Point4* out)
{
    const unsigned p = m_curve.order - 1;
    const float* x = m_curve.knots;
    const std::size_t knotCount = m_curve.numPoints + m_curve.order;
    if (l != m_next)
        leftClamped(m_curve, l, m_left);
    for (unsigned i = 0; i <= p; ++i)
        out[i] = m_left[i];
    // The run of knots equal to b = x_{l+1}: indices l+1 .. e.
    std::size_t e = l + 1;
    while (e + 1 < knotCount && x[e + 1] == x[l + 1])
        ++e;
    const unsigned mult = unsigned(std::min<std::size_t>(e - l, p));
    const unsigned r = p - mult;
    Point4 next[kMaxOrder];
    if (r > 0) {
        const double a = x[l];
        const double numer = double(x[l + 1]) - a;
        double alphas[kMaxOrder];
        for (unsigned j = p; j > mult; --j)
            alphas[j - mult - 1] = numer / (double(x[l + j]) - a);
        for (unsigned j = 1; j <= r; ++j) {
            const unsigned save = r - j;
            const unsigned s = mult + j;
            for (unsigned k = p; k >= s; --k)
                out[k] = lerp(out[k - 1], out[k], alphas[k - s]);
            next[save] = out[p];
        }
    }
    // The next span starts at knot e; its polygon's right part is original points.
    m_next = std::size_t(-1);
    if (e < m_curve.numPoints) {
        const float* pts = m_curve.points;
        for (unsigned i = r; i <= p; ++i) {
            const float* q = pts + 4 * (e - p + i);
            next[i] = Point4{q[0], q[1], q[2], q[3]};
        }
        for (unsigned i = 0; i <= p; ++i)
            m_left[i] = next[i];
        m_next = e;
    }
}

Point4 evaluateBezier(const Point4* points, unsigned order, double u)
{
    const unsigned deg = order - 1;
    const double* binomial = kBinomials.value[deg];
    Point4 acc;
    double scale = 1.0;
    if (u <= 0.5) {
        const double v = 1.0 - u;
        const double s = u / v;
        acc = points[deg];
        for (unsigned r = deg; r-- > 0;) {
            const double c = binomial[r];
            acc = Point4{acc.x * s + c * points[r].x, acc.y * s + c * points[r].y,
                         acc.z * s + c * points[r].z, acc.w * s + c * points[r].w};
            scale *= v;
        }
    } else {
        const double s = (1.0 - u) / u;
        acc = points[0];
        for (unsigned r = 1; r <= deg; ++r) {
            const double c = binomial[r];
            acc = Point4{acc.x * s + c * points[r].x, acc.y * s + c * points[r].y,
                         acc.z * s + c * points[r].z, acc.w * s + c * points[r].w};
            scale *= u;
        }
    }
    return Point4{acc.x * scale, acc.y * scale, acc.z * scale, acc.w * scale};
}

void sampleBezier(const Point4* points, const BernsteinTable& table, std::uint32_t first,
                  std::uint32_t count, float* xyz)
{
    sampleDispatch(points, table, first, count, xyz);
}

void sampleBezier(const Point4* points, const BernsteinTable& table, std::uint32_t first,
                  std::uint32_t count, double* xyz)
{
    sampleDispatch(points, table, first, count, xyz);
}

BezierForm::BezierForm(const CurveRef& curve)
{
    rebuild(curve);
}

void BezierForm::rebuild(const CurveRef& curve)
{
    m_spans.clear();
    m_points.clear();
    m_order = 0;
    if (!validateCurve(curve).ok()) {
        return;
    }
    m_order = curve.order;
    for (std::size_t i = curve.order - 1; i < curve.numPoints; ++i) {
        const double a = curve.knots[i];
        const double b = curve.knots[i + 1];
        if (a < b) {
            m_spans.push_back(Span{i, a, b});
        }
    }
    m_points.resize(m_spans.size() * m_order);
    BezierSweep sweep(curve);
    for (std::size_t s = 0; s < m_spans.size(); ++s) {
        sweep.convert(m_spans[s].knotIndex, m_points.data() + s * m_order);
    }
}

Domain BezierForm::domain() const
{
    return empty() ? Domain{} : Domain{m_spans.front().start, m_spans.back().end};
}

std::size_t BezierForm::findSpan(double t) const
{
    // Largest s with span(s).start <= t, or 0.
    std::size_t lo = 0;
    std::size_t hi = m_spans.size();
    while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (m_spans[mid].start <= t) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return lo;
}

Point4 BezierForm::evaluateHomogeneous(double t) const
{
    if (empty()) {
        return Point4{};
    }
    t = clampToDomain(domain(), t);
    const std::size_t s = findSpan(t);
    const Span& span = m_spans[s];
    double u = (t - span.start) / (span.end - span.start);
    u = std::min(1.0, std::max(0.0, u));
    return evaluateBezier(spanPoints(s), m_order, u);
}

Point3 BezierForm::evaluate(double t) const
{
    return project(evaluateHomogeneous(t));
}

void BezierForm::sampleSpan(std::size_t s, const BernsteinTable& table, std::uint32_t first,
                            std::uint32_t count, float* xyz) const
{
    sampleDispatch(spanPoints(s), table, first, count, xyz);
}

void BezierForm::sampleSpan(std::size_t s, const BernsteinTable& table, std::uint32_t first,
                            std::uint32_t count, double* xyz) const
{
    sampleDispatch(spanPoints(s), table, first, count, xyz);
}

} // namespace q3::nurbs
