// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/Triangle.h"

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Triangle)
Q3_INDEXED_VERTEX_ENTRY_POINTS(Triangle, triangle, point)

} // extern "C"
