// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DLight.h"
#include "api/LightEntry.h"
#include "light/DirectionalLight.h"

extern "C" {

Q3_LIGHT_DATA_ENTRY_POINTS(Directional, TQ3DirectionalLightData, directionalLightData)
Q3_LIGHT_VALUE_FIELD_ENTRY_POINTS(Directional, CastShadowsState, TQ3Boolean, castsShadows)
Q3_LIGHT_POINTER_FIELD_ENTRY_POINTS(Directional, Direction, TQ3Vector3D, direction)

} // extern "C"
