// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The surface on a tensor grid of parameters (the constant method's mesh).
//
// A tensor-product grid needs the basis functions of each distinct u and
// each distinct v once: columnCount + rowCount evaluations of
// basisWithDerivative instead of two per vertex. Each vertex is then a small
// tensor contraction, done in two steps as SurfaceRowEvaluator does it: the
// vOrder rows of homogeneous points of the u span are collapsed at the row's
// v (with their v derivatives), then the uOrder collapsed columns are summed
// with the u basis (and its derivative) into the homogeneous point and its two
// partial derivatives; the quotient rule and a cross product give the exact
// partials of the rational surface and its unit normal (Surface.cpp).
//
// Vector code paths. Several rows (two doubles a vector with SSE2, four with
// AVX2, chosen at run time as Bezier.cpp's kernels are) go through the
// contraction and the normal together, one row a lane: the collapsed columns
// are stored lane by lane, so every multiply-add of the contraction is one
// vector instruction with the u basis value broadcast, and the division by
// w, the quotient rule, the cross product and the normalisation are shared
// too. Each lane does exactly the scalar arithmetic in the same order and
// nothing enables fused multiply-add, so the values are the scalar
// evaluator's, bit for bit, on every machine. Only the columns of one u span
// are collapsed at a time (uOrder of them, on the stack), so memory does not
// grow with the patch.

#include "geometry/nurbs/SurfaceGrid.h"

#include "geometry/nurbs/Bezier.h"
#include "geometry/nurbs/Lanes.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace q3::nurbs {
namespace {

constexpr unsigned kMaxLanes = 4;

double clampTo(double t, double lo, double hi)
{
    if (!(t > lo))
        return lo;
    return t < hi ? t : hi;
}

/// What the kernel reads: the u basis of every column, computed once.
struct GridInput {
    const SurfaceRef* surface;
    SurfaceDomain domain;
    const double* us;
    std::size_t columns;
    const double* vs;
    std::size_t rows;
    const std::size_t* uSpan;  // knot span of every column
    const double* uBasis;      // 2 * uOrder per column: values, then derivatives
    float* positions;
    float* normals;
};

// Rows r0 .. r0 + kLanes<V> - 1 (the last repeated past the grid's end), all
// columns.
template <typename V>
Q3_LANES_INLINE void gridRows(const GridInput& in, std::size_t r0)
{
    constexpr unsigned L = kLanes<V>;
    const SurfaceRef& s = *in.surface;
    const unsigned ku = s.uOrder, kv = s.vOrder;
    const std::size_t numColumns = s.numColumns;

    // The v basis of each lane's row (as SurfaceRowEvaluator::setV).
    double rowV[L];
    std::size_t firstRow[L];
    double nv[L][kMaxPatchOrder], dnv[L][kMaxPatchOrder];
    for (unsigned l = 0; l < L; ++l) {
        const std::size_t r = std::min<std::size_t>(r0 + l, in.rows - 1);
        const double v = clampTo(in.vs[r], in.domain.v0, in.domain.v1);
        rowV[l] = v;
        const std::size_t span = findKnotSpan(s.vKnots, s.numRows, kv, v);
        basisWithDerivative(s.vKnots, span, kv, v, nv[l], dnv[l]);
        firstRow[l] = span + 1 - kv;
    }
    const std::size_t lanesUsed = std::min<std::size_t>(L, in.rows - r0);

    // The collapsed columns of one u span: [column][x y z w, dx dy dz dw][lane].
    alignas(32) double block[kMaxPatchOrder][8][L];

    for (std::size_t i0 = 0; i0 < in.columns;) {
        const std::size_t span = in.uSpan[i0];
        std::size_t i1 = i0 + 1;
        while (i1 < in.columns && in.uSpan[i1] == span)
            ++i1;
        const std::size_t firstColumn = span + 1 - ku;
        for (unsigned j = 0; j < ku; ++j)
            for (unsigned l = 0; l < L; ++l) {
                double q[8] = {};
                for (unsigned r = 0; r < kv; ++r) {
                    const float* p = s.points + 4 * ((firstRow[l] + r) * numColumns + firstColumn + j);
                    const double n = nv[l][r], dn = dnv[l][r];
                    for (unsigned c = 0; c < 4; ++c) {
                        q[c] += n * p[c];
                        q[4 + c] += dn * p[c];
                    }
                }
                for (unsigned c = 0; c < 8; ++c)
                    block[j][c][l] = q[c];
            }

        for (std::size_t i = i0; i < i1; ++i) {
            const double* n = in.uBasis + 2 * std::size_t(ku) * i;
            const double* dn = n + ku;
            // The homogeneous point h and its partials hu and hv, x y z w each.
            V h[4] = {}, hu[4] = {}, hv[4] = {};
            for (unsigned j = 0; j < ku; ++j) {
                const double a = n[j], b = dn[j];
                for (unsigned c = 0; c < 4; ++c) {
                    V q, d;
                    loadLanes(q, block[j][c]);
                    loadLanes(d, block[j][4 + c]);
                    h[c] += a * q;
                    hu[c] += b * q;
                    hv[c] += a * d;
                }
            }
            // The rational point and partials (Surface.cpp's finish).
            const V inverseW = 1.0 / h[3];
            const V px = h[0] * inverseW, py = h[1] * inverseW, pz = h[2] * inverseW;
            const V dux = (hu[0] - px * hu[3]) * inverseW, duy = (hu[1] - py * hu[3]) * inverseW,
                    duz = (hu[2] - pz * hu[3]) * inverseW;
            const V dvx = (hv[0] - px * hv[3]) * inverseW, dvy = (hv[1] - py * hv[3]) * inverseW,
                    dvz = (hv[2] - pz * hv[3]) * inverseW;
            // The unit normal (Surface.cpp's unitNormal).
            const V nx = duy * dvz - duz * dvy, ny = duz * dvx - dux * dvz, nz = dux * dvy - duy * dvx;
            const V n2 = nx * nx + ny * ny + nz * nz;
            const V du2 = dux * dux + duy * duy + duz * duz;
            const V dv2 = dvx * dvx + dvy * dvy + dvz * dvz;
            const V floor = 1e-20 * du2 * dv2;
            V root = {};
            for (unsigned l = 0; l < L; ++l)
                root[l] = std::sqrt(n2[l]);
            const V inverse = 1.0 / root;
            const V ox = nx * inverse, oy = ny * inverse, oz = nz * inverse;
            for (unsigned l = 0; l < lanesUsed; ++l) {
                const std::size_t k = (r0 + l) * in.columns + i;
                float* position = in.positions + 3 * k;
                float* normal = in.normals + 3 * k;
                position[0] = float(px[l]);
                position[1] = float(py[l]);
                position[2] = float(pz[l]);
                if (n2[l] > floor[l] && n2[l] < std::numeric_limits<double>::infinity()) {
                    normal[0] = float(ox[l]);
                    normal[1] = float(oy[l]);
                    normal[2] = float(oz[l]);
                } else {
                    // A pole, a collapsed edge or a cusp: the scalar evaluator's
                    // limit of the neighbours' normals.
                    const Point3 o = evaluateWithNormal(s, in.us[i], rowV[l]).normal;
                    normal[0] = float(o.x);
                    normal[1] = float(o.y);
                    normal[2] = float(o.z);
                }
            }
        }
        i0 = i1;
    }
}

void gridBaseline(const GridInput& in)
{
    for (std::size_t r0 = 0; r0 < in.rows; r0 += kLanes<Double2>)
        gridRows<Double2>(in, r0);
}

#if Q3_LANES_AVX2
Q3_LANES_TARGET_AVX2 void gridAvx2(const GridInput& in)
{
    for (std::size_t r0 = 0; r0 < in.rows; r0 += kLanes<Double4>)
        gridRows<Double4>(in, r0);
}
#endif

static_assert(kLanes<Double4> <= kMaxLanes, "lanes");

} // namespace

void evaluateGrid(const SurfaceRef& surface, const double* us, std::size_t columnCount, const double* vs,
                  std::size_t rowCount, float* positions, float* normals)
{
    if (columnCount == 0 || rowCount == 0)
        return;
    const unsigned ku = surface.uOrder;
    GridInput in;
    in.surface = &surface;
    in.domain = surfaceDomain(surface);
    in.us = us;
    in.columns = columnCount;
    in.vs = vs;
    in.rows = rowCount;
    in.positions = positions;
    in.normals = normals;
    std::vector<std::size_t> spans(columnCount);
    std::vector<double> basis(2 * std::size_t(ku) * columnCount);
    for (std::size_t i = 0; i < columnCount; ++i) {
        spans[i] = findKnotSpan(surface.uKnots, surface.numColumns, ku, us[i]);
        basisWithDerivative(surface.uKnots, spans[i], ku, us[i], &basis[2 * ku * i], &basis[2 * ku * i + ku]);
    }
    in.uSpan = spans.data();
    in.uBasis = basis.data();
#if Q3_LANES_AVX2
    if (activeKernelIsa() == KernelIsa::kAvx2) {
        gridAvx2(in);
        return;
    }
#endif
    gridBaseline(in);
}

} // namespace q3::nurbs
