// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/Object.h"
#include "style/DrawState.h"

namespace q3 {

extern const ClassInfo kShaderClass;
extern const ClassInfo kIlluminationShaderClass;

/// Every QuickDraw 3D shader: a drawable shared object that, submitted to a
/// view, sets its part of the traversal's DrawState.
class Shader : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapeTypeShader;

    bool isDrawable() const override { return true; }
    void accept(ShapeVisitor& visitor) const override;

    virtual void apply(DrawState& state) const = 0;

protected:
    Shader() = default;
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
