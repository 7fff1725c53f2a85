// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/Point.h"

using namespace q3;
using namespace q3::api;

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Point)

TQ3Status Q3Point_SetPosition(TQ3GeometryObject point, const TQ3Point3D* position)
{
    return setValue<Point>(__func__, point, "point", position, "position", &Point::setPosition);
}

TQ3Status Q3Point_GetPosition(TQ3GeometryObject point, TQ3Point3D* position)
{
    return getValue<Point>(__func__, point, "point", position, "position", [](const Point& p) { return p.point(); });
}

} // extern "C"
