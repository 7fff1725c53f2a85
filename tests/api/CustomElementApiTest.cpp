// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Custom element and attribute classes (QD3DSet.h) in sets and attribute
// sets; the element calls on shapes and on any object (QD3D.h); Apple's
// name and URL elements (QD3DCustomElements.h) through the API and through
// text and binary 3DMF files.

#include "FileTestSupport.h"
#include "DiffuseColor.h"
#include "Q3ApiTest.h"

#include "QD3DCustomElements.h"
#include "QD3DExtension.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DSet.h"
#include "QD3DStorage.h"
#include "QD3DString.h"

#include <climits>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using namespace q3test;

// A counter element: the application passes an int, the set keeps it
// doubled, Get gives it back halved; every method counts its calls.
struct Counts {
    int add = 0, replace = 0, get = 0, duplicate = 0, remove = 0;
    bool fail = false;
};
Counts g_counts;

TQ3Status counterAdd(const void* from, void* to)
{
    ++g_counts.add;
    if (g_counts.fail)
        return kQ3Failure;
    *static_cast<int*>(to) = 2 * *static_cast<const int*>(from);
    return kQ3Success;
}
TQ3Status counterReplace(const void* from, void* onto)
{
    ++g_counts.replace;
    if (g_counts.fail)
        return kQ3Failure;
    *static_cast<int*>(onto) = 2 * *static_cast<const int*>(from);
    return kQ3Success;
}
TQ3Status counterGet(const void* from, void* to)
{
    ++g_counts.get;
    *static_cast<int*>(to) = *static_cast<const int*>(from) / 2;
    return kQ3Success;
}
TQ3Status counterDuplicate(const void* from, void* to)
{
    ++g_counts.duplicate;
    *static_cast<int*>(to) = *static_cast<const int*>(from);
    return kQ3Success;
}
TQ3Status counterDelete(void*)
{
    ++g_counts.remove;
    return kQ3Success;
}

bool g_inherits = true;

TQ3XFunctionPointer counterMetaHandler(TQ3XMethodType type)
{
    switch (type) {
    case kQ3XMethodTypeElementCopyAdd:
        return reinterpret_cast<TQ3XFunctionPointer>(counterAdd);
    case kQ3XMethodTypeElementCopyReplace:
        return reinterpret_cast<TQ3XFunctionPointer>(counterReplace);
    case kQ3XMethodTypeElementCopyGet:
        return reinterpret_cast<TQ3XFunctionPointer>(counterGet);
    case kQ3XMethodTypeElementCopyDuplicate:
        return reinterpret_cast<TQ3XFunctionPointer>(counterDuplicate);
    case kQ3XMethodTypeElementDelete:
        return reinterpret_cast<TQ3XFunctionPointer>(counterDelete);
    case kQ3XMethodTypeAttributeInherit:
        return reinterpret_cast<TQ3XFunctionPointer>(static_cast<std::uintptr_t>(g_inherits ? kQ3True : kQ3False));
    default:
        return nullptr;
    }
}

// Owns its objects itself: they go before the classes their elements are
// of, and those before Q3Exit.
class CustomElementApiTest : public Q3ApiTest {
protected:
    void SetUp() override
    {
        Q3ApiTest::SetUp();
        g_counts = Counts{};
        g_inherits = true;
    }
    void TearDown() override
    {
        for (TQ3Object object : m_owned)
            Q3Object_Dispose(object);
        for (TQ3XObjectClass registered : m_classes)
            EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(registered), kQ3Success);
        Q3ApiTest::TearDown();
    }
    template <class T>
    T own(T object)
    {
        m_owned.push_back(object);
        return object;
    }
    std::vector<TQ3Object> m_owned;
    TQ3ElementType registerCounter(const char* name, TQ3ElementType asked = Q3_OBJECT_TYPE('c', 'n', 't', 'r'))
    {
        TQ3ElementType type = asked;
        TQ3XObjectClass made = Q3XElementClass_Register(&type, name, sizeof(int), counterMetaHandler);
        EXPECT_NE(made, nullptr);
        m_classes.push_back(made);
        return type;
    }
    TQ3AttributeType registerAttribute(const char* name, bool inherits)
    {
        g_inherits = inherits;
        TQ3AttributeType type = 0;
        TQ3XObjectClass made = Q3XAttributeClass_Register(&type, name, sizeof(int), counterMetaHandler);
        EXPECT_NE(made, nullptr);
        m_classes.push_back(made);
        return type;
    }
    std::vector<TQ3XObjectClass> m_classes;
};

std::vector<TQ3ElementType> walk(TQ3Object object)
{
    std::vector<TQ3ElementType> types;
    TQ3ElementType type = kQ3ElementTypeNone;
    while (Q3Object_GetNextElementType(object, &type) == kQ3Success && type != kQ3ElementTypeNone)
        types.push_back(type);
    return types;
}

TEST_F(CustomElementApiTest, RegisteringKeepsAFreeTypeAndMovesAReservedOne)
{
    const TQ3ElementType kept = registerCounter("Test:Kept");
    EXPECT_EQ(kept, Q3_OBJECT_TYPE('c', 'n', 't', 'r'));
    const TQ3ElementType moved = registerCounter("Test:Moved", kQ3AttributeTypeDiffuseColor);
    EXPECT_NE(moved, kQ3AttributeTypeDiffuseColor);
    EXPECT_FALSE(moved >= 0 && moved <= kQ3ElementTypeSet);
    const TQ3ElementType clash = registerCounter("Test:Clash", kept);
    EXPECT_NE(clash, kept);
    unsigned long size = 0;
    EXPECT_EQ(Q3XElementType_GetElementSize(kept, &size), kQ3Success);
    EXPECT_EQ(size, sizeof(int));
    TQ3ObjectType byName = 0;
    TQ3ObjectClassNameString name = "Test:Kept";
    EXPECT_EQ(Q3ObjectHierarchy_GetTypeFromString(name, &byName), kQ3Success);
    EXPECT_EQ(byName, kept);
    TQ3SubClassData elements{0, nullptr};
    ASSERT_EQ(Q3ObjectHierarchy_GetSubClassData(kQ3ObjectTypeElement, &elements), kQ3Success);
    EXPECT_GE(elements.numClasses, 3u);
    Q3ObjectHierarchy_EmptySubClassData(&elements);
}

TEST_F(CustomElementApiTest, RegistrationRefusesBadInput)
{
    TQ3ElementType type = 77;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XElementClass_Register(nullptr, "Test:X", 4, nullptr), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XElementClass_Register(&type, nullptr, 4, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XElementClass_Register(&type, "", 4, nullptr), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XAttributeClass_Register(&type, CEcNameElementName, 4, nullptr), nullptr),
                    kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XAttributeClass_Register(&type, "TriMesh", 4, nullptr), nullptr),
                    kQ3ErrorInvalidParameter);
    EXPECT_EQ(type, 77);
    unsigned long size = 9;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XElementType_GetElementSize(kQ3AttributeTypeNormal, &size), kQ3Failure),
                    kQ3ErrorUnknownElementType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XElementType_GetElementSize(LONG_MIN, &size), kQ3Failure),
                    kQ3ErrorUnknownElementType);
    EXPECT_EQ(size, 9u);
    const TQ3ElementType counter = registerCounter("Test:SizeOf");
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XElementType_GetElementSize(counter, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
}

TEST_F(CustomElementApiTest, ASetKeepsACustomElementThroughItsMethods)
{
    const TQ3ElementType type = registerCounter("Test:InASet");
    TQ3SetObject set = own(Q3Set_New());
    const int five = 5;
    EXPECT_EQ(Q3Set_Add(set, type, &five), kQ3Success);
    EXPECT_EQ(g_counts.add, 1);
    EXPECT_EQ(Q3Set_Contains(set, type), kQ3True);
    int back = 0;
    EXPECT_EQ(Q3Set_Get(set, type, &back), kQ3Success);
    EXPECT_EQ(back, 5); // doubled in, halved out
    const int six = 6;
    EXPECT_EQ(Q3Set_Add(set, type, &six), kQ3Success);
    EXPECT_EQ(g_counts.replace, 1);
    EXPECT_EQ(Q3Set_Get(set, type, &back), kQ3Success);
    EXPECT_EQ(back, 6);

    // The walk: the attribute types first, then the custom ones.
    const TQ3ColorRGB grey{0.5f, 0.5f, 0.5f};
    EXPECT_EQ(Q3Set_Add(set, kQ3AttributeTypeDiffuseColor, &grey), kQ3Success);
    std::vector<TQ3ElementType> types = walk(set);
    ASSERT_EQ(types.size(), 2u);
    EXPECT_EQ(types[0], kQ3AttributeTypeDiffuseColor);
    EXPECT_EQ(types[1], type);

    // Duplicate copies by copy-duplicate; each copy is deleted once.
    TQ3SetObject copy = Q3Object_Duplicate(set);
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(g_counts.duplicate, 1);
    EXPECT_EQ(Q3Set_Get(copy, type, &back), kQ3Success);
    EXPECT_EQ(back, 6);
    Q3Object_Dispose(copy);
    EXPECT_EQ(g_counts.remove, 1);

    EXPECT_EQ(Q3Set_Clear(set, type), kQ3Success);
    EXPECT_EQ(g_counts.remove, 2);
    EXPECT_EQ(Q3Set_Contains(set, type), kQ3False);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Get(set, type, &back), kQ3Failure), kQ3ErrorAttributeNotContained);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Clear(set, type), kQ3Failure), kQ3ErrorAttributeNotContained);
    EXPECT_EQ(Q3Set_Add(set, type, &five), kQ3Success);
    EXPECT_EQ(Q3Set_Empty(set), kQ3Success);
    EXPECT_EQ(g_counts.remove, 3);
}

TEST_F(CustomElementApiTest, AFailedCopyLeavesTheSetAsItWas)
{
    const TQ3ElementType type = registerCounter("Test:Failing");
    TQ3SetObject set = own(Q3Set_New());
    const int five = 5;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Add(set, type, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    g_counts.fail = true;
    const unsigned long before = Q3Shared_GetEditIndex(set);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Add(set, type, &five), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_EQ(Q3Set_Contains(set, type), kQ3False);
    EXPECT_EQ(Q3Shared_GetEditIndex(set), before);
    EXPECT_EQ(g_counts.remove, 0); // the element never made is never deleted
    g_counts.fail = false;
    int back = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Get(set, type, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Get(set, type, &back), kQ3Failure), kQ3ErrorAttributeNotContained);
}

TEST_F(CustomElementApiTest, AClassInUseStaysRegistered)
{
    TQ3ElementType type = 0;
    TQ3XObjectClass made = Q3XElementClass_Register(&type, "Test:InUse", sizeof(int), nullptr);
    ASSERT_NE(made, nullptr);
    TQ3SetObject set = Q3Set_New();
    const int value = 41;
    EXPECT_EQ(Q3Set_Add(set, type, &value), kQ3Success); // a byte copy: no methods
    int back = 0;
    EXPECT_EQ(Q3Set_Get(set, type, &back), kQ3Success);
    EXPECT_EQ(back, 41);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(made), kQ3Failure), kQ3ErrorObjectClassInUse);
    Q3Object_Dispose(set);
    EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(made), kQ3Success);
    TQ3SetObject after = own(Q3Set_New());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Add(after, type, &value), kQ3Failure), kQ3ErrorUnknownElementType);
}

TEST_F(CustomElementApiTest, AttributeSetsInheritCustomAttributesThatAskForIt)
{
    const TQ3AttributeType inherited = registerAttribute("Test:Inherited", true);
    const TQ3AttributeType kept = registerAttribute("Test:NotInherited", false);
    TQ3AttributeSet parent = own(Q3AttributeSet_New());
    TQ3AttributeSet child = own(Q3AttributeSet_New());
    TQ3AttributeSet result = own(Q3AttributeSet_New());
    const int one = 1, two = 2;
    EXPECT_EQ(Q3AttributeSet_Add(parent, inherited, &one), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Add(parent, kept, &two), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Inherit(parent, child, result), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Contains(result, inherited), kQ3True);
    EXPECT_EQ(Q3AttributeSet_Contains(result, kept), kQ3False);
    int back = 0;
    EXPECT_EQ(Q3AttributeSet_Get(result, inherited, &back), kQ3Success);
    EXPECT_EQ(back, 1);
    // The child's own value wins.
    const int three = 3;
    EXPECT_EQ(Q3AttributeSet_Add(child, inherited, &three), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Inherit(parent, child, result), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Get(result, inherited, &back), kQ3Success);
    EXPECT_EQ(back, 3);
}

TEST_F(CustomElementApiTest, ShapesKeepElementsAndAnAttachedSet)
{
    const TQ3ElementType type = registerCounter("Test:OnAShape");
    TQ3GeometryObject box = own(newBox());
    const int nine = 9;
    const unsigned long before = Q3Shared_GetEditIndex(box);
    EXPECT_EQ(Q3Shape_AddElement(box, type, &nine), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(box), before);
    EXPECT_EQ(Q3Shape_ContainsElement(box, type), kQ3True);
    int back = 0;
    EXPECT_EQ(Q3Shape_GetElement(box, type, &back), kQ3Success);
    EXPECT_EQ(back, 9);

    TQ3SetObject shared = own(Q3Set_New());
    TQ3SetObject got = nullptr;
    EXPECT_EQ(Q3Shape_GetSet(box, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    EXPECT_EQ(Q3Shape_SetSet(box, shared), kQ3Success);
    EXPECT_EQ(Q3Shape_GetSet(box, &got), kQ3Success);
    EXPECT_EQ(got, shared);
    Q3Object_Dispose(got);
    EXPECT_EQ(Q3Shape_ContainsElement(box, kQ3ElementTypeSet), kQ3True);
    EXPECT_EQ(Q3Shape_GetElement(box, kQ3ElementTypeSet, &got), kQ3Success);
    EXPECT_EQ(got, shared);
    Q3Object_Dispose(got);
    std::vector<TQ3ElementType> types = walk(box);
    ASSERT_EQ(types.size(), 2u);
    EXPECT_EQ(types[0], type);
    EXPECT_EQ(types[1], kQ3ElementTypeSet);

    // Duplicate: own elements copied, the attached set shared.
    TQ3GeometryObject copy = own(Q3Object_Duplicate(box));
    EXPECT_EQ(Q3Shape_GetElement(copy, type, &back), kQ3Success);
    EXPECT_EQ(back, 9);
    EXPECT_EQ(Q3Shape_GetSet(copy, &got), kQ3Success);
    EXPECT_EQ(got, shared);
    Q3Object_Dispose(got);

    EXPECT_EQ(Q3Shape_ClearElement(box, kQ3ElementTypeSet), kQ3Success);
    EXPECT_EQ(Q3Shape_ContainsElement(box, kQ3ElementTypeSet), kQ3False);
    EXPECT_EQ(Q3Shape_ClearElement(box, type), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_ClearElement(box, type), kQ3Failure), kQ3ErrorAttributeNotContained);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_GetElement(box, type, &back), kQ3Failure), kQ3ErrorAttributeNotContained);
    EXPECT_EQ(Q3Shape_EmptyElements(copy), kQ3Success);
    EXPECT_TRUE(walk(copy).empty());
    EXPECT_EQ(Q3Shape_SetSet(copy, nullptr), kQ3Success);
}

TEST_F(CustomElementApiTest, ShapeCallsOnASetAreTheSetCalls)
{
    TQ3SetObject set = own(Q3Set_New());
    const TQ3Vector3D up{0, 1, 0};
    EXPECT_EQ(Q3Shape_AddElement(set, kQ3AttributeTypeNormal, &up), kQ3Success);
    EXPECT_EQ(Q3Set_Contains(set, kQ3AttributeTypeNormal), kQ3True);
    EXPECT_EQ(Q3Object_ContainsElement(set, kQ3AttributeTypeNormal), kQ3True);
    TQ3ElementType type = kQ3ElementTypeNone;
    EXPECT_EQ(Q3Shape_GetNextElementType(set, &type), kQ3Success);
    EXPECT_EQ(type, kQ3AttributeTypeNormal);
    // A set attached to a set is no element of it.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_AddElement(set, kQ3ElementTypeSet, &set), kQ3Failure),
                    kQ3ErrorUnknownElementType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_GetSet(set, &set), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(Q3Shape_EmptyElements(set), kQ3Success);
    EXPECT_EQ(Q3Set_Contains(set, kQ3AttributeTypeNormal), kQ3False);
}

TEST_F(CustomElementApiTest, AnyObjectTakesTheObjectElementCalls)
{
    TQ3StorageObject storage = own(Q3MemoryStorage_New(nullptr, 0));
    const TQ3ColorRGB red{1, 0, 0};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_AddElement(storage, kQ3AttributeTypeDiffuseColor, &red), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_EQ(Q3Object_AddElement(storage, kQ3AttributeTypeDiffuseColor, &red), kQ3Success);
    TQ3ColorRGB back{};
    EXPECT_EQ(Q3Object_GetElement(storage, kQ3AttributeTypeDiffuseColor, &back), kQ3Success);
    EXPECT_EQ(back.r, 1.0f);
    EXPECT_EQ(walk(storage), std::vector<TQ3ElementType>{kQ3AttributeTypeDiffuseColor});
    EXPECT_EQ(Q3Object_ClearElement(storage, kQ3AttributeTypeDiffuseColor), kQ3Success);
    EXPECT_EQ(Q3Object_ContainsElement(storage, kQ3AttributeTypeDiffuseColor), kQ3False);
    EXPECT_EQ(Q3Object_EmptyElements(storage), kQ3Success);

    TQ3ViewObject view = Q3View_New();
    EXPECT_EQ(Q3Object_AddElement(view, kQ3AttributeTypeDiffuseColor, &red), kQ3Success);
    EXPECT_EQ(Q3Object_Dispose(view), kQ3Success); // its elements go with it: the leak check says so
}

TEST_F(CustomElementApiTest, ElementCallsRefuseBadInputAndChangeNothing)
{
    TQ3GeometryObject box = own(newBox());
    TQ3GeometryObject dead = newBox();
    Q3Object_Dispose(dead);
    const TQ3ColorRGB red{1, 0, 0};
    TQ3ColorRGB out{7, 7, 7};
    TQ3ElementType type = kQ3ElementTypeNone;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_AddElement(nullptr, kQ3AttributeTypeDiffuseColor, &red), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_AddElement(dead, kQ3AttributeTypeDiffuseColor, &red), kQ3Failure),
                    kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_GetElement(dead, kQ3AttributeTypeDiffuseColor, &out), kQ3Failure),
                    kQ3ErrorInvalidObject);
    const unsigned long before = Q3Shared_GetEditIndex(box);
    for (TQ3ElementType bad : {TQ3ElementType(kQ3ElementTypeNone), TQ3ElementType(kQ3ElementTypeUnknown),
                               TQ3ElementType(kQ3AttributeTypeNumTypes), TQ3ElementType(-1), TQ3ElementType(LONG_MAX)}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_AddElement(box, bad, &red), kQ3Failure), kQ3ErrorUnknownElementType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_GetElement(box, bad, &out), kQ3Failure), kQ3ErrorUnknownElementType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_ContainsElement(box, bad), kQ3False), kQ3ErrorUnknownElementType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_ClearElement(box, bad), kQ3Failure), kQ3ErrorUnknownElementType);
        if (bad != kQ3ElementTypeNone) {
            type = bad;
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_GetNextElementType(box, &type), kQ3Failure),
                            kQ3ErrorUnknownElementType);
            EXPECT_EQ(type, bad);
        }
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_AddElement(box, kQ3AttributeTypeDiffuseColor, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    const TQ3ColorRGB notANumber{std::numeric_limits<float>::quiet_NaN(), 0, 0};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_AddElement(box, kQ3AttributeTypeDiffuseColor, &notANumber), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    TQ3Object notASet = own(newBox());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_AddElement(box, kQ3ElementTypeSet, &notASet), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_SetSet(box, notASet), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_GetSet(box, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_GetNextElementType(box, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_GetElement(box, kQ3AttributeTypeDiffuseColor, &out), kQ3Failure),
                    kQ3ErrorAttributeNotContained);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_GetElement(box, kQ3ElementTypeSet, &out), kQ3Failure),
                    kQ3ErrorAttributeNotContained);
    EXPECT_EQ(out.r, 7.0f);
    EXPECT_EQ(Q3Shared_GetEditIndex(box), before);
    EXPECT_TRUE(walk(box).empty());
}

// ---- The name and URL elements.

TEST_F(CustomElementApiTest, NamesComeBackAndGo)
{
    TQ3GeometryObject box = own(newBox());
    char* name = reinterpret_cast<char*>(1);
    EXPECT_EQ(CENameElement_GetData(box, &name), kQ3Success);
    EXPECT_EQ(name, nullptr);
    EXPECT_EQ(CENameElement_SetData(box, "the box"), kQ3Success);
    EXPECT_EQ(CENameElement_GetData(box, &name), kQ3Success);
    ASSERT_NE(name, nullptr);
    EXPECT_STREQ(name, "the box");
    EXPECT_EQ(CENameElement_EmptyData(&name), kQ3Success);
    EXPECT_EQ(name, nullptr);
    EXPECT_EQ(CENameElement_EmptyData(&name), kQ3Success);

    // The element's type is the class's, and its data a string object.
    TQ3ObjectType type = 0;
    TQ3ObjectClassNameString className = CEcNameElementName;
    ASSERT_EQ(Q3ObjectHierarchy_GetTypeFromString(className, &type), kQ3Success);
    EXPECT_EQ(Q3Shape_ContainsElement(box, type), kQ3True);
    TQ3StringObject text = nullptr;
    EXPECT_EQ(Q3Shape_GetElement(box, type, &text), kQ3Success);
    char* chars = nullptr;
    EXPECT_EQ(Q3CString_GetString(text, &chars), kQ3Success);
    EXPECT_STREQ(chars, "the box");
    Q3CString_EmptyData(&chars);
    Q3Object_Dispose(text);

    TQ3GeometryObject copy = own(Q3Object_Duplicate(box));
    EXPECT_EQ(CENameElement_GetData(copy, &name), kQ3Success);
    EXPECT_STREQ(name, "the box");
    CENameElement_EmptyData(&name);

    EXPECT_EQ(CENameElement_SetData(box, nullptr), kQ3Success);
    EXPECT_EQ(CENameElement_GetData(box, &name), kQ3Success);
    EXPECT_EQ(name, nullptr);

    // On a set it is one of the set's elements.
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    EXPECT_EQ(CENameElement_SetData(set, "a set"), kQ3Success);
    EXPECT_EQ(Q3Set_Contains(set, type), kQ3True);

    EXPECT_Q3_ERROR(EXPECT_EQ(CENameElement_SetData(nullptr, "x"), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(CENameElement_GetData(box, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(CENameElement_EmptyData(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    TQ3Object notAString = own(newBox());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shape_AddElement(box, type, &notAString), kQ3Failure), kQ3ErrorInvalidParameter);
}

// The object's URL element, expected to hold `url` and `description` with
// kCEUrlOptionUseMap; NULL, a failure, when it has none. The caller empties it.
TCEUrlData* expectUrlUsingAMap(TQ3Object object, const char* url, const char* description)
{
    TCEUrlData* back = nullptr;
    EXPECT_EQ(CEUrlElement_GetData(object, &back), kQ3Success);
    EXPECT_NE(back, nullptr);
    if (back != nullptr) {
        EXPECT_STREQ(back->url, url);
        EXPECT_STREQ(back->description, description);
        EXPECT_EQ(back->options, kCEUrlOptionUseMap);
    }
    return back;
}

TEST_F(CustomElementApiTest, UrlsComeBackWithTheirDescriptionAndOptions)
{
    TQ3GroupObject group = own(Q3DisplayGroup_New());
    char url[] = "http://example.com/model";
    char description[] = "the model";
    TCEUrlData data{url, description, kCEUrlOptionUseMap};
    EXPECT_EQ(CEUrlElement_SetData(group, &data), kQ3Success);
    TCEUrlData* back = expectUrlUsingAMap(group, url, description);
    ASSERT_NE(back, nullptr);
    EXPECT_NE(back->url, url);
    EXPECT_EQ(CEUrlElement_EmptyData(&back), kQ3Success);
    EXPECT_EQ(back, nullptr);

    TCEUrlData bare{url, nullptr, kCEUrlOptionNone};
    EXPECT_EQ(CEUrlElement_SetData(group, &bare), kQ3Success);
    EXPECT_EQ(CEUrlElement_GetData(group, &back), kQ3Success);
    EXPECT_EQ(back->description, nullptr);
    CEUrlElement_EmptyData(&back);

    TCEUrlData noUrl{nullptr, description, kCEUrlOptionNone};
    EXPECT_Q3_ERROR(EXPECT_EQ(CEUrlElement_SetData(group, &noUrl), kQ3Failure), kQ3ErrorNULLParameter);
    TCEUrlData badOptions{url, nullptr, kCEUrlOptionNone};
    const int seven = 7;
    std::memcpy(&badOptions.options, &seven, sizeof seven);
    EXPECT_Q3_ERROR(EXPECT_EQ(CEUrlElement_SetData(group, &badOptions), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(CEUrlElement_GetData(group, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(CEUrlElement_EmptyData(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_EQ(CEUrlElement_GetData(group, &back), kQ3Success); // unchanged by the failures
    EXPECT_EQ(back->description, nullptr);
    CEUrlElement_EmptyData(&back);
    EXPECT_EQ(CEUrlElement_SetData(group, nullptr), kQ3Success);
    EXPECT_EQ(CEUrlElement_GetData(group, &back), kQ3Success);
    EXPECT_EQ(back, nullptr);
}

std::string nameOf(TQ3Object object)
{
    char* name = nullptr;
    if (CENameElement_GetData(object, &name) != kQ3Success || name == nullptr)
        return "<none>";
    std::string result = name;
    CENameElement_EmptyData(&name);
    return result;
}

TEST_F(CustomElementApiTest, NamesAndUrlsRoundTripThroughTextAndBinaryFiles)
{
    TQ3GroupObject group = own(Q3DisplayGroup_New());
    TQ3GeometryObject box = own(newBox());
    TQ3GeometryObject triangleBox = own(newBox());
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    const TQ3ColorRGB green{0, 1, 0};
    ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &green), kQ3Success);
    ASSERT_EQ(Q3Geometry_SetAttributeSet(triangleBox, set), kQ3Success);
    ASSERT_EQ(CENameElement_SetData(group, "the group"), kQ3Success);
    ASSERT_EQ(CENameElement_SetData(box, "a plain box"), kQ3Success);
    ASSERT_EQ(CENameElement_SetData(triangleBox, "a green box"), kQ3Success);
    ASSERT_EQ(CENameElement_SetData(set, "green"), kQ3Success);
    char url[] = "http://example.com/";
    char description[] = "more";
    TCEUrlData link{url, description, kCEUrlOptionUseMap};
    ASSERT_EQ(CEUrlElement_SetData(box, &link), kQ3Success);
    ASSERT_NE(Q3Group_AddObject(group, box), nullptr);
    ASSERT_NE(Q3Group_AddObject(group, triangleBox), nullptr);

    for (TQ3FileMode mode : {kQ3FileModeNormal, kQ3FileModeText, kQ3FileModeStream}) {
        const std::vector<unsigned char> bytes = writeObjects({group}, mode);
        std::vector<TQ3Object> read = readAll(bytes);
        ASSERT_EQ(read.size(), 1u) << "mode " << mode;
        EXPECT_EQ(nameOf(read[0]), "the group");
        TQ3GroupPosition position = nullptr;
        ASSERT_EQ(Q3Group_GetFirstPosition(read[0], &position), kQ3Success);
        TQ3Object first = nullptr, second = nullptr;
        ASSERT_EQ(Q3Group_GetPositionObject(read[0], position, &first), kQ3Success);
        ASSERT_EQ(Q3Group_GetNextPosition(read[0], &position), kQ3Success);
        ASSERT_EQ(Q3Group_GetPositionObject(read[0], position, &second), kQ3Success);
        EXPECT_EQ(nameOf(first), "a plain box");
        TCEUrlData* back = expectUrlUsingAMap(first, url, description);
        ASSERT_NE(back, nullptr);
        CEUrlElement_EmptyData(&back);
        EXPECT_EQ(nameOf(second), "a green box");
        TQ3AttributeSet readSet = nullptr;
        ASSERT_EQ(Q3Geometry_GetAttributeSet(second, &readSet), kQ3Success);
        ASSERT_NE(readSet, nullptr);
        EXPECT_EQ(nameOf(readSet), "green");
        EXPECT_EQ(expectDiffuseColor(readSet).g, 1.0f);
        Q3Object_Dispose(readSet);
        Q3Object_Dispose(first);
        Q3Object_Dispose(second);
        if (mode == kQ3FileModeText) {
            const std::string text(bytes.begin(), bytes.end());
            EXPECT_NE(text.find("Apple Computer, Inc.:NameElement ( )"), std::string::npos) << text;
            EXPECT_NE(text.find("CString ( \"a green box\" )"), std::string::npos) << text;
        }
        disposeAll(read);
    }
}

TEST_F(CustomElementApiTest, BinaryFilesDeclareTheNameClassWithATypeObject)
{
    TQ3GeometryObject box = own(newBox());
    ASSERT_EQ(CENameElement_SetData(box, "declared"), kQ3Success);
    const std::vector<unsigned char> bytes = writeObjects({box}, kQ3FileModeNormal);
    const std::string file(bytes.begin(), bytes.end());
    // After the 24-byte header: a Type object (its tag in the file's byte
    // order), type -1 and the class name, before any other object.
    ASSERT_GT(file.size(), 40u);
    const bool little = file.compare(0, 4, "FMD3") == 0;
    EXPECT_EQ(file.substr(24, 4), little ? std::string("epyt") : std::string("type"));
    EXPECT_EQ(file.substr(32, 4), std::string("\xff\xff\xff\xff", 4));
    EXPECT_EQ(file.compare(36, std::strlen(CEcNameElementName), CEcNameElementName), 0);
    std::vector<TQ3Object> read = readAll(bytes);
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(nameOf(read[0]), "declared");
    disposeAll(read);
}

TEST_F(CustomElementApiTest, AQuesaTestModelsGroupNameIsAName)
{
    const std::string text = "3DMetafile ( 1 6 Normal )\n"
                             "BeginGroup ( DisplayGroup ( ) DisplayGroupState ( Inline )\n"
                             "  Container ( Apple Computer, Inc.:NameElement ( ) CString ( \"middle box\" ) ) )\n"
                             "Container ( Box ( ) Container ( Apple Computer, Inc.:NameElement ( ) CString ( \"b\" ) ) )\n"
                             "EndGroup ( )\n";
    std::vector<TQ3Object> objects = readAll(bytesOf(text));
    ASSERT_EQ(objects.size(), 1u);
    EXPECT_EQ(nameOf(objects[0]), "middle box");
    TQ3GroupPosition position = nullptr;
    ASSERT_EQ(Q3Group_GetFirstPosition(objects[0], &position), kQ3Success);
    TQ3Object box = nullptr;
    ASSERT_EQ(Q3Group_GetPositionObject(objects[0], position, &box), kQ3Success);
    EXPECT_EQ(nameOf(box), "b");
    Q3Object_Dispose(box);
    disposeAll(objects);
}

TEST_F(CustomElementApiTest, AnApplicationElementHasNoFileFormAndIsLeftOutWithAWarning)
{
    const TQ3ElementType type = registerCounter("Test:NotInFiles");
    TQ3GeometryObject box = own(newBox());
    const int one = 1;
    ASSERT_EQ(Q3Shape_AddElement(box, type, &one), kQ3Success);
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    ASSERT_EQ(Q3Set_Add(set, type, &one), kQ3Success);
    ASSERT_EQ(Q3Geometry_SetAttributeSet(box, set), kQ3Success);
    std::vector<unsigned char> bytes;
    EXPECT_Q3_WARNING(bytes = writeObjects({box}, kQ3FileModeText), kQ3WarningNoObjectSupportForWriteMethod);
    std::vector<TQ3Object> read = readAll(bytes);
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(Q3Shape_ContainsElement(read[0], type), kQ3False);
    disposeAll(read);
}

} // namespace
