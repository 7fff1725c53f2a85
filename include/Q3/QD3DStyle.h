/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Styles: the subdivision style, which tells a view how finely to break
 * curved geometry (NURB curves) into line segments.
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error and leaves every object and output it was
 * given unchanged. Warnings do not make a call fail. The checks run in this
 * order, and the first that fails decides the error: Q3 is initialized; then
 * the arguments from left to right (a handle: not NULL, a live Q3 object, of
 * the right class; a pointer: not NULL); then the function's other
 * conditions in the order it lists them (for a data structure, the rules
 * given with its type, in their order).
 */
#ifndef QD3DSTYLE_H
#define QD3DSTYLE_H

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

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
 * kQ3SubdivisionMaxConstantSegments
 *   The largest c1 or c2 accepted for kQ3SubdivisionMethodConstant
 *   (segments per knot span); larger values are replaced by this one.
 * kQ3SubdivisionDefaultC1
 *   The value substituted for a non-finite c1 or c2, or for one that is not
 *   positive under the world-space and screen-space methods. It equals
 *   QuickDraw 3D's view default (kQ3ViewDefaultSubdivisionC1 in QD3DView.h:
 *   screen-space subdivision with c1 = c2 = 20).
 */
#define kQ3SubdivisionMaxSegmentsPerCurve (1 << 20)
#define kQ3SubdivisionMaxTrianglesPerPatch (1 << 20)
#define kQ3SubdivisionMaxConstantSegments 1024
#define kQ3SubdivisionDefaultC1 20.0f

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

#ifdef __cplusplus
}
#endif

#endif /* QD3DSTYLE_H */
