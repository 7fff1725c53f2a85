// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The geometric tests picking is made of, as plain values in double
// precision: no objects, no state.
//
// - Ray against triangle: Moller and Trumbore, "Fast, Minimum Storage
//   Ray/Triangle Intersection", JGT 2(1), 1997 (both sides count; a ray in
//   the triangle's plane misses).
// - Closest points between a ray and a point or a segment: the
//   parametric minimisation of Eberly, "Distance Between Point and Line,
//   Ray, or Line Segment" / Ericson, Real-Time Collision Detection, 5.1.2
//   and 5.1.9, with the ray parameter clamped to t >= 0.
// - Clipping in homogeneous coordinates to QuickDraw 3D's frustum depth
//   range -w <= z <= 0 (Sutherland-Hodgman, one plane at a time; Blinn and
//   Newell, "Clipping Using Homogeneous Coordinates", SIGGRAPH 1978).
// - A convex polygon against an axis-aligned rectangle: the separating axis
//   theorem (Ericson 4.4), axes x, y and each edge's normal.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace q3::pickmath {

/// Where a ray meets a triangle: origin + t * direction, and the
/// barycentric weights u of b and v of c (a has 1 - u - v).
struct TriangleHit {
    double t = 0.0;
    double u = 0.0;
    double v = 0.0;
};

/// The ray's first meeting with triangle abc at t >= 0, if any. The edges
/// and corners count as inside.
std::optional<TriangleHit> rayTriangle(const glm::dvec3& origin, const glm::dvec3& direction,
                                       const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

/// The closest approach of a ray (t >= 0) to something.
struct Approach {
    double t = 0.0;        ///< ray parameter of its closest point
    double s = 0.0;        ///< segment parameter (0 at a, 1 at b); 0 for a point
    double distance = 0.0; ///< between the two closest points
};

Approach rayPoint(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& p);
Approach raySegment(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& a,
                    const glm::dvec3& b);

/// The point of segment ab closest to p, as its parameter s in [0, 1], and
/// the distance.
struct SegmentClosest {
    double s = 0.0;
    double distance = 0.0;
};
SegmentClosest pointSegment2D(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b);

/// A homogeneous point with the parameter it has along what it was cut from.
struct ClipVertex {
    glm::dvec4 clip{0.0};
    double s = 0.0;
};

/// Cuts segment ab (homogeneous frustum coordinates) to -w <= z <= 0 and
/// w > 0: false when nothing is left; a and b become the ends left, their
/// s the parameters along the original segment.
bool clipSegment(ClipVertex& a, ClipVertex& b);

/// Cuts a polygon to the same region (in place); it may become empty.
void clipPolygon(std::vector<glm::dvec4>& polygon);

/// The screen point of a clipped segment's parameter sigma (0 at a's
/// image, 1 at b's) as the homogeneous parameter between a and b: where
/// linear interpolation of the homogeneous (and world) coordinates lands.
double screenToHomogeneous(double sigma, double wa, double wb);

/// Whether a convex polygon (its vertices in order, either winding; one
/// point or two make a point or a segment) and the closed rectangle
/// [lo, hi] share a point.
bool convexOverlapsRect(const glm::dvec2* points, std::size_t count, const glm::dvec2& lo, const glm::dvec2& hi);

} // namespace q3::pickmath
