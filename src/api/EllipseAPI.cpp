// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Ellipse.h"

using namespace q3;
using namespace q3::api;

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Ellipse)

Q3_QUADRIC_FIELD_ENTRY_POINTS(Ellipse, Origin, TQ3Point3D, origin)
Q3_QUADRIC_FIELD_ENTRY_POINTS(Ellipse, MajorRadius, TQ3Vector3D, majorRadius)
Q3_QUADRIC_FIELD_ENTRY_POINTS(Ellipse, MinorRadius, TQ3Vector3D, minorRadius)

} // extern "C"
