// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// QD3DMath.h's arithmetic on plain values: points, vectors and 4x4 matrices
// in QuickDraw 3D's row-vector convention (p' = p * M, translation in
// value[3][0..2]). It works in the view layer's double-precision glm Matrix
// (view/Matrix.h, which owns the one conversion between the conventions) and
// rounds to float once, at the end. No handles and no error manager: the two
// domain failures, a direction of length 0 and a singular matrix, throw
// q3::Error for the API layer to post.

#include "QD3D.h"

namespace q3::math {

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

TQ3Matrix4x4 identity();
TQ3Matrix4x4 translation(float x, float y, float z);
TQ3Matrix4x4 scaling(float x, float y, float z);
/// Counterclockwise as seen from the positive end of the axis; the entries
/// outside the rotated plane are exactly 0 and 1.
TQ3Matrix4x4 rotationX(float radians);
TQ3Matrix4x4 rotationY(float radians);
TQ3Matrix4x4 rotationZ(float radians);
/// About the line through origin along orientation (any non-zero length),
/// counterclockwise as seen from the tip of orientation. Throws
/// kQ3ErrorVector3DZeroLength when orientation has length 0.
TQ3Matrix4x4 rotationAboutAxis(const TQ3Point3D& origin, const TQ3Vector3D& orientation, float radians);

/// a * b: the map that applies a first, then b.
TQ3Matrix4x4 multiply(const TQ3Matrix4x4& a, const TQ3Matrix4x4& b);
/// Throws kQ3ErrorNonInvertibleMatrix when the determinant is 0 (or not a
/// number) or an entry of the inverse does not fit in a float.
TQ3Matrix4x4 invert(const TQ3Matrix4x4& matrix);
TQ3Matrix4x4 transpose(const TQ3Matrix4x4& matrix);

bool isFinite(const TQ3Matrix4x4& matrix);

} // namespace q3::math
