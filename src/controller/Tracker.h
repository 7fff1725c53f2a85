// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DController.h"
#include "core/Object.h"

#include <deque>
#include <map>

namespace q3 {

extern const ClassInfo kTrackerClass;

/// A QuickDraw 3D tracker (QD3DController.h): an absolute position and
/// orientation, accumulators of relative motion, the buttons each
/// controller holds down on it, notify thresholds and a ring buffer of event
/// coordinates. The system cursor tracker is a Tracker too, made by the
/// controller registry and never registered as a live object (no handle to
/// it is ever given out).
///
/// Invariants: the orientations are unit quaternions; m_serial is never 0
/// (so a caller's 0 always reads as "changed"); m_buttons holds no zero
/// entries; at most limits::kTrackerEventCount events are kept. Every member
/// function expects the caller to hold controllerMutex() (Controller.h),
/// which every entry point of the Pointing Device Manager takes.
class Tracker final : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SharedTypeTracker;

    /// An application's tracker notifying `notify`; a cursor tracker calls
    /// the registry's cursor notify function instead.
    explicit Tracker(TQ3TrackerNotifyFunc notify, bool cursor = false);
    ~Tracker() override;

    const ClassInfo& classInfo() const override { return kTrackerClass; }

    bool active() const { return m_active; }
    void setActive(bool active) { m_active = active; }
    float positionThreshold() const { return m_positionThreshold; }
    float orientationThreshold() const { return m_orientationThreshold; }
    /// Both finite and >= 0, else kQ3ErrorInvalidParameter.
    void setThresholds(float position, float orientation);

    unsigned long buttons() const;
    void changeButtons(TQ3ControllerRef controller, unsigned long buttons, unsigned long mask);
    /// The buttons `controller` holds down here (0 if none).
    unsigned long buttonsOf(TQ3ControllerRef controller) const;

    /// The position and orientation with the unread relative motion applied.
    TQ3Point3D currentPosition() const;
    TQ3Quaternion currentOrientation() const;

    void setPosition(TQ3ControllerRef controller, const TQ3Point3D& position);
    void movePosition(TQ3ControllerRef controller, const TQ3Vector3D& delta);
    void setOrientation(TQ3ControllerRef controller, const TQ3Quaternion& orientation);
    void moveOrientation(TQ3ControllerRef controller, const TQ3Quaternion& delta);

    /// Q3Tracker_GetPosition / _GetOrientation: false (nothing written)
    /// when inactive or `serial` already holds the serial number.
    bool readPosition(TQ3Point3D& position, TQ3Vector3D* delta, unsigned long* serial);
    bool readOrientation(TQ3Quaternion& orientation, TQ3Quaternion* delta, unsigned long* serial);
    unsigned long serial() const { return m_serial; }

    void setEventCoordinates(unsigned long timeStamp, unsigned long buttons, const TQ3Point3D* position,
                             const TQ3Quaternion* orientation);
    /// kQ3ErrorDataNotAvailable when no event is recorded.
    void eventCoordinates(unsigned long timeStamp, unsigned long* buttons, TQ3Point3D* position,
                          TQ3Quaternion* orientation);

    // The cursor tracker's deltas (Q3CursorTracker_*): the depth and turn
    // reported since the last clear, and whether any turn was reported.
    float depthDelta() const { return m_depthDelta; }
    const TQ3Quaternion& turnDelta() const { return m_turnDelta; }
    bool hasTurn() const { return m_hasTurn; }
    void clearCursorDeltas();

private:
    struct Event {
        unsigned long timeStamp;
        unsigned long buttons;
        TQ3Point3D position;
        TQ3Quaternion orientation;
    };

    /// After a coordinate report: a new serial number, and the notify
    /// function if the change since the last notification reaches a
    /// threshold.
    void coordinatesChanged(TQ3ControllerRef controller);
    void notify(TQ3ControllerRef controller);

    TQ3TrackerNotifyFunc m_notify;
    bool m_cursor;
    bool m_active = true;
    bool m_notifying = false;
    float m_positionThreshold = 0.0f;
    float m_orientationThreshold = 0.0f;
    TQ3Point3D m_position{0.0f, 0.0f, 0.0f};
    TQ3Vector3D m_positionDelta{0.0f, 0.0f, 0.0f};
    TQ3Quaternion m_orientation{1.0f, 0.0f, 0.0f, 0.0f};
    TQ3Quaternion m_orientationDelta{1.0f, 0.0f, 0.0f, 0.0f};
    TQ3Point3D m_notifiedPosition{0.0f, 0.0f, 0.0f};
    TQ3Quaternion m_notifiedOrientation{1.0f, 0.0f, 0.0f, 0.0f};
    unsigned long m_serial = 1;
    std::map<TQ3ControllerRef, unsigned long> m_buttons;
    std::deque<Event> m_events;
    float m_depthDelta = 0.0f;
    TQ3Quaternion m_turnDelta{1.0f, 0.0f, 0.0f, 0.0f};
    bool m_hasTurn = false;
};

/// A finite, nonzero quaternion, normalized; kQ3ErrorInvalidParameter
/// naming `name` otherwise.
TQ3Quaternion checkedRotation(const TQ3Quaternion& q, const char* name);

} // namespace q3
