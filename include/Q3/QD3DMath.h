/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Point, vector, matrix, quaternion and bounding-volume arithmetic: every
 * function and macro of QuickDraw 3D 1.6's QD3DMath.h, with its names and
 * signatures.
 *
 * Matrices act on row vectors, as in QuickDraw 3D: a point p is transformed
 * as p * M, so the translation sits in value[3][0..2] (value[2][0..1] for a
 * 3x3 matrix acting on 2-D points), and transforming by A * B means
 * transforming by A first, then by B. Angles are in radians; rotations turn
 * counterclockwise as seen from the positive end of their axis.
 *
 * Every function that returns a pointer returns its result argument on
 * success and NULL on failure; every function that returns a float returns 0
 * on failure, Q3Quaternion_IsIdentity kQ3False and the array functions
 * kQ3Failure. The result may point to the same storage as an input (for
 * example Q3Matrix4x4_Multiply(&m, &n, &m)): every result is computed in
 * full before it is stored. Values are not checked for
 * being finite: NaNs and infinities go through the IEEE arithmetic.
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error and leaves its result unchanged. Like every
 * Q3 call outside the error manager, these fail with kQ3ErrorNotInitialized
 * before Q3Initialize; after that, the pointer arguments are checked for
 * NULL from left to right, then the function's other conditions.
 *
 * The rules the functions below share:
 *
 *   - Homogeneous coordinates. Whenever a result is divided by its last
 *     coordinate (w, or z for a 2-D point as (x, y, z)), a last coordinate
 *     of exactly 0 (a point at infinity) leaves the others undivided, the
 *     rule Q3Point3D_Transform has always had. No error is posted.
 *   - Domain errors, the only failures besides NULL pointers and arrays: a
 *     vector of length 0 where a direction is needed
 *     (kQ3ErrorVector3DZeroLength, for 2-D vectors too: QuickDraw 3D has no
 *     other code), a singular matrix to invert
 *     (kQ3ErrorNonInvertibleMatrix), ratios or weights that sum to 0 and
 *     the quaternion (0, 0, 0, 0) where a rotation is needed
 *     (kQ3ErrorInvalidParameter), no points to combine
 *     (kQ3ErrorParameterOutOfRange). Each is an exact test; NaN passes it
 *     and gives NaN results.
 *   - Arrays with a count and a stride (the *TransformArray and
 *     *_SetFromPoints / *_SetFromRationalPoints4D functions; a stride is
 *     the distance in bytes from one element to the next, so that the
 *     points may sit inside larger structures). In order: an array may be
 *     NULL only when the count is 0 (kQ3ErrorNULLParameter); a negative
 *     count, a stride smaller than the element (sizeof(TQ3Point3D) for
 *     example), or a count of elements no array could hold (more bytes than
 *     an object may have, PTRDIFF_MAX, or than the address space holds
 *     after the array's start) is kQ3ErrorParameterOutOfRange, checked
 *     before anything is read. Elements need not be aligned. Q3 cannot see
 *     an array shorter than its count: that is the caller's to get right.
 *     The output array may be the input array with the same stride.
 */
#ifndef QD3DMATH_H
#define QD3DMATH_H

#include <float.h>

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Constants ---------------------------------------------------------- */

/* The smallest float e with 1 + e != 1, and the largest finite float. */
#define kQ3RealZero (FLT_EPSILON)
#define kQ3MaxFloat (FLT_MAX)

#define kQ3Pi ((float)3.1415926535898)
#define kQ32Pi ((float)(2.0 * 3.1415926535898))
#define kQ3PiOver2 ((float)(3.1415926535898 / 2.0))
#define kQ33PiOver2 ((float)(3.0 * 3.1415926535898 / 2.0))

/* Angle conversion and min/max. Like QuickDraw 3D's, these are macros: the
 * Min/Max arguments are evaluated twice. */
#define Q3Math_DegreesToRadians(x) ((float)((x) * kQ3Pi / 180.0f))
#define Q3Math_RadiansToDegrees(x) ((float)((x) * 180.0f / kQ3Pi))
#define Q3Math_Min(x, y) ((x) <= (y) ? (x) : (y))
#define Q3Math_Max(x, y) ((x) >= (y) ? (x) : (y))

/* ---- Setting points and vectors ----------------------------------------- */

/**
 * Sets the coordinates of a 2D point, a parametric (u, v) point or a 2D
 * vector.
 *
 * @param point2D   (Q3Point2D_Set) the point to set.
 * @param param2D   (Q3Param2D_Set) the parametric point to set.
 * @param vector2D  (Q3Vector2D_Set) the vector to set.
 * @param x, u      the new first coordinate.
 * @param y, v      the new second coordinate.
 * @return the structure set, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   the structure to set is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Point2D *) Q3Point2D_Set(TQ3Point2D *point2D, float x, float y);
Q3_EXTERN_API_C(TQ3Param2D *) Q3Param2D_Set(TQ3Param2D *param2D, float u, float v);
Q3_EXTERN_API_C(TQ3Vector2D *) Q3Vector2D_Set(TQ3Vector2D *vector2D, float x, float y);

/**
 * Sets the coordinates of a 3D point.
 *
 * @param point3D  the point to set.
 * @param x        the new x coordinate.
 * @param y        the new y coordinate.
 * @param z        the new z coordinate.
 * @return point3D, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   point3D is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Point3D *) Q3Point3D_Set(TQ3Point3D *point3D, float x, float y, float z);

/**
 * Sets the components of a 3D vector.
 *
 * @param vector3D  the vector to set.
 * @param x         the new x component.
 * @param y         the new y component.
 * @param z         the new z component.
 * @return vector3D, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   vector3D is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Vector3D *) Q3Vector3D_Set(TQ3Vector3D *vector3D, float x, float y, float z);

/**
 * Sets the coordinates of a 2D homogeneous point (position x/w, y/w; w is
 * the weight of a NURB trim curve's control point).
 *
 * @param point3D  the point to set.
 * @param x        the new x coordinate.
 * @param y        the new y coordinate.
 * @param w        the new w coordinate (weight).
 * @return point3D, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   point3D is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3RationalPoint3D *) Q3RationalPoint3D_Set(TQ3RationalPoint3D *point3D, float x, float y,
                                                            float w);

/**
 * Sets the coordinates of a homogeneous point (position x/w, y/w, z/w;
 * w is the weight of a NURB control point).
 *
 * @param point4D  the point to set.
 * @param x        the new x coordinate.
 * @param y        the new y coordinate.
 * @param z        the new z coordinate.
 * @param w        the new w coordinate (weight).
 * @return point4D, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   point4D is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3RationalPoint4D *) Q3RationalPoint4D_Set(TQ3RationalPoint4D *point4D,
                                                            float x, float y, float z, float w);

/*
 * Article-compatibility alias: TQ3RationalPoint4D_Set is another name for
 * Q3RationalPoint4D_Set. The develop article's Listing 3 calls
 * TQ3RationalPoint4D_Set(&p, x, y, z, 1.0), a name QuickDraw 3D never had.
 * Defining Q3_NO_ARTICLE_ALIASES before including any Q3 header turns this
 * alias (and nurbCurveAttributes in QD3DGeometry.h) off.
 */
#ifndef Q3_NO_ARTICLE_ALIASES
#define TQ3RationalPoint4D_Set Q3RationalPoint4D_Set
#endif

/**
 * Sets the coordinates of a polar point (distance r from the origin, angle
 * theta counterclockwise from +x) or a spherical point (distance rho from
 * the origin, angle theta of its projection onto the xy plane
 * counterclockwise from +x, angle phi from +z). Any values are stored.
 *
 * @param polarPoint      (Q3PolarPoint_Set) the point to set.
 * @param sphericalPoint  (Q3SphericalPoint_Set) the point to set.
 * @param r, rho          the new distance.
 * @param theta           the new angle from +x, in radians.
 * @param phi             the new angle from +z, in radians.
 * @return the point set, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   the point to set is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3PolarPoint *) Q3PolarPoint_Set(TQ3PolarPoint *polarPoint, float r, float theta);
Q3_EXTERN_API_C(TQ3SphericalPoint *) Q3SphericalPoint_Set(TQ3SphericalPoint *sphericalPoint, float rho,
                                                          float theta, float phi);

/* ---- Converting dimensions ---------------------------------------------- */

/**
 * Converts between dimensions as QuickDraw 3D defines it: going up appends
 * a last coordinate of 1; going down divides the others by the last
 * coordinate and drops it (undivided when it is 0).
 *
 *   Q3Point2D_To3D          (x, y)       -> (x, y, 1), in a TQ3Point3D as
 *                                            Apple declares it
 *   Q3RationalPoint3D_To2D  (x, y, w)    -> (x/w, y/w)
 *   Q3Point3D_To4D          (x, y, z)    -> (x, y, z, 1)
 *   Q3RationalPoint4D_To3D  (x, y, z, w) -> (x/w, y/w, z/w)
 *   Q3Vector2D_To3D         (x, y)       -> (x, y, 1)
 *   Q3Vector3D_To2D         (x, y, z)    -> (x/z, y/z)
 *
 * @param point2D, point3D, point4D, vector2D, vector3D  the value to convert.
 * @param result  receives the converted value.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   the input or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Point3D *) Q3Point2D_To3D(const TQ3Point2D *point2D, TQ3Point3D *result);
Q3_EXTERN_API_C(TQ3Point2D *) Q3RationalPoint3D_To2D(const TQ3RationalPoint3D *point3D, TQ3Point2D *result);
Q3_EXTERN_API_C(TQ3RationalPoint4D *) Q3Point3D_To4D(const TQ3Point3D *point3D, TQ3RationalPoint4D *result);
Q3_EXTERN_API_C(TQ3Point3D *) Q3RationalPoint4D_To3D(const TQ3RationalPoint4D *point4D, TQ3Point3D *result);
Q3_EXTERN_API_C(TQ3Vector3D *) Q3Vector2D_To3D(const TQ3Vector2D *vector2D, TQ3Vector3D *result);
Q3_EXTERN_API_C(TQ3Vector2D *) Q3Vector3D_To2D(const TQ3Vector3D *vector3D, TQ3Vector2D *result);

/* ---- Subtracting points ------------------------------------------------- */

/**
 * Subtracts one point from another: result = p1 - p2, the vector from p2
 * to p1 ((u, v) parametric points give the vector (du, dv)).
 *
 * @param p1      the point subtracted from.
 * @param p2      the point subtracted.
 * @param result  receives the vector.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   p1, p2 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Vector2D *) Q3Point2D_Subtract(const TQ3Point2D *p1, const TQ3Point2D *p2,
                                                  TQ3Vector2D *result);
Q3_EXTERN_API_C(TQ3Vector2D *) Q3Param2D_Subtract(const TQ3Param2D *p1, const TQ3Param2D *p2,
                                                  TQ3Vector2D *result);
Q3_EXTERN_API_C(TQ3Vector3D *) Q3Point3D_Subtract(const TQ3Point3D *p1, const TQ3Point3D *p2,
                                                  TQ3Vector3D *result);

/* ---- Distances between points ------------------------------------------- */

/**
 * Computes the distance between two points, or its square (which needs no
 * square root). Rational points are measured between the points they
 * stand for: (x/w, y/w) and (x/w, y/w, z/w), undivided when w is 0.
 *
 * @param p1  one point.
 * @param p2  the other point.
 * @return the Euclidean distance or its square, or 0 on failure. It is
 *         computed in double precision and rounded once, so a distance
 *         does not overflow for finite coordinates; a squared distance
 *         beyond FLT_MAX is infinity.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   p1 or p2 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(float) Q3Point2D_Distance(const TQ3Point2D *p1, const TQ3Point2D *p2);
Q3_EXTERN_API_C(float) Q3Point2D_DistanceSquared(const TQ3Point2D *p1, const TQ3Point2D *p2);
Q3_EXTERN_API_C(float) Q3Param2D_Distance(const TQ3Param2D *p1, const TQ3Param2D *p2);
Q3_EXTERN_API_C(float) Q3Param2D_DistanceSquared(const TQ3Param2D *p1, const TQ3Param2D *p2);
Q3_EXTERN_API_C(float) Q3RationalPoint3D_Distance(const TQ3RationalPoint3D *p1, const TQ3RationalPoint3D *p2);
Q3_EXTERN_API_C(float) Q3RationalPoint3D_DistanceSquared(const TQ3RationalPoint3D *p1,
                                                         const TQ3RationalPoint3D *p2);
Q3_EXTERN_API_C(float) Q3Point3D_DistanceSquared(const TQ3Point3D *p1, const TQ3Point3D *p2);
Q3_EXTERN_API_C(float) Q3RationalPoint4D_Distance(const TQ3RationalPoint4D *p1, const TQ3RationalPoint4D *p2);
Q3_EXTERN_API_C(float) Q3RationalPoint4D_DistanceSquared(const TQ3RationalPoint4D *p1,
                                                         const TQ3RationalPoint4D *p2);

/**
 * Computes the distance between two points.
 *
 * @param p1  one point.
 * @param p2  the other point.
 * @return the Euclidean distance, or 0 on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   p1 or p2 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(float) Q3Point3D_Distance(const TQ3Point3D *p1, const TQ3Point3D *p2);

/* ---- Relative ratios ---------------------------------------------------- */

/**
 * Finds the point on the line through p1 and p2 at a given ratio:
 * result = p1 + (p2 - p1) * r2 / (r1 + r2), coordinate by coordinate (w
 * included for the rational point, which is interpolated in homogeneous
 * coordinates). So r1 = 1, r2 = 3 gives the point three quarters of the
 * way from p1 to p2. Apple's book says r1 / (r1 + r2); the QuickDraw 3D 1.6
 * library measured r2 / (r1 + r2) (Quesa found so by experiment and does the
 * same), and legacy code was written against the library, so Q3 does as the
 * library did. Ratios outside [0, 1] extrapolate.
 *
 * @param p1      the first point.
 * @param p2      the second point.
 * @param r1, r2  the ratio's terms.
 * @param result  receives the point; it may be p1 or p2.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     p1, p2 or result is NULL.
 *   kQ3ErrorInvalidParameter  r1 + r2 is 0.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Point2D *) Q3Point2D_RRatio(const TQ3Point2D *p1, const TQ3Point2D *p2, float r1, float r2,
                                               TQ3Point2D *result);
Q3_EXTERN_API_C(TQ3Param2D *) Q3Param2D_RRatio(const TQ3Param2D *p1, const TQ3Param2D *p2, float r1, float r2,
                                               TQ3Param2D *result);
Q3_EXTERN_API_C(TQ3Point3D *) Q3Point3D_RRatio(const TQ3Point3D *p1, const TQ3Point3D *p2, float r1, float r2,
                                               TQ3Point3D *result);
Q3_EXTERN_API_C(TQ3RationalPoint4D *) Q3RationalPoint4D_RRatio(const TQ3RationalPoint4D *p1,
                                                               const TQ3RationalPoint4D *p2, float r1, float r2,
                                                               TQ3RationalPoint4D *result);

/* ---- Adding vectors to points ------------------------------------------- */

/**
 * Moves a point by a vector: result = point + vector (_Add) or
 * point - vector (_Subtract); a parametric point's (u, v) moves by the
 * vector's (x, y).
 *
 * @param point2D, param2D, point3D  the point.
 * @param vector2D, vector3D         the vector.
 * @param result  receives the moved point; it may be the point.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   the point, the vector or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Point2D *) Q3Point2D_Vector2D_Add(const TQ3Point2D *point2D, const TQ3Vector2D *vector2D,
                                                     TQ3Point2D *result);
Q3_EXTERN_API_C(TQ3Param2D *) Q3Param2D_Vector2D_Add(const TQ3Param2D *param2D, const TQ3Vector2D *vector2D,
                                                     TQ3Param2D *result);
Q3_EXTERN_API_C(TQ3Point3D *) Q3Point3D_Vector3D_Add(const TQ3Point3D *point3D, const TQ3Vector3D *vector3D,
                                                     TQ3Point3D *result);
Q3_EXTERN_API_C(TQ3Point2D *) Q3Point2D_Vector2D_Subtract(const TQ3Point2D *point2D,
                                                          const TQ3Vector2D *vector2D, TQ3Point2D *result);
Q3_EXTERN_API_C(TQ3Param2D *) Q3Param2D_Vector2D_Subtract(const TQ3Param2D *param2D,
                                                          const TQ3Vector2D *vector2D, TQ3Param2D *result);
Q3_EXTERN_API_C(TQ3Point3D *) Q3Point3D_Vector3D_Subtract(const TQ3Point3D *point3D,
                                                          const TQ3Vector3D *vector3D, TQ3Point3D *result);

/* ---- Vector arithmetic -------------------------------------------------- */

/**
 * Scales a vector: result = vector * scalar.
 *
 * @param vector2D, vector3D  the vector.
 * @param scalar              the factor.
 * @param result              receives the scaled vector; it may be the vector.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   the vector or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Vector2D *) Q3Vector2D_Scale(const TQ3Vector2D *vector2D, float scalar, TQ3Vector2D *result);
Q3_EXTERN_API_C(TQ3Vector3D *) Q3Vector3D_Scale(const TQ3Vector3D *vector3D, float scalar, TQ3Vector3D *result);

/**
 * Computes the length of a 2D vector.
 *
 * @param vector2D  the vector.
 * @return its Euclidean length, or 0 on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   vector2D is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(float) Q3Vector2D_Length(const TQ3Vector2D *vector2D);

/**
 * Computes the length of a vector.
 *
 * @param vector3D  the vector.
 * @return its Euclidean length, or 0 on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   vector3D is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(float) Q3Vector3D_Length(const TQ3Vector3D *vector3D);

/**
 * Scales a 2D vector to unit length, keeping its direction.
 *
 * @param vector2D  the vector.
 * @param result    receives the unit vector; it may be vector2D.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized      Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter       vector2D or result is NULL.
 *   kQ3ErrorVector3DZeroLength  *vector2D has length 0, so has no direction
 *                               (QuickDraw 3D has no 2D code).
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Vector2D *) Q3Vector2D_Normalize(const TQ3Vector2D *vector2D, TQ3Vector2D *result);

/**
 * Scales a vector to unit length, keeping its direction.
 *
 * @param vector3D  the vector.
 * @param result    receives the unit vector.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized      Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter       vector3D or result is NULL.
 *   kQ3ErrorVector3DZeroLength  *vector3D has length 0, so has no direction.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Vector3D *) Q3Vector3D_Normalize(const TQ3Vector3D *vector3D,
                                                    TQ3Vector3D *result);

/**
 * Adds or subtracts two vectors: result = v1 + v2 (_Add) or v1 - v2
 * (_Subtract).
 *
 * @param v1      the first operand.
 * @param v2      the second operand.
 * @param result  receives the sum or difference; it may be v1 or v2.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   v1, v2 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Vector2D *) Q3Vector2D_Add(const TQ3Vector2D *v1, const TQ3Vector2D *v2, TQ3Vector2D *result);
Q3_EXTERN_API_C(TQ3Vector3D *) Q3Vector3D_Add(const TQ3Vector3D *v1, const TQ3Vector3D *v2, TQ3Vector3D *result);
Q3_EXTERN_API_C(TQ3Vector2D *) Q3Vector2D_Subtract(const TQ3Vector2D *v1, const TQ3Vector2D *v2,
                                                   TQ3Vector2D *result);
Q3_EXTERN_API_C(TQ3Vector3D *) Q3Vector3D_Subtract(const TQ3Vector3D *v1, const TQ3Vector3D *v2,
                                                   TQ3Vector3D *result);

/**
 * Computes the 2D cross product: the z component of (v1.x, v1.y, 0) x
 * (v2.x, v2.y, 0), that is v1.x * v2.y - v1.y * v2.x; positive when v2 is
 * counterclockwise from v1.
 *
 * @param v1  the left operand.
 * @param v2  the right operand.
 * @return the cross product, or 0 on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   v1 or v2 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(float) Q3Vector2D_Cross(const TQ3Vector2D *v1, const TQ3Vector2D *v2);

/**
 * Computes the cross product v1 x v2 (right-handed: X x Y = Z).
 *
 * @param v1      the left operand.
 * @param v2      the right operand.
 * @param result  receives the product.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   v1, v2 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Vector3D *) Q3Vector3D_Cross(const TQ3Vector3D *v1, const TQ3Vector3D *v2,
                                                TQ3Vector3D *result);

/**
 * Computes the normal of a triangle: (point2 - point1) x (point3 - point1),
 * which points towards the side from which point1, point2, point3 run
 * counterclockwise and has twice the triangle's area as its length. It is
 * not normalized.
 *
 * @param point1, point2, point3  the triangle's corners.
 * @param crossVector             receives the normal.
 * @return crossVector, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   a point or crossVector is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Vector3D *) Q3Point3D_CrossProductTri(const TQ3Point3D *point1, const TQ3Point3D *point2,
                                                         const TQ3Point3D *point3, TQ3Vector3D *crossVector);

/**
 * Computes the dot product of two 2D vectors.
 *
 * @param v1  one vector.
 * @param v2  the other vector.
 * @return v1 . v2, or 0 on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   v1 or v2 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(float) Q3Vector2D_Dot(const TQ3Vector2D *v1, const TQ3Vector2D *v2);

/**
 * Computes the dot product of two vectors.
 *
 * @param v1  one vector.
 * @param v2  the other vector.
 * @return v1 . v2, or 0 on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   v1 or v2 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(float) Q3Vector3D_Dot(const TQ3Vector3D *v1, const TQ3Vector3D *v2);

/* ---- Transforming points and vectors ------------------------------------ */

/**
 * Transforms a vector, a direction: (x, y, 0) * M for a 2D vector and a
 * 3x3 matrix, (x, y, z, 0) * M for a 3D vector and a 4x4 matrix. Only the
 * matrix's upper-left 2x2 (3x3) part acts: translation does not move a
 * direction, and nothing is divided.
 *
 * @param vector2D, vector3D    the vector.
 * @param matrix3x3, matrix4x4  the matrix.
 * @param result                receives the transformed vector; it may be
 *                              the vector.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   the vector, the matrix or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Vector2D *) Q3Vector2D_Transform(const TQ3Vector2D *vector2D, const TQ3Matrix3x3 *matrix3x3,
                                                    TQ3Vector2D *result);
Q3_EXTERN_API_C(TQ3Vector3D *) Q3Vector3D_Transform(const TQ3Vector3D *vector3D, const TQ3Matrix4x4 *matrix4x4,
                                                    TQ3Vector3D *result);

/**
 * Transforms a 2D point or a parametric (u, v) point by a 3x3 matrix:
 * (x, y, 1) * M gives (x', y', w'), and the result is (x'/w', y'/w'), or
 * (x', y') when w' is 0.
 *
 * @param point2D, param2D  the point.
 * @param matrix3x3         the matrix.
 * @param result            receives the transformed point; it may be the point.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   the point, matrix3x3 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Point2D *) Q3Point2D_Transform(const TQ3Point2D *point2D, const TQ3Matrix3x3 *matrix3x3,
                                                  TQ3Point2D *result);
Q3_EXTERN_API_C(TQ3Param2D *) Q3Param2D_Transform(const TQ3Param2D *param2D, const TQ3Matrix3x3 *matrix3x3,
                                                  TQ3Param2D *result);

/**
 * Transforms a point by a matrix: (x, y, z, 1) * M gives (x', y', z', w'),
 * and the result is (x'/w', y'/w', z'/w'). When w' is 0 (the point maps to
 * infinity) the result is (x', y', z'), undivided.
 *
 * @param point3D    the point.
 * @param matrix4x4  the matrix.
 * @param result     receives the transformed point.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   point3D, matrix4x4 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Point3D *) Q3Point3D_Transform(const TQ3Point3D *point3D,
                                                  const TQ3Matrix4x4 *matrix4x4,
                                                  TQ3Point3D *result);

/**
 * Transforms a homogeneous point by a matrix: (x, y, z, w) * M, with no
 * division.
 *
 * @param point4D    the point.
 * @param matrix4x4  the matrix.
 * @param result     receives the transformed point.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   point4D, matrix4x4 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3RationalPoint4D *) Q3RationalPoint4D_Transform(const TQ3RationalPoint4D *point4D,
                                                                  const TQ3Matrix4x4 *matrix4x4,
                                                                  TQ3RationalPoint4D *result);

/**
 * Transforms an array of points by one matrix, each element as
 *
 *   Q3Point3D_To3DTransformArray          Q3Point3D_Transform: (x, y, z, 1) * M,
 *                                         divided by w' (undivided when w' is 0)
 *   Q3Point3D_To4DTransformArray          (x, y, z, 1) * M, undivided, into a
 *                                         rational point
 *   Q3RationalPoint4D_To4DTransformArray  Q3RationalPoint4D_Transform:
 *                                         (x, y, z, w) * M, undivided
 *
 * The arrays follow the rules for arrays at the top of this header: the
 * first element of each is at the pointer, the next inStructSize
 * (outStructSize) bytes further on.
 *
 * @param inPoint3D, inPoint4D    the points.
 * @param matrix                  the matrix.
 * @param outPoint3D, outPoint4D  receives the transformed points; it may be
 *                                the input array, with the same stride.
 * @param numPoints               how many points; 0 does nothing.
 * @param inStructSize            the input stride in bytes, at least the
 *                                size of a point.
 * @param outStructSize           the output stride in bytes, at least the
 *                                size of a point.
 * @return kQ3Success, or kQ3Failure with no point written.
 *
 * Errors:
 *   kQ3ErrorNotInitialized      Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter       matrix is NULL, or an array is NULL while
 *                               numPoints is not 0.
 *   kQ3ErrorParameterOutOfRange numPoints is negative or more than an array
 *                               could hold at its stride, or a stride is
 *                               smaller than a point.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Point3D_To3DTransformArray(const TQ3Point3D *inPoint3D, const TQ3Matrix4x4 *matrix,
                                                        TQ3Point3D *outPoint3D, long numPoints,
                                                        unsigned long inStructSize, unsigned long outStructSize);
Q3_EXTERN_API_C(TQ3Status) Q3Point3D_To4DTransformArray(const TQ3Point3D *inPoint3D, const TQ3Matrix4x4 *matrix,
                                                        TQ3RationalPoint4D *outPoint4D, long numPoints,
                                                        unsigned long inStructSize, unsigned long outStructSize);
Q3_EXTERN_API_C(TQ3Status) Q3RationalPoint4D_To4DTransformArray(const TQ3RationalPoint4D *inPoint4D,
                                                                const TQ3Matrix4x4 *matrix,
                                                                TQ3RationalPoint4D *outPoint4D, long numPoints,
                                                                unsigned long inStructSize,
                                                                unsigned long outStructSize);

/* ---- Negating vectors --------------------------------------------------- */

/**
 * Negates a vector: result = -vector (each component's sign flipped, so 0
 * becomes -0 and NaN stays NaN).
 *
 * @param vector2D, vector3D  the vector.
 * @param result              receives the negated vector; it may be the vector.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   the vector or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Vector2D *) Q3Vector2D_Negate(const TQ3Vector2D *vector2D, TQ3Vector2D *result);
Q3_EXTERN_API_C(TQ3Vector3D *) Q3Vector3D_Negate(const TQ3Vector3D *vector3D, TQ3Vector3D *result);

/* ---- Polar and spherical coordinates ------------------------------------ */

/**
 * Converts a 2D point to polar coordinates: r is its distance from the
 * origin, theta its angle counterclockwise from +x, in [0, 2 pi) before the
 * rounding to float (so at most kQ32Pi). The origin gives (0, 0).
 *
 * @param point2D  the point.
 * @param result   receives the polar point.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   point2D or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3PolarPoint *) Q3Point2D_ToPolar(const TQ3Point2D *point2D, TQ3PolarPoint *result);

/**
 * Converts a polar point to Cartesian coordinates: (r cos theta,
 * r sin theta). Any r and theta are accepted (a negative r points the
 * other way; theta need not be in [0, 2 pi)).
 *
 * @param polarPoint  the polar point.
 * @param result      receives the point.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   polarPoint or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Point2D *) Q3PolarPoint_ToPoint2D(const TQ3PolarPoint *polarPoint, TQ3Point2D *result);

/**
 * Converts a 3D point to spherical coordinates: rho is its distance from
 * the origin; theta the angle of its projection onto the xy plane,
 * counterclockwise from +x, as Q3Point2D_ToPolar gives it (0 on the z
 * axis); phi its angle from +z, in [0, pi]. The origin gives (0, 0, 0).
 *
 * @param point3D  the point.
 * @param result   receives the spherical point.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   point3D or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3SphericalPoint *) Q3Point3D_ToSpherical(const TQ3Point3D *point3D, TQ3SphericalPoint *result);

/**
 * Converts a spherical point to Cartesian coordinates: (rho sin phi
 * cos theta, rho sin phi sin theta, rho cos phi), for any values.
 *
 * @param sphericalPoint  the spherical point.
 * @param result          receives the point.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   sphericalPoint or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Point3D *) Q3SphericalPoint_ToPoint3D(const TQ3SphericalPoint *sphericalPoint,
                                                         TQ3Point3D *result);

/* ---- Affine combinations ------------------------------------------------ */

/**
 * Combines points with weights: result = sum(weights[i] * points[i]) /
 * sum(weights[i]), coordinate by coordinate (w included for rational
 * points, combined in homogeneous coordinates). When the weights sum to 1,
 * as an affine combination's do, that is sum(weights[i] * points[i]); other
 * weights give their weighted mean (later Quesa does the same).
 *
 * @param points2D, params2D, points3D, points4D  the array of points.
 * @param weights                 the array of weights, one per point.
 * @param nPoints, numPoints      how many points (and weights).
 * @param result                  receives the combination; it may be one of
 *                                the points.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        the points, weights or result is NULL (the
 *                                arrays may be NULL when the count is 0,
 *                                which then fails as out of range).
 *   kQ3ErrorParameterOutOfRange  the count is 0, or more than an array
 *                                could hold.
 *   kQ3ErrorInvalidParameter     the weights sum to 0.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Point2D *) Q3Point2D_AffineComb(const TQ3Point2D *points2D, const float *weights,
                                                   unsigned long nPoints, TQ3Point2D *result);
Q3_EXTERN_API_C(TQ3Param2D *) Q3Param2D_AffineComb(const TQ3Param2D *params2D, const float *weights,
                                                   unsigned long nPoints, TQ3Param2D *result);
Q3_EXTERN_API_C(TQ3RationalPoint3D *) Q3RationalPoint3D_AffineComb(const TQ3RationalPoint3D *points3D,
                                                                   const float *weights,
                                                                   unsigned long numPoints,
                                                                   TQ3RationalPoint3D *result);
Q3_EXTERN_API_C(TQ3Point3D *) Q3Point3D_AffineComb(const TQ3Point3D *points3D, const float *weights,
                                                   unsigned long numPoints, TQ3Point3D *result);
Q3_EXTERN_API_C(TQ3RationalPoint4D *) Q3RationalPoint4D_AffineComb(const TQ3RationalPoint4D *points4D,
                                                                   const float *weights,
                                                                   unsigned long numPoints,
                                                                   TQ3RationalPoint4D *result);

/* ---- Matrices ----------------------------------------------------------- */

/**
 * Copies a 3x3 matrix.
 *
 * @param matrix3x3  the matrix.
 * @param result     receives the copy.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix3x3 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix3x3 *) Q3Matrix3x3_Copy(const TQ3Matrix3x3 *matrix3x3, TQ3Matrix3x3 *result);

/**
 * Copies a matrix.
 *
 * @param matrix4x4  the matrix.
 * @param result     receives the copy.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix4x4 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_Copy(const TQ3Matrix4x4 *matrix4x4,
                                                 TQ3Matrix4x4 *result);

/**
 * Sets a 3x3 matrix to the identity.
 *
 * @param matrix3x3  the matrix to set.
 * @return matrix3x3, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix3x3 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix3x3 *) Q3Matrix3x3_SetIdentity(TQ3Matrix3x3 *matrix3x3);

/**
 * Sets a matrix to the identity.
 *
 * @param matrix4x4  the matrix to set.
 * @return matrix4x4, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix4x4 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_SetIdentity(TQ3Matrix4x4 *matrix4x4);

/**
 * Transposes a 3x3 matrix (value[i][j] becomes value[j][i]).
 *
 * @param matrix3x3  the matrix.
 * @param result     receives the transpose; it may be matrix3x3.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix3x3 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix3x3 *) Q3Matrix3x3_Transpose(const TQ3Matrix3x3 *matrix3x3, TQ3Matrix3x3 *result);

/**
 * Transposes a matrix (value[i][j] becomes value[j][i]).
 *
 * @param matrix4x4  the matrix.
 * @param result     receives the transpose; it may be matrix4x4.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix4x4 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_Transpose(const TQ3Matrix4x4 *matrix4x4,
                                                      TQ3Matrix4x4 *result);

/**
 * Inverts a 3x3 matrix.
 *
 * @param matrix3x3  the matrix.
 * @param result     receives the inverse; it may be matrix3x3.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        matrix3x3 or result is NULL.
 *   kQ3ErrorNonInvertibleMatrix  the matrix is singular (its determinant is
 *                                0), or its inverse would have an entry that
 *                                is not finite.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix3x3 *) Q3Matrix3x3_Invert(const TQ3Matrix3x3 *matrix3x3, TQ3Matrix3x3 *result);

/**
 * Inverts a matrix.
 *
 * @param matrix4x4  the matrix.
 * @param result     receives the inverse; it may be matrix4x4.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        matrix4x4 or result is NULL.
 *   kQ3ErrorNonInvertibleMatrix  the matrix is singular (its determinant is
 *                                0), or its inverse would have an entry that
 *                                is not finite.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_Invert(const TQ3Matrix4x4 *matrix4x4,
                                                   TQ3Matrix4x4 *result);

/**
 * Computes the adjoint (adjugate) of a 3x3 matrix: the transpose of its
 * cofactor matrix, so that adjoint(M) * M = determinant(M) * I. Unlike the
 * inverse it exists for every matrix, and it equals determinant(M) times
 * the inverse when that exists.
 *
 * @param matrix3x3  the matrix.
 * @param result     receives the adjoint; it may be matrix3x3.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix3x3 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix3x3 *) Q3Matrix3x3_Adjoint(const TQ3Matrix3x3 *matrix3x3, TQ3Matrix3x3 *result);

/**
 * Multiplies two 3x3 matrices: result = matrixA * matrixB, the transform
 * that applies matrixA first and matrixB second.
 *
 * @param matrixA  the left factor, applied first.
 * @param matrixB  the right factor, applied second.
 * @param result   receives the product; it may be either factor.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrixA, matrixB or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix3x3 *) Q3Matrix3x3_Multiply(const TQ3Matrix3x3 *matrixA, const TQ3Matrix3x3 *matrixB,
                                                     TQ3Matrix3x3 *result);

/**
 * Multiplies two matrices: result = matrixA * matrixB, the transform that
 * applies matrixA first and matrixB second.
 *
 * @param matrixA  the left factor, applied first.
 * @param matrixB  the right factor, applied second.
 * @param result   receives the product; it may be either factor.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrixA, matrixB or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_Multiply(const TQ3Matrix4x4 *matrixA,
                                                     const TQ3Matrix4x4 *matrixB,
                                                     TQ3Matrix4x4 *result);

/**
 * Sets a 3x3 matrix to a 2D translation, the identity with value[2][0..1]
 * set to (xTrans, yTrans), or to a 2D scale about the origin, the diagonal
 * (xScale, yScale, 1). The values are stored as given.
 *
 * @param matrix3x3       the matrix to set.
 * @param xTrans, yTrans  (_SetTranslate) the offsets along x and y.
 * @param xScale, yScale  (_SetScale) the factors along x and y.
 * @return matrix3x3, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix3x3 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix3x3 *) Q3Matrix3x3_SetTranslate(TQ3Matrix3x3 *matrix3x3, float xTrans, float yTrans);
Q3_EXTERN_API_C(TQ3Matrix3x3 *) Q3Matrix3x3_SetScale(TQ3Matrix3x3 *matrix3x3, float xScale, float yScale);

/**
 * Sets a 3x3 matrix to a 2D rotation about a point, counterclockwise: a
 * quarter turn about the origin takes (1, 0) to (0, 1). The point origin
 * does not move.
 *
 * @param matrix3x3  the matrix to set.
 * @param origin     the centre of the rotation.
 * @param angle      the angle in radians.
 * @return matrix3x3, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix3x3 or origin is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix3x3 *) Q3Matrix3x3_SetRotateAboutPoint(TQ3Matrix3x3 *matrix3x3, const TQ3Point2D *origin,
                                                                float angle);

/**
 * Sets a matrix to a translation: the identity with value[3][0..2] set to
 * (xTrans, yTrans, zTrans).
 *
 * @param matrix4x4  the matrix to set.
 * @param xTrans     the offset along x.
 * @param yTrans     the offset along y.
 * @param zTrans     the offset along z.
 * @return matrix4x4, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix4x4 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_SetTranslate(TQ3Matrix4x4 *matrix4x4,
                                                         float xTrans, float yTrans, float zTrans);

/**
 * Sets a matrix to a scale about the origin: the diagonal (xScale, yScale,
 * zScale, 1).
 *
 * @param matrix4x4  the matrix to set.
 * @param xScale     the factor along x.
 * @param yScale     the factor along y.
 * @param zScale     the factor along z.
 * @return matrix4x4, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix4x4 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_SetScale(TQ3Matrix4x4 *matrix4x4,
                                                     float xScale, float yScale, float zScale);

/**
 * Sets a matrix to Q3Matrix4x4_SetRotate_XYZ's rotation about the lines
 * through origin parallel to the axes, instead of about the axes: the point
 * origin does not move.
 *
 * @param matrix4x4  the matrix to set.
 * @param origin     the centre of the rotation.
 * @param xAngle     the angle about the x direction, applied first.
 * @param yAngle     the angle about the y direction, applied second.
 * @param zAngle     the angle about the z direction, applied last.
 * @return matrix4x4, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix4x4 or origin is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_SetRotateAboutPoint(TQ3Matrix4x4 *matrix4x4, const TQ3Point3D *origin,
                                                                float xAngle, float yAngle, float zAngle);

/**
 * Sets a matrix to a rotation about an arbitrary line: the line through
 * origin with direction orientation, counterclockwise as seen from the tip
 * of orientation looking back along it. Points on the line do not move.
 *
 * @param matrix4x4    the matrix to set.
 * @param origin       a point on the axis.
 * @param orientation  the axis direction; it need not be unit length.
 * @param angle        the angle in radians.
 * @return matrix4x4, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized      Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter       matrix4x4, origin or orientation is NULL.
 *   kQ3ErrorVector3DZeroLength  *orientation has length 0.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_SetRotateAboutAxis(TQ3Matrix4x4 *matrix4x4,
                                                               const TQ3Point3D *origin,
                                                               const TQ3Vector3D *orientation,
                                                               float angle);

/**
 * Sets a matrix to a rotation about the x axis, counterclockwise as seen
 * from +x: a quarter turn takes (0, 1, 0) to (0, 0, 1).
 *
 * @param matrix4x4  the matrix to set.
 * @param angle      the angle in radians.
 * @return matrix4x4, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix4x4 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_SetRotate_X(TQ3Matrix4x4 *matrix4x4, float angle);

/**
 * Sets a matrix to a rotation about the y axis, counterclockwise as seen
 * from +y: a quarter turn takes (0, 0, 1) to (1, 0, 0).
 *
 * @param matrix4x4  the matrix to set.
 * @param angle      the angle in radians.
 * @return matrix4x4, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix4x4 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_SetRotate_Y(TQ3Matrix4x4 *matrix4x4, float angle);

/**
 * Sets a matrix to a rotation about the z axis, counterclockwise as seen
 * from +z: a quarter turn takes (1, 0, 0) to (0, 1, 0).
 *
 * @param matrix4x4  the matrix to set.
 * @param angle      the angle in radians.
 * @return matrix4x4, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix4x4 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_SetRotate_Z(TQ3Matrix4x4 *matrix4x4, float angle);

/**
 * Sets a matrix to a rotation about the x axis, then the y axis, then the
 * z axis, each as Q3Matrix4x4_SetRotate_X/_Y/_Z makes it: the product
 * Rx * Ry * Rz (QuickDraw 3D's order, which Quesa keeps).
 *
 * @param matrix4x4  the matrix to set.
 * @param xAngle     the angle about x in radians, applied first.
 * @param yAngle     the angle about y in radians, applied second.
 * @param zAngle     the angle about z in radians, applied last.
 * @return matrix4x4, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   matrix4x4 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_SetRotate_XYZ(TQ3Matrix4x4 *matrix4x4, float xAngle, float yAngle,
                                                          float zAngle);

/**
 * Sets a matrix to the rotation about the origin that takes the direction
 * of v1 to the direction of v2, turning about their common normal v1 x v2.
 * Neither needs unit length. Equal directions give the identity; opposite
 * ones a half turn about the axis along v1 x e, e being the coordinate axis
 * of v1's component smallest in magnitude (the first of equals).
 *
 * @param matrix4x4  the matrix to set.
 * @param v1         the direction to turn from.
 * @param v2         the direction to turn to.
 * @return matrix4x4, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized      Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter       matrix4x4, v1 or v2 is NULL.
 *   kQ3ErrorVector3DZeroLength  *v1 or *v2 has length 0.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_SetRotateVectorToVector(TQ3Matrix4x4 *matrix4x4, const TQ3Vector3D *v1,
                                                                    const TQ3Vector3D *v2);

/**
 * Sets a matrix to the rotation a quaternion stands for (see the
 * quaternion section): the rotation part in the upper-left 3x3, no
 * translation or perspective. Any nonzero multiple of a quaternion gives
 * the same matrix, so the quaternion need not have unit length.
 *
 * @param matrix      the matrix to set.
 * @param quaternion  the rotation.
 * @return matrix, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     matrix or quaternion is NULL.
 *   kQ3ErrorInvalidParameter  the quaternion is (0, 0, 0, 0), no rotation.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Matrix4x4 *) Q3Matrix4x4_SetQuaternion(TQ3Matrix4x4 *matrix, const TQ3Quaternion *quaternion);

/**
 * Computes the determinant of a 3x3 or a 4x4 matrix, in double precision
 * and rounded once (so it may overflow to an infinity). An infinite entry
 * meets zeros in the expansion, so it gives an infinity or NaN.
 *
 * @param matrix3x3, matrix4x4  the matrix.
 * @return the determinant, or 0 on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   the matrix is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(float) Q3Matrix3x3_Determinant(const TQ3Matrix3x3 *matrix3x3);
Q3_EXTERN_API_C(float) Q3Matrix4x4_Determinant(const TQ3Matrix4x4 *matrix4x4);

/* ---- Quaternions -------------------------------------------------------- */

/*
 * A quaternion (w, x, y, z) = w + xi + yj + zk other than 0 stands for the
 * rotation v -> q v q^-1: a unit quaternion (cos(a/2), sin(a/2) * axis)
 * turns counterclockwise by a about the unit axis, the same turn as the
 * matrices above (Q3Matrix4x4_SetQuaternion gives its matrix). q and any
 * nonzero multiple of it, -q included, stand for the same rotation.
 * Products compose like QuickDraw 3D's matrices, left to right:
 * Q3Quaternion_Multiply(q1, q2) is q1 first, then q2.
 */

/**
 * Sets a quaternion's components, or sets it to the identity (1, 0, 0, 0),
 * or copies one.
 *
 * @param quaternion  (_Set, _SetIdentity) the quaternion to set;
 *                    (_Copy) the quaternion to copy.
 * @param w, x, y, z  (_Set) the new components.
 * @param result      (_Copy) receives the copy.
 * @return the quaternion set or result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   a quaternion argument is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_Set(TQ3Quaternion *quaternion, float w, float x, float y, float z);
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_SetIdentity(TQ3Quaternion *quaternion);
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_Copy(const TQ3Quaternion *quaternion, TQ3Quaternion *result);

/**
 * Tells whether a quaternion stands for no rotation: whether x, y and z
 * are all within kQ3RealZero of 0, as QuickDraw 3D 1.6 tests it (w is not
 * looked at, so (-1, 0, 0, 0), a whole turn, is the identity too).
 *
 * @param quaternion  the quaternion.
 * @return kQ3True or kQ3False; kQ3False on failure and when a component
 *         tested is NaN.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   quaternion is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Boolean) Q3Quaternion_IsIdentity(const TQ3Quaternion *quaternion);

/**
 * Inverts a quaternion: result = conjugate(q) / |q|^2, so that
 * q * result = 1. For a unit quaternion that is the conjugate
 * (w, -x, -y, -z), the opposite rotation.
 *
 * @param quaternion  the quaternion.
 * @param result      receives the inverse; it may be quaternion.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     quaternion or result is NULL.
 *   kQ3ErrorInvalidParameter  the quaternion is (0, 0, 0, 0).
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_Invert(const TQ3Quaternion *quaternion, TQ3Quaternion *result);

/**
 * Scales a quaternion to unit length; it stands for the same rotation.
 *
 * @param quaternion  the quaternion.
 * @param result      receives the unit quaternion; it may be quaternion.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     quaternion or result is NULL.
 *   kQ3ErrorInvalidParameter  the quaternion is (0, 0, 0, 0).
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_Normalize(const TQ3Quaternion *quaternion, TQ3Quaternion *result);

/**
 * Computes the dot product of two quaternions as 4-vectors: for unit
 * quaternions, the cosine of half the angle between their rotations.
 *
 * @param q1  one quaternion.
 * @param q2  the other quaternion.
 * @return q1 . q2, or 0 on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   q1 or q2 is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(float) Q3Quaternion_Dot(const TQ3Quaternion *q1, const TQ3Quaternion *q2);

/**
 * Composes two rotations, q1 first, then q2: the Hamilton product q2 * q1,
 * so that the matrix of the result is the matrix of q1 times the matrix of
 * q2, as Q3Matrix4x4_Multiply composes (Quesa composes the same way).
 *
 * @param q1      the rotation applied first.
 * @param q2      the rotation applied second.
 * @param result  receives the composition; it may be q1 or q2.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   q1, q2 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_Multiply(const TQ3Quaternion *q1, const TQ3Quaternion *q2,
                                                       TQ3Quaternion *result);

/**
 * Sets a quaternion to a rotation about an axis through the origin,
 * counterclockwise as seen from the tip of axis: the unit quaternion
 * (cos(angle/2), sin(angle/2) * axis / |axis|). The axis need not have unit
 * length.
 *
 * @param quaternion  the quaternion to set.
 * @param axis        the axis direction.
 * @param angle       the angle in radians.
 * @return quaternion, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized      Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter       quaternion or axis is NULL.
 *   kQ3ErrorVector3DZeroLength  *axis has length 0.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_SetRotateAboutAxis(TQ3Quaternion *quaternion,
                                                                  const TQ3Vector3D *axis, float angle);

/**
 * Sets a quaternion to the rotation of Q3Matrix4x4_SetRotate_XYZ (about x,
 * then y, then z) or of Q3Matrix4x4_SetRotate_X, _Y, _Z, as a unit
 * quaternion: _X makes (cos(angle/2), sin(angle/2), 0, 0).
 *
 * @param quaternion              the quaternion to set.
 * @param xAngle, yAngle, zAngle  (_XYZ) the angles in radians, in the order
 *                                they are applied.
 * @param angle                   (_X, _Y, _Z) the angle in radians.
 * @return quaternion, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   quaternion is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_SetRotate_XYZ(TQ3Quaternion *quaternion, float xAngle, float yAngle,
                                                            float zAngle);
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_SetRotate_X(TQ3Quaternion *quaternion, float angle);
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_SetRotate_Y(TQ3Quaternion *quaternion, float angle);
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_SetRotate_Z(TQ3Quaternion *quaternion, float angle);

/**
 * Sets a quaternion to the rotation in a matrix's upper-left 3x3 (the rest
 * is ignored), as a unit quaternion (Shepperd's method). The 3x3 should be
 * a rotation; for any other the result is the unit quaternion the method
 * makes of it, not an error. Apple's implementation is known to return
 * wrong quaternions here (Quesa notes that a quaternion taken to a matrix
 * and back does not come back); Q3 returns the quaternion whose
 * Q3Matrix4x4_SetQuaternion matrix is the rotation given.
 *
 * @param quaternion  the quaternion to set.
 * @param matrix      the matrix.
 * @return quaternion, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   quaternion or matrix is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_SetMatrix(TQ3Quaternion *quaternion, const TQ3Matrix4x4 *matrix);

/**
 * Sets a quaternion to Q3Matrix4x4_SetRotateVectorToVector's rotation,
 * taking the direction of v1 to the direction of v2, as a unit quaternion
 * (the same axis for opposite directions).
 *
 * @param quaternion  the quaternion to set.
 * @param v1          the direction to turn from.
 * @param v2          the direction to turn to.
 * @return quaternion, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized      Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter       quaternion, v1 or v2 is NULL.
 *   kQ3ErrorVector3DZeroLength  *v1 or *v2 has length 0.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_SetRotateVectorToVector(TQ3Quaternion *quaternion,
                                                                       const TQ3Vector3D *v1,
                                                                       const TQ3Vector3D *v2);

/**
 * Picks the sign of q1 that lies on q2's side: q1 when q1 . q2 > 0, -q1
 * otherwise (also when the dot product is 0 or NaN). Both stand for the
 * same rotation; interpolating from the result to q2 takes the shorter way.
 *
 * @param q1      the quaternion whose sign is picked.
 * @param q2      the quaternion to match.
 * @param result  receives q1 or -q1; it may be q1 or q2.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   q1, q2 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_MatchReflection(const TQ3Quaternion *q1, const TQ3Quaternion *q2,
                                                               TQ3Quaternion *result);

/**
 * Interpolates between two rotations.
 *
 * Q3Quaternion_InterpolateFast takes the straight line from q1 to q2,
 * (1 - t) q1 + t q2, and scales it to unit length: quick, but the rotation
 * does not turn at a constant speed.
 *
 * Q3Quaternion_InterpolateLinear moves along the great arc from q1 to q2
 * at a constant angular speed (spherical linear interpolation, Shoemake
 * 1985): sin((1 - t) a) / sin(a) q1 + sin(t a) / sin(a) q2, a being the
 * angle between q1 and q2 as 4-vectors. Where that divides by almost 0
 * (q1 and q2 within 1e-6 radians, one of them 0, or a NaN) it takes the
 * straight line (unscaled); where they are nearly opposite it turns from q1
 * through (-x, w, -z, y), perpendicular to it, reaching -q1 at t = 1.
 *
 * Neither changes a sign: t = 0 gives q1 and t = 1 gives q2 (scaled to unit
 * length by _InterpolateFast; -q1, within 1e-6 radians of q2, when
 * _InterpolateLinear takes the perpendicular way). For the shorter way round
 * between the same rotations, call Q3Quaternion_MatchReflection(q1, q2, &q1)
 * first. t outside [0, 1] extrapolates.
 *
 * @param q1      the rotation at t = 0.
 * @param q2      the rotation at t = 1.
 * @param t       the interpolation factor.
 * @param result  receives the interpolated quaternion; it may be q1 or q2.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     q1, q2 or result is NULL.
 *   kQ3ErrorInvalidParameter  (_InterpolateFast) the straight line passes
 *                             through 0 at t (q2 a negative multiple of
 *                             q1), so there is no rotation to scale.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_InterpolateFast(const TQ3Quaternion *q1, const TQ3Quaternion *q2,
                                                              float t, TQ3Quaternion *result);
Q3_EXTERN_API_C(TQ3Quaternion *) Q3Quaternion_InterpolateLinear(const TQ3Quaternion *q1, const TQ3Quaternion *q2,
                                                                float t, TQ3Quaternion *result);

/**
 * Rotates a vector, or a point about the origin, by the rotation a
 * quaternion stands for (any nonzero length): the same as transforming it
 * by the Q3Matrix4x4_SetQuaternion matrix, computed without rounding the
 * matrix first.
 *
 * @param vector3D, point3D  the vector or point.
 * @param quaternion         the rotation.
 * @param result             receives the rotated vector or point; it may be
 *                           the vector or point.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     the vector or point, quaternion or result is
 *                             NULL.
 *   kQ3ErrorInvalidParameter  the quaternion is (0, 0, 0, 0).
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3Vector3D *) Q3Vector3D_TransformQuaternion(const TQ3Vector3D *vector3D,
                                                              const TQ3Quaternion *quaternion,
                                                              TQ3Vector3D *result);
Q3_EXTERN_API_C(TQ3Point3D *) Q3Point3D_TransformQuaternion(const TQ3Point3D *point3D,
                                                            const TQ3Quaternion *quaternion, TQ3Point3D *result);

/* ---- Bounding boxes ----------------------------------------------------- */

/*
 * A bound whose isEmpty is not kQ3False (any nonzero value counts, as a C
 * caller may store it) holds nothing, and its other fields are ignored; the
 * empty bounds these functions make have them all 0. Bounds made from
 * points or from other bounds are rounded outwards after a computation in
 * double precision, so they hold every point exactly; a NaN coordinate
 * makes the corresponding bound NaN. Rational points are taken as the
 * points they stand for, (x/w, y/w, z/w), undivided when w is 0.
 */

/**
 * Copies a bounding box.
 *
 * @param src   the box.
 * @param dest  receives the copy, every byte as it is.
 * @return dest, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   src or dest is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3BoundingBox *) Q3BoundingBox_Copy(const TQ3BoundingBox *src, TQ3BoundingBox *dest);

/**
 * Computes the smallest box holding two boxes: each coordinate's least
 * min and greatest max. An empty box adds nothing; two empty boxes give an
 * empty box.
 *
 * @param v1      one box.
 * @param v2      the other box.
 * @param result  receives the union; it may be v1 or v2.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   v1, v2 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3BoundingBox *) Q3BoundingBox_Union(const TQ3BoundingBox *v1, const TQ3BoundingBox *v2,
                                                      TQ3BoundingBox *result);

/**
 * Sets a bounding box's fields as given (min is not checked against max);
 * a nonzero isEmpty is stored as kQ3True.
 *
 * @param bBox     the box to set.
 * @param min      the corner with the least coordinates.
 * @param max      the corner with the greatest coordinates.
 * @param isEmpty  whether the box holds nothing.
 * @return bBox, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   bBox, min or max is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3BoundingBox *) Q3BoundingBox_Set(TQ3BoundingBox *bBox, const TQ3Point3D *min,
                                                    const TQ3Point3D *max, TQ3Boolean isEmpty);

/**
 * Computes the smallest box holding a box and a point (a 3D point or the
 * point a rational point stands for); an empty box gives the box of the
 * point alone.
 *
 * @param bBox              the box.
 * @param point3D, point4D  the point.
 * @param result            receives the union; it may be bBox.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   bBox, the point or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3BoundingBox *) Q3BoundingBox_UnionPoint3D(const TQ3BoundingBox *bBox,
                                                             const TQ3Point3D *point3D, TQ3BoundingBox *result);
Q3_EXTERN_API_C(TQ3BoundingBox *) Q3BoundingBox_UnionRationalPoint4D(const TQ3BoundingBox *bBox,
                                                                     const TQ3RationalPoint4D *point4D,
                                                                     TQ3BoundingBox *result);

/**
 * Sets a bounding box to the smallest box holding an array of points (3D
 * points, or the points rational points stand for); no points give an
 * empty box. The array follows the rules for arrays at the top of this
 * header.
 *
 * @param bBox               the box to set.
 * @param points3D, points4D the first point.
 * @param numPoints          how many points.
 * @param structSize         the stride in bytes, at least the size of a point.
 * @return bBox, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        bBox is NULL, or the points are NULL while
 *                                numPoints is not 0.
 *   kQ3ErrorParameterOutOfRange  structSize is smaller than a point, or
 *                                numPoints is more than an array could hold.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3BoundingBox *) Q3BoundingBox_SetFromPoints3D(TQ3BoundingBox *bBox, const TQ3Point3D *points3D,
                                                                unsigned long numPoints,
                                                                unsigned long structSize);
Q3_EXTERN_API_C(TQ3BoundingBox *) Q3BoundingBox_SetFromRationalPoints4D(TQ3BoundingBox *bBox,
                                                                        const TQ3RationalPoint4D *points4D,
                                                                        unsigned long numPoints,
                                                                        unsigned long structSize);

/* ---- Bounding spheres --------------------------------------------------- */

/**
 * Copies a bounding sphere.
 *
 * @param src   the sphere.
 * @param dest  receives the copy, every byte as it is.
 * @return dest, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   src or dest is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3BoundingSphere *) Q3BoundingSphere_Copy(const TQ3BoundingSphere *src, TQ3BoundingSphere *dest);

/**
 * Computes the smallest sphere holding two spheres: one of them if it holds
 * the other, otherwise the sphere whose diameter runs along the line
 * through their centres from the far side of one to the far side of the
 * other. An empty sphere adds nothing; two empty spheres give an empty
 * sphere. Radii are taken as they are (a negative radius is not checked).
 *
 * @param s1      one sphere.
 * @param s2      the other sphere.
 * @param result  receives the union; it may be s1 or s2.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   s1, s2 or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3BoundingSphere *) Q3BoundingSphere_Union(const TQ3BoundingSphere *s1,
                                                            const TQ3BoundingSphere *s2,
                                                            TQ3BoundingSphere *result);

/**
 * Sets a bounding sphere's fields as given (the radius is not checked); a
 * nonzero isEmpty is stored as kQ3True.
 *
 * @param bSphere  the sphere to set.
 * @param origin   the centre.
 * @param radius   the radius.
 * @param isEmpty  whether the sphere holds nothing.
 * @return bSphere, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   bSphere or origin is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3BoundingSphere *) Q3BoundingSphere_Set(TQ3BoundingSphere *bSphere, const TQ3Point3D *origin,
                                                          float radius, TQ3Boolean isEmpty);

/**
 * Computes the smallest sphere holding a sphere and a point (a 3D point or
 * the point a rational point stands for): the sphere itself if it holds
 * the point, otherwise as Q3BoundingSphere_Union with a sphere of radius 0
 * there. An empty sphere gives the point with radius 0.
 *
 * @param bSphere           the sphere.
 * @param point3D, point4D  the point.
 * @param result            receives the union; it may be bSphere.
 * @return result, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   bSphere, the point or result is NULL.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3BoundingSphere *) Q3BoundingSphere_UnionPoint3D(const TQ3BoundingSphere *bSphere,
                                                                   const TQ3Point3D *point3D,
                                                                   TQ3BoundingSphere *result);
Q3_EXTERN_API_C(TQ3BoundingSphere *) Q3BoundingSphere_UnionRationalPoint4D(const TQ3BoundingSphere *bSphere,
                                                                           const TQ3RationalPoint4D *point4D,
                                                                           TQ3BoundingSphere *result);

/**
 * Sets a bounding sphere around an array of points (3D points, or the
 * points rational points stand for): centred on their bounding box, with
 * the radius reaching the farthest point. That holds every point, and its
 * radius is at most sqrt(3) times the smallest enclosing sphere's (the
 * smallest sphere is not searched for). No points give an empty sphere. The
 * array follows the rules for arrays at the top of this header.
 *
 * @param bSphere            the sphere to set.
 * @param points3D, points4D the first point.
 * @param numPoints          how many points.
 * @param structSize         the stride in bytes, at least the size of a point.
 * @return bSphere, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        bSphere is NULL, or the points are NULL
 *                                while numPoints is not 0.
 *   kQ3ErrorParameterOutOfRange  structSize is smaller than a point, or
 *                                numPoints is more than an array could hold.
 *
 * Ownership: no objects are involved.
 */
Q3_EXTERN_API_C(TQ3BoundingSphere *) Q3BoundingSphere_SetFromPoints3D(TQ3BoundingSphere *bSphere,
                                                                      const TQ3Point3D *points3D,
                                                                      unsigned long numPoints,
                                                                      unsigned long structSize);
Q3_EXTERN_API_C(TQ3BoundingSphere *) Q3BoundingSphere_SetFromRationalPoints4D(TQ3BoundingSphere *bSphere,
                                                                              const TQ3RationalPoint4D *points4D,
                                                                              unsigned long numPoints,
                                                                              unsigned long structSize);

#ifdef __cplusplus
}
#endif

#endif /* QD3DMATH_H */
