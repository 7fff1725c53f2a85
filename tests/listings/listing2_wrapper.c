/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* Listing 2 ("Inserting a knot"): a static function definition, included at
 * file scope, with what it uses (malloc, Q3Object_Duplicate) declared. */
#include "ListingWrappers.h"

#include <stdlib.h>

#include "listing2_insert_knot.c.txt"

TQ3NURBCurveData *q3listing2_insert_knot(TQ3NURBCurveData *curve, float tNew)
{
    return InsertKnot(curve, tNew);
}

void q3listing_free_curve(TQ3NURBCurveData *curve)
{
    if (curve == NULL)
        return;
    if (curve->curveAttributeSet != NULL)
        Q3Object_Dispose(curve->curveAttributeSet);
    free(curve->controlPoints);
    free(curve->knots);
    free(curve);
}
