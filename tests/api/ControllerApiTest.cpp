// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DController.h: controllers, controller states, trackers and the cursor
// tracker, each call with good and bad input, against the QD3D Book's
// rules; and a camera driven by a tracker's notify function, checked
// against the look-at formula and against a rendered image.

#include "RenderTestSupport.h"

#include "QD3DController.h"
#include "QD3DGeometry.h"
#include "QD3DMath.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <vector>

namespace {

using namespace q3test;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A fake device's channels, kept by the test: what the driver's methods
// were given and what they report.
struct Channels {
    std::map<unsigned long, std::vector<unsigned char>> data;
    std::vector<std::pair<unsigned long, unsigned long>> sets; // (channel, size) per set call
    bool failGet = false;
    bool failSet = false;
    TQ3ControllerRef lastRef = nullptr;
};
Channels g_channels;

// What one of a controller's Boolean getters reports. It is read into a
// False and into a True, which must agree: a call that wrote nothing fails.
TQ3Boolean booleanOf(TQ3Status (*get)(TQ3ControllerRef, TQ3Boolean*), TQ3ControllerRef ref)
{
    TQ3Boolean fromFalse = kQ3False, fromTrue = kQ3True;
    EXPECT_EQ(get(ref, &fromFalse), kQ3Success);
    EXPECT_EQ(get(ref, &fromTrue), kQ3Success);
    EXPECT_EQ(fromFalse, fromTrue) << "the call writes its result";
    return fromTrue;
}

TQ3Status getChannel(TQ3ControllerRef ref, unsigned long channel, void* data, unsigned long* size)
{
    g_channels.lastRef = ref;
    if (g_channels.failGet)
        return kQ3Failure;
    const std::vector<unsigned char>& bytes = g_channels.data[channel];
    const unsigned long n = std::min<unsigned long>(*size, bytes.size());
    if (n != 0)
        std::memcpy(data, bytes.data(), n);
    *size = n;
    return kQ3Success;
}

TQ3Status setChannel(TQ3ControllerRef ref, unsigned long channel, const void* data, unsigned long size)
{
    g_channels.lastRef = ref;
    if (g_channels.failSet)
        return kQ3Failure;
    g_channels.sets.emplace_back(channel, size);
    const auto* bytes = static_cast<const unsigned char*>(data);
    g_channels.data[channel].assign(bytes, bytes + size);
    return kQ3Success;
}

// What the notify functions saw.
struct Notes {
    int count = 0;
    TQ3TrackerObject tracker = nullptr;
    TQ3ControllerRef controller = nullptr;
    int cursorCount = 0;
    bool reenter = false; // the notify function moves its own tracker again
};
Notes g_notes;

TQ3Status recordNotify(TQ3TrackerObject tracker, TQ3ControllerRef controller)
{
    ++g_notes.count;
    g_notes.tracker = tracker;
    g_notes.controller = controller;
    if (g_notes.reenter) {
        const TQ3Vector3D step{1.0f, 0.0f, 0.0f};
        Q3Tracker_MovePosition(tracker, nullptr, &step);
    }
    return kQ3Success;
}

void recordCursorNotify()
{
    ++g_notes.cursorCount;
}

class ControllerApiTest : public Q3ApiTest {
protected:
    // The controllers Q3Controller_Next walks from the start of the list to
    // its end (at most 100), each call expected to succeed.
    static std::vector<TQ3ControllerRef> controllerList()
    {
        std::vector<TQ3ControllerRef> list;
        TQ3ControllerRef walk = nullptr;
        EXPECT_EQ(Q3Controller_Next(nullptr, &walk), kQ3Success);
        while (walk != nullptr && list.size() < 100) {
            list.push_back(walk);
            EXPECT_EQ(Q3Controller_Next(walk, &walk), kQ3Success);
        }
        return list;
    }

    void SetUp() override
    {
        Q3ApiTest::SetUp();
        g_channels = Channels{};
        g_notes = Notes{};
    }

    // A device with 3 values and 2 channels, active.
    TQ3ControllerRef makeDevice(const char* signature = "Q3 Test Devices:Cube", bool active = true)
    {
        m_signature = signature;
        TQ3ControllerData data{};
        data.signature = const_cast<char*>(m_signature.c_str());
        data.valueCount = 3;
        data.channelCount = 2;
        data.channelGetMethod = getChannel;
        data.channelSetMethod = setChannel;
        TQ3ControllerRef ref = Q3Controller_New(&data);
        EXPECT_NE(ref, nullptr);
        if (active)
            EXPECT_EQ(Q3Controller_SetActivation(ref, kQ3True), kQ3Success);
        return ref;
    }

    std::string m_signature;
};

bool samePoint(const TQ3Point3D& a, const TQ3Point3D& b, float tolerance = 1e-5f)
{
    return std::fabs(a.x - b.x) <= tolerance && std::fabs(a.y - b.y) <= tolerance &&
           std::fabs(a.z - b.z) <= tolerance;
}

// Unit quaternions q and -q are the same rotation.
bool sameRotation(const TQ3Quaternion& a, const TQ3Quaternion& b, float tolerance = 1e-5f)
{
    const double d = double(a.w) * b.w + double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z;
    return std::fabs(std::fabs(d) - 1.0) <= tolerance;
}

// (cos(a/2), sin(a/2) axis): a counterclockwise turn by a about the unit axis.
TQ3Quaternion turn(double radians, double x, double y, double z)
{
    const double s = std::sin(radians / 2.0);
    return TQ3Quaternion{float(std::cos(radians / 2.0)), float(s * x), float(s * y), float(s * z)};
}

// v turned by unit q: q v q^-1 written out (Hamilton product).
Point3 rotate(const TQ3Quaternion& q, const Point3& v)
{
    const double w = q.w, x = q.x, y = q.y, z = q.z;
    // t = 2 (q.xyz x v); v' = v + w t + q.xyz x t
    const double tx = 2.0 * (y * v.z - z * v.y), ty = 2.0 * (z * v.x - x * v.z), tz = 2.0 * (x * v.y - y * v.x);
    return Point3{v.x + w * tx + (y * tz - z * ty), v.y + w * ty + (z * tx - x * tz),
                  v.z + w * tz + (x * ty - y * tx)};
}

// ---- Controllers ----------------------------------------------------------

TEST_F(ControllerApiTest, NewMakesAnInactiveControllerWithTheDriversDescription)
{
    TQ3ControllerRef ref = makeDevice("Acme:Wand", false);
    EXPECT_EQ(booleanOf(Q3Controller_GetActivation, ref), kQ3False);
    unsigned long count = 0;
    ASSERT_EQ(Q3Controller_GetValueCount(ref, &count), kQ3Success);
    EXPECT_EQ(count, 3u);
    char signature[64];
    ASSERT_EQ(Q3Controller_GetSignature(ref, signature, sizeof signature), kQ3Success);
    EXPECT_STREQ(signature, "Acme:Wand");
    unsigned long buttons = 99;
    ASSERT_EQ(Q3Controller_GetButtons(ref, &buttons), kQ3Success);
    EXPECT_EQ(buttons, 0u);
    EXPECT_EQ(booleanOf(Q3Controller_HasTracker, ref), kQ3False);
}

TEST_F(ControllerApiTest, NewRejectsBadData)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    TQ3ControllerData data{};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_New(&data), nullptr), kQ3ErrorNULLParameter);
    char signature[] = "x";
    data.signature = signature;
    data.valueCount = 1025;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_New(&data), nullptr), kQ3ErrorParameterOutOfRange);
    data.valueCount = UINT32_MAX;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_New(&data), nullptr), kQ3ErrorParameterOutOfRange);
    data.valueCount = 1024;
    data.channelCount = 1025;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_New(&data), nullptr), kQ3ErrorParameterOutOfRange);
    TQ3ControllerRef first = nullptr;
    ASSERT_EQ(Q3Controller_Next(nullptr, &first), kQ3Success);
    EXPECT_EQ(first, nullptr) << "a refused controller must not enter the list";
}

TEST_F(ControllerApiTest, EveryCallRejectsANullOrUnknownControllerRef)
{
    int notAController = 0;
    TQ3ControllerRef bogus = &notAController;
    TQ3Boolean b;
    unsigned long n = 0;
    float f[3] = {};
    char text[8];
    TQ3Point3D p{};
    TQ3Vector3D v{};
    TQ3Quaternion q{1, 0, 0, 0};
    unsigned char bytes[4] = {};
    for (TQ3ControllerRef ref : {TQ3ControllerRef{nullptr}, bogus}) {
        const TQ3Error code = ref == nullptr ? kQ3ErrorNULLParameter : kQ3ErrorInvalidParameter;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_Decommission(ref), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetActivation(ref, kQ3True), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetActivation(ref, &b), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetSignature(ref, text, 8), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetChannel(ref, 0, bytes, 4), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetChannel(ref, 0, bytes, &n), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetValueCount(ref, &n), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetTracker(ref, nullptr), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_HasTracker(ref, &b), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_Track2DCursor(ref, &b), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_Track3DCursor(ref, &b), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetButtons(ref, &n), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetButtons(ref, 1), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetTrackerPosition(ref, &p), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetTrackerPosition(ref, &p), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_MoveTrackerPosition(ref, &v), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetTrackerOrientation(ref, &q), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetTrackerOrientation(ref, &q), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_MoveTrackerOrientation(ref, &q), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetValues(ref, 3, f, &b, nullptr), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetValues(ref, f, 3), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3ControllerState_New(ref), nullptr), code);
    }
    // Next takes NULL (the start of the list) but not an unknown pointer.
    TQ3ControllerRef next = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_Next(bogus, &next), kQ3Failure), kQ3ErrorInvalidParameter);
}

TEST_F(ControllerApiTest, EveryCallRejectsNullOutputs)
{
    TQ3ControllerRef ref = makeDevice();
    unsigned long n = 0;
    TQ3Boolean b = kQ3False;
    float f[3] = {};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetListChanged(nullptr, &n), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetListChanged(&b, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_Next(nullptr, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetActivation(ref, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetSignature(ref, nullptr, 8), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetValueCount(ref, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_HasTracker(ref, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_Track2DCursor(ref, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_Track3DCursor(ref, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetButtons(ref, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetTrackerPosition(ref, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetTrackerPosition(ref, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_MoveTrackerPosition(ref, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetTrackerOrientation(ref, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetTrackerOrientation(ref, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_MoveTrackerOrientation(ref, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetValues(ref, 3, nullptr, &b, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetValues(ref, 3, f, nullptr, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetValues(ref, nullptr, 3), kQ3Failure), kQ3ErrorNULLParameter);
}

TEST_F(ControllerApiTest, ListSerialNumberChangesWithTheListAndNextWalksIt)
{
    TQ3Boolean changed = kQ3False;
    unsigned long serial = 0;
    ASSERT_EQ(Q3Controller_GetListChanged(&changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3True) << "0 never matches";
    ASSERT_EQ(Q3Controller_GetListChanged(&changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3False);

    TQ3ControllerRef a = makeDevice("A", false);
    ASSERT_EQ(Q3Controller_GetListChanged(&changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3True) << "a new controller";
    TQ3ControllerRef b = makeDevice("B", false);
    ASSERT_EQ(Q3Controller_SetActivation(a, kQ3True), kQ3Success);
    ASSERT_EQ(Q3Controller_GetListChanged(&changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3True) << "activation";
    ASSERT_EQ(Q3Controller_SetActivation(a, static_cast<TQ3Boolean>(7)), kQ3Success);
    ASSERT_EQ(Q3Controller_GetListChanged(&changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3False) << "7 counts as kQ3True: no change";

    EXPECT_EQ(controllerList(), (std::vector<TQ3ControllerRef>{a, b}));

    ASSERT_EQ(Q3Controller_Decommission(a), kQ3Success);
    ASSERT_EQ(Q3Controller_GetListChanged(&changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3True) << "decommission";
    ASSERT_EQ(Q3Controller_Decommission(a), kQ3Success);
    ASSERT_EQ(Q3Controller_GetListChanged(&changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3False) << "a second decommission changes nothing";
    EXPECT_EQ(controllerList(), std::vector<TQ3ControllerRef>{b}) << "decommissioned controllers are skipped";
    TQ3ControllerRef walk = nullptr;
    ASSERT_EQ(Q3Controller_Next(a, &walk), kQ3Success);
    EXPECT_EQ(walk, b) << "a decommissioned ref is still a valid place to continue from";
}

TEST_F(ControllerApiTest, DecommissionedControllerStaysValidAndIsRecommissionedBySignature)
{
    TQ3ControllerRef a = makeDevice("Acme:Glove");
    ASSERT_EQ(Q3Controller_SetButtons(a, 5), kQ3Success);
    ASSERT_EQ(Q3Controller_Decommission(a), kQ3Success);
    TQ3Boolean active = kQ3True;
    ASSERT_EQ(Q3Controller_GetActivation(a, &active), kQ3Success);
    EXPECT_EQ(active, kQ3False);
    ASSERT_EQ(Q3Controller_SetActivation(a, kQ3True), kQ3Success);
    ASSERT_EQ(Q3Controller_GetActivation(a, &active), kQ3Success);
    EXPECT_EQ(active, kQ3False) << "a decommissioned controller cannot be activated";
    unsigned char data[4] = {1, 2, 3, 4};
    unsigned long size = 4;
    ASSERT_EQ(Q3Controller_SetChannel(a, 0, data, 4), kQ3Success);
    EXPECT_TRUE(g_channels.sets.empty()) << "no longer operational";
    ASSERT_EQ(Q3Controller_GetChannel(a, 0, data, &size), kQ3Success);
    EXPECT_EQ(size, 0u);

    TQ3ControllerRef again = makeDevice("Acme:Glove", false);
    EXPECT_EQ(again, a) << "the same signature brings the controller back";
    ASSERT_EQ(Q3Controller_GetActivation(a, &active), kQ3Success);
    EXPECT_EQ(active, kQ3False);
    unsigned long buttons = 1;
    ASSERT_EQ(Q3Controller_GetButtons(a, &buttons), kQ3Success);
    EXPECT_EQ(buttons, 0u);
    TQ3ControllerRef other = makeDevice("Acme:Glove", false);
    EXPECT_NE(other, a) << "a second device of the same model while the first is live";
}

TEST_F(ControllerApiTest, GetSignatureCutsToNumChars)
{
    TQ3ControllerRef ref = makeDevice("Spaceball 4000");
    char text[6];
    std::memset(text, 'z', sizeof text);
    ASSERT_EQ(Q3Controller_GetSignature(ref, text, 6), kQ3Success);
    EXPECT_STREQ(text, "Space");
    ASSERT_EQ(Q3Controller_GetSignature(ref, text, 1), kQ3Success);
    EXPECT_STREQ(text, "");
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetSignature(ref, text, 0), kQ3Failure), kQ3ErrorParameterOutOfRange);
}

TEST_F(ControllerApiTest, ChannelsReachTheDriversMethods)
{
    TQ3ControllerRef ref = makeDevice();
    const unsigned char gain[3] = {9, 8, 7};
    ASSERT_EQ(Q3Controller_SetChannel(ref, 1, gain, 3), kQ3Success);
    ASSERT_EQ(g_channels.sets.size(), 1u);
    EXPECT_EQ(g_channels.sets[0], (std::pair<unsigned long, unsigned long>(1, 3)));
    EXPECT_EQ(g_channels.lastRef, ref);
    unsigned char out[8] = {};
    unsigned long size = sizeof out;
    ASSERT_EQ(Q3Controller_GetChannel(ref, 1, out, &size), kQ3Success);
    ASSERT_EQ(size, 3u);
    EXPECT_EQ(std::memcmp(out, gain, 3), 0);
    ASSERT_EQ(Q3Controller_SetChannel(ref, 0, nullptr, 0), kQ3Success) << "no data is a valid report";
    unsigned char big[257] = {};
    ASSERT_EQ(Q3Controller_SetChannel(ref, 0, big, 256), kQ3Success) << "exactly the maximum";

    // Channel 2 is one past the end; UINT32_MAX far past it.
    for (unsigned long channel : {2ul, (unsigned long)UINT32_MAX}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetChannel(ref, channel, gain, 3), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetChannel(ref, channel, out, &size), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetChannel(ref, 0, big, 257), kQ3Failure), kQ3ErrorParameterOutOfRange);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetChannel(ref, 0, nullptr, 1), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetChannel(ref, 0, nullptr, &size), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetChannel(ref, 0, out, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    const std::size_t setsBefore = g_channels.sets.size();
    g_channels.failSet = true;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetChannel(ref, 0, gain, 3), kQ3Failure), kQ3ErrorInvalidParameter);
    g_channels.failGet = true;
    size = 8;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_GetChannel(ref, 1, out, &size), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_EQ(size, 8u) << "a failed get leaves *dataSize";
    EXPECT_EQ(g_channels.sets.size(), setsBefore);
}

TEST_F(ControllerApiTest, ControllerWithoutChannelMethodsIgnoresChannels)
{
    char signature[] = "Plain mouse";
    TQ3ControllerData data{signature, 2, 1, nullptr, nullptr};
    TQ3ControllerRef ref = Q3Controller_New(&data);
    ASSERT_NE(ref, nullptr);
    unsigned char byte = 1;
    EXPECT_EQ(Q3Controller_SetChannel(ref, 0, &byte, 1), kQ3Success);
    unsigned long size = 1;
    EXPECT_EQ(Q3Controller_GetChannel(ref, 0, &byte, &size), kQ3Success);
    EXPECT_EQ(size, 0u);
}

TEST_F(ControllerApiTest, ValuesFollowTheSerialNumberRules)
{
    TQ3ControllerRef ref = makeDevice();
    const float reported[3] = {0.25f, -1.0f, 3.0f};
    ASSERT_EQ(Q3Controller_SetValues(ref, reported, 3), kQ3Success);
    float values[4] = {9, 9, 9, 9};
    TQ3Boolean changed = kQ3False;
    unsigned long serial = 0;
    ASSERT_EQ(Q3Controller_GetValues(ref, 4, values, &changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3True);
    EXPECT_EQ(values[0], 0.25f);
    EXPECT_EQ(values[1], -1.0f);
    EXPECT_EQ(values[2], 3.0f);
    EXPECT_EQ(values[3], 9.0f) << "only the controller's 3 values are written";
    values[0] = 42;
    ASSERT_EQ(Q3Controller_GetValues(ref, 3, values, &changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3False);
    EXPECT_EQ(values[0], 42.0f) << "same serial: untouched";
    ASSERT_EQ(Q3Controller_GetValues(ref, 1, values, &changed, nullptr), kQ3Success);
    EXPECT_EQ(changed, kQ3True) << "no serial: always read";
    EXPECT_EQ(values[0], 0.25f);

    const float two[2] = {5.0f, 6.0f};
    ASSERT_EQ(Q3Controller_SetValues(ref, two, 2), kQ3Success);
    ASSERT_EQ(Q3Controller_GetValues(ref, 3, values, &changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3True);
    EXPECT_EQ(values[0], 5.0f);
    EXPECT_EQ(values[2], 3.0f) << "values past valueCount keep their value";

    // Inactive: no effect, nothing read.
    ASSERT_EQ(Q3Controller_SetActivation(ref, kQ3False), kQ3Success);
    const float other[3] = {7, 7, 7};
    ASSERT_EQ(Q3Controller_SetValues(ref, other, 3), kQ3Success);
    values[0] = -5;
    ASSERT_EQ(Q3Controller_GetValues(ref, 3, values, &changed, nullptr), kQ3Success);
    EXPECT_EQ(changed, kQ3False);
    EXPECT_EQ(values[0], -5.0f);
    ASSERT_EQ(Q3Controller_SetActivation(ref, kQ3True), kQ3Success);
    ASSERT_EQ(Q3Controller_GetValues(ref, 3, values, &changed, nullptr), kQ3Success);
    EXPECT_EQ(values[0], 5.0f);
}

TEST_F(ControllerApiTest, SetValuesRejectsTooManyAndNonFiniteValuesAndChangesNothing)
{
    TQ3ControllerRef ref = makeDevice();
    const float start[3] = {1, 2, 3};
    ASSERT_EQ(Q3Controller_SetValues(ref, start, 3), kQ3Success);
    const float four[4] = {0, 0, 0, 0};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetValues(ref, four, 4), kQ3Failure), kQ3ErrorParameterOutOfRange);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetValues(ref, four, UINT32_MAX), kQ3Failure),
                    kQ3ErrorParameterOutOfRange);
    for (float bad : {kNaN, kInf, -kInf}) {
        const float values[3] = {0, bad, 0};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetValues(ref, values, 3), kQ3Failure), kQ3ErrorInvalidParameter);
    }
    float values[3];
    TQ3Boolean changed;
    ASSERT_EQ(Q3Controller_GetValues(ref, 3, values, &changed, nullptr), kQ3Success);
    EXPECT_EQ(values[0], 1.0f);
    EXPECT_EQ(values[1], 2.0f);
    EXPECT_EQ(values[2], 3.0f);
}

TEST_F(ControllerApiTest, TrackerButtonsAreTheOrOfItsControllers)
{
    TQ3TrackerObject tracker = Q3Tracker_New(recordNotify);
    TQ3ControllerRef a = makeDevice("A");
    TQ3ControllerRef b = makeDevice("B");
    ASSERT_EQ(Q3Controller_SetTracker(a, tracker), kQ3Success);
    ASSERT_EQ(Q3Controller_SetTracker(b, tracker), kQ3Success);
    ASSERT_EQ(Q3Controller_SetButtons(a, 0x1), kQ3Success);
    EXPECT_EQ(g_notes.count, 1);
    EXPECT_EQ(g_notes.controller, a);
    EXPECT_EQ(g_notes.tracker, tracker);
    ASSERT_EQ(Q3Controller_SetButtons(b, 0x5), kQ3Success);
    unsigned long buttons = 0;
    ASSERT_EQ(Q3Tracker_GetButtons(tracker, &buttons), kQ3Success);
    EXPECT_EQ(buttons, 0x5u);
    ASSERT_EQ(Q3Controller_SetButtons(b, 0x0), kQ3Success);
    ASSERT_EQ(Q3Tracker_GetButtons(tracker, &buttons), kQ3Success);
    EXPECT_EQ(buttons, 0x1u) << "button 0 is still down on A";
    ASSERT_EQ(Q3Controller_GetButtons(b, &buttons), kQ3Success);
    EXPECT_EQ(buttons, 0u);

    // Deactivating A withdraws its buttons; reactivating reports them again.
    ASSERT_EQ(Q3Controller_SetActivation(a, kQ3False), kQ3Success);
    ASSERT_EQ(Q3Tracker_GetButtons(tracker, &buttons), kQ3Success);
    EXPECT_EQ(buttons, 0u);
    ASSERT_EQ(Q3Controller_SetButtons(a, 0x2), kQ3Success);
    ASSERT_EQ(Q3Controller_GetButtons(a, &buttons), kQ3Success);
    EXPECT_EQ(buttons, 0x1u) << "an inactive controller's SetButtons has no effect";
    ASSERT_EQ(Q3Controller_SetActivation(a, kQ3True), kQ3Success);
    ASSERT_EQ(Q3Tracker_GetButtons(tracker, &buttons), kQ3Success);
    EXPECT_EQ(buttons, 0x1u);

    // Disposing the tracker sends A and B back to the cursor tracker.
    ASSERT_EQ(Q3Object_Dispose(tracker), kQ3Success);
    EXPECT_EQ(booleanOf(Q3Controller_HasTracker, a), kQ3False);
    EXPECT_EQ(booleanOf(Q3Controller_Track2DCursor, a), kQ3True);
}

TEST_F(ControllerApiTest, ChangeButtonsMasksAndTrackerInactivityHoldsNotification)
{
    TQ3TrackerObject tracker = Q3Tracker_New(recordNotify);
    ASSERT_EQ(Q3Tracker_ChangeButtons(tracker, nullptr, 0xF, 0x3), kQ3Success);
    unsigned long buttons = 0;
    ASSERT_EQ(Q3Tracker_GetButtons(tracker, &buttons), kQ3Success);
    EXPECT_EQ(buttons, 0x3u) << "only the masked bits";
    EXPECT_EQ(g_notes.count, 1);
    ASSERT_EQ(Q3Tracker_ChangeButtons(tracker, nullptr, 0x3, 0x3), kQ3Success);
    EXPECT_EQ(g_notes.count, 1) << "no change, no notification";
    ASSERT_EQ(Q3Tracker_SetActivation(tracker, kQ3False), kQ3Success);
    ASSERT_EQ(Q3Tracker_ChangeButtons(tracker, nullptr, 0x0, 0x1), kQ3Success);
    ASSERT_EQ(Q3Tracker_GetButtons(tracker, &buttons), kQ3Success);
    EXPECT_EQ(buttons, 0x2u) << "an inactive tracker still counts buttons";
    EXPECT_EQ(g_notes.count, 1) << "but does not notify";
    int bogus = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_ChangeButtons(tracker, &bogus, 1, 1), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    ASSERT_EQ(Q3Tracker_GetButtons(tracker, &buttons), kQ3Success);
    EXPECT_EQ(buttons, 0x2u);
    Q3Object_Dispose(tracker);
}

TEST_F(ControllerApiTest, SetTrackerRejectsObjectsThatAreNotTrackers)
{
    TQ3ControllerRef ref = makeDevice();
    const TQ3PointData data{{0, 0, 0}, nullptr};
    TQ3GeometryObject geometry = Q3Point_New(&data);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetTracker(ref, geometry), kQ3Failure), kQ3ErrorInvalidObjectType);
    TQ3TrackerObject dead = Q3Tracker_New(nullptr);
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetTracker(ref, dead), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_EQ(booleanOf(Q3Controller_Track2DCursor, ref), kQ3True) << "still on the cursor tracker";
    Q3Object_Dispose(geometry);
}

TEST_F(ControllerApiTest, ControllerMovesItsTrackerOnlyWhileActive)
{
    TQ3TrackerObject tracker = Q3Tracker_New(recordNotify);
    TQ3ControllerRef ref = makeDevice();
    ASSERT_EQ(Q3Controller_SetTracker(ref, tracker), kQ3Success);
    TQ3Boolean has = kQ3False;
    ASSERT_EQ(Q3Controller_HasTracker(ref, &has), kQ3Success);
    EXPECT_EQ(has, kQ3True);
    const TQ3Point3D at{1, 2, 3};
    ASSERT_EQ(Q3Controller_SetTrackerPosition(ref, &at), kQ3Success);
    const TQ3Vector3D step{0.5f, 0, -1};
    ASSERT_EQ(Q3Controller_MoveTrackerPosition(ref, &step), kQ3Success);
    TQ3Point3D seen{};
    ASSERT_EQ(Q3Controller_GetTrackerPosition(ref, &seen), kQ3Success);
    EXPECT_TRUE(samePoint(seen, {1.5f, 2, 2}));
    const TQ3Quaternion quarter = turn(M_PI / 2, 0, 0, 1);
    ASSERT_EQ(Q3Controller_SetTrackerOrientation(ref, &quarter), kQ3Success);
    ASSERT_EQ(Q3Controller_MoveTrackerOrientation(ref, &quarter), kQ3Success);
    TQ3Quaternion q{};
    ASSERT_EQ(Q3Controller_GetTrackerOrientation(ref, &q), kQ3Success);
    EXPECT_TRUE(sameRotation(q, turn(M_PI, 0, 0, 1))) << "two quarter turns about z";
    EXPECT_EQ(g_notes.count, 4);

    ASSERT_EQ(Q3Controller_SetActivation(ref, kQ3False), kQ3Success);
    const TQ3Point3D elsewhere{9, 9, 9};
    ASSERT_EQ(Q3Controller_SetTrackerPosition(ref, &elsewhere), kQ3Success);
    ASSERT_EQ(Q3Controller_MoveTrackerPosition(ref, &step), kQ3Success);
    ASSERT_EQ(Q3Controller_SetTrackerOrientation(ref, &quarter), kQ3Success);
    ASSERT_EQ(Q3Controller_GetTrackerPosition(ref, &seen), kQ3Success);
    EXPECT_TRUE(samePoint(seen, {1.5f, 2, 2})) << "an inactive controller has no effect";
    EXPECT_EQ(g_notes.count, 4);
    ASSERT_EQ(Q3Controller_HasTracker(ref, &has), kQ3Success);
    EXPECT_EQ(has, kQ3False);

    // Bad coordinates are refused before anything moves.
    ASSERT_EQ(Q3Controller_SetActivation(ref, kQ3True), kQ3Success);
    for (float bad : {kNaN, kInf, -kInf}) {
        const TQ3Point3D p{0, bad, 0};
        const TQ3Vector3D v{bad, 0, 0};
        const TQ3Quaternion r{1, 0, 0, bad};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetTrackerPosition(ref, &p), kQ3Failure), kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_MoveTrackerPosition(ref, &v), kQ3Failure), kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetTrackerOrientation(ref, &r), kQ3Failure),
                        kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_MoveTrackerOrientation(ref, &r), kQ3Failure),
                        kQ3ErrorInvalidParameter);
    }
    const TQ3Quaternion zero{0, 0, 0, 0};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Controller_SetTrackerOrientation(ref, &zero), kQ3Failure), kQ3ErrorInvalidParameter);
    ASSERT_EQ(Q3Controller_GetTrackerPosition(ref, &seen), kQ3Success);
    EXPECT_TRUE(samePoint(seen, {1.5f, 2, 2}));
    EXPECT_EQ(g_notes.count, 4);
    Q3Object_Dispose(tracker);
}

TEST_F(ControllerApiTest, ControllerStateSavesResetsAndRestoresChannels)
{
    TQ3ControllerRef ref = makeDevice();
    const unsigned char c0[2] = {1, 2};
    const unsigned char c1[3] = {7, 8, 9};
    ASSERT_EQ(Q3Controller_SetChannel(ref, 0, c0, 2), kQ3Success);
    ASSERT_EQ(Q3Controller_SetChannel(ref, 1, c1, 3), kQ3Success);
    TQ3ControllerStateObject state = Q3ControllerState_New(ref);
    ASSERT_NE(state, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(state), kQ3SharedTypeControllerState);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ControllerState_Restore(state), kQ3Failure), kQ3ErrorStateUnavailable);

    g_channels.sets.clear();
    ASSERT_EQ(Q3ControllerState_SaveAndReset(state), kQ3Success);
    ASSERT_EQ(g_channels.sets.size(), 2u);
    EXPECT_EQ(g_channels.sets[0].second, 0u) << "reset: the set method receives no data";
    EXPECT_TRUE(g_channels.data[0].empty());
    EXPECT_TRUE(g_channels.data[1].empty());

    // Another application changes a channel meanwhile.
    const unsigned char theirs[1] = {0xEE};
    ASSERT_EQ(Q3Controller_SetChannel(ref, 1, theirs, 1), kQ3Success);
    ASSERT_EQ(Q3ControllerState_Restore(state), kQ3Success);
    EXPECT_EQ(g_channels.data[0], (std::vector<unsigned char>{1, 2}));
    EXPECT_EQ(g_channels.data[1], (std::vector<unsigned char>{7, 8, 9}));
    ASSERT_EQ(Q3ControllerState_Restore(state), kQ3Success) << "restorable again";

    TQ3TrackerObject notState = Q3Tracker_New(nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ControllerState_SaveAndReset(notState), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ControllerState_Restore(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    Q3Object_Dispose(notState);
    Q3Object_Dispose(state);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ControllerState_Restore(state), kQ3Failure), kQ3ErrorInvalidObject);
}

// ---- Trackers -------------------------------------------------------------

TEST_F(ControllerApiTest, NewTrackerIsActiveAtTheOriginWithZeroThresholds)
{
    TQ3TrackerObject tracker = Q3Tracker_New(nullptr);
    ASSERT_NE(tracker, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(tracker), kQ3SharedTypeTracker);
    TQ3Boolean active = kQ3False;
    ASSERT_EQ(Q3Tracker_GetActivation(tracker, &active), kQ3Success);
    EXPECT_EQ(active, kQ3True);
    float p = -1, o = -1;
    ASSERT_EQ(Q3Tracker_GetNotifyThresholds(tracker, &p, &o), kQ3Success);
    EXPECT_EQ(p, 0.0f);
    EXPECT_EQ(o, 0.0f);
    TQ3Point3D position{9, 9, 9};
    TQ3Boolean changed = kQ3False;
    ASSERT_EQ(Q3Tracker_GetPosition(tracker, &position, nullptr, &changed, nullptr), kQ3Success);
    EXPECT_EQ(changed, kQ3True);
    EXPECT_TRUE(samePoint(position, {0, 0, 0}));
    TQ3Quaternion q{};
    ASSERT_EQ(Q3Tracker_GetOrientation(tracker, &q, nullptr, &changed, nullptr), kQ3Success);
    EXPECT_TRUE(sameRotation(q, {1, 0, 0, 0}));
    Q3Object_Dispose(tracker);
}

TEST_F(ControllerApiTest, TrackerCallsRejectBadHandlesAndNullOutputs)
{
    const TQ3BoxData box{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, nullptr, nullptr};
    TQ3GeometryObject notTracker = Q3Box_New(&box);
    TQ3TrackerObject tracker = Q3Tracker_New(nullptr);
    float f;
    unsigned long n;
    TQ3Boolean b;
    TQ3Point3D p{};
    TQ3Vector3D v{};
    TQ3Quaternion q{1, 0, 0, 0};
    for (TQ3Object bad : {TQ3Object{nullptr}, notTracker}) {
        const TQ3Error code = bad == nullptr ? kQ3ErrorNULLParameter : kQ3ErrorInvalidObjectType;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetNotifyThresholds(bad, 0, 0), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetNotifyThresholds(bad, &f, &f), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetActivation(bad, kQ3True), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetActivation(bad, &b), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetButtons(bad, &n), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_ChangeButtons(bad, nullptr, 1, 1), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetPosition(bad, &p, &v, &b, &n), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetPosition(bad, nullptr, &p), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_MovePosition(bad, nullptr, &v), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetOrientation(bad, &q, &q, &b, &n), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetOrientation(bad, nullptr, &q), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_MoveOrientation(bad, nullptr, &q), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetEventCoordinates(bad, 0, 0, &p, &q), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetEventCoordinates(bad, 0, &n, &p, &q), kQ3Failure), code);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetNotifyThresholds(tracker, nullptr, &f), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetNotifyThresholds(tracker, &f, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetActivation(tracker, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetButtons(tracker, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetPosition(tracker, nullptr, &v, &b, &n), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetPosition(tracker, &p, &v, nullptr, &n), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetOrientation(tracker, nullptr, &q, &b, &n), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetOrientation(tracker, &q, &q, nullptr, &n), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetPosition(tracker, nullptr, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_MovePosition(tracker, nullptr, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetOrientation(tracker, nullptr, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_MoveOrientation(tracker, nullptr, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    int bogus = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetPosition(tracker, &bogus, &p), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_MovePosition(tracker, &bogus, &v), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetOrientation(tracker, &bogus, &q), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_MoveOrientation(tracker, &bogus, &q), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    Q3Object_Dispose(tracker);
    Q3Object_Dispose(notTracker);
}

TEST_F(ControllerApiTest, ThresholdsRejectNegativeAndNonFiniteValuesAndStayUnchanged)
{
    TQ3TrackerObject tracker = Q3Tracker_New(nullptr);
    ASSERT_EQ(Q3Tracker_SetNotifyThresholds(tracker, 0.5f, 0.25f), kQ3Success);
    for (float bad : {kNaN, kInf, -kInf, -0.1f}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetNotifyThresholds(tracker, bad, 0.0f), kQ3Failure),
                        kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetNotifyThresholds(tracker, 0.0f, bad), kQ3Failure),
                        kQ3ErrorInvalidParameter);
    }
    float p = 0, o = 0;
    ASSERT_EQ(Q3Tracker_GetNotifyThresholds(tracker, &p, &o), kQ3Success);
    EXPECT_EQ(p, 0.5f);
    EXPECT_EQ(o, 0.25f);
    Q3Object_Dispose(tracker);
}

TEST_F(ControllerApiTest, GetPositionHandsOutOrFoldsTheRelativeMotion)
{
    TQ3TrackerObject tracker = Q3Tracker_New(nullptr);
    const TQ3Point3D at{1, 1, 1};
    ASSERT_EQ(Q3Tracker_SetPosition(tracker, nullptr, &at), kQ3Success);
    const TQ3Vector3D step{0.5f, 0, 0};
    ASSERT_EQ(Q3Tracker_MovePosition(tracker, nullptr, &step), kQ3Success);
    ASSERT_EQ(Q3Tracker_MovePosition(tracker, nullptr, &step), kQ3Success);

    TQ3Point3D position{};
    TQ3Vector3D delta{};
    TQ3Boolean changed = kQ3False;
    unsigned long serial = 0;
    ASSERT_EQ(Q3Tracker_GetPosition(tracker, &position, &delta, &changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3True);
    EXPECT_TRUE(samePoint(position, at)) << "with delta given, the position excludes it";
    EXPECT_TRUE(samePoint({delta.x, delta.y, delta.z}, {1, 0, 0}));
    ASSERT_EQ(Q3Tracker_GetPosition(tracker, &position, &delta, &changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3False) << "nothing reported since";

    ASSERT_EQ(Q3Tracker_MovePosition(tracker, nullptr, &step), kQ3Success);
    ASSERT_EQ(Q3Tracker_GetPosition(tracker, &position, nullptr, &changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3True);
    EXPECT_TRUE(samePoint(position, {1.5f, 1, 1})) << "without delta, it is folded in";
    ASSERT_EQ(Q3Tracker_GetPosition(tracker, &position, &delta, &changed, nullptr), kQ3Success);
    EXPECT_TRUE(samePoint(position, {1.5f, 1, 1}));
    EXPECT_TRUE(samePoint({delta.x, delta.y, delta.z}, {0, 0, 0})) << "the accumulator was reset";

    // An inactive tracker ignores reports and answers nothing.
    ASSERT_EQ(Q3Tracker_SetActivation(tracker, kQ3False), kQ3Success);
    const TQ3Point3D far{50, 50, 50};
    ASSERT_EQ(Q3Tracker_SetPosition(tracker, nullptr, &far), kQ3Success);
    position = TQ3Point3D{-7, -7, -7};
    ASSERT_EQ(Q3Tracker_GetPosition(tracker, &position, nullptr, &changed, nullptr), kQ3Success);
    EXPECT_EQ(changed, kQ3False);
    EXPECT_TRUE(samePoint(position, {-7, -7, -7}));
    ASSERT_EQ(Q3Tracker_SetActivation(tracker, kQ3True), kQ3Success);
    ASSERT_EQ(Q3Tracker_GetPosition(tracker, &position, nullptr, &changed, nullptr), kQ3Success);
    EXPECT_TRUE(samePoint(position, {1.5f, 1, 1}));

    for (float bad : {kNaN, kInf, -kInf}) {
        const TQ3Point3D p{bad, 0, 0};
        const TQ3Vector3D v{0, 0, bad};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetPosition(tracker, nullptr, &p), kQ3Failure), kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_MovePosition(tracker, nullptr, &v), kQ3Failure), kQ3ErrorInvalidParameter);
    }
    ASSERT_EQ(Q3Tracker_GetPosition(tracker, &position, nullptr, &changed, nullptr), kQ3Success);
    EXPECT_TRUE(samePoint(position, {1.5f, 1, 1}));
    Q3Object_Dispose(tracker);
}

TEST_F(ControllerApiTest, GetOrientationHandsOutOrFoldsTheRelativeTurn)
{
    TQ3TrackerObject tracker = Q3Tracker_New(nullptr);
    const TQ3Quaternion aboutX = turn(M_PI / 2, 1, 0, 0);
    const TQ3Quaternion aboutY = turn(M_PI / 2, 0, 1, 0);
    ASSERT_EQ(Q3Tracker_SetOrientation(tracker, nullptr, &aboutX), kQ3Success);
    const TQ3Quaternion unnormalized{2.0f * aboutY.w, 2.0f * aboutY.x, 2.0f * aboutY.y, 2.0f * aboutY.z};
    ASSERT_EQ(Q3Tracker_MoveOrientation(tracker, nullptr, &unnormalized), kQ3Success);

    TQ3Quaternion orientation{}, delta{};
    TQ3Boolean changed = kQ3False;
    ASSERT_EQ(Q3Tracker_GetOrientation(tracker, &orientation, &delta, &changed, nullptr), kQ3Success);
    EXPECT_TRUE(sameRotation(orientation, aboutX));
    EXPECT_TRUE(sameRotation(delta, aboutY)) << "stored normalized";

    ASSERT_EQ(Q3Tracker_MoveOrientation(tracker, nullptr, &aboutY), kQ3Success);
    ASSERT_EQ(Q3Tracker_GetOrientation(tracker, &orientation, nullptr, &changed, nullptr), kQ3Success);
    // aboutX first, then aboutY: (0, 0, 1) -> (0, -1, 0) -> (0, -1, 0); (0, 1, 0) -> (0, 0, 1) -> (1, 0, 0).
    const Point3 z = rotate(orientation, {0, 0, 1});
    const Point3 y = rotate(orientation, {0, 1, 0});
    EXPECT_NEAR(z.x, 0.0, 1e-5);
    EXPECT_NEAR(z.y, -1.0, 1e-5);
    EXPECT_NEAR(z.z, 0.0, 1e-5);
    EXPECT_NEAR(y.x, 1.0, 1e-5);
    EXPECT_NEAR(y.y, 0.0, 1e-5);
    EXPECT_NEAR(y.z, 0.0, 1e-5);
    ASSERT_EQ(Q3Tracker_GetOrientation(tracker, &orientation, &delta, &changed, nullptr), kQ3Success);
    EXPECT_TRUE(sameRotation(delta, {1, 0, 0, 0})) << "the accumulator was reset";

    const TQ3Quaternion zero{0, 0, 0, 0};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetOrientation(tracker, nullptr, &zero), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_MoveOrientation(tracker, nullptr, &zero), kQ3Failure), kQ3ErrorInvalidParameter);
    for (float bad : {kNaN, kInf, -kInf}) {
        const TQ3Quaternion q{bad, 0, 0, 0};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetOrientation(tracker, nullptr, &q), kQ3Failure),
                        kQ3ErrorInvalidParameter);
    }
    ASSERT_EQ(Q3Tracker_GetOrientation(tracker, &delta, nullptr, &changed, nullptr), kQ3Success);
    EXPECT_TRUE(sameRotation(delta, orientation)) << "refused reports changed nothing";
    Q3Object_Dispose(tracker);
}

TEST_F(ControllerApiTest, SerialNumberChangesWithEveryCoordinateReport)
{
    TQ3TrackerObject tracker = Q3Tracker_New(nullptr);
    TQ3Point3D p{};
    TQ3Boolean changed = kQ3False;
    unsigned long serial = 0;
    ASSERT_EQ(Q3Tracker_GetPosition(tracker, &p, nullptr, &changed, &serial), kQ3Success);
    const unsigned long first = serial;
    EXPECT_NE(first, 0u);
    const TQ3Quaternion q = turn(0.1, 0, 0, 1);
    ASSERT_EQ(Q3Tracker_SetOrientation(tracker, nullptr, &q), kQ3Success);
    ASSERT_EQ(Q3Tracker_GetPosition(tracker, &p, nullptr, &changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3True) << "an orientation report is a coordinate change too";
    EXPECT_NE(serial, first);
    Q3Object_Dispose(tracker);
}

TEST_F(ControllerApiTest, NotifyFunctionRunsWhenAThresholdIsReached)
{
    TQ3TrackerObject tracker = Q3Tracker_New(recordNotify);
    ASSERT_EQ(Q3Tracker_SetNotifyThresholds(tracker, 1.0f, 0.5f), kQ3Success);
    const TQ3Vector3D small{0.4f, 0, 0};
    ASSERT_EQ(Q3Tracker_MovePosition(tracker, nullptr, &small), kQ3Success);
    ASSERT_EQ(Q3Tracker_MovePosition(tracker, nullptr, &small), kQ3Success);
    EXPECT_EQ(g_notes.count, 0) << "0.8 < 1";
    ASSERT_EQ(Q3Tracker_MovePosition(tracker, nullptr, &small), kQ3Success);
    EXPECT_EQ(g_notes.count, 1) << "1.2 >= 1";
    EXPECT_EQ(g_notes.tracker, tracker);
    EXPECT_EQ(g_notes.controller, nullptr);
    ASSERT_EQ(Q3Tracker_MovePosition(tracker, nullptr, &small), kQ3Success);
    EXPECT_EQ(g_notes.count, 1) << "measured from the last notification";

    const TQ3Quaternion slight = turn(0.3, 0, 1, 0);
    ASSERT_EQ(Q3Tracker_MoveOrientation(tracker, nullptr, &slight), kQ3Success);
    EXPECT_EQ(g_notes.count, 1) << "0.3 rad < 0.5";
    ASSERT_EQ(Q3Tracker_MoveOrientation(tracker, nullptr, &slight), kQ3Success);
    EXPECT_EQ(g_notes.count, 2) << "0.6 rad >= 0.5";

    ASSERT_EQ(Q3Tracker_SetNotifyThresholds(tracker, 0.0f, 0.0f), kQ3Success);
    TQ3Point3D here{};
    TQ3Boolean changed;
    ASSERT_EQ(Q3Tracker_GetPosition(tracker, &here, nullptr, &changed, nullptr), kQ3Success);
    ASSERT_EQ(Q3Tracker_SetPosition(tracker, nullptr, &here), kQ3Success);
    EXPECT_EQ(g_notes.count, 2) << "no change never notifies";
    const TQ3Vector3D tiny{0, 1e-3f, 0};
    ASSERT_EQ(Q3Tracker_MovePosition(tracker, nullptr, &tiny), kQ3Success);
    EXPECT_EQ(g_notes.count, 3) << "threshold 0: every change";
    Q3Object_Dispose(tracker);
}

TEST_F(ControllerApiTest, NotifyFunctionIsNeverCalledReentrantly)
{
    TQ3TrackerObject tracker = Q3Tracker_New(recordNotify);
    g_notes.reenter = true;
    const TQ3Vector3D step{0, 1, 0};
    ASSERT_EQ(Q3Tracker_MovePosition(tracker, nullptr, &step), kQ3Success);
    EXPECT_EQ(g_notes.count, 1);
    g_notes.reenter = false;
    TQ3Point3D p{};
    TQ3Boolean changed;
    ASSERT_EQ(Q3Tracker_GetPosition(tracker, &p, nullptr, &changed, nullptr), kQ3Success);
    EXPECT_TRUE(samePoint(p, {1, 1, 0})) << "the notify function's own move was kept";
    Q3Object_Dispose(tracker);
}

TEST_F(ControllerApiTest, EventCoordinatesPickTheClosestTimeAndDiscardOlderOnes)
{
    TQ3TrackerObject tracker = Q3Tracker_New(nullptr);
    unsigned long buttons = 0;
    TQ3Point3D p{};
    TQ3Quaternion q{};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_GetEventCoordinates(tracker, 0, &buttons, &p, &q), kQ3Failure),
                    kQ3ErrorDataNotAvailable);
    for (unsigned long t = 1; t <= 20; ++t) {
        const TQ3Point3D at{float(t), 0, 0};
        ASSERT_EQ(Q3Tracker_SetEventCoordinates(tracker, t * 100, t, &at, nullptr), kQ3Success);
    }
    // Only the latest 16 (times 500..2000) are kept: 120 is closest to 500.
    ASSERT_EQ(Q3Tracker_GetEventCoordinates(tracker, 120, &buttons, &p, &q), kQ3Success);
    EXPECT_EQ(buttons, 5u);
    EXPECT_TRUE(sameRotation(q, {1, 0, 0, 0})) << "NULL orientation: the tracker's own";
    ASSERT_EQ(Q3Tracker_GetEventCoordinates(tracker, 1049, &buttons, nullptr, nullptr), kQ3Success);
    EXPECT_EQ(buttons, 10u);
    ASSERT_EQ(Q3Tracker_GetEventCoordinates(tracker, 1050, &buttons, &p, nullptr), kQ3Success);
    EXPECT_EQ(buttons, 10u) << "a tie goes to the older event";
    ASSERT_EQ(Q3Tracker_GetEventCoordinates(tracker, 0, &buttons, &p, nullptr), kQ3Success);
    EXPECT_EQ(buttons, 10u) << "events older than 1000 were discarded";
    EXPECT_TRUE(samePoint(p, {10, 0, 0}));
    ASSERT_EQ(Q3Tracker_GetEventCoordinates(tracker, UINT32_MAX, &buttons, nullptr, nullptr), kQ3Success);
    EXPECT_EQ(buttons, 20u);

    const TQ3Quaternion zero{0, 0, 0, 0};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetEventCoordinates(tracker, 1, 1, nullptr, &zero), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    const TQ3Point3D nan{kNaN, 0, 0};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Tracker_SetEventCoordinates(tracker, 1, 1, &nan, nullptr), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    ASSERT_EQ(Q3Tracker_SetActivation(tracker, kQ3False), kQ3Success);
    ASSERT_EQ(Q3Tracker_SetEventCoordinates(tracker, 5000, 99, nullptr, nullptr), kQ3Success);
    ASSERT_EQ(Q3Tracker_GetEventCoordinates(tracker, 5000, &buttons, nullptr, nullptr), kQ3Success);
    EXPECT_EQ(buttons, 20u) << "an inactive tracker records nothing";
    Q3Object_Dispose(tracker);
}

// ---- The cursor tracker ---------------------------------------------------

TEST_F(ControllerApiTest, ControllerWithoutTrackerDrivesTheCursorTracker)
{
    TQ3ControllerRef ref = makeDevice();
    ASSERT_EQ(Q3CursorTracker_SetNotifyFunc(recordCursorNotify), kQ3Success);
    TQ3CursorTrackerNotifyFunc f = nullptr;
    ASSERT_EQ(Q3CursorTracker_GetNotifyFunc(&f), kQ3Success);
    EXPECT_EQ(f, &recordCursorNotify);

    TQ3Boolean is2D = kQ3False, is3D = kQ3True;
    ASSERT_EQ(Q3Controller_Track2DCursor(ref, &is2D), kQ3Success);
    ASSERT_EQ(Q3Controller_Track3DCursor(ref, &is3D), kQ3Success);
    EXPECT_EQ(is2D, kQ3True);
    EXPECT_EQ(is3D, kQ3False);

    ASSERT_EQ(Q3CursorTracker_PrepareTracking(), kQ3Success);
    const TQ3Vector3D deeper{0.0f, 0.0f, -2.0f};
    ASSERT_EQ(Q3Controller_MoveTrackerPosition(ref, &deeper), kQ3Success);
    EXPECT_EQ(g_notes.cursorCount, 1);
    float depth = 9;
    TQ3Quaternion q{};
    TQ3Boolean hasOrientation = kQ3True, changed = kQ3False;
    ASSERT_EQ(Q3CursorTracker_GetAndClearDeltas(&depth, &q, &hasOrientation, &changed, nullptr), kQ3Success);
    EXPECT_EQ(changed, kQ3True);
    EXPECT_EQ(depth, 0.0f) << "a 2D cursor ignores depth";
    EXPECT_EQ(hasOrientation, kQ3False);

    ASSERT_EQ(Q3CursorTracker_SetTrackDeltas(kQ3True), kQ3Success);
    ASSERT_EQ(Q3Controller_Track3DCursor(ref, &is3D), kQ3Success);
    EXPECT_EQ(is3D, kQ3True);
    ASSERT_EQ(Q3Controller_MoveTrackerPosition(ref, &deeper), kQ3Success);
    const TQ3Point3D at{0, 0, 1.0f};
    ASSERT_EQ(Q3Controller_SetTrackerPosition(ref, &at), kQ3Success);
    const TQ3Quaternion tilt = turn(0.25, 1, 0, 0);
    ASSERT_EQ(Q3Controller_MoveTrackerOrientation(ref, &tilt), kQ3Success);
    unsigned long serial = 0;
    ASSERT_EQ(Q3CursorTracker_GetAndClearDeltas(&depth, &q, &hasOrientation, &changed, &serial), kQ3Success);
    EXPECT_FLOAT_EQ(depth, -2.0f + 1.0f) << "the move, then the set from z 0 to 1";
    EXPECT_EQ(hasOrientation, kQ3True);
    EXPECT_TRUE(sameRotation(q, tilt));
    depth = 77;
    ASSERT_EQ(Q3CursorTracker_GetAndClearDeltas(&depth, &q, &hasOrientation, &changed, &serial), kQ3Success);
    EXPECT_EQ(changed, kQ3False);
    EXPECT_EQ(depth, 77.0f);
    ASSERT_EQ(Q3CursorTracker_GetAndClearDeltas(&depth, &q, &hasOrientation, &changed, nullptr), kQ3Success);
    EXPECT_EQ(depth, 0.0f) << "cleared";
    EXPECT_EQ(hasOrientation, kQ3False);

    EXPECT_Q3_ERROR(EXPECT_EQ(Q3CursorTracker_GetAndClearDeltas(nullptr, &q, &hasOrientation, &changed, nullptr),
                              kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3CursorTracker_GetAndClearDeltas(&depth, nullptr, &hasOrientation, &changed, nullptr),
                              kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(
        EXPECT_EQ(Q3CursorTracker_GetAndClearDeltas(&depth, &q, nullptr, &changed, nullptr), kQ3Failure),
        kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(
        EXPECT_EQ(Q3CursorTracker_GetAndClearDeltas(&depth, &q, &hasOrientation, nullptr, nullptr), kQ3Failure),
        kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3CursorTracker_GetNotifyFunc(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    ASSERT_EQ(Q3CursorTracker_SetNotifyFunc(nullptr), kQ3Success);
    ASSERT_EQ(Q3CursorTracker_GetNotifyFunc(&f), kQ3Success);
    EXPECT_EQ(f, nullptr);
}

TEST_F(ControllerApiTest, LastExitForgetsEveryControllerAndTheCursorSettings)
{
    makeDevice("Forgotten");
    ASSERT_EQ(Q3CursorTracker_SetTrackDeltas(kQ3True), kQ3Success);
    // The fixture's Initialize is the outer one; leave it and start over.
    ASSERT_EQ(Q3Exit(), kQ3Success);
    ASSERT_EQ(Q3Initialize(), kQ3Success);
    TQ3ControllerRef first = nullptr;
    ASSERT_EQ(Q3Controller_Next(nullptr, &first), kQ3Success);
    EXPECT_EQ(first, nullptr);
    TQ3ControllerRef ref = makeDevice("Fresh");
    EXPECT_EQ(booleanOf(Q3Controller_Track2DCursor, ref), kQ3True) << "track deltas is back to its default";
}

// ---- A camera driven by a tracker -----------------------------------------

// The application's side: the notify function places the camera where the
// tracker is, looking along the tracker's -z with its +y up.
TQ3CameraObject g_camera = nullptr;

TQ3Status placeCamera(TQ3TrackerObject tracker, TQ3ControllerRef)
{
    TQ3Point3D position{};
    TQ3Quaternion orientation{};
    TQ3Boolean changed = kQ3False;
    Q3Tracker_GetPosition(tracker, &position, nullptr, &changed, nullptr);
    Q3Tracker_GetOrientation(tracker, &orientation, nullptr, &changed, nullptr);
    const Point3 forward = rotate(orientation, {0, 0, -1});
    const Point3 up = rotate(orientation, {0, 1, 0});
    TQ3CameraPlacement placement{position,
                                 {float(position.x + forward.x), float(position.y + forward.y),
                                  float(position.z + forward.z)},
                                 {float(up.x), float(up.y), float(up.z)}};
    ++g_notes.count;
    return Q3Camera_SetPlacement(g_camera, &placement);
}

// The lit pixels' centroid of the red triangle, in pixels (-1 if none).
Point3 redCentroid(const Pixmap& image)
{
    double sx = 0, sy = 0;
    int n = 0;
    for (unsigned long y = 0; y < image.height(); ++y)
        for (unsigned long x = 0; x < image.width(); ++x) {
            const Rgba c = image.at(x, y);
            if (c.r > 127 && c.g < 64 && c.b < 64) {
                sx += x + 0.5;
                sy += y + 0.5;
                ++n;
            }
        }
    return n == 0 ? Point3{-1, -1, 0} : Point3{sx / n, sy / n, double(n)};
}

TEST_F(ControllerApiTest, TrackerDrivesACameraThroughItsNotifyFunction)
{
    const Point3 start{0, 0, 5};
    const TQ3ViewAngleAspectCameraData cameraData = viewAngleCamera(start, {0, 0, 0}, {0, 1, 0}, M_PI / 3, 1.0);
    g_camera = Q3ViewAngleAspectCamera_New(&cameraData);
    ASSERT_NE(g_camera, nullptr);
    Pixmap image(64, 64);
    TestView view(image.pixmap(), kQ3RendererTypeInteractive, g_camera);

    // A red triangle around the world point (-2, 0, 0), facing +x and +z.
    const TQ3ColorRGB red{1, 0, 0};
    TQ3AttributeSet set = Q3AttributeSet_New();
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &red);
    const Point3 target{-2, 0, 0};
    TQ3TriangleData triangle{};
    const TQ3Point3D corners[3] = {{-2.3f, -0.3f, 0.3f}, {-1.7f, -0.3f, -0.3f}, {-2.0f, 0.4f, 0.0f}};
    for (int i = 0; i < 3; ++i)
        triangle.vertices[i] = TQ3Vertex3D{corners[i], nullptr};
    triangle.triangleAttributeSet = set;
    TQ3GeometryObject shape = Q3Triangle_New(&triangle);
    Q3Object_Dispose(set);
    const TQ3StyleObject both = Q3BackfacingStyle_New(kQ3BackfacingStyleBoth);
    auto draw = [&](TQ3ViewObject v) {
        Q3Style_Submit(both, v);
        Q3Geometry_Submit(shape, v);
    };

    // The device: a tracker with the application's notify function, and a
    // controller attached to it.
    TQ3TrackerObject tracker = Q3Tracker_New(placeCamera);
    TQ3ControllerRef device = makeDevice("Acme:Head tracker");
    ASSERT_EQ(Q3Controller_SetTracker(device, tracker), kQ3Success);

    // 1. The device reports the starting position: the camera is placed
    // there, looking down -z, so the triangle is left of centre.
    const TQ3Point3D at{float(start.x), float(start.y), float(start.z)};
    ASSERT_EQ(Q3Controller_SetTrackerPosition(device, &at), kQ3Success);
    ASSERT_EQ(g_notes.count, 1);
    TQ3CameraPlacement placement{};
    ASSERT_EQ(Q3Camera_GetPlacement(g_camera, &placement), kQ3Success);
    EXPECT_TRUE(samePoint(placement.cameraLocation, at));
    EXPECT_TRUE(samePoint(placement.pointOfInterest, {0, 0, 4}));
    ASSERT_EQ(view.render(draw), kQ3ViewStatusDone);
    Projection project = perspectiveProjection(start, {0, 0, 4}, {0, 1, 0}, M_PI / 3, 1.0, 64, 64);
    Point3 expected = project(target);
    Point3 seen = redCentroid(image);
    ASSERT_GT(seen.z, 0.0) << "the triangle is in view";
    // The centroid of the drawn pixels is the projected area's centroid,
    // within about a pixel of the projected centre for a triangle this
    // small and this far (0.6 units at depth 5: about 3.5 pixels of
    // perspective spread across it).
    EXPECT_NEAR(seen.x, expected.x, 1.5);
    EXPECT_NEAR(seen.y, expected.y, 1.5);
    EXPECT_LT(seen.x, 28.0) << "left of centre";

    // 2. The device turns a quarter turn to the left (about +y) and moves
    // to (2, 0, 0): the camera now looks down -x, straight at the
    // triangle, which is drawn at the centre.
    const TQ3Quaternion left = turn(M_PI / 2, 0, 1, 0);
    ASSERT_EQ(Q3Controller_MoveTrackerOrientation(device, &left), kQ3Success);
    const TQ3Vector3D step{2, 0, -5};
    ASSERT_EQ(Q3Controller_MoveTrackerPosition(device, &step), kQ3Success);
    ASSERT_EQ(g_notes.count, 3);
    ASSERT_EQ(Q3Camera_GetPlacement(g_camera, &placement), kQ3Success);
    EXPECT_TRUE(samePoint(placement.cameraLocation, {2, 0, 0}));
    EXPECT_TRUE(samePoint(placement.pointOfInterest, {1, 0, 0}, 1e-5f));
    EXPECT_TRUE(samePoint({placement.upVector.x, placement.upVector.y, placement.upVector.z}, {0, 1, 0}, 1e-5f));

    // The world-to-view transform reflects it: the target is 4 units in
    // front of the camera (view space looks down -z).
    TQ3Matrix4x4 worldToView{};
    ASSERT_EQ(Q3Camera_GetWorldToView(g_camera, &worldToView), kQ3Success);
    const TQ3Point3D world{-2, 0, 0};
    TQ3Point3D inView{};
    Q3Point3D_Transform(&world, &worldToView, &inView);
    EXPECT_TRUE(samePoint(inView, {0, 0, -4}, 1e-4f));

    ASSERT_EQ(view.render(draw), kQ3ViewStatusDone);
    project = perspectiveProjection({2, 0, 0}, {1, 0, 0}, {0, 1, 0}, M_PI / 3, 1.0, 64, 64);
    expected = project(target);
    seen = redCentroid(image);
    ASSERT_GT(seen.z, 0.0);
    EXPECT_NEAR(expected.x, 32.0, 1e-6);
    EXPECT_NEAR(seen.x, expected.x, 1.5);
    EXPECT_NEAR(seen.y, expected.y, 1.5);

    Q3Object_Dispose(tracker);
    Q3Object_Dispose(shape);
    Q3Object_Dispose(both);
    Q3Object_Dispose(g_camera);
    g_camera = nullptr;
}

} // namespace
