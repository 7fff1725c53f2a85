/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3SCENE_UTIL_H
#define Q3SCENE_UTIL_H

/*
 * The small helpers the scene libraries share (samples/scenes,
 * samples/lighting, samples/geometries): values built in one expression, a
 * diffuse-colour attribute set, and dispose-if-made.
 */

#include "QD3D.h"
#include "QD3DSet.h"

#include <stddef.h>

static inline TQ3ColorRGB rgb(float r, float g, float b)
{
    TQ3ColorRGB color;
    color.r = r;
    color.g = g;
    color.b = b;
    return color;
}

static inline TQ3Point3D point3(float x, float y, float z)
{
    TQ3Point3D p;
    p.x = x;
    p.y = y;
    p.z = z;
    return p;
}

static inline TQ3Vector3D vector3(float x, float y, float z)
{
    TQ3Vector3D v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static inline void dispose(TQ3Object object)
{
    if (object != NULL)
        Q3Object_Dispose(object);
}

/* A new attribute set holding a diffuse colour (the caller disposes it), or
 * NULL. */
static inline TQ3AttributeSet color_set(TQ3ColorRGB color)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    if (set != NULL && Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color) != kQ3Success) {
        Q3Object_Dispose(set);
        set = NULL;
    }
    return set;
}

/* Submits an object made by New (NULL counts as a failure) and disposes it. */
static inline TQ3Status submit_new(TQ3Object object, TQ3ViewObject view)
{
    TQ3Status status;
    if (object == NULL)
        return kQ3Failure;
    status = Q3Object_Submit(object, view);
    Q3Object_Dispose(object);
    return status;
}

#endif /* Q3SCENE_UTIL_H */
