/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Cameras: where the viewer stands, what it looks at, and how the scene is
 * projected (orthographic, view plane, or view angle and aspect ratio).
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
 *
 * A view reads its camera at Q3View_StartRendering; a camera changed during
 * a rendering loop affects the next loop.
 *
 * Each single-value setter (Q3OrthographicCamera_SetLeft, ...) checks the
 * camera's whole data with that value replaced, by the same rules as the
 * kind's _SetData, and fails as _SetData would.
 *
 * Coordinate systems (matrices act on row vectors, p' = p * M, see QD3D.h):
 *   world    the space geometry ends up in after its transforms.
 *   view     the camera's own space: the camera at the origin looking down
 *            -z, +y towards the up vector (made perpendicular to the viewing
 *            direction), +x to the right.
 *   frustum  after the projection and the homogeneous divide: the part of
 *            the view plane selected by the view port spans x and y from -1
 *            to 1 (x to the right, y up), and z runs from 0 at the hither
 *            plane to -1 at the yon plane.
 */
#ifndef QD3DCAMERA_H
#define QD3DCAMERA_H

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Where the camera is and how it is oriented, in world coordinates. */
struct TQ3CameraPlacement {
    TQ3Point3D cameraLocation;  /* the eye                                */
    TQ3Point3D pointOfInterest; /* the point looked at                    */
    TQ3Vector3D upVector;       /* roughly "up"; need not be unit length  */
};
typedef struct TQ3CameraPlacement TQ3CameraPlacement;

/* The hither (near) and yon (far) clipping planes, as distances from the
 * camera location along the viewing direction. */
struct TQ3CameraRange {
    float hither;
    float yon;
};
typedef struct TQ3CameraRange TQ3CameraRange;

/*
 * The part of the view plane shown in the draw context's pane. The whole
 * view plane spans -1 to 1 in x and y; origin is the view port's top-left
 * corner. Showing everything is origin (-1, 1), width 2, height 2.
 */
struct TQ3CameraViewPort {
    TQ3Point2D origin;
    float width;
    float height;
};
typedef struct TQ3CameraViewPort TQ3CameraViewPort;

/*
 * What every camera has.
 *
 * The rules a TQ3CameraData must obey wherever one is accepted, all reported
 * as kQ3ErrorInvalidCameraValues:
 *   placement: every coordinate finite; cameraLocation differs from
 *     pointOfInterest; upVector is not zero and not parallel to the viewing
 *     direction;
 *   range: both values finite and hither < yon; for a perspective camera
 *     (view plane, view angle aspect) also hither > 0;
 *   viewPort: every value finite; width > 0 and height > 0.
 */
struct TQ3CameraData {
    TQ3CameraPlacement placement;
    TQ3CameraRange range;
    TQ3CameraViewPort viewPort;
};
typedef struct TQ3CameraData TQ3CameraData;

/*
 * An orthographic (parallel projection) camera. left, top, right and bottom
 * bound the visible rectangle in view coordinates (x from left to right, y
 * from bottom to top).
 * Rules, reported as kQ3ErrorInvalidCameraValues: cameraData obeys the
 * TQ3CameraData rules; the four bounds are finite, left != right and
 * top != bottom.
 */
struct TQ3OrthographicCameraData {
    TQ3CameraData cameraData;
    float left;
    float top;
    float right;
    float bottom;
};
typedef struct TQ3OrthographicCameraData TQ3OrthographicCameraData;

/*
 * A perspective camera given by the rectangle it sees on a plane at distance
 * viewPlane from the camera: centred at (centerXOnViewPlane,
 * centerYOnViewPlane) in view coordinates, halfWidthAtViewPlane by
 * halfHeightAtViewPlane in half-size. An off-centre rectangle gives an
 * off-axis projection.
 * Rules, reported as kQ3ErrorInvalidCameraValues: cameraData obeys the
 * TQ3CameraData rules; every value is finite; viewPlane,
 * halfWidthAtViewPlane and halfHeightAtViewPlane are greater than 0.
 */
struct TQ3ViewPlaneCameraData {
    TQ3CameraData cameraData;
    float viewPlane;
    float halfWidthAtViewPlane;
    float halfHeightAtViewPlane;
    float centerXOnViewPlane;
    float centerYOnViewPlane;
};
typedef struct TQ3ViewPlaneCameraData TQ3ViewPlaneCameraData;

/*
 * A perspective camera given by a field of view and an aspect ratio. fov, in
 * radians, is the angle across the narrower dimension: vertical when
 * aspectRatioXToY >= 1, horizontal otherwise. aspectRatioXToY is width over
 * height.
 * Rules, reported as kQ3ErrorInvalidCameraValues: cameraData obeys the
 * TQ3CameraData rules; 0 < fov < pi; aspectRatioXToY is finite and greater
 * than 0.
 */
struct TQ3ViewAngleAspectCameraData {
    TQ3CameraData cameraData;
    float fov;
    float aspectRatioXToY;
};
typedef struct TQ3ViewAngleAspectCameraData TQ3ViewAngleAspectCameraData;

/* ---- Any camera --------------------------------------------------------- */

/**
 * Reports the kind of a camera.
 *
 * @param camera  the camera to query.
 * @return kQ3CameraTypeOrthographic, kQ3CameraTypeViewPlane or
 *         kQ3CameraTypeViewAngleAspect, or kQ3ObjectTypeInvalid on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Camera_GetType(TQ3CameraObject camera);

/**
 * Replaces the placement, range and view port of a camera at once.
 *
 * @param camera      the camera to change.
 * @param cameraData  the new values; they must obey the TQ3CameraData rules
 *                    for this camera's kind.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera or cameraData is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not a camera.
 *   kQ3ErrorInvalidCameraValues  cameraData breaks a TQ3CameraData rule.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Camera_SetData(TQ3CameraObject camera,
                                            const TQ3CameraData *cameraData);

/**
 * Reads the placement, range and view port of a camera.
 *
 * @param camera      the camera to read.
 * @param cameraData  receives the values.
 * @return kQ3Success, or kQ3Failure with *cameraData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or cameraData is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Camera_GetData(TQ3CameraObject camera, TQ3CameraData *cameraData);

/**
 * Moves and re-orients a camera.
 *
 * @param camera     the camera to change.
 * @param placement  the new placement; it must obey the placement rule of
 *                   TQ3CameraData.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera or placement is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not a camera.
 *   kQ3ErrorInvalidCameraValues  a coordinate is not finite, the location
 *                                equals the point of interest, or the up
 *                                vector is zero or parallel to the viewing
 *                                direction.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Camera_SetPlacement(TQ3CameraObject camera,
                                                 const TQ3CameraPlacement *placement);

/**
 * Reads the placement of a camera.
 *
 * @param camera     the camera to read.
 * @param placement  receives the placement.
 * @return kQ3Success, or kQ3Failure with *placement unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or placement is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Camera_GetPlacement(TQ3CameraObject camera,
                                                 TQ3CameraPlacement *placement);

/**
 * Sets the hither and yon planes of a camera.
 *
 * @param camera  the camera to change.
 * @param range   the new range; it must obey the range rule of TQ3CameraData
 *                for this camera's kind.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera or range is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not a camera.
 *   kQ3ErrorInvalidCameraValues  a value is not finite, hither >= yon, or
 *                                hither <= 0 for a perspective camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Camera_SetRange(TQ3CameraObject camera, const TQ3CameraRange *range);

/**
 * Reads the hither and yon planes of a camera.
 *
 * @param camera  the camera to read.
 * @param range   receives the range.
 * @return kQ3Success, or kQ3Failure with *range unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or range is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Camera_GetRange(TQ3CameraObject camera, TQ3CameraRange *range);

/**
 * Selects the part of the view plane that is shown.
 *
 * @param camera    the camera to change.
 * @param viewPort  the new view port; its values must be finite, with width
 *                  and height greater than 0.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera or viewPort is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not a camera.
 *   kQ3ErrorInvalidCameraValues  a value is not finite, or width or height is
 *                                not greater than 0.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Camera_SetViewPort(TQ3CameraObject camera,
                                                const TQ3CameraViewPort *viewPort);

/**
 * Reads the view port of a camera.
 *
 * @param camera    the camera to read.
 * @param viewPort  receives the view port.
 * @return kQ3Success, or kQ3Failure with *viewPort unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or viewPort is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Camera_GetViewPort(TQ3CameraObject camera,
                                                TQ3CameraViewPort *viewPort);

/**
 * Computes the matrix taking world coordinates to the camera's view
 * coordinates (a rigid motion: rotation and translation only).
 *
 * @param camera       the camera.
 * @param worldToView  receives the matrix.
 * @return kQ3Success, or kQ3Failure with *worldToView unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or worldToView is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Camera_GetWorldToView(TQ3CameraObject camera,
                                                   TQ3Matrix4x4 *worldToView);

/**
 * Computes the projection matrix taking the camera's view coordinates to
 * frustum coordinates (before the homogeneous divide for a perspective
 * camera). It includes the view port.
 *
 * @param camera         the camera.
 * @param viewToFrustum  receives the matrix.
 * @return kQ3Success, or kQ3Failure with *viewToFrustum unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or viewToFrustum is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Camera_GetViewToFrustum(TQ3CameraObject camera,
                                                     TQ3Matrix4x4 *viewToFrustum);

/**
 * Computes the matrix taking world coordinates to frustum coordinates: the
 * world-to-view matrix times the view-to-frustum matrix.
 *
 * @param camera          the camera.
 * @param worldToFrustum  receives the matrix.
 * @return kQ3Success, or kQ3Failure with *worldToFrustum unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or worldToFrustum is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Camera_GetWorldToFrustum(TQ3CameraObject camera,
                                                      TQ3Matrix4x4 *worldToFrustum);

/* ---- Orthographic camera ------------------------------------------------ */

/**
 * Creates an orthographic camera.
 *
 * @param orthographicData  the camera; it must obey the
 *                          TQ3OrthographicCameraData rules.
 * @return the new camera, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        orthographicData is NULL.
 *   kQ3ErrorInvalidCameraValues  orthographicData breaks a rule.
 *   kQ3ErrorOutOfMemory          the camera cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new camera is born with
 * and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3CameraObject) Q3OrthographicCamera_New(
    const TQ3OrthographicCameraData *orthographicData);

/**
 * Reads all the values of an orthographic camera.
 *
 * @param camera      the camera to read.
 * @param cameraData  receives the values.
 * @return kQ3Success, or kQ3Failure with *cameraData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or cameraData is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not an orthographic camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3OrthographicCamera_GetData(TQ3CameraObject camera,
                                                        TQ3OrthographicCameraData *cameraData);

/**
 * Replaces all the values of an orthographic camera.
 *
 * @param camera      the camera to change.
 * @param cameraData  the new values; they must obey the
 *                    TQ3OrthographicCameraData rules.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera or cameraData is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not an orthographic camera.
 *   kQ3ErrorInvalidCameraValues  cameraData breaks a rule.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3OrthographicCamera_SetData(
    TQ3CameraObject camera, const TQ3OrthographicCameraData *cameraData);

/**
 * Moves the left edge of an orthographic camera's visible rectangle, keeping
 * its other values.
 *
 * @param camera  the orthographic camera to change.
 * @param left    the new view x of the left edge; it must be finite and
 *                differ from the right edge.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not an orthographic camera.
 *   kQ3ErrorInvalidCameraValues  left is not finite or equals right.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3OrthographicCamera_SetLeft(TQ3CameraObject camera, float left);

/**
 * Reads the left edge of an orthographic camera's visible rectangle.
 *
 * @param camera  the orthographic camera to read.
 * @param left    receives the view x of the left edge.
 * @return kQ3Success, or kQ3Failure with *left unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or left is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not an orthographic camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3OrthographicCamera_GetLeft(TQ3CameraObject camera, float *left);

/**
 * Moves the top edge of an orthographic camera's visible rectangle, keeping
 * its other values.
 *
 * @param camera  the orthographic camera to change.
 * @param top     the new view y of the top edge; it must be finite and differ
 *                from the bottom edge.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not an orthographic camera.
 *   kQ3ErrorInvalidCameraValues  top is not finite or equals bottom.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3OrthographicCamera_SetTop(TQ3CameraObject camera, float top);

/**
 * Reads the top edge of an orthographic camera's visible rectangle.
 *
 * @param camera  the orthographic camera to read.
 * @param top     receives the view y of the top edge.
 * @return kQ3Success, or kQ3Failure with *top unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or top is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not an orthographic camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3OrthographicCamera_GetTop(TQ3CameraObject camera, float *top);

/**
 * Moves the right edge of an orthographic camera's visible rectangle,
 * keeping its other values.
 *
 * @param camera  the orthographic camera to change.
 * @param right   the new view x of the right edge; it must be finite and
 *                differ from the left edge.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not an orthographic camera.
 *   kQ3ErrorInvalidCameraValues  right is not finite or equals left.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3OrthographicCamera_SetRight(TQ3CameraObject camera, float right);

/**
 * Reads the right edge of an orthographic camera's visible rectangle.
 *
 * @param camera  the orthographic camera to read.
 * @param right   receives the view x of the right edge.
 * @return kQ3Success, or kQ3Failure with *right unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or right is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not an orthographic camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3OrthographicCamera_GetRight(TQ3CameraObject camera, float *right);

/**
 * Moves the bottom edge of an orthographic camera's visible rectangle,
 * keeping its other values.
 *
 * @param camera  the orthographic camera to change.
 * @param bottom  the new view y of the bottom edge; it must be finite and
 *                differ from the top edge.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not an orthographic camera.
 *   kQ3ErrorInvalidCameraValues  bottom is not finite or equals top.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3OrthographicCamera_SetBottom(TQ3CameraObject camera, float bottom);

/**
 * Reads the bottom edge of an orthographic camera's visible rectangle.
 *
 * @param camera  the orthographic camera to read.
 * @param bottom  receives the view y of the bottom edge.
 * @return kQ3Success, or kQ3Failure with *bottom unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or bottom is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not an orthographic camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3OrthographicCamera_GetBottom(TQ3CameraObject camera, float *bottom);

/* ---- View plane camera -------------------------------------------------- */

/**
 * Creates a view plane (perspective) camera.
 *
 * @param cameraData  the camera; it must obey the TQ3ViewPlaneCameraData
 *                    rules.
 * @return the new camera, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        cameraData is NULL.
 *   kQ3ErrorInvalidCameraValues  cameraData breaks a rule.
 *   kQ3ErrorOutOfMemory          the camera cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new camera is born with
 * and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3CameraObject) Q3ViewPlaneCamera_New(const TQ3ViewPlaneCameraData *cameraData);

/**
 * Reads all the values of a view plane camera.
 *
 * @param camera      the camera to read.
 * @param cameraData  receives the values.
 * @return kQ3Success, or kQ3Failure with *cameraData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or cameraData is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a view plane camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewPlaneCamera_GetData(TQ3CameraObject camera,
                                                     TQ3ViewPlaneCameraData *cameraData);

/**
 * Replaces all the values of a view plane camera.
 *
 * @param camera      the camera to change.
 * @param cameraData  the new values; they must obey the
 *                    TQ3ViewPlaneCameraData rules.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera or cameraData is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not a view plane camera.
 *   kQ3ErrorInvalidCameraValues  cameraData breaks a rule.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewPlaneCamera_SetData(TQ3CameraObject camera,
                                                     const TQ3ViewPlaneCameraData *cameraData);

/**
 * Moves a view plane camera's view plane, keeping its other values (the
 * rectangle keeps its size and centre on the moved plane, so the field of
 * view changes).
 *
 * @param camera     the view plane camera to change.
 * @param viewPlane  the new distance from the camera to the plane; it must
 *                   be finite and greater than 0.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not a view plane camera.
 *   kQ3ErrorInvalidCameraValues  viewPlane is not finite or not greater
 *                                than 0.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewPlaneCamera_SetViewPlane(TQ3CameraObject camera, float viewPlane);

/**
 * Reads the distance from a view plane camera to its view plane.
 *
 * @param camera     the view plane camera to read.
 * @param viewPlane  receives the distance.
 * @return kQ3Success, or kQ3Failure with *viewPlane unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or viewPlane is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a view plane camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewPlaneCamera_GetViewPlane(TQ3CameraObject camera, float *viewPlane);

/**
 * Changes the half-width of the rectangle a view plane camera sees on its
 * view plane, keeping its other values.
 *
 * @param camera                the view plane camera to change.
 * @param halfWidthAtViewPlane  the new half-width; it must be finite and
 *                              greater than 0.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not a view plane camera.
 *   kQ3ErrorInvalidCameraValues  halfWidthAtViewPlane is not finite or not
 *                                greater than 0.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewPlaneCamera_SetHalfWidth(TQ3CameraObject camera,
                                                          float halfWidthAtViewPlane);

/**
 * Reads the half-width of the rectangle a view plane camera sees on its view
 * plane.
 *
 * @param camera                the view plane camera to read.
 * @param halfWidthAtViewPlane  receives the half-width.
 * @return kQ3Success, or kQ3Failure with *halfWidthAtViewPlane unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or halfWidthAtViewPlane is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a view plane camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewPlaneCamera_GetHalfWidth(TQ3CameraObject camera,
                                                          float *halfWidthAtViewPlane);

/**
 * Changes the half-height of the rectangle a view plane camera sees on its
 * view plane, keeping its other values.
 *
 * @param camera                 the view plane camera to change.
 * @param halfHeightAtViewPlane  the new half-height; it must be finite and
 *                               greater than 0.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not a view plane camera.
 *   kQ3ErrorInvalidCameraValues  halfHeightAtViewPlane is not finite or not
 *                                greater than 0.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewPlaneCamera_SetHalfHeight(TQ3CameraObject camera,
                                                           float halfHeightAtViewPlane);

/**
 * Reads the half-height of the rectangle a view plane camera sees on its
 * view plane.
 *
 * @param camera                 the view plane camera to read.
 * @param halfHeightAtViewPlane  receives the half-height.
 * @return kQ3Success, or kQ3Failure with *halfHeightAtViewPlane unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or halfHeightAtViewPlane is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a view plane camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewPlaneCamera_GetHalfHeight(TQ3CameraObject camera,
                                                           float *halfHeightAtViewPlane);

/**
 * Moves the centre of the rectangle a view plane camera sees across its view
 * plane (an off-axis projection when not 0), keeping its other values.
 *
 * @param camera              the view plane camera to change.
 * @param centerXOnViewPlane  the new view x of the centre; it must be finite.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not a view plane camera.
 *   kQ3ErrorInvalidCameraValues  centerXOnViewPlane is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewPlaneCamera_SetCenterX(TQ3CameraObject camera,
                                                        float centerXOnViewPlane);

/**
 * Reads the view x of the centre of the rectangle a view plane camera sees
 * on its view plane.
 *
 * @param camera              the view plane camera to read.
 * @param centerXOnViewPlane  receives the centre's view x.
 * @return kQ3Success, or kQ3Failure with *centerXOnViewPlane unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or centerXOnViewPlane is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a view plane camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewPlaneCamera_GetCenterX(TQ3CameraObject camera,
                                                        float *centerXOnViewPlane);

/**
 * Moves the centre of the rectangle a view plane camera sees up or down its
 * view plane (an off-axis projection when not 0), keeping its other values.
 *
 * @param camera              the view plane camera to change.
 * @param centerYOnViewPlane  the new view y of the centre; it must be finite.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not a view plane camera.
 *   kQ3ErrorInvalidCameraValues  centerYOnViewPlane is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewPlaneCamera_SetCenterY(TQ3CameraObject camera,
                                                        float centerYOnViewPlane);

/**
 * Reads the view y of the centre of the rectangle a view plane camera sees
 * on its view plane.
 *
 * @param camera              the view plane camera to read.
 * @param centerYOnViewPlane  receives the centre's view y.
 * @return kQ3Success, or kQ3Failure with *centerYOnViewPlane unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or centerYOnViewPlane is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a view plane camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewPlaneCamera_GetCenterY(TQ3CameraObject camera,
                                                        float *centerYOnViewPlane);

/* ---- View angle aspect camera ------------------------------------------- */

/**
 * Creates a view angle aspect (perspective) camera.
 *
 * @param cameraData  the camera; it must obey the
 *                    TQ3ViewAngleAspectCameraData rules.
 * @return the new camera, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        cameraData is NULL.
 *   kQ3ErrorInvalidCameraValues  cameraData breaks a rule.
 *   kQ3ErrorOutOfMemory          the camera cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new camera is born with
 * and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3CameraObject) Q3ViewAngleAspectCamera_New(
    const TQ3ViewAngleAspectCameraData *cameraData);

/**
 * Reads all the values of a view angle aspect camera.
 *
 * @param camera      the camera to read.
 * @param cameraData  receives the values.
 * @return kQ3Success, or kQ3Failure with *cameraData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or cameraData is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a view angle aspect camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewAngleAspectCamera_GetData(
    TQ3CameraObject camera, TQ3ViewAngleAspectCameraData *cameraData);

/**
 * Replaces all the values of a view angle aspect camera.
 *
 * @param camera      the camera to change.
 * @param cameraData  the new values; they must obey the
 *                    TQ3ViewAngleAspectCameraData rules.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera or cameraData is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not a view angle aspect camera.
 *   kQ3ErrorInvalidCameraValues  cameraData breaks a rule.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewAngleAspectCamera_SetData(
    TQ3CameraObject camera, const TQ3ViewAngleAspectCameraData *cameraData);

/**
 * Changes the field of view of a view angle aspect camera, keeping its other
 * values.
 *
 * @param camera  the view angle aspect camera to change.
 * @param fov     the new angle in radians across the narrower dimension (see
 *                TQ3ViewAngleAspectCameraData); it must be finite, with
 *                0 < fov < pi.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not a view angle aspect camera.
 *   kQ3ErrorInvalidCameraValues  fov is not finite, or not between 0 and pi
 *                                (both excluded).
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewAngleAspectCamera_SetFOV(TQ3CameraObject camera, float fov);

/**
 * Reads the field of view of a view angle aspect camera.
 *
 * @param camera  the view angle aspect camera to read.
 * @param fov     receives the angle in radians.
 * @return kQ3Success, or kQ3Failure with *fov unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or fov is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a view angle aspect camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewAngleAspectCamera_GetFOV(TQ3CameraObject camera, float *fov);

/**
 * Changes the aspect ratio of a view angle aspect camera, keeping its other
 * values.
 *
 * @param camera           the view angle aspect camera to change.
 * @param aspectRatioXToY  the new width over height; it must be finite and
 *                         greater than 0.
 * @return kQ3Success, or kQ3Failure with the camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        camera is NULL.
 *   kQ3ErrorInvalidObject        camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    camera is not a view angle aspect camera.
 *   kQ3ErrorInvalidCameraValues  aspectRatioXToY is not finite or not
 *                                greater than 0.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewAngleAspectCamera_SetAspectRatio(TQ3CameraObject camera,
                                                                  float aspectRatioXToY);

/**
 * Reads the aspect ratio of a view angle aspect camera.
 *
 * @param camera           the view angle aspect camera to read.
 * @param aspectRatioXToY  receives the width over height.
 * @return kQ3Success, or kQ3Failure with *aspectRatioXToY unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      camera or aspectRatioXToY is NULL.
 *   kQ3ErrorInvalidObject      camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  camera is not a view angle aspect camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewAngleAspectCamera_GetAspectRatio(TQ3CameraObject camera,
                                                                  float *aspectRatioXToY);

#ifdef __cplusplus
}
#endif

#endif /* QD3DCAMERA_H */
