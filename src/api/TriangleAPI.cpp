// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/Triangle.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3Triangle_New(const TQ3TriangleData* triangleData)
{
    return newGeometry<Triangle>(__func__, triangleData);
}

TQ3Status Q3Triangle_Submit(const TQ3TriangleData* triangleData, TQ3ViewObject view)
{
    return submitGeometry<Triangle>(__func__, triangleData, view);
}

TQ3Status Q3Triangle_SetData(TQ3GeometryObject triangle, const TQ3TriangleData* triangleData)
{
    return setGeometryData<Triangle>(__func__, triangle, triangleData);
}

TQ3Status Q3Triangle_GetData(TQ3GeometryObject triangle, TQ3TriangleData* triangleData)
{
    return getGeometryData<Triangle>(__func__, triangle, triangleData);
}

TQ3Status Q3Triangle_EmptyData(TQ3TriangleData* triangleData)
{
    return emptyGeometryData<Triangle>(__func__, triangleData);
}

TQ3Status Q3Triangle_GetVertexPosition(TQ3GeometryObject triangle, unsigned long index, TQ3Point3D* point)
{
    return getVertexPosition<Triangle>(__func__, triangle, "triangle", point, "point", index);
}

TQ3Status Q3Triangle_SetVertexPosition(TQ3GeometryObject triangle, unsigned long index, const TQ3Point3D* point)
{
    return setVertexPosition<Triangle>(__func__, triangle, "triangle", point, "point", index);
}

TQ3Status Q3Triangle_GetVertexAttributeSet(TQ3GeometryObject triangle, unsigned long index,
                                           TQ3AttributeSet* attributeSet)
{
    return getVertexAttributeSet<Triangle>(__func__, triangle, "triangle", attributeSet, index);
}

TQ3Status Q3Triangle_SetVertexAttributeSet(TQ3GeometryObject triangle, unsigned long index,
                                           TQ3AttributeSet attributeSet)
{
    return setVertexAttributeSet<Triangle>(__func__, triangle, "triangle", attributeSet, index);
}

} // extern "C"
