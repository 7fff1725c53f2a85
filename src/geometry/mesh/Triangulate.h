// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Triangulation of planar polygons with any number of contours (holes,
// islands, concave outlines): pure math, plain values in and out.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace q3::mesh {

/// The unit normal of a closed 3D outline by Newell's method (the direction
/// from which the outline runs counterclockwise), or zero when the outline
/// encloses no area.
glm::dvec3 newellNormal(const glm::dvec3* points, std::size_t count);

/// A unit normal of the plane of points whose outline encloses no net area
/// (a symmetric bow tie, whose two loops cancel in newellNormal): the
/// normal of the widest triangle of the first point, the point farthest
/// from it and the point farthest from the line through both; zero when
/// the points are collinear. Its sign is that triangle's.
glm::dvec3 spanNormal(const glm::dvec3* points, std::size_t count);

/// Projects points onto the plane through the origin with unit normal n, in
/// a basis (u, v, n) that is right-handed, so an outline counterclockwise
/// about n stays counterclockwise in 2D.
std::vector<glm::dvec2> projectToPlane(const glm::dvec3* points, std::size_t count, const glm::dvec3& n);

/// Triangulates the region inside an odd number of the contours (the
/// even-odd rule: a contour inside another is a hole, one inside a hole an
/// island). points holds every contour's vertices one contour after another;
/// contourStarts[i] is where contour i begins (the first is 0) and each runs
/// to the next start (the last to the end). Each contour is closed
/// implicitly. Returns vertex index triples into points, each
/// counterclockwise. Contours with fewer than 3 distinct points, repeated
/// points and collinear runs are tolerated (they add no triangles).
/// Contours must not cross each other or themselves: if they do, the result
/// still has at most (vertices - 2) triangles per outer region but may
/// cover part of the plane twice or miss some. Ear clipping (D. Eberly,
/// "Triangulation by Ear Clipping") after joining each hole to its outline
/// by a bridge; O(n^2) in the worst case, near linear for typical input.
std::vector<std::uint32_t> triangulate(const std::vector<glm::dvec2>& points,
                                       const std::vector<std::size_t>& contourStarts);

/// A point a triangulation adds: t (0..1) of the way along the edge from
/// points[a] to points[b].
struct EdgePoint {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    double t = 0.0;
};

/// What triangulateEvenOdd gives: index triples, counterclockwise, into
/// points followed by `added` (index points.size() + i is added[i]).
struct Triangulation {
    std::vector<std::uint32_t> triangles;
    std::vector<EdgePoint> added;
};

/// Triangulates the region inside an odd number of the contours for any
/// contours, crossing each other or themselves or not (the QD3D Book,
/// "General Polygons": contours "may overlap", and "the even-odd rule is
/// used to determine which parts are inside the polygon"). Contours that do
/// not cross are triangulated as triangulate() does, adding no points.
/// Where edges cross, the plane is cut into horizontal slabs at every vertex
/// and crossing, so that no two edges cross inside a slab; within a slab the
/// edges are ordered along x and the trapezoids between the first and
/// second, the third and fourth, ... are inside (a horizontal line crosses
/// an odd number of edges to reach them). Each trapezoid becomes two
/// triangles over points added on its edges. O(n^2) in the edges.
Triangulation triangulateEvenOdd(const std::vector<glm::dvec2>& points,
                                 const std::vector<std::size_t>& contourStarts);

} // namespace q3::mesh
