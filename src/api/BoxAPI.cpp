// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Box.h"

using namespace q3;
using namespace q3::api;

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Box)

Q3_QUADRIC_FIELD_ENTRY_POINTS(Box, Origin, TQ3Point3D, origin)
Q3_QUADRIC_FIELD_ENTRY_POINTS(Box, Orientation, TQ3Vector3D, orientation)
Q3_QUADRIC_FIELD_ENTRY_POINTS(Box, MajorAxis, TQ3Vector3D, majorAxis)
Q3_QUADRIC_FIELD_ENTRY_POINTS(Box, MinorAxis, TQ3Vector3D, minorAxis)
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
