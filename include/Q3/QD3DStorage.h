/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef QD3DSTORAGE_H
#define QD3DSTORAGE_H

/*
 * Storage objects: where a file object (QD3DIO.h) reads and writes its bytes.
 *
 *   memory storage     bytes in memory: a copy Q3 owns and grows as it is
 *                      written (Q3MemoryStorage_New), or the caller's buffer,
 *                      never grown past its size (Q3MemoryStorage_NewBuffer).
 *   Unix path storage  a file named by a path, opened when a file object
 *                      reads or writes it (Q3UnixPathStorage_New; Quesa's
 *                      name for the same, Q3PathStorage_New).
 *
 * A storage is a shared object. While a file object is open on it, it cannot
 * be changed (kQ3ErrorStorageInUse).
 *
 * Errors every function below shares, checked first, in this order:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      a handle or pointer argument is NULL.
 *   kQ3ErrorInvalidObject      a handle is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  storage is not a storage (or not one of the
 *                              kind the call takes).
 * A function that fails changes nothing, leaves its outputs unchanged and
 * returns kQ3Failure (NULL for _New).
 */

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Q3Storage_GetType: the storage's kind: kQ3StorageTypeMemory or
 * kQ3UnixStorageTypePath. kQ3ObjectTypeInvalid on error.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Storage_GetType(TQ3StorageObject storage);

/*
 * Q3Storage_GetSize: the number of valid bytes (a path storage: the file's
 * size, 0 when the file does not exist yet).
 * Errors: kQ3ErrorFileNotOpen when a path storage's file exists but cannot be
 * read.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Storage_GetSize(TQ3StorageObject storage, unsigned long *size);

/*
 * Q3Storage_GetData: copies up to dataSize bytes starting at offset into
 * data; *sizeRead is the number copied, fewer than dataSize only at the end
 * of the storage (0 at or past it).
 * Errors: kQ3ErrorFileNotOpen when a path storage's file cannot be read.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Storage_GetData(TQ3StorageObject storage, unsigned long offset,
                                             unsigned long dataSize, unsigned char *data,
                                             unsigned long *sizeRead);

/*
 * Q3Storage_SetData: writes dataSize bytes from data at offset; the storage
 * grows as needed (a caller's buffer not past its size: then *sizeWritten is
 * what fitted). Bytes between the old end and offset become 0.
 * Errors: kQ3ErrorStorageInUse while a file object has it open;
 * kQ3ErrorFileNotOpen when a path storage's file cannot be written.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Storage_SetData(TQ3StorageObject storage, unsigned long offset,
                                             unsigned long dataSize, const unsigned char *data,
                                             unsigned long *sizeWritten);

/*
 * Q3MemoryStorage_New: a memory storage holding a copy of validSize bytes of
 * buffer (buffer may be NULL with any validSize: then it starts empty).
 * Ownership: the caller holds the new storage's one reference.
 */
Q3_EXTERN_API_C(TQ3StorageObject) Q3MemoryStorage_New(const unsigned char *buffer, unsigned long validSize);

/**
 * Reports the kind of a memory storage: the type of its class below
 * kQ3StorageTypeMemory. QuickDraw 3D's one such class is the Mac handle
 * storage (kQ3MemoryStorageTypeHandle), which cannot exist on Linux, so
 * every Q3 memory storage answers kQ3ObjectTypeInvalid: a plain memory
 * storage.
 *
 * @param storage  a memory storage.
 * @return kQ3ObjectTypeInvalid (also on failure).
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      storage is NULL.
 *   kQ3ErrorInvalidObject      storage is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  storage is not a memory storage.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3MemoryStorage_GetType(TQ3StorageObject storage);

/*
 * Q3MemoryStorage_Set: replaces the contents by a copy of validSize bytes of
 * buffer (NULL: empty).
 * Errors: kQ3ErrorStorageInUse while a file object has it open.
 */
Q3_EXTERN_API_C(TQ3Status) Q3MemoryStorage_Set(TQ3StorageObject storage, const unsigned char *buffer,
                                               unsigned long validSize);

/*
 * Q3MemoryStorage_NewBuffer: a memory storage using the caller's buffer in
 * place: validSize bytes are valid, bufferSize bytes may be written. The
 * caller keeps the buffer alive while the storage uses it and frees it
 * after. A NULL buffer makes a storage that owns a buffer of bufferSize
 * bytes (and grows it), as Q3MemoryStorage_New does.
 * Errors: kQ3ErrorInvalidParameter when validSize exceeds bufferSize.
 */
Q3_EXTERN_API_C(TQ3StorageObject) Q3MemoryStorage_NewBuffer(unsigned char *buffer, unsigned long validSize,
                                                            unsigned long bufferSize);

/*
 * Q3MemoryStorage_SetBuffer: as Q3MemoryStorage_NewBuffer, for an existing
 * memory storage.
 * Errors: kQ3ErrorInvalidParameter when validSize exceeds bufferSize;
 * kQ3ErrorStorageInUse while a file object has it open.
 */
Q3_EXTERN_API_C(TQ3Status) Q3MemoryStorage_SetBuffer(TQ3StorageObject storage, unsigned char *buffer,
                                                     unsigned long validSize, unsigned long bufferSize);

/*
 * Q3MemoryStorage_GetBuffer: the bytes the storage uses, in place (valid
 * until it is next written or set), the number valid and the buffer's size.
 * Any output pointer may be NULL.
 * Ownership: the buffer stays the storage's (or the caller's, for a buffer
 * given to NewBuffer/SetBuffer).
 */
Q3_EXTERN_API_C(TQ3Status) Q3MemoryStorage_GetBuffer(TQ3StorageObject storage, unsigned char **buffer,
                                                     unsigned long *validSize, unsigned long *bufferSize);

/*
 * Q3UnixPathStorage_New: a storage for the file at pathName (a C string; the
 * file need not exist yet: writing creates it).
 * Ownership: the caller holds the new storage's one reference.
 */
Q3_EXTERN_API_C(TQ3StorageObject) Q3UnixPathStorage_New(const char *pathName);

/*
 * Q3UnixPathStorage_Set: names another file.
 * Errors: kQ3ErrorStorageInUse while a file object has it open.
 */
Q3_EXTERN_API_C(TQ3Status) Q3UnixPathStorage_Set(TQ3StorageObject storage, const char *pathName);

/*
 * Q3UnixPathStorage_Get: copies the path, with its terminating 0, into
 * pathName, which must hold it.
 */
Q3_EXTERN_API_C(TQ3Status) Q3UnixPathStorage_Get(TQ3StorageObject storage, char *pathName);

/*
 * Q3PathStorage_New (Q3 extension, Quesa's name): the same as
 * Q3UnixPathStorage_New.
 */
Q3_EXTERN_API_C(TQ3StorageObject) Q3PathStorage_New(const char *pathName);

#ifdef __cplusplus
}
#endif

#endif /* QD3DSTORAGE_H */
