// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Q3Texture_, Q3PixmapTexture_ and Q3MipmapTexture_: every texture call
// is a lookup and one method of shader/Texture.h.

#include "QD3DShader.h"
#include "api/Entry.h"
#include "shader/Texture.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3ObjectType Q3Texture_GetType(TQ3TextureObject texture)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookup<Texture>(texture, "texture").classInfo().typeAtLevel(3); });
}

TQ3Status Q3Texture_GetWidth(TQ3TextureObject texture, unsigned long* width)
{
    return getValue<Texture>(__func__, texture, "texture", width, "width", &Texture::width);
}

TQ3Status Q3Texture_GetHeight(TQ3TextureObject texture, unsigned long* height)
{
    return getValue<Texture>(__func__, texture, "texture", height, "height", &Texture::height);
}

TQ3TextureObject Q3PixmapTexture_New(const TQ3StoragePixmap* pixmap)
{
    return newShared<PixmapTexture>(__func__, pixmap, "pixmap");
}

Q3_POINTER_VALUE_ENTRY_POINTS(Q3PixmapTexture, PixmapTexture, TQ3TextureObject, texture, Pixmap, TQ3StoragePixmap,
                              pixmap)

TQ3TextureObject Q3MipmapTexture_New(const TQ3Mipmap* mipmap)
{
    return newShared<MipmapTexture>(__func__, mipmap, "mipmap");
}

Q3_POINTER_VALUE_ENTRY_POINTS(Q3MipmapTexture, MipmapTexture, TQ3TextureObject, texture, Mipmap, TQ3Mipmap, mipmap)

} // extern "C"
