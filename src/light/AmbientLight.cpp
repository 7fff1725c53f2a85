// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "light/AmbientLight.h"

#include "light/LightChecks.h"

namespace q3 {

const ClassInfo kAmbientLightClass{kQ3LightTypeAmbient, &kLightClass, "ambient light"};

LightSource AmbientLight::source() const
{
    return commonSource(kQ3LightTypeAmbient, data());
}

} // namespace q3
