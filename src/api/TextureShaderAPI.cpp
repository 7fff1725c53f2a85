// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Q3SurfaceShader_ and Q3TextureShader_ (the one surface shader).

#include "QD3DShader.h"
#include "api/Entry.h"
#include "shader/TextureShader.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3ObjectType Q3SurfaceShader_GetType(TQ3SurfaceShaderObject shader)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookup<SurfaceShader>(shader, "shader").classInfo().typeAtLevel(5); });
}

TQ3ShaderObject Q3TextureShader_New(TQ3TextureObject texture)
{
    return guard(__func__, TQ3ShaderObject{nullptr}, [&]() -> TQ3ShaderObject {
        return makeShared<TextureShader>(lookupRef<Texture>(texture, "texture")).detach();
    });
}

TQ3Status Q3TextureShader_GetTexture(TQ3ShaderObject shader, TQ3TextureObject* texture)
{
    return getValue<TextureShader>(__func__, shader, "shader", texture, "texture", [&](const TextureShader& source) {
        return Ref<Texture>(source.texture()).detach();
    });
}

TQ3Status Q3TextureShader_SetTexture(TQ3ShaderObject shader, TQ3TextureObject texture)
{
    return guardStatus(__func__, [&] {
        TextureShader& target = lookup<TextureShader>(shader, "shader");
        target.setTexture(lookupRef<Texture>(texture, "texture"));
    });
}

} // extern "C"
