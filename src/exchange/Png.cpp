// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// PNG through libpng's simplified API (png.h, "simplified API", libpng
// 1.6): memory in, memory out, no callbacks or longjmp to manage.

#include "exchange/Png.h"

#include "core/Error.h"

#include <png.h>

#include <cstring>

namespace q3::exchange {

std::vector<unsigned char> encodePng(const Image& image)
{
    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    png.width = image.width;
    png.height = image.height;
    png.format = image.hasAlpha ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
    std::vector<unsigned char> pixels;
    if (image.hasAlpha) {
        pixels = image.rgba;
    } else {
        pixels.resize(std::size_t(image.width) * image.height * 3);
        for (std::size_t i = 0; i < std::size_t(image.width) * image.height; ++i)
            std::memcpy(&pixels[3 * i], &image.rgba[4 * i], 3);
    }
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&png, nullptr, &size, 0, pixels.data(), 0, nullptr))
        fail(kQ3ErrorInternalError, std::string("a texture cannot be encoded as PNG: ") + png.message);
    std::vector<unsigned char> out(size);
    if (!png_image_write_to_memory(&png, out.data(), &size, 0, pixels.data(), 0, nullptr))
        fail(kQ3ErrorInternalError, std::string("a texture cannot be encoded as PNG: ") + png.message);
    out.resize(size);
    return out;
}

Image decodePng(const unsigned char* bytes, std::size_t size, const std::string& what)
{
    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&png, bytes, size))
        fail(kQ3ErrorInvalidData, what + " is not a PNG image Q3 can read: " + png.message);
    png.format = PNG_FORMAT_RGBA;
    Image image;
    image.width = png.width;
    image.height = png.height;
    image.rgba.resize(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, image.rgba.data(), 0, nullptr)) {
        png_image_free(&png);
        fail(kQ3ErrorInvalidData, what + " is not a PNG image Q3 can read: " + png.message);
    }
    for (std::size_t i = 3; i < image.rgba.size(); i += 4)
        image.hasAlpha = image.hasAlpha || image.rgba[i] != 255;
    return image;
}

} // namespace q3::exchange
