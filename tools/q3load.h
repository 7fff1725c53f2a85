/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3LOAD_H
#define Q3LOAD_H

/* Reading every object of a 3DMF file, and printing the library's warnings,
 * shared by q3render and q3convert. */

#include "QD3D.h"
#include "QD3DErrors.h"
#include "QD3DIO.h"
#include "QD3DStorage.h"

#include <stdio.h>
#include <stdlib.h>

/* The objects of the file at path, in order, in *objects (free with
 * q3load_free); the number read, or -1 after printing why the file cannot
 * be read to stderr. */
static long q3load_read(const char *path, TQ3Object **objects)
{
    TQ3StorageObject storage = Q3UnixPathStorage_New(path);
    TQ3FileObject file = Q3File_New();
    TQ3FileMode mode = 0;
    long count = 0, capacity = 16;
    FILE *probe = fopen(path, "rb");
    *objects = NULL;
    if (probe == NULL) {
        fprintf(stderr, "cannot open %s\n", path);
        Q3Object_Dispose(file);
        Q3Object_Dispose(storage);
        return -1;
    }
    fclose(probe);
    if (storage == NULL || file == NULL || Q3File_SetStorage(file, storage) != kQ3Success ||
        Q3File_OpenRead(file, &mode) != kQ3Success) {
        fprintf(stderr, "%s is not a 3DMF file Q3 can read: %s\n", path, Q3Error_GetMessage());
        if (file != NULL)
            Q3Object_Dispose(file);
        if (storage != NULL)
            Q3Object_Dispose(storage);
        return -1;
    }
    *objects = (TQ3Object *)malloc(sizeof(TQ3Object) * (size_t)capacity);
    while (*objects != NULL && Q3File_IsEndOfFile(file) == kQ3False) {
        TQ3Object object = Q3File_ReadObject(file);
        if (object == NULL) {
            fprintf(stderr, "%s: an object cannot be read: %s\n", path, Q3Error_GetMessage());
            count = -1 - count;
            break;
        }
        if (count == capacity) {
            TQ3Object *more = (TQ3Object *)realloc(*objects, sizeof(TQ3Object) * (size_t)(capacity * 2));
            if (more == NULL) {
                Q3Object_Dispose(object);
                break;
            }
            *objects = more;
            capacity *= 2;
        }
        (*objects)[count++] = object;
    }
    Q3File_Close(file);
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
    if (count < 0) {
        long i, read = -1 - count;
        for (i = 0; i < read; ++i)
            Q3Object_Dispose((*objects)[i]);
        free(*objects);
        *objects = NULL;
        return -1;
    }
    return count;
}

/* A warning callback (Q3Warning_Register) printing every warning the
 * library posts to stderr: an object left out of a file, a value
 * substituted, so that nothing is lost silently. */
static void q3load_printWarning(TQ3Warning firstWarning, TQ3Warning lastWarning, long reference)
{
    (void)firstWarning;
    (void)reference;
    fprintf(stderr, "warning %d: %s\n", (int)lastWarning, Q3Warning_GetMessage());
}

static void q3load_free(TQ3Object *objects, long count)
{
    long i;
    for (i = 0; i < count; ++i)
        Q3Object_Dispose(objects[i]);
    free(objects);
}

#endif /* Q3LOAD_H */
