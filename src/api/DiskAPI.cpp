// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Disk.h"

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Disk)

Q3_QUADRIC_PLANE_ENTRY_POINTS(Disk)

} // extern "C"
