/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Transforms: objects and immediate-mode calls that change a view's
 * local-to-world transform while a scene is submitted.
 *
 * Submitting a transform with matrix T inside a traversal changes the view's
 * local-to-world matrix L to T * L (matrices act on row vectors, see QD3D.h):
 * T applies to geometry submitted afterwards, before every transform already
 * in effect. Q3Push_Submit / Q3Pop_Submit (QD3DView.h) save and restore L.
 *
 * A retained transform's value can be read and replaced; a replacement
 * checks what _New checks, bumps the edit index (Q3Shared_GetEditIndex), and
 * takes effect the next time the transform is submitted.
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error and leaves every object and output it was
 * given unchanged. "Not a live Q3 object" means a handle that was disposed
 * or never came from Q3. The checks run in this order, and the first that
 * fails decides the error: Q3 is initialized; then the arguments from left
 * to right (a handle: not NULL, a live Q3 object, of the right class; a
 * pointer: not NULL); then the function's other conditions in the order it
 * lists them (for a data structure, the rules given with its type, in their
 * order).
 */
#ifndef QD3DTRANSFORM_H
#define QD3DTRANSFORM_H

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * A rotation by radians about one coordinate axis through the local origin;
 * positive angles turn counterclockwise as seen from the positive end of the
 * axis (y towards z about X, z towards x about Y, x towards y about Z), the
 * same matrix as Q3Matrix4x4_SetRotate_X/_Y/_Z (QD3DMath.h).
 * Rules, reported as kQ3ErrorInvalidData: axis is a TQ3Axis value and
 * radians is finite.
 */
struct TQ3RotateTransformData {
    TQ3Axis axis;
    float radians;
};
typedef struct TQ3RotateTransformData TQ3RotateTransformData;

/* ---- Any transform ------------------------------------------------------ */

/**
 * Reports the kind of a transform.
 *
 * @param transform  the transform to query.
 * @return kQ3TransformTypeMatrix, kQ3TransformTypeTranslate,
 *         kQ3TransformTypeScale, kQ3TransformTypeRotate,
 *         kQ3TransformTypeRotateAboutPoint, kQ3TransformTypeRotateAboutAxis,
 *         kQ3TransformTypeQuaternion or kQ3TransformTypeReset, or
 *         kQ3ObjectTypeInvalid on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Transform_GetType(TQ3TransformObject transform);

/**
 * Computes the matrix a transform of any kind applies when submitted
 * (row vectors, see above); for a reset transform, the identity it puts in
 * place.
 *
 * @param transform  the transform.
 * @param matrix     receives the matrix.
 * @return matrix, or NULL on failure with *matrix unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or matrix is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Transform_GetMatrix(TQ3TransformObject transform,
                                                      TQ3Matrix4x4 *matrix);

/**
 * Submits a transform object of any kind to a view (retained mode): it
 * multiplies the view's local-to-world transform like the kind's own
 * immediate-mode Submit call. Q3Object_Submit does the same for any
 * submittable object.
 *
 * @param transform  the transform.
 * @param view       a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or view is NULL.
 *   kQ3ErrorInvalidObject      transform or view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a transform, or view is not
 *                              a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Transform_Submit(TQ3TransformObject transform,
                                              TQ3ViewObject view);

/* ---- Matrix transform --------------------------------------------------- */

/**
 * Creates a transform object holding an arbitrary matrix (it need not be
 * invertible).
 *
 * @param matrix  the matrix; every entry must be finite. It is copied.
 * @return the new transform, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     matrix is NULL.
 *   kQ3ErrorInvalidParameter  an entry of *matrix is not finite.
 *   kQ3ErrorOutOfMemory       the transform cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new transform is born
 * with and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3TransformObject) Q3MatrixTransform_New(const TQ3Matrix4x4 *matrix);

/**
 * Applies a matrix to a view's local-to-world transform without creating an
 * object (immediate mode).
 *
 * @param matrix  the matrix; every entry must be finite.
 * @param view    a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      matrix or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   kQ3ErrorInvalidParameter   an entry of *matrix is not finite.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3MatrixTransform_Submit(const TQ3Matrix4x4 *matrix,
                                                    TQ3ViewObject view);

/**
 * Replaces the matrix of a matrix transform.
 *
 * @param transform  the matrix transform to change.
 * @param matrix     the new matrix; every entry must be finite. It is copied.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or matrix is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a matrix transform.
 *   kQ3ErrorInvalidParameter   an entry of *matrix is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3MatrixTransform_Set(TQ3TransformObject transform,
                                                 const TQ3Matrix4x4 *matrix);

/**
 * Reads the matrix of a matrix transform.
 *
 * @param transform  the matrix transform to read.
 * @param matrix     receives the matrix.
 * @return kQ3Success, or kQ3Failure with *matrix unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or matrix is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a matrix transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3MatrixTransform_Get(TQ3TransformObject transform,
                                                 TQ3Matrix4x4 *matrix);

/* ---- Translate transform ------------------------------------------------ */

/**
 * Creates a transform object that moves geometry by a vector.
 *
 * @param translate  the offset; its components must be finite. It is copied.
 * @return the new transform, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     translate is NULL.
 *   kQ3ErrorInvalidParameter  a component of *translate is not finite.
 *   kQ3ErrorOutOfMemory       the transform cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new transform is born
 * with and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3TransformObject) Q3TranslateTransform_New(const TQ3Vector3D *translate);

/**
 * Applies a translation to a view's local-to-world transform without
 * creating an object (immediate mode).
 *
 * @param translate  the offset; its components must be finite.
 * @param view       a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      translate or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   kQ3ErrorInvalidParameter   a component of *translate is not finite.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TranslateTransform_Submit(const TQ3Vector3D *translate,
                                                       TQ3ViewObject view);

/**
 * Replaces the offset of a translate transform.
 *
 * @param transform  the translate transform to change.
 * @param translate  the new offset; its components must be finite. It is
 *                   copied.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or translate is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a translate transform.
 *   kQ3ErrorInvalidParameter   a component of *translate is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TranslateTransform_Set(TQ3TransformObject transform,
                                                    const TQ3Vector3D *translate);

/**
 * Reads the offset of a translate transform.
 *
 * @param transform  the translate transform to read.
 * @param translate  receives the offset.
 * @return kQ3Success, or kQ3Failure with *translate unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or translate is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a translate transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TranslateTransform_Get(TQ3TransformObject transform,
                                                    TQ3Vector3D *translate);

/* ---- Scale transform ---------------------------------------------------- */

/**
 * Creates a transform object that scales geometry about the local origin,
 * by a separate factor along each axis (zero and negative factors allowed).
 *
 * @param scale  the factors; they must be finite. They are copied.
 * @return the new transform, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     scale is NULL.
 *   kQ3ErrorInvalidParameter  a component of *scale is not finite.
 *   kQ3ErrorOutOfMemory       the transform cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new transform is born
 * with and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3TransformObject) Q3ScaleTransform_New(const TQ3Vector3D *scale);

/**
 * Applies a scale to a view's local-to-world transform without creating an
 * object (immediate mode).
 *
 * @param scale  the factors; they must be finite.
 * @param view   a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      scale or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   kQ3ErrorInvalidParameter   a component of *scale is not finite.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ScaleTransform_Submit(const TQ3Vector3D *scale, TQ3ViewObject view);

/**
 * Replaces the factors of a scale transform (zero and negative factors
 * allowed, as in Q3ScaleTransform_New).
 *
 * @param transform  the scale transform to change.
 * @param scale      the new factors; they must be finite. They are copied.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or scale is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a scale transform.
 *   kQ3ErrorInvalidParameter   a component of *scale is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ScaleTransform_Set(TQ3TransformObject transform,
                                                const TQ3Vector3D *scale);

/**
 * Reads the factors of a scale transform.
 *
 * @param transform  the scale transform to read.
 * @param scale      receives the factors.
 * @return kQ3Success, or kQ3Failure with *scale unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or scale is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a scale transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ScaleTransform_Get(TQ3TransformObject transform, TQ3Vector3D *scale);

/* ---- Rotate transform --------------------------------------------------- */

/**
 * Creates a transform object that rotates geometry about one coordinate
 * axis.
 *
 * @param data  the axis and angle; they must obey the TQ3RotateTransformData
 *              rules. They are copied.
 * @return the new transform, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   data is NULL.
 *   kQ3ErrorInvalidData     axis is not a TQ3Axis value, or radians is not
 *                           finite.
 *   kQ3ErrorOutOfMemory     the transform cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new transform is born
 * with and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3TransformObject) Q3RotateTransform_New(const TQ3RotateTransformData *data);

/**
 * Applies a rotation about one coordinate axis to a view's local-to-world
 * transform without creating an object (immediate mode).
 *
 * @param data  the axis and angle; they must obey the TQ3RotateTransformData
 *              rules.
 * @param view  a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      data or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   kQ3ErrorInvalidData        axis is not a TQ3Axis value, or radians is not
 *                              finite.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateTransform_Submit(const TQ3RotateTransformData *data,
                                                    TQ3ViewObject view);

/**
 * Replaces the axis and angle of a rotate transform.
 *
 * @param transform  the rotate transform to change.
 * @param data       the new axis and angle; they must obey the
 *                   TQ3RotateTransformData rules. They are copied.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or data is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate transform.
 *   kQ3ErrorInvalidData        axis is not a TQ3Axis value, or radians is not
 *                              finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateTransform_SetData(TQ3TransformObject transform,
                                                     const TQ3RotateTransformData *data);

/**
 * Reads the axis and angle of a rotate transform.
 *
 * @param transform  the rotate transform to read.
 * @param data       receives the axis and angle.
 * @return kQ3Success, or kQ3Failure with *data unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or data is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateTransform_GetData(TQ3TransformObject transform,
                                                     TQ3RotateTransformData *data);

/**
 * Replaces the axis of a rotate transform, keeping its angle.
 *
 * @param transform  the rotate transform to change.
 * @param axis       the new axis: kQ3AxisX, kQ3AxisY or kQ3AxisZ.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate transform.
 *   kQ3ErrorInvalidData        axis is not a TQ3Axis value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateTransform_SetAxis(TQ3TransformObject transform, TQ3Axis axis);

/**
 * Reads the axis of a rotate transform.
 *
 * @param transform  the rotate transform to read.
 * @param axis       receives the axis.
 * @return kQ3Success, or kQ3Failure with *axis unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or axis is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateTransform_GetAxis(TQ3TransformObject transform, TQ3Axis *axis);

/**
 * Replaces the angle of a rotate transform, keeping its axis.
 *
 * @param transform  the rotate transform to change.
 * @param radians    the new angle; it must be finite.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate transform.
 *   kQ3ErrorInvalidData        radians is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateTransform_SetAngle(TQ3TransformObject transform, float radians);

/**
 * Reads the angle of a rotate transform.
 *
 * @param transform  the rotate transform to read.
 * @param radians    receives the angle.
 * @return kQ3Success, or kQ3Failure with *radians unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or radians is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateTransform_GetAngle(TQ3TransformObject transform,
                                                      float *radians);

/* ---- Quaternion transform ------------------------------------------------ */

/*
 * A rotation given as a quaternion (w, x, y, z): submitting it multiplies the
 * local-to-world matrix by Q3Matrix4x4_SetQuaternion's matrix of the
 * quaternion scaled to unit length (QD3DMath.h). Rules, reported as
 * kQ3ErrorInvalidParameter: every component is finite and the quaternion is
 * not (0, 0, 0, 0). 3DMF: Quaternion ( w x y z ), docs/3dmf.md.
 */

/**
 * Creates a quaternion transform.
 *
 * @param quaternion  the rotation; it must obey the rules above. It is copied.
 * @return the new transform, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      quaternion is NULL.
 *   kQ3ErrorInvalidParameter   a component is not finite, or all are 0.
 *   kQ3ErrorOutOfMemory        the transform cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new transform is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3TransformObject) Q3QuaternionTransform_New(const TQ3Quaternion *quaternion);

/**
 * Applies a quaternion rotation to a view's local-to-world transform
 * without creating an object (immediate mode).
 *
 * @param quaternion  the rotation; it must obey the rules above.
 * @param view  a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      quaternion or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   kQ3ErrorInvalidParameter   a component is not finite, or all are 0.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3QuaternionTransform_Submit(const TQ3Quaternion *quaternion, TQ3ViewObject view);

/**
 * Replaces the quaternion of a quaternion transform.
 *
 * @param transform  the quaternion transform to change.
 * @param quaternion  the new rotation; it must obey the rules above.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or quaternion is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a quaternion transform.
 *   kQ3ErrorInvalidParameter   a component is not finite, or all are 0.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3QuaternionTransform_Set(TQ3TransformObject transform,
                                                     const TQ3Quaternion *quaternion);

/**
 * Reads the quaternion of a quaternion transform, as set (not normalized).
 *
 * @param transform  the quaternion transform to read.
 * @param quaternion  receives the quaternion.
 * @return kQ3Success, or kQ3Failure with *quaternion unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or quaternion is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a quaternion transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3QuaternionTransform_Get(TQ3TransformObject transform, TQ3Quaternion *quaternion);

/* ---- Rotate-about-point transform ----------------------------------------- */

/*
 * A rotation by radians about the line through `about` parallel to one
 * coordinate axis, turning as TQ3RotateTransformData does: the matrix of
 * Q3Matrix4x4_SetRotateAboutPoint with the other two angles 0 (QD3DMath.h).
 * Rules, reported as kQ3ErrorInvalidData: axis is a TQ3Axis value, radians
 * and the coordinates of about are finite. 3DMF: RotateAboutPoint ( axis
 * radians about ), docs/3dmf.md.
 */
struct TQ3RotateAboutPointTransformData {
    TQ3Axis axis;
    float radians;
    TQ3Point3D about;
};
typedef struct TQ3RotateAboutPointTransformData TQ3RotateAboutPointTransformData;

/**
 * Creates a rotate-about-point transform.
 *
 * @param data  the axis, angle and point; they must obey the rules above.
 *              They are copied.
 * @return the new transform, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      data is NULL.
 *   kQ3ErrorInvalidData        data breaks a TQ3RotateAboutPointTransformData rule.
 *   kQ3ErrorOutOfMemory        the transform cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new transform is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3TransformObject) Q3RotateAboutPointTransform_New(const TQ3RotateAboutPointTransformData *data);

/**
 * Applies a rotation about a point to a view's local-to-world transform
 * without creating an object (immediate mode).
 *
 * @param data  the axis, angle and point; they must obey the rules above.
 * @param view  a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      data or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   kQ3ErrorInvalidData        data breaks a TQ3RotateAboutPointTransformData rule.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutPointTransform_Submit(const TQ3RotateAboutPointTransformData *data,
                                                              TQ3ViewObject view);

/**
 * Replaces the data of a rotate-about-point transform.
 *
 * @param transform  the rotate-about-point transform to change.
 * @param data  the new data; it must obey the rules above. It is copied.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or data is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-point transform.
 *   kQ3ErrorInvalidData        data breaks a TQ3RotateAboutPointTransformData rule.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutPointTransform_SetData(TQ3TransformObject transform,
                                                               const TQ3RotateAboutPointTransformData *data);

/**
 * Reads the data of a rotate-about-point transform.
 *
 * @param transform  the rotate-about-point transform to read.
 * @param data  receives the data.
 * @return kQ3Success, or kQ3Failure with *data unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or data is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-point transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutPointTransform_GetData(TQ3TransformObject transform,
                                                               TQ3RotateAboutPointTransformData *data);

/**
 * Replaces the axis of a rotate-about-point transform, keeping the rest.
 *
 * @param transform  the rotate-about-point transform to change.
 * @param axis  the new axis: kQ3AxisX, kQ3AxisY or kQ3AxisZ.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-point transform.
 *   kQ3ErrorInvalidData        axis is not a TQ3Axis value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutPointTransform_SetAxis(TQ3TransformObject transform, TQ3Axis axis);

/**
 * Reads the axis of a rotate-about-point transform.
 *
 * @param transform  the rotate-about-point transform to read.
 * @param axis  receives the axis.
 * @return kQ3Success, or kQ3Failure with *axis unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or axis is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-point transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutPointTransform_GetAxis(TQ3TransformObject transform, TQ3Axis *axis);

/**
 * Replaces the angle of a rotate-about-point transform, keeping the rest.
 *
 * @param transform  the rotate-about-point transform to change.
 * @param radians  the new angle; it must be finite.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-point transform.
 *   kQ3ErrorInvalidData        radians is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutPointTransform_SetAngle(TQ3TransformObject transform, float radians);

/**
 * Reads the angle of a rotate-about-point transform.
 *
 * @param transform  the rotate-about-point transform to read.
 * @param radians  receives the angle.
 * @return kQ3Success, or kQ3Failure with *radians unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or radians is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-point transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutPointTransform_GetAngle(TQ3TransformObject transform, float *radians);

/**
 * Replaces the point a rotate-about-point transform turns about, keeping
 * the rest.
 *
 * @param transform  the rotate-about-point transform to change.
 * @param about  the new point; its coordinates must be finite.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or about is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-point transform.
 *   kQ3ErrorInvalidData        a coordinate of about is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutPointTransform_SetAboutPoint(TQ3TransformObject transform,
                                                                     const TQ3Point3D *about);

/**
 * Reads the point a rotate-about-point transform turns about.
 *
 * @param transform  the rotate-about-point transform to read.
 * @param about  receives the point.
 * @return kQ3Success, or kQ3Failure with *about unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or about is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-point transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutPointTransform_GetAboutPoint(TQ3TransformObject transform,
                                                                     TQ3Point3D *about);

/* ---- Rotate-about-axis transform ------------------------------------------ */

/*
 * A rotation by radians about the line through origin along orientation,
 * counterclockwise as seen from the tip of orientation: the matrix of
 * Q3Matrix4x4_SetRotateAboutAxis (QD3DMath.h). orientation may have any
 * length but 0. Rules, reported as kQ3ErrorInvalidData: the coordinates of
 * origin and orientation and radians are finite, and orientation is not the
 * zero vector. 3DMF: RotateAboutAxis ( origin orientation radians ),
 * docs/3dmf.md.
 */
struct TQ3RotateAboutAxisTransformData {
    TQ3Point3D origin;
    TQ3Vector3D orientation;
    float radians;
};
typedef struct TQ3RotateAboutAxisTransformData TQ3RotateAboutAxisTransformData;

/**
 * Creates a rotate-about-axis transform.
 *
 * @param data  the line and angle; they must obey the rules above. They
 *              are copied.
 * @return the new transform, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      data is NULL.
 *   kQ3ErrorInvalidData        data breaks a TQ3RotateAboutAxisTransformData rule.
 *   kQ3ErrorOutOfMemory        the transform cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new transform is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3TransformObject) Q3RotateAboutAxisTransform_New(const TQ3RotateAboutAxisTransformData *data);

/**
 * Applies a rotation about a line to a view's local-to-world transform
 * without creating an object (immediate mode).
 *
 * @param data  the line and angle; they must obey the rules above.
 * @param view  a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      data or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   kQ3ErrorInvalidData        data breaks a TQ3RotateAboutAxisTransformData rule.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutAxisTransform_Submit(const TQ3RotateAboutAxisTransformData *data,
                                                             TQ3ViewObject view);

/**
 * Replaces the data of a rotate-about-axis transform.
 *
 * @param transform  the rotate-about-axis transform to change.
 * @param data  the new data; it must obey the rules above. It is copied.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or data is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-axis transform.
 *   kQ3ErrorInvalidData        data breaks a TQ3RotateAboutAxisTransformData rule.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutAxisTransform_SetData(TQ3TransformObject transform,
                                                              const TQ3RotateAboutAxisTransformData *data);

/**
 * Reads the data of a rotate-about-axis transform.
 *
 * @param transform  the rotate-about-axis transform to read.
 * @param data  receives the data.
 * @return kQ3Success, or kQ3Failure with *data unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or data is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-axis transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutAxisTransform_GetData(TQ3TransformObject transform,
                                                              TQ3RotateAboutAxisTransformData *data);

/**
 * Replaces the direction of a rotate-about-axis transform's line, keeping
 * the rest.
 *
 * @param transform  the rotate-about-axis transform to change.
 * @param axis  the new direction: finite, not the zero vector.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or axis is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-axis transform.
 *   kQ3ErrorInvalidData        a component of axis is not finite, or all are 0.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutAxisTransform_SetOrientation(TQ3TransformObject transform,
                                                                     const TQ3Vector3D *axis);

/**
 * Reads the direction of a rotate-about-axis transform's line, as set.
 *
 * @param transform  the rotate-about-axis transform to read.
 * @param axis  receives the direction.
 * @return kQ3Success, or kQ3Failure with *axis unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or axis is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-axis transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutAxisTransform_GetOrientation(TQ3TransformObject transform,
                                                                     TQ3Vector3D *axis);

/**
 * Replaces the angle of a rotate-about-axis transform, keeping the rest.
 *
 * @param transform  the rotate-about-axis transform to change.
 * @param radians  the new angle; it must be finite.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-axis transform.
 *   kQ3ErrorInvalidData        radians is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutAxisTransform_SetAngle(TQ3TransformObject transform, float radians);

/**
 * Reads the angle of a rotate-about-axis transform.
 *
 * @param transform  the rotate-about-axis transform to read.
 * @param radians  receives the angle.
 * @return kQ3Success, or kQ3Failure with *radians unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or radians is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-axis transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutAxisTransform_GetAngle(TQ3TransformObject transform, float *radians);

/**
 * Replaces the point a rotate-about-axis transform's line passes through,
 * keeping the rest.
 *
 * @param transform  the rotate-about-axis transform to change.
 * @param origin  the new point; its coordinates must be finite.
 * @return kQ3Success, or kQ3Failure with the transform unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or origin is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-axis transform.
 *   kQ3ErrorInvalidData        a coordinate of origin is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutAxisTransform_SetOrigin(TQ3TransformObject transform,
                                                                const TQ3Point3D *origin);

/**
 * Reads the point a rotate-about-axis transform's line passes through.
 *
 * @param transform  the rotate-about-axis transform to read.
 * @param origin  receives the point.
 * @return kQ3Success, or kQ3Failure with *origin unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      transform or origin is NULL.
 *   kQ3ErrorInvalidObject      transform is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  transform is not a rotate-about-axis transform.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RotateAboutAxisTransform_GetOrigin(TQ3TransformObject transform, TQ3Point3D *origin);

/* ---- Reset transform ---------------------------------------------------- */

/**
 * Creates a transform object that, when submitted, sets the view's
 * local-to-world matrix back to the identity.
 *
 * @return the new transform, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorOutOfMemory     the transform cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new transform is born
 * with and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3TransformObject) Q3ResetTransform_New(void);

/**
 * Sets a view's local-to-world matrix back to the identity (immediate mode).
 *
 * @param view  a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ResetTransform_Submit(TQ3ViewObject view);

#ifdef __cplusplus
}
#endif

#endif /* QD3DTRANSFORM_H */
