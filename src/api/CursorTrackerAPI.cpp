// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DController.h"

#include "api/Entry.h"
#include "base/QuaternionMath.h"
#include "controller/Controller.h"
#include "core/ParameterChecks.h"

using namespace q3;
using q3::api::guardStatus;

extern "C" {

TQ3Status Q3CursorTracker_PrepareTracking(void)
{
    return guardStatus(__func__, [] {
        std::lock_guard<std::recursive_mutex> lock(controllerMutex());
        controllers::cursorTracker().clearCursorDeltas();
    });
}

TQ3Status Q3CursorTracker_SetTrackDeltas(TQ3Boolean trackDeltas)
{
    return guardStatus(__func__, [&] {
        std::lock_guard<std::recursive_mutex> lock(controllerMutex());
        controllers::setTrackDeltas(booleanOf(trackDeltas) == kQ3True);
    });
}

TQ3Status Q3CursorTracker_GetAndClearDeltas(float* depth, TQ3Quaternion* orientation, TQ3Boolean* hasOrientation,
                                            TQ3Boolean* changed, unsigned long* serialNumber)
{
    return guardStatus(__func__, [&] {
        requireNonNull(depth, "depth");
        requireNonNull(orientation, "orientation");
        requireNonNull(hasOrientation, "hasOrientation");
        requireNonNull(changed, "changed");
        std::lock_guard<std::recursive_mutex> lock(controllerMutex());
        Tracker& cursor = controllers::cursorTracker();
        if (serialNumber != nullptr && *serialNumber == cursor.serial()) {
            *changed = kQ3False;
            return;
        }
        const bool track = controllers::trackDeltas();
        *depth = track ? cursor.depthDelta() : 0.0f;
        *orientation = track ? cursor.turnDelta() : math::quaternionIdentity();
        *hasOrientation = track && cursor.hasTurn() ? kQ3True : kQ3False;
        *changed = kQ3True;
        if (serialNumber != nullptr)
            *serialNumber = cursor.serial();
        cursor.clearCursorDeltas();
    });
}

TQ3Status Q3CursorTracker_SetNotifyFunc(TQ3CursorTrackerNotifyFunc notifyFunc)
{
    return guardStatus(__func__, [&] {
        std::lock_guard<std::recursive_mutex> lock(controllerMutex());
        controllers::setCursorNotify(notifyFunc);
    });
}

TQ3Status Q3CursorTracker_GetNotifyFunc(TQ3CursorTrackerNotifyFunc* notifyFunc)
{
    return guardStatus(__func__, [&] {
        requireNonNull(notifyFunc, "notifyFunc");
        std::lock_guard<std::recursive_mutex> lock(controllerMutex());
        *notifyFunc = controllers::cursorNotify();
    });
}

} // extern "C"
