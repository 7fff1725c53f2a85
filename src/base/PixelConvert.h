// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "base/RenderResult.h"

#include <cstddef>
#include <cstdint>

namespace q3 {

/// The pixel types of QuickDraw 3D 1.6 (TQ3PixelType), same values. A plain
/// enum of its own so that this file does not depend on the public headers;
/// the view layer casts TQ3PixelType to it, and every function here rejects
/// values outside the list.
///
/// Bit layout of one pixel as an unsigned word, most significant bit first
/// ("x" bits are ignored by QuickDraw 3D; this file writes them as 1s, so the
/// pixel also reads as opaque if taken for the ARGB variant):
///   kRGB32     32 bits  xxxxxxxx RRRRRRRR GGGGGGGG BBBBBBBB
///   kARGB32    32 bits  AAAAAAAA RRRRRRRR GGGGGGGG BBBBBBBB
///   kRGB16     16 bits  x RRRRR GGGGG BBBBB
///   kARGB16    16 bits  A RRRRR GGGGG BBBBB      (A: 1 if alpha >= 128)
///   kRGB16_565 16 bits  RRRRR GGGGGG BBBBB
///   kRGB24     24 bits  RRRRRRRR GGGGGGGG BBBBBBBB
enum class PixelType : std::uint32_t {
    kRGB32 = 0,
    kARGB32 = 1,
    kRGB16 = 2,
    kARGB16 = 3,
    kRGB16_565 = 4,
    kRGB24 = 5,
};

/// How a pixel's word is laid out in memory (TQ3Endian values): kBig puts the
/// most significant byte at the lowest address, kLittle the least significant.
/// For kRGB24 that means the bytes R, G, B (big) or B, G, R (little); for
/// kARGB32 big it means A, R, G, B and little B, G, R, A.
enum class ByteOrder : std::uint32_t {
    kBig = 0,
    kLittle = 1,
};

/// Describes a caller's pixmap (the TQ3Pixmap fields other than the image
/// pointer). Row r starts rowBytes * r bytes after the image pointer, row 0 at
/// the top; pixels in a row are packed, bytesPerPixel apart.
struct PixmapLayout {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::uint32_t rowBytes = 0;
    PixelType pixelType = PixelType::kARGB32;
    ByteOrder byteOrder = ByteOrder::kBig;
};

/// A read-only RGBA8 image: 4 bytes per pixel in the order R, G, B, A, top row
/// first, rows rowBytes apart (OffscreenRenderer::pixels() is one).
struct Rgba8ImageView {
    const std::uint8_t* pixels = nullptr;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::size_t rowBytes = 0;
};

struct Rgba8 {
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
    std::uint8_t a = 0;

    bool operator==(const Rgba8& other) const
    {
        return r == other.r && g == other.g && b == other.b && a == other.a;
    }
    bool operator!=(const Rgba8& other) const { return !(*this == other); }
};

/// 4, 4, 2, 2, 2 or 3; 0 for a value that is not a PixelType.
std::uint32_t bytesPerPixel(PixelType type);

/// The pixel's word (layout above; kRGB24 in the low 24 bits). 8-bit channels
/// become 5 or 6 bits by rounding to nearest: (c * 31 + 127) / 255 and
/// (c * 63 + 127) / 255. Returns 0 for an unknown type.
std::uint32_t packPixel(PixelType type, Rgba8 color);

/// The inverse of packPixel: 5- and 6-bit channels widen by bit replication
/// ((v << 3) | (v >> 2), (v << 2) | (v >> 4)), so 0 and full scale map to 0
/// and 255 and packPixel(type, unpackPixel(type, w)) == w for every word of
/// every type whose ignored bits are all 1s. Alpha is 255 for types without alpha and 0 or
/// 255 for kARGB16.
Rgba8 unpackPixel(PixelType type, std::uint32_t word);

/// A pixel's channels as fractions of their range: an n-bit channel holding
/// v is v / (2^n - 1), so a 5-bit 16 is 16/31, not the 132/255 of
/// unpackPixel's widening. Alpha is 1 for types without alpha and 0 or 1 for
/// kARGB16. All 0 for an unknown type.
struct RgbaUnit {
    float r = 0.0f;
    float g = 0.0f;
    float b = 0.0f;
    float a = 0.0f;
};
RgbaUnit unpackPixelUnit(PixelType type, std::uint32_t word);

/// The word of pixel (x, y) of a pixmap whose layout validatePixmapLayout
/// accepts, with x and y inside it (not checked: the caller has).
std::uint32_t pixmapWord(const void* pixmap, const PixmapLayout& layout, std::uint32_t x, std::uint32_t y);

/// Checks a layout: known pixel type and byte order, width and height >= 1,
/// rowBytes >= width * bytesPerPixel. Errors: kInvalidArgument naming the field.
RenderResult validatePixmapLayout(const PixmapLayout& layout);

/// Converts the sourceRect part of an RGBA8 image and stores it into the
/// pixmap with its top-left pixel at (destinationX, destinationY), y from the
/// top. Pixmap pixels outside that rectangle and the padding at row ends are
/// not touched. An empty sourceRect writes nothing.
/// Errors: kInvalidArgument if a pointer is NULL, the layout is invalid, the
/// source rowBytes < width * 4, or either rectangle is not inside its image.
/// Nothing is written on error.
RenderResult writeRgba8ToPixmap(const Rgba8ImageView& source, const PixelRect& sourceRect, void* pixmap,
                                const PixmapLayout& layout, int destinationX, int destinationY);

/// Reads the rect part of a pixmap into RGBA8 (unpackPixel per pixel),
/// rgba receiving rect.width x rect.height pixels, rows rgbaRowBytes apart.
/// Errors: as writeRgba8ToPixmap (rgbaRowBytes < rect.width * 4 included).
RenderResult readPixmapToRgba8(const void* pixmap, const PixmapLayout& layout, const PixelRect& rect,
                               std::uint8_t* rgba, std::size_t rgbaRowBytes);

/// One pixel of a pixmap as RGBA8, for tests and checks. Returns (0,0,0,0)
/// when the pointer is NULL, the layout invalid or (x, y) outside it.
Rgba8 readPixmapPixel(const void* pixmap, const PixmapLayout& layout, std::uint32_t x, std::uint32_t y);

} // namespace q3
