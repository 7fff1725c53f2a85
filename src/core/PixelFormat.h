// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The pixel formats QD3DDrawContext.h defines, as the objects that hold
// pixels (draw contexts, pixmap markers, textures) validate them. Values are
// taken as long (read with enumValue) since a caller may have stored any int.

#include "QD3D.h"

namespace q3 {

/// Bits per pixel of each TQ3PixelType (QD3DDrawContext.h's table); 0 for a
/// value outside the enumeration.
inline unsigned long bitsPerPixel(long pixelType)
{
    switch (pixelType) {
    case kQ3PixelTypeRGB32:
    case kQ3PixelTypeARGB32:
        return 32;
    case kQ3PixelTypeRGB24:
        return 24;
    case kQ3PixelTypeRGB16:
    case kQ3PixelTypeARGB16:
    case kQ3PixelTypeRGB16_565:
        return 16;
    default:
        return 0;
    }
}

/// Whether a stored TQ3Endian value is one of its two values.
inline bool isEndian(long value)
{
    return value == kQ3EndianBig || value == kQ3EndianLittle;
}

} // namespace q3
