// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "light/LightChecks.h"

namespace q3 {

TQ3Vector3D checkDirection(const TQ3Vector3D& direction)
{
    checkFinite(direction, "direction");
    if (direction.x == 0.0f && direction.y == 0.0f && direction.z == 0.0f)
        fail(kQ3ErrorInvalidParameter, "direction is the zero vector");
    return direction;
}

TQ3AttenuationType checkAttenuation(const TQ3AttenuationType& attenuation)
{
    return checkEnum(attenuation, kQ3AttenuationTypeNone, kQ3AttenuationTypeInverseDistanceSquared,
                     "attenuation", "kQ3AttenuationTypeNone, InverseDistance, InverseDistanceSquared");
}

LightSource commonSource(TQ3ObjectType type, const TQ3LightData& data)
{
    LightSource source;
    source.type = type;
    source.on = data.isOn == kQ3True;
    source.brightness = data.brightness;
    source.color = data.color;
    return source;
}

} // namespace q3
