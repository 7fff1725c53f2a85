/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3LOAD_H
#define Q3LOAD_H

/* Reading every object of a 3DMF file, and printing the library's warnings,
 * shared by q3render, q3convert and q3view; fitting a file's camera to an
 * image and measuring a model, and the --size and --renderer options,
 * shared by q3render and q3view. */

#include "QD3D.h"
#include "QD3DCamera.h"
#include "QD3DErrors.h"
#include "QD3DGroup.h"
#include "QD3DIO.h"
#include "QD3DRenderer.h"
#include "QD3DStorage.h"
#include "QD3DView.h"

#include <math.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The objects of the file at path, in order, in *objects (free with
 * q3load_free); the number read, or -1 after printing why the file cannot
 * be read to stderr. */
static long q3load_read(const char *path, TQ3Object **objects)
{
    TQ3StorageObject storage = Q3UnixPathStorage_New(path);
    TQ3FileObject file = Q3File_New();
    TQ3FileMode mode = 0;
    long count = 0, capacity = 16;
    FILE *probe = fopen(path, "rb");
    *objects = NULL;
    if (probe == NULL) {
        fprintf(stderr, "cannot open %s\n", path);
        Q3Object_Dispose(file);
        Q3Object_Dispose(storage);
        return -1;
    }
    fclose(probe);
    if (storage == NULL || file == NULL || Q3File_SetStorage(file, storage) != kQ3Success ||
        Q3File_OpenRead(file, &mode) != kQ3Success) {
        fprintf(stderr, "%s is not a 3DMF file Q3 can read: %s\n", path, Q3Error_GetMessage());
        if (file != NULL)
            Q3Object_Dispose(file);
        if (storage != NULL)
            Q3Object_Dispose(storage);
        return -1;
    }
    *objects = (TQ3Object *)malloc(sizeof(TQ3Object) * (size_t)capacity);
    while (*objects != NULL && Q3File_IsEndOfFile(file) == kQ3False) {
        TQ3Object object = Q3File_ReadObject(file);
        if (object == NULL) {
            fprintf(stderr, "%s: an object cannot be read: %s\n", path, Q3Error_GetMessage());
            count = -1 - count;
            break;
        }
        if (count == capacity) {
            TQ3Object *more = (TQ3Object *)realloc(*objects, sizeof(TQ3Object) * (size_t)(capacity * 2));
            if (more == NULL) {
                Q3Object_Dispose(object);
                break;
            }
            *objects = more;
            capacity *= 2;
        }
        (*objects)[count++] = object;
    }
    Q3File_Close(file);
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
    if (count < 0) {
        long i, read = -1 - count;
        for (i = 0; i < read; ++i)
            Q3Object_Dispose((*objects)[i]);
        free(*objects);
        *objects = NULL;
        return -1;
    }
    return count;
}

/* A warning callback (Q3Warning_Register) printing every warning the
 * library posts to stderr: an object left out of a file, a value
 * substituted, so that nothing is lost silently. */
static void q3load_printWarning(TQ3Warning firstWarning, TQ3Warning lastWarning, long reference)
{
    (void)firstWarning;
    (void)reference;
    fprintf(stderr, "warning %d: %s\n", (int)lastWarning, Q3Warning_GetMessage());
}

static void q3load_free(TQ3Object *objects, long count)
{
    long i;
    for (i = 0; i < count; ++i)
        Q3Object_Dispose(objects[i]);
    free(objects);
}

/* A copy of a file's camera whose visible rectangle has the image's aspect
 * ratio (width / height), accounting for a view port that is not square. */
static inline TQ3CameraObject q3load_adaptedCamera(TQ3CameraObject fileCamera, float imageAspect)
{
    TQ3CameraObject camera = Q3Object_Duplicate(fileCamera);
    TQ3CameraViewPort viewPort;
    float aspect;
    if (camera == NULL || Q3Camera_GetViewPort(camera, &viewPort) != kQ3Success) {
        if (camera != NULL)
            Q3Object_Dispose(camera);
        return NULL;
    }
    aspect = imageAspect * viewPort.height / viewPort.width;
    switch (Q3Camera_GetType(camera)) {
    case kQ3CameraTypeViewAngleAspect:
        Q3ViewAngleAspectCamera_SetAspectRatio(camera, aspect);
        break;
    case kQ3CameraTypeViewPlane: {
        TQ3ViewPlaneCameraData data;
        Q3ViewPlaneCamera_GetData(camera, &data);
        data.halfWidthAtViewPlane = data.halfHeightAtViewPlane * aspect;
        Q3ViewPlaneCamera_SetData(camera, &data);
        break;
    }
    case kQ3CameraTypeOrthographic: {
        TQ3OrthographicCameraData data;
        float centre, halfWidth;
        Q3OrthographicCamera_GetData(camera, &data);
        centre = (data.left + data.right) / 2;
        halfWidth = fabsf(data.top - data.bottom) / 2 * aspect;
        if (data.right < data.left)
            halfWidth = -halfWidth;
        data.left = centre - halfWidth;
        data.right = centre + halfWidth;
        Q3OrthographicCamera_SetData(camera, &data);
        break;
    }
    default:
        break;
    }
    return camera;
}

/* The exact bounding box of a model in world space; 0 when it cannot be
 * computed. */
static inline int q3load_bounds(TQ3ViewObject view, TQ3GroupObject model, TQ3BoundingBox *box)
{
    TQ3ViewStatus status;
    if (Q3View_StartBoundingBox(view, kQ3ComputeBoundsExact) != kQ3Success)
        return 0;
    do {
        Q3Object_Submit(model, view);
        status = Q3View_EndBoundingBox(view, box);
    } while (status == kQ3ViewStatusRetraverse);
    return status == kQ3ViewStatusDone;
}

/* Takes from a view hints object what the earlier ones did not give: its
 * camera, its lights (a non-empty light group) and, unless the user gave a
 * background, its clear colour when its clear method is WithColor. The
 * camera and lights are new references for the caller. */
static inline void q3load_readHints(TQ3ViewHintsObject hints, TQ3CameraObject *camera, TQ3GroupObject *lights,
                                    int *hasBackground, TQ3ColorARGB *background, int backgroundGiven)
{
    TQ3DrawContextClearImageMethod method;
    if (*camera == NULL)
        Q3ViewHints_GetCamera(hints, camera);
    if (*lights == NULL && Q3ViewHints_GetLightGroup(hints, lights) == kQ3Success && *lights != NULL) {
        TQ3GroupPosition first = NULL;
        if (Q3Group_GetFirstPosition(*lights, &first) != kQ3Success || first == NULL) {
            Q3Object_Dispose(*lights);
            *lights = NULL;
        }
    }
    if (!backgroundGiven && !*hasBackground && Q3ViewHints_GetClearImageMethod(hints, &method) == kQ3Success &&
        method == kQ3ClearMethodWithColor && Q3ViewHints_GetClearImageColor(hints, background) == kQ3Success) {
        background->a = 1.0f;
        *hasBackground = 1;
    }
}

/* --size WIDTHxHEIGHT: 1 to 8192 each; 1 when value is one, 0 otherwise. */
static inline int q3load_parseSize(const char *value, unsigned long *width, unsigned long *height)
{
    return sscanf(value, "%lux%lu", width, height) == 2 && *width >= 1 && *height >= 1 && *width <= 8192 &&
           *height <= 8192;
}

/* --renderer interactive | wireframe: 1 with *type set, 0 for another name. */
static inline int q3load_parseRenderer(const char *value, TQ3ObjectType *type)
{
    if (strcmp(value, "interactive") == 0)
        *type = kQ3RendererTypeInteractive;
    else if (strcmp(value, "wireframe") == 0)
        *type = kQ3RendererTypeWireFrame;
    else
        return 0;
    return 1;
}

#endif /* Q3LOAD_H */
