/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* Listing 1 ("Rendering a NURB curve in retained mode") as printed: it needs
 * a variable `view` ready to render, and runs as a function body. */
#include "ListingWrappers.h"

#include "QD3DView.h"

#include <stdlib.h>

void q3listing1_retained(TQ3ViewObject view)
{
#include "listing1_retained.c.txt"
}
