// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// QD3DIO.h's I/O methods of registered classes: a custom object class and a
// custom attribute class write themselves into 3DMF files (traverse and
// write methods, Q3XView_SubmitWriteData, subobjects) and read themselves
// back (read and read-data methods), text and binary; their class names
// appear in the file as the 3D Metafile Reference has them (text: the
// object's name; binary: a Type object declaring the negative type); a file
// whose class nobody registered reads as an unknown object and is written
// back unchanged; failing methods and truncated data fail cleanly.

#include "OwningApiTest.h"

#include "QD3DCustomElements.h"
#include "QD3DExtension.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DSet.h"
#include "QD3DString.h"
#include "FileTestSupport.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

namespace {

using namespace q3test;

// An attribute class's data: a weight and flags (Test:Weight, below).
struct Weight {
    float weight;
    TQ3Uns32 flags;
};

// ---- A shape class: a float, a count and a label, with an optional
// sub-object (written after its data, in a container).

struct Spot {
    float size;
    TQ3Uns32 count;
    char label[32];
    TQ3Object child; // a reference, or NULL
    Weight weight;   // what a set among its subobjects held, when hasWeight
    bool hasWeight;
};

struct SpotBehaviour {
    bool failTraverse = false;
    bool failWrite = false;
    bool postFromWrite = false;
    bool wrongSize = false;
    bool skipWrite = false; // the traverse method writes nothing
    bool subObjectData = false; // the traverse method adds a Test:Weight
    bool leaveElements = false; // the read method reads geometries only
    int deletes = 0;        // calls of the data delete method
};
SpotBehaviour g_spot;
TQ3XObjectClass g_spotClass = nullptr;
TQ3AttributeType g_weightType = 0; // the attribute class below

TQ3Status spotNew(TQ3Object, void* privateData, void* parameters)
{
    auto* spot = static_cast<Spot*>(privateData);
    if (parameters != nullptr)
        *spot = *static_cast<const Spot*>(parameters);
    if (spot->child != nullptr)
        spot->child = Q3Shared_GetReference(spot->child);
    return kQ3Success;
}

void spotDelete(TQ3Object, void* privateData)
{
    auto* spot = static_cast<Spot*>(privateData);
    if (spot->child != nullptr)
        Q3Object_Dispose(spot->child);
}

TQ3Status spotDuplicate(TQ3Object, const void* from, TQ3Object, const void* to)
{
    auto* target = static_cast<Spot*>(const_cast<void*>(to));
    *target = *static_cast<const Spot*>(from);
    if (target->child != nullptr)
        target->child = Q3Shared_GetReference(target->child);
    return kQ3Success;
}

void countDelete(void*)
{
    ++g_spot.deletes;
}

TQ3Status spotTraverse(TQ3Object, void* data, TQ3ViewObject view)
{
    if (g_spot.failTraverse)
        return kQ3Failure;
    if (g_spot.skipWrite)
        return kQ3Success;
    auto* spot = static_cast<Spot*>(data);
    TQ3Size size = 8 + Q3Size_Pad(static_cast<TQ3Size>(std::strlen(spot->label) + 1));
    if (g_spot.wrongSize)
        size += 4;
    if (Q3XView_SubmitWriteData(view, size, spot, countDelete) != kQ3Success)
        return kQ3Failure;
    if (g_spot.subObjectData) {
        static float s_weight[2] = {0.5f, 0.0f};
        std::uint32_t flags = 7;
        std::memcpy(&s_weight[1], &flags, sizeof flags);
        if (Q3XView_SubmitSubObjectData(view, Q3XObjectHierarchy_FindClassByType(g_weightType), 8, s_weight,
                                        countDelete) != kQ3Success)
            return kQ3Failure;
    }
    if (spot->child != nullptr)
        return Q3Object_Submit(spot->child, view);
    return kQ3Success;
}

TQ3Status spotWrite(const void* data, TQ3FileObject file)
{
    if (g_spot.postFromWrite) {
        Q3XError_Post(kQ3ErrorOutOfMemory);
        return kQ3Failure;
    }
    if (g_spot.failWrite)
        return kQ3Failure;
    const auto* spot = static_cast<const Spot*>(data);
    if (Q3Float32_Write(spot->size, file) != kQ3Success || Q3Uns32_Write(spot->count, file) != kQ3Success)
        return kQ3Failure;
    return Q3String_Write(spot->label, file);
}

TQ3Object spotRead(TQ3FileObject file)
{
    Spot spot{};
    unsigned long length = 0;
    if (Q3Float32_Read(&spot.size, file) != kQ3Success || Q3Uns32_Read(&spot.count, file) != kQ3Success)
        return nullptr;
    char label[kQ3StringMaximumLength];
    if (Q3String_Read(label, &length, file) != kQ3Success)
        return nullptr;
    std::strncpy(spot.label, label, sizeof spot.label - 1);
    while (Q3File_IsEndOfContainer(file, nullptr) == kQ3False) {
        if (g_spot.leaveElements && Q3File_IsNextObjectOfType(file, kQ3ShapeTypeGeometry) == kQ3False)
            break;
        TQ3Object sub = Q3File_ReadObject(file);
        if (sub == nullptr)
            return nullptr;
        // An element comes as a set holding it (an attribute set is a child).
        if (Q3Object_IsType(sub, kQ3SharedTypeSet) == kQ3True && Q3Object_IsType(sub, kQ3SetTypeAttribute) == kQ3False) {
            if (Q3Set_Contains(sub, g_weightType) == kQ3True &&
                Q3Set_Get(sub, g_weightType, &spot.weight) == kQ3Success)
                spot.hasWeight = true;
            Q3Object_Dispose(sub);
            continue;
        }
        if (spot.child != nullptr)
            Q3Object_Dispose(spot.child);
        spot.child = sub;
    }
    TQ3Object made = Q3XObjectHierarchy_NewObject(g_spotClass, &spot);
    if (spot.child != nullptr)
        Q3Object_Dispose(spot.child); // the new method took its own reference
    return made;
}

TQ3XFunctionPointer spotMetaHandler(TQ3XMethodType type)
{
    switch (type) {
    case kQ3XMethodTypeObjectNew:
        return reinterpret_cast<TQ3XFunctionPointer>(spotNew);
    case kQ3XMethodTypeObjectDelete:
        return reinterpret_cast<TQ3XFunctionPointer>(spotDelete);
    case kQ3XMethodTypeObjectDuplicate:
        return reinterpret_cast<TQ3XFunctionPointer>(spotDuplicate);
    case kQ3XMethodTypeObjectTraverse:
        return reinterpret_cast<TQ3XFunctionPointer>(spotTraverse);
    case kQ3XMethodTypeObjectWrite:
        return reinterpret_cast<TQ3XFunctionPointer>(spotWrite);
    case kQ3XMethodTypeObjectRead:
        return reinterpret_cast<TQ3XFunctionPointer>(spotRead);
    default:
        return nullptr;
    }
}

// ---- An attribute class: Weight's data.

bool g_failReadData = false;

TQ3Status weightTraverse(TQ3Object object, void* data, TQ3ViewObject view)
{
    if (object != nullptr) // elements get no object (QD3DIO.h)
        return kQ3Failure;
    return Q3XView_SubmitWriteData(view, 8, data, nullptr);
}

TQ3Status weightWrite(const void* data, TQ3FileObject file)
{
    const auto* weight = static_cast<const Weight*>(data);
    if (Q3Float32_Write(weight->weight, file) != kQ3Success)
        return kQ3Failure;
    return Q3Uns32_Write(weight->flags, file);
}

TQ3Status weightReadData(TQ3Object parentObject, TQ3FileObject file)
{
    if (g_failReadData)
        return kQ3Failure;
    Weight weight{};
    if (Q3Float32_Read(&weight.weight, file) != kQ3Success || Q3Uns32_Read(&weight.flags, file) != kQ3Success)
        return kQ3Failure;
    return Q3Set_Add(parentObject, g_weightType, &weight);
}

TQ3XFunctionPointer weightMetaHandler(TQ3XMethodType type)
{
    switch (type) {
    case kQ3XMethodTypeObjectTraverse:
        return reinterpret_cast<TQ3XFunctionPointer>(weightTraverse);
    case kQ3XMethodTypeObjectWrite:
        return reinterpret_cast<TQ3XFunctionPointer>(weightWrite);
    case kQ3XMethodTypeObjectReadData:
        return reinterpret_cast<TQ3XFunctionPointer>(weightReadData);
    default:
        return nullptr;
    }
}

// ---- A class whose objects attach themselves to the object whose
// container holds them.

struct Attached {
    TQ3ObjectType parentType = 0;
    TQ3Uns32 value = 0;
    int calls = 0;
};
Attached g_attached;
TQ3XObjectClass g_tagClass = nullptr;

TQ3Object tagRead(TQ3FileObject file)
{
    TQ3Uns32 value = 0;
    if (Q3Uns32_Read(&value, file) != kQ3Success)
        return nullptr;
    TQ3Object tag = Q3XObjectHierarchy_NewObject(g_tagClass, nullptr);
    if (tag != nullptr)
        *static_cast<TQ3Uns32*>(Q3XObjectClass_GetPrivate(g_tagClass, tag)) = value;
    return tag;
}

TQ3Status tagAttach(TQ3Object child, TQ3Object parent)
{
    ++g_attached.calls;
    g_attached.parentType = Q3Object_GetLeafType(parent);
    g_attached.value = *static_cast<TQ3Uns32*>(Q3XObjectClass_GetPrivate(g_tagClass, child));
    return kQ3Success;
}

TQ3XFunctionPointer tagMetaHandler(TQ3XMethodType type)
{
    switch (type) {
    case kQ3XMethodTypeObjectRead:
        return reinterpret_cast<TQ3XFunctionPointer>(tagRead);
    case kQ3XMethodTypeObjectAttach:
        return reinterpret_cast<TQ3XFunctionPointer>(tagAttach);
    default:
        return nullptr;
    }
}

class CustomClassFileTest : public OwningApiTest {
protected:
    void SetUp() override
    {
        OwningApiTest::SetUp();
        g_spot = SpotBehaviour{};
        g_failReadData = false;
        ASSERT_NO_FATAL_FAILURE(registerSpot());
        g_weightType = 0;
        m_weightClass = Q3XAttributeClass_Register(&g_weightType, "Test:Weight", sizeof(Weight), weightMetaHandler);
        ASSERT_NE(m_weightClass, nullptr);
    }
    void TearDown() override
    {
        disposeOwned();
        if (m_weightClass != nullptr)
            EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(m_weightClass), kQ3Success);
        if (g_spotClass != nullptr)
            EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(g_spotClass), kQ3Success);
        g_spotClass = nullptr;
        OwningApiTest::TearDown();
    }

    /// Registers Test:Spot (again, after a test unregistered it).
    void registerSpot()
    {
        TQ3ObjectType type = 0;
        g_spotClass = Q3XObjectHierarchy_RegisterClass(kQ3SharedTypeShape, &type, const_cast<char*>("Test:Spot"),
                                                       spotMetaHandler, nullptr, 0, sizeof(Spot));
        ASSERT_NE(g_spotClass, nullptr);
        m_spotType = type;
    }
    /// Unregisters Test:Spot, its objects disposed first.
    void unregisterSpot()
    {
        disposeOwned();
        ASSERT_EQ(Q3XObjectHierarchy_UnregisterClass(g_spotClass), kQ3Success);
        g_spotClass = nullptr;
    }

    TQ3Object newSpot(float size, TQ3Uns32 count, const char* label, TQ3Object child = nullptr)
    {
        Spot spot{};
        spot.size = size;
        spot.count = count;
        std::strncpy(spot.label, label, sizeof spot.label - 1);
        spot.child = child;
        return keep(Q3XObjectHierarchy_NewObject(g_spotClass, &spot));
    }
    static const Spot& spotOf(TQ3Object object)
    {
        return *static_cast<const Spot*>(Q3XObjectClass_GetPrivate(g_spotClass, object));
    }

    /// Disposed before the classes are unregistered (objects of a class keep
    /// it registered).
    template <class T>
    T keep(T object)
    {
        m_mine.push_back(object);
        return object;
    }
    /// Reads the one object `bytes` hold (kept: disposed with the test's
    /// objects); null, with a failure, when they hold another number.
    TQ3Object readOne(const std::vector<unsigned char>& bytes)
    {
        std::vector<TQ3Object> read = readAll(bytes);
        for (TQ3Object object : read)
            keep(object);
        EXPECT_EQ(read.size(), 1u);
        return read.size() == 1 ? read[0] : nullptr;
    }
    void disposeOwned()
    {
        for (TQ3Object object : m_mine)
            Q3Object_Dispose(object);
        m_mine.clear();
    }

    TQ3ObjectType m_spotType = 0;
    TQ3XObjectClass m_weightClass = nullptr;
    std::vector<TQ3Object> m_mine;
};

std::string textOf(const std::vector<unsigned char>& bytes)
{
    return std::string(bytes.begin(), bytes.end());
}

// The text's words, each followed by one space: the text without its layout.
std::string wordsOf(const std::vector<unsigned char>& bytes)
{
    std::istringstream in(textOf(bytes));
    std::string words, word;
    while (in >> word)
        words += word + ' ';
    return words;
}

// Where `needle` occurs in the bytes (npos when nowhere).
std::size_t find(const std::vector<unsigned char>& bytes, const std::string& needle)
{
    return textOf(bytes).find(needle);
}

std::uint32_t bigU32(const std::vector<unsigned char>& bytes, std::size_t at)
{
    return std::uint32_t{bytes[at]} << 24 | std::uint32_t{bytes[at + 1]} << 16 | std::uint32_t{bytes[at + 2]} << 8 |
           bytes[at + 3];
}

const TQ3FileMode kModes[] = {kQ3FileModeNormal, kQ3FileModeText, kQ3FileModeSwap, kQ3FileModeStream | kQ3FileModeText};

TEST_F(CustomClassFileTest, ACustomObjectRoundTripsThroughEveryEncoding)
{
    for (TQ3FileMode mode : kModes) {
        SCOPED_TRACE(mode);
        TQ3Object spot = newSpot(2.5f, 7, "seven");
        const std::vector<unsigned char> bytes = writeObjects({spot}, mode);
        TQ3Object readBack = readOne(bytes);
        ASSERT_NE(readBack, nullptr);
        EXPECT_EQ(Q3Object_GetLeafType(readBack), m_spotType);
        EXPECT_EQ(Q3XObject_GetClass(readBack), g_spotClass);
        const Spot& back = spotOf(readBack);
        EXPECT_EQ(back.size, 2.5f);
        EXPECT_EQ(back.count, 7u);
        EXPECT_STREQ(back.label, "seven");
        EXPECT_EQ(back.child, nullptr);
    }
    // The data's delete method ran once after each write.
    EXPECT_EQ(g_spot.deletes, 4);
}

TEST_F(CustomClassFileTest, SubmittedSubObjectsFollowTheDataInAContainer)
{
    TQ3Object box = keep(newBox());
    TQ3Object spot = newSpot(1.0f, 3, "with a box", box);
    for (TQ3FileMode mode : {kQ3FileModeNormal, kQ3FileModeText}) {
        SCOPED_TRACE(mode);
        const std::vector<unsigned char> bytes = writeObjects({spot}, mode);
        if (mode == kQ3FileModeText) {
            const std::string text = textOf(bytes);
            const std::size_t container = text.find("Container (");
            const std::size_t object = text.find("Test:Spot ( 1 3 \"with a box\" )");
            const std::size_t boxAt = text.find("Box (");
            ASSERT_NE(container, std::string::npos) << text;
            ASSERT_NE(object, std::string::npos) << text;
            ASSERT_NE(boxAt, std::string::npos) << text;
            EXPECT_LT(container, object);
            EXPECT_LT(object, boxAt);
        }
        TQ3Object readBack = readOne(bytes);
        ASSERT_NE(readBack, nullptr);
        const Spot& back = spotOf(readBack);
        EXPECT_EQ(back.count, 3u);
        ASSERT_NE(back.child, nullptr);
        EXPECT_EQ(Q3Object_GetLeafType(back.child), kQ3GeometryTypeBox);
    }
}

TEST_F(CustomClassFileTest, ABinaryFileDeclaresTheClassWithATypeObject)
{
    TQ3Object spot = newSpot(0.5f, 1, "a");
    const std::vector<unsigned char> bytes = writeObjects({spot, spot}, kQ3FileModeNormal);
    // The header (24 bytes), then Type ( -1 "Test:Spot" ): 'type', its size
    // (4 + the padded name), -1, the name.
    ASSERT_GE(bytes.size(), 24u + 8 + 4 + 12);
    EXPECT_EQ(bigU32(bytes, 24), static_cast<std::uint32_t>(Q3_OBJECT_TYPE('t', 'y', 'p', 'e')));
    EXPECT_EQ(bigU32(bytes, 28), 4u + 12u);
    EXPECT_EQ(bigU32(bytes, 32), 0xFFFFFFFFu);
    EXPECT_EQ(std::string(reinterpret_cast<const char*>(&bytes[36])), "Test:Spot");
    // The object: type -1 and its data, 4 + 4 + the padded "a".
    const std::size_t object = 24 + 8 + 16;
    EXPECT_EQ(bigU32(bytes, object), 0xFFFFFFFFu);
    EXPECT_EQ(bigU32(bytes, object + 4), 12u);
    // The table of contents lists it (referred to twice) with that type: its
    // one entry ends the file (ID, 64-bit location, type).
    EXPECT_EQ(bigU32(bytes, bytes.size() - 4), 0xFFFFFFFFu);
    EXPECT_EQ(bigU32(bytes, bytes.size() - 8), object);
    // The second submit refers to the first: one object comes back twice.
    std::vector<TQ3Object> read = readAll(bytes);
    ASSERT_EQ(read.size(), 2u);
    EXPECT_EQ(read[0], read[1]);
    disposeAll(read);
}

TEST_F(CustomClassFileTest, ACustomObjectInAGroupRoundTrips)
{
    TQ3Object group = keep(Q3DisplayGroup_New());
    TQ3Object spot = newSpot(4.0f, 9, "in a group");
    ASSERT_NE(Q3Group_AddObject(group, spot), nullptr);
    for (TQ3FileMode mode : {kQ3FileModeNormal, kQ3FileModeText}) {
        TQ3Object readBack = readOne(writeObjects({group}, mode));
        ASSERT_NE(readBack, nullptr);
        TQ3GroupPosition position = nullptr;
        ASSERT_EQ(Q3Group_GetFirstPosition(readBack, &position), kQ3Success);
        TQ3Object member = nullptr;
        ASSERT_EQ(Q3Group_GetPositionObject(readBack, position, &member), kQ3Success);
        EXPECT_EQ(spotOf(member).count, 9u);
        EXPECT_STREQ(spotOf(member).label, "in a group");
        Q3Object_Dispose(member);
    }
}

TEST_F(CustomClassFileTest, ACustomAttributeRoundTripsInAnAttributeSetAndOnAShape)
{
    for (TQ3FileMode mode : kModes) {
        SCOPED_TRACE(mode);
        TQ3GeometryObject box = keep(newBox());
        TQ3AttributeSet set = keep(Q3AttributeSet_New());
        const Weight inSet{0.25f, 0xA5u};
        ASSERT_EQ(Q3AttributeSet_Add(set, g_weightType, &inSet), kQ3Success);
        ASSERT_EQ(Q3Geometry_SetAttributeSet(box, set), kQ3Success);
        const Weight onShape{8.0f, 3u};
        ASSERT_EQ(Q3Shape_AddElement(box, g_weightType, &onShape), kQ3Success);
        const std::vector<unsigned char> bytes = writeObjects({box}, mode);
        if (mode & kQ3FileModeText)
            EXPECT_NE(find(bytes, "Test:Weight ( 0.25 165 )"), std::string::npos) << textOf(bytes);
        else
            EXPECT_NE(find(bytes, "Test:Weight"), std::string::npos); // its Type object
        TQ3Object readBack = readOne(bytes);
        ASSERT_NE(readBack, nullptr);
        Weight back{};
        ASSERT_EQ(Q3Shape_GetElement(readBack, g_weightType, &back), kQ3Success);
        EXPECT_EQ(back.weight, 8.0f);
        EXPECT_EQ(back.flags, 3u);
        TQ3AttributeSet readSet = nullptr;
        ASSERT_EQ(Q3Geometry_GetAttributeSet(readBack, &readSet), kQ3Success);
        ASSERT_NE(readSet, nullptr);
        ASSERT_EQ(Q3AttributeSet_Get(readSet, g_weightType, &back), kQ3Success);
        EXPECT_EQ(back.weight, 0.25f);
        EXPECT_EQ(back.flags, 0xA5u);
        Q3Object_Dispose(readSet);
    }
}

TEST_F(CustomClassFileTest, AnUnregisteredClassReadsAsAnUnknownObjectAndIsWrittenBackUnchanged)
{
    std::vector<unsigned char> binary, text;
    {
        TQ3Object spot = newSpot(3.0f, 2, "orphan");
        binary = writeObjects({spot}, kQ3FileModeNormal);
        text = writeObjects({spot}, kQ3FileModeText);
    }
    ASSERT_NO_FATAL_FAILURE(unregisterSpot());

    std::vector<TQ3Object> read;
    EXPECT_Q3_WARNING(read = readAll(binary), kQ3WarningUnknownObject);
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(Q3Object_GetLeafType(read[0]), kQ3UnknownTypeBinary);
    char* typeString = nullptr;
    ASSERT_EQ(Q3UnknownBinary_GetTypeString(read[0], &typeString), kQ3Success);
    ASSERT_NE(typeString, nullptr);
    EXPECT_STREQ(typeString, "Test:Spot");
    EXPECT_EQ(Q3UnknownBinary_EmptyTypeString(&typeString), kQ3Success);
    EXPECT_EQ(writeObjects({read[0]}, kQ3FileModeNormal), binary);
    disposeAll(read);

    // Text as binary: the same warning, an unknown (text) object written
    // back unchanged.
    EXPECT_Q3_WARNING(read = readAll(text), kQ3WarningUnknownObject);
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(Q3Object_GetLeafType(read[0]), kQ3UnknownTypeText);
    TQ3UnknownTextData unknown{};
    ASSERT_EQ(Q3UnknownText_GetData(read[0], &unknown), kQ3Success);
    EXPECT_STREQ(unknown.objectName, "Test:Spot");
    EXPECT_STREQ(unknown.contents, "3 2 \"orphan\"");
    EXPECT_EQ(Q3UnknownText_EmptyData(&unknown), kQ3Success);
    EXPECT_EQ(writeObjects({read[0]}, kQ3FileModeText), text);
    disposeAll(read);
    // A name of no such form (a keyword Q3 has no class for) reads silently.
    read = readAll(bytesOf("3DMetafile ( 1 6 Normal )\nSpotThing ( 1 )\n"));
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(Q3Object_GetLeafType(read[0]), kQ3UnknownTypeText);
    disposeAll(read);

    // Registered again, the class reads the file the unknown object wrote.
    ASSERT_NO_FATAL_FAILURE(registerSpot());
    read = readAll(binary);
    ASSERT_EQ(read.size(), 1u);
    EXPECT_STREQ(spotOf(read[0]).label, "orphan");
    disposeAll(read);
}

TEST_F(CustomClassFileTest, AnUnregisteredObjectWithSubObjectsKeepsItsClassNameInANewFile)
{
    std::vector<unsigned char> binary, text;
    {
        TQ3Object box = keep(newBox());
        TQ3Object spot = newSpot(3.0f, 2, "parent", box);
        binary = writeObjects({spot}, kQ3FileModeNormal);
        text = writeObjects({spot}, kQ3FileModeText);
    }
    ASSERT_NO_FATAL_FAILURE(unregisterSpot());
    std::vector<TQ3Object> read;
    EXPECT_Q3_WARNING(read = readAll(text), kQ3WarningUnknownObject);
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(Q3Object_GetLeafType(read[0]), kQ3UnknownTypeText);
    // The same objects and words; an unknown text container keeps its
    // contents as one text, laid out on one line.
    EXPECT_EQ(wordsOf(writeObjects({read[0]}, kQ3FileModeText)), wordsOf(text));
    disposeAll(read);
    EXPECT_Q3_WARNING(read = readAll(binary), kQ3WarningUnknownObject);
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(Q3Object_GetLeafType(read[0]), kQ3UnknownTypeBinary);
    EXPECT_EQ(writeObjects({read[0]}, kQ3FileModeNormal), binary);

    // Written after an object of another class, which takes the type -1:
    // the unknown container's root is renumbered with the name it had.
    TQ3GeometryObject box = keep(newBox());
    const Weight weight{1.0f, 1u};
    ASSERT_EQ(Q3Shape_AddElement(box, g_weightType, &weight), kQ3Success);
    const std::vector<unsigned char> mixed = writeObjects({box, read[0]}, kQ3FileModeNormal);
    disposeAll(read);
    ASSERT_NO_FATAL_FAILURE(registerSpot());
    read = readAll(mixed);
    ASSERT_EQ(read.size(), 2u);
    EXPECT_EQ(Q3Object_GetLeafType(read[0]), kQ3GeometryTypeBox);
    ASSERT_EQ(Q3Object_GetLeafType(read[1]), m_spotType);
    EXPECT_STREQ(spotOf(read[1]).label, "parent");
    ASSERT_NE(spotOf(read[1]).child, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(spotOf(read[1]).child), kQ3GeometryTypeBox);
    disposeAll(read);
}

TEST_F(CustomClassFileTest, ATraverseMethodMayWriteNothing)
{
    g_spot.skipWrite = true;
    TQ3Object spot = newSpot(1.0f, 1, "skipped");
    TQ3Object box = keep(newBox());
    std::vector<TQ3Object> read = readAll(writeObjects({spot, box, spot}, kQ3FileModeNormal));
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(Q3Object_GetLeafType(read[0]), kQ3GeometryTypeBox);
    disposeAll(read);
}

TEST_F(CustomClassFileTest, FailingMethodsFailTheSubmitAndLeaveTheFileAsItWas)
{
    TQ3Object spot = newSpot(1.0f, 1, "bad");
    TQ3Object box = keep(newBox());
    const std::vector<unsigned char> boxOnly = writeObjects({box}, kQ3FileModeNormal);
    struct Case {
        bool SpotBehaviour::*flag;
        TQ3Error error;
    };
    const Case cases[] = {{&SpotBehaviour::failTraverse, kQ3ErrorInvalidParameter},
                          {&SpotBehaviour::failWrite, kQ3ErrorInvalidParameter},
                          {&SpotBehaviour::wrongSize, kQ3ErrorWroteLessThanSize}};
    for (const Case& c : cases) {
        g_spot = SpotBehaviour{};
        g_spot.*c.flag = true;
        const std::vector<unsigned char> bytes = writeAfterRefusal(
            [&](TQ3ViewObject view) { EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Submit(spot, view), kQ3Failure), c.error); },
            box);
        EXPECT_EQ(bytes, boxOnly);
        if (c.flag != &SpotBehaviour::failTraverse)
            EXPECT_EQ(g_spot.deletes, 1); // the data's delete method ran once
    }
    // An error the write method posts is reported with the submit's own.
    g_spot = SpotBehaviour{};
    g_spot.postFromWrite = true;
    const std::vector<unsigned char> bytes = writeAfterRefusal(
        [&](TQ3ViewObject view) {
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Submit(spot, view), kQ3Failure), kQ3ErrorInvalidParameter);
            consume(Kind::Error, kQ3ErrorOutOfMemory, "the write method's error", __FILE__, __LINE__);
        },
        box);
    EXPECT_EQ(bytes, boxOnly);
}

TEST_F(CustomClassFileTest, SubmitWriteDataOutsideATraverseMethodIsRefused)
{
    int deleted = 0;
    static int* s_deleted = nullptr;
    s_deleted = &deleted;
    TQ3XDataDeleteMethod count = [](void*) { ++*s_deleted; };
    TQ3ViewObject view = Q3View_New();
    int data = 1;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XView_SubmitWriteData(view, 4, &data, count), kQ3Failure),
                    kQ3ErrorWriteStateInactive);
    EXPECT_EQ(deleted, 1);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XView_SubmitWriteData(nullptr, 4, &data, count), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_EQ(deleted, 2);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XView_SubmitSubObjectData(view, m_weightClass, 4, &data, nullptr), kQ3Failure),
                    kQ3ErrorWriteStateInactive);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XView_SubmitSubObjectData(view, nullptr, 4, &data, count), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_EQ(deleted, 3);
    Q3Object_Dispose(view);
}

TEST_F(CustomClassFileTest, TruncatedOrFailingCustomDataFailTheRead)
{
    // The spot's data end after its size: the count is missing.
    const std::string text = "3DMetafile ( 1 6 Normal )\nTest:Spot ( 1.5 )\nBox ( 1 0 0 0 1 0 0 0 1 0 0 0 )\n";
    TQ3FileObject file = openBytes(bytesOf(text));
    ASSERT_NE(file, nullptr);
    TQ3Object object = nullptr;
    EXPECT_Q3_ERROR(object = Q3File_ReadObject(file), kQ3ErrorInvalidMetafileObject);
    consume(Kind::Error, kQ3ErrorReadMoreThanSize, "the read method's Q3Uns32_Read", __FILE__, __LINE__);
    EXPECT_EQ(object, nullptr);
    // The next read reads the box.
    object = Q3File_ReadObject(file);
    ASSERT_NE(object, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(object), kQ3GeometryTypeBox);
    Q3Object_Dispose(object);
    Q3File_Close(file);
    Q3Object_Dispose(file);

    // A read-data method that fails fails the read of its object.
    g_failReadData = true;
    const std::string withElement = "3DMetafile ( 1 6 Normal )\n"
                                    "Container ( Box ( 1 0 0 0 1 0 0 0 1 0 0 0 ) Test:Weight ( 1 2 ) )\n";
    file = openBytes(bytesOf(withElement));
    ASSERT_NE(file, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_ReadObject(file), nullptr), kQ3ErrorInvalidMetafileObject);
    Q3File_Close(file);
    Q3Object_Dispose(file);
    g_failReadData = false;
    std::vector<TQ3Object> read = readAll(bytesOf(withElement));
    ASSERT_EQ(read.size(), 1u);
    Weight back{};
    ASSERT_EQ(Q3Shape_GetElement(read[0], g_weightType, &back), kQ3Success);
    EXPECT_EQ(back.flags, 2u);
    disposeAll(read);
}

TEST_F(CustomClassFileTest, AReadMethodReadsNothingPastItsOwnObject)
{
    // The spot has no subobjects; the box after it is the file's, not the
    // spot's: the read method's end-of-container test says so.
    const std::string text = "3DMetafile ( 1 6 Normal )\nTest:Spot ( 1 2 \"x\" )\nBox ( 1 0 0 0 1 0 0 0 1 0 0 0 )\n";
    std::vector<TQ3Object> read = readAll(bytesOf(text));
    ASSERT_EQ(read.size(), 2u);
    EXPECT_EQ(spotOf(read[0]).child, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(read[1]), kQ3GeometryTypeBox);
    disposeAll(read);
}

TEST_F(CustomClassFileTest, SubObjectDataIsWrittenByItsClassAfterTheData)
{
    g_spot.subObjectData = true;
    TQ3Object spot = newSpot(1.0f, 2, "s");
    const std::vector<unsigned char> bytes = writeObjects({spot}, kQ3FileModeText);
    const std::string text = textOf(bytes);
    const std::size_t data = text.find("Test:Spot ( 1 2 \"s\" )");
    const std::size_t sub = text.find("Test:Weight ( 0.5 7 )");
    ASSERT_NE(data, std::string::npos) << text;
    ASSERT_NE(sub, std::string::npos) << text;
    EXPECT_LT(data, sub);
    EXPECT_NE(text.find("Container ("), std::string::npos);
    EXPECT_EQ(g_spot.deletes, 2); // the spot's data and the weight's
    // Binary: the sizes match what the traverse method gave.
    g_spot.deletes = 0;
    EXPECT_FALSE(writeObjects({spot}, kQ3FileModeNormal).empty());
    EXPECT_EQ(g_spot.deletes, 2);
}

TEST_F(CustomClassFileTest, AnAttachMethodGetsTheObjectWhoseContainerHoldsIt)
{
    TQ3ObjectType type = 0;
    g_tagClass = Q3XObjectHierarchy_RegisterClass(kQ3ObjectTypeShared, &type, const_cast<char*>("Test:Tag"),
                                                  tagMetaHandler, nullptr, 0, sizeof(TQ3Uns32));
    ASSERT_NE(g_tagClass, nullptr);
    g_attached = Attached{};
    const std::string text = "3DMetafile ( 1 6 Normal )\n"
                             "Container ( Box ( 1 0 0 0 1 0 0 0 1 0 0 0 ) Test:Tag ( 5 ) )\n";
    std::vector<TQ3Object> read = readAll(bytesOf(text));
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(Q3Object_GetLeafType(read[0]), kQ3GeometryTypeBox);
    EXPECT_EQ(g_attached.calls, 1);
    EXPECT_EQ(g_attached.parentType, kQ3GeometryTypeBox);
    EXPECT_EQ(g_attached.value, 5u);
    disposeAll(read);

    // A class without an attach method: left out with a warning.
    const std::string spotInBox = "3DMetafile ( 1 6 Normal )\n"
                                  "Container ( Box ( 1 0 0 0 1 0 0 0 1 0 0 0 ) Test:Spot ( 1 2 \"x\" ) )\n";
    EXPECT_Q3_WARNING(read = readAll(bytesOf(spotInBox)), kQ3WarningNoAttachMethod);
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(Q3Object_GetLeafType(read[0]), kQ3GeometryTypeBox);
    disposeAll(read);
    EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(g_tagClass), kQ3Success);
    g_tagClass = nullptr;
}

TEST_F(CustomClassFileTest, SubObjectElementDataComesBackToTheReadMethodAsASet)
{
    g_spot.subObjectData = true; // the traverse method submits a Test:Weight ( 0.5 7 )
    for (TQ3FileMode mode : kModes) {
        SCOPED_TRACE(mode);
        TQ3Object readBack = readOne(writeObjects({newSpot(1.0f, 2, "weighed")}, mode));
        ASSERT_NE(readBack, nullptr);
        const Spot& back = spotOf(readBack);
        EXPECT_TRUE(back.hasWeight);
        EXPECT_EQ(back.weight.weight, 0.5f);
        EXPECT_EQ(back.weight.flags, 7u);
        EXPECT_EQ(back.child, nullptr); // the set was no child
    }
}

TEST_F(CustomClassFileTest, AnAttributeSetSubObjectComesBackAsAnAttributeSet)
{
    TQ3AttributeSet set = keep(Q3AttributeSet_New());
    const TQ3ColorRGB red{1.0f, 0.0f, 0.0f};
    ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &red), kQ3Success);
    const Weight inSet{2.0f, 9u};
    ASSERT_EQ(Q3AttributeSet_Add(set, g_weightType, &inSet), kQ3Success);
    TQ3Object spot = newSpot(1.0f, 1, "coloured", set);
    for (TQ3FileMode mode : {kQ3FileModeNormal, kQ3FileModeText}) {
        SCOPED_TRACE(mode);
        TQ3Object readBack = readOne(writeObjects({spot}, mode));
        ASSERT_NE(readBack, nullptr);
        TQ3Object child = spotOf(readBack).child;
        ASSERT_NE(child, nullptr);
        EXPECT_EQ(Q3Object_GetLeafType(child), kQ3SetTypeAttribute);
        TQ3ColorRGB color{};
        ASSERT_EQ(Q3AttributeSet_Get(child, kQ3AttributeTypeDiffuseColor, &color), kQ3Success);
        EXPECT_EQ(color.r, 1.0f);
        EXPECT_EQ(color.g, 0.0f);
        Weight weight{};
        ASSERT_EQ(Q3AttributeSet_Get(child, g_weightType, &weight), kQ3Success);
        EXPECT_EQ(weight.weight, 2.0f);
        EXPECT_EQ(weight.flags, 9u);
    }
}

TEST_F(CustomClassFileTest, ElementsAddedToACustomObjectRoundTrip)
{
    TQ3Object spot = newSpot(1.0f, 4, "tagged");
    const Weight weight{3.5f, 11u};
    ASSERT_EQ(Q3Object_AddElement(spot, g_weightType, &weight), kQ3Success);
    ASSERT_EQ(CENameElement_SetData(spot, "the spot"), kQ3Success);
    for (TQ3FileMode mode : kModes) {
        SCOPED_TRACE(mode);
        const std::vector<unsigned char> bytes = writeObjects({spot}, mode);
        // A read method that leaves the elements: they are its object's.
        g_spot.leaveElements = true;
        TQ3Object readBack = readOne(bytes);
        ASSERT_NE(readBack, nullptr);
        EXPECT_FALSE(spotOf(readBack).hasWeight);
        Weight back{};
        ASSERT_EQ(Q3Object_GetElement(readBack, g_weightType, &back), kQ3Success);
        EXPECT_EQ(back.weight, 3.5f);
        EXPECT_EQ(back.flags, 11u);
        char* name = nullptr;
        ASSERT_EQ(CENameElement_GetData(readBack, &name), kQ3Success);
        ASSERT_NE(name, nullptr);
        EXPECT_STREQ(name, "the spot");
        EXPECT_EQ(CENameElement_EmptyData(&name), kQ3Success);
        // A read method that reads them gets each as a set.
        g_spot.leaveElements = false;
        readBack = readOne(bytes);
        ASSERT_NE(readBack, nullptr);
        EXPECT_TRUE(spotOf(readBack).hasWeight);
        EXPECT_EQ(spotOf(readBack).weight.flags, 11u);
        EXPECT_EQ(Q3Object_ContainsElement(readBack, g_weightType), kQ3False);
    }
}

TEST_F(CustomClassFileTest, AnElementReadOnItsOwnIsASetHoldingIt)
{
    const std::string text = "3DMetafile ( 1 6 Normal )\nTest:Weight ( 0.75 3 )\n";
    TQ3FileObject file = openBytes(bytesOf(text));
    ASSERT_NE(file, nullptr);
    EXPECT_EQ(Q3File_GetNextObjectType(file), g_weightType);
    TQ3Object set = Q3File_ReadObject(file);
    ASSERT_NE(set, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(set), kQ3SharedTypeSet);
    Weight back{};
    ASSERT_EQ(Q3Set_Get(set, g_weightType, &back), kQ3Success);
    EXPECT_EQ(back.weight, 0.75f);
    EXPECT_EQ(back.flags, 3u);
    Q3Object_Dispose(set);
    EXPECT_EQ(Q3File_IsEndOfFile(file), kQ3True);
    Q3File_Close(file);
    Q3Object_Dispose(file);

    // Truncated element data fail the read; the file goes on after it.
    const std::string truncated =
        "3DMetafile ( 1 6 Normal )\nTest:Weight ( 0.75 )\nBox ( 1 0 0 0 1 0 0 0 1 0 0 0 )\n";
    file = openBytes(bytesOf(truncated));
    ASSERT_NE(file, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_ReadObject(file), nullptr), kQ3ErrorInvalidMetafileObject);
    consume(Kind::Error, kQ3ErrorReadMoreThanSize, "the read-data method's Q3Uns32_Read", __FILE__, __LINE__);
    TQ3Object box = Q3File_ReadObject(file);
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(box), kQ3GeometryTypeBox);
    Q3Object_Dispose(box);
    Q3File_Close(file);
    Q3Object_Dispose(file);
}

// Test:Versioned's file version, which its metahandler answers.
TQ3FileVersion g_fileVersion = 0;

TQ3XFunctionPointer versionedMetaHandler(TQ3XMethodType type)
{
    if (type == kQ3XMethodTypeObjectFileVersion)
        return reinterpret_cast<TQ3XFunctionPointer>(static_cast<std::uintptr_t>(g_fileVersion));
    return spotMetaHandler(type);
}

TEST_F(CustomClassFileTest, AClassFileVersionNewerThanQ3sFilesIsRefused)
{
    EXPECT_EQ(kQ3XMethodTypeObjectFileVersion, Q3_METHOD_TYPE('v', 'e', 'r', 's'));
    char name[] = "Test:Versioned";
    // 1.7, and a major version past 1: 3DMF formats Q3's 1.6 files cannot carry.
    for (TQ3FileVersion newer : {TQ3FileVersion(Q3FileVersion(1, 7)), TQ3FileVersion(Q3FileVersion(2, 0))}) {
        g_fileVersion = newer;
        TQ3ObjectType type = 77;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_RegisterClass(kQ3SharedTypeShape, &type, name,
                                                                   versionedMetaHandler, nullptr, 0, sizeof(Spot)),
                                  nullptr),
                        kQ3ErrorInvalidParameter);
        EXPECT_EQ(type, 77);
        EXPECT_EQ(Q3ObjectHierarchy_IsNameRegistered(name), kQ3False);
    }
    // The current version and older ones register, and their objects
    // round-trip through text and binary files.
    for (TQ3FileVersion version : {TQ3FileVersion(kQ3FileVersionCurrent), TQ3FileVersion(Q3FileVersion(1, 5))}) {
        g_fileVersion = version;
        TQ3ObjectType type = 0;
        TQ3XObjectClass versioned = Q3XObjectHierarchy_RegisterClass(kQ3SharedTypeShape, &type, name,
                                                                     versionedMetaHandler, nullptr, 0, sizeof(Spot));
        ASSERT_NE(versioned, nullptr);
        Spot data{};
        data.size = 1.0f;
        data.count = version & 0xFFFF;
        TQ3Object object = Q3XObjectHierarchy_NewObject(versioned, &data);
        ASSERT_NE(object, nullptr);
        for (TQ3FileMode mode : {kQ3FileModeNormal, kQ3FileModeText}) {
            std::vector<TQ3Object> read = readAll(writeObjects({object}, mode));
            ASSERT_EQ(read.size(), 1u);
            // Test:Versioned's read method is Test:Spot's, which makes a spot.
            EXPECT_EQ(spotOf(read[0]).count, version & 0xFFFF);
            disposeAll(read);
        }
        Q3Object_Dispose(object);
        EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(versioned), kQ3Success);
    }
}

} // namespace
