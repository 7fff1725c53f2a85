/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* The article's subdivision-style loop ("CONTROLLING SUBDIVISION"): the
 * printed fragment minus its "..." elision lines (removed at configure time
 * into the build tree, tests/listings/CMakeLists.txt), with `view` and the
 * `curveData` of the immediate-mode example it expands on. */
#include "ListingWrappers.h"

#include "QD3DStyle.h"
#include "QD3DView.h"

#include <stdlib.h>

void q3listing_subdivision_style(TQ3ViewObject view, const TQ3NURBCurveData *curve)
{
    TQ3NURBCurveData curveData = *curve;
#include "subdivision_style.without_elisions.c.txt"
}
