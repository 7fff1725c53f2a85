// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "base/MatrixMath.h"

#include "core/Error.h"
#include "base/MathValues.h"
#include "base/Matrix.h"

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <cfloat>
#include <cmath>
#include <string>

namespace q3::math {

namespace {

// The 4x4 conversions and composition of base/Matrix.h, overloaded below
// for the 3x3 matrices.
using q3::fromQ3;
using q3::then;
using q3::toQ3;

constexpr double kPi = 3.14159265358979323846;

// The rotation turning axis `from` towards axis `to`, in the plane of the
// two, written out so that every other entry stays exactly 0 or 1.
Matrix planeTurn(int from, int to, double radians)
{
    const double c = std::cos(radians);
    const double s = std::sin(radians);
    Matrix m(1.0);
    m[from][from] = c;
    m[from][to] = s;
    m[to][from] = -s;
    m[to][to] = c;
    return m;
}

TQ3Matrix4x4 planeRotation(int from, int to, float radians)
{
    return toQ3(planeTurn(from, to, static_cast<double>(radians)));
}

Matrix turnXYZ(float xRadians, float yRadians, float zRadians)
{
    return then(then(planeTurn(1, 2, xRadians), planeTurn(2, 0, yRadians)), planeTurn(0, 1, zRadians));
}

// The 2-D maps as 3x3 matrices, stored like Matrix: m[i][j] holds
// value[i][j], which makes m * v the row-vector product v * M.
using Matrix3 = glm::dmat3;

Matrix3 fromQ3(const TQ3Matrix3x3& value)
{
    Matrix3 m(1.0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m[i][j] = value.value[i][j];
    return m;
}

TQ3Matrix3x3 toQ3(const Matrix3& m)
{
    TQ3Matrix3x3 value;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            value.value[i][j] = static_cast<float>(m[i][j]);
    return value;
}

Matrix3 then(const Matrix3& first, const Matrix3& second)
{
    return second * first;
}

Matrix3 translate2D(const glm::dvec2& offset)
{
    Matrix3 m(1.0);
    m[2][0] = offset.x;
    m[2][1] = offset.y;
    return m;
}

// A determinant of 0 or NaN, or an inverse entry beyond FLT_MAX, cannot be
// stored as a float inverse.
void requireInvertible(double determinant)
{
    if (determinant == 0.0 || !std::isfinite(determinant))
        fail(kQ3ErrorNonInvertibleMatrix,
             "the matrix is singular (determinant " + std::to_string(determinant) + ")");
}

template <class M>
void requireFloatEntries(const M& inverse, int size)
{
    for (int i = 0; i < size; ++i)
        for (int j = 0; j < size; ++j)
            if (!(std::fabs(inverse[i][j]) <= FLT_MAX))
                fail(kQ3ErrorNonInvertibleMatrix, "inverse entry value[" + std::to_string(i) + "][" +
                                                      std::to_string(j) + "] is too large for a float");
}

// The inverse of a QuickDraw 3D matrix of `size` rows, checked as above.
template <class Q3Matrix>
Q3Matrix checkedInverse(const Q3Matrix& matrix, int size)
{
    const auto m = fromQ3(matrix);
    requireInvertible(glm::determinant(m));
    const auto inverse = glm::inverse(m);
    requireFloatEntries(inverse, size);
    return toQ3(inverse);
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
    return normalizedOf(vector);
}

TQ3Vector3D cross(const TQ3Vector3D& v1, const TQ3Vector3D& v2)
{
    return toFloat<TQ3Vector3D>(glm::cross(toDouble(v1), toDouble(v2)));
}

float dot(const TQ3Vector3D& v1, const TQ3Vector3D& v2)
{
    return static_cast<float>(glm::dot(toDouble(v1), toDouble(v2)));
}

TQ3Point3D transform(const TQ3Point3D& point, const TQ3Matrix4x4& matrix)
{
    return toFloat<TQ3Point3D>(dehomogenize(transformPoint(fromQ3(matrix), toDouble(point))));
}

TQ3RationalPoint4D transform(const TQ3RationalPoint4D& point, const TQ3Matrix4x4& matrix)
{
    return toFloat<TQ3RationalPoint4D>(fromQ3(matrix) * toDouble(point));
}

TQ3RationalPoint4D transformToRational(const TQ3Point3D& point, const TQ3Matrix4x4& matrix)
{
    return toFloat<TQ3RationalPoint4D>(transformPoint(fromQ3(matrix), toDouble(point)));
}

TQ3Vector3D transform(const TQ3Vector3D& vector, const TQ3Matrix4x4& matrix)
{
    return toFloat<TQ3Vector3D>(glm::dvec3(fromQ3(matrix) * glm::dvec4(toDouble(vector), 0.0)));
}

TQ3Point2D transform(const TQ3Point2D& point, const TQ3Matrix3x3& matrix)
{
    return toFloat<TQ3Point2D>(dehomogenize(fromQ3(matrix) * glm::dvec3(toDouble(point), 1.0)));
}

TQ3Param2D transform(const TQ3Param2D& param, const TQ3Matrix3x3& matrix)
{
    return toFloat<TQ3Param2D>(dehomogenize(fromQ3(matrix) * glm::dvec3(toDouble(param), 1.0)));
}

TQ3Vector2D transform(const TQ3Vector2D& vector, const TQ3Matrix3x3& matrix)
{
    return toFloat<TQ3Vector2D>(glm::dvec2(fromQ3(matrix) * glm::dvec3(toDouble(vector), 0.0)));
}

TQ3Matrix4x4 identity()
{
    return toQ3(Matrix(1.0));
}

// Translation and scale are written entry by entry rather than with
// glm::translate and glm::scale, which multiply the identity through: that
// turns the identity's zeros into -0 for a negative factor and into NaN
// (0 * inf) for an infinite one, where QuickDraw 3D stores exactly what it
// was given: x, y and z in the last row (translation) or on the diagonal
// (scaling) of the identity.
namespace {

TQ3Matrix4x4 identityWith(float x, float y, float z, bool inLastRow)
{
    TQ3Matrix4x4 m = identity();
    const float values[3] = {x, y, z};
    for (int i = 0; i < 3; ++i)
        m.value[inLastRow ? 3 : i][i] = values[i];
    return m;
}

} // namespace

TQ3Matrix4x4 translation(float x, float y, float z)
{
    return identityWith(x, y, z, true);
}

TQ3Matrix4x4 scaling(float x, float y, float z)
{
    return identityWith(x, y, z, false);
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

TQ3Matrix4x4 rotationXYZ(float xRadians, float yRadians, float zRadians)
{
    return toQ3(turnXYZ(xRadians, yRadians, zRadians));
}

TQ3Matrix4x4 rotationAboutPoint(const TQ3Point3D& origin, float xRadians, float yRadians, float zRadians)
{
    const glm::dvec3 o = toDouble(origin);
    const Matrix toOrigin = glm::translate(Matrix(1.0), -o);
    const Matrix back = glm::translate(Matrix(1.0), o);
    return toQ3(then(then(toOrigin, turnXYZ(xRadians, yRadians, zRadians)), back));
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

AxisAngle rotationBetween(const TQ3Vector3D& v1, const TQ3Vector3D& v2)
{
    const double size1 = glm::length(toDouble(v1));
    const double size2 = glm::length(toDouble(v2));
    if (size1 == 0.0 || size2 == 0.0)
        fail(kQ3ErrorVector3DZeroLength, std::string(size1 == 0.0 ? "v1" : "v2") +
                                             " has length 0, so it has no direction");
    const glm::dvec3 from = toDouble(v1) / size1;
    const glm::dvec3 to = toDouble(v2) / size2;
    const glm::dvec3 normal = glm::cross(from, to);
    const double sine = glm::length(normal);
    const double cosine = glm::dot(from, to);
    // NaNs take this branch too, and stay NaNs.
    if (sine != 0.0)
        return AxisAngle{normal / sine, std::atan2(sine, cosine)};
    if (cosine > 0.0)
        return AxisAngle{from, 0.0};
    int smallest = 0;
    for (int i = 1; i < 3; ++i)
        if (std::fabs(from[i]) < std::fabs(from[smallest]))
            smallest = i;
    glm::dvec3 axis(0.0);
    axis[smallest] = 1.0;
    const glm::dvec3 perpendicular = glm::cross(from, axis);
    return AxisAngle{perpendicular / glm::length(perpendicular), kPi};
}

TQ3Matrix4x4 rotationVectorToVector(const TQ3Vector3D& v1, const TQ3Vector3D& v2)
{
    const AxisAngle turn = rotationBetween(v1, v2);
    return toQ3(glm::rotate(Matrix(1.0), turn.angle, turn.axis));
}

TQ3Matrix4x4 multiply(const TQ3Matrix4x4& a, const TQ3Matrix4x4& b)
{
    return toQ3(then(fromQ3(a), fromQ3(b)));
}

TQ3Matrix4x4 invert(const TQ3Matrix4x4& matrix)
{
    return checkedInverse(matrix, 4);
}

TQ3Matrix4x4 transpose(const TQ3Matrix4x4& matrix)
{
    return toQ3(glm::transpose(fromQ3(matrix)));
}

// The transpose's determinant is the matrix's, so the layout does not matter.
float determinant(const TQ3Matrix4x4& matrix)
{
    return static_cast<float>(glm::determinant(fromQ3(matrix)));
}

TQ3Matrix3x3 identity3x3()
{
    return toQ3(Matrix3(1.0));
}

TQ3Matrix3x3 translation2D(float x, float y)
{
    TQ3Matrix3x3 m = identity3x3();
    m.value[2][0] = x;
    m.value[2][1] = y;
    return m;
}

TQ3Matrix3x3 scaling2D(float x, float y)
{
    TQ3Matrix3x3 m = identity3x3();
    m.value[0][0] = x;
    m.value[1][1] = y;
    return m;
}

TQ3Matrix3x3 rotationAboutPoint(const TQ3Point2D& origin, float radians)
{
    const double c = std::cos(static_cast<double>(radians));
    const double s = std::sin(static_cast<double>(radians));
    Matrix3 turn(1.0);
    turn[0][0] = c;
    turn[0][1] = s;
    turn[1][0] = -s;
    turn[1][1] = c;
    const glm::dvec2 o = toDouble(origin);
    return toQ3(then(then(translate2D(-o), turn), translate2D(o)));
}

TQ3Matrix3x3 multiply(const TQ3Matrix3x3& a, const TQ3Matrix3x3& b)
{
    return toQ3(then(fromQ3(a), fromQ3(b)));
}

TQ3Matrix3x3 invert(const TQ3Matrix3x3& matrix)
{
    return checkedInverse(matrix, 3);
}

// Entry (j, i) of the adjoint is the cofactor of entry (i, j): the 2x2
// determinant of the rows and columns after i and j, taken cyclically, which
// carries the cofactor's sign by itself.
TQ3Matrix3x3 adjoint(const TQ3Matrix3x3& matrix)
{
    const Matrix3 m = fromQ3(matrix);
    Matrix3 result(0.0);
    for (int i = 0; i < 3; ++i) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        for (int j = 0; j < 3; ++j) {
            const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            result[j][i] = m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
        }
    }
    return toQ3(result);
}

TQ3Matrix3x3 transpose(const TQ3Matrix3x3& matrix)
{
    return toQ3(glm::transpose(fromQ3(matrix)));
}

float determinant(const TQ3Matrix3x3& matrix)
{
    return static_cast<float>(glm::determinant(fromQ3(matrix)));
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
