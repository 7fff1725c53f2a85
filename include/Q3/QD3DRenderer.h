/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Renderers: the objects that turn what a view traverses into pixels in its
 * draw context. The renderer type codes (kQ3RendererType...) are in QD3D.h.
 *
 * Q3 provides two renderers, both rasterizing offscreen into the view's
 * pixmap: the wireframe renderer (kQ3RendererTypeWireFrame), which draws
 * curves, lines and points and the edges of filled shapes, and the
 * interactive renderer (kQ3RendererTypeInteractive), which also fills what
 * it is given. The Q3InteractiveRenderer_... settings below were hints for QuickDraw 3D's RAVE
 * acceleration layer, which Q3 does not have: Q3 stores each value and
 * returns it, so legacy code that sets and reads them keeps working, but the
 * values do not change the image.
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
#ifndef QD3DRENDERER_H
#define QD3DRENDERER_H

#include "QD3D.h"
#include "QD3DSet.h"
#include "QD3DView.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Constructive solid geometry (stored only; see above) --------------- */

/* Attribute type naming the CSG object (A to E) a geometry belongs to. Q3's
 * attribute sets do not store it (Q3AttributeSet_Add rejects it). */
#define kQ3AttributeTypeConstructiveSolidGeometryID Q3_OBJECT_TYPE('c', 's', 'g', 'i')

/* CSG object IDs, the values of that attribute. */
#define kQ3SolidGeometryObjNone (-1)
#define kQ3SolidGeometryObjA 0
#define kQ3SolidGeometryObjB 1
#define kQ3SolidGeometryObjC 2
#define kQ3SolidGeometryObjD 3
#define kQ3SolidGeometryObjE 4

/*
 * CSG equations: 32-bit truth tables over objects A to E; these are common
 * ones, and any other 32-bit value is also an equation.
 * kQ3CSGEquationAandB is the bit pattern 0x88888888. QuickDraw 3D wrote it as
 * (long)0x88888888, which is negative with 32-bit long; here it is spelled as
 * that negative int so that the enumeration stays within int, as C99
 * requires.
 */
enum TQ3CSGEquation {
    kQ3CSGEquationAandB      = -0x77777777 - 1,
    kQ3CSGEquationAandnotB   = 0x22222222,
    kQ3CSGEquationAanBonCad  = 0x2F222F22,
    kQ3CSGEquationnotAandB   = 0x44444444,
    kQ3CSGEquationnAaBorCanB = 0x74747474
};
typedef enum TQ3CSGEquation TQ3CSGEquation;

/* ---- Renderer ----------------------------------------------------------- */

/**
 * Creates a renderer of the given type.
 *
 * @param rendererObjectType  a renderer type code of a renderer Q3 provides
 *                            (kQ3RendererTypeWireFrame or
 *                            kQ3RendererTypeInteractive).
 * @return the new renderer, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorInvalidObjectType  rendererObjectType is not the type of a
 *                              renderer Q3 provides.
 *   kQ3ErrorOutOfMemory        the renderer cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new renderer is born with
 * and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3RendererObject) Q3Renderer_NewFromType(TQ3ObjectType rendererObjectType);

/**
 * Reports the kind of a renderer.
 *
 * @param renderer  the renderer to query.
 * @return its type code (kQ3RendererType...), or kQ3ObjectTypeInvalid on
 *         failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not a renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Renderer_GetType(TQ3RendererObject renderer);

/**
 * Reports whether a renderer is meant for interactive use. Both of Q3's
 * renderers draw a frame at once, in the call that submits it, so both are
 * interactive.
 *
 * @param renderer  the renderer to query.
 * @return kQ3True, or kQ3False on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not a renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Boolean) Q3Renderer_IsInteractive(TQ3RendererObject renderer);

/**
 * Writes the name of a renderer class meant for people (a menu item):
 * "Interactive" for kQ3RendererTypeInteractive, "Wireframe" for
 * kQ3RendererTypeWireFrame. Applications fall back to the class name
 * (Q3ObjectHierarchy_GetStringFromType) when this fails.
 *
 * @param rendererClassType    a renderer class type.
 * @param rendererClassString  receives the name, '\0' terminated.
 * @return kQ3Success, or kQ3Failure with rendererClassString unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     rendererClassString is NULL.
 *   kQ3ErrorInvalidParameter  rendererClassType is not a renderer that Q3
 *                             provides (kQ3SharedTypeRenderer itself
 *                             included).
 *
 * Ownership: none.
 */
Q3_EXTERN_API_C(TQ3Status) Q3RendererClass_GetNickNameString(TQ3ObjectType rendererClassType,
                                                             TQ3ObjectClassNameString rendererClassString);

/* ---- Interactive renderer settings (stored only; see above) ------------- */

/**
 * Stores the CSG equation of an interactive renderer. Q3 does not perform
 * CSG.
 *
 * @param renderer  an interactive renderer.
 * @param equation  any 32-bit truth table (TQ3CSGEquation lists common ones).
 * @return kQ3Success, or kQ3Failure with the renderer unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not an interactive renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InteractiveRenderer_SetCSGEquation(TQ3RendererObject renderer,
                                                                TQ3CSGEquation equation);

/**
 * Reads the stored CSG equation of an interactive renderer
 * (kQ3CSGEquationAandB until one is set).
 *
 * @param renderer  an interactive renderer.
 * @param equation  receives the equation.
 * @return kQ3Success, or kQ3Failure with *equation unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer or equation is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not an interactive renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InteractiveRenderer_GetCSGEquation(TQ3RendererObject renderer,
                                                                TQ3CSGEquation *equation);

/**
 * Stores the preferred RAVE drawing engine of an interactive renderer. Q3
 * always draws with its own engine.
 *
 * @param renderer  an interactive renderer.
 * @param vendorID  a RAVE vendor ID (-1 is RAVE's "best choice"); any value.
 * @param engineID  a RAVE engine ID of that vendor; any value.
 * @return kQ3Success, or kQ3Failure with the renderer unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not an interactive renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InteractiveRenderer_SetPreferences(TQ3RendererObject renderer,
                                                                long vendorID,
                                                                long engineID);

/**
 * Reads the stored RAVE engine preference of an interactive renderer
 * (vendorID -1 and engineID 0 until set).
 *
 * @param renderer  an interactive renderer.
 * @param vendorID  receives the vendor ID.
 * @param engineID  receives the engine ID.
 * @return kQ3Success, or kQ3Failure with both outputs unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer, vendorID or engineID is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not an interactive renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InteractiveRenderer_GetPreferences(TQ3RendererObject renderer,
                                                                long *vendorID,
                                                                long *engineID);

/**
 * Stores whether an interactive renderer may draw straight to the front
 * buffer. Q3 renders into the draw context's own image in every case.
 *
 * @param renderer  an interactive renderer.
 * @param bypass    kQ3True or kQ3False; any other value is stored as kQ3True.
 * @return kQ3Success, or kQ3Failure with the renderer unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not an interactive renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InteractiveRenderer_SetDoubleBufferBypass(TQ3RendererObject renderer,
                                                                       TQ3Boolean bypass);

/**
 * Reads the stored double-buffer bypass setting of an interactive renderer
 * (kQ3False until set).
 *
 * @param renderer  an interactive renderer.
 * @param bypass    receives kQ3True or kQ3False.
 * @return kQ3Success, or kQ3Failure with *bypass unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer or bypass is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not an interactive renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InteractiveRenderer_GetDoubleBufferBypass(TQ3RendererObject renderer,
                                                                       TQ3Boolean *bypass);

/**
 * Stores the RAVE draw context flags (RAVE's kQAContext_... bits) of an
 * interactive renderer. The flags do not change how Q3 renders.
 *
 * @param renderer          an interactive renderer.
 * @param RAVEContextHints  any combination of flags.
 * @return kQ3Success, or kQ3Failure with the renderer unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not an interactive renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InteractiveRenderer_SetRAVEContextHints(
    TQ3RendererObject renderer, unsigned long RAVEContextHints);

/**
 * Reads the stored RAVE draw context flags of an interactive renderer (0
 * until set).
 *
 * @param renderer          an interactive renderer.
 * @param RAVEContextHints  receives the flags.
 * @return kQ3Success, or kQ3Failure with *RAVEContextHints unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer or RAVEContextHints is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not an interactive renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InteractiveRenderer_GetRAVEContextHints(
    TQ3RendererObject renderer, unsigned long *RAVEContextHints);

/**
 * Stores the RAVE texture filter of an interactive renderer (RAVE's
 * kQATextureFilter_Fast 0, _Mid 1, _Best 2). Q3 draws no textures.
 *
 * @param renderer                an interactive renderer.
 * @param RAVEtextureFilterValue  any value.
 * @return kQ3Success, or kQ3Failure with the renderer unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not an interactive renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InteractiveRenderer_SetRAVETextureFilter(
    TQ3RendererObject renderer, unsigned long RAVEtextureFilterValue);

/**
 * Reads the stored RAVE texture filter of an interactive renderer (0 until
 * set).
 *
 * @param renderer                an interactive renderer.
 * @param RAVEtextureFilterValue  receives the value.
 * @return kQ3Success, or kQ3Failure with *RAVEtextureFilterValue unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer or RAVEtextureFilterValue is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not an interactive renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InteractiveRenderer_GetRAVETextureFilter(
    TQ3RendererObject renderer, unsigned long *RAVEtextureFilterValue);

/**
 * Counts the RAVE draw contexts an interactive renderer draws with. Q3 has
 * no RAVE (a Mac-only rasterizer interface), so the answer is always 0.
 *
 * @param renderer         an interactive renderer.
 * @param numRAVEContexts  receives 0.
 * @return kQ3Success, or kQ3Failure with *numRAVEContexts unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer or numRAVEContexts is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not an interactive renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InteractiveRenderer_CountRAVEDrawContexts(TQ3RendererObject renderer,
                                                                       unsigned long *numRAVEContexts);

/* RAVE's draw context and engine (RAVE.h); only pointers to them are used,
 * and Q3 never has one. */
typedef struct TQADrawContext TQADrawContext;
typedef struct TQAEngine TQAEngine;

/* Called when the RAVE draw contexts a renderer handed out go away. */
typedef void (*TQ3RaveDestroyCallback)(TQ3RendererObject renderer);

/**
 * Lists the RAVE draw contexts and engines of an interactive renderer. Q3
 * has none: *numRAVEContexts is set to 0, the lists are not written and the
 * callback is never called.
 *
 * @param renderer                an interactive renderer.
 * @param raveDrawContextList     room for the contexts; may be NULL.
 * @param raveDrawingEnginesList  room for the engines; may be NULL.
 * @param numRAVEContexts         receives 0.
 * @param raveDestroyCallback     may be NULL; not kept.
 * @return kQ3Success, or kQ3Failure with *numRAVEContexts unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      renderer or numRAVEContexts is NULL.
 *   kQ3ErrorInvalidObject      renderer is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  renderer is not an interactive renderer.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InteractiveRenderer_GetRAVEDrawContexts(TQ3RendererObject renderer,
                                                                     TQADrawContext **raveDrawContextList,
                                                                     TQAEngine **raveDrawingEnginesList,
                                                                     unsigned long *numRAVEContexts,
                                                                     TQ3RaveDestroyCallback raveDestroyCallback);

/* ---- Settings dialogs and configuration data ----------------------------- */

/* Apple's Unix dialog anchor: a place holder (Q3 has no settings dialog). */
typedef struct TQ3DialogAnchor {
    void *notUsed;
} TQ3DialogAnchor;

/**
 * Whether the renderer has a modal settings dialog. Q3's renderers have
 * none: kQ3False.
 *
 * Errors: kQ3ErrorNotInitialized; kQ3ErrorNULLParameter,
 * kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType (renderer), each with
 * kQ3False.
 */
Q3_EXTERN_API_C(TQ3Boolean) Q3Renderer_HasModalConfigure(TQ3RendererObject renderer);

/**
 * Shows the renderer's modal settings dialog. Q3's renderers have none, so
 * the call behaves as a dialog the user cancelled at once: *canceled is
 * kQ3True and no setting changes.
 *
 * Errors: the renderer's (as Q3Renderer_HasModalConfigure), then
 * kQ3ErrorNULLParameter (canceled).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Renderer_ModalConfigure(TQ3RendererObject renderer, TQ3DialogAnchor dialogAnchor,
                                                     TQ3Boolean *canceled);

/**
 * The renderer's private configuration, for an application to save (with
 * the renderer's class name) and hand back with SetConfigurationData. Q3's
 * renderers keep none: *actualDataSize is 0 and dataBuffer (which may be
 * NULL, to ask for the size) is not written.
 *
 * Errors: the renderer's, then kQ3ErrorNULLParameter (actualDataSize).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Renderer_GetConfigurationData(TQ3RendererObject renderer, unsigned char *dataBuffer,
                                                           unsigned long bufferSize, unsigned long *actualDataSize);

/**
 * Hands back configuration data GetConfigurationData gave. For Q3's
 * renderers that is always empty: bufferSize 0 (dataBuffer may then be
 * NULL) is accepted and changes nothing.
 *
 * Errors: the renderer's, then kQ3ErrorNULLParameter (dataBuffer NULL with
 * bufferSize above 0), kQ3ErrorInvalidParameter (bufferSize above 0: not
 * data this renderer gave).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Renderer_SetConfigurationData(TQ3RendererObject renderer, unsigned char *dataBuffer,
                                                           unsigned long bufferSize);

/* ---- Renderer view and attribute set tools ------------------------------- */

/**
 * What a renderer calls while it draws to report progress: during a
 * rendering loop, calls the view's idle progress method with (current,
 * completed), or, if it has none, its idle method; when that method returns
 * kQ3Failure the loop is cancelled (Q3View_EndRendering then answers
 * kQ3ViewStatusCancelled) and this call returns kQ3Failure without posting
 * an error. Q3's renderers report no progress themselves (the view calls the
 * methods with 0, 0 before each object); code that renders in steps of its
 * own can report through this call.
 *
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject,
 * kQ3ErrorInvalidObjectType (view), kQ3ErrorInvalidParameter (current
 * above completed), kQ3ErrorRenderingNotStarted (outside a rendering
 * loop).
 */
Q3_EXTERN_API_C(TQ3Status) Q3XView_IdleProgress(TQ3ViewObject view, unsigned long current, unsigned long completed);

/**
 * What an asynchronous renderer calls when it has finished a frame: calls
 * the view's end-frame method (Q3View_SetEndFrameMethod), if any. Q3's
 * renderers finish every frame in Q3View_EndRendering, which already calls
 * it; a frame produced by other means can be announced with this call.
 *
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject,
 * kQ3ErrorInvalidObjectType (view), kQ3ErrorRenderingIsActive (inside a
 * rendering loop: the frame is not finished).
 */
Q3_EXTERN_API_C(TQ3Status) Q3XView_EndFrame(TQ3ViewObject view);

/* Which attributes a set holds, one bit per standard attribute type
 * (1 << (type - 1)), and one for any other (custom) attribute. */
enum {
    kQ3XAttributeMaskNone = 0L,
    kQ3XAttributeMaskSurfaceUV = 1 << (kQ3AttributeTypeSurfaceUV - 1),
    kQ3XAttributeMaskShadingUV = 1 << (kQ3AttributeTypeShadingUV - 1),
    kQ3XAttributeMaskNormal = 1 << (kQ3AttributeTypeNormal - 1),
    kQ3XAttributeMaskAmbientCoefficient = 1 << (kQ3AttributeTypeAmbientCoefficient - 1),
    kQ3XAttributeMaskDiffuseColor = 1 << (kQ3AttributeTypeDiffuseColor - 1),
    kQ3XAttributeMaskSpecularColor = 1 << (kQ3AttributeTypeSpecularColor - 1),
    kQ3XAttributeMaskSpecularControl = 1 << (kQ3AttributeTypeSpecularControl - 1),
    kQ3XAttributeMaskTransparencyColor = 1 << (kQ3AttributeTypeTransparencyColor - 1),
    kQ3XAttributeMaskSurfaceTangent = 1 << (kQ3AttributeTypeSurfaceTangent - 1),
    kQ3XAttributeMaskHighlightState = 1 << (kQ3AttributeTypeHighlightState - 1),
    kQ3XAttributeMaskSurfaceShader = 1 << (kQ3AttributeTypeSurfaceShader - 1),
    kQ3XAttributeMaskInherited = 0x03FF,
    kQ3XAttributeMaskInterpolated = kQ3XAttributeMaskSurfaceUV | kQ3XAttributeMaskShadingUV |
                                    kQ3XAttributeMaskNormal | kQ3XAttributeMaskAmbientCoefficient |
                                    kQ3XAttributeMaskDiffuseColor | kQ3XAttributeMaskSpecularColor |
                                    kQ3XAttributeMaskSpecularControl | kQ3XAttributeMaskTransparencyColor |
                                    kQ3XAttributeMaskSurfaceTangent
};
typedef unsigned long TQ3XAttributeMask;
/* Apple's values; macros rather than enumerators because they do not fit an
 * int, which ISO C requires of an enumerator. */
#define kQ3XAttributeMaskCustomAttribute ((TQ3XAttributeMask)0x80000000UL)
#define kQ3XAttributeMaskAll ((TQ3XAttributeMask)0x800007FFUL)

/**
 * Which attributes the set holds, as kQ3XAttributeMask bits; 0 on failure.
 *
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject,
 * kQ3ErrorInvalidObjectType (attributeSet: not an attribute set).
 */
Q3_EXTERN_API_C(TQ3XAttributeMask) Q3XAttributeSet_GetMask(TQ3AttributeSet attributeSet);

#ifdef __cplusplus
}
#endif

#endif /* QD3DRENDERER_H */
