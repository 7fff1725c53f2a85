// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Surface.h"

#include <array>
#include <vector>

namespace q3::nurbs {

/// Which parts of a patch a view cannot show, by the convex-hull property of
/// Bezier patches: the piece of the surface over a parameter rectangle inside
/// one pair of knot spans is a rational Bezier patch whose control points
/// come from knot insertion (blossoms), and with positive weights the
/// homogeneous piece lies in the convex hull of its homogeneous control
/// points, so a linear half-space test on them bounds the whole piece.
class SurfaceHull {
public:
    /// `clip` maps homogeneous local points (x, y, z, 1) to the view's
    /// frustum coordinates, row-major: frustum_i = sum_j clip[4 i + j] p_j.
    /// The view volume is -w <= x <= w, -w <= y <= w, z <= 0 (nearer than
    /// the hither plane is z > 0).
    SurfaceHull(const SurfaceRef& surface, const std::array<double, 16>& clip);

    /// True when the surface over [u0, u1] x [v0, v1] (inside the domain,
    /// u0 <= u1, v0 <= v1) lies, with a margin of 1e-6 of each control
    /// point's size, outside one of the view volume's five planes (the same
    /// plane for all of it). Then so does every flat triangle between points
    /// of it. O(spans covered * (uOrder^2 vOrder + vOrder^2 uOrder)).
    bool outside(double u0, double u1, double v0, double v1) const;

    /// True when every Bezier control point of the surface over [u0, u1] x
    /// [v0, v1] is inside all five planes (no margin): then no piece of it
    /// can be outside one. Same cost as outside().
    bool inside(double u0, double u1, double v0, double v1) const;

    /// The five plane values of local point p (each >= 0 inside the volume).
    void planes(double x, double y, double z, double out[5]) const;

private:
    // Bitmask of the planes the piece in span pair (su, sv) is outside of;
    // `straddles` (when given) tells whether any of its Bezier points is
    // outside any plane.
    unsigned outsidePlanes(std::size_t su, std::size_t sv, double u0, double u1, double v0, double v1,
                           bool* straddles = nullptr) const;
    // Calls f(su, sv, a, b, c, d) for each span pair's part of the
    // rectangle; false when the rectangle is empty or malformed.
    template <class F>
    bool forEachPiece(double u0, double u1, double v0, double v1, F&& f) const;

    SurfaceRef m_s;
    std::array<double, 16> m_clip;
    std::vector<Span> m_uSpans;
    std::vector<Span> m_vSpans;
};

} // namespace q3::nurbs
