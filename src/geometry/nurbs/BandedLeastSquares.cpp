// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Banded least squares by Givens rotations. Each new row is rotated against the
// triangle's rows from its first nonzero column on: the rotation that zeroes the
// row's leading entry against the diagonal (c = r_cc / h, s = a_c / h with
// h = hypot(r_cc, a_c)) is orthogonal, so the residual's norm is kept and the
// method is backward stable (Lawson & Hanson, "Solving Least Squares Problems";
// Golub & Van Loan, "Matrix Computations", section 5.1.8). A row that meets an
// empty triangle row takes its place. Back substitution solves R X = Q^T B.
// The basis functions are Piegl & Tiller's algorithm A2.2: the Cox-de Boor
// triangle kept to the degree + 1 functions that are nonzero on the span, with
// the left and right differences u - x_{l+1-j} and x_{l+j} - u reused.
#include "geometry/nurbs/BandedLeastSquares.h"

#include "geometry/nurbs/Curve.h"

#include <algorithm>
#include <cmath>

namespace q3::nurbs {

void basisFunctionsOnSpan(const std::vector<double>& knots, std::size_t span, unsigned degree, double u,
                          double* out)
{
    double left[kMaxOrder];
    double right[kMaxOrder];
    out[0] = 1.0;
    for (unsigned j = 1; j <= degree; ++j) {
        left[j] = u - knots[span + 1 - j];
        right[j] = knots[span + j] - u;
        double saved = 0.0;
        for (unsigned r = 0; r < j; ++r) {
            const double term = out[r] / (right[r + 1] + left[j - r]);
            out[r] = saved + right[r + 1] * term;
            saved = left[j - r] * term;
        }
        out[j] = saved;
    }
}

BandedLeastSquares::BandedLeastSquares(std::size_t unknowns, unsigned width, unsigned rightHandSides)
    : m_unknowns(unknowns),
      m_width(width),
      m_sides(rightHandSides),
      m_rows(unknowns * (width + rightHandSides), 0.0),
      m_used(unknowns, false)
{
}

void BandedLeastSquares::addRow(std::size_t column, double* a, double* rhs)
{
    while (column < m_unknowns) {
        if (a[0] == 0.0) {
            if (!shift(a))
                return;
            ++column;
            continue;
        }
        double* row = &m_rows[column * (m_width + m_sides)];
        if (!m_used[column]) {
            std::copy(a, a + m_width, row);
            std::copy(rhs, rhs + m_sides, row + m_width);
            m_used[column] = true;
            return;
        }
        const double r = std::hypot(row[0], a[0]);
        const double c = row[0] / r;
        const double s = a[0] / r;
        for (unsigned d = 0; d < m_width; ++d) {
            const double top = row[d];
            row[d] = c * top + s * a[d];
            a[d] = c * a[d] - s * top;
        }
        for (unsigned d = 0; d < m_sides; ++d) {
            const double top = row[m_width + d];
            row[m_width + d] = c * top + s * rhs[d];
            rhs[d] = c * rhs[d] - s * top;
        }
        a[0] = 0.0;
        if (!shift(a))
            return;
        ++column;
    }
}

void BandedLeastSquares::addCurveRow(std::size_t span, unsigned degree, const double* basis, std::size_t count,
                                     const double* value, const double* first, const double* last)
{
    double a[kMaxOrder] = {};
    double rhs[kMaxOrder] = {};
    std::copy(value, value + m_sides, rhs);
    const std::size_t firstPoint = span - degree;
    // Unknown c is control point c + 1.
    const std::size_t column = firstPoint == 0 ? 0 : firstPoint - 1;
    for (unsigned r = 0; r <= degree; ++r) {
        const std::size_t i = firstPoint + r;
        if (i == 0 || i + 1 == count) {
            const double* known = i == 0 ? first : last;
            for (unsigned d = 0; d < m_sides; ++d)
                rhs[d] -= basis[r] * known[d];
        } else {
            a[i - 1 - column] = basis[r];
        }
    }
    addRow(column, a, rhs);
}

bool BandedLeastSquares::solve(std::vector<double>& solution) const
{
    solution.assign(m_unknowns * m_sides, 0.0);
    for (std::size_t c = m_unknowns; c-- > 0;) {
        const double* row = &m_rows[c * (m_width + m_sides)];
        if (!m_used[c] || !(std::fabs(row[0]) > 1e-13))
            return false;
        for (unsigned s = 0; s < m_sides; ++s) {
            double sum = row[m_width + s];
            for (unsigned d = 1; d < m_width && c + d < m_unknowns; ++d)
                sum -= row[d] * solution[(c + d) * m_sides + s];
            solution[c * m_sides + s] = sum / row[0];
        }
    }
    return true;
}

bool BandedLeastSquares::shift(double* a) const
{
    bool any = false;
    for (unsigned d = 0; d + 1 < m_width; ++d) {
        a[d] = a[d + 1];
        any = any || a[d] != 0.0;
    }
    a[m_width - 1] = 0.0;
    return any;
}

} // namespace q3::nurbs
