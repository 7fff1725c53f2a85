/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3PNG_H
#define Q3PNG_H

/*
 * q3png: just enough PNG for the samples and the tests (C99, on libpng).
 *
 * Written files are deterministic: no time stamp or other ancillary chunk, no
 * interlacing, one fixed row filter and a fixed zlib level, so rewriting a
 * golden image from identical pixels gives a byte-identical file (for a given
 * libpng and zlib).
 *
 * Every function returns Q3PNG_OK (0) on success and one of the nonzero codes
 * below on failure; on failure nothing is leaked, no output pointer is set,
 * and a partly written regular file is removed. Nothing is printed.
 */

#ifdef __cplusplus
extern "C" {
#endif

enum {
    Q3PNG_OK = 0,
    Q3PNG_ERROR_ARGUMENT = 1, /* NULL pointer, size <= 0 or rowBytes too small */
    Q3PNG_ERROR_OPEN = 2,     /* the file could not be opened */
    Q3PNG_ERROR_NOT_PNG = 3,  /* the file does not start with the PNG signature */
    Q3PNG_ERROR_FORMAT = 4,   /* libpng rejected the data (corrupt or truncated) */
    Q3PNG_ERROR_MEMORY = 5,   /* out of memory, or the image is too large */
    Q3PNG_ERROR_WRITE = 6     /* writing or closing the file failed */
};

/* A short English description of a return code ("unknown error" for others). */
const char* q3png_error_string(int code);

/*
 * Writes an 8-bit RGBA PNG. rgba holds height rows, top row first, each of
 * width pixels R, G, B, A; consecutive rows start rowBytes apart
 * (rowBytes >= width * 4).
 */
int q3png_write_rgba8(const char* path, const unsigned char* rgba, int width, int height, int rowBytes);

/* As q3png_write_rgba8 for 3-byte R, G, B pixels (rowBytes >= width * 3). */
int q3png_write_rgb8(const char* path, const unsigned char* rgb, int width, int height, int rowBytes);

/*
 * Reads any PNG (gray, palette, RGB, with or without alpha, 1 to 16 bits,
 * interlaced or not) as 8-bit RGBA: *rgba receives width * height * 4 bytes,
 * top row first, rows packed, allocated with malloc (the caller frees it).
 * Missing alpha reads as 255; 16-bit channels keep their high byte.
 */
int q3png_read_rgba8(const char* path, unsigned char** rgba, int* width, int* height);

#ifdef __cplusplus
}
#endif

#endif /* Q3PNG_H */
