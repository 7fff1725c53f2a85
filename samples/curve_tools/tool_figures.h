/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3TOOLFIGURES_H
#define Q3TOOLFIGURES_H

/*
 * q3toolfigures: figures drawn with the curve tools of Q3NURBCurveTools.h,
 * as plain Q3Figure data for q3fig_render (samples/figures). The curve_tools
 * sample writes them as PNG files; tests/article renders the same figures and
 * checks them. Both functions call Q3, so Q3 must be initialized; they return
 * 0 on success, and on failure Q3 has posted the error that says why.
 */

#include "figures.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The knot the article inserts into Figure 9's curve for Figure 22. */
#define Q3TOOLS_FIGURE22_KNOT 3.6f

/*
 * The article's Figure 22 rebuilt with Q3NURBCurveData_InsertKnot instead of
 * Listing 2: Figure 9's curve and control polygon, and the control polygon
 * after inserting t = 3.6. It draws exactly what q3fig_find(22, ...) draws,
 * so its image is the article figure's golden.
 */
int q3tools_figure22(Q3Figure *figure);

/* The points q3tools_interpolation passes its curves through (z = 0). */
enum { Q3TOOLS_INTERPOLATED_POINTS = 8 };
const TQ3Point3D *q3tools_interpolated_points(void);

/*
 * Curves through the eight points of q3tools_interpolated_points, made by
 * Q3NURBCurveData_Interpolate: a cubic with chord-length parameters (blue,
 * the B-spline lecture's method) and one with centripetal parameters
 * (orange), over the polyline through the points (gray, the points as red
 * markers); and the least-squares cubic with five control points
 * (Q3NURBCurveData_Approximate, green, no markers).
 */
int q3tools_interpolation(Q3Figure *figure);

#ifdef __cplusplus
}
#endif

#endif /* Q3TOOLFIGURES_H */
