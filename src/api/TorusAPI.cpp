// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Torus.h"

using namespace q3;
using namespace q3::api;

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Torus)

Q3_QUADRIC_FIELD_ENTRY_POINTS(Torus, Origin, TQ3Point3D, origin)
Q3_QUADRIC_FIELD_ENTRY_POINTS(Torus, Orientation, TQ3Vector3D, orientation)
Q3_QUADRIC_FIELD_ENTRY_POINTS(Torus, MajorRadius, TQ3Vector3D, majorRadius)
Q3_QUADRIC_FIELD_ENTRY_POINTS(Torus, MinorRadius, TQ3Vector3D, minorRadius)
Q3_QUADRIC_VALUE_FIELD_ENTRY_POINTS(Torus, Ratio, float, ratio)

} // extern "C"
