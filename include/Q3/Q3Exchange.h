/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef Q3EXCHANGE_H
#define Q3EXCHANGE_H

/*
 * Q3 extension: model exchange with today's formats (QuickDraw 3D had none
 * of this). Q3Exchange_Write writes what a group or geometry draws as glTF
 * 2.0 (.gltf, .glb), Wavefront OBJ (.obj) or STL (.stl); Q3Exchange_Read
 * reads such a file into a display group of TriMeshes, so that a QuickDraw
 * 3D program can load new content.
 *
 *     TQ3ExchangeOptions options;
 *     Q3Exchange_InitOptions(&options);
 *     Q3Exchange_Write(group, "model.glb", &options);
 *     TQ3GroupObject back = Q3Exchange_Read("model.glb", kQ3ExchangeFormatAny);
 *
 * docs/exchange.md gives every mapping and what each format cannot carry.
 */

#include "QD3D.h"
#include "QD3DStyle.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A file format. kQ3ExchangeFormatAny: from the file name's extension
 * (.gltf, .glb, .obj, .stl), case-insensitively. */
typedef enum TQ3ExchangeFormat {
    kQ3ExchangeFormatAny = 0,
    kQ3ExchangeFormatGLTF = 1, /* glTF 2.0, JSON with the buffer embedded */
    kQ3ExchangeFormatGLB = 2,  /* glTF 2.0, binary container, PNG textures inside */
    kQ3ExchangeFormatOBJ = 3,  /* Wavefront OBJ with its MTL file, PNG textures beside it */
    kQ3ExchangeFormatSTL = 4   /* binary STL: triangles only */
} TQ3ExchangeFormat;

/* How Q3Exchange_Write works. format: as above. subdivisionFromSize:
 * kQ3True (the default) subdivides in world space, no side longer than
 * 1/32 of the diagonal of the model's bounding box; kQ3False uses
 * subdivisionMethod, kQ3SubdivisionMethodWorldSpace (subdivisionValue the
 * longest side, in world units), kQ3SubdivisionMethodConstant
 * (subdivisionValue segments around, and along, each curve and surface) or,
 * with a view, kQ3SubdivisionMethodScreenSpace (subdivisionValue pixels).
 * Either replaces every subdivision style of the model. view: NULL (the
 * default), or a view with a camera and a pixmap draw context whose pane
 * lengths are measured in, as its rendering loop measures them, so that
 * the file holds the triangles that view draws. */
typedef struct TQ3ExchangeOptions {
    TQ3ExchangeFormat format;
    TQ3Boolean subdivisionFromSize;
    TQ3SubdivisionMethod subdivisionMethod;
    float subdivisionValue;
    TQ3ViewObject view;
} TQ3ExchangeOptions;

/*
 * Q3Exchange_InitOptions: fills *options with the defaults (format from the
 * extension, subdivision from the model's size).
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   options is NULL.
 * Ownership: none.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Exchange_InitOptions(TQ3ExchangeOptions *options);

/*
 * Q3Exchange_Write: writes what `object` draws to the file at path. object
 * is a geometry, a display group, or a plain group whose objects are taken
 * in order (cameras and lights among them become glTF cameras and
 * KHR_lights_punctual lights; Q3File_ReadObject's results put into one
 * Q3Group_New group give a whole file). Every geometry is decomposed into
 * triangles, line strips and points as Q3Geometry_GetDecomposed does. The
 * file is written beside path under a temporary name and renamed over path
 * when complete: on failure nothing is left at path and an older file there
 * is unchanged. OBJ and STL are flat: each drawn mesh is written with its
 * transform applied. An OBJ file's MTL file (<stem>.mtl) and textures
 * (<stem>_<n>.png) are written beside it, renamed into place before the
 * .obj. STL keeps triangles only.
 *
 * @param object   the group or geometry.
 * @param path     the file to write.
 * @param options  NULL for the defaults.
 * @return kQ3Success, or kQ3Failure with an error posted.
 *
 * Errors:
 *   kQ3ErrorNotInitialized        Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter         object or path is NULL.
 *   kQ3ErrorInvalidObject         object (or options->view) is not a live
 *                                 Q3 object.
 *   kQ3ErrorInvalidObjectType     options->view is not a view.
 *   kQ3ErrorInvalidParameter      the format is not one above, or Any and
 *                                 the extension names none; the subdivision
 *                                 method is not one above (screen space
 *                                 without a view with a camera and a pixmap
 *                                 draw context), or its value is not finite
 *                                 and greater than 0.
 *   kQ3ErrorFileNotOpen           the file cannot be written.
 *   kQ3ErrorInvalidData           a texture's storage no longer holds its
 *                                 image.
 *   kQ3ErrorOutOfMemory           memory ran out.
 * Warnings:
 *   kQ3WarningFunctionalityNotSupported  an object the format has no place
 *                                 for (a string, view hints) was left out.
 *   kQ3WarningParameterOutOfRange a subdivision value QD3DStyle.h's rules
 *                                 replace (as a subdivision style would).
 * Ownership: none; object is not changed.
 */
Q3_EXTERN_API_C(TQ3Status)
Q3Exchange_Write(TQ3Object object, const char *path, const TQ3ExchangeOptions *options);

/*
 * Q3Exchange_Read: the file at path as a new display group: per glTF node a
 * display group with a matrix transform, the node's meshes as TriMeshes
 * (vertex normals, surface uvs, diffuse and transparency colours as
 * attribute arrays; the material in the TriMesh's attribute set, its
 * texture as a texture shader with a mipmap texture under
 * kQ3AttributeTypeSurfaceShader), PolyLines and Points, then its children's groups.
 * A mesh used by several nodes is shared. glTF cameras (a view angle aspect
 * or orthographic camera) and KHR_lights_punctual lights (in one light
 * group) are placed in world coordinates and added to the returned group,
 * which holds them without drawing them (Q3Group_GetFirstPositionOfType).
 *
 * An OBJ file's material files and textures (PNG) must be beside it.
 *
 * @param path    the file to read.
 * @param format  kQ3ExchangeFormatAny: OBJ and STL by the extension, glTF
 *                and GLB told apart by content.
 * @return a new display group, or NULL with an error posted.
 *
 * Errors:
 *   kQ3ErrorNotInitialized           Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter            path is NULL.
 *   kQ3ErrorInvalidParameter         format is not one above.
 *   kQ3ErrorFileNotOpen              the file cannot be opened.
 *   kQ3ErrorInvalidData              the file is not valid glTF 2.0, OBJ or
 *                                    STL (the message says where), an OBJ's
 *                                    material file or texture is missing,
 *                                    or a texture is not a PNG image.
 *   kQ3ErrorUnsupportedFunctionality the file requires an extension Q3 does
 *                                    not read.
 *   kQ3ErrorOutOfMemory              memory ran out.
 * Ownership: the caller owns the group's one reference.
 */
Q3_EXTERN_API_C(TQ3GroupObject) Q3Exchange_Read(const char *path, TQ3ExchangeFormat format);

#ifdef __cplusplus
}
#endif

#endif
