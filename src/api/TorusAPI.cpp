// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Torus.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3Torus_New(const TQ3TorusData* torusData)
{
    return newGeometry<Torus>(__func__, torusData);
}

TQ3Status Q3Torus_Submit(const TQ3TorusData* torusData, TQ3ViewObject view)
{
    return submitGeometry<Torus>(__func__, torusData, view);
}

TQ3Status Q3Torus_SetData(TQ3GeometryObject torus, const TQ3TorusData* torusData)
{
    return setGeometryData<Torus>(__func__, torus, torusData);
}

TQ3Status Q3Torus_GetData(TQ3GeometryObject torus, TQ3TorusData* torusData)
{
    return getGeometryData<Torus>(__func__, torus, torusData);
}

TQ3Status Q3Torus_EmptyData(TQ3TorusData* torusData)
{
    return emptyGeometryData<Torus>(__func__, torusData);
}

TQ3Status Q3Torus_SetOrigin(TQ3GeometryObject torus, const TQ3Point3D* origin)
{
    return setField<Torus>(__func__, torus, &TQ3TorusData::origin, origin, "origin");
}

TQ3Status Q3Torus_GetOrigin(TQ3GeometryObject torus, TQ3Point3D* origin)
{
    return getField<Torus>(__func__, torus, &TQ3TorusData::origin, origin, "origin");
}

TQ3Status Q3Torus_SetOrientation(TQ3GeometryObject torus, const TQ3Vector3D* orientation)
{
    return setField<Torus>(__func__, torus, &TQ3TorusData::orientation, orientation, "orientation");
}

TQ3Status Q3Torus_GetOrientation(TQ3GeometryObject torus, TQ3Vector3D* orientation)
{
    return getField<Torus>(__func__, torus, &TQ3TorusData::orientation, orientation, "orientation");
}

TQ3Status Q3Torus_SetMajorRadius(TQ3GeometryObject torus, const TQ3Vector3D* majorRadius)
{
    return setField<Torus>(__func__, torus, &TQ3TorusData::majorRadius, majorRadius, "majorRadius");
}

TQ3Status Q3Torus_GetMajorRadius(TQ3GeometryObject torus, TQ3Vector3D* majorRadius)
{
    return getField<Torus>(__func__, torus, &TQ3TorusData::majorRadius, majorRadius, "majorRadius");
}

TQ3Status Q3Torus_SetMinorRadius(TQ3GeometryObject torus, const TQ3Vector3D* minorRadius)
{
    return setField<Torus>(__func__, torus, &TQ3TorusData::minorRadius, minorRadius, "minorRadius");
}

TQ3Status Q3Torus_GetMinorRadius(TQ3GeometryObject torus, TQ3Vector3D* minorRadius)
{
    return getField<Torus>(__func__, torus, &TQ3TorusData::minorRadius, minorRadius, "minorRadius");
}

TQ3Status Q3Torus_SetRatio(TQ3GeometryObject torus, float ratio)
{
    return setFieldValue<Torus>(__func__, torus, &TQ3TorusData::ratio, ratio);
}

TQ3Status Q3Torus_GetRatio(TQ3GeometryObject torus, float* ratio)
{
    return getField<Torus>(__func__, torus, &TQ3TorusData::ratio, ratio, "ratio");
}

} // extern "C"
