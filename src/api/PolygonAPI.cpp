// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/Polygon.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3Polygon_New(const TQ3PolygonData* polygonData)
{
    return newGeometry<Polygon>(__func__, polygonData);
}

TQ3Status Q3Polygon_Submit(const TQ3PolygonData* polygonData, TQ3ViewObject view)
{
    return submitGeometry<Polygon>(__func__, polygonData, view);
}

TQ3Status Q3Polygon_SetData(TQ3GeometryObject polygon, const TQ3PolygonData* polygonData)
{
    return setGeometryData<Polygon>(__func__, polygon, polygonData);
}

TQ3Status Q3Polygon_GetData(TQ3GeometryObject polygon, TQ3PolygonData* polygonData)
{
    return getGeometryData<Polygon>(__func__, polygon, polygonData);
}

TQ3Status Q3Polygon_EmptyData(TQ3PolygonData* polygonData)
{
    return emptyGeometryData<Polygon>(__func__, polygonData);
}

TQ3Status Q3Polygon_GetVertexPosition(TQ3GeometryObject polygon, unsigned long index, TQ3Point3D* point)
{
    return getVertexPosition<Polygon>(__func__, polygon, "polygon", point, "point", index);
}

TQ3Status Q3Polygon_SetVertexPosition(TQ3GeometryObject polygon, unsigned long index, const TQ3Point3D* point)
{
    return setVertexPosition<Polygon>(__func__, polygon, "polygon", point, "point", index);
}

TQ3Status Q3Polygon_GetVertexAttributeSet(TQ3GeometryObject polygon, unsigned long index,
                                           TQ3AttributeSet* attributeSet)
{
    return getVertexAttributeSet<Polygon>(__func__, polygon, "polygon", attributeSet, index);
}

TQ3Status Q3Polygon_SetVertexAttributeSet(TQ3GeometryObject polygon, unsigned long index,
                                           TQ3AttributeSet attributeSet)
{
    return setVertexAttributeSet<Polygon>(__func__, polygon, "polygon", attributeSet, index);
}

} // extern "C"
