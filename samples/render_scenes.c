/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * render_scenes OUTDIR: renders every scene of samples/scenes (surfaces filled and
 * in wireframe, per-vertex colours, hidden surfaces) and samples/lighting (lights,
 * illumination shaders, fill, backfacing and interpolation styles, groups) to OUTDIR/NAME.png and
 * lists them with their captions in OUTDIR/index.md.
 */
#define _POSIX_C_SOURCE 200809L

#include "QD3D.h"
#include "QD3DErrors.h"
#include "q3sample_png.h"
#include "lit_scenes.h"
#include "scenes.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static void print_error(TQ3Error firstError, TQ3Error lastError, long reference)
{
    (void)firstError;
    (void)reference;
    fprintf(stderr, "render_scenes: Q3 error %d: %s\n", (int)lastError, Q3Error_GetMessage());
}

/* Writes a rendered scene to OUTDIR/NAME.png and lists it in the index;
 * returns the number of failures (0 or 1). */
static int write_scene(const char *outdir, FILE *index, const Q3Scene *scene, int rendered, const unsigned char *rgba)
{
    char path[4096];
    int written;
    if (rendered != 0) {
        fprintf(stderr, "render_scenes: %s could not be rendered\n", scene->name);
        return 1;
    }
    snprintf(path, sizeof path, "%s/%s.png", outdir, scene->name);
    written = q3sample_write_png(path, rgba, Q3SCENE_WIDTH, Q3SCENE_HEIGHT);
    if (written != kQ3Success) {
        fprintf(stderr, "render_scenes: %s: %s\n", path, Q3Error_GetMessage());
        return 1;
    }
    fprintf(index, "\n## %s\n\n%s.\n\n![%s](%s.png)\n", scene->name, scene->caption, scene->name, scene->name);
    return 0;
}

int main(int argc, char **argv)
{
    char path[4096];
    unsigned char *rgba;
    FILE *index;
    unsigned long i;
    int failures = 0;

    if (argc != 2) {
        fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
        return 2;
    }
    if (mkdir(argv[1], 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "render_scenes: cannot create %s: %s\n", argv[1], strerror(errno));
        return 1;
    }
    rgba = malloc(Q3SCENE_WIDTH * Q3SCENE_HEIGHT * 4);
    snprintf(path, sizeof path, "%s/index.md", argv[1]);
    index = fopen(path, "w");
    if (rgba == NULL || index == NULL || Q3Initialize() != kQ3Success) {
        fprintf(stderr, "render_scenes: cannot start (memory, %s or Q3Initialize)\n", path);
        free(rgba);
        if (index != NULL)
            fclose(index);
        return 1;
    }
    Q3Error_Register(print_error, 0);
    fprintf(index, "# Scenes\n\nRendered by Q3 through its public C API (samples/scenes).\n");
    for (i = 0; i < q3scene_count(); i++) {
        const Q3Scene *scene = q3scene_get(i);
        failures += write_scene(argv[1], index, scene, q3scene_render(scene, Q3SCENE_WIDTH, Q3SCENE_HEIGHT, rgba),
                                rgba);
    }
    for (i = 0; i < q3litscene_count(); i++) {
        const Q3LitScene *lit = q3litscene_get(i);
        failures += write_scene(argv[1], index, &lit->scene,
                                q3litscene_render(lit, Q3SCENE_WIDTH, Q3SCENE_HEIGHT, rgba), rgba);
    }
    fclose(index);
    free(rgba);
    Q3Exit();
    return failures == 0 ? 0 : 1;
}
