/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef QD3DIO_H
#define QD3DIO_H

/*
 * File objects: reading and writing QuickDraw 3D metafiles (3DMF 1.6), text
 * and binary.
 *
 * Reading:
 *     TQ3FileObject file = Q3File_New();
 *     Q3File_SetStorage(file, Q3UnixPathStorage_New("model.3dmf"));
 *     TQ3FileMode mode;
 *     Q3File_OpenRead(file, &mode);
 *     while (!Q3File_IsEndOfFile(file)) {
 *         TQ3Object object = Q3File_ReadObject(file);   (NULL: see Q3Error_Get)
 *         ...
 *     }
 *     Q3File_Close(file);
 *
 * Writing: Q3File_OpenWrite(file, mode), then a writing loop
 *     Q3View_StartWriting(view, file);
 *     do { Q3Object_Submit(object, view); ... }
 *     while (Q3View_EndWriting(view) == kQ3ViewStatusRetraverse);
 * then Q3File_Close(file), which puts the bytes into the storage. A file is
 * binary and big-endian (as Mac QuickDraw 3D wrote it) unless the mode
 * includes kQ3FileModeText, or kQ3FileModeSwap for a little-endian binary
 * file (whose header's tag reads "FMD3"). Reading takes both encodings and
 * both byte orders.
 *
 * An object written twice into one file (a shared attribute set, a geometry
 * in two groups) is written once and referred to the second time, through
 * the table of contents, in Normal and Database mode (Q3 writes Database
 * files as Normal ones, with the Database mode in the header); Stream mode
 * writes it again. Groups are written again each time. Reading gives back one
 * object for every reference to it.
 *
 * What Q3 reads and writes: the geometries Point, Line, PolyLine, Triangle,
 * Polygon, TriMesh (with its attribute arrays), NURBCurve, Box, Cone,
 * Cylinder, Disk, Ellipse, Ellipsoid and Torus, with their own attribute set,
 * their vertices' sets (VertexAttributeSetList) and the solids' Caps;
 * attribute sets (surface and shading UV, normal, ambient coefficient,
 * diffuse, specular and transparency colour, specular control, surface
 * tangent, highlight state); groups (Group, DisplayGroup,
 * OrderedDisplayGroup, IOProxyDisplayGroup, LightGroup, InfoGroup) through
 * BeginGroup and EndGroup, with display group states; the subdivision,
 * anti-alias, fog, highlight, backfacing, interpolation, fill, orientation,
 * pick ID, pick parts and shadow styles; the Phong, Lambert and
 * NULL illumination shaders; ambient, directional, point and spot lights;
 * matrix, translate, scale, rotate and reset transforms; view hints (below),
 * with their camera, lights, attribute set, image dimensions, mask and clear
 * colour; objects and elements of the classes an application registers,
 * through their class's I/O methods (below). Anything else in a file is
 * read as an unknown object.
 *
 * Objects of a type Q3 does not know are read as unknown objects
 * (Q3Unknown_GetType) and written back unchanged.
 *
 * A malformed file never crashes Q3 and never makes it allocate more than
 * the file's size justifies: a truncated object, a size that overruns its
 * container, a count its data cannot hold, a reference to nothing or to
 * itself, a bad type or label, or a malformed number makes the call fail with
 * the error saying which (kQ3ErrorInvalidMetafile, ...Primitive, ...Label,
 * ...Object, ...SubObject), with the object's position in the message.
 *
 * Errors every function below shares, checked first, in this order:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      a handle or pointer argument is NULL.
 *   kQ3ErrorInvalidObject      a handle is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  a handle is not of the kind the call takes.
 * A function that fails changes nothing, leaves outputs unchanged and
 * returns kQ3Failure (NULL, kQ3False, kQ3ObjectTypeInvalid).
 */

#include "QD3D.h"
#include "QD3DDrawContext.h"
#include "QD3DView.h"

#ifdef __cplusplus
extern "C" {
#endif

enum TQ3FileModeMasks {
    kQ3FileModeNormal = 0,
    kQ3FileModeStream = 1 << 0,
    kQ3FileModeDatabase = 1 << 1,
    kQ3FileModeText = 1 << 2,
    /* Q3 extension (Quesa's name and value): a binary file in little-endian
     * byte order. OpenWrite writes one; OpenRead reports it for one. */
    kQ3FileModeSwap = 1 << 3
};
typedef enum TQ3FileModeMasks TQ3FileModeMasks;
typedef unsigned long TQ3FileMode;

#define Q3FileVersion(majorVersion, minorVersion)                                                  \
    (TQ3FileVersion)((((TQ3Uns32)(majorVersion)&0xFFFF) << 16) | ((TQ3Uns32)(minorVersion)&0xFFFF))
typedef unsigned long TQ3FileVersion;
#define kQ3FileVersionCurrent Q3FileVersion(1, 6)

/*
 * I/O methods of the classes an application registers (QD3DExtension.h's
 * Q3XObjectHierarchy_RegisterClass, QD3DSet.h's Q3XElementClass_Register and
 * Q3XAttributeClass_Register): how their objects and elements are written
 * to and read from 3DMF files. Each object is written under its class name
 * (a text file: `Name ( data )`; a binary file: a negative type that a Type
 * object ahead of the objects declares with the name), so a class is found
 * again by its name when the file is read by any program that registered
 * it. A file's object of a class nobody registered reads as an unknown
 * object (Q3UnknownBinary/Q3UnknownText) and is written back unchanged.
 *
 * Writing: when an object of the class (Q3Object_Submit in a writing loop,
 * or as a member of a group) or an element of the class (on a shape, an
 * object, a set or an attribute set being written) is written, Q3 calls the
 * class's traverse method: kQ3XMethodTypeObjectTraverse, or for an element
 * class kQ3XMethodTypeObjectTraverseData if it has one. The method decides
 * whether to write at all (returning kQ3Success without submitting anything
 * writes nothing), then calls Q3XView_SubmitWriteData once with the data
 * its write method will write, and may then submit subobjects: other
 * objects with Q3Object_Submit (or an immediate-mode call such as
 * Q3Triangle_Submit), data of a registered class with
 * Q3XView_SubmitSubObjectData. When the method has returned, Q3 writes the
 * object: the class's kQ3XMethodTypeObjectWrite method is called with the
 * data pointer and the file and writes the data with the primitive calls
 * below (Q3Uns32_Write, Q3String_Write, ...); then the subobjects follow,
 * the whole in a Container when there are any. Every delete method given
 * with the data is called once the object is written or has failed. A class
 * without a traverse method is left out of files with
 * kQ3WarningNoObjectSupportForWriteMethod.
 *
 * Reading: an object of a registered object class is made by its
 * kQ3XMethodTypeObjectRead method, an element by its element class's
 * kQ3XMethodTypeObjectReadData method. The method reads the object's data
 * with the primitive calls until Q3File_IsEndOfData is kQ3True, then, while
 * Q3File_IsEndOfContainer is kQ3False, its subobjects with
 * Q3File_ReadObject (or passes over them with Q3File_SkipObject). Past its
 * own object, Q3File_ReadObject fails with kQ3ErrorEndOfFile. A subobject
 * that is an object of a registered class with kQ3XMethodTypeObjectAttach,
 * in the container of an object whose reader does not take it, is read and
 * given to that method with the object it belongs to. Going through its
 * container, a read method gets an element of a registered element or
 * attribute class as a new set (kQ3SharedTypeSet) holding it; elements it
 * leaves unread there are its object's.
 *
 * kQ3XMethodTypeObjectFileVersion: the 3DMF version (a TQ3FileVersion,
 * Q3FileVersion(major, minor)) of the format the class's read and write
 * methods read and write, which the metahandler returns cast to a
 * TQ3XFunctionPointer, as it returns kQ3XMethodTypeObjectClassVersion (no
 * answer: the current version). A version newer than kQ3FileVersionCurrent,
 * which Q3's files cannot carry, fails the class's registration with
 * kQ3ErrorInvalidParameter.
 */
#define kQ3XMethodTypeObjectFileVersion Q3_METHOD_TYPE('v', 'e', 'r', 's')
#define kQ3XMethodTypeObjectTraverse Q3_METHOD_TYPE('t', 'r', 'v', 's')
#define kQ3XMethodTypeObjectTraverseData Q3_METHOD_TYPE('t', 'r', 'v', 'd')
#define kQ3XMethodTypeObjectWrite Q3_METHOD_TYPE('w', 'r', 'i', 't')
#define kQ3XMethodTypeObjectReadData Q3_METHOD_TYPE('r', 'd', 'd', 't')
#define kQ3XMethodTypeObjectRead Q3_METHOD_TYPE('r', 'e', 'a', 'd')
#define kQ3XMethodTypeObjectAttach Q3_METHOD_TYPE('a', 't', 't', 'c')

/*
 * TQ3XObjectTraverseMethod: object is the object being written and data its
 * instance data for the class (Q3XObjectClass_GetPrivate); for an element,
 * object is NULL and data the element's internal data. view is the writing
 * loop's view, to pass to Q3XView_SubmitWriteData and the submit calls.
 * Returning kQ3Failure fails the write (kQ3ErrorInvalidParameter; a
 * submitted object is then written whole or not at all).
 */
typedef TQ3Status (*TQ3XObjectTraverseMethod)(TQ3Object object, void *data, TQ3ViewObject view);
typedef TQ3Status (*TQ3XObjectTraverseDataMethod)(TQ3Object object, void *data, TQ3ViewObject view);

/*
 * TQ3XObjectWriteMethod: writes the data given to Q3XView_SubmitWriteData
 * (or Q3XView_SubmitSubObjectData) into theFile with the primitive write
 * calls. In a binary file it must write exactly the size given with the
 * data: more is kQ3ErrorWroteMoreThanSize, less kQ3ErrorWroteLessThanSize
 * (text files have no sizes). Returning kQ3Failure fails the write
 * (kQ3ErrorInvalidParameter).
 */
typedef TQ3Status (*TQ3XObjectWriteMethod)(const void *object, TQ3FileObject theFile);

/* TQ3XDataDeleteMethod: frees data given to the calls below, once written
 * (or once the write failed). */
typedef void (*TQ3XDataDeleteMethod)(void *data);

/*
 * Q3XView_SubmitWriteData: from a traverse method (above): the object's own
 * data, size bytes (binary files), which the class's write method writes;
 * deleteData (may be NULL) is called with data afterwards. size 0 writes an
 * object with no data and needs no write method.
 * Errors: kQ3ErrorWriteStateInactive outside a traverse method of a writing
 * loop on that view, or called twice in one; kQ3ErrorNeedRequiredMethods
 * for a size above 0 when the class has no write method (the object is
 * then not written). On failure deleteData is called all the same.
 */
Q3_EXTERN_API_C(TQ3Status) Q3XView_SubmitWriteData(TQ3ViewObject view, TQ3Size size, void *data,
                                                   TQ3XDataDeleteMethod deleteData);

/*
 * Q3XView_SubmitSubObjectData: from a traverse method, after
 * Q3XView_SubmitWriteData: a subobject of objectClass (a registered class:
 * objects of an object class, elements of an element class, are written by
 * that class's write method with data, as above).
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObjectClass (objectClass);
 * kQ3ErrorWriteStateInactive as above, or before Q3XView_SubmitWriteData;
 * kQ3ErrorNeedRequiredMethods as above. On failure deleteData is called.
 */
Q3_EXTERN_API_C(TQ3Status) Q3XView_SubmitSubObjectData(TQ3ViewObject view, TQ3XObjectClass objectClass,
                                                       unsigned long size, void *data,
                                                       TQ3XDataDeleteMethod deleteData);

/*
 * TQ3XObjectReadMethod: reads an object of the class from theFile (above)
 * and returns it with one reference for the caller, or NULL on failure
 * (Q3File_ReadObject then fails with kQ3ErrorInvalidMetafileObject). The
 * object must be a shared one.
 */
typedef TQ3Object (*TQ3XObjectReadMethod)(TQ3FileObject theFile);

/*
 * TQ3XObjectReadDataMethod: reads an element of the class from theFile and
 * adds it with Q3Set_Add to parentObject, a set whose elements Q3 then gives
 * to the object the element belongs to (its set, attribute set, shape or
 * group). kQ3Failure fails the read of that object
 * (kQ3ErrorInvalidMetafileObject).
 */
typedef TQ3Status (*TQ3XObjectReadDataMethod)(TQ3Object parentObject, TQ3FileObject theFile);

/*
 * TQ3XObjectAttachMethod: childObject, an object of the class read from the
 * container of parentObject (above), is to be attached to it. kQ3Failure
 * fails the read (kQ3ErrorInvalidMetafileObject). A subobject of a
 * registered class without one is left out with kQ3WarningNoAttachMethod.
 */
typedef TQ3Status (*TQ3XObjectAttachMethod)(TQ3Object childObject, TQ3Object parentObject);

/*
 * Q3File_New: a file object with no storage, closed.
 * Ownership: the caller holds the new file's one reference.
 */
Q3_EXTERN_API_C(TQ3FileObject) Q3File_New(void);

/*
 * Q3File_GetStorage: the file's storage, or NULL when it has none.
 * Ownership: a non-NULL *storage is a new reference for the caller.
 */
Q3_EXTERN_API_C(TQ3Status) Q3File_GetStorage(TQ3FileObject theFile, TQ3StorageObject *storage);

/*
 * Q3File_SetStorage: the storage the file reads and writes (NULL: none).
 * Errors: kQ3ErrorFileIsOpen while the file is open.
 * Ownership: the file keeps its own reference to the storage.
 */
Q3_EXTERN_API_C(TQ3Status) Q3File_SetStorage(TQ3FileObject theFile, TQ3StorageObject storage);

/*
 * Q3File_OpenRead: reads the storage's header and opens the file for
 * reading; *mode (may be NULL) is the file's mode, with kQ3FileModeText for a
 * text file and kQ3FileModeSwap for a little-endian binary one.
 * Errors: kQ3ErrorFileAlreadyOpen; kQ3ErrorNoStorageSetForFile;
 * kQ3ErrorInvalidMetafile and the other metafile errors for a file that is
 * not a 3DMF 1.x file (the file stays closed).
 */
Q3_EXTERN_API_C(TQ3Status) Q3File_OpenRead(TQ3FileObject theFile, TQ3FileMode *mode);

/*
 * Q3File_OpenWrite: opens the file for writing in `mode` (Normal, Stream or
 * Database, optionally with kQ3FileModeText or kQ3FileModeSwap). The storage
 * is written when the file is closed.
 * Errors: kQ3ErrorFileAlreadyOpen; kQ3ErrorNoStorageSetForFile;
 * kQ3ErrorInvalidParameter for a mode with other bits, both Stream and
 * Database, or both Text and Swap.
 */
Q3_EXTERN_API_C(TQ3Status) Q3File_OpenWrite(TQ3FileObject theFile, TQ3FileMode mode);

/* Q3File_IsOpen: *isOpen is kQ3True while the file is open. */
Q3_EXTERN_API_C(TQ3Status) Q3File_IsOpen(TQ3FileObject theFile, TQ3Boolean *isOpen);

/*
 * Q3File_GetMode: the open file's mode (as OpenRead gave it, or as given to
 * OpenWrite). Errors: kQ3ErrorFileNotOpen.
 */
Q3_EXTERN_API_C(TQ3Status) Q3File_GetMode(TQ3FileObject theFile, TQ3FileMode *mode);

/*
 * Q3File_GetVersion: the open file's version (kQ3FileVersionCurrent for a
 * file being written). Errors: kQ3ErrorFileNotOpen.
 */
Q3_EXTERN_API_C(TQ3Status) Q3File_GetVersion(TQ3FileObject theFile, TQ3FileVersion *version);

/*
 * Q3File_Close: closes the file; a file open for writing puts what was
 * written into its storage first.
 * Errors: kQ3ErrorFileNotOpen; kQ3ErrorFileNotOpen or kQ3ErrorOutOfMemory
 * when the storage cannot take the bytes (the file is closed all the same).
 */
Q3_EXTERN_API_C(TQ3Status) Q3File_Close(TQ3FileObject theFile);

/*
 * Q3File_Cancel: closes the file without writing anything to its storage.
 * Errors: kQ3ErrorFileNotOpen.
 */
Q3_EXTERN_API_C(TQ3Status) Q3File_Cancel(TQ3FileObject theFile);

/*
 * Q3View_StartWriting: starts a writing loop: every object submitted to the
 * view until Q3View_EndWriting is written to the file, retained objects and
 * immediate-mode geometries alike.
 * Errors: kQ3ErrorViewIsStarted inside another loop; kQ3ErrorFileNotOpen
 * unless the file is open for writing.
 */
Q3_EXTERN_API_C(TQ3Status) Q3View_StartWriting(TQ3ViewObject view, TQ3FileObject theFile);

/*
 * Q3View_EndWriting: ends the loop: kQ3ViewStatusDone (Q3 never asks for a
 * retraversal), kQ3ViewStatusCancelled after Q3View_Cancel (objects
 * submitted after the cancel were not written), kQ3ViewStatusError on
 * failure. The file is complete when it is closed.
 * Errors: kQ3ErrorWriteStateInactive outside a writing loop.
 */
Q3_EXTERN_API_C(TQ3ViewStatus) Q3View_EndWriting(TQ3ViewObject view);

/*
 * Q3File_GetNextObjectType: the type of the object Q3File_ReadObject would
 * read next: a class's type (kQ3GeometryTypeTriangle, ...),
 * kQ3SharedTypeEndGroup, kQ3ShapeTypeUnknown for a type Q3 does not know,
 * kQ3ObjectTypeInvalid at the end of the file.
 * Errors: kQ3ErrorFileNotOpen unless open for reading.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3File_GetNextObjectType(TQ3FileObject theFile);

/* Q3File_IsNextObjectOfType: whether the next object is of that type (or a
 * subclass of it). Errors: as Q3File_GetNextObjectType. */
Q3_EXTERN_API_C(TQ3Boolean) Q3File_IsNextObjectOfType(TQ3FileObject theFile, TQ3ObjectType ofType);

/*
 * Q3File_ReadObject: reads the next object; a BeginGroup reads the whole
 * group. An object Q3 cannot read is skipped: the call fails with the error
 * saying why and the next call reads the object after it.
 * Errors: kQ3ErrorFileNotOpen unless open for reading; kQ3ErrorEndOfFile at
 * the end; the metafile errors for a malformed object; the object's own
 * data errors (kQ3ErrorInvalidMetafileObject, naming the rule broken).
 * Ownership: the caller holds one reference to the object.
 */
Q3_EXTERN_API_C(TQ3Object) Q3File_ReadObject(TQ3FileObject theFile);

/*
 * Q3File_SkipObject: passes over the next object (a BeginGroup: the whole
 * group). Errors: as Q3File_ReadObject, kQ3ErrorEndOfFile at the end.
 */
Q3_EXTERN_API_C(TQ3Status) Q3File_SkipObject(TQ3FileObject theFile);

/* Q3File_IsEndOfFile: kQ3True when no object is left to read, and for a
 * file that is not open for reading. */
Q3_EXTERN_API_C(TQ3Boolean) Q3File_IsEndOfFile(TQ3FileObject theFile);

/*
 * External references (QuickDraw 3D 1.5): an object of another metafile,
 * written as
 *     Container ( ExternalReference ( refID ) CString ( "path" ) )
 * where refID is the object's entry in that file's table of contents.
 * Reading one reads the object from that file (a relative path starts at the
 * directory of the file being read when that is a Unix path storage); a file
 * that cannot be read, an ID its table of contents lacks, or a chain of
 * external references back to a file being read is
 * kQ3ErrorInvalidMetafileObject and the read returns NULL.
 *
 * Q3File_MarkAsExternalReference: theFile is open for reading on a Unix path
 * storage and sharedObject was read from it as an object its table of
 * contents lists (a Database file, or an object referred to twice). From now
 * on, until theFile is disposed of, every write of sharedObject, to any
 * file, is an external reference to it. Errors: kQ3ErrorFileNotOpen (not open
 * for reading), kQ3ErrorInvalidParameter (not a Unix path storage, or an
 * object not read from theFile with a table of contents entry).
 * Ownership: theFile holds a reference to sharedObject until it is disposed
 * of.
 */
Q3_EXTERN_API_C(TQ3Status) Q3File_MarkAsExternalReference(TQ3FileObject theFile, TQ3SharedObject sharedObject);

/*
 * Q3File_GetExternalReferences: a group holding one C string object
 * (QD3DString.h) per external reference in the open file, in file order,
 * each the path as written (so a path may appear more than once); NULL with
 * no error when there are none. Errors: kQ3ErrorFileNotOpen (not open for
 * reading). Ownership: the caller holds the group's one reference.
 */
Q3_EXTERN_API_C(TQ3GroupObject) Q3File_GetExternalReferences(TQ3FileObject theFile);

/*
 * Edit tracking (Apple's "tracking editing in read-in objects"): a flag on
 * every shared object that each edit sets (everything that changes its edit
 * index, Q3Shared_Edited included) and Q3Shared_ClearEditTracking clears. A
 * new object starts with the flag clear; an object read from a file may
 * have been edited while it was built, so clear the flag after reading and
 * ask later whether anything changed it since.
 */

/**
 * Clears the edit-tracking flag of a shared object. Its edit index does not
 * change.
 *
 * @param sharedObject  the object.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      sharedObject is NULL.
 *   kQ3ErrorInvalidObject      sharedObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  sharedObject is not a shared object.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Shared_ClearEditTracking(TQ3SharedObject sharedObject);

/**
 * Reports whether a shared object was edited since its edit-tracking flag
 * was last cleared (or since it was made).
 *
 * @param sharedObject  the object.
 * @return kQ3True when edited, kQ3False when not or on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      sharedObject is NULL.
 *   kQ3ErrorInvalidObject      sharedObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  sharedObject is not a shared object.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Boolean) Q3Shared_GetEditTrackingState(TQ3SharedObject sharedObject);

/*
 * Q3File_IsEndOfData: whether the data the primitive read calls (Q3Uns32_Read
 * and the others below) read is all read. Primitive reads read one object's
 * data in order: the first one starts on the next object of the file (for a
 * container, on its root object's data), which Q3File_ReadObject will then
 * not read again. Before the first primitive read it tells whether the next
 * object has no data (a group, a reference or an empty object). kQ3True at
 * the end of the file and for a file not open for reading.
 */
Q3_EXTERN_API_C(TQ3Boolean) Q3File_IsEndOfData(TQ3FileObject theFile);

/*
 * Q3File_IsEndOfContainer: kQ3False while the container primitive reads
 * started on has subobjects left: Q3File_GetNextObjectType,
 * Q3File_IsNextObjectOfType, Q3File_ReadObject and Q3File_SkipObject then go
 * through them, one at a time. kQ3True otherwise (a plain object, a file not
 * open for reading). rootObject is Apple's parameter; Q3 does not need it and
 * accepts any value, NULL included.
 */
Q3_EXTERN_API_C(TQ3Boolean) Q3File_IsEndOfContainer(TQ3FileObject theFile, TQ3Object rootObject);

enum TQ3FileReadGroupStateMasks {
    kQ3FileReadWholeGroup = 0,
    kQ3FileReadObjectsInGroup = 1 << 0,
    kQ3FileCurrentlyInsideGroup = 1 << 1
};
typedef enum TQ3FileReadGroupStateMasks TQ3FileReadGroupStateMasks;
typedef unsigned long TQ3FileReadGroupState;

/*
 * Q3File_SetReadInGroup: how Q3File_ReadObject reads groups from now on:
 * kQ3FileReadWholeGroup (the default: one call reads a group and everything
 * in it) or kQ3FileReadObjectsInGroup (a call reads the group itself, empty;
 * each later call one object of it; the last one returns an object of type
 * kQ3SharedTypeEndGroup). Groups already being read one object at a time
 * finish that way.
 * Errors: kQ3ErrorInvalidParameter for any other value.
 */
Q3_EXTERN_API_C(TQ3Status) Q3File_SetReadInGroup(TQ3FileObject theFile, TQ3FileReadGroupState readGroupState);

/*
 * Q3File_GetReadInGroup: the mode, with kQ3FileCurrentlyInsideGroup added
 * while a group read one object at a time has not reached its end.
 */
Q3_EXTERN_API_C(TQ3Status) Q3File_GetReadInGroup(TQ3FileObject theFile, TQ3FileReadGroupState *readGroupState);

typedef TQ3Status (*TQ3FileIdleMethod)(TQ3FileObject theFile, const void *idlerData);

/*
 * Q3File_SetIdleMethod: `idle` (NULL: none) is called with idleData before
 * each object Q3File_ReadObject or Q3File_SkipObject reads and before each
 * object a writing loop writes. When it returns kQ3Failure the operation is
 * cancelled: the read fails with kQ3ErrorFileCancelled and reads nothing
 * (the next call tries again); a writing loop writes nothing more and
 * Q3View_EndWriting returns kQ3ViewStatusCancelled (what was written before
 * stays in the file). The method must not call Q3 (as in QuickDraw 3D).
 */
Q3_EXTERN_API_C(TQ3Status) Q3File_SetIdleMethod(TQ3FileObject theFile, TQ3FileIdleMethod idle, const void *idleData);

/*
 * Primitive reads and writes, for reading and writing data by hand.
 *
 * Reading: each call reads the next value of the data Q3File_IsEndOfData
 * describes, in the file's encoding and byte order, into *data (unchanged on
 * failure, and the position with it).
 * Errors (besides the shared ones, a NULL data included):
 *   kQ3ErrorReadStateInactive  the file is not open for reading;
 *   kQ3ErrorEndOfFile          no object is left to read data from;
 *   kQ3ErrorInvalidMetafileObject  the next object has no data of its own
 *                              (a group, a reference);
 *   kQ3ErrorReadMoreThanSize   the object's data end before the value;
 *   kQ3ErrorInvalidMetafilePrimitive  a malformed value (a word for a
 *                              number, a number out of range, a NaN).
 *
 * Writing: each call writes the value into the file at the point writing has
 * reached (after the objects written so far), in the file's encoding: binary
 * values as the file's byte order has them, text values as words. Errors:
 * kQ3ErrorWriteStateInactive unless the file is open for writing.
 *
 * In text, integers are decimal words, floats the shortest words that read
 * back as the same value, strings quoted ("a \"b\""), raw data one word of
 * 0x and two hex digits a byte. In binary, strings end with a NUL and are
 * padded with zeros to a multiple of 4 bytes, and so is raw data.
 */
Q3_EXTERN_API_C(TQ3Status) Q3NewLine_Write(TQ3FileObject theFile); /* text: a line break; binary: nothing */
Q3_EXTERN_API_C(TQ3Status) Q3Uns8_Read(TQ3Uns8 *data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Uns8_Write(TQ3Uns8 data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Uns16_Read(TQ3Uns16 *data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Uns16_Write(TQ3Uns16 data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Uns32_Read(TQ3Uns32 *data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Uns32_Write(TQ3Uns32 data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Int8_Read(TQ3Int8 *data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Int8_Write(TQ3Int8 data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Int16_Read(TQ3Int16 *data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Int16_Write(TQ3Int16 data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Int32_Read(TQ3Int32 *data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Int32_Write(TQ3Int32 data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Uns64_Read(TQ3Uns64 *data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Uns64_Write(TQ3Uns64 data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Int64_Read(TQ3Int64 *data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Int64_Write(TQ3Int64 data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Float32_Read(TQ3Float32 *data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Float32_Write(TQ3Float32 data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Float64_Read(TQ3Float64 *data, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Float64_Write(TQ3Float64 data, TQ3FileObject theFile);

/* Q3Size_Pad: size rounded up to a multiple of 4 (binary strings and raw
 * data take that many bytes). */
Q3_EXTERN_API_C(TQ3Size) Q3Size_Pad(TQ3Size size);

/*
 * Q3String_Read: reads a string into data, a buffer of
 * kQ3StringMaximumLength bytes: a longer string is cut to
 * kQ3StringMaximumLength - 1 characters and NUL-terminated; *length is the
 * length copied. With data NULL (Quesa's extension) *length is the string's
 * whole length and nothing is read. Errors: as the other reads; a NULL length.
 */
Q3_EXTERN_API_C(TQ3Status) Q3String_Read(char *data, unsigned long *length, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3String_Write(const char *data, TQ3FileObject theFile);

/* Q3RawData_Read / Q3RawData_Write: size bytes (binary: Q3Size_Pad(size)
 * bytes in the file). */
Q3_EXTERN_API_C(TQ3Status) Q3RawData_Read(unsigned char *data, unsigned long size, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3RawData_Write(const unsigned char *data, unsigned long size, TQ3FileObject theFile);

/*
 * Q3 extension (Quesa's names and signatures): Q3Uns8_ReadArray,
 * Q3Uns16_ReadArray, Q3Uns32_ReadArray and Q3Float32_ReadArray read numNums
 * values into the array in one call, as that many Q3Uns8_Read (...) calls
 * would, for a custom class's read method reading a block of points or
 * indices. All or nothing: when the data cannot hold them all
 * (kQ3ErrorReadMoreThanSize) or one is malformed, the array and the
 * position are unchanged. numNums 0 reads nothing (the array may then be
 * NULL). Errors: as the reads above; kQ3ErrorNULLParameter for a NULL array
 * with numNums above 0.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Uns8_ReadArray(TQ3Uns32 numNums, TQ3Uns8 *intArray, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Uns16_ReadArray(TQ3Uns32 numNums, TQ3Uns16 *intArray, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Uns32_ReadArray(TQ3Uns32 numNums, TQ3Uns32 *intArray, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Float32_ReadArray(TQ3Uns32 numFloats, TQ3Float32 *floatArray, TQ3FileObject theFile);

Q3_EXTERN_API_C(TQ3Status) Q3Point2D_Read(TQ3Point2D *point2D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Point2D_Write(const TQ3Point2D *point2D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Point3D_Read(TQ3Point3D *point3D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Point3D_Write(const TQ3Point3D *point3D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3RationalPoint3D_Read(TQ3RationalPoint3D *point3D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3RationalPoint3D_Write(const TQ3RationalPoint3D *point3D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3RationalPoint4D_Read(TQ3RationalPoint4D *point4D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3RationalPoint4D_Write(const TQ3RationalPoint4D *point4D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Vector2D_Read(TQ3Vector2D *vector2D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Vector2D_Write(const TQ3Vector2D *vector2D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Vector3D_Read(TQ3Vector3D *vector3D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Vector3D_Write(const TQ3Vector3D *vector3D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Matrix4x4_Read(TQ3Matrix4x4 *matrix4x4, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Matrix4x4_Write(const TQ3Matrix4x4 *matrix4x4, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Tangent2D_Read(TQ3Tangent2D *tangent2D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Tangent2D_Write(const TQ3Tangent2D *tangent2D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Tangent3D_Read(TQ3Tangent3D *tangent3D, TQ3FileObject theFile);
Q3_EXTERN_API_C(TQ3Status) Q3Tangent3D_Write(const TQ3Tangent3D *tangent3D, TQ3FileObject theFile);

/* Q3Comment_Write: text: the comment on a line of its own (`# comment`, line
 * breaks in it made spaces); binary: nothing (as in QuickDraw 3D). */
Q3_EXTERN_API_C(TQ3Status) Q3Comment_Write(char *comment, TQ3FileObject theFile);

/*
 * Q3Unknown_GetType: kQ3UnknownTypeText or kQ3UnknownTypeBinary.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Unknown_GetType(TQ3UnknownObject unknownObject);

/*
 * Q3Unknown_GetDirtyState / Q3Unknown_SetDirtyState: a flag the application
 * keeps on the object (kQ3False when read).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Unknown_GetDirtyState(TQ3UnknownObject unknownObject, TQ3Boolean *isDirty);
Q3_EXTERN_API_C(TQ3Status) Q3Unknown_SetDirtyState(TQ3UnknownObject unknownObject, TQ3Boolean isDirty);

typedef struct TQ3UnknownTextData {
    char *objectName; /* '\0' terminated */
    char *contents;   /* '\0' terminated */
} TQ3UnknownTextData;

/*
 * Q3UnknownText_GetData: copies of an unknown text object's name and
 * contents (the tokens between its parentheses, separated by spaces).
 * Errors: kQ3ErrorInvalidObjectType for an unknown binary object.
 * Ownership: release the copies with Q3UnknownText_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3UnknownText_GetData(TQ3UnknownObject unknownObject, TQ3UnknownTextData *unknownTextData);

/* Q3UnknownText_EmptyData: frees what GetData copied, and NULLs the fields. */
Q3_EXTERN_API_C(TQ3Status) Q3UnknownText_EmptyData(TQ3UnknownTextData *unknownTextData);

typedef struct TQ3UnknownBinaryData {
    TQ3ObjectType objectType;
    unsigned long size;
    TQ3Endian byteOrder;
    char *contents;
} TQ3UnknownBinaryData;

/*
 * Q3UnknownBinary_GetData: an unknown binary object's type, size, the byte
 * order of the file it came from and a copy of its data (NULL when size is
 * 0). Errors: kQ3ErrorInvalidObjectType for an unknown text object.
 * Ownership: release the copy with Q3UnknownBinary_EmptyData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3UnknownBinary_GetData(TQ3UnknownObject unknownObject,
                                                   TQ3UnknownBinaryData *unknownBinaryData);

/* Q3UnknownBinary_EmptyData: frees what GetData copied, and NULLs contents. */
Q3_EXTERN_API_C(TQ3Status) Q3UnknownBinary_EmptyData(TQ3UnknownBinaryData *unknownBinaryData);

/**
 * Gives the type name a 3D Metafile declared for an unknown binary object's
 * type in its type table ('type' objects, which name the negative type
 * codes of custom classes): the name of a class no one registered, which
 * writing the object declares again. *typeString is NULL for any other type
 * (no declared name).
 *
 * @param unknownObject  an unknown binary object.
 * @param typeString     receives the name, or NULL.
 * @return kQ3Success, or kQ3Failure with *typeString unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      unknownObject or typeString is NULL.
 *   kQ3ErrorInvalidObject      unknownObject is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  unknownObject is not an unknown binary object.
 *
 * Ownership: a non-NULL *typeString is the caller's, to free with
 * Q3UnknownBinary_EmptyTypeString.
 */
Q3_EXTERN_API_C(TQ3Status) Q3UnknownBinary_GetTypeString(TQ3UnknownObject unknownObject, char **typeString);

/**
 * Frees a string Q3UnknownBinary_GetTypeString gave and sets *typeString to
 * NULL; a NULL *typeString is left alone.
 *
 * @param typeString  the string to free.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   typeString is NULL.
 *
 * Ownership: consumes *typeString.
 */
Q3_EXTERN_API_C(TQ3Status) Q3UnknownBinary_EmptyTypeString(char **typeString);

/*
 * View hints (Apple's QD3DIO.h, "ViewHints routines"): a shared object a
 * metafile carries to suggest how to draw its model: a renderer, a camera, a
 * light group, an attribute set, the image's dimensions, a mask and how to
 * clear the image. A reader may configure its view from them or ignore them.
 * To write one, make it from a view (Q3ViewHints_New) and submit it in a
 * writing loop, before the model. 3DMF form: a ViewHints container, in
 * docs/3dmf.md.
 *
 * Fields of a new view hints object when the view lacks the part they come
 * from: no renderer, camera, light group; dimensions state kQ3False with
 * 0 x 0; mask state kQ3False with an empty mask (image NULL, fields 0); clear
 * method kQ3ClearMethodNone with colour (a 1, r 0, g 0, b 0).
 *
 * Get calls of objects return a new reference (release it with
 * Q3Object_Dispose), or NULL when the hints hold none; Set calls keep a
 * reference to the object passed, which is shared, not copied.
 *
 * Errors besides the shared ones above are listed with each call. A call
 * that fails leaves the hints as they were.
 */

/*
 * Q3ViewHints_New: hints holding the view's configuration: its renderer,
 * camera and light group (shared), its default attribute set
 * (Q3View_GetDefaultAttributeSet), and from its draw context the clear
 * method and colour, the mask state and a copy of the mask (when it is a
 * valid bitmap), and the size drawn into, as dimensions with the state
 * kQ3True: the pane's extent in whole pixels when the pane state is on, else
 * the pixmap's width and height.
 * Ownership: the caller holds the one reference.
 */
Q3_EXTERN_API_C(TQ3ViewHintsObject) Q3ViewHints_New(TQ3ViewObject view);

/* Q3ViewHints_SetRenderer / GetRenderer: the renderer suggested. */
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_SetRenderer(TQ3ViewHintsObject viewHints, TQ3RendererObject renderer);
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_GetRenderer(TQ3ViewHintsObject viewHints, TQ3RendererObject *renderer);

/* Q3ViewHints_SetCamera / GetCamera: the camera suggested. */
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_SetCamera(TQ3ViewHintsObject viewHints, TQ3CameraObject camera);
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_GetCamera(TQ3ViewHintsObject viewHints, TQ3CameraObject *camera);

/*
 * Q3ViewHints_SetLightGroup / GetLightGroup: the lights suggested, a light
 * group (Q3LightGroup_New); NULL removes them, as for Q3View_SetLightGroup.
 * Errors: kQ3ErrorInvalidObjectType for a group that is not a light group.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_SetLightGroup(TQ3ViewHintsObject viewHints, TQ3GroupObject lightGroup);
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_GetLightGroup(TQ3ViewHintsObject viewHints, TQ3GroupObject *lightGroup);

/*
 * Q3ViewHints_SetAttributeSet / GetAttributeSet: the view attributes
 * suggested; NULL removes them.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_SetAttributeSet(TQ3ViewHintsObject viewHints, TQ3AttributeSet attributeSet);
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_GetAttributeSet(TQ3ViewHintsObject viewHints, TQ3AttributeSet *attributeSet);

/*
 * Q3ViewHints_SetDimensionsState / GetDimensionsState: whether the
 * dimensions are meant (any nonzero value is kQ3True).
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_SetDimensionsState(TQ3ViewHintsObject viewHints, TQ3Boolean isValid);
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_GetDimensionsState(TQ3ViewHintsObject viewHints, TQ3Boolean *isValid);

/*
 * Q3ViewHints_SetDimensions / GetDimensions: the image's preferred width and
 * height in pixels. Setting them does not change the dimensions state.
 * Errors: kQ3ErrorInvalidParameter for 0 or more than 0xFFFFFFFF (the
 * file's Uns32).
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_SetDimensions(TQ3ViewHintsObject viewHints, unsigned long width,
                                                     unsigned long height);
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_GetDimensions(TQ3ViewHintsObject viewHints, unsigned long *width,
                                                     unsigned long *height);

/*
 * Q3ViewHints_SetMaskState / GetMaskState: whether the mask is meant (any
 * nonzero value is kQ3True).
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_SetMaskState(TQ3ViewHintsObject viewHints, TQ3Boolean isValid);
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_GetMaskState(TQ3ViewHintsObject viewHints, TQ3Boolean *isValid);

/*
 * Q3ViewHints_SetMask: copies a bitmap as the mask (a set bit draws the
 * pixel). Setting it does not change the mask state.
 * Errors: as Q3Marker_SetBitmap: kQ3ErrorNULLParameter for a NULL image,
 * kQ3ErrorInvalidData for a 0 width or height, rowBytes too small for the
 * width or a bitOrder that is not a TQ3Endian; kQ3ErrorParameterOutOfRange
 * for an image of more than kQ3GeometryMaxArrayCount bytes.
 *
 * Q3ViewHints_GetMask: a copy of the mask; all zero (image NULL) when none
 * was set.
 * Ownership: call Q3Bitmap_Empty when done with the mask.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_SetMask(TQ3ViewHintsObject viewHints, const TQ3Bitmap *mask);
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_GetMask(TQ3ViewHintsObject viewHints, TQ3Bitmap *mask);

/*
 * Q3ViewHints_SetClearImageMethod / GetClearImageMethod: how the image is
 * cleared. Errors: kQ3ErrorInvalidParameter for a value that is neither
 * kQ3ClearMethodNone nor kQ3ClearMethodWithColor.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_SetClearImageMethod(TQ3ViewHintsObject viewHints,
                                                           TQ3DrawContextClearImageMethod clearMethod);
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_GetClearImageMethod(TQ3ViewHintsObject viewHints,
                                                           TQ3DrawContextClearImageMethod *clearMethod);

/*
 * Q3ViewHints_SetClearImageColor / GetClearImageColor: the colour the image
 * is cleared with. Setting it does not change the clear method.
 * Errors: kQ3ErrorInvalidParameter for a non-finite component.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_SetClearImageColor(TQ3ViewHintsObject viewHints, const TQ3ColorARGB *color);
Q3_EXTERN_API_C(TQ3Status) Q3ViewHints_GetClearImageColor(TQ3ViewHintsObject viewHints, TQ3ColorARGB *color);

#ifdef __cplusplus
}
#endif

#endif /* QD3DIO_H */
