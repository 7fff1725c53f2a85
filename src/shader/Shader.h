// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DShader.h"
#include "core/Object.h"
#include "base/DrawState.h"

namespace q3 {

extern const ClassInfo kShaderClass;
extern const ClassInfo kIlluminationShaderClass;

/// Every QuickDraw 3D shader: a drawable shared object that, submitted to a
/// view, sets its part of the traversal's DrawState. Every shader also
/// stores the uv transform and boundaries QD3DShader.h gives all shaders
/// (texture shaders use them). Invariant: the uv transform is finite and
/// each boundary is kQ3ShaderUVBoundaryWrap or kQ3ShaderUVBoundaryClamp.
class Shader : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapeTypeShader;

    bool isDrawable() const override { return true; }
    void accept(ShapeVisitor& visitor) const override;

    virtual void apply(DrawState& state) const = 0;

    const TQ3Matrix3x3& uvTransform() const { return m_uvTransform; }
    TQ3ShaderUVBoundary uBoundary() const { return m_uBoundary; }
    TQ3ShaderUVBoundary vBoundary() const { return m_vBoundary; }
    /// Each setter checks its value (kQ3ErrorInvalidParameter), then stores
    /// it and marks the edit; on failure nothing changes.
    void setUVTransform(const TQ3Matrix3x3& transform);
    void setUBoundary(const TQ3ShaderUVBoundary& boundary);
    void setVBoundary(const TQ3ShaderUVBoundary& boundary);

protected:
    Shader() = default;
    /// A new T carrying this shader's uv transform and boundaries, holding
    /// one reference for the caller (duplicate() of shaders without data).
    template <class T>
    static Object* duplicateAs(const T& original)
    {
        Ref<T> copy = makeShared<T>();
        copy->copyUVSettings(original);
        return copy.detach();
    }
    /// Takes the uv transform and boundaries of another shader.
    void copyUVSettings(const Shader& original)
    {
        m_uvTransform = original.m_uvTransform;
        m_uBoundary = original.m_uBoundary;
        m_vBoundary = original.m_vBoundary;
    }

private:
    TQ3Matrix3x3 m_uvTransform{{{1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}}};
    TQ3ShaderUVBoundary m_uBoundary = kQ3ShaderUVBoundaryWrap;
    TQ3ShaderUVBoundary m_vBoundary = kQ3ShaderUVBoundaryWrap;
};

/// An illumination shader (Phong, Lambert, NULL): it chooses how lights
/// colour surfaces. Invariant: the leaf class is the illumination type.
class IlluminationShader : public Shader {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShaderTypeIllumination;

    /// Makes the shader's type the state's illumination.
    void apply(DrawState& state) const override { state.illumination = leafType(); }

protected:
    IlluminationShader() = default;
};

} // namespace q3
