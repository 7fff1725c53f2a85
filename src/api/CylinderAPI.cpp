// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Cylinder.h"

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Cylinder)

Q3_QUADRIC_FRAME_ENTRY_POINTS(Cylinder)
Q3_QUADRIC_CAPS_ENTRY_POINTS(Cylinder)
Q3_QUADRIC_PART_SET_ENTRY_POINTS(Cylinder, TopAttributeSet, topAttributeSet)

} // extern "C"
