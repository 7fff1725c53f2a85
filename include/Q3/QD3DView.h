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

/* ---- Idle and end-frame methods ---------------------------------------- */

/*
 * The idle methods let an application keep its user interface alive during
 * a long rendering and cancel it. In a rendering loop the view calls the
 * registered method before drawing each object submitted to it (a group
 * counts as one object, however much it holds). Returning kQ3Failure
 * cancels the loop, as Q3View_Cancel does: the object about to be drawn and
 * every later one are ignored and Q3View_EndRendering returns
 * kQ3ViewStatusCancelled. Return kQ3Success to go on; post no error. A
 * method must not call Q3 on the view that called it. Bounding, picking and
 * writing loops do not call them.
 *
 * When both are set the progress method is called instead of the idle
 * method. Q3's renderers cannot tell how much of the frame is left, so the
 * progress method always receives current == 0 and completed == 0, the
 * values QuickDraw 3D gives for a renderer without progress information.
 */
typedef TQ3Status (*TQ3ViewIdleMethod)(TQ3ViewObject view, const void *idlerData);
typedef TQ3Status (*TQ3ViewIdleProgressMethod)(TQ3ViewObject view, const void *idlerData, unsigned long current,
                                               unsigned long completed);

/**
 * Registers (or, with NULL, removes) the idle method of a view.
 *
 * @param view        the view.
 * @param idleMethod  the method, or NULL.
 * @param idleData    passed to the method as idlerData; any value.
 * @return kQ3Success, or kQ3Failure with the view unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *
 * Ownership: no references change; idleData stays the caller's.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_SetIdleMethod(TQ3ViewObject view, TQ3ViewIdleMethod idleMethod,
                                                const void *idleData);

/**
 * Registers (or, with NULL, removes) the idle progress method of a view.
 *
 * @param view        the view.
 * @param idleMethod  the method, or NULL.
 * @param idleData    passed to the method as idlerData; any value.
 * @return kQ3Success, or kQ3Failure with the view unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *
 * Ownership: no references change; idleData stays the caller's.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_SetIdleProgressMethod(TQ3ViewObject view, TQ3ViewIdleProgressMethod idleMethod,
                                                        const void *idleData);

/*
 * The end-frame method tells the application that a frame is complete. Q3's
 * renderers finish a frame inside Q3View_EndRendering, so the view calls it
 * there, once the image is in the draw context and before returning
 * kQ3ViewStatusDone; a cancelled or failed frame does not call it.
 */
typedef void (*TQ3ViewEndFrameMethod)(TQ3ViewObject view, void *endFrameData);

/**
 * Registers (or, with NULL, removes) the end-frame method of a view.
 *
 * @param view          the view.
 * @param endFrame      the method, or NULL.
 * @param endFrameData  passed to the method; any value.
 * @return kQ3Success, or kQ3Failure with the view unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *
 * Ownership: no references change; endFrameData stays the caller's.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_SetEndFrameMethod(TQ3ViewObject view, TQ3ViewEndFrameMethod endFrame,
                                                    void *endFrameData);

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

/* ---- Picking (QD3DPick.h) ------------------------------------------------ */

/**
 * Starts a picking loop: the shapes submitted until Q3View_EndPicking are
 * tested against the pick (QD3DPick.h), whose hit list is emptied now.
 * Window-point and window-rect picks need the view's camera and draw
 * context (the window is the draw context's pane); world-ray picks need
 * neither. The view uses a copy of the pick's settings taken now.
 *
 * @param view  the view, in no loop.
 * @param pick  the pick.
 * @return kQ3Success, or kQ3Failure (no loop started).
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or pick is NULL.
 *   kQ3ErrorInvalidObject      view or pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view, pick is not a pick.
 *   kQ3ErrorViewIsStarted      a loop is already running in view.
 *   kQ3ErrorDrawContextNotSet  a window pick, and the view has no draw
 *                              context.
 *   kQ3ErrorCameraNotSet       a window pick, and the view has no camera.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_StartPicking(TQ3ViewObject view, TQ3PickObject pick);

/**
 * Ends a traversal of a picking loop and gives the pick its hits, sorted
 * and cut to numHitsToReturn. Q3 needs one traversal, so it never returns
 * kQ3ViewStatusRetraverse.
 *
 * @param view  the view.
 * @return kQ3ViewStatusDone (the hits are in the pick);
 *         kQ3ViewStatusCancelled after Q3View_Cancel (the hit list stays
 *         empty); kQ3ViewStatusError on failure. The loop is over in every
 *         case but kQ3ErrorPickingNotStarted.
 *
 * Errors (kQ3ViewStatusError):
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorPickingNotStarted  no picking loop is running in view.
 *   kQ3ErrorPickingLoopFailed  the pick was disposed during the loop.
 *
 * Ownership: the hits hold references to the geometries and root groups
 * they name, until the hit list is emptied or the pick disposed.
 */
Q3_EXTERN_API_C(TQ3ViewStatus) Q3View_EndPicking(TQ3ViewObject view);

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

/* ---- Lights -------------------------------------------------------------- */

/**
 * Sets the lights the view's rendering loops are lit by: the lights in a
 * light group (Q3LightGroup_New), read at the start of each rendering loop,
 * so later edits of the group or its lights show in the next loop. Lights
 * that are off light nothing; of those that are on, the first 32 in the
 * group's order light the scene (Q3 draws at most 32 lights). Surfaces are
 * lit only under an illumination shader (QD3DShader.h); without one they
 * are drawn in their diffuse colours.
 *
 * @param view        a view outside any loop.
 * @param lightGroup  a light group, or NULL for no lights.
 * @return kQ3Success, or kQ3Failure with the view unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view or lightGroup is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view, or lightGroup is not a
 *                              light group.
 *   kQ3ErrorViewIsStarted      view is inside a rendering or bounding loop.
 *
 * Ownership: the view takes a new reference to the group and releases the
 * one it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_SetLightGroup(TQ3ViewObject view, TQ3GroupObject lightGroup);

/**
 * Reads the view's light group.
 *
 * @param view        a view.
 * @param lightGroup  receives a new reference to the group, or NULL when
 *                    the view has none.
 * @return kQ3Success, or kQ3Failure with *lightGroup unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or lightGroup is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *
 * Ownership: the caller owns the reference it receives.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetLightGroup(TQ3ViewObject view, TQ3GroupObject *lightGroup);

/* ---- Rendering loop --------------------------------------------------------
 */

/**
 * Asks the renderer to draw what has been submitted so far. Q3's renderers
 * draw each shape as it is submitted and finish the image in
 * Q3View_EndRendering, so inside a rendering loop this succeeds and changes
 * nothing.
 *
 * @param view  a view inside a rendering loop.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        view is NULL.
 *   kQ3ErrorInvalidObject        view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    view is not a view.
 *   kQ3ErrorRenderingNotStarted  no rendering loop is running in the view.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_Flush(TQ3ViewObject view);

/* ---- Graphics state -------------------------------------------------------
 */

/*
 * The graphics state calls below share these rules. The view must be inside
 * a rendering or bounding loop; the value read is the one in force at the
 * call: the last one submitted in this traversal and not undone by a pop or
 * the end of a group, else QuickDraw 3D's default (given with each call).
 *
 * Errors, besides those each call lists:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or the output pointer is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 * On failure the output is unchanged. Ownership: no references change unless
 * the call says so.
 */

/**
 * Reads the camera's world-to-frustum matrix for the running loop: world
 * points (row vectors, p' = p * M) to the frustum, where x and y run from -1
 * to 1 across the view and z from 0 (hither) to -1 (yon).
 *
 * @param view    a view inside a rendering loop, or a bounding loop of a view
 *                with a camera and a draw context.
 * @param matrix  receives the matrix.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors (besides the shared ones):
 *   kQ3ErrorCameraNotSet  a bounding loop of a view with no camera or no
 *                         draw context has no frustum.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetWorldToFrustumMatrixState(TQ3ViewObject view,
                                                               TQ3Matrix4x4 *matrix);

/**
 * Reads the frustum-to-window matrix for the running loop: frustum x and y
 * (-1..1) to pixels of the draw context's pane (or whole image), x to the
 * right and y down from the top-left corner; z is kept.
 *
 * @param view    as for Q3View_GetWorldToFrustumMatrixState.
 * @param matrix  receives the matrix.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors (besides the shared ones):
 *   kQ3ErrorCameraNotSet  as for Q3View_GetWorldToFrustumMatrixState.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetFrustumToWindowMatrixState(TQ3ViewObject view,
                                                                TQ3Matrix4x4 *matrix);

/**
 * Reads the backfacing style in force (default kQ3BackfacingStyleBoth).
 *
 * @param view             a view inside a loop.
 * @param backfacingStyle  receives the style.
 * @return kQ3Success, or kQ3Failure (the shared errors).
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetBackfacingStyleState(TQ3ViewObject view,
                                                          TQ3BackfacingStyle *backfacingStyle);

/**
 * Reads the interpolation style in force (default
 * kQ3InterpolationStyleVertex).
 *
 * @param view               a view inside a loop.
 * @param interpolationType  receives the style.
 * @return kQ3Success, or kQ3Failure (the shared errors).
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetInterpolationStyleState(
    TQ3ViewObject view, TQ3InterpolationStyle *interpolationType);

/**
 * Reads the fill style in force (default kQ3FillStyleFilled).
 *
 * @param view       a view inside a loop.
 * @param fillStyle  receives the style.
 * @return kQ3Success, or kQ3Failure (the shared errors).
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetFillStyleState(TQ3ViewObject view, TQ3FillStyle *fillStyle);

/**
 * Reads the highlight style in force: the attribute set drawn over
 * geometries whose highlight state attribute is kQ3On (default: none).
 *
 * @param view            a view inside a loop.
 * @param highlightStyle  receives a new reference to the style's attribute
 *                        set, or NULL when no highlight style is in force.
 * @return kQ3Success, or kQ3Failure (the shared errors).
 *
 * Ownership: the caller owns the reference it receives.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetHighlightStyleState(TQ3ViewObject view,
                                                         TQ3AttributeSet *highlightStyle);

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

/**
 * Reads the orientation style in force: which winding faces front (default
 * kQ3OrientationStyleCounterClockwise).
 *
 * @param view                      a view inside a loop.
 * @param fontFacingDirectionStyle  receives the style.
 * @return kQ3Success, or kQ3Failure (the shared errors).
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetOrientationStyleState(
    TQ3ViewObject view, TQ3OrientationStyle *fontFacingDirectionStyle);

/**
 * Reads the receive-shadows style in force (default kQ3True). Q3 draws no
 * shadows; the value is kept for applications and files.
 *
 * @param view      a view inside a loop.
 * @param receives  receives the value.
 * @return kQ3Success, or kQ3Failure (the shared errors).
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetReceiveShadowsStyleState(TQ3ViewObject view,
                                                              TQ3Boolean *receives);

/**
 * Reads the pick ID style in force (default 0).
 *
 * @param view         a view inside a loop.
 * @param pickIDStyle  receives the ID.
 * @return kQ3Success, or kQ3Failure (the shared errors).
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetPickIDStyleState(TQ3ViewObject view,
                                                      unsigned long *pickIDStyle);

/**
 * Reads the pick parts style in force (default kQ3PickPartsObject).
 *
 * @param view            a view inside a loop.
 * @param pickPartsStyle  receives the parts mask.
 * @return kQ3Success, or kQ3Failure (the shared errors).
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetPickPartsStyleState(TQ3ViewObject view,
                                                         TQ3PickParts *pickPartsStyle);

/**
 * Reads the anti-alias style in force (default: kQ3Off,
 * kQ3AntiAliasModeMaskEdges, quality 1). Q3 keeps the value but draws
 * without anti-aliasing, so images stay identical from machine to machine.
 *
 * @param view           a view inside a loop.
 * @param antiAliasData  receives the style's data.
 * @return kQ3Success, or kQ3Failure (the shared errors).
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetAntiAliasStyleState(TQ3ViewObject view,
                                                         TQ3AntiAliasStyleData *antiAliasData);

/* ---- Attributes ------------------------------------------------------------
 */

/**
 * Reads the attribute set every traversal of the view starts with.
 *
 * @param view          a view.
 * @param attributeSet  receives a new reference to the set given to
 *                      Q3View_SetDefaultAttributeSet, or, when none was, a
 *                      new set holding QuickDraw 3D's defaults
 *                      (kQ3ViewDefault*: ambient coefficient, diffuse,
 *                      specular and transparency colours, specular control,
 *                      highlight state).
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view or attributeSet is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorOutOfMemory        the set cannot be made.
 *
 * Ownership: the caller owns the reference it receives.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetDefaultAttributeSet(TQ3ViewObject view,
                                                         TQ3AttributeSet *attributeSet);

/**
 * Sets the attributes every traversal of the view starts with: the set's
 * attributes over QuickDraw 3D's defaults (an attribute the set lacks keeps
 * its default). The set is read at the start of each loop.
 *
 * @param view          a view outside any loop.
 * @param attributeSet  an attribute set, or NULL for the defaults alone.
 * @return kQ3Success, or kQ3Failure with the view unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view or attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view, or attributeSet is not an
 *                              attribute set.
 *   kQ3ErrorViewIsStarted      view is inside a rendering or bounding loop.
 *
 * Ownership: the view takes a new reference to the set and releases the one
 * it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_SetDefaultAttributeSet(TQ3ViewObject view,
                                                         TQ3AttributeSet attributeSet);

/**
 * Reads every attribute in force: the defaults overlaid by each attribute set
 * submitted in this traversal and not undone by a pop or a group's end.
 *
 * @param view          a view inside a loop.
 * @param attributeSet  receives a new attribute set holding them.
 * @return kQ3Success, or kQ3Failure (the shared errors, or
 *         kQ3ErrorOutOfMemory).
 *
 * Ownership: the caller owns the new set.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetAttributeSetState(TQ3ViewObject view,
                                                       TQ3AttributeSet *attributeSet);

/**
 * Reads one attribute in force, as Q3View_GetAttributeSetState's set holds it.
 *
 * @param view           a view inside a loop.
 * @param attributeType  the attribute's type (kQ3AttributeType...).
 * @param data           receives the value: as many bytes as the type's data
 *                       (a TQ3ColorRGB for a colour, a float for the ambient
 *                       coefficient, and so on; for
 *                       kQ3AttributeTypeSurfaceShader a
 *                       TQ3SurfaceShaderObject).
 * @return kQ3Success, or kQ3Failure with *data unchanged.
 *
 * Errors (besides the shared ones):
 *   kQ3ErrorAttributeInvalidType  attributeType is not an attribute type Q3
 *                                 stores.
 *   kQ3ErrorAttributeNotContained no attribute of that type is in force (the
 *                                 defaults hold only the kQ3ViewDefault*
 *                                 attributes).
 *
 * Ownership: a surface shader is returned as a new reference, which the
 * caller releases with Q3Object_Dispose; nothing else changes hands.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_GetAttributeState(TQ3ViewObject view,
                                                    TQ3AttributeType attributeType, void *data);

/* ---- Culling ----------------------------------------------------------------
 */

/**
 * Whether a box may be seen: false when, carried by the local-to-world
 * matrix in force and the camera into the frustum, all eight of its corners
 * lie beyond one of the frustum's six planes, and for a box whose isEmpty is
 * kQ3True; true otherwise. Only boxes the view cannot see are reported
 * invisible: a box beside a corner of the frustum may be called visible.
 *
 * @param view  a view inside a loop.
 * @param bbox  the box, in the current local coordinates.
 * @return kQ3True or kQ3False; kQ3False on failure.
 *
 * Errors: the shared ones, with bbox as the output pointer.
 */
Q3_EXTERN_API_C(TQ3Boolean) Q3View_IsBoundingBoxVisible(TQ3ViewObject view,
                                                        const TQ3BoundingBox *bbox);

/**
 * Lets the view treat display groups that use their bounding box
 * (kQ3DisplayGroupStateMaskUseBoundingBox and a box set by
 * Q3DisplayGroup_SetAndUseBoundingBox or CalcAndUseBoundingBox) by the box:
 * rendering skips a group whose box cannot be seen, and bounding loops take
 * the box for the group's objects. On by default; off, every group is
 * traversed in full.
 *
 * @param view          a view.
 * @param allowCulling  kQ3True or kQ3False.
 * @return kQ3Success, or kQ3Failure with the view unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorInvalidParameter   allowCulling is neither kQ3True nor kQ3False.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_AllowAllGroupCulling(TQ3ViewObject view,
                                                       TQ3Boolean allowCulling);

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

/**
 * Creates a push state operator: a shape that, submitted with
 * Q3StateOperator_Submit or met in a group, does what Q3Push_Submit does.
 *
 * @return the new operator, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorOutOfMemory     the object cannot be allocated.
 *
 * Ownership: the caller owns the one reference.
 */
Q3_EXTERN_API_C(TQ3StateOperatorObject) Q3Push_New(void);

/**
 * Creates a pop state operator: a shape that, submitted or met in a group,
 * does what Q3Pop_Submit does. Met in a display group, it cannot pop a state
 * pushed before the group (kQ3ErrorNothingToPop, and the rest of the group
 * is not drawn); states the group's objects push and do not pop are dropped
 * at the group's end.
 *
 * @return the new operator, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorOutOfMemory     the object cannot be allocated.
 *
 * Ownership: the caller owns the one reference.
 */
Q3_EXTERN_API_C(TQ3StateOperatorObject) Q3Pop_New(void);

/**
 * Submits a push or pop state operator to a view.
 *
 * @param stateOperator  a push or pop operator.
 * @param view           a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      stateOperator or view is NULL.
 *   kQ3ErrorInvalidObject      either is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  stateOperator is not a state operator, or
 *                              view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   kQ3ErrorNothingToPop       a pop with nothing pushed left to restore.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3StateOperator_Submit(TQ3StateOperatorObject stateOperator,
                                                  TQ3ViewObject view);

#ifdef __cplusplus
}
#endif

#endif /* QD3DVIEW_H */
