// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/TriMesh.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3TriMesh_New(const TQ3TriMeshData* triMeshData)
{
    return newGeometry<TriMesh>(__func__, triMeshData);
}

TQ3Status Q3TriMesh_Submit(const TQ3TriMeshData* triMeshData, TQ3ViewObject view)
{
    return submitGeometry<TriMesh>(__func__, triMeshData, view);
}

TQ3Status Q3TriMesh_SetData(TQ3GeometryObject triMesh, const TQ3TriMeshData* triMeshData)
{
    return setGeometryData<TriMesh>(__func__, triMesh, triMeshData);
}

TQ3Status Q3TriMesh_GetData(TQ3GeometryObject triMesh, TQ3TriMeshData* triMeshData)
{
    return getGeometryData<TriMesh>(__func__, triMesh, triMeshData);
}

TQ3Status Q3TriMesh_EmptyData(TQ3TriMeshData* triMeshData)
{
    return emptyGeometryData<TriMesh>(__func__, triMeshData);
}

} // extern "C"
