/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Legacy code for QuickDraw 3D 1.6's X11 draw context, written the way
 * Apple's Unix samples were: an Xlib window, Q3X_GetVisualInfo,
 * TQ3XDrawContextData filled field by field, Q3XDrawContext_New, and a
 * render loop turning a box, with Q3XBuffers_Swap after each frame. It
 * compiles as strict C99 against the public headers only and runs on an
 * Xvfb it starts itself (exit 77, "skipped", when Xvfb is missing). Returns
 * 0 when every frame reached the window: its centre shows the box and its
 * corner the clear colour.
 */
#define _POSIX_C_SOURCE 200809L

#include <QD3D.h>
#include <QD3DCamera.h>
#include <QD3DDrawContext.h>
#include <QD3DErrors.h>
#include <QD3DGeometry.h>
#include <QD3DMath.h>
#include <QD3DRenderer.h>
#include <QD3DTransform.h>
#include <QD3DView.h>

#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#define kWidth  160
#define kHeight 120

static int gFailures = 0;
static pid_t gServer = -1;

static void Check(int ok, const char *what)
{
    if (!ok) {
        printf("LegacyX11: %s failed (error %d)\n", what, (int)Q3Error_Get(NULL));
        gFailures++;
    }
}

#define CHECK(call) Check((call) == kQ3Success, #call)

/* Starts Xvfb on a free display; returns its name, or NULL. */
static const char *StartServer(void)
{
    static char name[32];
    int fds[2];
    char number[16];
    size_t length = 0;
    struct pollfd wait;

    if (pipe(fds) != 0)
        return NULL;
    gServer = fork();
    if (gServer == 0) {
        char fd[16];
        close(fds[0]);
        sprintf(fd, "%d", fds[1]);
        if (freopen("/dev/null", "w", stderr) == NULL)
            _exit(127);
        execlp("Xvfb", "Xvfb", "-displayfd", fd, "-screen", "0", "640x480x24", "-nolisten", "tcp", (char *)NULL);
        _exit(127);
    }
    close(fds[1]);
    wait.fd = fds[0];
    wait.events = POLLIN;
    while (length + 1 < sizeof number && poll(&wait, 1, 20000) > 0) {
        char c;
        if (read(fds[0], &c, 1) != 1 || c == '\n')
            break;
        number[length++] = c;
    }
    close(fds[0]);
    if (length == 0)
        return NULL;
    number[length] = '\0';
    sprintf(name, ":%s", number);
    return name;
}

static void StopServer(void)
{
    if (gServer > 0) {
        kill(gServer, SIGTERM);
        waitpid(gServer, NULL, 0);
    }
}

static TQ3DrawContextObject MyNewDrawContext(Display *display, Window window, Visual *visual)
{
    TQ3XDrawContextData data;

    memset(&data, 0, sizeof data);
    data.contextData.clearImageMethod = kQ3ClearMethodWithColor;
    data.contextData.clearImageColor.a = 1.0f;
    data.contextData.clearImageColor.r = 0.0f;
    data.contextData.clearImageColor.g = 0.0f;
    data.contextData.clearImageColor.b = 1.0f;
    data.contextData.paneState = kQ3False;
    data.contextData.maskState = kQ3False;
    data.contextData.doubleBufferState = kQ3True;
    data.display = display;
    data.drawable = window;
    data.visual = visual;
    data.cmap = DefaultColormap(display, DefaultScreen(display));
    data.colorMapData = NULL;
    return Q3XDrawContext_New(&data);
}

int main(void)
{
    const char *serverName;
    Display *display;
    XVisualInfo *visualInfo;
    Window window;
    XEvent event;
    TQ3XBufferObject buffers;
    TQ3DrawContextObject drawContext;
    TQ3ViewObject view;
    TQ3CameraObject camera;
    TQ3RendererObject renderer;
    TQ3ViewAngleAspectCameraData cameraData;
    TQ3BoxData box;
    TQ3Matrix4x4 rotation;
    TQ3ViewStatus status;
    XImage *image;
    int frame;

    serverName = StartServer();
    if (serverName == NULL) {
        printf("LegacyX11: skipped, Xvfb could not be started (scripts/setup.sh installs xvfb)\n");
        StopServer();
        return 77;
    }
    display = XOpenDisplay(serverName);
    if (display == NULL) {
        printf("LegacyX11: cannot open %s\n", serverName);
        StopServer();
        return 1;
    }
    CHECK(Q3Initialize());

    visualInfo = Q3X_GetVisualInfo(display, DefaultScreenOfDisplay(display));
    Check(visualInfo != NULL, "Q3X_GetVisualInfo");
    if (visualInfo == NULL) {
        StopServer();
        return 1;
    }
    window = XCreateSimpleWindow(display, RootWindow(display, DefaultScreen(display)), 0, 0, kWidth, kHeight, 0,
                                 0, 0);
    XSelectInput(display, window, StructureNotifyMask);
    XMapWindow(display, window);
    do
        XNextEvent(display, &event);
    while (event.type != MapNotify);

    drawContext = MyNewDrawContext(display, window, visualInfo->visual);
    Check(drawContext != NULL, "Q3XDrawContext_New");
    buffers = Q3XBuffers_New(display, 2, window);
    Check(buffers != NULL, "Q3XBuffers_New");

    memset(&cameraData, 0, sizeof cameraData);
    cameraData.cameraData.placement.cameraLocation.z = 4.0f;
    cameraData.cameraData.placement.upVector.y = 1.0f;
    cameraData.cameraData.range.hither = 0.5f;
    cameraData.cameraData.range.yon = 20.0f;
    cameraData.cameraData.viewPort.origin.x = -1.0f;
    cameraData.cameraData.viewPort.origin.y = 1.0f;
    cameraData.cameraData.viewPort.width = 2.0f;
    cameraData.cameraData.viewPort.height = 2.0f;
    cameraData.fov = 0.8f;
    cameraData.aspectRatioXToY = (float)kWidth / kHeight;
    camera = Q3ViewAngleAspectCamera_New(&cameraData);
    renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    view = Q3View_New();
    CHECK(Q3View_SetCamera(view, camera));
    CHECK(Q3View_SetRenderer(view, renderer));
    CHECK(Q3View_SetDrawContext(view, drawContext));

    Q3Point3D_Set(&box.origin, -0.5f, -0.5f, -0.5f);
    Q3Vector3D_Set(&box.orientation, 0.0f, 1.0f, 0.0f);
    Q3Vector3D_Set(&box.majorAxis, 0.0f, 0.0f, 1.0f);
    Q3Vector3D_Set(&box.minorAxis, 1.0f, 0.0f, 0.0f);
    box.faceAttributeSet = NULL;
    box.boxAttributeSet = NULL;

    for (frame = 0; frame < 3; frame++) {
        Q3Matrix4x4_SetRotate_XYZ(&rotation, 0.3f * frame, 0.5f * frame, 0.0f);
        CHECK(Q3View_StartRendering(view));
        do {
            CHECK(Q3MatrixTransform_Submit(&rotation, view));
            CHECK(Q3Box_Submit(&box, view));
            status = Q3View_EndRendering(view);
        } while (status == kQ3ViewStatusRetraverse);
        Check(status == kQ3ViewStatusDone, "the rendering loop");
        Q3XBuffers_Swap(display, buffers);
    }

    XSync(display, False);
    image = XGetImage(display, window, 0, 0, kWidth, kHeight, AllPlanes, ZPixmap);
    Check(image != NULL, "XGetImage");
    if (image != NULL) {
        unsigned long centre = XGetPixel(image, kWidth / 2, kHeight / 2) & 0xFFFFFFUL;
        unsigned long corner = XGetPixel(image, 0, 0) & 0xFFFFFFUL;
        Check(corner == 0x0000FFUL, "the clear colour in the window's corner");
        Check(centre != 0x0000FFUL && centre != 0, "the box in the window's centre");
        XDestroyImage(image);
    }

    Q3Object_Dispose(view);
    Q3Object_Dispose(camera);
    Q3Object_Dispose(renderer);
    Q3Object_Dispose(drawContext);
    XFree(visualInfo);
    XDestroyWindow(display, window);
    XCloseDisplay(display);
    CHECK(Q3Exit());
    StopServer();
    return gFailures == 0 ? 0 : 1;
}
