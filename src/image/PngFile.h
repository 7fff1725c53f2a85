// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// PNG files of 8-bit RGBA images (libpng), for Q3PixmapPNG.h. Errors are
// thrown as q3::Error with the codes Q3PixmapPNG.h documents.

#include "base/PixelConvert.h"

#include <cstdint>
#include <string>
#include <vector>

namespace q3 {

/// How a PNG file stores its pixels, and each channel's real depth (an sBIT
/// chunk is written when one is below 8).
struct PngEncoding {
    bool alpha = true;               ///< RGBA; otherwise RGB and the A bytes are dropped
    std::uint8_t significantBits[4] = {8, 8, 8, 8}; ///< R, G, B, A
};

/// Writes image to path, row by row: `row(y, rgba)` fills rgba with row y's
/// width * 4 bytes and must not throw (libpng long-jumps over the frames
/// between). Output bytes depend on the pixels only (fixed filter,
/// zlib level, no time stamp). On failure nothing is left at path if it is a
/// regular file. Throws kQ3ErrorValueExceedsMaximumSize (a side above
/// 2^31 - 1), kQ3ErrorFileNotOpen, kQ3ErrorWroteLessThanSize.
class PngRowSource {
public:
    virtual ~PngRowSource() = default;
    virtual void row(std::uint32_t y, std::uint8_t* rgba) const = 0;
};
void writePngFile(const std::string& path, std::uint32_t width, std::uint32_t height,
                  const PngEncoding& encoding, const PngRowSource& rows);

/// An 8-bit RGBA image, rows packed, top row first.
struct Rgba8Image {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> pixels;
};

/// Reads any PNG file as 8-bit RGBA (16-bit channels keep their high byte,
/// missing alpha reads 255). Throws kQ3ErrorFileNotOpen, kQ3ErrorInvalidData
/// (not a PNG file, corrupt, truncated), kQ3ErrorValueExceedsMaximumSize
/// (more than maxPixels pixels, checked before allocating).
Rgba8Image readPngFile(const std::string& path, std::uint64_t maxPixels);

} // namespace q3
