/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3SAMPLE_PNG_H
#define Q3SAMPLE_PNG_H

/*
 * The samples' PNG writer, a user of Q3's own extension Q3PixmapPNG.h: the
 * samples hand their pictures around as 8-bit RGBA rows (R, G, B, A, top row
 * first, rows packed), which this wraps in an ARGB32 pixmap for
 * Q3Pixmap_WritePNG. The files are the bytes q3png.c writes for the same
 * pixels (same PNG settings). Q3 must be initialized; on failure the Q3
 * error is posted (Q3Error_GetMessage says why) and nothing is left at path.
 */

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

TQ3Status q3sample_write_png(const char *path, const unsigned char *rgba, unsigned long width,
                             unsigned long height);

#ifdef __cplusplus
}
#endif

#endif /* Q3SAMPLE_PNG_H */
