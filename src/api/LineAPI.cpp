// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/Line.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3Line_New(const TQ3LineData* lineData)
{
    return newGeometry<Line>(__func__, lineData);
}

TQ3Status Q3Line_Submit(const TQ3LineData* lineData, TQ3ViewObject view)
{
    return submitGeometry<Line>(__func__, lineData, view);
}

TQ3Status Q3Line_GetData(TQ3GeometryObject line, TQ3LineData* lineData)
{
    return getGeometryData<Line>(__func__, line, lineData);
}

TQ3Status Q3Line_SetData(TQ3GeometryObject line, const TQ3LineData* lineData)
{
    return setGeometryData<Line>(__func__, line, lineData);
}

TQ3Status Q3Line_EmptyData(TQ3LineData* lineData)
{
    return emptyGeometryData<Line>(__func__, lineData);
}

TQ3Status Q3Line_GetVertexPosition(TQ3GeometryObject line, unsigned long index, TQ3Point3D* position)
{
    return getVertexPosition<Line>(__func__, line, "line", position, "position", index);
}

TQ3Status Q3Line_SetVertexPosition(TQ3GeometryObject line, unsigned long index, const TQ3Point3D* position)
{
    return setVertexPosition<Line>(__func__, line, "line", position, "position", index);
}

TQ3Status Q3Line_GetVertexAttributeSet(TQ3GeometryObject line, unsigned long index,
                                       TQ3AttributeSet* attributeSet)
{
    return getVertexAttributeSet<Line>(__func__, line, "line", attributeSet, index);
}

TQ3Status Q3Line_SetVertexAttributeSet(TQ3GeometryObject line, unsigned long index,
                                       TQ3AttributeSet attributeSet)
{
    return setVertexAttributeSet<Line>(__func__, line, "line", attributeSet, index);
}

} // extern "C"
