// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "light/PointLight.h"

#include "light/LightChecks.h"

namespace q3 {

const ClassInfo kPointLightClass{kQ3LightTypePoint, &kLightClass, "point light"};

TQ3PointLightData PointLight::check(const TQ3PointLightData& data)
{
    return checkedPositionalLight(data);
}

LightSource PointLight::source() const
{
    LightSource source = commonSource(kQ3LightTypePoint, data().lightData);
    source.location = data().location;
    source.attenuation = data().attenuation;
    return source;
}

} // namespace q3
