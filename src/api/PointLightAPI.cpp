// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DLight.h"
#include "api/LightEntry.h"
#include "light/PointLight.h"

using namespace q3;
using namespace q3::api;

using Data = TQ3PointLightData;

extern "C" {

TQ3LightObject Q3PointLight_New(const TQ3PointLightData* pointLightData)
{
    return newLight<PointLight>(__func__, pointLightData, "pointLightData");
}

TQ3Status Q3PointLight_GetCastShadowsState(TQ3LightObject light, TQ3Boolean* castsShadows)
{
    return getLightField<PointLight>(__func__, light, castsShadows, "castsShadows", &Data::castsShadows);
}

TQ3Status Q3PointLight_GetAttenuation(TQ3LightObject light, TQ3AttenuationType* attenuation)
{
    return getLightField<PointLight>(__func__, light, attenuation, "attenuation", &Data::attenuation);
}

TQ3Status Q3PointLight_GetLocation(TQ3LightObject light, TQ3Point3D* location)
{
    return getLightField<PointLight>(__func__, light, location, "location", &Data::location);
}

TQ3Status Q3PointLight_GetData(TQ3LightObject light, TQ3PointLightData* pointLightData)
{
    return getLightData<PointLight>(__func__, light, pointLightData, "pointLightData");
}

TQ3Status Q3PointLight_SetCastShadowsState(TQ3LightObject light, TQ3Boolean castsShadows)
{
    return setLightField<PointLight>(__func__, light, castsShadows, &Data::castsShadows);
}

TQ3Status Q3PointLight_SetAttenuation(TQ3LightObject light, TQ3AttenuationType attenuation)
{
    return setLightField<PointLight>(__func__, light, attenuation, &Data::attenuation);
}

TQ3Status Q3PointLight_SetLocation(TQ3LightObject light, const TQ3Point3D* location)
{
    return setLightField<PointLight>(__func__, light, location, "location", &Data::location);
}

TQ3Status Q3PointLight_SetData(TQ3LightObject light, const TQ3PointLightData* pointLightData)
{
    return setLightData<PointLight>(__func__, light, pointLightData, "pointLightData");
}

} // extern "C"
