// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "light/Light.h"

namespace q3 {

extern const ClassInfo kSpotLightClass;

/// A cone of light from one location: full intensity within the hot angle,
/// falling off to nothing at the outer angle.
class SpotLight final : public DataLight<SpotLight, TQ3SpotLightData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3LightTypeSpot;

    /// The TQ3SpotLightData rules of QD3DLight.h.
    static TQ3SpotLightData check(const TQ3SpotLightData& data);
    using DataLight::DataLight;

    const ClassInfo& classInfo() const override { return kSpotLightClass; }
    LightSource source() const override;
};

} // namespace q3
