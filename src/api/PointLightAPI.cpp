// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DLight.h"
#include "api/LightEntry.h"
#include "light/PointLight.h"

extern "C" {

Q3_LIGHT_DATA_ENTRY_POINTS(Point, TQ3PointLightData, pointLightData)
Q3_LOCATED_LIGHT_ENTRY_POINTS(Point)

} // extern "C"
