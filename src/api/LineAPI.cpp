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
    return getValue<Line>(__func__, line, "line", position, "position",
                          [&](const Line& source) { return source.vertex(index).point; });
}

TQ3Status Q3Line_SetVertexPosition(TQ3GeometryObject line, unsigned long index, const TQ3Point3D* position)
{
    return guardStatus(__func__, [&] {
        Line& target = lookup<Line>(line, "line");
        requireNonNull(position, "position");
        target.setVertexPosition(index, *position);
    });
}

TQ3Status Q3Line_GetVertexAttributeSet(TQ3GeometryObject line, unsigned long index,
                                       TQ3AttributeSet* attributeSet)
{
    return getValue<Line>(__func__, line, "line", attributeSet, "attributeSet",
                          [&](const Line& source) { return attributeSetToHandle(source.vertexAttributeSet(index)); });
}

TQ3Status Q3Line_SetVertexAttributeSet(TQ3GeometryObject line, unsigned long index,
                                       TQ3AttributeSet attributeSet)
{
    return guardStatus(__func__, [&] {
        Line& target = lookup<Line>(line, "line");
        target.setVertexAttributeSet(index, attributeSetFromHandle(attributeSet, "attributeSet"));
    });
}

} // extern "C"
