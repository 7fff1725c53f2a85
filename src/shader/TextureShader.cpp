// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "shader/TextureShader.h"

#include <utility>

namespace q3 {

const ClassInfo kSurfaceShaderClass{kQ3ShaderTypeSurface, &kShaderClass, "surface shader"};
const ClassInfo kTextureShaderClass{kQ3SurfaceShaderTypeTexture, &kSurfaceShaderClass, "texture shader"};

Object* TextureShader::duplicate() const
{
    Ref<Texture> texture = Ref<Texture>::adopt(static_cast<Texture*>(m_texture->duplicate()));
    Ref<TextureShader> copy = makeShared<TextureShader>(std::move(texture));
    copy->copyUVSettings(*this);
    return copy.detach();
}

void TextureShader::apply(DrawState& state) const
{
    state.texture = m_texture;
    state.uvTransform = uvTransform();
    state.uBoundary = uBoundary();
    state.vBoundary = vBoundary();
}

void TextureShader::setTexture(Ref<Texture> texture)
{
    m_texture = std::move(texture);
    markEdited();
}

} // namespace q3
