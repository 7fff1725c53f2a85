/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef QD3DSTRING_H
#define QD3DSTRING_H

/*
 * String objects: shared objects holding text. Q3 has one kind, the C string
 * (kQ3StringTypeCString); Q3File_GetExternalReferences (QD3DIO.h) returns the
 * names of the files a metafile refers to as C string objects.
 *
 * Errors every function below shares, checked first, in this order:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      a handle or pointer argument is NULL.
 *   kQ3ErrorInvalidObject      a handle is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  stringObj is not a string object.
 * A function that fails changes nothing, leaves its outputs unchanged and
 * returns kQ3Failure (NULL for _New, kQ3ObjectTypeInvalid for _GetType).
 */

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Q3String_GetType: the string's kind (kQ3StringTypeCString). */
Q3_EXTERN_API_C(TQ3ObjectType) Q3String_GetType(TQ3StringObject stringObj);

/* Q3CString_New: a C string object holding a copy of str.
 * Ownership: the caller holds the new object's one reference. */
Q3_EXTERN_API_C(TQ3StringObject) Q3CString_New(const char *str);

/* Q3CString_GetLength: *length is the number of characters, without the NUL. */
Q3_EXTERN_API_C(TQ3Status) Q3CString_GetLength(TQ3StringObject stringObj, unsigned long *length);

/* Q3CString_SetString: the object holds a copy of str from now on. */
Q3_EXTERN_API_C(TQ3Status) Q3CString_SetString(TQ3StringObject stringObj, const char *str);

/*
 * Q3CString_GetString: *str is a new NUL-terminated copy of the text, which
 * the caller releases with Q3CString_EmptyData. Whatever *str held before is
 * overwritten, not released.
 * Ownership: the copy is the caller's until Q3CString_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3CString_GetString(TQ3StringObject stringObj, char **str);

/* Q3CString_EmptyData: releases a copy Q3CString_GetString made and sets *str
 * to NULL (a NULL *str is left as it is). */
Q3_EXTERN_API_C(TQ3Status) Q3CString_EmptyData(char **str);

#ifdef __cplusplus
}
#endif

#endif /* QD3DSTRING_H */
