/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * The article's curve figures as data, and their drawing. The numbers come
 * from the article's text: the knot vectors of Figures 7 to 15 ("KNOTS",
 * "KNOTS AND KINKS"), the conic-arc rules of Figure 18 ("CONIC SECTIONS"),
 * the circular-arc construction of Figure 19 (isosceles control triangle,
 * inner weight cos(theta)), the one-curve circles of Figures 20 and 21 and
 * the knot inserted at t = 3.6 for Figure 22 ("KNOT INSERTION"). Where the
 * article gives no numbers (the free-form control points, which weight
 * Figure 16 raises, the conic arcs' triangle) this file chooses them, once.
 */
#include "figures.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DView.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Pixels from a control-point marker's centre to its edge (a 7-pixel square). */
#define MARKER_HALF_SIZE 3.0f
/* Pixels per unit of multiplicity of a knot tick below a plot's t axis. */
#define TICK_LENGTH 5.0f

static const TQ3ColorRGB kCurveBlue = {0.08f, 0.24f, 0.62f};
static const TQ3ColorRGB kPolygonGray = {0.60f, 0.60f, 0.60f};
static const TQ3ColorRGB kPointRed = {0.82f, 0.08f, 0.08f};
static const TQ3ColorRGB kPaleBlue = {0.60f, 0.74f, 0.94f};
static const TQ3ColorRGB kGuideGray = {0.84f, 0.84f, 0.84f};
static const TQ3ColorRGB kAxisGray = {0.30f, 0.30f, 0.30f};
static const TQ3ColorRGB kDarkGray = {0.25f, 0.25f, 0.25f};
static const TQ3ColorRGB kOrange = {0.93f, 0.46f, 0.00f};
static const TQ3ColorRGB kGreen = {0.10f, 0.56f, 0.16f};

/* One colour per basis function of the plots, B0 to B4. */
static const TQ3ColorRGB kBasisColors[5] = {
    {0.08f, 0.24f, 0.62f}, {0.82f, 0.08f, 0.08f}, {0.10f, 0.56f, 0.16f},
    {0.93f, 0.46f, 0.00f}, {0.52f, 0.18f, 0.70f},
};

/*
 * The free-form control points B0 to B4: a zigzag, so that the effects the
 * article describes show: the curve is pulled towards B2 and B3 by the
 * narrow knot intervals of Figure 11, starts at B0 in Figure 13, passes
 * through B2 with a kink in Figure 15, and is pulled towards B2 by its
 * weight in Figure 16.
 */
static const TQ3RationalPoint4D kFreeForm[5] = {
    {0.0f, 0.5f, 0.0f, 1.0f},
    {1.5f, 3.5f, 0.0f, 1.0f},
    {3.0f, 0.5f, 0.0f, 1.0f},
    {4.5f, 3.0f, 0.0f, 1.0f},
    {6.0f, 1.0f, 0.0f, 1.0f},
};

/* The knot vectors of the article's free-form curves: order 3, 5 points, 8 knots. */
static const float kUniformKnots[8] = {0, 1, 2, 3, 4, 5, 6, 7};
static const float kNonuniformKnots[8] = {0, 1, 2, 3.75f, 4, 4.25f, 6, 7};
static const float kStartKnots[8] = {0, 0, 0, 3, 4, 5, 6, 7};
static const float kMiddleKnots[8] = {0, 1, 2, 3, 3, 5, 6, 7};

/* Figure 16: the weight given to B2. */
#define RAISED_WEIGHT 3.0f
/* Figure 22: the knot inserted. */
#define INSERTED_KNOT 3.6f

const TQ3RationalPoint4D *q3fig_free_form_points(void)
{
    return kFreeForm;
}

TQ3ColorRGB q3fig_background(void)
{
    TQ3ColorRGB white = {1.0f, 1.0f, 1.0f};
    return white;
}

TQ3NURBCurveData q3fig_curve_data(Q3FigCurve *curve)
{
    TQ3NURBCurveData data;
    data.order = curve->order;
    data.numPoints = curve->numPoints;
    data.controlPoints = curve->points;
    data.knots = curve->knots;
    data.curveAttributeSet = NULL;
    return data;
}

/* ---- Building curves ----------------------------------------------------- */

/* A curve with the usual look: blue curve, gray polygon, red markers. */
static Q3FigCurve *add_curve(Q3Figure *figure, unsigned long order, unsigned long numPoints,
                             const TQ3RationalPoint4D *points, const float *knots)
{
    Q3FigCurve *curve = &figure->curves[figure->numCurves++];
    unsigned long i;

    memset(curve, 0, sizeof *curve);
    curve->order = order;
    curve->numPoints = numPoints;
    for (i = 0; i < numPoints; i++)
        curve->points[i] = points[i];
    for (i = 0; i < numPoints + order; i++)
        curve->knots[i] = knots[i];
    curve->drawCurve = 1;
    curve->drawControls = 1;
    curve->curveColor = kCurveBlue;
    curve->polygonColor = kPolygonGray;
    curve->pointColor = kPointRed;
    return curve;
}

/* Sets a control point from its position and weight (stored homogeneous). */
static void set_weighted(TQ3RationalPoint4D *point, double x, double y, double w)
{
    point->x = (float)(x * w);
    point->y = (float)(y * w);
    point->z = 0.0f;
    point->w = (float)w;
}

/* Frames the control points of every curve, with a margin. */
static void frame_control_points(Q3Figure *figure, float margin)
{
    float xMin = 1e30f, yMin = 1e30f, xMax = -1e30f, yMax = -1e30f;
    unsigned long c, i;

    for (c = 0; c < figure->numCurves; c++) {
        const Q3FigCurve *curve = &figure->curves[c];
        for (i = 0; i < curve->numPoints; i++) {
            float x = curve->points[i].x / curve->points[i].w;
            float y = curve->points[i].y / curve->points[i].w;
            xMin = x < xMin ? x : xMin;
            xMax = x > xMax ? x : xMax;
            yMin = y < yMin ? y : yMin;
            yMax = y > yMax ? y : yMax;
        }
    }
    figure->frame.xMin = xMin - margin;
    figure->frame.xMax = xMax + margin;
    figure->frame.yMin = yMin - margin;
    figure->frame.yMax = yMax + margin;
}

static void name_figure(Q3Figure *figure, int number, const char *caption, const char *knotText,
                        const char *description)
{
    memset(figure, 0, sizeof *figure);
    figure->number = number;
    snprintf(figure->name, sizeof figure->name, "figure%02d", number);
    figure->caption = caption;
    figure->knotText = knotText;
    figure->description = description;
}

int q3fig_insert_knot(const Q3FigCurve *curve, float tNew, Q3FigCurve *result)
{
    const unsigned long k = curve->order;
    const unsigned long n = curve->numPoints;
    const float *x = curve->knots;
    Q3FigCurve out;
    unsigned long span, j;

    if (k < 2 || n < k || n + 1 > Q3FIG_MAX_POINTS || n + k + 1 > Q3FIG_MAX_KNOTS)
        return 1;
    if (!(tNew >= x[k - 1] && tNew < x[n]))
        return 1;
    /* The span holding tNew: x[span] <= tNew < x[span + 1], k - 1 <= span <= n - 1. */
    span = k - 1;
    while (span + 1 < n && x[span + 1] <= tNew)
        span++;

    out = *curve;
    out.numPoints = n + 1;
    for (j = 0; j <= n + k; j++) {
        if (j <= span)
            out.knots[j] = x[j];
        else if (j == span + 1)
            out.knots[j] = tNew;
        else
            out.knots[j] = x[j - 1];
    }
    for (j = 0; j <= n; j++) {
        if (j + k <= span + 1) {
            out.points[j] = curve->points[j];
        } else if (j <= span) {
            /* span - k + 2 <= j <= span, so x[j] <= tNew < x[j + k - 1]. */
            const TQ3RationalPoint4D *p = &curve->points[j - 1];
            const TQ3RationalPoint4D *q = &curve->points[j];
            double a = ((double)tNew - x[j]) / ((double)x[j + k - 1] - x[j]);
            out.points[j].x = (float)((1.0 - a) * p->x + a * q->x);
            out.points[j].y = (float)((1.0 - a) * p->y + a * q->y);
            out.points[j].z = (float)((1.0 - a) * p->z + a * q->z);
            out.points[j].w = (float)((1.0 - a) * p->w + a * q->w);
        } else {
            out.points[j] = curve->points[j - 1];
        }
    }
    *result = out;
    return 0;
}

int q3fig_basis_plot_curve(const float *knots, unsigned long numPoints, unsigned long order,
                           unsigned long i, Q3FigCurve *result)
{
    const unsigned long count = numPoints + order;
    unsigned long startMultiplicity = 1, endMultiplicity = 1;
    unsigned long padStart, padEnd, plotPoints, j, l;
    float extended[Q3FIG_MAX_KNOTS];

    if (order < 2 || numPoints < order || i >= numPoints)
        return 1;
    while (startMultiplicity < count && knots[startMultiplicity] == knots[0])
        startMultiplicity++;
    while (endMultiplicity < count && knots[count - 1 - endMultiplicity] == knots[count - 1])
        endMultiplicity++;
    if (startMultiplicity > order || endMultiplicity > order)
        return 1;
    padStart = order - startMultiplicity;
    padEnd = order - endMultiplicity;
    plotPoints = numPoints + padStart + padEnd;
    if (plotPoints > Q3FIG_MAX_POINTS || plotPoints + order > Q3FIG_MAX_KNOTS)
        return 1;

    for (j = 0; j < padStart; j++)
        extended[j] = knots[0];
    for (j = 0; j < count; j++)
        extended[padStart + j] = knots[j];
    for (j = 0; j < padEnd; j++)
        extended[padStart + count + j] = knots[count - 1];

    memset(result, 0, sizeof *result);
    result->order = order;
    result->numPoints = plotPoints;
    for (j = 0; j < plotPoints + order; j++)
        result->knots[j] = extended[j];
    for (j = 0; j < plotPoints; j++) {
        double greville = 0.0;
        for (l = j + 1; l <= j + order - 1; l++)
            greville += extended[l];
        greville /= (double)(order - 1);
        result->points[j].x = (float)greville;
        result->points[j].y = (j == i + padStart) ? 1.0f : 0.0f;
        result->points[j].z = 0.0f;
        result->points[j].w = 1.0f;
    }
    result->drawCurve = 1;
    result->drawControls = 0;
    result->curveColor = kBasisColors[i % 5];
    result->polygonColor = kPolygonGray;
    result->pointColor = kPointRed;
    return 0;
}

/* ---- The figures ---------------------------------------------------------- */

/* A plot of the five order-3 basis functions of an 8-knot vector. */
static int build_basis_plot(Q3Figure *figure, const float *knots)
{
    unsigned long i;

    for (i = 0; i < 5; i++) {
        if (q3fig_basis_plot_curve(knots, 5, 3, i, &figure->curves[i]) != 0)
            return 1;
    }
    figure->numCurves = 5;
    figure->plot = 1;
    figure->frame.xMin = knots[0] - 0.4f;
    figure->frame.xMax = knots[7] + 0.4f;
    figure->frame.yMin = -0.22f;
    figure->frame.yMax = 1.12f;
    return 0;
}

/* A free-form curve of the article: order 3, the five shared points. */
static int build_free_form(Q3Figure *figure, const float *knots)
{
    add_curve(figure, 3, 5, kFreeForm, knots);
    frame_control_points(figure, 0.6f);
    return 0;
}

static int figure07(Q3Figure *f)
{
    name_figure(f, 7, "Uniform basis functions for a set of control points",
                "{0, 1, 2, 3, 4, 5, 6, 7}",
                "N(0,3) to N(4,3) against t from 0 to 7, one colour each (B0 blue, B1 red, "
                "B2 green, B3 orange, B4 purple); ticks mark the knots, the gray line is N = 1");
    return build_basis_plot(f, kUniformKnots);
}

static int figure09(Q3Figure *f)
{
    name_figure(f, 9, "NURB curve with uniform knot vector", "{0, 1, 2, 3, 4, 5, 6, 7}",
                "order 3, the five free-form control points; defined for t from 2 to 5");
    return build_free_form(f, kUniformKnots);
}

static int figure10(Q3Figure *f)
{
    name_figure(f, 10, "Nonuniform basis functions for a set of control points",
                "{0, 1, 2, 3.75, 4, 4.25, 6, 7}",
                "N(0,3) to N(4,3); N(2,3) and N(3,3) are taller and narrower");
    return build_basis_plot(f, kNonuniformKnots);
}

static int figure11(Q3Figure *f)
{
    name_figure(f, 11, "NURB curve with nonuniform knot vector", "{0, 1, 2, 3.75, 4, 4.25, 6, 7}",
                "Figure 9's control points; the curve is pulled towards B2 and B3");
    return build_free_form(f, kNonuniformKnots);
}

static int figure12(Q3Figure *f)
{
    name_figure(f, 12, "Basis functions for a curve with multiple identical knots at the beginning",
                "{0, 0, 0, 3, 4, 5, 6, 7}", "N(0,3) to N(4,3); only N(0,3) is nonzero at t = 0");
    return build_basis_plot(f, kStartKnots);
}

static int figure13(Q3Figure *f)
{
    name_figure(f, 13, "NURB curve with multiple identical knots at the beginning",
                "{0, 0, 0, 3, 4, 5, 6, 7}",
                "Figure 9's control points; the curve starts at B0");
    return build_free_form(f, kStartKnots);
}

static int figure14(Q3Figure *f)
{
    name_figure(f, 14, "Basis functions for a curve with multiple identical knots in the middle",
                "{0, 1, 2, 3, 3, 5, 6, 7}", "N(0,3) to N(4,3); only N(2,3) is nonzero at t = 3");
    return build_basis_plot(f, kMiddleKnots);
}

static int figure15(Q3Figure *f)
{
    name_figure(f, 15, "NURB curve with multiple identical knots in the middle",
                "{0, 1, 2, 3, 3, 5, 6, 7}",
                "Figure 9's control points; the curve passes through B2 with a kink");
    return build_free_form(f, kMiddleKnots);
}

static int figure16(Q3Figure *f)
{
    TQ3RationalPoint4D weighted[5];
    Q3FigCurve *plain;
    unsigned long i;

    name_figure(f, 16, "Increasing the weight of a control point", "{0, 1, 2, 3, 4, 5, 6, 7}",
                "Figure 9's curve (pale) and the same curve with B2's weight raised from 1 to 3 "
                "(blue), pulled towards B2");
    for (i = 0; i < 5; i++)
        set_weighted(&weighted[i], kFreeForm[i].x, kFreeForm[i].y, i == 2 ? RAISED_WEIGHT : 1.0);
    plain = add_curve(f, 3, 5, kFreeForm, kUniformKnots);
    plain->drawControls = 0;
    plain->curveColor = kPaleBlue;
    add_curve(f, 3, 5, weighted, kUniformKnots);
    frame_control_points(f, 0.6f);
    return 0;
}

static int figure18(Q3Figure *f)
{
    static const float knots[6] = {0, 0, 0, 1, 1, 1};
    static const double weights[3] = {0.5, 1.0, 2.0};
    const TQ3ColorRGB colors[3] = {kCurveBlue, kGreen, kOrange};
    unsigned long i;

    name_figure(f, 18, "Constructing conic arcs", "{0, 0, 0, 1, 1, 1}",
                "control points (0, 0), (1.5, 2.5), (3, 0) with end weights 1 and inner weight "
                "0.5 (ellipse, blue), 1 (parabola, green) and 2 (hyperbola, orange)");
    for (i = 0; i < 3; i++) {
        TQ3RationalPoint4D points[3];
        Q3FigCurve *curve;
        set_weighted(&points[0], 0.0, 0.0, 1.0);
        set_weighted(&points[1], 1.5, 2.5, weights[i]);
        set_weighted(&points[2], 3.0, 0.0, 1.0);
        curve = add_curve(f, 3, 3, points, knots);
        curve->curveColor = colors[i];
        curve->drawControls = (i == 0);
    }
    frame_control_points(f, 0.5f);
    return 0;
}

/* The unit circle as one curve of four 90-degree arcs (Figure 21's). */
static Q3FigCurve *add_four_arc_circle(Q3Figure *f)
{
    static const float knots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    static const double corners[9][2] = {{1, 0},  {1, 1},   {0, 1},  {-1, 1}, {-1, 0},
                                         {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    const double corner = sqrt(2.0) / 2.0;
    TQ3RationalPoint4D points[9];
    unsigned long i;

    for (i = 0; i < 9; i++)
        set_weighted(&points[i], corners[i][0], corners[i][1], (i % 2) ? corner : 1.0);
    return add_curve(f, 3, 9, points, knots);
}

static int figure19(Q3Figure *f)
{
    static const float knots[6] = {0, 0, 0, 1, 1, 1};
    const double half = sqrt(3.0) / 2.0;
    TQ3RationalPoint4D points[3];
    Q3FigCurve *guide;

    name_figure(f, 19, "Constructing a circular arc", "{0, 0, 0, 1, 1, 1}",
                "a 120-degree arc of the unit circle: equilateral control triangle "
                "(sqrt(3)/2, 1/2), (0, 2), (-sqrt(3)/2, 1/2); theta = 60 degrees, inner weight "
                "cos 60 = 0.5, stored homogeneous as (0, 1, 0, 0.5); the pale circle is Figure "
                "21's, for reference");
    guide = add_four_arc_circle(f);
    guide->drawControls = 0;
    guide->curveColor = kGuideGray;
    set_weighted(&points[0], half, 0.5, 1.0);
    set_weighted(&points[1], 0.0, 2.0, cos(60.0 * 3.14159265358979323846 / 180.0));
    set_weighted(&points[2], -half, 0.5, 1.0);
    add_curve(f, 3, 3, points, knots);
    frame_control_points(f, 0.35f);
    return 0;
}

static int figure20(Q3Figure *f)
{
    static const float knots[10] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 3};
    const double r3 = sqrt(3.0);
    /* Tangent points of the unit circle and corners of the circumscribed
     * equilateral triangle, alternately, around the circle. */
    const double xy[7][2] = {{0, -1},  {r3, -1},  {r3 / 2, 0.5}, {0, 2},
                             {-r3 / 2, 0.5}, {-r3, -1}, {0, -1}};
    TQ3RationalPoint4D points[7];
    unsigned long i;

    name_figure(f, 20, "Constructing a circle with three arcs", "{0, 0, 0, 1, 1, 2, 2, 3, 3, 3}",
                "the unit circle as ONE order-3 curve of 7 control points: tangent points "
                "(0, -1), (sqrt(3)/2, 1/2), (-sqrt(3)/2, 1/2) with weight 1 and the corners "
                "(sqrt(3), -1), (0, 2), (-sqrt(3), -1) of the circumscribed equilateral triangle "
                "with weight cos 60 = 0.5");
    for (i = 0; i < 7; i++)
        set_weighted(&points[i], xy[i][0], xy[i][1], (i % 2) ? 0.5 : 1.0);
    add_curve(f, 3, 7, points, knots);
    frame_control_points(f, 0.35f);
    return 0;
}

static int figure21(Q3Figure *f)
{
    name_figure(f, 21, "Constructing a circle with four arcs",
                "{0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4}",
                "the unit circle as ONE order-3 curve of 9 control points around the square "
                "(+-1, +-1): edge midpoints with weight 1, corners with weight cos 45 = "
                "sqrt(2)/2");
    add_four_arc_circle(f);
    frame_control_points(f, 0.35f);
    return 0;
}

static int figure22(Q3Figure *f)
{
    Q3FigCurve *before;
    Q3FigCurve *after;

    name_figure(f, 22, "Inserting a knot",
                "{0, 1, 2, 3, 4, 5, 6, 7} -> {0, 1, 2, 3, 3.6, 4, 5, 6, 7}",
                "Figure 9's curve and control polygon (gray), and the six control points after "
                "inserting the knot t = 3.6 (orange): B2 and B3 move onto the old polygon, the "
                "curve is unchanged");
    before = add_curve(f, 3, 5, kFreeForm, kUniformKnots);
    before->pointColor = kDarkGray;
    if (f->numCurves >= Q3FIG_MAX_CURVES)
        return 1;
    after = &f->curves[f->numCurves];
    if (q3fig_insert_knot(before, INSERTED_KNOT, after) != 0)
        return 1;
    f->numCurves++;
    after->drawCurve = 0;
    after->polygonColor = kOrange;
    after->pointColor = kOrange;
    frame_control_points(f, 0.6f);
    return 0;
}

typedef int (*FigureBuilder)(Q3Figure *figure);

static const FigureBuilder kBuilders[] = {
    figure07, figure09, figure10, figure11, figure12, figure13, figure14,
    figure15, figure16, figure18, figure19, figure20, figure21, figure22,
};

unsigned long q3fig_count(void)
{
    return sizeof kBuilders / sizeof kBuilders[0];
}

int q3fig_build(unsigned long index, Q3Figure *figure)
{
    if (figure == NULL || index >= q3fig_count())
        return 1;
    return kBuilders[index](figure);
}

int q3fig_find(int number, Q3Figure *figure)
{
    unsigned long i;
    Q3Figure candidate;

    for (i = 0; i < q3fig_count(); i++) {
        if (q3fig_build(i, &candidate) == 0 && candidate.number == number) {
            *figure = candidate;
            return 0;
        }
    }
    return 1;
}

/* ---- Drawing --------------------------------------------------------------- */

void q3fig_fit_frame(const Q3FigRect *frame, unsigned long width, unsigned long height,
                     Q3FigRect *shown)
{
    double unitsPerPixel = fmax((frame->xMax - frame->xMin) / (double)width,
                                (frame->yMax - frame->yMin) / (double)height);
    double cx = 0.5 * ((double)frame->xMin + frame->xMax);
    double cy = 0.5 * ((double)frame->yMin + frame->yMax);
    shown->xMin = (float)(cx - 0.5 * unitsPerPixel * (double)width);
    shown->xMax = (float)(cx + 0.5 * unitsPerPixel * (double)width);
    shown->yMin = (float)(cy - 0.5 * unitsPerPixel * (double)height);
    shown->yMax = (float)(cy + 0.5 * unitsPerPixel * (double)height);
}

int q3fig_canvas_open(Q3FigCanvas *canvas, unsigned long width, unsigned long height,
                      const Q3FigRect *frame, int keepAspect, TQ3ColorRGB background)
{
    TQ3PixmapDrawContextData contextData;
    TQ3OrthographicCameraData cameraData;
    TQ3DrawContextObject context;
    TQ3CameraObject camera;
    Q3FigRect shown = *frame;
    float centerX, centerY, halfWidth, halfHeight;
    int failed = 0;

    memset(canvas, 0, sizeof *canvas);
    if (width == 0 || height == 0 || !(frame->xMax > frame->xMin) || !(frame->yMax > frame->yMin))
        return 1;
    if (keepAspect)
        q3fig_fit_frame(frame, width, height, &shown);
    centerX = 0.5f * (shown.xMin + shown.xMax);
    centerY = 0.5f * (shown.yMin + shown.yMax);
    halfWidth = 0.5f * (shown.xMax - shown.xMin);
    halfHeight = 0.5f * (shown.yMax - shown.yMin);

    canvas->argb = calloc(width * height, 4);
    canvas->view = Q3View_New();
    if (canvas->argb == NULL || canvas->view == NULL) {
        q3fig_canvas_close(canvas);
        return 1;
    }
    canvas->width = width;
    canvas->height = height;
    canvas->frame = shown;

    memset(&contextData, 0, sizeof contextData);
    contextData.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
    contextData.drawContextData.clearImageColor.a = 1.0f;
    contextData.drawContextData.clearImageColor.r = background.r;
    contextData.drawContextData.clearImageColor.g = background.g;
    contextData.drawContextData.clearImageColor.b = background.b;
    contextData.drawContextData.paneState = kQ3False;
    contextData.drawContextData.maskState = kQ3False;
    contextData.drawContextData.doubleBufferState = kQ3False;
    contextData.pixmap.image = canvas->argb;
    contextData.pixmap.width = width;
    contextData.pixmap.height = height;
    contextData.pixmap.rowBytes = width * 4;
    contextData.pixmap.pixelSize = 32;
    contextData.pixmap.pixelType = kQ3PixelTypeARGB32;
    contextData.pixmap.bitOrder = kQ3EndianBig;
    contextData.pixmap.byteOrder = kQ3EndianBig;
    context = Q3PixmapDrawContext_New(&contextData);
    if (context == NULL || Q3View_SetDrawContext(canvas->view, context) != kQ3Success)
        failed = 1;
    if (context != NULL)
        Q3Object_Dispose(context);

    memset(&cameraData, 0, sizeof cameraData);
    cameraData.cameraData.placement.cameraLocation.x = centerX;
    cameraData.cameraData.placement.cameraLocation.y = centerY;
    cameraData.cameraData.placement.cameraLocation.z = 10.0f;
    cameraData.cameraData.placement.pointOfInterest.x = centerX;
    cameraData.cameraData.placement.pointOfInterest.y = centerY;
    cameraData.cameraData.placement.pointOfInterest.z = 0.0f;
    cameraData.cameraData.placement.upVector.y = 1.0f;
    cameraData.cameraData.range.hither = 1.0f;
    cameraData.cameraData.range.yon = 20.0f;
    cameraData.cameraData.viewPort.origin.x = -1.0f;
    cameraData.cameraData.viewPort.origin.y = 1.0f;
    cameraData.cameraData.viewPort.width = 2.0f;
    cameraData.cameraData.viewPort.height = 2.0f;
    cameraData.left = -halfWidth;
    cameraData.right = halfWidth;
    cameraData.top = halfHeight;
    cameraData.bottom = -halfHeight;
    camera = Q3OrthographicCamera_New(&cameraData);
    if (camera == NULL || Q3View_SetCamera(canvas->view, camera) != kQ3Success)
        failed = 1;
    if (camera != NULL)
        Q3Object_Dispose(camera);

    if (Q3View_SetRendererByType(canvas->view, kQ3RendererTypeInteractive) != kQ3Success)
        failed = 1;
    if (failed) {
        q3fig_canvas_close(canvas);
        return 1;
    }
    return 0;
}

void q3fig_canvas_close(Q3FigCanvas *canvas)
{
    if (canvas->view != NULL)
        Q3Object_Dispose(canvas->view);
    free(canvas->argb);
    memset(canvas, 0, sizeof *canvas);
}

void q3fig_canvas_rgba(const Q3FigCanvas *canvas, unsigned char *rgba)
{
    unsigned long i;

    for (i = 0; i < canvas->width * canvas->height; i++) {
        const unsigned char *argb = canvas->argb + 4 * i;
        rgba[4 * i + 0] = argb[1];
        rgba[4 * i + 1] = argb[2];
        rgba[4 * i + 2] = argb[3];
        rgba[4 * i + 3] = argb[0];
    }
}

void q3fig_canvas_pixel(const Q3FigCanvas *canvas, float x, float y, float *px, float *py)
{
    const Q3FigRect *r = &canvas->frame;
    *px = (float)(((double)x - r->xMin) / ((double)r->xMax - r->xMin) * (double)canvas->width);
    *py = (float)(((double)r->yMax - y) / ((double)r->yMax - r->yMin) * (double)canvas->height);
}

/* World units per pixel along x and y. */
static void pixel_size(const Q3FigCanvas *canvas, float *dx, float *dy)
{
    *dx = (canvas->frame.xMax - canvas->frame.xMin) / (float)canvas->width;
    *dy = (canvas->frame.yMax - canvas->frame.yMin) / (float)canvas->height;
}

static TQ3AttributeSet new_color_set(TQ3ColorRGB color)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    if (set != NULL &&
        Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color) != kQ3Success) {
        Q3Object_Dispose(set);
        set = NULL;
    }
    return set;
}

/* Submits a polyline through count points of the z = 0 plane (xy pairs). */
static TQ3Status submit_polyline(TQ3ViewObject view, const float *xy, unsigned long count,
                                 TQ3ColorRGB color)
{
    TQ3Vertex3D vertices[Q3FIG_MAX_POINTS + 1];
    TQ3PolyLineData data;
    TQ3Status status;
    unsigned long i;

    if (count < 2 || count > Q3FIG_MAX_POINTS + 1)
        return kQ3Failure;
    for (i = 0; i < count; i++) {
        vertices[i].point.x = xy[2 * i];
        vertices[i].point.y = xy[2 * i + 1];
        vertices[i].point.z = 0.0f;
        vertices[i].attributeSet = NULL;
    }
    data.numVertices = count;
    data.vertices = vertices;
    data.segmentAttributeSet = NULL;
    data.polyLineAttributeSet = new_color_set(color);
    if (data.polyLineAttributeSet == NULL)
        return kQ3Failure;
    status = Q3PolyLine_Submit(&data, view);
    Q3Object_Dispose(data.polyLineAttributeSet);
    return status;
}

static TQ3Status submit_control_polygon(const Q3FigCurve *curve, const Q3FigCanvas *canvas)
{
    float xy[2 * Q3FIG_MAX_POINTS];
    unsigned long i;

    for (i = 0; i < curve->numPoints; i++) {
        xy[2 * i] = curve->points[i].x / curve->points[i].w;
        xy[2 * i + 1] = curve->points[i].y / curve->points[i].w;
    }
    return submit_polyline(canvas->view, xy, curve->numPoints, curve->polygonColor);
}

/* A 7-pixel square outline around each control point, and the point itself. */
static TQ3Status submit_markers(const Q3FigCurve *curve, const Q3FigCanvas *canvas)
{
    TQ3Status status = kQ3Success;
    TQ3PointData point;
    float dx, dy;
    unsigned long i;

    pixel_size(canvas, &dx, &dy);
    dx *= MARKER_HALF_SIZE;
    dy *= MARKER_HALF_SIZE;
    point.pointAttributeSet = new_color_set(curve->pointColor);
    if (point.pointAttributeSet == NULL)
        return kQ3Failure;
    for (i = 0; i < curve->numPoints && status == kQ3Success; i++) {
        float x = curve->points[i].x / curve->points[i].w;
        float y = curve->points[i].y / curve->points[i].w;
        const float square[10] = {x - dx, y - dy, x + dx, y - dy, x + dx,
                                  y + dy, x - dx, y + dy, x - dx, y - dy};
        status = submit_polyline(canvas->view, square, 5, curve->pointColor);
        point.point.x = x;
        point.point.y = y;
        point.point.z = 0.0f;
        if (status == kQ3Success)
            status = Q3Point_Submit(&point, canvas->view);
    }
    Q3Object_Dispose(point.pointAttributeSet);
    return status;
}

static TQ3Status submit_curve(const Q3FigCurve *curve, const Q3FigCanvas *canvas)
{
    TQ3NURBCurveData data = q3fig_curve_data((Q3FigCurve *)curve);
    TQ3Status status;

    data.curveAttributeSet = new_color_set(curve->curveColor);
    if (data.curveAttributeSet == NULL)
        return kQ3Failure;
    status = Q3NURBCurve_Submit(&data, canvas->view);
    Q3Object_Dispose(data.curveAttributeSet);
    return status;
}

static void set_line(float line[4], float x0, float y0, float x1, float y1)
{
    line[0] = x0;
    line[1] = y0;
    line[2] = x1;
    line[3] = y1;
}

/* A plot's t axis from the first knot to the last, a tick below it at each
 * knot (longer for a repeated knot), and a pale line at N = 1. */
static TQ3Status submit_plot_axes(const Q3Figure *figure, const Q3FigCanvas *canvas)
{
    const Q3FigCurve *curve = &figure->curves[0];
    const unsigned long count = curve->numPoints + curve->order;
    const float first = curve->knots[0];
    const float last = curve->knots[count - 1];
    float line[4];
    float dx, dy;
    unsigned long i;
    TQ3Status status;

    pixel_size(canvas, &dx, &dy);
    set_line(line, first, 1.0f, last, 1.0f);
    status = submit_polyline(canvas->view, line, 2, kGuideGray);
    set_line(line, first, 0.0f, last, 0.0f);
    if (status == kQ3Success)
        status = submit_polyline(canvas->view, line, 2, kAxisGray);
    for (i = 0; i < count && status == kQ3Success; i++) {
        unsigned long multiplicity = 1;
        if (i > 0 && curve->knots[i - 1] == curve->knots[i])
            continue;
        while (i + multiplicity < count && curve->knots[i + multiplicity] == curve->knots[i])
            multiplicity++;
        set_line(line, curve->knots[i], 0.0f, curve->knots[i],
                 -TICK_LENGTH * (float)multiplicity * dy);
        status = submit_polyline(canvas->view, line, 2, kAxisGray);
    }
    return status;
}

TQ3Status q3fig_submit(const Q3Figure *figure, const Q3FigCanvas *canvas)
{
    TQ3SubdivisionStyleData style;
    TQ3Status status;
    unsigned long c;

    style.method = kQ3SubdivisionMethodConstant;
    style.c1 = style.c2 = Q3FIG_SEGMENTS_PER_SPAN;
    status = Q3SubdivisionStyle_Submit(&style, canvas->view);
    for (c = 0; c < figure->numCurves && status == kQ3Success; c++) {
        if (figure->curves[c].drawControls)
            status = submit_control_polygon(&figure->curves[c], canvas);
    }
    for (c = 0; c < figure->numCurves && status == kQ3Success; c++) {
        if (figure->curves[c].drawCurve)
            status = submit_curve(&figure->curves[c], canvas);
    }
    for (c = 0; c < figure->numCurves && status == kQ3Success; c++) {
        if (figure->curves[c].drawControls)
            status = submit_markers(&figure->curves[c], canvas);
    }
    /* A plot's axis goes over the curves, so that where a basis function is
     * zero the axis shows rather than the last function drawn. */
    if (status == kQ3Success && figure->plot)
        status = submit_plot_axes(figure, canvas);
    return status;
}

int q3fig_render(const Q3Figure *figure, unsigned long width, unsigned long height,
                 unsigned char *rgba)
{
    Q3FigCanvas canvas;
    TQ3ViewStatus viewStatus = kQ3ViewStatusError;
    TQ3Status status = kQ3Success;

    if (q3fig_canvas_open(&canvas, width, height, &figure->frame, !figure->plot,
                          q3fig_background()) != 0)
        return 1;
    if (Q3View_StartRendering(canvas.view) == kQ3Success) {
        do {
            if (q3fig_submit(figure, &canvas) != kQ3Success)
                status = kQ3Failure;
            viewStatus = Q3View_EndRendering(canvas.view);
        } while (viewStatus == kQ3ViewStatusRetraverse);
    }
    if (status == kQ3Success && viewStatus == kQ3ViewStatusDone)
        q3fig_canvas_rgba(&canvas, rgba);
    q3fig_canvas_close(&canvas);
    return (status == kQ3Success && viewStatus == kQ3ViewStatusDone) ? 0 : 1;
}
