// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DMath.h's Q3BoundingBox_* and Q3BoundingSphere_* calls.

#include "QD3DMath.h"
#include "api/MathEntry.h"
#include "base/BoundsMath.h"
#include "base/MathValues.h"

#include <cstring>

using namespace q3;
using q3::api::computeInto;

namespace {

// The i-th point of a checked array, as the point it stands for.
glm::dvec3 pointAt(const TQ3Point3D* points, unsigned long stride, std::size_t i)
{
    return math::toDouble(api::elementAt<TQ3Point3D>(points, stride, i));
}

glm::dvec3 pointAt(const TQ3RationalPoint4D* points, unsigned long stride, std::size_t i)
{
    return math::dehomogenize(math::toDouble(api::elementAt<TQ3RationalPoint4D>(points, stride, i)));
}

// Calls make(count, point(i)) on a strided array after its checks.
template <class Bound, class T, class Make>
Bound* fromPoints(const char* function, Bound* bound, const char* boundName, const T* points, const char* pointsName,
                  unsigned long numPoints, unsigned long structSize, Make make)
{
    return computeInto(function, {}, bound, [&] {
        requireNonNull(bound, boundName);
        api::checkArray(api::StridedArray{points, pointsName, sizeof(T), structSize, "structSize"}, numPoints,
                        "numPoints");
        return make(numPoints, [&](std::size_t i) { return pointAt(points, structSize, i); });
    });
}

// A copy of every byte: an isEmpty outside the enumeration stays as it was.
template <class T>
T bytesOf(const T& value)
{
    T copy;
    std::memcpy(&copy, &value, sizeof copy);
    return copy;
}

} // namespace

extern "C" {

TQ3BoundingBox* Q3BoundingBox_Copy(const TQ3BoundingBox* src, TQ3BoundingBox* dest)
{
    return computeInto(__func__, {{src, "src"}, {dest, "dest"}}, dest, [&] { return bytesOf(*src); });
}

TQ3BoundingBox* Q3BoundingBox_Union(const TQ3BoundingBox* v1, const TQ3BoundingBox* v2, TQ3BoundingBox* result)
{
    return computeInto(__func__, {{v1, "v1"}, {v2, "v2"}, {result, "result"}}, result,
                       [&] { return math::unite(*v1, *v2); });
}

TQ3BoundingBox* Q3BoundingBox_Set(TQ3BoundingBox* bBox, const TQ3Point3D* min, const TQ3Point3D* max,
                                  TQ3Boolean isEmpty)
{
    return computeInto(__func__, {{bBox, "bBox"}, {min, "min"}, {max, "max"}}, bBox,
                       [&] { return math::makeBox(*min, *max, isEmpty); });
}

TQ3BoundingBox* Q3BoundingBox_UnionPoint3D(const TQ3BoundingBox* bBox, const TQ3Point3D* point3D,
                                           TQ3BoundingBox* result)
{
    return computeInto(__func__, {{bBox, "bBox"}, {point3D, "point3D"}, {result, "result"}}, result,
                       [&] { return math::unite(*bBox, math::toDouble(*point3D)); });
}

TQ3BoundingBox* Q3BoundingBox_UnionRationalPoint4D(const TQ3BoundingBox* bBox, const TQ3RationalPoint4D* point4D,
                                                   TQ3BoundingBox* result)
{
    return computeInto(__func__, {{bBox, "bBox"}, {point4D, "point4D"}, {result, "result"}}, result,
                       [&] { return math::unite(*bBox, math::dehomogenize(math::toDouble(*point4D))); });
}

TQ3BoundingBox* Q3BoundingBox_SetFromPoints3D(TQ3BoundingBox* bBox, const TQ3Point3D* points3D,
                                              unsigned long numPoints, unsigned long structSize)
{
    return fromPoints(__func__, bBox, "bBox", points3D, "points3D", numPoints, structSize,
                      [](std::size_t n, const auto& point) { return math::boxOf(n, point); });
}

TQ3BoundingBox* Q3BoundingBox_SetFromRationalPoints4D(TQ3BoundingBox* bBox, const TQ3RationalPoint4D* points4D,
                                                      unsigned long numPoints, unsigned long structSize)
{
    return fromPoints(__func__, bBox, "bBox", points4D, "points4D", numPoints, structSize,
                      [](std::size_t n, const auto& point) { return math::boxOf(n, point); });
}

TQ3BoundingSphere* Q3BoundingSphere_Copy(const TQ3BoundingSphere* src, TQ3BoundingSphere* dest)
{
    return computeInto(__func__, {{src, "src"}, {dest, "dest"}}, dest, [&] { return bytesOf(*src); });
}

TQ3BoundingSphere* Q3BoundingSphere_Union(const TQ3BoundingSphere* s1, const TQ3BoundingSphere* s2,
                                          TQ3BoundingSphere* result)
{
    return computeInto(__func__, {{s1, "s1"}, {s2, "s2"}, {result, "result"}}, result,
                       [&] { return math::unite(*s1, *s2); });
}

TQ3BoundingSphere* Q3BoundingSphere_Set(TQ3BoundingSphere* bSphere, const TQ3Point3D* origin, float radius,
                                        TQ3Boolean isEmpty)
{
    return computeInto(__func__, {{bSphere, "bSphere"}, {origin, "origin"}}, bSphere,
                       [&] { return math::makeSphere(*origin, radius, isEmpty); });
}

TQ3BoundingSphere* Q3BoundingSphere_UnionPoint3D(const TQ3BoundingSphere* bSphere, const TQ3Point3D* point3D,
                                                 TQ3BoundingSphere* result)
{
    return computeInto(__func__, {{bSphere, "bSphere"}, {point3D, "point3D"}, {result, "result"}}, result,
                       [&] { return math::unite(*bSphere, math::toDouble(*point3D)); });
}

TQ3BoundingSphere* Q3BoundingSphere_UnionRationalPoint4D(const TQ3BoundingSphere* bSphere,
                                                         const TQ3RationalPoint4D* point4D, TQ3BoundingSphere* result)
{
    return computeInto(__func__, {{bSphere, "bSphere"}, {point4D, "point4D"}, {result, "result"}}, result,
                       [&] { return math::unite(*bSphere, math::dehomogenize(math::toDouble(*point4D))); });
}

TQ3BoundingSphere* Q3BoundingSphere_SetFromPoints3D(TQ3BoundingSphere* bSphere, const TQ3Point3D* points3D,
                                                    unsigned long numPoints, unsigned long structSize)
{
    return fromPoints(__func__, bSphere, "bSphere", points3D, "points3D", numPoints, structSize,
                      [](std::size_t n, const auto& point) { return math::sphereOf(n, point); });
}

TQ3BoundingSphere* Q3BoundingSphere_SetFromRationalPoints4D(TQ3BoundingSphere* bSphere,
                                                            const TQ3RationalPoint4D* points4D,
                                                            unsigned long numPoints, unsigned long structSize)
{
    return fromPoints(__func__, bSphere, "bSphere", points4D, "points4D", numPoints, structSize,
                      [](std::size_t n, const auto& point) { return math::sphereOf(n, point); });
}

} // extern "C"
