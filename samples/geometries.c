/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * render_geometries OUTDIR (built from geometries.c): one picture per QuickDraw 3D geometry type
 * (samples/geometries/gallery.h), each in the wireframe renderer and in the
 * lit interactive renderer, with attribute colours, written as
 * OUTDIR/NAME_wireframe.png and OUTDIR/NAME_lit.png.
 */
#define _POSIX_C_SOURCE 200809L

#include "QD3D.h"
#include "QD3DErrors.h"
#include "gallery.h"
#include "q3sample_png.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

static void print_error(TQ3Error firstError, TQ3Error lastError, long reference)
{
    (void)firstError;
    (void)reference;
    fprintf(stderr, "geometries: Q3 error %d: %s\n", (int)lastError, Q3Error_GetMessage());
}

int main(int argc, char **argv)
{
    static unsigned char rgba[Q3GALLERY_WIDTH * Q3GALLERY_HEIGHT * 4];
    char path[4096];
    unsigned long i;
    int lit, failures = 0;

    if (argc != 2) {
        fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
        return 2;
    }
    if (mkdir(argv[1], 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "geometries: cannot create %s: %s\n", argv[1], strerror(errno));
        return 1;
    }
    if (Q3Initialize() != kQ3Success)
        return 1;
    Q3Error_Register(print_error, 0);
    for (i = 0; i < q3gallery_count(); i++)
        for (lit = 0; lit <= 1; lit++) {
            int written;
            if (q3gallery_render(i, lit, Q3GALLERY_WIDTH, Q3GALLERY_HEIGHT, rgba) != 0) {
                fprintf(stderr, "geometries: %s could not be drawn\n", q3gallery_name(i));
                failures++;
                continue;
            }
            snprintf(path, sizeof path, "%s/%s_%s.png", argv[1], q3gallery_name(i), lit ? "lit" : "wireframe");
            written = q3sample_write_png(path, rgba, Q3GALLERY_WIDTH, Q3GALLERY_HEIGHT);
            if (written != kQ3Success) {
                fprintf(stderr, "geometries: %s: %s\n", path, Q3Error_GetMessage());
                failures++;
            }
        }
    Q3Exit();
    return failures == 0 ? 0 : 1;
}
