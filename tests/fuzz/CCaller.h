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
TQ3Status q3fuzz_ViewHints_SetClearImageMethod(TQ3Object viewHints, int method);
TQ3Status q3fuzz_SetDoubleBufferBypass(TQ3Object renderer, int bypass);
TQ3Status q3fuzz_StartBoundingBox(TQ3Object view, int computeBounds);
TQ3Status q3fuzz_StartBoundingSphere(TQ3Object view, int computeBounds);
TQ3Status q3fuzz_CalcAndUseBoundingBox(TQ3Object group, int computeBounds, TQ3Object view);
TQ3Status q3fuzz_RotateTransform_SetAxis(TQ3Object transform, int axis);
TQ3Status q3fuzz_GeneralPolygon_SetShapeHint(TQ3Object generalPolygon, int shapeHint);
/* Q3XError_Post, Q3XWarning_Post and Q3XNotice_Post of any int. */
void q3fuzz_PostError(int code);
void q3fuzz_PostWarning(int code);
void q3fuzz_PostNotice(int code);
TQ3BoundingBox *q3fuzz_BoundingBox_Set(TQ3BoundingBox *bBox, const TQ3Point3D *min, const TQ3Point3D *max,
                                       int isEmpty);
TQ3BoundingSphere *q3fuzz_BoundingSphere_Set(TQ3BoundingSphere *bSphere, const TQ3Point3D *origin, float radius,
                                             int isEmpty);

/* Styles, shaders and lights (QD3DStyle.h, QD3DShader.h, QD3DLight.h).
 * `which` picks the style: 0 fill, 1 backfacing, 2 interpolation,
 * 3 orientation, 4 cast shadows, 5 receive shadows. */
TQ3Object q3fuzz_EnumStyle_New(int which, int value);
TQ3Status q3fuzz_EnumStyle_Submit(int which, int value, TQ3Object view);
TQ3Status q3fuzz_EnumStyle_Set(int which, TQ3Object style, int value);
/* `which`: 0 Q3Light_SetState, 1 Q3DirectionalLight_SetCastShadowsState,
 * 2 Q3PointLight_SetCastShadowsState, 3 Q3PointLight_SetAttenuation,
 * 4 Q3SpotLight_SetCastShadowsState, 5 Q3SpotLight_SetAttenuation,
 * 6 Q3SpotLight_SetFallOff, 7 Q3Shader_SetUBoundary, 8 Q3Shader_SetVBoundary. */
TQ3Status q3fuzz_SetEnumField(int which, TQ3Object object, int value);

#ifdef __cplusplus
}
#endif

#endif /* Q3_FUZZ_CCALLER_H */
