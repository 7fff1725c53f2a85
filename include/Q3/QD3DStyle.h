/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Styles: how a view draws the geometry that follows them. Every style of
 * QuickDraw 3D 1.6 is here (subdivision, pick ID, pick parts, receive
 * shadows, fill, backfacing, interpolation, highlight, orientation,
 * anti-alias, fog), plus Quesa's cast shadows style.
 *
 * A style is a shape: submitted to a view in a rendering or bounding loop
 * (its kind's _Submit, Q3Style_Submit, Q3Object_Submit, or from a group) it
 * sets its part of the view's state for the geometry submitted after it,
 * until another style of the same kind is submitted or a Q3Pop_Submit
 * restores an earlier state. Each kind's _Submit taking values instead of
 * an object (immediate mode) checks them exactly as _New and _Set do.
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error and leaves every object and output it was
 * given unchanged. Warnings do not make a call fail. The checks run in this
 * order, and the first that fails decides the error: Q3 is initialized; then
 * the arguments from left to right (a handle: not NULL, a live Q3 object, of
 * the right class; a pointer: not NULL); then the function's other
 * conditions in the order it lists them (for a data structure, the rules
 * given with its type, in their order). Every successful _Set or _SetData
 * changes the style's edit index (Q3Shared_GetEditIndex); a failed one
 * leaves it unchanged.
 *
 * A value that breaks a rule of the styles below the subdivision style (an
 * enumeration value that is none of its constants, a number that is NaN,
 * infinite or out of its range) fails with kQ3ErrorInvalidParameter. A
 * TQ3Boolean argument is never an error: any value other than kQ3False is
 * taken, and stored, as kQ3True (legacy code passes plain nonzero ints), as
 * in QD3DDrawContext.h.
 */
#ifndef QD3DSTYLE_H
#define QD3DSTYLE_H

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Q3 extension (Quesa's name and value): the type of the cast shadows style,
 * which QuickDraw 3D 1.6 did not have.
 */
#define kQ3StyleTypeCastShadows Q3_OBJECT_TYPE('c', 'a', 's', 'h')

/* ---- Every style --------------------------------------------------------- */

/**
 * Returns the kind of a style.
 *
 * @param style  any style.
 * @return its type (kQ3StyleTypeSubdivision, kQ3StyleTypeFill, ...), or
 *         kQ3ObjectTypeInvalid on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      style is NULL.
 *   kQ3ErrorInvalidObject      style is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  style is not a style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Style_GetType(TQ3StyleObject style);

/**
 * Submits a style object to a view in a rendering or bounding loop: it sets
 * its part of the view's state (see the top of this header).
 * Q3Object_Submit does the same.
 *
 * @param style  the style.
 * @param view   a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      style or view is NULL.
 *   kQ3ErrorInvalidObject      style or view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  style is not a style, or view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *
 * Ownership: the view keeps no reference beyond the loop.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Style_Submit(TQ3StyleObject style, TQ3ViewObject view);

/* ---- Subdivision --------------------------------------------------------- */

/*
 * How a curve is subdivided; c1 (c2 for surfaces) of TQ3SubdivisionStyleData
 * means:
 *   kQ3SubdivisionMethodConstant    the number of segments between each pair
 *                                   of adjacent distinct knots (a whole number;
 *                                   a fraction is truncated when used);
 *   kQ3SubdivisionMethodWorldSpace  the longest a segment may be, in world
 *                                   units;
 *   kQ3SubdivisionMethodScreenSpace the longest a segment may be, in pixels.
 */
enum TQ3SubdivisionMethod {
    kQ3SubdivisionMethodConstant   = 0,
    kQ3SubdivisionMethodWorldSpace = 1,
    kQ3SubdivisionMethodScreenSpace = 2
};
typedef enum TQ3SubdivisionMethod TQ3SubdivisionMethod;

/* A subdivision style: c1 is used by curves, c2 by surfaces. */
struct TQ3SubdivisionStyleData {
    TQ3SubdivisionMethod method;
    float c1;
    float c2;
};
typedef struct TQ3SubdivisionStyleData TQ3SubdivisionStyleData;

/*
 * Q3 extension constants (QuickDraw 3D never had these names). They bound
 * the work a subdivision style can ask for.
 *
 * kQ3SubdivisionMaxSegmentsPerCurve
 *   The most line segments one NURB curve is ever drawn with, whatever the
 *   style. A curve whose style asks for more is drawn with at most this
 *   many, and its submit posts kQ3WarningParameterOutOfRange.
 * kQ3SubdivisionMaxTrianglesPerPatch
 *   The most triangles one NURB patch is ever drawn with, whatever the
 *   style, except that every pair of knot spans gets at least two. A patch
 *   whose style asks for more is drawn with at most this many (longer
 *   edges, or fewer segments per span), and its submit posts
 *   kQ3WarningParameterOutOfRange.
 * kQ3SubdivisionMaxTrianglesPerSurface
 *   The most triangles one box, cone, cylinder, disk, ellipsoid or torus is
 *   ever drawn with, whatever the style. One whose style asks for more is
 *   drawn with fewer (constant counts scaled down, or longer world- or
 *   screen-space edges), and its submit posts
 *   kQ3WarningParameterOutOfRange. (An ellipse is a curve: it is bounded by
 *   kQ3SubdivisionMaxSegmentsPerCurve.)
 * kQ3SubdivisionMaxConstantSegments
 *   The largest c1 or c2 accepted for kQ3SubdivisionMethodConstant
 *   (segments per knot span); larger values are replaced by this one.
 * kQ3SubdivisionViewSegmentsPerPixel
 *   In a view (a rendering loop, or a bounding loop whose view has a camera
 *   and a pixmap draw context), a world- or screen-space curve is drawn with
 *   at most this many segments per pixel of the pane's width plus height
 *   (4096 for a 128 x 128 pane), and never more than
 *   kQ3SubdivisionMaxSegmentsPerCurve. A curve that would need more gets a
 *   longer segment length, and its submit posts
 *   kQ3WarningParameterOutOfRange. Without a view the cap stays
 *   kQ3SubdivisionMaxSegmentsPerCurve. Whatever the method, a rendering loop
 *   draws each knot span whose control points all lie outside one side of
 *   the view volume, or nearer than its hither plane, as one segment: no
 *   point of it can be seen.
 * kQ3SubdivisionMinScreenSpaceC1
 *   The smallest screen-space c1 or c2, in pixels (1/8). The image is
 *   sampled once per pixel: a curve cut into segments of 1/8 pixel already
 *   has eight vertices in every pixel it crosses, and cutting it finer
 *   costs time in proportion for a difference the samples cannot show.
 *   Smaller positive values are replaced by this one (also in a bounding
 *   loop without a camera, where screen-space c1 is a world length).
 * kQ3SubdivisionDefaultC1
 *   The value substituted for a non-finite c1 or c2, or for one that is not
 *   positive under the world-space and screen-space methods. It equals
 *   QuickDraw 3D's view default (kQ3ViewDefaultSubdivisionC1 in QD3DView.h:
 *   screen-space subdivision with c1 = c2 = 20).
 */
#define kQ3SubdivisionMaxSegmentsPerCurve (1 << 20)
#define kQ3SubdivisionMaxTrianglesPerPatch (1 << 20)
#define kQ3SubdivisionMaxTrianglesPerSurface (1 << 20)
#define kQ3SubdivisionMaxConstantSegments 1024
#define kQ3SubdivisionDefaultC1 20.0f
#define kQ3SubdivisionViewSegmentsPerPixel 16
#define kQ3SubdivisionMinScreenSpaceC1 0.125f

/*
 * The substitution rule used by every function below that accepts a
 * TQ3SubdivisionStyleData (New, SetData and Submit alike). Both c1 and c2 are
 * checked, whichever kind of geometry follows, and each unreasonable value is
 * replaced as follows:
 *   non-finite (NaN or an infinity)          -> kQ3SubdivisionDefaultC1
 *   constant method, value < 1               -> 1
 *   constant method, value above
 *     kQ3SubdivisionMaxConstantSegments      -> kQ3SubdivisionMaxConstantSegments
 *   world- or screen-space method, value <= 0 -> kQ3SubdivisionDefaultC1
 *   screen-space method, 0 < value < kQ3SubdivisionMinScreenSpaceC1
 *                                            -> kQ3SubdivisionMinScreenSpaceC1
 * If any value was replaced, kQ3WarningParameterOutOfRange is posted once and
 * the call still succeeds with the replaced values.
 */

/**
 * Creates a subdivision style object.
 *
 * @param data  the method and parameters; unreasonable c1 and c2 values are
 *              replaced by the substitution rule above.
 * @return the new style, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   data is NULL.
 *   kQ3ErrorInvalidData     data->method is not a TQ3SubdivisionMethod value.
 *   kQ3ErrorOutOfMemory     the style cannot be allocated.
 * Warnings:
 *   kQ3WarningParameterOutOfRange  c1 or c2 was replaced.
 *
 * Ownership: the caller owns the one reference the new style is born with
 * and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3StyleObject) Q3SubdivisionStyle_New(const TQ3SubdivisionStyleData *data);

/**
 * Applies a subdivision style to a view in a rendering or bounding loop
 * without creating an object (immediate mode). It governs every curve
 * submitted afterwards in the same pass until another subdivision style is
 * submitted or a Q3Pop_Submit restores an earlier state.
 *
 * @param data  the method and parameters; unreasonable c1 and c2 values are
 *              replaced by the substitution rule above.
 * @param view  a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      data or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   kQ3ErrorInvalidData        data->method is not a TQ3SubdivisionMethod value.
 * Warnings:
 *   kQ3WarningParameterOutOfRange  c1 or c2 was replaced.
 *
 * Ownership: no references are kept; *data is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SubdivisionStyle_Submit(const TQ3SubdivisionStyleData *data,
                                                     TQ3ViewObject view);

/**
 * Replaces the method and parameters of a subdivision style object.
 *
 * @param subdiv  the style to change.
 * @param data    the new method and parameters; unreasonable c1 and c2
 *                values are replaced by the substitution rule above.
 * @return kQ3Success, or kQ3Failure with the style unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      subdiv or data is NULL.
 *   kQ3ErrorInvalidObject      subdiv is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  subdiv is not a subdivision style.
 *   kQ3ErrorInvalidData        data->method is not a TQ3SubdivisionMethod value.
 * Warnings:
 *   kQ3WarningParameterOutOfRange  c1 or c2 was replaced.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SubdivisionStyle_SetData(TQ3StyleObject subdiv,
                                                      const TQ3SubdivisionStyleData *data);

/**
 * Reads the method and parameters of a subdivision style object, after any
 * substitution made when they were set.
 *
 * @param subdiv  the style to read.
 * @param data    receives the method, c1 and c2.
 * @return kQ3Success, or kQ3Failure with *data unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      subdiv or data is NULL.
 *   kQ3ErrorInvalidObject      subdiv is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  subdiv is not a subdivision style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SubdivisionStyle_GetData(TQ3StyleObject subdiv,
                                                      TQ3SubdivisionStyleData *data);

/* ---- Pick ID ------------------------------------------------------------- */

/*
 * The pick ID style tags the geometry submitted after it with a number that
 * picking reports for it. The view's default is 0.
 */

/**
 * Creates a pick ID style object.
 *
 * @param id  the ID; any value.
 * @return the new style, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorOutOfMemory     the style cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new style is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3StyleObject) Q3PickIDStyle_New(unsigned long id);

/**
 * Applies a pick ID style to a view in a rendering or bounding loop without
 * creating an object (immediate mode): it governs the geometry submitted
 * after it, as a pick ID style object submitted there would.
 *
 * @param id    the ID; any value.
 * @param view  a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding
 *                              loop.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PickIDStyle_Submit(unsigned long id, TQ3ViewObject view);

/**
 * Reads the value of a pick ID style object.
 *
 * @param pickIDObject  the style to read.
 * @param id            receives the value.
 * @return kQ3Success, or kQ3Failure with *id unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pickIDObject or id is NULL.
 *   kQ3ErrorInvalidObject      pickIDObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pickIDObject is not a pick ID style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PickIDStyle_Get(TQ3StyleObject pickIDObject, unsigned long *id);

/**
 * Replaces the value of a pick ID style object.
 *
 * @param pickIDObject  the style to change.
 * @param id            the ID; any value.
 * @return kQ3Success, or kQ3Failure with the style unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pickIDObject is NULL.
 *   kQ3ErrorInvalidObject      pickIDObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pickIDObject is not a pick ID style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PickIDStyle_Set(TQ3StyleObject pickIDObject, unsigned long id);

/* ---- Pick parts ---------------------------------------------------------- */

/*
 * The pick parts style says which parts of the geometry after it picking
 * reports: the whole object (kQ3PickPartsObject, the view's default), or
 * any combination of its faces, edges and vertices.
 */
enum TQ3PickPartsMasks {
    kQ3PickPartsObject = 0,
    kQ3PickPartsMaskFace = 1 << 0,
    kQ3PickPartsMaskEdge = 1 << 1,
    kQ3PickPartsMaskVertex = 1 << 2
};
typedef enum TQ3PickPartsMasks TQ3PickPartsMasks;
typedef unsigned long TQ3PickParts;

/**
 * Creates a pick parts style object.
 *
 * @param parts  kQ3PickPartsObject, or any combination of
 *               kQ3PickPartsMaskFace, kQ3PickPartsMaskEdge and
 *               kQ3PickPartsMaskVertex.
 * @return the new style, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorInvalidParameter  parts has a bit set that is none of the three
 *                             masks.
 *   kQ3ErrorOutOfMemory       the style cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new style is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3StyleObject) Q3PickPartsStyle_New(TQ3PickParts parts);

/**
 * Applies a pick parts style to a view in a rendering or bounding loop
 * without creating an object (immediate mode): it governs the geometry
 * submitted after it, as a pick parts style object submitted there would.
 *
 * @param parts  kQ3PickPartsObject, or any combination of
 *               kQ3PickPartsMaskFace, kQ3PickPartsMaskEdge and
 *               kQ3PickPartsMaskVertex.
 * @param view   a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding
 *                              loop.
 *   kQ3ErrorInvalidParameter   parts has a bit set that is none of the three
 *                              masks.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PickPartsStyle_Submit(TQ3PickParts parts, TQ3ViewObject view);

/**
 * Reads the value of a pick parts style object.
 *
 * @param pickPartsObject  the style to read.
 * @param parts            receives the value.
 * @return kQ3Success, or kQ3Failure with *parts unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pickPartsObject or parts is NULL.
 *   kQ3ErrorInvalidObject      pickPartsObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pickPartsObject is not a pick parts style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PickPartsStyle_Get(TQ3StyleObject pickPartsObject, TQ3PickParts *parts);

/**
 * Replaces the value of a pick parts style object.
 *
 * @param pickPartsObject  the style to change.
 * @param parts            kQ3PickPartsObject, or any combination of
 *                         kQ3PickPartsMaskFace, kQ3PickPartsMaskEdge and
 *                         kQ3PickPartsMaskVertex.
 * @return kQ3Success, or kQ3Failure with the style unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pickPartsObject is NULL.
 *   kQ3ErrorInvalidObject      pickPartsObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pickPartsObject is not a pick parts style.
 *   kQ3ErrorInvalidParameter   parts has a bit set that is none of the three
 *                              masks.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PickPartsStyle_Set(TQ3StyleObject pickPartsObject, TQ3PickParts parts);

/* ---- Cast shadows (Q3 extension, Quesa's names) -------------------------- */

/*
 * Q3 extension (Quesa's names): QuickDraw 3D 1.6 had no cast shadows style.
 * It says whether the geometry after it casts shadows from lights that cast
 * them. The view's default is kQ3True.
 */

/**
 * Creates a cast shadows style object.
 *
 * @param castsShadows  kQ3True if the geometry casts shadows; any nonzero
 *                      value is stored as kQ3True.
 * @return the new style, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorOutOfMemory     the style cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new style is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3StyleObject) Q3CastShadowsStyle_New(TQ3Boolean castsShadows);

/**
 * Applies a cast shadows style to a view in a rendering or bounding loop
 * without creating an object (immediate mode): it governs the geometry
 * submitted after it, as a cast shadows style object submitted there would.
 *
 * @param castShadows  kQ3True if the geometry casts shadows; any nonzero
 *                     value is stored as kQ3True.
 * @param view         a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding
 *                              loop.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3CastShadowsStyle_Submit(TQ3Boolean castShadows, TQ3ViewObject view);

/**
 * Reads the value of a cast shadows style object.
 *
 * @param styleObject  the style to read.
 * @param castShadows  receives the value.
 * @return kQ3Success, or kQ3Failure with *castShadows unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      styleObject or castShadows is NULL.
 *   kQ3ErrorInvalidObject      styleObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  styleObject is not a cast shadows style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3CastShadowsStyle_Get(TQ3StyleObject styleObject, TQ3Boolean *castShadows);

/**
 * Replaces the value of a cast shadows style object.
 *
 * @param styleObject  the style to change.
 * @param castShadows  kQ3True if the geometry casts shadows; any nonzero
 *                     value is stored as kQ3True.
 * @return kQ3Success, or kQ3Failure with the style unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      styleObject is NULL.
 *   kQ3ErrorInvalidObject      styleObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  styleObject is not a cast shadows style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3CastShadowsStyle_Set(TQ3StyleObject styleObject, TQ3Boolean castShadows);

/* ---- Receive shadows ----------------------------------------------------- */

/*
 * The receive shadows style says whether the geometry after it shows the
 * shadows other geometry casts on it. The view's default is kQ3True.
 */

/**
 * Creates a receive shadows style object.
 *
 * @param receives  kQ3True if the geometry receives shadows; any nonzero
 *                  value is stored as kQ3True.
 * @return the new style, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorOutOfMemory     the style cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new style is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3StyleObject) Q3ReceiveShadowsStyle_New(TQ3Boolean receives);

/**
 * Applies a receive shadows style to a view in a rendering or bounding loop
 * without creating an object (immediate mode): it governs the geometry
 * submitted after it, as a receive shadows style object submitted there
 * would.
 *
 * @param receives  kQ3True if the geometry receives shadows; any nonzero
 *                  value is stored as kQ3True.
 * @param view      a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding
 *                              loop.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ReceiveShadowsStyle_Submit(TQ3Boolean receives, TQ3ViewObject view);

/**
 * Reads the value of a receive shadows style object.
 *
 * @param styleObject  the style to read.
 * @param receives     receives the value.
 * @return kQ3Success, or kQ3Failure with *receives unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      styleObject or receives is NULL.
 *   kQ3ErrorInvalidObject      styleObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  styleObject is not a receive shadows style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ReceiveShadowsStyle_Get(TQ3StyleObject styleObject, TQ3Boolean *receives);

/**
 * Replaces the value of a receive shadows style object.
 *
 * @param styleObject  the style to change.
 * @param receives     kQ3True if the geometry receives shadows; any nonzero
 *                     value is stored as kQ3True.
 * @return kQ3Success, or kQ3Failure with the style unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      styleObject is NULL.
 *   kQ3ErrorInvalidObject      styleObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  styleObject is not a receive shadows style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ReceiveShadowsStyle_Set(TQ3StyleObject styleObject, TQ3Boolean receives);

/* ---- Fill ---------------------------------------------------------------- */

/*
 * The fill style says how surfaces are drawn: filled, as their edges, or as
 * their vertices. The view's default is kQ3FillStyleFilled.
 */
enum TQ3FillStyle { kQ3FillStyleFilled = 0, kQ3FillStyleEdges = 1, kQ3FillStylePoints = 2 };
typedef enum TQ3FillStyle TQ3FillStyle;

/**
 * Creates a fill style object.
 *
 * @param fillStyle  kQ3FillStyleFilled, kQ3FillStyleEdges or
 *                   kQ3FillStylePoints.
 * @return the new style, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorInvalidParameter  fillStyle is not a TQ3FillStyle value.
 *   kQ3ErrorOutOfMemory       the style cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new style is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3StyleObject) Q3FillStyle_New(TQ3FillStyle fillStyle);

/**
 * Applies a fill style to a view in a rendering or bounding loop without
 * creating an object (immediate mode): it governs the geometry submitted
 * after it, as a fill style object submitted there would.
 *
 * @param fillStyle  kQ3FillStyleFilled, kQ3FillStyleEdges or
 *                   kQ3FillStylePoints.
 * @param view       a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding
 *                              loop.
 *   kQ3ErrorInvalidParameter   fillStyle is not a TQ3FillStyle value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3FillStyle_Submit(TQ3FillStyle fillStyle, TQ3ViewObject view);

/**
 * Reads the value of a fill style object.
 *
 * @param styleObject  the style to read.
 * @param fillStyle    receives the value.
 * @return kQ3Success, or kQ3Failure with *fillStyle unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      styleObject or fillStyle is NULL.
 *   kQ3ErrorInvalidObject      styleObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  styleObject is not a fill style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3FillStyle_Get(TQ3StyleObject styleObject, TQ3FillStyle *fillStyle);

/**
 * Replaces the value of a fill style object.
 *
 * @param styleObject  the style to change.
 * @param fillStyle    kQ3FillStyleFilled, kQ3FillStyleEdges or
 *                     kQ3FillStylePoints.
 * @return kQ3Success, or kQ3Failure with the style unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      styleObject is NULL.
 *   kQ3ErrorInvalidObject      styleObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  styleObject is not a fill style.
 *   kQ3ErrorInvalidParameter   fillStyle is not a TQ3FillStyle value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3FillStyle_Set(TQ3StyleObject styleObject, TQ3FillStyle fillStyle);

/* ---- Backfacing ---------------------------------------------------------- */

/*
 * The backfacing style says what happens to the faces that point away from
 * the camera: drawn like the others (kQ3BackfacingStyleBoth, the view's
 * default), removed, or drawn with their normals reversed (flip). Under
 * Both a back face is lit with its own normal, which points away from the
 * camera, so the lights on the camera's side leave it dark but for ambient
 * light, and a light behind it lights it: the QD3D Book's "Backfacing
 * Styles" says such faces "may be illuminated only dimly or not at all,
 * because their face normals point away from the camera", and only the flip
 * style inverts the normals. (Quesa flips them under Both as well.)
 */
enum TQ3BackfacingStyle { kQ3BackfacingStyleBoth = 0, kQ3BackfacingStyleRemove = 1, kQ3BackfacingStyleFlip = 2 };
typedef enum TQ3BackfacingStyle TQ3BackfacingStyle;

/**
 * Creates a backfacing style object.
 *
 * @param backfacingStyle  kQ3BackfacingStyleBoth, kQ3BackfacingStyleRemove or
 *                         kQ3BackfacingStyleFlip.
 * @return the new style, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorInvalidParameter  backfacingStyle is not a TQ3BackfacingStyle
 *                             value.
 *   kQ3ErrorOutOfMemory       the style cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new style is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3StyleObject) Q3BackfacingStyle_New(TQ3BackfacingStyle backfacingStyle);

/**
 * Applies a backfacing style to a view in a rendering or bounding loop
 * without creating an object (immediate mode): it governs the geometry
 * submitted after it, as a backfacing style object submitted there would.
 *
 * @param backfacingStyle  kQ3BackfacingStyleBoth, kQ3BackfacingStyleRemove or
 *                         kQ3BackfacingStyleFlip.
 * @param view             a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding
 *                              loop.
 *   kQ3ErrorInvalidParameter   backfacingStyle is not a TQ3BackfacingStyle
 *                              value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3BackfacingStyle_Submit(TQ3BackfacingStyle backfacingStyle, TQ3ViewObject view);

/**
 * Reads the value of a backfacing style object.
 *
 * @param backfacingObject  the style to read.
 * @param backfacingStyle   receives the value.
 * @return kQ3Success, or kQ3Failure with *backfacingStyle unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      backfacingObject or backfacingStyle is NULL.
 *   kQ3ErrorInvalidObject      backfacingObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  backfacingObject is not a backfacing style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3BackfacingStyle_Get(TQ3StyleObject backfacingObject,
                                                 TQ3BackfacingStyle *backfacingStyle);

/**
 * Replaces the value of a backfacing style object.
 *
 * @param backfacingObject  the style to change.
 * @param backfacingStyle   kQ3BackfacingStyleBoth, kQ3BackfacingStyleRemove
 *                          or kQ3BackfacingStyleFlip.
 * @return kQ3Success, or kQ3Failure with the style unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      backfacingObject is NULL.
 *   kQ3ErrorInvalidObject      backfacingObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  backfacingObject is not a backfacing style.
 *   kQ3ErrorInvalidParameter   backfacingStyle is not a TQ3BackfacingStyle
 *                              value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3BackfacingStyle_Set(TQ3StyleObject backfacingObject,
                                                 TQ3BackfacingStyle backfacingStyle);

/* ---- Interpolation ------------------------------------------------------- */

/*
 * The interpolation style says how lighting varies across a face: one
 * colour per face (none), colours computed at the vertices and blended
 * (vertex, the view's default), or computed at every pixel.
 */
enum TQ3InterpolationStyle {
    kQ3InterpolationStyleNone = 0,
    kQ3InterpolationStyleVertex = 1,
    kQ3InterpolationStylePixel = 2
};
typedef enum TQ3InterpolationStyle TQ3InterpolationStyle;

/**
 * Creates a interpolation style object.
 *
 * @param interpolationStyle  kQ3InterpolationStyleNone,
 *                            kQ3InterpolationStyleVertex or
 *                            kQ3InterpolationStylePixel.
 * @return the new style, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorInvalidParameter  interpolationStyle is not a
 *                             TQ3InterpolationStyle value.
 *   kQ3ErrorOutOfMemory       the style cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new style is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3StyleObject) Q3InterpolationStyle_New(TQ3InterpolationStyle interpolationStyle);

/**
 * Applies a interpolation style to a view in a rendering or bounding loop
 * without creating an object (immediate mode): it governs the geometry
 * submitted after it, as a interpolation style object submitted there would.
 *
 * @param interpolationStyle  kQ3InterpolationStyleNone,
 *                            kQ3InterpolationStyleVertex or
 *                            kQ3InterpolationStylePixel.
 * @param view                a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding
 *                              loop.
 *   kQ3ErrorInvalidParameter   interpolationStyle is not a
 *                              TQ3InterpolationStyle value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InterpolationStyle_Submit(TQ3InterpolationStyle interpolationStyle,
                                                       TQ3ViewObject view);

/**
 * Reads the value of a interpolation style object.
 *
 * @param interpolationObject  the style to read.
 * @param interpolationStyle   receives the value.
 * @return kQ3Success, or kQ3Failure with *interpolationStyle unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      interpolationObject or interpolationStyle is
 *                              NULL.
 *   kQ3ErrorInvalidObject      interpolationObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  interpolationObject is not a interpolation
 *                              style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InterpolationStyle_Get(TQ3StyleObject interpolationObject,
                                                    TQ3InterpolationStyle *interpolationStyle);

/**
 * Replaces the value of a interpolation style object.
 *
 * @param interpolationObject  the style to change.
 * @param interpolationStyle   kQ3InterpolationStyleNone,
 *                             kQ3InterpolationStyleVertex or
 *                             kQ3InterpolationStylePixel.
 * @return kQ3Success, or kQ3Failure with the style unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      interpolationObject is NULL.
 *   kQ3ErrorInvalidObject      interpolationObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  interpolationObject is not a interpolation
 *                              style.
 *   kQ3ErrorInvalidParameter   interpolationStyle is not a
 *                              TQ3InterpolationStyle value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3InterpolationStyle_Set(TQ3StyleObject interpolationObject,
                                                    TQ3InterpolationStyle interpolationStyle);

/* ---- Highlight ----------------------------------------------------------- */

/*
 * The highlight style holds an attribute set whose attributes replace those
 * of every geometry (or face, or vertex) after it whose highlight state
 * attribute (kQ3AttributeTypeHighlightState) is kQ3On. A highlight style
 * with no attribute set (NULL) turns highlighting off, as in the view's
 * default state. The style holds a reference to the set, not a copy: later
 * changes to the set show.
 */

/**
 * Creates a highlight style object.
 *
 * @param highlightAttribute  the attribute set drawn over highlighted
 *                            geometry, or NULL for none.
 * @return the new style, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorInvalidObject      highlightAttribute is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  highlightAttribute is not an attribute set.
 *   kQ3ErrorOutOfMemory        the style cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new style is born with
 * and releases it with Q3Object_Dispose. The style takes a reference to
 * highlightAttribute (Q3Object_Duplicate of the style copies the set).
 */
Q3_EXTERN_API_C(TQ3StyleObject) Q3HighlightStyle_New(TQ3AttributeSet highlightAttribute);

/**
 * Applies a highlight attribute set to a view in a rendering or bounding
 * loop without creating an object (immediate mode), as a highlight style
 * object submitted there would.
 *
 * @param highlightAttribute  the attribute set drawn over highlighted
 *                            geometry, or NULL for none.
 * @param view                a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorInvalidObject      highlightAttribute or view is not a live Q3
 *                              object.
 *   kQ3ErrorInvalidObjectType  highlightAttribute is not an attribute set,
 *                              or view is not a view.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *
 * Ownership: the view holds a reference to highlightAttribute while its
 * state uses it, at most until the end of the loop.
 */
Q3_EXTERN_API_C(TQ3Status) Q3HighlightStyle_Submit(TQ3AttributeSet highlightAttribute, TQ3ViewObject view);

/**
 * Reads the attribute set of a highlight style object.
 *
 * @param highlight           the style to read.
 * @param highlightAttribute  receives the style's attribute set, or NULL
 *                            when it has none.
 * @return kQ3Success, or kQ3Failure with *highlightAttribute unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      highlight or highlightAttribute is NULL.
 *   kQ3ErrorInvalidObject      highlight is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  highlight is not a highlight style.
 *
 * Ownership: a set returned carries a new reference, which the caller
 * releases with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3HighlightStyle_Get(TQ3StyleObject highlight, TQ3AttributeSet *highlightAttribute);

/**
 * Replaces the attribute set of a highlight style object.
 *
 * @param highlight           the style to change.
 * @param highlightAttribute  the new attribute set, or NULL for none.
 * @return kQ3Success, or kQ3Failure with the style unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      highlight is NULL.
 *   kQ3ErrorInvalidObject      highlight or highlightAttribute is not a live
 *                              Q3 object.
 *   kQ3ErrorInvalidObjectType  highlight is not a highlight style, or
 *                              highlightAttribute is not an attribute set.
 *
 * Ownership: the style takes a reference to the new set and releases the one
 * it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3HighlightStyle_Set(TQ3StyleObject highlight, TQ3AttributeSet highlightAttribute);

/* ---- Orientation --------------------------------------------------------- */

/*
 * The orientation style says which side of a polygon is its front: the one
 * from which its vertices run counterclockwise (the view's default) or
 * clockwise. The backfacing style and lighting use it.
 */
enum TQ3OrientationStyle { kQ3OrientationStyleCounterClockwise = 0, kQ3OrientationStyleClockwise = 1 };
typedef enum TQ3OrientationStyle TQ3OrientationStyle;

/**
 * Creates a orientation style object.
 *
 * @param frontFacingDirection  kQ3OrientationStyleCounterClockwise or
 *                              kQ3OrientationStyleClockwise.
 * @return the new style, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorInvalidParameter  frontFacingDirection is not a
 *                             TQ3OrientationStyle value.
 *   kQ3ErrorOutOfMemory       the style cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new style is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3StyleObject) Q3OrientationStyle_New(TQ3OrientationStyle frontFacingDirection);

/**
 * Applies a orientation style to a view in a rendering or bounding loop
 * without creating an object (immediate mode): it governs the geometry
 * submitted after it, as a orientation style object submitted there would.
 *
 * @param frontFacingDirection  kQ3OrientationStyleCounterClockwise or
 *                              kQ3OrientationStyleClockwise.
 * @param view                  a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding
 *                              loop.
 *   kQ3ErrorInvalidParameter   frontFacingDirection is not a
 *                              TQ3OrientationStyle value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3OrientationStyle_Submit(TQ3OrientationStyle frontFacingDirection,
                                                     TQ3ViewObject view);

/**
 * Reads the value of a orientation style object.
 *
 * @param frontFacingDirectionObject  the style to read.
 * @param frontFacingDirection        receives the value.
 * @return kQ3Success, or kQ3Failure with *frontFacingDirection unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      frontFacingDirectionObject or
 *                              frontFacingDirection is NULL.
 *   kQ3ErrorInvalidObject      frontFacingDirectionObject is not a live Q3
 *                              object.
 *   kQ3ErrorInvalidObjectType  frontFacingDirectionObject is not a
 *                              orientation style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3OrientationStyle_Get(TQ3StyleObject frontFacingDirectionObject,
                                                  TQ3OrientationStyle *frontFacingDirection);

/**
 * Replaces the value of a orientation style object.
 *
 * @param frontFacingDirectionObject  the style to change.
 * @param frontFacingDirection        kQ3OrientationStyleCounterClockwise or
 *                                    kQ3OrientationStyleClockwise.
 * @return kQ3Success, or kQ3Failure with the style unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      frontFacingDirectionObject is NULL.
 *   kQ3ErrorInvalidObject      frontFacingDirectionObject is not a live Q3
 *                              object.
 *   kQ3ErrorInvalidObjectType  frontFacingDirectionObject is not a
 *                              orientation style.
 *   kQ3ErrorInvalidParameter   frontFacingDirection is not a
 *                              TQ3OrientationStyle value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3OrientationStyle_Set(TQ3StyleObject frontFacingDirectionObject,
                                                  TQ3OrientationStyle frontFacingDirection);

/* ---- Anti-alias ---------------------------------------------------------- */

/*
 * The anti-alias style asks the renderer to smooth jagged edges.
 *   state    kQ3On or kQ3Off (the view's default); the other fields are
 *            kept while it is off.
 *   mode     what is smoothed: kQ3AntiAliasModeMaskEdges (lines, and
 *            surfaces drawn as edges), kQ3AntiAliasModeMaskFilled (filled
 *            surfaces), both, or neither (0). The view's default is edges.
 *   quality  from 0 (fastest) to 1 (best, the view's default); how it is
 *            used is up to the renderer.
 * Q3's renderers smooth by multisampling: each smoothed primitive is
 * rasterized at 4 sample points in every pixel and the pixel is the mean of
 * its samples. Every quality gives those 4 samples (the rasterizer Q3 pins
 * has no other count), so images are the same at any quality and run after
 * run. Off by default, and a frame that smooths nothing draws exactly as
 * without the style.
 * Rules, checked in this order (kQ3ErrorInvalidParameter): state is kQ3On
 * or kQ3Off; mode has no bit but the two masks; quality is finite and
 * within 0..1.
 */
enum TQ3AntiAliasModeMasks { kQ3AntiAliasModeMaskEdges = 1 << 0, kQ3AntiAliasModeMaskFilled = 1 << 1 };
typedef enum TQ3AntiAliasModeMasks TQ3AntiAliasModeMasks;
typedef unsigned long TQ3AntiAliasMode;

struct TQ3AntiAliasStyleData {
    TQ3Switch state;
    TQ3AntiAliasMode mode;
    float quality;
};
typedef struct TQ3AntiAliasStyleData TQ3AntiAliasStyleData;

/**
 * Creates an anti-alias style object.
 *
 * @param data  the style's values.
 * @return the new style, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     data is NULL.
 *   kQ3ErrorInvalidParameter  data breaks a rule given with
 *                             TQ3AntiAliasStyleData.
 *   kQ3ErrorOutOfMemory       the style cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new style is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3StyleObject) Q3AntiAliasStyle_New(const TQ3AntiAliasStyleData *data);

/**
 * Applies an anti-alias style to a view in a rendering or bounding loop
 * without creating an object (immediate mode): it governs the geometry
 * submitted after it, as an anti-alias style object submitted there would.
 *
 * @param data  the style's values.
 * @param view  a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      data or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding
 *                              loop.
 *   kQ3ErrorInvalidParameter   data breaks a rule given with
 *                              TQ3AntiAliasStyleData.
 *
 * Ownership: no references are kept; *data is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AntiAliasStyle_Submit(const TQ3AntiAliasStyleData *data, TQ3ViewObject view);

/**
 * Reads the values of an anti-alias style object.
 *
 * @param styleObject  the style to read.
 * @param data         receives the values.
 * @return kQ3Success, or kQ3Failure with *data unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      styleObject or data is NULL.
 *   kQ3ErrorInvalidObject      styleObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  styleObject is not an anti-alias style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AntiAliasStyle_GetData(TQ3StyleObject styleObject, TQ3AntiAliasStyleData *data);

/**
 * Replaces the values of an anti-alias style object.
 *
 * @param styleObject  the style to change.
 * @param data         the new values.
 * @return kQ3Success, or kQ3Failure with the style unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      styleObject or data is NULL.
 *   kQ3ErrorInvalidObject      styleObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  styleObject is not an anti-alias style.
 *   kQ3ErrorInvalidParameter   data breaks a rule given with
 *                              TQ3AntiAliasStyleData.
 *
 * Ownership: no references change; *data is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AntiAliasStyle_SetData(TQ3StyleObject styleObject,
                                                    const TQ3AntiAliasStyleData *data);

/* ---- Fog ----------------------------------------------------------------- */

/*
 * The fog style blends what is drawn towards the fog colour with distance z
 * from the camera. The fraction of the object's own colour kept is
 *   kQ3FogModeLinear              (fogEnd - z) / (fogEnd - fogStart),
 *                                 clamped to 0..1
 *   kQ3FogModeExponential         exp(-density * z)
 *   kQ3FogModeExponentialSquared  exp(-(density * z)^2)
 *   kQ3FogModeAlpha               the vertex's alpha
 * The view's default is off, linear from 1 to 1000, density 1, opaque white.
 * Rules, checked in this order (kQ3ErrorInvalidParameter): state is kQ3On
 * or kQ3Off; mode is a TQ3FogMode value; fogStart, fogEnd, density and the
 * four components of color are finite; density is not negative; when state
 * is kQ3On and mode is kQ3FogModeLinear, fogStart is less than fogEnd (fog
 * that is off, or of another mode, may leave the fields it does not use
 * as they are, zero for instance).
 */
enum TQ3FogMode {
    kQ3FogModeLinear = 0,
    kQ3FogModeExponential = 1,
    kQ3FogModeExponentialSquared = 2,
    kQ3FogModeAlpha = 3
};
typedef enum TQ3FogMode TQ3FogMode;

struct TQ3FogStyleData {
    TQ3Switch state;
    TQ3FogMode mode;
    float fogStart;
    float fogEnd;
    float density;
    TQ3ColorARGB color;
};
typedef struct TQ3FogStyleData TQ3FogStyleData;

/**
 * Creates a fog style object.
 *
 * @param data  the style's values.
 * @return the new style, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     data is NULL.
 *   kQ3ErrorInvalidParameter  data breaks a rule given with TQ3FogStyleData.
 *   kQ3ErrorOutOfMemory       the style cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new style is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3StyleObject) Q3FogStyle_New(const TQ3FogStyleData *data);

/**
 * Applies a fog style to a view in a rendering or bounding loop without
 * creating an object (immediate mode): it governs the geometry submitted
 * after it, as a fog style object submitted there would.
 *
 * @param data  the style's values.
 * @param view  a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      data or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding
 *                              loop.
 *   kQ3ErrorInvalidParameter   data breaks a rule given with TQ3FogStyleData.
 *
 * Ownership: no references are kept; *data is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3FogStyle_Submit(const TQ3FogStyleData *data, TQ3ViewObject view);

/**
 * Reads the values of a fog style object.
 *
 * @param styleObject  the style to read.
 * @param data         receives the values.
 * @return kQ3Success, or kQ3Failure with *data unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      styleObject or data is NULL.
 *   kQ3ErrorInvalidObject      styleObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  styleObject is not a fog style.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3FogStyle_GetData(TQ3StyleObject styleObject, TQ3FogStyleData *data);

/**
 * Replaces the values of a fog style object.
 *
 * @param styleObject  the style to change.
 * @param data         the new values.
 * @return kQ3Success, or kQ3Failure with the style unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      styleObject or data is NULL.
 *   kQ3ErrorInvalidObject      styleObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  styleObject is not a fog style.
 *   kQ3ErrorInvalidParameter   data breaks a rule given with TQ3FogStyleData.
 *
 * Ownership: no references change; *data is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3FogStyle_SetData(TQ3StyleObject styleObject, const TQ3FogStyleData *data);

#ifdef __cplusplus
}
#endif

#endif /* QD3DSTYLE_H */
