// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "shader/Shader.h"
#include "shader/Texture.h"

namespace q3 {

extern const ClassInfo kSurfaceShaderClass;
extern const ClassInfo kTextureShaderClass;

/// A surface shader: it chooses what colours a surface before lighting.
class SurfaceShader : public Shader {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShaderTypeSurface;

protected:
    SurfaceShader() = default;
};

/// The texture shader (Q3TextureShader_): paints its texture over the
/// surfaces drawn after it. Invariant: it holds one reference to a live
/// texture.
class TextureShader final : public SurfaceShader {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SurfaceShaderTypeTexture;

    explicit TextureShader(Ref<Texture> texture) : m_texture(std::move(texture)) {}

    const ClassInfo& classInfo() const override { return kTextureShaderClass; }
    /// A new shader with a duplicate of the texture and the same uv
    /// transform and boundaries.
    Object* duplicate() const override;
    /// Makes this shader's texture, uv transform and boundaries the state's.
    void apply(DrawState& state) const override;

    const Ref<Texture>& texture() const { return m_texture; }
    void setTexture(Ref<Texture> texture);

private:
    Ref<Texture> m_texture;
};

} // namespace q3
