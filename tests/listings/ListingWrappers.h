/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3_LISTING_WRAPPERS_H
#define Q3_LISTING_WRAPPERS_H

/*
 * Entry points into the article's listings. Each wrapper (a .c file next to
 * this header) supplies what its listing assumes and #includes the listing's
 * text from Q3_LISTINGS_DIR unchanged (the subdivision-style fragment with
 * its "..." elision lines removed), compiled as C99.
 */

#include "QD3D.h"
#include "QD3DGeometry.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Listing 1: makes its retained curve, draws it in view, disposes it. */
void q3listing1_retained(TQ3ViewObject view);

/* The immediate-mode fragment, drawing *curve (the listing's curveData). */
void q3listing_immediate_mode(TQ3ViewObject view, const TQ3NURBCurveData *curve);

/* The subdivision-style fragment (five segments per span), drawing *curve. */
void q3listing_subdivision_style(TQ3ViewObject view, const TQ3NURBCurveData *curve);

/* Listing 2's InsertKnot; the result is the listing's malloc'ed curve, or NULL. */
TQ3NURBCurveData *q3listing2_insert_knot(TQ3NURBCurveData *curve, float tNew);

/*
 * Listing 3's BezierToNURBCurve on a Bezier curve of `order` control points
 * given as x, y, z triples; the result is the listing's malloc'ed curve.
 */
TQ3NURBCurveData *q3listing3_bezier_to_nurb(unsigned int order, const float *xyz);

/* Frees a curve made by Listing 2 or 3: both arrays, the attribute set
 * reference (Listing 2 duplicates the old curve's) and the structure. */
void q3listing_free_curve(TQ3NURBCurveData *curve);

#ifdef __cplusplus
}
#endif

#endif /* Q3_LISTING_WRAPPERS_H */
