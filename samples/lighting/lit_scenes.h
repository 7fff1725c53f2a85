/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3LITSCENES_H
#define Q3LITSCENES_H

/*
 * q3litscenes: scenes lit by QuickDraw 3D's lights and shaded by its
 * illumination shaders, one picture per light type, per illumination model,
 * per fill and backfacing style, per interpolation style, and an unordered
 * against an ordered display group. Each is a q3scenes scene (samples/scenes)
 * plus the light group it is lit by. The sample `render_scenes` writes them
 * as PNG files; the tests compare them with tests/golden/lit_NAME.png.
 */

#include "QD3D.h"
#include "scenes.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct Q3LitScene {
    Q3Scene scene;
    /* Makes the light group the scene is lit by (the caller disposes it). */
    TQ3GroupObject (*lights)(void);
} Q3LitScene;

unsigned long q3litscene_count(void);
const Q3LitScene *q3litscene_get(unsigned long index);
const Q3LitScene *q3litscene_find(const char *name);

/* A new light group of a white ambient light and a white directional light
 * shining along direction, at the brightnesses given (the caller disposes
 * it), or NULL. */
TQ3GroupObject q3litscene_new_lights(float ambient, float directional, TQ3Vector3D direction);

/* Renders a lit scene as q3scene_render does (0 on success). */
int q3litscene_render(const Q3LitScene *scene, unsigned long width, unsigned long height, unsigned char *rgba);

#ifdef __cplusplus
}
#endif

#endif /* Q3LITSCENES_H */
