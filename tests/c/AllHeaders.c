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

#include <stdio.h>
#include <string.h>

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
        /* The quadrics and solids' data structures and calls, from C. */
        TQ3BoxData box;
        TQ3ConeData cone;
        TQ3CylinderData cylinder;
        TQ3DiskData disk;
        TQ3EllipseData ellipse;
        TQ3EllipsoidData ellipsoid;
        TQ3TorusData torus;
        memset(&box, 0, sizeof box);
        memset(&cone, 0, sizeof cone);
        memset(&cylinder, 0, sizeof cylinder);
        memset(&disk, 0, sizeof disk);
        memset(&ellipse, 0, sizeof ellipse);
        memset(&ellipsoid, 0, sizeof ellipsoid);
        memset(&torus, 0, sizeof torus);
        if (Q3Box_New(&box) != NULL || Q3Error_Get(NULL) != kQ3ErrorDegenerateGeometry ||
            Q3Cone_New(&cone) != NULL || Q3Cylinder_New(&cylinder) != NULL || Q3Disk_New(&disk) != NULL ||
            Q3Ellipse_New(&ellipse) != NULL || Q3Ellipsoid_New(&ellipsoid) != NULL ||
            Q3Torus_New(&torus) != NULL || Q3Torus_SetRatio(NULL, 1.0f) != kQ3Failure ||
            Q3Box_GetFaceAttributeSet(NULL, 0, NULL) != kQ3Failure ||
            kQ3SubdivisionMaxTrianglesPerSurface < 1)
            return 4;
    }
    Q3Exit();
    printf("C99 headers OK (%lu.%lu), data.curveAttributeSet=%p\n", major, minor,
           (void *)data.curveAttributeSet);
    return 0;
}
