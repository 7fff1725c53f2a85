// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Ellipse.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3Ellipse_New(const TQ3EllipseData* ellipseData)
{
    return newGeometry<Ellipse>(__func__, ellipseData);
}

TQ3Status Q3Ellipse_Submit(const TQ3EllipseData* ellipseData, TQ3ViewObject view)
{
    return submitGeometry<Ellipse>(__func__, ellipseData, view);
}

TQ3Status Q3Ellipse_SetData(TQ3GeometryObject ellipse, const TQ3EllipseData* ellipseData)
{
    return setGeometryData<Ellipse>(__func__, ellipse, ellipseData);
}

TQ3Status Q3Ellipse_GetData(TQ3GeometryObject ellipse, TQ3EllipseData* ellipseData)
{
    return getGeometryData<Ellipse>(__func__, ellipse, ellipseData);
}

TQ3Status Q3Ellipse_EmptyData(TQ3EllipseData* ellipseData)
{
    return emptyGeometryData<Ellipse>(__func__, ellipseData);
}

TQ3Status Q3Ellipse_SetOrigin(TQ3GeometryObject ellipse, const TQ3Point3D* origin)
{
    return setField<Ellipse>(__func__, ellipse, &TQ3EllipseData::origin, origin, "origin");
}

TQ3Status Q3Ellipse_GetOrigin(TQ3GeometryObject ellipse, TQ3Point3D* origin)
{
    return getField<Ellipse>(__func__, ellipse, &TQ3EllipseData::origin, origin, "origin");
}

TQ3Status Q3Ellipse_SetMajorRadius(TQ3GeometryObject ellipse, const TQ3Vector3D* majorRadius)
{
    return setField<Ellipse>(__func__, ellipse, &TQ3EllipseData::majorRadius, majorRadius, "majorRadius");
}

TQ3Status Q3Ellipse_GetMajorRadius(TQ3GeometryObject ellipse, TQ3Vector3D* majorRadius)
{
    return getField<Ellipse>(__func__, ellipse, &TQ3EllipseData::majorRadius, majorRadius, "majorRadius");
}

TQ3Status Q3Ellipse_SetMinorRadius(TQ3GeometryObject ellipse, const TQ3Vector3D* minorRadius)
{
    return setField<Ellipse>(__func__, ellipse, &TQ3EllipseData::minorRadius, minorRadius, "minorRadius");
}

TQ3Status Q3Ellipse_GetMinorRadius(TQ3GeometryObject ellipse, TQ3Vector3D* minorRadius)
{
    return getField<Ellipse>(__func__, ellipse, &TQ3EllipseData::minorRadius, minorRadius, "minorRadius");
}

} // extern "C"
