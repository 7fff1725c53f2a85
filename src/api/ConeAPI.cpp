// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Cone.h"

using namespace q3;
using namespace q3::api;

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Cone)

Q3_QUADRIC_FIELD_ENTRY_POINTS(Cone, Origin, TQ3Point3D, origin)
Q3_QUADRIC_FIELD_ENTRY_POINTS(Cone, Orientation, TQ3Vector3D, orientation)
Q3_QUADRIC_FIELD_ENTRY_POINTS(Cone, MajorRadius, TQ3Vector3D, majorRadius)
Q3_QUADRIC_FIELD_ENTRY_POINTS(Cone, MinorRadius, TQ3Vector3D, minorRadius)
Q3_QUADRIC_VALUE_FIELD_ENTRY_POINTS(Cone, Caps, TQ3EndCap, caps)
Q3_QUADRIC_PART_SET_ENTRY_POINTS(Cone, BottomAttributeSet, bottomAttributeSet)
Q3_QUADRIC_PART_SET_ENTRY_POINTS(Cone, FaceAttributeSet, faceAttributeSet)

} // extern "C"
