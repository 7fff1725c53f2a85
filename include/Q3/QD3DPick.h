/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Picking: which objects lie under a window point, inside a window
 * rectangle, or along a ray in world space. A pick object describes the
 * question; a picking loop in a view answers it:
 *
 *     Q3View_StartPicking(view, pick);
 *     do {
 *         ... submit the scene ...
 *     } while (Q3View_EndPicking(view) == kQ3ViewStatusRetraverse);
 *     Q3Pick_GetNumHits(pick, &n);
 *
 * Q3View_StartPicking empties the pick's hit list; Q3View_EndPicking fills
 * it, sorted as the pick's TQ3PickData says and cut to numHitsToReturn
 * after sorting. Q3's picking finishes in one traversal, so the loop runs
 * once. Every geometry is tested against what it decomposes into, the
 * points, line segments and triangles the renderers draw
 * (docs/picking.md): triangles are hit as filled surfaces whatever the
 * renderer and fill style; points and lines count as hit within the pick's
 * vertex and edge tolerances. Window coordinates are the draw context's
 * pixels (x right, y down, a pixel's centre at +0.5), as for the pane;
 * tolerances of window-point picks are in pixels, of world-ray picks in
 * world units. Display groups without kQ3DisplayGroupStateMaskIsPicked are
 * skipped.
 *
 * A hit is one geometry submission, or under a pick parts style
 * (QD3DStyle.h) one part of it: its nearest face (a triangle), nearest edge
 * (a line, a side of a polygon or a triangle), nearest vertex, each part in
 * the style's mask giving at most one hit. Its details (the pick's mask,
 * kQ3PickDetailMask*) are read with Q3Pick_GetPickDetailData:
 *
 *   PickID              unsigned long: the pick ID style in force.
 *   Path                TQ3HitPath: the groups submitted around the
 *                       geometry; valid only when it was inside one.
 *   Object              TQ3Object: a new reference to the geometry; valid
 *                       only for retained (not immediate-mode) geometry.
 *                       For what a custom object's submit method submits
 *                       (QD3DExtension.h): the custom object, whose hits
 *                       these are (and whose path Path gives).
 *   LocalToWorldMatrix  TQ3Matrix4x4 in force for the geometry.
 *   XYZ                 TQ3Point3D: the world point hit (point, ray picks).
 *   Distance            float: its distance from the pick ray's origin
 *                       (point, ray picks); for a window point the ray
 *                       starts on the camera's hither plane.
 *   Normal              TQ3Vector3D: unit world normal of a face hit (the
 *                       vertex normals interpolated, else the triangle's
 *                       front side by the orientation style).
 *   ShapePart           TQ3ShapePartObject: a new reference to the part
 *                       of the shape that was hit; valid only for a face,
 *                       edge or vertex hit (a pick parts style other than
 *                       kQ3PickPartsObject) on a retained mesh in a
 *                       window-point or world-ray pick: a mesh face, edge
 *                       or vertex part (Q3MeshFacePart_GetFace, ...).
 *   PickPart            TQ3PickParts: the part hit (kQ3PickPartsObject
 *                       under the default pick parts style).
 *   UV                  TQ3Param2D: the surface uv of a face hit, where
 *                       its vertices have uvs (point, ray picks).
 *
 * With kQ3PickSortNearToFar / FarToNear the hits are ordered by Distance
 * (ties keep submission order); window-rect hits have no distance and stay
 * in submission order whatever the sort; kQ3PickSortNone keeps submission
 * order.
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error and leaves every object and output it was
 * given unchanged. The checks run in this order: Q3 is initialized; the
 * arguments from left to right (a handle: not NULL, a live Q3 object, of
 * the right class; a pointer: not NULL); then the data rules. Data rules
 * (kQ3ErrorInvalidParameter): sort is one of the TQ3PickSort values; mask
 * has no bit above kQ3PickDetailMaskUV; a point, rectangle corner, ray
 * origin or direction is finite; a rectangle's min is at most its max on
 * both axes; a ray direction is not the zero vector; a tolerance is finite
 * and not negative.
 */
#ifndef QD3DPICK_H
#define QD3DPICK_H

#include "QD3D.h"
#include "QD3DGeometry.h"
#include "QD3DStyle.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Which details a pick returns for each hit (TQ3PickData.mask). */
enum TQ3PickDetailMasks {
    kQ3PickDetailNone = 0,
    kQ3PickDetailMaskPickID = 1 << 0,
    kQ3PickDetailMaskPath = 1 << 1,
    kQ3PickDetailMaskObject = 1 << 2,
    kQ3PickDetailMaskLocalToWorldMatrix = 1 << 3,
    kQ3PickDetailMaskXYZ = 1 << 4,
    kQ3PickDetailMaskDistance = 1 << 5,
    kQ3PickDetailMaskNormal = 1 << 6,
    kQ3PickDetailMaskShapePart = 1 << 7,
    kQ3PickDetailMaskPickPart = 1 << 8,
    kQ3PickDetailMaskUV = 1 << 9
};
typedef enum TQ3PickDetailMasks TQ3PickDetailMasks;

typedef unsigned long TQ3PickDetail;

/* How the hit list is ordered. */
enum TQ3PickSort {
    kQ3PickSortNone = 0,
    kQ3PickSortNearToFar = 1,
    kQ3PickSortFarToNear = 2
};
typedef enum TQ3PickSort TQ3PickSort;

/* numHitsToReturn: no limit. */
#define kQ3ReturnAllHits 0

typedef struct TQ3PickData {
    TQ3PickSort sort;
    TQ3PickDetail mask;
    unsigned long numHitsToReturn;
} TQ3PickData;

typedef struct TQ3WindowPointPickData {
    TQ3PickData data;
    TQ3Point2D point;
    float vertexTolerance;
    float edgeTolerance;
} TQ3WindowPointPickData;

typedef struct TQ3WindowRectPickData {
    TQ3PickData data;
    TQ3Area rect;
} TQ3WindowRectPickData;

typedef struct TQ3WorldRayPickData {
    TQ3PickData data;
    TQ3Ray3D ray;
    float vertexTolerance;
    float edgeTolerance;
} TQ3WorldRayPickData;

/*
 * The groups around a hit: rootGroup is the group submitted to the view,
 * positions[0] the position in it of the next group down (or of the
 * geometry), and so on for depth levels; positions[depth - 1] holds the
 * geometry. Valid while the groups are not edited.
 */
typedef struct TQ3HitPath {
    TQ3GroupObject rootGroup;
    unsigned long depth;
    TQ3GroupPosition *positions;
} TQ3HitPath;

/* ---- Every pick ---------------------------------------------------------- */

/**
 * Returns the kind of a pick.
 *
 * @param pick  any pick.
 * @return kQ3PickTypeWindowPoint, kQ3PickTypeWindowRect or
 *         kQ3PickTypeWorldRay; kQ3ObjectTypeInvalid on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a pick.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Pick_GetType(TQ3PickObject pick);

/**
 * Reads the settings every kind of pick has.
 *
 * @param pick  the pick.
 * @param data  receives its sort, mask and numHitsToReturn.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick or data is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a pick.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pick_GetData(TQ3PickObject pick, TQ3PickData *data);

/**
 * Replaces the settings every kind of pick has. The next picking loop uses
 * them; the hit list is kept.
 *
 * @param pick  the pick.
 * @param data  sort, mask and numHitsToReturn (the header's data rules).
 * @return kQ3Success, or kQ3Failure (the pick unchanged).
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick or data is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a pick.
 *   kQ3ErrorInvalidParameter   data breaks a data rule.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pick_SetData(TQ3PickObject pick, const TQ3PickData *data);

/**
 * Reads the vertex tolerance of a window-point or world-ray pick.
 *
 * @param pick             the pick.
 * @param vertexTolerance  receives it (pixels, or world units for a ray).
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick or vertexTolerance is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a pick, or is a window-rect pick
 *                              (which has no tolerances).
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pick_GetVertexTolerance(TQ3PickObject pick, float *vertexTolerance);

/**
 * Reads the edge tolerance of a window-point or world-ray pick.
 *
 * @param pick           the pick.
 * @param edgeTolerance  receives it (pixels, or world units for a ray).
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors: as Q3Pick_GetVertexTolerance, for edgeTolerance.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pick_GetEdgeTolerance(TQ3PickObject pick, float *edgeTolerance);

/**
 * Replaces the vertex tolerance of a window-point or world-ray pick.
 *
 * @param pick             the pick.
 * @param vertexTolerance  how far from the pick a point or vertex may be
 *                         and count as hit: finite, at least 0.
 * @return kQ3Success, or kQ3Failure (the pick unchanged).
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a pick, or is a window-rect pick.
 *   kQ3ErrorInvalidParameter   vertexTolerance is NaN, infinite or negative.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pick_SetVertexTolerance(TQ3PickObject pick, float vertexTolerance);

/**
 * Replaces the edge tolerance of a window-point or world-ray pick.
 *
 * @param pick           the pick.
 * @param edgeTolerance  how far from the pick a line or edge may be and
 *                       count as hit: finite, at least 0.
 * @return kQ3Success, or kQ3Failure (the pick unchanged).
 *
 * Errors: as Q3Pick_SetVertexTolerance, for edgeTolerance.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pick_SetEdgeTolerance(TQ3PickObject pick, float edgeTolerance);

/**
 * Counts the hits the last picking loop found (after numHitsToReturn).
 *
 * @param pick     the pick.
 * @param numHits  receives the count (0 before any loop).
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick or numHits is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a pick.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pick_GetNumHits(TQ3PickObject pick, unsigned long *numHits);

/**
 * Empties the hit list, releasing the references its hits hold.
 *
 * @param pick  the pick.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a pick.
 *
 * Ownership: the hits' references to geometries and groups are released.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pick_EmptyHitList(TQ3PickObject pick);

/**
 * Says which details a hit has: the pick's mask less what does not apply
 * to the hit (see the header's table).
 *
 * @param pick                 the pick.
 * @param index                the hit, 0 .. numHits - 1.
 * @param pickDetailValidMask  receives the mask.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        pick or pickDetailValidMask is NULL.
 *   kQ3ErrorInvalidObject        pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    pick is not a pick.
 *   kQ3ErrorParameterOutOfRange  index is not below the number of hits.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pick_GetPickDetailValidMask(TQ3PickObject pick, unsigned long index,
                                                       TQ3PickDetail *pickDetailValidMask);

/**
 * Reads one detail of a hit into memory of the detail's type (the header's
 * table).
 *
 * @param pick             the pick.
 * @param index            the hit, 0 .. numHits - 1.
 * @param pickDetailValue  exactly one kQ3PickDetailMask* bit.
 * @param detailData       receives the detail.
 * @return kQ3Success, or kQ3Failure (detailData unchanged).
 *
 * Errors:
 *   kQ3ErrorNotInitialized       Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter        pick or detailData is NULL.
 *   kQ3ErrorInvalidObject        pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType    pick is not a pick.
 *   kQ3ErrorParameterOutOfRange  index is not below the number of hits.
 *   kQ3ErrorInvalidParameter     pickDetailValue is not one
 *                                kQ3PickDetailMask* bit.
 *   kQ3ErrorDataNotAvailable     the hit does not have that detail (not in
 *                                Q3Pick_GetPickDetailValidMask).
 *
 * Ownership: Object returns a new reference to the geometry (dispose it);
 * Path returns a new reference to rootGroup and an allocated positions
 * array (release both with Q3HitPath_EmptyData).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Pick_GetPickDetailData(TQ3PickObject pick, unsigned long index,
                                                  TQ3PickDetail pickDetailValue, void *detailData);

/**
 * Releases what Q3Pick_GetPickDetailData put in a hit path and sets it to
 * { NULL, 0, NULL }.
 *
 * @param hitPath  a hit path from Q3Pick_GetPickDetailData, or one already
 *                 emptied.
 * @return kQ3Success, or kQ3Failure (the path unchanged).
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      hitPath is NULL.
 *   kQ3ErrorInvalidObject      rootGroup is not NULL and not a live Q3
 *                              object.
 *   kQ3ErrorInvalidObjectType  rootGroup is not a group.
 *   kQ3ErrorInvalidParameter   depth is not 0 while positions is NULL.
 *
 * Ownership: the reference to rootGroup is released; positions is freed.
 */
Q3_EXTERN_API_C(TQ3Status) Q3HitPath_EmptyData(TQ3HitPath *hitPath);

/* ---- Window-point picks -------------------------------------------------- */

/**
 * Creates a pick for a point of the window: what is drawn at it.
 *
 * @param data  settings, the point in window pixels, and the tolerances
 *              in pixels (the header's data rules).
 * @return a new pick, or NULL.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      data is NULL.
 *   kQ3ErrorInvalidParameter   data breaks a data rule.
 *   kQ3ErrorOutOfMemory        no memory for the pick.
 *
 * Ownership: the caller owns the pick (Q3Object_Dispose destroys it; picks
 * are not shared).
 */
Q3_EXTERN_API_C(TQ3PickObject) Q3WindowPointPick_New(const TQ3WindowPointPickData *data);

/**
 * Reads the point of a window-point pick.
 *
 * @param pick   the pick.
 * @param point  receives the point (window pixels).
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick or point is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a window-point pick.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3WindowPointPick_GetPoint(TQ3PickObject pick, TQ3Point2D *point);

/**
 * Moves the point of a window-point pick.
 *
 * @param pick   the pick.
 * @param point  the new point (window pixels, finite).
 * @return kQ3Success, or kQ3Failure (the pick unchanged).
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick or point is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a window-point pick.
 *   kQ3ErrorInvalidParameter   a coordinate is NaN or infinite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3WindowPointPick_SetPoint(TQ3PickObject pick, const TQ3Point2D *point);

/**
 * Reads everything a window-point pick holds.
 *
 * @param pick  the pick.
 * @param data  receives it.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors: as Q3WindowPointPick_GetPoint, for data.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3WindowPointPick_GetData(TQ3PickObject pick, TQ3WindowPointPickData *data);

/**
 * Replaces everything a window-point pick holds; the hit list is kept.
 *
 * @param pick  the pick.
 * @param data  the new settings (the header's data rules).
 * @return kQ3Success, or kQ3Failure (the pick unchanged).
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick or data is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a window-point pick.
 *   kQ3ErrorInvalidParameter   data breaks a data rule.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3WindowPointPick_SetData(TQ3PickObject pick, const TQ3WindowPointPickData *data);

/* ---- Window-rect picks --------------------------------------------------- */

/**
 * Creates a pick for a rectangle of the window: everything drawn with any
 * part inside it (its edges included).
 *
 * @param data  settings and the rectangle in window pixels (the header's
 *              data rules).
 * @return a new pick, or NULL.
 *
 * Errors: as Q3WindowPointPick_New.
 *
 * Ownership: the caller owns the pick.
 */
Q3_EXTERN_API_C(TQ3PickObject) Q3WindowRectPick_New(const TQ3WindowRectPickData *data);

/**
 * Reads the rectangle of a window-rect pick.
 *
 * @param pick  the pick.
 * @param rect  receives the rectangle (window pixels).
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick or rect is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a window-rect pick.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3WindowRectPick_GetRect(TQ3PickObject pick, TQ3Area *rect);

/**
 * Replaces the rectangle of a window-rect pick.
 *
 * @param pick  the pick.
 * @param rect  the new rectangle (finite, min at most max).
 * @return kQ3Success, or kQ3Failure (the pick unchanged).
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick or rect is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a window-rect pick.
 *   kQ3ErrorInvalidParameter   a coordinate is NaN or infinite, or min
 *                              exceeds max.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3WindowRectPick_SetRect(TQ3PickObject pick, const TQ3Area *rect);

/**
 * Reads everything a window-rect pick holds.
 *
 * @param pick  the pick.
 * @param data  receives it.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors: as Q3WindowRectPick_GetRect, for data.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3WindowRectPick_GetData(TQ3PickObject pick, TQ3WindowRectPickData *data);

/**
 * Replaces everything a window-rect pick holds; the hit list is kept.
 *
 * @param pick  the pick.
 * @param data  the new settings (the header's data rules).
 * @return kQ3Success, or kQ3Failure (the pick unchanged).
 *
 * Errors: as Q3WindowPointPick_SetData, for a window-rect pick.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3WindowRectPick_SetData(TQ3PickObject pick, const TQ3WindowRectPickData *data);

/* ---- World-ray picks ----------------------------------------------------- */

/**
 * Creates a pick for a ray in world space: everything the ray meets at or
 * beyond its origin. Needs no camera or draw context.
 *
 * @param data  settings, the ray and the tolerances in world units (the
 *              header's data rules). The direction need not be unit.
 * @return a new pick, or NULL.
 *
 * Errors: as Q3WindowPointPick_New.
 *
 * Ownership: the caller owns the pick.
 */
Q3_EXTERN_API_C(TQ3PickObject) Q3WorldRayPick_New(const TQ3WorldRayPickData *data);

/**
 * Reads the ray of a world-ray pick.
 *
 * @param pick  the pick.
 * @param ray   receives the ray.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick or ray is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a world-ray pick.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3WorldRayPick_GetRay(TQ3PickObject pick, TQ3Ray3D *ray);

/**
 * Replaces the ray of a world-ray pick.
 *
 * @param pick  the pick.
 * @param ray   the new ray (finite, direction not zero).
 * @return kQ3Success, or kQ3Failure (the pick unchanged).
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      pick or ray is NULL.
 *   kQ3ErrorInvalidObject      pick is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  pick is not a world-ray pick.
 *   kQ3ErrorInvalidParameter   a coordinate is NaN or infinite, or the
 *                              direction is zero.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3WorldRayPick_SetRay(TQ3PickObject pick, const TQ3Ray3D *ray);

/**
 * Reads everything a world-ray pick holds.
 *
 * @param pick  the pick.
 * @param data  receives it.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors: as Q3WorldRayPick_GetRay, for data.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3WorldRayPick_GetData(TQ3PickObject pick, TQ3WorldRayPickData *data);

/**
 * Replaces everything a world-ray pick holds; the hit list is kept.
 *
 * @param pick  the pick.
 * @param data  the new settings (the header's data rules).
 * @return kQ3Success, or kQ3Failure (the pick unchanged).
 *
 * Errors: as Q3WindowPointPick_SetData, for a world-ray pick.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3WorldRayPick_SetData(TQ3PickObject pick, const TQ3WorldRayPickData *data);

/* ---- Shape parts ----------------------------------------------------------
 *
 * The part of a shape a pick hit (the ShapePart detail). Q3's only shapes
 * with parts are meshes: a hit on a mesh's face, edge or vertex gives a
 * mesh face part (kQ3MeshPartTypeMeshFacePart), edge part or vertex part,
 * naming the mesh face the hit point lies in, the mesh edge nearest to it,
 * or the mesh vertex there. A part holds a reference to its mesh; the face,
 * edge or vertex it names is checked again on every call, so a part whose
 * face an edit deleted answers kQ3ErrorInvalidParameter.
 */

/**
 * The shape a part belongs to.
 *
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject,
 * kQ3ErrorInvalidObjectType (shapePartObject: not a shape part),
 * kQ3ErrorNULLParameter (shapeObject).
 *
 * Ownership: *shapeObject receives a new reference to the shape.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ShapePart_GetShape(TQ3ShapePartObject shapePartObject, TQ3ShapeObject *shapeObject);

/**
 * The part's type below kQ3SharedTypeShapePart: kQ3ShapePartTypeMeshPart
 * for every part Q3 makes.
 *
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject,
 * kQ3ErrorInvalidObjectType (then kQ3ObjectTypeInvalid).
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3ShapePart_GetType(TQ3ShapePartObject shapePartObject);

/**
 * The mesh part's type below kQ3ShapePartTypeMeshPart: the face part
 * (kQ3MeshPartTypeMeshFacePart), edge part (kQ3MeshPartTypeMeshEdgePart)
 * or vertex part (kQ3MeshPartTypeMeshVertexPart) a pick gave.
 *
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject,
 * kQ3ErrorInvalidObjectType (meshPartObject: not a mesh part); then
 * kQ3ObjectTypeInvalid.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3MeshPart_GetType(TQ3MeshPartObject meshPartObject);

/**
 * The mesh component (QD3DGeometry.h) the part's face, edge or vertex
 * belongs to, as Q3Mesh_FirstMeshComponent names it.
 *
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject,
 * kQ3ErrorInvalidObjectType (meshPartObject: not a mesh part),
 * kQ3ErrorNULLParameter (component), kQ3ErrorInvalidParameter (the part
 * no longer exists in the mesh).
 */
Q3_EXTERN_API_C(TQ3Status) Q3MeshPart_GetComponent(TQ3MeshPartObject meshPartObject, TQ3MeshComponent *component);

/**
 * The mesh face a face part names. Errors: as Q3MeshPart_GetComponent,
 * kQ3ErrorInvalidObjectType for a part that is not a face part.
 */
Q3_EXTERN_API_C(TQ3Status) Q3MeshFacePart_GetFace(TQ3MeshFacePartObject meshFacePartObject, TQ3MeshFace *face);

/**
 * The mesh edge an edge part names. Errors: as Q3MeshPart_GetComponent,
 * kQ3ErrorInvalidObjectType for a part that is not an edge part.
 */
Q3_EXTERN_API_C(TQ3Status) Q3MeshEdgePart_GetEdge(TQ3MeshEdgePartObject meshEdgePartObject, TQ3MeshEdge *edge);

/**
 * The mesh vertex a vertex part names. Errors: as Q3MeshPart_GetComponent,
 * kQ3ErrorInvalidObjectType for a part that is not a vertex part.
 */
Q3_EXTERN_API_C(TQ3Status) Q3MeshVertexPart_GetVertex(TQ3MeshVertexPartObject meshVertexPartObject,
                                                      TQ3MeshVertex *vertex);

#ifdef __cplusplus
}
#endif

#endif /* QD3DPICK_H */
