// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// QD3DMath.h's quaternions: q = (w, x, y, z) = w + xi + yj + zk. A nonzero
// q stands for the rotation v -> q v q^-1 (Hamilton's product), which for a
// unit q = (cos(a/2), sin(a/2) * axis) turns counterclockwise by a about the
// unit axis, the same turn as the matrices of base/MatrixMath.h. q and any
// nonzero multiple of it, -q included, stand for the same rotation; the zero
// quaternion stands for none, and the calls that need a rotation throw
// kQ3ErrorInvalidParameter for it.
//
// Composition follows QuickDraw 3D's matrices, left to right:
// multiply(q1, q2) is q1 first, then q2, which is the Hamilton product
// q2 * q1, so that matrix(multiply(q1, q2)) equals
// multiply(matrix(q1), matrix(q2)).
//
// Computed in double and rounded once. Sources: the rotation and matrix
// formulas are Shoemake, "Animating Rotation with Quaternion Curves"
// (SIGGRAPH 1985), section 3 and appendix; the matrix-to-quaternion
// conversion is Shepperd's method (J. Guidance and Control 1(3), 1978),
// choosing the largest of 4w^2, 4x^2, 4y^2, 4z^2 for accuracy.

#include "QD3D.h"

namespace q3::math {

TQ3Quaternion quaternionIdentity();
float dot(const TQ3Quaternion& q1, const TQ3Quaternion& q2);
/// Whether q is a rotation by a multiple of 2 pi: x, y and z all within
/// kQ3RealZero (FLT_EPSILON) of 0, as QuickDraw 3D 1.6 tests it; w is not
/// looked at. NaN components make it false.
bool isIdentity(const TQ3Quaternion& q);
/// q / |q|. Throws kQ3ErrorInvalidParameter for the zero quaternion.
TQ3Quaternion normalize(const TQ3Quaternion& q);
/// conjugate(q) / |q|^2, so q * invert(q) = 1 (for a unit q, the conjugate).
/// Throws kQ3ErrorInvalidParameter for the zero quaternion.
TQ3Quaternion invert(const TQ3Quaternion& q);
/// q1 first, then q2: the Hamilton product q2 * q1.
TQ3Quaternion multiply(const TQ3Quaternion& q1, const TQ3Quaternion& q2);

/// Unit quaternions for the turns of rotationX/Y/Z/XYZ in MatrixMath.h.
TQ3Quaternion quaternionRotationX(float radians);
TQ3Quaternion quaternionRotationY(float radians);
TQ3Quaternion quaternionRotationZ(float radians);
TQ3Quaternion quaternionRotationXYZ(float xRadians, float yRadians, float zRadians);
/// Counterclockwise about axis (any non-zero length). Throws
/// kQ3ErrorVector3DZeroLength when the axis has length 0.
TQ3Quaternion quaternionAboutAxis(const TQ3Vector3D& axis, float radians);
/// rotationBetween(v1, v2) of MatrixMath.h as a unit quaternion.
TQ3Quaternion quaternionVectorToVector(const TQ3Vector3D& v1, const TQ3Vector3D& v2);
/// The unit quaternion of the rotation in the upper-left 3x3 of matrix (the
/// rest is ignored); for a 3x3 that is no rotation, the unit quaternion
/// Shepperd's method makes of it.
TQ3Quaternion quaternionFromMatrix(const TQ3Matrix4x4& matrix);
/// The rotation of q as a matrix, translation and perspective entries 0
/// and value[3][3] 1. Throws kQ3ErrorInvalidParameter for the zero
/// quaternion.
TQ3Matrix4x4 matrixFromQuaternion(const TQ3Quaternion& q);

/// q1 or -q1, whichever has a positive dot product with q2 (-q1 when the
/// product is 0 or NaN): the same rotation as q1, on q2's side.
TQ3Quaternion matchReflection(const TQ3Quaternion& q1, const TQ3Quaternion& q2);
/// The straight line from q1 to q2 at t, scaled to unit length. Throws
/// kQ3ErrorInvalidParameter when the point at t is the zero quaternion.
TQ3Quaternion interpolateFast(const TQ3Quaternion& q1, const TQ3Quaternion& q2, float t);
/// Along the great arc from q1 to q2 at t, at constant angular speed
/// (Shoemake's slerp), with q1 at t = 0 and q2 at t = 1, whatever their
/// signs. Nearly equal directions (within 1e-6 radians), a zero quaternion
/// or NaN use the straight line instead; nearly opposite ones turn through
/// the quaternion perpendicular to q1, (-x, w, -z, y), to -q1 at t = 1.
TQ3Quaternion interpolateLinear(const TQ3Quaternion& q1, const TQ3Quaternion& q2, float t);

/// vector rotated by q. Throws kQ3ErrorInvalidParameter for the zero quaternion.
TQ3Vector3D rotate(const TQ3Vector3D& vector, const TQ3Quaternion& q);
/// point rotated by q about the origin.
TQ3Point3D rotate(const TQ3Point3D& point, const TQ3Quaternion& q);

} // namespace q3::math
