// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Disk.h"

using namespace q3;
using namespace q3::api;

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Disk)

Q3_QUADRIC_FIELD_ENTRY_POINTS(Disk, Origin, TQ3Point3D, origin)
Q3_QUADRIC_FIELD_ENTRY_POINTS(Disk, MajorRadius, TQ3Vector3D, majorRadius)
Q3_QUADRIC_FIELD_ENTRY_POINTS(Disk, MinorRadius, TQ3Vector3D, minorRadius)

} // extern "C"
