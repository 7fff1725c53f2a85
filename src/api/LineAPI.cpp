// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/Line.h"

extern "C" {

Q3_DATA_GEOMETRY_ENTRY_POINTS(Line)
Q3_INDEXED_VERTEX_ENTRY_POINTS(Line, line, position)

} // extern "C"
