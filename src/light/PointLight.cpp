// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "light/PointLight.h"

#include "light/LightChecks.h"

namespace q3 {

const ClassInfo kPointLightClass{kQ3LightTypePoint, &kLightClass, "point light"};

TQ3PointLightData PointLight::check(const TQ3PointLightData& data)
{
    TQ3PointLightData result;
    result.lightData = checkLightData(data.lightData);
    result.castsShadows = booleanOf(data.castsShadows);
    result.attenuation = checkAttenuation(data.attenuation);
    checkFinite(data.location, "location");
    result.location = data.location;
    return result;
}

LightSource PointLight::source() const
{
    LightSource source = commonSource(kQ3LightTypePoint, data().lightData);
    source.location = data().location;
    source.attenuation = data().attenuation;
    return source;
}

} // namespace q3
