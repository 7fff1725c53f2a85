// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Point.h"

#include "geometry/DataGeometryImpl.h"

namespace q3 {

const ClassInfo kPointClass{kQ3GeometryTypePoint, &kGeometryClass, "point"};

template class DataGeometry<Point, TQ3PointData>;

void Point::decompose(const DecomposeContext&, PrimitiveSink& sink) const
{
    static const std::uint32_t kFirst = 0;
    MeshView mesh;
    mesh.points = &kFirst;
    mesh.pointCount = 1;
    drawAt(data().point, mesh, sink);
}

void Point::setPosition(const TQ3Point3D& position)
{
    requireFinite(position, "point");
    editableData().point = position;
    markEdited();
}

} // namespace q3
