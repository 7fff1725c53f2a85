/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3_FUZZ_CCALLER_H
#define Q3_FUZZ_CCALLER_H

/*
 * Calls that take an enumeration by value, made from C as a legacy caller
 * makes them: in C any int converts to an enum type, so these pass values
 * outside the enumeration (which C++ code cannot even form without undefined
 * behaviour).
 */

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

TQ3Status q3fuzz_SetPaneState(TQ3Object drawContext, int state);
TQ3Status q3fuzz_SetClearImageMethod(TQ3Object drawContext, int method);
TQ3Status q3fuzz_SetDoubleBufferBypass(TQ3Object renderer, int bypass);
TQ3Status q3fuzz_StartBoundingBox(TQ3Object view, int computeBounds);
TQ3Status q3fuzz_StartBoundingSphere(TQ3Object view, int computeBounds);
TQ3Status q3fuzz_RotateTransform_SetAxis(TQ3Object transform, int axis);
TQ3BoundingBox *q3fuzz_BoundingBox_Set(TQ3BoundingBox *bBox, const TQ3Point3D *min, const TQ3Point3D *max,
                                       int isEmpty);
TQ3BoundingSphere *q3fuzz_BoundingSphere_Set(TQ3BoundingSphere *bSphere, const TQ3Point3D *origin, float radius,
                                             int isEmpty);

#ifdef __cplusplus
}
#endif

#endif /* Q3_FUZZ_CCALLER_H */
