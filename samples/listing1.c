/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * listing1 [OUT.png]: runs the develop article's Listing 1 ("Rendering a NURB
 * curve in retained mode") exactly as printed, compiled from the article's
 * text (listing1_retained.c.txt, found through Q3_LISTINGS_DIR), and saves
 * what it drew (default listing1.png). The listing draws with the default
 * attributes, so the curve is white; the background is dark.
 */
#include "QD3D.h"
#include "QD3DErrors.h"
#include "QD3DGeometry.h"
#include "QD3DView.h"
#include "figures.h"
#include "q3sample_png.h"

#include <stdio.h>
#include <stdlib.h>

/* The listing needs a variable `view`, set up with a draw context, a camera
 * and a renderer; its own declarations and statements follow. */
static void run_listing1(TQ3ViewObject view)
{
#include "listing1_retained.c.txt"
}

int main(int argc, char **argv)
{
    /* Listing 1's control points span x 0 to 3 and y 0 to 1. */
    const Q3FigRect frame = {-0.25f, -0.5f, 3.25f, 1.5f};
    const TQ3ColorRGB background = {0.10f, 0.12f, 0.16f};
    const char *path = argc > 1 ? argv[1] : "listing1.png";
    const unsigned long width = 320, height = 240;
    unsigned char *rgba = malloc(width * height * 4);
    Q3FigCanvas canvas;
    int result;

    if (rgba == NULL || Q3Initialize() != kQ3Success) {
        fprintf(stderr, "listing1: cannot start\n");
        free(rgba);
        return 1;
    }
    if (q3fig_canvas_open(&canvas, width, height, &frame, 1, background) != 0) {
        fprintf(stderr, "listing1: cannot make the view (Q3 error %d)\n", (int)Q3Error_Get(NULL));
        free(rgba);
        Q3Exit();
        return 1;
    }
    run_listing1(canvas.view);
    q3fig_canvas_rgba(&canvas, rgba);
    q3fig_canvas_close(&canvas);

    result = q3sample_write_png(path, rgba, width, height);
    free(rgba);
    Q3Exit();
    if (result != kQ3Success) {
        fprintf(stderr, "listing1: %s: %s\n", path, Q3Error_GetMessage());
        return 1;
    }
    printf("listing1: wrote %s\n", path);
    return 0;
}
