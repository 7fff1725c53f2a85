// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/NURBCurve.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3NURBCurve_New(const TQ3NURBCurveData* curveData)
{
    return newGeometry<NURBCurve>(__func__, curveData);
}

TQ3Status Q3NURBCurve_Submit(const TQ3NURBCurveData* curveData, TQ3ViewObject view)
{
    return submitGeometry<NURBCurve>(__func__, curveData, view);
}

TQ3Status Q3NURBCurve_SetData(TQ3GeometryObject curve, const TQ3NURBCurveData* nurbCurveData)
{
    return setGeometryData<NURBCurve>(__func__, curve, nurbCurveData);
}

TQ3Status Q3NURBCurve_GetData(TQ3GeometryObject curve, TQ3NURBCurveData* nurbCurveData)
{
    return getGeometryData<NURBCurve>(__func__, curve, nurbCurveData);
}

TQ3Status Q3NURBCurve_EmptyData(TQ3NURBCurveData* nurbCurveData)
{
    return emptyGeometryData<NURBCurve>(__func__, nurbCurveData);
}

TQ3Status Q3NURBCurve_SetControlPoint(TQ3GeometryObject curve, unsigned long pointIndex,
                                      const TQ3RationalPoint4D* point4D)
{
    return guardStatus(__func__, [&] {
        NURBCurve& target = lookup<NURBCurve>(curve, "curve");
        requireNonNull(point4D, "point4D");
        target.setControlPoint(pointIndex, *point4D);
    });
}

TQ3Status Q3NURBCurve_GetControlPoint(TQ3GeometryObject curve, unsigned long pointIndex,
                                      TQ3RationalPoint4D* point4D)
{
    return getValue<NURBCurve>(__func__, curve, "curve", point4D, "point4D",
                               [&](const NURBCurve& source) { return source.controlPoint(pointIndex); });
}

TQ3Status Q3NURBCurve_SetKnot(TQ3GeometryObject curve, unsigned long knotIndex, float knotValue)
{
    return guardStatus(__func__,
                       [&] { lookup<NURBCurve>(curve, "curve").setKnot(knotIndex, knotValue); });
}

TQ3Status Q3NURBCurve_GetKnot(TQ3GeometryObject curve, unsigned long knotIndex, float* knotValue)
{
    return getValue<NURBCurve>(__func__, curve, "curve", knotValue, "knotValue",
                               [&](const NURBCurve& source) { return source.knot(knotIndex); });
}

} // extern "C"
