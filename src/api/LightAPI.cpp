// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DLight.h"
#include "api/Entry.h"
#include "core/ParameterChecks.h"
#include "light/Light.h"

using namespace q3;
using namespace q3::api;

namespace {

// Get and Set of one field of the part every light has; a Set goes through
// the light's own check (Light::setLightData).
template <class Value>
TQ3Status getCommon(const char* function, TQ3LightObject light, Value* value, const char* valueName,
                    Value TQ3LightData::*field)
{
    return guardStatus(function, [&] {
        readInto<Light>(light, "light", value, valueName,
                        [&](const Light& source) { return source.lightData().*field; });
    });
}

template <class Value>
void setCommon(Light& target, const Value& value, Value TQ3LightData::*field)
{
    TQ3LightData next = target.lightData();
    storeRaw(next.*field, value);
    target.setLightData(next);
}

} // namespace

extern "C" {

TQ3ObjectType Q3Light_GetType(TQ3LightObject light)
{
    return api::getLeafType<Light>(__func__, light, "light");
}

TQ3Status Q3Light_GetState(TQ3LightObject light, TQ3Boolean* isOn)
{
    return getCommon(__func__, light, isOn, "isOn", &TQ3LightData::isOn);
}

TQ3Status Q3Light_GetBrightness(TQ3LightObject light, float* brightness)
{
    return getCommon(__func__, light, brightness, "brightness", &TQ3LightData::brightness);
}

TQ3Status Q3Light_GetColor(TQ3LightObject light, TQ3ColorRGB* color)
{
    return getCommon(__func__, light, color, "color", &TQ3LightData::color);
}

TQ3Status Q3Light_SetState(TQ3LightObject light, TQ3Boolean isOn)
{
    return guardStatus(__func__, [&] { setCommon(lookup<Light>(light, "light"), isOn, &TQ3LightData::isOn); });
}

TQ3Status Q3Light_SetBrightness(TQ3LightObject light, float brightness)
{
    return guardStatus(__func__,
                       [&] { setCommon(lookup<Light>(light, "light"), brightness, &TQ3LightData::brightness); });
}

TQ3Status Q3Light_SetColor(TQ3LightObject light, const TQ3ColorRGB* color)
{
    return guardStatus(__func__, [&] {
        Light& target = lookup<Light>(light, "light");
        requireNonNull(color, "color");
        setCommon(target, *color, &TQ3LightData::color);
    });
}

TQ3Status Q3Light_GetData(TQ3LightObject light, TQ3LightData* lightData)
{
    return getValue<Light>(__func__, light, "light", lightData, "lightData", &Light::lightData);
}

TQ3Status Q3Light_SetData(TQ3LightObject light, const TQ3LightData* lightData)
{
    return setValue<Light>(__func__, light, "light", lightData, "lightData", &Light::setLightData);
}

} // extern "C"
