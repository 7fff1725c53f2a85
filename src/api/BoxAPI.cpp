// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Box.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3Box_New(const TQ3BoxData* boxData)
{
    return newGeometry<Box>(__func__, boxData);
}

TQ3Status Q3Box_Submit(const TQ3BoxData* boxData, TQ3ViewObject view)
{
    return submitGeometry<Box>(__func__, boxData, view);
}

TQ3Status Q3Box_SetData(TQ3GeometryObject box, const TQ3BoxData* boxData)
{
    return setGeometryData<Box>(__func__, box, boxData);
}

TQ3Status Q3Box_GetData(TQ3GeometryObject box, TQ3BoxData* boxData)
{
    return getGeometryData<Box>(__func__, box, boxData);
}

TQ3Status Q3Box_EmptyData(TQ3BoxData* boxData)
{
    return emptyGeometryData<Box>(__func__, boxData);
}

TQ3Status Q3Box_SetOrigin(TQ3GeometryObject box, const TQ3Point3D* origin)
{
    return setField<Box>(__func__, box, &TQ3BoxData::origin, origin, "origin");
}

TQ3Status Q3Box_GetOrigin(TQ3GeometryObject box, TQ3Point3D* origin)
{
    return getField<Box>(__func__, box, &TQ3BoxData::origin, origin, "origin");
}

TQ3Status Q3Box_SetOrientation(TQ3GeometryObject box, const TQ3Vector3D* orientation)
{
    return setField<Box>(__func__, box, &TQ3BoxData::orientation, orientation, "orientation");
}

TQ3Status Q3Box_GetOrientation(TQ3GeometryObject box, TQ3Vector3D* orientation)
{
    return getField<Box>(__func__, box, &TQ3BoxData::orientation, orientation, "orientation");
}

TQ3Status Q3Box_SetMajorAxis(TQ3GeometryObject box, const TQ3Vector3D* majorAxis)
{
    return setField<Box>(__func__, box, &TQ3BoxData::majorAxis, majorAxis, "majorAxis");
}

TQ3Status Q3Box_GetMajorAxis(TQ3GeometryObject box, TQ3Vector3D* majorAxis)
{
    return getField<Box>(__func__, box, &TQ3BoxData::majorAxis, majorAxis, "majorAxis");
}

TQ3Status Q3Box_SetMinorAxis(TQ3GeometryObject box, const TQ3Vector3D* minorAxis)
{
    return setField<Box>(__func__, box, &TQ3BoxData::minorAxis, minorAxis, "minorAxis");
}

TQ3Status Q3Box_GetMinorAxis(TQ3GeometryObject box, TQ3Vector3D* minorAxis)
{
    return getField<Box>(__func__, box, &TQ3BoxData::minorAxis, minorAxis, "minorAxis");
}

TQ3Status Q3Box_GetFaceAttributeSet(TQ3GeometryObject box, unsigned long faceIndex, TQ3AttributeSet* faceAttributeSet)
{
    return getValue<Box>(__func__, box, "box", faceAttributeSet, "faceAttributeSet",
                         [&](const Box& b) { return attributeSetToHandle(b.faceSet(faceIndex)); });
}

TQ3Status Q3Box_SetFaceAttributeSet(TQ3GeometryObject box, unsigned long faceIndex, TQ3AttributeSet faceAttributeSet)
{
    return guardStatus(__func__, [&] {
        Box& target = lookup<Box>(box, "box");
        target.setFaceSet(faceIndex, attributeSetFromHandle(faceAttributeSet, "faceAttributeSet"));
    });
}

} // extern "C"
