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

} // namespace q3
