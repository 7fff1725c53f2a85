// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// QD3DMath.h's arithmetic on points and vectors that needs no matrix: sums,
// differences, lengths and distances, relative ratios, affine combinations,
// changes of dimension and polar and spherical coordinates. Computed in
// double and rounded once (base/MathValues.h). The domain failures throw
// q3::Error for the API layer to post: a zero vector to normalize
// (kQ3ErrorVector3DZeroLength), ratios or weights summing to 0
// (kQ3ErrorInvalidParameter), no points to combine
// (kQ3ErrorParameterOutOfRange).

#include "QD3D.h"

#include <cstddef>

namespace q3::math {

float length(const TQ3Vector2D& vector);
/// Throws kQ3ErrorVector3DZeroLength (QuickDraw 3D has no 2-D code) when
/// the vector has length 0.
TQ3Vector2D normalize(const TQ3Vector2D& vector);
float dot(const TQ3Vector2D& v1, const TQ3Vector2D& v2);
/// The z component of (v1, 0) x (v2, 0).
float cross(const TQ3Vector2D& v1, const TQ3Vector2D& v2);
TQ3Vector2D add(const TQ3Vector2D& v1, const TQ3Vector2D& v2);
TQ3Vector3D add(const TQ3Vector3D& v1, const TQ3Vector3D& v2);
TQ3Vector2D subtract(const TQ3Vector2D& v1, const TQ3Vector2D& v2);
TQ3Vector3D subtract(const TQ3Vector3D& v1, const TQ3Vector3D& v2);
TQ3Vector2D scale(const TQ3Vector2D& vector, float scalar);
TQ3Vector3D scale(const TQ3Vector3D& vector, float scalar);
TQ3Vector2D negate(const TQ3Vector2D& vector);
TQ3Vector3D negate(const TQ3Vector3D& vector);

/// p1 - p2, the vector from p2 to p1.
TQ3Vector2D subtract(const TQ3Point2D& p1, const TQ3Point2D& p2);
TQ3Vector2D subtract(const TQ3Param2D& p1, const TQ3Param2D& p2);
TQ3Vector3D subtract(const TQ3Point3D& p1, const TQ3Point3D& p2);
TQ3Point2D add(const TQ3Point2D& point, const TQ3Vector2D& vector);
TQ3Param2D add(const TQ3Param2D& param, const TQ3Vector2D& vector);
TQ3Point3D add(const TQ3Point3D& point, const TQ3Vector3D& vector);
TQ3Point2D subtract(const TQ3Point2D& point, const TQ3Vector2D& vector);
TQ3Param2D subtract(const TQ3Param2D& param, const TQ3Vector2D& vector);
TQ3Point3D subtract(const TQ3Point3D& point, const TQ3Vector3D& vector);
/// (p2 - p1) x (p3 - p1): normal to the triangle, counterclockwise positive.
TQ3Vector3D crossProductTri(const TQ3Point3D& p1, const TQ3Point3D& p2, const TQ3Point3D& p3);

float distance(const TQ3Point2D& p1, const TQ3Point2D& p2);
float distance(const TQ3Param2D& p1, const TQ3Param2D& p2);
/// Between the points represented: (x/w, y/w) (undivided when w is 0).
float distance(const TQ3RationalPoint3D& p1, const TQ3RationalPoint3D& p2);
/// Between the points represented: (x/w, y/w, z/w) (undivided when w is 0).
float distance(const TQ3RationalPoint4D& p1, const TQ3RationalPoint4D& p2);
float distanceSquared(const TQ3Point2D& p1, const TQ3Point2D& p2);
float distanceSquared(const TQ3Param2D& p1, const TQ3Param2D& p2);
float distanceSquared(const TQ3RationalPoint3D& p1, const TQ3RationalPoint3D& p2);
float distanceSquared(const TQ3Point3D& p1, const TQ3Point3D& p2);
float distanceSquared(const TQ3RationalPoint4D& p1, const TQ3RationalPoint4D& p2);

/// p1 + (p2 - p1) * r2 / (r1 + r2), coordinate by coordinate (w too for the
/// rational point). Throws kQ3ErrorInvalidParameter when r1 + r2 is 0.
TQ3Point2D relativeRatio(const TQ3Point2D& p1, const TQ3Point2D& p2, float r1, float r2);
TQ3Param2D relativeRatio(const TQ3Param2D& p1, const TQ3Param2D& p2, float r1, float r2);
TQ3Point3D relativeRatio(const TQ3Point3D& p1, const TQ3Point3D& p2, float r1, float r2);
TQ3RationalPoint4D relativeRatio(const TQ3RationalPoint4D& p1, const TQ3RationalPoint4D& p2, float r1,
                                 float r2);

/// sum(weights[i] * points[i]) / sum(weights[i]), coordinate by coordinate
/// (w too for rational points): the affine combination when the weights sum
/// to 1, their weighted mean otherwise. Throws kQ3ErrorParameterOutOfRange
/// when count is 0 and kQ3ErrorInvalidParameter when the weights sum to 0.
TQ3Point2D affineCombination(const TQ3Point2D* points, const float* weights, std::size_t count);
TQ3Param2D affineCombination(const TQ3Param2D* points, const float* weights, std::size_t count);
TQ3RationalPoint3D affineCombination(const TQ3RationalPoint3D* points, const float* weights, std::size_t count);
TQ3Point3D affineCombination(const TQ3Point3D* points, const float* weights, std::size_t count);
TQ3RationalPoint4D affineCombination(const TQ3RationalPoint4D* points, const float* weights, std::size_t count);

/// Changes of dimension, as QuickDraw 3D defines them: going up appends a
/// last coordinate of 1; going down divides by the last coordinate and drops
/// it (undivided when it is 0).
TQ3Point3D to3D(const TQ3Point2D& point);
TQ3Point2D to2D(const TQ3RationalPoint3D& point);
TQ3RationalPoint4D to4D(const TQ3Point3D& point);
TQ3Point3D to3D(const TQ3RationalPoint4D& point);
TQ3Vector3D to3D(const TQ3Vector2D& vector);
TQ3Vector2D to2D(const TQ3Vector3D& vector);

/// r the distance from the origin; theta counterclockwise from +x, in
/// [0, 2 pi) before rounding. The origin gives (0, 0).
TQ3PolarPoint toPolar(const TQ3Point2D& point);
TQ3Point2D toCartesian(const TQ3PolarPoint& point);
/// rho the distance from the origin; theta as for toPolar, of the
/// projection onto the xy plane (0 on the z axis); phi from +z, in [0, pi].
/// The origin gives (0, 0, 0).
TQ3SphericalPoint toSpherical(const TQ3Point3D& point);
TQ3Point3D toCartesian(const TQ3SphericalPoint& point);

} // namespace q3::math
