/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * QD3DController.h as a 1990s program used it, in C99: a device driver that
 * registers a controller with channel methods and reports values, buttons
 * and motion, and an application that finds it through the controller list,
 * attaches it to a tracker whose notify function moves the camera, saves and
 * restores the device's channels around a suspend, and reads the cursor
 * tracker's deltas. The exit status says whether every call behaved.
 */
#include <QD3D.h>
#include <QD3DCamera.h>
#include <QD3DController.h>
#include <QD3DErrors.h>
#include <QD3DMath.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

static unsigned char gGain[4] = {1, 2, 3, 4};
static unsigned long gGainSize = 4;
static TQ3CameraObject gCamera = NULL;
static int gNotified = 0;
static int gFailures = 0;

#define CHECK(condition)                                                      \
    do {                                                                      \
        if (!(condition)) {                                                   \
            fprintf(stderr, "%s:%d: %s\n", __FILE__, __LINE__, #condition);   \
            ++gFailures;                                                      \
        }                                                                     \
    } while (0)

/* ---- The driver ---- */

static TQ3Status MyChannelGet(TQ3ControllerRef controllerRef, unsigned long channel, void *data,
                              unsigned long *dataSize)
{
    (void)controllerRef;
    if (channel != 0 || *dataSize < gGainSize)
        return kQ3Failure;
    memcpy(data, gGain, gGainSize);
    *dataSize = gGainSize;
    return kQ3Success;
}

static TQ3Status MyChannelSet(TQ3ControllerRef controllerRef, unsigned long channel, const void *data,
                              unsigned long dataSize)
{
    (void)controllerRef;
    if (channel != 0 || dataSize > sizeof gGain)
        return kQ3Failure;
    if (dataSize > 0)
        memcpy(gGain, data, dataSize);
    gGainSize = dataSize;
    return kQ3Success;
}

static TQ3ControllerRef MyDriverStart(void)
{
    TQ3ControllerData data;
    TQ3ControllerRef controller;

    data.signature = "Legacy Devices Inc.:Space Puck";
    data.valueCount = 6;
    data.channelCount = 1;
    data.channelGetMethod = MyChannelGet;
    data.channelSetMethod = MyChannelSet;
    controller = Q3Controller_New(&data);
    if (controller != NULL)
        Q3Controller_SetActivation(controller, kQ3True);
    return controller;
}

/* ---- The application ---- */

static TQ3Status MyTrackerNotify(TQ3TrackerObject tracker, TQ3ControllerRef controller)
{
    TQ3Point3D position;
    TQ3Boolean changed;
    TQ3CameraPlacement placement;

    (void)controller;
    Q3Tracker_GetPosition(tracker, &position, NULL, &changed, NULL);
    Q3Camera_GetPlacement(gCamera, &placement);
    placement.cameraLocation = position;
    placement.pointOfInterest.x = position.x;
    placement.pointOfInterest.y = position.y;
    placement.pointOfInterest.z = position.z - 1.0f;
    gNotified++;
    return Q3Camera_SetPlacement(gCamera, &placement);
}

static TQ3ControllerRef MyFindDevice(const char *signature)
{
    TQ3ControllerRef controller = NULL;
    char name[256];

    for (Q3Controller_Next(NULL, &controller); controller != NULL; Q3Controller_Next(controller, &controller)) {
        if (Q3Controller_GetSignature(controller, name, sizeof name) == kQ3Success && strcmp(name, signature) == 0)
            return controller;
    }
    return NULL;
}

int main(void)
{
    TQ3ViewAngleAspectCameraData cameraData;
    TQ3ControllerRef device;
    TQ3TrackerObject tracker;
    TQ3ControllerStateObject state;
    TQ3Boolean listChanged, changed, hasOrientation;
    unsigned long listSerial = 0, serial = 0, buttons = 0;
    float values[6] = {0.1f, 0.2f, 0.3f, 0.0f, 0.0f, 0.0f}, readBack[6];
    TQ3Point3D origin = {0.0f, 0.0f, 10.0f};
    TQ3Vector3D push = {0.0f, 0.0f, -4.0f};
    TQ3CameraPlacement placement;
    TQ3Quaternion turn;
    float depth;
    unsigned char gain[4];
    unsigned long gainSize = sizeof gain;

    if (Q3Initialize() != kQ3Success)
        return 1;

    memset(&cameraData, 0, sizeof cameraData);
    cameraData.cameraData.placement.cameraLocation = origin;
    cameraData.cameraData.placement.upVector.y = 1.0f;
    cameraData.cameraData.range.hither = 0.1f;
    cameraData.cameraData.range.yon = 100.0f;
    cameraData.cameraData.viewPort.origin.x = -1.0f;
    cameraData.cameraData.viewPort.origin.y = 1.0f;
    cameraData.cameraData.viewPort.width = 2.0f;
    cameraData.cameraData.viewPort.height = 2.0f;
    cameraData.fov = 1.0f;
    cameraData.aspectRatioXToY = 1.0f;
    gCamera = Q3ViewAngleAspectCamera_New(&cameraData);
    CHECK(gCamera != NULL);

    device = MyDriverStart();
    CHECK(device != NULL);
    CHECK(Q3Controller_GetListChanged(&listChanged, &listSerial) == kQ3Success && listChanged == kQ3True);
    CHECK(MyFindDevice("Legacy Devices Inc.:Space Puck") == device);

    tracker = Q3Tracker_New(MyTrackerNotify);
    CHECK(Q3Tracker_SetNotifyThresholds(tracker, 0.5f, 0.1f) == kQ3Success);
    CHECK(Q3Controller_SetTracker(device, tracker) == kQ3Success);
    CHECK(Q3Controller_SetTrackerPosition(device, &origin) == kQ3Success);
    CHECK(Q3Controller_MoveTrackerPosition(device, &push) == kQ3Success);
    CHECK(gNotified == 2);
    CHECK(Q3Camera_GetPlacement(gCamera, &placement) == kQ3Success);
    CHECK(fabs(placement.cameraLocation.z - 6.0f) < 1e-5f);

    CHECK(Q3Controller_SetButtons(device, 1) == kQ3Success);
    CHECK(Q3Tracker_GetButtons(tracker, &buttons) == kQ3Success && buttons == 1);
    CHECK(Q3Controller_SetValues(device, values, 3) == kQ3Success);
    CHECK(Q3Controller_GetValues(device, 6, readBack, &changed, &serial) == kQ3Success && changed == kQ3True);
    CHECK(readBack[2] == 0.3f);

    /* Suspend: save and reset the device's channels; resume: restore them. */
    state = Q3ControllerState_New(device);
    CHECK(state != NULL);
    CHECK(Q3ControllerState_SaveAndReset(state) == kQ3Success && gGainSize == 0);
    CHECK(Q3ControllerState_Restore(state) == kQ3Success);
    CHECK(Q3Controller_GetChannel(device, 0, gain, &gainSize) == kQ3Success && gainSize == 4 && gain[3] == 4);

    /* The cursor tracker, as a 3D cursor. */
    CHECK(Q3Controller_SetTracker(device, NULL) == kQ3Success);
    CHECK(Q3CursorTracker_SetTrackDeltas(kQ3True) == kQ3Success);
    CHECK(Q3CursorTracker_PrepareTracking() == kQ3Success);
    CHECK(Q3Controller_MoveTrackerPosition(device, &push) == kQ3Success);
    Q3Quaternion_SetRotate_Z(&turn, 0.5f);
    CHECK(Q3Controller_MoveTrackerOrientation(device, &turn) == kQ3Success);
    CHECK(Q3CursorTracker_GetAndClearDeltas(&depth, &turn, &hasOrientation, &changed, NULL) == kQ3Success);
    CHECK(depth == -4.0f && hasOrientation == kQ3True);

    /* Bad input is refused through the error manager. */
    CHECK(Q3Controller_SetValues(device, values, 7) == kQ3Failure);
    CHECK(Q3Error_Get(NULL) == kQ3ErrorParameterOutOfRange);

    Q3Controller_Decommission(device);
    Q3Object_Dispose(state);
    Q3Object_Dispose(tracker);
    Q3Object_Dispose(gCamera);
    CHECK(Q3Exit() == kQ3Success);
    if (gFailures == 0)
        printf("LegacyController: every call behaved\n");
    return gFailures == 0 ? 0 : 1;
}
