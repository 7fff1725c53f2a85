// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "base/BoundsMath.h"

#include "core/EnumValue.h"
#include "base/MathValues.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <utility>

namespace q3::math {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Least and greatest that keep a NaN once they have met one.
double lower(double a, double b)
{
    return std::isnan(a) || std::isnan(b) ? kNaN : (b < a ? b : a);
}

double higher(double a, double b)
{
    return std::isnan(a) || std::isnan(b) ? kNaN : (b > a ? b : a);
}

glm::dvec3 lower(const glm::dvec3& a, const glm::dvec3& b)
{
    return glm::dvec3(lower(a.x, b.x), lower(a.y, b.y), lower(a.z, b.z));
}

glm::dvec3 higher(const glm::dvec3& a, const glm::dvec3& b)
{
    return glm::dvec3(higher(a.x, b.x), higher(a.y, b.y), higher(a.z, b.z));
}

TQ3BoundingBox boxFrom(const glm::dvec3& low, const glm::dvec3& high)
{
    return TQ3BoundingBox{TQ3Point3D{roundDown(low.x), roundDown(low.y), roundDown(low.z)},
                          TQ3Point3D{roundUp(high.x), roundUp(high.y), roundUp(high.z)}, kQ3False};
}

// A sphere centred on the float nearest centre: the radius grows by the
// distance the centre moved, then rounds up.
TQ3BoundingSphere sphereFrom(const glm::dvec3& centre, double radius)
{
    const TQ3Point3D origin = toFloat<TQ3Point3D>(centre);
    const double shift = glm::distance(centre, toDouble(origin));
    return TQ3BoundingSphere{origin, roundUp(radius + shift), kQ3False};
}

// The same sphere as a bound that is not empty.
TQ3BoundingSphere asNotEmpty(const TQ3BoundingSphere& sphere)
{
    return TQ3BoundingSphere{sphere.origin, sphere.radius, kQ3False};
}

TQ3BoundingBox asNotEmpty(const TQ3BoundingBox& box)
{
    return TQ3BoundingBox{box.min, box.max, kQ3False};
}

// The smallest sphere holding the sphere (c1, r1) and the sphere (c2, r2)
// when neither holds the other: the diameter runs along the line through
// the centres from the far side of one to the far side of the other.
TQ3BoundingSphere merged(const glm::dvec3& c1, double r1, const glm::dvec3& c2, double r2)
{
    const double apart = glm::distance(c1, c2);
    const double radius = (apart + r1 + r2) / 2.0;
    const double along = apart == 0.0 ? 0.0 : (radius - r1) / apart;
    return sphereFrom(c1 + (c2 - c1) * along, radius);
}

// The corners of the box around count > 0 points, NaN kept.
std::pair<glm::dvec3, glm::dvec3> extentOf(std::size_t count, const std::function<glm::dvec3(std::size_t)>& point)
{
    glm::dvec3 low = point(0);
    glm::dvec3 high = low;
    for (std::size_t i = 1; i < count; ++i) {
        const glm::dvec3 p = point(i);
        low = lower(low, p);
        high = higher(high, p);
    }
    return {low, high};
}

// The union of two bounds (boxes or spheres) either of which may be empty;
// `merge` unites two that are not.
template <class B, class Merge>
B uniteEither(const B& b1, const B& b2, const B& empty, Merge merge)
{
    if (isEmpty(b1))
        return isEmpty(b2) ? empty : asNotEmpty(b2);
    if (isEmpty(b2))
        return asNotEmpty(b1);
    return merge();
}

// An isEmpty read from the caller as kQ3True or kQ3False.
TQ3Boolean emptyFlag(const TQ3Boolean& isEmpty)
{
    return enumValue(isEmpty) != kQ3False ? kQ3True : kQ3False;
}

} // namespace

float roundDown(double value)
{
    const float f = static_cast<float>(value);
    return double(f) > value ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

float roundUp(double value)
{
    const float f = static_cast<float>(value);
    return double(f) < value ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

TQ3BoundingBox emptyBox()
{
    return TQ3BoundingBox{TQ3Point3D{0.0f, 0.0f, 0.0f}, TQ3Point3D{0.0f, 0.0f, 0.0f}, kQ3True};
}

TQ3BoundingBox makeBox(const TQ3Point3D& min, const TQ3Point3D& max, const TQ3Boolean& isEmpty)
{
    return TQ3BoundingBox{min, max, emptyFlag(isEmpty)};
}

bool isEmpty(const TQ3BoundingBox& box)
{
    return enumValue(box.isEmpty) != kQ3False;
}

TQ3BoundingBox unite(const TQ3BoundingBox& b1, const TQ3BoundingBox& b2)
{
    return uniteEither(b1, b2, emptyBox(), [&] {
        return boxFrom(lower(toDouble(b1.min), toDouble(b2.min)), higher(toDouble(b1.max), toDouble(b2.max)));
    });
}

TQ3BoundingBox unite(const TQ3BoundingBox& box, const glm::dvec3& point)
{
    if (isEmpty(box))
        return boxFrom(point, point);
    return boxFrom(lower(toDouble(box.min), point), higher(toDouble(box.max), point));
}

TQ3BoundingBox boxOf(std::size_t count, const std::function<glm::dvec3(std::size_t)>& point)
{
    if (count == 0)
        return emptyBox();
    const auto [low, high] = extentOf(count, point);
    return boxFrom(low, high);
}

TQ3BoundingSphere emptySphere()
{
    return TQ3BoundingSphere{TQ3Point3D{0.0f, 0.0f, 0.0f}, 0.0f, kQ3True};
}

TQ3BoundingSphere makeSphere(const TQ3Point3D& origin, float radius, const TQ3Boolean& isEmpty)
{
    return TQ3BoundingSphere{origin, radius, emptyFlag(isEmpty)};
}

bool isEmpty(const TQ3BoundingSphere& sphere)
{
    return enumValue(sphere.isEmpty) != kQ3False;
}

TQ3BoundingSphere unite(const TQ3BoundingSphere& s1, const TQ3BoundingSphere& s2)
{
    return uniteEither(s1, s2, emptySphere(), [&] {
        const glm::dvec3 c1 = toDouble(s1.origin), c2 = toDouble(s2.origin);
        const double r1 = s1.radius, r2 = s2.radius;
        const double apart = glm::distance(c1, c2);
        if (apart + r2 <= r1)
            return asNotEmpty(s1);
        if (apart + r1 <= r2)
            return asNotEmpty(s2);
        return merged(c1, r1, c2, r2);
    });
}

TQ3BoundingSphere unite(const TQ3BoundingSphere& sphere, const glm::dvec3& point)
{
    if (isEmpty(sphere))
        return sphereFrom(point, 0.0);
    const glm::dvec3 centre = toDouble(sphere.origin);
    if (glm::distance(centre, point) <= sphere.radius)
        return asNotEmpty(sphere);
    return merged(centre, sphere.radius, point, 0.0);
}

TQ3BoundingSphere sphereOf(std::size_t count, const std::function<glm::dvec3(std::size_t)>& point)
{
    if (count == 0)
        return emptySphere();
    const auto [low, high] = extentOf(count, point);
    const glm::dvec3 centre = (low + high) / 2.0;
    double radius = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const double d = glm::distance(centre, point(i));
        if (std::isnan(d) || d > radius)
            radius = d;
    }
    return sphereFrom(centre, radius);
}

} // namespace q3::math
