// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Texture data the texture, file and exchange tests build.

#include "QD3DShader.h"

#include <initializer_list>

namespace q3test {

/// A mipmap over `storage`, big-endian in bits and bytes, of `type`, with
/// `images` (the full-size one first; a TQ3Mipmap holds up to 32).
inline TQ3Mipmap bigEndianMipmap(TQ3StorageObject storage, TQ3PixelType type, bool useMipmapping,
                                 std::initializer_list<TQ3MipmapImage> images)
{
    TQ3Mipmap mipmap{};
    mipmap.image = storage;
    mipmap.useMipmapping = useMipmapping ? kQ3True : kQ3False;
    mipmap.pixelType = type;
    mipmap.bitOrder = kQ3EndianBig;
    mipmap.byteOrder = kQ3EndianBig;
    unsigned i = 0;
    for (const TQ3MipmapImage& image : images)
        mipmap.mipmaps[i++] = image;
    return mipmap;
}

} // namespace q3test
