/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Q3NURBCurveTools.h: Q3 extension. Working with NURB curves, not only drawing
 * them: evaluation with derivatives, tangent and curvature; knot insertion,
 * refinement and removal; degree elevation; Bezier pieces and splitting;
 * interpolation and least-squares approximation of points; arc length; the
 * closest point. QuickDraw 3D never had any of these calls; the develop
 * article "NURB Curves: A Guide for the Uninitiated" explains the operations
 * (its Listings 2 and 3) and docs/curve-tools.md gives each algorithm and its
 * source.
 *
 * Every operation comes in two forms: Q3NURBCurveData_Xxx works on a
 * TQ3NURBCurveData in caller memory (it must obey the TQ3NURBCurveData rules
 * of QD3DGeometry.h; its curveAttributeSet is ignored), and Q3NURBCurve_Xxx on
 * a retained NURB curve, which it only reads. Fitting, which starts from
 * points, has only the data form. Inputs are never changed.
 *
 * Curves come back as a TQ3NURBCurveData whose controlPoints and knots are
 * new arrays owned by the caller, to be released with Q3NURBCurve_EmptyData
 * (QD3DGeometry.h); its curveAttributeSet is NULL. The result structure may
 * be the structure the curve came from: its arrays are then not freed (they
 * are the caller's), only replaced.
 *
 * Conventions shared by every function here, as in QD3DGeometry.h: a call that
 * fails posts exactly one error, returns kQ3Failure and leaves every output
 * unchanged; warnings do not make a call fail. The checks run in this order,
 * and the first that fails decides the error: Q3 is initialized; the
 * arguments from left to right (a handle: not NULL, a live Q3 object, a NURB
 * curve; a pointer: not NULL); the TQ3NURBCurveData rules of QD3DGeometry.h,
 * in their order; then the function's own conditions in the order listed.
 *
 * Parameters are floats, as the knots are; computation is in double. The
 * domain of a curve is [knots[order - 1], knots[numPoints]]. A parameter that
 * is NaN or infinite posts kQ3ErrorInvalidParameter; a finite one outside the
 * range a call accepts posts kQ3ErrorParameterOutOfRange. A result that float
 * cannot hold (a value beyond FLT_MAX, knots that round to equal values, a
 * weight that is not positive) posts kQ3ErrorDegenerateGeometry.
 */
#ifndef Q3NURBCURVETOOLS_H
#define Q3NURBCURVETOOLS_H

#include "QD3D.h"
#include "QD3DGeometry.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Q3 extension constants.
 *
 * kQ3NURBCurveToolsMaxPoints
 *   The most control points a curve tool makes and the most points it fits:
 *   2^28, the numPoints limit of TQ3NURBCurveData (QD3DGeometry.h). A call
 *   whose result would have more posts kQ3ErrorParameterOutOfRange before it
 *   allocates anything.
 * kQ3NURBCurveToolsMaxBisections
 *   The most interval bisections one arc-length call makes beyond one
 *   interval per knot span. When its tolerance has not been met by then the
 *   call succeeds with its best value and posts kQ3WarningParameterOutOfRange,
 *   whose message gives the estimated error.
 */
#define kQ3NURBCurveToolsMaxPoints 268435456UL
#define kQ3NURBCurveToolsMaxBisections 4096UL

/*
 * Q3 extension. How a fitted curve's parameters follow the points: the
 * parameter advances from point to point in proportion to the distance
 * between them (chord length, the lecture's choice), or to its square root
 * (centripetal), which follows sharp turns more tightly. Either way the
 * parameters run from 0 at the first point to 1 at the last.
 */
typedef enum TQ3NURBCurveParameterization {
    kQ3NURBCurveParameterizationChordLength = 0,
    kQ3NURBCurveParameterizationCentripetal = 1
} TQ3NURBCurveParameterization;

/* ---- Evaluation ---------------------------------------------------------- */

/**
 * Q3 extension. Reports the parameter range on which a curve is defined,
 * [knots[order - 1], knots[numPoints]].
 *
 * @param curveData  the curve.
 * @param start      receives knots[order - 1].
 * @param end        receives knots[numPoints].
 * @return kQ3Success, or kQ3Failure with *start and *end unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   curveData, start or end is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h).
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_GetDomain(const TQ3NURBCurveData *curveData, float *start,
                                                     float *end);

/**
 * Q3 extension. As Q3NURBCurveData_GetDomain, for a retained curve.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      curve, start or end is NULL.
 *   kQ3ErrorInvalidObject      curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  curve is not a NURB curve.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_GetDomain(TQ3GeometryObject curve, float *start, float *end);

/**
 * Q3 extension. The point of a curve at parameter t (de Boor's algorithm on
 * the homogeneous control points, divided by w).
 *
 * @param curveData  the curve.
 * @param t          a parameter in the closed domain.
 * @param point      receives the point.
 * @return kQ3Success, or kQ3Failure with *point unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData or point is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h), then:
 *   kQ3ErrorInvalidParameter     t is NaN or infinite.
 *   kQ3ErrorParameterOutOfRange  t is outside the domain.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_Evaluate(const TQ3NURBCurveData *curveData, float t,
                                                    TQ3Point3D *point);

/**
 * Q3 extension. As Q3NURBCurveData_Evaluate, for a retained curve.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve or point is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   kQ3ErrorInvalidParameter     t is NaN or infinite.
 *   kQ3ErrorParameterOutOfRange  t is outside the domain.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_Evaluate(TQ3GeometryObject curve, float t, TQ3Point3D *point);

/**
 * Q3 extension. The point of a curve at t and its first and second
 * derivatives with respect to t (of the rational curve, not of its
 * homogeneous form). At a knot where the curve is not smooth the derivatives
 * are those of the span to the right; at the domain's end, of the last span.
 *
 * @param curveData         the curve.
 * @param t                 a parameter in the closed domain.
 * @param point             receives C(t).
 * @param firstDerivative   receives C'(t).
 * @param secondDerivative  receives C''(t) (zero for a non-rational order-2
 *                          curve).
 * @return kQ3Success, or kQ3Failure with the outputs unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData, point, firstDerivative or
 *                                secondDerivative is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h), then:
 *   kQ3ErrorInvalidParameter     t is NaN or infinite.
 *   kQ3ErrorParameterOutOfRange  t is outside the domain.
 *   kQ3ErrorDegenerateGeometry   a derivative is too large for a float.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_EvaluateDerivatives(const TQ3NURBCurveData *curveData, float t,
                                                               TQ3Point3D *point,
                                                               TQ3Vector3D *firstDerivative,
                                                               TQ3Vector3D *secondDerivative);

/**
 * Q3 extension. As Q3NURBCurveData_EvaluateDerivatives, for a retained curve.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve, point, firstDerivative or
 *                                secondDerivative is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   kQ3ErrorInvalidParameter     t is NaN or infinite.
 *   kQ3ErrorParameterOutOfRange  t is outside the domain.
 *   kQ3ErrorDegenerateGeometry   a derivative is too large for a float.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_EvaluateDerivatives(TQ3GeometryObject curve, float t,
                                                           TQ3Point3D *point,
                                                           TQ3Vector3D *firstDerivative,
                                                           TQ3Vector3D *secondDerivative);

/**
 * Q3 extension. The unit tangent C'(t) / |C'(t)| of a curve at t (the
 * right-hand one at a kink, as for the derivatives).
 *
 * @param curveData  the curve.
 * @param t          a parameter in the closed domain.
 * @param tangent    receives the unit tangent.
 * @return kQ3Success, or kQ3Failure with *tangent unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData or tangent is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h), then:
 *   kQ3ErrorInvalidParameter     t is NaN or infinite.
 *   kQ3ErrorParameterOutOfRange  t is outside the domain.
 *   kQ3ErrorVector3DZeroLength   C'(t) is zero (below 1e-12 of the size of the
 *                                span's control points per unit of t, where
 *                                rounding hides its direction), e.g. where two
 *                                control points coincide.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_GetTangent(const TQ3NURBCurveData *curveData, float t,
                                                      TQ3Vector3D *tangent);

/**
 * Q3 extension. As Q3NURBCurveData_GetTangent, for a retained curve.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve or tangent is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   kQ3ErrorInvalidParameter     t is NaN or infinite.
 *   kQ3ErrorParameterOutOfRange  t is outside the domain.
 *   kQ3ErrorVector3DZeroLength   C'(t) is zero.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_GetTangent(TQ3GeometryObject curve, float t, TQ3Vector3D *tangent);

/**
 * Q3 extension. The curvature |C' x C''| / |C'|^3 of a curve at t: the
 * reciprocal of the radius of the circle that fits the curve best there (1/r
 * on a circular arc of radius r, 0 on a straight piece).
 *
 * @param curveData  the curve.
 * @param t          a parameter in the closed domain.
 * @param curvature  receives the curvature, 0 or more.
 * @return kQ3Success, or kQ3Failure with *curvature unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData or curvature is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h), then:
 *   kQ3ErrorInvalidParameter     t is NaN or infinite.
 *   kQ3ErrorParameterOutOfRange  t is outside the domain.
 *   kQ3ErrorVector3DZeroLength   C'(t) is zero (as for Q3NURBCurveData_GetTangent).
 *   kQ3ErrorDegenerateGeometry   the curvature is too large for a float.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_GetCurvature(const TQ3NURBCurveData *curveData, float t,
                                                        float *curvature);

/**
 * Q3 extension. As Q3NURBCurveData_GetCurvature, for a retained curve.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve or curvature is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   kQ3ErrorInvalidParameter     t is NaN or infinite.
 *   kQ3ErrorParameterOutOfRange  t is outside the domain.
 *   kQ3ErrorVector3DZeroLength   C'(t) is zero.
 *   kQ3ErrorDegenerateGeometry   the curvature is too large for a float.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_GetCurvature(TQ3GeometryObject curve, float t, float *curvature);

/* ---- Knots --------------------------------------------------------------- */

/**
 * Q3 extension. Inserts a knot `times` times (the article's Listing 2,
 * repeated): the same curve, with `times` more knots and control points.
 * Inserting a knot order - 1 times puts a control point on the curve there.
 *
 * @param curveData  the curve.
 * @param knot       the value to insert, strictly inside the domain; it may
 *                   already be a knot.
 * @param times      how many copies to insert; 0 returns a copy of the curve.
 *                   The knot may not end up occurring more than order - 1
 *                   times.
 * @param result     receives the new curve.
 * @return kQ3Success, or kQ3Failure with *result unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData or result is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h), then:
 *   kQ3ErrorInvalidParameter     knot is NaN or infinite.
 *   kQ3ErrorParameterOutOfRange  knot is not strictly inside the domain;
 *                                times would make it occur more than
 *                                order - 1 times; or the result would have
 *                                more than kQ3NURBCurveToolsMaxPoints points.
 *   kQ3ErrorOutOfMemory          the result cannot be allocated.
 *
 * Ownership: the caller owns the arrays of *result and frees them with
 * Q3NURBCurve_EmptyData; result->curveAttributeSet is NULL.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_InsertKnot(const TQ3NURBCurveData *curveData, float knot,
                                                      unsigned long times, TQ3NURBCurveData *result);

/**
 * Q3 extension. As Q3NURBCurveData_InsertKnot, for a retained curve, which is
 * not changed (pass the result to Q3NURBCurve_SetData to change it).
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve or result is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   then the conditions of Q3NURBCurveData_InsertKnot.
 *
 * Ownership: as Q3NURBCurveData_InsertKnot.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_InsertKnot(TQ3GeometryObject curve, float knot, unsigned long times,
                                                  TQ3NURBCurveData *result);

/**
 * Q3 extension. Inserts many knots at once (knot refinement), in time
 * proportional to the size of the result: the same curve with numKnots more
 * knots and control points.
 *
 * @param curveData  the curve.
 * @param numKnots   how many knots to insert; 0 returns a copy of the curve.
 * @param knots      numKnots values, in any order, each strictly inside the
 *                   domain; a value may repeat and may already be a knot,
 *                   but no value may end up occurring more than order - 1
 *                   times. May be NULL when numKnots is 0.
 * @param result     receives the new curve.
 * @return kQ3Success, or kQ3Failure with *result unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData or result is NULL, or knots is
 *                                NULL while numKnots is not 0.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h), then:
 *   kQ3ErrorParameterOutOfRange  numPoints + numKnots is more than
 *                                kQ3NURBCurveToolsMaxPoints (checked before
 *                                knots is read).
 *   kQ3ErrorInvalidParameter     a knot is NaN or infinite, or
 *   kQ3ErrorParameterOutOfRange  a knot is not strictly inside the domain
 *                                (the first such knot decides);
 *   kQ3ErrorInvalidParameter     a value would occur more than order - 1
 *                                times.
 *   kQ3ErrorOutOfMemory          the result cannot be allocated.
 *
 * Ownership: the caller owns the arrays of *result and frees them with
 * Q3NURBCurve_EmptyData; result->curveAttributeSet is NULL.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_RefineKnots(const TQ3NURBCurveData *curveData,
                                                       unsigned long numKnots, const float *knots,
                                                       TQ3NURBCurveData *result);

/**
 * Q3 extension. As Q3NURBCurveData_RefineKnots, for a retained curve, which
 * is not changed.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve or result is NULL, or knots is NULL
 *                                while numKnots is not 0.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   then the conditions of Q3NURBCurveData_RefineKnots.
 *
 * Ownership: as Q3NURBCurveData_RefineKnots.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_RefineKnots(TQ3GeometryObject curve, unsigned long numKnots,
                                                   const float *knots, TQ3NURBCurveData *result);

/**
 * Q3 extension. Removes an interior knot up to `times` times, as often as
 * the curve allows without moving by more than `tolerance` anywhere: the
 * largest count that keeps the float result within tolerance of the curve,
 * proven by a bound, not by sampling. A knot that was inserted (and not
 * moved since) comes out again exactly. The control points next to the knot
 * are chosen to fit the curve best (least squares); the others stay.
 *
 * @param curveData   the curve.
 * @param knotIndex   which knot, 0 to numPoints + order - 1; its value must
 *                    lie strictly inside the domain. Any index of a run of
 *                    equal knots names the run.
 * @param times       the most copies to remove, at most the knot's
 *                    multiplicity; 0 returns a copy of the curve.
 * @param tolerance   the largest distance the curve may move, in its own
 *                    units; finite and greater than 0.
 * @param result      receives the new curve (a copy of the curve when nothing
 *                    could be removed).
 * @param numRemoved  receives how many copies were removed, 0 to times.
 * @return kQ3Success (also when nothing could be removed), or kQ3Failure with
 *         *result and *numRemoved unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData, result or numRemoved is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h), then:
 *   kQ3ErrorParameterOutOfRange  knotIndex >= numPoints + order, or the knot
 *                                is not strictly inside the domain, or times
 *                                is more than its multiplicity.
 *   kQ3ErrorInvalidParameter     tolerance is NaN, infinite, 0 or negative.
 *   kQ3ErrorOutOfMemory          the result cannot be allocated.
 *
 * Ownership: the caller owns the arrays of *result and frees them with
 * Q3NURBCurve_EmptyData; result->curveAttributeSet is NULL.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_RemoveKnot(const TQ3NURBCurveData *curveData,
                                                      unsigned long knotIndex, unsigned long times,
                                                      float tolerance, TQ3NURBCurveData *result,
                                                      unsigned long *numRemoved);

/**
 * Q3 extension. As Q3NURBCurveData_RemoveKnot, for a retained curve, which is
 * not changed.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve, result or numRemoved is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   then the conditions of Q3NURBCurveData_RemoveKnot.
 *
 * Ownership: as Q3NURBCurveData_RemoveKnot.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_RemoveKnot(TQ3GeometryObject curve, unsigned long knotIndex,
                                                  unsigned long times, float tolerance,
                                                  TQ3NURBCurveData *result, unsigned long *numRemoved);

/* ---- Degree, pieces and splitting --------------------------------------- */

/**
 * Q3 extension. Raises a curve's order by `times` without changing its shape
 * or its smoothness: every interior knot of multiplicity m comes out with
 * multiplicity m + times. The result is clamped: its knots start and end
 * with order + times copies of the domain's ends (an unclamped curve loses
 * the part outside its domain, which is never drawn).
 *
 * @param curveData  the curve.
 * @param times      how much to raise the order; order + times may be at most
 *                   kQ3NURBCurveMaxOrder. 0 returns the curve clamped:
 *                   a copy if it is clamped already.
 * @param result     receives the new curve.
 * @return kQ3Success, or kQ3Failure with *result unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData or result is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h), then:
 *   kQ3ErrorParameterOutOfRange  order + times exceeds kQ3NURBCurveMaxOrder,
 *                                or the result would have more than
 *                                kQ3NURBCurveToolsMaxPoints points.
 *   kQ3ErrorDegenerateGeometry   the result cannot be held in float.
 *   kQ3ErrorOutOfMemory          the result cannot be allocated.
 *
 * Ownership: the caller owns the arrays of *result and frees them with
 * Q3NURBCurve_EmptyData; result->curveAttributeSet is NULL.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_ElevateDegree(const TQ3NURBCurveData *curveData,
                                                         unsigned long times, TQ3NURBCurveData *result);

/**
 * Q3 extension. As Q3NURBCurveData_ElevateDegree, for a retained curve, which
 * is not changed.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve or result is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   then the conditions of Q3NURBCurveData_ElevateDegree.
 *
 * Ownership: as Q3NURBCurveData_ElevateDegree.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_ElevateDegree(TQ3GeometryObject curve, unsigned long times,
                                                     TQ3NURBCurveData *result);

/**
 * Q3 extension. The number of Bezier pieces of a curve: its non-empty knot
 * spans inside the domain (the article's "CONVERTING NURB TO BEZIER CURVES").
 *
 * @param curveData  the curve.
 * @param numPieces  receives the count, at least 1.
 * @return kQ3Success, or kQ3Failure with *numPieces unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   curveData or numPieces is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h).
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_CountBezierPieces(const TQ3NURBCurveData *curveData,
                                                             unsigned long *numPieces);

/**
 * Q3 extension. As Q3NURBCurveData_CountBezierPieces, for a retained curve.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      curve or numPieces is NULL.
 *   kQ3ErrorInvalidObject      curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  curve is not a NURB curve.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_CountBezierPieces(TQ3GeometryObject curve, unsigned long *numPieces);

/**
 * Q3 extension. One Bezier piece of a curve: the curve on its pieceIndex-th
 * non-empty knot span [a, b], as a rational Bezier curve of the same order
 * (order control points, knots a repeated order times then b repeated order
 * times, so the parameters are the curve's own). Together the pieces are the
 * whole curve.
 *
 * @param curveData   the curve.
 * @param pieceIndex  which piece, 0 to numPieces - 1 (see
 *                    Q3NURBCurveData_CountBezierPieces), in increasing t.
 * @param piece       receives the piece.
 * @return kQ3Success, or kQ3Failure with *piece unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData or piece is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h), then:
 *   kQ3ErrorParameterOutOfRange  pieceIndex >= numPieces.
 *   kQ3ErrorDegenerateGeometry   the piece cannot be held in float.
 *   kQ3ErrorOutOfMemory          the piece cannot be allocated.
 *
 * Ownership: the caller owns the arrays of *piece and frees them with
 * Q3NURBCurve_EmptyData; piece->curveAttributeSet is NULL.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_GetBezierPiece(const TQ3NURBCurveData *curveData,
                                                          unsigned long pieceIndex, TQ3NURBCurveData *piece);

/**
 * Q3 extension. As Q3NURBCurveData_GetBezierPiece, for a retained curve.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve or piece is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   then the conditions of Q3NURBCurveData_GetBezierPiece.
 *
 * Ownership: as Q3NURBCurveData_GetBezierPiece.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_GetBezierPiece(TQ3GeometryObject curve, unsigned long pieceIndex,
                                                      TQ3NURBCurveData *piece);

/**
 * Q3 extension. Cuts a curve in two at parameter t: left is the curve on
 * [start, t], right on [t, end], both with the original parameters, both
 * ending (left) or starting (right) with order copies of t. They meet at the
 * curve's point at t.
 *
 * @param curveData  the curve.
 * @param t          where to cut, strictly inside the domain.
 * @param left       receives the part before t.
 * @param right      receives the part after t.
 * @return kQ3Success, or kQ3Failure with *left and *right unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData, left or right is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h), then:
 *   kQ3ErrorInvalidParameter     t is NaN or infinite, or left and right are
 *                                the same structure.
 *   kQ3ErrorParameterOutOfRange  t is not strictly inside the domain.
 *   kQ3ErrorOutOfMemory          the halves cannot be allocated.
 *
 * Ownership: the caller owns the arrays of *left and *right and frees each
 * with Q3NURBCurve_EmptyData; their curveAttributeSet is NULL.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_Split(const TQ3NURBCurveData *curveData, float t,
                                                 TQ3NURBCurveData *left, TQ3NURBCurveData *right);

/**
 * Q3 extension. As Q3NURBCurveData_Split, for a retained curve, which is not
 * changed.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve, left or right is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   then the conditions of Q3NURBCurveData_Split.
 *
 * Ownership: as Q3NURBCurveData_Split.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_Split(TQ3GeometryObject curve, float t, TQ3NURBCurveData *left,
                                             TQ3NURBCurveData *right);

/* ---- Length and distance ------------------------------------------------- */

/**
 * Q3 extension. The length of a curve between two parameters, by adaptive
 * Gauss-Legendre quadrature of |C'(t)| over each knot span, to within
 * `tolerance` by the quadrature's own error estimate.
 *
 * @param curveData  the curve.
 * @param t0         where to start, in the closed domain.
 * @param t1         where to stop, in the closed domain, t1 >= t0.
 * @param tolerance  the largest error wanted, in the curve's units; finite and
 *                   greater than 0.
 * @param length     receives the length.
 * @return kQ3Success, or kQ3Failure with *length unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData or length is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h), then:
 *   kQ3ErrorInvalidParameter     t0 or t1 is NaN or infinite.
 *   kQ3ErrorParameterOutOfRange  t0 or t1 is outside the domain.
 *   kQ3ErrorInvalidParameter     tolerance is NaN, infinite, 0 or negative,
 *                                or t0 > t1.
 *   kQ3ErrorDegenerateGeometry   the length is too large for a float.
 * Warnings:
 *   kQ3WarningParameterOutOfRange  the tolerance was not reached within
 *                                kQ3NURBCurveToolsMaxBisections bisections;
 *                                *length is the best value found and the
 *                                message gives its estimated error.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_GetArcLength(const TQ3NURBCurveData *curveData, float t0,
                                                        float t1, float tolerance, float *length);

/**
 * Q3 extension. As Q3NURBCurveData_GetArcLength, for a retained curve.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve or length is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   then the conditions and warnings of Q3NURBCurveData_GetArcLength.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_GetArcLength(TQ3GeometryObject curve, float t0, float t1,
                                                    float tolerance, float *length);

/**
 * Q3 extension. The parameter t at which the curve's length from t0 reaches
 * `length`: the inverse of Q3NURBCurveData_GetArcLength, found by Newton's
 * method inside a bisection bracket. The length from t0 to the returned t is
 * within tolerance of `length`, plus what rounding t to a float moves it (at
 * most the speed |C'| times half a float step of t).
 *
 * @param curveData  the curve.
 * @param t0         where the length is measured from, in the closed domain.
 * @param length     the length wanted, from 0 to the length from t0 to the
 *                   end of the domain (a length longer by at most tolerance
 *                   gives the domain's end).
 * @param tolerance  the largest error wanted, in the curve's units; finite and
 *                   greater than 0.
 * @param t          receives the parameter, t0 <= *t <= end.
 * @return kQ3Success, or kQ3Failure with *t unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData or t is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h), then:
 *   kQ3ErrorInvalidParameter     t0 is NaN or infinite.
 *   kQ3ErrorParameterOutOfRange  t0 is outside the domain.
 *   kQ3ErrorInvalidParameter     tolerance is NaN, infinite, 0 or negative,
 *                                or length is NaN or infinite.
 *   kQ3ErrorParameterOutOfRange  length is negative, or longer than the rest
 *                                of the curve by more than tolerance.
 * Warnings:
 *   kQ3WarningParameterOutOfRange  the tolerance was not reached within
 *                                kQ3NURBCurveToolsMaxBisections bisections or
 *                                100 Newton steps; *t is the best found.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_GetParameterAtLength(const TQ3NURBCurveData *curveData,
                                                                float t0, float length, float tolerance,
                                                                float *t);

/**
 * Q3 extension. As Q3NURBCurveData_GetParameterAtLength, for a retained curve.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve or t is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   then the conditions and warnings of Q3NURBCurveData_GetParameterAtLength.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_GetParameterAtLength(TQ3GeometryObject curve, float t0, float length,
                                                            float tolerance, float *t);

/**
 * Q3 extension. The point of a curve nearest to a given point, and its
 * parameter. Every non-empty knot span is searched as a Bezier piece by
 * branch and bound (a piece lies within its control points' convex hull), with
 * a safeguarded Newton iteration in each piece that may hold a nearer point;
 * the span ends, corners included, are candidates too. Guarantee: in double
 * precision the parameter found is at a distance from the point that exceeds
 * the curve's least distance by at most 1e-9 times the diagonal of the
 * bounding box of the control points (x/w, y/w, z/w). The one exception is a
 * point so near a centre of curvature that thousands of pieces of the curve
 * are that nearly equally near (the centre of a circular arc): the search then
 * stops splitting after 4096 splits and returns the nearest point found by
 * then. *t is that parameter rounded to float and *closest the
 * curve's point at *t, so they add what rounding t moves the point (at most
 * |C'| times half a float step of t).
 *
 * @param curveData  the curve.
 * @param point      the point to approach; its coordinates must be finite.
 * @param t          receives the parameter of the nearest point.
 * @param closest    receives the curve's point at *t.
 * @return kQ3Success, or kQ3Failure with *t and *closest unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     curveData, point, t or closest is NULL.
 *   then the codes of the TQ3NURBCurveData rules (QD3DGeometry.h), then:
 *   kQ3ErrorInvalidParameter  a coordinate of *point is NaN or infinite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_GetClosestPoint(const TQ3NURBCurveData *curveData,
                                                           const TQ3Point3D *point, float *t,
                                                           TQ3Point3D *closest);

/**
 * Q3 extension. As Q3NURBCurveData_GetClosestPoint, for a retained curve.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      curve, point, t or closest is NULL.
 *   kQ3ErrorInvalidObject      curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  curve is not a NURB curve.
 *   kQ3ErrorInvalidParameter   a coordinate of *point is NaN or infinite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_GetClosestPoint(TQ3GeometryObject curve, const TQ3Point3D *point,
                                                       float *t, TQ3Point3D *closest);

/* ---- Fitting ------------------------------------------------------------- */

/**
 * Q3 extension. A non-rational curve of the given order through every point,
 * in order (the B-spline lecture's interpolation, section 6.5, for any
 * order). The curve is clamped on [0, 1] and has as many control points as
 * there are points; it passes through point i at the parameter the
 * parameterization gives it, the first and last points at 0 and 1. For
 * cubics the interior knots are the parameters of points 2 to numPoints - 3
 * (counting from 0), the lecture's choice; docs/curve-tools.md gives the rule
 * for every order.
 *
 * @param order             2 to kQ3NURBCurveMaxOrder.
 * @param numPoints         at least order, at most kQ3NURBCurveToolsMaxPoints.
 * @param points            numPoints points with finite coordinates, no two
 *                          consecutive ones equal.
 * @param parameterization  kQ3NURBCurveParameterizationChordLength or
 *                          kQ3NURBCurveParameterizationCentripetal.
 * @param result            receives the curve.
 * @return kQ3Success, or kQ3Failure with *result unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        points or result is NULL.
 *   kQ3ErrorParameterOutOfRange  order is outside 2 to kQ3NURBCurveMaxOrder.
 *   kQ3ErrorGeometryInsufficientNumberOfPoints  numPoints < order.
 *   kQ3ErrorParameterOutOfRange  numPoints is more than
 *                                kQ3NURBCurveToolsMaxPoints (checked before
 *                                points is read).
 *   kQ3ErrorInvalidParameter     parameterization is not one of the two, a
 *                                coordinate is NaN or infinite, or two
 *                                consecutive points are equal.
 *   kQ3ErrorDegenerateGeometry   points so unevenly spaced that their
 *                                parameters or the float knots coincide.
 *   kQ3ErrorOutOfMemory          the curve cannot be allocated.
 *
 * Ownership: the caller owns the arrays of *result and frees them with
 * Q3NURBCurve_EmptyData; result->curveAttributeSet is NULL.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_Interpolate(unsigned long order, unsigned long numPoints,
                                                       const TQ3Point3D *points,
                                                       TQ3NURBCurveParameterization parameterization,
                                                       TQ3NURBCurveData *result);

/**
 * Q3 extension. A non-rational curve of the given order with
 * numControlPoints control points that passes through the first and last
 * points and comes as close to the others as it can: the sum of squared
 * distances between each point and the curve at that point's parameter is
 * least. Parameters as Q3NURBCurveData_Interpolate; the interior knots spread
 * over them evenly, and with numControlPoints == numPoints the result is
 * exactly Q3NURBCurveData_Interpolate's.
 *
 * @param order             2 to kQ3NURBCurveMaxOrder.
 * @param numPoints         at least order, at most kQ3NURBCurveToolsMaxPoints.
 * @param points            numPoints points with finite coordinates, no two
 *                          consecutive ones equal.
 * @param numControlPoints  order to numPoints.
 * @param parameterization  kQ3NURBCurveParameterizationChordLength or
 *                          kQ3NURBCurveParameterizationCentripetal.
 * @param result            receives the curve.
 * @return kQ3Success, or kQ3Failure with *result unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        points or result is NULL.
 *   kQ3ErrorParameterOutOfRange  order is outside 2 to kQ3NURBCurveMaxOrder.
 *   kQ3ErrorGeometryInsufficientNumberOfPoints  numPoints < order.
 *   kQ3ErrorParameterOutOfRange  numPoints is more than
 *                                kQ3NURBCurveToolsMaxPoints (checked before
 *                                points is read), or numControlPoints is
 *                                outside order to numPoints.
 *   kQ3ErrorInvalidParameter     parameterization is not one of the two, a
 *                                coordinate is NaN or infinite, or two
 *                                consecutive points are equal.
 *   kQ3ErrorDegenerateGeometry   points so unevenly spaced that their
 *                                parameters or the float knots coincide.
 *   kQ3ErrorOutOfMemory          the curve cannot be allocated.
 *
 * Ownership: the caller owns the arrays of *result and frees them with
 * Q3NURBCurve_EmptyData; result->curveAttributeSet is NULL.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurveData_Approximate(unsigned long order, unsigned long numPoints,
                                                       const TQ3Point3D *points,
                                                       unsigned long numControlPoints,
                                                       TQ3NURBCurveParameterization parameterization,
                                                       TQ3NURBCurveData *result);

#ifdef __cplusplus
}
#endif

#endif /* Q3NURBCURVETOOLS_H */
