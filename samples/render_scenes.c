/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * render_scenes OUTDIR: renders every scene of samples/scenes (surfaces filled and
 * in wireframe, per-vertex colours, hidden surfaces) to OUTDIR/NAME.png and
 * lists them with their captions in OUTDIR/index.md.
 */
#define _POSIX_C_SOURCE 200809L

#include "QD3D.h"
#include "QD3DErrors.h"
#include "q3png.h"
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
        int written;
        if (q3scene_render(scene, Q3SCENE_WIDTH, Q3SCENE_HEIGHT, rgba) != 0) {
            fprintf(stderr, "render_scenes: %s could not be rendered\n", scene->name);
            failures++;
            continue;
        }
        snprintf(path, sizeof path, "%s/%s.png", argv[1], scene->name);
        written = q3png_write_rgba8(path, rgba, Q3SCENE_WIDTH, Q3SCENE_HEIGHT, Q3SCENE_WIDTH * 4);
        if (written != Q3PNG_OK) {
            fprintf(stderr, "render_scenes: %s: %s\n", path, q3png_error_string(written));
            failures++;
            continue;
        }
        fprintf(index, "\n## %s\n\n%s.\n\n![%s](%s.png)\n", scene->name, scene->caption, scene->name, scene->name);
    }
    fclose(index);
    free(rgba);
    Q3Exit();
    return failures == 0 ? 0 : 1;
}
