// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/Polygon.h"

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Polygon)
Q3_INDEXED_VERTEX_ENTRY_POINTS(Polygon, polygon, point)

} // extern "C"
