/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#include "box_document.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DMath.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <stdlib.h>
#include <string.h>

struct BoxDocument {
    unsigned long width, height;
    unsigned char *argb;         /* the pixmap's memory, ARGB32 big-endian */
    TQ3ViewObject view;
    TQ3GroupObject model;        /* shader, colour, rotation, box */
    TQ3TransformObject rotation; /* also in model: turned every frame */
};

static void dispose(TQ3Object object)
{
    if (object != NULL)
        Q3Object_Dispose(object);
}

/* Adds object to group and gives up the caller's reference to it. */
static int add(TQ3GroupObject group, TQ3Object object)
{
    int ok = object != NULL && Q3Group_AddObject(group, object) != NULL;
    dispose(object);
    return ok;
}

static TQ3GroupObject new_model(TQ3TransformObject rotation)
{
    TQ3GroupObject model = Q3DisplayGroup_New();
    TQ3AttributeSet colour = Q3AttributeSet_New();
    TQ3ColorRGB diffuse;
    TQ3BoxData box;
    int ok;

    diffuse.r = 0.95f;
    diffuse.g = 0.55f;
    diffuse.b = 0.15f;
    memset(&box, 0, sizeof box);
    box.origin.x = box.origin.y = box.origin.z = -1.0f;
    box.orientation.y = 2.0f;
    box.majorAxis.z = 2.0f;
    box.minorAxis.x = 2.0f;
    ok = model != NULL && colour != NULL &&
         Q3AttributeSet_Add(colour, kQ3AttributeTypeDiffuseColor, &diffuse) == kQ3Success &&
         add(model, Q3PhongIllumination_New()) && Q3Group_AddObject(model, colour) != NULL &&
         Q3Group_AddObject(model, rotation) != NULL && add(model, Q3Box_New(&box));
    dispose(colour);
    if (!ok) {
        dispose(model);
        return NULL;
    }
    return model;
}

static TQ3GroupObject new_lights(void)
{
    TQ3GroupObject lights = Q3LightGroup_New();
    TQ3LightData ambient;
    TQ3DirectionalLightData directional;

    ambient.isOn = kQ3True;
    ambient.brightness = 0.25f;
    ambient.color.r = ambient.color.g = ambient.color.b = 1.0f;
    directional.lightData = ambient;
    directional.lightData.brightness = 1.0f;
    directional.castsShadows = kQ3False;
    directional.direction.x = 0.6f;
    directional.direction.y = -0.7f;
    directional.direction.z = -1.0f;
    if (lights == NULL || !add(lights, Q3AmbientLight_New(&ambient)) ||
        !add(lights, Q3DirectionalLight_New(&directional))) {
        dispose(lights);
        return NULL;
    }
    return lights;
}

static TQ3ViewObject new_view(BoxDocument *document)
{
    TQ3PixmapDrawContextData context;
    TQ3ViewAngleAspectCameraData camera;
    TQ3DrawContextObject drawContext;
    TQ3CameraObject cameraObject;
    TQ3GroupObject lights = new_lights();
    TQ3ViewObject view = Q3View_New();
    int ok;

    memset(&context, 0, sizeof context);
    context.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
    context.drawContextData.clearImageColor.a = 1.0f;
    context.drawContextData.clearImageColor.r = 0.16f;
    context.drawContextData.clearImageColor.g = 0.18f;
    context.drawContextData.clearImageColor.b = 0.26f;
    context.pixmap.image = document->argb;
    context.pixmap.width = document->width;
    context.pixmap.height = document->height;
    context.pixmap.rowBytes = document->width * 4;
    context.pixmap.pixelSize = 32;
    context.pixmap.pixelType = kQ3PixelTypeARGB32;
    context.pixmap.bitOrder = kQ3EndianBig;
    context.pixmap.byteOrder = kQ3EndianBig;
    drawContext = Q3PixmapDrawContext_New(&context);

    memset(&camera, 0, sizeof camera);
    camera.cameraData.placement.cameraLocation.z = 7.0f;
    camera.cameraData.placement.upVector.y = 1.0f;
    camera.cameraData.range.hither = 1.0f;
    camera.cameraData.range.yon = 20.0f;
    camera.cameraData.viewPort.origin.x = -1.0f;
    camera.cameraData.viewPort.origin.y = 1.0f;
    camera.cameraData.viewPort.width = 2.0f;
    camera.cameraData.viewPort.height = 2.0f;
    camera.fov = Q3Math_DegreesToRadians(40.0f);
    camera.aspectRatioXToY = (float)document->width / (float)document->height;
    cameraObject = Q3ViewAngleAspectCamera_New(&camera);

    ok = view != NULL && drawContext != NULL && cameraObject != NULL && lights != NULL &&
         Q3View_SetDrawContext(view, drawContext) == kQ3Success &&
         Q3View_SetCamera(view, cameraObject) == kQ3Success &&
         Q3View_SetRendererByType(view, kQ3RendererTypeInteractive) == kQ3Success &&
         Q3View_SetLightGroup(view, lights) == kQ3Success;
    dispose(drawContext);
    dispose(cameraObject);
    dispose(lights);
    if (!ok) {
        dispose(view);
        return NULL;
    }
    return view;
}

BoxDocument *box_document_new(unsigned long width, unsigned long height)
{
    BoxDocument *document;
    TQ3Matrix4x4 identity;

    if (width == 0 || height == 0)
        return NULL;
    document = calloc(1, sizeof *document);
    if (document == NULL)
        return NULL;
    document->width = width;
    document->height = height;
    document->argb = calloc(width * height, 4);
    document->rotation = Q3MatrixTransform_New(Q3Matrix4x4_SetIdentity(&identity));
    if (document->argb != NULL && document->rotation != NULL) {
        document->model = new_model(document->rotation);
        document->view = new_view(document);
    }
    if (document->model == NULL || document->view == NULL) {
        box_document_dispose(document);
        return NULL;
    }
    return document;
}

int box_document_draw(BoxDocument *document, unsigned long frame, unsigned char *rgba)
{
    TQ3Matrix4x4 turn;
    TQ3ViewStatus status;
    unsigned long i;

    if (document == NULL || rgba == NULL)
        return 1;
    /* A step about each axis per frame, as the sample's idle loop did. */
    Q3Matrix4x4_SetRotate_XYZ(&turn, 0.45f + 0.12f * (float)frame, 0.6f + 0.2f * (float)frame, 0.05f * (float)frame);
    if (Q3MatrixTransform_Set(document->rotation, &turn) != kQ3Success ||
        Q3View_StartRendering(document->view) != kQ3Success)
        return 1;
    do {
        if (Q3DisplayGroup_Submit(document->model, document->view) != kQ3Success)
            Q3View_Cancel(document->view);
        status = Q3View_EndRendering(document->view);
    } while (status == kQ3ViewStatusRetraverse);
    if (status != kQ3ViewStatusDone)
        return 1;
    for (i = 0; i < document->width * document->height; i++) {
        rgba[4 * i + 0] = document->argb[4 * i + 1];
        rgba[4 * i + 1] = document->argb[4 * i + 2];
        rgba[4 * i + 2] = document->argb[4 * i + 3];
        rgba[4 * i + 3] = 255;
    }
    return 0;
}

void box_document_dispose(BoxDocument *document)
{
    if (document == NULL)
        return;
    dispose(document->view);
    dispose(document->model);
    dispose(document->rotation);
    free(document->argb);
    free(document);
}
