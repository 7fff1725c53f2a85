// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "light/Light.h"

namespace q3 {

extern const ClassInfo kAmbientLightClass;

/// Light that reaches every surface equally from no direction.
class AmbientLight final : public DataLight<AmbientLight, TQ3LightData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3LightTypeAmbient;

    static TQ3LightData check(const TQ3LightData& data) { return checkLightData(data); }
    using DataLight::DataLight;

    const ClassInfo& classInfo() const override { return kAmbientLightClass; }
    LightSource source() const override;
};

} // namespace q3
