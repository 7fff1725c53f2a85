/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3SCENES_H
#define Q3SCENES_H

/*
 * q3scenes: small scenes that show what Q3 draws beyond the article's curves
 * (filled and wireframe surfaces, per-vertex colours, hidden surfaces),
 * built and drawn through the public C API only. The sample `scenes` writes
 * them as PNG files; the tests render the same scenes and compare them with
 * golden images (tests/golden/scene_NAME.png).
 *
 * A scene is a name, a camera, a renderer, a background and a function that
 * submits its objects inside a rendering loop. Functions returning int
 * return 0 on success.
 */

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    Q3SCENE_WIDTH = 320, /* the size the sample and the goldens use */
    Q3SCENE_HEIGHT = 240
};

typedef struct Q3Scene {
    const char *name;        /* file stem: tests/golden/scene_NAME.png */
    const char *caption;     /* what the picture shows */
    TQ3ObjectType renderer;  /* kQ3RendererTypeInteractive or kQ3RendererTypeWireFrame */
    TQ3Point3D eye;          /* camera location, looking at the origin with y up */
    float fieldOfView;       /* view angle aspect camera, radians, along y */
    TQ3ColorRGB background;
    /* Submits the scene's objects to view (inside a rendering loop). */
    TQ3Status (*submit)(TQ3ViewObject view);
} Q3Scene;

/* How many scenes there are, and scene index (0 to count - 1), or NULL. */
unsigned long q3scene_count(void);
const Q3Scene *q3scene_get(unsigned long index);
/* The scene called name, or NULL. */
const Q3Scene *q3scene_find(const char *name);

/*
 * Renders a scene into width x height RGBA pixels (rgba holds
 * width * height * 4 bytes, top row first). Q3 must be initialized.
 */
int q3scene_render(const Q3Scene *scene, unsigned long width, unsigned long height, unsigned char *rgba);
/* The same, lit by the light group lights (NULL: none; see Q3View_SetLightGroup). */
int q3scene_render_lit(const Q3Scene *scene, TQ3GroupObject lights, unsigned long width, unsigned long height,
                       unsigned char *rgba);

/*
 * The NURB patches of the patch scenes, also drawn lit by samples/lighting:
 * each submits a screen-space subdivision style of `pixels` and then its
 * patch in the attribute set `set` (may be NULL). Plain: a bicubic hill over
 * x, z in [-1.6, 1.6]. Trimmed: the same patch with a clockwise circular hole
 * of radius 0.7 in the middle of its domain [0, 2] x [0, 2] and a
 * counterclockwise square island of half-side 0.3 in the hole. Cylinder:
 * half of the cylinder x^2 + (y + 0.5)^2 = 1 with y >= -0.5, z in
 * [-1.4, 1.4], as rational quadratic quarter circles.
 */
TQ3Status q3scene_submit_plain_patch(TQ3ViewObject view, TQ3AttributeSet set, float pixels);
TQ3Status q3scene_submit_trimmed_patch(TQ3ViewObject view, TQ3AttributeSet set, float pixels);
TQ3Status q3scene_submit_cylinder_patch(TQ3ViewObject view, TQ3AttributeSet set, float pixels);

#ifdef __cplusplus
}
#endif

#endif /* Q3SCENES_H */
