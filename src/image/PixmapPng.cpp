// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Each pixel goes through PixelConvert's unpackPixel on the way out (5- and
// 6-bit channels widened by bit replication) and its packPixel on the way in
// (rounded to nearest), which is unpackPixel's exact inverse: a pixmap
// written and read back keeps every bit but those its type ignores.

#include "image/PixmapPng.h"

#include "core/EnumValue.h"
#include "core/Error.h"
#include "core/Limits.h"
#include "core/PixelFormat.h"
#include "image/PngFile.h"
#include "view/DrawContext.h"

#include <cstdlib>
#include <new>
#include <string>

namespace q3 {
namespace {

PngEncoding encodingOf(PixelType type)
{
    PngEncoding encoding;
    switch (type) {
    case PixelType::kARGB32:
        break;
    case PixelType::kRGB32:
    case PixelType::kRGB24:
        encoding.alpha = false;
        break;
    case PixelType::kARGB16:
        encoding = PngEncoding{true, {5, 5, 5, 1}};
        break;
    case PixelType::kRGB16:
        encoding = PngEncoding{false, {5, 5, 5, 8}};
        break;
    case PixelType::kRGB16_565:
        encoding = PngEncoding{false, {5, 6, 5, 8}};
        break;
    }
    return encoding;
}

class PixmapRows final : public PngRowSource {
public:
    PixmapRows(const void* image, const PixmapLayout& layout) : m_image(image), m_layout(layout) {}
    void row(std::uint32_t y, std::uint8_t* rgba) const override
    {
        const PixelRect rect{0, static_cast<int>(y), static_cast<int>(m_layout.width), 1};
        (void)readPixmapToRgba8(m_image, m_layout, rect, rgba, std::size_t(m_layout.width) * 4);
    }

private:
    const void* m_image;
    PixmapLayout m_layout;
};

} // namespace

void writePixmapPng(const TQ3Pixmap& pixmap, const char* path)
{
    validatePixmap(pixmap);
    if (pixmap.width > 0x7FFFFFFFul || pixmap.height > 0x7FFFFFFFul)
        fail(kQ3ErrorValueExceedsMaximumSize, "the pixmap is " + std::to_string(pixmap.width) + " x " +
                                                  std::to_string(pixmap.height) +
                                                  " pixels; PNG allows at most 2^31 - 1 on a side");
    const PixmapLayout layout = layoutOf(pixmap);
    writePngFile(path, layout.width, layout.height, encodingOf(layout.pixelType), PixmapRows(pixmap.image, layout));
}

TQ3Pixmap readPixmapPng(const char* path, const TQ3PixelType& pixelType, const TQ3Endian& byteOrder)
{
    const unsigned long bits = bitsPerPixel(enumValue(pixelType));
    if (bits == 0)
        fail(kQ3ErrorInvalidParameter,
             "pixelType " + std::to_string(enumValue(pixelType)) + " is not a TQ3PixelType value");
    if (!isEndian(enumValue(byteOrder)))
        fail(kQ3ErrorInvalidParameter,
             "byteOrder " + std::to_string(enumValue(byteOrder)) + " is not kQ3EndianBig or kQ3EndianLittle");

    const Rgba8Image decoded = readPngFile(path, limits::kMaxPngPixels);
    TQ3Pixmap pixmap{};
    pixmap.width = decoded.width;
    pixmap.height = decoded.height;
    pixmap.rowBytes = decoded.width * (bits / 8);
    pixmap.pixelSize = bits;
    pixmap.pixelType = pixelType;
    pixmap.bitOrder = byteOrder;
    pixmap.byteOrder = byteOrder;
    void* image = std::malloc(std::size_t(pixmap.rowBytes) * pixmap.height);
    if (image == nullptr)
        throw std::bad_alloc();
    pixmap.image = image;
    const PixmapLayout layout = layoutOf(pixmap);
    const Rgba8ImageView source{decoded.pixels.data(), decoded.width, decoded.height, std::size_t(decoded.width) * 4};
    const PixelRect all{0, 0, static_cast<int>(decoded.width), static_cast<int>(decoded.height)};
    const RenderResult converted = writeRgba8ToPixmap(source, all, image, layout, 0, 0);
    if (!converted) {
        std::free(image);
        fail(kQ3ErrorInternalError, "converting the PNG pixels failed: " + converted.message);
    }
    return pixmap;
}

void freePixmapImage(TQ3Pixmap& pixmap)
{
    std::free(pixmap.image);
    pixmap.image = nullptr;
}

} // namespace q3
