// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DLight.h"
#include "api/LightEntry.h"
#include "light/SpotLight.h"

using namespace q3;
using namespace q3::api;

using Data = TQ3SpotLightData;

extern "C" {

TQ3LightObject Q3SpotLight_New(const TQ3SpotLightData* spotLightData)
{
    return newLight<SpotLight>(__func__, spotLightData, "spotLightData");
}

TQ3Status Q3SpotLight_GetCastShadowsState(TQ3LightObject light, TQ3Boolean* castsShadows)
{
    return getLightField<SpotLight>(__func__, light, castsShadows, "castsShadows", &Data::castsShadows);
}

TQ3Status Q3SpotLight_GetAttenuation(TQ3LightObject light, TQ3AttenuationType* attenuation)
{
    return getLightField<SpotLight>(__func__, light, attenuation, "attenuation", &Data::attenuation);
}

TQ3Status Q3SpotLight_GetLocation(TQ3LightObject light, TQ3Point3D* location)
{
    return getLightField<SpotLight>(__func__, light, location, "location", &Data::location);
}

TQ3Status Q3SpotLight_GetDirection(TQ3LightObject light, TQ3Vector3D* direction)
{
    return getLightField<SpotLight>(__func__, light, direction, "direction", &Data::direction);
}

TQ3Status Q3SpotLight_GetHotAngle(TQ3LightObject light, float* hotAngle)
{
    return getLightField<SpotLight>(__func__, light, hotAngle, "hotAngle", &Data::hotAngle);
}

TQ3Status Q3SpotLight_GetOuterAngle(TQ3LightObject light, float* outerAngle)
{
    return getLightField<SpotLight>(__func__, light, outerAngle, "outerAngle", &Data::outerAngle);
}

TQ3Status Q3SpotLight_GetFallOff(TQ3LightObject light, TQ3FallOffType* fallOff)
{
    return getLightField<SpotLight>(__func__, light, fallOff, "fallOff", &Data::fallOff);
}

TQ3Status Q3SpotLight_GetData(TQ3LightObject light, TQ3SpotLightData* spotLightData)
{
    return getLightData<SpotLight>(__func__, light, spotLightData, "spotLightData");
}

TQ3Status Q3SpotLight_SetCastShadowsState(TQ3LightObject light, TQ3Boolean castsShadows)
{
    return setLightField<SpotLight>(__func__, light, castsShadows, &Data::castsShadows);
}

TQ3Status Q3SpotLight_SetAttenuation(TQ3LightObject light, TQ3AttenuationType attenuation)
{
    return setLightField<SpotLight>(__func__, light, attenuation, &Data::attenuation);
}

TQ3Status Q3SpotLight_SetLocation(TQ3LightObject light, const TQ3Point3D* location)
{
    return setLightField<SpotLight>(__func__, light, location, "location", &Data::location);
}

TQ3Status Q3SpotLight_SetDirection(TQ3LightObject light, const TQ3Vector3D* direction)
{
    return setLightField<SpotLight>(__func__, light, direction, "direction", &Data::direction);
}

TQ3Status Q3SpotLight_SetHotAngle(TQ3LightObject light, float hotAngle)
{
    return setLightField<SpotLight>(__func__, light, hotAngle, &Data::hotAngle);
}

TQ3Status Q3SpotLight_SetOuterAngle(TQ3LightObject light, float outerAngle)
{
    return setLightField<SpotLight>(__func__, light, outerAngle, &Data::outerAngle);
}

TQ3Status Q3SpotLight_SetFallOff(TQ3LightObject light, TQ3FallOffType fallOff)
{
    return setLightField<SpotLight>(__func__, light, fallOff, &Data::fallOff);
}

TQ3Status Q3SpotLight_SetData(TQ3LightObject light, const TQ3SpotLightData* spotLightData)
{
    return setLightData<SpotLight>(__func__, light, spotLightData, "spotLightData");
}

} // extern "C"
