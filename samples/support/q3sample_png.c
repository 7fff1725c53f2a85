/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#include "q3sample_png.h"

#include "QD3DErrors.h"
#include "Q3PixmapPNG.h"

#include <stdlib.h>

TQ3Status q3sample_write_png(const char *path, const unsigned char *rgba, unsigned long width,
                             unsigned long height)
{
    TQ3Pixmap pixmap;
    TQ3Status status;
    unsigned char *argb;
    unsigned long i;

    if (rgba == NULL || width == 0 || height == 0 || width > (unsigned long)-1 / 4 / height)
        return Q3Pixmap_WritePNG(NULL, path); /* posts kQ3ErrorNULLParameter */
    argb = (unsigned char *)malloc(width * height * 4);
    if (argb == NULL)
        return kQ3Failure;
    /* ARGB32 big-endian: A, R, G, B in memory. */
    for (i = 0; i < width * height; ++i) {
        argb[4 * i + 0] = rgba[4 * i + 3];
        argb[4 * i + 1] = rgba[4 * i + 0];
        argb[4 * i + 2] = rgba[4 * i + 1];
        argb[4 * i + 3] = rgba[4 * i + 2];
    }
    pixmap.image = argb;
    pixmap.width = width;
    pixmap.height = height;
    pixmap.rowBytes = width * 4;
    pixmap.pixelSize = 32;
    pixmap.pixelType = kQ3PixelTypeARGB32;
    pixmap.bitOrder = kQ3EndianBig;
    pixmap.byteOrder = kQ3EndianBig;
    status = Q3Pixmap_WritePNG(&pixmap, path);
    free(argb);
    return status;
}
