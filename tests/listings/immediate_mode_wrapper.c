/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* The article's immediate-mode loop as printed: it needs `view` and the
 * `curveData` that Listing 1 would have filled in. */
#include "ListingWrappers.h"

#include "QD3DView.h"

#include <stdlib.h>

void q3listing_immediate_mode(TQ3ViewObject view, const TQ3NURBCurveData *curve)
{
    TQ3NURBCurveData curveData = *curve;
#include "immediate_mode.c.txt"
}
