// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include <cstddef>
#include <vector>

namespace q3::nurbs {

/// The degree + 1 basis functions N_{l-degree .. l} that are nonzero at u, for u in
/// span l of `knots` (knots[l] <= u < knots[l+1], or u == knots[l+1] at the end), by
/// the Cox-de Boor recursion (article "DEFINING THE BASIS FUNCTIONS", lecture eqs.
/// 6.5-6.6) in the triangular form of Piegl & Tiller's algorithm A2.2. out holds
/// degree + 1 values. Cost O(degree^2), no allocation.
void basisFunctionsOnSpan(const std::vector<double>& knots, std::size_t span, unsigned degree, double u,
                          double* out);

/// A linear least-squares problem min |A X - B| whose rows each have at most `width`
/// nonzero entries in consecutive columns, the first of which never moves left from
/// one row to the next (the shape of B-spline collocation at increasing
/// parameters). Rows are folded in one at a time by Givens rotations into an upper
/// triangular band of the same width (sequential accumulation, Lawson & Hanson,
/// "Solving Least Squares Problems"), so memory is O(unknowns * width) however many
/// rows there are; a square system is solved exactly. B has `rightHandSides` columns
/// (one per coordinate). Backward stable; no pivoting is needed.
class BandedLeastSquares {
public:
    BandedLeastSquares(std::size_t unknowns, unsigned width, unsigned rightHandSides);

    /// Folds in the row sum_d a[d] X[column + d] = rhs; a (width entries) and rhs
    /// (rightHandSides entries) are used as scratch.
    void addRow(std::size_t column, double* a, double* rhs);

    /// Adds the equation sum_i N_i X_i = value of a curve with control points
    /// X_0 .. X_{count-1}, of which X_0 = first and X_{count-1} = last are known and
    /// X_1 .. X_{count-2} are the unknowns 0 .. count-3. basis holds the degree + 1
    /// functions N_{span-degree .. span}; value, first and last hold rightHandSides
    /// numbers each.
    void addCurveRow(std::size_t span, unsigned degree, const double* basis, std::size_t count,
                     const double* value, const double* first, const double* last);

    /// Back substitution into solution (unknowns * rightHandSides values, unknown by
    /// unknown). False, with solution unspecified, when a diagonal entry of the
    /// triangle is below 1e-13 (the rows do not determine every unknown).
    bool solve(std::vector<double>& solution) const;

private:
    bool shift(double* a) const;

    std::size_t m_unknowns;
    unsigned m_width;
    unsigned m_sides;
    std::vector<double> m_rows;  // per unknown: width entries, then the sides
    std::vector<bool> m_used;
};

} // namespace q3::nurbs
