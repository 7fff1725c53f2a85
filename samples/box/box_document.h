/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3BOX_DOCUMENT_H
#define Q3BOX_DOCUMENT_H

/*
 * The scene of Apple's Box sample (develop issue 22's introduction to
 * QuickDraw 3D), written for Q3: a box in a display group with a Phong
 * illumination shader, a diffuse colour attribute set and a rotation, lit by
 * an ambient and a directional light, drawn through a pixmap draw context
 * into the document's own memory. Each frame turns the box a step further.
 */

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct BoxDocument BoxDocument;

/* A document drawing into width x height pixels, or NULL (Q3 initialized). */
BoxDocument *box_document_new(unsigned long width, unsigned long height);
/* Draws frame number frame into rgba (width * height * 4 bytes, top row
 * first, 8-bit RGBA); 0 on success. */
int box_document_draw(BoxDocument *document, unsigned long frame, unsigned char *rgba);
void box_document_dispose(BoxDocument *document);

#ifdef __cplusplus
}
#endif

#endif /* Q3BOX_DOCUMENT_H */
