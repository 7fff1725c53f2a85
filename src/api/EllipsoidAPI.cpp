// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Ellipsoid.h"

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Ellipsoid)

Q3_QUADRIC_FRAME_ENTRY_POINTS(Ellipsoid)

} // extern "C"
