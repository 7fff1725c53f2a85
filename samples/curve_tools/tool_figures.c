/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Figures made with the curve tools (Q3NURBCurveTools.h). Each result comes
 * back in a TQ3NURBCurveData that Q3 allocated; it is copied into the figure
 * and released with Q3NURBCurve_EmptyData.
 */
#include "tool_figures.h"

#include "Q3NURBCurveTools.h"
#include "QD3DGeometry.h"

#include <string.h>

static const TQ3ColorRGB kBlue = {0.08f, 0.24f, 0.62f};
static const TQ3ColorRGB kGray = {0.60f, 0.60f, 0.60f};
static const TQ3ColorRGB kRed = {0.82f, 0.08f, 0.08f};
static const TQ3ColorRGB kOrange = {0.93f, 0.46f, 0.00f};
static const TQ3ColorRGB kGreen = {0.10f, 0.56f, 0.16f};
static const TQ3ColorRGB kPaleGray = {0.84f, 0.84f, 0.84f};

/* Copies a curve Q3 returned into a figure curve, if it fits, and releases it. */
static int take_curve(TQ3NURBCurveData *data, Q3FigCurve *curve)
{
    unsigned long i;
    int fits = data->numPoints <= Q3FIG_MAX_POINTS && data->numPoints + data->order <= Q3FIG_MAX_KNOTS;

    if (fits) {
        curve->order = data->order;
        curve->numPoints = data->numPoints;
        for (i = 0; i < data->numPoints; i++)
            curve->points[i] = data->controlPoints[i];
        for (i = 0; i < data->numPoints + data->order; i++)
            curve->knots[i] = data->knots[i];
    }
    Q3NURBCurve_EmptyData(data);
    return fits ? 0 : 1;
}

int q3tools_figure22(Q3Figure *figure)
{
    TQ3NURBCurveData before, inserted;
    Q3FigCurve *after;

    /* The article's figure supplies the frame, the captions and the colours;
     * only the inserted curve is replaced by the knot-insertion call's. */
    if (q3fig_find(22, figure) != 0 || figure->numCurves != 2)
        return 1;
    before = q3fig_curve_data(&figure->curves[0]);
    if (Q3NURBCurveData_InsertKnot(&before, Q3TOOLS_FIGURE22_KNOT, 1, &inserted) != kQ3Success)
        return 1;
    after = &figure->curves[1];
    return take_curve(&inserted, after);
}

static const TQ3Point3D kPoints[Q3TOOLS_INTERPOLATED_POINTS] = {
    {0.0f, 0.0f, 0.0f}, {1.0f, 2.0f, 0.0f}, {1.5f, 2.2f, 0.0f}, {3.0f, 0.5f, 0.0f},
    {4.0f, 0.2f, 0.0f}, {4.4f, 2.6f, 0.0f}, {6.0f, 3.0f, 0.0f}, {7.0f, 1.0f, 0.0f},
};

const TQ3Point3D *q3tools_interpolated_points(void)
{
    return kPoints;
}

static Q3FigCurve *next_curve(Q3Figure *figure)
{
    Q3FigCurve *curve = &figure->curves[figure->numCurves++];
    memset(curve, 0, sizeof *curve);
    curve->drawCurve = 1;
    curve->polygonColor = kGray;
    curve->pointColor = kRed;
    return curve;
}

int q3tools_interpolation(Q3Figure *figure)
{
    TQ3NURBCurveData result;
    Q3FigCurve *curve;
    unsigned long i;

    memset(figure, 0, sizeof *figure);
    figure->number = 0;
    strcpy(figure->name, "interpolation");
    figure->caption = "Curves through points";
    figure->knotText = "clamped on [0, 1], interior knots from the parameters";
    figure->description = "cubics through eight points with chord-length (blue) and centripetal (orange) "
                          "parameters, and the least-squares cubic with five control points (green)";
    figure->frame.xMin = -0.7f;
    figure->frame.xMax = 7.7f;
    figure->frame.yMin = -0.8f;
    figure->frame.yMax = 3.6f;

    /* The points, as the control polygon of an order-2 curve that is not drawn. */
    curve = next_curve(figure);
    curve->order = 2;
    curve->numPoints = Q3TOOLS_INTERPOLATED_POINTS;
    for (i = 0; i < Q3TOOLS_INTERPOLATED_POINTS; i++) {
        curve->points[i].x = kPoints[i].x;
        curve->points[i].y = kPoints[i].y;
        curve->points[i].z = kPoints[i].z;
        curve->points[i].w = 1.0f;
    }
    /* Clamped knots 0, 0, 1, ..., n - 2, n - 1, n - 1 make it a valid polyline. */
    curve->knots[0] = 0.0f;
    for (i = 0; i < Q3TOOLS_INTERPOLATED_POINTS; i++)
        curve->knots[i + 1] = (float)i;
    curve->knots[Q3TOOLS_INTERPOLATED_POINTS + 1] = (float)(Q3TOOLS_INTERPOLATED_POINTS - 1);
    curve->drawCurve = 0;
    curve->drawControls = 1;
    curve->polygonColor = kPaleGray;

    if (Q3NURBCurveData_Approximate(4, Q3TOOLS_INTERPOLATED_POINTS, kPoints, 5,
                                    kQ3NURBCurveParameterizationChordLength, &result) != kQ3Success)
        return 1;
    curve = next_curve(figure);
    curve->curveColor = kGreen;
    if (take_curve(&result, curve) != 0)
        return 1;

    if (Q3NURBCurveData_Interpolate(4, Q3TOOLS_INTERPOLATED_POINTS, kPoints, kQ3NURBCurveParameterizationCentripetal,
                                    &result) != kQ3Success)
        return 1;
    curve = next_curve(figure);
    curve->curveColor = kOrange;
    if (take_curve(&result, curve) != 0)
        return 1;

    if (Q3NURBCurveData_Interpolate(4, Q3TOOLS_INTERPOLATED_POINTS, kPoints, kQ3NURBCurveParameterizationChordLength,
                                    &result) != kQ3Success)
        return 1;
    curve = next_curve(figure);
    curve->curveColor = kBlue;
    return take_curve(&result, curve);
}
