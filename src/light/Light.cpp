// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "light/Light.h"

#include "core/ParameterChecks.h"

namespace q3 {

const ClassInfo kLightClass{kQ3ShapeTypeLight, &kShapeClass, "light"};

TQ3LightData checkLightData(const TQ3LightData& data)
{
    TQ3LightData result;
    result.isOn = booleanOf(data.isOn);
    checkFinite(data.brightness, "brightness");
    result.brightness = data.brightness;
    checkFinite(data.color, "color");
    result.color = data.color;
    return result;
}

} // namespace q3
