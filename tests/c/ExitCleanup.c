/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * A QuickDraw 3D program that tidies up in an atexit handler, as many 1990s
 * programs did. By then the C runtime has destroyed the main thread's
 * thread_local objects (glibc runs them before atexit handlers), so the
 * handler's calls must not reach them: it draws a group holding a nested
 * group and a NURB curve under screen-space subdivision (the curve's sample
 * tables), disposes of the groups (the group release queue), and checks that
 * an error posted then is seen by Q3Error_Get (the error state). main makes
 * the same calls first, so every one of those objects exists and is
 * destroyed before the handler runs. Under AddressSanitizer (CI) a use after
 * free would stop the program; the exit status says whether every call
 * behaved.
 *
 * Built a second time with MY_HANDLER_FIRST: the handler is registered
 * before Q3Initialize, as a C++ program's static objects' destructors are
 * (before main). It then runs after the exit handlers of the rendering
 * library Q3 loaded at the first draw (Mesa's), when no OpenGL call is
 * safe: its draw must fail with an error posted, not crash, and the rest of
 * its calls must work as in the first build.
 */
#include <QD3D.h>
#include <QD3DCamera.h>
#include <QD3DDrawContext.h>
#include <QD3DErrors.h>
#include <QD3DGeometry.h>
#include <QD3DGroup.h>
#include <QD3DMath.h>
#include <QD3DRenderer.h>
#include <QD3DStyle.h>
#include <QD3DView.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "LegacyCommon.h"

const char *gMyProgramName = "ExitCleanup";

#ifdef MY_HANDLER_FIRST
#define MY_RENDERER kQ3RendererTypeInteractive
#else
#define MY_RENDERER kQ3RendererTypeWireFrame
#endif

static TQ3ViewObject gView = NULL;
static TQ3DrawContextObject gContext = NULL;
static TQ3GroupObject gScene = NULL;
static unsigned char gPixels[64 * 64 * 4];

static TQ3GroupObject MyMakeScene(void)
{
    static TQ3RationalPoint4D points[4] = {
        {-1.0f, -1.0f, 0.0f, 1.0f}, {-0.5f, 1.0f, 0.0f, 1.0f}, {0.5f, -1.0f, 0.0f, 1.0f}, {1.0f, 1.0f, 0.0f, 1.0f}};
    TQ3NURBCurveData curveData = MyBezierCurveData(points);
    TQ3GroupObject outer, inner;
    TQ3GeometryObject curve;

    curve = Q3NURBCurve_New(&curveData);
    outer = Q3DisplayGroup_New();
    inner = Q3DisplayGroup_New();
    if (curve == NULL || outer == NULL || inner == NULL)
        return NULL;
    Q3Group_AddObject(inner, curve);
    Q3Group_AddObject(outer, inner);
    Q3Object_Dispose(curve);
    Q3Object_Dispose(inner);
    return outer;
}

/* Draws the scene once under screen-space subdivision; returns the count of
 * lit pixels, or -1 when a call failed. */
static long MyDraw(TQ3GroupObject scene)
{
    TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodScreenSpace, 2.0f, 2.0f};
    TQ3ViewStatus status;
    long lit = 0, i;

    if (Q3View_StartRendering(gView) != kQ3Success)
        return -1;
    do {
        Q3SubdivisionStyle_Submit(&style, gView);
        Q3DisplayGroup_Submit(scene, gView);
        status = Q3View_EndRendering(gView);
    } while (status == kQ3ViewStatusRetraverse);
    if (status != kQ3ViewStatusDone)
        return -1;
    for (i = 0; i < 64 * 64; i++)
        if (gPixels[4 * i + 1] != 0 || gPixels[4 * i + 2] != 0 || gPixels[4 * i + 3] != 0)
            lit++;
    return lit;
}

/* The same calls as main's; exits with 1 when one misbehaves. */
static void MyCleanUp(void)
{
    TQ3GroupObject again = MyMakeScene();
    long lit = again == NULL ? -1 : MyDraw(again);

#ifdef MY_HANDLER_FIRST
    if (again == NULL || lit != -1 || Q3Error_Get(NULL) != kQ3ErrorRenderingLoopFailed) {
        printf("ExitCleanup: a draw after Mesa's exit handlers did not fail with an error (%ld pixels)\n", lit);
        fflush(stdout);
        _Exit(1);
    }
#else
    if (lit <= 0) {
        printf("ExitCleanup: drawing in the atexit handler failed (%ld pixels)\n", lit);
        fflush(stdout);
        _Exit(1);
    }
#endif
    Q3Object_Dispose(again);
    Q3Object_Dispose(gScene);
    if (Q3Object_Dispose(NULL) != kQ3Failure || Q3Error_Get(NULL) != kQ3ErrorNULLParameter) {
        printf("ExitCleanup: an error posted in the atexit handler was not seen\n");
        fflush(stdout);
        _Exit(1);
    }
    Q3Object_Dispose(gView);
    Q3Object_Dispose(gContext);
    if (Q3Exit() != kQ3Success) {
        printf("ExitCleanup: Q3Exit failed\n");
        fflush(stdout);
        _Exit(1);
    }
}

int main(void)
{
    TQ3CameraObject camera;

#ifdef MY_HANDLER_FIRST
    if (atexit(MyCleanUp) != 0)
        return 1;
#endif
    if (Q3Initialize() != kQ3Success)
        return 1;
    gContext = MyNewARGBDrawContext(gPixels, 64, 64);
    camera = MyNewOrthographicCamera(5.0f, 0.5f, 20.0f, -1.5f, 1.5f, 1.5f, -1.5f);
    gView = Q3View_New();
    gScene = MyMakeScene();
    if (gContext == NULL || camera == NULL || gView == NULL || gScene == NULL)
        return 1;
    Q3View_SetDrawContext(gView, gContext);
    Q3View_SetCamera(gView, camera);
    Q3View_SetRendererByType(gView, MY_RENDERER);
    Q3Object_Dispose(camera);
    if (MyDraw(gScene) <= 0 || Q3Object_Dispose(NULL) != kQ3Failure) {
        printf("ExitCleanup: drawing in main failed\n");
        return 1;
    }
#ifndef MY_HANDLER_FIRST
    if (atexit(MyCleanUp) != 0)
        return 1;
#endif
    return 0;
}
