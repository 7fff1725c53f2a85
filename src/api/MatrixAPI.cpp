// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DMath.h's Q3Matrix3x3_* and Q3Matrix4x4_* calls.

#include "QD3DMath.h"
#include "api/MathEntry.h"
#include "base/MatrixMath.h"
#include "base/QuaternionMath.h"

using namespace q3;
using q3::api::computeInto;
using q3::api::computeValue;

extern "C" {

TQ3Matrix3x3* Q3Matrix3x3_Copy(const TQ3Matrix3x3* matrix3x3, TQ3Matrix3x3* result)
{
    return computeInto(__func__, {{matrix3x3, "matrix3x3"}, {result, "result"}}, result, [&] { return *matrix3x3; });
}

TQ3Matrix4x4* Q3Matrix4x4_Copy(const TQ3Matrix4x4* matrix4x4, TQ3Matrix4x4* result)
{
    return computeInto(__func__, {{matrix4x4, "matrix4x4"}, {result, "result"}}, result, [&] { return *matrix4x4; });
}

TQ3Matrix3x3* Q3Matrix3x3_SetIdentity(TQ3Matrix3x3* matrix3x3)
{
    return computeInto(__func__, {{matrix3x3, "matrix3x3"}}, matrix3x3, [] { return math::identity3x3(); });
}

TQ3Matrix4x4* Q3Matrix4x4_SetIdentity(TQ3Matrix4x4* matrix4x4)
{
    return computeInto(__func__, {{matrix4x4, "matrix4x4"}}, matrix4x4, [] { return math::identity(); });
}

TQ3Matrix3x3* Q3Matrix3x3_Transpose(const TQ3Matrix3x3* matrix3x3, TQ3Matrix3x3* result)
{
    return computeInto(__func__, {{matrix3x3, "matrix3x3"}, {result, "result"}}, result,
                       [&] { return math::transpose(*matrix3x3); });
}

TQ3Matrix4x4* Q3Matrix4x4_Transpose(const TQ3Matrix4x4* matrix4x4, TQ3Matrix4x4* result)
{
    return computeInto(__func__, {{matrix4x4, "matrix4x4"}, {result, "result"}}, result,
                       [&] { return math::transpose(*matrix4x4); });
}

TQ3Matrix3x3* Q3Matrix3x3_Invert(const TQ3Matrix3x3* matrix3x3, TQ3Matrix3x3* result)
{
    return computeInto(__func__, {{matrix3x3, "matrix3x3"}, {result, "result"}}, result,
                       [&] { return math::invert(*matrix3x3); });
}

TQ3Matrix4x4* Q3Matrix4x4_Invert(const TQ3Matrix4x4* matrix4x4, TQ3Matrix4x4* result)
{
    return computeInto(__func__, {{matrix4x4, "matrix4x4"}, {result, "result"}}, result,
                       [&] { return math::invert(*matrix4x4); });
}

TQ3Matrix3x3* Q3Matrix3x3_Adjoint(const TQ3Matrix3x3* matrix3x3, TQ3Matrix3x3* result)
{
    return computeInto(__func__, {{matrix3x3, "matrix3x3"}, {result, "result"}}, result,
                       [&] { return math::adjoint(*matrix3x3); });
}

TQ3Matrix3x3* Q3Matrix3x3_Multiply(const TQ3Matrix3x3* matrixA, const TQ3Matrix3x3* matrixB, TQ3Matrix3x3* result)
{
    return computeInto(__func__, {{matrixA, "matrixA"}, {matrixB, "matrixB"}, {result, "result"}}, result,
                       [&] { return math::multiply(*matrixA, *matrixB); });
}

TQ3Matrix4x4* Q3Matrix4x4_Multiply(const TQ3Matrix4x4* matrixA, const TQ3Matrix4x4* matrixB, TQ3Matrix4x4* result)
{
    return computeInto(__func__, {{matrixA, "matrixA"}, {matrixB, "matrixB"}, {result, "result"}}, result,
                       [&] { return math::multiply(*matrixA, *matrixB); });
}

TQ3Matrix3x3* Q3Matrix3x3_SetTranslate(TQ3Matrix3x3* matrix3x3, float xTrans, float yTrans)
{
    return computeInto(__func__, {{matrix3x3, "matrix3x3"}}, matrix3x3,
                       [&] { return math::translation2D(xTrans, yTrans); });
}

TQ3Matrix3x3* Q3Matrix3x3_SetScale(TQ3Matrix3x3* matrix3x3, float xScale, float yScale)
{
    return computeInto(__func__, {{matrix3x3, "matrix3x3"}}, matrix3x3,
                       [&] { return math::scaling2D(xScale, yScale); });
}

TQ3Matrix3x3* Q3Matrix3x3_SetRotateAboutPoint(TQ3Matrix3x3* matrix3x3, const TQ3Point2D* origin, float angle)
{
    return computeInto(__func__, {{matrix3x3, "matrix3x3"}, {origin, "origin"}}, matrix3x3,
                       [&] { return math::rotationAboutPoint(*origin, angle); });
}

TQ3Matrix4x4* Q3Matrix4x4_SetTranslate(TQ3Matrix4x4* matrix4x4, float xTrans, float yTrans, float zTrans)
{
    return computeInto(__func__, {{matrix4x4, "matrix4x4"}}, matrix4x4,
                       [&] { return math::translation(xTrans, yTrans, zTrans); });
}

TQ3Matrix4x4* Q3Matrix4x4_SetScale(TQ3Matrix4x4* matrix4x4, float xScale, float yScale, float zScale)
{
    return computeInto(__func__, {{matrix4x4, "matrix4x4"}}, matrix4x4,
                       [&] { return math::scaling(xScale, yScale, zScale); });
}

TQ3Matrix4x4* Q3Matrix4x4_SetRotateAboutPoint(TQ3Matrix4x4* matrix4x4, const TQ3Point3D* origin, float xAngle,
                                              float yAngle, float zAngle)
{
    return computeInto(__func__, {{matrix4x4, "matrix4x4"}, {origin, "origin"}}, matrix4x4,
                       [&] { return math::rotationAboutPoint(*origin, xAngle, yAngle, zAngle); });
}

TQ3Matrix4x4* Q3Matrix4x4_SetRotateAboutAxis(TQ3Matrix4x4* matrix4x4, const TQ3Point3D* origin,
                                             const TQ3Vector3D* orientation, float angle)
{
    return computeInto(__func__, {{matrix4x4, "matrix4x4"}, {origin, "origin"}, {orientation, "orientation"}},
                       matrix4x4, [&] { return math::rotationAboutAxis(*origin, *orientation, angle); });
}

TQ3Matrix4x4* Q3Matrix4x4_SetRotate_X(TQ3Matrix4x4* matrix4x4, float angle)
{
    return computeInto(__func__, {{matrix4x4, "matrix4x4"}}, matrix4x4, [&] { return math::rotationX(angle); });
}

TQ3Matrix4x4* Q3Matrix4x4_SetRotate_Y(TQ3Matrix4x4* matrix4x4, float angle)
{
    return computeInto(__func__, {{matrix4x4, "matrix4x4"}}, matrix4x4, [&] { return math::rotationY(angle); });
}

TQ3Matrix4x4* Q3Matrix4x4_SetRotate_Z(TQ3Matrix4x4* matrix4x4, float angle)
{
    return computeInto(__func__, {{matrix4x4, "matrix4x4"}}, matrix4x4, [&] { return math::rotationZ(angle); });
}

TQ3Matrix4x4* Q3Matrix4x4_SetRotate_XYZ(TQ3Matrix4x4* matrix4x4, float xAngle, float yAngle, float zAngle)
{
    return computeInto(__func__, {{matrix4x4, "matrix4x4"}}, matrix4x4,
                       [&] { return math::rotationXYZ(xAngle, yAngle, zAngle); });
}

TQ3Matrix4x4* Q3Matrix4x4_SetRotateVectorToVector(TQ3Matrix4x4* matrix4x4, const TQ3Vector3D* v1,
                                                  const TQ3Vector3D* v2)
{
    return computeInto(__func__, {{matrix4x4, "matrix4x4"}, {v1, "v1"}, {v2, "v2"}}, matrix4x4,
                       [&] { return math::rotationVectorToVector(*v1, *v2); });
}

TQ3Matrix4x4* Q3Matrix4x4_SetQuaternion(TQ3Matrix4x4* matrix, const TQ3Quaternion* quaternion)
{
    return computeInto(__func__, {{matrix, "matrix"}, {quaternion, "quaternion"}}, matrix,
                       [&] { return math::matrixFromQuaternion(*quaternion); });
}

float Q3Matrix3x3_Determinant(const TQ3Matrix3x3* matrix3x3)
{
    return computeValue(__func__, 0.0f, {{matrix3x3, "matrix3x3"}}, [&] { return math::determinant(*matrix3x3); });
}

float Q3Matrix4x4_Determinant(const TQ3Matrix4x4* matrix4x4)
{
    return computeValue(__func__, 0.0f, {{matrix4x4, "matrix4x4"}}, [&] { return math::determinant(*matrix4x4); });
}

} // extern "C"
