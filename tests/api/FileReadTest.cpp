// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Reading files written by hand (tests/data): both byte orders, references,
// nested groups, unknown objects; and every kind of malformed file.

#include "FileTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DSet.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

using namespace q3test;

namespace {

class FileReadTest : public Q3ApiTest {};

std::vector<unsigned char> dataFile(const char* name)
{
    std::ifstream in(std::string(Q3_TEST_DATA_DIR) + "/" + name, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TQ3ColorRGB diffuseOf(TQ3AttributeSet set)
{
    TQ3ColorRGB color = {-1, -1, -1};
    Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, &color);
    return color;
}

} // namespace

TEST_F(FileReadTest, BigAndLittleEndianFilesReadTheSame)
{
    for (const char* name : {"triangle_be.3dmf", "triangle_le.3dmf"}) {
        SCOPED_TRACE(name);
        const auto objects = readAll(dataFile(name));
        ASSERT_EQ(objects.size(), 1u);
        TQ3TriangleData data;
        ASSERT_EQ(Q3Triangle_GetData(objects[0], &data), kQ3Success);
        EXPECT_EQ(data.vertices[0].point.x, -1.0f);
        EXPECT_EQ(data.vertices[2].point.y, 1.0f);
        EXPECT_EQ(diffuseOf(data.triangleAttributeSet).r, 1.0f);
        EXPECT_EQ(data.vertices[0].attributeSet, nullptr);
        ASSERT_NE(data.vertices[1].attributeSet, nullptr);
        EXPECT_EQ(diffuseOf(data.vertices[1].attributeSet).b, 1.0f);
        EXPECT_EQ(data.vertices[2].attributeSet, nullptr);
        Q3Triangle_EmptyData(&data);
        disposeAll(objects);
    }
}

TEST_F(FileReadTest, AReferenceGivesTheOneObjectItRefersTo)
{
    // QuickDraw 3D 1.0's table of contents entries have no object types.
    const auto untyped = readAll(dataFile("references_toc0_be.3dmf"));
    ASSERT_EQ(untyped.size(), 1u);
    TQ3GroupPosition at = nullptr;
    Q3Group_GetFirstPosition(untyped[0], &at);
    TQ3Object triangle = nullptr;
    Q3Group_GetPositionObject(untyped[0], at, &triangle);
    TQ3AttributeSet set = nullptr;
    Q3Geometry_GetAttributeSet(triangle, &set);
    EXPECT_EQ(diffuseOf(set).g, 1.0f);
    Q3Object_Dispose(set);
    Q3Object_Dispose(triangle);
    disposeAll(untyped);

    const auto objects = readAll(dataFile("references_be.3dmf"));
    ASSERT_EQ(objects.size(), 1u);
    ASSERT_EQ(Q3Object_GetLeafType(objects[0]), kQ3GroupTypeDisplay);
    unsigned long count = 0;
    Q3Group_CountObjects(objects[0], &count);
    ASSERT_EQ(count, 2u);
    TQ3GroupPosition position = nullptr;
    Q3Group_GetFirstPosition(objects[0], &position);
    TQ3Object first = nullptr, second = nullptr;
    Q3Group_GetPositionObject(objects[0], position, &first);
    Q3Group_GetNextPosition(objects[0], &position);
    Q3Group_GetPositionObject(objects[0], position, &second);
    TQ3AttributeSet a = nullptr, b = nullptr;
    Q3Geometry_GetAttributeSet(first, &a);
    Q3Geometry_GetAttributeSet(second, &b);
    EXPECT_NE(a, nullptr);
    EXPECT_EQ(a, b); // one set, shared
    EXPECT_EQ(diffuseOf(a).g, 1.0f);
    for (TQ3Object o : {first, second, a, b})
        Q3Object_Dispose(o);

    // Written again, the shared set is written once and referred to (Normal),
    // or written twice (Stream).
    const auto normal = readAll(writeObjects(objects, kQ3FileModeNormal | kQ3FileModeText));
    const auto stream = readAll(writeObjects(objects, kQ3FileModeStream | kQ3FileModeText));
    for (const auto* read : {&normal, &stream}) {
        ASSERT_EQ(read->size(), 1u);
        TQ3GroupPosition p = nullptr;
        Q3Group_GetFirstPosition((*read)[0], &p);
        Q3Group_GetPositionObject((*read)[0], p, &first);
        Q3Group_GetNextPosition((*read)[0], &p);
        Q3Group_GetPositionObject((*read)[0], p, &second);
        Q3Geometry_GetAttributeSet(first, &a);
        Q3Geometry_GetAttributeSet(second, &b);
        EXPECT_EQ(a == b, read == &normal);
        for (TQ3Object o : {first, second, a, b})
            Q3Object_Dispose(o);
    }
    std::string text;
    {
        const auto bytes = writeObjects(objects, kQ3FileModeNormal | kQ3FileModeText);
        text.assign(bytes.begin(), bytes.end());
    }
    EXPECT_NE(text.find("Reference ( 1 )"), std::string::npos) << text;
    EXPECT_NE(text.find("TableOfContents"), std::string::npos) << text;
    disposeAll(normal);
    disposeAll(stream);
    disposeAll(objects);
}

TEST_F(FileReadTest, NestedGroupsKeepTheirObjectsAndKinds)
{
    TQ3Object group = nullptr;
    {
        const auto bytes = dataFile("groups.3dmf");
        TQ3FileObject file = openBytes(bytes);
        ASSERT_NE(file, nullptr);
        EXPECT_EQ(Q3File_GetNextObjectType(file), kQ3DisplayGroupTypeOrdered);
        group = Q3File_ReadObject(file);
        // The light group cannot hold the triangle the file puts in it.
        TQ3Object lights = nullptr;
        EXPECT_Q3_WARNING(lights = Q3File_ReadObject(file), kQ3WarningInvalidObjectInGroupMetafile);
        ASSERT_NE(lights, nullptr);
        EXPECT_EQ(Q3Object_GetLeafType(lights), kQ3GroupTypeLight);
        unsigned long n = 99;
        Q3Group_CountObjects(lights, &n);
        EXPECT_EQ(n, 0u);
        Q3Object_Dispose(lights);
        EXPECT_EQ(Q3File_IsEndOfFile(file), kQ3True);
        Q3File_Close(file);
        Q3Object_Dispose(file);
    }
    ASSERT_NE(group, nullptr);
    unsigned long count = 0;
    Q3Group_CountObjects(group, &count);
    EXPECT_EQ(count, 3u);
    Q3Group_CountObjectsOfType(group, kQ3GroupTypeDisplay, &count);
    EXPECT_EQ(count, 1u);
    TQ3GroupPosition position = nullptr;
    Q3Group_GetFirstPositionOfType(group, kQ3GroupTypeDisplay, &position);
    TQ3Object inner = nullptr;
    Q3Group_GetPositionObject(group, position, &inner);
    Q3Group_CountObjects(inner, &count);
    EXPECT_EQ(count, 2u);
    Q3Object_Dispose(inner);
    Q3Object_Dispose(group);
}

TEST_F(FileReadTest, SkippingPassesOverWholeGroups)
{
    const auto bytes = dataFile("groups.3dmf");
    TQ3FileObject file = openBytes(bytes);
    ASSERT_NE(file, nullptr);
    ASSERT_EQ(Q3File_SkipObject(file), kQ3Success);
    EXPECT_EQ(Q3File_GetNextObjectType(file), kQ3GroupTypeLight);
    ASSERT_EQ(Q3File_SkipObject(file), kQ3Success);
    EXPECT_EQ(Q3File_IsEndOfFile(file), kQ3True);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_SkipObject(file), kQ3Failure), kQ3ErrorEndOfFile);
    Q3File_Close(file);
    Q3Object_Dispose(file);
}

TEST_F(FileReadTest, UnknownObjectsAreKeptAndWrittenBackUnchanged)
{
    {
        const auto objects = readAll(dataFile("unknown.3dmf"));
        ASSERT_EQ(objects.size(), 3u);
        EXPECT_EQ(Q3Object_GetLeafType(objects[1]), kQ3UnknownTypeText);
        EXPECT_EQ(Q3Unknown_GetType(objects[1]), kQ3UnknownTypeText);
        TQ3UnknownTextData text;
        ASSERT_EQ(Q3UnknownText_GetData(objects[1], &text), kQ3Success);
        EXPECT_STREQ(text.objectName, "MyPrivateThing");
        EXPECT_STREQ(text.contents, "1 2.5 \"three words here\" Nested ( 4 )");
        Q3UnknownText_EmptyData(&text);
        EXPECT_EQ(text.contents, nullptr);
        TQ3UnknownBinaryData wrong;
        EXPECT_Q3_ERROR(Q3UnknownBinary_GetData(objects[1], &wrong), kQ3ErrorInvalidObjectType);
        TQ3Boolean dirty = kQ3True;
        ASSERT_EQ(Q3Unknown_GetDirtyState(objects[1], &dirty), kQ3Success);
        EXPECT_EQ(dirty, kQ3False);
        ASSERT_EQ(Q3Unknown_SetDirtyState(objects[1], kQ3True), kQ3Success);
        Q3Unknown_GetDirtyState(objects[1], &dirty);
        EXPECT_EQ(dirty, kQ3True);
        const auto again = writeObjects(objects, kQ3FileModeStream | kQ3FileModeText);
        const std::string written(again.begin(), again.end());
        EXPECT_NE(written.find("MyPrivateThing ( 1 2.5 \"three words here\" Nested ( 4 ) )"), std::string::npos)
            << written;
        disposeAll(objects);
    }
    {
        const auto original = dataFile("unknown_be.3dmf");
        const auto objects = readAll(original);
        ASSERT_EQ(objects.size(), 3u);
        EXPECT_EQ(Q3Unknown_GetType(objects[1]), kQ3UnknownTypeBinary);
        TQ3UnknownBinaryData binary;
        ASSERT_EQ(Q3UnknownBinary_GetData(objects[1], &binary), kQ3Success);
        EXPECT_EQ(binary.objectType, static_cast<TQ3ObjectType>(Q3_OBJECT_TYPE('M', 'i', 'N', 'e')));
        EXPECT_EQ(binary.size, 8u);
        EXPECT_EQ(binary.byteOrder, kQ3EndianBig);
        EXPECT_EQ(binary.contents[7], 8);
        Q3UnknownBinary_EmptyData(&binary);
        // Written back in the same mode, the file is the same, byte for byte.
        EXPECT_EQ(writeObjects(objects, kQ3FileModeStream), original);
        disposeAll(objects);
    }
}

TEST_F(FileReadTest, UnknownBinaryObjectsHaveNoDeclaredTypeString)
{
    const auto objects = readAll(dataFile("unknown_be.3dmf"));
    ASSERT_EQ(objects.size(), 3u);
    char* typeString = reinterpret_cast<char*>(&typeString); // anything but NULL
    ASSERT_EQ(Q3UnknownBinary_GetTypeString(objects[1], &typeString), kQ3Success);
    EXPECT_EQ(typeString, nullptr);
    EXPECT_EQ(Q3UnknownBinary_EmptyTypeString(&typeString), kQ3Success);
    EXPECT_EQ(typeString, nullptr);

    // A string the caller was given is freed and cleared.
    typeString = static_cast<char*>(std::malloc(5));
    ASSERT_NE(typeString, nullptr);
    EXPECT_EQ(Q3UnknownBinary_EmptyTypeString(&typeString), kQ3Success);
    EXPECT_EQ(typeString, nullptr);

    const auto text = readAll(dataFile("unknown.3dmf"));
    ASSERT_EQ(text.size(), 3u);
    TQ3UnknownObject dead = Q3Object_Duplicate(objects[1]);
    Q3Object_Dispose(dead);
    char* kept = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3UnknownBinary_GetTypeString(nullptr, &kept), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3UnknownBinary_GetTypeString(dead, &kept), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3UnknownBinary_GetTypeString(text[1], &kept), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3UnknownBinary_GetTypeString(objects[1], nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3UnknownBinary_EmptyTypeString(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    disposeAll(objects);
    disposeAll(text);
}

TEST_F(FileReadTest, MalformedBinaryFilesAreErrorsNeverCrashes)
{
    // Truncated: a header cut short, then an object cut short.
    std::vector<unsigned char> header = binaryHeader();
    EXPECT_READ_ERROR((std::vector<unsigned char>(header.begin(), header.begin() + 10)), kQ3ErrorInvalidMetafile);
    auto truncated = binaryHeader();
    putTag(truncated, "pnt ");
    put32(truncated, 12);
    put32(truncated, 0);
    EXPECT_READ_ERROR(truncated, kQ3ErrorInvalidMetafile);

    // A size overrunning its container.
    auto overrun = binaryHeader();
    putTag(overrun, "cntr");
    put32(overrun, 16);
    putTag(overrun, "pnt ");
    put32(overrun, 12); // 16 bytes of container cannot hold 8 + 12
    for (int i = 0; i < 3; ++i)
        put32(overrun, 0);
    EXPECT_READ_ERROR(overrun, kQ3ErrorInvalidMetafile);

    // A count that would need gigabytes: refused before anything is allocated.
    auto huge = binaryHeader();
    putTag(huge, "plyg");
    put32(huge, 4 + 12);
    put32(huge, 0x7FFFFFFF);
    for (int i = 0; i < 3; ++i)
        put32(huge, 0);
    EXPECT_READ_ERROR(huge, kQ3ErrorInvalidMetafileObject);

    // An object's data shorter than its fields.
    auto shortData = binaryHeader();
    putTag(shortData, "trng");
    put32(shortData, 8);
    put32(shortData, 0);
    put32(shortData, 0);
    EXPECT_READ_ERROR(shortData, kQ3ErrorInvalidMetafilePrimitive);

    // A NaN where a number must be.
    auto nan = binaryHeader();
    putTag(nan, "pnt ");
    put32(nan, 12);
    put32(nan, 0x7FC00000);
    put32(nan, 0);
    put32(nan, 0);
    EXPECT_READ_ERROR(nan, kQ3ErrorInvalidMetafilePrimitive);

    // A reference to nothing.
    auto dangling = binaryHeader();
    putTag(dangling, "rfrn");
    put32(dangling, 4);
    put32(dangling, 7);
    EXPECT_READ_ERROR(dangling, kQ3ErrorInvalidMetafileObject);

    // A version Q3 does not read, and a mode that is none.
    auto version = binaryHeader();
    version[9] = 2;
    EXPECT_READ_ERROR(version, kQ3ErrorInvalidMetafile);
    auto badMode = binaryHeader();
    badMode[15] = 9;
    EXPECT_READ_ERROR(badMode, kQ3ErrorInvalidMetafile);

    // Containers nested past the limit.
    std::vector<unsigned char> deep = binaryHeader();
    const int levels = 300;
    for (int i = 0; i < levels; ++i) {
        putTag(deep, "cntr");
        put32(deep, static_cast<std::uint32_t>(8 * (levels - 1 - i)));
    }
    EXPECT_READ_ERROR(deep, kQ3ErrorInvalidMetafile);

    // A geometry whose data breaks its class's rules.
    auto badCurve = binaryHeader();
    putTag(badCurve, "nrbc");
    put32(badCurve, 8 + 16 * 2 + 4 * 3);
    put32(badCurve, 1); // order 1
    put32(badCurve, 2);
    for (int i = 0; i < 8 + 3; ++i)
        put32(badCurve, 0x3F800000);
    EXPECT_READ_ERROR(badCurve, kQ3ErrorInvalidMetafileObject);
}

TEST_F(FileReadTest, MalformedTextFilesAreErrorsNeverCrashes)
{
    struct Bad {
        const char* text;
        TQ3Error error;
    };
    const Bad bad[] = {
        {"", kQ3ErrorInvalidMetafile},
        {"not a metafile", kQ3ErrorInvalidMetafile},
        {"3DMetafile ( 1 6 Sideways )", kQ3ErrorInvalidMetafilePrimitive},
        {"3DMetafile ( 2 0 Normal )", kQ3ErrorInvalidMetafile},
        {"3DMetafile ( 1 6 Normal )\nPoint ( 1 2 ", kQ3ErrorInvalidMetafile},
        {"3DMetafile ( 1 6 Normal )\nPoint ( 1 2.5.5 3 )", kQ3ErrorInvalidMetafilePrimitive},
        {"3DMetafile ( 1 6 Normal )\nPoint ( 1 nan 3 )", kQ3ErrorInvalidMetafilePrimitive},
        {"3DMetafile ( 1 6 Normal )\nPoint ( 1e39 0 3 )", kQ3ErrorInvalidMetafilePrimitive},
        {"3DMetafile ( 1 6 Normal )\nPoint ( 1 2 )", kQ3ErrorInvalidMetafilePrimitive},
        {"3DMetafile ( 1 6 Normal )\n( 1 2 3 )", kQ3ErrorInvalidMetafilePrimitive},
        {"3DMetafile ( 1 6 Normal )\nPolygon ( 4000000000 0 0 0 )", kQ3ErrorInvalidMetafileObject},
        {"3DMetafile ( 1 6 Normal )\nPolyLine ( -3 0 0 0 1 1 1 )", kQ3ErrorInvalidMetafilePrimitive},
        {"3DMetafile ( 1 6 Normal )\nReference ( 3 )", kQ3ErrorInvalidMetafileObject},
        {"3DMetafile ( 1 6 Normal )\nContainer ( )", kQ3ErrorInvalidMetafileObject},
        {"3DMetafile ( 1 6 Normal )\nEndGroup ( )", kQ3ErrorInvalidMetafileObject},
        {"3DMetafile ( 1 6 Normal )\nBeginGroup ( DisplayGroup ( ) )\nPoint ( 0 0 0 )", kQ3ErrorInvalidMetafile},
        {"3DMetafile ( 1 6 Normal )\nDiffuseColor ( 1 0 0 )", kQ3ErrorInvalidMetafileObject},
        {"3DMetafile ( 1 6 Normal )\nContainer ( Point ( 0 0 0 ) Container ( AttributeSet ( ) "
         "HighlightState ( Maybe ) ) )",
         kQ3ErrorInvalidMetafilePrimitive},
        {"3DMetafile ( 1 6 Normal )\nContainer ( Triangle ( 0 0 0 1 0 0 0 1 0 ) Container ( "
         "VertexAttributeSetList ( 3 Include 1 7 ) ) )",
         kQ3ErrorInvalidMetafileSubObject},
        // A table of contents entry naming a label no object has.
        {"3DMetafile ( 1 6 Normal toc> )\nPoint ( 0 0 0 )\ntoc: TableOfContents ( 0 2 0 0 8 1 1 nowhere> )",
         kQ3ErrorInvalidMetafileLabel},
        // A reference cycle: the triangle's vertex set refers to the triangle.
        {"3DMetafile ( 1 6 Normal toc> )\ntri: Container ( Triangle ( 0 0 0 1 0 0 0 1 0 ) Container ( "
         "VertexAttributeSetList ( 3 Include 1 0 ) Reference ( 1 ) ) )\n"
         "toc: TableOfContents ( 0 2 0 0 8 1 1 tri> )",
         kQ3ErrorInvalidMetafileObject},
    };
    for (const Bad& b : bad) {
        SCOPED_TRACE(b.text);
        EXPECT_READ_ERROR(bytesOf(b.text), b.error);
    }
}

TEST_F(FileReadTest, AFailedObjectIsSkippedAndTheNextOneRead)
{
    const auto bytes = bytesOf("3DMetafile ( 1 6 Normal )\nPoint ( 1 x 3 )\nPoint ( 4 5 6 )\n");
    TQ3FileObject file = openBytes(bytes);
    ASSERT_NE(file, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_ReadObject(file), nullptr), kQ3ErrorInvalidMetafilePrimitive);
    TQ3Object point = Q3File_ReadObject(file);
    ASSERT_NE(point, nullptr);
    TQ3PointData data;
    Q3Point_GetData(point, &data);
    EXPECT_EQ(data.point.x, 4.0f);
    Q3Point_EmptyData(&data);
    Q3Object_Dispose(point);
    EXPECT_EQ(Q3File_IsEndOfFile(file), kQ3True);
    Q3File_Close(file);
    Q3Object_Dispose(file);
}

TEST_F(FileReadTest, DisplayGroupStatesRoundTrip)
{
    TQ3GroupObject group = Q3DisplayGroup_New();
    const TQ3DisplayGroupState state = kQ3DisplayGroupStateMaskIsInline | kQ3DisplayGroupStateMaskIsDrawn |
                                       kQ3DisplayGroupStateMaskUseBoundingSphere | kQ3DisplayGroupStateMaskIsWritten;
    ASSERT_EQ(Q3DisplayGroup_SetState(group, state), kQ3Success);
    for (TQ3FileMode mode : {TQ3FileMode(kQ3FileModeNormal), TQ3FileMode(kQ3FileModeText)}) {
        const auto bytes = writeObjects({group}, mode);
        if (mode & kQ3FileModeText) {
            const std::string text(bytes.begin(), bytes.end());
            EXPECT_NE(text.find("DisplayGroupState ( Inline | NoBoundingBox | DoNotPick )"), std::string::npos)
                << text;
        }
        const auto objects = readAll(bytes);
        ASSERT_EQ(objects.size(), 1u);
        TQ3DisplayGroupState back = 0;
        ASSERT_EQ(Q3DisplayGroup_GetState(objects[0], &back), kQ3Success);
        EXPECT_EQ(back, state);
        disposeAll(objects);
    }
    Q3Object_Dispose(group);
}

TEST_F(FileReadTest, LightsStylesTransformsAndTriMeshArraysFromAHandWrittenFile)
{
    const auto objects = readAll(dataFile("lights_styles.3dmf"));
    ASSERT_EQ(objects.size(), 2u);
    EXPECT_EQ(Q3Object_GetLeafType(objects[0]), kQ3GroupTypeLight);
    unsigned long n = 0;
    Q3Group_CountObjectsOfType(objects[0], kQ3ShapeTypeLight, &n);
    EXPECT_EQ(n, 2u);
    EXPECT_EQ(Q3Object_GetLeafType(objects[1]), kQ3GroupTypeDisplay);
    TQ3DisplayGroupState state = 0;
    Q3DisplayGroup_GetState(objects[1], &state);
    EXPECT_EQ(state & kQ3DisplayGroupStateMaskUseBoundingBox, 0u);
    EXPECT_NE(state & kQ3DisplayGroupStateMaskIsDrawn, 0u);
    Q3Group_CountObjects(objects[1], &n);
    EXPECT_EQ(n, 8u);
    Q3Group_CountObjectsOfType(objects[1], kQ3ShapeTypeTransform, &n);
    EXPECT_EQ(n, 3u);
    TQ3GroupPosition position = nullptr;
    Q3Group_GetFirstPositionOfType(objects[1], kQ3GeometryTypeTriMesh, &position);
    TQ3Object mesh = nullptr;
    Q3Group_GetPositionObject(objects[1], position, &mesh);
    TQ3TriMeshData data;
    ASSERT_EQ(Q3TriMesh_GetData(mesh, &data), kQ3Success);
    ASSERT_EQ(data.numTriangleAttributeTypes, 1u);
    EXPECT_EQ(data.triangleAttributeTypes[0].attributeType, kQ3AttributeTypeDiffuseColor);
    EXPECT_EQ(static_cast<const TQ3ColorRGB*>(data.triangleAttributeTypes[0].data)[1].b, 1.0f);
    ASSERT_NE(data.triangleAttributeTypes[0].attributeUseArray, nullptr);
    EXPECT_EQ(data.triangleAttributeTypes[0].attributeUseArray[1], 0);
    ASSERT_EQ(data.numVertexAttributeTypes, 1u);
    EXPECT_EQ(static_cast<const TQ3Vector3D*>(data.vertexAttributeTypes[0].data)[2].z, 0.8f);
    Q3TriMesh_EmptyData(&data);
    Q3Object_Dispose(mesh);
    disposeAll(objects);
}

// A binary light as Apple's QuickDraw 3D wrote it: a container holding the
// DirectionalLight and its LightData, tagged 'lght' (Apple's MF3D parser,
// kMF3DObjLightData). Written back, the LightData keeps that tag.
TEST_F(FileReadTest, ABinaryLightDataTaggedAsAppleTagsItKeepsTheLightsState)
{
    std::vector<unsigned char> bytes = binaryHeader();
    putTag(bytes, "cntr");
    put32(bytes, (8 + 16) + (8 + 20));
    putTag(bytes, "drct");
    put32(bytes, 16);
    putFloat(bytes, 0.0f);
    putFloat(bytes, -1.0f);
    putFloat(bytes, 0.0f);
    put32(bytes, 1); // castsShadows: True
    putTag(bytes, "lght");
    put32(bytes, 20);
    put32(bytes, 0); // isOn: False
    putFloat(bytes, 0.25f);
    putFloat(bytes, 1.0f);
    putFloat(bytes, 0.5f);
    putFloat(bytes, 0.125f);

    const auto objects = readAll(bytes);
    ASSERT_EQ(objects.size(), 1u);
    TQ3DirectionalLightData data;
    ASSERT_EQ(Q3DirectionalLight_GetData(objects[0], &data), kQ3Success);
    EXPECT_EQ(data.lightData.isOn, kQ3False);
    EXPECT_EQ(data.lightData.brightness, 0.25f);
    EXPECT_EQ(data.lightData.color.r, 1.0f);
    EXPECT_EQ(data.lightData.color.g, 0.5f);
    EXPECT_EQ(data.lightData.color.b, 0.125f);
    EXPECT_EQ(data.castsShadows, kQ3True);
    EXPECT_EQ(data.direction.y, -1.0f);

    const std::vector<unsigned char> written = writeObjects(objects, kQ3FileModeNormal);
    const std::string text(written.begin(), written.end());
    EXPECT_NE(text.find("lght"), std::string::npos);
    EXPECT_EQ(text.find("lgdt"), std::string::npos);
    disposeAll(objects);
}

TEST_F(FileReadTest, GroupsReadObjectByObjectEndWithAnEndGroupObject)
{
    const auto bytes = dataFile("groups.3dmf");
    TQ3FileObject file = openBytes(bytes);
    ASSERT_NE(file, nullptr);
    TQ3FileReadGroupState state = 99;
    ASSERT_EQ(Q3File_GetReadInGroup(file, &state), kQ3Success);
    EXPECT_EQ(state, static_cast<TQ3FileReadGroupState>(kQ3FileReadWholeGroup));
    EXPECT_Q3_ERROR(Q3File_SetReadInGroup(file, 7), kQ3ErrorInvalidParameter);
    ASSERT_EQ(Q3File_SetReadInGroup(file, kQ3FileReadObjectsInGroup), kQ3Success);
    std::vector<TQ3ObjectType> types;
    while (Q3File_IsEndOfFile(file) == kQ3False) {
        TQ3Object object = nullptr;
        if (Q3File_GetNextObjectType(file) == kQ3GroupTypeLight)
            Q3File_SetReadInGroup(file, kQ3FileReadWholeGroup);
        if (Q3File_GetNextObjectType(file) == kQ3GroupTypeLight)
            EXPECT_Q3_WARNING(object = Q3File_ReadObject(file), kQ3WarningInvalidObjectInGroupMetafile);
        else
            object = Q3File_ReadObject(file);
        ASSERT_NE(object, nullptr);
        types.push_back(Q3Object_GetLeafType(object));
        if (types.size() == 1) {
            unsigned long n = 99;
            Q3Group_CountObjects(object, &n);
            EXPECT_EQ(n, 0u);
            Q3File_GetReadInGroup(file, &state);
            EXPECT_EQ(state, static_cast<TQ3FileReadGroupState>(kQ3FileReadObjectsInGroup |
                                                                 kQ3FileCurrentlyInsideGroup));
        }
        Q3Object_Dispose(object);
    }
    const std::vector<TQ3ObjectType> expected = {
        kQ3DisplayGroupTypeOrdered, kQ3GeometryTypeTriangle, kQ3GroupTypeDisplay, kQ3GeometryTypePoint,
        kQ3GeometryTypeLine,        kQ3SharedTypeEndGroup,   kQ3GeometryTypePolygon, kQ3SharedTypeEndGroup,
        kQ3GroupTypeLight};
    EXPECT_EQ(types, expected);
    Q3File_GetReadInGroup(file, &state);
    EXPECT_EQ(state, static_cast<TQ3FileReadGroupState>(kQ3FileReadWholeGroup));
    Q3File_Close(file);
    Q3Object_Dispose(file);
}
