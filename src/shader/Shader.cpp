// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "shader/Shader.h"

#include "core/ParameterChecks.h"
#include "core/ShapeVisitor.h"

#include <string>

namespace q3 {

const ClassInfo kShaderClass{kQ3ShapeTypeShader, &kShapeClass, "shader"};
const ClassInfo kIlluminationShaderClass{kQ3ShaderTypeIllumination, &kShaderClass, "illumination shader"};

namespace {

TQ3ShaderUVBoundary checkBoundary(const TQ3ShaderUVBoundary& boundary, const char* name)
{
    return checkEnum(boundary, kQ3ShaderUVBoundaryWrap, kQ3ShaderUVBoundaryClamp, name,
                     "kQ3ShaderUVBoundaryWrap, Clamp");
}

} // namespace

void Shader::accept(ShapeVisitor& visitor) const
{
    visitor.visitShader(*this);
}

void Shader::setUVTransform(const TQ3Matrix3x3& transform)
{
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column) {
            const std::string name =
                "uvTransform->value[" + std::to_string(row) + "][" + std::to_string(column) + "]";
            checkFinite(transform.value[row][column], name.c_str());
        }
    m_uvTransform = transform;
    markEdited();
}

void Shader::setUBoundary(const TQ3ShaderUVBoundary& boundary)
{
    m_uBoundary = checkBoundary(boundary, "uBoundary");
    markEdited();
}

void Shader::setVBoundary(const TQ3ShaderUVBoundary& boundary)
{
    m_vBoundary = checkBoundary(boundary, "vBoundary");
    markEdited();
}

} // namespace q3
