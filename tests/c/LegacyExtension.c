/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* QuickDraw 3D 1.6 plug-in style C: a custom element class with its own copy
 * methods in a set, a custom shape class with instance data, and Apple's
 * name element on a box, through QD3DExtension.h, QD3DSet.h and
 * QD3DCustomElements.h only. */
#include "QD3D.h"
#include "QD3DCustomElements.h"
#include "QD3DErrors.h"
#include "QD3DExtension.h"
#include "QD3DGeometry.h"
#include "QD3DSet.h"

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

static TQ3XFunctionPointer MyShape_MetaHandler(TQ3XMethodType methodType)
{
    switch (methodType) {
    case kQ3XMethodTypeObjectNew:
        return (TQ3XFunctionPointer)MyShape_New;
    case kQ3XMethodTypeObjectClassVersion:
        return (TQ3XFunctionPointer)Q3_OBJECT_CLASS_VERSION(1, 2);
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
    TQ3Object shape;
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
