// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DController.h"
#include "controller/Tracker.h"
#include "core/Object.h"

#include <mutex>
#include <string>
#include <vector>

namespace q3 {

extern const ClassInfo kControllerStateClass;

/// The one lock of the Pointing Device Manager: every entry point of
/// QD3DController.h holds it for its whole call, so the controller list, the
/// trackers and the cursor tracker change one call at a time. Recursive,
/// because notify functions run inside the call and may call back in.
std::recursive_mutex& controllerMutex();

/// One pointing device (QD3DController.h). Controllers are never deleted
/// before the registry forgets them all (controllers::forgetAll): a
/// TQ3ControllerRef stays valid, decommissioned or not. The ref is the
/// Controller's address, checked against the registry before every use.
///
/// Invariants: m_values.size() == valueCount <= limits::kMaxControllerValues;
/// channelCount <= limits::kMaxControllerChannels; a decommissioned
/// controller is inactive; an active controller's buttons are reported to
/// its tracker (the cursor tracker when m_tracker is null) under its ref,
/// an inactive one's are not; m_serial is never 0.
class Controller {
public:
    explicit Controller(const TQ3ControllerData& data);

    TQ3ControllerRef ref() { return this; }
    /// Takes a new device description (Q3Controller_New of a decommissioned
    /// signature): values reset, inactive, back in the list.
    void recommission(const TQ3ControllerData& data);
    void decommission();
    bool decommissioned() const { return m_decommissioned; }

    const std::string& signature() const { return m_signature; }
    unsigned long valueCount() const { return static_cast<unsigned long>(m_values.size()); }
    unsigned long channelCount() const { return m_channelCount; }

    bool active() const { return m_active; }
    void setActive(bool active);

    void setChannel(unsigned long channel, const void* data, unsigned long dataSize);
    void getChannel(unsigned long channel, void* data, unsigned long* dataSize);
    /// The driver's methods without the argument checks (controller states).
    bool readChannel(unsigned long channel, std::vector<unsigned char>& data);
    void writeChannel(unsigned long channel, const void* data, unsigned long dataSize);

    /// The tracker the controller drives: its own or the cursor tracker.
    Tracker& tracker();
    Tracker* ownTracker() const { return m_tracker; }
    void setTracker(Tracker* tracker);
    /// Called by a tracker's destructor: back to the cursor tracker.
    void forgetTracker(const Tracker* tracker);

    unsigned long buttons() const { return m_buttons; }
    void setButtons(unsigned long buttons);

    /// False (nothing written) when inactive or `serial` holds the serial.
    bool readValues(unsigned long count, float* values, unsigned long* serial) const;
    void setValues(const float* values, unsigned long count);

private:
    void assign(const TQ3ControllerData& data);
    void reportButtons(bool report);

    std::string m_signature;
    std::vector<float> m_values;
    unsigned long m_channelCount = 0;
    TQ3ChannelGetMethod m_get = nullptr;
    TQ3ChannelSetMethod m_set = nullptr;
    bool m_active = false;
    bool m_decommissioned = false;
    Tracker* m_tracker = nullptr; // not owned: the tracker detaches itself
    unsigned long m_buttons = 0;
    unsigned long m_serial = 1;
};

namespace controllers {

/// Q3Controller_New: a new controller, or a decommissioned one with the
/// same signature recommissioned. Checks the data first.
Controller& make(const TQ3ControllerData& data);
/// The controller `ref` names: kQ3ErrorNULLParameter, or
/// kQ3ErrorInvalidParameter for a pointer that is not a live controller.
Controller& lookup(TQ3ControllerRef ref, const char* name);
/// As lookup, NULL allowed (gives nullptr).
Controller* lookupOptional(TQ3ControllerRef ref, const char* name);
/// The controller after `after` (nullptr: the first) that is not
/// decommissioned, or nullptr.
Controller* next(const Controller* after);
unsigned long listSerial();
void listChanged();

/// The system cursor tracker, made on first use.
Tracker& cursorTracker();
bool trackDeltas();
void setTrackDeltas(bool track);
TQ3CursorTrackerNotifyFunc cursorNotify();
void setCursorNotify(TQ3CursorTrackerNotifyFunc notify);

/// Every controller attached to `tracker` goes back to the cursor tracker.
void trackerDestroyed(const Tracker* tracker);
/// The last Q3Exit: forgets every controller, the cursor tracker and its
/// settings.
void forgetAll();

} // namespace controllers

/// A controller state object (QD3DController.h): the channel data saved by
/// Q3ControllerState_SaveAndReset. Refers to its controller by ref, looked
/// up on every use. Invariant: m_saved.size() == m_present.size(), each
/// saved block at most limits::kMaxChannelBytes.
class ControllerState final : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SharedTypeControllerState;

    explicit ControllerState(TQ3ControllerRef controller) : m_controller(controller) {}
    const ClassInfo& classInfo() const override { return kControllerStateClass; }

    void saveAndReset();
    /// kQ3ErrorStateUnavailable before the first saveAndReset.
    void restore();

private:
    TQ3ControllerRef m_controller;
    bool m_hasSaved = false;
    std::vector<std::vector<unsigned char>> m_saved;
    std::vector<bool> m_present;
};

} // namespace q3
