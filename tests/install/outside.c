/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* A program outside the Q3 tree, built against an installed Q3 with
 * pkg-config, the way legacy code is: #include <QD3DGeometry.h>. */
#include <QD3D.h>
#include <QD3DErrors.h>
#include <QD3DGeometry.h>
#include <stdio.h>

int main(void)
{
    static TQ3RationalPoint4D points[4] = {{0, 0, 0, 1}, {1, 1, 0, 1}, {2, 0, 0, 1}, {3, 1, 0, 1}};
    static float knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    TQ3NURBCurveData data = {4, 4, points, knots, NULL};
    TQ3GeometryObject curve;
    float knot = -1.0f;

    if (Q3Initialize() != kQ3Success)
        return 1;
    curve = Q3NURBCurve_New(&data);
    if (curve == NULL)
        return 2;
    if (Q3NURBCurve_SetKnot(curve, 4, -1.0f) != kQ3Failure || Q3Error_Get(NULL) != kQ3ErrorInvalidParameter)
        return 3;
    if (Q3NURBCurve_GetKnot(curve, 7, &knot) != kQ3Success || knot != 1.0f)
        return 4;
    Q3Object_Dispose(curve);
    Q3Exit();
    printf("outside program OK\n");
    return 0;
}
