// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DMath.h's Q3Vector2D_* and Q3Vector3D_* calls.

#include "QD3DMath.h"
#include "api/MathEntry.h"
#include "base/MatrixMath.h"
#include "base/QuaternionMath.h"
#include "base/VectorMath.h"

using namespace q3;
using q3::api::computeInto;
using q3::api::computeValue;

extern "C" {

TQ3Vector2D* Q3Vector2D_Set(TQ3Vector2D* vector2D, float x, float y)
{
    return computeInto(__func__, {{vector2D, "vector2D"}}, vector2D, [&] { return TQ3Vector2D{x, y}; });
}

TQ3Vector3D* Q3Vector3D_Set(TQ3Vector3D* vector3D, float x, float y, float z)
{
    return computeInto(__func__, {{vector3D, "vector3D"}}, vector3D, [&] { return TQ3Vector3D{x, y, z}; });
}

TQ3Vector3D* Q3Vector2D_To3D(const TQ3Vector2D* vector2D, TQ3Vector3D* result)
{
    return computeInto(__func__, {{vector2D, "vector2D"}, {result, "result"}}, result,
                       [&] { return math::to3D(*vector2D); });
}

TQ3Vector2D* Q3Vector3D_To2D(const TQ3Vector3D* vector3D, TQ3Vector2D* result)
{
    return computeInto(__func__, {{vector3D, "vector3D"}, {result, "result"}}, result,
                       [&] { return math::to2D(*vector3D); });
}

TQ3Vector2D* Q3Vector2D_Scale(const TQ3Vector2D* vector2D, float scalar, TQ3Vector2D* result)
{
    return computeInto(__func__, {{vector2D, "vector2D"}, {result, "result"}}, result,
                       [&] { return math::scale(*vector2D, scalar); });
}

TQ3Vector3D* Q3Vector3D_Scale(const TQ3Vector3D* vector3D, float scalar, TQ3Vector3D* result)
{
    return computeInto(__func__, {{vector3D, "vector3D"}, {result, "result"}}, result,
                       [&] { return math::scale(*vector3D, scalar); });
}

float Q3Vector2D_Length(const TQ3Vector2D* vector2D)
{
    return computeValue(__func__, 0.0f, {{vector2D, "vector2D"}}, [&] { return math::length(*vector2D); });
}

float Q3Vector3D_Length(const TQ3Vector3D* vector3D)
{
    return computeValue(__func__, 0.0f, {{vector3D, "vector3D"}}, [&] { return math::length(*vector3D); });
}

TQ3Vector2D* Q3Vector2D_Normalize(const TQ3Vector2D* vector2D, TQ3Vector2D* result)
{
    return computeInto(__func__, {{vector2D, "vector2D"}, {result, "result"}}, result,
                       [&] { return math::normalize(*vector2D); });
}

TQ3Vector3D* Q3Vector3D_Normalize(const TQ3Vector3D* vector3D, TQ3Vector3D* result)
{
    return computeInto(__func__, {{vector3D, "vector3D"}, {result, "result"}}, result,
                       [&] { return math::normalize(*vector3D); });
}

TQ3Vector2D* Q3Vector2D_Add(const TQ3Vector2D* v1, const TQ3Vector2D* v2, TQ3Vector2D* result)
{
    return computeInto(__func__, {{v1, "v1"}, {v2, "v2"}, {result, "result"}}, result,
                       [&] { return math::add(*v1, *v2); });
}

TQ3Vector3D* Q3Vector3D_Add(const TQ3Vector3D* v1, const TQ3Vector3D* v2, TQ3Vector3D* result)
{
    return computeInto(__func__, {{v1, "v1"}, {v2, "v2"}, {result, "result"}}, result,
                       [&] { return math::add(*v1, *v2); });
}

TQ3Vector2D* Q3Vector2D_Subtract(const TQ3Vector2D* v1, const TQ3Vector2D* v2, TQ3Vector2D* result)
{
    return computeInto(__func__, {{v1, "v1"}, {v2, "v2"}, {result, "result"}}, result,
                       [&] { return math::subtract(*v1, *v2); });
}

TQ3Vector3D* Q3Vector3D_Subtract(const TQ3Vector3D* v1, const TQ3Vector3D* v2, TQ3Vector3D* result)
{
    return computeInto(__func__, {{v1, "v1"}, {v2, "v2"}, {result, "result"}}, result,
                       [&] { return math::subtract(*v1, *v2); });
}

float Q3Vector2D_Cross(const TQ3Vector2D* v1, const TQ3Vector2D* v2)
{
    return computeValue(__func__, 0.0f, {{v1, "v1"}, {v2, "v2"}}, [&] { return math::cross(*v1, *v2); });
}

TQ3Vector3D* Q3Vector3D_Cross(const TQ3Vector3D* v1, const TQ3Vector3D* v2, TQ3Vector3D* result)
{
    return computeInto(__func__, {{v1, "v1"}, {v2, "v2"}, {result, "result"}}, result,
                       [&] { return math::cross(*v1, *v2); });
}

float Q3Vector2D_Dot(const TQ3Vector2D* v1, const TQ3Vector2D* v2)
{
    return computeValue(__func__, 0.0f, {{v1, "v1"}, {v2, "v2"}}, [&] { return math::dot(*v1, *v2); });
}

float Q3Vector3D_Dot(const TQ3Vector3D* v1, const TQ3Vector3D* v2)
{
    return computeValue(__func__, 0.0f, {{v1, "v1"}, {v2, "v2"}}, [&] { return math::dot(*v1, *v2); });
}

TQ3Vector2D* Q3Vector2D_Transform(const TQ3Vector2D* vector2D, const TQ3Matrix3x3* matrix3x3, TQ3Vector2D* result)
{
    return computeInto(__func__, {{vector2D, "vector2D"}, {matrix3x3, "matrix3x3"}, {result, "result"}}, result,
                       [&] { return math::transform(*vector2D, *matrix3x3); });
}

TQ3Vector3D* Q3Vector3D_Transform(const TQ3Vector3D* vector3D, const TQ3Matrix4x4* matrix4x4, TQ3Vector3D* result)
{
    return computeInto(__func__, {{vector3D, "vector3D"}, {matrix4x4, "matrix4x4"}, {result, "result"}}, result,
                       [&] { return math::transform(*vector3D, *matrix4x4); });
}

TQ3Vector2D* Q3Vector2D_Negate(const TQ3Vector2D* vector2D, TQ3Vector2D* result)
{
    return computeInto(__func__, {{vector2D, "vector2D"}, {result, "result"}}, result,
                       [&] { return math::negate(*vector2D); });
}

TQ3Vector3D* Q3Vector3D_Negate(const TQ3Vector3D* vector3D, TQ3Vector3D* result)
{
    return computeInto(__func__, {{vector3D, "vector3D"}, {result, "result"}}, result,
                       [&] { return math::negate(*vector3D); });
}

TQ3Vector3D* Q3Vector3D_TransformQuaternion(const TQ3Vector3D* vector3D, const TQ3Quaternion* quaternion,
                                            TQ3Vector3D* result)
{
    return computeInto(__func__, {{vector3D, "vector3D"}, {quaternion, "quaternion"}, {result, "result"}}, result,
                       [&] { return math::rotate(*vector3D, *quaternion); });
}

} // extern "C"
