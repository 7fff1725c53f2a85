/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#include "CCaller.h"

#include "QD3DDrawContext.h"
#include "QD3DErrors.h"
#include "QD3DExtension.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DIO.h"
#include "QD3DMath.h"
#include "QD3DLight.h"
#include "QD3DRenderer.h"
#include "QD3DShader.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

TQ3Status q3fuzz_SetPaneState(TQ3Object drawContext, int state)
{
    return Q3DrawContext_SetPaneState(drawContext, (TQ3Boolean)state);
}

TQ3Status q3fuzz_SetClearImageMethod(TQ3Object drawContext, int method)
{
    return Q3DrawContext_SetClearImageMethod(drawContext, (TQ3DrawContextClearImageMethod)method);
}

TQ3Status q3fuzz_ViewHints_SetClearImageMethod(TQ3Object viewHints, int method)
{
    return Q3ViewHints_SetClearImageMethod(viewHints, (TQ3DrawContextClearImageMethod)method);
}

TQ3Status q3fuzz_SetDoubleBufferBypass(TQ3Object renderer, int bypass)
{
    return Q3InteractiveRenderer_SetDoubleBufferBypass(renderer, (TQ3Boolean)bypass);
}

void q3fuzz_PostError(int code)
{
    Q3XError_Post((TQ3Error)code);
}

void q3fuzz_PostWarning(int code)
{
    Q3XWarning_Post((TQ3Warning)code);
}

void q3fuzz_PostNotice(int code)
{
    Q3XNotice_Post((TQ3Notice)code);
}

TQ3Status q3fuzz_GeneralPolygon_SetShapeHint(TQ3Object generalPolygon, int shapeHint)
{
    return Q3GeneralPolygon_SetShapeHint(generalPolygon, (TQ3GeneralPolygonShapeHint)shapeHint);
}

TQ3Status q3fuzz_StartBoundingBox(TQ3Object view, int computeBounds)
{
    return Q3View_StartBoundingBox(view, (TQ3ComputeBounds)computeBounds);
}

TQ3Status q3fuzz_StartBoundingSphere(TQ3Object view, int computeBounds)
{
    return Q3View_StartBoundingSphere(view, (TQ3ComputeBounds)computeBounds);
}

TQ3Status q3fuzz_CalcAndUseBoundingBox(TQ3Object group, int computeBounds, TQ3Object view)
{
    return Q3DisplayGroup_CalcAndUseBoundingBox(group, (TQ3ComputeBounds)computeBounds, view);
}

TQ3Status q3fuzz_RotateTransform_SetAxis(TQ3Object transform, int axis)
{
    return Q3RotateTransform_SetAxis(transform, (TQ3Axis)axis);
}

TQ3BoundingBox *q3fuzz_BoundingBox_Set(TQ3BoundingBox *bBox, const TQ3Point3D *min, const TQ3Point3D *max,
                                       int isEmpty)
{
    return Q3BoundingBox_Set(bBox, min, max, (TQ3Boolean)isEmpty);
}

TQ3BoundingSphere *q3fuzz_BoundingSphere_Set(TQ3BoundingSphere *bSphere, const TQ3Point3D *origin, float radius,
                                             int isEmpty)
{
    return Q3BoundingSphere_Set(bSphere, origin, radius, (TQ3Boolean)isEmpty);
}

TQ3Object q3fuzz_EnumStyle_New(int which, int value)
{
    switch (which) {
    case 0: return Q3FillStyle_New((TQ3FillStyle)value);
    case 1: return Q3BackfacingStyle_New((TQ3BackfacingStyle)value);
    case 2: return Q3InterpolationStyle_New((TQ3InterpolationStyle)value);
    case 3: return Q3OrientationStyle_New((TQ3OrientationStyle)value);
    case 4: return Q3CastShadowsStyle_New((TQ3Boolean)value);
    default: return Q3ReceiveShadowsStyle_New((TQ3Boolean)value);
    }
}

TQ3Status q3fuzz_EnumStyle_Submit(int which, int value, TQ3Object view)
{
    switch (which) {
    case 0: return Q3FillStyle_Submit((TQ3FillStyle)value, view);
    case 1: return Q3BackfacingStyle_Submit((TQ3BackfacingStyle)value, view);
    case 2: return Q3InterpolationStyle_Submit((TQ3InterpolationStyle)value, view);
    case 3: return Q3OrientationStyle_Submit((TQ3OrientationStyle)value, view);
    case 4: return Q3CastShadowsStyle_Submit((TQ3Boolean)value, view);
    default: return Q3ReceiveShadowsStyle_Submit((TQ3Boolean)value, view);
    }
}

TQ3Status q3fuzz_EnumStyle_Set(int which, TQ3Object style, int value)
{
    switch (which) {
    case 0: return Q3FillStyle_Set(style, (TQ3FillStyle)value);
    case 1: return Q3BackfacingStyle_Set(style, (TQ3BackfacingStyle)value);
    case 2: return Q3InterpolationStyle_Set(style, (TQ3InterpolationStyle)value);
    case 3: return Q3OrientationStyle_Set(style, (TQ3OrientationStyle)value);
    case 4: return Q3CastShadowsStyle_Set(style, (TQ3Boolean)value);
    default: return Q3ReceiveShadowsStyle_Set(style, (TQ3Boolean)value);
    }
}

TQ3Status q3fuzz_SetEnumField(int which, TQ3Object object, int value)
{
    switch (which) {
    case 0: return Q3Light_SetState(object, (TQ3Boolean)value);
    case 1: return Q3DirectionalLight_SetCastShadowsState(object, (TQ3Boolean)value);
    case 2: return Q3PointLight_SetCastShadowsState(object, (TQ3Boolean)value);
    case 3: return Q3PointLight_SetAttenuation(object, (TQ3AttenuationType)value);
    case 4: return Q3SpotLight_SetCastShadowsState(object, (TQ3Boolean)value);
    case 5: return Q3SpotLight_SetAttenuation(object, (TQ3AttenuationType)value);
    case 6: return Q3SpotLight_SetFallOff(object, (TQ3FallOffType)value);
    case 7: return Q3Shader_SetUBoundary(object, (TQ3ShaderUVBoundary)value);
    default: return Q3Shader_SetVBoundary(object, (TQ3ShaderUVBoundary)value);
    }
}
