// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Cone.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3Cone_New(const TQ3ConeData* coneData)
{
    return newGeometry<Cone>(__func__, coneData);
}

TQ3Status Q3Cone_Submit(const TQ3ConeData* coneData, TQ3ViewObject view)
{
    return submitGeometry<Cone>(__func__, coneData, view);
}

TQ3Status Q3Cone_SetData(TQ3GeometryObject cone, const TQ3ConeData* coneData)
{
    return setGeometryData<Cone>(__func__, cone, coneData);
}

TQ3Status Q3Cone_GetData(TQ3GeometryObject cone, TQ3ConeData* coneData)
{
    return getGeometryData<Cone>(__func__, cone, coneData);
}

TQ3Status Q3Cone_EmptyData(TQ3ConeData* coneData)
{
    return emptyGeometryData<Cone>(__func__, coneData);
}

TQ3Status Q3Cone_SetOrigin(TQ3GeometryObject cone, const TQ3Point3D* origin)
{
    return setField<Cone>(__func__, cone, &TQ3ConeData::origin, origin, "origin");
}

TQ3Status Q3Cone_GetOrigin(TQ3GeometryObject cone, TQ3Point3D* origin)
{
    return getField<Cone>(__func__, cone, &TQ3ConeData::origin, origin, "origin");
}

TQ3Status Q3Cone_SetOrientation(TQ3GeometryObject cone, const TQ3Vector3D* orientation)
{
    return setField<Cone>(__func__, cone, &TQ3ConeData::orientation, orientation, "orientation");
}

TQ3Status Q3Cone_GetOrientation(TQ3GeometryObject cone, TQ3Vector3D* orientation)
{
    return getField<Cone>(__func__, cone, &TQ3ConeData::orientation, orientation, "orientation");
}

TQ3Status Q3Cone_SetMajorRadius(TQ3GeometryObject cone, const TQ3Vector3D* majorRadius)
{
    return setField<Cone>(__func__, cone, &TQ3ConeData::majorRadius, majorRadius, "majorRadius");
}

TQ3Status Q3Cone_GetMajorRadius(TQ3GeometryObject cone, TQ3Vector3D* majorRadius)
{
    return getField<Cone>(__func__, cone, &TQ3ConeData::majorRadius, majorRadius, "majorRadius");
}

TQ3Status Q3Cone_SetMinorRadius(TQ3GeometryObject cone, const TQ3Vector3D* minorRadius)
{
    return setField<Cone>(__func__, cone, &TQ3ConeData::minorRadius, minorRadius, "minorRadius");
}

TQ3Status Q3Cone_GetMinorRadius(TQ3GeometryObject cone, TQ3Vector3D* minorRadius)
{
    return getField<Cone>(__func__, cone, &TQ3ConeData::minorRadius, minorRadius, "minorRadius");
}

TQ3Status Q3Cone_SetCaps(TQ3GeometryObject cone, TQ3EndCap caps)
{
    return setFieldValue<Cone>(__func__, cone, &TQ3ConeData::caps, caps);
}

TQ3Status Q3Cone_GetCaps(TQ3GeometryObject cone, TQ3EndCap* caps)
{
    return getField<Cone>(__func__, cone, &TQ3ConeData::caps, caps, "caps");
}

TQ3Status Q3Cone_SetBottomAttributeSet(TQ3GeometryObject cone, TQ3AttributeSet bottomAttributeSet)
{
    return setPartSet<Cone>(__func__, cone, &TQ3ConeData::bottomAttributeSet, bottomAttributeSet, "bottomAttributeSet");
}

TQ3Status Q3Cone_GetBottomAttributeSet(TQ3GeometryObject cone, TQ3AttributeSet* bottomAttributeSet)
{
    return getPartSet<Cone>(__func__, cone, &TQ3ConeData::bottomAttributeSet, bottomAttributeSet, "bottomAttributeSet");
}

TQ3Status Q3Cone_SetFaceAttributeSet(TQ3GeometryObject cone, TQ3AttributeSet faceAttributeSet)
{
    return setPartSet<Cone>(__func__, cone, &TQ3ConeData::faceAttributeSet, faceAttributeSet, "faceAttributeSet");
}

TQ3Status Q3Cone_GetFaceAttributeSet(TQ3GeometryObject cone, TQ3AttributeSet* faceAttributeSet)
{
    return getPartSet<Cone>(__func__, cone, &TQ3ConeData::faceAttributeSet, faceAttributeSet, "faceAttributeSet");
}

} // extern "C"
