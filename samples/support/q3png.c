/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * libpng reports errors by calling an error function that must not return;
 * ours long-jumps back to the setjmp in the public function, which frees what
 * it allocated. Anything assigned after setjmp and used after the jump is
 * volatile (C99 7.13.2.1). The error and warning functions print nothing.
 */

/* lstat is POSIX, not C99. */
#define _POSIX_C_SOURCE 200809L

#include "q3png.h"

#include <png.h>
#include <zlib.h>

#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

/* Fixed so that output bytes depend on the pixels only. The up filter
 * (subtract the row above) suits wireframe images, which are mostly rows
 * equal to the one above. */
#define Q3PNG_ZLIB_LEVEL 6
#define Q3PNG_ROW_FILTER PNG_FILTER_UP

typedef struct {
    int code; /* what a long jump should return; 0 until known */
} ErrorState;

/* Removes what a failed write left behind, but only a regular file: the path
 * may name a device or a symbolic link such as /dev/stdout, which must stay. */
static void discard_partial(const char* path)
{
    struct stat info;
    if (lstat(path, &info) == 0 && S_ISREG(info.st_mode))
        remove(path);
}

static void on_error(png_structp png, png_const_charp message)
{
    ErrorState* state = (ErrorState*)png_get_error_ptr(png);
    (void)message;
    if (state->code == Q3PNG_OK)
        state->code = Q3PNG_ERROR_FORMAT;
    png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp message)
{
    (void)png;
    (void)message;
}

static void write_bytes(png_structp png, png_bytep data, png_size_t length)
{
    FILE* file = (FILE*)png_get_io_ptr(png);
    if (fwrite(data, 1, length, file) != length) {
        ErrorState* state = (ErrorState*)png_get_error_ptr(png);
        state->code = Q3PNG_ERROR_WRITE;
        png_error(png, "write failed");
    }
}

static void flush_bytes(png_structp png)
{
    FILE* file = (FILE*)png_get_io_ptr(png);
    if (fflush(file) != 0) {
        ErrorState* state = (ErrorState*)png_get_error_ptr(png);
        state->code = Q3PNG_ERROR_WRITE;
        png_error(png, "flush failed");
    }
}

const char* q3png_error_string(int code)
{
    switch (code) {
    case Q3PNG_OK:
        return "success";
    case Q3PNG_ERROR_ARGUMENT:
        return "invalid argument";
    case Q3PNG_ERROR_OPEN:
        return "cannot open file";
    case Q3PNG_ERROR_NOT_PNG:
        return "not a PNG file";
    case Q3PNG_ERROR_FORMAT:
        return "corrupt or unsupported PNG data";
    case Q3PNG_ERROR_MEMORY:
        return "out of memory";
    case Q3PNG_ERROR_WRITE:
        return "cannot write file";
    default:
        return "unknown error";
    }
}

static int write_png(const char* path, const unsigned char* pixels, int width, int height, int rowBytes,
                     int channels)
{
    FILE* file;
    png_structp png;
    png_infop info;
    ErrorState state = {Q3PNG_OK};
    int y;

    if (path == NULL || pixels == NULL || width <= 0 || height <= 0 ||
        (long long)rowBytes < (long long)width * channels)
        return Q3PNG_ERROR_ARGUMENT;

    file = fopen(path, "wb");
    if (file == NULL)
        return Q3PNG_ERROR_OPEN;

    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, on_error, on_warning);
    info = png != NULL ? png_create_info_struct(png) : NULL;
    if (png == NULL || info == NULL) {
        png_destroy_write_struct(&png, &info);
        fclose(file);
        discard_partial(path);
        return Q3PNG_ERROR_MEMORY;
    }

    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fclose(file);
        discard_partial(path);
        return state.code;
    }

    png_set_write_fn(png, file, write_bytes, flush_bytes);
    png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 8,
                 channels == 4 ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, Q3PNG_ROW_FILTER);
    png_set_compression_level(png, Q3PNG_ZLIB_LEVEL);
    png_set_compression_strategy(png, Z_DEFAULT_STRATEGY);
    png_set_compression_mem_level(png, 8);
    png_set_compression_window_bits(png, 15);
    png_write_info(png, info);
    for (y = 0; y < height; ++y)
        png_write_row(png, pixels + (size_t)rowBytes * (size_t)y);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);

    if (fclose(file) != 0) {
        discard_partial(path);
        return Q3PNG_ERROR_WRITE;
    }
    return Q3PNG_OK;
}

int q3png_write_rgba8(const char* path, const unsigned char* rgba, int width, int height, int rowBytes)
{
    return write_png(path, rgba, width, height, rowBytes, 4);
}

int q3png_write_rgb8(const char* path, const unsigned char* rgb, int width, int height, int rowBytes)
{
    return write_png(path, rgb, width, height, rowBytes, 3);
}

int q3png_read_rgba8(const char* path, unsigned char** rgba, int* width, int* height)
{
    FILE* file;
    png_structp png;
    png_infop info;
    ErrorState state = {Q3PNG_OK};
    unsigned char signature[8];
    unsigned char* volatile image = NULL;
    png_bytep* volatile rows = NULL;
    png_uint_32 imageWidth, imageHeight, y;
    int colorType, bitDepth, hasTransparency;
    size_t rowSize;

    if (path == NULL || rgba == NULL || width == NULL || height == NULL)
        return Q3PNG_ERROR_ARGUMENT;

    file = fopen(path, "rb");
    if (file == NULL)
        return Q3PNG_ERROR_OPEN;
    if (fread(signature, 1, sizeof signature, file) != sizeof signature ||
        png_sig_cmp(signature, 0, sizeof signature) != 0) {
        fclose(file);
        return Q3PNG_ERROR_NOT_PNG;
    }

    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, on_error, on_warning);
    info = png != NULL ? png_create_info_struct(png) : NULL;
    if (png == NULL || info == NULL) {
        png_destroy_read_struct(&png, &info, NULL);
        fclose(file);
        return Q3PNG_ERROR_MEMORY;
    }

    if (setjmp(png_jmpbuf(png))) {
        free(image);
        free(rows);
        png_destroy_read_struct(&png, &info, NULL);
        fclose(file);
        return state.code;
    }

    png_init_io(png, file);
    png_set_sig_bytes(png, (int)sizeof signature);
    png_read_info(png, info);

    imageWidth = png_get_image_width(png, info);
    imageHeight = png_get_image_height(png, info);
    colorType = png_get_color_type(png, info);
    bitDepth = png_get_bit_depth(png, info);
    hasTransparency = png_get_valid(png, info, PNG_INFO_tRNS) != 0;

    if (colorType == PNG_COLOR_TYPE_PALETTE)
        png_set_palette_to_rgb(png);
    if (colorType == PNG_COLOR_TYPE_GRAY && bitDepth < 8)
        png_set_expand_gray_1_2_4_to_8(png);
    if (hasTransparency)
        png_set_tRNS_to_alpha(png);
    if (bitDepth == 16)
        png_set_strip_16(png);
    if (colorType == PNG_COLOR_TYPE_GRAY || colorType == PNG_COLOR_TYPE_GRAY_ALPHA)
        png_set_gray_to_rgb(png);
    if ((colorType & PNG_COLOR_MASK_ALPHA) == 0 && !hasTransparency)
        png_set_filler(png, 0xFF, PNG_FILLER_AFTER);
    (void)png_set_interlace_handling(png);
    png_read_update_info(png, info);

    if (imageWidth == 0 || imageHeight == 0 || imageWidth > INT_MAX || imageHeight > INT_MAX)
        png_error(png, "bad image size");
    rowSize = (size_t)imageWidth * 4;
    if (png_get_rowbytes(png, info) != rowSize)
        png_error(png, "unexpected row size after transformations");
    if (imageHeight > SIZE_MAX / rowSize) {
        state.code = Q3PNG_ERROR_MEMORY;
        png_error(png, "image too large");
    }

    image = (unsigned char*)malloc(rowSize * imageHeight);
    rows = (png_bytep*)malloc(sizeof(png_bytep) * imageHeight);
    if (image == NULL || rows == NULL) {
        state.code = Q3PNG_ERROR_MEMORY;
        png_error(png, "out of memory");
    }
    for (y = 0; y < imageHeight; ++y)
        rows[y] = image + rowSize * y;
    png_read_image(png, rows);
    png_read_end(png, NULL);

    png_destroy_read_struct(&png, &info, NULL);
    fclose(file);
    free(rows);
    *rgba = image;
    *width = (int)imageWidth;
    *height = (int)imageHeight;
    return Q3PNG_OK;
}
