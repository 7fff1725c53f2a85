// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "light/Light.h"

namespace q3 {

extern const ClassInfo kDirectionalLightClass;

/// Parallel light travelling in one direction, as from a distant source.
class DirectionalLight final : public DataLight<DirectionalLight, TQ3DirectionalLightData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3LightTypeDirectional;

    /// The TQ3DirectionalLightData rules of QD3DLight.h.
    static TQ3DirectionalLightData check(const TQ3DirectionalLightData& data);
    using DataLight::DataLight;

    const ClassInfo& classInfo() const override { return kDirectionalLightClass; }
    LightSource source() const override;
};

} // namespace q3
