/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* QuickDraw 3D 1.6 plug-in style C: a custom element class with its own copy
 * methods in a set, a custom shape class with instance data that writes
 * itself to a 3DMF file and reads itself back (QD3DIO.h's traverse, write
 * and read methods), and Apple's name element on a box, through
 * QD3DExtension.h, QD3DSet.h, QD3DIO.h and QD3DCustomElements.h only. */
#include "QD3D.h"
#include "QD3DCustomElements.h"
#include "QD3DErrors.h"
#include "QD3DExtension.h"
#include "QD3DGeometry.h"
#include "QD3DIO.h"
#include "QD3DSet.h"
#include "QD3DStorage.h"

#include <stdio.h>
#include <string.h>

typedef struct MyTag {
    long serial;
} MyTag;

static int gDeleted = 0;

static TQ3Status MyTag_CopyAdd(const void *from, void *to)
{
    ((MyTag *)to)->serial = *(const long *)from + 100;
    return kQ3Success;
}

static TQ3Status MyTag_CopyGet(const void *from, void *to)
{
    *(long *)to = ((const MyTag *)from)->serial;
    return kQ3Success;
}

static TQ3Status MyTag_Delete(void *element)
{
    (void)element;
    ++gDeleted;
    return kQ3Success;
}

static TQ3XFunctionPointer MyTag_MetaHandler(TQ3XMethodType methodType)
{
    switch (methodType) {
    case kQ3XMethodTypeElementCopyAdd:
        return (TQ3XFunctionPointer)MyTag_CopyAdd;
    case kQ3XMethodTypeElementCopyGet:
        return (TQ3XFunctionPointer)MyTag_CopyGet;
    case kQ3XMethodTypeElementDelete:
        return (TQ3XFunctionPointer)MyTag_Delete;
    default:
        return NULL;
    }
}

typedef struct MyShapePrivate {
    float weight;
} MyShapePrivate;

static TQ3Status MyShape_New(TQ3Object object, void *privateData, void *parameters)
{
    (void)object;
    ((MyShapePrivate *)privateData)->weight = parameters ? *(float *)parameters : 1.0f;
    return kQ3Success;
}

static TQ3XObjectClass gShapeClass = NULL;

static TQ3Status MyShape_Traverse(TQ3Object object, void *data, TQ3ViewObject view)
{
    (void)object;
    return Q3XView_SubmitWriteData(view, sizeof(TQ3Float32), data, NULL);
}

static TQ3Status MyShape_Write(const void *data, TQ3FileObject file)
{
    return Q3Float32_Write(((const MyShapePrivate *)data)->weight, file);
}

static TQ3Object MyShape_Read(TQ3FileObject file)
{
    float weight = 0.0f;
    if (Q3Float32_Read(&weight, file) != kQ3Success)
        return NULL;
    return Q3XObjectHierarchy_NewObject(gShapeClass, &weight);
}

static TQ3XFunctionPointer MyShape_MetaHandler(TQ3XMethodType methodType)
{
    switch (methodType) {
    case kQ3XMethodTypeObjectNew:
        return (TQ3XFunctionPointer)MyShape_New;
    case kQ3XMethodTypeObjectTraverse:
        return (TQ3XFunctionPointer)MyShape_Traverse;
    case kQ3XMethodTypeObjectWrite:
        return (TQ3XFunctionPointer)MyShape_Write;
    case kQ3XMethodTypeObjectRead:
        return (TQ3XFunctionPointer)MyShape_Read;
    case kQ3XMethodTypeObjectClassVersion:
        return (TQ3XFunctionPointer)Q3_OBJECT_CLASS_VERSION(1, 2);
    case kQ3XMethodTypeObjectFileVersion:
        return (TQ3XFunctionPointer)kQ3FileVersionCurrent;
    default:
        return NULL;
    }
}

int main(void)
{
    TQ3ElementType tagType = 0;
    TQ3XObjectClass tagClass, shapeClass;
    TQ3ObjectType shapeType = 0;
    TQ3SetObject set;
    TQ3GeometryObject box;
    TQ3BoxData boxData;
    TQ3Object shape, readBack = NULL;
    TQ3StorageObject storage;
    TQ3FileObject file;
    TQ3ViewObject view;
    TQ3FileMode mode = 0;
    MyShapePrivate *shapeData;
    TQ3XObjectClassVersion version = 0;
    char shapeName[] = "Legacy Corp.:Weight";
    char *name = NULL;
    long serial = 7, back = 0;
    float weight = 2.5f;
    int ok = 1;

    if (Q3Initialize() != kQ3Success)
        return 1;

    tagClass = Q3XElementClass_Register(&tagType, "Legacy Corp.:Tag", sizeof(MyTag), MyTag_MetaHandler);
    ok = ok && tagClass != NULL;
    set = Q3Set_New();
    ok = ok && Q3Set_Add(set, tagType, &serial) == kQ3Success;
    ok = ok && Q3Set_Get(set, tagType, &back) == kQ3Success && back == 107;
    Q3Object_Dispose(set);
    ok = ok && gDeleted == 1;
    ok = ok && Q3XObjectHierarchy_UnregisterClass(tagClass) == kQ3Success;

    shapeClass = Q3XObjectHierarchy_RegisterClass(kQ3SharedTypeShape, &shapeType, shapeName, MyShape_MetaHandler,
                                                  NULL, 0, sizeof(MyShapePrivate));
    ok = ok && shapeClass != NULL && Q3XObjectClass_GetLeafType(shapeClass) == shapeType;
    ok = ok && Q3XObjectHierarchy_GetClassVersion(shapeType, &version) == kQ3Success &&
         Q3_OBJECT_CLASS_GET_MINOR_VERSION(version) == 2;
    shape = Q3XObjectHierarchy_NewObject(shapeClass, &weight);
    shapeData = (MyShapePrivate *)Q3XObjectClass_GetPrivate(shapeClass, shape);
    ok = ok && shapeData != NULL && shapeData->weight == 2.5f;
    ok = ok && Q3Object_IsType(shape, kQ3SharedTypeShape) == kQ3True;
    gShapeClass = shapeClass;

    /* Write the shape to a text file in memory and read it back. */
    storage = Q3MemoryStorage_New(NULL, 0);
    file = Q3File_New();
    view = Q3View_New();
    ok = ok && Q3File_SetStorage(file, storage) == kQ3Success;
    ok = ok && Q3File_OpenWrite(file, kQ3FileModeText) == kQ3Success;
    ok = ok && Q3View_StartWriting(view, file) == kQ3Success;
    ok = ok && Q3Object_Submit(shape, view) == kQ3Success;
    ok = ok && Q3View_EndWriting(view) == kQ3ViewStatusDone;
    ok = ok && Q3File_Close(file) == kQ3Success;
    ok = ok && Q3File_OpenRead(file, &mode) == kQ3Success && (mode & kQ3FileModeText) != 0;
    if (ok)
        readBack = Q3File_ReadObject(file);
    ok = ok && readBack != NULL && Q3Object_GetLeafType(readBack) == shapeType;
    if (readBack != NULL) {
        shapeData = (MyShapePrivate *)Q3XObjectClass_GetPrivate(shapeClass, readBack);
        ok = ok && shapeData != NULL && shapeData->weight == 2.5f;
        Q3Object_Dispose(readBack);
    }
    Q3File_Close(file);
    Q3Object_Dispose(view);
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
    Q3Object_Dispose(shape);
    ok = ok && Q3XObjectHierarchy_UnregisterClass(shapeClass) == kQ3Success;

    memset(&boxData, 0, sizeof boxData);
    boxData.orientation.x = 1.0f;
    boxData.majorAxis.y = 1.0f;
    boxData.minorAxis.z = 1.0f;
    box = Q3Box_New(&boxData);
    ok = ok && CENameElement_SetData(box, "legacy box") == kQ3Success;
    ok = ok && CENameElement_GetData(box, &name) == kQ3Success && name != NULL && strcmp(name, "legacy box") == 0;
    CENameElement_EmptyData(&name);
    Q3Object_Dispose(box);

    Q3XError_Post(kQ3ErrorOutOfMemory);
    ok = ok && Q3Error_Get(NULL) == kQ3ErrorOutOfMemory;

    Q3Exit();
    if (!ok) {
        fprintf(stderr, "LegacyExtension: a check failed\n");
        return 1;
    }
    return 0;
}
