// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "base/VectorMath.h"

#include "core/Error.h"
#include "base/MathValues.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace q3::math {

namespace {

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

// The angle of (x, y) counterclockwise from +x, in [0, 2 pi). Both zeros
// give 0 (atan2 would give pi for (-0, 0)); -0 becomes +0.
double angleOf(double x, double y)
{
    if (x == 0.0 && y == 0.0)
        return 0.0;
    const double angle = std::atan2(y, x);
    return angle < 0.0 ? angle + kTwoPi : angle + 0.0;
}

} // namespace

double ratioFraction(float r1, float r2)
{
    const double sum = double(r1) + double(r2);
    if (sum == 0.0)
        fail(kQ3ErrorInvalidParameter,
             "r1 + r2 is 0 (r1 " + std::to_string(r1) + "), so the ratio r2 / (r1 + r2) is undefined");
    return double(r2) / sum;
}

float length(const TQ3Vector2D& vector)
{
    return static_cast<float>(glm::length(toDouble(vector)));
}

TQ3Vector2D normalize(const TQ3Vector2D& vector)
{
    return normalizedOf(vector);
}

float dot(const TQ3Vector2D& v1, const TQ3Vector2D& v2)
{
    return static_cast<float>(glm::dot(toDouble(v1), toDouble(v2)));
}

float cross(const TQ3Vector2D& v1, const TQ3Vector2D& v2)
{
    return static_cast<float>(double(v1.x) * v2.y - double(v1.y) * v2.x);
}

TQ3Vector3D crossProductTri(const TQ3Point3D& p1, const TQ3Point3D& p2, const TQ3Point3D& p3)
{
    const glm::dvec3 a = toDouble(p1);
    return toFloat<TQ3Vector3D>(glm::cross(toDouble(p2) - a, toDouble(p3) - a));
}

TQ3Point3D to3D(const TQ3Point2D& point)
{
    return TQ3Point3D{point.x, point.y, 1.0f};
}

TQ3Point2D to2D(const TQ3RationalPoint3D& point)
{
    return toFloat<TQ3Point2D>(dehomogenize(toDouble(point)));
}

TQ3RationalPoint4D to4D(const TQ3Point3D& point)
{
    return TQ3RationalPoint4D{point.x, point.y, point.z, 1.0f};
}

TQ3Point3D to3D(const TQ3RationalPoint4D& point)
{
    return toFloat<TQ3Point3D>(dehomogenize(toDouble(point)));
}

TQ3Vector3D to3D(const TQ3Vector2D& vector)
{
    return TQ3Vector3D{vector.x, vector.y, 1.0f};
}

TQ3Vector2D to2D(const TQ3Vector3D& vector)
{
    return toFloat<TQ3Vector2D>(dehomogenize(toDouble(vector)));
}

TQ3PolarPoint toPolar(const TQ3Point2D& point)
{
    const double r = std::hypot(double(point.x), double(point.y));
    return TQ3PolarPoint{static_cast<float>(r), static_cast<float>(angleOf(point.x, point.y))};
}

TQ3Point2D toCartesian(const TQ3PolarPoint& point)
{
    const double theta = point.theta;
    return toFloat<TQ3Point2D>(glm::dvec2(std::cos(theta), std::sin(theta)) * double(point.r));
}

TQ3SphericalPoint toSpherical(const TQ3Point3D& point)
{
    const double x = point.x, y = point.y, z = point.z;
    const double rho = glm::length(glm::dvec3(x, y, z));
    if (rho == 0.0)
        return TQ3SphericalPoint{0.0f, 0.0f, 0.0f};
    const double phi = std::atan2(std::hypot(x, y), z);
    return TQ3SphericalPoint{static_cast<float>(rho), static_cast<float>(angleOf(x, y)),
                             static_cast<float>(phi)};
}

TQ3Point3D toCartesian(const TQ3SphericalPoint& point)
{
    const double theta = point.theta, phi = point.phi, rho = point.rho;
    const double planar = rho * std::sin(phi);
    return toFloat<TQ3Point3D>(glm::dvec3(planar * std::cos(theta), planar * std::sin(theta), rho * std::cos(phi)));
}

} // namespace q3::math
