// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// QD3DExtension.h: object classes an application registers, their methods
// (new, delete, duplicate, register, unregister, version), their instance
// data, their place in the class hierarchy, and bad input; posting errors
// from extensions; shared library registration.

#include "OwningApiTest.h"

#include "QD3DExtension.h"
#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DStorage.h"
#include "QD3DString.h"
#include "FileTestSupport.h"

#include <cstdint>
#include <cstring>

namespace {

using namespace q3test;

// A shape class keeping a number and a reference to a sub-object.
struct Counted {
    int value;
    TQ3Object sub;
};

struct Calls {
    int registered = 0, unregistered = 0, made = 0, deleted = 0, duplicated = 0;
    bool failNew = false;
};
Calls g_calls;

TQ3Status countedRegister(TQ3XObjectClass, void*)
{
    ++g_calls.registered;
    return kQ3Success;
}

void countedUnregister(TQ3XObjectClass, void*)
{
    ++g_calls.unregistered;
}

TQ3Status countedNew(TQ3Object, void* privateData, void* parameters)
{
    ++g_calls.made;
    if (g_calls.failNew)
        return kQ3Failure;
    auto* data = static_cast<Counted*>(privateData);
    data->value = parameters == nullptr ? 0 : *static_cast<const int*>(parameters);
    data->sub = Q3CString_New("sub-object");
    return data->sub != nullptr ? kQ3Success : kQ3Failure;
}

void countedDelete(TQ3Object, void* privateData)
{
    ++g_calls.deleted;
    auto* data = static_cast<Counted*>(privateData);
    if (data->sub != nullptr)
        Q3Object_Dispose(data->sub);
}

TQ3Status countedDuplicate(TQ3Object, const void* fromPrivate, TQ3Object, const void* toPrivate)
{
    ++g_calls.duplicated;
    const auto* from = static_cast<const Counted*>(fromPrivate);
    auto* to = static_cast<Counted*>(const_cast<void*>(toPrivate));
    to->value = from->value + 1000;
    to->sub = Q3Shared_GetReference(from->sub);
    return kQ3Success;
}

TQ3XFunctionPointer countedMetaHandler(TQ3XMethodType type)
{
    switch (type) {
    case kQ3XMethodTypeObjectClassVersion:
        return reinterpret_cast<TQ3XFunctionPointer>(static_cast<std::uintptr_t>(Q3_OBJECT_CLASS_VERSION(2, 3)));
    case kQ3XMethodTypeObjectClassRegister:
        return reinterpret_cast<TQ3XFunctionPointer>(countedRegister);
    case kQ3XMethodTypeObjectClassUnregister:
        return reinterpret_cast<TQ3XFunctionPointer>(countedUnregister);
    case kQ3XMethodTypeObjectNew:
        return reinterpret_cast<TQ3XFunctionPointer>(countedNew);
    case kQ3XMethodTypeObjectDelete:
        return reinterpret_cast<TQ3XFunctionPointer>(countedDelete);
    case kQ3XMethodTypeObjectDuplicate:
        return reinterpret_cast<TQ3XFunctionPointer>(countedDuplicate);
    case kQ3XMethodTypeObjectIsDrawable:
        return reinterpret_cast<TQ3XFunctionPointer>(static_cast<std::uintptr_t>(kQ3True));
    default:
        return nullptr;
    }
}

class ExtensionApiTest : public OwningApiTest {
protected:
    void SetUp() override
    {
        OwningApiTest::SetUp();
        g_calls = Calls{};
    }
    TQ3XObjectClass registerCounted(TQ3ObjectType parent, const char* name, TQ3ObjectType* type)
    {
        char buffer[kQ3StringMaximumLength];
        std::strcpy(buffer, name);
        return Q3XObjectHierarchy_RegisterClass(parent, type, buffer, countedMetaHandler, nullptr, 0,
                                                sizeof(Counted));
    }
};

TEST_F(ExtensionApiTest, ARegisteredShapeClassJoinsTheHierarchy)
{
    TQ3ObjectType type = 0;
    TQ3XObjectClass shapeClass = registerCounted(kQ3SharedTypeShape, "Test:CountedShape", &type);
    ASSERT_NE(shapeClass, nullptr);
    EXPECT_EQ(g_calls.registered, 1);
    EXPECT_NE(type, 0);
    EXPECT_EQ(Q3XObjectClass_GetLeafType(shapeClass), type);
    TQ3ObjectType again = 0;
    EXPECT_EQ(Q3XObjectClass_GetType(shapeClass, &again), kQ3Success);
    EXPECT_EQ(again, type);
    EXPECT_EQ(Q3XObjectHierarchy_FindClassByType(type), shapeClass);
    EXPECT_EQ(Q3ObjectHierarchy_IsTypeRegistered(type), kQ3True);
    EXPECT_EQ(Q3ObjectHierarchy_IsNameRegistered("Test:CountedShape"), kQ3True);
    TQ3ObjectClassNameString name;
    EXPECT_EQ(Q3ObjectHierarchy_GetStringFromType(type, name), kQ3Success);
    EXPECT_STREQ(name, "Test:CountedShape");
    TQ3ObjectType byName = 0;
    EXPECT_EQ(Q3ObjectHierarchy_GetTypeFromString(name, &byName), kQ3Success);
    EXPECT_EQ(byName, type);
    TQ3XObjectClassVersion version = 0;
    EXPECT_EQ(Q3XObjectHierarchy_GetClassVersion(type, &version), kQ3Success);
    EXPECT_EQ(Q3_OBJECT_CLASS_GET_MAJOR_VERSION(version), 2u);
    EXPECT_EQ(Q3_OBJECT_CLASS_GET_MINOR_VERSION(version), 3u);
    EXPECT_EQ(Q3XObjectClass_GetMethod(shapeClass, kQ3XMethodTypeObjectNew),
              reinterpret_cast<TQ3XFunctionPointer>(countedNew));
    EXPECT_EQ(Q3XObjectClass_GetMethod(shapeClass, Q3_METHOD_TYPE('n', 'o', 'n', 'e')), nullptr);

    // It is a subclass of the shape class.
    TQ3SubClassData shapes{0, nullptr};
    ASSERT_EQ(Q3ObjectHierarchy_GetSubClassData(kQ3SharedTypeShape, &shapes), kQ3Success);
    bool listed = false;
    for (unsigned long i = 0; i < shapes.numClasses; ++i)
        listed = listed || shapes.classTypes[i] == type;
    EXPECT_TRUE(listed);
    Q3ObjectHierarchy_EmptySubClassData(&shapes);

    EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(shapeClass), kQ3Success);
    EXPECT_EQ(g_calls.unregistered, 1);
    EXPECT_EQ(Q3ObjectHierarchy_IsTypeRegistered(type), kQ3False);
    EXPECT_EQ(Q3XObjectHierarchy_FindClassByType(type), nullptr);
}

TEST_F(ExtensionApiTest, ObjectsRunTheirMethodsAndKeepTheirInstanceData)
{
    TQ3ObjectType type = 0;
    TQ3XObjectClass shapeClass = registerCounted(kQ3SharedTypeShape, "Test:CountedShape", &type);
    ASSERT_NE(shapeClass, nullptr);
    int seven = 7;
    TQ3Object object = Q3XObjectHierarchy_NewObject(shapeClass, &seven);
    ASSERT_NE(object, nullptr);
    EXPECT_EQ(g_calls.made, 1);
    EXPECT_EQ(Q3Object_GetLeafType(object), type);
    EXPECT_EQ(Q3Object_IsType(object, kQ3SharedTypeShape), kQ3True);
    EXPECT_EQ(Q3Object_GetType(object), kQ3ObjectTypeShared);
    EXPECT_EQ(Q3Object_IsDrawable(object), kQ3True);
    EXPECT_EQ(Q3XObject_GetClass(object), shapeClass);
    auto* data = static_cast<Counted*>(Q3XObjectClass_GetPrivate(shapeClass, object));
    ASSERT_NE(data, nullptr);
    EXPECT_EQ(data->value, 7);

    // A shape takes the shape element calls.
    TQ3ColorRGB red{1, 0, 0};
    EXPECT_EQ(Q3Shape_AddElement(object, kQ3AttributeTypeDiffuseColor, &red), kQ3Success);

    // Duplicate: the duplicate method, and the elements copied.
    TQ3Object copy = Q3Object_Duplicate(object);
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(g_calls.duplicated, 1);
    const auto* copied = static_cast<Counted*>(Q3XObjectClass_GetPrivate(shapeClass, copy));
    EXPECT_EQ(copied->value, 1007);
    EXPECT_EQ(copied->sub, data->sub);
    TQ3ColorRGB back{};
    EXPECT_EQ(Q3Shape_GetElement(copy, kQ3AttributeTypeDiffuseColor, &back), kQ3Success);
    EXPECT_EQ(back.r, 1.0f);

    // A live object keeps its class registered.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(shapeClass), kQ3Failure),
                    kQ3ErrorObjectClassInUse);
    EXPECT_EQ(Q3ObjectHierarchy_IsTypeRegistered(type), kQ3True);

    // Shared: the delete method runs at the last reference.
    TQ3Object second = Q3Shared_GetReference(object);
    Q3Object_Dispose(object);
    EXPECT_EQ(g_calls.deleted, 0);
    Q3Object_Dispose(second);
    EXPECT_EQ(g_calls.deleted, 1);
    Q3Object_Dispose(copy);
    EXPECT_EQ(g_calls.deleted, 2);
    EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(shapeClass), kQ3Success);
}

TEST_F(ExtensionApiTest, AClassUnderTQ3ObjectIsDisposedAtOnceAndSubclassesInherit)
{
    TQ3ObjectType baseType = 0, childType = 0;
    TQ3XObjectClass base = registerCounted(kQ3ObjectTypeInvalid, "Test:PlainBase", &baseType);
    ASSERT_NE(base, nullptr);
    char childName[] = "Test:PlainChild";
    TQ3XObjectClass child =
        Q3XObjectHierarchy_RegisterClass(baseType, &childType, childName, nullptr, nullptr, 0, sizeof(int));
    ASSERT_NE(child, nullptr);
    TQ3Object object = Q3XObjectHierarchy_NewObject(child, nullptr);
    ASSERT_NE(object, nullptr);
    EXPECT_EQ(g_calls.made, 1); // the base class's new method, for its block
    EXPECT_EQ(Q3Object_IsType(object, baseType), kQ3True);
    EXPECT_EQ(Q3Object_IsType(object, kQ3ObjectTypeShared), kQ3False);
    EXPECT_NE(Q3XObjectClass_GetPrivate(base, object), nullptr);
    EXPECT_NE(Q3XObjectClass_GetPrivate(child, object), nullptr);
    EXPECT_NE(Q3XObjectClass_GetPrivate(base, object), Q3XObjectClass_GetPrivate(child, object));
    // The base cannot go while a class is registered under it.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(base), kQ3Failure), kQ3ErrorObjectClassInUse);
    EXPECT_EQ(Q3Object_Dispose(object), kQ3Success);
    EXPECT_EQ(g_calls.deleted, 1);
    EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(child), kQ3Success);
    EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(base), kQ3Success);
}

TEST_F(ExtensionApiTest, ANewMethodThatFailsGivesNoObject)
{
    TQ3ObjectType type = 0;
    TQ3XObjectClass shapeClass = registerCounted(kQ3ObjectTypeShared, "Test:Failing", &type);
    ASSERT_NE(shapeClass, nullptr);
    g_calls.failNew = true;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_NewObject(shapeClass, nullptr), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_EQ(g_calls.deleted, 0); // its new method did not succeed: no delete
    EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(shapeClass), kQ3Success);
}

TEST_F(ExtensionApiTest, RegistrationRefusesBadInput)
{
    TQ3ObjectType type = 12345;
    char name[] = "Test:Bad";
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_RegisterClass(kQ3ObjectTypeShared, nullptr, name, nullptr, nullptr,
                                                               0, 0),
                              nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_RegisterClass(kQ3ObjectTypeShared, &type, nullptr, nullptr, nullptr,
                                                               0, 0),
                              nullptr),
                    kQ3ErrorNULLParameter);
    char empty[] = "";
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_RegisterClass(kQ3ObjectTypeShared, &type, empty, nullptr, nullptr,
                                                               0, 0),
                              nullptr),
                    kQ3ErrorInvalidParameter);
    char tooLong[kQ3StringMaximumLength + 8];
    std::memset(tooLong, 'x', sizeof tooLong - 1);
    tooLong[sizeof tooLong - 1] = '\0';
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_RegisterClass(kQ3ObjectTypeShared, &type, tooLong, nullptr, nullptr,
                                                               0, 0),
                              nullptr),
                    kQ3ErrorInvalidParameter);
    char box[] = "Box";
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_RegisterClass(kQ3ObjectTypeShared, &type, box, nullptr, nullptr,
                                                               0, 0),
                              nullptr),
                    kQ3ErrorInvalidParameter);
    // Geometries and renderers cannot be subclassed (porting.md: no
    // plug-in renderer methods); groups can (CustomGroupApiTest.cpp).
    for (TQ3ObjectType parent : {TQ3ObjectType(kQ3ShapeTypeGeometry), TQ3ObjectType(kQ3SharedTypeRenderer),
                                 TQ3ObjectType(kQ3ShapeTypeLight), TQ3ObjectType(Q3_OBJECT_TYPE('n', 'o', 'n', 'e'))})
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_RegisterClass(parent, &type, name, nullptr, nullptr, 0, 0),
                                  nullptr),
                        kQ3ErrorInvalidObjectClass);
    EXPECT_EQ(type, 12345);
    EXPECT_EQ(Q3ObjectHierarchy_IsNameRegistered("Test:Bad"), kQ3False);

    // A name registered already.
    TQ3XObjectClass first = Q3XObjectHierarchy_RegisterClass(kQ3ObjectTypeShared, &type, name, nullptr, nullptr, 0, 0);
    ASSERT_NE(first, nullptr);
    TQ3ObjectType second = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_RegisterClass(kQ3ObjectTypeShared, &second, name, nullptr, nullptr,
                                                               0, 0),
                              nullptr),
                    kQ3ErrorInvalidParameter);
    EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(first), kQ3Success);
}

TEST_F(ExtensionApiTest, ClassCallsRefuseBadHandles)
{
    TQ3ObjectType type = 0;
    char name[] = "Test:Gone";
    TQ3XObjectClass gone = Q3XObjectHierarchy_RegisterClass(kQ3ObjectTypeShared, &type, name, nullptr, nullptr, 0, 0);
    ASSERT_NE(gone, nullptr);
    ASSERT_EQ(Q3XObjectHierarchy_UnregisterClass(gone), kQ3Success);
    for (TQ3XObjectClass bad : {TQ3XObjectClass{nullptr}, gone}) {
        const TQ3Error code = bad == nullptr ? kQ3ErrorNULLParameter : kQ3ErrorInvalidObjectClass;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(bad), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectClass_GetMethod(bad, kQ3XMethodTypeObjectNew), nullptr), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_NewObject(bad, nullptr), nullptr), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectClass_GetLeafType(bad), kQ3ObjectTypeInvalid), code);
        TQ3ObjectType out = 99;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectClass_GetType(bad, &out), kQ3Failure), code);
        EXPECT_EQ(out, 99);
        TQ3Object box = own(newBox());
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectClass_GetPrivate(bad, box), nullptr), code);
    }
    TQ3XObjectClassVersion version = 5;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_GetClassVersion(type, &version), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_GetClassVersion(kQ3GeometryTypeBox, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_EQ(version, 5u);
    EXPECT_EQ(Q3XObjectHierarchy_GetClassVersion(kQ3GeometryTypeBox, &version), kQ3Success);
    EXPECT_EQ(version, Q3_OBJECT_CLASS_VERSION(1, 6));
    EXPECT_EQ(Q3XObjectHierarchy_FindClassByType(kQ3GeometryTypeBox), nullptr);
    TQ3Object box = own(newBox());
    EXPECT_EQ(Q3XObject_GetClass(box), nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObject_GetClass(nullptr), nullptr), kQ3ErrorNULLParameter);

    // An object of another class.
    TQ3ObjectType countedType = 0;
    TQ3XObjectClass counted = registerCounted(kQ3ObjectTypeShared, "Test:Counted", &countedType);
    ASSERT_NE(counted, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectClass_GetPrivate(counted, box), nullptr), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectClass_GetPrivate(counted, nullptr), nullptr), kQ3ErrorNULLParameter);
    // An element class makes no objects.
    TQ3ElementType elementType = 0;
    TQ3XObjectClass element = Q3XElementClass_Register(&elementType, "Test:AnElement", 4, nullptr);
    ASSERT_NE(element, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_NewObject(element, nullptr), nullptr), kQ3ErrorInvalidObjectClass);
    EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(element), kQ3Success);
    EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(counted), kQ3Success);
}

TEST_F(ExtensionApiTest, ACustomObjectIsLeftOutOfFilesWithAWarning)
{
    TQ3ObjectType type = 0;
    TQ3XObjectClass shapeClass = registerCounted(kQ3SharedTypeShape, "Test:Unwritten", &type);
    ASSERT_NE(shapeClass, nullptr);
    TQ3Object object = Q3XObjectHierarchy_NewObject(shapeClass, nullptr);
    ASSERT_NE(object, nullptr);
    TQ3Object box = own(newBox());
    std::vector<unsigned char> bytes;
    EXPECT_Q3_WARNING(bytes = writeObjects({object, box}, kQ3FileModeText), kQ3WarningNoObjectSupportForWriteMethod);
    std::vector<TQ3Object> read = readAll(bytes);
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(Q3Object_GetLeafType(read[0]), kQ3GeometryTypeBox);
    disposeAll(read);
    Q3Object_Dispose(object);
    EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(shapeClass), kQ3Success);
}

TEST_F(ExtensionApiTest, PostedCodesReachTheErrorManager)
{
    EXPECT_Q3_ERROR(Q3XError_Post(kQ3ErrorOutOfMemory), kQ3ErrorOutOfMemory);
    EXPECT_Q3_WARNING(Q3XWarning_Post(kQ3WarningInternalException), kQ3WarningInternalException);
    EXPECT_Q3_NOTICE(Q3XNotice_Post(kQ3NoticeDataAlreadyEmpty), kQ3NoticeDataAlreadyEmpty);
    Q3XWarning_Post(kQ3WarningNone);
    Q3XNotice_Post(kQ3NoticeNone);
    EXPECT_Q3_ERROR(Q3XError_Post(static_cast<TQ3Error>(12345)), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3XWarning_Post(static_cast<TQ3Warning>(kQ3ErrorOutOfMemory)), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3XNotice_Post(static_cast<TQ3Notice>(-1)), kQ3ErrorInvalidParameter);
}

int g_libraryCalls = 0;
TQ3Status libraryRegister()
{
    ++g_libraryCalls;
    return kQ3Success;
}
TQ3Status libraryFails()
{
    return kQ3Failure;
}

TEST_F(ExtensionApiTest, SharedLibrariesRegisterAtOnce)
{
    g_libraryCalls = 0;
    TQ3XSharedLibraryInfo info{libraryRegister, 42};
    EXPECT_EQ(Q3XSharedLibrary_Register(&info), kQ3Success);
    EXPECT_EQ(g_libraryCalls, 1);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XSharedLibrary_Register(&info), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_EQ(g_libraryCalls, 1);
    EXPECT_EQ(Q3XSharedLibrary_Unregister(42), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XSharedLibrary_Unregister(42), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XSharedLibrary_Register(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    TQ3XSharedLibraryInfo none{nullptr, 43};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XSharedLibrary_Register(&none), kQ3Failure), kQ3ErrorNULLParameter);
    TQ3XSharedLibraryInfo failing{libraryFails, 44};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XSharedLibrary_Register(&failing), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XSharedLibrary_Unregister(44), kQ3Failure), kQ3ErrorInvalidParameter);
}

} // namespace
