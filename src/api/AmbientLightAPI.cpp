// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DLight.h"
#include "api/LightEntry.h"
#include "light/AmbientLight.h"

extern "C" {

Q3_LIGHT_DATA_ENTRY_POINTS(Ambient, TQ3LightData, lightData)

} // extern "C"
