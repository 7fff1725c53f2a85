/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef QD3DGROUP_H
#define QD3DGROUP_H

/*
 * Groups: ordered lists of objects, addressed by positions.
 *
 *   Q3Group_New              any shared object.
 *   Q3DisplayGroup_New       drawable objects (and lights and cameras, which
 *                            do nothing when drawn). Submitting the group
 *                            submits its objects in order; unless the group
 *                            is inline, the view's graphics state (transform,
 *                            styles, shaders, attributes) is saved before and
 *                            restored after, so what the group sets applies
 *                            to the rest of the group only.
 *   Q3OrderedDisplayGroup_New a display group kept in the order transforms,
 *                            styles, attribute sets, shaders, cameras,
 *                            lights, geometries, groups, unknown objects
 *                            (each added at the end of its kind).
 *   Q3IOProxyDisplayGroup_New several representations of one object, the
 *                            most preferred first: drawing uses the first
 *                            that is not an unknown object.
 *   Q3LightGroup_New         lights only: a view's lights
 *                            (Q3View_SetLightGroup, QD3DView.h).
 *   Q3InfoGroup_New          string objects only.
 *
 * A group holds one reference to each object in it. A position
 * (TQ3GroupPosition) stays valid until its object is removed; Q3 checks
 * every position it is given against the group's own, so a removed
 * position, another group's or a stray pointer gives
 * kQ3ErrorInvalidPositionForGroup, never a crash.
 *
 * A group never contains itself: adding a group to itself, or to a group
 * inside it at any depth, fails with kQ3ErrorInvalidObjectForGroup.
 *
 * Errors every function below shares, checked first, in this order:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      group (or another handle or pointer argument)
 *                              is NULL.
 *   kQ3ErrorInvalidObject      a handle is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  group is not a group (or not a display group,
 *                              for Q3DisplayGroup_ calls).
 * A function that fails changes nothing and, if it returns a position or an
 * object, returns NULL; an output pointer is left unchanged.
 */

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

enum TQ3DisplayGroupStateMasks {
    kQ3DisplayGroupStateNone = 0,
    kQ3DisplayGroupStateMaskIsDrawn = 1 << 0,
    kQ3DisplayGroupStateMaskIsInline = 1 << 1,
    kQ3DisplayGroupStateMaskUseBoundingBox = 1 << 2,
    kQ3DisplayGroupStateMaskUseBoundingSphere = 1 << 3,
    kQ3DisplayGroupStateMaskIsPicked = 1 << 4,
    kQ3DisplayGroupStateMaskIsWritten = 1 << 5
};
typedef enum TQ3DisplayGroupStateMasks TQ3DisplayGroupStateMasks;
typedef unsigned long TQ3DisplayGroupState;

/*
 * Q3 extension: how deep display groups may nest when they are drawn,
 * bounded or duplicated. A submit that reaches a deeper group fails with
 * kQ3ErrorInvalidObject (nothing further of that submit is drawn).
 */
#define kQ3GroupMaxNesting 256

/* ---- Creating groups ------------------------------------------------------ */

/**
 * Creates an empty group of one kind (see the top of this header).
 *
 * @return the new group, or NULL on failure (kQ3ErrorNotInitialized,
 *         kQ3ErrorOutOfMemory).
 *
 * Ownership: the caller owns the new group's one reference.
 */
Q3_EXTERN_API_C(TQ3GroupObject) Q3Group_New(void);
Q3_EXTERN_API_C(TQ3GroupObject) Q3LightGroup_New(void);
Q3_EXTERN_API_C(TQ3GroupObject) Q3InfoGroup_New(void);
Q3_EXTERN_API_C(TQ3GroupObject) Q3DisplayGroup_New(void);
Q3_EXTERN_API_C(TQ3GroupObject) Q3OrderedDisplayGroup_New(void);
Q3_EXTERN_API_C(TQ3GroupObject) Q3IOProxyDisplayGroup_New(void);

/**
 * The kind of a group: kQ3GroupTypeDisplay, kQ3GroupTypeLight or
 * kQ3GroupTypeInfo, or kQ3ObjectTypeInvalid for a plain group (and on
 * failure).
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Group_GetType(TQ3GroupObject group);

/* ---- Adding, replacing and removing --------------------------------------- */

/**
 * Adds object at the end of the group (an ordered display group: at the end
 * of the object's kind); Q3Group_AddObjectBefore / _AddObjectAfter add it
 * next to position instead.
 *
 * @return the new position, or NULL on failure.
 *
 * Errors (besides the shared ones):
 *   kQ3ErrorInvalidPositionForGroup   position is not one of group's.
 *   kQ3ErrorInvalidObjectForGroup     the group cannot hold object (its
 *                                     kind, or it is the group or a group
 *                                     containing it).
 *   kQ3ErrorInvalidObjectForPosition  an ordered display group: object's
 *                                     kind does not belong next to position.
 *
 * Ownership: the group takes its own reference to object.
 */
Q3_EXTERN_API_C(TQ3GroupPosition) Q3Group_AddObject(TQ3GroupObject group, TQ3Object object);
Q3_EXTERN_API_C(TQ3GroupPosition) Q3Group_AddObjectBefore(TQ3GroupObject group, TQ3GroupPosition position,
                                                          TQ3Object object);
Q3_EXTERN_API_C(TQ3GroupPosition) Q3Group_AddObjectAfter(TQ3GroupObject group, TQ3GroupPosition position,
                                                         TQ3Object object);

/**
 * Reads the object at position.
 *
 * Errors: kQ3ErrorInvalidPositionForGroup (position is not one of group's),
 * besides the shared ones.
 *
 * Ownership: *object is a new reference the caller disposes.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Group_GetPositionObject(TQ3GroupObject group, TQ3GroupPosition position,
                                                     TQ3Object *object);

/**
 * Replaces the object at position (the position stays valid).
 *
 * Errors: as Q3Group_AddObjectBefore.
 *
 * Ownership: the group takes a reference to object and releases the one it
 * held at that position.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Group_SetPositionObject(TQ3GroupObject group, TQ3GroupPosition position,
                                                     TQ3Object object);

/**
 * Removes position from the group; the position is no longer valid.
 *
 * @return the object that was there, or NULL on failure
 *         (kQ3ErrorInvalidPositionForGroup besides the shared errors).
 *
 * Ownership: the group's reference passes to the caller, who disposes it.
 */
Q3_EXTERN_API_C(TQ3Object) Q3Group_RemovePosition(TQ3GroupObject group, TQ3GroupPosition position);

/* ---- Walking a group ------------------------------------------------------ */

/**
 * The first or last position of the group (NULL in an empty group).
 * Q3Group_GetNextPosition / _GetPreviousPosition replace *position with the
 * one after or before it (NULL past either end). Each returns kQ3Success
 * when *position was set, NULL included.
 *
 * Errors: kQ3ErrorInvalidPositionForGroup (next / previous: *position is
 * not one of group's), besides the shared ones.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Group_GetFirstPosition(TQ3GroupObject group, TQ3GroupPosition *position);
Q3_EXTERN_API_C(TQ3Status) Q3Group_GetLastPosition(TQ3GroupObject group, TQ3GroupPosition *position);
Q3_EXTERN_API_C(TQ3Status) Q3Group_GetNextPosition(TQ3GroupObject group, TQ3GroupPosition *position);
Q3_EXTERN_API_C(TQ3Status) Q3Group_GetPreviousPosition(TQ3GroupObject group, TQ3GroupPosition *position);

/**
 * The number of objects in the group (Q3Group_CountObjectsOfType: of type
 * isType or a subclass of it).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Group_CountObjects(TQ3GroupObject group, unsigned long *nObjects);
Q3_EXTERN_API_C(TQ3Status) Q3Group_CountObjectsOfType(TQ3GroupObject group, TQ3ObjectType isType,
                                                      unsigned long *nObjects);

/**
 * Removes every object (Q3Group_EmptyObjectsOfType: every object of type
 * isType or a subclass of it); their positions are no longer valid.
 *
 * Ownership: the group releases its references.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Group_EmptyObjects(TQ3GroupObject group);
Q3_EXTERN_API_C(TQ3Status) Q3Group_EmptyObjectsOfType(TQ3GroupObject group, TQ3ObjectType isType);

/**
 * As Q3Group_GetFirstPosition etc., counting only objects of type isType or
 * a subclass of it.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Group_GetFirstPositionOfType(TQ3GroupObject group, TQ3ObjectType isType,
                                                          TQ3GroupPosition *position);
Q3_EXTERN_API_C(TQ3Status) Q3Group_GetLastPositionOfType(TQ3GroupObject group, TQ3ObjectType isType,
                                                         TQ3GroupPosition *position);
Q3_EXTERN_API_C(TQ3Status) Q3Group_GetNextPositionOfType(TQ3GroupObject group, TQ3ObjectType isType,
                                                         TQ3GroupPosition *position);
Q3_EXTERN_API_C(TQ3Status) Q3Group_GetPreviousPositionOfType(TQ3GroupObject group, TQ3ObjectType isType,
                                                             TQ3GroupPosition *position);

/**
 * As Q3Group_GetFirstPosition etc., counting only positions that hold
 * object itself.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Group_GetFirstObjectPosition(TQ3GroupObject group, TQ3Object object,
                                                          TQ3GroupPosition *position);
Q3_EXTERN_API_C(TQ3Status) Q3Group_GetLastObjectPosition(TQ3GroupObject group, TQ3Object object,
                                                         TQ3GroupPosition *position);
Q3_EXTERN_API_C(TQ3Status) Q3Group_GetNextObjectPosition(TQ3GroupObject group, TQ3Object object,
                                                         TQ3GroupPosition *position);
Q3_EXTERN_API_C(TQ3Status) Q3Group_GetPreviousObjectPosition(TQ3GroupObject group, TQ3Object object,
                                                             TQ3GroupPosition *position);

/* ---- Display groups ------------------------------------------------------- */

/**
 * The kind of a display group: kQ3DisplayGroupTypeOrdered or
 * kQ3DisplayGroupTypeIOProxy, or kQ3ObjectTypeInvalid for a plain display
 * group (and on failure).
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3DisplayGroup_GetType(TQ3GroupObject group);

/**
 * Reads or sets a display group's state, a combination of
 * TQ3DisplayGroupStateMasks. A new display group has every flag but
 * kQ3DisplayGroupStateMaskIsInline. Q3 draws a group only when IsDrawn is
 * set, saves and restores the graphics state around it unless IsInline is
 * set, and with UseBoundingBox and a bounding box set, bounds the group by
 * that box in bounding loops and skips drawing it when the box is outside
 * the view. Bits Q3 does not know are kept.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DisplayGroup_GetState(TQ3GroupObject group, TQ3DisplayGroupState *state);
Q3_EXTERN_API_C(TQ3Status) Q3DisplayGroup_SetState(TQ3GroupObject group, TQ3DisplayGroupState state);

/**
 * Draws (or bounds) a display group in a view's loop: the same as
 * Q3Object_Submit of the group.
 *
 * Errors (besides the shared ones): kQ3ErrorViewNotStarted outside a loop;
 * kQ3ErrorInvalidObject when groups nest deeper than kQ3GroupMaxNesting;
 * and what the group's objects post.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DisplayGroup_Submit(TQ3GroupObject group, TQ3ViewObject view);

/**
 * Gives a display group a bounding box (and turns UseBoundingBox on), reads
 * it, or removes it. Q3DisplayGroup_CalcAndUseBoundingBox computes the box
 * of the group's objects with a bounding loop in view (which must not be
 * inside a loop), whatever the group's own state and box, and sets it.
 *
 * Errors (besides the shared ones): kQ3ErrorInvalidParameter for a box with
 * a non-finite corner or min above max, or a computeBounds that is no
 * TQ3ComputeBounds; Q3DisplayGroup_GetBoundingBox: kQ3ErrorInvalidParameter
 * when the group has no box; CalcAndUse: kQ3ErrorViewIsStarted when view is
 * inside a loop, and a group that bounds to nothing gets an empty box.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DisplayGroup_SetAndUseBoundingBox(TQ3GroupObject group, TQ3BoundingBox *bBox);
Q3_EXTERN_API_C(TQ3Status) Q3DisplayGroup_GetBoundingBox(TQ3GroupObject group, TQ3BoundingBox *bBox);
Q3_EXTERN_API_C(TQ3Status) Q3DisplayGroup_RemoveBoundingBox(TQ3GroupObject group);
Q3_EXTERN_API_C(TQ3Status) Q3DisplayGroup_CalcAndUseBoundingBox(TQ3GroupObject group, TQ3ComputeBounds computeBounds,
                                                               TQ3ViewObject view);

/*
 * Group classes (QD3DExtension.h's Q3XObjectHierarchy_RegisterClass with a
 * group class as parentType: kQ3ShapeTypeGroup, kQ3GroupTypeDisplay,
 * kQ3DisplayGroupTypeOrdered, kQ3DisplayGroupTypeIOProxy,
 * kQ3GroupTypeLight, kQ3GroupTypeInfo, or a group class registered under
 * one). An object of such a class (Q3XObjectHierarchy_NewObject) is a group
 * of its parent's kind: every Q3Group_ call works on it, and it draws,
 * picks, bounds, duplicates and is read and written as its parent, under
 * its own class name. Its class's metahandler may give these methods; each
 * is optional, and Q3 calls it as follows.
 *
 * The search and edit methods replace the Q3Group_ call of the same name
 * (Q3Group_AddObject, ..., Q3Group_GetPreviousObjectPosition; the calls
 * without "OfType" use the OfType method with kQ3ObjectTypeShared, which
 * every object in a group is). Q3 checks the group handle and the output
 * pointer, then returns what the method returns. A method that calls the
 * Q3Group_ function it replaces, on the same group, gets Q3's own
 * behaviour (the parent class's): that is how a method adds to what Q3
 * does. Positions stay Q3's: a method hands out positions Q3 made. A method
 * that fails posts its own error (Q3XError_Post).
 *
 * kQ3XMethodType_GroupAcceptObject decides which objects the group holds
 * (in place of the parent's rule; a group still holds shared objects only
 * and never itself): kQ3False gives kQ3ErrorInvalidObjectForGroup.
 *
 * Position methods: a class that returns a size from
 * kQ3XMethodType_GroupPositionSize (cast to TQ3XFunctionPointer; at most
 * 65536 bytes), or gives kQ3XMethodType_GroupPositionNew, keeps data for
 * each position: a zeroed block of that size, filled by the new method
 * (gPos the block, object the object at the position, initData the group's
 * instance data for the class), copied by the copy method when the group is
 * duplicated (a byte copy without one) and given to the delete method when
 * the position goes (removed, emptied, or the group disposed). Setting a
 * position's object keeps the position and its data. A failing new or copy
 * method fails the call with kQ3ErrorInvalidParameter.
 * Q3XGroup_GetPositionPrivate returns the block.
 *
 * Drawing helpers: a display group whose class gives both
 * kQ3XMethodType_GroupStartIterate and kQ3XMethodType_GroupEndIterate draws
 * (and picks and bounds) what they pass back instead of its objects: the
 * start method passes back the first object to draw (NULL: none, and the
 * end method is not called); the end method gets the object just drawn
 * (the class releases it, if it should) and passes back the next, NULL
 * after the last. *iterator is the class's own iteration state; when it
 * holds one of the group's positions, pick hits name it. A failing method
 * fails the submit with kQ3ErrorInvalidParameter.
 *
 * kQ3XMethodType_GroupEndRead is called when a file has given a group of
 * the class all its objects; kQ3Failure fails the read
 * (kQ3ErrorInvalidMetafileObject).
 */
#define kQ3XMethodType_GroupAcceptObject Q3_METHOD_TYPE('g', 'a', 'c', 'o')
typedef TQ3Boolean(QD3D_CALLBACK *TQ3XGroupAcceptObjectMethod)(TQ3GroupObject group, TQ3Object object);

#define kQ3XMethodType_GroupAddObject Q3_METHOD_TYPE('g', 'a', 'd', 'o')
typedef TQ3GroupPosition(QD3D_CALLBACK *TQ3XGroupAddObjectMethod)(TQ3GroupObject group, TQ3Object object);

#define kQ3XMethodType_GroupAddObjectBefore Q3_METHOD_TYPE('g', 'a', 'o', 'b')
typedef TQ3GroupPosition(QD3D_CALLBACK *TQ3XGroupAddObjectBeforeMethod)(TQ3GroupObject group,
                                                                        TQ3GroupPosition position, TQ3Object object);

#define kQ3XMethodType_GroupAddObjectAfter Q3_METHOD_TYPE('g', 'a', 'o', 'a')
typedef TQ3GroupPosition(QD3D_CALLBACK *TQ3XGroupAddObjectAfterMethod)(TQ3GroupObject group,
                                                                       TQ3GroupPosition position, TQ3Object object);

#define kQ3XMethodType_GroupSetPositionObject Q3_METHOD_TYPE('g', 's', 'p', 'o')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupSetPositionObjectMethod)(TQ3GroupObject group, TQ3GroupPosition gPos,
                                                                   TQ3Object obj);

#define kQ3XMethodType_GroupRemovePosition Q3_METHOD_TYPE('g', 'r', 'm', 'p')
typedef TQ3Object(QD3D_CALLBACK *TQ3XGroupRemovePositionMethod)(TQ3GroupObject group, TQ3GroupPosition position);

#define kQ3XMethodType_GroupGetFirstPositionOfType Q3_METHOD_TYPE('g', 'f', 'r', 't')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupGetFirstPositionOfTypeMethod)(TQ3GroupObject group, TQ3ObjectType isType,
                                                                        TQ3GroupPosition *gPos);

#define kQ3XMethodType_GroupGetLastPositionOfType Q3_METHOD_TYPE('g', 'l', 's', 't')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupGetLastPositionOfTypeMethod)(TQ3GroupObject group, TQ3ObjectType isType,
                                                                       TQ3GroupPosition *gPos);

#define kQ3XMethodType_GroupGetNextPositionOfType Q3_METHOD_TYPE('g', 'n', 'x', 't')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupGetNextPositionOfTypeMethod)(TQ3GroupObject group, TQ3ObjectType isType,
                                                                       TQ3GroupPosition *gPos);

#define kQ3XMethodType_GroupGetPrevPositionOfType Q3_METHOD_TYPE('g', 'p', 'v', 't')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupGetPrevPositionOfTypeMethod)(TQ3GroupObject group, TQ3ObjectType isType,
                                                                       TQ3GroupPosition *gPos);

#define kQ3XMethodType_GroupCountObjectsOfType Q3_METHOD_TYPE('g', 'c', 'n', 't')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupCountObjectsOfTypeMethod)(TQ3GroupObject group, TQ3ObjectType isType,
                                                                    unsigned long *nObjects);

#define kQ3XMethodType_GroupEmptyObjectsOfType Q3_METHOD_TYPE('g', 'e', 'o', 't')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupEmptyObjectsOfTypeMethod)(TQ3GroupObject group, TQ3ObjectType isType);

#define kQ3XMethodType_GroupGetFirstObjectPosition Q3_METHOD_TYPE('g', 'f', 'o', 'p')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupGetFirstObjectPositionMethod)(TQ3GroupObject group, TQ3Object object,
                                                                        TQ3GroupPosition *gPos);

#define kQ3XMethodType_GroupGetLastObjectPosition Q3_METHOD_TYPE('g', 'l', 'o', 'p')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupGetLastObjectPositionMethod)(TQ3GroupObject group, TQ3Object object,
                                                                       TQ3GroupPosition *gPos);

#define kQ3XMethodType_GroupGetNextObjectPosition Q3_METHOD_TYPE('g', 'n', 'o', 'p')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupGetNextObjectPositionMethod)(TQ3GroupObject group, TQ3Object object,
                                                                       TQ3GroupPosition *gPos);

#define kQ3XMethodType_GroupGetPrevObjectPosition Q3_METHOD_TYPE('g', 'p', 'o', 'p')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupGetPrevObjectPositionMethod)(TQ3GroupObject group, TQ3Object object,
                                                                       TQ3GroupPosition *gPos);

#define kQ3XMethodType_GroupPositionSize Q3_METHOD_TYPE('g', 'g', 'p', 'z')
typedef unsigned long TQ3XMethodTypeGroupPositionSize;

#define kQ3XMethodType_GroupPositionNew Q3_METHOD_TYPE('g', 'g', 'p', 'n')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupPositionNewMethod)(void *gPos, TQ3Object object, const void *initData);

#define kQ3XMethodType_GroupPositionCopy Q3_METHOD_TYPE('g', 'g', 'p', 'c')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupPositionCopyMethod)(void *srcGPos, void *dstGPos);

#define kQ3XMethodType_GroupPositionDelete Q3_METHOD_TYPE('g', 'g', 'p', 'd')
typedef void(QD3D_CALLBACK *TQ3XGroupPositionDeleteMethod)(void *gPos);

#define kQ3XMethodType_GroupStartIterate Q3_METHOD_TYPE('g', 's', 't', 'd')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupStartIterateMethod)(TQ3GroupObject group, TQ3GroupPosition *iterator,
                                                              TQ3Object *object, TQ3ViewObject view);

#define kQ3XMethodType_GroupEndIterate Q3_METHOD_TYPE('g', 'i', 't', 'd')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupEndIterateMethod)(TQ3GroupObject group, TQ3GroupPosition *iterator,
                                                            TQ3Object *object, TQ3ViewObject view);

#define kQ3XMethodType_GroupEndRead Q3_METHOD_TYPE('g', 'e', 'r', 'd')
typedef TQ3Status(QD3D_CALLBACK *TQ3XGroupEndReadMethod)(TQ3GroupObject group);

/**
 * The private data of one of a group's positions, kept for the group's
 * class (see "Group classes" above).
 *
 * Errors (besides the shared ones): kQ3ErrorNULLParameter for a NULL
 * position; kQ3ErrorInvalidPositionForGroup for a position not of the
 * group; kQ3ErrorInvalidObjectClass when the group's class keeps no data
 * per position (every class Q3 defines).
 */
Q3_EXTERN_API_C(void *) Q3XGroup_GetPositionPrivate(TQ3GroupObject group, TQ3GroupPosition position);

#ifdef __cplusplus
}
#endif

#endif /* QD3DGROUP_H */
