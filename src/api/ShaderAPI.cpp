// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DShader.h"
#include "api/Entry.h"
#include "shader/Shader.h"
#include "view/View.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3ObjectType Q3Shader_GetType(TQ3ShaderObject shader)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookup<Shader>(shader, "shader").classInfo().typeAtLevel(4); });
}

TQ3Status Q3Shader_Submit(TQ3ShaderObject shader, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        const Shader& source = lookup<Shader>(shader, "shader");
        lookup<View>(view, "view").submit(source);
    });
}

TQ3Status Q3Shader_SetUVTransform(TQ3ShaderObject shader, const TQ3Matrix3x3* uvTransform)
{
    return setValue<Shader>(__func__, shader, "shader", uvTransform, "uvTransform", &Shader::setUVTransform);
}

TQ3Status Q3Shader_GetUVTransform(TQ3ShaderObject shader, TQ3Matrix3x3* uvTransform)
{
    return getValue<Shader>(__func__, shader, "shader", uvTransform, "uvTransform",
                            [](const Shader& source) { return source.uvTransform(); });
}

TQ3Status Q3Shader_SetUBoundary(TQ3ShaderObject shader, TQ3ShaderUVBoundary uBoundary)
{
    return guardStatus(__func__, [&] { lookup<Shader>(shader, "shader").setUBoundary(uBoundary); });
}

TQ3Status Q3Shader_SetVBoundary(TQ3ShaderObject shader, TQ3ShaderUVBoundary vBoundary)
{
    return guardStatus(__func__, [&] { lookup<Shader>(shader, "shader").setVBoundary(vBoundary); });
}

TQ3Status Q3Shader_GetUBoundary(TQ3ShaderObject shader, TQ3ShaderUVBoundary* uBoundary)
{
    return getValue<Shader>(__func__, shader, "shader", uBoundary, "uBoundary",
                            [](const Shader& source) { return source.uBoundary(); });
}

TQ3Status Q3Shader_GetVBoundary(TQ3ShaderObject shader, TQ3ShaderUVBoundary* vBoundary)
{
    return getValue<Shader>(__func__, shader, "shader", vBoundary, "vBoundary",
                            [](const Shader& source) { return source.vBoundary(); });
}

} // extern "C"
