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

/// The TQ3LightData rules of QD3DLight.h (a finite brightness and colour;
/// isOn read as a C Boolean): the data to store, or kQ3ErrorInvalidParameter.
TQ3LightData checkLightData(const TQ3LightData& data);

/// Every QuickDraw 3D light (QD3DLight.h). Lights are not submitted: a view
/// is lit by the lights of its light group. Invariant: source() describes
/// the light's current data.
class Light : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapeTypeLight;

    /// The light's values for rendering.
    virtual LightSource source() const = 0;

    /// The part every light has (Q3Light_GetData).
    virtual TQ3LightData lightData() const = 0;
    /// Replaces that part after checking it; on failure nothing changes.
    virtual void setLightData(const TQ3LightData& data) = 0;

protected:
    Light() = default;
};

/// The shape every light class shares: its state is one QD3DLight.h data
/// structure, kept as the caller gave it after Derived::check, which applies
/// the structure's rules in the order QD3DLight.h lists them and returns the
/// data to store (Booleans made kQ3False or kQ3True), or throws
/// kQ3ErrorInvalidParameter. New, SetData and every single-field setter go
/// through check, so they accept and reject the same values. Invariant: the
/// stored data passed check.
template <class Derived, class Data>
class DataLight : public Light {
public:
    using DataType = Data;

    explicit DataLight(const Data& data) : m_data(Derived::check(data)) {}

    Object* duplicate() const override { return makeShared<Derived>(m_data).detach(); }
    TQ3LightData lightData() const override { return commonPart(m_data); }
    void setLightData(const TQ3LightData& data) override
    {
        edit([&](Data& next) { commonPart(next) = data; });
    }

    const Data& data() const { return m_data; }
    void setData(const Data& data)
    {
        m_data = Derived::check(data);
        markEdited();
    }
    /// A single-field setter: `change` edits a copy of the data, which then
    /// goes through setData.
    template <class Change>
    void edit(Change&& change)
    {
        Data next = m_data;
        change(next);
        setData(next);
    }

private:
    static TQ3LightData& commonPart(TQ3LightData& data) { return data; }
    static const TQ3LightData& commonPart(const TQ3LightData& data) { return data; }
    template <class Full>
    static TQ3LightData& commonPart(Full& data) { return data.lightData; }
    template <class Full>
    static const TQ3LightData& commonPart(const Full& data) { return data.lightData; }

    Data m_data;
};

} // namespace q3
