// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "base/QuaternionMath.h"

#include "core/Error.h"
#include "base/MathValues.h"
#include "base/MatrixMath.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <cfloat>
#include <cmath>

namespace q3::math {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Below this angle between two quaternions slerp divides by almost 0, and
// the straight line is as good to float precision.
constexpr double kSmallAngle = 1e-6;

struct Quat {
    double w, x, y, z;
};

Quat toQuat(const TQ3Quaternion& q)
{
    return Quat{q.w, q.x, q.y, q.z};
}

TQ3Quaternion toFloat(const Quat& q)
{
    return TQ3Quaternion{static_cast<float>(q.w), static_cast<float>(q.x), static_cast<float>(q.y),
                         static_cast<float>(q.z)};
}

Quat operator*(double s, const Quat& q)
{
    return Quat{s * q.w, s * q.x, s * q.y, s * q.z};
}

Quat operator+(const Quat& a, const Quat& b)
{
    return Quat{a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
}

double dotOf(const Quat& a, const Quat& b)
{
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}

double normOf(const Quat& q)
{
    return std::sqrt(dotOf(q, q));
}

// Hamilton's product a * b.
Quat hamilton(const Quat& a, const Quat& b)
{
    return Quat{a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

Quat fromAxisAngle(const glm::dvec3& unitAxis, double radians)
{
    const double s = std::sin(radians / 2.0);
    return Quat{std::cos(radians / 2.0), s * unitAxis.x, s * unitAxis.y, s * unitAxis.z};
}

double squaredNormOrFail(const Quat& q)
{
    const double n = dotOf(q, q);
    if (n == 0.0)
        fail(kQ3ErrorInvalidParameter, "the quaternion is (0, 0, 0, 0), which stands for no rotation");
    return n;
}

// The rotation of q as the column-vector map R (R v = q v q^-1), written
// with s = 2 / |q|^2 so that any nonzero multiple of q gives the same R.
glm::dmat3 rotationOf(const Quat& q)
{
    const double s = 2.0 / squaredNormOrFail(q);
    const double xx = s * q.x * q.x, yy = s * q.y * q.y, zz = s * q.z * q.z;
    const double xy = s * q.x * q.y, xz = s * q.x * q.z, yz = s * q.y * q.z;
    const double wx = s * q.w * q.x, wy = s * q.w * q.y, wz = s * q.w * q.z;
    glm::dmat3 r; // r[column][row]
    r[0] = glm::dvec3(1.0 - yy - zz, xy + wz, xz - wy);
    r[1] = glm::dvec3(xy - wz, 1.0 - xx - zz, yz + wx);
    r[2] = glm::dvec3(xz + wy, yz - wx, 1.0 - xx - yy);
    return r;
}

} // namespace

TQ3Quaternion quaternionIdentity()
{
    return TQ3Quaternion{1.0f, 0.0f, 0.0f, 0.0f};
}

float dot(const TQ3Quaternion& q1, const TQ3Quaternion& q2)
{
    return static_cast<float>(dotOf(toQuat(q1), toQuat(q2)));
}

bool isIdentity(const TQ3Quaternion& q)
{
    return std::fabs(q.x) <= FLT_EPSILON && std::fabs(q.y) <= FLT_EPSILON && std::fabs(q.z) <= FLT_EPSILON;
}

TQ3Quaternion normalize(const TQ3Quaternion& q)
{
    const Quat a = toQuat(q);
    return toFloat((1.0 / std::sqrt(squaredNormOrFail(a))) * a);
}

TQ3Quaternion invert(const TQ3Quaternion& q)
{
    const Quat a = toQuat(q);
    const double n = squaredNormOrFail(a);
    return toFloat(Quat{a.w / n, -a.x / n, -a.y / n, -a.z / n});
}

TQ3Quaternion multiply(const TQ3Quaternion& q1, const TQ3Quaternion& q2)
{
    return toFloat(hamilton(toQuat(q2), toQuat(q1)));
}

TQ3Quaternion quaternionRotationX(float radians)
{
    return toFloat(fromAxisAngle(glm::dvec3(1.0, 0.0, 0.0), radians));
}

TQ3Quaternion quaternionRotationY(float radians)
{
    return toFloat(fromAxisAngle(glm::dvec3(0.0, 1.0, 0.0), radians));
}

TQ3Quaternion quaternionRotationZ(float radians)
{
    return toFloat(fromAxisAngle(glm::dvec3(0.0, 0.0, 1.0), radians));
}

TQ3Quaternion quaternionRotationXYZ(float xRadians, float yRadians, float zRadians)
{
    const Quat qx = fromAxisAngle(glm::dvec3(1.0, 0.0, 0.0), xRadians);
    const Quat qy = fromAxisAngle(glm::dvec3(0.0, 1.0, 0.0), yRadians);
    const Quat qz = fromAxisAngle(glm::dvec3(0.0, 0.0, 1.0), zRadians);
    return toFloat(hamilton(qz, hamilton(qy, qx)));
}

TQ3Quaternion quaternionAboutAxis(const TQ3Vector3D& axis, float radians)
{
    const glm::dvec3 a = toDouble(axis);
    const double size = glm::length(a);
    if (size == 0.0)
        fail(kQ3ErrorVector3DZeroLength, "the rotation axis has length 0, so it has no direction");
    return toFloat(fromAxisAngle(a / size, radians));
}

TQ3Quaternion quaternionVectorToVector(const TQ3Vector3D& v1, const TQ3Vector3D& v2)
{
    const AxisAngle turn = rotationBetween(v1, v2);
    return toFloat(fromAxisAngle(turn.axis, turn.angle));
}

TQ3Quaternion quaternionFromMatrix(const TQ3Matrix4x4& matrix)
{
    // r(i, j): row i, column j of the column-vector rotation, the transpose
    // of QuickDraw 3D's row-vector matrix.
    auto r = [&](int i, int j) { return double(matrix.value[j][i]); };
    const double trace = r(0, 0) + r(1, 1) + r(2, 2);
    // 4w^2, 4x^2, 4y^2, 4z^2; they sum to 4, so the largest is at least 1.
    const double squares[4] = {1.0 + trace, 1.0 + r(0, 0) - r(1, 1) - r(2, 2), 1.0 - r(0, 0) + r(1, 1) - r(2, 2),
                               1.0 - r(0, 0) - r(1, 1) + r(2, 2)};
    int largest = 0;
    for (int i = 1; i < 4; ++i)
        if (squares[i] > squares[largest])
            largest = i;
    const double big = std::sqrt(squares[largest]) / 2.0; // that component, chosen positive
    const double quarter = 1.0 / (4.0 * big);
    Quat q{};
    switch (largest) {
    case 0:
        q = Quat{big, (r(2, 1) - r(1, 2)) * quarter, (r(0, 2) - r(2, 0)) * quarter, (r(1, 0) - r(0, 1)) * quarter};
        break;
    case 1:
        q = Quat{(r(2, 1) - r(1, 2)) * quarter, big, (r(0, 1) + r(1, 0)) * quarter, (r(0, 2) + r(2, 0)) * quarter};
        break;
    case 2:
        q = Quat{(r(0, 2) - r(2, 0)) * quarter, (r(0, 1) + r(1, 0)) * quarter, big, (r(1, 2) + r(2, 1)) * quarter};
        break;
    default:
        q = Quat{(r(1, 0) - r(0, 1)) * quarter, (r(0, 2) + r(2, 0)) * quarter, (r(1, 2) + r(2, 1)) * quarter, big};
        break;
    }
    return toFloat((1.0 / normOf(q)) * q);
}

TQ3Matrix4x4 matrixFromQuaternion(const TQ3Quaternion& q)
{
    const glm::dmat3 r = rotationOf(toQuat(q));
    TQ3Matrix4x4 m = identity();
    // QuickDraw 3D's value[i][j] is the transpose's (i, j): r[i][j] in
    // glm's column-major indexing.
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m.value[i][j] = static_cast<float>(r[i][j]);
    return m;
}

TQ3Quaternion matchReflection(const TQ3Quaternion& q1, const TQ3Quaternion& q2)
{
    if (dotOf(toQuat(q1), toQuat(q2)) > 0.0)
        return q1;
    return TQ3Quaternion{-q1.w, -q1.x, -q1.y, -q1.z};
}

TQ3Quaternion interpolateFast(const TQ3Quaternion& q1, const TQ3Quaternion& q2, float t)
{
    const Quat line = (1.0 - double(t)) * toQuat(q1) + double(t) * toQuat(q2);
    const double n = dotOf(line, line);
    if (n == 0.0)
        fail(kQ3ErrorInvalidParameter, "q1 and q2 cancel out at t, which leaves no rotation");
    return toFloat((1.0 / std::sqrt(n)) * line);
}

TQ3Quaternion interpolateLinear(const TQ3Quaternion& q1, const TQ3Quaternion& q2, float t)
{
    const Quat a = toQuat(q1), b = toQuat(q2);
    const double s = t;
    const double cosine = dotOf(a, b) / (normOf(a) * normOf(b));
    const double angle = std::acos(std::fmax(-1.0, std::fmin(1.0, cosine)));
    const double sine = std::sin(angle);
    if (sine > kSmallAngle)
        return toFloat((std::sin((1.0 - s) * angle) / sine) * a + (std::sin(s * angle) / sine) * b);
    if (cosine < 0.0) {
        const Quat perpendicular{-a.x, a.w, -a.z, a.y};
        return toFloat(std::cos(kPi * s) * a + std::sin(kPi * s) * perpendicular);
    }
    return toFloat((1.0 - s) * a + s * b);
}

TQ3Vector3D rotate(const TQ3Vector3D& vector, const TQ3Quaternion& q)
{
    return toFloat<TQ3Vector3D>(rotationOf(toQuat(q)) * toDouble(vector));
}

TQ3Point3D rotate(const TQ3Point3D& point, const TQ3Quaternion& q)
{
    return toFloat<TQ3Point3D>(rotationOf(toQuat(q)) * toDouble(point));
}

} // namespace q3::math
