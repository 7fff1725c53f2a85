/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Point, vector and 4x4 matrix arithmetic.
 *
 * Matrices act on row vectors, as in QuickDraw 3D: a point p is transformed
 * as p * M, so the translation sits in value[3][0..2], and transforming by
 * A * B means transforming by A first, then by B.
 *
 * Every function that returns a pointer returns its result argument on
 * success and NULL on failure; every function that returns a float returns 0
 * on failure. The result may point to the same storage as an input (for
 * example Q3Matrix4x4_Multiply(&m, &n, &m)). Values are not checked for
 * being finite: NaNs and infinities go through the IEEE arithmetic.
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error and leaves its result unchanged. Like every
 * Q3 call outside the error manager, these fail with kQ3ErrorNotInitialized
 * before Q3Initialize; after that, the pointer arguments are checked for
 * NULL from left to right, then the function's other conditions.
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

/* ---- Lengths, distances and products ------------------------------------ */

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

/* ---- Transforming points ------------------------------------------------ */

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

/* ---- Building matrices -------------------------------------------------- */

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

/* ---- Matrix operations -------------------------------------------------- */

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

#ifdef __cplusplus
}
#endif

#endif /* QD3DMATH_H */
