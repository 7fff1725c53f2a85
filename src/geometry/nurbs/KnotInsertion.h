// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"

#include <optional>

namespace q3::nurbs {

/// Inserts one knot with Boehm's algorithm: returns the same curve with one more
/// knot (tNew) and one more control point.
/// Returns nullopt, leaving nothing changed, when tNew is not strictly inside the
/// domain (knots[k-1] < tNew < knots[n]) or when it would make more than order - 1
/// equal knots. Requires a curve whose knots and points obey the validateCurve() rules.
/// Cost O(n + k) time and memory. Errors: none besides nullopt.
/// Ownership: the result is a new, independent curve.
std::optional<HomogeneousCurve> insertKnot(const HomogeneousCurve& curve, double tNew);

} // namespace q3::nurbs
