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
    return getValue<Texture>(__func__, texture, "texture", width, "width",
                             [](const Texture& source) { return source.width(); });
}

TQ3Status Q3Texture_GetHeight(TQ3TextureObject texture, unsigned long* height)
{
    return getValue<Texture>(__func__, texture, "texture", height, "height",
                             [](const Texture& source) { return source.height(); });
}

TQ3TextureObject Q3PixmapTexture_New(const TQ3StoragePixmap* pixmap)
{
    return newShared<PixmapTexture>(__func__, pixmap, "pixmap");
}

TQ3Status Q3PixmapTexture_GetPixmap(TQ3TextureObject texture, TQ3StoragePixmap* pixmap)
{
    return getValue<PixmapTexture>(__func__, texture, "texture", pixmap, "pixmap",
                                   [](const PixmapTexture& source) { return source.pixmap(); });
}

TQ3Status Q3PixmapTexture_SetPixmap(TQ3TextureObject texture, const TQ3StoragePixmap* pixmap)
{
    return setValue<PixmapTexture>(__func__, texture, "texture", pixmap, "pixmap", &PixmapTexture::setPixmap);
}

TQ3TextureObject Q3MipmapTexture_New(const TQ3Mipmap* mipmap)
{
    return newShared<MipmapTexture>(__func__, mipmap, "mipmap");
}

TQ3Status Q3MipmapTexture_GetMipmap(TQ3TextureObject texture, TQ3Mipmap* mipmap)
{
    return getValue<MipmapTexture>(__func__, texture, "texture", mipmap, "mipmap",
                                   [](const MipmapTexture& source) { return source.mipmap(); });
}

TQ3Status Q3MipmapTexture_SetMipmap(TQ3TextureObject texture, const TQ3Mipmap* mipmap)
{
    return setValue<MipmapTexture>(__func__, texture, "texture", mipmap, "mipmap", &MipmapTexture::setMipmap);
}

} // extern "C"
