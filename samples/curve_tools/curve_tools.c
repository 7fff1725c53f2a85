/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * curve_tools OUTDIR: the curve tools of Q3NURBCurveTools.h at work.
 *
 *   OUTDIR/figure22_insert_knot.png  the article's Figure 22, with the knot
 *       inserted by Q3NURBCurveData_InsertKnot instead of Listing 2;
 *   OUTDIR/interpolation.png  cubics through eight points
 *       (Q3NURBCurveData_Interpolate, chord-length and centripetal) and a
 *       least-squares cubic (Q3NURBCurveData_Approximate).
 *
 * It also prints what the tools report about the curves: the new control
 * points of Figure 22, and for the interpolating cubic its length, the
 * parameter halfway along it, its curvature there and how far each point is
 * from the curve.
 */
#define _POSIX_C_SOURCE 200809L

#include "Q3NURBCurveTools.h"
#include "QD3D.h"
#include "QD3DErrors.h"
#include "figures.h"
#include "q3sample_png.h"
#include "tool_figures.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static void print_error(TQ3Error firstError, TQ3Error lastError, long reference)
{
    (void)firstError;
    (void)reference;
    fprintf(stderr, "curve_tools: Q3 error %d: %s\n", (int)lastError, Q3Error_GetMessage());
}

static void print_warning(TQ3Warning firstWarning, TQ3Warning lastWarning, long reference)
{
    (void)firstWarning;
    (void)reference;
    fprintf(stderr, "curve_tools: Q3 warning %d: %s\n", (int)lastWarning, Q3Warning_GetMessage());
}

static int write_figure(const Q3Figure *figure, const char *outDir, const char *file, unsigned char *rgba)
{
    char path[4096];
    int result;

    snprintf(path, sizeof path, "%s/%s", outDir, file);
    if (q3fig_render(figure, Q3FIG_WIDTH, Q3FIG_HEIGHT, rgba) != 0) {
        fprintf(stderr, "curve_tools: rendering %s failed\n", file);
        return 1;
    }
    result = q3sample_write_png(path, rgba, Q3FIG_WIDTH, Q3FIG_HEIGHT);
    if (result != kQ3Success) {
        fprintf(stderr, "curve_tools: %s: %s\n", path, Q3Error_GetMessage());
        return 1;
    }
    printf("wrote %s\n", path);
    return 0;
}

static void report_figure22(const Q3Figure *figure)
{
    const Q3FigCurve *after = &figure->curves[1];
    unsigned long i;

    printf("Figure 22: knot %g inserted; knots", Q3TOOLS_FIGURE22_KNOT);
    for (i = 0; i < after->numPoints + after->order; i++)
        printf(" %g", after->knots[i]);
    printf("\n  control points:");
    for (i = 0; i < after->numPoints; i++)
        printf(" (%g, %g)", after->points[i].x / after->points[i].w, after->points[i].y / after->points[i].w);
    printf("\n");
}

static int report_interpolation(const Q3Figure *figure)
{
    /* The last curve of the figure is the chord-length cubic. */
    Q3FigCurve curve = figure->curves[figure->numCurves - 1];
    TQ3NURBCurveData data = q3fig_curve_data(&curve);
    const TQ3Point3D *points = q3tools_interpolated_points();
    float length = 0.0f, half = 0.0f, curvature = 0.0f, worst = 0.0f;
    unsigned long i;

    if (Q3NURBCurveData_GetArcLength(&data, 0.0f, 1.0f, 1e-5f, &length) != kQ3Success ||
        Q3NURBCurveData_GetParameterAtLength(&data, 0.0f, 0.5f * length, 1e-5f, &half) != kQ3Success ||
        Q3NURBCurveData_GetCurvature(&data, half, &curvature) != kQ3Success)
        return 1;
    for (i = 0; i < Q3TOOLS_INTERPOLATED_POINTS; i++) {
        float t;
        TQ3Point3D closest;
        float dx, dy, dz;
        if (Q3NURBCurveData_GetClosestPoint(&data, &points[i], &t, &closest) != kQ3Success)
            return 1;
        dx = closest.x - points[i].x;
        dy = closest.y - points[i].y;
        dz = closest.z - points[i].z;
        if (sqrtf(dx * dx + dy * dy + dz * dz) > worst)
            worst = sqrtf(dx * dx + dy * dy + dz * dz);
    }
    printf("Interpolating cubic: length %.6g; halfway along at t = %.6g, curvature %.6g there; "
           "farthest point from the curve %.3g\n",
           length, half, curvature, worst);
    return 0;
}

int main(int argc, char **argv)
{
    Q3Figure figure22, interpolation;
    unsigned char *rgba;
    int failures = 0;

    if (argc != 2) {
        fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
        return 2;
    }
    if (mkdir(argv[1], 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "curve_tools: cannot create %s: %s\n", argv[1], strerror(errno));
        return 1;
    }
    rgba = malloc(Q3FIG_WIDTH * Q3FIG_HEIGHT * 4);
    if (rgba == NULL || Q3Initialize() != kQ3Success) {
        fprintf(stderr, "curve_tools: cannot start (memory or Q3Initialize)\n");
        free(rgba);
        return 1;
    }
    Q3Error_Register(print_error, 0);
    Q3Warning_Register(print_warning, 0);

    if (q3tools_figure22(&figure22) == 0) {
        report_figure22(&figure22);
        failures += write_figure(&figure22, argv[1], "figure22_insert_knot.png", rgba);
    } else {
        fprintf(stderr, "curve_tools: cannot build Figure 22\n");
        failures++;
    }
    if (q3tools_interpolation(&interpolation) == 0 && report_interpolation(&interpolation) == 0) {
        failures += write_figure(&interpolation, argv[1], "interpolation.png", rgba);
    } else {
        fprintf(stderr, "curve_tools: cannot build the interpolation figure\n");
        failures++;
    }
    free(rgba);
    Q3Exit();
    return failures == 0 ? 0 : 1;
}
