// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/Entry.h"
#include "geometry/NURBCurve.h"
#include "view/View.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3GeometryObject Q3NURBCurve_New(const TQ3NURBCurveData* curveData)
{
    return guard(__func__, TQ3GeometryObject{nullptr}, [&]() -> TQ3GeometryObject {
        validateNURBCurveData(curveData);
        return makeShared<NURBCurve>(*curveData).detach();
    });
}

TQ3Status Q3NURBCurve_Submit(const TQ3NURBCurveData* curveData, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        requireNonNull(curveData, "curveData");
        ShapeVisitor& target = lookup<View>(view, "view").submitTarget();
        validateNURBCurveData(curveData);
        const Ref<AttributeSet> attributes =
            attributeSetFromHandle(curveData->curveAttributeSet, "curveAttributeSet");
        target.visitNURBCurve(curveRefOf(*curveData), attributes.get(), nullptr);
    });
}

TQ3Status Q3NURBCurve_SetData(TQ3GeometryObject curve, const TQ3NURBCurveData* nurbCurveData)
{
    return guardStatus(__func__, [&] {
        NURBCurve& target = lookup<NURBCurve>(curve, "curve");
        requireNonNull(nurbCurveData, "nurbCurveData");
        target.setData(*nurbCurveData);
    });
}

TQ3Status Q3NURBCurve_GetData(TQ3GeometryObject curve, TQ3NURBCurveData* nurbCurveData)
{
    return guardStatus(__func__, [&] {
        const NURBCurve& source = lookup<NURBCurve>(curve, "curve");
        requireNonNull(nurbCurveData, "nurbCurveData");
        source.getData(*nurbCurveData);
    });
}

TQ3Status Q3NURBCurve_EmptyData(TQ3NURBCurveData* nurbCurveData)
{
    return guardStatus(__func__, [&] {
        requireNonNull(nurbCurveData, "nurbCurveData");
        NURBCurve::emptyData(*nurbCurveData);
    });
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
    return guardStatus(__func__, [&] {
        const NURBCurve& source = lookup<NURBCurve>(curve, "curve");
        requireNonNull(point4D, "point4D");
        *point4D = source.controlPoint(pointIndex);
    });
}

TQ3Status Q3NURBCurve_SetKnot(TQ3GeometryObject curve, unsigned long knotIndex, float knotValue)
{
    return guardStatus(__func__,
                       [&] { lookup<NURBCurve>(curve, "curve").setKnot(knotIndex, knotValue); });
}

TQ3Status Q3NURBCurve_GetKnot(TQ3GeometryObject curve, unsigned long knotIndex, float* knotValue)
{
    return guardStatus(__func__, [&] {
        const NURBCurve& source = lookup<NURBCurve>(curve, "curve");
        requireNonNull(knotValue, "knotValue");
        *knotValue = source.knot(knotIndex);
    });
}

} // extern "C"
