// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/NURBPatch.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3NURBPatch_New(const TQ3NURBPatchData* nurbPatchData)
{
    return newGeometry<NURBPatch>(__func__, nurbPatchData);
}

TQ3Status Q3NURBPatch_Submit(const TQ3NURBPatchData* nurbPatchData, TQ3ViewObject view)
{
    return submitGeometry<NURBPatch>(__func__, nurbPatchData, view);
}

TQ3Status Q3NURBPatch_SetData(TQ3GeometryObject nurbPatch, const TQ3NURBPatchData* nurbPatchData)
{
    return setGeometryData<NURBPatch>(__func__, nurbPatch, nurbPatchData);
}

TQ3Status Q3NURBPatch_GetData(TQ3GeometryObject nurbPatch, TQ3NURBPatchData* nurbPatchData)
{
    return getGeometryData<NURBPatch>(__func__, nurbPatch, nurbPatchData);
}

TQ3Status Q3NURBPatch_EmptyData(TQ3NURBPatchData* nurbPatchData)
{
    return emptyGeometryData<NURBPatch>(__func__, nurbPatchData);
}

TQ3Status Q3NURBPatch_SetControlPoint(TQ3GeometryObject nurbPatch, unsigned long rowIndex, unsigned long columnIndex,
                                      const TQ3RationalPoint4D* point4D)
{
    return guardStatus(__func__, [&] {
        NURBPatch& target = lookup<NURBPatch>(nurbPatch, "nurbPatch");
        requireNonNull(point4D, "point4D");
        target.setControlPoint(rowIndex, columnIndex, *point4D);
    });
}

TQ3Status Q3NURBPatch_GetControlPoint(TQ3GeometryObject nurbPatch, unsigned long rowIndex, unsigned long columnIndex,
                                      TQ3RationalPoint4D* point4D)
{
    return getValue<NURBPatch>(__func__, nurbPatch, "nurbPatch", point4D, "point4D",
                               [&](const NURBPatch& source) { return source.controlPoint(rowIndex, columnIndex); });
}

TQ3Status Q3NURBPatch_SetUKnot(TQ3GeometryObject nurbPatch, unsigned long knotIndex, float knotValue)
{
    return guardStatus(__func__, [&] { lookup<NURBPatch>(nurbPatch, "nurbPatch").setUKnot(knotIndex, knotValue); });
}

TQ3Status Q3NURBPatch_SetVKnot(TQ3GeometryObject nurbPatch, unsigned long knotIndex, float knotValue)
{
    return guardStatus(__func__, [&] { lookup<NURBPatch>(nurbPatch, "nurbPatch").setVKnot(knotIndex, knotValue); });
}

TQ3Status Q3NURBPatch_GetUKnot(TQ3GeometryObject nurbPatch, unsigned long knotIndex, float* knotValue)
{
    return getValue<NURBPatch>(__func__, nurbPatch, "nurbPatch", knotValue, "knotValue",
                               [&](const NURBPatch& source) { return source.uKnot(knotIndex); });
}

TQ3Status Q3NURBPatch_GetVKnot(TQ3GeometryObject nurbPatch, unsigned long knotIndex, float* knotValue)
{
    return getValue<NURBPatch>(__func__, nurbPatch, "nurbPatch", knotValue, "knotValue",
                               [&](const NURBPatch& source) { return source.vKnot(knotIndex); });
}

} // extern "C"
