// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Conversion between RGBA8 images and QuickDraw 3D pixmaps. The row loops are
// instantiated once per (pixel type, byte order) so the inner loop carries no
// per-pixel switch; packPixel/unpackPixel define the bit layouts in one place.

#include "base/PixelConvert.h"

#include <cstring>
#include <string>

namespace q3 {
namespace {

constexpr std::uint32_t to5(std::uint32_t c)
{
    return (c * 31 + 127) / 255;
}

constexpr std::uint32_t to6(std::uint32_t c)
{
    return (c * 63 + 127) / 255;
}

constexpr std::uint8_t from5(std::uint32_t v)
{
    return std::uint8_t((v << 3) | (v >> 2));
}

constexpr std::uint8_t from6(std::uint32_t v)
{
    return std::uint8_t((v << 2) | (v >> 4));
}

template <PixelType kType>
constexpr std::uint32_t pack(std::uint32_t r, std::uint32_t g, std::uint32_t b, std::uint32_t a)
{
    switch (kType) {
    case PixelType::kRGB32:
        return 0xFF000000u | (r << 16) | (g << 8) | b;
    case PixelType::kARGB32:
        return (a << 24) | (r << 16) | (g << 8) | b;
    case PixelType::kRGB16:
        return 0x8000u | (to5(r) << 10) | (to5(g) << 5) | to5(b);
    case PixelType::kARGB16:
        return (a >= 128 ? 0x8000u : 0u) | (to5(r) << 10) | (to5(g) << 5) | to5(b);
    case PixelType::kRGB16_565:
        return (to5(r) << 11) | (to6(g) << 5) | to5(b);
    case PixelType::kRGB24:
        return (r << 16) | (g << 8) | b;
    }
    return 0;
}

template <PixelType kType>
constexpr Rgba8 unpack(std::uint32_t w)
{
    switch (kType) {
    case PixelType::kRGB32:
        return {std::uint8_t(w >> 16), std::uint8_t(w >> 8), std::uint8_t(w), 255};
    case PixelType::kARGB32:
        return {std::uint8_t(w >> 16), std::uint8_t(w >> 8), std::uint8_t(w), std::uint8_t(w >> 24)};
    case PixelType::kRGB16:
        return {from5((w >> 10) & 31), from5((w >> 5) & 31), from5(w & 31), 255};
    case PixelType::kARGB16:
        return {from5((w >> 10) & 31), from5((w >> 5) & 31), from5(w & 31),
                std::uint8_t((w & 0x8000u) ? 255 : 0)};
    case PixelType::kRGB16_565:
        return {from5((w >> 11) & 31), from6((w >> 5) & 63), from5(w & 31), 255};
    case PixelType::kRGB24:
        return {std::uint8_t(w >> 16), std::uint8_t(w >> 8), std::uint8_t(w), 255};
    }
    return {};
}

template <PixelType kType>
constexpr std::uint32_t bytesOf()
{
    return kType == PixelType::kRGB24 ? 3 : (kType == PixelType::kRGB32 || kType == PixelType::kARGB32) ? 4 : 2;
}

template <std::uint32_t kBytes, ByteOrder kOrder>
inline void store(std::uint8_t* p, std::uint32_t w)
{
    for (std::uint32_t i = 0; i < kBytes; ++i) {
        const std::uint32_t shift = kOrder == ByteOrder::kBig ? 8 * (kBytes - 1 - i) : 8 * i;
        p[i] = std::uint8_t(w >> shift);
    }
}

template <std::uint32_t kBytes, ByteOrder kOrder>
inline std::uint32_t load(const std::uint8_t* p)
{
    std::uint32_t w = 0;
    for (std::uint32_t i = 0; i < kBytes; ++i) {
        const std::uint32_t shift = kOrder == ByteOrder::kBig ? 8 * (kBytes - 1 - i) : 8 * i;
        w |= std::uint32_t(p[i]) << shift;
    }
    return w;
}

struct RowJob {
    const std::uint8_t* from;
    std::size_t fromRowBytes;
    std::uint8_t* to;
    std::size_t toRowBytes;
    std::uint32_t width;
    std::uint32_t height;
};

template <PixelType kType, ByteOrder kOrder>
void writeRows(const RowJob& job)
{
    constexpr std::uint32_t kBytes = bytesOf<kType>();
    const std::uint32_t width = job.width;
    const std::uint32_t height = job.height;
    for (std::uint32_t y = 0; y < height; ++y) {
        const std::uint8_t* __restrict s = job.from + job.fromRowBytes * y;
        std::uint8_t* __restrict d = job.to + job.toRowBytes * y;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
        if constexpr (kBytes == 4) {
            // Whole words: R, G, B, A in memory is R | G << 8 | B << 16 | A << 24.
            for (std::size_t x = 0; x < width; ++x) {
                std::uint32_t v;
                std::memcpy(&v, s + 4 * x, 4);
                std::uint32_t w = pack<kType>(v & 255u, (v >> 8) & 255u, (v >> 16) & 255u, v >> 24);
                if constexpr (kOrder == ByteOrder::kBig)
                    w = __builtin_bswap32(w);
                std::memcpy(d + 4 * x, &w, 4);
            }
            continue;
        }
#endif
        for (std::size_t x = 0; x < width; ++x)
            store<kBytes, kOrder>(d + kBytes * x, pack<kType>(s[4 * x], s[4 * x + 1], s[4 * x + 2], s[4 * x + 3]));
    }
}

template <PixelType kType, ByteOrder kOrder>
void readRows(const RowJob& job)
{
    constexpr std::uint32_t kBytes = bytesOf<kType>();
    for (std::uint32_t y = 0; y < job.height; ++y) {
        const std::uint8_t* s = job.from + job.fromRowBytes * y;
        std::uint8_t* d = job.to + job.toRowBytes * y;
        for (std::uint32_t x = 0; x < job.width; ++x, s += kBytes, d += 4) {
            const Rgba8 c = unpack<kType>(load<kBytes, kOrder>(s));
            d[0] = c.r;
            d[1] = c.g;
            d[2] = c.b;
            d[3] = c.a;
        }
    }
}

using RowFunction = void (*)(const RowJob&);

template <template <PixelType, ByteOrder> class Pick>
RowFunction pickRowFunction(PixelType type, ByteOrder order)
{
    const bool big = order == ByteOrder::kBig;
    switch (type) {
    case PixelType::kRGB32:
        return big ? Pick<PixelType::kRGB32, ByteOrder::kBig>::kFunction
                   : Pick<PixelType::kRGB32, ByteOrder::kLittle>::kFunction;
    case PixelType::kARGB32:
        return big ? Pick<PixelType::kARGB32, ByteOrder::kBig>::kFunction
                   : Pick<PixelType::kARGB32, ByteOrder::kLittle>::kFunction;
    case PixelType::kRGB16:
        return big ? Pick<PixelType::kRGB16, ByteOrder::kBig>::kFunction
                   : Pick<PixelType::kRGB16, ByteOrder::kLittle>::kFunction;
    case PixelType::kARGB16:
        return big ? Pick<PixelType::kARGB16, ByteOrder::kBig>::kFunction
                   : Pick<PixelType::kARGB16, ByteOrder::kLittle>::kFunction;
    case PixelType::kRGB16_565:
        return big ? Pick<PixelType::kRGB16_565, ByteOrder::kBig>::kFunction
                   : Pick<PixelType::kRGB16_565, ByteOrder::kLittle>::kFunction;
    case PixelType::kRGB24:
        return big ? Pick<PixelType::kRGB24, ByteOrder::kBig>::kFunction
                   : Pick<PixelType::kRGB24, ByteOrder::kLittle>::kFunction;
    }
    return nullptr;
}

template <PixelType kType, ByteOrder kOrder>
struct PickWrite {
    static constexpr RowFunction kFunction = &writeRows<kType, kOrder>;
};

template <PixelType kType, ByteOrder kOrder>
struct PickRead {
    static constexpr RowFunction kFunction = &readRows<kType, kOrder>;
};

RenderResult invalid(std::string message)
{
    return RenderResult::failure(RenderStatus::kInvalidArgument, std::move(message));
}

// Whether [x, x + width) x [y, y + height) lies inside a width x height image.
bool rectInside(std::int64_t x, std::int64_t y, std::int64_t width, std::int64_t height,
                std::int64_t imageWidth, std::int64_t imageHeight)
{
    return x >= 0 && y >= 0 && width >= 0 && height >= 0 && x + width <= imageWidth &&
           y + height <= imageHeight;
}

std::string describe(const PixelRect& r)
{
    return "(" + std::to_string(r.x) + ", " + std::to_string(r.y) + ", " + std::to_string(r.width) + " x " +
           std::to_string(r.height) + ")";
}

} // namespace

std::uint32_t bytesPerPixel(PixelType type)
{
    switch (type) {
    case PixelType::kRGB32:
    case PixelType::kARGB32:
        return 4;
    case PixelType::kRGB16:
    case PixelType::kARGB16:
    case PixelType::kRGB16_565:
        return 2;
    case PixelType::kRGB24:
        return 3;
    }
    return 0;
}

std::uint32_t packPixel(PixelType type, Rgba8 c)
{
    switch (type) {
    case PixelType::kRGB32:
        return pack<PixelType::kRGB32>(c.r, c.g, c.b, c.a);
    case PixelType::kARGB32:
        return pack<PixelType::kARGB32>(c.r, c.g, c.b, c.a);
    case PixelType::kRGB16:
        return pack<PixelType::kRGB16>(c.r, c.g, c.b, c.a);
    case PixelType::kARGB16:
        return pack<PixelType::kARGB16>(c.r, c.g, c.b, c.a);
    case PixelType::kRGB16_565:
        return pack<PixelType::kRGB16_565>(c.r, c.g, c.b, c.a);
    case PixelType::kRGB24:
        return pack<PixelType::kRGB24>(c.r, c.g, c.b, c.a);
    }
    return 0;
}

Rgba8 unpackPixel(PixelType type, std::uint32_t word)
{
    switch (type) {
    case PixelType::kRGB32:
        return unpack<PixelType::kRGB32>(word);
    case PixelType::kARGB32:
        return unpack<PixelType::kARGB32>(word);
    case PixelType::kRGB16:
        return unpack<PixelType::kRGB16>(word);
    case PixelType::kARGB16:
        return unpack<PixelType::kARGB16>(word);
    case PixelType::kRGB16_565:
        return unpack<PixelType::kRGB16_565>(word);
    case PixelType::kRGB24:
        return unpack<PixelType::kRGB24>(word);
    }
    return {};
}

RenderResult validatePixmapLayout(const PixmapLayout& layout)
{
    const std::uint32_t bytes = bytesPerPixel(layout.pixelType);
    if (bytes == 0)
        return invalid("unknown pixel type " + std::to_string(std::uint32_t(layout.pixelType)));
    if (layout.byteOrder != ByteOrder::kBig && layout.byteOrder != ByteOrder::kLittle)
        return invalid("unknown byte order " + std::to_string(std::uint32_t(layout.byteOrder)));
    if (layout.width == 0 || layout.height == 0)
        return invalid("pixmap is " + std::to_string(layout.width) + " x " + std::to_string(layout.height));
    if (std::uint64_t(layout.rowBytes) < std::uint64_t(layout.width) * bytes)
        return invalid("rowBytes " + std::to_string(layout.rowBytes) + " is less than width * " +
                       std::to_string(bytes));
    return RenderResult::success();
}

RenderResult writeRgba8ToPixmap(const Rgba8ImageView& source, const PixelRect& sourceRect, void* pixmap,
                                const PixmapLayout& layout, int destinationX, int destinationY)
{
    if (pixmap == nullptr)
        return invalid("pixmap image pointer is NULL");
    if (source.pixels == nullptr)
        return invalid("source pixels are NULL");
    RenderResult valid = validatePixmapLayout(layout);
    if (!valid)
        return valid;
    if (source.rowBytes < std::size_t(source.width) * 4)
        return invalid("source rowBytes is less than width * 4");
    if (!rectInside(sourceRect.x, sourceRect.y, sourceRect.width, sourceRect.height, source.width,
                    source.height))
        return invalid("source rectangle " + describe(sourceRect) + " is not inside the " +
                       std::to_string(source.width) + " x " + std::to_string(source.height) + " image");
    if (!rectInside(destinationX, destinationY, sourceRect.width, sourceRect.height, layout.width,
                    layout.height))
        return invalid("destination rectangle at (" + std::to_string(destinationX) + ", " +
                       std::to_string(destinationY) + ") is not inside the " + std::to_string(layout.width) +
                       " x " + std::to_string(layout.height) + " pixmap");
    if (sourceRect.width == 0 || sourceRect.height == 0)
        return RenderResult::success();

    const std::uint32_t bytes = bytesPerPixel(layout.pixelType);
    RowJob job;
    job.from = source.pixels + source.rowBytes * std::size_t(sourceRect.y) + std::size_t(sourceRect.x) * 4;
    job.fromRowBytes = source.rowBytes;
    job.to = static_cast<std::uint8_t*>(pixmap) + std::size_t(layout.rowBytes) * std::size_t(destinationY) +
             std::size_t(destinationX) * bytes;
    job.toRowBytes = layout.rowBytes;
    job.width = std::uint32_t(sourceRect.width);
    job.height = std::uint32_t(sourceRect.height);
    pickRowFunction<PickWrite>(layout.pixelType, layout.byteOrder)(job);
    return RenderResult::success();
}

RenderResult readPixmapToRgba8(const void* pixmap, const PixmapLayout& layout, const PixelRect& rect,
                               std::uint8_t* rgba, std::size_t rgbaRowBytes)
{
    if (pixmap == nullptr)
        return invalid("pixmap image pointer is NULL");
    if (rgba == nullptr)
        return invalid("destination pixels are NULL");
    RenderResult valid = validatePixmapLayout(layout);
    if (!valid)
        return valid;
    if (!rectInside(rect.x, rect.y, rect.width, rect.height, layout.width, layout.height))
        return invalid("rectangle " + describe(rect) + " is not inside the " + std::to_string(layout.width) +
                       " x " + std::to_string(layout.height) + " pixmap");
    if (rgbaRowBytes < std::size_t(rect.width) * 4)
        return invalid("destination rowBytes is less than width * 4");
    if (rect.width == 0 || rect.height == 0)
        return RenderResult::success();

    const std::uint32_t bytes = bytesPerPixel(layout.pixelType);
    RowJob job;
    job.from = static_cast<const std::uint8_t*>(pixmap) + std::size_t(layout.rowBytes) * std::size_t(rect.y) +
               std::size_t(rect.x) * bytes;
    job.fromRowBytes = layout.rowBytes;
    job.to = rgba;
    job.toRowBytes = rgbaRowBytes;
    job.width = std::uint32_t(rect.width);
    job.height = std::uint32_t(rect.height);
    pickRowFunction<PickRead>(layout.pixelType, layout.byteOrder)(job);
    return RenderResult::success();
}

RgbaUnit unpackPixelUnit(PixelType type, std::uint32_t w)
{
    auto unit = [w](unsigned shift, unsigned bits) {
        const std::uint32_t top = (1u << bits) - 1u;
        return float((w >> shift) & top) / float(top);
    };
    switch (type) {
    case PixelType::kRGB32:
    case PixelType::kRGB24:
        return {unit(16, 8), unit(8, 8), unit(0, 8), 1.0f};
    case PixelType::kARGB32:
        return {unit(16, 8), unit(8, 8), unit(0, 8), unit(24, 8)};
    case PixelType::kRGB16:
        return {unit(10, 5), unit(5, 5), unit(0, 5), 1.0f};
    case PixelType::kARGB16:
        return {unit(10, 5), unit(5, 5), unit(0, 5), unit(15, 1)};
    case PixelType::kRGB16_565:
        return {unit(11, 5), unit(5, 6), unit(0, 5), 1.0f};
    }
    return {};
}

std::uint32_t pixmapWord(const void* pixmap, const PixmapLayout& layout, std::uint32_t x, std::uint32_t y)
{
    const std::uint32_t bytes = bytesPerPixel(layout.pixelType);
    const std::uint8_t* p =
        static_cast<const std::uint8_t*>(pixmap) + std::size_t(layout.rowBytes) * y + std::size_t(x) * bytes;
    std::uint32_t word = 0;
    for (std::uint32_t i = 0; i < bytes; ++i) {
        const std::uint32_t shift = layout.byteOrder == ByteOrder::kBig ? 8 * (bytes - 1 - i) : 8 * i;
        word |= std::uint32_t(p[i]) << shift;
    }
    return word;
}

Rgba8 readPixmapPixel(const void* pixmap, const PixmapLayout& layout, std::uint32_t x, std::uint32_t y)
{
    if (pixmap == nullptr || !validatePixmapLayout(layout) || x >= layout.width || y >= layout.height)
        return {};
    return unpackPixel(layout.pixelType, pixmapWord(pixmap, layout, x, y));
}

} // namespace q3
