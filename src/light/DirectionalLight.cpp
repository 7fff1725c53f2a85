// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "light/DirectionalLight.h"

#include "light/LightChecks.h"

namespace q3 {

const ClassInfo kDirectionalLightClass{kQ3LightTypeDirectional, &kLightClass, "directional light"};

TQ3DirectionalLightData DirectionalLight::check(const TQ3DirectionalLightData& data)
{
    TQ3DirectionalLightData result = checkedShadowingLight(data);
    result.direction = checkDirection(data.direction);
    return result;
}

LightSource DirectionalLight::source() const
{
    LightSource source = commonSource(kQ3LightTypeDirectional, data().lightData);
    source.direction = data().direction;
    return source;
}

} // namespace q3
