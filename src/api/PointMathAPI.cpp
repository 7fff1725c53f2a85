// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DMath.h's calls on points: Q3Point2D_*, Q3Param2D_*, Q3Point3D_*,
// Q3RationalPoint3D_*, Q3RationalPoint4D_*, Q3PolarPoint_* and
// Q3SphericalPoint_*. (The point geometry, Q3Point_*, is PointAPI.cpp.)

#include "QD3DMath.h"
#include "api/MathEntry.h"
#include "base/MatrixMath.h"
#include "base/QuaternionMath.h"
#include "base/VectorMath.h"

#include <string>

using namespace q3;
using q3::api::computeInto;
using q3::api::computeValue;

namespace {

using q3::api::StridedArray;

// One element after another through the checked arrays, each read in full
// before its result is written, so the output may be the input array.
template <class In, class Out, class Map>
TQ3Status transformArray(const char* function, const In* in, const char* inName, const TQ3Matrix4x4* matrix,
                         Out* out, const char* outName, long numPoints, unsigned long inStructSize,
                         unsigned long outStructSize, Map map)
{
    return api::guardStatus(function, [&] {
        // A negative count is checked after the pointers; as an array
        // length it counts as "not 0".
        const unsigned long count = numPoints < 0 ? 1 : static_cast<unsigned long>(numPoints);
        api::requireArray(in, count, inName);
        requireNonNull(matrix, "matrix");
        api::requireArray(out, count, outName);
        if (numPoints < 0)
            fail(kQ3ErrorParameterOutOfRange, "numPoints " + std::to_string(numPoints) + " is negative");
        api::checkArray(StridedArray{in, inName, sizeof(In), inStructSize, "inStructSize"}, count, "numPoints");
        api::checkArray(StridedArray{out, outName, sizeof(Out), outStructSize, "outStructSize"}, count, "numPoints");
        for (unsigned long i = 0; i < count; ++i)
            api::storeAt(out, outStructSize, i, map(api::elementAt<In>(in, inStructSize, i), *matrix));
    });
}

// The pointers of an affine combination in argument order, then the sizes
// of its arrays: count points and count weights, one after another.
template <class T>
void checkCombination(const T* points, const char* pointsName, const float* weights, unsigned long count,
                      const char* countName, const void* result)
{
    api::requireArray(points, count, pointsName);
    api::requireArray(weights, count, "weights");
    requireNonNull(result, "result");
    api::checkArray(StridedArray{points, pointsName, sizeof(T), sizeof(T), "the point size"}, count, countName);
    api::checkArray(StridedArray{weights, "weights", sizeof(float), sizeof(float), "the weight size"}, count,
                    countName);
}

} // namespace

extern "C" {

TQ3Point2D* Q3Point2D_Set(TQ3Point2D* point2D, float x, float y)
{
    return computeInto(__func__, {{point2D, "point2D"}}, point2D, [&] { return TQ3Point2D{x, y}; });
}

TQ3Param2D* Q3Param2D_Set(TQ3Param2D* param2D, float u, float v)
{
    return computeInto(__func__, {{param2D, "param2D"}}, param2D, [&] { return TQ3Param2D{u, v}; });
}

TQ3Point3D* Q3Point3D_Set(TQ3Point3D* point3D, float x, float y, float z)
{
    return computeInto(__func__, {{point3D, "point3D"}}, point3D, [&] { return TQ3Point3D{x, y, z}; });
}

TQ3RationalPoint3D* Q3RationalPoint3D_Set(TQ3RationalPoint3D* point3D, float x, float y, float w)
{
    return computeInto(__func__, {{point3D, "point3D"}}, point3D, [&] { return TQ3RationalPoint3D{x, y, w}; });
}

TQ3RationalPoint4D* Q3RationalPoint4D_Set(TQ3RationalPoint4D* point4D, float x, float y, float z, float w)
{
    return computeInto(__func__, {{point4D, "point4D"}}, point4D,
                       [&] { return TQ3RationalPoint4D{x, y, z, w}; });
}

TQ3PolarPoint* Q3PolarPoint_Set(TQ3PolarPoint* polarPoint, float r, float theta)
{
    return computeInto(__func__, {{polarPoint, "polarPoint"}}, polarPoint, [&] { return TQ3PolarPoint{r, theta}; });
}

TQ3SphericalPoint* Q3SphericalPoint_Set(TQ3SphericalPoint* sphericalPoint, float rho, float theta, float phi)
{
    return computeInto(__func__, {{sphericalPoint, "sphericalPoint"}}, sphericalPoint,
                       [&] { return TQ3SphericalPoint{rho, theta, phi}; });
}

TQ3Point3D* Q3Point2D_To3D(const TQ3Point2D* point2D, TQ3Point3D* result)
{
    return computeInto(__func__, {{point2D, "point2D"}, {result, "result"}}, result,
                       [&] { return math::to3D(*point2D); });
}

TQ3Point2D* Q3RationalPoint3D_To2D(const TQ3RationalPoint3D* point3D, TQ3Point2D* result)
{
    return computeInto(__func__, {{point3D, "point3D"}, {result, "result"}}, result,
                       [&] { return math::to2D(*point3D); });
}

TQ3RationalPoint4D* Q3Point3D_To4D(const TQ3Point3D* point3D, TQ3RationalPoint4D* result)
{
    return computeInto(__func__, {{point3D, "point3D"}, {result, "result"}}, result,
                       [&] { return math::to4D(*point3D); });
}

TQ3Point3D* Q3RationalPoint4D_To3D(const TQ3RationalPoint4D* point4D, TQ3Point3D* result)
{
    return computeInto(__func__, {{point4D, "point4D"}, {result, "result"}}, result,
                       [&] { return math::to3D(*point4D); });
}

TQ3Vector2D* Q3Point2D_Subtract(const TQ3Point2D* p1, const TQ3Point2D* p2, TQ3Vector2D* result)
{
    return computeInto(__func__, {{p1, "p1"}, {p2, "p2"}, {result, "result"}}, result,
                       [&] { return math::subtract(*p1, *p2); });
}

TQ3Vector2D* Q3Param2D_Subtract(const TQ3Param2D* p1, const TQ3Param2D* p2, TQ3Vector2D* result)
{
    return computeInto(__func__, {{p1, "p1"}, {p2, "p2"}, {result, "result"}}, result,
                       [&] { return math::subtract(*p1, *p2); });
}

TQ3Vector3D* Q3Point3D_Subtract(const TQ3Point3D* p1, const TQ3Point3D* p2, TQ3Vector3D* result)
{
    return computeInto(__func__, {{p1, "p1"}, {p2, "p2"}, {result, "result"}}, result,
                       [&] { return math::subtract(*p1, *p2); });
}

float Q3Point2D_Distance(const TQ3Point2D* p1, const TQ3Point2D* p2)
{
    return computeValue(__func__, 0.0f, {{p1, "p1"}, {p2, "p2"}}, [&] { return math::distance(*p1, *p2); });
}

float Q3Point2D_DistanceSquared(const TQ3Point2D* p1, const TQ3Point2D* p2)
{
    return computeValue(__func__, 0.0f, {{p1, "p1"}, {p2, "p2"}}, [&] { return math::distanceSquared(*p1, *p2); });
}

float Q3Param2D_Distance(const TQ3Param2D* p1, const TQ3Param2D* p2)
{
    return computeValue(__func__, 0.0f, {{p1, "p1"}, {p2, "p2"}}, [&] { return math::distance(*p1, *p2); });
}

float Q3Param2D_DistanceSquared(const TQ3Param2D* p1, const TQ3Param2D* p2)
{
    return computeValue(__func__, 0.0f, {{p1, "p1"}, {p2, "p2"}}, [&] { return math::distanceSquared(*p1, *p2); });
}

float Q3RationalPoint3D_Distance(const TQ3RationalPoint3D* p1, const TQ3RationalPoint3D* p2)
{
    return computeValue(__func__, 0.0f, {{p1, "p1"}, {p2, "p2"}}, [&] { return math::distance(*p1, *p2); });
}

float Q3RationalPoint3D_DistanceSquared(const TQ3RationalPoint3D* p1, const TQ3RationalPoint3D* p2)
{
    return computeValue(__func__, 0.0f, {{p1, "p1"}, {p2, "p2"}}, [&] { return math::distanceSquared(*p1, *p2); });
}

float Q3Point3D_Distance(const TQ3Point3D* p1, const TQ3Point3D* p2)
{
    return computeValue(__func__, 0.0f, {{p1, "p1"}, {p2, "p2"}}, [&] { return math::distance(*p1, *p2); });
}

float Q3Point3D_DistanceSquared(const TQ3Point3D* p1, const TQ3Point3D* p2)
{
    return computeValue(__func__, 0.0f, {{p1, "p1"}, {p2, "p2"}}, [&] { return math::distanceSquared(*p1, *p2); });
}

float Q3RationalPoint4D_Distance(const TQ3RationalPoint4D* p1, const TQ3RationalPoint4D* p2)
{
    return computeValue(__func__, 0.0f, {{p1, "p1"}, {p2, "p2"}}, [&] { return math::distance(*p1, *p2); });
}

float Q3RationalPoint4D_DistanceSquared(const TQ3RationalPoint4D* p1, const TQ3RationalPoint4D* p2)
{
    return computeValue(__func__, 0.0f, {{p1, "p1"}, {p2, "p2"}}, [&] { return math::distanceSquared(*p1, *p2); });
}

TQ3Point2D* Q3Point2D_RRatio(const TQ3Point2D* p1, const TQ3Point2D* p2, float r1, float r2, TQ3Point2D* result)
{
    return computeInto(__func__, {{p1, "p1"}, {p2, "p2"}, {result, "result"}}, result,
                       [&] { return math::relativeRatio(*p1, *p2, r1, r2); });
}

TQ3Param2D* Q3Param2D_RRatio(const TQ3Param2D* p1, const TQ3Param2D* p2, float r1, float r2, TQ3Param2D* result)
{
    return computeInto(__func__, {{p1, "p1"}, {p2, "p2"}, {result, "result"}}, result,
                       [&] { return math::relativeRatio(*p1, *p2, r1, r2); });
}

TQ3Point3D* Q3Point3D_RRatio(const TQ3Point3D* p1, const TQ3Point3D* p2, float r1, float r2, TQ3Point3D* result)
{
    return computeInto(__func__, {{p1, "p1"}, {p2, "p2"}, {result, "result"}}, result,
                       [&] { return math::relativeRatio(*p1, *p2, r1, r2); });
}

TQ3RationalPoint4D* Q3RationalPoint4D_RRatio(const TQ3RationalPoint4D* p1, const TQ3RationalPoint4D* p2, float r1,
                                             float r2, TQ3RationalPoint4D* result)
{
    return computeInto(__func__, {{p1, "p1"}, {p2, "p2"}, {result, "result"}}, result,
                       [&] { return math::relativeRatio(*p1, *p2, r1, r2); });
}

TQ3Point2D* Q3Point2D_Vector2D_Add(const TQ3Point2D* point2D, const TQ3Vector2D* vector2D, TQ3Point2D* result)
{
    return computeInto(__func__, {{point2D, "point2D"}, {vector2D, "vector2D"}, {result, "result"}}, result,
                       [&] { return math::add(*point2D, *vector2D); });
}

TQ3Param2D* Q3Param2D_Vector2D_Add(const TQ3Param2D* param2D, const TQ3Vector2D* vector2D, TQ3Param2D* result)
{
    return computeInto(__func__, {{param2D, "param2D"}, {vector2D, "vector2D"}, {result, "result"}}, result,
                       [&] { return math::add(*param2D, *vector2D); });
}

TQ3Point3D* Q3Point3D_Vector3D_Add(const TQ3Point3D* point3D, const TQ3Vector3D* vector3D, TQ3Point3D* result)
{
    return computeInto(__func__, {{point3D, "point3D"}, {vector3D, "vector3D"}, {result, "result"}}, result,
                       [&] { return math::add(*point3D, *vector3D); });
}

TQ3Point2D* Q3Point2D_Vector2D_Subtract(const TQ3Point2D* point2D, const TQ3Vector2D* vector2D, TQ3Point2D* result)
{
    return computeInto(__func__, {{point2D, "point2D"}, {vector2D, "vector2D"}, {result, "result"}}, result,
                       [&] { return math::subtract(*point2D, *vector2D); });
}

TQ3Param2D* Q3Param2D_Vector2D_Subtract(const TQ3Param2D* param2D, const TQ3Vector2D* vector2D, TQ3Param2D* result)
{
    return computeInto(__func__, {{param2D, "param2D"}, {vector2D, "vector2D"}, {result, "result"}}, result,
                       [&] { return math::subtract(*param2D, *vector2D); });
}

TQ3Point3D* Q3Point3D_Vector3D_Subtract(const TQ3Point3D* point3D, const TQ3Vector3D* vector3D, TQ3Point3D* result)
{
    return computeInto(__func__, {{point3D, "point3D"}, {vector3D, "vector3D"}, {result, "result"}}, result,
                       [&] { return math::subtract(*point3D, *vector3D); });
}

TQ3Vector3D* Q3Point3D_CrossProductTri(const TQ3Point3D* point1, const TQ3Point3D* point2, const TQ3Point3D* point3,
                                       TQ3Vector3D* crossVector)
{
    return computeInto(__func__,
                       {{point1, "point1"}, {point2, "point2"}, {point3, "point3"}, {crossVector, "crossVector"}},
                       crossVector, [&] { return math::crossProductTri(*point1, *point2, *point3); });
}

TQ3Point2D* Q3Point2D_Transform(const TQ3Point2D* point2D, const TQ3Matrix3x3* matrix3x3, TQ3Point2D* result)
{
    return computeInto(__func__, {{point2D, "point2D"}, {matrix3x3, "matrix3x3"}, {result, "result"}}, result,
                       [&] { return math::transform(*point2D, *matrix3x3); });
}

TQ3Param2D* Q3Param2D_Transform(const TQ3Param2D* param2D, const TQ3Matrix3x3* matrix3x3, TQ3Param2D* result)
{
    return computeInto(__func__, {{param2D, "param2D"}, {matrix3x3, "matrix3x3"}, {result, "result"}}, result,
                       [&] { return math::transform(*param2D, *matrix3x3); });
}

TQ3Point3D* Q3Point3D_Transform(const TQ3Point3D* point3D, const TQ3Matrix4x4* matrix4x4, TQ3Point3D* result)
{
    return computeInto(__func__, {{point3D, "point3D"}, {matrix4x4, "matrix4x4"}, {result, "result"}}, result,
                       [&] { return math::transform(*point3D, *matrix4x4); });
}

TQ3RationalPoint4D* Q3RationalPoint4D_Transform(const TQ3RationalPoint4D* point4D, const TQ3Matrix4x4* matrix4x4,
                                                TQ3RationalPoint4D* result)
{
    return computeInto(__func__, {{point4D, "point4D"}, {matrix4x4, "matrix4x4"}, {result, "result"}}, result,
                       [&] { return math::transform(*point4D, *matrix4x4); });
}

TQ3Status Q3Point3D_To3DTransformArray(const TQ3Point3D* inPoint3D, const TQ3Matrix4x4* matrix,
                                       TQ3Point3D* outPoint3D, long numPoints, unsigned long inStructSize,
                                       unsigned long outStructSize)
{
    return transformArray(__func__, inPoint3D, "inPoint3D", matrix, outPoint3D, "outPoint3D", numPoints,
                          inStructSize, outStructSize,
                          [](const TQ3Point3D& p, const TQ3Matrix4x4& m) { return math::transform(p, m); });
}

TQ3Status Q3Point3D_To4DTransformArray(const TQ3Point3D* inPoint3D, const TQ3Matrix4x4* matrix,
                                       TQ3RationalPoint4D* outPoint4D, long numPoints, unsigned long inStructSize,
                                       unsigned long outStructSize)
{
    return transformArray(__func__, inPoint3D, "inPoint3D", matrix, outPoint4D, "outPoint4D", numPoints,
                          inStructSize, outStructSize,
                          [](const TQ3Point3D& p, const TQ3Matrix4x4& m) { return math::transformToRational(p, m); });
}

TQ3Status Q3RationalPoint4D_To4DTransformArray(const TQ3RationalPoint4D* inPoint4D, const TQ3Matrix4x4* matrix,
                                               TQ3RationalPoint4D* outPoint4D, long numPoints,
                                               unsigned long inStructSize, unsigned long outStructSize)
{
    return transformArray(__func__, inPoint4D, "inPoint4D", matrix, outPoint4D, "outPoint4D", numPoints,
                          inStructSize, outStructSize,
                          [](const TQ3RationalPoint4D& p, const TQ3Matrix4x4& m) { return math::transform(p, m); });
}

TQ3PolarPoint* Q3Point2D_ToPolar(const TQ3Point2D* point2D, TQ3PolarPoint* result)
{
    return computeInto(__func__, {{point2D, "point2D"}, {result, "result"}}, result,
                       [&] { return math::toPolar(*point2D); });
}

TQ3Point2D* Q3PolarPoint_ToPoint2D(const TQ3PolarPoint* polarPoint, TQ3Point2D* result)
{
    return computeInto(__func__, {{polarPoint, "polarPoint"}, {result, "result"}}, result,
                       [&] { return math::toCartesian(*polarPoint); });
}

TQ3SphericalPoint* Q3Point3D_ToSpherical(const TQ3Point3D* point3D, TQ3SphericalPoint* result)
{
    return computeInto(__func__, {{point3D, "point3D"}, {result, "result"}}, result,
                       [&] { return math::toSpherical(*point3D); });
}

TQ3Point3D* Q3SphericalPoint_ToPoint3D(const TQ3SphericalPoint* sphericalPoint, TQ3Point3D* result)
{
    return computeInto(__func__, {{sphericalPoint, "sphericalPoint"}, {result, "result"}}, result,
                       [&] { return math::toCartesian(*sphericalPoint); });
}

TQ3Point2D* Q3Point2D_AffineComb(const TQ3Point2D* points2D, const float* weights, unsigned long nPoints,
                                 TQ3Point2D* result)
{
    return computeInto(__func__, {}, result, [&] {
        checkCombination(points2D, "points2D", weights, nPoints, "nPoints", result);
        return math::affineCombination(points2D, weights, nPoints);
    });
}

TQ3Param2D* Q3Param2D_AffineComb(const TQ3Param2D* params2D, const float* weights, unsigned long nPoints,
                                 TQ3Param2D* result)
{
    return computeInto(__func__, {}, result, [&] {
        checkCombination(params2D, "params2D", weights, nPoints, "nPoints", result);
        return math::affineCombination(params2D, weights, nPoints);
    });
}

TQ3RationalPoint3D* Q3RationalPoint3D_AffineComb(const TQ3RationalPoint3D* points3D, const float* weights,
                                                 unsigned long numPoints, TQ3RationalPoint3D* result)
{
    return computeInto(__func__, {}, result, [&] {
        checkCombination(points3D, "points3D", weights, numPoints, "numPoints", result);
        return math::affineCombination(points3D, weights, numPoints);
    });
}

TQ3Point3D* Q3Point3D_AffineComb(const TQ3Point3D* points3D, const float* weights, unsigned long numPoints,
                                 TQ3Point3D* result)
{
    return computeInto(__func__, {}, result, [&] {
        checkCombination(points3D, "points3D", weights, numPoints, "numPoints", result);
        return math::affineCombination(points3D, weights, numPoints);
    });
}

TQ3RationalPoint4D* Q3RationalPoint4D_AffineComb(const TQ3RationalPoint4D* points4D, const float* weights,
                                                 unsigned long numPoints, TQ3RationalPoint4D* result)
{
    return computeInto(__func__, {}, result, [&] {
        checkCombination(points4D, "points4D", weights, numPoints, "numPoints", result);
        return math::affineCombination(points4D, weights, numPoints);
    });
}

TQ3Point3D* Q3Point3D_TransformQuaternion(const TQ3Point3D* point3D, const TQ3Quaternion* quaternion,
                                          TQ3Point3D* result)
{
    return computeInto(__func__, {{point3D, "point3D"}, {quaternion, "quaternion"}, {result, "result"}}, result,
                       [&] { return math::rotate(*point3D, *quaternion); });
}

} // extern "C"
