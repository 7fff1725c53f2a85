// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DMath.h's Q3Quaternion_* calls. (Q3Vector3D_TransformQuaternion and
// Q3Point3D_TransformQuaternion are with their prefixes' calls.)

#include "QD3DMath.h"
#include "api/MathEntry.h"
#include "base/QuaternionMath.h"

using namespace q3;
using q3::api::computeInto;
using q3::api::computeValue;

extern "C" {

TQ3Quaternion* Q3Quaternion_Set(TQ3Quaternion* quaternion, float w, float x, float y, float z)
{
    return computeInto(__func__, {{quaternion, "quaternion"}}, quaternion,
                       [&] { return TQ3Quaternion{w, x, y, z}; });
}

TQ3Quaternion* Q3Quaternion_SetIdentity(TQ3Quaternion* quaternion)
{
    return computeInto(__func__, {{quaternion, "quaternion"}}, quaternion, [] { return math::quaternionIdentity(); });
}

TQ3Quaternion* Q3Quaternion_Copy(const TQ3Quaternion* quaternion, TQ3Quaternion* result)
{
    return computeInto(__func__, {{quaternion, "quaternion"}, {result, "result"}}, result,
                       [&] { return *quaternion; });
}

TQ3Boolean Q3Quaternion_IsIdentity(const TQ3Quaternion* quaternion)
{
    return computeValue(__func__, kQ3False, {{quaternion, "quaternion"}},
                        [&] { return math::isIdentity(*quaternion) ? kQ3True : kQ3False; });
}

TQ3Quaternion* Q3Quaternion_Invert(const TQ3Quaternion* quaternion, TQ3Quaternion* result)
{
    return computeInto(__func__, {{quaternion, "quaternion"}, {result, "result"}}, result,
                       [&] { return math::invert(*quaternion); });
}

TQ3Quaternion* Q3Quaternion_Normalize(const TQ3Quaternion* quaternion, TQ3Quaternion* result)
{
    return computeInto(__func__, {{quaternion, "quaternion"}, {result, "result"}}, result,
                       [&] { return math::normalize(*quaternion); });
}

float Q3Quaternion_Dot(const TQ3Quaternion* q1, const TQ3Quaternion* q2)
{
    return computeValue(__func__, 0.0f, {{q1, "q1"}, {q2, "q2"}}, [&] { return math::dot(*q1, *q2); });
}

TQ3Quaternion* Q3Quaternion_Multiply(const TQ3Quaternion* q1, const TQ3Quaternion* q2, TQ3Quaternion* result)
{
    return computeInto(__func__, {{q1, "q1"}, {q2, "q2"}, {result, "result"}}, result,
                       [&] { return math::multiply(*q1, *q2); });
}

TQ3Quaternion* Q3Quaternion_SetRotateAboutAxis(TQ3Quaternion* quaternion, const TQ3Vector3D* axis, float angle)
{
    return computeInto(__func__, {{quaternion, "quaternion"}, {axis, "axis"}}, quaternion,
                       [&] { return math::quaternionAboutAxis(*axis, angle); });
}

TQ3Quaternion* Q3Quaternion_SetRotate_XYZ(TQ3Quaternion* quaternion, float xAngle, float yAngle, float zAngle)
{
    return computeInto(__func__, {{quaternion, "quaternion"}}, quaternion,
                       [&] { return math::quaternionRotationXYZ(xAngle, yAngle, zAngle); });
}

TQ3Quaternion* Q3Quaternion_SetRotate_X(TQ3Quaternion* quaternion, float angle)
{
    return computeInto(__func__, {{quaternion, "quaternion"}}, quaternion,
                       [&] { return math::quaternionRotationX(angle); });
}

TQ3Quaternion* Q3Quaternion_SetRotate_Y(TQ3Quaternion* quaternion, float angle)
{
    return computeInto(__func__, {{quaternion, "quaternion"}}, quaternion,
                       [&] { return math::quaternionRotationY(angle); });
}

TQ3Quaternion* Q3Quaternion_SetRotate_Z(TQ3Quaternion* quaternion, float angle)
{
    return computeInto(__func__, {{quaternion, "quaternion"}}, quaternion,
                       [&] { return math::quaternionRotationZ(angle); });
}

TQ3Quaternion* Q3Quaternion_SetMatrix(TQ3Quaternion* quaternion, const TQ3Matrix4x4* matrix)
{
    return computeInto(__func__, {{quaternion, "quaternion"}, {matrix, "matrix"}}, quaternion,
                       [&] { return math::quaternionFromMatrix(*matrix); });
}

TQ3Quaternion* Q3Quaternion_SetRotateVectorToVector(TQ3Quaternion* quaternion, const TQ3Vector3D* v1,
                                                    const TQ3Vector3D* v2)
{
    return computeInto(__func__, {{quaternion, "quaternion"}, {v1, "v1"}, {v2, "v2"}}, quaternion,
                       [&] { return math::quaternionVectorToVector(*v1, *v2); });
}

TQ3Quaternion* Q3Quaternion_MatchReflection(const TQ3Quaternion* q1, const TQ3Quaternion* q2, TQ3Quaternion* result)
{
    return computeInto(__func__, {{q1, "q1"}, {q2, "q2"}, {result, "result"}}, result,
                       [&] { return math::matchReflection(*q1, *q2); });
}

TQ3Quaternion* Q3Quaternion_InterpolateFast(const TQ3Quaternion* q1, const TQ3Quaternion* q2, float t,
                                            TQ3Quaternion* result)
{
    return computeInto(__func__, {{q1, "q1"}, {q2, "q2"}, {result, "result"}}, result,
                       [&] { return math::interpolateFast(*q1, *q2, t); });
}

TQ3Quaternion* Q3Quaternion_InterpolateLinear(const TQ3Quaternion* q1, const TQ3Quaternion* q2, float t,
                                              TQ3Quaternion* result)
{
    return computeInto(__func__, {{q1, "q1"}, {q2, "q2"}, {result, "result"}}, result,
                       [&] { return math::interpolateLinear(*q1, *q2, t); });
}

} // extern "C"
