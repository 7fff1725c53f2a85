/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Views: a camera, a renderer and a draw context, plus the graphics state
 * (transform, styles, attributes) built up while a scene is submitted.
 *
 * A view draws in loops. A rendering loop is
 *
 *     Q3View_StartRendering(view);
 *     do {
 *         ... submit the scene ...
 *     } while (Q3View_EndRendering(view) == kQ3ViewStatusRetraverse);
 *
 * and a bounding loop has the same shape with Q3View_StartBoundingBox /
 * Q3View_EndBoundingBox (or the sphere variants). Each pass through the loop
 * is a traversal; every traversal must submit the same scene. A traversal
 * starts from the default state: identity local-to-world transform, the
 * default subdivision style (kQ3ViewDefaultSubdivision*), the default
 * attributes (kQ3ViewDefault*) and an empty Push/Pop stack.
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error and leaves every object and output it was
 * given unchanged (a running loop keeps running). "Not a live Q3 object"
 * means a handle that was disposed or never came from Q3. The checks run in
 * this order, and the first that fails decides the error: Q3 is initialized;
 * then the arguments from left to right (a handle: not NULL, a live Q3
 * object, of the right class; a pointer: not NULL); then the function's
 * other conditions in the order it lists them (for a data structure, the
 * rules given with its type, in their order).
 */
#ifndef QD3DVIEW_H
#define QD3DVIEW_H

#include "QD3D.h"
#include "QD3DStyle.h"
#include "QD3DSet.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What the end of a loop pass reports. */
enum TQ3ViewStatus {
    kQ3ViewStatusDone       = 0, /* the loop is over and its result ready */
    kQ3ViewStatusRetraverse = 1, /* submit the scene again, then end again */
    kQ3ViewStatusError      = 2, /* the call failed; see the posted error  */
    kQ3ViewStatusCancelled  = 3  /* Q3View_Cancel ended the loop           */
};
typedef enum TQ3ViewStatus TQ3ViewStatus;

/*
 * The state every traversal starts from (QuickDraw 3D's values). The colour
 * macros expand to three comma-separated components, for initialising a
 * TQ3ColorRGB.
 */
#define kQ3ViewDefaultAmbientCoefficient 1.0
#define kQ3ViewDefaultDiffuseColor 1.0, 1.0, 1.0
#define kQ3ViewDefaultSpecularColor 0.5, 0.5, 0.5
#define kQ3ViewDefaultSpecularControl 4.0
#define kQ3ViewDefaultTransparency 1.0, 1.0, 1.0
#define kQ3ViewDefaultHighlightState kQ3Off
#define kQ3ViewDefaultHighlightColor 1.0, 0.0, 0.0
#define kQ3ViewDefaultSubdivisionMethod kQ3SubdivisionMethodScreenSpace
#define kQ3ViewDefaultSubdivisionC1 20.0
#define kQ3ViewDefaultSubdivisionC2 20.0

/* ---- View --------------------------------------------------------------- */

/**
 * Creates a view with no draw context, camera or renderer.
 *
 * @return the new view, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorOutOfMemory     the view cannot be allocated.
 *
 * Ownership: the caller owns the view. Views are not shared:
 * Q3Object_Dispose destroys it at once and releases the references it holds
 * to its draw context, camera and renderer.
 */
Q3_EXTERN_API_C(TQ3ViewObject) Q3View_New(void);

/**
 * Asks the loop running in a view to stop. The loop's next Q3View_End...
 * call returns kQ3ViewStatusCancelled and ends the loop; objects submitted
 * between this call and that one are ignored. For a rendering loop the draw
 * context's image is left as far as it got. Outside a loop the call does
 * nothing and succeeds.
 *
 * @param view  the view.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_Cancel(TQ3ViewObject view);

/* ---- Renderer ----------------------------------------------------------- */

/**
 * Gives a view a new renderer of the given type, replacing its renderer.
 *
 * @param view     the view; not inside a loop.
 * @param theType  a renderer type code (kQ3RendererType..., QD3D.h) of a
 *                 renderer Q3 provides (see QD3DRenderer.h).
 * @return kQ3Success, or kQ3Failure with the view unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewIsStarted      view is inside a rendering or bounding loop.
 *   kQ3ErrorInvalidObjectType  theType is not the type of a renderer Q3
 *                              provides.
 *   kQ3ErrorOutOfMemory        the renderer cannot be allocated.
 *
 * Ownership: the view holds the only reference to the new renderer and
 * releases the one it held to its previous renderer.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_SetRendererByType(TQ3ViewObject view, TQ3ObjectType theType);

/**
 * Sets the renderer of a view.
 *
 * @param view      the view; not inside a loop.
 * @param renderer  the renderer.
 * @return kQ3Success, or kQ3Failure with the view unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or renderer is NULL.
 *   kQ3ErrorInvalidObject      view or renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view, or renderer is not a
 *                              renderer.
 *   kQ3ErrorViewIsStarted      view is inside a rendering or bounding loop.
 *
 * Ownership: the view takes a reference to renderer and releases the one it
 * held to its previous renderer; the caller keeps its own reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_SetRenderer(TQ3ViewObject view, TQ3RendererObject renderer);

/**
 * Reads the renderer of a view.
 *
 * @param view      the view.
 * @param renderer  receives the renderer, or NULL if the view has none.
 * @return kQ3Success, or kQ3Failure with *renderer unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or renderer is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *
 * Ownership: when *renderer is not NULL the caller owns a new reference to it
 * and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetRenderer(TQ3ViewObject view, TQ3RendererObject *renderer);

/* ---- Rendering loop ----------------------------------------------------- */

/**
 * Starts a rendering loop and its first traversal from the default state.
 * The view reads its camera and draw context here and starts a frame that
 * is cleared as the clear method says; the caller's pixmap is written (only
 * its pane, when the pane state is on) when Q3View_EndRendering returns.
 *
 * @param view  the view; it needs a draw context, a camera and a renderer.
 * @return kQ3Success, or kQ3Failure with no loop started.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewIsStarted      a rendering or bounding loop is already
 *                              running in view.
 *   kQ3ErrorDrawContextNotSet  view has no draw context.
 *   kQ3ErrorCameraNotSet       view has no camera.
 *   kQ3ErrorRendererNotSet     view has no renderer.
 *   kQ3ErrorInvalidData        the pixmap's width, height or rowBytes do not
 *                              fit in 32 bits.
 *   kQ3ErrorInvalidParameter   the pixmap or pane is larger than the
 *                              rasterizer's limit (16384 pixels a side).
 *   kQ3ErrorRenderingLoopFailed  no offscreen rasterizer (llvmpipe) could
 *                              be created.
 *   kQ3ErrorOutOfMemory        the renderer cannot allocate its buffers.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_StartRendering(TQ3ViewObject view);

/**
 * Ends a traversal of a rendering loop.
 *
 * @param view  the view.
 * @return kQ3ViewStatusDone when the image is complete in the draw context
 *         (for a pixmap draw context, in the caller's pixmap memory) and the
 *         loop is over; kQ3ViewStatusRetraverse when the renderer needs the
 *         scene submitted again (the loop goes on, from the default state);
 *         kQ3ViewStatusCancelled when Q3View_Cancel stopped the loop (it is
 *         over); kQ3ViewStatusError on failure.
 *
 * Errors (kQ3ViewStatusError):
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        view is NULL.
 *   kQ3ErrorInvalidObject        view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    view is not a view.
 *   kQ3ErrorRenderingNotStarted  no rendering loop is running in view.
 *   kQ3ErrorRenderingLoopFailed  the renderer could not finish the image; the
 *                                loop is over and the image is left as far
 *                                as it got.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ViewStatus) Q3View_EndRendering(TQ3ViewObject view);

/**
 * Waits until the renderer has finished writing the last image to the draw
 * context. Q3's renderers finish each image before Q3View_EndRendering
 * returns kQ3ViewStatusDone, so this returns at once; legacy code calls it
 * before reading the pixels.
 *
 * @param view  the view; not inside a rendering loop.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorRenderingIsActive  a rendering loop is running in view.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_Sync(TQ3ViewObject view);

/* ---- Bounding loops ----------------------------------------------------- */

/*
 * A bounding loop needs no renderer, camera or draw context. It measures, in
 * world coordinates, what a rendering loop would submit. As the article
 * says, a NURB curve is bounded by its control points projected to 3D
 * (x/w, y/w, z/w), not by the curve itself (the box encloses the curve, since
 * a NURB curve with positive weights lies in their convex hull). Points,
 * lines, polylines, triangles and polygons are bounded by their vertices, a
 * trimesh by all its points (the box its GetData reports as bBox).
 */

/**
 * Starts a bounding-box loop.
 *
 * @param view           the view.
 * @param computeBounds  kQ3ComputeBoundsExact or kQ3ComputeBoundsApproximate
 *                       (QD3D.h).
 * @return kQ3Success, or kQ3Failure with no loop started.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewIsStarted      a rendering or bounding loop is already
 *                              running in view.
 *   kQ3ErrorInvalidParameter   computeBounds is not a TQ3ComputeBounds value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_StartBoundingBox(TQ3ViewObject view,
                                                   TQ3ComputeBounds computeBounds);

/**
 * Ends a traversal of a bounding-box loop.
 *
 * @param view    the view.
 * @param result  receives, with kQ3ViewStatusDone, the world-space box
 *                around everything submitted; isEmpty is kQ3True (and min
 *                and max are zero) when nothing with extent was submitted.
 * @return kQ3ViewStatusDone (loop over, *result set), kQ3ViewStatusRetraverse
 *         (submit again), kQ3ViewStatusCancelled (loop over, *result
 *         unchanged) or kQ3ViewStatusError.
 *
 * Errors (kQ3ViewStatusError):
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or result is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorBoundsNotStarted   no bounding-box loop is running in view.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ViewStatus) Q3View_EndBoundingBox(TQ3ViewObject view, TQ3BoundingBox *result);

/**
 * Starts a bounding-sphere loop.
 *
 * @param view           the view.
 * @param computeBounds  kQ3ComputeBoundsExact or kQ3ComputeBoundsApproximate
 *                       (QD3D.h).
 * @return kQ3Success, or kQ3Failure with no loop started.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewIsStarted      a rendering or bounding loop is already
 *                              running in view.
 *   kQ3ErrorInvalidParameter   computeBounds is not a TQ3ComputeBounds value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_StartBoundingSphere(TQ3ViewObject view,
                                                      TQ3ComputeBounds computeBounds);

/**
 * Ends a traversal of a bounding-sphere loop.
 *
 * @param view    the view.
 * @param result  receives, with kQ3ViewStatusDone, a world-space sphere
 *                around everything submitted (not necessarily the smallest);
 *                isEmpty is kQ3True (and origin and radius are zero) when
 *                nothing with extent was submitted.
 * @return kQ3ViewStatusDone (loop over, *result set), kQ3ViewStatusRetraverse
 *         (submit again), kQ3ViewStatusCancelled (loop over, *result
 *         unchanged) or kQ3ViewStatusError.
 *
 * Errors (kQ3ViewStatusError):
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or result is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorBoundsNotStarted   no bounding-sphere loop is running in view.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ViewStatus) Q3View_EndBoundingSphere(TQ3ViewObject view,
                                                        TQ3BoundingSphere *result);

/* ---- Camera ------------------------------------------------------------- */

/**
 * Reads the camera of a view.
 *
 * @param view    the view.
 * @param camera  receives the camera, or NULL if the view has none.
 * @return kQ3Success, or kQ3Failure with *camera unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or camera is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *
 * Ownership: when *camera is not NULL the caller owns a new reference to it
 * and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetCamera(TQ3ViewObject view, TQ3CameraObject *camera);

/**
 * Sets the camera of a view.
 *
 * @param view    the view; not inside a loop.
 * @param camera  the camera.
 * @return kQ3Success, or kQ3Failure with the view unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or camera is NULL.
 *   kQ3ErrorInvalidObject      view or camera is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view, or camera is not a camera.
 *   kQ3ErrorViewIsStarted      view is inside a rendering or bounding loop.
 *
 * Ownership: the view takes a reference to camera and releases the one it
 * held to its previous camera; the caller keeps its own reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_SetCamera(TQ3ViewObject view, TQ3CameraObject camera);

/* ---- Draw context ------------------------------------------------------- */

/**
 * Sets the draw context of a view.
 *
 * @param view         the view; not inside a loop.
 * @param drawContext  the draw context.
 * @return kQ3Success, or kQ3Failure with the view unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or drawContext is NULL.
 *   kQ3ErrorInvalidObject      view or drawContext is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view, or drawContext is not a
 *                              draw context.
 *   kQ3ErrorViewIsStarted      view is inside a rendering or bounding loop.
 *
 * Ownership: the view takes a reference to drawContext and releases the one
 * it held to its previous draw context; the caller keeps its own reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_SetDrawContext(TQ3ViewObject view,
                                                 TQ3DrawContextObject drawContext);

/**
 * Reads the draw context of a view.
 *
 * @param view         the view.
 * @param drawContext  receives the draw context, or NULL if the view has
 *                     none.
 * @return kQ3Success, or kQ3Failure with *drawContext unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or drawContext is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *
 * Ownership: when *drawContext is not NULL the caller owns a new reference to
 * it and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetDrawContext(TQ3ViewObject view,
                                                 TQ3DrawContextObject *drawContext);

/* ---- Graphics state (inside a loop only) -------------------------------- */

/**
 * Reads the view's current local-to-world matrix: the product of the
 * transforms submitted so far in this traversal (identity at its start).
 *
 * @param view    a view inside a rendering or bounding loop.
 * @param matrix  receives the matrix.
 * @return kQ3Success, or kQ3Failure with *matrix unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or matrix is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetLocalToWorldMatrixState(TQ3ViewObject view,
                                                             TQ3Matrix4x4 *matrix);

/**
 * Reads the view's current subdivision style: the last one submitted in this
 * traversal, after substitution of unreasonable values, or the default
 * (kQ3ViewDefaultSubdivisionMethod, kQ3ViewDefaultSubdivisionC1,
 * kQ3ViewDefaultSubdivisionC2) if none was.
 *
 * @param view              a view inside a rendering or bounding loop.
 * @param subdivisionStyle  receives the style.
 * @return kQ3Success, or kQ3Failure with *subdivisionStyle unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or subdivisionStyle is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetSubdivisionStyleState(
    TQ3ViewObject view, TQ3SubdivisionStyleData *subdivisionStyle);

/* ---- Push / pop --------------------------------------------------------- */

/**
 * Saves the view's current graphics state (local-to-world transform, styles,
 * attributes) on its stack, for the matching Q3Pop_Submit to restore. States
 * still pushed at the end of a traversal are discarded.
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
 *   kQ3ErrorOutOfMemory        the state cannot be saved.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Push_Submit(TQ3ViewObject view);

/**
 * Restores the graphics state saved by the most recent unmatched
 * Q3Push_Submit in this traversal.
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
 *   kQ3ErrorNothingToPop       no state pushed in this traversal is left.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pop_Submit(TQ3ViewObject view);

#ifdef __cplusplus
}
#endif

#endif /* QD3DVIEW_H */
