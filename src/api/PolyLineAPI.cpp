// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/PolyLine.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3PolyLine_New(const TQ3PolyLineData* polylineData)
{
    return newGeometry<PolyLine>(__func__, polylineData);
}

TQ3Status Q3PolyLine_Submit(const TQ3PolyLineData* polyLineData, TQ3ViewObject view)
{
    return submitGeometry<PolyLine>(__func__, polyLineData, view);
}

TQ3Status Q3PolyLine_SetData(TQ3GeometryObject polyLine, const TQ3PolyLineData* polyLineData)
{
    return setGeometryData<PolyLine>(__func__, polyLine, polyLineData);
}

TQ3Status Q3PolyLine_GetData(TQ3GeometryObject polyLine, TQ3PolyLineData* polyLineData)
{
    return getGeometryData<PolyLine>(__func__, polyLine, polyLineData);
}

TQ3Status Q3PolyLine_EmptyData(TQ3PolyLineData* polyLineData)
{
    return emptyGeometryData<PolyLine>(__func__, polyLineData);
}

TQ3Status Q3PolyLine_GetVertexPosition(TQ3GeometryObject polyLine, unsigned long index,
                                       TQ3Point3D* position)
{
    return getVertexPosition<PolyLine>(__func__, polyLine, "polyLine", position, "position", index);
}

TQ3Status Q3PolyLine_SetVertexPosition(TQ3GeometryObject polyLine, unsigned long index,
                                       const TQ3Point3D* position)
{
    return setVertexPosition<PolyLine>(__func__, polyLine, "polyLine", position, "position", index);
}

TQ3Status Q3PolyLine_GetVertexAttributeSet(TQ3GeometryObject polyLine, unsigned long index,
                                           TQ3AttributeSet* attributeSet)
{
    return getVertexAttributeSet<PolyLine>(__func__, polyLine, "polyLine", attributeSet, index);
}

TQ3Status Q3PolyLine_SetVertexAttributeSet(TQ3GeometryObject polyLine, unsigned long index,
                                           TQ3AttributeSet attributeSet)
{
    return setVertexAttributeSet<PolyLine>(__func__, polyLine, "polyLine", attributeSet, index);
}

TQ3Status Q3PolyLine_GetSegmentAttributeSet(TQ3GeometryObject polyLine, unsigned long index,
                                            TQ3AttributeSet* attributeSet)
{
    return guardStatus(__func__, [&] {
        const PolyLine& source = lookup<PolyLine>(polyLine, "polyLine");
        requireNonNull(attributeSet, "attributeSet");
        *attributeSet = attributeSetToHandle(source.segmentAttributeSet(index));
    });
}

TQ3Status Q3PolyLine_SetSegmentAttributeSet(TQ3GeometryObject polyLine, unsigned long index,
                                            TQ3AttributeSet attributeSet)
{
    return guardStatus(__func__, [&] {
        PolyLine& target = lookup<PolyLine>(polyLine, "polyLine");
        target.setSegmentAttributeSet(index, attributeSetFromHandle(attributeSet, "attributeSet"));
    });
}

} // extern "C"
