// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Cylinder.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3Cylinder_New(const TQ3CylinderData* cylinderData)
{
    return newGeometry<Cylinder>(__func__, cylinderData);
}

TQ3Status Q3Cylinder_Submit(const TQ3CylinderData* cylinderData, TQ3ViewObject view)
{
    return submitGeometry<Cylinder>(__func__, cylinderData, view);
}

TQ3Status Q3Cylinder_SetData(TQ3GeometryObject cylinder, const TQ3CylinderData* cylinderData)
{
    return setGeometryData<Cylinder>(__func__, cylinder, cylinderData);
}

TQ3Status Q3Cylinder_GetData(TQ3GeometryObject cylinder, TQ3CylinderData* cylinderData)
{
    return getGeometryData<Cylinder>(__func__, cylinder, cylinderData);
}

TQ3Status Q3Cylinder_EmptyData(TQ3CylinderData* cylinderData)
{
    return emptyGeometryData<Cylinder>(__func__, cylinderData);
}

TQ3Status Q3Cylinder_SetOrigin(TQ3GeometryObject cylinder, const TQ3Point3D* origin)
{
    return setField<Cylinder>(__func__, cylinder, &TQ3CylinderData::origin, origin, "origin");
}

TQ3Status Q3Cylinder_GetOrigin(TQ3GeometryObject cylinder, TQ3Point3D* origin)
{
    return getField<Cylinder>(__func__, cylinder, &TQ3CylinderData::origin, origin, "origin");
}

TQ3Status Q3Cylinder_SetOrientation(TQ3GeometryObject cylinder, const TQ3Vector3D* orientation)
{
    return setField<Cylinder>(__func__, cylinder, &TQ3CylinderData::orientation, orientation, "orientation");
}

TQ3Status Q3Cylinder_GetOrientation(TQ3GeometryObject cylinder, TQ3Vector3D* orientation)
{
    return getField<Cylinder>(__func__, cylinder, &TQ3CylinderData::orientation, orientation, "orientation");
}

TQ3Status Q3Cylinder_SetMajorRadius(TQ3GeometryObject cylinder, const TQ3Vector3D* majorRadius)
{
    return setField<Cylinder>(__func__, cylinder, &TQ3CylinderData::majorRadius, majorRadius, "majorRadius");
}

TQ3Status Q3Cylinder_GetMajorRadius(TQ3GeometryObject cylinder, TQ3Vector3D* majorRadius)
{
    return getField<Cylinder>(__func__, cylinder, &TQ3CylinderData::majorRadius, majorRadius, "majorRadius");
}

TQ3Status Q3Cylinder_SetMinorRadius(TQ3GeometryObject cylinder, const TQ3Vector3D* minorRadius)
{
    return setField<Cylinder>(__func__, cylinder, &TQ3CylinderData::minorRadius, minorRadius, "minorRadius");
}

TQ3Status Q3Cylinder_GetMinorRadius(TQ3GeometryObject cylinder, TQ3Vector3D* minorRadius)
{
    return getField<Cylinder>(__func__, cylinder, &TQ3CylinderData::minorRadius, minorRadius, "minorRadius");
}

TQ3Status Q3Cylinder_SetCaps(TQ3GeometryObject cylinder, TQ3EndCap caps)
{
    return setFieldValue<Cylinder>(__func__, cylinder, &TQ3CylinderData::caps, caps);
}

TQ3Status Q3Cylinder_GetCaps(TQ3GeometryObject cylinder, TQ3EndCap* caps)
{
    return getField<Cylinder>(__func__, cylinder, &TQ3CylinderData::caps, caps, "caps");
}

TQ3Status Q3Cylinder_SetTopAttributeSet(TQ3GeometryObject cylinder, TQ3AttributeSet topAttributeSet)
{
    return setPartSet<Cylinder>(__func__, cylinder, &TQ3CylinderData::topAttributeSet, topAttributeSet,
                                "topAttributeSet");
}

TQ3Status Q3Cylinder_GetTopAttributeSet(TQ3GeometryObject cylinder, TQ3AttributeSet* topAttributeSet)
{
    return getPartSet<Cylinder>(__func__, cylinder, &TQ3CylinderData::topAttributeSet, topAttributeSet,
                                "topAttributeSet");
}

TQ3Status Q3Cylinder_SetBottomAttributeSet(TQ3GeometryObject cylinder, TQ3AttributeSet bottomAttributeSet)
{
    return setPartSet<Cylinder>(__func__, cylinder, &TQ3CylinderData::bottomAttributeSet, bottomAttributeSet,
                                "bottomAttributeSet");
}

TQ3Status Q3Cylinder_GetBottomAttributeSet(TQ3GeometryObject cylinder, TQ3AttributeSet* bottomAttributeSet)
{
    return getPartSet<Cylinder>(__func__, cylinder, &TQ3CylinderData::bottomAttributeSet, bottomAttributeSet,
                                "bottomAttributeSet");
}

TQ3Status Q3Cylinder_SetFaceAttributeSet(TQ3GeometryObject cylinder, TQ3AttributeSet faceAttributeSet)
{
    return setPartSet<Cylinder>(__func__, cylinder, &TQ3CylinderData::faceAttributeSet, faceAttributeSet,
                                "faceAttributeSet");
}

TQ3Status Q3Cylinder_GetFaceAttributeSet(TQ3GeometryObject cylinder, TQ3AttributeSet* faceAttributeSet)
{
    return getPartSet<Cylinder>(__func__, cylinder, &TQ3CylinderData::faceAttributeSet, faceAttributeSet,
                                "faceAttributeSet");
}

} // extern "C"
