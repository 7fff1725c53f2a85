// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"
#include "geometry/nurbs/Knots.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace q3::nurbs {

/// Bernstein weights B_{r,k-1}(u_j) at the uniform local parameters u_j = j / segments,
/// j = 0..segments, for one order. Build one per (order, segments) and reuse it for
/// every span; samples 0 and `segments` are exactly (1, 0, ..., 0) and (0, ..., 0, 1).
/// Stored by basis function (column r holds B_r at every sample) so the sampling kernel
/// reads consecutive samples with one vector load.
/// Invariant: (segments + 1) * order weights.
class BernsteinTable {
public:
    BernsteinTable() = default;
    /// order in 2..16, segments >= 1 (otherwise the table is empty: order() == 0).
    /// Memory (segments + 1) * order doubles.
    BernsteinTable(unsigned order, std::uint32_t segments);

    unsigned order() const { return m_order; }
    std::uint32_t segments() const { return m_segments; }
    /// B_{r,order-1}(j / segments), 0 <= j <= segments, 0 <= r < order.
    double weight(std::uint32_t j, unsigned r) const { return column(r)[j]; }
    /// The segments + 1 values of B_{r,order-1} at the samples.
    const double* column(unsigned r) const { return m_weights.data() + std::size_t(r) * (m_segments + 1); }

private:
    unsigned m_order = 0;
    std::uint32_t m_segments = 0;
    std::vector<double> m_weights;
};

/// Converts the span [knots[knotIndex], knots[knotIndex+1]) of a valid curve to
/// rational Bezier form: writes `order` homogeneous Bezier control points to out.
/// The span must be non-empty and inside the domain. Cost O(order^2), no allocation.
void spanToBezier(const CurveRef& curve, std::size_t knotIndex, Point4* out);

/// Converts the non-empty spans of a valid curve one after another, each from
/// the previous one's by-products (Piegl & Tiller A5.6 per span): the span
/// (knot index l) must be the first span or the next non-empty span after the
/// last one converted; otherwise that span starts from scratch (de Boor's triangle at
/// its start, as in spanToBezier). The same points as spanToBezier up to rounding.
class BezierSweep {
public:
    explicit BezierSweep(const CurveRef& curve) : m_curve(curve) {}
    /// Writes the `order` Bezier points of span l to out.
    void convert(std::size_t l, Point4* out);

private:
    CurveRef m_curve;
    std::size_t m_next = std::size_t(-1); // knot index whose left-clamped polygon m_left holds
    Point4 m_left[kMaxOrder];
};

/// Instruction sets the two hot loops (sampleBezier and the span conversion) exist for.
/// The library is compiled for baseline x86-64 (SSE2), like the distribution's other
/// libraries; on a CPU with AVX2 the loops switch to 256-bit vectors at run time. The
/// results are bit-identical: every lane performs the same multiplications and
/// additions in the same order as the scalar code, and no path uses fused
/// multiply-add, so a rendering never depends on the machine. Other architectures
/// always use kBaseline (GCC/Clang 128-bit vector extensions).
enum class KernelIsa { kBaseline, kAvx2 };

/// The widest instruction set this CPU (and operating system) supports, checked once.
KernelIsa supportedKernelIsa();
/// The instruction set the kernels use: supportedKernelIsa() unless forceKernelIsa chose
/// another.
KernelIsa activeKernelIsa();
/// Test and benchmark hook: makes the kernels use `isa`. Returns false and changes
/// nothing when this CPU does not support it. Thread-safe (an atomic), but a kernel
/// already running finishes with the set it started with.
bool forceKernelIsa(KernelIsa isa);

/// The homogeneous point of a Bezier curve with `order` control points at local
/// parameter u in [0, 1]. O(order), no allocation; exact control points at u = 0 and 1.
Point4 evaluateBezier(const Point4* points, unsigned order, double u);

/// Writes samples first .. first+count-1 of `table` for the Bezier curve `points`
/// (table.order() control points) as projected x, y, z triples: 3 * count values.
/// This is the fast kernel: no allocation, no branches per vertex beyond the loop.
void sampleBezier(const Point4* points, const BernsteinTable& table, std::uint32_t first,
                  std::uint32_t count, float* xyz);
void sampleBezier(const Point4* points, const BernsteinTable& table, std::uint32_t first,
                  std::uint32_t count, double* xyz);

/// A curve cut into its non-empty spans, each converted once to rational Bezier form
/// in double: what the adaptive method converts a curve to up front (kWholeFormLimit).
/// Invariant: points().size() == spanCount() * order(); span s covers
/// [span(s).start, span(s).end] and its Bezier points are spanPoints(s)[0 .. order-1].
/// An invalid curve gives an empty form (spanCount() == 0); it evaluates to (0, 0, 0, 0)
/// and tessellates to nothing. Ownership: copies what it needs; the CurveRef's arrays
/// need not outlive it.
/// Memory: spanCount * order * 32 bytes (order 16 with a million spans is 512 MB; the
/// tessellators also accept a CurveRef and then convert one span at a time).
class BezierForm {
public:
    BezierForm() = default;
    explicit BezierForm(const CurveRef& curve);

    /// Replaces the contents with the form of `curve`, reusing the storage.
    void rebuild(const CurveRef& curve);

    bool empty() const { return m_spans.empty(); }
    unsigned order() const { return m_order; }
    std::size_t spanCount() const { return m_spans.size(); }
    const Span& span(std::size_t s) const { return m_spans[s]; }
    const Point4* spanPoints(std::size_t s) const { return m_points.data() + s * m_order; }
    Domain domain() const;

    /// The span holding t (clamped to the domain; the last span at its end).
    std::size_t findSpan(double t) const;

    /// The curve at t, in double, through the Bezier points (t clamped as in evaluate()).
    Point4 evaluateHomogeneous(double t) const;
    Point3 evaluate(double t) const;

    /// sampleBezier() on span s.
    void sampleSpan(std::size_t s, const BernsteinTable& table, std::uint32_t first,
                    std::uint32_t count, float* xyz) const;
    void sampleSpan(std::size_t s, const BernsteinTable& table, std::uint32_t first,
                    std::uint32_t count, double* xyz) const;

private:
    unsigned m_order = 0;
    std::vector<Span> m_spans;
    std::vector<Point4> m_points;
};

} // namespace q3::nurbs
