// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Helpers shared by the Triangle, Polygon and TriMesh API tests: the
// non-finite floats every float input is tried with, the bad indices every
// index-taking call is tried with, coloured attribute sets, an exact
// reference count read through the public API, handles that are not live
// objects, and a geometry's decomposition.

#include "QD3D.h"
#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DView.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace q3test {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
inline const float kNonFinite[] = {kNaN, kInf, -kInf};

/// The indices past the end of an array of `count`: one past the end,
/// UINT32_MAX and the largest unsigned long (which a narrowing to int would
/// turn into -1 or 0).
inline std::vector<unsigned long> indicesPastTheEnd(unsigned long count)
{
    return {count, std::numeric_limits<std::uint32_t>::max(), std::numeric_limits<unsigned long>::max()};
}

inline TQ3AttributeSet colorSet(float r, float g, float b)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB color{r, g, b};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color);
    return set;
}

/// The diffuse colour of a set, or (-1, -1, -1) when it has none.
inline TQ3ColorRGB colorOf(TQ3AttributeSet set)
{
    TQ3ColorRGB color{-1, -1, -1};
    if (set != nullptr && Q3AttributeSet_Contains(set, kQ3AttributeTypeDiffuseColor))
        Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, &color);
    return color;
}

/// The exact number of references a live shared object has, read with the
/// public calls only: the test gives references back one at a time while
/// Q3Shared_IsReferenced says another holder remains, then takes as many
/// again. The count never reaches zero, so nothing is destroyed.
inline unsigned long referenceCount(TQ3SharedObject object)
{
    unsigned long count = 1;
    while (Q3Shared_IsReferenced(object) == kQ3True) {
        Q3Object_Dispose(object);
        ++count;
    }
    for (unsigned long i = 1; i < count; ++i)
        Q3Shared_GetReference(object);
    return count;
}

/// The handle of an attribute set that has just been disposed. Use it at
/// once: a Q3 object created later may be given the same address (and then
/// be live again).
inline TQ3Object deadObject()
{
    TQ3Object object = Q3AttributeSet_New();
    Q3Object_Dispose(object);
    return object;
}

/// A pointer that never came from Q3.
inline TQ3Object strayHandle()
{
    static int notAnObject = 0;
    return reinterpret_cast<TQ3Object>(&notAnObject);
}

/// What Q3Geometry_GetDecomposed returns for `geometry` inside an exact
/// bounding loop of `view` (the call wants a started view); the caller
/// disposes it.
inline TQ3Object decomposedIn(TQ3ViewObject view, TQ3GeometryObject geometry)
{
    EXPECT_EQ(Q3View_StartBoundingBox(view, kQ3ComputeBoundsExact), kQ3Success);
    TQ3Object result = Q3Geometry_GetDecomposed(geometry, view);
    TQ3BoundingBox ignored;
    EXPECT_EQ(Q3View_EndBoundingBox(view, &ignored), kQ3ViewStatusDone);
    return result;
}

/// The triangles of `geometry`'s decomposition (a TriMesh), each as its
/// three corner points in order; none, and a failure, when there is no mesh.
inline std::vector<std::array<TQ3Point3D, 3>> decomposedTriangles(TQ3ViewObject view, TQ3GeometryObject geometry)
{
    std::vector<std::array<TQ3Point3D, 3>> triangles;
    TQ3Object mesh = decomposedIn(view, geometry);
    EXPECT_NE(mesh, nullptr);
    TQ3TriMeshData data{};
    if (mesh == nullptr || Q3TriMesh_GetData(mesh, &data) != kQ3Success) {
        ADD_FAILURE() << "no TriMesh decomposition";
        if (mesh != nullptr)
            Q3Object_Dispose(mesh);
        return triangles;
    }
    for (unsigned long t = 0; t < data.numTriangles; ++t) {
        const unsigned long* corner = data.triangles[t].pointIndices;
        triangles.push_back({data.points[corner[0]], data.points[corner[1]], data.points[corner[2]]});
    }
    Q3TriMesh_EmptyData(&data);
    Q3Object_Dispose(mesh);
    return triangles;
}

inline bool samePoint(const TQ3Point3D& a, const TQ3Point3D& b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

} // namespace q3test
