// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The QD3DMath.h value structs as glm double vectors and back, shared by the
// pure math files (MatrixMath, VectorMath, QuaternionMath, BoundsMath).
// Every product of two floats is exact in double and the sums of a few such
// products cannot overflow, so computing in double and rounding to float
// once, at the end, gives lengths that do not overflow for finite inputs and
// results within one rounding of the exact ones.

#include "QD3D.h"
#include "core/Error.h"

#include <glm/geometric.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace q3::math {

inline glm::dvec2 toDouble(const TQ3Point2D& p) { return glm::dvec2(p.x, p.y); }
inline glm::dvec2 toDouble(const TQ3Param2D& p) { return glm::dvec2(p.u, p.v); }
inline glm::dvec2 toDouble(const TQ3Vector2D& v) { return glm::dvec2(v.x, v.y); }
inline glm::dvec3 toDouble(const TQ3Point3D& p) { return glm::dvec3(p.x, p.y, p.z); }
inline glm::dvec3 toDouble(const TQ3Vector3D& v) { return glm::dvec3(v.x, v.y, v.z); }
inline glm::dvec3 toDouble(const TQ3RationalPoint3D& p) { return glm::dvec3(p.x, p.y, p.w); }
inline glm::dvec4 toDouble(const TQ3RationalPoint4D& p) { return glm::dvec4(p.x, p.y, p.z, p.w); }

/// A double vector rounded to the QD3DMath.h struct T of the same size.
template <class T>
T toFloat(const glm::dvec2& v);
template <class T>
T toFloat(const glm::dvec3& v);
template <class T>
T toFloat(const glm::dvec4& v);

template <>
inline TQ3Point2D toFloat<TQ3Point2D>(const glm::dvec2& v)
{
    return TQ3Point2D{static_cast<float>(v.x), static_cast<float>(v.y)};
}
template <>
inline TQ3Param2D toFloat<TQ3Param2D>(const glm::dvec2& v)
{
    return TQ3Param2D{static_cast<float>(v.x), static_cast<float>(v.y)};
}
template <>
inline TQ3Vector2D toFloat<TQ3Vector2D>(const glm::dvec2& v)
{
    return TQ3Vector2D{static_cast<float>(v.x), static_cast<float>(v.y)};
}
template <>
inline TQ3Point3D toFloat<TQ3Point3D>(const glm::dvec3& v)
{
    return TQ3Point3D{static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
template <>
inline TQ3Vector3D toFloat<TQ3Vector3D>(const glm::dvec3& v)
{
    return TQ3Vector3D{static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
template <>
inline TQ3RationalPoint3D toFloat<TQ3RationalPoint3D>(const glm::dvec3& v)
{
    return TQ3RationalPoint3D{static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
template <>
inline TQ3RationalPoint4D toFloat<TQ3RationalPoint4D>(const glm::dvec4& v)
{
    return TQ3RationalPoint4D{static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z),
                              static_cast<float>(v.w)};
}

/// Divides by the last coordinate, QuickDraw 3D's one rule for leaving
/// homogeneous coordinates: a last coordinate of exactly 0 (a point at
/// infinity) leaves the others undivided, as Q3Point3D_Transform always has.
inline glm::dvec2 dehomogenize(const glm::dvec3& p)
{
    const double w = p.z == 0.0 ? 1.0 : p.z;
    return glm::dvec2(p.x / w, p.y / w);
}

inline glm::dvec3 dehomogenize(const glm::dvec4& p)
{
    const double w = p.w == 0.0 ? 1.0 : p.w;
    return glm::dvec3(p.x / w, p.y / w, p.z / w);
}

/// The vector scaled to length 1, computed in double; kQ3ErrorVector3DZeroLength
/// (QuickDraw 3D has no 2-D code) when its length is 0.
template <class T>
T normalizedOf(const T& vector)
{
    const auto v = toDouble(vector);
    const double size = glm::length(v);
    if (size == 0.0)
        fail(kQ3ErrorVector3DZeroLength, "the vector has length 0, so it has no direction");
    return toFloat<T>(v / size);
}

} // namespace q3::math
