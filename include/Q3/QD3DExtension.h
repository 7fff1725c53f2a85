/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Custom object classes: the plug-in architecture of QuickDraw 3D 1.6
 * (Apple's QD3DExtension.h), for the classes an application registers
 * itself.
 *
 * A class is registered under a parent class with a metahandler: a function
 * Q3 calls once for each method type it knows, while the register call
 * runs, and never again. The methods it returns (NULL for none) are the
 * class's: kQ3XMethodTypeObjectNew when Q3XObjectHierarchy_NewObject makes
 * an object, kQ3XMethodTypeObjectDelete when the object goes (its last
 * reference disposed), kQ3XMethodTypeObjectDuplicate for Q3Object_Duplicate
 * (without one, the instance data are copied byte for byte). The virtual
 * metahandler's methods are the class's too and are inherited by classes
 * registered under it. Each class in an object's chain has its own block of
 * instance data (instanceSize bytes, zeroed before the new method runs),
 * which Q3XObjectClass_GetPrivate finds.
 *
 * What Q3 takes as a parent: 0 (the object is no shared object, disposed at
 * once), kQ3ObjectTypeShared, kQ3SharedTypeShape (a shape: it takes the
 * Q3Shape_ element calls), or a class registered before under one of
 * these. A class under any other Q3 class (a geometry, a renderer, a file
 * format) would need Q3's internal methods for it; such a parent is
 * refused with kQ3ErrorInvalidObjectClass. Element and attribute classes
 * are registered with QD3DSet.h's Q3XElementClass_Register and
 * Q3XAttributeClass_Register. A custom object is drawable when its class
 * answers kQ3XMethodTypeObjectIsDrawable or has a submit method (below);
 * it draws, picks and bounds only through its submit methods.
 * Objects and elements of a class with QD3DIO.h's I/O methods (traverse,
 * write, read, read-data, attach) are written to and read from 3DMF files
 * by them; without a traverse method they are left out of files with
 * kQ3WarningNoObjectSupportForWriteMethod.
 *
 * Q3XSharedLibrary_Register calls the registration function it is given at
 * once (Q3 loads no plug-in libraries itself); the Mac creator and file
 * types (kQ3XExtensionMacCreatorType) are not declared.
 *
 * Errors: a call that fails posts one error and changes nothing. A NULL
 * class handle is kQ3ErrorNULLParameter, one that names no registered class
 * kQ3ErrorInvalidObjectClass.
 */
#ifndef QD3DEXTENSION_H
#define QD3DEXTENSION_H

#include "QD3D.h"
#include "QD3DErrors.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A class's version: major in the high 16 bits, minor in the low 16. */
#define Q3_OBJECT_CLASS_VERSION(major, minor) (unsigned long)(((major) << 16) | (minor))
#define Q3_OBJECT_CLASS_GET_MAJOR_VERSION(version) (unsigned long)((version) >> 16)
#define Q3_OBJECT_CLASS_GET_MINOR_VERSION(version) (unsigned long)((version)&0x0000ffff)

/* Return the class version itself from the metahandler, cast to a
 * TQ3XFunctionPointer. */
enum { kQ3XMethodTypeObjectClassVersion = Q3_METHOD_TYPE('v', 'r', 's', 'n') };
typedef unsigned long TQ3XObjectClassVersion;

enum { kQ3XMethodTypeObjectClassRegister = Q3_METHOD_TYPE('r', 'g', 's', 't') };
typedef TQ3Status (*TQ3XObjectClassRegisterMethod)(TQ3XObjectClass objectClass, void *classPrivate);

enum { kQ3XMethodTypeObjectClassReplace = Q3_METHOD_TYPE('r', 'g', 'r', 'p') };
typedef void (*TQ3XObjectClassReplaceMethod)(TQ3XObjectClass oldObjectClass, void *oldClassPrivate,
                                             TQ3XObjectClass newObjectClass, void *newClassPrivate);

enum { kQ3XMethodTypeObjectClassUnregister = Q3_METHOD_TYPE('u', 'n', 'r', 'g') };
typedef void (*TQ3XObjectClassUnregisterMethod)(TQ3XObjectClass objectClass, void *classPrivate);

enum { kQ3XMethodTypeObjectNew = Q3_METHOD_TYPE('n', 'e', 'w', 'o') };
typedef TQ3Status (*TQ3XObjectNewMethod)(TQ3Object object, void *privateData, void *parameters);

enum { kQ3XMethodTypeObjectDelete = Q3_METHOD_TYPE('d', 'l', 't', 'e') };
typedef void (*TQ3XObjectDeleteMethod)(TQ3Object object, void *privateData);

enum { kQ3XMethodTypeObjectDuplicate = Q3_METHOD_TYPE('d', 'u', 'p', 'l') };
typedef TQ3Status (*TQ3XObjectDuplicateMethod)(TQ3Object fromObject, const void *fromPrivateData,
                                               TQ3Object toObject, const void *toPrivateData);

typedef TQ3Status (*TQ3XSharedLibraryRegister)(void);

/*
 * Q3 extension (Quesa's names, values and signature; Apple's 1.6 headers
 * leave submit methods private): how a custom object draws, picks and
 * bounds. When an object of the class is submitted (Q3Object_Submit, or as
 * a member of a group being drawn), the submit method of the running loop
 * is called: kQ3XMethodTypeObjectSubmitRender in a rendering loop,
 * kQ3XMethodTypeObjectSubmitPick in a picking loop,
 * kQ3XMethodTypeObjectSubmitBounds in a bounding loop. theView is the
 * loop's view, objectType the object's leaf type, theObject the object and
 * objectData its instance data for the class (Q3XObjectClass_GetPrivate).
 * The method submits what the object stands for to theView (geometries,
 * styles, transforms, in retained or immediate mode); those are drawn,
 * picked and bounded as if submitted directly. Without the loop's method
 * the object adds nothing to it. Returning kQ3Failure fails the submit
 * (kQ3ErrorInvalidParameter); an object that submits itself deeper than
 * 256 levels fails with kQ3ErrorInvalidObject.
 */
#define kQ3XMethodTypeObjectSubmitRender Q3_METHOD_TYPE('Q', 's', 'u', 'r')
#define kQ3XMethodTypeObjectSubmitPick Q3_METHOD_TYPE('Q', 's', 'u', 'p')
#define kQ3XMethodTypeObjectSubmitBounds Q3_METHOD_TYPE('Q', 's', 'u', 'b')
typedef TQ3Status (*TQ3XObjectSubmitMethod)(TQ3ViewObject theView, TQ3ObjectType objectType, TQ3Object theObject,
                                            const void *objectData);

/*
 * Q3XObjectHierarchy_RegisterClass: registers an object class named
 * objectName (its text name in files; unique) under parentType (0 for
 * TQ3Object), and sets *objectType to the type Q3 gives it. The class
 * register method, if any, is called; its kQ3Failure undoes the
 * registration. methodsSize is accepted and unused (Q3 keeps no class
 * private block: the register and unregister methods get NULL).
 * instanceSize: the bytes of instance data each object has for this class.
 * Errors: kQ3ErrorNULLParameter (objectType, objectName);
 * kQ3ErrorInvalidParameter (an empty name, one of kQ3StringMaximumLength
 * characters or more, one a class has already; the register method
 * failed); kQ3ErrorInvalidObjectClass (a parent Q3 does not take).
 * Ownership: the class stays registered until
 * Q3XObjectHierarchy_UnregisterClass. Returns NULL on failure.
 */
Q3_EXTERN_API_C(TQ3XObjectClass)
Q3XObjectHierarchy_RegisterClass(TQ3ObjectType parentType, TQ3ObjectType *objectType, char *objectName,
                                 TQ3XMetaHandler metaHandler, TQ3XMetaHandler virtualMetaHandler,
                                 unsigned long methodsSize, unsigned long instanceSize);

/*
 * Q3XObjectHierarchy_UnregisterClass: unregisters a class (any registered
 * class: object, element or attribute) and calls its unregister methods.
 * Errors: kQ3ErrorObjectClassInUse while objects or elements of it live or
 * a class is registered under it (the class stays registered).
 */
Q3_EXTERN_API_C(TQ3Status) Q3XObjectHierarchy_UnregisterClass(TQ3XObjectClass objectClass);

/* Q3XObjectClass_GetMethod: the class's method of that type, as its
 * metahandlers gave it (NULL for none, or on error). */
Q3_EXTERN_API_C(TQ3XFunctionPointer) Q3XObjectClass_GetMethod(TQ3XObjectClass objectClass,
                                                              TQ3XMethodType methodType);

/*
 * Q3XObjectHierarchy_NewObject: a new object of an object class: the
 * instance data of every custom class in its chain zeroed, then each class's
 * new method called, from the top of the chain down, with parameters.
 * Errors: kQ3ErrorInvalidObjectClass (an element or attribute class);
 * kQ3ErrorInvalidParameter (a new method returned kQ3Failure: the delete
 * methods of the classes whose new method ran are called). Ownership: the
 * caller holds the object (one reference for a shared object).
 */
Q3_EXTERN_API_C(TQ3Object) Q3XObjectHierarchy_NewObject(TQ3XObjectClass objectClass, void *parameters);

/* Q3XObjectClass_GetLeafType: the class's type (kQ3ObjectTypeInvalid on
 * error). */
Q3_EXTERN_API_C(TQ3ObjectType) Q3XObjectClass_GetLeafType(TQ3XObjectClass objectClass);

/*
 * Q3XObjectHierarchy_GetClassVersion: *version = the version the class's
 * metahandler gave for kQ3XMethodTypeObjectClassVersion (0 for none; a
 * class Q3 defines has 1.6). Errors: kQ3ErrorInvalidParameter (no class has
 * the type); kQ3ErrorNULLParameter (version).
 */
Q3_EXTERN_API_C(TQ3Status) Q3XObjectHierarchy_GetClassVersion(TQ3ObjectType objectClassType,
                                                              TQ3XObjectClassVersion *version);

/* Q3XObjectClass_GetType: *theType = the class's type (for an element or
 * attribute class, the element type Q3 gave it). Errors: as above;
 * kQ3ErrorNULLParameter (theType). */
Q3_EXTERN_API_C(TQ3Status) Q3XObjectClass_GetType(TQ3XObjectClass objectClass, TQ3ObjectType *theType);

/* Q3XObjectHierarchy_FindClassByType: the registered custom class of that
 * type, or NULL (a class Q3 defines has no TQ3XObjectClass; no error). */
Q3_EXTERN_API_C(TQ3XObjectClass) Q3XObjectHierarchy_FindClassByType(TQ3ObjectType theType);

/*
 * Q3XObjectClass_GetPrivate: the instance data of targetObject for
 * objectClass (a class in the object's chain), or NULL when the class has
 * instanceSize 0. Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject
 * (targetObject); kQ3ErrorInvalidObjectType (the object is not of the
 * class). Ownership: the block lives as long as the object.
 */
Q3_EXTERN_API_C(void *) Q3XObjectClass_GetPrivate(TQ3XObjectClass objectClass, TQ3Object targetObject);

/* Q3XObject_GetClass: the custom class of an object, NULL for an object of
 * a class Q3 defines (no error) or on error (kQ3ErrorNULLParameter,
 * kQ3ErrorInvalidObject). */
Q3_EXTERN_API_C(TQ3XObjectClass) Q3XObject_GetClass(TQ3Object object);

/* A plug-in library's registration entry point. sharedLibrary is the
 * caller's own identifier for it. */
typedef struct TQ3XSharedLibraryInfo {
    TQ3XSharedLibraryRegister registerFunction;
    unsigned long sharedLibrary;
} TQ3XSharedLibraryInfo;

/*
 * Q3XSharedLibrary_Register: calls sharedLibraryInfo->registerFunction now
 * and records sharedLibrary. Errors: kQ3ErrorNULLParameter
 * (sharedLibraryInfo, its registerFunction); kQ3ErrorInvalidParameter
 * (sharedLibrary registered already; the function returned kQ3Failure:
 * then nothing is recorded).
 */
Q3_EXTERN_API_C(TQ3Status) Q3XSharedLibrary_Register(TQ3XSharedLibraryInfo *sharedLibraryInfo);

/* Q3XSharedLibrary_Unregister: forgets a library Q3XSharedLibrary_Register
 * recorded (its classes stay until unregistered themselves). Errors:
 * kQ3ErrorInvalidParameter (not registered). */
Q3_EXTERN_API_C(TQ3Status) Q3XSharedLibrary_Unregister(unsigned long sharedLibrary);

/*
 * Q3XError_Post, Q3XWarning_Post, Q3XNotice_Post: post a QuickDraw 3D
 * error, warning or notice from an extension's method, as the call that
 * runs the method would: the registered callbacks run and the code is what
 * Q3Error_Get (Q3Warning_Get, Q3Notice_Get) reports after that call. Called
 * outside a method they post as well. kQ3WarningNone and kQ3NoticeNone are
 * ignored; a code outside QD3DErrors.h's range for its kind (errors -28500
 * to -28301, warnings -28300 to -28101, notices -28100 to -28001) posts
 * kQ3ErrorInvalidParameter instead.
 */
Q3_EXTERN_API_C(void) Q3XError_Post(TQ3Error error);
Q3_EXTERN_API_C(void) Q3XWarning_Post(TQ3Warning warning);
Q3_EXTERN_API_C(void) Q3XNotice_Post(TQ3Notice notice);

#ifdef __cplusplus
}
#endif

#endif /* QD3DEXTENSION_H */
