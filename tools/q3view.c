/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* q3view: shows a 3DMF model in an X window, as Apple's 3D Viewer did.
 *
 *   q3view model.3dmf [--size WIDTHxHEIGHT] [--renderer interactive | wireframe]
 *          [--background R,G,B] [--fit-camera] [--save PREFIX] [--script KEYS]
 *
 * The window is drawn through Apple's X11 draw context (QD3DDrawContext.h:
 * Q3X_GetVisualInfo gives the visual the window is created with,
 * Q3XDrawContext_New draws into it), which follows the window's size.
 *
 * The picture starts as q3render's (tools/q3render.c says why): the file's
 * camera (its first top-level camera, else its first ViewHints camera) with
 * its aspect ratio matched to the window's, else a 40-degree view angle
 * aspect camera fitted to the model's bounds; the file's lights, else a
 * white ambient light (0.3) and a white directional light (1.0) from over
 * the viewer's right shoulder, which here moves with the camera so that the
 * side in view is always lit; a Phong illumination shader before the model;
 * the file's clear colour or mid grey.
 *
 * Mouse: the left button drags the model around the centre of its bounding
 * box, as if grabbed (a turn of pi/400 radians per pixel: 800 pixels turn
 * it once around; horizontal drags turn it about the camera's first up
 * vector, vertical ones about the camera's first right vector); the middle
 * or right button, or the left with Shift, moves it in the picture plane
 * (one pixel per pixel at the depth of the camera's point of interest); the
 * wheel moves the camera toward the point of interest (each step 0.9 times
 * the distance) or away (1/0.9); an orthographic camera, which moving does
 * not change, shows 0.9 (1/0.9) times its rectangle instead. Moving the mouse without a button picks
 * (Q3WindowPointPick) the geometry under the cursor and shows its type in
 * the title and on standard output.
 *
 * Keys: i interactive renderer, w wireframe renderer, f filled, e edges,
 * p points (the fill style), l lights on/off (off: no lights and NULL
 * illumination, the flat colours), r reset the camera, s save the picture
 * (PREFIX-N.png, N counting from 1), q or Escape quit.
 *
 * Standard output gets one line per event a script or test may wait for:
 * "window 0xID WIDTHxHEIGHT" once the first frame is shown, "size WxH"
 * when the window's size changes, "renderer NAME", "fill NAME",
 * "lights on|off", "camera reset", "saved PATH WIDTHxHEIGHT", and
 * "pick NAME" ("pick nothing") when what is under the cursor changes.
 *
 * Exit status: 0 done, 1 bad arguments, 2 the model cannot be read, 3 no X
 * display can be opened (or it has no visual Q3 can draw with, or the
 * connection is lost), 4 the model cannot be drawn, an X request fails or
 * a picture cannot be saved. */

#define _POSIX_C_SOURCE 200809L

#include "q3load.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DMath.h"
#include "QD3DPick.h"
#include "QD3DRenderer.h"
#include "QD3DShader.h"
#include "QD3DStyle.h"
#include "QD3DView.h"
#include "Q3PixmapPNG.h"

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/keysym.h>

#include <math.h>
#include <string.h>

enum { kExitDone = 0, kExitUsage = 1, kExitUnreadable = 2, kExitNoDisplay = 3, kExitCannotDraw = 4 };

#define kPi 3.14159265358979f
/* Radians of turn per pixel dragged: 800 pixels turn the model once. */
#define kTurnPerPixel (kPi / 400.0f)
/* The factor of the camera's distance per wheel step toward the model. */
#define kZoomStep 0.9f
/* q3render's fitted camera: 40 degrees vertically. */
#define kFittedFieldOfView 0.6981317f

static void printUsage(FILE *to)
{
    fprintf(to, "usage: q3view model.3dmf [--size WIDTHxHEIGHT] [--renderer interactive | wireframe]\n"
                "              [--background R,G,B] [--fit-camera] [--save PREFIX] [--script KEYS]\n"
                "\n"
                "Shows a 3DMF model in an X window (Apple's X11 draw context), lit and shaded as\n"
                "q3render draws it, from the file's camera or a camera fitted to the model.\n"
                "\n"
                "  --size          the window's first size in pixels (default 800x600)\n"
                "  --renderer      interactive (default) or wireframe\n"
                "  --background    the background colour, 0..1 each (default: the clear colour\n"
                "                  of the file's first ViewHints that has one, else mid grey)\n"
                "  --fit-camera    ignore the file's camera and fit one to the model's bounds\n"
                "  --save PREFIX   the key s saves the picture as PREFIX-1.png, PREFIX-2.png, ...\n"
                "                  (default prefix: q3view)\n"
                "  --script KEYS   type these keys once the first frame is shown, as if from the\n"
                "                  keyboard (e.g. \"wsq\": wireframe, save, quit); spaces are skipped\n"
                "  --help, -h      print this text and exit\n"
                "\n"
                "Mouse: left drag turns the model about its bounds' centre (pi/400 radians a\n"
                "pixel); middle or right drag, or Shift with left, moves it; the wheel zooms.\n"
                "Moving the mouse shows the type of the geometry under it (picking) in the\n"
                "title and on standard output.\n"
                "Keys: i interactive renderer, w wireframe renderer, f filled, e edges, p points,\n"
                "l lights on/off, r reset the camera, s save the picture as PNG, q or Escape quit.\n"
                "\n"
                "Exit status: 0 done, 1 bad arguments, 2 the model cannot be read, 3 no X display\n"
                "can be opened (DISPLAY) or the connection is lost, 4 the model cannot be drawn,\n"
                "an X request fails or a picture cannot be saved.\n");
}

static int usage(void)
{
    printUsage(stderr);
    return kExitUsage;
}

/* ---- Vectors ---------------------------------------------------------- */

static TQ3Vector3D vec(float x, float y, float z)
{
    TQ3Vector3D v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static TQ3Vector3D sub(TQ3Point3D a, TQ3Point3D b)
{
    return vec(a.x - b.x, a.y - b.y, a.z - b.z);
}

static TQ3Point3D add(TQ3Point3D p, TQ3Vector3D v, float scale)
{
    TQ3Point3D r;
    r.x = p.x + v.x * scale;
    r.y = p.y + v.y * scale;
    r.z = p.z + v.z * scale;
    return r;
}

static float dot(TQ3Vector3D a, TQ3Vector3D b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static TQ3Vector3D cross(TQ3Vector3D a, TQ3Vector3D b)
{
    return vec(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

static float length(TQ3Vector3D v)
{
    return sqrtf(dot(v, v));
}

static TQ3Vector3D normalized(TQ3Vector3D v)
{
    float l = length(v);
    return l > 0 ? vec(v.x / l, v.y / l, v.z / l) : v;
}

/* v turned by angle about the unit axis (Rodrigues' rotation formula). */
static TQ3Vector3D turned(TQ3Vector3D v, TQ3Vector3D axis, float angle)
{
    float c = cosf(angle), s = sinf(angle), d = dot(axis, v) * (1 - c);
    TQ3Vector3D k = cross(axis, v);
    return vec(v.x * c + k.x * s + axis.x * d, v.y * c + k.y * s + axis.y * d, v.z * c + k.z * s + axis.z * d);
}

/* ---- The viewer ------------------------------------------------------- */

typedef struct Viewer {
    const char *path;
    const char *savePrefix;
    int saved;
    Display *display;
    Window window;
    Atom deleteWindow;
    unsigned long width, height;
    TQ3ViewObject view;
    TQ3DrawContextObject context;
    TQ3GroupObject model;
    TQ3StyleObject subdivision;
    TQ3ShaderObject phong, flat;
    TQ3GroupObject lights, noLights;
    TQ3LightObject headLight; /* the default directional light, or NULL */
    TQ3CameraObject fileCamera; /* borrowed from the objects read, or NULL */
    TQ3CameraObject camera;
    /* An orthographic camera's rectangle at the window's aspect: zoom
     * scales it, as moving an orthographic camera changes nothing. */
    TQ3OrthographicCameraData ortho;
    int isOrtho;
    TQ3ObjectType renderer;
    TQ3FillStyle fill;
    int lightsOn;
    /* The first camera: where it stands and looks, its range, and the
     * centre the model turns about; the fitted camera's field of view,
     * which also sizes a pan under a view plane camera (an estimate). */
    TQ3CameraPlacement home;
    TQ3CameraRange homeRange;
    TQ3Point3D centre;
    float fieldOfView;
    /* What the mouse did since: turns (radians), a zoom factor, a move in
     * the first camera's right and up directions (world units). */
    float yaw, pitch, zoom, panRight, panUp;
    int dirty;
    char picked[kQ3StringMaximumLength];
} Viewer;

/* The camera's placement now: the first one turned about the centre (pitch
 * about its right vector, then yaw about its up vector), moved toward its
 * point of interest by zoom and across by the pan. */
static TQ3CameraPlacement currentPlacement(const Viewer *v)
{
    TQ3CameraPlacement p;
    TQ3Vector3D up = normalized(v->home.upVector);
    TQ3Vector3D forward = normalized(sub(v->home.pointOfInterest, v->home.cameraLocation));
    TQ3Vector3D right = normalized(cross(forward, up));
    TQ3Vector3D eye = sub(v->home.cameraLocation, v->centre);
    TQ3Vector3D poi = sub(v->home.pointOfInterest, v->centre);
    TQ3Vector3D newUp = v->home.upVector, toEye, pan;
    /* The model turns as if grabbed, so the camera turns the other way. */
    eye = turned(turned(eye, right, -v->pitch), up, -v->yaw);
    poi = turned(turned(poi, right, -v->pitch), up, -v->yaw);
    newUp = turned(turned(newUp, right, -v->pitch), up, -v->yaw);
    right = turned(turned(right, right, -v->pitch), up, -v->yaw);
    p.cameraLocation = add(v->centre, eye, 1);
    p.pointOfInterest = add(v->centre, poi, 1);
    toEye = sub(p.cameraLocation, p.pointOfInterest);
    p.cameraLocation = add(p.pointOfInterest, toEye, v->zoom);
    /* The picture's up: the up vector made square to the view. */
    up = normalized(cross(right, normalized(sub(p.pointOfInterest, p.cameraLocation))));
    pan = vec(-right.x * v->panRight - up.x * v->panUp, -right.y * v->panRight - up.y * v->panUp,
              -right.z * v->panRight - up.z * v->panUp);
    p.cameraLocation = add(p.cameraLocation, pan, 1);
    p.pointOfInterest = add(p.pointOfInterest, pan, 1);
    p.upVector = newUp;
    return p;
}

/* World units per pixel at the depth of the point of interest. */
static float worldPerPixel(const Viewer *v)
{
    TQ3CameraPlacement p = currentPlacement(v);
    float distance = length(sub(p.pointOfInterest, p.cameraLocation));
    float fov = v->fieldOfView;
    if (Q3Camera_GetType(v->camera) == kQ3CameraTypeViewAngleAspect) {
        Q3ViewAngleAspectCamera_GetFOV(v->camera, &fov);
        /* The field of view spans the shorter side. */
        return 2 * distance * tanf(fov / 2) / (float)(v->width < v->height ? v->width : v->height);
    }
    if (v->isOrtho)
        return fabsf(v->ortho.top - v->ortho.bottom) * v->zoom / (float)v->height;
    return 2 * distance * tanf(fov / 2) / (float)v->height;
}

/* Puts the current placement, range and aspect ratio into the camera. */
static void updateCamera(Viewer *v)
{
    TQ3CameraPlacement placement = currentPlacement(v);
    TQ3CameraRange range = v->homeRange;
    TQ3Vector3D direction;
    /* The range moves with the camera's distance from the centre. */
    float shift = length(sub(placement.cameraLocation, v->centre)) - length(sub(v->home.cameraLocation, v->centre));
    range.hither = range.hither + shift > range.hither * 0.01f ? range.hither + shift : range.hither * 0.01f;
    range.yon += shift;
    if (v->isOrtho) {
        TQ3OrthographicCameraData data = v->ortho;
        float x = (data.left + data.right) / 2, y = (data.top + data.bottom) / 2;
        data.left = x + (data.left - x) * v->zoom;
        data.right = x + (data.right - x) * v->zoom;
        data.top = y + (data.top - y) * v->zoom;
        data.bottom = y + (data.bottom - y) * v->zoom;
        Q3OrthographicCamera_SetData(v->camera, &data);
    }
    Q3Camera_SetPlacement(v->camera, &placement);
    Q3Camera_SetRange(v->camera, &range);
    if (v->headLight != NULL) {
        /* From over the viewer's right shoulder, as q3render lights. */
        TQ3Vector3D forward = normalized(sub(placement.pointOfInterest, placement.cameraLocation));
        TQ3Vector3D up = normalized(placement.upVector);
        TQ3Vector3D right = normalized(cross(forward, up));
        direction = normalized(vec(forward.x - 0.3f * right.x - 0.5f * up.x, forward.y - 0.3f * right.y - 0.5f * up.y,
                                   forward.z - 0.3f * right.z - 0.5f * up.z));
        Q3DirectionalLight_SetDirection(v->headLight, &direction);
    }
}

/* A new camera of the window's aspect ratio: the file's, else one fitted to
 * the model's bounds (q3render's). */
static TQ3CameraObject newCamera(Viewer *v)
{
    float aspect = (float)v->width / (float)v->height;
    TQ3ViewAngleAspectCameraData data;
    if (v->fileCamera != NULL)
        return q3load_adaptedCamera(v->fileCamera, aspect);
    memset(&data, 0, sizeof data);
    data.cameraData.placement = v->home;
    data.cameraData.range = v->homeRange;
    data.cameraData.viewPort.origin.x = -1.0f;
    data.cameraData.viewPort.origin.y = 1.0f;
    data.cameraData.viewPort.width = 2.0f;
    data.cameraData.viewPort.height = 2.0f;
    data.fov = kFittedFieldOfView;
    data.aspectRatioXToY = aspect;
    return Q3ViewAngleAspectCamera_New(&data);
}

/* Makes a camera of the window's aspect ratio the view's. */
static int useNewCamera(Viewer *v)
{
    TQ3CameraObject camera = newCamera(v);
    if (camera == NULL || Q3View_SetCamera(v->view, camera) != kQ3Success) {
        if (camera != NULL)
            Q3Object_Dispose(camera);
        return 0;
    }
    if (v->camera != NULL)
        Q3Object_Dispose(v->camera);
    v->camera = camera;
    v->isOrtho = Q3Camera_GetType(camera) == kQ3CameraTypeOrthographic &&
                 Q3OrthographicCamera_GetData(camera, &v->ortho) == kQ3Success;
    return 1;
}

/* The first camera: the file's placement and range, or q3render's fitted
 * one; the centre turned about is the middle of the model's bounds. */
static void findHome(Viewer *v)
{
    TQ3BoundingBox box;
    TQ3Vector3D toEye = normalized(vec(0.35f, 0.3f, 1.0f)), diagonal;
    float radius = 1.0f, distance;
    int bounded = q3load_bounds(v->view, v->model, &box) && box.isEmpty == kQ3False;
    memset(&v->centre, 0, sizeof v->centre);
    if (bounded) {
        v->centre.x = (box.min.x + box.max.x) / 2;
        v->centre.y = (box.min.y + box.max.y) / 2;
        v->centre.z = (box.min.z + box.max.z) / 2;
        diagonal = sub(box.max, box.min);
        radius = length(diagonal) / 2;
        if (!(radius > 1e-6f))
            radius = 1.0f;
    }
    v->fieldOfView = kFittedFieldOfView;
    if (v->fileCamera != NULL) {
        Q3Camera_GetPlacement(v->fileCamera, &v->home);
        Q3Camera_GetRange(v->fileCamera, &v->homeRange);
        if (!bounded)
            v->centre = v->home.pointOfInterest;
        return;
    }
    distance = radius / sinf(kFittedFieldOfView / 2) * 1.05f;
    v->home.cameraLocation = add(v->centre, toEye, distance);
    v->home.pointOfInterest = v->centre;
    v->home.upVector = vec(0, 1, 0);
    v->homeRange.hither = distance - radius * 1.5f > distance * 0.01f ? distance - radius * 1.5f : distance * 0.01f;
    v->homeRange.yon = distance + radius * 1.5f;
}

static int draw(Viewer *v)
{
    TQ3ViewStatus status;
    updateCamera(v);
    if (Q3View_StartRendering(v->view) != kQ3Success)
        return 0;
    do {
        Q3Object_Submit(v->subdivision, v->view);
        Q3Object_Submit(v->lightsOn ? v->phong : v->flat, v->view);
        Q3FillStyle_Submit(v->fill, v->view);
        Q3Object_Submit(v->model, v->view);
        status = Q3View_EndRendering(v->view);
    } while (status == kQ3ViewStatusRetraverse);
    v->dirty = 0;
    return status == kQ3ViewStatusDone;
}

/* The type name of the geometry drawn at window pixel (x, y), or
 * "nothing". */
static void pickAt(Viewer *v, int x, int y, char name[kQ3StringMaximumLength])
{
    TQ3WindowPointPickData data;
    TQ3PickObject pick;
    unsigned long hits = 0;
    strcpy(name, "nothing");
    memset(&data, 0, sizeof data);
    data.data.sort = kQ3PickSortNearToFar;
    data.data.mask = kQ3PickDetailMaskObject;
    data.data.numHitsToReturn = 1;
    data.point.x = (float)x + 0.5f;
    data.point.y = (float)y + 0.5f;
    data.vertexTolerance = 3.0f;
    data.edgeTolerance = 3.0f;
    pick = Q3WindowPointPick_New(&data);
    if (pick == NULL)
        return;
    updateCamera(v);
    if (Q3View_StartPicking(v->view, pick) == kQ3Success) {
        TQ3ViewStatus status;
        do {
            Q3FillStyle_Submit(v->fill, v->view);
            Q3Object_Submit(v->model, v->view);
            status = Q3View_EndPicking(v->view);
        } while (status == kQ3ViewStatusRetraverse);
        if (status == kQ3ViewStatusDone && Q3Pick_GetNumHits(pick, &hits) == kQ3Success && hits > 0) {
            TQ3Object object = NULL;
            if (Q3Pick_GetPickDetailData(pick, 0, kQ3PickDetailMaskObject, &object) == kQ3Success &&
                object != NULL) {
                if (Q3ObjectHierarchy_GetStringFromType(Q3Object_GetLeafType(object), name) != kQ3Success)
                    strcpy(name, "geometry");
                Q3Object_Dispose(object);
            }
        }
    }
    Q3Object_Dispose(pick);
}

static void setTitle(Viewer *v)
{
    /* Room for the prefix, 2048 bytes of the path and a type name. */
    char title[9 + 2048 + 3 + kQ3StringMaximumLength];
    snprintf(title, sizeof title, "q3view: %.2048s%s%s", v->path, strcmp(v->picked, "nothing") != 0 ? " - " : "",
             strcmp(v->picked, "nothing") != 0 ? v->picked : "");
    XStoreName(v->display, v->window, title);
    /* The server has the title before anything is printed about it. */
    XSync(v->display, False);
}

/* One colour channel of a TrueColor pixel, as 0..255. */
static unsigned channel(unsigned long pixel, unsigned long mask)
{
    unsigned long max;
    if (mask == 0)
        return 0;
    while ((mask & 1) == 0) {
        mask >>= 1;
        pixel >>= 1;
    }
    max = mask;
    return (unsigned)(((pixel & mask) * 255 + max / 2) / max);
}

/* Saves what the window shows (read back from the server) as a PNG. */
static int save(Viewer *v)
{
    char path[4096];
    XImage *image;
    TQ3Pixmap pixmap;
    unsigned char *rgb;
    unsigned long x, y;
    int ok;
    snprintf(path, sizeof path, "%s-%d.png", v->savePrefix, v->saved + 1);
    XSync(v->display, False);
    image = XGetImage(v->display, v->window, 0, 0, (unsigned)v->width, (unsigned)v->height, AllPlanes, ZPixmap);
    if (image == NULL) {
        fprintf(stderr, "cannot read the window back to save %s\n", path);
        return 0;
    }
    rgb = (unsigned char *)malloc(v->width * v->height * 4);
    if (rgb == NULL) {
        XDestroyImage(image);
        fprintf(stderr, "no memory to save %s\n", path);
        return 0;
    }
    /* kQ3PixelTypeRGB32 in big-endian byte order: X, R, G, B. */
    for (y = 0; y < v->height; ++y)
        for (x = 0; x < v->width; ++x) {
            unsigned long pixel = XGetPixel(image, (int)x, (int)y);
            unsigned char *out = rgb + (y * v->width + x) * 4;
            out[0] = 255;
            out[1] = (unsigned char)channel(pixel, image->red_mask);
            out[2] = (unsigned char)channel(pixel, image->green_mask);
            out[3] = (unsigned char)channel(pixel, image->blue_mask);
        }
    XDestroyImage(image);
    pixmap.image = rgb;
    pixmap.width = v->width;
    pixmap.height = v->height;
    pixmap.rowBytes = v->width * 4;
    pixmap.pixelSize = 32;
    pixmap.pixelType = kQ3PixelTypeRGB32;
    pixmap.bitOrder = kQ3EndianBig;
    pixmap.byteOrder = kQ3EndianBig;
    ok = Q3Pixmap_WritePNG(&pixmap, path) == kQ3Success;
    free(rgb);
    if (!ok) {
        fprintf(stderr, "cannot write %s: %s\n", path, Q3Error_GetMessage());
        return 0;
    }
    v->saved++;
    printf("saved %s %lux%lu\n", path, v->width, v->height);
    return 1;
}

/* Does what a key asks; 0 to quit, -1 on a failure that ends the viewer. */
static int key(Viewer *v, KeySym symbol)
{
    switch (symbol) {
    case XK_i:
    case XK_w:
        v->renderer = symbol == XK_i ? kQ3RendererTypeInteractive : kQ3RendererTypeWireFrame;
        if (Q3View_SetRendererByType(v->view, v->renderer) != kQ3Success)
            return -1;
        printf("renderer %s\n", symbol == XK_i ? "interactive" : "wireframe");
        break;
    case XK_f:
    case XK_e:
    case XK_p:
        v->fill = symbol == XK_f ? kQ3FillStyleFilled : symbol == XK_e ? kQ3FillStyleEdges : kQ3FillStylePoints;
        printf("fill %s\n", symbol == XK_f ? "filled" : symbol == XK_e ? "edges" : "points");
        break;
    case XK_l:
        v->lightsOn = !v->lightsOn;
        if (Q3View_SetLightGroup(v->view, v->lightsOn ? v->lights : v->noLights) != kQ3Success)
            return -1;
        printf("lights %s\n", v->lightsOn ? "on" : "off");
        break;
    case XK_r:
        v->yaw = v->pitch = v->panRight = v->panUp = 0;
        v->zoom = 1;
        printf("camera reset\n");
        break;
    case XK_s:
        /* What the keys before asked for is drawn before it is saved. */
        if (v->dirty && !draw(v)) {
            fprintf(stderr, "cannot draw %s: %s\n", v->path, Q3Error_GetMessage());
            return -1;
        }
        return save(v) ? 1 : -1;
    case XK_q:
    case XK_Escape:
        return 0;
    default:
        return 1;
    }
    v->dirty = 1;
    return 1;
}

/* Xlib's default handlers end the process with status 1, which here means
 * bad arguments: a lost connection ends it with the no-display status, an
 * X error with the cannot-draw one, each with a message. */
static int lostDisplay(Display *display)
{
    fprintf(stderr, "the connection to the X display %s was lost\n", DisplayString(display));
    exit(kExitNoDisplay);
}

static int xError(Display *display, XErrorEvent *error)
{
    char text[256];
    XGetErrorText(display, error->error_code, text, sizeof text);
    fprintf(stderr, "X error %d (%s), request %d\n", (int)error->error_code, text, (int)error->request_code);
    exit(kExitCannotDraw);
}

static KeySym scriptKey(char c)
{
    char name[2] = {c, 0};
    return XStringToKeysym(name);
}

static int run(Viewer *v, const char *script)
{
    int dragging = 0, lastX = 0, lastY = 0, shown = 0;
    unsigned dragButton = 0;
    int hoverX = -1, hoverY = -1;
    for (;;) {
        XEvent event;
        if (XPending(v->display) == 0) {
            if (v->dirty) {
                if (!draw(v)) {
                    fprintf(stderr, "cannot draw %s: %s\n", v->path, Q3Error_GetMessage());
                    return kExitCannotDraw;
                }
                if (!shown) {
                    shown = 1;
                    printf("window 0x%lx %lux%lu\n", (unsigned long)v->window, v->width, v->height);
                    for (; script != NULL && *script != '\0'; ++script) {
                        int result;
                        if (*script == ' ')
                            continue;
                        result = key(v, scriptKey(*script));
                        if (result <= 0)
                            return result == 0 ? kExitDone : kExitCannotDraw;
                        if (v->dirty && !draw(v)) {
                            fprintf(stderr, "cannot draw %s: %s\n", v->path, Q3Error_GetMessage());
                            return kExitCannotDraw;
                        }
                    }
                }
                continue;
            }
            if (hoverX >= 0) {
                char name[kQ3StringMaximumLength];
                pickAt(v, hoverX, hoverY, name);
                hoverX = -1;
                if (strcmp(name, v->picked) != 0) {
                    strcpy(v->picked, name);
                    setTitle(v);
                    printf("pick %s\n", name);
                }
                continue;
            }
            fflush(stdout);
        }
        XNextEvent(v->display, &event);
        switch (event.type) {
        case Expose:
            if (event.xexpose.count == 0)
                v->dirty = 1;
            break;
        case ConfigureNotify:
            if ((unsigned long)event.xconfigure.width != v->width ||
                (unsigned long)event.xconfigure.height != v->height) {
                v->width = (unsigned long)event.xconfigure.width;
                v->height = (unsigned long)event.xconfigure.height;
                if (!useNewCamera(v)) {
                    fprintf(stderr, "cannot follow the window's size: %s\n", Q3Error_GetMessage());
                    return kExitCannotDraw;
                }
                v->dirty = 1;
                printf("size %lux%lu\n", v->width, v->height);
            }
            break;
        case KeyPress: {
            KeySym symbol = XLookupKeysym(&event.xkey, 0);
            int result = key(v, symbol);
            if (result <= 0)
                return result == 0 ? kExitDone : kExitCannotDraw;
            break;
        }
        case ButtonPress:
            if (event.xbutton.button == Button4 || event.xbutton.button == Button5) {
                v->zoom *= event.xbutton.button == Button4 ? kZoomStep : 1 / kZoomStep;
                v->dirty = 1;
            } else if (!dragging) {
                dragging = 1;
                dragButton = event.xbutton.button;
                if (dragButton == Button1 && (event.xbutton.state & ShiftMask) != 0)
                    dragButton = Button2;
                lastX = event.xbutton.x;
                lastY = event.xbutton.y;
            }
            break;
        case ButtonRelease:
            if (dragging && (event.xbutton.button == dragButton ||
                             (dragButton == Button2 && event.xbutton.button == Button1)))
                dragging = 0;
            break;
        case MotionNotify: {
            int dx = event.xmotion.x - lastX, dy = event.xmotion.y - lastY;
            if (!dragging) {
                hoverX = event.xmotion.x;
                hoverY = event.xmotion.y;
                break;
            }
            if (dragButton == Button1) {
                v->yaw += (float)dx * kTurnPerPixel;
                v->pitch += (float)dy * kTurnPerPixel;
            } else {
                float step = worldPerPixel(v);
                v->panRight += (float)dx * step;
                v->panUp -= (float)dy * step;
            }
            lastX = event.xmotion.x;
            lastY = event.xmotion.y;
            v->dirty = dx != 0 || dy != 0 || v->dirty;
            break;
        }
        case ClientMessage:
            if ((Atom)event.xclient.data.l[0] == v->deleteWindow)
                return kExitDone;
            break;
        default:
            break;
        }
    }
}

int main(int argc, char **argv)
{
    const char *in = NULL, *script = NULL;
    unsigned long width = 800, height = 600;
    TQ3ObjectType renderer = kQ3RendererTypeInteractive;
    TQ3SubdivisionStyleData subdivision = {kQ3SubdivisionMethodConstant, 16.0f, 16.0f};
    TQ3ColorARGB background = {1.0f, 0.5f, 0.5f, 0.5f};
    int fitCamera = 0, backgroundGiven = 0, hintsBackground = 0;
    TQ3Object *objects = NULL;
    TQ3CameraObject hintsCamera = NULL;
    TQ3GroupObject fileLights = NULL, hintsLights = NULL;
    XVisualInfo *visualInfo;
    XSetWindowAttributes attributes;
    TQ3XDrawContextData contextData;
    Viewer v;
    long count, i;
    int arg, status;
    memset(&v, 0, sizeof v);
    v.savePrefix = "q3view";
    for (arg = 1; arg < argc; ++arg) {
        const char *a = argv[arg];
        const char *value = arg + 1 < argc ? argv[arg + 1] : NULL;
        if (strcmp(a, "--size") == 0 && value != NULL) {
            if (!q3load_parseSize(value, &width, &height))
                return usage();
            ++arg;
        } else if (strcmp(a, "--renderer") == 0 && value != NULL) {
            if (!q3load_parseRenderer(value, &renderer))
                return usage();
            ++arg;
        } else if (strcmp(a, "--background") == 0 && value != NULL) {
            if (sscanf(value, "%f,%f,%f", &background.r, &background.g, &background.b) != 3)
                return usage();
            backgroundGiven = 1;
            ++arg;
        } else if (strcmp(a, "--save") == 0 && value != NULL) {
            v.savePrefix = value;
            ++arg;
        } else if (strcmp(a, "--script") == 0 && value != NULL) {
            script = value;
            ++arg;
        } else if (strcmp(a, "--fit-camera") == 0) {
            fitCamera = 1;
        } else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            printUsage(stdout);
            return kExitDone;
        } else if (a[0] == '-' || in != NULL) {
            return usage();
        } else {
            in = a;
        }
    }
    if (in == NULL)
        return usage();
    /* A test or script reads the event lines as they come. */
    setvbuf(stdout, NULL, _IOLBF, 0);
    if (Q3Initialize() != kQ3Success)
        return kExitCannotDraw;
    Q3Warning_Register(q3load_printWarning, 0);
    count = q3load_read(in, &objects);
    if (count < 0) {
        Q3Exit();
        return kExitUnreadable;
    }
    v.path = in;
    v.width = width;
    v.height = height;
    v.renderer = renderer;
    v.fill = kQ3FillStyleFilled;
    v.lightsOn = 1;
    v.zoom = 1;
    strcpy(v.picked, "nothing");
    v.model = Q3DisplayGroup_New();
    for (i = 0; i < count; ++i) {
        if (Q3Object_IsDrawable(objects[i]))
            Q3Group_AddObject(v.model, objects[i]);
        else if (fileLights == NULL && Q3Object_GetLeafType(objects[i]) == kQ3GroupTypeLight)
            fileLights = objects[i];
        else if (v.fileCamera == NULL && Q3Object_IsType(objects[i], kQ3ShapeTypeCamera))
            v.fileCamera = objects[i];
        else if (Q3Object_IsType(objects[i], kQ3SharedTypeViewHints))
            q3load_readHints(objects[i], &hintsCamera, &hintsLights, &hintsBackground, &background, backgroundGiven);
    }
    if (v.fileCamera == NULL)
        v.fileCamera = hintsCamera;
    if (fitCamera)
        v.fileCamera = NULL;
    if (fileLights == NULL)
        fileLights = hintsLights;

    v.display = XOpenDisplay(NULL);
    if (v.display == NULL) {
        const char *name = getenv("DISPLAY");
        fprintf(stderr, "cannot open the X display %s%s\n", name != NULL && *name != '\0' ? name : "(DISPLAY is not set)",
                name != NULL && *name != '\0' ? "" : ": q3view needs an X server");
        status = kExitNoDisplay;
        goto done;
    }
    XSetIOErrorHandler(lostDisplay);
    XSetErrorHandler(xError);
    visualInfo = Q3X_GetVisualInfo(v.display, DefaultScreenOfDisplay(v.display));
    if (visualInfo == NULL) {
        fprintf(stderr, "the X display has no visual Q3 can draw with: %s\n", Q3Error_GetMessage());
        XCloseDisplay(v.display);
        status = kExitNoDisplay;
        goto done;
    }
    memset(&attributes, 0, sizeof attributes);
    attributes.colormap = XCreateColormap(v.display, RootWindow(v.display, visualInfo->screen), visualInfo->visual,
                                          AllocNone);
    attributes.background_pixel = 0;
    attributes.border_pixel = 0;
    attributes.event_mask = ExposureMask | StructureNotifyMask | KeyPressMask | ButtonPressMask |
                            ButtonReleaseMask | PointerMotionMask;
    v.window = XCreateWindow(v.display, RootWindow(v.display, visualInfo->screen), 0, 0, (unsigned)width,
                             (unsigned)height, 0, visualInfo->depth, InputOutput, visualInfo->visual,
                             CWColormap | CWBackPixel | CWBorderPixel | CWEventMask, &attributes);
    v.deleteWindow = XInternAtom(v.display, "WM_DELETE_WINDOW", False);
    XSetWMProtocols(v.display, v.window, &v.deleteWindow, 1);
    setTitle(&v);
    XMapWindow(v.display, v.window);
    XSync(v.display, False);

    memset(&contextData, 0, sizeof contextData);
    contextData.contextData.clearImageMethod = kQ3ClearMethodWithColor;
    contextData.contextData.clearImageColor = background;
    contextData.contextData.clearImageColor.a = 1.0f;
    contextData.contextData.paneState = kQ3False;
    contextData.contextData.maskState = kQ3False;
    contextData.contextData.doubleBufferState = kQ3True;
    contextData.display = v.display;
    contextData.drawable = v.window;
    contextData.visual = visualInfo->visual;
    contextData.cmap = attributes.colormap;
    contextData.colorMapData = NULL;
    v.context = Q3XDrawContext_New(&contextData);
    v.view = Q3View_New();
    v.subdivision = Q3SubdivisionStyle_New(&subdivision);
    v.phong = Q3PhongIllumination_New();
    v.flat = Q3NULLIllumination_New();
    v.noLights = Q3LightGroup_New();
    if (fileLights != NULL) {
        v.lights = Q3Shared_GetReference(fileLights);
    } else {
        TQ3LightData ambient = {kQ3True, 0.3f, {1.0f, 1.0f, 1.0f}};
        TQ3DirectionalLightData directional = {{kQ3True, 1.0f, {1.0f, 1.0f, 1.0f}}, kQ3False, {0, 0, -1}};
        TQ3LightObject a = Q3AmbientLight_New(&ambient);
        v.headLight = Q3DirectionalLight_New(&directional);
        v.lights = Q3LightGroup_New();
        Q3Group_AddObject(v.lights, a);
        Q3Group_AddObject(v.lights, v.headLight);
        Q3Object_Dispose(a);
    }
    status = kExitDone;
    if (v.context == NULL || v.view == NULL || v.subdivision == NULL || v.phong == NULL || v.flat == NULL ||
        v.lights == NULL || v.noLights == NULL || Q3View_SetDrawContext(v.view, v.context) != kQ3Success) {
        fprintf(stderr, "cannot draw into the window: %s\n", Q3Error_GetMessage());
        status = kExitCannotDraw;
    } else {
        findHome(&v);
        if (!useNewCamera(&v) || Q3View_SetRendererByType(v.view, v.renderer) != kQ3Success ||
            Q3View_SetLightGroup(v.view, v.lights) != kQ3Success) {
            fprintf(stderr, "cannot draw %s: %s\n", in, Q3Error_GetMessage());
            status = kExitCannotDraw;
        } else {
            v.dirty = 1;
            status = run(&v, script);
        }
    }
    if (v.camera != NULL)
        Q3Object_Dispose(v.camera);
    if (v.headLight != NULL)
        Q3Object_Dispose(v.headLight);
    if (v.lights != NULL)
        Q3Object_Dispose(v.lights);
    if (v.noLights != NULL)
        Q3Object_Dispose(v.noLights);
    if (v.flat != NULL)
        Q3Object_Dispose(v.flat);
    if (v.phong != NULL)
        Q3Object_Dispose(v.phong);
    if (v.subdivision != NULL)
        Q3Object_Dispose(v.subdivision);
    if (v.view != NULL)
        Q3Object_Dispose(v.view);
    if (v.context != NULL)
        Q3Object_Dispose(v.context);
    XDestroyWindow(v.display, v.window);
    XFreeColormap(v.display, attributes.colormap);
    XFree(visualInfo);
    XCloseDisplay(v.display);
done:
    if (hintsCamera != NULL)
        Q3Object_Dispose(hintsCamera);
    if (hintsLights != NULL)
        Q3Object_Dispose(hintsLights);
    Q3Object_Dispose(v.model);
    q3load_free(objects, count);
    Q3Exit();
    return status;
}
