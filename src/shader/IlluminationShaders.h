// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The three illumination shaders of QD3DShader.h. They have no data: the
// class is the illumination model (IlluminationShader::apply).

#include "shader/Shader.h"

namespace q3 {

extern const ClassInfo kPhongIlluminationClass;
extern const ClassInfo kLambertIlluminationClass;
extern const ClassInfo kNULLIlluminationClass;

/// Ambient, diffuse and specular reflection.
class PhongIllumination final : public IlluminationShader {
public:
    static constexpr TQ3ObjectType kClassType = kQ3IlluminationTypePhong;
    const ClassInfo& classInfo() const override { return kPhongIlluminationClass; }
    Object* duplicate() const override { return duplicateAs(*this); }
};

/// Ambient and diffuse reflection.
class LambertIllumination final : public IlluminationShader {
public:
    static constexpr TQ3ObjectType kClassType = kQ3IlluminationTypeLambert;
    const ClassInfo& classInfo() const override { return kLambertIlluminationClass; }
    Object* duplicate() const override { return duplicateAs(*this); }
};

/// No lighting: surfaces in their own diffuse colour.
class NULLIllumination final : public IlluminationShader {
public:
    static constexpr TQ3ObjectType kClassType = kQ3IlluminationTypeNULL;
    const ClassInfo& classInfo() const override { return kNULLIlluminationClass; }
    Object* duplicate() const override { return duplicateAs(*this); }
};

} // namespace q3
