// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/Entry.h"
#include "geometry/Line.h"
#include "view/View.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3GeometryObject Q3Line_New(const TQ3LineData* lineData)
{
    return guard(__func__, TQ3GeometryObject{nullptr}, [&]() -> TQ3GeometryObject {
        validateLineData(lineData);
        return makeShared<Line>(*lineData).detach();
    });
}

TQ3Status Q3Line_Submit(const TQ3LineData* lineData, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        requireNonNull(lineData, "lineData");
        ShapeVisitor& target = lookup<View>(view, "view").submitTarget();
        validateLineData(lineData);
        target.visitLine(*makeShared<Line>(*lineData));
    });
}

TQ3Status Q3Line_GetData(TQ3GeometryObject line, TQ3LineData* lineData)
{
    return guardStatus(__func__, [&] {
        const Line& source = lookup<Line>(line, "line");
        requireNonNull(lineData, "lineData");
        source.getData(*lineData);
    });
}

TQ3Status Q3Line_SetData(TQ3GeometryObject line, const TQ3LineData* lineData)
{
    return guardStatus(__func__, [&] {
        Line& target = lookup<Line>(line, "line");
        requireNonNull(lineData, "lineData");
        target.setData(*lineData);
    });
}

TQ3Status Q3Line_EmptyData(TQ3LineData* lineData)
{
    return guardStatus(__func__, [&] {
        requireNonNull(lineData, "lineData");
        Line::emptyData(*lineData);
    });
}

TQ3Status Q3Line_GetVertexPosition(TQ3GeometryObject line, unsigned long index, TQ3Point3D* position)
{
    return guardStatus(__func__, [&] {
        const Line& source = lookup<Line>(line, "line");
        requireNonNull(position, "position");
        *position = source.vertex(index).point;
    });
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
    return guardStatus(__func__, [&] {
        const Line& source = lookup<Line>(line, "line");
        requireNonNull(attributeSet, "attributeSet");
        *attributeSet = attributeSetToHandle(source.vertexAttributeSet(index));
    });
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
