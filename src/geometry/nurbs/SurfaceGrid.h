// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Surface.h"

#include <cstddef>

namespace q3::nurbs {

/// The surface and its unit normals on a tensor grid of parameters, the
/// constant method's untrimmed mesh: vertex (r, i) is S(us[i], vs[r]), written
/// at index r * columnCount + i as three floats of `positions` and three of
/// `normals`. The values are, bit for bit, those SurfaceRowEvaluator gives
/// (setV(vs[r], true), then pointWithNormal(us[i])), rounded to float once,
/// whatever the instruction set (Bezier.h, KernelIsa): the basis functions of
/// each distinct u and v are computed once (columnCount + rowCount
/// evaluations), the columns of one u span are collapsed at several rows at
/// a time, and those rows share every vector instruction of the contraction
/// and of the normal. Parameters outside the domain are clamped to it.
/// Work: O(columnCount * rowCount * uOrder + rowCount * spans * uOrder * vOrder);
/// memory O(columnCount * uOrder), no allocation per vertex.
void evaluateGrid(const SurfaceRef& surface, const double* us, std::size_t columnCount, const double* vs,
                  std::size_t rowCount, float* positions, float* normals);

} // namespace q3::nurbs
