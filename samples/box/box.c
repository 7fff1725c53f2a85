/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * box OUTDIR [FRAMES]: Apple's Box sample's scene (box_document.h) drawn for
 * FRAMES frames (default 4) into a 320 x 240 pixmap, each frame written as
 * OUTDIR/box_frame_N.png.
 */
#define _POSIX_C_SOURCE 200809L

#include "QD3D.h"
#include "QD3DErrors.h"
#include "box_document.h"
#include "q3sample_png.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

enum { kWidth = 320, kHeight = 240 };

static void print_error(TQ3Error firstError, TQ3Error lastError, long reference)
{
    (void)firstError;
    (void)reference;
    fprintf(stderr, "box: Q3 error %d: %s\n", (int)lastError, Q3Error_GetMessage());
}

int main(int argc, char **argv)
{
    static unsigned char rgba[kWidth * kHeight * 4];
    char path[4096];
    BoxDocument *document;
    unsigned long frames = 4, frame;
    int failures = 0;

    if (argc < 2 || argc > 3 || (argc == 3 && (frames = strtoul(argv[2], NULL, 10)) == 0)) {
        fprintf(stderr, "usage: %s OUTDIR [FRAMES]\n", argv[0]);
        return 2;
    }
    if (mkdir(argv[1], 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "box: cannot create %s: %s\n", argv[1], strerror(errno));
        return 1;
    }
    if (Q3Initialize() != kQ3Success)
        return 1;
    Q3Error_Register(print_error, 0);
    document = box_document_new(kWidth, kHeight);
    if (document == NULL) {
        fprintf(stderr, "box: cannot build the document\n");
        Q3Exit();
        return 1;
    }
    for (frame = 0; frame < frames; frame++) {
        int written;
        if (box_document_draw(document, frame, rgba) != 0) {
            fprintf(stderr, "box: frame %lu could not be drawn\n", frame);
            failures++;
            continue;
        }
        snprintf(path, sizeof path, "%s/box_frame_%lu.png", argv[1], frame);
        written = q3sample_write_png(path, rgba, kWidth, kHeight);
        if (written != kQ3Success) {
            fprintf(stderr, "box: %s: %s\n", path, Q3Error_GetMessage());
            failures++;
        }
    }
    box_document_dispose(document);
    Q3Exit();
    return failures == 0 ? 0 : 1;
}
