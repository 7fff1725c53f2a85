// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// QD3DLight.h: the calls every light has, and the ambient, directional,
// point and spot lights with their data rules, checked alike by New,
// SetData and every single-field setter.

#include "OwningApiTest.h"
#include "ShapeTypeChain.h"

#include "QD3DLight.h"
#include "QD3DMath.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"

#include <climits>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

using q3test::expectShapeTypeChain;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
const float kNonFinite[] = {kNaN, kInf, -kInf};
// Values outside a C enumeration's constants besides one past the last.
const int kOutsideEveryEnum[] = {-1, 1000000, INT_MAX, INT_MIN};

template <class T>
bool sameBytes(const T& a, const T& b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// What a C caller can store in an enum field: any int.
template <class E>
void storeInt(E& field, int value)
{
    static_assert(sizeof field == sizeof value, "Q3's enums are int-sized");
    std::memcpy(&field, &value, sizeof value);
}

TQ3LightData goodLightData()
{
    return TQ3LightData{kQ3True, 0.75f, {1.0f, 0.5f, 0.25f}};
}

TQ3DirectionalLightData goodDirectional()
{
    return TQ3DirectionalLightData{goodLightData(), kQ3False, {0.0f, -2.0f, -1.0f}};
}

TQ3PointLightData goodPoint()
{
    return TQ3PointLightData{goodLightData(), kQ3True, kQ3AttenuationTypeInverseDistance, {1.0f, 2.0f, 3.0f}};
}

TQ3SpotLightData goodSpot()
{
    return TQ3SpotLightData{goodLightData(), kQ3False, kQ3AttenuationTypeNone, {0.0f, 5.0f, 0.0f},
                            {0.0f, -1.0f, 0.0f},   0.25f,    0.5f,   kQ3FallOffTypeCosine};
}

// The four kinds, seen through their whole data as bytes.
struct LightKind {
    const char* name;
    TQ3ObjectType type;
    std::function<TQ3LightObject()> create;
    std::function<std::vector<unsigned char>(TQ3LightObject)> snapshot;
};

template <class Data>
std::vector<unsigned char> bytesOf(const Data& data)
{
    const unsigned char* p = reinterpret_cast<const unsigned char*>(&data);
    return std::vector<unsigned char>(p, p + sizeof data);
}

template <class Data>
std::function<std::vector<unsigned char>(TQ3LightObject)> snapshotWith(TQ3Status (*getData)(TQ3LightObject, Data*))
{
    return [getData](TQ3LightObject light) {
        Data data{};
        EXPECT_EQ(getData(light, &data), kQ3Success);
        return bytesOf(data);
    };
}

const std::vector<LightKind>& lightKinds()
{
    static const std::vector<LightKind> kinds = {
        {"ambient", kQ3LightTypeAmbient,
         [] {
             const TQ3LightData data = goodLightData();
             return Q3AmbientLight_New(&data);
         },
         snapshotWith(Q3AmbientLight_GetData)},
        {"directional", kQ3LightTypeDirectional,
         [] {
             const TQ3DirectionalLightData data = goodDirectional();
             return Q3DirectionalLight_New(&data);
         },
         snapshotWith(Q3DirectionalLight_GetData)},
        {"point", kQ3LightTypePoint,
         [] {
             const TQ3PointLightData data = goodPoint();
             return Q3PointLight_New(&data);
         },
         snapshotWith(Q3PointLight_GetData)},
        {"spot", kQ3LightTypeSpot,
         [] {
             const TQ3SpotLightData data = goodSpot();
             return Q3SpotLight_New(&data);
         },
         snapshotWith(Q3SpotLight_GetData)},
    };
    return kinds;
}

// Every way to break the TQ3LightData rules.
std::vector<TQ3LightData> badLightData()
{
    std::vector<TQ3LightData> cases;
    for (float bad : kNonFinite) {
        TQ3LightData d = goodLightData();
        d.brightness = bad;
        cases.push_back(d);
        for (float TQ3ColorRGB::*component : {&TQ3ColorRGB::r, &TQ3ColorRGB::g, &TQ3ColorRGB::b}) {
            TQ3LightData c = goodLightData();
            c.color.*component = bad;
            cases.push_back(c);
        }
    }
    return cases;
}

// Every way to break a direction.
std::vector<TQ3Vector3D> badDirections()
{
    std::vector<TQ3Vector3D> cases = {{0.0f, 0.0f, 0.0f}, {-0.0f, 0.0f, -0.0f}};
    for (float bad : kNonFinite)
        for (float TQ3Vector3D::*component : {&TQ3Vector3D::x, &TQ3Vector3D::y, &TQ3Vector3D::z}) {
            TQ3Vector3D v{0.0f, 0.0f, 1.0f};
            v.*component = bad;
            cases.push_back(v);
        }
    return cases;
}

std::vector<TQ3Point3D> badLocations()
{
    std::vector<TQ3Point3D> cases;
    for (float bad : kNonFinite)
        for (float TQ3Point3D::*component : {&TQ3Point3D::x, &TQ3Point3D::y, &TQ3Point3D::z}) {
            TQ3Point3D p{1.0f, 2.0f, 3.0f};
            p.*component = bad;
            cases.push_back(p);
        }
    return cases;
}

// Angles no spot light may have.
const float kBadAngles[] = {kNaN, kInf, -kInf, -0.001f, std::nextafter(kQ3PiOver2, 4.0f), 3.2f};

class LightApiTest : public q3test::OwningApiTest {
protected:
    /// A handle disposed already. Take it after creating the objects a
    /// check needs: a new object may reuse its address.
    TQ3Object disposedLight()
    {
        const TQ3LightData data = goodLightData();
        TQ3LightObject light = Q3AmbientLight_New(&data);
        Q3Object_Dispose(light);
        return light;
    }

    TQ3Object stray() { return reinterpret_cast<TQ3Object>(&m_stray); }

    /// Runs `change` on a light of `kind` expecting kQ3ErrorInvalidParameter,
    /// and checks that neither the light's data nor its edit index moved.
    void expectRejected(const LightKind& kind, TQ3LightObject light,
                        const std::function<TQ3Status()>& change, const std::string& what)
    {
        const std::vector<unsigned char> before = kind.snapshot(light);
        const unsigned long index = Q3Shared_GetEditIndex(light);
        EXPECT_Q3_ERROR(EXPECT_EQ(change(), kQ3Failure) << kind.name << ": " << what, kQ3ErrorInvalidParameter);
        EXPECT_STRNE(Q3Error_GetMessage(), "");
        EXPECT_EQ(kind.snapshot(light), before) << kind.name << ": " << what;
        EXPECT_EQ(Q3Shared_GetEditIndex(light), index) << kind.name << ": " << what;
    }

    /// Runs `change` expecting success and a new edit index.
    void expectAccepted(TQ3LightObject light, const std::function<TQ3Status()>& change, const std::string& what)
    {
        const unsigned long index = Q3Shared_GetEditIndex(light);
        EXPECT_EQ(change(), kQ3Success) << what;
        EXPECT_NE(Q3Shared_GetEditIndex(light), index) << what;
    }

    /// Checks `call` against NULL, disposed and stray handles, an attribute
    /// set, a style, and (for a kind's own calls) a light of another kind.
    void expectBadHandlesRejected(const std::function<TQ3Status(TQ3Object)>& call, const char* what,
                                  TQ3ObjectType kind = kQ3ObjectTypeInvalid)
    {
        std::vector<std::pair<TQ3Object, TQ3Error>> bad = {
            {nullptr, kQ3ErrorNULLParameter},
            {stray(), kQ3ErrorInvalidObject},
            {own(Q3AttributeSet_New()), kQ3ErrorInvalidObjectType},
            {own(Q3FillStyle_New(kQ3FillStyleFilled)), kQ3ErrorInvalidObjectType},
        };
        if (kind != kQ3ObjectTypeInvalid)
            for (const LightKind& other : lightKinds())
                if (other.type != kind)
                    bad.push_back({own(other.create()), kQ3ErrorInvalidObjectType});
        // Last, so that no object created after it can reuse its address.
        bad.push_back({disposedLight(), kQ3ErrorInvalidObject});
        for (const auto& [handle, error] : bad)
            EXPECT_Q3_ERROR(EXPECT_EQ(call(handle), kQ3Failure) << what, error);
    }

private:
    int m_stray = 0;
};

// ---- Every light --------------------------------------------------------------

TEST_F(LightApiTest, EachKindHasItsTypeChainAndIsNotDrawable)
{
    for (const LightKind& kind : lightKinds()) {
        TQ3LightObject light = own(kind.create());
        ASSERT_NE(light, nullptr) << kind.name;
        expectShapeTypeChain(light, kQ3ShapeTypeLight, kind.type, kQ3False, kind.name);
        EXPECT_EQ(Q3Light_GetType(light), kind.type) << kind.name;
    }
}

TEST_F(LightApiTest, LightsAreNotSubmittedToViews)
{
    for (const LightKind& kind : lightKinds()) {
        TQ3LightObject light = own(kind.create());
        boundsOf([&](TQ3ViewObject v) {
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Submit(light, v), kQ3Failure) << kind.name, kQ3ErrorInvalidObjectType);
        });
    }
}

TEST_F(LightApiTest, DuplicateIsAnIndependentCopy)
{
    for (const LightKind& kind : lightKinds()) {
        TQ3LightObject light = own(kind.create());
        TQ3LightObject copy = own(Q3Object_Duplicate(light));
        ASSERT_NE(copy, nullptr) << kind.name;
        EXPECT_NE(copy, light);
        EXPECT_EQ(Q3Light_GetType(copy), kind.type) << kind.name;
        EXPECT_EQ(kind.snapshot(copy), kind.snapshot(light)) << kind.name;
        ASSERT_EQ(Q3Light_SetBrightness(copy, 0.125f), kQ3Success);
        float brightness = 0.0f;
        ASSERT_EQ(Q3Light_GetBrightness(light, &brightness), kQ3Success);
        EXPECT_EQ(brightness, goodLightData().brightness) << kind.name;
    }
}

TEST_F(LightApiTest, GetTypeRejectsBadHandles)
{
    expectBadHandlesRejected(
        [](TQ3Object handle) { return Q3Light_GetType(handle) == kQ3ObjectTypeInvalid ? kQ3Failure : kQ3Success; },
        "Q3Light_GetType");
}

TEST_F(LightApiTest, CommonFieldsReadBackOnEveryKind)
{
    for (const LightKind& kind : lightKinds()) {
        TQ3LightObject light = own(kind.create());
        const std::vector<unsigned char> before = kind.snapshot(light);
        expectAccepted(light, [&] { return Q3Light_SetState(light, kQ3False); }, kind.name);
        TQ3Boolean isOn = kQ3True;
        ASSERT_EQ(Q3Light_GetState(light, &isOn), kQ3Success);
        EXPECT_EQ(isOn, kQ3False) << kind.name;
        // Brightness: any finite value, overbright and negative too.
        for (float brightness : {0.0f, 1.0f, 2.5f, -0.5f, 1e30f}) {
            expectAccepted(light, [&] { return Q3Light_SetBrightness(light, brightness); }, kind.name);
            float got = kNaN;
            ASSERT_EQ(Q3Light_GetBrightness(light, &got), kQ3Success);
            EXPECT_EQ(got, brightness) << kind.name;
        }
        const TQ3ColorRGB color{0.125f, 2.0f, -1.0f};
        expectAccepted(light, [&] { return Q3Light_SetColor(light, &color); }, kind.name);
        TQ3ColorRGB gotColor{};
        ASSERT_EQ(Q3Light_GetColor(light, &gotColor), kQ3Success);
        EXPECT_TRUE(sameBytes(gotColor, color)) << kind.name;
        const TQ3LightData data{kQ3True, 0.25f, {0.0f, 1.0f, 0.0f}};
        expectAccepted(light, [&] { return Q3Light_SetData(light, &data); }, kind.name);
        TQ3LightData got{};
        ASSERT_EQ(Q3Light_GetData(light, &got), kQ3Success);
        EXPECT_TRUE(sameBytes(got, data)) << kind.name;
        // The kind's own fields did not move: set the common part back and
        // the whole data is what it was.
        const TQ3LightData original = goodLightData();
        ASSERT_EQ(Q3Light_SetData(light, &original), kQ3Success);
        EXPECT_EQ(kind.snapshot(light), before) << kind.name;
    }
}

TEST_F(LightApiTest, StateStoresAnyNonzeroValueAsTrue)
{
    for (const LightKind& kind : lightKinds()) {
        TQ3LightObject light = own(kind.create());
        for (int raw : {2, -1, INT_MAX, INT_MIN}) {
            ASSERT_EQ(Q3Light_SetState(light, kQ3False), kQ3Success);
            EXPECT_EQ(Q3Light_SetState(light, static_cast<TQ3Boolean>(raw)), kQ3Success);
            TQ3Boolean isOn = kQ3False;
            ASSERT_EQ(Q3Light_GetState(light, &isOn), kQ3Success);
            EXPECT_EQ(isOn, kQ3True) << kind.name << " " << raw;
            TQ3LightData data = goodLightData();
            storeInt(data.isOn, raw);
            ASSERT_EQ(Q3Light_SetData(light, &data), kQ3Success);
            TQ3LightData got{};
            ASSERT_EQ(Q3Light_GetData(light, &got), kQ3Success);
            EXPECT_EQ(got.isOn, kQ3True) << kind.name << " " << raw;
        }
    }
}

TEST_F(LightApiTest, CommonSettersRejectNonFiniteValuesAndChangeNothing)
{
    for (const LightKind& kind : lightKinds()) {
        TQ3LightObject light = own(kind.create());
        for (float bad : kNonFinite) {
            expectRejected(kind, light, [&] { return Q3Light_SetBrightness(light, bad); }, "brightness");
            for (float TQ3ColorRGB::*component : {&TQ3ColorRGB::r, &TQ3ColorRGB::g, &TQ3ColorRGB::b}) {
                TQ3ColorRGB color{0.5f, 0.5f, 0.5f};
                color.*component = bad;
                expectRejected(kind, light, [&] { return Q3Light_SetColor(light, &color); }, "color");
            }
        }
        for (const TQ3LightData& data : badLightData())
            expectRejected(kind, light, [&] { return Q3Light_SetData(light, &data); }, "Q3Light_SetData");
    }
}

TEST_F(LightApiTest, CommonCallsRejectBadHandlesAndPointers)
{
    TQ3Boolean isOn = kQ3True;
    float brightness = 0.5f;
    TQ3ColorRGB color{0.5f, 0.5f, 0.5f};
    TQ3LightData data = goodLightData();
    const std::vector<std::pair<const char*, std::function<TQ3Status(TQ3Object)>>> calls = {
        {"GetState", [&](TQ3Object l) { return Q3Light_GetState(l, &isOn); }},
        {"GetBrightness", [&](TQ3Object l) { return Q3Light_GetBrightness(l, &brightness); }},
        {"GetColor", [&](TQ3Object l) { return Q3Light_GetColor(l, &color); }},
        {"SetState", [&](TQ3Object l) { return Q3Light_SetState(l, kQ3False); }},
        {"SetBrightness", [&](TQ3Object l) { return Q3Light_SetBrightness(l, 0.5f); }},
        {"SetColor", [&](TQ3Object l) { return Q3Light_SetColor(l, &color); }},
        {"GetData", [&](TQ3Object l) { return Q3Light_GetData(l, &data); }},
        {"SetData", [&](TQ3Object l) { return Q3Light_SetData(l, &data); }},
    };
    for (const auto& [name, call] : calls)
        expectBadHandlesRejected(call, name);
    // Failed getters left their outputs alone.
    EXPECT_EQ(isOn, kQ3True);
    EXPECT_EQ(brightness, 0.5f);
    EXPECT_EQ(color.r, 0.5f);
    EXPECT_TRUE(sameBytes(data, goodLightData()));
    TQ3LightObject light = own(lightKinds()[3].create());
    EXPECT_Q3_ERROR(Q3Light_GetState(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Light_GetBrightness(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Light_GetColor(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Light_SetColor(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Light_GetData(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Light_SetData(light, nullptr), kQ3ErrorNULLParameter);
    // The handle comes before the pointer.
    EXPECT_Q3_ERROR(Q3Light_SetColor(disposedLight(), nullptr), kQ3ErrorInvalidObject);
}

// ---- Ambient --------------------------------------------------------------------

TEST_F(LightApiTest, AmbientLightStoresItsDataAndChecksIt)
{
    const LightKind& kind = lightKinds()[0];
    const TQ3LightData good = goodLightData();
    TQ3LightObject light = own(Q3AmbientLight_New(&good));
    TQ3LightData got{};
    ASSERT_EQ(Q3AmbientLight_GetData(light, &got), kQ3Success);
    EXPECT_TRUE(sameBytes(got, good));
    const TQ3LightData other{kQ3False, 3.0f, {0.0f, 0.0f, 1.0f}};
    expectAccepted(light, [&] { return Q3AmbientLight_SetData(light, &other); }, "SetData");
    ASSERT_EQ(Q3AmbientLight_GetData(light, &got), kQ3Success);
    EXPECT_TRUE(sameBytes(got, other));
    for (const TQ3LightData& bad : badLightData()) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AmbientLight_New(&bad), nullptr), kQ3ErrorInvalidParameter);
        expectRejected(kind, light, [&] { return Q3AmbientLight_SetData(light, &bad); }, "SetData");
    }
}

TEST_F(LightApiTest, AmbientLightCallsRejectBadHandlesAndPointers)
{
    TQ3LightData data = goodLightData();
    expectBadHandlesRejected([&](TQ3Object l) { return Q3AmbientLight_GetData(l, &data); }, "GetData",
                             kQ3LightTypeAmbient);
    expectBadHandlesRejected([&](TQ3Object l) { return Q3AmbientLight_SetData(l, &data); }, "SetData",
                             kQ3LightTypeAmbient);
    EXPECT_TRUE(sameBytes(data, goodLightData()));
    TQ3LightObject light = own(Q3AmbientLight_New(&data));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AmbientLight_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3AmbientLight_GetData(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3AmbientLight_SetData(light, nullptr), kQ3ErrorNULLParameter);
}

// ---- Directional ------------------------------------------------------------------

TEST_F(LightApiTest, DirectionalLightStoresItsDataAsGiven)
{
    TQ3DirectionalLightData data = goodDirectional();
    TQ3LightObject light = own(Q3DirectionalLight_New(&data));
    TQ3DirectionalLightData got{};
    ASSERT_EQ(Q3DirectionalLight_GetData(light, &got), kQ3Success);
    EXPECT_TRUE(sameBytes(got, data));
    // The direction is kept as given, not normalized.
    TQ3Vector3D direction{};
    ASSERT_EQ(Q3DirectionalLight_GetDirection(light, &direction), kQ3Success);
    EXPECT_TRUE(sameBytes(direction, data.direction));
    const TQ3Vector3D tiny{0.0f, std::numeric_limits<float>::denorm_min(), 0.0f};
    expectAccepted(light, [&] { return Q3DirectionalLight_SetDirection(light, &tiny); }, "SetDirection");
    ASSERT_EQ(Q3DirectionalLight_GetDirection(light, &direction), kQ3Success);
    EXPECT_TRUE(sameBytes(direction, tiny));
    for (TQ3Boolean casts : {kQ3True, kQ3False}) {
        expectAccepted(light, [&] { return Q3DirectionalLight_SetCastShadowsState(light, casts); }, "SetCastShadows");
        TQ3Boolean gotCasts = kQ3False;
        ASSERT_EQ(Q3DirectionalLight_GetCastShadowsState(light, &gotCasts), kQ3Success);
        EXPECT_EQ(gotCasts, casts);
    }
    for (int raw : {2, -1, INT_MIN}) {
        ASSERT_EQ(Q3DirectionalLight_SetCastShadowsState(light, static_cast<TQ3Boolean>(raw)), kQ3Success);
        TQ3Boolean gotCasts = kQ3False;
        ASSERT_EQ(Q3DirectionalLight_GetCastShadowsState(light, &gotCasts), kQ3Success);
        EXPECT_EQ(gotCasts, kQ3True) << raw;
        storeInt(data.castsShadows, raw);
        storeInt(data.lightData.isOn, raw);
        ASSERT_EQ(Q3DirectionalLight_SetData(light, &data), kQ3Success);
        ASSERT_EQ(Q3DirectionalLight_GetData(light, &got), kQ3Success);
        EXPECT_EQ(got.castsShadows, kQ3True);
        EXPECT_EQ(got.lightData.isOn, kQ3True);
    }
}

TEST_F(LightApiTest, DirectionalLightRejectsBrokenRulesOnEveryPath)
{
    const LightKind& kind = lightKinds()[1];
    TQ3LightObject light = own(kind.create());
    for (const TQ3Vector3D& bad : badDirections()) {
        TQ3DirectionalLightData data = goodDirectional();
        data.direction = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3DirectionalLight_New(&data), nullptr), kQ3ErrorInvalidParameter);
        expectRejected(kind, light, [&] { return Q3DirectionalLight_SetData(light, &data); }, "SetData");
        expectRejected(kind, light, [&] { return Q3DirectionalLight_SetDirection(light, &bad); }, "SetDirection");
    }
    for (const TQ3LightData& bad : badLightData()) {
        TQ3DirectionalLightData data = goodDirectional();
        data.lightData = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3DirectionalLight_New(&data), nullptr), kQ3ErrorInvalidParameter);
        expectRejected(kind, light, [&] { return Q3DirectionalLight_SetData(light, &data); }, "SetData");
    }
}

TEST_F(LightApiTest, DirectionalLightCallsRejectBadHandlesAndPointers)
{
    TQ3DirectionalLightData data = goodDirectional();
    TQ3Boolean casts = kQ3True;
    TQ3Vector3D direction{1, 2, 3};
    const std::vector<std::pair<const char*, std::function<TQ3Status(TQ3Object)>>> calls = {
        {"GetCastShadowsState", [&](TQ3Object l) { return Q3DirectionalLight_GetCastShadowsState(l, &casts); }},
        {"GetDirection", [&](TQ3Object l) { return Q3DirectionalLight_GetDirection(l, &direction); }},
        {"SetCastShadowsState", [&](TQ3Object l) { return Q3DirectionalLight_SetCastShadowsState(l, kQ3False); }},
        {"SetDirection", [&](TQ3Object l) { return Q3DirectionalLight_SetDirection(l, &direction); }},
        {"GetData", [&](TQ3Object l) { return Q3DirectionalLight_GetData(l, &data); }},
        {"SetData", [&](TQ3Object l) { return Q3DirectionalLight_SetData(l, &data); }},
    };
    for (const auto& [name, call] : calls)
        expectBadHandlesRejected(call, name, kQ3LightTypeDirectional);
    EXPECT_EQ(casts, kQ3True);
    EXPECT_EQ(direction.z, 3.0f);
    EXPECT_TRUE(sameBytes(data, goodDirectional()));
    TQ3LightObject light = own(Q3DirectionalLight_New(&data));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DirectionalLight_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3DirectionalLight_GetCastShadowsState(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3DirectionalLight_GetDirection(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3DirectionalLight_SetDirection(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3DirectionalLight_GetData(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3DirectionalLight_SetData(light, nullptr), kQ3ErrorNULLParameter);
}

// ---- Point ----------------------------------------------------------------------

TEST_F(LightApiTest, PointLightStoresItsDataAsGiven)
{
    const TQ3PointLightData data = goodPoint();
    TQ3LightObject light = own(Q3PointLight_New(&data));
    TQ3PointLightData got{};
    ASSERT_EQ(Q3PointLight_GetData(light, &got), kQ3Success);
    EXPECT_TRUE(sameBytes(got, data));
    for (TQ3AttenuationType attenuation : {kQ3AttenuationTypeNone, kQ3AttenuationTypeInverseDistance,
                                           kQ3AttenuationTypeInverseDistanceSquared}) {
        expectAccepted(light, [&] { return Q3PointLight_SetAttenuation(light, attenuation); }, "SetAttenuation");
        TQ3AttenuationType gotAttenuation = kQ3AttenuationTypeNone;
        ASSERT_EQ(Q3PointLight_GetAttenuation(light, &gotAttenuation), kQ3Success);
        EXPECT_EQ(gotAttenuation, attenuation);
        TQ3PointLightData withIt = data;
        withIt.attenuation = attenuation;
        TQ3LightObject other = own(Q3PointLight_New(&withIt));
        ASSERT_NE(other, nullptr);
    }
    const TQ3Point3D location{-1e30f, 0.0f, 1e-30f};
    expectAccepted(light, [&] { return Q3PointLight_SetLocation(light, &location); }, "SetLocation");
    TQ3Point3D gotLocation{};
    ASSERT_EQ(Q3PointLight_GetLocation(light, &gotLocation), kQ3Success);
    EXPECT_TRUE(sameBytes(gotLocation, location));
    for (int casts : {0, 1, 7}) {
        expectAccepted(light, [&] { return Q3PointLight_SetCastShadowsState(light, static_cast<TQ3Boolean>(casts)); },
                       "SetCastShadows");
        TQ3Boolean gotCasts = kQ3False;
        ASSERT_EQ(Q3PointLight_GetCastShadowsState(light, &gotCasts), kQ3Success);
        EXPECT_EQ(gotCasts, casts == 0 ? kQ3False : kQ3True);
    }
}

TEST_F(LightApiTest, PointLightRejectsBrokenRulesOnEveryPath)
{
    const LightKind& kind = lightKinds()[2];
    TQ3LightObject light = own(kind.create());
    std::vector<int> badAttenuations = {kQ3AttenuationTypeInverseDistanceSquared + 1};
    badAttenuations.insert(badAttenuations.end(), std::begin(kOutsideEveryEnum), std::end(kOutsideEveryEnum));
    for (int bad : badAttenuations) {
        TQ3PointLightData data = goodPoint();
        storeInt(data.attenuation, bad);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PointLight_New(&data), nullptr), kQ3ErrorInvalidParameter);
        expectRejected(kind, light, [&] { return Q3PointLight_SetData(light, &data); }, "SetData");
        expectRejected(kind, light,
                       [&] { return Q3PointLight_SetAttenuation(light, static_cast<TQ3AttenuationType>(bad)); },
                       "SetAttenuation " + std::to_string(bad));
    }
    for (const TQ3Point3D& bad : badLocations()) {
        TQ3PointLightData data = goodPoint();
        data.location = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PointLight_New(&data), nullptr), kQ3ErrorInvalidParameter);
        expectRejected(kind, light, [&] { return Q3PointLight_SetData(light, &data); }, "SetData");
        expectRejected(kind, light, [&] { return Q3PointLight_SetLocation(light, &bad); }, "SetLocation");
    }
    for (const TQ3LightData& bad : badLightData()) {
        TQ3PointLightData data = goodPoint();
        data.lightData = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PointLight_New(&data), nullptr), kQ3ErrorInvalidParameter);
        expectRejected(kind, light, [&] { return Q3PointLight_SetData(light, &data); }, "SetData");
    }
}

TEST_F(LightApiTest, PointLightCallsRejectBadHandlesAndPointers)
{
    TQ3PointLightData data = goodPoint();
    TQ3Boolean casts = kQ3False;
    TQ3AttenuationType attenuation = kQ3AttenuationTypeInverseDistanceSquared;
    TQ3Point3D location{4, 5, 6};
    const std::vector<std::pair<const char*, std::function<TQ3Status(TQ3Object)>>> calls = {
        {"GetCastShadowsState", [&](TQ3Object l) { return Q3PointLight_GetCastShadowsState(l, &casts); }},
        {"GetAttenuation", [&](TQ3Object l) { return Q3PointLight_GetAttenuation(l, &attenuation); }},
        {"GetLocation", [&](TQ3Object l) { return Q3PointLight_GetLocation(l, &location); }},
        {"GetData", [&](TQ3Object l) { return Q3PointLight_GetData(l, &data); }},
        {"SetCastShadowsState", [&](TQ3Object l) { return Q3PointLight_SetCastShadowsState(l, kQ3True); }},
        {"SetAttenuation",
         [&](TQ3Object l) { return Q3PointLight_SetAttenuation(l, kQ3AttenuationTypeNone); }},
        {"SetLocation", [&](TQ3Object l) { return Q3PointLight_SetLocation(l, &location); }},
        {"SetData", [&](TQ3Object l) { return Q3PointLight_SetData(l, &data); }},
    };
    for (const auto& [name, call] : calls)
        expectBadHandlesRejected(call, name, kQ3LightTypePoint);
    EXPECT_EQ(casts, kQ3False);
    EXPECT_EQ(attenuation, kQ3AttenuationTypeInverseDistanceSquared);
    EXPECT_EQ(location.x, 4.0f);
    EXPECT_TRUE(sameBytes(data, goodPoint()));
    // The handle comes before the value's rule.
    EXPECT_Q3_ERROR(Q3PointLight_SetAttenuation(nullptr, static_cast<TQ3AttenuationType>(9)), kQ3ErrorNULLParameter);
    TQ3LightObject light = own(Q3PointLight_New(&data));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PointLight_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3PointLight_GetCastShadowsState(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3PointLight_GetAttenuation(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3PointLight_GetLocation(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3PointLight_SetLocation(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3PointLight_GetData(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3PointLight_SetData(light, nullptr), kQ3ErrorNULLParameter);
}

// ---- Spot -------------------------------------------------------------------------

TEST_F(LightApiTest, SpotLightStoresItsDataAsGiven)
{
    const TQ3SpotLightData data = goodSpot();
    TQ3LightObject light = own(Q3SpotLight_New(&data));
    TQ3SpotLightData got{};
    ASSERT_EQ(Q3SpotLight_GetData(light, &got), kQ3Success);
    EXPECT_TRUE(sameBytes(got, data));
    for (TQ3FallOffType fallOff :
         {kQ3FallOffTypeNone, kQ3FallOffTypeLinear, kQ3FallOffTypeExponential, kQ3FallOffTypeCosine}) {
        expectAccepted(light, [&] { return Q3SpotLight_SetFallOff(light, fallOff); }, "SetFallOff");
        TQ3FallOffType gotFallOff = kQ3FallOffTypeNone;
        ASSERT_EQ(Q3SpotLight_GetFallOff(light, &gotFallOff), kQ3Success);
        EXPECT_EQ(gotFallOff, fallOff);
    }
    for (TQ3AttenuationType attenuation : {kQ3AttenuationTypeNone, kQ3AttenuationTypeInverseDistance,
                                           kQ3AttenuationTypeInverseDistanceSquared}) {
        expectAccepted(light, [&] { return Q3SpotLight_SetAttenuation(light, attenuation); }, "SetAttenuation");
        TQ3AttenuationType gotAttenuation = kQ3AttenuationTypeNone;
        ASSERT_EQ(Q3SpotLight_GetAttenuation(light, &gotAttenuation), kQ3Success);
        EXPECT_EQ(gotAttenuation, attenuation);
    }
    const TQ3Point3D location{7, 8, 9};
    expectAccepted(light, [&] { return Q3SpotLight_SetLocation(light, &location); }, "SetLocation");
    TQ3Point3D gotLocation{};
    ASSERT_EQ(Q3SpotLight_GetLocation(light, &gotLocation), kQ3Success);
    EXPECT_TRUE(sameBytes(gotLocation, location));
    const TQ3Vector3D direction{3, 0, 4};
    expectAccepted(light, [&] { return Q3SpotLight_SetDirection(light, &direction); }, "SetDirection");
    TQ3Vector3D gotDirection{};
    ASSERT_EQ(Q3SpotLight_GetDirection(light, &gotDirection), kQ3Success);
    EXPECT_TRUE(sameBytes(gotDirection, direction)); // not normalized
    expectAccepted(light, [&] { return Q3SpotLight_SetCastShadowsState(light, kQ3True); }, "SetCastShadows");
    TQ3Boolean casts = kQ3False;
    ASSERT_EQ(Q3SpotLight_GetCastShadowsState(light, &casts), kQ3Success);
    EXPECT_EQ(casts, kQ3True);
}

TEST_F(LightApiTest, SpotLightAnglesAcceptTheWholeRangeInclusive)
{
    TQ3LightObject light = own(lightKinds()[3].create());
    // Widen: outer first. Up to the float pi/2 exactly.
    expectAccepted(light, [&] { return Q3SpotLight_SetOuterAngle(light, kQ3PiOver2); }, "outer pi/2");
    expectAccepted(light, [&] { return Q3SpotLight_SetHotAngle(light, kQ3PiOver2); }, "hot pi/2");
    float hot = 0.0f, outer = 0.0f;
    ASSERT_EQ(Q3SpotLight_GetHotAngle(light, &hot), kQ3Success);
    ASSERT_EQ(Q3SpotLight_GetOuterAngle(light, &outer), kQ3Success);
    EXPECT_EQ(hot, kQ3PiOver2);
    EXPECT_EQ(outer, kQ3PiOver2);
    // Narrow: hot first. Down to zero, a cone of nothing.
    expectAccepted(light, [&] { return Q3SpotLight_SetHotAngle(light, 0.0f); }, "hot 0");
    expectAccepted(light, [&] { return Q3SpotLight_SetOuterAngle(light, 0.0f); }, "outer 0");
    ASSERT_EQ(Q3SpotLight_GetOuterAngle(light, &outer), kQ3Success);
    EXPECT_EQ(outer, 0.0f);
    TQ3SpotLightData data = goodSpot();
    data.hotAngle = data.outerAngle = 0.5f; // equal angles: a hard-edged cone
    TQ3LightObject hard = own(Q3SpotLight_New(&data));
    EXPECT_NE(hard, nullptr);
}

TEST_F(LightApiTest, SpotLightAngleSettersKeepOuterAtLeastHot)
{
    const LightKind& kind = lightKinds()[3];
    TQ3LightObject light = own(kind.create()); // hot 0.25, outer 0.5
    expectRejected(kind, light, [&] { return Q3SpotLight_SetHotAngle(light, 0.75f); }, "hot above outer");
    expectRejected(kind, light, [&] { return Q3SpotLight_SetOuterAngle(light, 0.125f); }, "outer below hot");
    TQ3SpotLightData data = goodSpot();
    data.hotAngle = 0.5f;
    data.outerAngle = std::nextafter(0.5f, 0.0f);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3SpotLight_New(&data), nullptr), kQ3ErrorInvalidParameter);
    expectRejected(kind, light, [&] { return Q3SpotLight_SetData(light, &data); }, "outer just below hot");
}

TEST_F(LightApiTest, SpotLightRejectsBrokenRulesOnEveryPath)
{
    const LightKind& kind = lightKinds()[3];
    TQ3LightObject light = own(kind.create());
    auto rejectData = [&](const TQ3SpotLightData& data, const std::string& what) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3SpotLight_New(&data), nullptr) << what, kQ3ErrorInvalidParameter);
        expectRejected(kind, light, [&] { return Q3SpotLight_SetData(light, &data); }, what);
    };
    for (float bad : kBadAngles) {
        TQ3SpotLightData data = goodSpot();
        data.hotAngle = bad;
        rejectData(data, "hotAngle " + std::to_string(bad));
        expectRejected(kind, light, [&] { return Q3SpotLight_SetHotAngle(light, bad); }, "SetHotAngle");
        data = goodSpot();
        data.outerAngle = bad;
        rejectData(data, "outerAngle " + std::to_string(bad));
        expectRejected(kind, light, [&] { return Q3SpotLight_SetOuterAngle(light, bad); }, "SetOuterAngle");
    }
    std::vector<int> badFallOffs = {kQ3FallOffTypeCosine + 1};
    badFallOffs.insert(badFallOffs.end(), std::begin(kOutsideEveryEnum), std::end(kOutsideEveryEnum));
    for (int bad : badFallOffs) {
        TQ3SpotLightData data = goodSpot();
        storeInt(data.fallOff, bad);
        rejectData(data, "fallOff " + std::to_string(bad));
        expectRejected(kind, light, [&] { return Q3SpotLight_SetFallOff(light, static_cast<TQ3FallOffType>(bad)); },
                       "SetFallOff");
    }
    std::vector<int> badAttenuations = {kQ3AttenuationTypeInverseDistanceSquared + 1};
    badAttenuations.insert(badAttenuations.end(), std::begin(kOutsideEveryEnum), std::end(kOutsideEveryEnum));
    for (int bad : badAttenuations) {
        TQ3SpotLightData data = goodSpot();
        storeInt(data.attenuation, bad);
        rejectData(data, "attenuation " + std::to_string(bad));
        expectRejected(kind, light,
                       [&] { return Q3SpotLight_SetAttenuation(light, static_cast<TQ3AttenuationType>(bad)); },
                       "SetAttenuation");
    }
    for (const TQ3Point3D& bad : badLocations()) {
        TQ3SpotLightData data = goodSpot();
        data.location = bad;
        rejectData(data, "location");
        expectRejected(kind, light, [&] { return Q3SpotLight_SetLocation(light, &bad); }, "SetLocation");
    }
    for (const TQ3Vector3D& bad : badDirections()) {
        TQ3SpotLightData data = goodSpot();
        data.direction = bad;
        rejectData(data, "direction");
        expectRejected(kind, light, [&] { return Q3SpotLight_SetDirection(light, &bad); }, "SetDirection");
    }
    for (const TQ3LightData& bad : badLightData()) {
        TQ3SpotLightData data = goodSpot();
        data.lightData = bad;
        rejectData(data, "lightData");
    }
}

TEST_F(LightApiTest, SpotLightCallsRejectBadHandlesAndPointers)
{
    TQ3SpotLightData data = goodSpot();
    TQ3Boolean casts = kQ3True;
    TQ3AttenuationType attenuation = kQ3AttenuationTypeInverseDistance;
    TQ3Point3D location{4, 5, 6};
    TQ3Vector3D direction{1, 0, 0};
    float angle = 0.3f;
    TQ3FallOffType fallOff = kQ3FallOffTypeExponential;
    const std::vector<std::pair<const char*, std::function<TQ3Status(TQ3Object)>>> calls = {
        {"GetCastShadowsState", [&](TQ3Object l) { return Q3SpotLight_GetCastShadowsState(l, &casts); }},
        {"GetAttenuation", [&](TQ3Object l) { return Q3SpotLight_GetAttenuation(l, &attenuation); }},
        {"GetLocation", [&](TQ3Object l) { return Q3SpotLight_GetLocation(l, &location); }},
        {"GetDirection", [&](TQ3Object l) { return Q3SpotLight_GetDirection(l, &direction); }},
        {"GetHotAngle", [&](TQ3Object l) { return Q3SpotLight_GetHotAngle(l, &angle); }},
        {"GetOuterAngle", [&](TQ3Object l) { return Q3SpotLight_GetOuterAngle(l, &angle); }},
        {"GetFallOff", [&](TQ3Object l) { return Q3SpotLight_GetFallOff(l, &fallOff); }},
        {"GetData", [&](TQ3Object l) { return Q3SpotLight_GetData(l, &data); }},
        {"SetCastShadowsState", [&](TQ3Object l) { return Q3SpotLight_SetCastShadowsState(l, kQ3False); }},
        {"SetAttenuation", [&](TQ3Object l) { return Q3SpotLight_SetAttenuation(l, kQ3AttenuationTypeNone); }},
        {"SetLocation", [&](TQ3Object l) { return Q3SpotLight_SetLocation(l, &location); }},
        {"SetDirection", [&](TQ3Object l) { return Q3SpotLight_SetDirection(l, &direction); }},
        {"SetHotAngle", [&](TQ3Object l) { return Q3SpotLight_SetHotAngle(l, 0.1f); }},
        {"SetOuterAngle", [&](TQ3Object l) { return Q3SpotLight_SetOuterAngle(l, 1.0f); }},
        {"SetFallOff", [&](TQ3Object l) { return Q3SpotLight_SetFallOff(l, kQ3FallOffTypeNone); }},
        {"SetData", [&](TQ3Object l) { return Q3SpotLight_SetData(l, &data); }},
    };
    for (const auto& [name, call] : calls)
        expectBadHandlesRejected(call, name, kQ3LightTypeSpot);
    EXPECT_EQ(casts, kQ3True);
    EXPECT_EQ(attenuation, kQ3AttenuationTypeInverseDistance);
    EXPECT_EQ(location.y, 5.0f);
    EXPECT_EQ(direction.x, 1.0f);
    EXPECT_EQ(angle, 0.3f);
    EXPECT_EQ(fallOff, kQ3FallOffTypeExponential);
    EXPECT_TRUE(sameBytes(data, goodSpot()));
    // The handle comes before the value's rule.
    EXPECT_Q3_ERROR(Q3SpotLight_SetHotAngle(nullptr, kNaN), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SpotLight_SetFallOff(nullptr, static_cast<TQ3FallOffType>(-1)), kQ3ErrorNULLParameter);
    TQ3LightObject light = own(Q3SpotLight_New(&data));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3SpotLight_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SpotLight_GetCastShadowsState(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SpotLight_GetAttenuation(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SpotLight_GetLocation(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SpotLight_GetDirection(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SpotLight_GetHotAngle(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SpotLight_GetOuterAngle(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SpotLight_GetFallOff(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SpotLight_GetData(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SpotLight_SetLocation(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SpotLight_SetDirection(light, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SpotLight_SetData(light, nullptr), kQ3ErrorNULLParameter);
}

// ---- Before Q3Initialize ------------------------------------------------------------

TEST(LightApiUninitialized, EveryFunctionFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    const TQ3LightData common = goodLightData();
    const TQ3DirectionalLightData directional = goodDirectional();
    const TQ3PointLightData point = goodPoint();
    const TQ3SpotLightData spot = goodSpot();
    for (TQ3LightObject light : {Q3AmbientLight_New(&common), Q3DirectionalLight_New(&directional),
                                 Q3PointLight_New(&point), Q3SpotLight_New(&spot)}) {
        EXPECT_EQ(light, nullptr);
        EXPECT_TRUE(failed());
    }
    EXPECT_EQ(Q3Light_GetType(nullptr), kQ3ObjectTypeInvalid);
    EXPECT_TRUE(failed());
    TQ3Boolean b = kQ3True;
    float f = 0.0f;
    TQ3ColorRGB color{};
    TQ3LightData lightOut{};
    TQ3DirectionalLightData directionalOut{};
    TQ3PointLightData pointOut{};
    TQ3SpotLightData spotOut{};
    TQ3Vector3D vector{};
    TQ3Point3D location{};
    TQ3AttenuationType attenuation{};
    TQ3FallOffType fallOff{};
    const std::vector<std::function<TQ3Status()>> calls = {
        [&] { return Q3Light_GetState(nullptr, &b); },
        [&] { return Q3Light_GetBrightness(nullptr, &f); },
        [&] { return Q3Light_GetColor(nullptr, &color); },
        [&] { return Q3Light_SetState(nullptr, kQ3True); },
        [&] { return Q3Light_SetBrightness(nullptr, 1.0f); },
        [&] { return Q3Light_SetColor(nullptr, &color); },
        [&] { return Q3Light_GetData(nullptr, &lightOut); },
        [&] { return Q3Light_SetData(nullptr, &common); },
        [&] { return Q3AmbientLight_GetData(nullptr, &lightOut); },
        [&] { return Q3AmbientLight_SetData(nullptr, &common); },
        [&] { return Q3DirectionalLight_GetCastShadowsState(nullptr, &b); },
        [&] { return Q3DirectionalLight_GetDirection(nullptr, &vector); },
        [&] { return Q3DirectionalLight_SetCastShadowsState(nullptr, kQ3True); },
        [&] { return Q3DirectionalLight_SetDirection(nullptr, &vector); },
        [&] { return Q3DirectionalLight_GetData(nullptr, &directionalOut); },
        [&] { return Q3DirectionalLight_SetData(nullptr, &directional); },
        [&] { return Q3PointLight_GetCastShadowsState(nullptr, &b); },
        [&] { return Q3PointLight_GetAttenuation(nullptr, &attenuation); },
        [&] { return Q3PointLight_GetLocation(nullptr, &location); },
        [&] { return Q3PointLight_GetData(nullptr, &pointOut); },
        [&] { return Q3PointLight_SetCastShadowsState(nullptr, kQ3True); },
        [&] { return Q3PointLight_SetAttenuation(nullptr, kQ3AttenuationTypeNone); },
        [&] { return Q3PointLight_SetLocation(nullptr, &location); },
        [&] { return Q3PointLight_SetData(nullptr, &point); },
        [&] { return Q3SpotLight_GetCastShadowsState(nullptr, &b); },
        [&] { return Q3SpotLight_GetAttenuation(nullptr, &attenuation); },
        [&] { return Q3SpotLight_GetLocation(nullptr, &location); },
        [&] { return Q3SpotLight_GetDirection(nullptr, &vector); },
        [&] { return Q3SpotLight_GetHotAngle(nullptr, &f); },
        [&] { return Q3SpotLight_GetOuterAngle(nullptr, &f); },
        [&] { return Q3SpotLight_GetFallOff(nullptr, &fallOff); },
        [&] { return Q3SpotLight_GetData(nullptr, &spotOut); },
        [&] { return Q3SpotLight_SetCastShadowsState(nullptr, kQ3True); },
        [&] { return Q3SpotLight_SetAttenuation(nullptr, kQ3AttenuationTypeNone); },
        [&] { return Q3SpotLight_SetLocation(nullptr, &location); },
        [&] { return Q3SpotLight_SetDirection(nullptr, &vector); },
        [&] { return Q3SpotLight_SetHotAngle(nullptr, 0.1f); },
        [&] { return Q3SpotLight_SetOuterAngle(nullptr, 0.2f); },
        [&] { return Q3SpotLight_SetFallOff(nullptr, kQ3FallOffTypeNone); },
        [&] { return Q3SpotLight_SetData(nullptr, &spot); },
    };
    for (std::size_t i = 0; i < calls.size(); ++i) {
        EXPECT_EQ(calls[i](), kQ3Failure) << "call " << i;
        EXPECT_TRUE(failed()) << "call " << i;
    }
}

} // namespace
