/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* Listing 3 ("Converting a Bezier curve to NURB format") with the article's
 * BezierCurve structure. Both assume the application defines Point3D; the
 * listing also uses TQ3RationalPoint4D_Set and the field name
 * nurbCurveAttributes, which Q3's headers provide as article-compatibility
 * aliases (QD3DMath.h, QD3DGeometry.h). */
#include "ListingWrappers.h"

#include "QD3DMath.h"

#include <stdlib.h>

typedef struct Point3D {
    float x;
    float y;
    float z;
} Point3D;

#include "bezier_curve_struct.c.txt"

#include "listing3_bezier_to_nurb.c.txt"

TQ3NURBCurveData *q3listing3_bezier_to_nurb(unsigned int order, const float *xyz)
{
    Point3D points[16];
    BezierCurve bezier;
    unsigned int i;

    if (order > 16)
        return NULL;
    for (i = 0; i < order; i++) {
        points[i].x = xyz[3 * i];
        points[i].y = xyz[3 * i + 1];
        points[i].z = xyz[3 * i + 2];
    }
    bezier.order = order;
    bezier.controlPoints = points;
    return BezierToNURBCurve(&bezier);
}
