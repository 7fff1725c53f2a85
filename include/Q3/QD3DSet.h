/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Sets and attribute sets.
 *
 * A set (Q3Set_New) holds elements, at most one of each element type; an
 * attribute set (Q3AttributeSet_New) is a set of surface attributes
 * (colour, normal, highlight state, a surface shader, ...) that geometries
 * carry and views inherit. An attribute set is a set: every Q3Set_ call
 * takes one too.
 *
 * The element types Q3 has classes for are the attribute types of
 * TQ3AttributeTypes, kQ3AttributeTypeSurfaceUV to
 * kQ3AttributeTypeSurfaceShader (1 to 11), with the data listed there, in a
 * set as in an attribute set: QuickDraw 3D's attributes are elements, and
 * an attribute type is their element type. The custom element and
 * attribute classes an application registers (Q3XElementClass_Register,
 * Q3XAttributeClass_Register, at the end of this header) are element types
 * as well, in sets and attribute sets alike, with the data their methods
 * take. The Q3Set_ calls refuse any other type with
 * kQ3ErrorUnknownElementType, the Q3AttributeSet_ calls with
 * kQ3ErrorAttributeInvalidType. A walk over a set's types gives the
 * attribute types in their order, then the custom types in ascending
 * order.
 *
 * Surface shader attributes are held by reference: Add retains the shader
 * and Get returns a new reference (QD3DSet.h: "reference counts are
 * incremented on the _Add and _Get").
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error and leaves every object and output it was
 * given unchanged (a set's edit index included). The checks run in this
 * order, and the first that fails decides the error: Q3 is initialized;
 * then the arguments from left to right (a handle: not NULL, a live Q3
 * object, of the right class; a type: one the call takes; a pointer: not
 * NULL); then the function's other conditions in the order it lists them
 * (for a data structure, the rules given with its type, in their order).
 */
#ifndef QD3DSET_H
#define QD3DSET_H

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Sets ---------------------------------------------------------------- */

/**
 * Creates an empty set.
 *
 * @return the new set, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized   Q3Initialize has not been called.
 *   kQ3ErrorOutOfMemory      the set cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new set is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3SetObject) Q3Set_New(void);

/**
 * Returns the kind of a set: its leaf type.
 *
 * @param theSet  any set.
 * @return kQ3SharedTypeSet for a set made by Q3Set_New, kQ3SetTypeAttribute
 *         for an attribute set, or kQ3ObjectTypeInvalid on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      theSet is NULL.
 *   kQ3ErrorInvalidObject      theSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  theSet is not a set.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Set_GetType(TQ3SetObject theSet);

/**
 * Stores one element in a set, replacing any element of the same type
 * already there. Takes an attribute set too, where it does what
 * Q3AttributeSet_Add does.
 *
 * @param theSet   the set to modify.
 * @param theType  the element type: an attribute type from
 *                 kQ3AttributeTypeSurfaceUV to kQ3AttributeTypeSurfaceShader,
 *                 or a registered custom element or attribute class's.
 * @param data     points to a value of the C type listed for theType in
 *                 TQ3AttributeTypes, which is copied; for
 *                 kQ3AttributeTypeSurfaceShader,
 *                 points to a TQ3SurfaceShaderObject handle; for a custom
 *                 class, to what its copy-add (copy-replace) method takes.
 * @return kQ3Success, or kQ3Failure with the set unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized      Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter       theSet or data is NULL, or *data is a NULL
 *                               surface shader handle.
 *   kQ3ErrorInvalidObject       theSet is not a live Q3 object, or *data is
 *                               not a live surface shader handle.
 *   kQ3ErrorInvalidObjectType   theSet is not a set, or *data is a live
 *                               object but not a surface shader.
 *   kQ3ErrorUnknownElementType  theType is not one of the types listed
 *                               above (no element class is registered for
 *                               it).
 *   kQ3ErrorInvalidParameter    a float in *data is not finite, or a switch
 *                               is neither kQ3On nor kQ3Off, or a custom
 *                               class's copy method returned kQ3Failure.
 *   kQ3ErrorOutOfMemory         the element cannot be stored.
 *
 * Ownership: the set keeps its own copy of a value; a surface shader is
 * retained (one reference added, released when the element is replaced or
 * removed or the set is destroyed), and the caller keeps its own reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Set_Add(TQ3SetObject theSet, TQ3ElementType theType, const void *data);

/**
 * Copies one element out of a set.
 *
 * @param theSet   the set to read.
 * @param theType  the element type (as for Q3Set_Add).
 * @param data     receives a value of the C type listed for theType in
 *                 TQ3AttributeTypes; for kQ3AttributeTypeSurfaceShader, a
 *                 TQ3SurfaceShaderObject handle.
 * @return kQ3Success, or kQ3Failure with *data unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized         Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter          theSet or data is NULL.
 *   kQ3ErrorInvalidObject          theSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType      theSet is not a set.
 *   kQ3ErrorUnknownElementType     theType is not a type Q3Set_Add takes.
 *   kQ3ErrorAttributeNotContained  the set holds no element of that type.
 *
 * Ownership: a surface shader is returned as a new reference, which the
 * caller releases with Q3Object_Dispose; nothing else changes hands.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Set_Get(TQ3SetObject theSet, TQ3ElementType theType, void *data);

/**
 * Reports whether a set holds an element of the given type.
 *
 * @param theSet   the set to query.
 * @param theType  the element type (as for Q3Set_Add).
 * @return kQ3True if the set holds that element; kQ3False if it does not or
 *         the call fails.
 *
 * Errors:
 *   kQ3ErrorNotInitialized      Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter       theSet is NULL.
 *   kQ3ErrorInvalidObject       theSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType   theSet is not a set.
 *   kQ3ErrorUnknownElementType  theType is not a type Q3Set_Add takes.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Boolean) Q3Set_Contains(TQ3SetObject theSet, TQ3ElementType theType);

/**
 * Removes the element of the given type from a set.
 *
 * @param theSet   the set to modify.
 * @param theType  the element type (as for Q3Set_Add).
 * @return kQ3Success, or kQ3Failure with the set unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized         Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter          theSet is NULL.
 *   kQ3ErrorInvalidObject          theSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType      theSet is not a set.
 *   kQ3ErrorUnknownElementType     theType is not a type Q3Set_Add takes.
 *   kQ3ErrorAttributeNotContained  the set holds no element of that type.
 *
 * Ownership: a surface shader element releases the set's reference to the
 * shader.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Set_Clear(TQ3SetObject theSet, TQ3ElementType theType);

/**
 * Removes every element from a set, including the objects a 3DMF file gave
 * it that Q3 has no class for.
 *
 * @param target  the set to empty.
 * @return kQ3Success, or kQ3Failure with the set unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      target is NULL.
 *   kQ3ErrorInvalidObject      target is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  target is not a set.
 *
 * Ownership: the set's references to the objects it held (a surface shader,
 * unknown objects) are released.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Set_Empty(TQ3SetObject target);

/**
 * Steps through the element types a set holds. Pass kQ3ElementTypeNone to
 * get the first; each call then gives the next type held after *theType,
 * in increasing order of type (kQ3AttributeTypeSurfaceUV first,
 * kQ3AttributeTypeSurfaceShader last), and kQ3ElementTypeNone after the
 * last one. The walk keeps no state in the set, so the set may change
 * between calls. Objects a 3DMF file gave the set that Q3 has no class for
 * have no element type and are not listed.
 *
 * @param theSet   the set to walk.
 * @param theType  on entry kQ3ElementTypeNone or an element type Q3Set_Add
 *                 takes (the set need not hold it); on exit the next type
 *                 held, or kQ3ElementTypeNone.
 * @return kQ3Success, or kQ3Failure with *theType unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized      Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter       theSet or theType is NULL.
 *   kQ3ErrorInvalidObject       theSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType   theSet is not a set.
 *   kQ3ErrorUnknownElementType  *theType is neither kQ3ElementTypeNone nor a
 *                               type Q3Set_Add takes.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Set_GetNextElementType(TQ3SetObject theSet, TQ3ElementType *theType);

/* ---- Attribute types ----------------------------------------------------- */

/*
 * Built-in attribute types. The comment on each names the C type that the
 * Add calls read from, and the Get calls write to, the data pointer. The
 * surface shader is passed as a handle: Add retains it, Get returns a new
 * reference.
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

/* ---- Attribute drawing --------------------------------------------------- */

/**
 * Submits one attribute to a view in a rendering or bounding loop, as
 * submitting an attribute set holding only that attribute would: it becomes
 * the view's current attribute of its type for everything submitted
 * afterwards in the same pass, until a Q3Pop_Submit restores the state
 * saved by the matching Q3Push_Submit. A surface shader attribute also
 * shades what follows as submitting the shader itself would (a texture
 * shader's texture, uv transform and boundaries).
 *
 * @param attributeType  which attribute to submit (as for
 *                       Q3AttributeSet_Add).
 * @param data           the attribute's data (as for Q3AttributeSet_Add).
 * @param view           a view inside a loop.
 * @return kQ3Success, or kQ3Failure with the view state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized        Q3Initialize has not been called.
 *   kQ3ErrorAttributeInvalidType  attributeType is not one Q3AttributeSet_Add
 *                                 takes.
 *   kQ3ErrorNULLParameter         data or view is NULL, or *data is a NULL
 *                                 surface shader handle.
 *   kQ3ErrorInvalidObject         *data (a surface shader) or view is not a
 *                                 live Q3 object.
 *   kQ3ErrorInvalidObjectType     *data is not a surface shader, or view is
 *                                 not a view.
 *   kQ3ErrorInvalidParameter      a float in *data is not finite, or a switch
 *                                 is neither kQ3On nor kQ3Off.
 *   kQ3ErrorViewNotStarted        view is not inside a rendering or bounding
 *                                 loop.
 *
 * Ownership: the view's state holds a surface shader until the pass ends
 * (or a pop restores an earlier state); the caller keeps its reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Attribute_Submit(TQ3AttributeType attributeType, const void *data,
                                              TQ3ViewObject view);

/* ---- Attribute sets ------------------------------------------------------ */

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
 * Q3 stores kQ3AttributeTypeSurfaceUV through kQ3AttributeTypeSurfaceShader
 * (1 to 11). Custom attribute types are not provided.
 *
 * @param attributeSet  the set to modify.
 * @param theType       which attribute to store.
 * @param data          points to a value of the C type listed for theType in
 *                      TQ3AttributeTypes, which is copied; for
 *                      kQ3AttributeTypeSurfaceShader, points to a
 *                      TQ3SurfaceShaderObject handle (a texture shader).
 * @return kQ3Success, or kQ3Failure with the set unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized        Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter         attributeSet or data is NULL, or *data is a
 *                                 NULL surface shader handle.
 *   kQ3ErrorInvalidObject         attributeSet is not a live Q3 object, or
 *                                 *data is not a live surface shader handle.
 *   kQ3ErrorInvalidObjectType     attributeSet is not an attribute set, or
 *                                 *data is a live object but not a surface
 *                                 shader (an illumination shader, say).
 *   kQ3ErrorAttributeInvalidType  theType is not one of the types listed above.
 *   kQ3ErrorInvalidParameter      a float in *data is not finite, or a switch
 *                                 is neither kQ3On nor kQ3Off.
 *   kQ3ErrorOutOfMemory           the attribute cannot be stored.
 *
 * Ownership: the set keeps its own copy of a value. A surface shader is
 * retained: the set adds one reference, released when the attribute is
 * replaced, cleared or emptied or the set is destroyed; the caller keeps
 * its own.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AttributeSet_Add(TQ3AttributeSet attributeSet,
                                              TQ3AttributeType theType,
                                              const void *data);

/**
 * Reports whether a set holds an attribute of the given type.
 *
 * @param attributeSet   the set to query.
 * @param attributeType  the attribute type to look for (as for
 *                       Q3AttributeSet_Add).
 * @return kQ3True if the set holds that attribute; kQ3False if it does not
 *         or the call fails.
 *
 * Errors:
 *   kQ3ErrorNotInitialized        Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter         attributeSet is NULL.
 *   kQ3ErrorInvalidObject         attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType     attributeSet is not an attribute set.
 *   kQ3ErrorAttributeInvalidType  attributeType is not one Q3AttributeSet_Add
 *                                 takes.
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
 *                      TQ3AttributeTypes; for kQ3AttributeTypeSurfaceShader,
 *                      a TQ3SurfaceShaderObject handle.
 * @return kQ3Success, or kQ3Failure with *data unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized         Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter          attributeSet or data is NULL.
 *   kQ3ErrorInvalidObject          attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType      attributeSet is not an attribute set.
 *   kQ3ErrorAttributeInvalidType   theType is not one Q3AttributeSet_Add
 *                                  takes.
 *   kQ3ErrorAttributeNotContained  the set holds no attribute of type theType.
 *
 * Ownership: a surface shader is returned as a new reference, which the
 * caller releases with Q3Object_Dispose; nothing else changes hands.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AttributeSet_Get(TQ3AttributeSet attributeSet,
                                              TQ3AttributeType theType,
                                              void *data);

/**
 * Removes the attribute of the given type from a set.
 *
 * @param attributeSet  the set to modify.
 * @param theType       which attribute to remove.
 * @return kQ3Success, or kQ3Failure with the set unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized         Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter          attributeSet is NULL.
 *   kQ3ErrorInvalidObject          attributeSet is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType      attributeSet is not an attribute set.
 *   kQ3ErrorAttributeInvalidType   theType is not one Q3AttributeSet_Add
 *                                  takes.
 *   kQ3ErrorAttributeNotContained  the set holds no attribute of type theType.
 *
 * Ownership: clearing the surface shader releases the set's reference to it.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AttributeSet_Clear(TQ3AttributeSet attributeSet,
                                                TQ3AttributeType theType);

/**
 * Removes every attribute from a set, and the objects a 3DMF file gave it
 * that Q3 has no attribute for.
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
 * Ownership: the set's references to the objects it held (a surface shader,
 * unknown objects) are released.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AttributeSet_Empty(TQ3AttributeSet target);

/**
 * Steps through the attribute types a set holds. Pass kQ3AttributeTypeNone
 * to get the first; each call then gives the next type held after
 * *theType, in increasing order of type (kQ3AttributeTypeSurfaceUV first,
 * kQ3AttributeTypeSurfaceShader last), and kQ3AttributeTypeNone after the
 * last one. The walk keeps no state in the set, so the set may change
 * between calls.
 *
 * @param source   the set to walk.
 * @param theType  on entry kQ3AttributeTypeNone or a type
 *                 Q3AttributeSet_Add takes (the set need not hold it); on
 *                 exit the next type held, or kQ3AttributeTypeNone.
 * @return kQ3Success, or kQ3Failure with *theType unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized        Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter         source or theType is NULL.
 *   kQ3ErrorInvalidObject         source is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType     source is not an attribute set.
 *   kQ3ErrorAttributeInvalidType  *theType is neither kQ3AttributeTypeNone
 *                                 nor a type Q3AttributeSet_Add takes.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AttributeSet_GetNextAttributeType(TQ3AttributeSet source,
                                                               TQ3AttributeType *theType);

/**
 * Submits an attribute set to a view in a rendering or bounding loop. Its
 * attributes become the view's current attributes for everything submitted
 * afterwards in the same pass, until a Q3Pop_Submit restores the state saved
 * by the matching Q3Push_Submit. A geometry's own attribute set still
 * overrides them. A surface shader in the set also shades what follows as
 * submitting the shader itself would.
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
 * Ownership: the view's state holds the set's surface shader until the pass
 * ends (or a pop restores an earlier state); no reference to the set is
 * kept.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AttributeSet_Submit(TQ3AttributeSet attributeSet,
                                                 TQ3ViewObject view);

/**
 * Merges two attribute sets into a third: afterwards result holds every
 * attribute of child, and every attribute of parent whose type child does
 * not hold (the child's value wins where both have one). Whatever result
 * held before is replaced, the objects a 3DMF file gave it included; those
 * objects of parent and child are not attributes and are not inherited.
 * result may be parent or child (or both may be one set). The surface
 * shader is inherited like the other attributes.
 *
 * @param parent  the set whose attributes child's override.
 * @param child   the set whose attributes win.
 * @param result  the set that receives the merge.
 * @return kQ3Success, or kQ3Failure with result unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      parent, child or result is NULL.
 *   kQ3ErrorInvalidObject      parent, child or result is not a live Q3
 *                              object.
 *   kQ3ErrorInvalidObjectType  parent, child or result is not an attribute
 *                              set.
 *
 * Ownership: result retains the surface shader it inherits and releases the
 * one it held; parent and child do not change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AttributeSet_Inherit(TQ3AttributeSet parent, TQ3AttributeSet child,
                                                  TQ3AttributeSet result);

/* ---- Custom element registration ------------------------------------------
 *
 * A custom element class stores sizeOfElement bytes of internal data per
 * element, made and read by its methods (each optional: without one, the
 * bytes are copied as they are):
 *   CopyAdd        Q3Set_Add of a new element: from the application's data
 *                  into the zeroed internal element.
 *   CopyReplace    Q3Set_Add over an element the set has (without it: a new
 *                  element by CopyAdd, then the old one deleted).
 *   CopyGet        Q3Set_Get: from the internal element to the
 *                  application's data.
 *   CopyDuplicate  Q3Object_Duplicate of a set or object holding it.
 *   Delete         once for every internal element, when it is replaced,
 *                  cleared, emptied or its set is destroyed.
 * A copy method that returns kQ3Failure fails the call with
 * kQ3ErrorInvalidParameter; the set keeps what it held (a failed
 * CopyReplace may have changed the element it was given).
 */
#define kQ3XMethodTypeElementCopyAdd Q3_METHOD_TYPE('e', 'c', 'p', 'a')
#define kQ3XMethodTypeElementCopyReplace Q3_METHOD_TYPE('e', 'c', 'p', 'r')
#define kQ3XMethodTypeElementCopyGet Q3_METHOD_TYPE('e', 'c', 'p', 'g')
#define kQ3XMethodTypeElementCopyDuplicate Q3_METHOD_TYPE('e', 'c', 'p', 'd')
#define kQ3XMethodTypeElementDelete Q3_METHOD_TYPE('e', 'd', 'e', 'l')
typedef TQ3Status (*TQ3XElementCopyAddMethod)(const void *fromAPIElement, void *toInternalElement);
typedef TQ3Status (*TQ3XElementCopyReplaceMethod)(const void *fromAPIElement, void *ontoInternalElement);
typedef TQ3Status (*TQ3XElementCopyGetMethod)(const void *fromInternalElement, void *toAPIElement);
typedef TQ3Status (*TQ3XElementCopyDuplicateMethod)(const void *fromInternalElement, void *toInternalElement);
typedef TQ3Status (*TQ3XElementDeleteMethod)(void *internalElement);

/*
 * Q3XElementClass_Register: registers an element class named name (unique)
 * under kQ3ObjectTypeElement. *elementType is the type asked for; Q3 keeps
 * it when no class has it and it is none of the reserved element types (0
 * to 33), else gives a new (negative) type, and sets *elementType to the
 * type the class has. metaHandler may be NULL (every method by byte copy).
 * Errors: kQ3ErrorNULLParameter (elementType, name);
 * kQ3ErrorInvalidParameter (an empty name, one of kQ3StringMaximumLength
 * characters or more, one a class has already). Ownership: the class stays
 * registered until Q3XObjectHierarchy_UnregisterClass (QD3DExtension.h).
 * Returns the class, or NULL on failure (*elementType unchanged).
 */
Q3_EXTERN_API_C(TQ3XObjectClass) Q3XElementClass_Register(TQ3ElementType *elementType, const char *name,
                                                          unsigned long sizeOfElement,
                                                          TQ3XMetaHandler metaHandler);

/*
 * Q3XElementType_GetElementSize: *sizeOfElement = the internal size of a
 * registered custom element or attribute class's elements. Errors:
 * kQ3ErrorUnknownElementType (no custom class has elementType);
 * kQ3ErrorNULLParameter (sizeOfElement).
 */
Q3_EXTERN_API_C(TQ3Status) Q3XElementType_GetElementSize(TQ3ElementType elementType,
                                                         unsigned long *sizeOfElement);

/* ---- Custom attribute registration -----------------------------------------
 *
 * An attribute class is an element class under kQ3ElementTypeAttribute,
 * with the element methods above and these: the metahandler returns
 * (TQ3XFunctionPointer)kQ3True for kQ3XMethodTypeAttributeInherit when
 * Q3AttributeSet_Inherit passes the parent's attribute on; CopyInherit
 * copies it there (without it, CopyDuplicate, else the bytes). A view does
 * not draw with custom attributes. Default and IsDefault (QuickDraw 3D
 * 1.5) are asked for and kept; Q3 calls neither.
 */
#define kQ3XMethodTypeAttributeInherit Q3_METHOD_TYPE('i', 'n', 'h', 't')
typedef TQ3Boolean TQ3XAttributeInheritMethod;
#define kQ3XMethodTypeAttributeCopyInherit Q3_METHOD_TYPE('a', 'c', 'p', 'i')
typedef TQ3Status (*TQ3XAttributeCopyInheritMethod)(const void *fromInternalAttribute, void *toInternalAttribute);

/*
 * Q3XAttributeClass_Register: as Q3XElementClass_Register, for an attribute
 * class named creatorName.
 */
Q3_EXTERN_API_C(TQ3XObjectClass) Q3XAttributeClass_Register(TQ3AttributeType *attributeType,
                                                            const char *creatorName, unsigned long sizeOfElement,
                                                            TQ3XMetaHandler metaHandler);

#define kQ3XMethodTypeAttributeDefault Q3_METHOD_TYPE('a', 's', 'd', 'f')
typedef TQ3Status (*TQ3XAttributeDefaultMethod)(void *internalElement);
#define kQ3XMethodTypeAttributeIsDefault Q3_METHOD_TYPE('a', 'i', 'd', 'f')
typedef TQ3Boolean (*TQ3XAttributeIsDefaultMethod)(void *internalElement);

#ifdef __cplusplus
}
#endif

#endif /* QD3DSET_H */
