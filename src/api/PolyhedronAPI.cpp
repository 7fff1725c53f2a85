// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/Polyhedron.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3Polyhedron_New(const TQ3PolyhedronData* polyhedronData)
{
    return newGeometry<Polyhedron>(__func__, polyhedronData);
}

TQ3Status Q3Polyhedron_Submit(const TQ3PolyhedronData* polyhedronData, TQ3ViewObject view)
{
    return submitGeometry<Polyhedron>(__func__, polyhedronData, view);
}

TQ3Status Q3Polyhedron_SetData(TQ3GeometryObject polyhedron, const TQ3PolyhedronData* polyhedronData)
{
    return setGeometryData<Polyhedron>(__func__, polyhedron, polyhedronData);
}

TQ3Status Q3Polyhedron_GetData(TQ3GeometryObject polyhedron, TQ3PolyhedronData* polyhedronData)
{
    return getGeometryData<Polyhedron>(__func__, polyhedron, polyhedronData);
}

TQ3Status Q3Polyhedron_EmptyData(TQ3PolyhedronData* polyhedronData)
{
    return emptyGeometryData<Polyhedron>(__func__, polyhedronData);
}

TQ3Status Q3Polyhedron_SetVertexPosition(TQ3GeometryObject polyhedron, unsigned long index, const TQ3Point3D* point)
{
    return setVertexPosition<Polyhedron>(__func__, polyhedron, "polyhedron", point, "point", index);
}

TQ3Status Q3Polyhedron_GetVertexPosition(TQ3GeometryObject polyhedron, unsigned long index, TQ3Point3D* point)
{
    return getVertexPosition<Polyhedron>(__func__, polyhedron, "polyhedron", point, "point", index);
}

TQ3Status Q3Polyhedron_SetVertexAttributeSet(TQ3GeometryObject polyhedron, unsigned long index,
                                             TQ3AttributeSet attributeSet)
{
    return setVertexAttributeSet<Polyhedron>(__func__, polyhedron, "polyhedron", attributeSet, index);
}

TQ3Status Q3Polyhedron_GetVertexAttributeSet(TQ3GeometryObject polyhedron, unsigned long index,
                                             TQ3AttributeSet* attributeSet)
{
    return getVertexAttributeSet<Polyhedron>(__func__, polyhedron, "polyhedron", attributeSet, index);
}

TQ3Status Q3Polyhedron_GetTriangleData(TQ3GeometryObject polyhedron, unsigned long triangleIndex,
                                       TQ3PolyhedronTriangleData* triangleData)
{
    return getValue<Polyhedron>(__func__, polyhedron, "polyhedron", triangleData, "triangleData",
                                [&](const Polyhedron& p) { return p.triangle(triangleIndex); });
}

TQ3Status Q3Polyhedron_SetTriangleData(TQ3GeometryObject polyhedron, unsigned long triangleIndex,
                                       const TQ3PolyhedronTriangleData* triangleData)
{
    return guardStatus(__func__, [&] {
        Polyhedron& target = lookup<Polyhedron>(polyhedron, "polyhedron");
        requireNonNull(triangleData, "triangleData");
        target.setTriangle(triangleIndex, *triangleData);
    });
}

TQ3Status Q3Polyhedron_GetEdgeData(TQ3GeometryObject polyhedron, unsigned long edgeIndex,
                                   TQ3PolyhedronEdgeData* edgeData)
{
    return getValue<Polyhedron>(__func__, polyhedron, "polyhedron", edgeData, "edgeData",
                                [&](const Polyhedron& p) { return p.edge(edgeIndex); });
}

TQ3Status Q3Polyhedron_SetEdgeData(TQ3GeometryObject polyhedron, unsigned long edgeIndex,
                                   const TQ3PolyhedronEdgeData* edgeData)
{
    return guardStatus(__func__, [&] {
        Polyhedron& target = lookup<Polyhedron>(polyhedron, "polyhedron");
        requireNonNull(edgeData, "edgeData");
        target.setEdge(edgeIndex, *edgeData);
    });
}

} // extern "C"
