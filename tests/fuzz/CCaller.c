/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#include "CCaller.h"

#include "QD3DDrawContext.h"
#include "QD3DMath.h"
#include "QD3DRenderer.h"
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

TQ3Status q3fuzz_SetDoubleBufferBypass(TQ3Object renderer, int bypass)
{
    return Q3InteractiveRenderer_SetDoubleBufferBypass(renderer, (TQ3Boolean)bypass);
}

TQ3Status q3fuzz_StartBoundingBox(TQ3Object view, int computeBounds)
{
    return Q3View_StartBoundingBox(view, (TQ3ComputeBounds)computeBounds);
}

TQ3Status q3fuzz_StartBoundingSphere(TQ3Object view, int computeBounds)
{
    return Q3View_StartBoundingSphere(view, (TQ3ComputeBounds)computeBounds);
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
