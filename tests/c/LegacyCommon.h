/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * The utility routines the legacy test programs share, kept in one file of
 * their own as 1990s QuickDraw 3D samples kept theirs. Each program defines
 * gMyProgramName (the prefix of its failure messages) and counts its
 * failures in gFailures.
 */
#ifndef LEGACY_COMMON_H
#define LEGACY_COMMON_H

#include <QD3D.h>
#include <QD3DCamera.h>
#include <QD3DDrawContext.h>
#include <QD3DGeometry.h>
#include <QD3DSet.h>
#include <QD3DView.h>

extern const char *gMyProgramName;
extern int gFailures;

/* Counts a failure and prints what failed with the latest error and its
 * message (Q3Error_GetMessage, a Q3 extension). */
void Check(TQ3Boolean ok, const char *what);

#define CHECK(call) Check((TQ3Boolean)((call) == kQ3Success), #call)
#define EXPECT(condition) Check((TQ3Boolean)((condition) != 0), #condition)

/* Initializes QuickDraw 3D and makes a view and a red attribute set for a
 * program that bounds its geometries; returns 0, or the exit status to end
 * with (1: Q3Initialize failed, 2: no view or set). */
int MyStartBounding(TQ3ViewObject *view, TQ3AttributeSet *red);

/* Disposes of what MyStartBounding made, exits QuickDraw 3D (a failure if
 * that fails) and returns the exit status: 0 with `summary` printed when no
 * check failed, 3 otherwise. */
int MyFinishBounding(TQ3ViewObject view, TQ3AttributeSet red, const char *summary);

/* A cubic Bezier span over four `points`: order 4, knots 0 0 0 0 1 1 1 1,
 * no attribute set. */
TQ3NURBCurveData MyBezierCurveData(TQ3RationalPoint4D *points);

/* A new attribute set holding a diffuse colour. */
TQ3AttributeSet MyNewColorSet(float r, float g, float b);

/* Checks that a Get call gave `expected` back and disposes of the reference. */
void MyCheckAndDisposeSet(TQ3AttributeSet set, TQ3AttributeSet expected, const char *what);

/* Bounds a geometry exactly in `view`, checks the box is not empty and
 * disposes of the geometry. */
void MyBoundAndDispose(TQ3ViewObject view, TQ3GeometryObject geometry);

/* A pixmap draw context over `pixels` (width x height, rows without
 * padding, pixelSize bits a pixel of pixelType, bits and bytes in `order`),
 * cleared to opaque black; no pane, no mask, single-buffered. */
TQ3DrawContextObject MyNewPixmapDrawContext(void *pixels, unsigned long width, unsigned long height,
                                            unsigned long pixelSize, TQ3PixelType pixelType, TQ3Endian order);

/* The same for ARGB32 big-endian. */
TQ3DrawContextObject MyNewARGBDrawContext(void *pixels, unsigned long width, unsigned long height);

/* An orthographic camera at (0, 0, z) looking down -z, up +y, showing
 * left..right by bottom..top, hither and yon as given. */
TQ3CameraObject MyNewOrthographicCamera(float z, float hither, float yon, float left, float top, float right,
                                        float bottom);

/* A view angle aspect camera at (0, 0, z) looking down -z, up +y, square,
 * with the field of view and hither and yon as given. */
TQ3CameraObject MyNewViewAngleCamera(float z, float hither, float yon, float fov);

#endif
