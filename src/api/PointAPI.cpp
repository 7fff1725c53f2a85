// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/Point.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3Point_New(const TQ3PointData* pointData)
{
    return newGeometry<Point>(__func__, pointData);
}

TQ3Status Q3Point_Submit(const TQ3PointData* pointData, TQ3ViewObject view)
{
    return submitGeometry<Point>(__func__, pointData, view);
}

TQ3Status Q3Point_GetData(TQ3GeometryObject point, TQ3PointData* pointData)
{
    return getGeometryData<Point>(__func__, point, pointData);
}

TQ3Status Q3Point_SetData(TQ3GeometryObject point, const TQ3PointData* pointData)
{
    return setGeometryData<Point>(__func__, point, pointData);
}

TQ3Status Q3Point_EmptyData(TQ3PointData* pointData)
{
    return emptyGeometryData<Point>(__func__, pointData);
}

TQ3Status Q3Point_SetPosition(TQ3GeometryObject point, const TQ3Point3D* position)
{
    return setValue<Point>(__func__, point, "point", position, "position", &Point::setPosition);
}

TQ3Status Q3Point_GetPosition(TQ3GeometryObject point, TQ3Point3D* position)
{
    return getValue<Point>(__func__, point, "point", position, "position", [](const Point& p) { return p.point(); });
}

} // extern "C"
