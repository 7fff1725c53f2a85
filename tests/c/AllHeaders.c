/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* Proves that every public header compiles as strict C99 with warnings as
 * errors, together and in any order, and that the C ABI links and runs. */
#include "QD3D.h"
#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DErrors.h"
#include "QD3DGeometry.h"
#include "QD3DMath.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"
#include "QD3DView.h"
#include "Q3NURBCurveTools.h"

#include <stdio.h>

int main(void)
{
    TQ3NURBCurveData data;
    TQ3SubdivisionStyleData style;
    TQ3GeometryObject curve = NULL;
    unsigned long major = 0, minor = 0;

    data.curveAttributeSet = NULL;
    style.method = kQ3SubdivisionMethodConstant;
    style.c1 = style.c2 = 5.0f;
    (void)style;
    (void)curve;
    if (Q3Initialize() != kQ3Success)
        return 1;
    if (Q3GetVersion(&major, &minor) != kQ3Success || major != 1 || minor != 6)
        return 2;
    if (Q3NURBCurve_New(NULL) != NULL || Q3Error_Get(NULL) != kQ3ErrorNULLParameter)
        return 3;
    {
        /* A curve tool from C: Listing 1's cubic, evaluated at its middle. */
        static TQ3RationalPoint4D points[4] = {{0, 0, 0, 1}, {1, 1, 0, 1}, {2, 0, 0, 1}, {3, 1, 0, 1}};
        static float knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
        TQ3NURBCurveData listing1;
        TQ3Point3D middle;
        TQ3NURBCurveParameterization how = kQ3NURBCurveParameterizationCentripetal;
        listing1.order = 4;
        listing1.numPoints = 4;
        listing1.controlPoints = points;
        listing1.knots = knots;
        listing1.curveAttributeSet = NULL;
        (void)how;
        if (Q3NURBCurveData_Evaluate(&listing1, 0.5f, &middle) != kQ3Success || middle.x != 1.5f)
            return 4;
    }
    Q3Exit();
    printf("C99 headers OK (%lu.%lu), data.curveAttributeSet=%p\n", major, minor,
           (void *)data.curveAttributeSet);
    return 0;
}
