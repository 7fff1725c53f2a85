// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Ellipsoid.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3Ellipsoid_New(const TQ3EllipsoidData* ellipsoidData)
{
    return newGeometry<Ellipsoid>(__func__, ellipsoidData);
}

TQ3Status Q3Ellipsoid_Submit(const TQ3EllipsoidData* ellipsoidData, TQ3ViewObject view)
{
    return submitGeometry<Ellipsoid>(__func__, ellipsoidData, view);
}

TQ3Status Q3Ellipsoid_SetData(TQ3GeometryObject ellipsoid, const TQ3EllipsoidData* ellipsoidData)
{
    return setGeometryData<Ellipsoid>(__func__, ellipsoid, ellipsoidData);
}

TQ3Status Q3Ellipsoid_GetData(TQ3GeometryObject ellipsoid, TQ3EllipsoidData* ellipsoidData)
{
    return getGeometryData<Ellipsoid>(__func__, ellipsoid, ellipsoidData);
}

TQ3Status Q3Ellipsoid_EmptyData(TQ3EllipsoidData* ellipsoidData)
{
    return emptyGeometryData<Ellipsoid>(__func__, ellipsoidData);
}

TQ3Status Q3Ellipsoid_SetOrigin(TQ3GeometryObject ellipsoid, const TQ3Point3D* origin)
{
    return setField<Ellipsoid>(__func__, ellipsoid, &TQ3EllipsoidData::origin, origin, "origin");
}

TQ3Status Q3Ellipsoid_GetOrigin(TQ3GeometryObject ellipsoid, TQ3Point3D* origin)
{
    return getField<Ellipsoid>(__func__, ellipsoid, &TQ3EllipsoidData::origin, origin, "origin");
}

TQ3Status Q3Ellipsoid_SetOrientation(TQ3GeometryObject ellipsoid, const TQ3Vector3D* orientation)
{
    return setField<Ellipsoid>(__func__, ellipsoid, &TQ3EllipsoidData::orientation, orientation, "orientation");
}

TQ3Status Q3Ellipsoid_GetOrientation(TQ3GeometryObject ellipsoid, TQ3Vector3D* orientation)
{
    return getField<Ellipsoid>(__func__, ellipsoid, &TQ3EllipsoidData::orientation, orientation, "orientation");
}

TQ3Status Q3Ellipsoid_SetMajorRadius(TQ3GeometryObject ellipsoid, const TQ3Vector3D* majorRadius)
{
    return setField<Ellipsoid>(__func__, ellipsoid, &TQ3EllipsoidData::majorRadius, majorRadius, "majorRadius");
}

TQ3Status Q3Ellipsoid_GetMajorRadius(TQ3GeometryObject ellipsoid, TQ3Vector3D* majorRadius)
{
    return getField<Ellipsoid>(__func__, ellipsoid, &TQ3EllipsoidData::majorRadius, majorRadius, "majorRadius");
}

TQ3Status Q3Ellipsoid_SetMinorRadius(TQ3GeometryObject ellipsoid, const TQ3Vector3D* minorRadius)
{
    return setField<Ellipsoid>(__func__, ellipsoid, &TQ3EllipsoidData::minorRadius, minorRadius, "minorRadius");
}

TQ3Status Q3Ellipsoid_GetMinorRadius(TQ3GeometryObject ellipsoid, TQ3Vector3D* minorRadius)
{
    return getField<Ellipsoid>(__func__, ellipsoid, &TQ3EllipsoidData::minorRadius, minorRadius, "minorRadius");
}

} // extern "C"
