/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3GALLERY_H
#define Q3GALLERY_H

/*
 * q3gallery: one retained object of every QuickDraw 3D geometry type, with
 * attribute colours, and the two ways samples/geometries.c draws each: the
 * wireframe renderer, and the interactive renderer lit through a Phong
 * shader by an ambient and a directional light. The tests compare the
 * pictures with tests/golden/geometry_NAME_{wireframe,lit}.png.
 */

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    Q3GALLERY_WIDTH = 200, /* the size the sample and the goldens use */
    Q3GALLERY_HEIGHT = 150
};

/* How many geometry types the gallery shows, and the name of entry index
 * (the Q3 type name without its prefix, e.g. "nurb_patch"), or NULL. */
unsigned long q3gallery_count(void);
const char *q3gallery_name(unsigned long index);

/* A new retained geometry of entry index (the caller disposes it), or NULL. */
TQ3GeometryObject q3gallery_new(unsigned long index);

/* Draws entry index into width x height 8-bit RGBA pixels (top row first),
 * lit (1) or in wireframe (0); 0 on success. Q3 must be initialized. */
int q3gallery_render(unsigned long index, int lit, unsigned long width, unsigned long height, unsigned char *rgba);

/* Draws any drawable object (a geometry, a group) as q3gallery_render draws
 * an entry: the same camera, lights, subdivision and illumination. */
int q3gallery_render_object(TQ3Object object, int lit, unsigned long width, unsigned long height,
                            unsigned char *rgba);

#ifdef __cplusplus
}
#endif

#endif /* Q3GALLERY_H */
