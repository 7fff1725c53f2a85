// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Rules and conversions more than one light class uses.

#include "core/ParameterChecks.h"
#include "light/Light.h"

namespace q3 {

/// A direction: finite, and not the zero vector (it has no direction).
TQ3Vector3D checkDirection(const TQ3Vector3D& direction);
/// kQ3AttenuationTypeNone, InverseDistance or InverseDistanceSquared.
TQ3AttenuationType checkAttenuation(const TQ3AttenuationType& attenuation);
/// The source's type and the values of the common part.
LightSource commonSource(TQ3ObjectType type, const TQ3LightData& data);

/// The checked fields every light with a direction or a position starts
/// with: lightData and castsShadows. The rest is left for the caller.
template <class Data>
Data checkedShadowingLight(const Data& data)
{
    Data result;
    result.lightData = checkLightData(data.lightData);
    result.castsShadows = booleanOf(data.castsShadows);
    return result;
}

/// The same and the fields of a light at a position (a point or spot
/// light): attenuation, then location.
template <class Data>
Data checkedPositionalLight(const Data& data)
{
    Data result = checkedShadowingLight(data);
    result.attenuation = checkAttenuation(data.attenuation);
    checkFinite(data.location, "location");
    result.location = data.location;
    return result;
}

} // namespace q3
