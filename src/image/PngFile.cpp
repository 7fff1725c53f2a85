// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// libpng reports errors by calling an error function that must not return;
// ours records the message and long-jumps back to the setjmp of the function
// that called libpng. Those functions (encodeRows, decodeHeader, decodeRows)
// hold only trivially destructible locals and call nothing that throws, so
// the jump skips no destructor; everything with a destructor (the file, the
// libpng structures, the pixel buffers) lives in their callers.
//
// Output settings are fixed so that the bytes depend on the pixels only: the
// up filter (subtract the row above, which suits rendered images, mostly rows
// equal to the one above), zlib level 6, no time stamp. They are the settings
// of samples/support/q3png.c, so both give the same files.

#include "image/PngFile.h"

#include "core/Error.h"

#include <png.h>
#include <zlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <sys/stat.h>

namespace q3 {
namespace {

constexpr int kZlibLevel = 6;
constexpr int kRowFilter = PNG_FILTER_UP;
constexpr std::uint32_t kMaxPngSide = 0x7FFFFFFFu; // PNG's limit: 2^31 - 1

struct ErrorState {
    TQ3Error code = kQ3ErrorNone; // what the jump means; kQ3ErrorInvalidData unless set
    char message[200] = {};
};

void onError(png_structp png, png_const_charp message)
{
    auto* state = static_cast<ErrorState*>(png_get_error_ptr(png));
    if (state->code == kQ3ErrorNone)
        state->code = kQ3ErrorInvalidData;
    if (state->message[0] == '\0')
        std::snprintf(state->message, sizeof state->message, "%s", message);
    png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}

void writeBytes(png_structp png, png_bytep data, png_size_t length)
{
    FILE* file = static_cast<FILE*>(png_get_io_ptr(png));
    if (std::fwrite(data, 1, length, file) != length) {
        auto* state = static_cast<ErrorState*>(png_get_error_ptr(png));
        state->code = kQ3ErrorWroteLessThanSize;
        std::snprintf(state->message, sizeof state->message, "writing failed: %s", std::strerror(errno));
        png_error(png, state->message);
    }
}

void flushBytes(png_structp png)
{
    FILE* file = static_cast<FILE*>(png_get_io_ptr(png));
    if (std::fflush(file) != 0) {
        auto* state = static_cast<ErrorState*>(png_get_error_ptr(png));
        state->code = kQ3ErrorWroteLessThanSize;
        std::snprintf(state->message, sizeof state->message, "writing failed: %s", std::strerror(errno));
        png_error(png, state->message);
    }
}

struct FileCloser {
    void operator()(FILE* file) const { std::fclose(file); }
};
using FilePtr = std::unique_ptr<FILE, FileCloser>;

/// Removes what a failed write left behind, but only a regular file: the path
/// may name a device or a symbolic link such as /dev/stdout, which must stay.
void discardPartial(const std::string& path)
{
    struct stat info;
    if (lstat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode))
        std::remove(path.c_str());
}

bool encodeRows(png_structp png, png_infop info, FILE* file, std::uint32_t width, std::uint32_t height,
                const PngEncoding& encoding, const PngRowSource& rows, std::uint8_t* rgba, std::uint8_t* packed)
{
    if (setjmp(png_jmpbuf(png)))
        return false;
    png_set_write_fn(png, file, writeBytes, flushBytes);
    png_set_IHDR(png, info, width, height, 8, encoding.alpha ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    bool reduced = false;
    for (std::uint8_t bits : encoding.significantBits)
        reduced = reduced || bits < 8;
    if (reduced) {
        png_color_8 significant{};
        significant.red = encoding.significantBits[0];
        significant.green = encoding.significantBits[1];
        significant.blue = encoding.significantBits[2];
        significant.alpha = encoding.alpha ? encoding.significantBits[3] : 0;
        png_set_sBIT(png, info, &significant);
    }
    png_set_filter(png, PNG_FILTER_TYPE_BASE, kRowFilter);
    png_set_compression_level(png, kZlibLevel);
    png_set_compression_strategy(png, Z_DEFAULT_STRATEGY);
    png_set_compression_mem_level(png, 8);
    png_set_compression_window_bits(png, 15);
    png_write_info(png, info);
    for (std::uint32_t y = 0; y < height; ++y) {
        rows.row(y, rgba);
        if (encoding.alpha) {
            png_write_row(png, rgba);
            continue;
        }
        for (std::size_t x = 0; x < width; ++x) {
            packed[3 * x + 0] = rgba[4 * x + 0];
            packed[3 * x + 1] = rgba[4 * x + 1];
            packed[3 * x + 2] = rgba[4 * x + 2];
        }
        png_write_row(png, packed);
    }
    png_write_end(png, nullptr);
    return true;
}

bool decodeHeader(png_structp png, png_infop info, FILE* file, png_uint_32* width, png_uint_32* height)
{
    if (setjmp(png_jmpbuf(png)))
        return false;
    png_init_io(png, file);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    const int colorType = png_get_color_type(png, info);
    const int bitDepth = png_get_bit_depth(png, info);
    const bool transparency = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
    if (colorType == PNG_COLOR_TYPE_PALETTE)
        png_set_palette_to_rgb(png);
    if (colorType == PNG_COLOR_TYPE_GRAY && bitDepth < 8)
        png_set_expand_gray_1_2_4_to_8(png);
    if (transparency)
        png_set_tRNS_to_alpha(png);
    if (bitDepth == 16)
        png_set_strip_16(png);
    if (colorType == PNG_COLOR_TYPE_GRAY || colorType == PNG_COLOR_TYPE_GRAY_ALPHA)
        png_set_gray_to_rgb(png);
    if ((colorType & PNG_COLOR_MASK_ALPHA) == 0 && !transparency)
        png_set_filler(png, 0xFF, PNG_FILLER_AFTER);
    (void)png_set_interlace_handling(png);
    png_read_update_info(png, info);
    *width = png_get_image_width(png, info);
    *height = png_get_image_height(png, info);
    if (png_get_rowbytes(png, info) != std::size_t(*width) * 4)
        png_error(png, "unexpected row size after the conversion to RGBA");
    return true;
}

bool decodeRows(png_structp png, png_infop info, png_bytep* rows)
{
    if (setjmp(png_jmpbuf(png)))
        return false;
    png_read_image(png, rows);
    png_read_end(png, nullptr);
    return true;
}

} // namespace

void writePngFile(const std::string& path, std::uint32_t width, std::uint32_t height, const PngEncoding& encoding,
                  const PngRowSource& rows)
{
    if (width > kMaxPngSide || height > kMaxPngSide)
        fail(kQ3ErrorValueExceedsMaximumSize, "the image is " + std::to_string(width) + " x " +
                                                  std::to_string(height) +
                                                  " pixels; PNG allows at most 2^31 - 1 on a side");
    std::vector<std::uint8_t> rgba(std::size_t(width) * 4);
    std::vector<std::uint8_t> packed(encoding.alpha ? 0 : std::size_t(width) * 3);

    FilePtr file(std::fopen(path.c_str(), "wb"));
    if (!file)
        fail(kQ3ErrorFileNotOpen, "cannot open " + path + " for writing: " + std::strerror(errno));
    ErrorState state;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, onError, onWarning);
    png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
    const bool created = png != nullptr && info != nullptr;
    const bool written = created && encodeRows(png, info, file.get(), width, height, encoding, rows, rgba.data(), packed.data());
    png_destroy_write_struct(&png, &info);
    const bool closed = std::fclose(file.release()) == 0;
    if (!written || !closed) {
        discardPartial(path);
        if (!created)
            throw std::bad_alloc();
        const TQ3Error code = state.code != kQ3ErrorNone ? state.code : kQ3ErrorWroteLessThanSize;
        const std::string reason = written ? std::string("closing failed: ") + std::strerror(errno)
                                           : std::string(state.message);
        fail(code, "cannot write " + path + ": " + reason);
    }
}

Rgba8Image readPngFile(const std::string& path, std::uint64_t maxPixels)
{
    FilePtr file(std::fopen(path.c_str(), "rb"));
    if (!file)
        fail(kQ3ErrorFileNotOpen, "cannot open " + path + " for reading: " + std::strerror(errno));
    unsigned char signature[8];
    if (std::fread(signature, 1, sizeof signature, file.get()) != sizeof signature ||
        png_sig_cmp(signature, 0, sizeof signature) != 0)
        fail(kQ3ErrorInvalidData, path + " is not a PNG file (no PNG signature)");

    ErrorState state;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, onError, onWarning);
    png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
    struct ReadStructs {
        png_structp* png;
        png_infop* info;
        ~ReadStructs() { png_destroy_read_struct(png, info, nullptr); }
    } destroy{&png, &info};
    if (png == nullptr || info == nullptr)
        throw std::bad_alloc();

    png_uint_32 width = 0, height = 0;
    if (!decodeHeader(png, info, file.get(), &width, &height))
        fail(state.code, path + " is not a readable PNG file: " + state.message);
    if (std::uint64_t(width) * height > maxPixels)
        fail(kQ3ErrorValueExceedsMaximumSize, path + " is " + std::to_string(width) + " x " +
                                                  std::to_string(height) + " pixels, more than the " +
                                                  std::to_string(maxPixels) + " allowed");
    Rgba8Image image;
    image.width = width;
    image.height = height;
    image.pixels.resize(std::size_t(width) * height * 4);
    std::vector<png_bytep> rows(height);
    for (std::uint32_t y = 0; y < height; ++y)
        rows[y] = image.pixels.data() + std::size_t(width) * 4 * y;
    if (!decodeRows(png, info, rows.data()))
        fail(state.code, path + " is not a readable PNG file: " + state.message);
    return image;
}

} // namespace q3
