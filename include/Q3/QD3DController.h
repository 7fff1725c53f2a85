/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * The Pointing Device Manager: controllers, controller states, trackers and
 * the system cursor tracker, as QuickDraw 3D 1.6 declares them (the QD3D
 * Book, chapter "Pointing Device Manager").
 *
 * A controller stands for one pointing device. Its driver makes it with
 * Q3Controller_New and reports the device's state through it: values
 * (Q3Controller_SetValues), buttons, and the position and orientation of
 * the tracker the controller drives. A tracker is the thing in the
 * application's interface that devices move (a camera, a selected object);
 * the application makes it with Q3Tracker_New, attaches controllers to it
 * with Q3Controller_SetTracker, and reads it by polling (serial numbers) or
 * through its notify function. A controller with no tracker drives the
 * system cursor tracker (Q3CursorTracker_*).
 *
 * In Q3 all of this lives in the calling process: the list of controllers
 * is the process's own, there is no device server and no other
 * application. A driver is ordinary code calling these functions (a test, a
 * joystick or 6-DOF library's event loop). Controllers stay valid until the
 * Q3Exit that balances the first Q3Initialize, which forgets them all.
 *
 * Positions are points in the tracker's space (the application decides what
 * that is, typically world coordinates); orientations are quaternions
 * (QD3DMath.h's convention). A tracker keeps an absolute position and
 * orientation, set with _SetPosition/_SetOrientation, and an accumulator of
 * relative motion, fed by _MovePosition/_MoveOrientation and handed out (or
 * folded into the absolute value) by _GetPosition/_GetOrientation.
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error, returns kQ3Failure (or NULL) and changes
 * nothing. The checks run in this order: Q3 is initialized; then the
 * arguments from left to right (a TQ3ControllerRef: not NULL
 * (kQ3ErrorNULLParameter), one that Q3Controller_New returned since the
 * last full Q3Exit (kQ3ErrorInvalidParameter); an object: not NULL, live,
 * of the right class; an output pointer: not NULL; a float: finite
 * (kQ3ErrorInvalidParameter)); then the conditions the function lists.
 * Calls on an inactive controller or tracker that Apple documents as
 * having "no effect" succeed and change nothing.
 *
 * Notify functions are called synchronously, from inside the call that
 * caused the change, and never reentrantly: a tracker's notify function is
 * not called again while it runs (changes it makes to its own tracker are
 * kept, but do not notify).
 */
#ifndef QD3DCONTROLLER_H
#define QD3DCONTROLLER_H

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The most bytes one channel's data may have (Q3Controller_SetChannel). */
#define kQ3ControllerSetChannelMaxDataSize 256

/*
 * A driver's channel methods: read or write channel `channel` of the
 * device. The get method receives in *dataSize the room at data and
 * returns there the bytes it wrote; the set method receives the bytes to
 * apply. Q3 calls them from Q3Controller_GetChannel/_SetChannel and the
 * controller state calls, and returns what they return.
 */
typedef TQ3Status (*TQ3ChannelGetMethod)(TQ3ControllerRef controllerRef, unsigned long channel, void *data,
                                          unsigned long *dataSize);
typedef TQ3Status (*TQ3ChannelSetMethod)(TQ3ControllerRef controllerRef, unsigned long channel,
                                          const void *data, unsigned long dataSize);

/*
 * What a driver tells Q3Controller_New about its device.
 *   signature       NUL-terminated text naming the maker and model; not NULL.
 *   valueCount      how many float values the device reports (at most 1024).
 *   channelCount    how many channels it has (at most 1024).
 *   channelGetMethod, channelSetMethod  may be NULL: the device cannot
 *                   report (GetChannel gives 0 bytes) or take channel data
 *                   (SetChannel is accepted and ignored).
 */
typedef struct TQ3ControllerData {
    char *signature;
    unsigned long valueCount;
    unsigned long channelCount;
    TQ3ChannelGetMethod channelGetMethod;
    TQ3ChannelSetMethod channelSetMethod;
} TQ3ControllerData;

/* ---- Controllers --------------------------------------------------------- */

/*
 * Q3Controller_GetListChanged: whether the list of controllers changed (a
 * controller was made, recommissioned, decommissioned, activated or
 * deactivated) since *serialNumber was read: *listChanged is kQ3True when
 * *serialNumber differs from the list's serial number, which is then
 * stored in *serialNumber. Pass 0 the first time.
 * Errors: kQ3ErrorNULLParameter (listChanged, serialNumber).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_GetListChanged(TQ3Boolean *listChanged, unsigned long *serialNumber);

/*
 * Q3Controller_Next: the controller after controllerRef in the list, in the
 * order they were made, or the first one when controllerRef is NULL;
 * *nextControllerRef is NULL after the last. Decommissioned controllers are
 * skipped.
 * Errors: kQ3ErrorInvalidParameter (controllerRef not a controller),
 * kQ3ErrorNULLParameter (nextControllerRef).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_Next(TQ3ControllerRef controllerRef, TQ3ControllerRef *nextControllerRef);

/*
 * Q3Controller_New: a new controller for a device, made inactive (its
 * driver activates it when the device is on line), with no tracker, no
 * buttons down and every value 0. If a decommissioned controller has the
 * same signature, that controller is recommissioned instead (new counts
 * and methods, values reset, inactive) and returned. The list's serial
 * number changes. The signature is copied.
 * Errors: kQ3ErrorNULLParameter (controllerData, controllerData->signature),
 * kQ3ErrorParameterOutOfRange (valueCount or channelCount above 1024).
 * Ownership: the controller belongs to Q3 until the last Q3Exit; there is
 * nothing to dispose.
 */
Q3_EXTERN_API_C(TQ3ControllerRef) Q3Controller_New(const TQ3ControllerData *controllerData);

/*
 * Q3Controller_Decommission: the device is gone. The controller becomes
 * inactive, its buttons are withdrawn from its tracker (whose notify
 * function may run), and it leaves the list Q3Controller_Next walks; the
 * reference stays valid, its getters answer defaults and its setters do
 * nothing. The list's serial number changes (once: decommissioning twice
 * is not a change).
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_Decommission(TQ3ControllerRef controllerRef);

/*
 * Q3Controller_SetActivation: makes the controller active or inactive
 * (any nonzero TQ3Boolean counts as kQ3True). An inactive controller's
 * values, buttons and tracker calls have no effect; deactivating withdraws
 * its buttons from its tracker, reactivating reports them again (the
 * tracker's notify function may run). A change changes the list's serial
 * number. No effect on a decommissioned controller.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_SetActivation(TQ3ControllerRef controllerRef, TQ3Boolean active);

/*
 * Q3Controller_GetActivation: whether the controller is active.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter (active).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_GetActivation(TQ3ControllerRef controllerRef, TQ3Boolean *active);

/*
 * Q3Controller_GetSignature: copies the signature into signature, at most
 * numChars - 1 characters and a terminating NUL (longer signatures are
 * cut).
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter (signature), kQ3ErrorParameterOutOfRange
 * (numChars 0: no room for the NUL).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_GetSignature(TQ3ControllerRef controllerRef, char *signature,
                                                     unsigned long numChars);

/*
 * Q3Controller_SetChannel: hands dataSize bytes at data to the driver's
 * channel set method for channel `channel` and returns its result (a
 * failure posts kQ3ErrorInvalidParameter). Accepted and ignored when the
 * controller has no set method or is decommissioned.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorParameterOutOfRange (channel not below channelCount; dataSize
 * above kQ3ControllerSetChannelMaxDataSize), kQ3ErrorNULLParameter (data
 * NULL with dataSize above 0), kQ3ErrorInvalidParameter (the set method
 * failed).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_SetChannel(TQ3ControllerRef controllerRef, unsigned long channel,
                                                   const void *data, unsigned long dataSize);

/*
 * Q3Controller_GetChannel: asks the driver's channel get method for
 * channel `channel`: *dataSize is the room at data on entry and the bytes
 * written on return. With no get method, or decommissioned, *dataSize
 * becomes 0.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorParameterOutOfRange (channel), kQ3ErrorNULLParameter (data,
 * dataSize), kQ3ErrorInvalidParameter (the get method failed, or reported
 * more bytes than there was room for).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_GetChannel(TQ3ControllerRef controllerRef, unsigned long channel, void *data,
                                                   unsigned long *dataSize);

/*
 * Q3Controller_GetValueCount: how many values the controller reports.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter (valueCount).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_GetValueCount(TQ3ControllerRef controllerRef, unsigned long *valueCount);

/*
 * Q3Controller_SetTracker: attaches the controller to tracker, or to the
 * system cursor tracker when tracker is NULL. The controller's buttons
 * move from the old tracker to the new one. The controller does not keep
 * a reference: disposing the tracker detaches it (back to the cursor).
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType (tracker).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_SetTracker(TQ3ControllerRef controllerRef, TQ3TrackerObject tracker);

/*
 * Q3Controller_HasTracker: kQ3True when the controller is active and
 * attached to an active tracker of the application (not the cursor).
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter (hasTracker).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_HasTracker(TQ3ControllerRef controllerRef, TQ3Boolean *hasTracker);

/*
 * Q3Controller_Track2DCursor: kQ3True when the controller is active,
 * drives the system cursor tracker, and the cursor ignores depth and
 * orientation (Q3CursorTracker_SetTrackDeltas(kQ3False), the default).
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter (track2DCursor).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_Track2DCursor(TQ3ControllerRef controllerRef, TQ3Boolean *track2DCursor);

/*
 * Q3Controller_Track3DCursor: as Track2DCursor, but kQ3True when the cursor
 * tracks depth and orientation (Q3CursorTracker_SetTrackDeltas(kQ3True)).
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter (track3DCursor).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_Track3DCursor(TQ3ControllerRef controllerRef, TQ3Boolean *track3DCursor);

/*
 * Q3Controller_GetButtons: the controller's own button state (bit i set:
 * button i down).
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter (buttons).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_GetButtons(TQ3ControllerRef controllerRef, unsigned long *buttons);

/*
 * Q3Controller_SetButtons: the driver reports the device's buttons. The
 * controller's tracker (or the cursor tracker) receives the change as
 * Q3Tracker_ChangeButtons would, and its notify function may run. No
 * effect on an inactive controller.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_SetButtons(TQ3ControllerRef controllerRef, unsigned long buttons);

/*
 * Q3Controller_GetTrackerPosition: the position of the controller's tracker
 * (or of the cursor tracker), with the relative motion not yet read
 * included; reading it changes nothing.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter (position).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_GetTrackerPosition(TQ3ControllerRef controllerRef, TQ3Point3D *position);

/*
 * Q3Controller_SetTrackerPosition: Q3Tracker_SetPosition on the controller's
 * tracker (or the cursor tracker). No effect on an inactive controller.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (position: NaN or
 * infinite).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_SetTrackerPosition(TQ3ControllerRef controllerRef,
                                                           const TQ3Point3D *position);

/*
 * Q3Controller_MoveTrackerPosition: Q3Tracker_MovePosition on the
 * controller's tracker (or the cursor tracker). No effect on an inactive
 * controller.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (delta).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_MoveTrackerPosition(TQ3ControllerRef controllerRef,
                                                            const TQ3Vector3D *delta);

/*
 * Q3Controller_GetTrackerOrientation: the orientation of the controller's
 * tracker (or of the cursor tracker), relative turns not yet read
 * included; reading it changes nothing.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter (orientation).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_GetTrackerOrientation(TQ3ControllerRef controllerRef,
                                                              TQ3Quaternion *orientation);

/*
 * Q3Controller_SetTrackerOrientation: Q3Tracker_SetOrientation on the
 * controller's tracker (or the cursor tracker). No effect on an inactive
 * controller.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (orientation: not
 * finite, or the zero quaternion).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_SetTrackerOrientation(TQ3ControllerRef controllerRef,
                                                              const TQ3Quaternion *orientation);

/*
 * Q3Controller_MoveTrackerOrientation: Q3Tracker_MoveOrientation on the
 * controller's tracker (or the cursor tracker). No effect on an inactive
 * controller.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (delta).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_MoveTrackerOrientation(TQ3ControllerRef controllerRef,
                                                               const TQ3Quaternion *delta);

/*
 * Q3Controller_GetValues: the controller's values. With serialNumber NULL,
 * or *serialNumber different from the controller's serial number, the
 * first min(valueCount, the controller's count) values are written,
 * *changed is kQ3True and *serialNumber (if given) receives the serial
 * number; otherwise nothing is written and *changed is kQ3False. On an
 * inactive controller nothing is written and *changed is kQ3False.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter (values, changed).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_GetValues(TQ3ControllerRef controllerRef, unsigned long valueCount,
                                                  float *values, TQ3Boolean *changed, unsigned long *serialNumber);

/*
 * Q3Controller_SetValues: the driver reports the first valueCount values;
 * the controller's serial number changes. No effect on an inactive
 * controller.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter (values), kQ3ErrorParameterOutOfRange (valueCount
 * above the controller's count), kQ3ErrorInvalidParameter (a value NaN or
 * infinite).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Controller_SetValues(TQ3ControllerRef controllerRef, const float *values,
                                                  unsigned long valueCount);

/* ---- Controller states --------------------------------------------------- */

/*
 * Q3ControllerState_New: an object that can save and restore a
 * controller's channels (the settings an application changes and another
 * may change while it is in the background). Nothing is saved yet.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (controllerRef).
 * Ownership: returns a new shared object (kQ3SharedTypeControllerState)
 * with one reference for the caller.
 */
Q3_EXTERN_API_C(TQ3ControllerStateObject) Q3ControllerState_New(TQ3ControllerRef controllerRef);

/*
 * Q3ControllerState_SaveAndReset: saves every channel's data (what the get
 * method reports, up to kQ3ControllerSetChannelMaxDataSize bytes; a channel
 * whose get method fails is not saved), then resets each channel by
 * calling the set method with no data (NULL, 0), the driver's signal for
 * "back to the device's default". Call it when the application is about
 * to go to the background. A second call replaces what was saved.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject,
 * kQ3ErrorInvalidObjectType (controllerStateObject),
 * kQ3ErrorInvalidParameter (its controller was forgotten by Q3Exit).
 */
Q3_EXTERN_API_C(TQ3Status) Q3ControllerState_SaveAndReset(TQ3ControllerStateObject controllerStateObject);

/*
 * Q3ControllerState_Restore: hands every saved channel back to the set
 * method. The saved data stays, so it can be restored again.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject,
 * kQ3ErrorInvalidObjectType (controllerStateObject),
 * kQ3ErrorInvalidParameter (controller forgotten), kQ3ErrorStateUnavailable
 * (nothing saved yet).
 */
Q3_EXTERN_API_C(TQ3Status) Q3ControllerState_Restore(TQ3ControllerStateObject controllerStateObject);

/* ---- Trackers ------------------------------------------------------------ */

/*
 * A tracker's notify function: called (with the tracker and the controller
 * whose report caused it, NULL for the application's own calls) when the
 * tracker's position moved by at least its position threshold or its
 * orientation turned by at least its orientation threshold since the last
 * notification, or its buttons changed. The result is ignored.
 */
typedef TQ3Status (*TQ3TrackerNotifyFunc)(TQ3TrackerObject trackerObject, TQ3ControllerRef controllerRef);

/*
 * Q3Tracker_New: a new active tracker at the origin, identity orientation,
 * no buttons down, thresholds 0 (every change notifies), notifying
 * notifyFunc (may be NULL: poll instead).
 * Ownership: returns a new shared object (kQ3SharedTypeTracker) with one
 * reference for the caller.
 */
Q3_EXTERN_API_C(TQ3TrackerObject) Q3Tracker_New(TQ3TrackerNotifyFunc notifyFunc);

/*
 * Q3Tracker_SetNotifyThresholds: how far the position must move (a
 * distance) and the orientation turn (an angle in radians, between 0 and
 * pi) since the last notification before the notify function is called
 * again. A change of 0 never notifies, whatever the threshold.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject,
 * kQ3ErrorInvalidObjectType (trackerObject), kQ3ErrorInvalidParameter (a
 * threshold NaN, infinite or negative).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_SetNotifyThresholds(TQ3TrackerObject trackerObject, float positionThresh,
                                                         float orientationThresh);

/*
 * Q3Tracker_GetNotifyThresholds: the two thresholds.
 * Errors: the tracker's, then kQ3ErrorNULLParameter (positionThresh,
 * orientationThresh).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_GetNotifyThresholds(TQ3TrackerObject trackerObject, float *positionThresh,
                                                         float *orientationThresh);

/*
 * Q3Tracker_SetActivation: an inactive tracker ignores position,
 * orientation and event reports; its button state is still kept, but
 * nothing notifies. Any nonzero TQ3Boolean counts as kQ3True.
 * Errors: the tracker's.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_SetActivation(TQ3TrackerObject trackerObject, TQ3Boolean active);

/*
 * Q3Tracker_GetActivation: whether the tracker is active.
 * Errors: the tracker's, then kQ3ErrorNULLParameter (active).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_GetActivation(TQ3TrackerObject trackerObject, TQ3Boolean *active);

/*
 * Q3Tracker_GetButtons: the tracker's button state: bit i is set when
 * button i is down on any controller reporting to it (the OR of their
 * buttons).
 * Errors: the tracker's, then kQ3ErrorNULLParameter (buttons).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_GetButtons(TQ3TrackerObject trackerObject, unsigned long *buttons);

/*
 * Q3Tracker_ChangeButtons: controllerRef's buttons on this tracker become
 * buttons in the bits buttonMask selects (the other bits keep their
 * state). controllerRef may be NULL (the application's own buttons). When
 * the tracker is active and its button state changed, the notify function
 * runs.
 * Errors: the tracker's, then kQ3ErrorInvalidParameter (controllerRef not
 * NULL and not a controller).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_ChangeButtons(TQ3TrackerObject trackerObject, TQ3ControllerRef controllerRef,
                                                   unsigned long buttons, unsigned long buttonMask);

/*
 * Q3Tracker_GetPosition: the tracker's position, as the QD3D Book says:
 * with serialNumber NULL or different from the tracker's serial number
 * (which changes with every position or orientation report), *position
 * receives the absolute position and *changed is kQ3True; the relative
 * motion accumulated by MovePosition is then either returned in *delta
 * (when delta is not NULL; the absolute position does not include it) or
 * folded into the absolute position (delta NULL), and the accumulator is
 * reset to (0, 0, 0); *serialNumber, if given, receives the serial number.
 * With an equal serial number nothing is written and *changed is
 * kQ3False. On an inactive tracker nothing is written and *changed is
 * kQ3False.
 * Errors: the tracker's, then kQ3ErrorNULLParameter (position, changed).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_GetPosition(TQ3TrackerObject trackerObject, TQ3Point3D *position,
                                                 TQ3Vector3D *delta, TQ3Boolean *changed,
                                                 unsigned long *serialNumber);

/*
 * Q3Tracker_SetPosition: sets the absolute position, reported by
 * controllerRef (NULL: the application). The serial number changes; the
 * notify function may run. No effect on an inactive tracker.
 * Errors: the tracker's, then kQ3ErrorInvalidParameter (controllerRef not
 * NULL and not a controller), kQ3ErrorNULLParameter,
 * kQ3ErrorInvalidParameter (position not finite).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_SetPosition(TQ3TrackerObject trackerObject, TQ3ControllerRef controllerRef,
                                                 const TQ3Point3D *position);

/*
 * Q3Tracker_MovePosition: adds delta to the relative-motion accumulator.
 * The serial number changes; the notify function may run. No effect on an
 * inactive tracker.
 * Errors: as Q3Tracker_SetPosition (delta).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_MovePosition(TQ3TrackerObject trackerObject, TQ3ControllerRef controllerRef,
                                                  const TQ3Vector3D *delta);

/*
 * Q3Tracker_GetOrientation: as Q3Tracker_GetPosition for the orientation:
 * the accumulated relative turn is returned in *delta or folded into the
 * absolute orientation (absolute first, then the turn:
 * Q3Quaternion_Multiply(absolute, turn)), and the accumulator is reset to
 * the identity.
 * Errors: the tracker's, then kQ3ErrorNULLParameter (orientation,
 * changed).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_GetOrientation(TQ3TrackerObject trackerObject, TQ3Quaternion *orientation,
                                                    TQ3Quaternion *delta, TQ3Boolean *changed,
                                                    unsigned long *serialNumber);

/*
 * Q3Tracker_SetOrientation: sets the absolute orientation (stored
 * normalized). The serial number changes; the notify function may run. No
 * effect on an inactive tracker.
 * Errors: the tracker's, then kQ3ErrorInvalidParameter (controllerRef),
 * kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter (orientation not finite
 * or the zero quaternion).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_SetOrientation(TQ3TrackerObject trackerObject, TQ3ControllerRef controllerRef,
                                                    const TQ3Quaternion *orientation);

/*
 * Q3Tracker_MoveOrientation: adds the turn delta (normalized) to the
 * relative accumulator (the accumulated turn first, then delta). The
 * serial number changes; the notify function may run. No effect on an
 * inactive tracker.
 * Errors: as Q3Tracker_SetOrientation (delta).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_MoveOrientation(TQ3TrackerObject trackerObject, TQ3ControllerRef controllerRef,
                                                     const TQ3Quaternion *delta);

/*
 * Q3Tracker_SetEventCoordinates: records the tracker's state at timeStamp
 * (typically a button click) in its ring buffer of the 16 latest events:
 * buttons, and position and orientation (NULL: the tracker's current
 * ones, relative motion included). No effect on an inactive tracker.
 * Errors: the tracker's, then kQ3ErrorInvalidParameter (position or
 * orientation not finite, orientation the zero quaternion).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_SetEventCoordinates(TQ3TrackerObject trackerObject, unsigned long timeStamp,
                                                         unsigned long buttons, const TQ3Point3D *position,
                                                         const TQ3Quaternion *orientation);

/*
 * Q3Tracker_GetEventCoordinates: the recorded event whose time stamp is
 * closest to timeStamp (the older of two equally close); every older event
 * is discarded. Any output may be NULL.
 * Errors: the tracker's, then kQ3ErrorDataNotAvailable (no event
 * recorded).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Tracker_GetEventCoordinates(TQ3TrackerObject trackerObject, unsigned long timeStamp,
                                                         unsigned long *buttons, TQ3Point3D *position,
                                                         TQ3Quaternion *orientation);

/* ---- The system cursor tracker ------------------------------------------- */

/*
 * The cursor tracker's notify function, called when a controller attached
 * to no tracker moves the cursor tracker or changes its buttons.
 */
typedef void (*TQ3CursorTrackerNotifyFunc)(void);

/*
 * Q3CursorTracker_PrepareTracking: starts a tracking session: the depth and
 * orientation deltas Q3CursorTracker_GetAndClearDeltas reports are
 * cleared.
 */
Q3_EXTERN_API_C(TQ3Status) Q3CursorTracker_PrepareTracking(void);

/*
 * Q3CursorTracker_SetTrackDeltas: whether the cursor tracker keeps the
 * depth (z) and orientation deltas of the controllers driving it
 * (kQ3True: a 3D cursor) or ignores them (kQ3False, the default: a 2D
 * cursor). Any nonzero TQ3Boolean counts as kQ3True.
 */
Q3_EXTERN_API_C(TQ3Status) Q3CursorTracker_SetTrackDeltas(TQ3Boolean trackDeltas);

/*
 * Q3CursorTracker_GetAndClearDeltas: the depth change (the z of the
 * position reports) and the orientation turn accumulated since the last
 * call (or PrepareTracking), then clears them. *hasOrientation says
 * whether any orientation was reported; with serialNumber given and equal
 * to the cursor tracker's serial number nothing is written and *changed is
 * kQ3False. While deltas are not tracked the answer is 0 and the identity.
 * Errors: kQ3ErrorNULLParameter (depth, orientation, hasOrientation,
 * changed).
 */
Q3_EXTERN_API_C(TQ3Status) Q3CursorTracker_GetAndClearDeltas(float *depth, TQ3Quaternion *orientation,
                                                             TQ3Boolean *hasOrientation, TQ3Boolean *changed,
                                                             unsigned long *serialNumber);

/*
 * Q3CursorTracker_SetNotifyFunc: the cursor tracker's notify function
 * (NULL: none).
 */
Q3_EXTERN_API_C(TQ3Status) Q3CursorTracker_SetNotifyFunc(TQ3CursorTrackerNotifyFunc notifyFunc);

/*
 * Q3CursorTracker_GetNotifyFunc: the cursor tracker's notify function.
 * Errors: kQ3ErrorNULLParameter (notifyFunc).
 */
Q3_EXTERN_API_C(TQ3Status) Q3CursorTracker_GetNotifyFunc(TQ3CursorTrackerNotifyFunc *notifyFunc);

#ifdef __cplusplus
}
#endif

#endif /* QD3DCONTROLLER_H */
