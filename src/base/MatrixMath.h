// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// QD3DMath.h's arithmetic on plain values: points, vectors and 4x4 matrices
// in QuickDraw 3D's row-vector convention (p' = p * M, translation in
// value[3][0..2]), and 3x3 matrices acting the same way on 2-D points
// (translation in value[2][0..1]). It works in the view layer's
// double-precision glm Matrix (base/Matrix.h, which owns the one conversion
// between the conventions) and rounds to float once, at the end. No handles
// and no error manager: the two domain failures, a direction of length 0
// and a singular matrix, throw q3::Error for the API layer to post.

#include "QD3D.h"

#include <glm/vec3.hpp>

namespace q3::math {

/// A unit axis and an angle in radians, counterclockwise about the axis.
struct AxisAngle {
    glm::dvec3 axis;
    double angle;
};

/// The rotation taking the direction of v1 to the direction of v2 (any
/// non-zero lengths) about their common normal v1 x v2. Parallel directions
/// give angle 0 (about v1); opposite ones a half turn about the unit vector
/// along v1 x e, e being the coordinate axis of v1's smallest component in
/// magnitude (the first of equals). Throws kQ3ErrorVector3DZeroLength when
/// either vector has length 0.
AxisAngle rotationBetween(const TQ3Vector3D& v1, const TQ3Vector3D& v2);

float length(const TQ3Vector3D& vector);
float distance(const TQ3Point3D& p1, const TQ3Point3D& p2);
/// Throws kQ3ErrorVector3DZeroLength when the vector has length 0.
TQ3Vector3D normalize(const TQ3Vector3D& vector);
TQ3Vector3D cross(const TQ3Vector3D& v1, const TQ3Vector3D& v2);
float dot(const TQ3Vector3D& v1, const TQ3Vector3D& v2);

/// (x, y, z, 1) * M divided by the resulting w, or undivided when w is 0.
TQ3Point3D transform(const TQ3Point3D& point, const TQ3Matrix4x4& matrix);
/// (x, y, z, w) * M, undivided.
TQ3RationalPoint4D transform(const TQ3RationalPoint4D& point, const TQ3Matrix4x4& matrix);
/// (x, y, z, 1) * M, undivided.
TQ3RationalPoint4D transformToRational(const TQ3Point3D& point, const TQ3Matrix4x4& matrix);
/// (x, y, z, 0) * M: the upper-left 3x3 only, as for a direction.
TQ3Vector3D transform(const TQ3Vector3D& vector, const TQ3Matrix4x4& matrix);
/// (x, y, 1) * M divided by the resulting w, or undivided when w is 0.
TQ3Point2D transform(const TQ3Point2D& point, const TQ3Matrix3x3& matrix);
TQ3Param2D transform(const TQ3Param2D& param, const TQ3Matrix3x3& matrix);
/// (x, y, 0) * M: the upper-left 2x2 only, as for a direction.
TQ3Vector2D transform(const TQ3Vector2D& vector, const TQ3Matrix3x3& matrix);

TQ3Matrix4x4 identity();
TQ3Matrix4x4 translation(float x, float y, float z);
TQ3Matrix4x4 scaling(float x, float y, float z);
/// Counterclockwise as seen from the positive end of the axis; the entries
/// outside the rotated plane are exactly 0 and 1.
TQ3Matrix4x4 rotationX(float radians);
TQ3Matrix4x4 rotationY(float radians);
TQ3Matrix4x4 rotationZ(float radians);
/// About x, then y, then z (Rx * Ry * Rz), each as rotationX/Y/Z.
TQ3Matrix4x4 rotationXYZ(float xRadians, float yRadians, float zRadians);
/// rotationXYZ about the lines through origin parallel to the axes.
TQ3Matrix4x4 rotationAboutPoint(const TQ3Point3D& origin, float xRadians, float yRadians, float zRadians);
/// About the line through origin along orientation (any non-zero length),
/// counterclockwise as seen from the tip of orientation. Throws
/// kQ3ErrorVector3DZeroLength when orientation has length 0.
TQ3Matrix4x4 rotationAboutAxis(const TQ3Point3D& origin, const TQ3Vector3D& orientation, float radians);
/// rotationBetween(v1, v2) as a matrix about the origin.
TQ3Matrix4x4 rotationVectorToVector(const TQ3Vector3D& v1, const TQ3Vector3D& v2);

/// a * b: the map that applies a first, then b.
TQ3Matrix4x4 multiply(const TQ3Matrix4x4& a, const TQ3Matrix4x4& b);
/// Throws kQ3ErrorNonInvertibleMatrix when the determinant is 0 (or not a
/// number) or an entry of the inverse does not fit in a float.
TQ3Matrix4x4 invert(const TQ3Matrix4x4& matrix);
TQ3Matrix4x4 transpose(const TQ3Matrix4x4& matrix);
float determinant(const TQ3Matrix4x4& matrix);

TQ3Matrix3x3 identity3x3();
TQ3Matrix3x3 translation2D(float x, float y);
TQ3Matrix3x3 scaling2D(float x, float y);
/// Counterclockwise (a quarter turn takes (1, 0) to (0, 1)) about origin.
TQ3Matrix3x3 rotationAboutPoint(const TQ3Point2D& origin, float radians);
TQ3Matrix3x3 multiply(const TQ3Matrix3x3& a, const TQ3Matrix3x3& b);
/// The same rules as the 4x4 invert.
TQ3Matrix3x3 invert(const TQ3Matrix3x3& matrix);
/// The transposed cofactor matrix: adjoint(M) * M = determinant(M) * I.
TQ3Matrix3x3 adjoint(const TQ3Matrix3x3& matrix);
TQ3Matrix3x3 transpose(const TQ3Matrix3x3& matrix);
float determinant(const TQ3Matrix3x3& matrix);

bool isFinite(const TQ3Matrix4x4& matrix);

} // namespace q3::math
