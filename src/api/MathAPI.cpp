// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DMath.h"
#include "api/Entry.h"
#include "view/MatrixMath.h"

using namespace q3;
using q3::api::guard;

// Each result is computed in full before it is stored, so a result may alias
// an input and a failed call leaves it unchanged.

extern "C" {

TQ3Point3D* Q3Point3D_Set(TQ3Point3D* point3D, float x, float y, float z)
{
    return guard(__func__, static_cast<TQ3Point3D*>(nullptr), [&] {
        requireNonNull(point3D, "point3D");
        *point3D = TQ3Point3D{x, y, z};
        return point3D;
    });
}

TQ3Vector3D* Q3Vector3D_Set(TQ3Vector3D* vector3D, float x, float y, float z)
{
    return guard(__func__, static_cast<TQ3Vector3D*>(nullptr), [&] {
        requireNonNull(vector3D, "vector3D");
        *vector3D = TQ3Vector3D{x, y, z};
        return vector3D;
    });
}

TQ3RationalPoint4D* Q3RationalPoint4D_Set(TQ3RationalPoint4D* point4D, float x, float y, float z, float w)
{
    return guard(__func__, static_cast<TQ3RationalPoint4D*>(nullptr), [&] {
        requireNonNull(point4D, "point4D");
        *point4D = TQ3RationalPoint4D{x, y, z, w};
        return point4D;
    });
}

float Q3Point3D_Distance(const TQ3Point3D* p1, const TQ3Point3D* p2)
{
    return guard(__func__, 0.0f, [&] {
        requireNonNull(p1, "p1");
        requireNonNull(p2, "p2");
        return math::distance(*p1, *p2);
    });
}

float Q3Vector3D_Length(const TQ3Vector3D* vector3D)
{
    return guard(__func__, 0.0f, [&] {
        requireNonNull(vector3D, "vector3D");
        return math::length(*vector3D);
    });
}

TQ3Vector3D* Q3Vector3D_Normalize(const TQ3Vector3D* vector3D, TQ3Vector3D* result)
{
    return guard(__func__, static_cast<TQ3Vector3D*>(nullptr), [&] {
        requireNonNull(vector3D, "vector3D");
        requireNonNull(result, "result");
        *result = math::normalize(*vector3D);
        return result;
    });
}

TQ3Vector3D* Q3Vector3D_Cross(const TQ3Vector3D* v1, const TQ3Vector3D* v2, TQ3Vector3D* result)
{
    return guard(__func__, static_cast<TQ3Vector3D*>(nullptr), [&] {
        requireNonNull(v1, "v1");
        requireNonNull(v2, "v2");
        requireNonNull(result, "result");
        *result = math::cross(*v1, *v2);
        return result;
    });
}

float Q3Vector3D_Dot(const TQ3Vector3D* v1, const TQ3Vector3D* v2)
{
    return guard(__func__, 0.0f, [&] {
        requireNonNull(v1, "v1");
        requireNonNull(v2, "v2");
        return math::dot(*v1, *v2);
    });
}

TQ3Point3D* Q3Point3D_Transform(const TQ3Point3D* point3D, const TQ3Matrix4x4* matrix4x4,
                                TQ3Point3D* result)
{
    return guard(__func__, static_cast<TQ3Point3D*>(nullptr), [&] {
        requireNonNull(point3D, "point3D");
        requireNonNull(matrix4x4, "matrix4x4");
        requireNonNull(result, "result");
        *result = math::transform(*point3D, *matrix4x4);
        return result;
    });
}

TQ3RationalPoint4D* Q3RationalPoint4D_Transform(const TQ3RationalPoint4D* point4D,
                                                const TQ3Matrix4x4* matrix4x4, TQ3RationalPoint4D* result)
{
    return guard(__func__, static_cast<TQ3RationalPoint4D*>(nullptr), [&] {
        requireNonNull(point4D, "point4D");
        requireNonNull(matrix4x4, "matrix4x4");
        requireNonNull(result, "result");
        *result = math::transform(*point4D, *matrix4x4);
        return result;
    });
}

TQ3Matrix4x4* Q3Matrix4x4_SetIdentity(TQ3Matrix4x4* matrix4x4)
{
    return guard(__func__, static_cast<TQ3Matrix4x4*>(nullptr), [&] {
        requireNonNull(matrix4x4, "matrix4x4");
        *matrix4x4 = math::identity();
        return matrix4x4;
    });
}

TQ3Matrix4x4* Q3Matrix4x4_SetTranslate(TQ3Matrix4x4* matrix4x4, float xTrans, float yTrans, float zTrans)
{
    return guard(__func__, static_cast<TQ3Matrix4x4*>(nullptr), [&] {
        requireNonNull(matrix4x4, "matrix4x4");
        *matrix4x4 = math::translation(xTrans, yTrans, zTrans);
        return matrix4x4;
    });
}

TQ3Matrix4x4* Q3Matrix4x4_SetScale(TQ3Matrix4x4* matrix4x4, float xScale, float yScale, float zScale)
{
    return guard(__func__, static_cast<TQ3Matrix4x4*>(nullptr), [&] {
        requireNonNull(matrix4x4, "matrix4x4");
        *matrix4x4 = math::scaling(xScale, yScale, zScale);
        return matrix4x4;
    });
}

TQ3Matrix4x4* Q3Matrix4x4_SetRotate_X(TQ3Matrix4x4* matrix4x4, float angle)
{
    return guard(__func__, static_cast<TQ3Matrix4x4*>(nullptr), [&] {
        requireNonNull(matrix4x4, "matrix4x4");
        *matrix4x4 = math::rotationX(angle);
        return matrix4x4;
    });
}

TQ3Matrix4x4* Q3Matrix4x4_SetRotate_Y(TQ3Matrix4x4* matrix4x4, float angle)
{
    return guard(__func__, static_cast<TQ3Matrix4x4*>(nullptr), [&] {
        requireNonNull(matrix4x4, "matrix4x4");
        *matrix4x4 = math::rotationY(angle);
        return matrix4x4;
    });
}

TQ3Matrix4x4* Q3Matrix4x4_SetRotate_Z(TQ3Matrix4x4* matrix4x4, float angle)
{
    return guard(__func__, static_cast<TQ3Matrix4x4*>(nullptr), [&] {
        requireNonNull(matrix4x4, "matrix4x4");
        *matrix4x4 = math::rotationZ(angle);
        return matrix4x4;
    });
}

TQ3Matrix4x4* Q3Matrix4x4_SetRotateAboutAxis(TQ3Matrix4x4* matrix4x4, const TQ3Point3D* origin,
                                             const TQ3Vector3D* orientation, float angle)
{
    return guard(__func__, static_cast<TQ3Matrix4x4*>(nullptr), [&] {
        requireNonNull(matrix4x4, "matrix4x4");
        requireNonNull(origin, "origin");
        requireNonNull(orientation, "orientation");
        *matrix4x4 = math::rotationAboutAxis(*origin, *orientation, angle);
        return matrix4x4;
    });
}

TQ3Matrix4x4* Q3Matrix4x4_Multiply(const TQ3Matrix4x4* matrixA, const TQ3Matrix4x4* matrixB,
                                   TQ3Matrix4x4* result)
{
    return guard(__func__, static_cast<TQ3Matrix4x4*>(nullptr), [&] {
        requireNonNull(matrixA, "matrixA");
        requireNonNull(matrixB, "matrixB");
        requireNonNull(result, "result");
        *result = math::multiply(*matrixA, *matrixB);
        return result;
    });
}

TQ3Matrix4x4* Q3Matrix4x4_Invert(const TQ3Matrix4x4* matrix4x4, TQ3Matrix4x4* result)
{
    return guard(__func__, static_cast<TQ3Matrix4x4*>(nullptr), [&] {
        requireNonNull(matrix4x4, "matrix4x4");
        requireNonNull(result, "result");
        *result = math::invert(*matrix4x4);
        return result;
    });
}

TQ3Matrix4x4* Q3Matrix4x4_Transpose(const TQ3Matrix4x4* matrix4x4, TQ3Matrix4x4* result)
{
    return guard(__func__, static_cast<TQ3Matrix4x4*>(nullptr), [&] {
        requireNonNull(matrix4x4, "matrix4x4");
        requireNonNull(result, "result");
        *result = math::transpose(*matrix4x4);
        return result;
    });
}

TQ3Matrix4x4* Q3Matrix4x4_Copy(const TQ3Matrix4x4* matrix4x4, TQ3Matrix4x4* result)
{
    return guard(__func__, static_cast<TQ3Matrix4x4*>(nullptr), [&] {
        requireNonNull(matrix4x4, "matrix4x4");
        requireNonNull(result, "result");
        *result = *matrix4x4;
        return result;
    });
}

} // extern "C"
