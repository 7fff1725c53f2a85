// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DController.h"

#include "api/Entry.h"
#include "controller/Controller.h"
#include "core/ParameterChecks.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

namespace {

// Runs body(tracker) under the Pointing Device Manager's lock once the
// tracker handle is checked.
template <class Body>
TQ3Status withTracker(const char* function, TQ3TrackerObject handle, Body&& body)
{
    return guardStatus(function, [&] {
        std::lock_guard<std::recursive_mutex> lock(controllerMutex());
        body(lookup<Tracker>(handle, "trackerObject"));
    });
}

TQ3Boolean boolean(bool value)
{
    return value ? kQ3True : kQ3False;
}

// The value a Set or Move call stores, once checked: a finite position or
// delta, or a rotation (checkedRotation).
template <class Value>
Value checked(const Value& value, const char* name)
{
    checkFinite(value, name);
    return value;
}

TQ3Quaternion checked(const TQ3Quaternion& value, const char* name)
{
    return checkedRotation(value, name);
}

// The Get of the position or the orientation: the tracker, then the value
// and `changed` pointers (delta and serialNumber may be NULL).
template <class Value, class Delta>
TQ3Status readChange(const char* function, TQ3TrackerObject handle, Value* value, const char* name, Delta* delta,
                     TQ3Boolean* changed, unsigned long* serialNumber,
                     bool (Tracker::*read)(Value&, Delta*, unsigned long*))
{
    return withTracker(function, handle, [&](Tracker& t) {
        requireNonNull(value, name);
        requireNonNull(changed, "changed");
        *changed = boolean((t.*read)(*value, delta, serialNumber));
    });
}

// The Set and Move calls: the tracker, the controller (NULL allowed), the
// pointer, the value's check, then change(controllerRef, value).
template <class Value>
TQ3Status change(const char* function, TQ3TrackerObject handle, TQ3ControllerRef controllerRef, const Value* value,
                 const char* name, void (Tracker::*apply)(TQ3ControllerRef, const Value&))
{
    return withTracker(function, handle, [&](Tracker& t) {
        controllers::lookupOptional(controllerRef, "controllerRef");
        requireNonNull(value, name);
        (t.*apply)(controllerRef, checked(*value, name));
    });
}

} // namespace

// A C entry point cannot come from a template, so the three calls of a
// tracker's position and of its orientation are written once as a macro that
// defines them through readChange and change: Q3Tracker_Get<Field> (the
// value, called `param`, with the change since the serial number),
// _Set<Field> and _Move<Field> (by a Delta), through Tracker::read<Field>,
// set<Field> and move<Field>.
#define Q3_TRACKER_CHANGE_ENTRY_POINTS(Field, Type, Delta, param)                                               \
    TQ3Status Q3Tracker_Get##Field(TQ3TrackerObject trackerObject, Type* param, Delta* delta,                   \
                                   TQ3Boolean* changed, unsigned long* serialNumber)                            \
    {                                                                                                           \
        return readChange(__func__, trackerObject, param, #param, delta, changed, serialNumber,                 \
                          &Tracker::read##Field);                                                               \
    }                                                                                                           \
    TQ3Status Q3Tracker_Set##Field(TQ3TrackerObject trackerObject, TQ3ControllerRef controllerRef,              \
                                   const Type* param)                                                           \
    {                                                                                                           \
        return change(__func__, trackerObject, controllerRef, param, #param, &Tracker::set##Field);             \
    }                                                                                                           \
    TQ3Status Q3Tracker_Move##Field(TQ3TrackerObject trackerObject, TQ3ControllerRef controllerRef,             \
                                    const Delta* delta)                                                         \
    {                                                                                                           \
        return change(__func__, trackerObject, controllerRef, delta, "delta", &Tracker::move##Field);           \
    }

extern "C" {

TQ3TrackerObject Q3Tracker_New(TQ3TrackerNotifyFunc notifyFunc)
{
    return guard(__func__, TQ3TrackerObject{nullptr},
                 [&]() -> TQ3TrackerObject { return makeShared<Tracker>(notifyFunc).detach(); });
}

TQ3Status Q3Tracker_SetNotifyThresholds(TQ3TrackerObject trackerObject, float positionThresh,
                                        float orientationThresh)
{
    return withTracker(__func__, trackerObject,
                       [&](Tracker& t) { t.setThresholds(positionThresh, orientationThresh); });
}

TQ3Status Q3Tracker_GetNotifyThresholds(TQ3TrackerObject trackerObject, float* positionThresh,
                                        float* orientationThresh)
{
    return withTracker(__func__, trackerObject, [&](Tracker& t) {
        requireNonNull(positionThresh, "positionThresh");
        requireNonNull(orientationThresh, "orientationThresh");
        *positionThresh = t.positionThreshold();
        *orientationThresh = t.orientationThreshold();
    });
}

TQ3Status Q3Tracker_SetActivation(TQ3TrackerObject trackerObject, TQ3Boolean active)
{
    return withTracker(__func__, trackerObject, [&](Tracker& t) { t.setActive(booleanOf(active) == kQ3True); });
}

TQ3Status Q3Tracker_GetActivation(TQ3TrackerObject trackerObject, TQ3Boolean* active)
{
    return withTracker(__func__, trackerObject, [&](Tracker& t) {
        requireNonNull(active, "active");
        *active = boolean(t.active());
    });
}

TQ3Status Q3Tracker_GetButtons(TQ3TrackerObject trackerObject, unsigned long* buttons)
{
    return withTracker(__func__, trackerObject, [&](Tracker& t) {
        requireNonNull(buttons, "buttons");
        *buttons = t.buttons();
    });
}

TQ3Status Q3Tracker_ChangeButtons(TQ3TrackerObject trackerObject, TQ3ControllerRef controllerRef,
                                  unsigned long buttons, unsigned long buttonMask)
{
    return withTracker(__func__, trackerObject, [&](Tracker& t) {
        controllers::lookupOptional(controllerRef, "controllerRef");
        t.changeButtons(controllerRef, buttons, buttonMask);
    });
}

Q3_TRACKER_CHANGE_ENTRY_POINTS(Position, TQ3Point3D, TQ3Vector3D, position)

Q3_TRACKER_CHANGE_ENTRY_POINTS(Orientation, TQ3Quaternion, TQ3Quaternion, orientation)

TQ3Status Q3Tracker_SetEventCoordinates(TQ3TrackerObject trackerObject, unsigned long timeStamp,
                                        unsigned long buttons, const TQ3Point3D* position,
                                        const TQ3Quaternion* orientation)
{
    return withTracker(__func__, trackerObject, [&](Tracker& t) {
        if (position != nullptr)
            checkFinite(*position, "position");
        TQ3Quaternion q{};
        if (orientation != nullptr)
            q = checkedRotation(*orientation, "orientation");
        t.setEventCoordinates(timeStamp, buttons, position, orientation != nullptr ? &q : nullptr);
    });
}

TQ3Status Q3Tracker_GetEventCoordinates(TQ3TrackerObject trackerObject, unsigned long timeStamp,
                                        unsigned long* buttons, TQ3Point3D* position, TQ3Quaternion* orientation)
{
    return withTracker(__func__, trackerObject,
                       [&](Tracker& t) { t.eventCoordinates(timeStamp, buttons, position, orientation); });
}

} // extern "C"

#undef Q3_TRACKER_CHANGE_ENTRY_POINTS
