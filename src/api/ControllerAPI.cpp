// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DController.h"

#include "api/Entry.h"
#include "controller/Controller.h"
#include "core/ParameterChecks.h"

#include <algorithm>
#include <cstring>

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

namespace {

// Runs body(controller) under the Pointing Device Manager's lock once the
// controller ref is checked.
template <class Body>
TQ3Status withController(const char* function, TQ3ControllerRef ref, Body&& body)
{
    return guardStatus(function, [&] {
        std::lock_guard<std::recursive_mutex> lock(controllerMutex());
        body(controllers::lookup(ref, "controllerRef"));
    });
}

// A Get of one value of a controller, in the order every Get checks: the
// ref, then the pointer, then *out = read(controller), under the lock.
template <class Value, class Read>
TQ3Status readController(const char* function, TQ3ControllerRef ref, Value* out, const char* outName, Read read)
{
    return withController(function, ref, [&](Controller& c) {
        requireNonNull(out, outName);
        *out = read(c);
    });
}

TQ3Boolean boolean(bool value)
{
    return value ? kQ3True : kQ3False;
}

} // namespace

extern "C" {

TQ3Status Q3Controller_GetListChanged(TQ3Boolean* listChanged, unsigned long* serialNumber)
{
    return guardStatus(__func__, [&] {
        requireNonNull(listChanged, "listChanged");
        requireNonNull(serialNumber, "serialNumber");
        std::lock_guard<std::recursive_mutex> lock(controllerMutex());
        const unsigned long serial = controllers::listSerial();
        *listChanged = boolean(*serialNumber != serial);
        *serialNumber = serial;
    });
}

TQ3Status Q3Controller_Next(TQ3ControllerRef controllerRef, TQ3ControllerRef* nextControllerRef)
{
    return guardStatus(__func__, [&] {
        std::lock_guard<std::recursive_mutex> lock(controllerMutex());
        const Controller* after = controllers::lookupOptional(controllerRef, "controllerRef");
        requireNonNull(nextControllerRef, "nextControllerRef");
        Controller* next = controllers::next(after);
        *nextControllerRef = next != nullptr ? next->ref() : nullptr;
    });
}

TQ3ControllerRef Q3Controller_New(const TQ3ControllerData* controllerData)
{
    return guard(__func__, TQ3ControllerRef{nullptr}, [&] {
        requireNonNull(controllerData, "controllerData");
        std::lock_guard<std::recursive_mutex> lock(controllerMutex());
        return controllers::make(*controllerData).ref();
    });
}

TQ3Status Q3Controller_Decommission(TQ3ControllerRef controllerRef)
{
    return withController(__func__, controllerRef, [](Controller& c) { c.decommission(); });
}

TQ3Status Q3Controller_SetActivation(TQ3ControllerRef controllerRef, TQ3Boolean active)
{
    return withController(__func__, controllerRef,
                          [&](Controller& c) { c.setActive(booleanOf(active) == kQ3True); });
}

TQ3Status Q3Controller_GetActivation(TQ3ControllerRef controllerRef, TQ3Boolean* active)
{
    return readController(__func__, controllerRef, active, "active",
                          [&](Controller& c) { return boolean(c.active()); });
}

TQ3Status Q3Controller_GetSignature(TQ3ControllerRef controllerRef, char* signature, unsigned long numChars)
{
    return withController(__func__, controllerRef, [&](Controller& c) {
        requireNonNull(signature, "signature");
        if (numChars == 0)
            fail(kQ3ErrorParameterOutOfRange, "numChars is 0: no room for the terminating NUL");
        const std::size_t n = std::min<std::size_t>(c.signature().size(), numChars - 1);
        std::memcpy(signature, c.signature().data(), n);
        signature[n] = '\0';
    });
}

TQ3Status Q3Controller_SetChannel(TQ3ControllerRef controllerRef, unsigned long channel, const void* data,
                                  unsigned long dataSize)
{
    return withController(__func__, controllerRef,
                          [&](Controller& c) { c.setChannel(channel, data, dataSize); });
}

TQ3Status Q3Controller_GetChannel(TQ3ControllerRef controllerRef, unsigned long channel, void* data,
                                  unsigned long* dataSize)
{
    return withController(__func__, controllerRef,
                          [&](Controller& c) { c.getChannel(channel, data, dataSize); });
}

TQ3Status Q3Controller_GetValueCount(TQ3ControllerRef controllerRef, unsigned long* valueCount)
{
    return readController(__func__, controllerRef, valueCount, "valueCount",
                          [&](Controller& c) { return c.valueCount(); });
}

TQ3Status Q3Controller_SetTracker(TQ3ControllerRef controllerRef, TQ3TrackerObject tracker)
{
    return withController(__func__, controllerRef,
                          [&](Controller& c) { c.setTracker(lookupOptional<Tracker>(tracker, "tracker")); });
}

TQ3Status Q3Controller_HasTracker(TQ3ControllerRef controllerRef, TQ3Boolean* hasTracker)
{
    return readController(__func__, controllerRef, hasTracker, "hasTracker",
                          [&](Controller& c) {
                              return boolean(c.active() && c.ownTracker() != nullptr && c.ownTracker()->active());
                          });
}

TQ3Status Q3Controller_Track2DCursor(TQ3ControllerRef controllerRef, TQ3Boolean* track2DCursor)
{
    return readController(__func__, controllerRef, track2DCursor, "track2DCursor",
                          [&](Controller& c) {
                              return boolean(c.active() && c.ownTracker() == nullptr && !controllers::trackDeltas());
                          });
}

TQ3Status Q3Controller_Track3DCursor(TQ3ControllerRef controllerRef, TQ3Boolean* track3DCursor)
{
    return readController(__func__, controllerRef, track3DCursor, "track3DCursor",
                          [&](Controller& c) {
                              return boolean(c.active() && c.ownTracker() == nullptr && controllers::trackDeltas());
                          });
}

TQ3Status Q3Controller_GetButtons(TQ3ControllerRef controllerRef, unsigned long* buttons)
{
    return readController(__func__, controllerRef, buttons, "buttons", [&](Controller& c) { return c.buttons(); });
}

TQ3Status Q3Controller_SetButtons(TQ3ControllerRef controllerRef, unsigned long buttons)
{
    return withController(__func__, controllerRef, [&](Controller& c) { c.setButtons(buttons); });
}

TQ3Status Q3Controller_GetTrackerPosition(TQ3ControllerRef controllerRef, TQ3Point3D* position)
{
    return readController(__func__, controllerRef, position, "position",
                          [&](Controller& c) { return c.tracker().currentPosition(); });
}

TQ3Status Q3Controller_SetTrackerPosition(TQ3ControllerRef controllerRef, const TQ3Point3D* position)
{
    return withController(__func__, controllerRef, [&](Controller& c) {
        requireNonNull(position, "position");
        checkFinite(*position, "position");
        if (c.active())
            c.tracker().setPosition(c.ref(), *position);
    });
}

TQ3Status Q3Controller_MoveTrackerPosition(TQ3ControllerRef controllerRef, const TQ3Vector3D* delta)
{
    return withController(__func__, controllerRef, [&](Controller& c) {
        requireNonNull(delta, "delta");
        checkFinite(*delta, "delta");
        if (c.active())
            c.tracker().movePosition(c.ref(), *delta);
    });
}

TQ3Status Q3Controller_GetTrackerOrientation(TQ3ControllerRef controllerRef, TQ3Quaternion* orientation)
{
    return readController(__func__, controllerRef, orientation, "orientation",
                          [&](Controller& c) { return c.tracker().currentOrientation(); });
}

TQ3Status Q3Controller_SetTrackerOrientation(TQ3ControllerRef controllerRef, const TQ3Quaternion* orientation)
{
    return withController(__func__, controllerRef, [&](Controller& c) {
        requireNonNull(orientation, "orientation");
        const TQ3Quaternion q = checkedRotation(*orientation, "orientation");
        if (c.active())
            c.tracker().setOrientation(c.ref(), q);
    });
}

TQ3Status Q3Controller_MoveTrackerOrientation(TQ3ControllerRef controllerRef, const TQ3Quaternion* delta)
{
    return withController(__func__, controllerRef, [&](Controller& c) {
        requireNonNull(delta, "delta");
        const TQ3Quaternion q = checkedRotation(*delta, "delta");
        if (c.active())
            c.tracker().moveOrientation(c.ref(), q);
    });
}

TQ3Status Q3Controller_GetValues(TQ3ControllerRef controllerRef, unsigned long valueCount, float* values,
                                 TQ3Boolean* changed, unsigned long* serialNumber)
{
    return withController(__func__, controllerRef, [&](Controller& c) {
        requireNonNull(values, "values");
        requireNonNull(changed, "changed");
        *changed = boolean(c.readValues(valueCount, values, serialNumber));
    });
}

TQ3Status Q3Controller_SetValues(TQ3ControllerRef controllerRef, const float* values, unsigned long valueCount)
{
    return withController(__func__, controllerRef, [&](Controller& c) { c.setValues(values, valueCount); });
}

} // extern "C"
