/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3FIGURES_H
#define Q3FIGURES_H

/*
 * q3figures: the curve figures of the develop article "NURB Curves: A Guide
 * for the Uninitiated", rebuilt from the numbers the article gives and drawn
 * through Q3's public C API only. The sample article_figures writes them as
 * PNG files; the tests render the same figures and compare them with golden
 * images, and check their geometry numerically.
 *
 * A figure is plain data (Q3Figure): a few NURB curves, each drawn with or
 * without its control polygon and control-point markers, and the rectangle
 * of the xy plane the figure shows. q3fig_build fills one in; q3fig_render
 * draws it into an RGBA image; q3fig_submit draws it inside a rendering
 * loop the caller runs (the tests use that to reach the loop's state).
 *
 * The article gives no coordinates for its free-form control points, so one
 * set (q3fig_free_form_points) is chosen here and used by Figures 9 to 16
 * and 22, as the article uses one set across them. The basis-function plots
 * (Figures 7, 10, 12 and 14) are themselves B-spline curves: see
 * q3fig_basis_plot_curve.
 *
 * Only the functions that draw (q3fig_canvas_open, q3fig_submit,
 * q3fig_render, q3fig_canvas_close) need Q3 initialized; the rest work on
 * plain data. Functions returning int return 0 on success.
 */

#include "QD3D.h"
#include "QD3DGeometry.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    Q3FIG_MAX_POINTS = 16,  /* control points per curve */
    Q3FIG_MAX_KNOTS = 32,   /* knots per curve */
    Q3FIG_MAX_CURVES = 6,   /* curves per figure */
    Q3FIG_WIDTH = 480,      /* the size the sample and the goldens use */
    Q3FIG_HEIGHT = 360
};

/* A rectangle of the xy plane, in world units. */
typedef struct Q3FigRect {
    float xMin, yMin, xMax, yMax;
} Q3FigRect;

/* One NURB curve of a figure and how to draw it. */
typedef struct Q3FigCurve {
    unsigned long order;
    unsigned long numPoints;
    TQ3RationalPoint4D points[Q3FIG_MAX_POINTS]; /* homogeneous, as Q3 takes them */
    float knots[Q3FIG_MAX_KNOTS];                /* numPoints + order of them */
    int drawCurve;                               /* draw the curve itself */
    int drawControls;                            /* draw the control polygon and markers */
    TQ3ColorRGB curveColor;
    TQ3ColorRGB polygonColor;
    TQ3ColorRGB pointColor;
} Q3FigCurve;

/* A figure: what the article shows, as data. */
typedef struct Q3Figure {
    int number;              /* the article's figure number */
    char name[16];           /* file stem, e.g. "figure09" */
    const char *caption;     /* the article's caption */
    const char *knotText;    /* the knot vector(s), as text */
    const char *description; /* what is drawn, with the numbers chosen here */
    Q3FigRect frame;         /* the part of the plane to show */
    int plot;                /* a function plot: t axis, knot ticks, stretched frame */
    unsigned long numCurves;
    Q3FigCurve curves[Q3FIG_MAX_CURVES];
} Q3Figure;

/* The number of figures q3fig_build knows, in article order. */
unsigned long q3fig_count(void);

/* Fills *figure with figure number index (0 to q3fig_count() - 1). */
int q3fig_build(unsigned long index, Q3Figure *figure);

/* Fills *figure with the article's Figure `number` if it is one of them. */
int q3fig_find(int number, Q3Figure *figure);

/*
 * The five free-form control points (z = 0, weight 1) shared by Figures 9
 * to 16 and 22.
 */
const TQ3RationalPoint4D *q3fig_free_form_points(void);

/*
 * A TQ3NURBCurveData describing curve (arrays point into *curve; no
 * attribute set).
 */
TQ3NURBCurveData q3fig_curve_data(Q3FigCurve *curve);

/*
 * Inserts the knot tNew into a curve (Boehm's algorithm, the article's
 * "THE ALGORITHM", on homogeneous points in double precision): the result
 * has one more control point and knot and the same shape. tNew must lie in
 * the curve's domain [x(k-1), x(n)) and the result must fit the capacity.
 * The drawing fields are copied.
 */
int q3fig_insert_knot(const Q3FigCurve *curve, float tNew, Q3FigCurve *result);

/*
 * The plot of basis function N(i,k) of a knot vector (numPoints + order
 * knots) against t, as a B-spline curve: t -> (t, N(i,k)(t)) is the curve
 * with control points (g_j, delta_ij), where g_j are the Greville abscissae
 * (x(j+1) + ... + x(j+k-1)) / (k - 1). That identity (linear precision)
 * holds where the basis sums to 1, so the knot vector is first clamped by
 * repeating its end values until each occurs `order` times; the plot then
 * covers the whole knot range, and N(i,k) of the original knot vector is
 * one of the clamped basis functions because it depends only on knots
 * x(i) to x(i+k), which the clamping keeps in place.
 */
int q3fig_basis_plot_curve(const float *knots, unsigned long numPoints, unsigned long order,
                           unsigned long i, Q3FigCurve *result);

/* ---- Rendering ----------------------------------------------------------- */

/*
 * A view drawing into memory of ours: a pixmap draw context (32-bit ARGB,
 * big-endian), an orthographic camera looking down -z at `frame`, and the
 * interactive renderer.
 */
typedef struct Q3FigCanvas {
    unsigned long width;
    unsigned long height;
    Q3FigRect frame;      /* the rectangle shown, edge to edge */
    unsigned char *argb;  /* width * height pixels: A, R, G, B bytes */
    TQ3ViewObject view;
} Q3FigCanvas;

/*
 * Makes a canvas showing *frame; with keepAspect the frame is widened in x
 * or y about its centre so that pixels are square. On failure *canvas is
 * left empty (closing it does nothing).
 */
int q3fig_canvas_open(Q3FigCanvas *canvas, unsigned long width, unsigned long height,
                      const Q3FigRect *frame, int keepAspect, TQ3ColorRGB background);

/*
 * The rectangle a canvas of width x height shows for *frame when it keeps
 * square pixels: *frame widened in x or y about its centre.
 */
void q3fig_fit_frame(const Q3FigRect *frame, unsigned long width, unsigned long height,
                     Q3FigRect *shown);

/* Disposes the view and frees the pixels. */
void q3fig_canvas_close(Q3FigCanvas *canvas);

/* Copies the canvas pixels as R, G, B, A bytes, rows packed, top row first. */
void q3fig_canvas_rgba(const Q3FigCanvas *canvas, unsigned char *rgba);

/* Where a point of the plane lands in the image, in pixels from the top-left corner. */
void q3fig_canvas_pixel(const Q3FigCanvas *canvas, float x, float y, float *px, float *py);

/*
 * Submits a figure to canvas->view inside a rendering loop: a constant
 * subdivision style (Q3FIG_SEGMENTS_PER_SPAN), then the control polygons,
 * the curves and the control-point markers (later ones are drawn over
 * earlier ones), and for a plot its t axis, knot ticks and the line N = 1.
 */
TQ3Status q3fig_submit(const Q3Figure *figure, const Q3FigCanvas *canvas);

/* Segments per knot span the figures are drawn with. */
#define Q3FIG_SEGMENTS_PER_SPAN 48.0f

/* The white the figures are drawn on. */
TQ3ColorRGB q3fig_background(void);

/*
 * Renders a figure into width x height RGBA pixels (rgba holds
 * width * height * 4 bytes).
 */
int q3fig_render(const Q3Figure *figure, unsigned long width, unsigned long height,
                 unsigned char *rgba);

#ifdef __cplusplus
}
#endif

#endif /* Q3FIGURES_H */
