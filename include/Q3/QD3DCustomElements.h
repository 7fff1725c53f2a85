/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Apple's custom elements (QuickDraw 3D 1.6's QD3DCustomElements.h): a name
 * and a URL attached to any object. Each is an element class Q3 registers
 * at Q3Initialize under its class name below; its element type is the one
 * Q3ObjectHierarchy_GetTypeFromString gives for that name (Apple's header
 * declares no constant for it). On a set (attribute sets included) the
 * element is one of the set's elements; on any other object it is kept with
 * the object (QD3D.h, "Elements of shapes"), is duplicated with it
 * (Q3Object_Duplicate) and is read from and written to 3DMF files with it
 * (docs/3dmf.md, "Name and URL elements").
 *
 * As elements in their own right (Q3Set_Add, Q3Shape_AddElement,
 * Q3Object_AddElement with the element type, as Quesa's implementation of
 * these calls uses them), data points to a TQ3StringObject for the name
 * element (a C string object: Add retains it, Get returns a new reference)
 * and to a TCEUrlData * for the URL element (Add copies what it points to;
 * Get stores a newly allocated TCEUrlData the caller frees with
 * CEUrlElement_EmptyData).
 *
 * The wire element (CEWireElement_*, CEcWireElementName) holds a QuickTime
 * atom container (QTAtomContainer, Movies.h) and is not declared: Q3 has no
 * QuickTime.
 *
 * Errors shared by every call here: kQ3ErrorNotInitialized;
 * kQ3ErrorNULLParameter / kQ3ErrorInvalidObject for object; a failed call
 * changes nothing.
 */
#ifndef QD3DCUSTOMELEMENTS_H
#define QD3DCUSTOMELEMENTS_H

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Name element -------------------------------------------------------- */

#define CEcNameElementName "Apple Computer, Inc.:NameElement"

/* CENameElement_SetData: names object (a copy of name, any length); NULL
 * removes the name. Errors: as above. */
Q3_EXTERN_API_C(TQ3Status) CENameElement_SetData(TQ3Object object, const char *name);

/*
 * CENameElement_GetData: *name = a newly allocated copy of object's name,
 * or NULL when it has none (then kQ3Success too). Errors: as above;
 * kQ3ErrorNULLParameter (name). Ownership: the caller frees the copy with
 * CENameElement_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) CENameElement_GetData(TQ3Object object, char **name);

/* CENameElement_EmptyData: frees a name CENameElement_GetData gave and sets
 * *name to NULL (a NULL *name is left alone). Errors: kQ3ErrorNULLParameter
 * (name). */
Q3_EXTERN_API_C(TQ3Status) CENameElement_EmptyData(char **name);

/* ---- URL element --------------------------------------------------------- */

#define CEcUrlElementName "Apple Computer, Inc.:URLElement"

typedef enum TCEUrlOptions {
    kCEUrlOptionNone = 0,
    kCEUrlOptionUseMap = 1
} TCEUrlOptions;

typedef struct TCEUrlData {
    char *url;
    char *description; /* may be NULL */
    TCEUrlOptions options;
} TCEUrlData;

/*
 * CEUrlElement_SetData: gives object a URL element with copies of
 * urlData's strings and its options; NULL urlData removes it. Errors: as
 * above; kQ3ErrorNULLParameter (urlData->url); kQ3ErrorInvalidParameter
 * (options neither kCEUrlOptionNone nor kCEUrlOptionUseMap).
 */
Q3_EXTERN_API_C(TQ3Status) CEUrlElement_SetData(TQ3Object object, TCEUrlData *urlData);

/*
 * CEUrlElement_GetData: *urlData = a newly allocated TCEUrlData with copies
 * of object's URL, description (NULL when it has none) and options, or
 * NULL when object has no URL element (then kQ3Success too). Errors: as
 * above; kQ3ErrorNULLParameter (urlData). Ownership: the caller frees it
 * with CEUrlElement_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) CEUrlElement_GetData(TQ3Object object, TCEUrlData **urlData);

/* CEUrlElement_EmptyData: frees what CEUrlElement_GetData gave (the strings
 * and the structure) and sets *urlData to NULL (a NULL *urlData is left
 * alone). Errors: kQ3ErrorNULLParameter (urlData). */
Q3_EXTERN_API_C(TQ3Status) CEUrlElement_EmptyData(TCEUrlData **urlData);

#ifdef __cplusplus
}
#endif

#endif /* QD3DCUSTOMELEMENTS_H */
