// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "light/Light.h"

namespace q3 {

extern const ClassInfo kPointLightClass;

/// Light radiating in every direction from one location.
class PointLight final : public DataLight<PointLight, TQ3PointLightData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3LightTypePoint;

    /// The TQ3PointLightData rules of QD3DLight.h.
    static TQ3PointLightData check(const TQ3PointLightData& data);
    using DataLight::DataLight;

    const ClassInfo& classInfo() const override { return kPointLightClass; }
    LightSource source() const override;
};

} // namespace q3
