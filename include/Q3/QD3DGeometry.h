/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Geometries: NURB curves, polylines, lines, points, triangles, polygons,
 * general polygons, polyhedra, triangle grids, triangle meshes, markers,
 * pixmap markers, and the quadrics and solids (boxes, cones, cylinders,
 * disks, ellipses, ellipsoids, tori), in retained mode (an object made by ..._New and drawn with
 * Q3Geometry_Submit) and immediate mode (a data structure drawn at once with
 * ..._Submit).
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error and leaves every object and output it was
 * given unchanged (a retained geometry keeps its data and its edit index).
 * Warnings do not make a call fail. "Not a live Q3 object" means a handle
 * that was disposed or never came from Q3. The checks run in this order, and
 * the first that fails decides the error: Q3 is initialized; then the
 * arguments from left to right (a handle: not NULL, a live Q3 object, of the
 * right class; a pointer: not NULL); then the function's other conditions in
 * the order it lists them (for a data structure, the rules given with its
 * type, in their order).
 *
 * Attribute sets inside the data structures may be NULL. Q3 does not copy
 * them: a retained geometry holds its own reference to each set it was given.
 *
 * Attributes are inherited as in QuickDraw 3D: a vertex's own attribute set
 * wins over its face's (a triangle's, a polyline segment's, a TriMesh
 * triangle's), which wins over the geometry's attribute set, which wins over
 * the view's current attribute state (Q3AttributeSet_Submit). A geometry
 * whose vertices carry diffuse colours is drawn with the colours interpolated
 * along its lines and across its triangles. The wireframe renderer draws the
 * edges of surfaces; the interactive renderer fills them, hiding what is
 * behind (QD3DRenderer.h).
 *
 * The data calls every geometry type Xxx has behave alike:
 *   Q3Xxx_New(data)             a retained geometry owning a copy of data
 *                               (arrays copied, attribute sets referenced).
 *   Q3Xxx_Submit(data, view)    draws or bounds data in a view's loop without
 *                               making an object (immediate mode).
 *   Q3Xxx_GetData(obj, data)    fills data with newly allocated copies of the
 *                               arrays and one new reference per attribute
 *                               set, for the caller to give back with
 *   Q3Xxx_EmptyData(data)       which releases those references, frees the
 *                               arrays and sets the pointers to NULL (a
 *                               second call does nothing);
 *   Q3Xxx_SetData(obj, data)    replaces the object's data with a copy.
 * Each checks its data against the rules given with the data type, in their
 * order, and posts the first that fails (the object is then unchanged). Every
 * array count is at most kQ3GeometryMaxArrayCount.
 */
#ifndef QD3DGEOMETRY_H
#define QD3DGEOMETRY_H

#include "QD3D.h"
#include "QD3DSet.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Geometry ----------------------------------------------------------- */

/*
 * Q3 extension: the largest count Q3 accepts for any array in a geometry's
 * data (vertices, points, triangles, control points, attribute values...).
 * A larger count is refused with kQ3ErrorParameterOutOfRange. It keeps every
 * size computation far from overflow and is far above any real model.
 */
#define kQ3GeometryMaxArrayCount (1UL << 28)

/**
 * Reports the kind of a geometry.
 *
 * @param geometry  the geometry to query.
 * @return its type code (kQ3GeometryTypeNURBCurve, kQ3GeometryTypePolyLine,
 *         kQ3GeometryTypeLine, kQ3GeometryTypePoint, kQ3GeometryTypeTriangle,
 *         kQ3GeometryTypePolygon, kQ3GeometryTypeTriMesh, kQ3GeometryTypeBox,
 *         kQ3GeometryTypeCone, kQ3GeometryTypeCylinder, kQ3GeometryTypeDisk,
 *         kQ3GeometryTypeEllipse, kQ3GeometryTypeEllipsoid,
 *         kQ3GeometryTypeTorus), or
 *         kQ3ObjectTypeInvalid on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      geometry is NULL.
 *   kQ3ErrorInvalidObject      geometry is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  geometry is not a geometry.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Geometry_GetType(TQ3GeometryObject geometry);

/**
 * Reads the attribute set of a geometry as a whole: the curveAttributeSet,
 * polyLineAttributeSet, lineAttributeSet or pointAttributeSet of its data.
 *
 * @param geometry      the geometry to read.
 * @param attributeSet  receives the geometry's attribute set, or NULL when it
 *                      has none (still kQ3Success).
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      geometry or attributeSet is NULL.
 *   kQ3ErrorInvalidObject      geometry is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  geometry is not a geometry.
 *
 * Ownership: when *attributeSet is not NULL the caller owns a new reference
 * to it and releases it with Q3Object_Dispose. The set is the geometry's own,
 * not a copy: changing it changes the geometry's attributes.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Geometry_GetAttributeSet(TQ3GeometryObject geometry,
                                                      TQ3AttributeSet *attributeSet);

/**
 * Replaces the attribute set of a geometry as a whole (the set Get/SetData
 * call curveAttributeSet, polyLineAttributeSet, lineAttributeSet or
 * pointAttributeSet), and bumps the geometry's edit index.
 *
 * @param geometry      the geometry to change.
 * @param attributeSet  the new attribute set, or NULL to remove the one the
 *                      geometry has.
 * @return kQ3Success, or kQ3Failure with the geometry unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      geometry is NULL.
 *   kQ3ErrorInvalidObject      geometry or attributeSet is not a live Q3
 *                              object.
 *   kQ3ErrorInvalidObjectType  geometry is not a geometry, or attributeSet is
 *                              not an attribute set.
 *
 * Ownership: the geometry takes a reference to attributeSet and releases the
 * one it held; the caller keeps its own reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Geometry_SetAttributeSet(TQ3GeometryObject geometry,
                                                      TQ3AttributeSet attributeSet);

/**
 * Submits a retained geometry to a view in a rendering or bounding loop. It
 * is drawn (or bounded) under the view's current transform, style and
 * attribute state; a NURB curve is first subdivided into line segments as
 * the current subdivision style says.
 *
 * @param geometry  the geometry to draw.
 * @param view      a view inside a loop.
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      geometry or view is NULL.
 *   kQ3ErrorInvalidObject      geometry or view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  geometry is not a geometry, or view is not a
 *                              view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   kQ3ErrorOutOfMemory        a NURB curve cannot be subdivided for lack of
 *                              memory.
 * Warnings:
 *   kQ3WarningParameterOutOfRange  a NURB curve would need more than
 *                              kQ3SubdivisionMaxSegmentsPerCurve segments
 *                              (QD3DStyle.h) and is drawn with that many.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Geometry_Submit(TQ3GeometryObject geometry, TQ3ViewObject view);

/**
 * Q3 extension (the name and signature are Quesa's; QuickDraw 3D never had
 * this call). Returns, as a new geometry, exactly the primitives the view
 * would draw for a geometry if it were submitted now: same subdivision
 * style, same local-to-world transform, same camera and draw context (for
 * screen-space subdivision; a bounding loop without them subdivides as
 * QD3DView.h describes). Vertices are in the geometry's local coordinates,
 * untransformed.
 *
 * A NURB curve gives a PolyLine (a curve that subdivides to one point, a
 * polyline of two equal vertices); a polygon gives a TriMesh of its
 * triangulation, with the vertices' diffuse colours, transparency colours,
 * normals and surface uvs as vertex attribute arrays (an attributeUseArray
 * marks the vertices that have one, when not all do). The result's own
 * attribute set (polyLineAttributeSet, triMeshAttributeSet) is a new
 * reference to the geometry's, or NULL.
 *
 * Primitives (points, lines, polylines, triangles, trimeshes and markers) are drawn as
 * they are: for them the call returns NULL and posts nothing.
 *
 * @param geometry  the geometry to decompose.
 * @param view      a view inside a rendering or bounding loop, supplying the
 *                  current state.
 * @return a new PolyLine or TriMesh, or NULL on failure or for a primitive.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      geometry or view is NULL.
 *   kQ3ErrorInvalidObject      geometry or view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  geometry is not a geometry, or view is not a
 *                              view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   kQ3ErrorOutOfMemory        the polyline cannot be allocated.
 * Warnings:
 *   kQ3WarningParameterOutOfRange  the curve would need more than
 *                              kQ3SubdivisionMaxSegmentsPerCurve segments and
 *                              the polyline has that many.
 *
 * Ownership: the caller owns the one reference the new polyline is born with
 * and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Geometry_GetDecomposed(TQ3GeometryObject geometry,
                                                            TQ3ViewObject view);

/* ---- NURB curve --------------------------------------------------------- */

/* The highest order a NURB curve may have (order = degree + 1). */
#define kQ3NURBCurveMaxOrder 16

/*
 * A non-uniform rational B-spline curve.
 *   order          degree + 1, from 2 to kQ3NURBCurveMaxOrder.
 *   numPoints      the number of control points, at least order.
 *   controlPoints  numPoints homogeneous control points; the position of
 *                  each is (x/w, y/w, z/w) and w is its weight.
 *   knots          numPoints + order knot values.
 *   curveAttributeSet  attributes of the whole curve, or NULL.
 *
 * Q3 cannot see how long the arrays are: they must hold the counts above.
 *
 * The rules a TQ3NURBCurveData must obey wherever one is accepted
 * (Q3NURBCurve_New, Q3NURBCurve_SetData, Q3NURBCurve_Submit), with the error
 * posted when one is broken, checked in this order:
 *   2 <= order <= kQ3NURBCurveMaxOrder              kQ3ErrorParameterOutOfRange
 *   numPoints >= order                 kQ3ErrorGeometryInsufficientNumberOfPoints
 *   numPoints <= kQ3GeometryMaxArrayCount           kQ3ErrorParameterOutOfRange
 *   controlPoints and knots are not NULL            kQ3ErrorNULLParameter
 *   every coordinate, weight and knot is finite     kQ3ErrorInvalidData
 *   every weight w is greater than 0                kQ3ErrorInvalidData
 *   the knots never decrease                        kQ3ErrorInvalidData
 *   no knot value occurs more than order times at
 *     the start or at the end of the knot vector,
 *     or more than order - 1 times anywhere else    kQ3ErrorInvalidData
 *   curveAttributeSet is NULL or a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 *
 * Article-compatibility alias: "nurbCurveAttributes" is a second name for
 * curveAttributeSet, because the develop article's Listing 3 writes
 * "nurbCurveData->nurbCurveAttributes = NULL;" although QuickDraw 3D's field
 * was always curveAttributeSet. C99 has no anonymous unions, so the alias is
 * a macro that renames the identifier nurbCurveAttributes everywhere after
 * this header is included. Code that uses nurbCurveAttributes for anything
 * else can define Q3_NO_ARTICLE_ALIASES before including any Q3 header to
 * turn this alias (and TQ3RationalPoint4D_Set in QD3DMath.h) off.
 */
struct TQ3NURBCurveData {
    unsigned long order;
    unsigned long numPoints;
    TQ3RationalPoint4D *controlPoints;
    float *knots;
    TQ3AttributeSet curveAttributeSet;
};
typedef struct TQ3NURBCurveData TQ3NURBCurveData;

#ifndef Q3_NO_ARTICLE_ALIASES
#define nurbCurveAttributes curveAttributeSet
#endif

/**
 * Creates a retained NURB curve from a copy of the caller's description.
 *
 * @param curveData  the curve; it must obey the TQ3NURBCurveData rules above.
 *                   Its arrays are copied.
 * @return the new curve, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData is NULL.
 *   then the codes of the TQ3NURBCurveData rules, in their order:
 *   kQ3ErrorNULLParameter        controlPoints or knots is NULL.
 *   kQ3ErrorParameterOutOfRange  order is outside 2 to kQ3NURBCurveMaxOrder, or
 *                                the counts overflow a size_t.
 *   kQ3ErrorGeometryInsufficientNumberOfPoints  numPoints < order.
 *   kQ3ErrorInvalidData          a value is not finite, a weight is not
 *                                positive, the knots decrease, or a knot value
 *                                repeats more often than allowed.
 *   kQ3ErrorInvalidObject        curveAttributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curveAttributeSet is not an attribute set.
 *   kQ3ErrorOutOfMemory          the curve cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new curve is born with and
 * releases it with Q3Object_Dispose. The curve takes its own reference to
 * curveAttributeSet; the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3NURBCurve_New(const TQ3NURBCurveData *curveData);

/**
 * Draws (or bounds) a NURB curve described by a data structure without
 * creating an object (immediate mode), exactly as Q3Geometry_Submit would
 * draw a retained curve made from the same data.
 *
 * @param curveData  the curve; it must obey the TQ3NURBCurveData rules above.
 * @param view       a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curveData or view is NULL.
 *   kQ3ErrorInvalidObject        view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    view is not a view.
 *   kQ3ErrorViewNotStarted       view is not inside a rendering or bounding
 *                                loop.
 *   then the codes of the TQ3NURBCurveData rules, in their order:
 *   kQ3ErrorNULLParameter        controlPoints or knots is NULL.
 *   kQ3ErrorParameterOutOfRange  order is outside 2 to kQ3NURBCurveMaxOrder, or
 *                                the counts overflow a size_t.
 *   kQ3ErrorGeometryInsufficientNumberOfPoints  numPoints < order.
 *   kQ3ErrorInvalidData          a value is not finite, a weight is not
 *                                positive, the knots decrease, or a knot value
 *                                repeats more often than allowed.
 *   kQ3ErrorInvalidObject        curveAttributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curveAttributeSet is not an attribute set.
 *   kQ3ErrorOutOfMemory          the subdivided curve cannot be allocated.
 * Warnings:
 *   kQ3WarningParameterOutOfRange  the curve would need more than
 *                                kQ3SubdivisionMaxSegmentsPerCurve segments
 *                                and is drawn with that many.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_Submit(const TQ3NURBCurveData *curveData,
                                              TQ3ViewObject view);

/**
 * Replaces the whole description of a retained NURB curve; the only way to
 * change its order or number of control points.
 *
 * @param curve          the curve to change.
 * @param nurbCurveData  the new curve; it must obey the TQ3NURBCurveData
 *                       rules above. Its arrays are copied.
 * @return kQ3Success, or kQ3Failure with the curve unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve or nurbCurveData is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   then the codes of the TQ3NURBCurveData rules, in their order:
 *   kQ3ErrorNULLParameter        controlPoints or knots is NULL.
 *   kQ3ErrorParameterOutOfRange  order is outside 2 to kQ3NURBCurveMaxOrder, or
 *                                the counts overflow a size_t.
 *   kQ3ErrorGeometryInsufficientNumberOfPoints  numPoints < order.
 *   kQ3ErrorInvalidData          a value is not finite, a weight is not
 *                                positive, the knots decrease, or a knot value
 *                                repeats more often than allowed.
 *   kQ3ErrorInvalidObject        curveAttributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curveAttributeSet is not an attribute set.
 *   kQ3ErrorOutOfMemory          the copy cannot be allocated.
 *
 * Ownership: the curve takes a reference to the new curveAttributeSet and
 * releases the one it held; the caller keeps its own references.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_SetData(TQ3GeometryObject curve,
                                               const TQ3NURBCurveData *nurbCurveData);

/**
 * Copies the whole description of a retained NURB curve into caller memory
 * allocated by Q3. Release it with Q3NURBCurve_EmptyData.
 *
 * @param curve          the curve to read.
 * @param nurbCurveData  receives order, numPoints, newly allocated copies of
 *                       the control point and knot arrays, and the attribute
 *                       set (or NULL).
 * @return kQ3Success, or kQ3Failure with *nurbCurveData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      curve or nurbCurveData is NULL.
 *   kQ3ErrorInvalidObject      curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  curve is not a NURB curve.
 *   kQ3ErrorOutOfMemory        the arrays cannot be allocated.
 *
 * Ownership: the caller owns the two arrays and one new reference to the
 * attribute set, and gives them all back with Q3NURBCurve_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_GetData(TQ3GeometryObject curve,
                                               TQ3NURBCurveData *nurbCurveData);

/**
 * Releases what Q3NURBCurve_GetData put in a TQ3NURBCurveData: frees both
 * arrays, disposes the attribute set reference, and sets controlPoints,
 * knots and curveAttributeSet to NULL (order and numPoints are left alone).
 * Calling it again on the emptied structure does nothing and succeeds.
 * Use it only on data filled by Q3NURBCurve_GetData or by a curve tool of
 * Q3NURBCurveTools.h: arrays the caller allocated itself must be freed by the
 * caller.
 *
 * @param nurbCurveData  the structure to empty.
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   nurbCurveData is NULL.
 *
 * Ownership: consumes the attribute set reference held in the structure.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_EmptyData(TQ3NURBCurveData *nurbCurveData);

/**
 * Replaces one control point of a retained NURB curve.
 *
 * @param curve       the curve to change.
 * @param pointIndex  which control point, from 0 to numPoints - 1.
 * @param point4D     the new homogeneous control point; its coordinates must
 *                    be finite and its weight w greater than 0.
 * @return kQ3Success, or kQ3Failure with the curve unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve or point4D is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   kQ3ErrorParameterOutOfRange  pointIndex >= numPoints.
 *   kQ3ErrorInvalidParameter     a coordinate of *point4D is not finite, or its
 *                                w is not greater than 0.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_SetControlPoint(TQ3GeometryObject curve,
                                                       unsigned long pointIndex,
                                                       const TQ3RationalPoint4D *point4D);

/**
 * Reads one control point of a retained NURB curve.
 *
 * @param curve       the curve to read.
 * @param pointIndex  which control point, from 0 to numPoints - 1.
 * @param point4D     receives the homogeneous control point.
 * @return kQ3Success, or kQ3Failure with *point4D unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve or point4D is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   kQ3ErrorParameterOutOfRange  pointIndex >= numPoints.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_GetControlPoint(TQ3GeometryObject curve,
                                                       unsigned long pointIndex,
                                                       TQ3RationalPoint4D *point4D);

/**
 * Replaces one knot of a retained NURB curve. The knot vector that results
 * must still obey the knot rules of TQ3NURBCurveData (finite, never
 * decreasing, no value repeated too often).
 *
 * @param curve      the curve to change.
 * @param knotIndex  which knot, from 0 to numPoints + order - 1.
 * @param knotValue  the new value.
 * @return kQ3Success, or kQ3Failure with the curve unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   kQ3ErrorParameterOutOfRange  knotIndex >= numPoints + order.
 *   kQ3ErrorInvalidParameter     knotValue is not finite, is less than the
 *                                knot before it or greater than the knot after
 *                                it, or would repeat a value more often than
 *                                allowed.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_SetKnot(TQ3GeometryObject curve,
                                               unsigned long knotIndex,
                                               float knotValue);

/**
 * Reads one knot of a retained NURB curve.
 *
 * @param curve      the curve to read.
 * @param knotIndex  which knot, from 0 to numPoints + order - 1.
 * @param knotValue  receives the knot value.
 * @return kQ3Success, or kQ3Failure with *knotValue unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        curve or knotValue is NULL.
 *   kQ3ErrorInvalidObject        curve is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    curve is not a NURB curve.
 *   kQ3ErrorParameterOutOfRange  knotIndex >= numPoints + order.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBCurve_GetKnot(TQ3GeometryObject curve,
                                               unsigned long knotIndex,
                                               float *knotValue);

/* ---- NURB patch --------------------------------------------------------- */

/* The highest order a NURB patch may have in u or in v (order = degree + 1). */
#define kQ3NURBPatchMaxOrder 11

/*
 * A non-uniform rational B-spline surface, optionally trimmed by loops of
 * two-dimensional NURB curves in its parameter domain.
 *
 * Layout (Q3's reading where Apple's documents disagree: the one Apple's
 * declarations and files in the wild follow). The control points form
 * numRows rows of numColumns points:
 *   controlPoints[row * numColumns + column]
 * u runs along a row (from column to column), v across the rows (from row to
 * row). So numColumns counts the points in u and numRows those in v:
 *   uKnots  uOrder + numColumns knots;
 *   vKnots  vOrder + numRows knots.
 * Each control point is homogeneous and pre-multiplied, as for curves: its
 * position is (x/w, y/w, z/w) and w is its weight. The surface is defined on
 * the domain [uKnots[uOrder - 1], uKnots[numColumns]] x
 * [vKnots[vOrder - 1], vKnots[numRows]].
 *
 * A trim curve is a NURB curve in that (u, v) domain: its control points are
 * TQ3RationalPoint3D (x, y, w), homogeneous like the patch's, the point
 * (x/w, y/w) being (u, v); it has numPoints + order knots. A trim loop is one
 * or more trim curves joined end to end: each curve ends where the next one
 * starts, and the last ends where the first starts.
 *
 * The trim rule (GLU's, since no Apple document defines an orientation):
 * the region to the left of a loop is kept. A counterclockwise loop (in the
 * (u, v) plane, u to the right and v up) keeps its inside; a clockwise loop
 * cuts a hole. Precisely: a point of the domain is drawn when the innermost
 * loop around it runs counterclockwise; a point that no loop surrounds is
 * drawn when no outermost loop runs counterclockwise (so a lone clockwise
 * loop cuts a hole in the whole patch, and a lone counterclockwise loop
 * keeps only its inside). With no trim loops the whole domain is drawn.
 * Loops may touch the edges of the domain but must not cross or touch each
 * other or themselves (see "Crossing loops" below).
 *
 * The rules a TQ3NURBPatchData must obey wherever one is accepted
 * (Q3NURBPatch_New, Q3NURBPatch_SetData, Q3NURBPatch_Submit), with the error
 * posted when one is broken, checked in this order. The message names the
 * rule, where (e.g. "trimLoops[1].trimCurves[0].knots[5]") and the values.
 *   2 <= uOrder, vOrder <= kQ3NURBPatchMaxOrder     kQ3ErrorParameterOutOfRange
 *   numColumns >= uOrder, numRows >= vOrder
 *                                  kQ3ErrorGeometryInsufficientNumberOfPoints
 *   numRows * numColumns, uOrder + numColumns, vOrder + numRows and
 *     numTrimLoops <= kQ3GeometryMaxArrayCount      kQ3ErrorParameterOutOfRange
 *   controlPoints, uKnots and vKnots are not NULL,
 *     nor trimLoops when numTrimLoops > 0           kQ3ErrorNULLParameter
 *   every knot is finite; the knots never decrease; no knot value occurs
 *     more than order times at the start or at the end of its vector or
 *     more than order - 1 times anywhere else; the domain is not empty
 *     (uKnots first, then vKnots)                   kQ3ErrorInvalidData
 *   every coordinate and weight is finite, and every weight is greater
 *     than 0                                        kQ3ErrorInvalidData
 *   then each trim loop in turn, and in it each trim curve in turn:
 *   numTrimCurves >= 1                              kQ3ErrorInvalidData
 *   numTrimCurves <= kQ3GeometryMaxArrayCount       kQ3ErrorParameterOutOfRange
 *   trimCurves is not NULL                          kQ3ErrorNULLParameter
 *   2 <= order <= kQ3NURBCurveMaxOrder              kQ3ErrorParameterOutOfRange
 *   numPoints >= order                 kQ3ErrorGeometryInsufficientNumberOfPoints
 *   numPoints <= kQ3GeometryMaxArrayCount           kQ3ErrorParameterOutOfRange
 *   controlPoints and knots are not NULL            kQ3ErrorNULLParameter
 *   the knot rules above, for the curve's one knot vector
 *                                                   kQ3ErrorInvalidData
 *   every coordinate and weight finite, every weight greater than 0
 *                                                   kQ3ErrorInvalidData
 *   every control point (x/w, y/w) lies in the patch's domain, within the
 *     tolerance below (so the whole curve does)     kQ3ErrorInvalidData
 *   after the loop's curves: each curve ends within the tolerance of where
 *     the next one starts, the last of where the first starts
 *                                                   kQ3ErrorInvalidData
 *   patchAttributeSet is NULL or a live attribute set
 *                           kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 * The tolerance is 1e-5 times the largest of the domain's width, its height
 * and the magnitudes of its four end knots. A curve's start and end are its
 * points at the ends of its domain (its first and last control points when
 * its end knots repeat order times). Where a curve ends and the next starts
 * a little apart, the loop is drawn through the next curve's start.
 *
 * Crossing loops. Whether loops cross or touch each other or themselves is
 * not checked by New, SetData or Submit (an exact test would mean
 * intersecting the curves). It is found when the patch is subdivided, on the
 * polylines the loops are drawn with: Q3Geometry_Submit, Q3NURBPatch_Submit
 * and Q3Geometry_GetDecomposed then fail with kQ3ErrorInvalidData, naming
 * the loops and where in (u, v), and nothing of the patch is drawn. Because
 * the polylines depend on the subdivision style, loops that only come very
 * close may be refused under a coarse style and drawn under a fine one.
 *
 * Subdivision (QD3DStyle.h; docs/subdivision.md, "Surfaces"):
 *   kQ3SubdivisionMethodConstant  c1 segments across every non-empty knot
 *     span in u and c2 across every one in v (whole numbers; a fraction is
 *     dropped), at evenly spaced parameters: each pair of spans is a c1 x c2
 *     grid of quadrilaterals, each cut into two triangles along its shorter
 *     diagonal. Trim curves get c1 segments per span. Apple's book reads c1
 *     and c2 as counts for the whole mesh; Q3 counts them per span, as the
 *     develop article does for curves ("CONTROLLING SUBDIVISION") and as Q3's
 *     curves do, because then (1) an edge of the patch is subdivided exactly
 *     like the NURB curve with the same control points and knots under the
 *     same style, so curves drawn along a patch's edge meet it, and (2)
 *     every knot line is a line of the mesh, so a crease where knots repeat
 *     is never cut across.
 *   kQ3SubdivisionMethodWorldSpace  no triangle edge is longer than c1 world
 *     units, measured between its two vertices after the local-to-world
 *     transform.
 *   kQ3SubdivisionMethodScreenSpace  no triangle edge is longer than c1
 *     pixels, measured after the full transform to the pane, perspective
 *     divide included; for an edge that reaches nearer than the camera's
 *     hither plane, the part that is drawn.
 *   Trim curves are subdivided to the same bound, measured on the surface.
 *   c2 is not used by world and screen space.
 * Every vertex is a point of the surface: the surface evaluated in double
 * precision at a parameter (u, v) and rounded to float once; every vertex on
 * the edge of a trimmed region is a point of a trim curve. Each vertex has
 * the unit normal of the surface there, from its exact partial derivatives
 * (pointing to the side from which increasing u turns towards increasing v
 * counterclockwise; at a point where the derivatives vanish, such as a pole,
 * the normal a short step inside the domain), and its surface uv, the (u, v)
 * of the domain. The front of every triangle is the side its normal points
 * to. No patch is drawn with more than kQ3SubdivisionMaxTrianglesPerPatch
 * triangles (QD3DStyle.h), except that every pair of spans gets at least
 * two: a patch that would need more is drawn with longer edges (or fewer
 * segments per span) and posts kQ3WarningParameterOutOfRange.
 *
 * Bounds: a bounding loop bounds the control points (x/w, y/w, z/w), which
 * the surface never leaves, as for NURB curves.
 *
 * Q3Geometry_GetDecomposed gives a TriMesh of the triangles with the normals
 * and surface uvs as vertex attribute arrays.
 */
struct TQ3NURBPatchTrimCurveData {
    unsigned long order;
    unsigned long numPoints;
    TQ3RationalPoint3D *controlPoints;
    float *knots;
};
typedef struct TQ3NURBPatchTrimCurveData TQ3NURBPatchTrimCurveData;

struct TQ3NURBPatchTrimLoopData {
    unsigned long numTrimCurves;
    TQ3NURBPatchTrimCurveData *trimCurves;
};
typedef struct TQ3NURBPatchTrimLoopData TQ3NURBPatchTrimLoopData;

struct TQ3NURBPatchData {
    unsigned long uOrder;
    unsigned long vOrder;
    unsigned long numRows;
    unsigned long numColumns;
    TQ3RationalPoint4D *controlPoints;
    float *uKnots;
    float *vKnots;
    unsigned long numTrimLoops;
    TQ3NURBPatchTrimLoopData *trimLoops;
    TQ3AttributeSet patchAttributeSet;
};
typedef struct TQ3NURBPatchData TQ3NURBPatchData;

/**
 * Creates a retained NURB patch from a copy of the caller's description
 * (every array, trim loops and trim curves included).
 *
 * @param nurbPatchData  the patch; it must obey the TQ3NURBPatchData rules
 *                       above.
 * @return the new patch, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      nurbPatchData is NULL.
 *   then the codes of the TQ3NURBPatchData rules, in their order;
 *   kQ3ErrorOutOfMemory        the patch cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new patch is born with
 * and releases it with Q3Object_Dispose. The patch takes its own reference
 * to patchAttributeSet; the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3NURBPatch_New(const TQ3NURBPatchData *nurbPatchData);

/**
 * Draws (or bounds) a NURB patch described by a data structure without
 * creating an object (immediate mode), exactly as Q3Geometry_Submit draws a
 * retained patch made from the same data.
 *
 * @param nurbPatchData  the patch; it must obey the TQ3NURBPatchData rules.
 * @param view           a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      nurbPatchData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding
 *                              loop.
 *   then the codes of the TQ3NURBPatchData rules, in their order;
 *   kQ3ErrorInvalidData        the trim loops cross or touch (see "Crossing
 *                              loops" above).
 *   kQ3ErrorOutOfMemory        the triangles cannot be allocated.
 * Warnings:
 *   kQ3WarningParameterOutOfRange  the patch would need more than
 *                              kQ3SubdivisionMaxTrianglesPerPatch triangles
 *                              and is drawn with fewer, longer-edged ones.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBPatch_Submit(const TQ3NURBPatchData *nurbPatchData, TQ3ViewObject view);

/**
 * Replaces the whole description of a retained NURB patch; the only way to
 * change its orders, its numbers of control points or its trim loops.
 *
 * @param nurbPatch      the patch to change.
 * @param nurbPatchData  the new patch; it must obey the TQ3NURBPatchData
 *                       rules. Every array is copied.
 * @return kQ3Success, or kQ3Failure with the patch and its edit index
 *         unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      nurbPatch or nurbPatchData is NULL.
 *   kQ3ErrorInvalidObject      nurbPatch is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  nurbPatch is not a NURB patch.
 *   then the codes of the TQ3NURBPatchData rules, in their order;
 *   kQ3ErrorOutOfMemory        the copy cannot be allocated.
 *
 * Ownership: the patch takes a reference to the new patchAttributeSet and
 * releases the one it held; the caller keeps its own references.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBPatch_SetData(TQ3GeometryObject nurbPatch,
                                               const TQ3NURBPatchData *nurbPatchData);

/**
 * Copies the whole description of a retained NURB patch into caller memory
 * allocated by Q3: the control points, both knot vectors and every trim
 * loop with its trim curves and their arrays. Release it with
 * Q3NURBPatch_EmptyData.
 *
 * @param nurbPatch      the patch to read.
 * @param nurbPatchData  receives the description.
 * @return kQ3Success, or kQ3Failure with *nurbPatchData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      nurbPatch or nurbPatchData is NULL.
 *   kQ3ErrorInvalidObject      nurbPatch is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  nurbPatch is not a NURB patch.
 *   kQ3ErrorOutOfMemory        the arrays cannot be allocated.
 *
 * Ownership: the caller owns every array and one new reference to the
 * attribute set, and gives them all back with Q3NURBPatch_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBPatch_GetData(TQ3GeometryObject nurbPatch, TQ3NURBPatchData *nurbPatchData);

/**
 * Replaces the control point in row rowIndex and column columnIndex of a
 * retained NURB patch (controlPoints[rowIndex * numColumns + columnIndex]).
 *
 * @param nurbPatch    the patch to change.
 * @param rowIndex     the row, from 0 to numRows - 1.
 * @param columnIndex  the column, from 0 to numColumns - 1.
 * @param point4D      the new homogeneous control point; its coordinates
 *                     must be finite and its weight w greater than 0.
 * @return kQ3Success, or kQ3Failure with the patch and its edit index
 *         unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        nurbPatch or point4D is NULL.
 *   kQ3ErrorInvalidObject        nurbPatch is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    nurbPatch is not a NURB patch.
 *   kQ3ErrorParameterOutOfRange  rowIndex >= numRows or
 *                                columnIndex >= numColumns.
 *   kQ3ErrorInvalidParameter     a coordinate of *point4D is not finite, or
 *                                its w is not greater than 0.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBPatch_SetControlPoint(TQ3GeometryObject nurbPatch, unsigned long rowIndex,
                                                       unsigned long columnIndex, const TQ3RationalPoint4D *point4D);

/**
 * Reads the control point in row rowIndex and column columnIndex of a
 * retained NURB patch.
 *
 * @param nurbPatch    the patch to read.
 * @param rowIndex     the row, from 0 to numRows - 1.
 * @param columnIndex  the column, from 0 to numColumns - 1.
 * @param point4D      receives the homogeneous control point.
 * @return kQ3Success, or kQ3Failure with *point4D unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        nurbPatch or point4D is NULL.
 *   kQ3ErrorInvalidObject        nurbPatch is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    nurbPatch is not a NURB patch.
 *   kQ3ErrorParameterOutOfRange  rowIndex >= numRows or
 *                                columnIndex >= numColumns.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBPatch_GetControlPoint(TQ3GeometryObject nurbPatch, unsigned long rowIndex,
                                                       unsigned long columnIndex, TQ3RationalPoint4D *point4D);

/**
 * Replaces one knot of the u knot vector of a retained NURB patch. The patch
 * that results must still obey every TQ3NURBPatchData rule that involves the
 * u knots: finite, never decreasing, no value repeated too often, a
 * non-empty domain, and every trim curve inside the domain.
 *
 * @param nurbPatch  the patch to change.
 * @param knotIndex  which knot, from 0 to uOrder + numColumns - 1.
 * @param knotValue  the new value.
 * @return kQ3Success, or kQ3Failure with the patch and its edit index
 *         unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        nurbPatch is NULL.
 *   kQ3ErrorInvalidObject        nurbPatch is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    nurbPatch is not a NURB patch.
 *   kQ3ErrorParameterOutOfRange  knotIndex >= uOrder + numColumns.
 *   kQ3ErrorInvalidParameter     the new value breaks one of those rules (the
 *                                message says which).
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBPatch_SetUKnot(TQ3GeometryObject nurbPatch, unsigned long knotIndex,
                                                float knotValue);

/**
 * Replaces one knot of the v knot vector of a retained NURB patch, under the
 * same conditions as Q3NURBPatch_SetUKnot.
 *
 * @param nurbPatch  the patch to change.
 * @param knotIndex  which knot, from 0 to vOrder + numRows - 1.
 * @param knotValue  the new value.
 * @return kQ3Success, or kQ3Failure with the patch and its edit index
 *         unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        nurbPatch is NULL.
 *   kQ3ErrorInvalidObject        nurbPatch is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    nurbPatch is not a NURB patch.
 *   kQ3ErrorParameterOutOfRange  knotIndex >= vOrder + numRows.
 *   kQ3ErrorInvalidParameter     the new value breaks a rule (the message
 *                                says which).
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBPatch_SetVKnot(TQ3GeometryObject nurbPatch, unsigned long knotIndex,
                                                float knotValue);

/**
 * Reads one knot of the u knot vector of a retained NURB patch.
 *
 * @param nurbPatch  the patch to read.
 * @param knotIndex  which knot, from 0 to uOrder + numColumns - 1.
 * @param knotValue  receives the knot value.
 * @return kQ3Success, or kQ3Failure with *knotValue unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        nurbPatch or knotValue is NULL.
 *   kQ3ErrorInvalidObject        nurbPatch is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    nurbPatch is not a NURB patch.
 *   kQ3ErrorParameterOutOfRange  knotIndex >= uOrder + numColumns.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBPatch_GetUKnot(TQ3GeometryObject nurbPatch, unsigned long knotIndex,
                                                float *knotValue);

/**
 * Reads one knot of the v knot vector of a retained NURB patch.
 *
 * @param nurbPatch  the patch to read.
 * @param knotIndex  which knot, from 0 to vOrder + numRows - 1.
 * @param knotValue  receives the knot value.
 * @return kQ3Success, or kQ3Failure with *knotValue unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        nurbPatch or knotValue is NULL.
 *   kQ3ErrorInvalidObject        nurbPatch is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    nurbPatch is not a NURB patch.
 *   kQ3ErrorParameterOutOfRange  knotIndex >= vOrder + numRows.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBPatch_GetVKnot(TQ3GeometryObject nurbPatch, unsigned long knotIndex,
                                                float *knotValue);

/**
 * Releases what Q3NURBPatch_GetData put in a TQ3NURBPatchData: frees the
 * control points, both knot vectors and every trim loop with its curves'
 * arrays, disposes the attribute set reference, and sets the pointers to
 * NULL (the counts are left alone). Calling it again on the emptied
 * structure does nothing and succeeds. Use it only on data filled by
 * Q3NURBPatch_GetData: arrays the caller allocated itself must be freed by
 * the caller.
 *
 * @param nurbPatchData  the structure to empty.
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      nurbPatchData is NULL.
 *   kQ3ErrorInvalidObject      patchAttributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  patchAttributeSet is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NURBPatch_EmptyData(TQ3NURBPatchData *nurbPatchData);

/* ---- PolyLine ----------------------------------------------------------- */

/*
 * A connected sequence of line segments.
 *   numVertices          at least 2.
 *   vertices             numVertices points, each with an attribute set or
 *                        NULL.
 *   segmentAttributeSet  NULL, or numVertices - 1 attribute sets (entries may
 *                        be NULL); entry i belongs to the segment from vertex
 *                        i to vertex i + 1.
 *   polyLineAttributeSet attributes of the whole polyline, or NULL.
 *
 * The rules a TQ3PolyLineData must obey wherever one is accepted, with the
 * error posted when one is broken, checked in this order:
 *   vertices is not NULL                            kQ3ErrorNULLParameter
 *   numVertices >= 2                   kQ3ErrorGeometryInsufficientNumberOfPoints
 *   every coordinate is finite                      kQ3ErrorInvalidData
 *   every attribute set given is a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 */
struct TQ3PolyLineData {
    unsigned long numVertices;
    TQ3Vertex3D *vertices;
    TQ3AttributeSet *segmentAttributeSet;
    TQ3AttributeSet polyLineAttributeSet;
};
typedef struct TQ3PolyLineData TQ3PolyLineData;

/**
 * Creates a retained polyline from a copy of the caller's description.
 *
 * @param polylineData  the polyline; it must obey the TQ3PolyLineData rules
 *                      above. Its arrays are copied.
 * @return the new polyline, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polylineData is NULL.
 *   then the codes of the TQ3PolyLineData rules, in their order:
 *   kQ3ErrorNULLParameter      vertices is NULL.
 *   kQ3ErrorGeometryInsufficientNumberOfPoints  numVertices < 2.
 *   kQ3ErrorInvalidData        a coordinate is not finite.
 *   kQ3ErrorInvalidObject      an attribute set given is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set given is not an attribute set.
 *   kQ3ErrorOutOfMemory        the polyline cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new polyline is born with
 * and releases it with Q3Object_Dispose. The polyline takes its own
 * reference to every attribute set given; the caller keeps its references.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3PolyLine_New(const TQ3PolyLineData *polylineData);

/**
 * Draws (or bounds) a polyline described by a data structure without
 * creating an object (immediate mode).
 *
 * @param polyLineData  the polyline; it must obey the TQ3PolyLineData rules
 *                      above.
 * @param view          a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polyLineData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3PolyLineData rules, in their order:
 *   kQ3ErrorNULLParameter      vertices is NULL.
 *   kQ3ErrorGeometryInsufficientNumberOfPoints  numVertices < 2.
 *   kQ3ErrorInvalidData        a coordinate is not finite.
 *   kQ3ErrorInvalidObject      an attribute set given is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set given is not an attribute set.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PolyLine_Submit(const TQ3PolyLineData *polyLineData,
                                             TQ3ViewObject view);

/**
 * Replaces the whole description of a retained polyline.
 *
 * @param polyLine      the polyline to change.
 * @param polyLineData  the new polyline; it must obey the TQ3PolyLineData
 *                      rules above. Its arrays are copied.
 * @return kQ3Success, or kQ3Failure with the polyline unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polyLine or polyLineData is NULL.
 *   kQ3ErrorInvalidObject      polyLine is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  polyLine is not a polyline.
 *   then the codes of the TQ3PolyLineData rules, in their order:
 *   kQ3ErrorNULLParameter      vertices is NULL.
 *   kQ3ErrorGeometryInsufficientNumberOfPoints  numVertices < 2.
 *   kQ3ErrorInvalidData        a coordinate is not finite.
 *   kQ3ErrorInvalidObject      an attribute set given is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set given is not an attribute set.
 *   kQ3ErrorOutOfMemory        the copy cannot be allocated.
 *
 * Ownership: the polyline takes references to the attribute sets given and
 * releases those it held; the caller keeps its own references.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PolyLine_SetData(TQ3GeometryObject polyLine,
                                              const TQ3PolyLineData *polyLineData);

/**
 * Copies the whole description of a retained polyline into caller memory
 * allocated by Q3. Release it with Q3PolyLine_EmptyData.
 *
 * @param polyLine      the polyline to read.
 * @param polyLineData  receives numVertices, a newly allocated vertex array,
 *                      a newly allocated segment attribute array if the
 *                      polyline was given one (else NULL) and the polyline
 *                      attribute set (or NULL).
 * @return kQ3Success, or kQ3Failure with *polyLineData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polyLine or polyLineData is NULL.
 *   kQ3ErrorInvalidObject      polyLine is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  polyLine is not a polyline.
 *   kQ3ErrorOutOfMemory        the arrays cannot be allocated.
 *
 * Ownership: the caller owns the arrays and one new reference to every
 * attribute set in the result, and gives them all back with
 * Q3PolyLine_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PolyLine_GetData(TQ3GeometryObject polyLine,
                                              TQ3PolyLineData *polyLineData);

/**
 * Releases what Q3PolyLine_GetData put in a TQ3PolyLineData: disposes every
 * attribute set reference, frees both arrays, and sets vertices,
 * segmentAttributeSet and polyLineAttributeSet to NULL (numVertices is left
 * alone). Calling it again on the emptied structure does nothing and
 * succeeds. Use it only on data filled by Q3PolyLine_GetData.
 *
 * @param polyLineData  the structure to empty.
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   polyLineData is NULL.
 *
 * Ownership: consumes the attribute set references held in the structure.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PolyLine_EmptyData(TQ3PolyLineData *polyLineData);

/**
 * Reads the position of one vertex of a retained polyline.
 *
 * @param polyLine  the polyline to read.
 * @param index     which vertex, from 0 to numVertices - 1.
 * @param position  receives the vertex's position.
 * @return kQ3Success, or kQ3Failure with *position unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyLine or position is NULL.
 *   kQ3ErrorInvalidObject        polyLine is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polyLine is not a polyline.
 *   kQ3ErrorParameterOutOfRange  index >= numVertices.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PolyLine_GetVertexPosition(TQ3GeometryObject polyLine,
                                                        unsigned long index,
                                                        TQ3Point3D *position);

/**
 * Moves one vertex of a retained polyline, keeping its attribute set.
 *
 * @param polyLine  the polyline to change.
 * @param index     which vertex, from 0 to numVertices - 1.
 * @param position  the new position; its coordinates must be finite, as the
 *                  TQ3PolyLineData rules require.
 * @return kQ3Success, or kQ3Failure with the polyline unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyLine or position is NULL.
 *   kQ3ErrorInvalidObject        polyLine is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polyLine is not a polyline.
 *   kQ3ErrorParameterOutOfRange  index >= numVertices.
 *   kQ3ErrorInvalidData          a coordinate of *position is not finite (the
 *                                code Q3PolyLine_New and _SetData post).
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PolyLine_SetVertexPosition(TQ3GeometryObject polyLine,
                                                        unsigned long index,
                                                        const TQ3Point3D *position);

/**
 * Reads the attribute set of one vertex of a retained polyline.
 *
 * @param polyLine      the polyline to read.
 * @param index         which vertex, from 0 to numVertices - 1.
 * @param attributeSet  receives the vertex's attribute set, or NULL when it
 *                      has none (still kQ3Success).
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyLine or attributeSet is NULL.
 *   kQ3ErrorInvalidObject        polyLine is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polyLine is not a polyline.
 *   kQ3ErrorParameterOutOfRange  index >= numVertices.
 *
 * Ownership: when *attributeSet is not NULL the caller owns a new reference
 * to it and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PolyLine_GetVertexAttributeSet(TQ3GeometryObject polyLine,
                                                            unsigned long index,
                                                            TQ3AttributeSet *attributeSet);

/**
 * Replaces the attribute set of one vertex of a retained polyline.
 *
 * @param polyLine      the polyline to change.
 * @param index         which vertex, from 0 to numVertices - 1.
 * @param attributeSet  the new attribute set, or NULL to remove the vertex's.
 * @return kQ3Success, or kQ3Failure with the polyline unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyLine is NULL.
 *   kQ3ErrorInvalidObject        polyLine or attributeSet is not a live Q3
 *                                object.
 *   kQ3ErrorInvalidObjectType    polyLine is not a polyline, or attributeSet
 *                                is not an attribute set.
 *   kQ3ErrorParameterOutOfRange  index >= numVertices.
 *
 * Ownership: the polyline takes a reference to attributeSet and releases the
 * one the vertex held; the caller keeps its own reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PolyLine_SetVertexAttributeSet(TQ3GeometryObject polyLine,
                                                            unsigned long index,
                                                            TQ3AttributeSet attributeSet);

/**
 * Reads the attribute set of one segment of a retained polyline: segment i
 * runs from vertex i to vertex i + 1.
 *
 * @param polyLine      the polyline to read.
 * @param index         which segment, from 0 to numVertices - 2.
 * @param attributeSet  receives the segment's attribute set, or NULL when it
 *                      has none or the polyline has no segment attribute
 *                      sets at all (still kQ3Success).
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyLine or attributeSet is NULL.
 *   kQ3ErrorInvalidObject        polyLine is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polyLine is not a polyline.
 *   kQ3ErrorParameterOutOfRange  index >= numVertices - 1.
 *
 * Ownership: when *attributeSet is not NULL the caller owns a new reference
 * to it and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PolyLine_GetSegmentAttributeSet(TQ3GeometryObject polyLine,
                                                             unsigned long index,
                                                             TQ3AttributeSet *attributeSet);

/**
 * Replaces the attribute set of one segment of a retained polyline: segment
 * i runs from vertex i to vertex i + 1. A polyline made without a segment
 * array gains one when a segment is given a set (the other entries NULL), so
 * Q3PolyLine_GetData then returns a segmentAttributeSet array; removing a set
 * (NULL) from such a polyline leaves it without one.
 *
 * @param polyLine      the polyline to change.
 * @param index         which segment, from 0 to numVertices - 2.
 * @param attributeSet  the new attribute set, or NULL to remove the segment's.
 * @return kQ3Success, or kQ3Failure with the polyline unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyLine is NULL.
 *   kQ3ErrorInvalidObject        polyLine or attributeSet is not a live Q3
 *                                object.
 *   kQ3ErrorInvalidObjectType    polyLine is not a polyline, or attributeSet
 *                                is not an attribute set.
 *   kQ3ErrorParameterOutOfRange  index >= numVertices - 1.
 *   kQ3ErrorOutOfMemory          the segment array cannot be allocated.
 *
 * Ownership: the polyline takes a reference to attributeSet and releases the
 * one the segment held; the caller keeps its own reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PolyLine_SetSegmentAttributeSet(TQ3GeometryObject polyLine,
                                                             unsigned long index,
                                                             TQ3AttributeSet attributeSet);

/* ---- Line --------------------------------------------------------------- */

/*
 * A single line segment between two vertices, each with an attribute set or
 * NULL, plus an attribute set for the whole line or NULL.
 *
 * The rules a TQ3LineData must obey wherever one is accepted, with the error
 * posted when one is broken, checked in this order:
 *   every coordinate is finite                      kQ3ErrorInvalidData
 *   every attribute set given is a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 */
struct TQ3LineData {
    TQ3Vertex3D vertices[2];
    TQ3AttributeSet lineAttributeSet;
};
typedef struct TQ3LineData TQ3LineData;

/**
 * Creates a retained line from a copy of the caller's description.
 *
 * @param lineData  the line; it must obey the TQ3LineData rules above.
 * @return the new line, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      lineData is NULL.
 *   then the codes of the TQ3LineData rules, in their order:
 *   kQ3ErrorInvalidData        a coordinate is not finite.
 *   kQ3ErrorInvalidObject      an attribute set given is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set given is not an attribute set.
 *   kQ3ErrorOutOfMemory        the line cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new line is born with and
 * releases it with Q3Object_Dispose. The line takes its own reference to
 * every attribute set given; the caller keeps its references.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Line_New(const TQ3LineData *lineData);

/**
 * Draws (or bounds) a line described by a data structure without creating
 * an object (immediate mode).
 *
 * @param lineData  the line; it must obey the TQ3LineData rules above.
 * @param view      a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      lineData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3LineData rules, in their order:
 *   kQ3ErrorInvalidData        a coordinate is not finite.
 *   kQ3ErrorInvalidObject      an attribute set given is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set given is not an attribute set.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Line_Submit(const TQ3LineData *lineData, TQ3ViewObject view);

/**
 * Copies the description of a retained line.
 *
 * @param line      the line to read.
 * @param lineData  receives both vertices and the attribute sets (or NULL).
 * @return kQ3Success, or kQ3Failure with *lineData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      line or lineData is NULL.
 *   kQ3ErrorInvalidObject      line is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  line is not a line.
 *
 * Ownership: the caller owns one new reference to every attribute set in the
 * result and gives them back with Q3Line_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Line_GetData(TQ3GeometryObject line, TQ3LineData *lineData);

/**
 * Replaces the description of a retained line.
 *
 * @param line      the line to change.
 * @param lineData  the new line; it must obey the TQ3LineData rules above.
 * @return kQ3Success, or kQ3Failure with the line unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      line or lineData is NULL.
 *   kQ3ErrorInvalidObject      line is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  line is not a line.
 *   then the codes of the TQ3LineData rules, in their order:
 *   kQ3ErrorInvalidData        a coordinate is not finite.
 *   kQ3ErrorInvalidObject      an attribute set given is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set given is not an attribute set.
 *
 * Ownership: the line takes references to the attribute sets given and
 * releases those it held; the caller keeps its own references.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Line_SetData(TQ3GeometryObject line, const TQ3LineData *lineData);

/**
 * Releases what Q3Line_GetData put in a TQ3LineData: disposes the three
 * attribute set references and sets them to NULL. Calling it again on the
 * emptied structure does nothing and succeeds.
 *
 * @param lineData  the structure to empty.
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   lineData is NULL.
 *
 * Ownership: consumes the attribute set references held in the structure.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Line_EmptyData(TQ3LineData *lineData);

/**
 * Reads the position of one end of a retained line.
 *
 * @param line      the line to read.
 * @param index     which end, 0 or 1.
 * @param position  receives the end's position.
 * @return kQ3Success, or kQ3Failure with *position unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        line or position is NULL.
 *   kQ3ErrorInvalidObject        line is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    line is not a line.
 *   kQ3ErrorParameterOutOfRange  index is neither 0 nor 1.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Line_GetVertexPosition(TQ3GeometryObject line,
                                                    unsigned long index,
                                                    TQ3Point3D *position);

/**
 * Moves one end of a retained line, keeping its attribute set.
 *
 * @param line      the line to change.
 * @param index     which end, 0 or 1.
 * @param position  the new position; its coordinates must be finite, as the
 *                  TQ3LineData rules require.
 * @return kQ3Success, or kQ3Failure with the line unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        line or position is NULL.
 *   kQ3ErrorInvalidObject        line is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    line is not a line.
 *   kQ3ErrorParameterOutOfRange  index is neither 0 nor 1.
 *   kQ3ErrorInvalidData          a coordinate of *position is not finite (the
 *                                code Q3Line_New and _SetData post).
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Line_SetVertexPosition(TQ3GeometryObject line,
                                                    unsigned long index,
                                                    const TQ3Point3D *position);

/**
 * Reads the attribute set of one end of a retained line.
 *
 * @param line          the line to read.
 * @param index         which end, 0 or 1.
 * @param attributeSet  receives the end's attribute set, or NULL when it has
 *                      none (still kQ3Success).
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        line or attributeSet is NULL.
 *   kQ3ErrorInvalidObject        line is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    line is not a line.
 *   kQ3ErrorParameterOutOfRange  index is neither 0 nor 1.
 *
 * Ownership: when *attributeSet is not NULL the caller owns a new reference
 * to it and releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Line_GetVertexAttributeSet(TQ3GeometryObject line,
                                                        unsigned long index,
                                                        TQ3AttributeSet *attributeSet);

/**
 * Replaces the attribute set of one end of a retained line.
 *
 * @param line          the line to change.
 * @param index         which end, 0 or 1.
 * @param attributeSet  the new attribute set, or NULL to remove the end's.
 * @return kQ3Success, or kQ3Failure with the line unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        line is NULL.
 *   kQ3ErrorInvalidObject        line or attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    line is not a line, or attributeSet is not
 *                                an attribute set.
 *   kQ3ErrorParameterOutOfRange  index is neither 0 nor 1.
 *
 * Ownership: the line takes a reference to attributeSet and releases the one
 * the end held; the caller keeps its own reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Line_SetVertexAttributeSet(TQ3GeometryObject line,
                                                        unsigned long index,
                                                        TQ3AttributeSet attributeSet);

/* ---- Point -------------------------------------------------------------- */

/*
 * A single point with an attribute set or NULL.
 *
 * The rules a TQ3PointData must obey wherever one is accepted, with the
 * error posted when one is broken, checked in this order:
 *   every coordinate is finite                      kQ3ErrorInvalidData
 *   pointAttributeSet is NULL or a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 */
struct TQ3PointData {
    TQ3Point3D point;
    TQ3AttributeSet pointAttributeSet;
};
typedef struct TQ3PointData TQ3PointData;

/**
 * Creates a retained point from a copy of the caller's description.
 *
 * @param pointData  the point; it must obey the TQ3PointData rules above.
 * @return the new point, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pointData is NULL.
 *   then the codes of the TQ3PointData rules, in their order:
 *   kQ3ErrorInvalidData        a coordinate is not finite.
 *   kQ3ErrorInvalidObject      pointAttributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pointAttributeSet is not an attribute set.
 *   kQ3ErrorOutOfMemory        the point cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new point is born with
 * and releases it with Q3Object_Dispose. The point takes its own reference to
 * pointAttributeSet; the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Point_New(const TQ3PointData *pointData);

/**
 * Draws (or bounds) a point described by a data structure without creating
 * an object (immediate mode).
 *
 * @param pointData  the point; it must obey the TQ3PointData rules above.
 * @param view       a view inside a rendering or bounding loop.
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pointData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3PointData rules, in their order:
 *   kQ3ErrorInvalidData        a coordinate is not finite.
 *   kQ3ErrorInvalidObject      pointAttributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pointAttributeSet is not an attribute set.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Point_Submit(const TQ3PointData *pointData, TQ3ViewObject view);

/**
 * Copies the description of a retained point.
 *
 * @param point      the point to read.
 * @param pointData  receives the position and the attribute set (or NULL).
 * @return kQ3Success, or kQ3Failure with *pointData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      point or pointData is NULL.
 *   kQ3ErrorInvalidObject      point is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  point is not a point.
 *
 * Ownership: when pointData->pointAttributeSet is not NULL the caller owns a
 * new reference to it and releases it with Q3Point_EmptyData (or
 * Q3Object_Dispose).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Point_GetData(TQ3GeometryObject point, TQ3PointData *pointData);

/**
 * Replaces the description of a retained point.
 *
 * @param point      the point to change.
 * @param pointData  the new point; it must obey the TQ3PointData rules above.
 * @return kQ3Success, or kQ3Failure with the point unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      point or pointData is NULL.
 *   kQ3ErrorInvalidObject      point is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  point is not a point.
 *   then the codes of the TQ3PointData rules, in their order:
 *   kQ3ErrorInvalidData        a coordinate is not finite.
 *   kQ3ErrorInvalidObject      pointAttributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pointAttributeSet is not an attribute set.
 *
 * Ownership: the point takes a reference to the new pointAttributeSet and
 * releases the one it held; the caller keeps its own reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Point_SetData(TQ3GeometryObject point, const TQ3PointData *pointData);

/**
 * Releases what Q3Point_GetData handed out: the reference to the point's
 * attribute set, which is then set to NULL.
 *
 * @param pointData  data filled by Q3Point_GetData.
 * @return kQ3Success, or kQ3Failure with pointData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pointData is NULL.
 *   kQ3ErrorInvalidObject      pointData->pointAttributeSet is not a live Q3
 *                              object.
 *   kQ3ErrorInvalidObjectType  pointData->pointAttributeSet is not an
 *                              attribute set.
 *
 * Ownership: consumes the reference to pointData->pointAttributeSet.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Point_EmptyData(TQ3PointData *pointData);

/**
 * Moves a retained point, keeping its attribute set.
 *
 * @param point     the point to change.
 * @param position  the new position; its coordinates must be finite, as the
 *                  TQ3PointData rules require.
 * @return kQ3Success, or kQ3Failure with the point unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      point or position is NULL.
 *   kQ3ErrorInvalidObject      point is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  point is not a point.
 *   kQ3ErrorInvalidData        a coordinate of *position is not finite (the
 *                              code Q3Point_New and _SetData post).
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Point_SetPosition(TQ3GeometryObject point,
                                               const TQ3Point3D *position);

/**
 * Reads the position of a retained point.
 *
 * @param point     the point to read.
 * @param position  receives the point's position.
 * @return kQ3Success, or kQ3Failure with *position unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      point or position is NULL.
 *   kQ3ErrorInvalidObject      point is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  point is not a point.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Point_GetPosition(TQ3GeometryObject point,
                                               TQ3Point3D *position);

/* ---- Triangle ----------------------------------------------------------- */

/*
 * A triangle: three vertices (each with an attribute set or NULL) and the
 * triangle's attribute set or NULL. Its front is the side from which the
 * vertices run counterclockwise.
 *
 * The rules a TQ3TriangleData must obey wherever one is accepted, checked in
 * this order:
 *   every coordinate is finite                      kQ3ErrorInvalidData
 *   every attribute set given is a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 */
struct TQ3TriangleData {
    TQ3Vertex3D vertices[3];
    TQ3AttributeSet triangleAttributeSet;
};
typedef struct TQ3TriangleData TQ3TriangleData;

/**
 * Creates a retained triangle from a copy of triangleData (the data calls at
 * the top of this header).
 *
 * @return the new triangle, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triangleData is NULL.
 *   then the codes of the TQ3TriangleData rules, in their order;
 *   kQ3ErrorOutOfMemory        the triangle cannot be allocated.
 *
 * Ownership: the caller owns the new triangle's one reference. The triangle
 * takes its own reference to every attribute set given.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Triangle_New(const TQ3TriangleData *triangleData);

/**
 * Draws (or bounds) a triangle without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triangleData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3TriangleData rules, in their order.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Triangle_Submit(const TQ3TriangleData *triangleData, TQ3ViewObject view);

/**
 * Replaces the data of a retained triangle with a copy of triangleData.
 *
 * @return kQ3Success, or kQ3Failure with the triangle unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triangle or triangleData is NULL.
 *   kQ3ErrorInvalidObject      triangle is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  triangle is not a triangle.
 *   then the codes of the TQ3TriangleData rules, in their order.
 *
 * Ownership: the triangle references the attribute sets given and releases
 * those it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Triangle_SetData(TQ3GeometryObject triangle,
                                              const TQ3TriangleData *triangleData);

/**
 * Copies the data of a retained triangle into triangleData.
 *
 * @return kQ3Success, or kQ3Failure with *triangleData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triangle or triangleData is NULL.
 *   kQ3ErrorInvalidObject      triangle is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  triangle is not a triangle.
 *
 * Ownership: the caller owns a new reference to every attribute set in the
 * result and gives them back with Q3Triangle_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Triangle_GetData(TQ3GeometryObject triangle, TQ3TriangleData *triangleData);

/**
 * Releases the four attribute set references Q3Triangle_GetData put in
 * triangleData and sets them to NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triangleData is NULL.
 *   kQ3ErrorInvalidObject      an attribute set in it is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set in it is not an attribute set.
 *
 * Ownership: consumes the references held in the structure.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Triangle_EmptyData(TQ3TriangleData *triangleData);

/**
 * Reads the position of vertex index (0, 1 or 2) of a retained triangle.
 *
 * @return kQ3Success, or kQ3Failure with *point unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        triangle or point is NULL.
 *   kQ3ErrorInvalidObject        triangle is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    triangle is not a triangle.
 *   kQ3ErrorParameterOutOfRange  index is above 2.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Triangle_GetVertexPosition(TQ3GeometryObject triangle, unsigned long index,
                                                        TQ3Point3D *point);

/**
 * Moves vertex index (0, 1 or 2) of a retained triangle.
 *
 * @return kQ3Success, or kQ3Failure with the triangle unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        triangle or point is NULL.
 *   kQ3ErrorInvalidObject        triangle is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    triangle is not a triangle.
 *   kQ3ErrorParameterOutOfRange  index is above 2.
 *   kQ3ErrorInvalidData          a coordinate of *point is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Triangle_SetVertexPosition(TQ3GeometryObject triangle, unsigned long index,
                                                        const TQ3Point3D *point);

/**
 * Reads the attribute set of vertex index (0, 1 or 2) of a retained triangle
 * (NULL when it has none).
 *
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        triangle or attributeSet is NULL.
 *   kQ3ErrorInvalidObject        triangle is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    triangle is not a triangle.
 *   kQ3ErrorParameterOutOfRange  index is above 2.
 *
 * Ownership: a set returned is a new reference for the caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Triangle_GetVertexAttributeSet(TQ3GeometryObject triangle, unsigned long index,
                                                            TQ3AttributeSet *attributeSet);

/**
 * Replaces the attribute set of vertex index (0, 1 or 2) of a retained
 * triangle; NULL removes it.
 *
 * @return kQ3Success, or kQ3Failure with the triangle unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        triangle is NULL.
 *   kQ3ErrorInvalidObject        triangle or attributeSet is not a live Q3
 *                                object.
 *   kQ3ErrorInvalidObjectType    triangle is not a triangle, or attributeSet
 *                                is not an attribute set.
 *   kQ3ErrorParameterOutOfRange  index is above 2.
 *
 * Ownership: the triangle references attributeSet and releases the set the
 * vertex held; the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Triangle_SetVertexAttributeSet(TQ3GeometryObject triangle, unsigned long index,
                                                            TQ3AttributeSet attributeSet);

/* ---- Polygon ------------------------------------------------------------ */

/*
 * A simple polygon: numVertices vertices in order around its outline, and
 * its attribute set or NULL. QuickDraw 3D asks for a convex, planar polygon;
 * Q3 also fills concave ones correctly (it triangulates the outline in the
 * plane that fits the vertices best). Its front is the side from which the
 * vertices run counterclockwise. The wireframe renderer draws its outline.
 *
 * The rules a TQ3PolygonData must obey wherever one is accepted, checked in
 * this order:
 *   vertices is not NULL                            kQ3ErrorNULLParameter
 *   numVertices >= 3             kQ3ErrorGeometryInsufficientNumberOfPoints
 *   numVertices <= kQ3GeometryMaxArrayCount         kQ3ErrorParameterOutOfRange
 *   every coordinate is finite                      kQ3ErrorInvalidData
 *   every attribute set given is a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 */
struct TQ3PolygonData {
    unsigned long numVertices;
    TQ3Vertex3D *vertices;
    TQ3AttributeSet polygonAttributeSet;
};
typedef struct TQ3PolygonData TQ3PolygonData;

/**
 * Creates a retained polygon from a copy of polygonData (the data calls at
 * the top of this header).
 *
 * @return the new polygon, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polygonData is NULL.
 *   then the codes of the TQ3PolygonData rules, in their order;
 *   kQ3ErrorOutOfMemory        the polygon cannot be allocated.
 *
 * Ownership: the caller owns the new polygon's one reference. The polygon
 * takes its own reference to every attribute set given.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Polygon_New(const TQ3PolygonData *polygonData);

/**
 * Draws (or bounds) a polygon without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polygonData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3PolygonData rules, in their order.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polygon_Submit(const TQ3PolygonData *polygonData, TQ3ViewObject view);

/**
 * Replaces the data of a retained polygon with a copy of polygonData.
 *
 * @return kQ3Success, or kQ3Failure with the polygon unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polygon or polygonData is NULL.
 *   kQ3ErrorInvalidObject      polygon is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  polygon is not a polygon.
 *   then the codes of the TQ3PolygonData rules, in their order.
 *
 * Ownership: the polygon references the attribute sets given and releases
 * those it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polygon_SetData(TQ3GeometryObject polygon, const TQ3PolygonData *polygonData);

/**
 * Copies the data of a retained polygon into polygonData (a newly allocated
 * vertex array).
 *
 * @return kQ3Success, or kQ3Failure with *polygonData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polygon or polygonData is NULL.
 *   kQ3ErrorInvalidObject      polygon is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  polygon is not a polygon.
 *   kQ3ErrorOutOfMemory        the copy cannot be allocated.
 *
 * Ownership: the caller owns the array and a new reference to every
 * attribute set in the result, and gives them back with Q3Polygon_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polygon_GetData(TQ3GeometryObject polygon, TQ3PolygonData *polygonData);

/**
 * Releases what Q3Polygon_GetData put in polygonData: the attribute set
 * references and the vertex array; the pointers become NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polygonData is NULL.
 *   kQ3ErrorInvalidObject      an attribute set in it is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set in it is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polygon_EmptyData(TQ3PolygonData *polygonData);

/**
 * Reads the position of vertex index of a retained polygon.
 *
 * @return kQ3Success, or kQ3Failure with *point unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polygon or point is NULL.
 *   kQ3ErrorInvalidObject        polygon is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polygon is not a polygon.
 *   kQ3ErrorParameterOutOfRange  index is not below numVertices.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polygon_GetVertexPosition(TQ3GeometryObject polygon, unsigned long index,
                                                       TQ3Point3D *point);

/**
 * Moves vertex index of a retained polygon.
 *
 * @return kQ3Success, or kQ3Failure with the polygon unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polygon or point is NULL.
 *   kQ3ErrorInvalidObject        polygon is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polygon is not a polygon.
 *   kQ3ErrorParameterOutOfRange  index is not below numVertices.
 *   kQ3ErrorInvalidData          a coordinate of *point is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polygon_SetVertexPosition(TQ3GeometryObject polygon, unsigned long index,
                                                       const TQ3Point3D *point);

/**
 * Reads the attribute set of vertex index of a retained polygon (NULL when
 * it has none).
 *
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polygon or attributeSet is NULL.
 *   kQ3ErrorInvalidObject        polygon is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polygon is not a polygon.
 *   kQ3ErrorParameterOutOfRange  index is not below numVertices.
 *
 * Ownership: a set returned is a new reference for the caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polygon_GetVertexAttributeSet(TQ3GeometryObject polygon, unsigned long index,
                                                           TQ3AttributeSet *attributeSet);

/**
 * Replaces the attribute set of vertex index of a retained polygon; NULL
 * removes it.
 *
 * @return kQ3Success, or kQ3Failure with the polygon unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polygon is NULL.
 *   kQ3ErrorInvalidObject        polygon or attributeSet is not a live Q3
 *                                object.
 *   kQ3ErrorInvalidObjectType    polygon is not a polygon, or attributeSet is
 *                                not an attribute set.
 *   kQ3ErrorParameterOutOfRange  index is not below numVertices.
 *
 * Ownership: the polygon references attributeSet and releases the set the
 * vertex held; the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polygon_SetVertexAttributeSet(TQ3GeometryObject polygon, unsigned long index,
                                                           TQ3AttributeSet attributeSet);

/* ---- TriMesh ------------------------------------------------------------ */

/*
 * A triangle mesh: points, triangles over them, optional edges, and per
 * triangle, per edge and per point attribute arrays.
 *
 *   triangles[t].pointIndices    three indices into points; the triangle's
 *                                front is the side from which they run
 *                                counterclockwise.
 *   edges[e].pointIndices        the edge's two points; triangleIndices the
 *                                (up to) two triangles it borders, or
 *                                kQ3ArrayIndexNULL.
 *   xxxAttributeTypes[i]         one attribute of a standard type
 *                                (QD3DSet.h: surface uv, shading uv, normal,
 *                                ambient coefficient, diffuse colour,
 *                                specular colour, specular control,
 *                                transparency colour, surface tangent,
 *                                highlight state, surface shader) for every
 *                                triangle, edge or point: `data` holds
 *                                numTriangles, numEdges or numPoints values
 *                                of the type, one after another;
 *                                attributeUseArray is NULL, or holds one
 *                                char per element, 0 where the element has
 *                                no value. A surface shader value is a
 *                                TQ3SurfaceShaderObject, NULL for none: the
 *                                TriMesh holds a reference to each one in
 *                                use, GetData returns new references and
 *                                EmptyData releases them; Q3Object_Duplicate
 *                                shares them.
 *   bBox                         ignored by New, SetData and Submit; GetData
 *                                returns the box of the points (isEmpty when
 *                                there are none).
 *
 * Drawing: a point's values are its vertex's attributes; a triangle's apply
 * to its three corners (a point's own still win). A triangle is textured
 * with the surface shader at least two of its corners have, else the
 * TriMesh's attribute set's, else the view's (docs/textures.md). The wireframe renderer
 * draws every side of every triangle, and then every edge that has a diffuse
 * colour, in that colour.
 *
 * The rules a TQ3TriMeshData must obey wherever one is accepted, checked in
 * this order:
 *   every array whose count is not 0 is not NULL (the attribute arrays'
 *     data too)                                     kQ3ErrorNULLParameter
 *   every count <= kQ3GeometryMaxArrayCount         kQ3ErrorParameterOutOfRange
 *   every attribute type is a standard type (1 to
 *     11, not a custom type)                        kQ3ErrorAttributeInvalidType
 *   every point coordinate is finite                kQ3ErrorInvalidData
 *   every point index is below numPoints, every
 *     edge's triangle index below numTriangles or
 *     kQ3ArrayIndexNULL                             kQ3ErrorInvalidData
 *   every attribute value in use is well formed
 *     (finite; a highlight state kQ3On or kQ3Off)   kQ3ErrorInvalidData
 *   triMeshAttributeSet is NULL or a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 *   every surface shader value in use is NULL or a
 *     live surface shader   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 */
struct TQ3TriMeshTriangleData {
    unsigned long pointIndices[3];
};
typedef struct TQ3TriMeshTriangleData TQ3TriMeshTriangleData;

struct TQ3TriMeshEdgeData {
    unsigned long pointIndices[2];
    unsigned long triangleIndices[2];
};
typedef struct TQ3TriMeshEdgeData TQ3TriMeshEdgeData;

struct TQ3TriMeshAttributeData {
    TQ3AttributeType attributeType;
    void *data;
    char *attributeUseArray;
};
typedef struct TQ3TriMeshAttributeData TQ3TriMeshAttributeData;

struct TQ3TriMeshData {
    TQ3AttributeSet triMeshAttributeSet;

    unsigned long numTriangles;
    TQ3TriMeshTriangleData *triangles;

    unsigned long numTriangleAttributeTypes;
    TQ3TriMeshAttributeData *triangleAttributeTypes;

    unsigned long numEdges;
    TQ3TriMeshEdgeData *edges;

    unsigned long numEdgeAttributeTypes;
    TQ3TriMeshAttributeData *edgeAttributeTypes;

    unsigned long numPoints;
    TQ3Point3D *points;

    unsigned long numVertexAttributeTypes;
    TQ3TriMeshAttributeData *vertexAttributeTypes;

    TQ3BoundingBox bBox;
};
typedef struct TQ3TriMeshData TQ3TriMeshData;

/**
 * Creates a retained trimesh from a copy of triMeshData (every array and
 * attribute data block is copied; the data calls at the top of this header).
 *
 * @return the new trimesh, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triMeshData is NULL.
 *   then the codes of the TQ3TriMeshData rules, in their order;
 *   kQ3ErrorOutOfMemory        the trimesh cannot be allocated.
 *
 * Ownership: the caller owns the new trimesh's one reference. The trimesh
 * takes its own reference to triMeshAttributeSet.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3TriMesh_New(const TQ3TriMeshData *triMeshData);

/**
 * Draws (or bounds) a trimesh without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triMeshData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3TriMeshData rules, in their order.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriMesh_Submit(const TQ3TriMeshData *triMeshData, TQ3ViewObject view);

/**
 * Replaces the data of a retained trimesh with a copy of triMeshData.
 *
 * @return kQ3Success, or kQ3Failure with the trimesh unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triMesh or triMeshData is NULL.
 *   kQ3ErrorInvalidObject      triMesh is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  triMesh is not a trimesh.
 *   then the codes of the TQ3TriMeshData rules, in their order;
 *   kQ3ErrorOutOfMemory        the copy cannot be allocated.
 *
 * Ownership: the trimesh references the attribute set given and releases
 * the one it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriMesh_SetData(TQ3GeometryObject triMesh, const TQ3TriMeshData *triMeshData);

/**
 * Copies the data of a retained trimesh into triMeshData: newly allocated
 * arrays (attribute data blocks and use arrays included), and bBox the box of
 * the points.
 *
 * @return kQ3Success, or kQ3Failure with *triMeshData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triMesh or triMeshData is NULL.
 *   kQ3ErrorInvalidObject      triMesh is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  triMesh is not a trimesh.
 *   kQ3ErrorOutOfMemory        the copy cannot be allocated.
 *
 * Ownership: the caller owns the arrays and a new reference to
 * triMeshAttributeSet, and gives them back with Q3TriMesh_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriMesh_GetData(TQ3GeometryObject triMesh, TQ3TriMeshData *triMeshData);

/**
 * Releases what Q3TriMesh_GetData put in triMeshData: frees every array (and
 * each attribute array's data and use array), releases the attribute set
 * reference, and sets the pointers to NULL. The counts stay as they were.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triMeshData is NULL.
 *   kQ3ErrorInvalidObject      triMeshAttributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  triMeshAttributeSet is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriMesh_EmptyData(TQ3TriMeshData *triMeshData);

/* ---- Quadrics and solids ------------------------------------------------ */

/*
 * Boxes, cones, cylinders, disks, ellipses, ellipsoids and tori, as
 * QuickDraw 3D 1.6 defines them: an origin and vectors span each shape
 * (described with its type), and uMin..uMax, vMin..vMax keep a part of it.
 * u runs around, in turns: u = 0 is the direction of majorRadius, u = 1/4
 * that of minorRadius (counterclockwise seen from the end of orientation
 * when majorRadius, minorRadius and orientation are right-handed).
 *
 * The rules their data share (each type lists those that apply, in the
 * order they are checked). Apple's documents leave these open; Q3 decides:
 *   - Every coordinate and parameter is finite, and the shape stays within
 *     float's range (the origin's largest coordinate plus the vectors'
 *     lengths is at most FLT_MAX): kQ3ErrorInvalidData.
 *   - uMin, uMax, vMin, vMax lie in [0, 1] (the QD3D book asks for that);
 *     where v is not an angle (cone, cylinder, disk, ellipsoid),
 *     vMin <= vMax: kQ3ErrorInvalidData. A u range (and a torus's v range)
 *     is an angle and wraps through 0 when min > max, as Quesa draws it:
 *     uMin = 0.75, uMax = 0.25 is the half turn through u = 0.
 *   - caps holds only kQ3EndCapMaskTop, kQ3EndCapMaskBottom and
 *     kQ3EndCapMaskInterior: kQ3ErrorInvalidData.
 *   - Every attribute set given is a live attribute set:
 *     kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType.
 * Tolerated: a degenerate shape, which QuickDraw 3D kept (files written by
 * Apple-era tools hold them): vectors that are not independent (one is
 * zero, or the three, the two of a disk or an ellipse, lie in one plane,
 * on one line), tested as |x . (y x z)| <= 1e-6 |x| |y| |z|
 * (|x x y| <= 1e-6 |x| |y|); an empty range (uMin == uMax, or uMin = 1 with
 * uMax = 0; vMin == vMax); a torus's ratio of 0. Such data passes every
 * rule above; it is kept exactly as given (GetData returns it), and the
 * call that gives it (New, SetData, Submit, a per-field setter, a 3DMF
 * read) posts kQ3WarningInconsistentData naming the case. It has no area
 * and no normal, so it draws nothing and bounds nothing
 * (Q3Geometry_GetDecomposed gives a TriMesh of no points), except an
 * ellipse with dependent radii, a curve drawn as the segment (or point) its
 * formula gives; as Quesa draws
 * it (Quesa posts kQ3ErrorDegenerateGeometry, not fatal, at each draw;
 * Apple's QD3DErrors.h has no degenerate-geometry warning). See
 * docs/3dmf.md, "Tolerances".
 * Apple's per-field setters (Q3Cone_SetOrigin, Q3Torus_SetRatio, ...) check
 * the data as it would be with that one field changed, by the same rules:
 * a setter never accepts what SetData refuses. Change related fields
 * together (turn a frame, say) with SetData.
 *
 * Drawing. Each shape is triangles (an ellipse a polyline), every vertex
 * with a unit normal pointing out of the shape and a surface uv
 * (kQ3AttributeTypeSurfaceUV): (u, v) on a curved surface (u above 1 where
 * the range wraps through 0); on a disk and a cap, the point's place in the
 * unit square around the disk, (0.5 + 0.5 r cos 2 pi u, 0.5 + 0.5 r sin 2 pi u)
 * at the fraction r of the radius; on a box face, u and v from 0 to 1 with u
 * to the right and v up seen from outside; on the face of a cut, (s, v) with
 * s from the axis (0) to the surface (1). Triangles are counterclockwise
 * seen from outside, whatever the handedness of the vectors. A vertex takes
 * the attributes of its part's set (face, top, bottom, interior), then the
 * shape's own set, then the view's state. Parts that close a shape share
 * their edges' vertices with it: the shapes are watertight.
 *
 * Subdivision (QD3DStyle.h).
 *   Constant: c1 segments per full turn of u (a part of a turn in
 *   proportion, rounded up; at least 3 for a full turn) and c2 segments
 *   over v from 0 to 1 (likewise in proportion). Flat parts (caps, the faces
 *   of cuts, box faces) take the count of the edge they share with the
 *   curved surface and are not divided across.
 *   World space and screen space: no triangle edge is longer than c1,
 *   measured between the images of its ends in world units (after the
 *   local-to-world transform) or in pane pixels (after the camera's
 *   projection, perspective divide included); for an edge of which only a
 *   part has an image (it crosses the hither plane), the length of that
 *   part. c2 is not used. The triangles are close to the fewest this
 *   allows: rows along u staggered by half a step, so that triangles are
 *   nearly equilateral (Q3's tests measure the count against the lower bound
 *   drawn area / (sqrt(3)/4 c1^2)).
 *   A shape is drawn with at most kQ3SubdivisionMaxTrianglesPerSurface
 *   triangles (an ellipse with kQ3SubdivisionMaxSegmentsPerCurve segments):
 *   beyond it the constant counts are lowered, or edges longer than c1 are
 *   allowed, and the submit posts kQ3WarningParameterOutOfRange.
 *   A bounding loop bounds the whole shape analytically (a partial shape by
 *   its whole shape's box). Q3Geometry_GetDecomposed gives a TriMesh (for an
 *   ellipse a PolyLine) with the normals, uvs and part attributes as vertex
 *   attribute arrays.
 */

/*
 * A box: the parallelepiped with a corner at origin and the edges
 * orientation, majorAxis and minorAxis from it (a rectangular box when they
 * are orthogonal). faceAttributeSet is NULL or an array of six attribute
 * sets (each may be NULL), one per face in Apple's order: left, right,
 * front, back, top, bottom. Apple's documents disagree on which face is
 * which (the 3DMF reference numbers them top, bottom, front, ...); Q3 uses
 * the header's names with Quesa's geometry: left is the face at origin
 * spanned by majorAxis and orientation (minorAxis points away from it),
 * right the face opposite; front the face at the end of majorAxis, back the
 * one at origin; top the face at the end of orientation, bottom the one at
 * origin. A face's set wins over boxAttributeSet. The constant subdivision
 * method draws each face as two triangles (a face is flat).
 *
 * The rules a TQ3BoxData must obey wherever one is accepted, checked in
 * this order:
 *   every coordinate is finite; the box within float's
 *     range                                         kQ3ErrorInvalidData
 *   faceAttributeSet is NULL or six attribute sets, each NULL or live, and
 *     boxAttributeSet NULL or live
 *                           kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 * Tolerated, with kQ3WarningInconsistentData: a degenerate box (its
 * vectors not independent), kept as given and drawn as nothing (see above).
 */
struct TQ3BoxData {
    TQ3Point3D origin;
    TQ3Vector3D orientation;
    TQ3Vector3D majorAxis;
    TQ3Vector3D minorAxis;
    TQ3AttributeSet *faceAttributeSet; /* left, right, front, back, top, bottom */
    TQ3AttributeSet boxAttributeSet;
};
typedef struct TQ3BoxData TQ3BoxData;

/**
 * Creates a retained box from a copy of boxData (the data calls at the top
 * of this header).
 *
 * @return the new box, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      boxData is NULL.
 *   then the codes of the TQ3BoxData rules, in their order;
 *   kQ3ErrorOutOfMemory        the box cannot be allocated.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3BoxData rules): kept, drawn as nothing.
 *
 * Ownership: the caller owns the new box's one reference. The box
 * takes its own reference to every attribute set given.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Box_New(const TQ3BoxData *boxData);

/**
 * Draws (or bounds) a box without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      boxData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3BoxData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3BoxData rules): kept, drawn as nothing.
 *   kQ3WarningParameterOutOfRange  the subdivision style asks for more than
 *                              kQ3SubdivisionMaxTrianglesPerSurface triangles
 *                              (QD3DStyle.h); fewer are drawn.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_Submit(const TQ3BoxData *boxData, TQ3ViewObject view);

/**
 * Replaces the data of a retained box with a copy of boxData.
 *
 * @return kQ3Success, or kQ3Failure with the box unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      box or boxData is NULL.
 *   kQ3ErrorInvalidObject      box is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  box is not a box.
 *   then the codes of the TQ3BoxData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3BoxData rules): kept, drawn as nothing.
 *
 * Ownership: the box references the attribute sets given and releases
 * those it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_SetData(TQ3GeometryObject box, const TQ3BoxData *boxData);

/**
 * Copies the data of a retained box into boxData.
 *
 * @return kQ3Success, or kQ3Failure with *boxData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      box or boxData is NULL.
 *   kQ3ErrorInvalidObject      box is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  box is not a box.
 *   kQ3ErrorOutOfMemory        the face attribute set array cannot be allocated.
 *
 * Ownership: the caller owns a new reference to every attribute set in the
 * result, and the array of six (when the box has one) and gives them back with Q3Box_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_GetData(TQ3GeometryObject box, TQ3BoxData *boxData);

/**
 * Releases what Q3Box_GetData put in boxData: the attribute set
 * references and the face attribute set array; the pointers become NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      boxData is NULL.
 *   kQ3ErrorInvalidObject      an attribute set in it is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set in it is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_EmptyData(TQ3BoxData *boxData);

/**
 * Sets the origin (a corner) of a retained box; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the box unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      box or origin is NULL.
 *   kQ3ErrorInvalidObject      box is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  box is not a box.
 *   kQ3ErrorInvalidData        a coordinate is not finite, or the box
 *                              would leave float's range.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_SetOrigin(TQ3GeometryObject box, const TQ3Point3D *origin);

/**
 * Reads the origin (a corner) of a retained box.
 *
 * @return kQ3Success, or kQ3Failure with *origin unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      box or origin is NULL.
 *   kQ3ErrorInvalidObject      box is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  box is not a box.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_GetOrigin(TQ3GeometryObject box, TQ3Point3D *origin);

/**
 * Sets the orientation (an edge from the origin) of a retained box; the rest
 * of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the box unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      box or orientation is NULL.
 *   kQ3ErrorInvalidObject      box is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  box is not a box.
 *   kQ3ErrorInvalidData        a component is not finite, or the box
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the box's vectors are not independent: the
 *                              value is kept and the box draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_SetOrientation(TQ3GeometryObject box, const TQ3Vector3D *orientation);

/**
 * Reads the orientation (an edge from the origin) of a retained box.
 *
 * @return kQ3Success, or kQ3Failure with *orientation unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      box or orientation is NULL.
 *   kQ3ErrorInvalidObject      box is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  box is not a box.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_GetOrientation(TQ3GeometryObject box, TQ3Vector3D *orientation);

/**
 * Sets the major axis (an edge from the origin) of a retained box; the rest
 * of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the box unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      box or majorAxis is NULL.
 *   kQ3ErrorInvalidObject      box is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  box is not a box.
 *   kQ3ErrorInvalidData        a component is not finite, or the box
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the box's vectors are not independent: the
 *                              value is kept and the box draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_SetMajorAxis(TQ3GeometryObject box, const TQ3Vector3D *majorAxis);

/**
 * Reads the major axis (an edge from the origin) of a retained box.
 *
 * @return kQ3Success, or kQ3Failure with *majorAxis unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      box or majorAxis is NULL.
 *   kQ3ErrorInvalidObject      box is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  box is not a box.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_GetMajorAxis(TQ3GeometryObject box, TQ3Vector3D *majorAxis);

/**
 * Sets the minor axis (an edge from the origin) of a retained box; the rest
 * of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the box unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      box or minorAxis is NULL.
 *   kQ3ErrorInvalidObject      box is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  box is not a box.
 *   kQ3ErrorInvalidData        a component is not finite, or the box
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the box's vectors are not independent: the
 *                              value is kept and the box draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_SetMinorAxis(TQ3GeometryObject box, const TQ3Vector3D *minorAxis);

/**
 * Reads the minor axis (an edge from the origin) of a retained box.
 *
 * @return kQ3Success, or kQ3Failure with *minorAxis unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      box or minorAxis is NULL.
 *   kQ3ErrorInvalidObject      box is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  box is not a box.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_GetMinorAxis(TQ3GeometryObject box, TQ3Vector3D *minorAxis);

/**
 * Reads the attribute set of face faceIndex (0 left, 1 right, 2 front, 3 back,
 * 4 top, 5 bottom) of a retained box: NULL when the face has none.
 *
 * @return kQ3Success, or kQ3Failure with *faceAttributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        box or faceAttributeSet is NULL.
 *   kQ3ErrorInvalidObject        box is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    box is not a box.
 *   kQ3ErrorParameterOutOfRange  faceIndex is above 5.
 *
 * Ownership: a set returned is a new reference for the caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_GetFaceAttributeSet(TQ3GeometryObject box,
                                                     unsigned long faceIndex,
                                                     TQ3AttributeSet *faceAttributeSet);

/**
 * Replaces the attribute set of face faceIndex (0 left, 1 right, 2 front,
 * 3 back, 4 top, 5 bottom) of a retained box; NULL removes it. A box without
 * face sets gets an array of six, the others NULL.
 *
 * @return kQ3Success, or kQ3Failure with the box unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        box is NULL.
 *   kQ3ErrorInvalidObject        box or faceAttributeSet is not a live Q3
 *                                object.
 *   kQ3ErrorInvalidObjectType    box is not a box, or faceAttributeSet is
 *                                not an attribute set.
 *   kQ3ErrorParameterOutOfRange  faceIndex is above 5.
 *   kQ3ErrorOutOfMemory          the array of six cannot be allocated.
 *
 * Ownership: the box references faceAttributeSet and releases the set the
 * face held; the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Box_SetFaceAttributeSet(TQ3GeometryObject box,
                                                     unsigned long faceIndex,
                                                     TQ3AttributeSet faceAttributeSet);

/*
 * A cone: its base the ellipse origin + cos(2 pi u) majorRadius +
 * sin(2 pi u) minorRadius, its apex origin + orientation:
 *   P(u, v) = origin + v orientation
 *             + (1 - v) (cos(2 pi u) majorRadius + sin(2 pi u) minorRadius).
 * uMin..uMax keeps a wedge, vMin..vMax a band (vMin > 0 cuts off the bottom,
 * vMax < 1 the tip). faceAttributeSet is the side's set. Caps:
 * kQ3EndCapMaskBottom closes the bottom (at vMin) with bottomAttributeSet;
 * kQ3EndCapMaskInterior closes the cuts with interiorAttributeSet: the top
 * at vMax when vMax < 1 and the faces at uMin and uMax (from the axis to the
 * surface) when u is not a full turn; kQ3EndCapMaskTop is ignored (QD3D
 * book). The book does not say what closes a truncated top; Q3 follows
 * Quesa. Constant subdivision: c1 around, c2 along v.
 *
 * The rules a TQ3ConeData must obey wherever one is accepted, checked in
 * this order:
 *   every coordinate and parameter is finite; the
 *     cone within float's range                     kQ3ErrorInvalidData
 *   uMin, uMax, vMin, vMax in [0, 1]; vMin <= vMax  kQ3ErrorInvalidData
 *   caps holds only end cap masks                   kQ3ErrorInvalidData
 *   every attribute set given is a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 * Tolerated, with kQ3WarningInconsistentData: a degenerate cone (its
 * vectors not independent, an empty range), kept as given and
 * drawn as nothing (see above).
 */
struct TQ3ConeData {
    TQ3Point3D origin;
    TQ3Vector3D orientation;
    TQ3Vector3D majorRadius;
    TQ3Vector3D minorRadius;
    float uMin;
    float uMax;
    float vMin;
    float vMax;
    TQ3EndCap caps;
    TQ3AttributeSet interiorAttributeSet;
    TQ3AttributeSet faceAttributeSet;
    TQ3AttributeSet bottomAttributeSet;
    TQ3AttributeSet coneAttributeSet;
};
typedef struct TQ3ConeData TQ3ConeData;

/**
 * Creates a retained cone from a copy of coneData (the data calls at the top
 * of this header).
 *
 * @return the new cone, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      coneData is NULL.
 *   then the codes of the TQ3ConeData rules, in their order;
 *   kQ3ErrorOutOfMemory        the cone cannot be allocated.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3ConeData rules): kept, drawn as nothing.
 *
 * Ownership: the caller owns the new cone's one reference. The cone
 * takes its own reference to every attribute set given.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Cone_New(const TQ3ConeData *coneData);

/**
 * Draws (or bounds) a cone without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      coneData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3ConeData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3ConeData rules): kept, drawn as nothing.
 *   kQ3WarningParameterOutOfRange  the subdivision style asks for more than
 *                              kQ3SubdivisionMaxTrianglesPerSurface triangles
 *                              (QD3DStyle.h); fewer are drawn.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_Submit(const TQ3ConeData *coneData, TQ3ViewObject view);

/**
 * Replaces the data of a retained cone with a copy of coneData.
 *
 * @return kQ3Success, or kQ3Failure with the cone unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone or coneData is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *   then the codes of the TQ3ConeData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3ConeData rules): kept, drawn as nothing.
 *
 * Ownership: the cone references the attribute sets given and releases
 * those it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_SetData(TQ3GeometryObject cone, const TQ3ConeData *coneData);

/**
 * Copies the data of a retained cone into coneData.
 *
 * @return kQ3Success, or kQ3Failure with *coneData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone or coneData is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *
 * Ownership: the caller owns a new reference to every attribute set in the
 * result and gives them back with Q3Cone_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_GetData(TQ3GeometryObject cone, TQ3ConeData *coneData);

/**
 * Releases what Q3Cone_GetData put in coneData: the attribute set
 * references; the pointers become NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      coneData is NULL.
 *   kQ3ErrorInvalidObject      an attribute set in it is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set in it is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_EmptyData(TQ3ConeData *coneData);

/**
 * Sets the origin (the centre of the base) of a retained cone; the rest of
 * its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the cone unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone or origin is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *   kQ3ErrorInvalidData        a coordinate is not finite, or the cone
 *                              would leave float's range.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_SetOrigin(TQ3GeometryObject cone, const TQ3Point3D *origin);

/**
 * Reads the origin (the centre of the base) of a retained cone.
 *
 * @return kQ3Success, or kQ3Failure with *origin unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone or origin is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_GetOrigin(TQ3GeometryObject cone, TQ3Point3D *origin);

/**
 * Sets the orientation (from the base's centre to the apex) of a retained
 * cone; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the cone unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone or orientation is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *   kQ3ErrorInvalidData        a component is not finite, or the cone
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the cone's vectors are not independent: the
 *                              value is kept and the cone draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_SetOrientation(TQ3GeometryObject cone, const TQ3Vector3D *orientation);

/**
 * Reads the orientation (from the base's centre to the apex) of a retained
 * cone.
 *
 * @return kQ3Success, or kQ3Failure with *orientation unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone or orientation is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_GetOrientation(TQ3GeometryObject cone, TQ3Vector3D *orientation);

/**
 * Sets the major radius of a retained cone; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the cone unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone or majorRadius is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *   kQ3ErrorInvalidData        a component is not finite, or the cone
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the cone's vectors are not independent: the
 *                              value is kept and the cone draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_SetMajorRadius(TQ3GeometryObject cone, const TQ3Vector3D *majorRadius);

/**
 * Reads the major radius of a retained cone.
 *
 * @return kQ3Success, or kQ3Failure with *majorRadius unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone or majorRadius is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_GetMajorRadius(TQ3GeometryObject cone, TQ3Vector3D *majorRadius);

/**
 * Sets the minor radius of a retained cone; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the cone unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone or minorRadius is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *   kQ3ErrorInvalidData        a component is not finite, or the cone
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the cone's vectors are not independent: the
 *                              value is kept and the cone draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_SetMinorRadius(TQ3GeometryObject cone, const TQ3Vector3D *minorRadius);

/**
 * Reads the minor radius of a retained cone.
 *
 * @return kQ3Success, or kQ3Failure with *minorRadius unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone or minorRadius is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_GetMinorRadius(TQ3GeometryObject cone, TQ3Vector3D *minorRadius);

/**
 * Sets which end caps a retained cone has (TQ3EndCapMasks combined;
 * kQ3EndCapMaskTop is ignored).
 *
 * @return kQ3Success, or kQ3Failure with the cone unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *   kQ3ErrorInvalidData        caps has a bit that is not an end cap mask.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_SetCaps(TQ3GeometryObject cone, TQ3EndCap caps);

/**
 * Reads which end caps a retained cone has.
 *
 * @return kQ3Success, or kQ3Failure with *caps unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone or caps is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_GetCaps(TQ3GeometryObject cone, TQ3EndCap *caps);

/**
 * Replaces the attribute set of the bottom cap of a retained cone; NULL
 * removes it.
 *
 * @return kQ3Success, or kQ3Failure with the cone unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone is NULL.
 *   kQ3ErrorInvalidObject      cone or bottomAttributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone, or bottomAttributeSet is not an
 *                              attribute set.
 *
 * Ownership: the cone references bottomAttributeSet and releases the set it held;
 * the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_SetBottomAttributeSet(TQ3GeometryObject cone,
                                                        TQ3AttributeSet bottomAttributeSet);

/**
 * Reads the attribute set of the bottom cap of a retained cone (NULL when it
 * has none).
 *
 * @return kQ3Success, or kQ3Failure with *bottomAttributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone or bottomAttributeSet is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *
 * Ownership: a set returned is a new reference for the caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_GetBottomAttributeSet(TQ3GeometryObject cone,
                                                        TQ3AttributeSet *bottomAttributeSet);

/**
 * Replaces the attribute set of the side of a retained cone; NULL
 * removes it.
 *
 * @return kQ3Success, or kQ3Failure with the cone unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone is NULL.
 *   kQ3ErrorInvalidObject      cone or faceAttributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone, or faceAttributeSet is not an
 *                              attribute set.
 *
 * Ownership: the cone references faceAttributeSet and releases the set it held;
 * the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_SetFaceAttributeSet(TQ3GeometryObject cone, TQ3AttributeSet faceAttributeSet);

/**
 * Reads the attribute set of the side of a retained cone (NULL when it
 * has none).
 *
 * @return kQ3Success, or kQ3Failure with *faceAttributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cone or faceAttributeSet is NULL.
 *   kQ3ErrorInvalidObject      cone is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cone is not a cone.
 *
 * Ownership: a set returned is a new reference for the caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cone_GetFaceAttributeSet(TQ3GeometryObject cone, TQ3AttributeSet *faceAttributeSet);

/*
 * A cylinder: the ellipse origin + cos(2 pi u) majorRadius + sin(2 pi u)
 * minorRadius swept along orientation:
 *   P(u, v) = origin + v orientation + cos(2 pi u) majorRadius
 *             + sin(2 pi u) minorRadius.
 * uMin..uMax keeps a wedge, vMin..vMax a band. faceAttributeSet is the
 * side's set. Caps: kQ3EndCapMaskBottom closes the bottom (at vMin) with
 * bottomAttributeSet, kQ3EndCapMaskTop the top (at vMax) with
 * topAttributeSet, kQ3EndCapMaskInterior the faces at uMin and uMax (from
 * the axis to the surface) when u is not a full turn, with
 * interiorAttributeSet. Constant subdivision: c1 around, c2 along v.
 *
 * The rules a TQ3CylinderData must obey wherever one is accepted, checked in
 * this order:
 *   every coordinate and parameter is finite; the
 *     cylinder within float's range                 kQ3ErrorInvalidData
 *   uMin, uMax, vMin, vMax in [0, 1]; vMin <= vMax  kQ3ErrorInvalidData
 *   caps holds only end cap masks                   kQ3ErrorInvalidData
 *   every attribute set given is a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 * Tolerated, with kQ3WarningInconsistentData: a degenerate cylinder (its
 * vectors not independent, an empty range), kept as given and
 * drawn as nothing (see above).
 */
struct TQ3CylinderData {
    TQ3Point3D origin;
    TQ3Vector3D orientation;
    TQ3Vector3D majorRadius;
    TQ3Vector3D minorRadius;
    float uMin;
    float uMax;
    float vMin;
    float vMax;
    TQ3EndCap caps;
    TQ3AttributeSet interiorAttributeSet;
    TQ3AttributeSet topAttributeSet;
    TQ3AttributeSet faceAttributeSet;
    TQ3AttributeSet bottomAttributeSet;
    TQ3AttributeSet cylinderAttributeSet;
};
typedef struct TQ3CylinderData TQ3CylinderData;

/**
 * Creates a retained cylinder from a copy of cylinderData (the data calls at the top
 * of this header).
 *
 * @return the new cylinder, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinderData is NULL.
 *   then the codes of the TQ3CylinderData rules, in their order;
 *   kQ3ErrorOutOfMemory        the cylinder cannot be allocated.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3CylinderData rules): kept, drawn as nothing.
 *
 * Ownership: the caller owns the new cylinder's one reference. The cylinder
 * takes its own reference to every attribute set given.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Cylinder_New(const TQ3CylinderData *cylinderData);

/**
 * Draws (or bounds) a cylinder without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinderData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3CylinderData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3CylinderData rules): kept, drawn as nothing.
 *   kQ3WarningParameterOutOfRange  the subdivision style asks for more than
 *                              kQ3SubdivisionMaxTrianglesPerSurface triangles
 *                              (QD3DStyle.h); fewer are drawn.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_Submit(const TQ3CylinderData *cylinderData, TQ3ViewObject view);

/**
 * Replaces the data of a retained cylinder with a copy of cylinderData.
 *
 * @return kQ3Success, or kQ3Failure with the cylinder unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or cylinderData is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *   then the codes of the TQ3CylinderData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3CylinderData rules): kept, drawn as nothing.
 *
 * Ownership: the cylinder references the attribute sets given and releases
 * those it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_SetData(TQ3GeometryObject cylinder, const TQ3CylinderData *cylinderData);

/**
 * Copies the data of a retained cylinder into cylinderData.
 *
 * @return kQ3Success, or kQ3Failure with *cylinderData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or cylinderData is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *
 * Ownership: the caller owns a new reference to every attribute set in the
 * result and gives them back with Q3Cylinder_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_GetData(TQ3GeometryObject cylinder, TQ3CylinderData *cylinderData);

/**
 * Releases what Q3Cylinder_GetData put in cylinderData: the attribute set
 * references; the pointers become NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinderData is NULL.
 *   kQ3ErrorInvalidObject      an attribute set in it is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set in it is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_EmptyData(TQ3CylinderData *cylinderData);

/**
 * Sets the origin (the centre of the bottom) of a retained cylinder; the
 * rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the cylinder unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or origin is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *   kQ3ErrorInvalidData        a coordinate is not finite, or the cylinder
 *                              would leave float's range.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_SetOrigin(TQ3GeometryObject cylinder, const TQ3Point3D *origin);

/**
 * Reads the origin (the centre of the bottom) of a retained cylinder.
 *
 * @return kQ3Success, or kQ3Failure with *origin unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or origin is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_GetOrigin(TQ3GeometryObject cylinder, TQ3Point3D *origin);

/**
 * Sets the orientation (from the bottom's centre to the top's) of a retained
 * cylinder; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the cylinder unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or orientation is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *   kQ3ErrorInvalidData        a component is not finite, or the cylinder
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the cylinder's vectors are not independent: the
 *                              value is kept and the cylinder draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_SetOrientation(TQ3GeometryObject cylinder, const TQ3Vector3D *orientation);

/**
 * Reads the orientation (from the bottom's centre to the top's) of a
 * retained cylinder.
 *
 * @return kQ3Success, or kQ3Failure with *orientation unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or orientation is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_GetOrientation(TQ3GeometryObject cylinder, TQ3Vector3D *orientation);

/**
 * Sets the major radius of a retained cylinder; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the cylinder unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or majorRadius is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *   kQ3ErrorInvalidData        a component is not finite, or the cylinder
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the cylinder's vectors are not independent: the
 *                              value is kept and the cylinder draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_SetMajorRadius(TQ3GeometryObject cylinder, const TQ3Vector3D *majorRadius);

/**
 * Reads the major radius of a retained cylinder.
 *
 * @return kQ3Success, or kQ3Failure with *majorRadius unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or majorRadius is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_GetMajorRadius(TQ3GeometryObject cylinder, TQ3Vector3D *majorRadius);

/**
 * Sets the minor radius of a retained cylinder; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the cylinder unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or minorRadius is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *   kQ3ErrorInvalidData        a component is not finite, or the cylinder
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the cylinder's vectors are not independent: the
 *                              value is kept and the cylinder draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_SetMinorRadius(TQ3GeometryObject cylinder, const TQ3Vector3D *minorRadius);

/**
 * Reads the minor radius of a retained cylinder.
 *
 * @return kQ3Success, or kQ3Failure with *minorRadius unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or minorRadius is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_GetMinorRadius(TQ3GeometryObject cylinder, TQ3Vector3D *minorRadius);

/**
 * Sets which end caps a retained cylinder has (TQ3EndCapMasks combined; top,
 * bottom and interior).
 *
 * @return kQ3Success, or kQ3Failure with the cylinder unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *   kQ3ErrorInvalidData        caps has a bit that is not an end cap mask.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_SetCaps(TQ3GeometryObject cylinder, TQ3EndCap caps);

/**
 * Reads which end caps a retained cylinder has.
 *
 * @return kQ3Success, or kQ3Failure with *caps unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or caps is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_GetCaps(TQ3GeometryObject cylinder, TQ3EndCap *caps);

/**
 * Replaces the attribute set of the top cap of a retained cylinder; NULL
 * removes it.
 *
 * @return kQ3Success, or kQ3Failure with the cylinder unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder is NULL.
 *   kQ3ErrorInvalidObject      cylinder or topAttributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder, or topAttributeSet is not an
 *                              attribute set.
 *
 * Ownership: the cylinder references topAttributeSet and releases the set it held;
 * the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_SetTopAttributeSet(TQ3GeometryObject cylinder,
                                                         TQ3AttributeSet topAttributeSet);

/**
 * Reads the attribute set of the top cap of a retained cylinder (NULL when it
 * has none).
 *
 * @return kQ3Success, or kQ3Failure with *topAttributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or topAttributeSet is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *
 * Ownership: a set returned is a new reference for the caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_GetTopAttributeSet(TQ3GeometryObject cylinder,
                                                         TQ3AttributeSet *topAttributeSet);

/**
 * Replaces the attribute set of the bottom cap of a retained cylinder; NULL
 * removes it.
 *
 * @return kQ3Success, or kQ3Failure with the cylinder unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder is NULL.
 *   kQ3ErrorInvalidObject      cylinder or bottomAttributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder, or bottomAttributeSet is not an
 *                              attribute set.
 *
 * Ownership: the cylinder references bottomAttributeSet and releases the set it held;
 * the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_SetBottomAttributeSet(TQ3GeometryObject cylinder,
                                                            TQ3AttributeSet bottomAttributeSet);

/**
 * Reads the attribute set of the bottom cap of a retained cylinder (NULL when it
 * has none).
 *
 * @return kQ3Success, or kQ3Failure with *bottomAttributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or bottomAttributeSet is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *
 * Ownership: a set returned is a new reference for the caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_GetBottomAttributeSet(TQ3GeometryObject cylinder,
                                                            TQ3AttributeSet *bottomAttributeSet);

/**
 * Replaces the attribute set of the side of a retained cylinder; NULL
 * removes it.
 *
 * @return kQ3Success, or kQ3Failure with the cylinder unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder is NULL.
 *   kQ3ErrorInvalidObject      cylinder or faceAttributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder, or faceAttributeSet is not an
 *                              attribute set.
 *
 * Ownership: the cylinder references faceAttributeSet and releases the set it held;
 * the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_SetFaceAttributeSet(TQ3GeometryObject cylinder,
                                                          TQ3AttributeSet faceAttributeSet);

/**
 * Reads the attribute set of the side of a retained cylinder (NULL when it
 * has none).
 *
 * @return kQ3Success, or kQ3Failure with *faceAttributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      cylinder or faceAttributeSet is NULL.
 *   kQ3ErrorInvalidObject      cylinder is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  cylinder is not a cylinder.
 *
 * Ownership: a set returned is a new reference for the caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Cylinder_GetFaceAttributeSet(TQ3GeometryObject cylinder,
                                                          TQ3AttributeSet *faceAttributeSet);

/*
 * A disk: the region of the ellipse origin + cos(2 pi u) majorRadius +
 * sin(2 pi u) minorRadius,
 *   P(u, v) = origin + v (cos(2 pi u) majorRadius + sin(2 pi u) minorRadius),
 * v = 0 the centre, v = 1 the rim: uMin..uMax keeps a sector, vMin > 0
 * cuts a hole. Its front is the side from which u runs counterclockwise
 * (majorRadius x minorRadius points out of it). Constant subdivision: c1
 * around, c2 across v.
 *
 * The rules a TQ3DiskData must obey wherever one is accepted, checked in
 * this order:
 *   every coordinate and parameter is finite; the
 *     disk within float's range                     kQ3ErrorInvalidData
 *   uMin, uMax, vMin, vMax in [0, 1]; vMin <= vMax  kQ3ErrorInvalidData
 *   diskAttributeSet is NULL or a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 * Tolerated, with kQ3WarningInconsistentData: a degenerate disk (its
 * vectors not independent, an empty range), kept as given and
 * drawn as nothing (see above).
 */
struct TQ3DiskData {
    TQ3Point3D origin;
    TQ3Vector3D majorRadius;
    TQ3Vector3D minorRadius;
    float uMin;
    float uMax;
    float vMin;
    float vMax;
    TQ3AttributeSet diskAttributeSet;
};
typedef struct TQ3DiskData TQ3DiskData;

/**
 * Creates a retained disk from a copy of diskData (the data calls at the top
 * of this header).
 *
 * @return the new disk, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      diskData is NULL.
 *   then the codes of the TQ3DiskData rules, in their order;
 *   kQ3ErrorOutOfMemory        the disk cannot be allocated.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3DiskData rules): kept, drawn as nothing.
 *
 * Ownership: the caller owns the new disk's one reference. The disk
 * takes its own reference to every attribute set given.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Disk_New(const TQ3DiskData *diskData);

/**
 * Draws (or bounds) a disk without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      diskData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3DiskData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3DiskData rules): kept, drawn as nothing.
 *   kQ3WarningParameterOutOfRange  the subdivision style asks for more than
 *                              kQ3SubdivisionMaxTrianglesPerSurface triangles
 *                              (QD3DStyle.h); fewer are drawn.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Disk_Submit(const TQ3DiskData *diskData, TQ3ViewObject view);

/**
 * Replaces the data of a retained disk with a copy of diskData.
 *
 * @return kQ3Success, or kQ3Failure with the disk unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      disk or diskData is NULL.
 *   kQ3ErrorInvalidObject      disk is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  disk is not a disk.
 *   then the codes of the TQ3DiskData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3DiskData rules): kept, drawn as nothing.
 *
 * Ownership: the disk references the attribute sets given and releases
 * those it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Disk_SetData(TQ3GeometryObject disk, const TQ3DiskData *diskData);

/**
 * Copies the data of a retained disk into diskData.
 *
 * @return kQ3Success, or kQ3Failure with *diskData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      disk or diskData is NULL.
 *   kQ3ErrorInvalidObject      disk is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  disk is not a disk.
 *
 * Ownership: the caller owns a new reference to every attribute set in the
 * result and gives them back with Q3Disk_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Disk_GetData(TQ3GeometryObject disk, TQ3DiskData *diskData);

/**
 * Releases what Q3Disk_GetData put in diskData: the attribute set
 * references; the pointers become NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      diskData is NULL.
 *   kQ3ErrorInvalidObject      an attribute set in it is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set in it is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Disk_EmptyData(TQ3DiskData *diskData);

/**
 * Sets the origin (the centre) of a retained disk; the rest of its data
 * stays.
 *
 * @return kQ3Success, or kQ3Failure with the disk unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      disk or origin is NULL.
 *   kQ3ErrorInvalidObject      disk is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  disk is not a disk.
 *   kQ3ErrorInvalidData        a coordinate is not finite, or the disk
 *                              would leave float's range.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Disk_SetOrigin(TQ3GeometryObject disk, const TQ3Point3D *origin);

/**
 * Reads the origin (the centre) of a retained disk.
 *
 * @return kQ3Success, or kQ3Failure with *origin unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      disk or origin is NULL.
 *   kQ3ErrorInvalidObject      disk is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  disk is not a disk.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Disk_GetOrigin(TQ3GeometryObject disk, TQ3Point3D *origin);

/**
 * Sets the major radius of a retained disk; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the disk unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      disk or majorRadius is NULL.
 *   kQ3ErrorInvalidObject      disk is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  disk is not a disk.
 *   kQ3ErrorInvalidData        a component is not finite, or the disk
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the disk's vectors are not independent: the
 *                              value is kept and the disk draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Disk_SetMajorRadius(TQ3GeometryObject disk, const TQ3Vector3D *majorRadius);

/**
 * Reads the major radius of a retained disk.
 *
 * @return kQ3Success, or kQ3Failure with *majorRadius unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      disk or majorRadius is NULL.
 *   kQ3ErrorInvalidObject      disk is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  disk is not a disk.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Disk_GetMajorRadius(TQ3GeometryObject disk, TQ3Vector3D *majorRadius);

/**
 * Sets the minor radius of a retained disk; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the disk unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      disk or minorRadius is NULL.
 *   kQ3ErrorInvalidObject      disk is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  disk is not a disk.
 *   kQ3ErrorInvalidData        a component is not finite, or the disk
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the disk's vectors are not independent: the
 *                              value is kept and the disk draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Disk_SetMinorRadius(TQ3GeometryObject disk, const TQ3Vector3D *minorRadius);

/**
 * Reads the minor radius of a retained disk.
 *
 * @return kQ3Success, or kQ3Failure with *minorRadius unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      disk or minorRadius is NULL.
 *   kQ3ErrorInvalidObject      disk is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  disk is not a disk.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Disk_GetMinorRadius(TQ3GeometryObject disk, TQ3Vector3D *minorRadius);

/*
 * An ellipse (a curve):
 *   P(u) = origin + cos(2 pi u) majorRadius + sin(2 pi u) minorRadius,
 * drawn from uMin to uMax. It is drawn as a polyline and subdivided as a
 * curve: constant, c1 segments per full turn (in proportion for a part,
 * rounded up; at least 3 for a full turn); world and screen space, segments
 * whose drawn length is at most c1 and, but for the last, at least 0.98 c1.
 *
 * The rules a TQ3EllipseData must obey wherever one is accepted, checked in
 * this order:
 *   every coordinate and parameter is finite; the
 *     ellipse within float's range                  kQ3ErrorInvalidData
 *   uMin and uMax in [0, 1]                         kQ3ErrorInvalidData
 *   ellipseAttributeSet is NULL or a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 * Tolerated, with kQ3WarningInconsistentData: a degenerate ellipse (its
 * vectors not independent, an empty range), kept as given; drawn as its
 * segment, or as nothing for an empty range (see above).
 */
struct TQ3EllipseData {
    TQ3Point3D origin;
    TQ3Vector3D majorRadius;
    TQ3Vector3D minorRadius;
    float uMin;
    float uMax;
    TQ3AttributeSet ellipseAttributeSet;
};
typedef struct TQ3EllipseData TQ3EllipseData;

/**
 * Creates a retained ellipse from a copy of ellipseData (the data calls at the top
 * of this header).
 *
 * @return the new ellipse, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipseData is NULL.
 *   then the codes of the TQ3EllipseData rules, in their order;
 *   kQ3ErrorOutOfMemory        the ellipse cannot be allocated.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3EllipseData rules): kept, drawn as a
 *                              segment (nothing for an empty range).
 *
 * Ownership: the caller owns the new ellipse's one reference. The ellipse
 * takes its own reference to every attribute set given.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Ellipse_New(const TQ3EllipseData *ellipseData);

/**
 * Draws (or bounds) an ellipse without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipseData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3EllipseData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3EllipseData rules): kept, drawn as a
 *                              segment (nothing for an empty range).
 *   kQ3WarningParameterOutOfRange  the subdivision style asks for more than
 *                              kQ3SubdivisionMaxSegmentsPerCurve segments
 *                              (QD3DStyle.h); fewer are drawn.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipse_Submit(const TQ3EllipseData *ellipseData, TQ3ViewObject view);

/**
 * Replaces the data of a retained ellipse with a copy of ellipseData.
 *
 * @return kQ3Success, or kQ3Failure with the ellipse unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipse or ellipseData is NULL.
 *   kQ3ErrorInvalidObject      ellipse is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipse is not an ellipse.
 *   then the codes of the TQ3EllipseData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3EllipseData rules): kept, drawn as a
 *                              segment (nothing for an empty range).
 *
 * Ownership: the ellipse references the attribute sets given and releases
 * those it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipse_SetData(TQ3GeometryObject ellipse, const TQ3EllipseData *ellipseData);

/**
 * Copies the data of a retained ellipse into ellipseData.
 *
 * @return kQ3Success, or kQ3Failure with *ellipseData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipse or ellipseData is NULL.
 *   kQ3ErrorInvalidObject      ellipse is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipse is not an ellipse.
 *
 * Ownership: the caller owns a new reference to every attribute set in the
 * result and gives them back with Q3Ellipse_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipse_GetData(TQ3GeometryObject ellipse, TQ3EllipseData *ellipseData);

/**
 * Releases what Q3Ellipse_GetData put in ellipseData: the attribute set
 * references; the pointers become NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipseData is NULL.
 *   kQ3ErrorInvalidObject      an attribute set in it is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set in it is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipse_EmptyData(TQ3EllipseData *ellipseData);

/**
 * Sets the origin (the centre) of a retained ellipse; the rest of its data
 * stays.
 *
 * @return kQ3Success, or kQ3Failure with the ellipse unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipse or origin is NULL.
 *   kQ3ErrorInvalidObject      ellipse is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipse is not an ellipse.
 *   kQ3ErrorInvalidData        a coordinate is not finite, or the ellipse
 *                              would leave float's range.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipse_SetOrigin(TQ3GeometryObject ellipse, const TQ3Point3D *origin);

/**
 * Reads the origin (the centre) of a retained ellipse.
 *
 * @return kQ3Success, or kQ3Failure with *origin unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipse or origin is NULL.
 *   kQ3ErrorInvalidObject      ellipse is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipse is not an ellipse.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipse_GetOrigin(TQ3GeometryObject ellipse, TQ3Point3D *origin);

/**
 * Sets the major radius of a retained ellipse; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the ellipse unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipse or majorRadius is NULL.
 *   kQ3ErrorInvalidObject      ellipse is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipse is not an ellipse.
 *   kQ3ErrorInvalidData        a component is not finite, or the ellipse
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the ellipse's vectors are not independent: the
 *                              value is kept and the ellipse is drawn as a
 *                              segment.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipse_SetMajorRadius(TQ3GeometryObject ellipse, const TQ3Vector3D *majorRadius);

/**
 * Reads the major radius of a retained ellipse.
 *
 * @return kQ3Success, or kQ3Failure with *majorRadius unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipse or majorRadius is NULL.
 *   kQ3ErrorInvalidObject      ellipse is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipse is not an ellipse.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipse_GetMajorRadius(TQ3GeometryObject ellipse, TQ3Vector3D *majorRadius);

/**
 * Sets the minor radius of a retained ellipse; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the ellipse unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipse or minorRadius is NULL.
 *   kQ3ErrorInvalidObject      ellipse is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipse is not an ellipse.
 *   kQ3ErrorInvalidData        a component is not finite, or the ellipse
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the ellipse's vectors are not independent: the
 *                              value is kept and the ellipse is drawn as a
 *                              segment.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipse_SetMinorRadius(TQ3GeometryObject ellipse, const TQ3Vector3D *minorRadius);

/**
 * Reads the minor radius of a retained ellipse.
 *
 * @return kQ3Success, or kQ3Failure with *minorRadius unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipse or minorRadius is NULL.
 *   kQ3ErrorInvalidObject      ellipse is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipse is not an ellipse.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipse_GetMinorRadius(TQ3GeometryObject ellipse, TQ3Vector3D *minorRadius);

/*
 * An ellipsoid:
 *   P(u, v) = origin - cos(pi v) orientation
 *             + sin(pi v) (cos(2 pi u) majorRadius + sin(2 pi u) minorRadius),
 * v = 0 the pole at origin - orientation, v = 1 the pole at origin +
 * orientation: uMin..uMax keeps a wedge, vMin..vMax a band. Caps, all with
 * interiorAttributeSet (the data has no other part set):
 * kQ3EndCapMaskBottom and kQ3EndCapMaskTop close the cuts at vMin > 0 and
 * vMax < 1 with flat ellipses, kQ3EndCapMaskInterior the faces at uMin and
 * uMax (from the axis to the surface) when u is not a full turn. Apple's
 * header has no Q3Ellipsoid_SetCaps: caps are set with the data. Constant
 * subdivision: c1 around, c2 from pole to pole.
 *
 * The rules a TQ3EllipsoidData must obey wherever one is accepted, checked in
 * this order:
 *   every coordinate and parameter is finite; the
 *     ellipsoid within float's range                kQ3ErrorInvalidData
 *   uMin, uMax, vMin, vMax in [0, 1]; vMin <= vMax  kQ3ErrorInvalidData
 *   caps holds only end cap masks                   kQ3ErrorInvalidData
 *   every attribute set given is a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 * Tolerated, with kQ3WarningInconsistentData: a degenerate ellipsoid (its
 * vectors not independent, an empty range), kept as given and
 * drawn as nothing (see above).
 */
struct TQ3EllipsoidData {
    TQ3Point3D origin;
    TQ3Vector3D orientation;
    TQ3Vector3D majorRadius;
    TQ3Vector3D minorRadius;
    float uMin;
    float uMax;
    float vMin;
    float vMax;
    TQ3EndCap caps;
    TQ3AttributeSet interiorAttributeSet;
    TQ3AttributeSet ellipsoidAttributeSet;
};
typedef struct TQ3EllipsoidData TQ3EllipsoidData;

/**
 * Creates a retained ellipsoid from a copy of ellipsoidData (the data calls at the top
 * of this header).
 *
 * @return the new ellipsoid, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipsoidData is NULL.
 *   then the codes of the TQ3EllipsoidData rules, in their order;
 *   kQ3ErrorOutOfMemory        the ellipsoid cannot be allocated.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3EllipsoidData rules): kept, drawn as nothing.
 *
 * Ownership: the caller owns the new ellipsoid's one reference. The ellipsoid
 * takes its own reference to every attribute set given.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Ellipsoid_New(const TQ3EllipsoidData *ellipsoidData);

/**
 * Draws (or bounds) a ellipsoid without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipsoidData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3EllipsoidData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3EllipsoidData rules): kept, drawn as nothing.
 *   kQ3WarningParameterOutOfRange  the subdivision style asks for more than
 *                              kQ3SubdivisionMaxTrianglesPerSurface triangles
 *                              (QD3DStyle.h); fewer are drawn.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipsoid_Submit(const TQ3EllipsoidData *ellipsoidData, TQ3ViewObject view);

/**
 * Replaces the data of a retained ellipsoid with a copy of ellipsoidData.
 *
 * @return kQ3Success, or kQ3Failure with the ellipsoid unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipsoid or ellipsoidData is NULL.
 *   kQ3ErrorInvalidObject      ellipsoid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipsoid is not an ellipsoid.
 *   then the codes of the TQ3EllipsoidData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3EllipsoidData rules): kept, drawn as nothing.
 *
 * Ownership: the ellipsoid references the attribute sets given and releases
 * those it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipsoid_SetData(TQ3GeometryObject ellipsoid, const TQ3EllipsoidData *ellipsoidData);

/**
 * Copies the data of a retained ellipsoid into ellipsoidData.
 *
 * @return kQ3Success, or kQ3Failure with *ellipsoidData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipsoid or ellipsoidData is NULL.
 *   kQ3ErrorInvalidObject      ellipsoid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipsoid is not an ellipsoid.
 *
 * Ownership: the caller owns a new reference to every attribute set in the
 * result and gives them back with Q3Ellipsoid_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipsoid_GetData(TQ3GeometryObject ellipsoid, TQ3EllipsoidData *ellipsoidData);

/**
 * Releases what Q3Ellipsoid_GetData put in ellipsoidData: the attribute set
 * references; the pointers become NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipsoidData is NULL.
 *   kQ3ErrorInvalidObject      an attribute set in it is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set in it is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipsoid_EmptyData(TQ3EllipsoidData *ellipsoidData);

/**
 * Sets the origin (the centre) of a retained ellipsoid; the rest of its data
 * stays.
 *
 * @return kQ3Success, or kQ3Failure with the ellipsoid unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipsoid or origin is NULL.
 *   kQ3ErrorInvalidObject      ellipsoid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipsoid is not an ellipsoid.
 *   kQ3ErrorInvalidData        a coordinate is not finite, or the ellipsoid
 *                              would leave float's range.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipsoid_SetOrigin(TQ3GeometryObject ellipsoid, const TQ3Point3D *origin);

/**
 * Reads the origin (the centre) of a retained ellipsoid.
 *
 * @return kQ3Success, or kQ3Failure with *origin unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipsoid or origin is NULL.
 *   kQ3ErrorInvalidObject      ellipsoid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipsoid is not an ellipsoid.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipsoid_GetOrigin(TQ3GeometryObject ellipsoid, TQ3Point3D *origin);

/**
 * Sets the orientation (from the centre to the pole at v = 1) of a retained
 * ellipsoid; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the ellipsoid unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipsoid or orientation is NULL.
 *   kQ3ErrorInvalidObject      ellipsoid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipsoid is not an ellipsoid.
 *   kQ3ErrorInvalidData        a component is not finite, or the ellipsoid
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the ellipsoid's vectors are not independent: the
 *                              value is kept and the ellipsoid draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipsoid_SetOrientation(TQ3GeometryObject ellipsoid, const TQ3Vector3D *orientation);

/**
 * Reads the orientation (from the centre to the pole at v = 1) of a retained
 * ellipsoid.
 *
 * @return kQ3Success, or kQ3Failure with *orientation unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipsoid or orientation is NULL.
 *   kQ3ErrorInvalidObject      ellipsoid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipsoid is not an ellipsoid.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipsoid_GetOrientation(TQ3GeometryObject ellipsoid, TQ3Vector3D *orientation);

/**
 * Sets the major radius of a retained ellipsoid; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the ellipsoid unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipsoid or majorRadius is NULL.
 *   kQ3ErrorInvalidObject      ellipsoid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipsoid is not an ellipsoid.
 *   kQ3ErrorInvalidData        a component is not finite, or the ellipsoid
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the ellipsoid's vectors are not independent: the
 *                              value is kept and the ellipsoid draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipsoid_SetMajorRadius(TQ3GeometryObject ellipsoid, const TQ3Vector3D *majorRadius);

/**
 * Reads the major radius of a retained ellipsoid.
 *
 * @return kQ3Success, or kQ3Failure with *majorRadius unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipsoid or majorRadius is NULL.
 *   kQ3ErrorInvalidObject      ellipsoid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipsoid is not an ellipsoid.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipsoid_GetMajorRadius(TQ3GeometryObject ellipsoid, TQ3Vector3D *majorRadius);

/**
 * Sets the minor radius of a retained ellipsoid; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the ellipsoid unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipsoid or minorRadius is NULL.
 *   kQ3ErrorInvalidObject      ellipsoid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipsoid is not an ellipsoid.
 *   kQ3ErrorInvalidData        a component is not finite, or the ellipsoid
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the ellipsoid's vectors are not independent: the
 *                              value is kept and the ellipsoid draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipsoid_SetMinorRadius(TQ3GeometryObject ellipsoid, const TQ3Vector3D *minorRadius);

/**
 * Reads the minor radius of a retained ellipsoid.
 *
 * @return kQ3Success, or kQ3Failure with *minorRadius unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      ellipsoid or minorRadius is NULL.
 *   kQ3ErrorInvalidObject      ellipsoid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  ellipsoid is not an ellipsoid.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Ellipsoid_GetMinorRadius(TQ3GeometryObject ellipsoid, TQ3Vector3D *minorRadius);

/*
 * A torus: a ring, the ellipse a(u) = cos(2 pi u) majorRadius +
 * sin(2 pi u) minorRadius around origin, and a tube around it whose cross
 * section is an ellipse of half-axes |orientation| along orientation and
 * ratio |orientation| along the ring's radius (3DMF reference: ratio is
 * the length of the rotated ellipse's major radius over the orientation's):
 *   P(u, v) = origin + a(u) - sin(2 pi v) orientation
 *             - cos(2 pi v) ratio |orientation| a(u) / |a(u)|.
 * v = 0 is the inner equator (nearest the ring's centre) and v = 1/4 the
 * bottom, as Quesa draws it to match QuickDraw 3D's texture mapping. Both u
 * and v are angles: either range may wrap through 0. Apple asks for
 * orientation orthogonal to the radii; Q3 draws other independent frames by
 * the same formula (a sheared torus). Caps: kQ3EndCapMaskInterior closes the
 * cuts with interiorAttributeSet: the tube's cross-sections at uMin and uMax
 * when u is not a full turn (between the tube's centre line and the
 * surface) and, when v is not a full turn, the walls from the centre line
 * to the edges at vMin and vMax; top and bottom mean nothing for a torus and
 * are ignored. Apple's header has no Q3Torus_SetCaps. Constant
 * subdivision: c1 around the ring, c2 around the tube.
 *
 * The rules a TQ3TorusData must obey wherever one is accepted, checked in
 * this order:
 *   every coordinate and parameter is finite; the
 *     torus within float's range                    kQ3ErrorInvalidData
 *   uMin, uMax, vMin, vMax in [0, 1]                kQ3ErrorInvalidData
 *   ratio >= 0                                      kQ3ErrorInvalidData
 *   caps holds only end cap masks                   kQ3ErrorInvalidData
 *   every attribute set given is a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 * Tolerated, with kQ3WarningInconsistentData: a degenerate torus (its
 * vectors not independent, an empty range, ratio 0), kept as given and
 * drawn as nothing (see above).
 */
struct TQ3TorusData {
    TQ3Point3D origin;
    TQ3Vector3D orientation;
    TQ3Vector3D majorRadius;
    TQ3Vector3D minorRadius;
    float ratio;
    float uMin;
    float uMax;
    float vMin;
    float vMax;
    TQ3EndCap caps;
    TQ3AttributeSet interiorAttributeSet;
    TQ3AttributeSet torusAttributeSet;
};
typedef struct TQ3TorusData TQ3TorusData;

/**
 * Creates a retained torus from a copy of torusData (the data calls at the top
 * of this header).
 *
 * @return the new torus, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torusData is NULL.
 *   then the codes of the TQ3TorusData rules, in their order;
 *   kQ3ErrorOutOfMemory        the torus cannot be allocated.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3TorusData rules): kept, drawn as nothing.
 *
 * Ownership: the caller owns the new torus's one reference. The torus
 * takes its own reference to every attribute set given.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Torus_New(const TQ3TorusData *torusData);

/**
 * Draws (or bounds) a torus without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torusData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3TorusData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3TorusData rules): kept, drawn as nothing.
 *   kQ3WarningParameterOutOfRange  the subdivision style asks for more than
 *                              kQ3SubdivisionMaxTrianglesPerSurface triangles
 *                              (QD3DStyle.h); fewer are drawn.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_Submit(const TQ3TorusData *torusData, TQ3ViewObject view);

/**
 * Replaces the data of a retained torus with a copy of torusData.
 *
 * @return kQ3Success, or kQ3Failure with the torus unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torus or torusData is NULL.
 *   kQ3ErrorInvalidObject      torus is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  torus is not a torus.
 *   then the codes of the TQ3TorusData rules, in their order.
 * Warnings:
 *   kQ3WarningInconsistentData the data is degenerate (the tolerated cases
 *                              of the TQ3TorusData rules): kept, drawn as nothing.
 *
 * Ownership: the torus references the attribute sets given and releases
 * those it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_SetData(TQ3GeometryObject torus, const TQ3TorusData *torusData);

/**
 * Copies the data of a retained torus into torusData.
 *
 * @return kQ3Success, or kQ3Failure with *torusData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torus or torusData is NULL.
 *   kQ3ErrorInvalidObject      torus is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  torus is not a torus.
 *
 * Ownership: the caller owns a new reference to every attribute set in the
 * result and gives them back with Q3Torus_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_GetData(TQ3GeometryObject torus, TQ3TorusData *torusData);

/**
 * Releases what Q3Torus_GetData put in torusData: the attribute set
 * references; the pointers become NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torusData is NULL.
 *   kQ3ErrorInvalidObject      an attribute set in it is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set in it is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_EmptyData(TQ3TorusData *torusData);

/**
 * Sets the origin (the centre of the ring) of a retained torus; the rest of
 * its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the torus unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torus or origin is NULL.
 *   kQ3ErrorInvalidObject      torus is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  torus is not a torus.
 *   kQ3ErrorInvalidData        a coordinate is not finite, or the torus
 *                              would leave float's range.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_SetOrigin(TQ3GeometryObject torus, const TQ3Point3D *origin);

/**
 * Reads the origin (the centre of the ring) of a retained torus.
 *
 * @return kQ3Success, or kQ3Failure with *origin unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torus or origin is NULL.
 *   kQ3ErrorInvalidObject      torus is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  torus is not a torus.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_GetOrigin(TQ3GeometryObject torus, TQ3Point3D *origin);

/**
 * Sets the orientation (the tube's half-thickness along the ring's axis) of
 * a retained torus; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the torus unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torus or orientation is NULL.
 *   kQ3ErrorInvalidObject      torus is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  torus is not a torus.
 *   kQ3ErrorInvalidData        a component is not finite, or the torus
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the torus's vectors are not independent: the
 *                              value is kept and the torus draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_SetOrientation(TQ3GeometryObject torus, const TQ3Vector3D *orientation);

/**
 * Reads the orientation (the tube's half-thickness along the ring's axis) of
 * a retained torus.
 *
 * @return kQ3Success, or kQ3Failure with *orientation unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torus or orientation is NULL.
 *   kQ3ErrorInvalidObject      torus is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  torus is not a torus.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_GetOrientation(TQ3GeometryObject torus, TQ3Vector3D *orientation);

/**
 * Sets the major radius of a retained torus; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the torus unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torus or majorRadius is NULL.
 *   kQ3ErrorInvalidObject      torus is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  torus is not a torus.
 *   kQ3ErrorInvalidData        a component is not finite, or the torus
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the torus's vectors are not independent: the
 *                              value is kept and the torus draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_SetMajorRadius(TQ3GeometryObject torus, const TQ3Vector3D *majorRadius);

/**
 * Reads the major radius of a retained torus.
 *
 * @return kQ3Success, or kQ3Failure with *majorRadius unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torus or majorRadius is NULL.
 *   kQ3ErrorInvalidObject      torus is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  torus is not a torus.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_GetMajorRadius(TQ3GeometryObject torus, TQ3Vector3D *majorRadius);

/**
 * Sets the minor radius of a retained torus; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the torus unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torus or minorRadius is NULL.
 *   kQ3ErrorInvalidObject      torus is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  torus is not a torus.
 *   kQ3ErrorInvalidData        a component is not finite, or the torus
 *                              would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData the torus's vectors are not independent: the
 *                              value is kept and the torus draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_SetMinorRadius(TQ3GeometryObject torus, const TQ3Vector3D *minorRadius);

/**
 * Reads the minor radius of a retained torus.
 *
 * @return kQ3Success, or kQ3Failure with *minorRadius unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torus or minorRadius is NULL.
 *   kQ3ErrorInvalidObject      torus is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  torus is not a torus.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_GetMinorRadius(TQ3GeometryObject torus, TQ3Vector3D *minorRadius);

/**
 * Sets the ratio (of the tube's radial half-axis to |orientation|) of a
 * retained torus; the rest of its data stays.
 *
 * @return kQ3Success, or kQ3Failure with the torus unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torus is NULL.
 *   kQ3ErrorInvalidObject      torus is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  torus is not a torus.
 *   kQ3ErrorInvalidData        ratio is not finite or is negative, or the
 *                              torus would leave float's range.
 * Warnings:
 *   kQ3WarningInconsistentData ratio is 0 (a tube with no thickness): kept,
 *                              and the torus draws nothing.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_SetRatio(TQ3GeometryObject torus, float ratio);

/**
 * Reads the ratio (of the tube's radial half-axis to |orientation|) of a
 * retained torus.
 *
 * @return kQ3Success, or kQ3Failure with *ratio unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      torus or ratio is NULL.
 *   kQ3ErrorInvalidObject      torus is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  torus is not a torus.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Torus_GetRatio(TQ3GeometryObject torus, float *ratio);

/* ---- Mesh --------------------------------------------------------------- */

/*
 * A mesh is a retained polyhedral surface built and edited call by call: it
 * has no data structure and no Submit (QuickDraw 3D 1.6 declares none); draw
 * it with Q3Geometry_Submit or Q3Object_Submit.
 *
 * Parts. Vertices (a point and an attribute set) are added with
 * Q3Mesh_VertexNew. A face is a list of contours, each a closed loop of at
 * least 3 distinct vertices: Q3Mesh_FaceNew makes a face of one contour,
 * Q3Mesh_FaceToContour moves another face's contours into it. A face covers
 * what lies inside an odd number of its contours, measured in the plane of
 * its first contour (the even-odd rule: a contour inside another is a hole,
 * whichever way it runs). An edge joins two vertices that follow each other
 * in some contour; faces that run along the same two vertices share it. A
 * corner is a vertex of a face; it may have its own attribute set. A
 * component is a maximal set of faces connected through shared vertices,
 * with their vertices and edges; a vertex in no face belongs to none.
 *
 * Attributes. A triangle corner takes each attribute from its corner's set,
 * then its vertex's, then its face's, then the mesh's (Q3Geometry_
 * SetAttributeSet), then the view's state. An edge's diffuse colour is the
 * colour of its line in the wireframe.
 *
 * Handles. TQ3MeshVertex, TQ3MeshFace, TQ3MeshEdge, TQ3MeshContour and
 * TQ3MeshComponent are opaque values, never pointers Q3 dereferences: each
 * names one part of one mesh and is never reused. A handle of a deleted
 * part, of another mesh, of another kind, or any other value is refused
 * with kQ3ErrorInvalidParameter (NULL with kQ3ErrorNULLParameter); nothing
 * is changed and nothing is read through it. An edge lives while some
 * contour runs along it (its attribute set goes with it). A component
 * handle names its component by the component's first vertex (the earliest
 * made); once an edit gives the component another first vertex (merging
 * it into an earlier one, splitting it, deleting that vertex) the handle is
 * refused.
 *
 * Order. Vertices, faces and edges are counted, indexed and iterated in the
 * order they were made, components in the order of their first vertices.
 * A vertex's or face's index is its place in that order (0 first), so
 * deleting one renumbers those after it.
 *
 * Q3Object_Duplicate copies the whole mesh (its parts get new handles;
 * every distinct attribute set is duplicated once). Counts are bounded: at
 * most kQ3GeometryMaxArrayCount vertices, faces, and vertices per face
 * (kQ3ErrorParameterOutOfRange beyond).
 *
 * Every function below checks, in order: Q3 is initialized; a mesh handle
 * is not NULL (kQ3ErrorNULLParameter), a live Q3 object
 * (kQ3ErrorInvalidObject), a mesh (kQ3ErrorInvalidObjectType); each part
 * handle as above; each pointer is not NULL; then the function's own
 * conditions. These common errors are not repeated below.
 */

typedef struct OpaqueTQ3MeshComponent *TQ3MeshComponent;
typedef struct OpaqueTQ3MeshVertex *TQ3MeshVertex;
typedef struct OpaqueTQ3MeshFace *TQ3MeshFace;
typedef struct OpaqueTQ3MeshEdge *TQ3MeshEdge;
typedef struct OpaqueTQ3MeshContour *TQ3MeshContour;

/**
 * Creates an empty mesh: no vertices, faces or edges.
 *
 * @return the new mesh, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorOutOfMemory        the mesh could not be allocated.
 *
 * Ownership: the caller owns the one reference to the new mesh.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Mesh_New(void);

/**
 * Adds a vertex at vertex->point with the attribute set
 * vertex->attributeSet (NULL for none). It belongs to no face yet.
 *
 * @return the new vertex, or NULL on failure (the mesh unchanged).
 *
 * Errors (besides the common ones):
 *   kQ3ErrorInvalidData        a coordinate of vertex->point is not finite.
 *   kQ3ErrorInvalidObject      vertex->attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  vertex->attributeSet is not an attribute set.
 *   kQ3ErrorParameterOutOfRange the mesh has kQ3GeometryMaxArrayCount vertices.
 *
 * Ownership: the mesh takes its own reference to vertex->attributeSet.
 */
Q3_EXTERN_API_C(TQ3MeshVertex) Q3Mesh_VertexNew(TQ3GeometryObject mesh, const TQ3Vertex3D *vertex);

/**
 * Adds a face of one contour running through vertices[0 .. numVertices-1]
 * (closed from the last back to the first), with the attribute set
 * attributeSet (NULL for none). Edges are made where the face runs between
 * two vertices no contour joined before. The contour may pass a vertex more
 * than once, and an edge may have any number of faces: QuickDraw 3D and
 * Quesa keep such meshes, and so does Q3, with no warning (the face is
 * drawn as the area its contour encloses; docs/3dmf.md, Tolerances). The
 * face's vertex count and walk give each of its vertices once.
 *
 * @return the new face, or NULL on failure (the mesh unchanged).
 *
 * Errors (besides the common ones; vertices is checked for NULL first):
 *   kQ3ErrorGeometryInsufficientNumberOfPoints numVertices < 3.
 *   kQ3ErrorParameterOutOfRange numVertices > kQ3GeometryMaxArrayCount, or
 *                              the mesh has kQ3GeometryMaxArrayCount faces.
 *   kQ3ErrorNULLParameter      an entry of vertices is NULL.
 *   kQ3ErrorInvalidParameter   an entry is not a vertex of this mesh.
 *   kQ3ErrorInvalidObject      attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  attributeSet is not an attribute set.
 *
 * Ownership: the mesh takes its own reference to attributeSet.
 */
Q3_EXTERN_API_C(TQ3MeshFace) Q3Mesh_FaceNew(TQ3GeometryObject mesh, unsigned long numVertices,
                                            const TQ3MeshVertex *vertices, TQ3AttributeSet attributeSet);

/**
 * Deletes a vertex and every face that has it as a corner (with those
 * faces' contours, corners and the edges no other contour runs along).
 *
 * @return kQ3Success, or kQ3Failure with the mesh unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: the references the mesh held for what it deletes are released.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_VertexDelete(TQ3GeometryObject mesh, TQ3MeshVertex vertex);

/**
 * Deletes a face with its contours and corners, and the edges no other
 * contour runs along. Its vertices stay.
 *
 * @return kQ3Success, or kQ3Failure with the mesh unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: the references the mesh held for what it deletes are released.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_FaceDelete(TQ3GeometryObject mesh, TQ3MeshFace face);

/**
 * QuickDraw 3D let a program suspend the mesh's bookkeeping during long
 * edits. Q3 works out components, indices and orientation only when they
 * are asked for, so every result is the same with or without it; the call
 * marks the mesh as delayed until Q3Mesh_ResumeUpdates.
 *
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_DelayUpdates(TQ3GeometryObject mesh);

/**
 * Ends Q3Mesh_DelayUpdates (a mesh that is not delayed stays as it is).
 *
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_ResumeUpdates(TQ3GeometryObject mesh);

/**
 * Moves every contour of face to the end of containerFace's contours (a
 * hole, or an island in a hole, by the even-odd rule) and deletes face with
 * its attribute set; its corners' attribute sets move with the contours
 * where containerFace has no corner set for that vertex.
 *
 * @return the contour that was face's first, or NULL on failure (the mesh
 *         unchanged).
 *
 * Errors (besides the common ones):
 *   kQ3ErrorInvalidParameter   face is containerFace, or containerFace
 *                              would pass kQ3GeometryMaxArrayCount vertices.
 *
 * Ownership: face's attribute set reference is released.
 */
Q3_EXTERN_API_C(TQ3MeshContour) Q3Mesh_FaceToContour(TQ3GeometryObject mesh, TQ3MeshFace containerFace,
                                                     TQ3MeshFace face);

/**
 * Takes contour out of its face and makes it a face of its own, with no
 * attribute set; the corner sets of its vertices are copied to the new
 * face. A contour that is its face's only one is already a face: that face
 * is returned and nothing changes.
 *
 * @return the face, or NULL on failure (the mesh unchanged).
 *
 * Errors (besides the common ones):
 *   kQ3ErrorParameterOutOfRange the mesh has kQ3GeometryMaxArrayCount faces.
 *
 * Ownership: no references are handed to the caller.
 */
Q3_EXTERN_API_C(TQ3MeshFace) Q3Mesh_ContourToFace(TQ3GeometryObject mesh, TQ3MeshContour contour);

/**
 * The number of components (connected sets of faces) of the mesh.
 *
 * @return kQ3Success, or kQ3Failure with *numComponents unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetNumComponents(TQ3GeometryObject mesh, unsigned long *numComponents);

/**
 * The number of edges of the mesh.
 *
 * @return kQ3Success, or kQ3Failure with *numEdges unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetNumEdges(TQ3GeometryObject mesh, unsigned long *numEdges);

/**
 * The number of vertices of the mesh, in faces or not.
 *
 * @return kQ3Success, or kQ3Failure with *numVertices unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetNumVertices(TQ3GeometryObject mesh, unsigned long *numVertices);

/**
 * The number of faces of the mesh.
 *
 * @return kQ3Success, or kQ3Failure with *numFaces unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetNumFaces(TQ3GeometryObject mesh, unsigned long *numFaces);

/**
 * The number of corners that have an attribute set of their own
 * (Q3Mesh_SetCornerAttributeSet): the corners a 3DMF file lists.
 *
 * @return kQ3Success, or kQ3Failure with *numCorners unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetNumCorners(TQ3GeometryObject mesh, unsigned long *numCorners);

/**
 * Whether every component is orientable: its faces can each be given a
 * direction so that every edge two face sides run along is run in opposite
 * directions by them. An edge that more than two sides run along makes its
 * component not orientable. A mesh with no faces is orientable.
 *
 * @return kQ3Success, or kQ3Failure with *orientable unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetOrientable(TQ3GeometryObject mesh, TQ3Boolean *orientable);

/**
 * The number of vertices of a component.
 *
 * @return kQ3Success, or kQ3Failure with *numVertices unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetComponentNumVertices(TQ3GeometryObject mesh, TQ3MeshComponent component,
                                                          unsigned long *numVertices);

/**
 * The number of edges of a component.
 *
 * @return kQ3Success, or kQ3Failure with *numEdges unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetComponentNumEdges(TQ3GeometryObject mesh, TQ3MeshComponent component,
                                                       unsigned long *numEdges);

/**
 * The smallest axis-aligned box holding a component's vertices (isEmpty is
 * kQ3False).
 *
 * @return kQ3Success, or kQ3Failure with *boundingBox unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetComponentBoundingBox(TQ3GeometryObject mesh, TQ3MeshComponent component,
                                                          TQ3BoundingBox *boundingBox);

/**
 * Whether a component is orientable (Q3Mesh_GetOrientable's rule).
 *
 * @return kQ3Success, or kQ3Failure with *orientable unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetComponentOrientable(TQ3GeometryObject mesh, TQ3MeshComponent component,
                                                         TQ3Boolean *orientable);

/**
 * A vertex's coordinates.
 *
 * @return kQ3Success, or kQ3Failure with *coordinates unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetVertexCoordinates(TQ3GeometryObject mesh, TQ3MeshVertex vertex,
                                                       TQ3Point3D *coordinates);

/**
 * A vertex's index: its place among the mesh's vertices in the order they
 * were made, 0 first.
 *
 * @return kQ3Success, or kQ3Failure with *index unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetVertexIndex(TQ3GeometryObject mesh, TQ3MeshVertex vertex, unsigned long *index);

/**
 * Whether a vertex is an end of a boundary edge (Q3Mesh_GetEdgeOnBoundary);
 * a vertex in no face is not.
 *
 * @return kQ3Success, or kQ3Failure with *onBoundary unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetVertexOnBoundary(TQ3GeometryObject mesh, TQ3MeshVertex vertex,
                                                      TQ3Boolean *onBoundary);

/**
 * The component a vertex belongs to. A vertex in no face belongs to none:
 * *component is then NULL and the notice kQ3NoticeMeshVertexHasNoComponent
 * is posted (the call succeeds).
 *
 * @return kQ3Success, or kQ3Failure with *component unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetVertexComponent(TQ3GeometryObject mesh, TQ3MeshVertex vertex,
                                                     TQ3MeshComponent *component);

/**
 * A vertex's attribute set.
 *
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: *attributeSet is a new reference for the caller, or NULL.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetVertexAttributeSet(TQ3GeometryObject mesh, TQ3MeshVertex vertex,
                                                        TQ3AttributeSet *attributeSet);

/**
 * Moves a vertex.
 *
 * @return kQ3Success, or kQ3Failure with the mesh unchanged.
 *
 * Errors (besides the common ones):
 *   kQ3ErrorInvalidData        a coordinate is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_SetVertexCoordinates(TQ3GeometryObject mesh, TQ3MeshVertex vertex,
                                                       const TQ3Point3D *coordinates);

/**
 * Replaces a vertex's attribute set (NULL removes it).
 *
 * @return kQ3Success, or kQ3Failure with the mesh unchanged.
 *
 * Errors (besides the common ones):
 *   kQ3ErrorInvalidObject      attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  attributeSet is not an attribute set.
 *
 * Ownership: the mesh takes its own reference to attributeSet and releases
 * the old one.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_SetVertexAttributeSet(TQ3GeometryObject mesh, TQ3MeshVertex vertex,
                                                        TQ3AttributeSet attributeSet);

/**
 * The number of corners of a face: its contours' vertices, each vertex
 * counted once.
 *
 * @return kQ3Success, or kQ3Failure with *numVertices unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetFaceNumVertices(TQ3GeometryObject mesh, TQ3MeshFace face,
                                                     unsigned long *numVertices);

/**
 * The plane of a face's first contour: a unit normal (the direction from
 * which the contour runs counterclockwise, by Newell's method) and the
 * constant d of normal . p + d = 0 at the contour's centroid.
 *
 * @return kQ3Success, or kQ3Failure with *planeEquation unchanged.
 *
 * Errors (besides the common ones):
 *   kQ3ErrorDegenerateGeometry the first contour encloses no area.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetFacePlaneEquation(TQ3GeometryObject mesh, TQ3MeshFace face,
                                                       TQ3PlaneEquation *planeEquation);

/**
 * The number of contours of a face (1 for a face made by Q3Mesh_FaceNew).
 *
 * @return kQ3Success, or kQ3Failure with *numContours unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetFaceNumContours(TQ3GeometryObject mesh, TQ3MeshFace face,
                                                     unsigned long *numContours);

/**
 * A face's index: its place among the mesh's faces in the order they were
 * made, 0 first.
 *
 * @return kQ3Success, or kQ3Failure with *index unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetFaceIndex(TQ3GeometryObject mesh, TQ3MeshFace face, unsigned long *index);

/**
 * The component a face belongs to.
 *
 * @return kQ3Success, or kQ3Failure with *component unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetFaceComponent(TQ3GeometryObject mesh, TQ3MeshFace face,
                                                   TQ3MeshComponent *component);

/**
 * A face's attribute set.
 *
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: *attributeSet is a new reference for the caller, or NULL.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetFaceAttributeSet(TQ3GeometryObject mesh, TQ3MeshFace face,
                                                      TQ3AttributeSet *attributeSet);

/**
 * Replaces a face's attribute set (NULL removes it).
 *
 * @return kQ3Success, or kQ3Failure with the mesh unchanged.
 *
 * Errors (besides the common ones):
 *   kQ3ErrorInvalidObject      attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  attributeSet is not an attribute set.
 *
 * Ownership: the mesh takes its own reference to attributeSet and releases
 * the old one.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_SetFaceAttributeSet(TQ3GeometryObject mesh, TQ3MeshFace face,
                                                      TQ3AttributeSet attributeSet);

/**
 * An edge's two vertices, in the direction of the contour that made it.
 *
 * @return kQ3Success, or kQ3Failure with *vertex1 and *vertex2 unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetEdgeVertices(TQ3GeometryObject mesh, TQ3MeshEdge edge, TQ3MeshVertex *vertex1,
                                                  TQ3MeshVertex *vertex2);

/**
 * The faces on either side of an edge: the first two (in the order faces
 * were made) whose contours run along it; *face2 is NULL on a boundary
 * edge.
 *
 * @return kQ3Success, or kQ3Failure with *face1 and *face2 unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetEdgeFaces(TQ3GeometryObject mesh, TQ3MeshEdge edge, TQ3MeshFace *face1,
                                               TQ3MeshFace *face2);

/**
 * Whether an edge is on the mesh's boundary: exactly one contour side runs
 * along it.
 *
 * @return kQ3Success, or kQ3Failure with *onBoundary unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetEdgeOnBoundary(TQ3GeometryObject mesh, TQ3MeshEdge edge,
                                                    TQ3Boolean *onBoundary);

/**
 * The component an edge belongs to.
 *
 * @return kQ3Success, or kQ3Failure with *component unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetEdgeComponent(TQ3GeometryObject mesh, TQ3MeshEdge edge,
                                                   TQ3MeshComponent *component);

/**
 * An edge's attribute set.
 *
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: *attributeSet is a new reference for the caller, or NULL.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetEdgeAttributeSet(TQ3GeometryObject mesh, TQ3MeshEdge edge,
                                                      TQ3AttributeSet *attributeSet);

/**
 * Replaces an edge's attribute set (NULL removes it).
 *
 * @return kQ3Success, or kQ3Failure with the mesh unchanged.
 *
 * Errors (besides the common ones):
 *   kQ3ErrorInvalidObject      attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  attributeSet is not an attribute set.
 *
 * Ownership: the mesh takes its own reference to attributeSet and releases
 * the old one.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_SetEdgeAttributeSet(TQ3GeometryObject mesh, TQ3MeshEdge edge,
                                                      TQ3AttributeSet attributeSet);

/**
 * The face a contour belongs to.
 *
 * @return kQ3Success, or kQ3Failure with *face unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetContourFace(TQ3GeometryObject mesh, TQ3MeshContour contour, TQ3MeshFace *face);

/**
 * The number of vertices of a contour.
 *
 * @return kQ3Success, or kQ3Failure with *numVertices unchanged.
 *
 * Errors: the common ones only.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetContourNumVertices(TQ3GeometryObject mesh, TQ3MeshContour contour,
                                                        unsigned long *numVertices);

/**
 * The attribute set of the corner of face at vertex, or NULL when it has
 * none.
 *
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors (besides the common ones):
 *   kQ3ErrorInvalidParameter   vertex is not a corner of face.
 *
 * Ownership: *attributeSet is a new reference for the caller, or NULL.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_GetCornerAttributeSet(TQ3GeometryObject mesh, TQ3MeshVertex vertex,
                                                        TQ3MeshFace face, TQ3AttributeSet *attributeSet);

/**
 * Gives the corner of face at vertex its own attribute set (NULL removes
 * it): in that face the vertex takes its attributes from it first.
 *
 * @return kQ3Success, or kQ3Failure with the mesh unchanged.
 *
 * Errors (besides the common ones):
 *   kQ3ErrorInvalidParameter   vertex is not a corner of face.
 *   kQ3ErrorInvalidObject      attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  attributeSet is not an attribute set.
 *
 * Ownership: the mesh takes its own reference to attributeSet and releases
 * the old one.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Mesh_SetCornerAttributeSet(TQ3GeometryObject mesh, TQ3MeshVertex vertex,
                                                        TQ3MeshFace face, TQ3AttributeSet attributeSet);

/*
 * Iterators. Each Q3Mesh_FirstXxx fills *iterator and returns the first
 * part (NULL when there is none); Q3Mesh_NextXxx returns the next one, and
 * NULL once all were given (or after a failure). The caller owns the
 * iterator; its fields are Q3's (they hold handles and positions, never
 * pointers into the mesh). A Next call checks that the iterator was filled
 * by the matching First (kQ3ErrorInvalidParameter otherwise) and that what
 * it walks still exists: a mesh disposed (kQ3ErrorInvalidObject) or a part
 * deleted (kQ3ErrorInvalidParameter) ends the walk with that error.
 *
 * Editing during a walk never crashes. Walks over a mesh's components,
 * vertices, faces or edges go on after the last part given, in the order
 * parts were made: deleting the part just given (or any other) is safe,
 * and parts made meanwhile are met. A component's walks do the same while
 * the component keeps its handle (see Handles above). The other walks
 * list the parts around their part afresh at each step and go on by
 * position.
 *
 * What each walk gives, each part once:
 *   MeshComponent  the mesh's components.      ComponentVertex/Edge  a component's vertices/edges.
 *   MeshVertex/Face/Edge  the mesh's parts.
 *   VertexEdge     the edges ending at the vertex.
 *   VertexVertex   the vertices joined to it by an edge.
 *   VertexFace     the faces it is a corner of.
 *   FaceEdge       the edges its contours run along, contour by contour.
 *   FaceVertex     its corners, contour by contour.
 *   FaceFace       the other faces sharing an edge with it.
 *   FaceContour    its contours, the first one first.
 *   ContourEdge/Vertex  the contour's edges/vertices in its order.
 *   ContourFace    the faces, other than its own, sharing an edge with it.
 *
 * Errors of every First call: kQ3ErrorNotInitialized; kQ3ErrorNULLParameter
 * (the mesh or part, or iterator, is NULL); for a mesh kQ3ErrorInvalidObject
 * and kQ3ErrorInvalidObjectType; for a part kQ3ErrorInvalidParameter.
 * Every Next call: kQ3ErrorNotInitialized, kQ3ErrorNULLParameter (iterator),
 * and the errors above. On failure NULL is returned and *iterator is left
 * ended. No references change.
 */
struct TQ3MeshIterator {
    void *var1;
    void *var2;
    void *var3;
    struct {
        void *field1;
        char field2[4];
    } var4;
};
typedef struct TQ3MeshIterator TQ3MeshIterator;

/** The first component of mesh (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshComponent) Q3Mesh_FirstMeshComponent(TQ3GeometryObject mesh, TQ3MeshIterator *iterator);
/** The next component (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshComponent) Q3Mesh_NextMeshComponent(TQ3MeshIterator *iterator);
/** The first vertex of component (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshVertex) Q3Mesh_FirstComponentVertex(TQ3MeshComponent component, TQ3MeshIterator *iterator);
/** The next vertex of the component (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshVertex) Q3Mesh_NextComponentVertex(TQ3MeshIterator *iterator);
/** The first edge of component (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshEdge) Q3Mesh_FirstComponentEdge(TQ3MeshComponent component, TQ3MeshIterator *iterator);
/** The next edge of the component (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshEdge) Q3Mesh_NextComponentEdge(TQ3MeshIterator *iterator);
/** The first vertex of mesh (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshVertex) Q3Mesh_FirstMeshVertex(TQ3GeometryObject mesh, TQ3MeshIterator *iterator);
/** The next vertex of the mesh (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshVertex) Q3Mesh_NextMeshVertex(TQ3MeshIterator *iterator);
/** The first face of mesh (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshFace) Q3Mesh_FirstMeshFace(TQ3GeometryObject mesh, TQ3MeshIterator *iterator);
/** The next face of the mesh (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshFace) Q3Mesh_NextMeshFace(TQ3MeshIterator *iterator);
/** The first edge of mesh (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshEdge) Q3Mesh_FirstMeshEdge(TQ3GeometryObject mesh, TQ3MeshIterator *iterator);
/** The next edge of the mesh (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshEdge) Q3Mesh_NextMeshEdge(TQ3MeshIterator *iterator);
/** The first edge ending at vertex (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshEdge) Q3Mesh_FirstVertexEdge(TQ3MeshVertex vertex, TQ3MeshIterator *iterator);
/** The next edge ending at the vertex (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshEdge) Q3Mesh_NextVertexEdge(TQ3MeshIterator *iterator);
/** The first vertex joined to vertex by an edge (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshVertex) Q3Mesh_FirstVertexVertex(TQ3MeshVertex vertex, TQ3MeshIterator *iterator);
/** The next vertex joined to the vertex (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshVertex) Q3Mesh_NextVertexVertex(TQ3MeshIterator *iterator);
/** The first face vertex is a corner of (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshFace) Q3Mesh_FirstVertexFace(TQ3MeshVertex vertex, TQ3MeshIterator *iterator);
/** The next face the vertex is a corner of (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshFace) Q3Mesh_NextVertexFace(TQ3MeshIterator *iterator);
/** The first edge of face (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshEdge) Q3Mesh_FirstFaceEdge(TQ3MeshFace face, TQ3MeshIterator *iterator);
/** The next edge of the face (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshEdge) Q3Mesh_NextFaceEdge(TQ3MeshIterator *iterator);
/** The first corner of face (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshVertex) Q3Mesh_FirstFaceVertex(TQ3MeshFace face, TQ3MeshIterator *iterator);
/** The next corner of the face (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshVertex) Q3Mesh_NextFaceVertex(TQ3MeshIterator *iterator);
/** The first face sharing an edge with face (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshFace) Q3Mesh_FirstFaceFace(TQ3MeshFace face, TQ3MeshIterator *iterator);
/** The next face sharing an edge with the face (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshFace) Q3Mesh_NextFaceFace(TQ3MeshIterator *iterator);
/** The first contour of face (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshContour) Q3Mesh_FirstFaceContour(TQ3MeshFace face, TQ3MeshIterator *iterator);
/** The next contour of the face (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshContour) Q3Mesh_NextFaceContour(TQ3MeshIterator *iterator);
/** The first edge of contour (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshEdge) Q3Mesh_FirstContourEdge(TQ3MeshContour contour, TQ3MeshIterator *iterator);
/** The next edge of the contour (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshEdge) Q3Mesh_NextContourEdge(TQ3MeshIterator *iterator);
/** The first vertex of contour (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshVertex) Q3Mesh_FirstContourVertex(TQ3MeshContour contour, TQ3MeshIterator *iterator);
/** The next vertex of the contour (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshVertex) Q3Mesh_NextContourVertex(TQ3MeshIterator *iterator);
/** The first face sharing an edge with contour (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshFace) Q3Mesh_FirstContourFace(TQ3MeshContour contour, TQ3MeshIterator *iterator);
/** The next face sharing an edge with the contour (see Iterators above). */
Q3_EXTERN_API_C(TQ3MeshFace) Q3Mesh_NextContourFace(TQ3MeshIterator *iterator);

/* QuickDraw 3D's loops over the iterators, as `for` statements. */
#define Q3ForEachMeshComponent(m, c, i) \
    for ((c) = Q3Mesh_FirstMeshComponent((m), (i)); (c); (c) = Q3Mesh_NextMeshComponent((i)))
#define Q3ForEachComponentVertex(c, v, i) \
    for ((v) = Q3Mesh_FirstComponentVertex((c), (i)); (v); (v) = Q3Mesh_NextComponentVertex((i)))
#define Q3ForEachComponentEdge(c, e, i) \
    for ((e) = Q3Mesh_FirstComponentEdge((c), (i)); (e); (e) = Q3Mesh_NextComponentEdge((i)))
#define Q3ForEachMeshVertex(m, v, i) \
    for ((v) = Q3Mesh_FirstMeshVertex((m), (i)); (v); (v) = Q3Mesh_NextMeshVertex((i)))
#define Q3ForEachMeshFace(m, f, i) \
    for ((f) = Q3Mesh_FirstMeshFace((m), (i)); (f); (f) = Q3Mesh_NextMeshFace((i)))
#define Q3ForEachMeshEdge(m, e, i) \
    for ((e) = Q3Mesh_FirstMeshEdge((m), (i)); (e); (e) = Q3Mesh_NextMeshEdge((i)))
#define Q3ForEachVertexEdge(v, e, i) \
    for ((e) = Q3Mesh_FirstVertexEdge((v), (i)); (e); (e) = Q3Mesh_NextVertexEdge((i)))
#define Q3ForEachVertexVertex(v, n, i) \
    for ((n) = Q3Mesh_FirstVertexVertex((v), (i)); (n); (n) = Q3Mesh_NextVertexVertex((i)))
#define Q3ForEachVertexFace(v, f, i) \
    for ((f) = Q3Mesh_FirstVertexFace((v), (i)); (f); (f) = Q3Mesh_NextVertexFace((i)))
#define Q3ForEachFaceEdge(f, e, i) \
    for ((e) = Q3Mesh_FirstFaceEdge((f), (i)); (e); (e) = Q3Mesh_NextFaceEdge((i)))
#define Q3ForEachFaceVertex(f, v, i) \
    for ((v) = Q3Mesh_FirstFaceVertex((f), (i)); (v); (v) = Q3Mesh_NextFaceVertex((i)))
#define Q3ForEachFaceFace(f, n, i) \
    for ((n) = Q3Mesh_FirstFaceFace((f), (i)); (n); (n) = Q3Mesh_NextFaceFace((i)))
#define Q3ForEachFaceContour(f, h, i) \
    for ((h) = Q3Mesh_FirstFaceContour((f), (i)); (h); (h) = Q3Mesh_NextFaceContour((i)))
#define Q3ForEachContourEdge(h, e, i) \
    for ((e) = Q3Mesh_FirstContourEdge((h), (i)); (e); (e) = Q3Mesh_NextContourEdge((i)))
#define Q3ForEachContourVertex(h, v, i) \
    for ((v) = Q3Mesh_FirstContourVertex((h), (i)); (v); (v) = Q3Mesh_NextContourVertex((i)))
#define Q3ForEachContourFace(h, f, i) \
    for ((f) = Q3Mesh_FirstContourFace((h), (i)); (f); (f) = Q3Mesh_NextContourFace((i)))

/* ---- General polygon ---------------------------------------------------- */

/*
 * The hint a general polygon carries about its shape. Q3 draws every general
 * polygon the same way whatever its hint (a wrong hint never draws it
 * wrongly); the hint is kept and returned.
 */
enum TQ3GeneralPolygonShapeHint {
    kQ3GeneralPolygonShapeHintComplex = 0,
    kQ3GeneralPolygonShapeHintConcave = 1,
    kQ3GeneralPolygonShapeHintConvex = 2
};
typedef enum TQ3GeneralPolygonShapeHint TQ3GeneralPolygonShapeHint;

/* One closed outline of a general polygon: numVertices vertices in order. */
struct TQ3GeneralPolygonContourData {
    unsigned long numVertices;
    TQ3Vertex3D *vertices;
};
typedef struct TQ3GeneralPolygonContourData TQ3GeneralPolygonContourData;

/*
 * A general polygon: numContours closed contours in one plane, its shape
 * hint, and its attribute set or NULL. The area drawn is QuickDraw 3D's
 * even-odd fill: a point is inside when a ray from it crosses the contours an
 * odd number of times, so a contour inside another cuts a hole and one inside
 * a hole is an island. Contours may be concave. Q3 triangulates them in the
 * plane that fits all the vertices best; contours that cross each other or
 * themselves are drawn, but may then cover some area twice or miss some.
 * Each vertex keeps its own attributes. Its front is the side from which the
 * first contour runs counterclockwise. The wireframe renderer draws every
 * contour's outline.
 *
 * The rules a TQ3GeneralPolygonData must obey wherever one is accepted,
 * checked in this order:
 *   contours, and every contour's vertices, are not
 *     NULL                                          kQ3ErrorNULLParameter
 *   numContours >= 1, every contour's
 *     numVertices >= 3           kQ3ErrorGeometryInsufficientNumberOfPoints
 *   numContours and every contour's numVertices
 *     <= kQ3GeometryMaxArrayCount                   kQ3ErrorParameterOutOfRange
 *   every coordinate is finite                      kQ3ErrorInvalidData
 *   shapeHint is one of the enumeration's values    kQ3ErrorInvalidData
 *   the vertices of all contours together
 *     <= kQ3GeometryMaxArrayCount                   kQ3ErrorParameterOutOfRange
 *   every attribute set given is a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 */
struct TQ3GeneralPolygonData {
    unsigned long numContours;
    TQ3GeneralPolygonContourData *contours;
    TQ3GeneralPolygonShapeHint shapeHint;
    TQ3AttributeSet generalPolygonAttributeSet;
};
typedef struct TQ3GeneralPolygonData TQ3GeneralPolygonData;

/**
 * Creates a retained general polygon from a copy of generalPolygonData (the
 * data calls at the top of this header).
 *
 * @return the new general polygon, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      generalPolygonData is NULL.
 *   then the codes of the TQ3GeneralPolygonData rules, in their order;
 *   kQ3ErrorOutOfMemory        the general polygon cannot be allocated.
 *
 * Ownership: the caller owns the new general polygon's one reference. It
 * takes its own reference to every attribute set given.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3GeneralPolygon_New(const TQ3GeneralPolygonData *generalPolygonData);

/**
 * Draws (or bounds) a general polygon without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      generalPolygonData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3GeneralPolygonData rules, in their order.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GeneralPolygon_Submit(const TQ3GeneralPolygonData *generalPolygonData,
                                                   TQ3ViewObject view);

/**
 * Replaces the data of a retained general polygon with a copy of
 * generalPolygonData.
 *
 * @return kQ3Success, or kQ3Failure with the general polygon unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      generalPolygon or generalPolygonData is NULL.
 *   kQ3ErrorInvalidObject      generalPolygon is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  generalPolygon is not a general polygon.
 *   then the codes of the TQ3GeneralPolygonData rules, in their order.
 *
 * Ownership: the general polygon references the attribute sets given and
 * releases those it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GeneralPolygon_SetData(TQ3GeometryObject generalPolygon,
                                                    const TQ3GeneralPolygonData *generalPolygonData);

/**
 * Copies the data of a retained general polygon into generalPolygonData
 * (newly allocated contour and vertex arrays).
 *
 * @return kQ3Success, or kQ3Failure with *generalPolygonData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polygon or generalPolygonData is NULL.
 *   kQ3ErrorInvalidObject      polygon is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  polygon is not a general polygon.
 *   kQ3ErrorOutOfMemory        the copy cannot be allocated.
 *
 * Ownership: the caller owns the arrays and a new reference to every
 * attribute set in the result, and gives them back with
 * Q3GeneralPolygon_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GeneralPolygon_GetData(TQ3GeometryObject polygon,
                                                    TQ3GeneralPolygonData *generalPolygonData);

/**
 * Releases what Q3GeneralPolygon_GetData put in generalPolygonData: the
 * attribute set references, the vertex arrays and the contour array; the
 * pointers become NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      generalPolygonData is NULL.
 *   kQ3ErrorInvalidObject      an attribute set in it is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set in it is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GeneralPolygon_EmptyData(TQ3GeneralPolygonData *generalPolygonData);

/**
 * Reads the position of vertex pointIndex of contour contourIndex of a
 * retained general polygon.
 *
 * @return kQ3Success, or kQ3Failure with *position unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        generalPolygon or position is NULL.
 *   kQ3ErrorInvalidObject        generalPolygon is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    generalPolygon is not a general polygon.
 *   kQ3ErrorParameterOutOfRange  contourIndex is not below numContours, or
 *                                pointIndex not below that contour's
 *                                numVertices.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GeneralPolygon_GetVertexPosition(TQ3GeometryObject generalPolygon,
                                                              unsigned long contourIndex, unsigned long pointIndex,
                                                              TQ3Point3D *position);

/**
 * Moves vertex pointIndex of contour contourIndex of a retained general
 * polygon.
 *
 * @return kQ3Success, or kQ3Failure with the general polygon unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        generalPolygon or position is NULL.
 *   kQ3ErrorInvalidObject        generalPolygon is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    generalPolygon is not a general polygon.
 *   kQ3ErrorParameterOutOfRange  contourIndex or pointIndex is out of range.
 *   kQ3ErrorInvalidData          a coordinate of *position is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GeneralPolygon_SetVertexPosition(TQ3GeometryObject generalPolygon,
                                                              unsigned long contourIndex, unsigned long pointIndex,
                                                              const TQ3Point3D *position);

/**
 * Reads the attribute set of vertex pointIndex of contour contourIndex of a
 * retained general polygon (NULL when it has none).
 *
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        generalPolygon or attributeSet is NULL.
 *   kQ3ErrorInvalidObject        generalPolygon is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    generalPolygon is not a general polygon.
 *   kQ3ErrorParameterOutOfRange  contourIndex or pointIndex is out of range.
 *
 * Ownership: a set returned is a new reference for the caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GeneralPolygon_GetVertexAttributeSet(TQ3GeometryObject generalPolygon,
                                                                  unsigned long contourIndex,
                                                                  unsigned long pointIndex,
                                                                  TQ3AttributeSet *attributeSet);

/**
 * Replaces the attribute set of vertex pointIndex of contour contourIndex of
 * a retained general polygon; NULL removes it.
 *
 * @return kQ3Success, or kQ3Failure with the general polygon unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        generalPolygon is NULL.
 *   kQ3ErrorInvalidObject        generalPolygon or attributeSet is not a live
 *                                Q3 object.
 *   kQ3ErrorInvalidObjectType    generalPolygon is not a general polygon, or
 *                                attributeSet is not an attribute set.
 *   kQ3ErrorParameterOutOfRange  contourIndex or pointIndex is out of range.
 *
 * Ownership: the general polygon references attributeSet and releases the
 * set the vertex held; the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GeneralPolygon_SetVertexAttributeSet(TQ3GeometryObject generalPolygon,
                                                                  unsigned long contourIndex,
                                                                  unsigned long pointIndex,
                                                                  TQ3AttributeSet attributeSet);

/**
 * Replaces the shape hint of a retained general polygon.
 *
 * @return kQ3Success, or kQ3Failure with the general polygon unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      generalPolygon is NULL.
 *   kQ3ErrorInvalidObject      generalPolygon is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  generalPolygon is not a general polygon.
 *   kQ3ErrorInvalidParameter   shapeHint is none of the enumeration's values.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GeneralPolygon_SetShapeHint(TQ3GeometryObject generalPolygon,
                                                         TQ3GeneralPolygonShapeHint shapeHint);

/**
 * Reads the shape hint of a retained general polygon.
 *
 * @return kQ3Success, or kQ3Failure with *shapeHint unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      generalPolygon or shapeHint is NULL.
 *   kQ3ErrorInvalidObject      generalPolygon is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  generalPolygon is not a general polygon.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GeneralPolygon_GetShapeHint(TQ3GeometryObject generalPolygon,
                                                         TQ3GeneralPolygonShapeHint *shapeHint);

/* ---- Polyhedron --------------------------------------------------------- */

/* Which sides of a polyhedron triangle the wireframe draws (edgeFlag). */
enum TQ3PolyhedronEdgeMasks {
    kQ3PolyhedronEdgeNone = 0,
    kQ3PolyhedronEdge01 = 1 << 0,
    kQ3PolyhedronEdge12 = 1 << 1,
    kQ3PolyhedronEdge20 = 1 << 2,
    kQ3PolyhedronEdgeAll = kQ3PolyhedronEdge01 | kQ3PolyhedronEdge12 | kQ3PolyhedronEdge20
};
typedef enum TQ3PolyhedronEdgeMasks TQ3PolyhedronEdgeMasks;

typedef unsigned long TQ3PolyhedronEdge;

/*
 * An edge of a polyhedron, between two of its vertices, with the triangles
 * on either side (kQ3ArrayIndexNULL where there is none) and its attribute
 * set or NULL.
 */
struct TQ3PolyhedronEdgeData {
    unsigned long vertexIndices[2];
    unsigned long triangleIndices[2];
    TQ3AttributeSet edgeAttributeSet;
};
typedef struct TQ3PolyhedronEdgeData TQ3PolyhedronEdgeData;

/*
 * A triangle of a polyhedron: three vertex indices (its front is the side
 * from which they run counterclockwise), the mask of the sides the wireframe
 * draws, and its attribute set or NULL.
 */
struct TQ3PolyhedronTriangleData {
    unsigned long vertexIndices[3];
    TQ3PolyhedronEdge edgeFlag;
    TQ3AttributeSet triangleAttributeSet;
};
typedef struct TQ3PolyhedronTriangleData TQ3PolyhedronTriangleData;

/*
 * A polyhedron: vertices shared by triangles, optional edges, and its
 * attribute set or NULL. A vertex's attributes win over its triangle's. The
 * interactive renderer fills the triangles; the wireframe renderer draws
 * the sides each triangle's edgeFlag names and every edge in edges, an
 * edge's attribute set colouring it where its vertices have no colour.
 *
 * The rules a TQ3PolyhedronData must obey wherever one is accepted, checked
 * in this order:
 *   vertices and triangles are not NULL; edges is
 *     not NULL when numEdges > 0                    kQ3ErrorNULLParameter
 *   numVertices >= 3 and numTriangles >= 1
 *                                kQ3ErrorGeometryInsufficientNumberOfPoints
 *   numVertices, numEdges, numTriangles
 *     <= kQ3GeometryMaxArrayCount                   kQ3ErrorParameterOutOfRange
 *   every coordinate is finite                      kQ3ErrorInvalidData
 *   every triangle's vertex indices are below
 *     numVertices, its edgeFlag within
 *     kQ3PolyhedronEdgeAll                          kQ3ErrorInvalidData
 *   every edge's vertex indices are below
 *     numVertices, its triangle indices below
 *     numTriangles or kQ3ArrayIndexNULL             kQ3ErrorInvalidData
 *   every attribute set given is a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 */
struct TQ3PolyhedronData {
    unsigned long numVertices;
    TQ3Vertex3D *vertices;
    unsigned long numEdges;
    TQ3PolyhedronEdgeData *edges;
    unsigned long numTriangles;
    TQ3PolyhedronTriangleData *triangles;
    TQ3AttributeSet polyhedronAttributeSet;
};
typedef struct TQ3PolyhedronData TQ3PolyhedronData;

/**
 * Creates a retained polyhedron from a copy of polyhedronData (the data
 * calls at the top of this header).
 *
 * @return the new polyhedron, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polyhedronData is NULL.
 *   then the codes of the TQ3PolyhedronData rules, in their order;
 *   kQ3ErrorOutOfMemory        the polyhedron cannot be allocated.
 *
 * Ownership: the caller owns the new polyhedron's one reference. The
 * polyhedron takes its own reference to every attribute set given.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Polyhedron_New(const TQ3PolyhedronData *polyhedronData);

/**
 * Draws (or bounds) a polyhedron without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polyhedronData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3PolyhedronData rules, in their order.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polyhedron_Submit(const TQ3PolyhedronData *polyhedronData, TQ3ViewObject view);

/**
 * Replaces the data of a retained polyhedron with a copy of polyhedronData.
 *
 * @return kQ3Success, or kQ3Failure with the polyhedron unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polyhedron or polyhedronData is NULL.
 *   kQ3ErrorInvalidObject      polyhedron is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  polyhedron is not a polyhedron.
 *   then the codes of the TQ3PolyhedronData rules, in their order.
 *
 * Ownership: the polyhedron references the attribute sets given and releases
 * those it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polyhedron_SetData(TQ3GeometryObject polyhedron,
                                                const TQ3PolyhedronData *polyhedronData);

/**
 * Copies the data of a retained polyhedron into polyhedronData (newly
 * allocated arrays).
 *
 * @return kQ3Success, or kQ3Failure with *polyhedronData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polyhedron or polyhedronData is NULL.
 *   kQ3ErrorInvalidObject      polyhedron is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  polyhedron is not a polyhedron.
 *   kQ3ErrorOutOfMemory        the copy cannot be allocated.
 *
 * Ownership: the caller owns the arrays and a new reference to every
 * attribute set in the result, and gives them back with
 * Q3Polyhedron_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polyhedron_GetData(TQ3GeometryObject polyhedron, TQ3PolyhedronData *polyhedronData);

/**
 * Releases what Q3Polyhedron_GetData put in polyhedronData: the attribute
 * set references and the arrays; the pointers become NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      polyhedronData is NULL.
 *   kQ3ErrorInvalidObject      an attribute set in it is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set in it is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polyhedron_EmptyData(TQ3PolyhedronData *polyhedronData);

/**
 * Moves vertex index of a retained polyhedron.
 *
 * @return kQ3Success, or kQ3Failure with the polyhedron unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyhedron or point is NULL.
 *   kQ3ErrorInvalidObject        polyhedron is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polyhedron is not a polyhedron.
 *   kQ3ErrorParameterOutOfRange  index is not below numVertices.
 *   kQ3ErrorInvalidData          a coordinate of *point is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polyhedron_SetVertexPosition(TQ3GeometryObject polyhedron, unsigned long index,
                                                          const TQ3Point3D *point);

/**
 * Reads the position of vertex index of a retained polyhedron.
 *
 * @return kQ3Success, or kQ3Failure with *point unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyhedron or point is NULL.
 *   kQ3ErrorInvalidObject        polyhedron is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polyhedron is not a polyhedron.
 *   kQ3ErrorParameterOutOfRange  index is not below numVertices.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polyhedron_GetVertexPosition(TQ3GeometryObject polyhedron, unsigned long index,
                                                          TQ3Point3D *point);

/**
 * Replaces the attribute set of vertex index of a retained polyhedron; NULL
 * removes it.
 *
 * @return kQ3Success, or kQ3Failure with the polyhedron unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyhedron is NULL.
 *   kQ3ErrorInvalidObject        polyhedron or attributeSet is not a live Q3
 *                                object.
 *   kQ3ErrorInvalidObjectType    polyhedron is not a polyhedron, or
 *                                attributeSet is not an attribute set.
 *   kQ3ErrorParameterOutOfRange  index is not below numVertices.
 *
 * Ownership: the polyhedron references attributeSet and releases the set the
 * vertex held; the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polyhedron_SetVertexAttributeSet(TQ3GeometryObject polyhedron, unsigned long index,
                                                              TQ3AttributeSet attributeSet);

/**
 * Reads the attribute set of vertex index of a retained polyhedron (NULL
 * when it has none).
 *
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyhedron or attributeSet is NULL.
 *   kQ3ErrorInvalidObject        polyhedron is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polyhedron is not a polyhedron.
 *   kQ3ErrorParameterOutOfRange  index is not below numVertices.
 *
 * Ownership: a set returned is a new reference for the caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polyhedron_GetVertexAttributeSet(TQ3GeometryObject polyhedron, unsigned long index,
                                                              TQ3AttributeSet *attributeSet);

/**
 * Copies triangle triangleIndex of a retained polyhedron into triangleData.
 *
 * @return kQ3Success, or kQ3Failure with *triangleData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyhedron or triangleData is NULL.
 *   kQ3ErrorInvalidObject        polyhedron is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polyhedron is not a polyhedron.
 *   kQ3ErrorParameterOutOfRange  triangleIndex is not below numTriangles.
 *
 * Ownership: the triangle's attribute set, if any, is a new reference for
 * the caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polyhedron_GetTriangleData(TQ3GeometryObject polyhedron, unsigned long triangleIndex,
                                                        TQ3PolyhedronTriangleData *triangleData);

/**
 * Replaces triangle triangleIndex of a retained polyhedron with a copy of
 * triangleData, which must obey the triangle rules of TQ3PolyhedronData.
 *
 * @return kQ3Success, or kQ3Failure with the polyhedron unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyhedron or triangleData is NULL.
 *   kQ3ErrorInvalidObject        polyhedron, or the triangle's attribute
 *                                set, is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polyhedron is not a polyhedron, or the
 *                                triangle's set is not an attribute set.
 *   kQ3ErrorParameterOutOfRange  triangleIndex is not below numTriangles.
 *   kQ3ErrorInvalidData          a vertex index is not below numVertices, or
 *                                edgeFlag has bits outside
 *                                kQ3PolyhedronEdgeAll.
 *
 * Ownership: the polyhedron references the triangle's set and releases the
 * one the triangle held; the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polyhedron_SetTriangleData(TQ3GeometryObject polyhedron, unsigned long triangleIndex,
                                                        const TQ3PolyhedronTriangleData *triangleData);

/**
 * Copies edge edgeIndex of a retained polyhedron into edgeData.
 *
 * @return kQ3Success, or kQ3Failure with *edgeData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyhedron or edgeData is NULL.
 *   kQ3ErrorInvalidObject        polyhedron is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polyhedron is not a polyhedron.
 *   kQ3ErrorParameterOutOfRange  edgeIndex is not below numEdges.
 *
 * Ownership: the edge's attribute set, if any, is a new reference for the
 * caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polyhedron_GetEdgeData(TQ3GeometryObject polyhedron, unsigned long edgeIndex,
                                                    TQ3PolyhedronEdgeData *edgeData);

/**
 * Replaces edge edgeIndex of a retained polyhedron with a copy of edgeData,
 * which must obey the edge rules of TQ3PolyhedronData.
 *
 * @return kQ3Success, or kQ3Failure with the polyhedron unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        polyhedron or edgeData is NULL.
 *   kQ3ErrorInvalidObject        polyhedron, or the edge's attribute set, is
 *                                not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    polyhedron is not a polyhedron, or the
 *                                edge's set is not an attribute set.
 *   kQ3ErrorParameterOutOfRange  edgeIndex is not below numEdges.
 *   kQ3ErrorInvalidData          a vertex index is not below numVertices, or
 *                                a triangle index neither below numTriangles
 *                                nor kQ3ArrayIndexNULL.
 *
 * Ownership: the polyhedron references the edge's set and releases the one
 * the edge held; the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Polyhedron_SetEdgeData(TQ3GeometryObject polyhedron, unsigned long edgeIndex,
                                                    const TQ3PolyhedronEdgeData *edgeData);

/* ---- TriGrid ------------------------------------------------------------ */

/*
 * A triangle grid: numRows x numColumns vertices, row after row
 * (vertices[row * numColumns + column]), each cell of four neighbours cut
 * into two triangles, the facets. The cut alternates from column to column,
 * as in QuickDraw 3D: in even columns the diagonal runs from (row, column + 1)
 * to (row + 1, column), in odd columns from (row, column) to
 * (row + 1, column + 1). Cell (row, column) has facets 2k and 2k + 1 with
 * k = row * (numColumns - 1) + column: in even columns
 *   (row, c) (row, c + 1) (row + 1, c) and (row + 1, c) (row, c + 1) (row + 1, c + 1),
 * in odd columns
 *   (row, c) (row + 1, c + 1) (row + 1, c) and (row, c) (row, c + 1) (row + 1, c + 1).
 * facetAttributeSet is NULL or 2 (numRows - 1) (numColumns - 1) sets (each
 * may be NULL); a vertex's attributes win over its facet's. The wireframe
 * renderer draws every side of every facet.
 *
 * The rules a TQ3TriGridData must obey wherever one is accepted, checked in
 * this order:
 *   vertices is not NULL                            kQ3ErrorNULLParameter
 *   numRows >= 2 and numColumns >= 2
 *                                kQ3ErrorGeometryInsufficientNumberOfPoints
 *   numRows x numColumns <= kQ3GeometryMaxArrayCount
 *                                                   kQ3ErrorParameterOutOfRange
 *   every coordinate is finite                      kQ3ErrorInvalidData
 *   every attribute set given is a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 */
struct TQ3TriGridData {
    unsigned long numRows;
    unsigned long numColumns;
    TQ3Vertex3D *vertices;
    TQ3AttributeSet *facetAttributeSet;
    TQ3AttributeSet triGridAttributeSet;
};
typedef struct TQ3TriGridData TQ3TriGridData;

/**
 * Creates a retained triangle grid from a copy of triGridData (the data
 * calls at the top of this header).
 *
 * @return the new grid, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triGridData is NULL.
 *   then the codes of the TQ3TriGridData rules, in their order;
 *   kQ3ErrorOutOfMemory        the grid cannot be allocated.
 *
 * Ownership: the caller owns the new grid's one reference. The grid takes
 * its own reference to every attribute set given.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3TriGrid_New(const TQ3TriGridData *triGridData);

/**
 * Draws (or bounds) a triangle grid without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triGridData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3TriGridData rules, in their order.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriGrid_Submit(const TQ3TriGridData *triGridData, TQ3ViewObject view);

/**
 * Replaces the data of a retained triangle grid with a copy of triGridData.
 *
 * @return kQ3Success, or kQ3Failure with the grid unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triGrid or triGridData is NULL.
 *   kQ3ErrorInvalidObject      triGrid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  triGrid is not a triangle grid.
 *   then the codes of the TQ3TriGridData rules, in their order.
 *
 * Ownership: the grid references the attribute sets given and releases
 * those it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriGrid_SetData(TQ3GeometryObject triGrid, const TQ3TriGridData *triGridData);

/**
 * Copies the data of a retained triangle grid into triGridData (newly
 * allocated arrays).
 *
 * @return kQ3Success, or kQ3Failure with *triGridData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triGrid or triGridData is NULL.
 *   kQ3ErrorInvalidObject      triGrid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  triGrid is not a triangle grid.
 *   kQ3ErrorOutOfMemory        the copy cannot be allocated.
 *
 * Ownership: the caller owns the arrays and a new reference to every
 * attribute set in the result, and gives them back with Q3TriGrid_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriGrid_GetData(TQ3GeometryObject triGrid, TQ3TriGridData *triGridData);

/**
 * Releases what Q3TriGrid_GetData put in triGridData: the attribute set
 * references and the arrays; the pointers become NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      triGridData is NULL.
 *   kQ3ErrorInvalidObject      an attribute set in it is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  an attribute set in it is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriGrid_EmptyData(TQ3TriGridData *triGridData);

/**
 * Reads the position of the vertex at rowIndex, columnIndex of a retained
 * triangle grid.
 *
 * @return kQ3Success, or kQ3Failure with *position unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        triGrid or position is NULL.
 *   kQ3ErrorInvalidObject        triGrid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    triGrid is not a triangle grid.
 *   kQ3ErrorParameterOutOfRange  rowIndex is not below numRows, or
 *                                columnIndex not below numColumns.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriGrid_GetVertexPosition(TQ3GeometryObject triGrid, unsigned long rowIndex,
                                                       unsigned long columnIndex, TQ3Point3D *position);

/**
 * Moves the vertex at rowIndex, columnIndex of a retained triangle grid.
 *
 * @return kQ3Success, or kQ3Failure with the grid unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        triGrid or position is NULL.
 *   kQ3ErrorInvalidObject        triGrid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    triGrid is not a triangle grid.
 *   kQ3ErrorParameterOutOfRange  rowIndex or columnIndex is out of range.
 *   kQ3ErrorInvalidData          a coordinate of *position is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriGrid_SetVertexPosition(TQ3GeometryObject triGrid, unsigned long rowIndex,
                                                       unsigned long columnIndex, const TQ3Point3D *position);

/**
 * Reads the attribute set of the vertex at rowIndex, columnIndex of a
 * retained triangle grid (NULL when it has none).
 *
 * @return kQ3Success, or kQ3Failure with *attributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        triGrid or attributeSet is NULL.
 *   kQ3ErrorInvalidObject        triGrid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    triGrid is not a triangle grid.
 *   kQ3ErrorParameterOutOfRange  rowIndex or columnIndex is out of range.
 *
 * Ownership: a set returned is a new reference for the caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriGrid_GetVertexAttributeSet(TQ3GeometryObject triGrid, unsigned long rowIndex,
                                                           unsigned long columnIndex, TQ3AttributeSet *attributeSet);

/**
 * Replaces the attribute set of the vertex at rowIndex, columnIndex of a
 * retained triangle grid; NULL removes it.
 *
 * @return kQ3Success, or kQ3Failure with the grid unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        triGrid is NULL.
 *   kQ3ErrorInvalidObject        triGrid or attributeSet is not a live Q3
 *                                object.
 *   kQ3ErrorInvalidObjectType    triGrid is not a triangle grid, or
 *                                attributeSet is not an attribute set.
 *   kQ3ErrorParameterOutOfRange  rowIndex or columnIndex is out of range.
 *
 * Ownership: the grid references attributeSet and releases the set the
 * vertex held; the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriGrid_SetVertexAttributeSet(TQ3GeometryObject triGrid, unsigned long rowIndex,
                                                           unsigned long columnIndex, TQ3AttributeSet attributeSet);

/**
 * Reads the attribute set of facet faceIndex of a retained triangle grid
 * (NULL when it has none).
 *
 * @return kQ3Success, or kQ3Failure with *facetAttributeSet unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        triGrid or facetAttributeSet is NULL.
 *   kQ3ErrorInvalidObject        triGrid is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    triGrid is not a triangle grid.
 *   kQ3ErrorParameterOutOfRange  faceIndex is not below
 *                                2 (numRows - 1) (numColumns - 1).
 *
 * Ownership: a set returned is a new reference for the caller to dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriGrid_GetFacetAttributeSet(TQ3GeometryObject triGrid, unsigned long faceIndex,
                                                          TQ3AttributeSet *facetAttributeSet);

/**
 * Replaces the attribute set of facet faceIndex of a retained triangle grid;
 * NULL removes it. A grid without facet sets gets an array of them, the
 * others NULL.
 *
 * @return kQ3Success, or kQ3Failure with the grid unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        triGrid is NULL.
 *   kQ3ErrorInvalidObject        triGrid or facetAttributeSet is not a live
 *                                Q3 object.
 *   kQ3ErrorInvalidObjectType    triGrid is not a triangle grid, or
 *                                facetAttributeSet is not an attribute set.
 *   kQ3ErrorParameterOutOfRange  faceIndex is not below
 *                                2 (numRows - 1) (numColumns - 1).
 *   kQ3ErrorOutOfMemory          the array of facet sets cannot be allocated.
 *
 * Ownership: the grid references facetAttributeSet and releases the set the
 * facet held; the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3TriGrid_SetFacetAttributeSet(TQ3GeometryObject triGrid, unsigned long faceIndex,
                                                          TQ3AttributeSet facetAttributeSet);

/* ---- Marker ------------------------------------------------------------- */

/*
 * A marker: a bitmap drawn in screen space, its pixels parallel to the
 * pane's whatever the camera, at the image of location. The bitmap's top
 * left pixel lies xOffset pixels to the right of and yOffset pixels below
 * the pixel location projects to (negative offsets go left and up). Each set
 * bit is drawn in the marker's diffuse colour (its attribute set's, else the
 * view's state); clear bits leave the image alone. The interactive renderer
 * depth-tests the whole bitmap at location's depth. A marker whose location
 * is behind the camera or outside its hither and yon planes is not drawn;
 * its bound is location.
 *
 * bitmap.image holds height rows of rowBytes bytes, top row first; within a
 * row, pixel x is bit x % 8 of byte x / 8, counted from the most
 * significant bit when bitOrder is kQ3EndianBig and from the least
 * significant when it is kQ3EndianLittle.
 *
 * The rules a TQ3MarkerData must obey wherever one is accepted, checked in
 * this order:
 *   bitmap.image is not NULL                        kQ3ErrorNULLParameter
 *   bitmap.rowBytes * bitmap.height
 *     <= kQ3GeometryMaxArrayCount                   kQ3ErrorParameterOutOfRange
 *   location's coordinates are finite               kQ3ErrorInvalidData
 *   bitmap.width and bitmap.height are above 0, and
 *     bitmap.rowBytes * 8 >= bitmap.width           kQ3ErrorInvalidData
 *   bitmap.bitOrder is kQ3EndianBig or
 *     kQ3EndianLittle                               kQ3ErrorInvalidData
 *   markerAttributeSet is NULL or a live attribute
 *     set                   kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 */
struct TQ3MarkerData {
    TQ3Point3D location;
    long xOffset;
    long yOffset;
    TQ3Bitmap bitmap;
    TQ3AttributeSet markerAttributeSet;
};
typedef struct TQ3MarkerData TQ3MarkerData;

/**
 * Creates a retained marker from a copy of markerData, its bitmap bits
 * included (the data calls at the top of this header).
 *
 * @return the new marker, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      markerData is NULL.
 *   then the codes of the TQ3MarkerData rules, in their order;
 *   kQ3ErrorOutOfMemory        the marker cannot be allocated.
 *
 * Ownership: the caller owns the new marker's one reference. The marker
 * takes its own reference to its attribute set.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3Marker_New(const TQ3MarkerData *markerData);

/**
 * Draws (or bounds) a marker without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      markerData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3MarkerData rules, in their order.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Marker_Submit(const TQ3MarkerData *markerData, TQ3ViewObject view);

/**
 * Replaces the data of a retained marker with a copy of markerData.
 *
 * @return kQ3Success, or kQ3Failure with the marker unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      geometry or markerData is NULL.
 *   kQ3ErrorInvalidObject      geometry is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  geometry is not a marker.
 *   then the codes of the TQ3MarkerData rules, in their order.
 *
 * Ownership: the marker references the attribute set given and releases the
 * one it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Marker_SetData(TQ3GeometryObject geometry, const TQ3MarkerData *markerData);

/**
 * Copies the data of a retained marker into markerData (a newly allocated
 * copy of the bitmap's bits).
 *
 * @return kQ3Success, or kQ3Failure with *markerData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      geometry or markerData is NULL.
 *   kQ3ErrorInvalidObject      geometry is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  geometry is not a marker.
 *   kQ3ErrorOutOfMemory        the copy cannot be allocated.
 *
 * Ownership: the caller owns the bits and a new reference to the attribute
 * set, and gives them back with Q3Marker_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Marker_GetData(TQ3GeometryObject geometry, TQ3MarkerData *markerData);

/**
 * Releases what Q3Marker_GetData put in markerData: the attribute set
 * reference and the bitmap's bits; the pointers become NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      markerData is NULL.
 *   kQ3ErrorInvalidObject      its attribute set is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  its attribute set is not an attribute set.
 *
 * Ownership: consumes what the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Marker_EmptyData(TQ3MarkerData *markerData);

/**
 * Reads the location of a retained marker.
 *
 * @return kQ3Success, or kQ3Failure with *location unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      marker or location is NULL.
 *   kQ3ErrorInvalidObject      marker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  marker is not a marker.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Marker_GetPosition(TQ3GeometryObject marker, TQ3Point3D *location);

/**
 * Moves a retained marker's location.
 *
 * @return kQ3Success, or kQ3Failure with the marker unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      marker or location is NULL.
 *   kQ3ErrorInvalidObject      marker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  marker is not a marker.
 *   kQ3ErrorInvalidData        a coordinate of *location is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Marker_SetPosition(TQ3GeometryObject marker, const TQ3Point3D *location);

/**
 * Reads the horizontal offset, in pixels, of a retained marker's bitmap.
 *
 * @return kQ3Success, or kQ3Failure with *xOffset unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      marker or xOffset is NULL.
 *   kQ3ErrorInvalidObject      marker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  marker is not a marker.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Marker_GetXOffset(TQ3GeometryObject marker, long *xOffset);

/**
 * Replaces the horizontal offset, in pixels, of a retained marker's bitmap
 * (any value).
 *
 * @return kQ3Success, or kQ3Failure with the marker unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      marker is NULL.
 *   kQ3ErrorInvalidObject      marker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  marker is not a marker.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Marker_SetXOffset(TQ3GeometryObject marker, long xOffset);

/**
 * Reads the vertical offset, in pixels (positive down), of a retained
 * marker's bitmap.
 *
 * @return kQ3Success, or kQ3Failure with *yOffset unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      marker or yOffset is NULL.
 *   kQ3ErrorInvalidObject      marker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  marker is not a marker.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Marker_GetYOffset(TQ3GeometryObject marker, long *yOffset);

/**
 * Replaces the vertical offset, in pixels (positive down), of a retained
 * marker's bitmap (any value).
 *
 * @return kQ3Success, or kQ3Failure with the marker unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      marker is NULL.
 *   kQ3ErrorInvalidObject      marker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  marker is not a marker.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Marker_SetYOffset(TQ3GeometryObject marker, long yOffset);

/**
 * Copies a retained marker's bitmap into bitmap (a newly allocated copy of
 * its bits).
 *
 * @return kQ3Success, or kQ3Failure with *bitmap unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      marker or bitmap is NULL.
 *   kQ3ErrorInvalidObject      marker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  marker is not a marker.
 *   kQ3ErrorOutOfMemory        the copy cannot be allocated.
 *
 * Ownership: the caller owns the bits and gives them back with
 * Q3Bitmap_Empty (QD3D.h).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Marker_GetBitmap(TQ3GeometryObject marker, TQ3Bitmap *bitmap);

/**
 * Replaces a retained marker's bitmap with a copy of bitmap, which must obey
 * the bitmap rules of TQ3MarkerData.
 *
 * @return kQ3Success, or kQ3Failure with the marker unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        marker, bitmap or bitmap->image is NULL.
 *   kQ3ErrorInvalidObject        marker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    marker is not a marker.
 *   kQ3ErrorInvalidData          the sizes or bitOrder break the rules.
 *   kQ3ErrorParameterOutOfRange  rowBytes * height is above
 *                                kQ3GeometryMaxArrayCount.
 *   kQ3ErrorOutOfMemory          the copy cannot be allocated.
 *
 * Ownership: the marker keeps its own copy of the bits.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Marker_SetBitmap(TQ3GeometryObject marker, const TQ3Bitmap *bitmap);

/* ---- Pixmap marker ------------------------------------------------------ */

/*
 * A pixmap marker: a colour image drawn in screen space, its pixels parallel
 * to the pane's whatever the camera, at the image of position. The pixmap's
 * top left pixel lies xOffset pixels to the right of and yOffset pixels
 * below the pixel position projects to (negative offsets go left and up).
 * Each pixel is drawn in its own colour (an n-bit channel holding v is the
 * fraction v / (2^n - 1) of full intensity), unlit: attribute sets, lights
 * and the illumination shader do not change it. For kQ3PixelTypeARGB32 and
 * kQ3PixelTypeARGB16 a pixel whose alpha is 0 is not drawn and leaves the
 * image alone; any other alpha draws the pixel opaque (the renderers do not
 * blend). Pixels that fall outside the pane are not drawn. The interactive
 * renderer depth-tests the whole pixmap at position's depth. A pixmap marker
 * whose position is behind the camera or outside its hither and yon planes
 * is not drawn; its bound is position. It is its own decomposition
 * (Q3Geometry_GetDecomposed gives NULL, as for a marker).
 *
 * pixmap.image is a storage object (QD3DStorage.h) holding height rows of
 * rowBytes bytes, top row first; within a row, pixel x occupies bytes
 * x * pixelSize / 8 onwards. Each pixel is a pixelSize-bit word laid out as
 * QD3DDrawContext.h's table says for pixelType, its bytes stored most
 * significant first when byteOrder is kQ3EndianBig and least significant
 * first when it is kQ3EndianLittle; bitOrder is checked but not used. The
 * storage is read each time the marker is drawn, so changes to its contents
 * show at the next drawing; a storage that no longer holds
 * rowBytes * height bytes then makes the drawing fail with
 * kQ3ErrorInvalidData.
 *
 * The rules a TQ3PixmapMarkerData must obey wherever one is accepted,
 * checked in this order:
 *   pixmap.image is not NULL                        kQ3ErrorNULLParameter
 *   position's coordinates are finite               kQ3ErrorInvalidData
 *   pixmap.pixelType is a TQ3PixelType value, and
 *     pixmap.byteOrder and pixmap.bitOrder are
 *     TQ3Endian values                              kQ3ErrorInvalidData
 *   pixmap.pixelSize is the size QD3DDrawContext.h
 *     gives for pixelType (16, 24 or 32)     kQ3ErrorUnsupportedPixelDepth
 *   pixmap.width and pixmap.height are above 0,
 *     and pixmap.rowBytes >= width * pixelSize / 8  kQ3ErrorInvalidData
 *   pixmap.rowBytes * pixmap.height
 *     <= kQ3GeometryMaxArrayCount                   kQ3ErrorParameterOutOfRange
 *   pixmap.image is a live storage object
 *                           kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 *   the storage holds at least
 *     pixmap.rowBytes * pixmap.height bytes         kQ3ErrorInvalidData
 *     (a path storage whose file cannot be read:    kQ3ErrorFileNotOpen)
 *   pixmapMarkerAttributeSet is NULL or a live
 *     attribute set         kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 */
struct TQ3PixmapMarkerData {
    TQ3Point3D position;
    long xOffset;
    long yOffset;
    TQ3StoragePixmap pixmap;
    TQ3AttributeSet pixmapMarkerAttributeSet;
};
typedef struct TQ3PixmapMarkerData TQ3PixmapMarkerData;

/**
 * Creates a retained pixmap marker from a copy of pixmapMarkerData (the data
 * calls at the top of this header). The pixels stay in the storage object,
 * which the marker references; they are not copied.
 *
 * @return the new pixmap marker, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pixmapMarkerData is NULL.
 *   then the codes of the TQ3PixmapMarkerData rules, in their order;
 *   kQ3ErrorOutOfMemory        the marker cannot be allocated.
 *
 * Ownership: the caller owns the new marker's one reference. The marker
 * takes its own references to the storage and the attribute set; the caller
 * keeps its own.
 */
Q3_EXTERN_API_C(TQ3GeometryObject) Q3PixmapMarker_New(const TQ3PixmapMarkerData *pixmapMarkerData);

/**
 * Draws (or bounds) a pixmap marker without creating an object.
 *
 * @return kQ3Success, or kQ3Failure with nothing drawn.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pixmapMarkerData or view is NULL.
 *   kQ3ErrorInvalidObject      view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  view is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding loop.
 *   then the codes of the TQ3PixmapMarkerData rules, in their order.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapMarker_Submit(const TQ3PixmapMarkerData *pixmapMarkerData,
                                                 TQ3ViewObject view);

/**
 * Replaces the data of a retained pixmap marker with a copy of
 * pixmapMarkerData.
 *
 * @return kQ3Success, or kQ3Failure with the marker unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      geometry or pixmapMarkerData is NULL.
 *   kQ3ErrorInvalidObject      geometry is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  geometry is not a pixmap marker.
 *   then the codes of the TQ3PixmapMarkerData rules, in their order.
 *
 * Ownership: the marker references the storage and attribute set given and
 * releases the ones it held.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapMarker_SetData(TQ3GeometryObject geometry,
                                                  const TQ3PixmapMarkerData *pixmapMarkerData);

/**
 * Copies the data of a retained pixmap marker into pixmapMarkerData.
 *
 * @return kQ3Success, or kQ3Failure with *pixmapMarkerData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      geometry or pixmapMarkerData is NULL.
 *   kQ3ErrorInvalidObject      geometry is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  geometry is not a pixmap marker.
 *
 * Ownership: the caller owns a new reference to the storage (pixmap.image)
 * and to the attribute set, and gives them back with
 * Q3PixmapMarker_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapMarker_GetData(TQ3GeometryObject geometry,
                                                  TQ3PixmapMarkerData *pixmapMarkerData);

/**
 * Releases what Q3PixmapMarker_GetData put in pixmapMarkerData: the storage
 * and attribute set references; the handles become NULL.
 *
 * @return kQ3Success, or kQ3Failure with nothing released.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pixmapMarkerData is NULL.
 *   kQ3ErrorInvalidObject      its storage or attribute set is not a live Q3
 *                              object.
 *   kQ3ErrorInvalidObjectType  its storage is not a storage, or its
 *                              attribute set not an attribute set.
 *
 * Ownership: consumes the references the structure holds.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapMarker_EmptyData(TQ3PixmapMarkerData *pixmapMarkerData);

/**
 * Reads the position of a retained pixmap marker.
 *
 * @return kQ3Success, or kQ3Failure with *position unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pixmapMarker or position is NULL.
 *   kQ3ErrorInvalidObject      pixmapMarker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pixmapMarker is not a pixmap marker.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapMarker_GetPosition(TQ3GeometryObject pixmapMarker, TQ3Point3D *position);

/**
 * Moves a retained pixmap marker's position.
 *
 * @return kQ3Success, or kQ3Failure with the marker unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pixmapMarker or position is NULL.
 *   kQ3ErrorInvalidObject      pixmapMarker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pixmapMarker is not a pixmap marker.
 *   kQ3ErrorInvalidData        a coordinate of *position is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapMarker_SetPosition(TQ3GeometryObject pixmapMarker,
                                                      const TQ3Point3D *position);

/**
 * Reads the horizontal offset, in pixels, of a retained pixmap marker's
 * pixmap.
 *
 * @return kQ3Success, or kQ3Failure with *xOffset unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pixmapMarker or xOffset is NULL.
 *   kQ3ErrorInvalidObject      pixmapMarker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pixmapMarker is not a pixmap marker.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapMarker_GetXOffset(TQ3GeometryObject pixmapMarker, long *xOffset);

/**
 * Replaces the horizontal offset, in pixels, of a retained pixmap marker's
 * pixmap (any value).
 *
 * @return kQ3Success, or kQ3Failure with the marker unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pixmapMarker is NULL.
 *   kQ3ErrorInvalidObject      pixmapMarker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pixmapMarker is not a pixmap marker.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapMarker_SetXOffset(TQ3GeometryObject pixmapMarker, long xOffset);

/**
 * Reads the vertical offset, in pixels (positive down), of a retained pixmap
 * marker's pixmap.
 *
 * @return kQ3Success, or kQ3Failure with *yOffset unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pixmapMarker or yOffset is NULL.
 *   kQ3ErrorInvalidObject      pixmapMarker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pixmapMarker is not a pixmap marker.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapMarker_GetYOffset(TQ3GeometryObject pixmapMarker, long *yOffset);

/**
 * Replaces the vertical offset, in pixels (positive down), of a retained
 * pixmap marker's pixmap (any value).
 *
 * @return kQ3Success, or kQ3Failure with the marker unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pixmapMarker is NULL.
 *   kQ3ErrorInvalidObject      pixmapMarker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pixmapMarker is not a pixmap marker.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapMarker_SetYOffset(TQ3GeometryObject pixmapMarker, long yOffset);

/**
 * Copies a retained pixmap marker's pixmap description into pixmap.
 *
 * @return kQ3Success, or kQ3Failure with *pixmap unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pixmapMarker or pixmap is NULL.
 *   kQ3ErrorInvalidObject      pixmapMarker is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pixmapMarker is not a pixmap marker.
 *
 * Ownership: the caller owns a new reference to the storage (pixmap->image)
 * and gives it back with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapMarker_GetPixmap(TQ3GeometryObject pixmapMarker, TQ3StoragePixmap *pixmap);

/**
 * Replaces a retained pixmap marker's pixmap with pixmap, which must obey
 * the pixmap rules of TQ3PixmapMarkerData (all but the position's), in
 * their order.
 *
 * @return kQ3Success, or kQ3Failure with the marker unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized         Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter          pixmapMarker, pixmap or pixmap->image is
 *                                  NULL.
 *   kQ3ErrorInvalidObject          pixmapMarker or pixmap->image is not a
 *                                  live Q3 object.
 *   kQ3ErrorInvalidObjectType      pixmapMarker is not a pixmap marker, or
 *                                  pixmap->image not a storage.
 *   kQ3ErrorInvalidData            the enumerations or sizes break the rules,
 *                                  or the storage is too small.
 *   kQ3ErrorUnsupportedPixelDepth  pixelSize does not match pixelType.
 *   kQ3ErrorParameterOutOfRange    rowBytes * height is above
 *                                  kQ3GeometryMaxArrayCount.
 *   kQ3ErrorFileNotOpen            a path storage's file cannot be read.
 *
 * Ownership: the marker references the new storage and releases the one it
 * held; the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapMarker_SetPixmap(TQ3GeometryObject pixmapMarker,
                                                    const TQ3StoragePixmap *pixmap);

#ifdef __cplusplus
}
#endif

#endif /* QD3DGEOMETRY_H */
