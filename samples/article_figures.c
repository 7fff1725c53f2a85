/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * article_figures OUTDIR: renders every curve figure of the develop article
 * "NURB Curves: A Guide for the Uninitiated" through Q3, one PNG per figure
 * (OUTDIR/figureNN.png, 480 x 360), and writes OUTDIR/index.md listing each
 * figure with its file, knot vector and control points. The figures are
 * built by the q3figures library (samples/figures), which the tests use
 * too, so these are the images the golden tests check.
 */
#define _POSIX_C_SOURCE 200809L

#include "QD3D.h"
#include "QD3DErrors.h"
#include "figures.h"
#include "q3sample_png.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Creates dir and its missing parents, like mkdir -p. */
static int make_directories(const char *dir)
{
    char path[4096];
    size_t i, length = strlen(dir);

    if (length == 0 || length >= sizeof path)
        return 1;
    memcpy(path, dir, length + 1);
    for (i = 1; i <= length; i++) {
        if (path[i] == '/' || path[i] == '\0') {
            char saved = path[i];
            path[i] = '\0';
            if (mkdir(path, 0777) != 0 && errno != EEXIST)
                return 1;
            path[i] = saved;
        }
    }
    return 0;
}

/* Prints Q3's errors and warnings as they are posted. */
static void print_error(TQ3Error firstError, TQ3Error lastError, long reference)
{
    (void)firstError;
    (void)reference;
    fprintf(stderr, "article_figures: Q3 error %d: %s\n", (int)lastError, Q3Error_GetMessage());
}

static void print_warning(TQ3Warning firstWarning, TQ3Warning lastWarning, long reference)
{
    (void)firstWarning;
    (void)reference;
    fprintf(stderr, "article_figures: Q3 warning %d: %s\n", (int)lastWarning,
            Q3Warning_GetMessage());
}

static void write_point(FILE *out, const TQ3RationalPoint4D *p)
{
    if (p->w == 1.0f)
        fprintf(out, "(%g, %g)", p->x, p->y);
    else
        fprintf(out, "(%g, %g) w %g", p->x / p->w, p->y / p->w, p->w);
}

static void write_details(FILE *out, const Q3Figure *figure)
{
    unsigned long c, i;

    fprintf(out, "\n### Figure %d. %s\n\n", figure->number, figure->caption);
    fprintf(out, "![Figure %d](%s.png)\n\n", figure->number, figure->name);
    fprintf(out, "%s.\n\n", figure->description);
    if (figure->plot) {
        const Q3FigCurve *curve = &figure->curves[0];
        fprintf(out, "Each basis function is drawn as a B-spline curve of order %lu on the "
                     "clamped knot vector {", curve->order);
        for (i = 0; i < curve->numPoints + curve->order; i++)
            fprintf(out, "%s%g", i ? ", " : "", curve->knots[i]);
        fprintf(out, "} whose control points are (Greville abscissa, 0 or 1); abscissae:");
        for (i = 0; i < curve->numPoints; i++)
            fprintf(out, " %g", curve->points[i].x);
        fprintf(out, ".\n");
        return;
    }
    for (c = 0; c < figure->numCurves; c++) {
        const Q3FigCurve *curve = &figure->curves[c];
        fprintf(out, "- curve %lu: order %lu, knots {", c + 1, curve->order);
        for (i = 0; i < curve->numPoints + curve->order; i++)
            fprintf(out, "%s%g", i ? ", " : "", curve->knots[i]);
        fprintf(out, "}, %lu control points (x, y) [weight if not 1]:", curve->numPoints);
        for (i = 0; i < curve->numPoints; i++) {
            fprintf(out, " ");
            write_point(out, &curve->points[i]);
        }
        fprintf(out, "%s\n", curve->drawCurve ? "" : " (control polygon only)");
    }
}

int main(int argc, char **argv)
{
    const char *outDir;
    char path[4096];
    unsigned char *rgba;
    FILE *index;
    unsigned long i, count = q3fig_count();
    int failures = 0;

    if (argc != 2) {
        fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
        return 2;
    }
    outDir = argv[1];
    if (make_directories(outDir) != 0) {
        fprintf(stderr, "article_figures: cannot create %s: %s\n", outDir, strerror(errno));
        return 1;
    }
    rgba = malloc(Q3FIG_WIDTH * Q3FIG_HEIGHT * 4);
    snprintf(path, sizeof path, "%s/index.md", outDir);
    index = fopen(path, "w");
    if (rgba == NULL || index == NULL || Q3Initialize() != kQ3Success) {
        fprintf(stderr, "article_figures: cannot start (memory, %s or Q3Initialize)\n", path);
        free(rgba);
        if (index != NULL)
            fclose(index);
        return 1;
    }
    Q3Error_Register(print_error, 0);
    Q3Warning_Register(print_warning, 0);

    fprintf(index, "# The article's curve figures, drawn by Q3\n\n"
                   "Rendered by `article_figures` from the numbers in \"NURB Curves: A Guide for "
                   "the Uninitiated\" (develop). Curves are blue unless stated, control polygons "
                   "gray, control points red squares. The free-form control points (the article "
                   "gives none) are chosen once and shared by Figures 9 to 16 and 22.\n\n"
                   "| Figure | File | Knot vector | Drawn |\n|---|---|---|---|\n");
    for (i = 0; i < count; i++) {
        Q3Figure figure;
        int result;

        if (q3fig_build(i, &figure) != 0) {
            fprintf(stderr, "article_figures: cannot build figure %lu\n", i);
            failures++;
            continue;
        }
        snprintf(path, sizeof path, "%s/%s.png", outDir, figure.name);
        if (q3fig_render(&figure, Q3FIG_WIDTH, Q3FIG_HEIGHT, rgba) != 0) {
            fprintf(stderr, "article_figures: rendering Figure %d failed\n", figure.number);
            failures++;
            continue;
        }
        result = q3sample_write_png(path, rgba, Q3FIG_WIDTH, Q3FIG_HEIGHT);
        if (result != kQ3Success) {
            fprintf(stderr, "article_figures: %s: %s\n", path, Q3Error_GetMessage());
            failures++;
            continue;
        }
        printf("Figure %2d  %s\n", figure.number, path);
        fprintf(index, "| %d. %s | [%s.png](%s.png) | %s | %s |\n", figure.number, figure.caption,
                figure.name, figure.name, figure.knotText, figure.description);
    }
    fprintf(index, "\n## Details\n");
    for (i = 0; i < count; i++) {
        Q3Figure figure;
        if (q3fig_build(i, &figure) == 0)
            write_details(index, &figure);
    }
    fclose(index);
    free(rgba);
    Q3Exit();
    return failures == 0 ? 0 : 1;
}
