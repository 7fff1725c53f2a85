// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/MatrixMath.h"

#include "core/Error.h"
#include "view/Matrix.h"

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cfloat>
#include <cmath>
#include <string>

namespace q3::math {

namespace {

// Every product of two floats is exact in double and no sum of a few can
// overflow, so lengths of vectors with huge components stay finite, and a
// determinant computed from float entries is 0 only for a singular matrix.
glm::dvec3 toDouble(const TQ3Vector3D& v)
{
    return glm::dvec3(v.x, v.y, v.z);
}

glm::dvec3 toDouble(const TQ3Point3D& p)
{
    return glm::dvec3(p.x, p.y, p.z);
}

TQ3Vector3D toVector(const glm::dvec3& v)
{
    return TQ3Vector3D{static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}

// The rotation turning axis `from` towards axis `to`, in the plane of the
// two, written out so that every other entry stays exactly 0 or 1.
TQ3Matrix4x4 planeRotation(int from, int to, float radians)
{
    const double c = std::cos(static_cast<double>(radians));
    const double s = std::sin(static_cast<double>(radians));
    Matrix m(1.0);
    m[from][from] = c;
    m[from][to] = s;
    m[to][from] = -s;
    m[to][to] = c;
    return toQ3(m);
}

} // namespace

float length(const TQ3Vector3D& vector)
{
    return static_cast<float>(glm::length(toDouble(vector)));
}

float distance(const TQ3Point3D& p1, const TQ3Point3D& p2)
{
    return static_cast<float>(glm::distance(toDouble(p1), toDouble(p2)));
}

TQ3Vector3D normalize(const TQ3Vector3D& vector)
{
    const glm::dvec3 v = toDouble(vector);
    const double size = glm::length(v);
    if (size == 0.0)
        fail(kQ3ErrorVector3DZeroLength, "the vector has length 0, so it has no direction");
    return toVector(v / size);
}

TQ3Vector3D cross(const TQ3Vector3D& v1, const TQ3Vector3D& v2)
{
    return toVector(glm::cross(toDouble(v1), toDouble(v2)));
}

float dot(const TQ3Vector3D& v1, const TQ3Vector3D& v2)
{
    return static_cast<float>(glm::dot(toDouble(v1), toDouble(v2)));
}

TQ3Point3D transform(const TQ3Point3D& point, const TQ3Matrix4x4& matrix)
{
    const glm::dvec4 r = transformPoint(fromQ3(matrix), toDouble(point));
    const double w = r.w == 0.0 ? 1.0 : r.w;
    return TQ3Point3D{static_cast<float>(r.x / w), static_cast<float>(r.y / w), static_cast<float>(r.z / w)};
}

TQ3RationalPoint4D transform(const TQ3RationalPoint4D& point, const TQ3Matrix4x4& matrix)
{
    const glm::dvec4 r = fromQ3(matrix) * glm::dvec4(point.x, point.y, point.z, point.w);
    return TQ3RationalPoint4D{static_cast<float>(r.x), static_cast<float>(r.y), static_cast<float>(r.z),
                              static_cast<float>(r.w)};
}

TQ3Matrix4x4 identity()
{
    return toQ3(Matrix(1.0));
}

// Translation and scale are written entry by entry rather than with
// glm::translate and glm::scale, which multiply the identity through: that
// turns the identity's zeros into -0 for a negative factor and into NaN
// (0 * inf) for an infinite one, where QuickDraw 3D stores exactly what it
// was given.
TQ3Matrix4x4 translation(float x, float y, float z)
{
    TQ3Matrix4x4 m = identity();
    m.value[3][0] = x;
    m.value[3][1] = y;
    m.value[3][2] = z;
    return m;
}

TQ3Matrix4x4 scaling(float x, float y, float z)
{
    TQ3Matrix4x4 m = identity();
    m.value[0][0] = x;
    m.value[1][1] = y;
    m.value[2][2] = z;
    return m;
}

TQ3Matrix4x4 rotationX(float radians)
{
    return planeRotation(1, 2, radians);
}

TQ3Matrix4x4 rotationY(float radians)
{
    return planeRotation(2, 0, radians);
}

TQ3Matrix4x4 rotationZ(float radians)
{
    return planeRotation(0, 1, radians);
}

TQ3Matrix4x4 rotationAboutAxis(const TQ3Point3D& origin, const TQ3Vector3D& orientation, float radians)
{
    const glm::dvec3 axis = toDouble(orientation);
    const double size = glm::length(axis);
    if (size == 0.0)
        fail(kQ3ErrorVector3DZeroLength, "the rotation axis has length 0, so it has no direction");
    // Move a point of the axis to the origin, rotate (glm's rotate turns
    // counterclockwise about its axis), move back.
    const glm::dvec3 o = toDouble(origin);
    const Matrix toOrigin = glm::translate(Matrix(1.0), -o);
    const Matrix turn = glm::rotate(Matrix(1.0), static_cast<double>(radians), axis / size);
    const Matrix back = glm::translate(Matrix(1.0), o);
    return toQ3(then(then(toOrigin, turn), back));
}

TQ3Matrix4x4 multiply(const TQ3Matrix4x4& a, const TQ3Matrix4x4& b)
{
    return toQ3(then(fromQ3(a), fromQ3(b)));
}

TQ3Matrix4x4 invert(const TQ3Matrix4x4& matrix)
{
    const Matrix m = fromQ3(matrix);
    const double determinant = glm::determinant(m);
    if (determinant == 0.0 || !std::isfinite(determinant))
        fail(kQ3ErrorNonInvertibleMatrix,
             "the matrix is singular (determinant " + std::to_string(determinant) + ")");
    const Matrix inverse = glm::inverse(m);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!(std::fabs(inverse[i][j]) <= FLT_MAX))
                fail(kQ3ErrorNonInvertibleMatrix, "inverse entry value[" + std::to_string(i) + "][" +
                                                      std::to_string(j) + "] is too large for a float");
    return toQ3(inverse);
}

TQ3Matrix4x4 transpose(const TQ3Matrix4x4& matrix)
{
    return toQ3(glm::transpose(fromQ3(matrix)));
}

bool isFinite(const TQ3Matrix4x4& matrix)
{
    for (const auto& row : matrix.value)
        for (float entry : row)
            if (!std::isfinite(entry))
                return false;
    return true;
}

} // namespace q3::math
