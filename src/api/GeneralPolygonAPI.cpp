// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/GeneralPolygon.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3GeneralPolygon_New(const TQ3GeneralPolygonData* generalPolygonData)
{
    return newGeometry<GeneralPolygon>(__func__, generalPolygonData);
}

TQ3Status Q3GeneralPolygon_Submit(const TQ3GeneralPolygonData* generalPolygonData, TQ3ViewObject view)
{
    return submitGeometry<GeneralPolygon>(__func__, generalPolygonData, view);
}

TQ3Status Q3GeneralPolygon_SetData(TQ3GeometryObject generalPolygon, const TQ3GeneralPolygonData* generalPolygonData)
{
    return setGeometryData<GeneralPolygon>(__func__, generalPolygon, generalPolygonData);
}

TQ3Status Q3GeneralPolygon_GetData(TQ3GeometryObject polygon, TQ3GeneralPolygonData* generalPolygonData)
{
    return getGeometryData<GeneralPolygon>(__func__, polygon, generalPolygonData);
}

TQ3Status Q3GeneralPolygon_EmptyData(TQ3GeneralPolygonData* generalPolygonData)
{
    return emptyGeometryData<GeneralPolygon>(__func__, generalPolygonData);
}

TQ3Status Q3GeneralPolygon_GetVertexPosition(TQ3GeometryObject generalPolygon, unsigned long contourIndex,
                                             unsigned long pointIndex, TQ3Point3D* position)
{
    return getVertexPosition<GeneralPolygon>(__func__, generalPolygon, "generalPolygon",
                                             position, "position", contourIndex, pointIndex);
}

TQ3Status Q3GeneralPolygon_SetVertexPosition(TQ3GeometryObject generalPolygon, unsigned long contourIndex,
                                             unsigned long pointIndex, const TQ3Point3D* position)
{
    return setVertexPosition<GeneralPolygon>(__func__, generalPolygon, "generalPolygon",
                                             position, "position", contourIndex, pointIndex);
}

TQ3Status Q3GeneralPolygon_GetVertexAttributeSet(TQ3GeometryObject generalPolygon, unsigned long contourIndex,
                                                 unsigned long pointIndex, TQ3AttributeSet* attributeSet)
{
    return getVertexAttributeSet<GeneralPolygon>(__func__, generalPolygon, "generalPolygon",
                                                 attributeSet, contourIndex, pointIndex);
}

TQ3Status Q3GeneralPolygon_SetVertexAttributeSet(TQ3GeometryObject generalPolygon, unsigned long contourIndex,
                                                 unsigned long pointIndex, TQ3AttributeSet attributeSet)
{
    return setVertexAttributeSet<GeneralPolygon>(__func__, generalPolygon, "generalPolygon",
                                                 attributeSet, contourIndex, pointIndex);
}

TQ3Status Q3GeneralPolygon_SetShapeHint(TQ3GeometryObject generalPolygon, TQ3GeneralPolygonShapeHint shapeHint)
{
    return guardStatus(__func__, [&] {
        lookup<GeneralPolygon>(generalPolygon, "generalPolygon").setShapeHint(shapeHint);
    });
}

TQ3Status Q3GeneralPolygon_GetShapeHint(TQ3GeometryObject generalPolygon, TQ3GeneralPolygonShapeHint* shapeHint)
{
    return getValue<GeneralPolygon>(__func__, generalPolygon, "generalPolygon", shapeHint, "shapeHint",
                                    [](const GeneralPolygon& p) { return p.shapeHint(); });
}

} // extern "C"
