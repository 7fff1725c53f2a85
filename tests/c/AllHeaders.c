/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* Proves that every public header compiles as strict C99 with warnings as
 * errors, together and in any order, and that the C ABI links and runs. */
#include "QD3D.h"
#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DErrors.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DMath.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

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
        TQ3GroupObject group = Q3DisplayGroup_New();
        TQ3StateOperatorObject push = Q3Push_New();
        TQ3GroupPosition position = NULL;
        unsigned long count = 0;
        if (group == NULL || push == NULL || Q3Group_AddObject(group, push) == NULL)
            return 4;
        if (Q3Group_CountObjects(group, &count) != kQ3Success || count != 1 ||
            Q3Group_GetFirstPosition(group, &position) != kQ3Success || position == NULL)
            return 5;
        Q3Object_Dispose(push);
        Q3Object_Dispose(group);
    }
    Q3Exit();
    printf("C99 headers OK (%lu.%lu), data.curveAttributeSet=%p\n", major, minor,
           (void *)data.curveAttributeSet);
    return 0;
}
