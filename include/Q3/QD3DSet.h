/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Attribute sets: small collections of surface attributes (colour, normal,
 * highlight state, ...) that geometries carry and views inherit.
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error and leaves every object and output it was
 * given unchanged. The checks run in this order, and the first that fails
 * decides the error: Q3 is initialized; then the arguments from left to
 * right (a handle: not NULL, a live Q3 object, of the right class; a
 * pointer: not NULL); then the function's other conditions in the order it
 * lists them (for a data structure, the rules given with its type, in their
 * order).
 */
#ifndef QD3DSET_H
#define QD3DSET_H

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Built-in attribute types. The comment on each names the C type that
 * Q3AttributeSet_Add reads from, and Q3AttributeSet_Get writes to, the data
 * pointer.
 */
enum TQ3AttributeTypes {
    kQ3AttributeTypeNone               = 0,  /* no data; never stored       */
    kQ3AttributeTypeSurfaceUV          = 1,  /* TQ3Param2D                  */
    kQ3AttributeTypeShadingUV          = 2,  /* TQ3Param2D                  */
    kQ3AttributeTypeNormal             = 3,  /* TQ3Vector3D                 */
    kQ3AttributeTypeAmbientCoefficient = 4,  /* float                       */
    kQ3AttributeTypeDiffuseColor       = 5,  /* TQ3ColorRGB                 */
    kQ3AttributeTypeSpecularColor      = 6,  /* TQ3ColorRGB                 */
    kQ3AttributeTypeSpecularControl    = 7,  /* float                       */
    kQ3AttributeTypeTransparencyColor  = 8,  /* TQ3ColorRGB                 */
    kQ3AttributeTypeSurfaceTangent     = 9,  /* TQ3Tangent2D                */
    kQ3AttributeTypeHighlightState     = 10, /* TQ3Switch                   */
    kQ3AttributeTypeSurfaceShader      = 11, /* TQ3SurfaceShaderObject      */
    kQ3AttributeTypeNumTypes           = 12
};
typedef enum TQ3AttributeTypes TQ3AttributeTypes;

/* An attribute type code: a TQ3AttributeTypes value. */
typedef TQ3ElementType TQ3AttributeType;

/**
 * Creates an empty attribute set.
 *
 * @return the new attribute set, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized   Q3Initialize has not been called.
 *   kQ3ErrorOutOfMemory      the set cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new set is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3AttributeSet) Q3AttributeSet_New(void);

/**
 * Stores one attribute in a set, replacing any attribute of the same type
 * already there.
 *
 * Q3 stores kQ3AttributeTypeSurfaceUV through kQ3AttributeTypeHighlightState
 * (1 to 10). Shader attributes and custom attribute types are not provided.
 *
 * @param attributeSet  the set to modify.
 * @param theType       which attribute to store.
 * @param data          points to a value of the C type listed for theType in
 *                      TQ3AttributeTypes; the value is copied. A TQ3Switch
 *                      other than kQ3Off is stored as kQ3On.
 * @return kQ3Success, or kQ3Failure with the set unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized        Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter         attributeSet or data is NULL.
 *   kQ3ErrorInvalidObject         attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType     attributeSet is not an attribute set.
 *   kQ3ErrorAttributeInvalidType  theType is not one of the types listed above.
 *   kQ3ErrorInvalidParameter      a float in *data is not finite.
 *   kQ3ErrorOutOfMemory           the attribute cannot be stored.
 *
 * Ownership: no references change; the set keeps its own copy of *data.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AttributeSet_Add(TQ3AttributeSet attributeSet,
                                              TQ3AttributeType theType,
                                              const void *data);

/**
 * Reports whether a set holds an attribute of the given type.
 *
 * @param attributeSet   the set to query.
 * @param attributeType  the attribute type to look for.
 * @return kQ3True if the set holds that attribute; kQ3False if it does not
 *         or the call fails.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      attributeSet is NULL.
 *   kQ3ErrorInvalidObject      attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  attributeSet is not an attribute set.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Boolean) Q3AttributeSet_Contains(TQ3AttributeSet attributeSet,
                                                    TQ3AttributeType attributeType);

/**
 * Copies one attribute out of a set.
 *
 * @param attributeSet  the set to read.
 * @param theType       which attribute to read.
 * @param data          receives a value of the C type listed for theType in
 *                      TQ3AttributeTypes.
 * @return kQ3Success, or kQ3Failure with *data unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized         Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter          attributeSet or data is NULL.
 *   kQ3ErrorInvalidObject          attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType      attributeSet is not an attribute set.
 *   kQ3ErrorAttributeNotContained  the set holds no attribute of type theType.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AttributeSet_Get(TQ3AttributeSet attributeSet,
                                              TQ3AttributeType theType,
                                              void *data);

/**
 * Removes the attribute of the given type from a set. Removing a type the
 * set does not hold succeeds and changes nothing.
 *
 * @param attributeSet  the set to modify.
 * @param theType       which attribute to remove.
 * @return kQ3Success, or kQ3Failure with the set unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      attributeSet is NULL.
 *   kQ3ErrorInvalidObject      attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  attributeSet is not an attribute set.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AttributeSet_Clear(TQ3AttributeSet attributeSet,
                                                TQ3AttributeType theType);

/**
 * Removes every attribute from a set.
 *
 * @param target  the set to empty.
 * @return kQ3Success, or kQ3Failure with the set unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      target is NULL.
 *   kQ3ErrorInvalidObject      target is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  target is not an attribute set.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AttributeSet_Empty(TQ3AttributeSet target);

/**
 * Submits an attribute set to a view in a rendering or bounding loop. Its
 * attributes become the view's current attributes for everything submitted
 * afterwards in the same pass, until a Q3Pop_Submit restores the state saved
 * by the matching Q3Push_Submit. A geometry's own attribute set still
 * overrides them.
 *
 * @param attributeSet  the attributes to apply.
 * @param view          a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      attributeSet or view is NULL.
 *   kQ3ErrorInvalidObject      attributeSet or view is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  attributeSet is not an attribute set, or view
 *                              is not a view.
 *   kQ3ErrorViewNotStarted     view is not inside a rendering or bounding
 *                              loop.
 *
 * Ownership: no references are kept after the call returns.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AttributeSet_Submit(TQ3AttributeSet attributeSet,
                                                 TQ3ViewObject view);

#ifdef __cplusplus
}
#endif

#endif /* QD3DSET_H */
