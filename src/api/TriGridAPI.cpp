// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/TriGrid.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3TriGrid_New(const TQ3TriGridData* triGridData)
{
    return newGeometry<TriGrid>(__func__, triGridData);
}

TQ3Status Q3TriGrid_Submit(const TQ3TriGridData* triGridData, TQ3ViewObject view)
{
    return submitGeometry<TriGrid>(__func__, triGridData, view);
}

TQ3Status Q3TriGrid_SetData(TQ3GeometryObject triGrid, const TQ3TriGridData* triGridData)
{
    return setGeometryData<TriGrid>(__func__, triGrid, triGridData);
}

TQ3Status Q3TriGrid_GetData(TQ3GeometryObject triGrid, TQ3TriGridData* triGridData)
{
    return getGeometryData<TriGrid>(__func__, triGrid, triGridData);
}

TQ3Status Q3TriGrid_EmptyData(TQ3TriGridData* triGridData)
{
    return emptyGeometryData<TriGrid>(__func__, triGridData);
}

TQ3Status Q3TriGrid_GetVertexPosition(TQ3GeometryObject triGrid, unsigned long rowIndex, unsigned long columnIndex,
                                      TQ3Point3D* position)
{
    return getVertexPosition<TriGrid>(__func__, triGrid, "triGrid", position, "position", rowIndex, columnIndex);
}

TQ3Status Q3TriGrid_SetVertexPosition(TQ3GeometryObject triGrid, unsigned long rowIndex, unsigned long columnIndex,
                                      const TQ3Point3D* position)
{
    return setVertexPosition<TriGrid>(__func__, triGrid, "triGrid", position, "position", rowIndex, columnIndex);
}

TQ3Status Q3TriGrid_GetVertexAttributeSet(TQ3GeometryObject triGrid, unsigned long rowIndex,
                                          unsigned long columnIndex, TQ3AttributeSet* attributeSet)
{
    return getVertexAttributeSet<TriGrid>(__func__, triGrid, "triGrid", attributeSet, rowIndex, columnIndex);
}

TQ3Status Q3TriGrid_SetVertexAttributeSet(TQ3GeometryObject triGrid, unsigned long rowIndex,
                                          unsigned long columnIndex, TQ3AttributeSet attributeSet)
{
    return setVertexAttributeSet<TriGrid>(__func__, triGrid, "triGrid", attributeSet, rowIndex, columnIndex);
}

TQ3Status Q3TriGrid_GetFacetAttributeSet(TQ3GeometryObject triGrid, unsigned long faceIndex,
                                         TQ3AttributeSet* facetAttributeSet)
{
    return getValue<TriGrid>(__func__, triGrid, "triGrid", facetAttributeSet, "facetAttributeSet",
                             [&](const TriGrid& g) { return attributeSetToHandle(g.facetSet(faceIndex)); });
}

TQ3Status Q3TriGrid_SetFacetAttributeSet(TQ3GeometryObject triGrid, unsigned long faceIndex,
                                         TQ3AttributeSet facetAttributeSet)
{
    return guardStatus(__func__, [&] {
        TriGrid& target = lookup<TriGrid>(triGrid, "triGrid");
        target.setFacetSet(faceIndex, attributeSetFromHandle(facetAttributeSet, "facetAttributeSet"));
    });
}

} // extern "C"
