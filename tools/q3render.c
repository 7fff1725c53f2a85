/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* q3render: renders a 3DMF model to a PNG image.
 *
 *   q3render model.3dmf -o image.png [--size WIDTHxHEIGHT] [--renderer interactive | wireframe]
 *            [--subdivision constant:C1,C2 | world:LENGTH | screen:PIXELS] [--background R,G,B]
 *            [--fit-camera] [--unlit]
 *
 * By default the picture is what a user of QuickDraw 3D's viewer saw: the
 * model lit and shaded on a neutral background.
 *
 * Illumination: a Phong illumination shader is submitted before the model,
 * as QuickDraw 3D's viewer submits an illumination shader of its own right
 * before the model's group (Phong or Lambert, as Q3ViewerSetPhongShading
 * chooses; Quesa's reimplementation of the viewer, E3Viewer_DrawContent,
 * does the same and starts with Lambert). Q3 takes Phong so that the
 * specular colour and control a file gives show. A file that submits its own
 * illumination shader replaces it from that point on, as any later shader
 * replaces an earlier one. Without a shader the view's default
 * is NULL illumination, which draws a model that gives no colours (QuickDraw
 * 3D's default diffuse colour is white) as a white silhouette. --unlit
 * submits a NULL illumination shader instead and adds no lights: flat
 * diffuse colours (a file's own illumination shader still applies where the
 * file submits it).
 *
 * Camera: when the file holds a camera (at its top level), the image is what
 * the first one sees, with its aspect ratio matched to the image's so that
 * the image is never stretched (Q3's choice): a view angle aspect camera
 * takes the image's width / height (keeping its field of view), a view plane
 * or orthographic camera keeps its vertical extent and centre and gets the
 * width that fits (both scaled for a view port that is not square). A file
 * without a top-level camera may suggest one in a view hints object
 * (QD3DIO.h): the camera of the first ViewHints that has one is used the
 * same way. Otherwise, or with --fit-camera, the camera looks at the centre of
 * the model's bounding box from the front, a little above and to the right,
 * far enough for the whole box to fit its 40-degree field of view.
 *
 * Lights: the first light group in the file, else the lights of the first
 * ViewHints that has some, or, as QuickDraw 3D's viewer lit models that bring
 * no lights, a white ambient light of brightness 0.3 and a white directional
 * light of brightness 1 shining from over the viewer's right shoulder.
 *
 * Background: --background, else the clear colour of the first ViewHints
 * whose clear method is kQ3ClearMethodWithColor, else mid grey (0.5, 0.5,
 * 0.5): a white model (the default colour) and a black one both stand out
 * from it, where on white a white unlit model would vanish.
 *
 * Other defaults: 400x300, the interactive renderer, constant subdivision
 * 16 x 16.
 * Every warning the library posts is printed to stderr, and so is a warning
 * when the file holds nothing to draw (the image is then the background).
 * Exit status: 0 done, 1 bad arguments, 2 the model cannot be read, 3 it
 * cannot be drawn or the image cannot be written. */

#include "q3load.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DMath.h"
#include "QD3DRenderer.h"
#include "QD3DShader.h"
#include "QD3DStyle.h"
#include "QD3DView.h"
#include "Q3PixmapPNG.h"

#include <math.h>
#include <string.h>

static void printUsage(FILE *to)
{
    fprintf(to, "usage: q3render model.3dmf -o image.png [--size WIDTHxHEIGHT]\n"
                "                [--renderer interactive | wireframe]\n"
                "                [--subdivision constant:C1,C2 | world:LENGTH | screen:PIXELS]\n"
                "                [--background R,G,B] [--fit-camera] [--unlit]\n"
                "\n"
                "By default the model is lit and shaded as QuickDraw 3D's viewer showed it: a\n"
                "Phong illumination shader is submitted before the model (a shader the file\n"
                "submits replaces it), lit by the file's lights (its first light group, else\n"
                "its first ViewHints' lights) or else by a white ambient light (0.3) and a\n"
                "white directional light (1.0) from over the viewer's right shoulder.\n"
                "\n"
                "  -o image.png    the PNG to write\n"
                "  --size          the image's size in pixels (default 400x300)\n"
                "  --renderer      interactive (default) or wireframe\n"
                "  --subdivision   how curves and surfaces are subdivided (default constant:16,16)\n"
                "  --background    the background colour, 0..1 each (default: the clear colour\n"
                "                  of the file's first ViewHints that has one, else mid grey\n"
                "                  0.5,0.5,0.5, from which white and black models both stand out)\n"
                "  --fit-camera    ignore the file's camera and fit one to the model's bounds\n"
                "                  (the default when the file has no camera); a file's camera\n"
                "                  (at its top level, else in its first ViewHints with one)\n"
                "                  is used with its aspect ratio matched to the image's\n"
                "  --unlit         flat colours: NULL illumination and no default lights\n"
                "  --help, -h      print this text and exit\n"
                "\n"
                "Warnings (the library's, and a file that holds nothing to draw) go to\n"
                "standard error.\n"
                "\n"
                "Exit status: 0 done, 1 bad arguments, 2 the model cannot be read, 3 it cannot\n"
                "be drawn or the image cannot be written.\n");
}

static int usage(void)
{
    printUsage(stderr);
    return 1;
}

static int parseSubdivision(const char *text, TQ3SubdivisionStyleData *style)
{
    if (strncmp(text, "constant:", 9) == 0) {
        style->method = kQ3SubdivisionMethodConstant;
        return sscanf(text + 9, "%f,%f", &style->c1, &style->c2) == 2;
    }
    if (strncmp(text, "world:", 6) == 0) {
        style->method = kQ3SubdivisionMethodWorldSpace;
        style->c2 = 0;
        return sscanf(text + 6, "%f", &style->c1) == 1;
    }
    if (strncmp(text, "screen:", 7) == 0) {
        style->method = kQ3SubdivisionMethodScreenSpace;
        style->c2 = 0;
        return sscanf(text + 7, "%f", &style->c1) == 1;
    }
    return 0;
}

static TQ3GroupObject defaultLights(const TQ3Vector3D *viewDirection)
{
    TQ3GroupObject lights = Q3LightGroup_New();
    TQ3LightData ambient = {kQ3True, 0.3f, {1.0f, 1.0f, 1.0f}};
    TQ3DirectionalLightData directional = {{kQ3True, 1.0f, {1.0f, 1.0f, 1.0f}}, kQ3False, {0, 0, 0}};
    TQ3LightObject a, d;
    /* From over the viewer's right shoulder: the view direction, tilted down. */
    directional.direction.x = viewDirection->x - 0.3f;
    directional.direction.y = viewDirection->y - 0.5f;
    directional.direction.z = viewDirection->z;
    Q3Vector3D_Normalize(&directional.direction, &directional.direction);
    a = Q3AmbientLight_New(&ambient);
    d = Q3DirectionalLight_New(&directional);
    Q3Group_AddObject(lights, a);
    Q3Group_AddObject(lights, d);
    Q3Object_Dispose(a);
    Q3Object_Dispose(d);
    return lights;
}

int main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    unsigned long width = 400, height = 300;
    TQ3ObjectType renderer = kQ3RendererTypeInteractive;
    TQ3SubdivisionStyleData subdivision = {kQ3SubdivisionMethodConstant, 16.0f, 16.0f};
    TQ3ColorARGB background = {1.0f, 0.5f, 0.5f, 0.5f};
    int fitCamera = 0, backgroundGiven = 0, unlit = 0;
    TQ3Object *objects = NULL;
    long count, i;
    int status = 0;
    int arg;
    for (arg = 1; arg < argc; ++arg) {
        const char *a = argv[arg];
        const char *value = arg + 1 < argc ? argv[arg + 1] : NULL;
        if (strcmp(a, "-o") == 0 && value != NULL) {
            out = value;
            ++arg;
        } else if (strcmp(a, "--size") == 0 && value != NULL) {
            if (!q3load_parseSize(value, &width, &height))
                return usage();
            ++arg;
        } else if (strcmp(a, "--renderer") == 0 && value != NULL) {
            if (!q3load_parseRenderer(value, &renderer))
                return usage();
            ++arg;
        } else if (strcmp(a, "--subdivision") == 0 && value != NULL) {
            if (!parseSubdivision(value, &subdivision))
                return usage();
            ++arg;
        } else if (strcmp(a, "--background") == 0 && value != NULL) {
            if (sscanf(value, "%f,%f,%f", &background.r, &background.g, &background.b) != 3)
                return usage();
            backgroundGiven = 1;
            ++arg;
        } else if (strcmp(a, "--fit-camera") == 0) {
            fitCamera = 1;
        } else if (strcmp(a, "--unlit") == 0) {
            unlit = 1;
        } else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            printUsage(stdout);
            return 0;
        } else if (a[0] == '-' || in != NULL) {
            return usage();
        } else {
            in = a;
        }
    }
    if (in == NULL || out == NULL)
        return usage();
    if (Q3Initialize() != kQ3Success)
        return 3;
    Q3Warning_Register(q3load_printWarning, 0);
    count = q3load_read(in, &objects);
    if (count < 0) {
        Q3Exit();
        return 2;
    }
    {
        TQ3GroupObject model = Q3DisplayGroup_New();
        TQ3ViewObject view = Q3View_New();
        TQ3StyleObject style = Q3SubdivisionStyle_New(&subdivision);
        TQ3ShaderObject illumination = unlit ? Q3NULLIllumination_New() : Q3PhongIllumination_New();
        unsigned char *argb = (unsigned char *)calloc(width * height, 4);
        TQ3PixmapDrawContextData contextData;
        TQ3DrawContextObject context;
        TQ3ViewAngleAspectCameraData cameraData;
        TQ3CameraObject camera;
        TQ3GroupObject lights;
        TQ3BoundingBox box;
        TQ3Point3D centre = {0, 0, 0};
        TQ3Vector3D toEye = {0.35f, 0.3f, 1.0f}, viewDirection;
        float radius = 1.0f, distance;
        const float fov = 0.6981317f; /* 40 degrees */
        TQ3ViewStatus done;
        TQ3GroupObject fileLights = NULL;
        TQ3CameraObject fileCamera = NULL;
        TQ3CameraObject hintsCamera = NULL;
        TQ3GroupObject hintsLights = NULL;
        int hintsBackground = 0;
        unsigned long drawable = 0;
        for (i = 0; i < count; ++i) {
            if (Q3Object_IsDrawable(objects[i]))
                Q3Group_AddObject(model, objects[i]);
            else if (fileLights == NULL && Q3Object_GetLeafType(objects[i]) == kQ3GroupTypeLight)
                fileLights = objects[i];
            else if (fileCamera == NULL && Q3Object_IsType(objects[i], kQ3ShapeTypeCamera))
                fileCamera = objects[i];
            else if (Q3Object_IsType(objects[i], kQ3SharedTypeViewHints))
                q3load_readHints(objects[i], &hintsCamera, &hintsLights, &hintsBackground, &background, backgroundGiven);
        }
        if (Q3Group_CountObjects(model, &drawable) == kQ3Success && drawable == 0)
            fprintf(stderr, "warning: %s holds nothing to draw; the image is the background alone\n", in);
        if (fileCamera == NULL)
            fileCamera = hintsCamera;
        if (fileLights == NULL)
            fileLights = hintsLights;
        memset(&contextData, 0, sizeof contextData);
        contextData.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
        contextData.drawContextData.clearImageColor = background;
        contextData.drawContextData.paneState = kQ3False;
        contextData.drawContextData.maskState = kQ3False;
        contextData.drawContextData.doubleBufferState = kQ3False;
        contextData.pixmap.image = argb;
        contextData.pixmap.width = width;
        contextData.pixmap.height = height;
        contextData.pixmap.rowBytes = width * 4;
        contextData.pixmap.pixelSize = 32;
        contextData.pixmap.pixelType = kQ3PixelTypeARGB32;
        contextData.pixmap.bitOrder = kQ3EndianBig;
        contextData.pixmap.byteOrder = kQ3EndianBig;
        context = Q3PixmapDrawContext_New(&contextData);

        if (fileCamera != NULL && !fitCamera) {
            TQ3CameraPlacement placement;
            camera = q3load_adaptedCamera(fileCamera, (float)width / (float)height);
            Q3Camera_GetPlacement(fileCamera, &placement);
            Q3Point3D_Subtract(&placement.pointOfInterest, &placement.cameraLocation, &viewDirection);
            Q3Vector3D_Normalize(&viewDirection, &viewDirection);
        } else {
            if (q3load_bounds(view, model, &box) && box.isEmpty == kQ3False) {
                TQ3Vector3D diagonal;
                centre.x = (box.min.x + box.max.x) / 2;
                centre.y = (box.min.y + box.max.y) / 2;
                centre.z = (box.min.z + box.max.z) / 2;
                Q3Point3D_Subtract(&box.max, &box.min, &diagonal);
                radius = Q3Vector3D_Length(&diagonal) / 2;
                if (!(radius > 1e-6f))
                    radius = 1.0f;
            }
            Q3Vector3D_Normalize(&toEye, &toEye);
            distance = radius / sinf(fov / 2) * 1.05f;
            memset(&cameraData, 0, sizeof cameraData);
            cameraData.cameraData.placement.cameraLocation.x = centre.x + toEye.x * distance;
            cameraData.cameraData.placement.cameraLocation.y = centre.y + toEye.y * distance;
            cameraData.cameraData.placement.cameraLocation.z = centre.z + toEye.z * distance;
            cameraData.cameraData.placement.pointOfInterest = centre;
            cameraData.cameraData.placement.upVector.y = 1.0f;
            cameraData.cameraData.range.hither =
                distance - radius * 1.5f > distance * 0.01f ? distance - radius * 1.5f : distance * 0.01f;
            cameraData.cameraData.range.yon = distance + radius * 1.5f;
            cameraData.cameraData.viewPort.origin.x = -1.0f;
            cameraData.cameraData.viewPort.origin.y = 1.0f;
            cameraData.cameraData.viewPort.width = 2.0f;
            cameraData.cameraData.viewPort.height = 2.0f;
            cameraData.fov = fov;
            cameraData.aspectRatioXToY = (float)width / (float)height;
            camera = Q3ViewAngleAspectCamera_New(&cameraData);
            viewDirection.x = -toEye.x;
            viewDirection.y = -toEye.y;
            viewDirection.z = -toEye.z;
        }
        if (unlit)
            lights = Q3LightGroup_New();
        else if (fileLights != NULL)
            lights = Q3Shared_GetReference(fileLights);
        else
            lights = defaultLights(&viewDirection);

        if (argb == NULL || context == NULL || camera == NULL || illumination == NULL ||
            Q3View_SetDrawContext(view, context) != kQ3Success || Q3View_SetCamera(view, camera) != kQ3Success ||
            Q3View_SetRendererByType(view, renderer) != kQ3Success ||
            Q3View_SetLightGroup(view, lights) != kQ3Success || Q3View_StartRendering(view) != kQ3Success) {
            fprintf(stderr, "cannot draw %s: %s\n", in, Q3Error_GetMessage());
            status = 3;
        } else {
            do {
                Q3Object_Submit(style, view);
                Q3Object_Submit(illumination, view);
                Q3Object_Submit(model, view);
                done = Q3View_EndRendering(view);
            } while (done == kQ3ViewStatusRetraverse);
            if (done != kQ3ViewStatusDone) {
                fprintf(stderr, "cannot draw %s: %s\n", in, Q3Error_GetMessage());
                status = 3;
            } else {
                /* The picture is opaque whatever the clear colour's alpha. */
                unsigned long p;
                for (p = 0; p < width * height; ++p)
                    argb[4 * p] = 255;
                if (Q3PixmapDrawContext_WritePNG(context, out) != kQ3Success) {
                    fprintf(stderr, "cannot write %s: %s\n", out, Q3Error_GetMessage());
                    status = 3;
                }
            }
        }
        free(argb);
        Q3Object_Dispose(lights);
        if (hintsCamera != NULL)
            Q3Object_Dispose(hintsCamera);
        if (hintsLights != NULL)
            Q3Object_Dispose(hintsLights);
        if (camera != NULL)
            Q3Object_Dispose(camera);
        if (context != NULL)
            Q3Object_Dispose(context);
        if (illumination != NULL)
            Q3Object_Dispose(illumination);
        Q3Object_Dispose(style);
        Q3Object_Dispose(view);
        Q3Object_Dispose(model);
    }
    q3load_free(objects, count);
    Q3Exit();
    return status;
}
