// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "light/SpotLight.h"

#include "light/LightChecks.h"

#include "QD3DMath.h"

#include <string>

namespace q3 {

const ClassInfo kSpotLightClass{kQ3LightTypeSpot, &kLightClass, "spot light"};

namespace {

// A half-angle of the cone: 0 to pi/2 inclusive, pi/2 compared as the float
// kQ3PiOver2 so that a caller's own float pi/2 is accepted.
void checkAngle(float angle, const char* name)
{
    checkFinite(angle, name);
    if (!(angle >= 0.0f && angle <= kQ3PiOver2))
        fail(kQ3ErrorInvalidParameter, std::string(name) + " " + std::to_string(angle) +
                                           " is outside 0 to pi/2 radians");
}

} // namespace

TQ3SpotLightData SpotLight::check(const TQ3SpotLightData& data)
{
    TQ3SpotLightData result = checkedPositionalLight(data);
    result.direction = checkDirection(data.direction);
    checkAngle(data.hotAngle, "hotAngle");
    checkAngle(data.outerAngle, "outerAngle");
    if (data.outerAngle < data.hotAngle)
        fail(kQ3ErrorInvalidParameter, "outerAngle " + std::to_string(data.outerAngle) +
                                           " is less than hotAngle " + std::to_string(data.hotAngle));
    result.hotAngle = data.hotAngle;
    result.outerAngle = data.outerAngle;
    result.fallOff = checkEnum(data.fallOff, kQ3FallOffTypeNone, kQ3FallOffTypeCosine, "fallOff",
                               "kQ3FallOffTypeNone, Linear, Exponential, Cosine");
    return result;
}

LightSource SpotLight::source() const
{
    LightSource source = commonSource(kQ3LightTypeSpot, data().lightData);
    source.location = data().location;
    source.direction = data().direction;
    source.attenuation = data().attenuation;
    source.hotAngle = data().hotAngle;
    source.outerAngle = data().outerAngle;
    source.fallOff = data().fallOff;
    return source;
}

} // namespace q3
