// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Cone.h"

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Cone)

Q3_QUADRIC_FRAME_ENTRY_POINTS(Cone)
Q3_QUADRIC_CAPS_ENTRY_POINTS(Cone)

} // extern "C"
