// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "controller/Controller.h"

#include "core/Limits.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

namespace q3 {

const ClassInfo kControllerStateClass{kQ3SharedTypeControllerState, &kSharedClass, "controller state"};

std::recursive_mutex& controllerMutex()
{
    static std::recursive_mutex mutex;
    return mutex;
}

namespace {

// The process's controllers in the order they were made, the cursor tracker
// and its settings. Guarded by controllerMutex().
struct Registry {
    std::vector<std::unique_ptr<Controller>> controllers;
    unsigned long listSerial = 1;
    Ref<Tracker> cursor;
    bool trackDeltas = false;
    TQ3CursorTrackerNotifyFunc cursorNotify = nullptr;
};

Registry& registry()
{
    static Registry r;
    return r;
}

void checkData(const TQ3ControllerData& data)
{
    requireNonNull(data.signature, "controllerData->signature");
    if (data.valueCount > limits::kMaxControllerValues)
        fail(kQ3ErrorParameterOutOfRange, "controllerData->valueCount is above 1024");
    if (data.channelCount > limits::kMaxControllerChannels)
        fail(kQ3ErrorParameterOutOfRange, "controllerData->channelCount is above 1024");
}

void checkChannel(const Controller& c, unsigned long channel)
{
    if (channel >= c.channelCount())
        fail(kQ3ErrorParameterOutOfRange, "channel " + std::to_string(channel) + " is not below the controller's " +
                                              std::to_string(c.channelCount()) + " channels");
}

} // namespace

Controller::Controller(const TQ3ControllerData& data)
{
    assign(data);
}

void Controller::assign(const TQ3ControllerData& data)
{
    m_signature = data.signature;
    m_values.assign(data.valueCount, 0.0f);
    m_channelCount = data.channelCount;
    m_get = data.channelGetMethod;
    m_set = data.channelSetMethod;
    m_serial = m_serial + 1 == 0 ? 1 : m_serial + 1;
}

void Controller::recommission(const TQ3ControllerData& data)
{
    assign(data);
    m_decommissioned = false;
    m_active = false;
    m_buttons = 0;
}

void Controller::decommission()
{
    if (m_decommissioned)
        return;
    setActive(false);
    m_decommissioned = true;
    controllers::listChanged();
}

void Controller::setActive(bool active)
{
    if (m_decommissioned || active == m_active)
        return;
    m_active = active;
    controllers::listChanged();
    reportButtons(active);
}

void Controller::reportButtons(bool report)
{
    tracker().changeButtons(ref(), report ? m_buttons : 0, ~0ul);
}

void Controller::setChannel(unsigned long channel, const void* data, unsigned long dataSize)
{
    checkChannel(*this, channel);
    if (dataSize > limits::kMaxChannelBytes)
        fail(kQ3ErrorParameterOutOfRange, "dataSize is above kQ3ControllerSetChannelMaxDataSize (256)");
    if (dataSize > 0)
        requireNonNull(data, "data");
    if (m_decommissioned)
        return;
    writeChannel(channel, data, dataSize);
}

void Controller::writeChannel(unsigned long channel, const void* data, unsigned long dataSize)
{
    if (m_set != nullptr && m_set(ref(), channel, data, dataSize) != kQ3Success)
        fail(kQ3ErrorInvalidParameter, "the controller's channel set method failed");
}

void Controller::getChannel(unsigned long channel, void* data, unsigned long* dataSize)
{
    checkChannel(*this, channel);
    requireNonNull(data, "data");
    requireNonNull(dataSize, "dataSize");
    if (m_decommissioned || m_get == nullptr) {
        *dataSize = 0;
        return;
    }
    unsigned long size = *dataSize;
    if (m_get(ref(), channel, data, &size) != kQ3Success)
        fail(kQ3ErrorInvalidParameter, "the controller's channel get method failed");
    if (size > *dataSize)
        fail(kQ3ErrorInvalidParameter, "the channel get method reported more bytes than there was room for");
    *dataSize = size;
}

bool Controller::readChannel(unsigned long channel, std::vector<unsigned char>& data)
{
    if (m_get == nullptr || m_decommissioned)
        return false;
    data.assign(limits::kMaxChannelBytes, 0);
    unsigned long size = limits::kMaxChannelBytes;
    if (m_get(ref(), channel, data.data(), &size) != kQ3Success || size > limits::kMaxChannelBytes)
        return false;
    data.resize(size);
    return true;
}

Tracker& Controller::tracker()
{
    return m_tracker != nullptr ? *m_tracker : controllers::cursorTracker();
}

void Controller::setTracker(Tracker* tracker)
{
    if (tracker == m_tracker)
        return;
    if (m_active)
        reportButtons(false);
    m_tracker = tracker;
    if (m_active)
        reportButtons(true);
}

void Controller::forgetTracker(const Tracker* tracker)
{
    if (m_tracker != tracker)
        return;
    m_tracker = nullptr;
    if (m_active)
        reportButtons(true);
}

void Controller::setButtons(unsigned long buttons)
{
    if (!m_active)
        return;
    const unsigned long changed = m_buttons ^ buttons;
    m_buttons = buttons;
    tracker().changeButtons(ref(), buttons, changed);
}

bool Controller::readValues(unsigned long count, float* values, unsigned long* serial) const
{
    if (!m_active || (serial != nullptr && *serial == m_serial))
        return false;
    std::copy_n(m_values.begin(), std::min<std::size_t>(count, m_values.size()), values);
    if (serial != nullptr)
        *serial = m_serial;
    return true;
}

void Controller::setValues(const float* values, unsigned long count)
{
    requireNonNull(values, "values");
    if (count > m_values.size())
        fail(kQ3ErrorParameterOutOfRange, "valueCount " + std::to_string(count) + " is above the controller's " +
                                              std::to_string(m_values.size()) + " values");
    for (unsigned long i = 0; i < count; ++i)
        if (!std::isfinite(values[i]))
            fail(kQ3ErrorInvalidParameter, "values[" + std::to_string(i) + "] is NaN or infinite");
    if (!m_active)
        return;
    std::copy_n(values, count, m_values.begin());
    m_serial = m_serial + 1 == 0 ? 1 : m_serial + 1;
}

namespace controllers {

Controller& make(const TQ3ControllerData& data)
{
    checkData(data);
    Registry& r = registry();
    for (const auto& c : r.controllers)
        if (c->decommissioned() && c->signature() == data.signature) {
            c->recommission(data);
            listChanged();
            return *c;
        }
    r.controllers.push_back(std::make_unique<Controller>(data));
    listChanged();
    return *r.controllers.back();
}

Controller* lookupOptional(TQ3ControllerRef ref, const char* name)
{
    if (ref == nullptr)
        return nullptr;
    for (const auto& c : registry().controllers)
        if (c->ref() == ref)
            return c.get();
    fail(kQ3ErrorInvalidParameter,
         std::string(name) + " is not a controller (Q3Controller_New did not make it, or Q3Exit forgot it)");
}

Controller& lookup(TQ3ControllerRef ref, const char* name)
{
    requireNonNull(ref, name);
    return *lookupOptional(ref, name);
}

Controller* next(const Controller* after)
{
    auto& list = registry().controllers;
    auto it = list.begin();
    if (after != nullptr) {
        it = std::find_if(list.begin(), list.end(), [&](const auto& c) { return c.get() == after; });
        if (it != list.end())
            ++it;
    }
    for (; it != list.end(); ++it)
        if (!(*it)->decommissioned())
            return it->get();
    return nullptr;
}

unsigned long listSerial()
{
    return registry().listSerial;
}

void listChanged()
{
    unsigned long& serial = registry().listSerial;
    serial = serial + 1 == 0 ? 1 : serial + 1;
}

Tracker& cursorTracker()
{
    Registry& r = registry();
    if (!r.cursor)
        r.cursor = Ref<Tracker>::adopt(new Tracker(nullptr, true));
    return *r.cursor;
}

bool trackDeltas()
{
    return registry().trackDeltas;
}

void setTrackDeltas(bool track)
{
    registry().trackDeltas = track;
}

TQ3CursorTrackerNotifyFunc cursorNotify()
{
    return registry().cursorNotify;
}

void setCursorNotify(TQ3CursorTrackerNotifyFunc notify)
{
    registry().cursorNotify = notify;
}

void trackerDestroyed(const Tracker* tracker)
{
    for (const auto& c : registry().controllers)
        c->forgetTracker(tracker);
}

void forgetAll()
{
    std::lock_guard<std::recursive_mutex> lock(controllerMutex());
    Registry& r = registry();
    r.controllers.clear();
    r.listSerial = 1;
    r.cursor = Ref<Tracker>();
    r.trackDeltas = false;
    r.cursorNotify = nullptr;
}

} // namespace controllers

void ControllerState::saveAndReset()
{
    Controller& c = controllers::lookup(m_controller, "the state's controller");
    std::vector<std::vector<unsigned char>> saved(c.channelCount());
    std::vector<bool> present(c.channelCount(), false);
    for (unsigned long i = 0; i < c.channelCount(); ++i)
        present[i] = c.readChannel(i, saved[i]);
    m_saved.swap(saved);
    m_present.swap(present);
    m_hasSaved = true;
    if (c.decommissioned())
        return;
    for (unsigned long i = 0; i < c.channelCount(); ++i)
        c.writeChannel(i, nullptr, 0);
}

void ControllerState::restore()
{
    Controller& c = controllers::lookup(m_controller, "the state's controller");
    if (!m_hasSaved)
        fail(kQ3ErrorStateUnavailable, "nothing was saved: call Q3ControllerState_SaveAndReset first");
    if (c.decommissioned())
        return;
    for (unsigned long i = 0; i < m_saved.size() && i < c.channelCount(); ++i)
        if (m_present[i])
            c.writeChannel(i, m_saved[i].data(), static_cast<unsigned long>(m_saved[i].size()));
}

} // namespace q3
