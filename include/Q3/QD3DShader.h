/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Shaders and colours: the colour routines; the illumination shaders, which
 * choose how lights colour surfaces (Phong, Lambert, or none); the texture
 * shader, which paints a texture (a pixmap or mipmap held in a storage
 * object) over surfaces by their uv parameters; and what QuickDraw 3D 1.6
 * gives every shader (a uv transform and uv boundaries).
 *
 * Compressed pixmap textures (Q3CompressedPixmapTexture_, TQ3CompressedPixmap)
 * hold a QuickTime image and exist only on the Mac: Q3 does not declare them.
 *
 * A shader is a shape: submitted to a view in a rendering or bounding loop
 * (Q3Shader_Submit, Q3Object_Submit, or from a group) it becomes the view's
 * shader of its kind for the geometry submitted after it, until another
 * shader of that kind is submitted or a Q3Pop_Submit restores an earlier
 * state. Until an illumination shader is submitted, surfaces are drawn
 * unlit in their diffuse colours, as with the NULL illumination shader.
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error and leaves every object and output it was
 * given unchanged. "Not a live Q3 object" means a handle that was disposed
 * or never came from Q3. The checks run in this order, and the first that
 * fails decides the error: Q3 is initialized; then the arguments from left
 * to right (a handle: not NULL, a live Q3 object, of the right class; a
 * pointer: not NULL); then the function's other conditions in the order it
 * lists them. Every successful setter changes the shader's edit index
 * (Q3Shared_GetEditIndex); a failed one leaves it unchanged.
 */
#ifndef QD3DSHADER_H
#define QD3DSHADER_H

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Colours -------------------------------------------------------------- */

/*
 * The colour routines compute channel by channel in float arithmetic and
 * store the whole result before returning, so result may be one of the
 * inputs. They check only their pointers (kQ3ErrorNULLParameter, in
 * argument order) and return NULL after posting the error, leaving *result
 * unchanged; values outside 0..1, infinities and NaNs are computed with as
 * they are (Q3ColorRGB_Clamp brings a colour into 0..1). No objects are
 * involved, so none has an Ownership note beyond this one.
 */

/**
 * Sets the three channels of an RGB colour.
 *
 * @param color    receives (r, g, b).
 * @param r, g, b  the channels.
 * @return color, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   color is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3ColorRGB *) Q3ColorRGB_Set(TQ3ColorRGB *color, float r, float g, float b);

/**
 * Sets the four channels of an ARGB colour.
 *
 * @param color       receives (a, r, g, b).
 * @param a, r, g, b  the channels (a: 0 transparent, 1 opaque).
 * @return color, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   color is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3ColorARGB *) Q3ColorARGB_Set(TQ3ColorARGB *color, float a, float r, float g, float b);

/**
 * Adds two colours channel by channel: result = c1 + c2 (not clamped).
 *
 * @param c1, c2  the colours.
 * @param result  receives the sum; it may be c1 or c2.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   c1, c2 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3ColorRGB *) Q3ColorRGB_Add(const TQ3ColorRGB *c1, const TQ3ColorRGB *c2, TQ3ColorRGB *result);

/**
 * Subtracts one colour from another channel by channel: result = c1 - c2
 * (not clamped).
 *
 * @param c1, c2  the colours.
 * @param result  receives the difference; it may be c1 or c2.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   c1, c2 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3ColorRGB *) Q3ColorRGB_Subtract(const TQ3ColorRGB *c1, const TQ3ColorRGB *c2,
                                                   TQ3ColorRGB *result);

/**
 * Scales a colour: result = color * scale in each channel (not clamped).
 *
 * @param color   the colour.
 * @param scale   the factor.
 * @param result  receives the scaled colour; it may be color.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   color or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3ColorRGB *) Q3ColorRGB_Scale(const TQ3ColorRGB *color, float scale, TQ3ColorRGB *result);

/**
 * Clamps each channel of a colour into 0..1: a channel below 0 becomes 0
 * (-infinity included), one above 1 becomes 1 (+infinity included); a NaN
 * channel stays NaN.
 *
 * @param color   the colour.
 * @param result  receives the clamped colour; it may be color.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   color or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3ColorRGB *) Q3ColorRGB_Clamp(const TQ3ColorRGB *color, TQ3ColorRGB *result);

/**
 * Interpolates two colours linearly: result = first + alpha * (last - first)
 * in each channel, so alpha 0 gives first and 1 gives last (alpha is not
 * limited to 0..1).
 *
 * @param first, last  the colours.
 * @param alpha        where between them.
 * @param result       receives the colour; it may be first or last.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   first, last or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3ColorRGB *) Q3ColorRGB_Lerp(const TQ3ColorRGB *first, const TQ3ColorRGB *last, float alpha,
                                               TQ3ColorRGB *result);

/**
 * Adds a colour into another: result = result + src in each channel (not
 * clamped).
 *
 * @param src     the colour to add.
 * @param result  the colour added to, which receives the sum; it may be src.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   src or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3ColorRGB *) Q3ColorRGB_Accumulate(const TQ3ColorRGB *src, TQ3ColorRGB *result);

/**
 * Computes the luminance of a colour: 0.30078125 r + 0.58984375 g +
 * 0.109375 b (77, 151 and 28 parts in 256: the 0.30, 0.59, 0.11 video
 * weights, as Quesa computes them).
 *
 * @param color      the colour.
 * @param luminance  receives the luminance.
 * @return luminance, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   color or luminance is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(float *) Q3ColorRGB_Luminance(const TQ3ColorRGB *color, float *luminance);

/* ---- Shader types -------------------------------------------------------- */

/*
 * What a texture does outside 0..1 in u or v: repeat (wrap) or keep the
 * edge's value (clamp).
 */
enum TQ3ShaderUVBoundary { kQ3ShaderUVBoundaryWrap = 0, kQ3ShaderUVBoundaryClamp = 1 };
typedef enum TQ3ShaderUVBoundary TQ3ShaderUVBoundary;

/* ---- Every shader -------------------------------------------------------- */

/**
 * Returns the kind of a shader.
 *
 * @param shader  any shader.
 * @return kQ3ShaderTypeIllumination for an illumination shader,
 *         kQ3ShaderTypeSurface for a texture shader, or kQ3ObjectTypeInvalid
 *         on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      shader is NULL.
 *   kQ3ErrorInvalidObject      shader is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  shader is not a shader.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Shader_GetType(TQ3ShaderObject shader);

/**
 * Submits a shader to a view in a rendering or bounding loop: it becomes the
 * view's shader of its kind (see the top of this header). Q3Object_Submit
 * does the same.
 *
 * @param shader  the shader.
 * @param view    a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      shader or view is NULL.
 *   kQ3ErrorInvalidObject      shader or view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  shader is not a shader, or view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *
 * Ownership: the view keeps no reference beyond the loop.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Shader_Submit(TQ3ShaderObject shader, TQ3ViewObject view);

/**
 * Sets the matrix a shader applies to surface uv parameters, as row vectors
 * (u, v, 1), before it uses them. A new shader has the identity.
 *
 * @param shader       any shader.
 * @param uvTransform  the matrix; every entry must be finite.
 * @return kQ3Success, or kQ3Failure with the shader unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      shader or uvTransform is NULL.
 *   kQ3ErrorInvalidObject      shader is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  shader is not a shader.
 *   kQ3ErrorInvalidParameter   an entry of uvTransform is NaN or infinite.
 *
 * Ownership: no references change; *uvTransform is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Shader_SetUVTransform(TQ3ShaderObject shader,
                                                   const TQ3Matrix3x3 *uvTransform);

/**
 * Reads a shader's uv transform.
 *
 * @param shader       any shader.
 * @param uvTransform  receives the matrix.
 * @return kQ3Success, or kQ3Failure with *uvTransform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      shader or uvTransform is NULL.
 *   kQ3ErrorInvalidObject      shader is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  shader is not a shader.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Shader_GetUVTransform(TQ3ShaderObject shader, TQ3Matrix3x3 *uvTransform);

/**
 * Sets what a shader does with u values outside 0..1. A new shader wraps.
 *
 * @param shader     any shader.
 * @param uBoundary  kQ3ShaderUVBoundaryWrap or kQ3ShaderUVBoundaryClamp.
 * @return kQ3Success, or kQ3Failure with the shader unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      shader is NULL.
 *   kQ3ErrorInvalidObject      shader is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  shader is not a shader.
 *   kQ3ErrorInvalidParameter   uBoundary is not a TQ3ShaderUVBoundary value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Shader_SetUBoundary(TQ3ShaderObject shader, TQ3ShaderUVBoundary uBoundary);

/**
 * Sets what a shader does with v values outside 0..1. A new shader wraps.
 *
 * @param shader     any shader.
 * @param vBoundary  kQ3ShaderUVBoundaryWrap or kQ3ShaderUVBoundaryClamp.
 * @return kQ3Success, or kQ3Failure with the shader unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      shader is NULL.
 *   kQ3ErrorInvalidObject      shader is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  shader is not a shader.
 *   kQ3ErrorInvalidParameter   vBoundary is not a TQ3ShaderUVBoundary value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Shader_SetVBoundary(TQ3ShaderObject shader, TQ3ShaderUVBoundary vBoundary);

/**
 * Reads a shader's u boundary.
 *
 * @param shader     any shader.
 * @param uBoundary  receives kQ3ShaderUVBoundaryWrap or kQ3ShaderUVBoundaryClamp.
 * @return kQ3Success, or kQ3Failure with *uBoundary unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      shader or uBoundary is NULL.
 *   kQ3ErrorInvalidObject      shader is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  shader is not a shader.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Shader_GetUBoundary(TQ3ShaderObject shader, TQ3ShaderUVBoundary *uBoundary);

/**
 * Reads a shader's v boundary.
 *
 * @param shader     any shader.
 * @param vBoundary  receives kQ3ShaderUVBoundaryWrap or kQ3ShaderUVBoundaryClamp.
 * @return kQ3Success, or kQ3Failure with *vBoundary unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      shader or vBoundary is NULL.
 *   kQ3ErrorInvalidObject      shader is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  shader is not a shader.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Shader_GetVBoundary(TQ3ShaderObject shader, TQ3ShaderUVBoundary *vBoundary);

/* ---- Illumination shaders ------------------------------------------------ */

/**
 * Returns the illumination model of an illumination shader.
 *
 * @param shader  an illumination shader.
 * @return kQ3IlluminationTypePhong, kQ3IlluminationTypeLambert or
 *         kQ3IlluminationTypeNULL, or kQ3ObjectTypeInvalid on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      shader is NULL.
 *   kQ3ErrorInvalidObject      shader is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  shader is not an illumination shader.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3IlluminationShader_GetType(TQ3ShaderObject shader);

/**
 * Creates a Phong illumination shader: surfaces reflect ambient light and
 * the lights' diffuse and specular light (the specular colour and control
 * attributes give the highlights).
 *
 * @return the new shader, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorOutOfMemory     the shader cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new shader is born with
 * and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3ShaderObject) Q3PhongIllumination_New(void);

/**
 * Creates a Lambert illumination shader: surfaces reflect ambient light and
 * the lights' diffuse light, with no specular highlights.
 *
 * @return the new shader, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorOutOfMemory     the shader cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new shader is born with
 * and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3ShaderObject) Q3LambertIllumination_New(void);

/**
 * Creates a NULL illumination shader: lights are ignored and surfaces are
 * drawn in their own diffuse colours.
 *
 * @return the new shader, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorOutOfMemory     the shader cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new shader is born with
 * and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3ShaderObject) Q3NULLIllumination_New(void);

/* ---- Surface shaders ----------------------------------------------------- */

/**
 * Returns the kind of a surface shader.
 *
 * @param shader  a surface shader.
 * @return kQ3SurfaceShaderTypeTexture for a texture shader, or
 *         kQ3ObjectTypeInvalid on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      shader is NULL.
 *   kQ3ErrorInvalidObject      shader is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  shader is not a surface shader.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3SurfaceShader_GetType(TQ3SurfaceShaderObject shader);

/* ---- Texture shader ------------------------------------------------------ */

/**
 * Creates a texture shader: a surface shader that paints a texture over the
 * surfaces drawn after it.
 *
 * How it draws (the interactive renderer; the wireframe renderer draws no
 * surfaces, so no textures): submitted to a view, the shader is the view's
 * surface shader for the geometry submitted after it, until another surface
 * shader is submitted or Q3Pop_Submit restores an earlier state. Filled
 * triangles whose vertices have a uv (kQ3AttributeTypeSurfaceUV, else
 * kQ3AttributeTypeShadingUV, from the vertex, its face or the geometry; a
 * surface uv anywhere wins over a shading uv) are textured, a decomposed
 * geometry at a time: one with a vertex that has no uv is drawn as without
 * the shader. The box, the cone, cylinder, disk, ellipsoid and torus
 * (QD3DGeometry.h, "Drawing") and the NURB patch (its (u, v) parameters,
 * in its knots' units) give every vertex a surface uv of their own;
 * other geometries take them from their attribute sets. A vertex's (u, v) is first transformed by the shader's uv
 * transform as the row vector (u, v, 1) (its third column is not used: the
 * transform is affine); then u and v outside 0..1 wrap or clamp as the
 * shader's boundaries say. (0, 0) is the bottom left of the texture's image
 * and (1, 1) its top right (row 0 of the image is its top). The texture's
 * colour takes the place of the diffuse colour: unlit, a textured pixel is
 * the texture's colour; under a Lambert or Phong illumination shader it is
 * lit with the texture's colour as its diffuse colour (Phong highlights are
 * added on top, in the specular colour). Texels are sampled nearest, from
 * the first image of a mipmap, so that images are reproducible pixel for
 * pixel; alpha is not used (textured surfaces are opaque).
 *
 * @param texture  a pixmap or mipmap texture.
 * @return the new shader, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      texture is NULL.
 *   kQ3ErrorInvalidObject      texture is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  texture is not a texture.
 *   kQ3ErrorOutOfMemory        the shader cannot be allocated.
 *
 * Ownership: the shader takes a reference to texture. The caller owns the
 * one reference the new shader is born with and releases it with
 * Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3ShaderObject) Q3TextureShader_New(TQ3TextureObject texture);

/**
 * Reads a texture shader's texture.
 *
 * @param shader   a texture shader.
 * @param texture  receives the texture.
 * @return kQ3Success, or kQ3Failure with *texture unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      shader or texture is NULL.
 *   kQ3ErrorInvalidObject      shader is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  shader is not a texture shader.
 *
 * Ownership: *texture receives a new reference, which the caller releases
 * with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TextureShader_GetTexture(TQ3ShaderObject shader, TQ3TextureObject *texture);

/**
 * Replaces a texture shader's texture.
 *
 * @param shader   a texture shader.
 * @param texture  a pixmap or mipmap texture.
 * @return kQ3Success, or kQ3Failure with the shader unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      shader or texture is NULL.
 *   kQ3ErrorInvalidObject      shader or texture is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  shader is not a texture shader, or texture is
 *                              not a texture.
 *
 * Ownership: the shader takes a reference to texture and releases the one
 * it held to its previous texture.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TextureShader_SetTexture(TQ3ShaderObject shader, TQ3TextureObject texture);

/* ---- Textures ------------------------------------------------------------ */

/*
 * A texture is a shared object holding an image in a storage object: a
 * pixmap texture one image (TQ3StoragePixmap), a mipmap texture one image
 * or a chain of them (TQ3Mipmap). The image is read from the storage when
 * it is drawn, so the storage's contents may change after the texture is
 * made; drawing a texture whose storage no longer holds its image fails
 * with kQ3ErrorInvalidData. Pixels are laid out as QD3DDrawContext.h's
 * pixel table says, top row first.
 *
 * Data rules, checked in this order by New and Set (the first that fails
 * decides the error; the texture is then unchanged):
 *   image is not NULL, a live Q3 object, a storage
 *                             kQ3ErrorNULLParameter, kQ3ErrorInvalidObject,
 *                             kQ3ErrorInvalidObjectType
 *   (mipmaps) useMipmapping is kQ3False or kQ3True        kQ3ErrorInvalidData
 *   pixelType is a TQ3PixelType value                       kQ3ErrorInvalidData
 *   byteOrder and bitOrder are TQ3Endian values             kQ3ErrorInvalidData
 *   (pixmaps) pixelSize is the pixel type's bits (16, 24 or 32)
 *                                                  kQ3ErrorUnsupportedPixelDepth
 *   (mipmaps) reserved is 0                                 kQ3ErrorInvalidData
 *   each image (a mipmap's first, then with useMipmapping each next one):
 *     width and height are 1 to 4096 pixels                 kQ3ErrorInvalidData
 *     (mipmaps with useMipmapping) the first image's width and height are
 *       powers of 2, and image i is max(1, width >> i) x max(1, height >> i)
 *       for i = 1 .. log2 of the larger side                kQ3ErrorInvalidData
 *     rowBytes holds width pixels                           kQ3ErrorInvalidData
 *     (mipmaps) offset + rowBytes * height, and (pixmaps) rowBytes * height,
 *       is at most the storage's size now                   kQ3ErrorInvalidData
 * A mipmap texture without useMipmapping reads only mipmaps[0]; with it,
 * the entries after the last image are not read.
 */

/**
 * Returns the kind of a texture.
 *
 * @param texture  a texture.
 * @return kQ3TextureTypePixmap or kQ3TextureTypeMipmap, or
 *         kQ3ObjectTypeInvalid on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      texture is NULL.
 *   kQ3ErrorInvalidObject      texture is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  texture is not a texture.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Texture_GetType(TQ3TextureObject texture);

/**
 * Reads the width of a texture's image (a mipmap's first image), in pixels.
 *
 * @param texture  a texture.
 * @param width    receives the width.
 * @return kQ3Success, or kQ3Failure with *width unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      texture or width is NULL.
 *   kQ3ErrorInvalidObject      texture is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  texture is not a texture.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Texture_GetWidth(TQ3TextureObject texture, unsigned long *width);

/**
 * Reads the height of a texture's image (a mipmap's first image), in
 * pixels.
 *
 * @param texture  a texture.
 * @param height   receives the height.
 * @return kQ3Success, or kQ3Failure with *height unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      texture or height is NULL.
 *   kQ3ErrorInvalidObject      texture is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  texture is not a texture.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Texture_GetHeight(TQ3TextureObject texture, unsigned long *height);

/* ---- Pixmap texture ------------------------------------------------------ */

/**
 * Creates a pixmap texture from one image in a storage object.
 *
 * @param pixmap  the image: the data rules above.
 * @return the new texture, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   pixmap is NULL.
 *   the data rules' errors, in their order.
 *   kQ3ErrorOutOfMemory     the texture cannot be allocated.
 *
 * Ownership: the texture takes a reference to pixmap->image. The caller
 * owns the one reference the new texture is born with and releases it with
 * Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3TextureObject) Q3PixmapTexture_New(const TQ3StoragePixmap *pixmap);

/**
 * Reads a pixmap texture's image description.
 *
 * @param texture  a pixmap texture.
 * @param pixmap   receives the description.
 * @return kQ3Success, or kQ3Failure with *pixmap unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      texture or pixmap is NULL.
 *   kQ3ErrorInvalidObject      texture is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  texture is not a pixmap texture.
 *
 * Ownership: pixmap->image receives a new reference to the storage, which
 * the caller releases with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapTexture_GetPixmap(TQ3TextureObject texture, TQ3StoragePixmap *pixmap);

/**
 * Replaces a pixmap texture's image.
 *
 * @param texture  a pixmap texture.
 * @param pixmap   the new image: the data rules above.
 * @return kQ3Success, or kQ3Failure with the texture unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      texture or pixmap is NULL.
 *   kQ3ErrorInvalidObject      texture is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  texture is not a pixmap texture.
 *   the data rules' errors, in their order.
 *
 * Ownership: the texture takes a reference to pixmap->image and releases
 * the one it held to its previous storage.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapTexture_SetPixmap(TQ3TextureObject texture, const TQ3StoragePixmap *pixmap);

/* ---- Mipmap texture ------------------------------------------------------ */

/**
 * Creates a mipmap texture from one image, or a chain of images, in a
 * storage object.
 *
 * @param mipmap  the images: the data rules above.
 * @return the new texture, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   mipmap is NULL.
 *   the data rules' errors, in their order.
 *   kQ3ErrorOutOfMemory     the texture cannot be allocated.
 *
 * Ownership: the texture takes a reference to mipmap->image. The caller
 * owns the one reference the new texture is born with and releases it with
 * Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3TextureObject) Q3MipmapTexture_New(const TQ3Mipmap *mipmap);

/**
 * Reads a mipmap texture's description: every field as it was given
 * (the mipmaps entries that are not read included).
 *
 * @param texture  a mipmap texture.
 * @param mipmap   receives the description.
 * @return kQ3Success, or kQ3Failure with *mipmap unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      texture or mipmap is NULL.
 *   kQ3ErrorInvalidObject      texture is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  texture is not a mipmap texture.
 *
 * Ownership: mipmap->image receives a new reference to the storage, which
 * the caller releases with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3MipmapTexture_GetMipmap(TQ3TextureObject texture, TQ3Mipmap *mipmap);

/**
 * Replaces a mipmap texture's images.
 *
 * @param texture  a mipmap texture.
 * @param mipmap   the new images: the data rules above.
 * @return kQ3Success, or kQ3Failure with the texture unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      texture or mipmap is NULL.
 *   kQ3ErrorInvalidObject      texture is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  texture is not a mipmap texture.
 *   the data rules' errors, in their order.
 *
 * Ownership: the texture takes a reference to mipmap->image and releases
 * the one it held to its previous storage.
 */
Q3_EXTERN_API_C(TQ3Status) Q3MipmapTexture_SetMipmap(TQ3TextureObject texture, const TQ3Mipmap *mipmap);

#ifdef __cplusplus
}
#endif

#endif /* QD3DSHADER_H */
