// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DLight.h"
#include "api/LightEntry.h"
#include "light/DirectionalLight.h"

using namespace q3;
using namespace q3::api;

using Data = TQ3DirectionalLightData;

extern "C" {

TQ3LightObject Q3DirectionalLight_New(const TQ3DirectionalLightData* directionalLightData)
{
    return newLight<DirectionalLight>(__func__, directionalLightData, "directionalLightData");
}

TQ3Status Q3DirectionalLight_GetCastShadowsState(TQ3LightObject light, TQ3Boolean* castsShadows)
{
    return getLightField<DirectionalLight>(__func__, light, castsShadows, "castsShadows", &Data::castsShadows);
}

TQ3Status Q3DirectionalLight_GetDirection(TQ3LightObject light, TQ3Vector3D* direction)
{
    return getLightField<DirectionalLight>(__func__, light, direction, "direction", &Data::direction);
}

TQ3Status Q3DirectionalLight_SetCastShadowsState(TQ3LightObject light, TQ3Boolean castsShadows)
{
    return setLightField<DirectionalLight>(__func__, light, castsShadows, &Data::castsShadows);
}

TQ3Status Q3DirectionalLight_SetDirection(TQ3LightObject light, const TQ3Vector3D* direction)
{
    return setLightField<DirectionalLight>(__func__, light, direction, "direction", &Data::direction);
}

TQ3Status Q3DirectionalLight_GetData(TQ3LightObject light, TQ3DirectionalLightData* directionalLightData)
{
    return getLightData<DirectionalLight>(__func__, light, directionalLightData, "directionalLightData");
}

TQ3Status Q3DirectionalLight_SetData(TQ3LightObject light, const TQ3DirectionalLightData* directionalLightData)
{
    return setLightData<DirectionalLight>(__func__, light, directionalLightData, "directionalLightData");
}

} // extern "C"
