/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Legacy code for the QuickDraw 3D 1.6 NURB patch, written the way 1990s
 * Macintosh samples were (declarations first, Apple's headers by their own
 * names, every status checked), built with nothing but -I include/Q3: it must
 * compile unmodified against Q3. It makes a trimmed bicubic patch, calls all
 * eleven Q3NURBPatch routines, bounds it and submits it in immediate mode.
 * Returns 0 when every call did what the 1.6 API promises.
 */
#include <QD3D.h>
#include <QD3DErrors.h>
#include <QD3DGeometry.h>
#include <QD3DSet.h>
#include <QD3DStyle.h>
#include <QD3DView.h>

#include <stdio.h>

#include "LegacyCommon.h"

const char *gMyProgramName = "LegacyPatches";

static TQ3RationalPoint4D gPoints[16];
static float gKnots[8] = {0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f};
static TQ3RationalPoint3D gHolePoints[5] = {
    {0.25f, 0.25f, 1.0f}, {0.25f, 0.75f, 1.0f}, {0.75f, 0.75f, 1.0f}, {0.75f, 0.25f, 1.0f}, {0.25f, 0.25f, 1.0f}};
static float gHoleKnots[7] = {0.0f, 0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 4.0f};

static void MyFillPatch(TQ3NURBPatchData *patchData, TQ3NURBPatchTrimLoopData *loop,
                        TQ3NURBPatchTrimCurveData *curve)
{
    short row, column;

    for (row = 0; row < 4; row++)
        for (column = 0; column < 4; column++) {
            gPoints[row * 4 + column].x = (float)column;
            gPoints[row * 4 + column].y = (float)((row + column) % 2);
            gPoints[row * 4 + column].z = (float)row;
            gPoints[row * 4 + column].w = 1.0f;
        }
    curve->order = 2;
    curve->numPoints = 5;
    curve->controlPoints = gHolePoints; /* clockwise: a hole */
    curve->knots = gHoleKnots;
    loop->numTrimCurves = 1;
    loop->trimCurves = curve;

    patchData->uOrder = 4;
    patchData->vOrder = 4;
    patchData->numRows = 4;
    patchData->numColumns = 4;
    patchData->controlPoints = gPoints;
    patchData->uKnots = gKnots;
    patchData->vKnots = gKnots;
    patchData->numTrimLoops = 1;
    patchData->trimLoops = loop;
    patchData->patchAttributeSet = NULL;
}

int main(void)
{
    TQ3ViewObject view;
    TQ3GeometryObject patch;
    TQ3NURBPatchData patchData, readBack;
    TQ3NURBPatchTrimLoopData loop;
    TQ3NURBPatchTrimCurveData curve;
    TQ3RationalPoint4D point;
    TQ3BoundingBox bounds;
    float knot;

    if (Q3Initialize() != kQ3Success)
        return 1;
    view = Q3View_New();
    if (view == NULL)
        return 2;

    MyFillPatch(&patchData, &loop, &curve);
    patch = Q3NURBPatch_New(&patchData);
    if (patch == NULL)
        return 4;

    CHECK(Q3NURBPatch_GetControlPoint(patch, 3, 2, &point));
    Check((TQ3Boolean)(point.x == 2.0f && point.z == 3.0f), "control point (3, 2)");
    point.y = 2.0f;
    CHECK(Q3NURBPatch_SetControlPoint(patch, 3, 2, &point));
    CHECK(Q3NURBPatch_SetUKnot(patch, 0, -0.5f));
    CHECK(Q3NURBPatch_GetUKnot(patch, 0, &knot));
    Check((TQ3Boolean)(knot == -0.5f), "u knot 0");
    CHECK(Q3NURBPatch_SetVKnot(patch, 7, 1.5f));
    CHECK(Q3NURBPatch_GetVKnot(patch, 7, &knot));
    Check((TQ3Boolean)(knot == 1.5f), "v knot 7");
    Check((TQ3Boolean)(Q3NURBPatch_SetUKnot(patch, 8, 0.0f) == kQ3Failure), "u knot 8 refused");

    CHECK(Q3NURBPatch_GetData(patch, &readBack));
    Check((TQ3Boolean)(readBack.numTrimLoops == 1 && readBack.trimLoops[0].numTrimCurves == 1 &&
                       readBack.controlPoints[14].y == 2.0f && readBack.uKnots[0] == -0.5f),
          "GetData");
    CHECK(Q3NURBPatch_EmptyData(&readBack));
    CHECK(Q3NURBPatch_SetData(patch, &patchData));

    CHECK(Q3View_StartBoundingBox(view, kQ3ComputeBoundsExact));
    do {
        CHECK(Q3Geometry_Submit(patch, view));
        CHECK(Q3NURBPatch_Submit(&patchData, view));
    } while (Q3View_EndBoundingBox(view, &bounds) == kQ3ViewStatusRetraverse);
    Check((TQ3Boolean)(bounds.isEmpty == kQ3False && bounds.min.x == 0.0f && bounds.max.z == 3.0f), "bounds");

    Q3Object_Dispose(patch);
    Q3Object_Dispose(view);
    if (Q3Exit() != kQ3Success)
        gFailures++;
    if (gFailures == 0)
        printf("LegacyPatches: every 1.6 NURB patch call worked\n");
    return gFailures == 0 ? 0 : 3;
}
