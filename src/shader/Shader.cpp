// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "shader/Shader.h"

#include "core/ShapeVisitor.h"

namespace q3 {

const ClassInfo kShaderClass{kQ3ShapeTypeShader, &kShapeClass, "shader"};
const ClassInfo kIlluminationShaderClass{kQ3ShaderTypeIllumination, &kShaderClass, "illumination shader"};

void Shader::accept(ShapeVisitor& visitor) const
{
    visitor.visitShader(*this);
}

} // namespace q3
