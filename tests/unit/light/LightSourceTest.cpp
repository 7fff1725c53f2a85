// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// What each light hands the renderer (Light::source): its kind's values,
// and the defaults for the fields its kind does not have.

#include "core/Error.h"
#include "light/AmbientLight.h"
#include "light/DirectionalLight.h"
#include "light/PointLight.h"
#include "light/SpotLight.h"

#include <gtest/gtest.h>

namespace q3 {
namespace {

const TQ3LightData kCommon{kQ3True, 0.5f, {1.0f, 0.25f, 0.0f}};

void expectCommon(const LightSource& source, TQ3ObjectType type)
{
    EXPECT_EQ(source.type, type);
    EXPECT_TRUE(source.on);
    EXPECT_EQ(source.brightness, 0.5f);
    EXPECT_EQ(source.color.r, 1.0f);
    EXPECT_EQ(source.color.g, 0.25f);
    EXPECT_EQ(source.color.b, 0.0f);
}

TEST(LightSource, AmbientLightGivesItsCommonValues)
{
    const LightSource source = AmbientLight(kCommon).source();
    expectCommon(source, kQ3LightTypeAmbient);
    const LightSource defaults;
    EXPECT_EQ(source.attenuation, defaults.attenuation);
    EXPECT_EQ(source.fallOff, defaults.fallOff);
}

TEST(LightSource, AnOffLightSaysSo)
{
    TQ3LightData off = kCommon;
    off.isOn = kQ3False;
    EXPECT_FALSE(AmbientLight(off).source().on);
}

TEST(LightSource, DirectionalLightGivesItsDirectionAsStored)
{
    const TQ3DirectionalLightData data{kCommon, kQ3True, {0.0f, 0.0f, -4.0f}};
    const LightSource source = DirectionalLight(data).source();
    expectCommon(source, kQ3LightTypeDirectional);
    EXPECT_EQ(source.direction.z, -4.0f);
}

TEST(LightSource, PointLightGivesLocationAndAttenuation)
{
    const TQ3PointLightData data{kCommon, kQ3False, kQ3AttenuationTypeInverseDistanceSquared, {1, 2, 3}};
    const LightSource source = PointLight(data).source();
    expectCommon(source, kQ3LightTypePoint);
    EXPECT_EQ(source.location.y, 2.0f);
    EXPECT_EQ(source.attenuation, kQ3AttenuationTypeInverseDistanceSquared);
}

TEST(LightSource, SpotLightGivesItsCone)
{
    const TQ3SpotLightData data{kCommon, kQ3False, kQ3AttenuationTypeInverseDistance, {1, 2, 3}, {0, -1, 0},
                                0.25f,   0.75f,    kQ3FallOffTypeExponential};
    const LightSource source = SpotLight(data).source();
    expectCommon(source, kQ3LightTypeSpot);
    EXPECT_EQ(source.location.z, 3.0f);
    EXPECT_EQ(source.direction.y, -1.0f);
    EXPECT_EQ(source.attenuation, kQ3AttenuationTypeInverseDistance);
    EXPECT_EQ(source.hotAngle, 0.25f);
    EXPECT_EQ(source.outerAngle, 0.75f);
    EXPECT_EQ(source.fallOff, kQ3FallOffTypeExponential);
}

TEST(LightSource, SourceFollowsEveryEdit)
{
    SpotLight light(TQ3SpotLightData{kCommon, kQ3False, kQ3AttenuationTypeNone, {0, 0, 0}, {1, 0, 0},
                                     0.1f,    0.2f,     kQ3FallOffTypeNone});
    light.edit([](TQ3SpotLightData& d) { d.outerAngle = 0.5f; });
    light.setLightData(TQ3LightData{kQ3False, 2.0f, {0, 0, 1}});
    const LightSource source = light.source();
    EXPECT_EQ(source.outerAngle, 0.5f);
    EXPECT_FALSE(source.on);
    EXPECT_EQ(source.brightness, 2.0f);
    // A rejected edit leaves the source as it was.
    EXPECT_THROW(light.edit([](TQ3SpotLightData& d) { d.hotAngle = 0.9f; }), Error);
    EXPECT_EQ(light.source().hotAngle, 0.1f);
}

} // namespace
} // namespace q3
