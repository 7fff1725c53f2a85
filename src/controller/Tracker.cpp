// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "controller/Tracker.h"

#include "base/QuaternionMath.h"
#include "controller/Controller.h"
#include "core/Limits.h"
#include "core/ParameterChecks.h"

#include <algorithm>
#include <cmath>

namespace q3 {

const ClassInfo kTrackerClass{kQ3SharedTypeTracker, &kSharedClass, "tracker"};

namespace {

TQ3Point3D plus(const TQ3Point3D& p, const TQ3Vector3D& v)
{
    return TQ3Point3D{p.x + v.x, p.y + v.y, p.z + v.z};
}

double distance(const TQ3Point3D& a, const TQ3Point3D& b)
{
    const double dx = double(a.x) - b.x, dy = double(a.y) - b.y, dz = double(a.z) - b.z;
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// The angle of the turn from unit quaternion a to unit quaternion b, in
// 0..pi: 2 acos |a . b| (q and -q are the same rotation).
double turnAngle(const TQ3Quaternion& a, const TQ3Quaternion& b)
{
    const double d = std::fabs(double(a.w) * b.w + double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z);
    return 2.0 * std::acos(std::min(1.0, d));
}

unsigned long nextSerial(unsigned long serial)
{
    return serial + 1 == 0 ? 1 : serial + 1;
}

} // namespace

TQ3Quaternion checkedRotation(const TQ3Quaternion& q, const char* name)
{
    if (!std::isfinite(q.w) || !std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
        fail(kQ3ErrorInvalidParameter, std::string(name) + " has a NaN or infinite component");
    if (q.w == 0.0f && q.x == 0.0f && q.y == 0.0f && q.z == 0.0f)
        fail(kQ3ErrorInvalidParameter, std::string(name) + " is the zero quaternion, which is no rotation");
    return math::normalize(q);
}

Tracker::Tracker(TQ3TrackerNotifyFunc notify, bool cursor) : m_notify(notify), m_cursor(cursor) {}

Tracker::~Tracker()
{
    // No controller names the cursor tracker as its own, and the registry
    // that owns it may be mid-destruction at process exit: nothing to detach.
    if (m_cursor)
        return;
    std::lock_guard<std::recursive_mutex> lock(controllerMutex());
    controllers::trackerDestroyed(this);
}

void Tracker::setThresholds(float position, float orientation)
{
    checkFinite(position, "positionThresh");
    checkFinite(orientation, "orientationThresh");
    if (position < 0.0f || orientation < 0.0f)
        fail(kQ3ErrorInvalidParameter, "a notify threshold is negative");
    m_positionThreshold = position;
    m_orientationThreshold = orientation;
}

unsigned long Tracker::buttons() const
{
    unsigned long all = 0;
    for (const auto& entry : m_buttons)
        all |= entry.second;
    return all;
}

unsigned long Tracker::buttonsOf(TQ3ControllerRef controller) const
{
    const auto it = m_buttons.find(controller);
    return it == m_buttons.end() ? 0 : it->second;
}

void Tracker::changeButtons(TQ3ControllerRef controller, unsigned long buttons, unsigned long mask)
{
    const unsigned long before = this->buttons();
    const unsigned long now = (buttonsOf(controller) & ~mask) | (buttons & mask);
    if (now == 0)
        m_buttons.erase(controller);
    else
        m_buttons[controller] = now;
    if (m_active && this->buttons() != before)
        notify(controller);
}

TQ3Point3D Tracker::currentPosition() const
{
    return plus(m_position, m_positionDelta);
}

TQ3Quaternion Tracker::currentOrientation() const
{
    return math::multiply(m_orientation, m_orientationDelta);
}

void Tracker::setPosition(TQ3ControllerRef controller, const TQ3Point3D& position)
{
    if (!m_active)
        return;
    if (m_cursor)
        m_depthDelta += position.z - m_position.z;
    m_position = position;
    coordinatesChanged(controller);
}

void Tracker::movePosition(TQ3ControllerRef controller, const TQ3Vector3D& delta)
{
    if (!m_active)
        return;
    if (m_cursor)
        m_depthDelta += delta.z;
    m_positionDelta = TQ3Vector3D{m_positionDelta.x + delta.x, m_positionDelta.y + delta.y,
                                  m_positionDelta.z + delta.z};
    coordinatesChanged(controller);
}

void Tracker::setOrientation(TQ3ControllerRef controller, const TQ3Quaternion& orientation)
{
    if (!m_active)
        return;
    if (m_cursor) {
        m_turnDelta = math::normalize(math::multiply(m_turnDelta, math::multiply(math::invert(m_orientation), orientation)));
        m_hasTurn = true;
    }
    m_orientation = orientation;
    coordinatesChanged(controller);
}

void Tracker::moveOrientation(TQ3ControllerRef controller, const TQ3Quaternion& delta)
{
    if (!m_active)
        return;
    if (m_cursor) {
        m_turnDelta = math::normalize(math::multiply(m_turnDelta, delta));
        m_hasTurn = true;
    }
    m_orientationDelta = math::normalize(math::multiply(m_orientationDelta, delta));
    coordinatesChanged(controller);
}

bool Tracker::readPosition(TQ3Point3D& position, TQ3Vector3D* delta, unsigned long* serial)
{
    if (!m_active || (serial != nullptr && *serial == m_serial))
        return false;
    if (delta != nullptr) {
        *delta = m_positionDelta;
        // The motion handed out leaves the tracker: measure later changes
        // from where it now stands.
        m_notifiedPosition = TQ3Point3D{m_notifiedPosition.x - m_positionDelta.x,
                                        m_notifiedPosition.y - m_positionDelta.y,
                                        m_notifiedPosition.z - m_positionDelta.z};
    } else {
        m_position = plus(m_position, m_positionDelta);
    }
    m_positionDelta = TQ3Vector3D{0.0f, 0.0f, 0.0f};
    position = m_position;
    if (serial != nullptr)
        *serial = m_serial;
    return true;
}

bool Tracker::readOrientation(TQ3Quaternion& orientation, TQ3Quaternion* delta, unsigned long* serial)
{
    if (!m_active || (serial != nullptr && *serial == m_serial))
        return false;
    if (delta != nullptr) {
        *delta = m_orientationDelta;
        m_notifiedOrientation = m_orientation;
    } else {
        m_orientation = math::normalize(math::multiply(m_orientation, m_orientationDelta));
    }
    m_orientationDelta = math::quaternionIdentity();
    orientation = m_orientation;
    if (serial != nullptr)
        *serial = m_serial;
    return true;
}

void Tracker::setEventCoordinates(unsigned long timeStamp, unsigned long buttons, const TQ3Point3D* position,
                                  const TQ3Quaternion* orientation)
{
    if (!m_active)
        return;
    m_events.push_back(Event{timeStamp, buttons, position ? *position : currentPosition(),
                             orientation ? *orientation : currentOrientation()});
    while (m_events.size() > limits::kTrackerEventCount)
        m_events.pop_front();
}

void Tracker::eventCoordinates(unsigned long timeStamp, unsigned long* buttons, TQ3Point3D* position,
                               TQ3Quaternion* orientation)
{
    if (m_events.empty())
        fail(kQ3ErrorDataNotAvailable, "the tracker has no event coordinates recorded");
    std::size_t best = 0;
    unsigned long bestGap = 0;
    for (std::size_t i = 0; i < m_events.size(); ++i) {
        const unsigned long t = m_events[i].timeStamp;
        const unsigned long gap = t > timeStamp ? t - timeStamp : timeStamp - t;
        if (i == 0 || gap < bestGap) {
            best = i;
            bestGap = gap;
        }
    }
    const Event chosen = m_events[best];
    m_events.erase(m_events.begin(), m_events.begin() + std::ptrdiff_t(best));
    if (buttons != nullptr)
        *buttons = chosen.buttons;
    if (position != nullptr)
        *position = chosen.position;
    if (orientation != nullptr)
        *orientation = chosen.orientation;
}

void Tracker::clearCursorDeltas()
{
    m_depthDelta = 0.0f;
    m_turnDelta = math::quaternionIdentity();
    m_hasTurn = false;
}

void Tracker::coordinatesChanged(TQ3ControllerRef controller)
{
    m_serial = nextSerial(m_serial);
    const TQ3Point3D position = currentPosition();
    const TQ3Quaternion orientation = currentOrientation();
    const double moved = distance(position, m_notifiedPosition);
    const double turned = turnAngle(orientation, m_notifiedOrientation);
    const bool reached = (moved > 0.0 && moved >= m_positionThreshold) ||
                         (turned > 0.0 && turned >= m_orientationThreshold);
    if (!reached || m_notifying)
        return;
    m_notifiedPosition = position;
    m_notifiedOrientation = orientation;
    notify(controller);
}

void Tracker::notify(TQ3ControllerRef controller)
{
    if (m_notifying)
        return;
    m_notifying = true;
    struct Reset {
        bool& flag;
        ~Reset() { flag = false; }
    } reset{m_notifying};
    if (m_cursor) {
        if (TQ3CursorTrackerNotifyFunc f = controllers::cursorNotify())
            f();
    } else if (m_notify != nullptr) {
        m_notify(this, controller);
    }
}

} // namespace q3
