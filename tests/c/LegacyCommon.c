/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#include "LegacyCommon.h"

#include <QD3DErrors.h>
#include <QD3DGeometry.h>
#include <QD3DMath.h>

#include <stdio.h>
#include <string.h>

int gFailures = 0;

void Check(TQ3Boolean ok, const char *what)
{
    if (!ok) {
        printf("%s: %s failed (error %d: %s)\n", gMyProgramName, what, (int)Q3Error_Get(NULL), Q3Error_GetMessage());
        gFailures++;
    }
}

TQ3NURBCurveData MyBezierCurveData(TQ3RationalPoint4D *points)
{
    static float knots[8] = {0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f};
    TQ3NURBCurveData curveData;

    curveData.order = 4;
    curveData.numPoints = 4;
    curveData.controlPoints = points;
    curveData.knots = knots;
    curveData.curveAttributeSet = NULL;
    return curveData;
}

TQ3AttributeSet MyNewColorSet(float r, float g, float b)
{
    TQ3AttributeSet set;
    TQ3ColorRGB color;

    color.r = r;
    color.g = g;
    color.b = b;
    set = Q3AttributeSet_New();
    if (set != NULL)
        Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color);
    return set;
}

int MyStartBounding(TQ3ViewObject *view, TQ3AttributeSet *red)
{
    if (Q3Initialize() != kQ3Success)
        return 1;
    *view = Q3View_New();
    *red = MyNewColorSet(1.0f, 0.0f, 0.0f);
    return *view == NULL || *red == NULL ? 2 : 0;
}

int MyFinishBounding(TQ3ViewObject view, TQ3AttributeSet red, const char *summary)
{
    Q3Object_Dispose(red);
    Q3Object_Dispose(view);
    if (Q3Exit() != kQ3Success)
        gFailures++;
    if (gFailures == 0)
        printf("%s: %s\n", gMyProgramName, summary);
    return gFailures == 0 ? 0 : 3;
}

void MyCheckAndDisposeSet(TQ3AttributeSet set, TQ3AttributeSet expected, const char *what)
{
    Check((TQ3Boolean)(set == expected), what);
    if (set != NULL)
        Q3Object_Dispose(set);
}

void MyBoundAndDispose(TQ3ViewObject view, TQ3GeometryObject geometry)
{
    TQ3BoundingBox bounds;

    if (geometry == NULL) {
        gFailures++;
        return;
    }
    CHECK(Q3View_StartBoundingBox(view, kQ3ComputeBoundsExact));
    do {
        CHECK(Q3Geometry_Submit(geometry, view));
    } while (Q3View_EndBoundingBox(view, &bounds) == kQ3ViewStatusRetraverse);
    Check((TQ3Boolean)(bounds.isEmpty == kQ3False), "bounds");
    Q3Object_Dispose(geometry);
}

TQ3DrawContextObject MyNewPixmapDrawContext(void *pixels, unsigned long width, unsigned long height,
                                            unsigned long pixelSize, TQ3PixelType pixelType, TQ3Endian order)
{
    TQ3PixmapDrawContextData contextData;

    memset(&contextData, 0, sizeof contextData);
    contextData.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
    contextData.drawContextData.clearImageColor.a = 1.0f;
    contextData.pixmap.image = pixels;
    contextData.pixmap.width = width;
    contextData.pixmap.height = height;
    contextData.pixmap.rowBytes = width * (pixelSize / 8);
    contextData.pixmap.pixelSize = pixelSize;
    contextData.pixmap.pixelType = pixelType;
    contextData.pixmap.bitOrder = order;
    contextData.pixmap.byteOrder = order;
    return Q3PixmapDrawContext_New(&contextData);
}

TQ3DrawContextObject MyNewARGBDrawContext(void *pixels, unsigned long width, unsigned long height)
{
    return MyNewPixmapDrawContext(pixels, width, height, 32, kQ3PixelTypeARGB32, kQ3EndianBig);
}

/* Camera data at (0, 0, z) looking down -z (the point of interest the
 * origin, as zeroed), up +y, the whole view port, hither and yon as given. */
static void MySetFrontCamera(TQ3CameraData *camera, float z, float hither, float yon)
{
    Q3Point3D_Set(&camera->placement.cameraLocation, 0.0f, 0.0f, z);
    Q3Vector3D_Set(&camera->placement.upVector, 0.0f, 1.0f, 0.0f);
    camera->range.hither = hither;
    camera->range.yon = yon;
    camera->viewPort.origin.x = -1.0f;
    camera->viewPort.origin.y = 1.0f;
    camera->viewPort.width = 2.0f;
    camera->viewPort.height = 2.0f;
}

TQ3CameraObject MyNewOrthographicCamera(float z, float hither, float yon, float left, float top, float right,
                                        float bottom)
{
    TQ3OrthographicCameraData cameraData;

    memset(&cameraData, 0, sizeof cameraData);
    MySetFrontCamera(&cameraData.cameraData, z, hither, yon);
    cameraData.left = left;
    cameraData.top = top;
    cameraData.right = right;
    cameraData.bottom = bottom;
    return Q3OrthographicCamera_New(&cameraData);
}

TQ3CameraObject MyNewViewAngleCamera(float z, float hither, float yon, float fov)
{
    TQ3ViewAngleAspectCameraData cameraData;

    memset(&cameraData, 0, sizeof cameraData);
    MySetFrontCamera(&cameraData.cameraData, z, hither, yon);
    cameraData.fov = fov;
    cameraData.aspectRatioXToY = 1.0f;
    return Q3ViewAngleAspectCamera_New(&cameraData);
}
