// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Ellipse.h"

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Ellipse)

Q3_QUADRIC_PLANE_ENTRY_POINTS(Ellipse)

} // extern "C"
