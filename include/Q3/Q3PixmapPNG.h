/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Q3PixmapPNG.h: Q3 extension. PNG files of pixmaps: writing what a pixmap
 * draw context has drawn, or any TQ3Pixmap, to a PNG file, and reading a PNG
 * file into a new pixmap. QuickDraw 3D never had these calls; they exist for
 * golden-image tests (docs/golden-testing.md) and for loading textures.
 *
 * Pixels are converted as QD3DDrawContext.h describes each pixel type: a
 * 5- or 6-bit channel is written as 8 bits by bit replication ((v << 3) |
 * (v >> 2), the PNG specification's scaling), and an sBIT chunk records its
 * real depth; reading rounds 8 bits back to the nearest 5- or 6-bit value,
 * which gives back every written value exactly. Types with alpha
 * (kQ3PixelTypeARGB32, kQ3PixelTypeARGB16) are written as RGBA PNG files, the
 * others as RGB. So a pixmap written and read back with the same pixel type
 * and byte order has every bit it had, except the bits a type ignores (the
 * top byte of kQ3PixelTypeRGB32, bit 15 of kQ3PixelTypeRGB16), which read back
 * as ones, as Q3 draws them.
 *
 * Written files are deterministic: no time stamp or other ancillary chunk
 * but sBIT, no interlacing, one fixed row filter and zlib level, so the same
 * pixels give byte-identical files (for a given libpng and zlib).
 *
 * Reading accepts any PNG file (gray, palette, RGB, with or without alpha or
 * a tRNS chunk, 1 to 16 bits per channel, interlaced or not): 16-bit channels
 * keep their high byte; without alpha, alpha reads as opaque.
 *
 * Conventions shared by every function here, as in QD3DDrawContext.h: a call
 * that fails posts exactly one error and leaves every output unchanged; no
 * partly written regular file is left behind. The checks run in this order,
 * and the first that fails decides the error: Q3 is initialized; the
 * arguments from left to right (a handle: not NULL, a live Q3 object, of the
 * right class; a pointer: not NULL); then the function's other conditions in
 * the order it lists them.
 */
#ifndef Q3PIXMAPPNG_H
#define Q3PIXMAPPNG_H

#include "QD3D.h"
#include "QD3DDrawContext.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Q3 extension constant.
 *
 * kQ3PixmapPNGMaxPixels
 *   The most pixels (width times height) Q3Pixmap_ReadPNG reads: 2^28, a
 *   16384 x 16384 image, the largest Q3 renders. A larger file posts
 *   kQ3ErrorValueExceedsMaximumSize before anything is allocated.
 */
#define kQ3PixmapPNGMaxPixels 268435456UL

/**
 * Q3 extension. Writes the image a pixmap draw context renders into (its
 * pixmap's current pixels, whatever has been drawn so far) to a PNG file.
 *
 * @param drawContext  a pixmap draw context.
 * @param path         the file to write, replaced if it exists.
 * @return kQ3Success, or kQ3Failure with no file written.
 *
 * Errors:
 *   kQ3ErrorNotInitialized           Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter            drawContext or path is NULL.
 *   kQ3ErrorInvalidObject            drawContext is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType        drawContext is not a pixmap draw context.
 *   then the errors of Q3Pixmap_WritePNG for its pixmap.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapDrawContext_WritePNG(TQ3DrawContextObject drawContext, const char *path);

/**
 * Q3 extension. Writes a pixmap to a PNG file (RGBA for a pixel type with
 * alpha, RGB otherwise; see the top of this header).
 *
 * @param pixmap  the pixmap; it must obey the TQ3Pixmap rules of
 *                QD3DDrawContext.h.
 * @param path    the file to write, replaced if it exists.
 * @return kQ3Success, or kQ3Failure with no file written.
 *
 * Errors:
 *   kQ3ErrorNotInitialized           Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter            pixmap or path is NULL.
 *   then the codes of the TQ3Pixmap rules, in their order:
 *   kQ3ErrorNULLParameter            pixmap->image is NULL.
 *   kQ3ErrorInvalidData              pixelType, byteOrder or bitOrder is not
 *                                    a value of its enumeration.
 *   kQ3ErrorUnsupportedPixelDepth    pixelSize does not fit pixelType.
 *   kQ3ErrorInvalidData              width or height is 0, or rowBytes is too
 *                                    small for a row.
 *   kQ3ErrorValueExceedsMaximumSize  width or height is above 2^31 - 1, the
 *                                    PNG format's limit.
 *   kQ3ErrorFileNotOpen              path cannot be opened for writing (the
 *                                    message gives the system's reason).
 *   kQ3ErrorWroteLessThanSize        writing or closing the file failed (a
 *                                    full disk); the partial file is removed.
 *
 * Ownership: no references change; the image memory stays the caller's.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pixmap_WritePNG(const TQ3Pixmap *pixmap, const char *path);

/**
 * Q3 extension. Reads a PNG file into a new pixmap of the given pixel type
 * and byte order (any PNG file; see the top of this header).
 *
 * @param path       the file to read.
 * @param pixelType  the pixel type of the new pixmap.
 * @param byteOrder  its byte order.
 * @param pixmap     receives the pixmap: image is new memory of
 *                   rowBytes * height bytes, rows packed (rowBytes is width
 *                   times the bytes of a pixel), pixelSize the type's size,
 *                   bitOrder equal to byteOrder.
 * @return kQ3Success, or kQ3Failure with *pixmap unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized           Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter            path or pixmap is NULL.
 *   kQ3ErrorInvalidParameter         pixelType is not a TQ3PixelType value
 *                                    or byteOrder not a TQ3Endian value.
 *   kQ3ErrorFileNotOpen              path cannot be opened for reading (the
 *                                    message gives the system's reason).
 *   kQ3ErrorInvalidData              the file is not a PNG file, or is
 *                                    corrupt or truncated.
 *   kQ3ErrorValueExceedsMaximumSize  the image has more than
 *                                    kQ3PixmapPNGMaxPixels pixels.
 *   kQ3ErrorOutOfMemory              the image memory cannot be allocated.
 *
 * Ownership: the caller owns pixmap->image and releases it with
 * Q3Pixmap_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pixmap_ReadPNG(const char *path, TQ3PixelType pixelType, TQ3Endian byteOrder,
                                            TQ3Pixmap *pixmap);

/**
 * Q3 extension. Releases the image memory of a pixmap that Q3Pixmap_ReadPNG
 * filled in and sets image to NULL; the other fields are left as they are. A
 * pixmap whose image is already NULL is left alone.
 *
 * @param pixmap  a pixmap from Q3Pixmap_ReadPNG.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   pixmap is NULL.
 *
 * Ownership: the image memory is freed; it must have come from
 * Q3Pixmap_ReadPNG (Q3 cannot tell otherwise).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pixmap_EmptyData(TQ3Pixmap *pixmap);

#ifdef __cplusplus
}
#endif

#endif /* Q3PIXMAPPNG_H */
