// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DLight.h"
#include "api/LightEntry.h"
#include "light/AmbientLight.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3LightObject Q3AmbientLight_New(const TQ3LightData* lightData)
{
    return newLight<AmbientLight>(__func__, lightData, "lightData");
}

TQ3Status Q3AmbientLight_GetData(TQ3LightObject light, TQ3LightData* lightData)
{
    return getLightData<AmbientLight>(__func__, light, lightData, "lightData");
}

TQ3Status Q3AmbientLight_SetData(TQ3LightObject light, const TQ3LightData* lightData)
{
    return setLightData<AmbientLight>(__func__, light, lightData, "lightData");
}

} // extern "C"
