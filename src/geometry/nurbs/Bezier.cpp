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
// itself. spanToBezier converts one span on its own (O(k^2)); BezierSweep walks the
// spans in order as Piegl & Tiller's algorithm A5.6 does, starting each from the
// previous one's by-products, still one span at a time, so a tessellator never needs
// to store the whole form.
//
// Sampling. On a Bezier span the homogeneous point is sum_r B_{r,k-1}(u) P_r
// (Bernstein basis). For uniform samples u_j = j/m the weights B_{r,k-1}(u_j) do not
// depend on the span, so they are tabulated once per (order, m) and each sample is
// k multiply-adds per coordinate plus one division by w; consecutive samples share each
// vector instruction (two with SSE2, four with AVX2; see "Vector code paths"). The weights are built by the de Casteljau-style recurrence
// B_{r,d}(u) = (1-u) B_{r,d-1}(u) + u B_{r-1,d-1}(u), which makes the end samples exact.
//
// Single points at arbitrary u use the Bernstein form with Horner's rule in
// s = u/(1-u) (or (1-u)/u past the midpoint, so |s| <= 1), O(k) per point.

#include "geometry/nurbs/Bezier.h"
#include "geometry/nurbs/Lanes.h"

#include <algorithm>
#include <atomic>
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

// ---- Vector code paths -------------------------------------------------------------
//
// The hot loops are written once over a GCC/Clang vector type V of N doubles and
// instantiated twice: with 128-bit vectors (SSE2, the x86-64 baseline, or the target's
// own 128-bit unit) and, on x86, with 256-bit vectors inside functions compiled for
// AVX2 and chosen at run time. Each lane does exactly the scalar arithmetic, in the
// same order, and nothing enables FMA, so both paths give the same bits. The vector
// types and the pieces both kernels share are in Lanes.h.

template <typename V>
Q3_LANES_INLINE void splat(V& v, double value)
{
    for (unsigned i = 0; i < kLanes<V>; ++i)
        v[i] = value;
}

// out = (1 - alpha) a + alpha b, per coordinate as (1 - alpha) * a + alpha * b, on
// 4 / N vectors.
template <typename V>
Q3_LANES_INLINE void lerpInto(const Point4& a, const Point4& b, double alpha, Point4& out)
{
    static_assert(sizeof(Point4) == 4 * sizeof(double), "Point4 is four packed doubles");
    const double beta = 1.0 - alpha;
    const char* pa = reinterpret_cast<const char*>(&a);
    const char* pb = reinterpret_cast<const char*>(&b);
    char* po = reinterpret_cast<char*>(&out);
    V va[4 / kLanes<V>];
    V vb[4 / kLanes<V>];
    for (unsigned h = 0; h < 4 / kLanes<V>; ++h) {
        std::memcpy(&va[h], pa + h * sizeof(V), sizeof(V));
        std::memcpy(&vb[h], pb + h * sizeof(V), sizeof(V));
    }
    for (unsigned h = 0; h < 4 / kLanes<V>; ++h) {
        const V r = beta * va[h] + alpha * vb[h];
        std::memcpy(po + h * sizeof(V), &r, sizeof(V));
    }
}

// Divides N homogeneous samples by their w and writes them as N (x, y, z) triples.
template <typename V, typename Out>
Q3_LANES_INLINE void storeProjected(const V& x, const V& y, const V& z, const V& w, Out* out)
{
    const V inv = 1.0 / w;
    const V px = x * inv;
    const V py = y * inv;
    const V pz = z * inv;
    for (unsigned i = 0; i < kLanes<V>; ++i) {
        out[3 * i] = Out(px[i]);
        out[3 * i + 1] = Out(py[i]);
        out[3 * i + 2] = Out(pz[i]);
    }
}

// The Bernstein sum for samples first .. first+count-1: 2N samples per step, then N,
// then one at a time. Every lane (and the scalar tail) computes
// ((0 + b_0 P_0) + b_1 P_1) + ... for each coordinate, then multiplies by 1 / w.
template <unsigned K, typename Out, typename V>
Q3_LANES_INLINE void sampleLanes(const Point4* points, const BernsteinTable& table,
                                  std::uint32_t first, std::uint32_t count, Out* xyz)
{
    constexpr unsigned N = kLanes<V>;
    const double* column[K];
    // The control points broadcast once, so the loop multiplies by memory operands.
    V cx[K], cy[K], cz[K], cw[K];
    for (unsigned r = 0; r < K; ++r) {
        column[r] = table.column(r) + first;
        splat(cx[r], points[r].x);
        splat(cy[r], points[r].y);
        splat(cz[r], points[r].z);
        splat(cw[r], points[r].w);
    }
    std::uint32_t j = 0;
    for (; j + 2 * N <= count; j += 2 * N) {
        V x0 = {}, x1 = {}, y0 = {}, y1 = {}, z0 = {}, z1 = {}, w0 = {}, w1 = {};
        for (unsigned r = 0; r < K; ++r) {
            V b0, b1;
            loadLanes(b0, column[r] + j);
            loadLanes(b1, column[r] + j + N);
            x0 += b0 * cx[r];
            x1 += b1 * cx[r];
            y0 += b0 * cy[r];
            y1 += b1 * cy[r];
            z0 += b0 * cz[r];
            z1 += b1 * cz[r];
            w0 += b0 * cw[r];
            w1 += b1 * cw[r];
        }
        Out* out = xyz + 3 * std::size_t(j);
        storeProjected(x0, y0, z0, w0, out);
        storeProjected(x1, y1, z1, w1, out + 3 * N);
    }
    for (; j + N <= count; j += N) {
        V x = {}, y = {}, z = {}, w = {};
        for (unsigned r = 0; r < K; ++r) {
            V b;
            loadLanes(b, column[r] + j);
            x += b * cx[r];
            y += b * cy[r];
            z += b * cz[r];
            w += b * cw[r];
        }
        storeProjected(x, y, z, w, xyz + 3 * std::size_t(j));
    }
    for (; j < count; ++j) {
        double x = 0.0;
        double y = 0.0;
        double z = 0.0;
        double w = 0.0;
        for (unsigned r = 0; r < K; ++r) {
            const double b = column[r][j];
            x += b * points[r].x;
            y += b * points[r].y;
            z += b * points[r].z;
            w += b * points[r].w;
        }
        const double inv = 1.0 / w;
        Out* out = xyz + 3 * std::size_t(j);
        out[0] = Out(x * inv);
        out[1] = Out(y * inv);
        out[2] = Out(z * inv);
    }
}

template <typename V, typename Out>
Q3_LANES_INLINE void sampleAnyOrder(const Point4* points, const BernsteinTable& table,
                                     std::uint32_t first, std::uint32_t count, Out* xyz)
{
    switch (table.order()) {
    case 2: sampleLanes<2, Out, V>(points, table, first, count, xyz); break;
    case 3: sampleLanes<3, Out, V>(points, table, first, count, xyz); break;
    case 4: sampleLanes<4, Out, V>(points, table, first, count, xyz); break;
    case 5: sampleLanes<5, Out, V>(points, table, first, count, xyz); break;
    case 6: sampleLanes<6, Out, V>(points, table, first, count, xyz); break;
    case 7: sampleLanes<7, Out, V>(points, table, first, count, xyz); break;
    case 8: sampleLanes<8, Out, V>(points, table, first, count, xyz); break;
    case 9: sampleLanes<9, Out, V>(points, table, first, count, xyz); break;
    case 10: sampleLanes<10, Out, V>(points, table, first, count, xyz); break;
    case 11: sampleLanes<11, Out, V>(points, table, first, count, xyz); break;
    case 12: sampleLanes<12, Out, V>(points, table, first, count, xyz); break;
    case 13: sampleLanes<13, Out, V>(points, table, first, count, xyz); break;
    case 14: sampleLanes<14, Out, V>(points, table, first, count, xyz); break;
    case 15: sampleLanes<15, Out, V>(points, table, first, count, xyz); break;
    case 16: sampleLanes<16, Out, V>(points, table, first, count, xyz); break;
    default: break;
    }
}

// The span's left-clamped polygon f(a^{p-m}, x_{l+1} .. x_{l+m}): de Boor's
// triangle at a = x_l (the first triangle of spanToBezier).
template <typename V>
Q3_LANES_INLINE void leftClamped(const CurveRef& curve, std::size_t l, Point4* out)
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
            lerpInto<V>(d[j - 1], d[j], (a - lo) / (hi - lo), d[j]);
        }
        out[deg - r] = d[deg];
    }
}

// One step of the sweep (Piegl & Tiller A5.6 for span l): `left` holds the
// left-clamped polygon of knot index `next` when l == next.
template <typename V>
Q3_LANES_INLINE void sweepConvert(const CurveRef& curve, std::size_t l, Point4* left,
                                   std::size_t& next, Point4* out)
{
    const unsigned p = curve.order - 1;
    const float* x = curve.knots;
    const std::size_t knotCount = curve.numPoints + curve.order;
    if (l != next)
        leftClamped<V>(curve, l, left);
    for (unsigned i = 0; i <= p; ++i)
        out[i] = left[i];
    // The run of knots equal to b = x_{l+1}: indices l+1 .. e.
    std::size_t e = l + 1;
    while (e + 1 < knotCount && x[e + 1] == x[l + 1])
        ++e;
    const unsigned mult = unsigned(std::min<std::size_t>(e - l, p));
    const unsigned r = p - mult;
    Point4 saved[kMaxOrder];
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
                lerpInto<V>(out[k - 1], out[k], alphas[k - s], out[k]);
            saved[save] = out[p];
        }
    }
    // The next span starts at knot e; its polygon's right part is original points.
    next = std::size_t(-1);
    if (e < curve.numPoints) {
        const float* pts = curve.points;
        for (unsigned i = r; i <= p; ++i) {
            const float* q = pts + 4 * (e - p + i);
            saved[i] = Point4{q[0], q[1], q[2], q[3]};
        }
        for (unsigned i = 0; i <= p; ++i)
            left[i] = saved[i];
        next = e;
    }
}

// The entry points, one per instruction set.
template <typename Out>
__attribute__((noinline)) void sampleBaseline(const Point4* points, const BernsteinTable& table,
                                              std::uint32_t first, std::uint32_t count, Out* xyz)
{
    sampleAnyOrder<Double2>(points, table, first, count, xyz);
}

__attribute__((noinline)) void convertBaseline(const CurveRef& curve, std::size_t l, Point4* left,
                                               std::size_t& next, Point4* out)
{
    sweepConvert<Double2>(curve, l, left, next, out);
}

#if Q3_LANES_AVX2
template <typename Out>
Q3_LANES_TARGET_AVX2 __attribute__((noinline)) void sampleAvx2(const Point4* points,
                                                         const BernsteinTable& table,
                                                         std::uint32_t first,
                                                         std::uint32_t count, Out* xyz)
{
    sampleAnyOrder<Double4>(points, table, first, count, xyz);
}

Q3_LANES_TARGET_AVX2 __attribute__((noinline)) void convertAvx2(const CurveRef& curve, std::size_t l,
                                                          Point4* left, std::size_t& next,
                                                          Point4* out)
{
    sweepConvert<Double4>(curve, l, left, next, out);
}
#endif

KernelIsa detectKernelIsa()
{
#if Q3_LANES_AVX2
    // __builtin_cpu_supports also requires the OS to save the YMM registers.
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2"))
        return KernelIsa::kAvx2;
#endif
    return KernelIsa::kBaseline;
}

std::atomic<int>& activeIsa()
{
    static std::atomic<int> isa{int(supportedKernelIsa())};
    return isa;
}

template <typename Out>
void sampleDispatch(const Point4* points, const BernsteinTable& table, std::uint32_t first,
                    std::uint32_t count, Out* xyz)
{
#if Q3_LANES_AVX2
    if (activeIsa().load(std::memory_order_relaxed) == int(KernelIsa::kAvx2)) {
        sampleAvx2(points, table, first, count, xyz);
        return;
    }
#endif
    sampleBaseline(points, table, first, count, xyz);
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
    const double a = x[l];
    const double b = x[l + 1];

    // First triangle: de Boor at t = a; its right edge becomes out[deg], ..., out[0].
    leftClamped<Double2>(curve, l, out);

    // Second triangle: replace the right-hand knots x_{l+1} .. x_{l+m} by b.
    for (unsigned s = 1; s <= deg; ++s) {
        for (unsigned m = deg; m >= s; --m) {
            const double xm = x[l + m - s + 1];
            lerpInto<Double2>(out[m - 1], out[m], (b - a) / (xm - a), out[m]);
        }
    }
}

KernelIsa supportedKernelIsa()
{
    static const KernelIsa isa = detectKernelIsa();
    return isa;
}

KernelIsa activeKernelIsa()
{
    return KernelIsa(activeIsa().load(std::memory_order_relaxed));
}

bool forceKernelIsa(KernelIsa isa)
{
    if (isa == KernelIsa::kAvx2 && supportedKernelIsa() != KernelIsa::kAvx2)
        return false;
    activeIsa().store(int(isa), std::memory_order_relaxed);
    return true;
}

void BezierSweep::convert(std::size_t l, Point4* out)
{
#if Q3_LANES_AVX2
    if (activeIsa().load(std::memory_order_relaxed) == int(KernelIsa::kAvx2)) {
        convertAvx2(m_curve, l, m_left, m_next, out);
        return;
    }
#endif
    convertBaseline(m_curve, l, m_left, m_next, out);
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
    m_spans.reserve(curve.numPoints - curve.order + 1);
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
