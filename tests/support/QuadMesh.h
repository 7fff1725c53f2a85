// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// A quadrilateral as a TriMesh with a uv per corner, the surface most
// texture tests draw. The data is filled in and may be changed (an attribute
// set, more attribute arrays) before create().

#include "QD3D.h"
#include "QD3DGeometry.h"
#include "QD3DSet.h"

#include <algorithm>

namespace q3test {

struct QuadMesh {
    TQ3Point3D points[4];
    TQ3Param2D uvs[4];
    TQ3TriMeshTriangleData triangles[2];
    TQ3TriMeshAttributeData uvArray;
    TQ3TriMeshData data{};

    /// Corners 0 1 2 3 counterclockwise seen from the front, triangles
    /// (0 1 2) and (0 2 3); `clockwise` gives (0 2 1) and (0 3 2) instead.
    /// The uvs are vertex attributes of `uvType`; bBox is the corners' box.
    QuadMesh(const TQ3Point3D (&corners)[4], const TQ3Param2D (&cornerUvs)[4], bool clockwise = false,
             TQ3AttributeType uvType = kQ3AttributeTypeSurfaceUV)
        : uvArray{uvType, uvs, nullptr}
    {
        std::copy(corners, corners + 4, points);
        std::copy(cornerUvs, cornerUvs + 4, uvs);
        triangles[0] = clockwise ? TQ3TriMeshTriangleData{{0, 2, 1}} : TQ3TriMeshTriangleData{{0, 1, 2}};
        triangles[1] = clockwise ? TQ3TriMeshTriangleData{{0, 3, 2}} : TQ3TriMeshTriangleData{{0, 2, 3}};
        TQ3BoundingBox box{points[0], points[0], kQ3False};
        for (const TQ3Point3D& p : points) {
            box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y), std::min(box.min.z, p.z)};
            box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y), std::max(box.max.z, p.z)};
        }
        // No set, two triangles, no triangle or edge attributes, no edges,
        // four points with one attribute array.
        data = TQ3TriMeshData{nullptr, 2, triangles, 0, nullptr, 0, nullptr, 0, nullptr, 4, points, 1, &uvArray, box};
    }
    QuadMesh(const QuadMesh&) = delete;
    QuadMesh& operator=(const QuadMesh&) = delete;

    /// A new TriMesh of the data; NULL when Q3TriMesh_New refuses it.
    TQ3GeometryObject create() const { return Q3TriMesh_New(&data); }
};

} // namespace q3test
