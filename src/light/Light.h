// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DLight.h"
#include "core/Object.h"

namespace q3 {

extern const ClassInfo kLightClass;

/// A light as the renderer uses it: plain values, in world coordinates.
struct LightSource {
    TQ3ObjectType type = kQ3LightTypeAmbient; ///< kQ3LightType...
    bool on = true;
    float brightness = 1.0f;
    TQ3ColorRGB color{1.0f, 1.0f, 1.0f};
    /// Directional and spot: the direction the light travels (any length).
    TQ3Vector3D direction{0.0f, 0.0f, -1.0f};
    /// Point and spot.
    TQ3Point3D location{0.0f, 0.0f, 0.0f};
    TQ3AttenuationType attenuation = kQ3AttenuationTypeNone;
    /// Spot: half-angles in radians, and how the light falls off between them.
    float hotAngle = 0.0f;
    float outerAngle = 0.0f;
    TQ3FallOffType fallOff = kQ3FallOffTypeNone;
};

/// Every QuickDraw 3D light (QD3DLight.h). Lights are not submitted: a view
/// is lit by the lights of its light group. Invariant: source() describes
/// the light's current data.
class Light : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapeTypeLight;

    /// The light's values for rendering.
    virtual LightSource source() const = 0;

protected:
    Light() = default;
};

} // namespace q3
