// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The storage pixmap fields a PixmapTexture and a PixmapMarker both carry
// (3D Metafile Reference): width, height, rowBytes, pixelSize (Uns32),
// pixelType (RGB32 ARGB32 RGB16 ARGB16 RGB16_565 RGB24), bitOrder, byteOrder
// (BigEndian LittleEndian), then rowBytes * height bytes of image (raw data:
// padded with zeros to a multiple of 4 in binary, one 0x... token in text).

#include "io/ClassIO.h"

#include "base/Storage.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace q3::io {

inline const std::vector<std::pair<const char*, std::uint32_t>> kPixelTypes = {
    {"RGB32", kQ3PixelTypeRGB32},   {"ARGB32", kQ3PixelTypeARGB32},       {"RGB16", kQ3PixelTypeRGB16},
    {"ARGB16", kQ3PixelTypeARGB16}, {"RGB16_565", kQ3PixelTypeRGB16_565}, {"RGB24", kQ3PixelTypeRGB24}};
inline const std::vector<std::pair<const char*, std::uint32_t>> kEndians = {{"BigEndian", kQ3EndianBig},
                                                                            {"LittleEndian", kQ3EndianLittle}};

/// Reads the pixmap's fields from width to byteOrder, then its image bytes:
/// an image larger than the binary data holds is refused before anything is
/// allocated (in text, rawData checks the token). `pixmap.image` is left as
/// it was; the bytes are returned.
std::string readPixmapFields(DataReader& in, TQ3StoragePixmap& pixmap);

/// Writes the pixmap's fields from width to byteOrder, then `image`.
void writePixmapFields(Encoder& out, const TQ3StoragePixmap& pixmap, const std::vector<unsigned char>& image);

/// A new memory storage holding a copy of `bytes`.
Ref<MemoryStorage> storageOf(const std::string& bytes);

} // namespace q3::io
