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

#ifdef __cplusplus
}
#endif

#endif /* QD3DCAMERA_H */
