// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DLight.h"
#include "api/LightEntry.h"
#include "light/SpotLight.h"

extern "C" {

Q3_LIGHT_DATA_ENTRY_POINTS(Spot, TQ3SpotLightData, spotLightData)
Q3_LIGHT_POINTER_FIELD_ENTRY_POINTS(Spot, Direction, TQ3Vector3D, direction)
Q3_LIGHT_VALUE_FIELD_ENTRY_POINTS(Spot, HotAngle, float, hotAngle)
Q3_LIGHT_VALUE_FIELD_ENTRY_POINTS(Spot, OuterAngle, float, outerAngle)
Q3_LIGHT_VALUE_FIELD_ENTRY_POINTS(Spot, FallOff, TQ3FallOffType, fallOff)
Q3_LOCATED_LIGHT_ENTRY_POINTS(Spot)

} // extern "C"
