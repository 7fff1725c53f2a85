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
    return getValue<TriGrid>(__func__, triGrid, "triGrid", position, "position",
                             [&](const TriGrid& g) { return g.vertex(rowIndex, columnIndex).point; });
}

TQ3Status Q3TriGrid_SetVertexPosition(TQ3GeometryObject triGrid, unsigned long rowIndex, unsigned long columnIndex,
                                      const TQ3Point3D* position)
{
    return guardStatus(__func__, [&] {
        TriGrid& target = lookup<TriGrid>(triGrid, "triGrid");
        requireNonNull(position, "position");
        target.setVertexPosition(rowIndex, columnIndex, *position);
    });
}

TQ3Status Q3TriGrid_GetVertexAttributeSet(TQ3GeometryObject triGrid, unsigned long rowIndex,
                                          unsigned long columnIndex, TQ3AttributeSet* attributeSet)
{
    return getValue<TriGrid>(__func__, triGrid, "triGrid", attributeSet, "attributeSet", [&](const TriGrid& g) {
        return attributeSetToHandle(heldAttributeSet(g.vertex(rowIndex, columnIndex).attributeSet));
    });
}

TQ3Status Q3TriGrid_SetVertexAttributeSet(TQ3GeometryObject triGrid, unsigned long rowIndex,
                                          unsigned long columnIndex, TQ3AttributeSet attributeSet)
{
    return guardStatus(__func__, [&] {
        TriGrid& target = lookup<TriGrid>(triGrid, "triGrid");
        target.setVertexAttributeSet(rowIndex, columnIndex, attributeSetFromHandle(attributeSet, "attributeSet"));
    });
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
