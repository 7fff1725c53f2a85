// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/Entry.h"
#include "geometry/Point.h"
#include "view/View.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3GeometryObject Q3Point_New(const TQ3PointData* pointData)
{
    return guard(__func__, TQ3GeometryObject{nullptr}, [&]() -> TQ3GeometryObject {
        validatePointData(pointData);
        return makeShared<Point>(*pointData).detach();
    });
}

TQ3Status Q3Point_Submit(const TQ3PointData* pointData, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        requireNonNull(pointData, "pointData");
        ShapeVisitor& target = lookup<View>(view, "view").submitTarget();
        validatePointData(pointData);
        target.visitPoint(*makeShared<Point>(*pointData));
    });
}

TQ3Status Q3Point_GetData(TQ3GeometryObject point, TQ3PointData* pointData)
{
    return guardStatus(__func__, [&] {
        const Point& source = lookup<Point>(point, "point");
        requireNonNull(pointData, "pointData");
        source.getData(*pointData);
    });
}

TQ3Status Q3Point_SetData(TQ3GeometryObject point, const TQ3PointData* pointData)
{
    return guardStatus(__func__, [&] {
        Point& target = lookup<Point>(point, "point");
        requireNonNull(pointData, "pointData");
        target.setData(*pointData);
    });
}

TQ3Status Q3Point_EmptyData(TQ3PointData* pointData)
{
    return guardStatus(__func__, [&] {
        requireNonNull(pointData, "pointData");
        Point::emptyData(*pointData);
    });
}

TQ3Status Q3Point_SetPosition(TQ3GeometryObject point, const TQ3Point3D* position)
{
    return guardStatus(__func__, [&] {
        Point& target = lookup<Point>(point, "point");
        requireNonNull(position, "position");
        target.setPosition(*position);
    });
}

TQ3Status Q3Point_GetPosition(TQ3GeometryObject point, TQ3Point3D* position)
{
    return guardStatus(__func__, [&] {
        const Point& source = lookup<Point>(point, "point");
        requireNonNull(position, "position");
        *position = source.point();
    });
}

} // extern "C"
