/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Shaders: the illumination shaders, which choose how lights colour
 * surfaces (Phong, Lambert, or none), and what QuickDraw 3D 1.6 gives every
 * shader (a uv transform and uv boundaries).
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
 * @return kQ3ShaderTypeIllumination for an illumination shader, or
 *         kQ3ObjectTypeInvalid on failure.
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

#ifdef __cplusplus
}
#endif

#endif /* QD3DSHADER_H */
