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
#include "base/MathValues.h"

#include <glm/geometric.hpp>

#include <cstddef>
#include <type_traits>
#include <utility>

namespace q3::math {

float length(const TQ3Vector2D& vector);
/// Throws kQ3ErrorVector3DZeroLength (QuickDraw 3D has no 2-D code) when
/// the vector has length 0.
TQ3Vector2D normalize(const TQ3Vector2D& vector);
float dot(const TQ3Vector2D& v1, const TQ3Vector2D& v2);
/// The z component of (v1, 0) x (v2, 0).
float cross(const TQ3Vector2D& v1, const TQ3Vector2D& v2);
/// (p2 - p1) x (p3 - p1): normal to the triangle, counterclockwise positive.
TQ3Vector3D crossProductTri(const TQ3Point3D& p1, const TQ3Point3D& p2, const TQ3Point3D& p3);

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

// The arithmetic below is written once for every dimension: a template over
// the QD3DMath.h type, which is what tells the dimension.

/// The vector of a point's, a parameter's or a vector's dimension: what
/// moves one, and what the difference of two is. Declared only, for
/// VectorOf.
TQ3Vector2D vectorOf(const TQ3Point2D&);
TQ3Vector2D vectorOf(const TQ3Param2D&);
TQ3Vector2D vectorOf(const TQ3Vector2D&);
TQ3Vector3D vectorOf(const TQ3Point3D&);
TQ3Vector3D vectorOf(const TQ3Vector3D&);
template <class T>
using VectorOf = decltype(vectorOf(std::declval<T>()));
template <class T>
using IfVector = std::enable_if_t<std::is_same_v<T, VectorOf<T>>, int>;
template <class T>
using IfNotVector = std::enable_if_t<!std::is_same_v<T, VectorOf<T>>, int>;

/// a + v and a - v: a vector, point or parameter moved by a vector of its
/// dimension.
template <class T>
T add(const T& a, const VectorOf<T>& v)
{
    return toFloat<T>(toDouble(a) + toDouble(v));
}
template <class T>
T subtract(const T& a, const VectorOf<T>& v)
{
    return toFloat<T>(toDouble(a) - toDouble(v));
}

/// p1 - p2, the vector from p2 to p1 (two points or two parameters).
template <class T, IfNotVector<T> = 0>
VectorOf<T> subtract(const T& p1, const T& p2)
{
    return toFloat<VectorOf<T>>(toDouble(p1) - toDouble(p2));
}

template <class T, IfVector<T> = 0>
T scale(const T& vector, float scalar)
{
    return toFloat<T>(toDouble(vector) * double(scalar));
}
template <class T, IfVector<T> = 0>
T negate(const T& vector)
{
    return toFloat<T>(-toDouble(vector));
}

/// Where a point stands, in double: a rational point is the point it
/// represents, (x/w, y/w) or (x/w, y/w, z/w) (undivided when w is 0).
inline glm::dvec2 positionOf(const TQ3Point2D& point) { return toDouble(point); }
inline glm::dvec2 positionOf(const TQ3Param2D& param) { return toDouble(param); }
inline glm::dvec3 positionOf(const TQ3Point3D& point) { return toDouble(point); }
inline glm::dvec2 positionOf(const TQ3RationalPoint3D& point) { return dehomogenize(toDouble(point)); }
inline glm::dvec3 positionOf(const TQ3RationalPoint4D& point) { return dehomogenize(toDouble(point)); }

/// Between the positions of two points of one type.
template <class T>
auto distance(const T& p1, const T& p2) -> decltype(positionOf(p1), float())
{
    return static_cast<float>(glm::distance(positionOf(p1), positionOf(p2)));
}
template <class T>
auto distanceSquared(const T& p1, const T& p2) -> decltype(positionOf(p1), float())
{
    const auto d = positionOf(p1) - positionOf(p2);
    return static_cast<float>(glm::dot(d, d));
}

/// r2 / (r1 + r2); throws kQ3ErrorInvalidParameter when r1 + r2 is 0.
double ratioFraction(float r1, float r2);

/// p1 + (p2 - p1) * r2 / (r1 + r2), coordinate by coordinate (w too for a
/// rational point). Throws kQ3ErrorInvalidParameter when r1 + r2 is 0.
template <class T>
T relativeRatio(const T& p1, const T& p2, float r1, float r2)
{
    const auto a = toDouble(p1);
    return toFloat<T>(a + (toDouble(p2) - a) * ratioFraction(r1, r2));
}

/// sum(weights[i] * points[i]) / sum(weights[i]), coordinate by coordinate
/// (w too for rational points): the affine combination when the weights sum
/// to 1, their weighted mean otherwise. Throws kQ3ErrorParameterOutOfRange
/// when count is 0 and kQ3ErrorInvalidParameter when the weights sum to 0.
template <class T>
T affineCombination(const T* points, const float* weights, std::size_t count)
{
    if (count == 0)
        fail(kQ3ErrorParameterOutOfRange, "there are no points to combine");
    decltype(toDouble(points[0])) sum(0.0);
    double totalWeight = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        sum += toDouble(points[i]) * double(weights[i]);
        totalWeight += weights[i];
    }
    if (totalWeight == 0.0)
        fail(kQ3ErrorInvalidParameter, "the weights sum to 0, so they combine no point");
    return toFloat<T>(sum / totalWeight);
}

} // namespace q3::math
