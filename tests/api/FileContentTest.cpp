// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// 3DMF as Apple-era tools wrote it (issue 25): groups whose BeginGroup holds
// the group and its DisplayGroupState side by side, or whose state follows
// the BeginGroup; text files with CR, LF and CR LF line ends, booleans as
// words and keywords in any case; bytes after the last object; texture
// shaders kept in attribute sets and in TriMesh surface shader arrays,
// shared through references. The files are laid out by hand
// (tests/data/make_content_files.py) in both byte orders and three line
// ends, read, checked object by object, written back in every mode and
// read again; the malformed variants are file errors.

#include "FileTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"
#include "QD3DStyle.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>

using namespace q3test;

namespace {

class FileContentTest : public Q3ApiTest {};

std::vector<unsigned char> dataFile(const std::string& name)
{
    std::ifstream in(std::string(Q3_TEST_DATA_DIR) + "/" + name, std::ios::binary);
    EXPECT_TRUE(in.good()) << name;
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The image of a pixmap texture shader: its texture's storage bytes.
std::vector<unsigned char> imageOf(TQ3ShaderObject shader)
{
    std::vector<unsigned char> bytes;
    TQ3TextureObject texture = nullptr;
    EXPECT_EQ(Q3TextureShader_GetTexture(shader, &texture), kQ3Success);
    if (texture == nullptr)
        return bytes;
    EXPECT_EQ(Q3Texture_GetType(texture), kQ3TextureTypePixmap);
    TQ3StoragePixmap pixmap{};
    if (Q3PixmapTexture_GetPixmap(texture, &pixmap) == kQ3Success) {
        EXPECT_EQ(pixmap.width, 2u);
        EXPECT_EQ(pixmap.height, 1u);
        EXPECT_EQ(pixmap.pixelType, kQ3PixelTypeRGB32);
        bytes.resize(8);
        unsigned long read = 0;
        EXPECT_EQ(Q3Storage_GetData(pixmap.image, 0, 8, bytes.data(), &read), kQ3Success);
        EXPECT_EQ(read, 8u);
        Q3Object_Dispose(pixmap.image);
    }
    Q3Object_Dispose(texture);
    return bytes;
}

const std::vector<unsigned char> kRedGreen = {0, 0xFF, 0, 0, 0, 0, 0xFF, 0};
const std::vector<unsigned char> kBlueWhite = {0, 0, 0, 0xFF, 0, 0xFF, 0xFF, 0xFF};

// The surface shader of a set (a new reference released here: the set
// keeps its own), or NULL.
TQ3ShaderObject shaderOf(TQ3AttributeSet set)
{
    if (set == nullptr || Q3AttributeSet_Contains(set, kQ3AttributeTypeSurfaceShader) != kQ3True)
        return nullptr;
    TQ3ShaderObject shader = nullptr;
    EXPECT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    Q3Object_Dispose(shader);
    return shader;
}

// Checks the model every apple_content file holds (and every copy Q3
// writes of it): an inline display group holding a TriMesh and a plain
// group holding a Triangle; the TriMesh's set holds white and the red|green
// shader; its triangles' shader array holds the blue|white shader and the
// set's shader again (one object, through a reference); the Triangle's set
// refers to that same shader.
void expectAppleModel(const std::vector<TQ3Object>& objects, const std::string& what)
{
    SCOPED_TRACE(what);
    ASSERT_EQ(objects.size(), 1u);
    TQ3Object top = objects[0];
    ASSERT_EQ(Q3Object_IsType(top, kQ3GroupTypeDisplay), kQ3True);
    TQ3DisplayGroupState state = 0;
    EXPECT_EQ(Q3DisplayGroup_GetState(top, &state), kQ3Success);
    EXPECT_NE(state & kQ3DisplayGroupStateMaskIsInline, 0u);
    EXPECT_NE(state & kQ3DisplayGroupStateMaskIsDrawn, 0u);
    std::vector<TQ3Object> members = membersOf(top);
    ASSERT_EQ(members.size(), 2u);
    ASSERT_EQ(Q3Object_IsType(members[0], kQ3GeometryTypeTriMesh), kQ3True);
    ASSERT_EQ(Q3Object_GetLeafType(members[1]), kQ3ShapeTypeGroup);

    TQ3TriMeshData mesh{};
    ASSERT_EQ(Q3TriMesh_GetData(members[0], &mesh), kQ3Success);
    EXPECT_EQ(mesh.numTriangles, 2u);
    EXPECT_EQ(mesh.numPoints, 4u);
    EXPECT_EQ(mesh.bBox.isEmpty, kQ3False);
    TQ3ColorRGB white{};
    ASSERT_NE(mesh.triMeshAttributeSet, nullptr);
    EXPECT_EQ(Q3AttributeSet_Get(mesh.triMeshAttributeSet, kQ3AttributeTypeDiffuseColor, &white), kQ3Success);
    EXPECT_EQ(white.r, 1.0f);
    TQ3ShaderObject setShader = shaderOf(mesh.triMeshAttributeSet);
    ASSERT_NE(setShader, nullptr);
    EXPECT_EQ(imageOf(setShader), kRedGreen);
    ASSERT_EQ(mesh.numTriangleAttributeTypes, 1u);
    EXPECT_EQ(mesh.triangleAttributeTypes[0].attributeType, kQ3AttributeTypeSurfaceShader);
    const auto* faceShaders = static_cast<const TQ3Object*>(mesh.triangleAttributeTypes[0].data);
    ASSERT_NE(faceShaders, nullptr);
    ASSERT_NE(faceShaders[0], nullptr);
    EXPECT_EQ(imageOf(faceShaders[0]), kBlueWhite);
    EXPECT_EQ(faceShaders[1], setShader) << "a Reference gives the one object";
    ASSERT_EQ(mesh.numVertexAttributeTypes, 1u);
    EXPECT_EQ(mesh.vertexAttributeTypes[0].attributeType, kQ3AttributeTypeSurfaceUV);
    const auto* uvs = static_cast<const TQ3Param2D*>(mesh.vertexAttributeTypes[0].data);
    EXPECT_EQ(uvs[2].u, 1.0f);
    EXPECT_EQ(uvs[2].v, 1.0f);

    std::vector<TQ3Object> inner = membersOf(members[1]);
    ASSERT_EQ(inner.size(), 1u);
    EXPECT_EQ(Q3Object_IsType(inner[0], kQ3GeometryTypeTriangle), kQ3True);
    TQ3AttributeSet triangleSet = nullptr;
    EXPECT_EQ(Q3Geometry_GetAttributeSet(inner[0], &triangleSet), kQ3Success);
    EXPECT_EQ(shaderOf(triangleSet), setShader);
    if (triangleSet != nullptr)
        Q3Object_Dispose(triangleSet);
    disposeAll(inner);
    Q3TriMesh_EmptyData(&mesh);
    disposeAll(members);
}

const char* const kAppleFiles[] = {"apple_content_be.3dmf", "apple_content_le.3dmf", "apple_content_lf.3dmf",
                                   "apple_content_cr.3dmf", "apple_content_crlf.3dmf"};

TEST_F(FileContentTest, AppleLayoutsReadInEveryEncodingAndLineEnd)
{
    for (const char* name : kAppleFiles) {
        std::vector<TQ3Object> objects;
        // Each file carries bytes after its last object: read with a warning.
        EXPECT_Q3_WARNING(objects = readAll(dataFile(name)), kQ3WarningInvalidMetafileObject);
        expectAppleModel(objects, name);
        disposeAll(objects);
    }
}

TEST_F(FileContentTest, AppleModelRoundTripsInEveryModeAndKeepsSharing)
{
    std::vector<TQ3Object> original;
    EXPECT_Q3_WARNING(original = readAll(dataFile("apple_content_be.3dmf")), kQ3WarningInvalidMetafileObject);
    ASSERT_EQ(original.size(), 1u);
    const TQ3FileMode modes[] = {kQ3FileModeNormal, kQ3FileModeText, kQ3FileModeDatabase,
                                 kQ3FileModeDatabase | kQ3FileModeText};
    for (TQ3FileMode mode : modes) {
        const std::vector<unsigned char> bytes = writeObjects(original, mode);
        std::vector<TQ3Object> copy = readAll(bytes);
        expectAppleModel(copy, "written in mode " + std::to_string(mode));
        disposeAll(copy);
    }
    disposeAll(original);
}

TEST_F(FileContentTest, GroupsAreWrittenAsAppleToolsWroteThem)
{
    TQ3GroupObject group = Q3DisplayGroup_New();
    ASSERT_EQ(Q3DisplayGroup_SetState(group, kQ3DisplayGroupStateMaskIsInline | kQ3DisplayGroupStateMaskIsDrawn |
                                                 kQ3DisplayGroupStateMaskIsPicked |
                                                 kQ3DisplayGroupStateMaskIsWritten |
                                                 kQ3DisplayGroupStateMaskUseBoundingBox |
                                                 kQ3DisplayGroupStateMaskUseBoundingSphere),
              kQ3Success);
    const std::vector<unsigned char> bytes = writeObjects({group}, kQ3FileModeNormal);
    // BeginGroup of 20 bytes: DisplayGroup (size 0), DisplayGroupState
    // (size 4, Inline), no container.
    const unsigned char expected[] = {'b', 'g', 'n', 'g', 0, 0, 0, 20, 'd', 's', 'p', 'g', 0, 0, 0, 0,
                                      'd', 'g', 's', 't', 0, 0, 0, 4,  0,   0,   0,   1};
    const std::vector<unsigned char> want(std::begin(expected), std::end(expected));
    EXPECT_NE(std::search(bytes.begin(), bytes.end(), want.begin(), want.end()), bytes.end());
    const std::vector<unsigned char> text = writeObjects({group}, kQ3FileModeText);
    const std::string written(text.begin(), text.end());
    EXPECT_EQ(written.find("Container"), std::string::npos) << written;
    EXPECT_NE(written.find("DisplayGroupState ( Inline )"), std::string::npos) << written;
    Q3Object_Dispose(group);
}

TEST_F(FileContentTest, MalformedGroupsAndShaderArraysAreFileErrors)
{
    {
        TQ3FileObject file = openBytes(dataFile("bad_group_empty_be.3dmf"));
        ASSERT_NE(file, nullptr);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_ReadObject(file), nullptr), kQ3ErrorInvalidMetafileObject);
        Q3File_Close(file);
        Q3Object_Dispose(file);
    }
    {
        TQ3FileObject file = openBytes(dataFile("bad_group_nogroup_be.3dmf"));
        ASSERT_NE(file, nullptr);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_ReadObject(file), nullptr), kQ3ErrorInvalidMetafileSubObject);
        Q3File_Close(file);
        Q3Object_Dispose(file);
    }
    {
        TQ3FileObject file = openBytes(dataFile("bad_shader_array_be.3dmf"));
        ASSERT_NE(file, nullptr);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_ReadObject(file), nullptr), kQ3ErrorInvalidMetafileSubObject);
        Q3File_Close(file);
        Q3Object_Dispose(file);
    }
    // A CR-only file: the comment ends at its CR, so the error is the
    // unclosed Triangle on the next line, not an empty file.
    const std::vector<unsigned char> cr = dataFile("bad_text_comment_cr.3dmf");
    TQ3StorageObject storage = Q3MemoryStorage_New(cr.data(), static_cast<unsigned long>(cr.size()));
    TQ3FileObject file = Q3File_New();
    ASSERT_EQ(Q3File_SetStorage(file, storage), kQ3Success);
    TQ3FileMode mode = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_OpenRead(file, &mode), kQ3Failure), kQ3ErrorInvalidMetafile);
    EXPECT_NE(std::string(Q3Error_GetMessage()).find("Triangle"), std::string::npos) << Q3Error_GetMessage();
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
}

TEST_F(FileContentTest, CommentsEndAtEveryLineEnd)
{
    for (const std::string end : {"\n", "\r", "\r\n"}) {
        const std::string text = "3DMetafile ( 1 6 Normal )" + end + "# one comment" + end + "# another" + end +
                                 "Triangle ( 0 0 0  1 0 0  0 1 0 ) # after it" + end + "Point ( 1 2 3 )" + end;
        std::vector<TQ3Object> objects = readAll(bytesOf(text));
        ASSERT_EQ(objects.size(), 2u) << "line end " << static_cast<int>(end.back());
        EXPECT_EQ(Q3Object_IsType(objects[0], kQ3GeometryTypeTriangle), kQ3True);
        EXPECT_EQ(Q3Object_IsType(objects[1], kQ3GeometryTypePoint), kQ3True);
        disposeAll(objects);
    }
}

TEST_F(FileContentTest, BooleanWordsReadWhereNumbersAreStored)
{
    // The bounding box's isEmpty and an attribute array's use flag, each a
    // word (Q3 recomputes the box, so the use flag shows what was read:
    // with it on, use bytes follow the flag).
    for (const char* word : {"True", "TRUE", "true", "False", "false", "FaLsE"}) {
        const bool truth = word[0] == 'T' || word[0] == 't';
        const std::string text = std::string("3DMetafile ( 1 6 Normal )\n"
                                             "Container (\n"
                                             "  TriMesh ( 1 0 0 0 3 1  0 1 2  0 0 0  1 0 0  0 1 0  0 0 0  1 1 0  ") +
                                 word + " )\n  AttributeArray ( 5 0 2 0 " + word + (truth ? "  1 0 1" : "") +
                                 "  1 0 0  0 1 0  0 0 1 )\n)\n";
        std::vector<TQ3Object> objects = readAll(bytesOf(text));
        ASSERT_EQ(objects.size(), 1u) << word;
        TQ3TriMeshData data{};
        ASSERT_EQ(Q3TriMesh_GetData(objects[0], &data), kQ3Success);
        ASSERT_EQ(data.numVertexAttributeTypes, 1u);
        EXPECT_EQ(data.vertexAttributeTypes[0].attributeUseArray != nullptr, truth) << word;
        if (truth)
            EXPECT_EQ(data.vertexAttributeTypes[0].attributeUseArray[1], 0);
        Q3TriMesh_EmptyData(&data);
        disposeAll(objects);
    }
    // Any other word is still no number.
    EXPECT_READ_ERROR(bytesOf("3DMetafile ( 1 6 Normal )\n"
                              "TriMesh ( 1 0 0 0 3 0  0 1 2  0 0 0  1 0 0  0 1 0  0 0 0  1 1 0  Yes )\n"),
                      kQ3ErrorInvalidMetafilePrimitive);
}

TEST_F(FileContentTest, KeywordsAndEnumerationWordsReadInAnyCase)
{
    const std::string text = "3dmetafile ( 1 6 normal )\n"
                             "CONTAINER ( triangle ( 0 0 0  1 0 0  0 1 0 )\n"
                             "  container ( ATTRIBUTESET ( ) diffusecolor ( 0 1 0 ) HighLightState ( ON ) ) )\n"
                             "begingroup ( displaygroup ( ) displaygroupstate ( inline | DONOTPICK ) )\n"
                             "endgroup ( )\n";
    std::vector<TQ3Object> objects = readAll(bytesOf(text));
    ASSERT_EQ(objects.size(), 2u);
    TQ3AttributeSet set = nullptr;
    ASSERT_EQ(Q3Geometry_GetAttributeSet(objects[0], &set), kQ3Success);
    TQ3Switch highlight = kQ3Off;
    EXPECT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeHighlightState, &highlight), kQ3Success);
    EXPECT_EQ(highlight, kQ3On);
    Q3Object_Dispose(set);
    TQ3DisplayGroupState state = 0;
    EXPECT_EQ(Q3DisplayGroup_GetState(objects[1], &state), kQ3Success);
    EXPECT_NE(state & kQ3DisplayGroupStateMaskIsInline, 0u);
    EXPECT_EQ(state & kQ3DisplayGroupStateMaskIsPicked, 0u);
    disposeAll(objects);
}

TEST_F(FileContentTest, BytesAfterTheLastObjectAreIgnoredWithAWarning)
{
    std::vector<unsigned char> bytes = dataFile("apple_content_be.3dmf");
    bytes.resize(bytes.size() - 12); // without its padding: no warning
    std::vector<TQ3Object> objects = readAll(bytes);
    expectAppleModel(objects, "without padding");
    disposeAll(objects);
    // Fewer bytes than a type and a size, and junk that is no type.
    for (const std::vector<unsigned char>& junk : {std::vector<unsigned char>{1, 2, 3},
                                                   std::vector<unsigned char>{0x01, 0x02, 0x03, 0x04, 0xFF, 0xFF,
                                                                              0xFF, 0xFF, 9, 9}}) {
        std::vector<unsigned char> padded = bytes;
        padded.insert(padded.end(), junk.begin(), junk.end());
        EXPECT_Q3_WARNING(objects = readAll(padded), kQ3WarningInvalidMetafileObject);
        expectAppleModel(objects, "with junk");
        disposeAll(objects);
    }
    // An object whose type reads as one and whose size overruns the file is
    // a cut file: an error, as before.
    std::vector<unsigned char> cut = bytes;
    const unsigned char truncated[] = {'t', 'r', 'n', 'g', 0, 0, 0, 36, 0, 0};
    cut.insert(cut.end(), std::begin(truncated), std::end(truncated));
    EXPECT_READ_ERROR(cut, kQ3ErrorInvalidMetafile);
}

TEST_F(FileContentTest, UnknownElementsInAttributeSetsAreKeptAndWrittenBack)
{
    const std::string text = "3DMetafile ( 1 6 Normal )\n"
                             "Container ( Triangle ( 0 0 0  1 0 0  0 1 0 )\n"
                             "  Container ( AttributeSet ( ) DiffuseColor ( 1 0 0 ) MadeUpElement ( 7 8 9 ) ) )\n";
    std::vector<TQ3Object> objects;
    EXPECT_Q3_WARNING(objects = readAll(bytesOf(text)), kQ3WarningUnknownElementType);
    ASSERT_EQ(objects.size(), 1u);
    const std::vector<unsigned char> written = writeObjects(objects, kQ3FileModeText);
    const std::string copy(written.begin(), written.end());
    EXPECT_NE(copy.find("MadeUpElement ( 7 8 9 )"), std::string::npos) << copy;
    EXPECT_NE(copy.find("DiffuseColor"), std::string::npos) << copy;
    disposeAll(objects);
}

TEST_F(FileContentTest, AStateForAGroupThatIsNoDisplayGroupIsIgnoredWithAWarning)
{
    const std::string text = "3DMetafile ( 1 6 Normal )\n"
                             "BeginGroup ( Group ( ) DisplayGroupState ( Inline ) )\n"
                             "Point ( 0 0 0 )\n"
                             "EndGroup ( )\n";
    std::vector<TQ3Object> objects;
    EXPECT_Q3_WARNING(objects = readAll(bytesOf(text)), kQ3WarningInvalidSubObjectForObject);
    ASSERT_EQ(objects.size(), 1u);
    EXPECT_EQ(Q3Object_GetLeafType(objects[0]), kQ3ShapeTypeGroup);
    disposeAll(objects);
}

TEST_F(FileContentTest, AReferenceToAGroupGivesTheOneGroupWithItsMembers)
{
    const std::string text = "3DMetafile ( 1 6 Normal toc> )\n"
                             "shared: BeginGroup ( DisplayGroup ( ) )\n"
                             "Point ( 1 2 3 )\n"
                             "EndGroup ( )\n"
                             "BeginGroup ( Group ( ) )\n"
                             "Reference ( 1 )\n"
                             "EndGroup ( )\n"
                             "toc: TableOfContents ( 0 2 0 1 16 1\n"
                             "  1 shared>\n"
                             "  BeginGroup\n"
                             ")\n";
    std::vector<TQ3Object> objects = readAll(bytesOf(text));
    ASSERT_EQ(objects.size(), 2u);
    std::vector<TQ3Object> members = membersOf(objects[1]);
    ASSERT_EQ(members.size(), 1u);
    EXPECT_EQ(members[0], objects[0]) << "the reference gives the group read before";
    std::vector<TQ3Object> points = membersOf(objects[0]);
    ASSERT_EQ(points.size(), 1u);
    EXPECT_EQ(Q3Object_IsType(points[0], kQ3GeometryTypePoint), kQ3True);
    disposeAll(points);
    disposeAll(members);
    disposeAll(objects);
}

TEST_F(FileContentTest, OtherToolsWordsForSwitchesAndBackfacingRead)
{
    const std::string text = "3DMetafile ( 1 6 Normal )\n"
                             "BackfacingStyle ( Both )\n"
                             "Container ( Point ( 0 0 0 ) Container ( AttributeSet ( ) HighlightState ( True ) ) )\n";
    std::vector<TQ3Object> objects = readAll(bytesOf(text));
    ASSERT_EQ(objects.size(), 2u);
    TQ3BackfacingStyle backfacing = kQ3BackfacingStyleRemove;
    EXPECT_EQ(Q3BackfacingStyle_Get(objects[0], &backfacing), kQ3Success);
    EXPECT_EQ(backfacing, kQ3BackfacingStyleBoth);
    TQ3AttributeSet set = nullptr;
    ASSERT_EQ(Q3Geometry_GetAttributeSet(objects[1], &set), kQ3Success);
    TQ3Switch highlight = kQ3Off;
    EXPECT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeHighlightState, &highlight), kQ3Success);
    EXPECT_EQ(highlight, kQ3On);
    Q3Object_Dispose(set);
    disposeAll(objects);
    // A word for a choice of more than two values is still no value.
    EXPECT_READ_ERROR(bytesOf("3DMetafile ( 1 6 Normal )\nBackfacingStyle ( True )\n"),
                      kQ3ErrorInvalidMetafilePrimitive);
}

TEST_F(FileContentTest, ADisplayGroupThatIsNotWrittenIsLeftOutOfFiles)
{
    TQ3GroupObject hidden = Q3DisplayGroup_New();
    TQ3PointData data{{1, 2, 3}, nullptr};
    TQ3GeometryObject point = Q3Point_New(&data);
    ASSERT_NE(Q3Group_AddObject(hidden, point), nullptr);
    ASSERT_EQ(Q3DisplayGroup_SetState(hidden, kQ3DisplayGroupStateMaskIsDrawn | kQ3DisplayGroupStateMaskIsPicked),
              kQ3Success);
    TQ3GroupObject shown = Q3DisplayGroup_New();
    ASSERT_NE(Q3Group_AddObject(shown, point), nullptr);
    for (TQ3FileMode mode : {kQ3FileModeNormal, kQ3FileModeText}) {
        std::vector<TQ3Object> objects = readAll(writeObjects({hidden, shown}, mode));
        ASSERT_EQ(objects.size(), 1u) << "mode " << mode;
        TQ3DisplayGroupState state = 0;
        EXPECT_EQ(Q3DisplayGroup_GetState(objects[0], &state), kQ3Success);
        EXPECT_NE(state & kQ3DisplayGroupStateMaskIsWritten, 0u);
        disposeAll(objects);
    }
    Q3Object_Dispose(point);
    Q3Object_Dispose(hidden);
    Q3Object_Dispose(shown);
}

TEST_F(FileContentTest, ElementsOfAGroupQ3DoesNotKnowAreKeptAndWrittenBack)
{
    // An element of a class Q3 does not know in a group's BeginGroup, laid
    // out as Apple's name element is in Quesa's test models (which Q3 now
    // reads as a name: CustomElementApiTest): kept whole (its container,
    // with the string) and written back.
    const std::string text = "3DMetafile ( 1 6 Normal )\n"
                             "BeginGroup ( DisplayGroup ( ) DisplayGroupState ( Inline )\n"
                             "  Container ( Acme Inc.:LabelElement ( ) CString ( \"middle box\" ) ) )\n"
                             "Point ( 0 0 0 )\n"
                             "EndGroup ( )\n";
    std::vector<TQ3Object> objects;
    // Its "Vendor:Class" name is an application class's nobody registered:
    // kQ3WarningUnknownObject too, as for a binary file's Type object.
    EXPECT_Q3_WARNING(EXPECT_Q3_WARNING(objects = readAll(bytesOf(text)), kQ3WarningUnknownElementType),
                      kQ3WarningUnknownObject);
    ASSERT_EQ(objects.size(), 1u);
    TQ3GroupObject copy = Q3Object_Duplicate(objects[0]);
    ASSERT_NE(copy, nullptr);
    for (TQ3Object group : {objects[0], copy}) {
        const std::vector<unsigned char> written = writeObjects({group}, kQ3FileModeText);
        const std::string again(written.begin(), written.end());
        EXPECT_NE(again.find("CString ( \"middle box\" )"), std::string::npos) << again;
        EXPECT_NE(again.find("DisplayGroupState ( Inline )"), std::string::npos) << again;
        std::vector<TQ3Object> reread;
        EXPECT_Q3_WARNING(EXPECT_Q3_WARNING(reread = readAll(written), kQ3WarningUnknownElementType),
                          kQ3WarningUnknownObject);
        ASSERT_EQ(reread.size(), 1u);
        std::vector<TQ3Object> members = membersOf(reread[0]);
        EXPECT_EQ(members.size(), 1u);
        disposeAll(members);
        disposeAll(reread);
    }
    Q3Object_Dispose(copy);
    disposeAll(objects);
}

} // namespace
