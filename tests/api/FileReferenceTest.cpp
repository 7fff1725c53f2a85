// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// External references between metafiles (Q3File_MarkAsExternalReference,
// Q3File_GetExternalReferences) and the C string objects that name their
// files; and layouts checked against Apple's 3D Metafile Reference, its MF3D
// parser headers and Quesa with bytes laid out here by hand, not by Q3's
// writer: DisplayGroupState, Caps, TriMesh AttributeArray, Marker RawData.

#include "FileTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DString.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace q3test;

namespace {

class FileReferenceTest : public Q3ApiTest {};

std::string tempPath(const char* name)
{
    return ::testing::TempDir() + "q3_xref_" + name;
}

void writeFile(const std::string& path, const std::vector<unsigned char>& bytes)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

TQ3Object makeBox(float size)
{
    TQ3BoxData data{};
    data.origin = {1, 2, 3};
    data.orientation = {0, 0, size};
    data.majorAxis = {size, 0, 0};
    data.minorAxis = {0, size, 0};
    return Q3Box_New(&data);
}

/// A 32-bit field of a binary file in its byte order.
std::uint32_t word32(const std::vector<unsigned char>& bytes, std::size_t at, bool little)
{
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i)
        v |= std::uint32_t{bytes.at(at + i)} << (little ? 8 * i : 24 - 8 * i);
    return v;
}

/// The object types a written file's table of contents gives its entries,
/// keyed by what starts at each entry's location: for a binary file, the
/// type found there (a Container's first child's type for a container); for
/// a text file, the first object name after the entry's label. Fails the
/// test when the table's entries carry no types (entry type 0).
std::map<std::string, std::string> tocTypes(const std::vector<unsigned char>& file)
{
    std::map<std::string, std::string> out;
    const std::string text(file.begin(), file.end());
    if (text.compare(0, 10, "3DMetafile") == 0) {
        const std::size_t table = text.find("toc: TableOfContents (");
        EXPECT_NE(table, std::string::npos) << text;
        if (table == std::string::npos)
            return out;
        unsigned long next = 0, seed = 0, entryType = 9, entrySize = 0, entries = 0;
        int typeSeed = 0;
        std::size_t at = table + std::strlen("toc: TableOfContents (");
        std::istringstream in(text.substr(at));
        in >> next >> seed >> typeSeed >> entryType >> entrySize >> entries;
        EXPECT_EQ(entryType, 1u);
        EXPECT_EQ(entrySize, 16u);
        for (unsigned long i = 0; i < entries; ++i) {
            unsigned long id = 0;
            std::string label, type;
            in >> id >> label >> type;
            label.pop_back(); // "name>"
            const std::size_t labelled = text.find(label + ": ");
            EXPECT_NE(labelled, std::string::npos) << label;
            std::istringstream object(text.substr(labelled + label.size() + 2));
            std::string first, paren, child;
            object >> first >> paren >> child;
            out[first == "Container" ? child : first] = type;
        }
        return out;
    }
    const bool little = file.at(0) == 'F';
    const std::size_t table = word32(file, little ? 16 : 20, little);
    const auto tag = [&](std::size_t at) {
        std::string t(file.begin() + static_cast<long>(at), file.begin() + static_cast<long>(at) + 4);
        if (little)
            t = std::string(t.rbegin(), t.rend());
        return t;
    };
    EXPECT_EQ(tag(table), "toc ");
    EXPECT_EQ(word32(file, table + 8 + 16, little), 1u);  // entry type
    EXPECT_EQ(word32(file, table + 8 + 20, little), 16u); // entry size
    const std::uint32_t entries = word32(file, table + 8 + 24, little);
    for (std::uint32_t i = 0; i < entries; ++i) {
        const std::size_t entry = table + 8 + 28 + 16 * i;
        const std::size_t location = word32(file, entry + (little ? 4 : 8), little);
        std::string target = tag(location);
        if (target == "cntr")
            target = tag(location + 8);
        out[target] = tag(entry + 12);
    }
    return out;
}

float boxSize(TQ3Object box)
{
    TQ3BoxData data{};
    if (Q3Box_GetData(box, &data) != kQ3Success)
        return -1;
    const float size = data.majorAxis.x;
    Q3Box_EmptyData(&data);
    return size;
}

std::string stringOf(TQ3Object string)
{
    char* text = nullptr;
    if (Q3CString_GetString(string, &text) != kQ3Success)
        return "<failed>";
    std::string result(text);
    Q3CString_EmptyData(&text);
    return result;
}

// The C strings of a group, in order.
std::vector<std::string> stringsOf(TQ3GroupObject group)
{
    std::vector<std::string> result;
    TQ3GroupPosition position = nullptr;
    Q3Group_GetFirstPosition(group, &position);
    while (position != nullptr) {
        TQ3Object object = nullptr;
        Q3Group_GetPositionObject(group, position, &object);
        EXPECT_EQ(Q3Object_GetLeafType(object), kQ3StringTypeCString);
        result.push_back(stringOf(object));
        Q3Object_Dispose(object);
        Q3Group_GetNextPosition(group, &position);
    }
    return result;
}

// A file E on disk whose table of contents lists a box (submitted twice, so
// the second is a reference to the first, ID 1); E open for reading on a
// Unix path storage, its first object read into *box.
TQ3FileObject openSharedBoxFile(const std::string& path, TQ3FileMode mode, TQ3Object* box)
{
    TQ3Object original = makeBox(4);
    writeFile(path, writeObjects({original, original}, mode));
    Q3Object_Dispose(original);
    TQ3StorageObject storage = Q3UnixPathStorage_New(path.c_str());
    TQ3FileObject file = Q3File_New();
    Q3File_SetStorage(file, storage);
    Q3Object_Dispose(storage);
    TQ3FileMode opened = 0;
    EXPECT_EQ(Q3File_OpenRead(file, &opened), kQ3Success);
    *box = Q3File_ReadObject(file);
    return file;
}

} // namespace

// ---- C string objects (QD3DString.h) ----------------------------------------

TEST_F(FileReferenceTest, CStringObjectsHoldACopyOfTheirText)
{
    char text[] = "model.3dmf";
    TQ3StringObject string = Q3CString_New(text);
    ASSERT_NE(string, nullptr);
    text[0] = 'X'; // the object holds a copy
    EXPECT_EQ(Q3String_GetType(string), kQ3StringTypeCString);
    EXPECT_EQ(Q3Object_IsType(string, kQ3SharedTypeString), kQ3True);
    unsigned long length = 0;
    EXPECT_EQ(Q3CString_GetLength(string, &length), kQ3Success);
    EXPECT_EQ(length, 10u);
    EXPECT_EQ(stringOf(string), "model.3dmf");
    EXPECT_EQ(Q3CString_SetString(string, ""), kQ3Success);
    EXPECT_EQ(Q3CString_GetLength(string, &length), kQ3Success);
    EXPECT_EQ(length, 0u);
    EXPECT_EQ(stringOf(string), "");
    TQ3Object copy = Q3Object_Duplicate(string);
    EXPECT_EQ(Q3CString_SetString(string, "other"), kQ3Success);
    EXPECT_EQ(stringOf(copy), "");
    char* none = nullptr;
    EXPECT_EQ(Q3CString_EmptyData(&none), kQ3Success);
    EXPECT_EQ(none, nullptr);
    Q3Object_Dispose(copy);
    Q3Object_Dispose(string);
}

TEST_F(FileReferenceTest, CStringCallsRefuseBadInput)
{
    TQ3StringObject string = Q3CString_New("kept");
    TQ3FileObject notAString = Q3File_New();
    unsigned long length = 99;
    char* text = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3CString_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3CString_GetLength(nullptr, &length), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3CString_GetLength(string, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3CString_GetLength(notAString, &length), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(length, 99u);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3CString_SetString(string, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3CString_SetString(notAString, "x"), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3CString_GetString(string, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3CString_GetString(notAString, &text), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(text, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3CString_EmptyData(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3String_GetType(notAString), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(stringOf(string), "kept");
    Q3Object_Dispose(notAString);
    Q3Object_Dispose(string);
}

// ---- External references ----------------------------------------------------

TEST_F(FileReferenceTest, ExternalReferenceCallsRefuseBadInput)
{
    const std::string path = tempPath("bad_input.3dmf");
    TQ3Object box = nullptr;
    TQ3FileObject file = openSharedBoxFile(path, kQ3FileModeNormal, &box);
    ASSERT_NE(box, nullptr);
    TQ3FileObject closed = Q3File_New();
    TQ3Object notShared = Q3View_New();
    TQ3Object notFromFile = makeBox(1);

    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_MarkAsExternalReference(nullptr, box), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_MarkAsExternalReference(box, box), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_MarkAsExternalReference(closed, box), kQ3Failure), kQ3ErrorFileNotOpen);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_MarkAsExternalReference(file, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_MarkAsExternalReference(file, notShared), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_MarkAsExternalReference(file, notFromFile), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_GetExternalReferences(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_GetExternalReferences(box), nullptr), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_GetExternalReferences(closed), nullptr), kQ3ErrorFileNotOpen);
    // A file without external references: NULL, and no error.
    EXPECT_EQ(Q3File_GetExternalReferences(file), nullptr);

    // The same file read from memory cannot name itself by path.
    std::ifstream in(path, std::ios::binary);
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    TQ3FileObject memory = openBytes(bytes);
    ASSERT_NE(memory, nullptr);
    TQ3Object fromMemory = Q3File_ReadObject(memory);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_MarkAsExternalReference(memory, fromMemory), kQ3Failure),
                    kQ3ErrorInvalidParameter);

    // Nothing was marked: the box is written whole.
    const auto written = writeObjects({box}, kQ3FileModeText);
    const std::string text(written.begin(), written.end());
    EXPECT_EQ(text.find("ExternalReference"), std::string::npos) << text;
    EXPECT_NE(text.find("Box"), std::string::npos) << text;

    Q3Object_Dispose(fromMemory);
    Q3File_Close(memory);
    Q3Object_Dispose(memory);
    Q3Object_Dispose(notFromFile);
    Q3Object_Dispose(notShared);
    Q3Object_Dispose(closed);
    Q3Object_Dispose(box);
    Q3File_Close(file);
    Q3Object_Dispose(file);
    std::remove(path.c_str());
}

TEST_F(FileReferenceTest, AMarkedObjectIsWrittenAsAnExternalReferenceAndReadBackFromItsFile)
{
    for (TQ3FileMode sourceMode : {TQ3FileMode(kQ3FileModeNormal), TQ3FileMode(kQ3FileModeText)}) {
        const std::string path = tempPath(sourceMode ? "source.txt.3dmf" : "source.bin.3dmf");
        TQ3Object box = nullptr;
        TQ3FileObject source = openSharedBoxFile(path, sourceMode, &box);
        ASSERT_NE(box, nullptr);
        ASSERT_EQ(Q3File_MarkAsExternalReference(source, box), kQ3Success);

        for (TQ3FileMode mode : {TQ3FileMode(kQ3FileModeNormal), TQ3FileMode(kQ3FileModeText),
                                 TQ3FileMode(kQ3FileModeSwap)}) {
            TQ3Object group = Q3DisplayGroup_New();
            Q3Group_AddObject(group, box);
            const auto written = writeObjects({box, group}, mode);
            Q3Object_Dispose(group);
            const std::string text(written.begin(), written.end());
            if (mode & kQ3FileModeText) {
                EXPECT_NE(text.find("ExternalReference ( 1 )"), std::string::npos) << text;
                EXPECT_EQ(text.find("Box"), std::string::npos) << text;
            } else {
                EXPECT_NE(text.find(mode & kQ3FileModeSwap ? "xefr" : "rfex"), std::string::npos);
                EXPECT_EQ(text.find(mode & kQ3FileModeSwap ? " xob" : "box "), std::string::npos);
            }
            EXPECT_NE(text.find(path), std::string::npos);
            // The reference is written once (the group's member refers to
            // it) and its table of contents entry says it is one, as the
            // 3D Metafile Reference requires of a file holding external
            // references.
            const auto types = tocTypes(written);
            const std::string external = (mode & kQ3FileModeText) ? "ExternalReference" : "rfex";
            ASSERT_EQ(types.count(external), 1u) << text;
            EXPECT_EQ(types.at(external), external);

            TQ3FileObject target = openBytes(written);
            ASSERT_NE(target, nullptr);
            TQ3GroupObject references = Q3File_GetExternalReferences(target);
            ASSERT_NE(references, nullptr);
            EXPECT_EQ(stringsOf(references), (std::vector<std::string>{path}));
            Q3Object_Dispose(references);
            TQ3Object first = Q3File_ReadObject(target);
            ASSERT_NE(first, nullptr);
            EXPECT_EQ(Q3Object_GetLeafType(first), kQ3GeometryTypeBox);
            EXPECT_EQ(boxSize(first), 4.0f);
            TQ3Object second = Q3File_ReadObject(target);
            ASSERT_NE(second, nullptr);
            unsigned long count = 0;
            Q3Group_CountObjectsOfType(second, kQ3GeometryTypeBox, &count);
            EXPECT_EQ(count, 1u);
            Q3Object_Dispose(second);
            Q3Object_Dispose(first);
            Q3File_Close(target);
            Q3Object_Dispose(target);
        }

        // A stream file refers to nothing: each submit writes the reference
        // whole, and each is listed with its type.
        {
            const auto written = writeObjects({box, box}, kQ3FileModeStream | kQ3FileModeText);
            const std::string text(written.begin(), written.end());
            const std::string table = text.substr(text.find("toc: TableOfContents"));
            std::size_t listed = 0;
            for (std::size_t at = table.find("\n  ExternalReference"); at != std::string::npos;
                 at = table.find("\n  ExternalReference", at + 1))
                ++listed;
            EXPECT_EQ(listed, 2u) << text;
            EXPECT_EQ(text.find("\n  Reference ("), std::string::npos) << text;
            EXPECT_EQ(text.find("\nReference ("), std::string::npos) << text;
            TQ3FileObject target = openBytes(written);
            ASSERT_NE(target, nullptr);
            TQ3GroupObject references = Q3File_GetExternalReferences(target);
            ASSERT_NE(references, nullptr);
            EXPECT_EQ(stringsOf(references), (std::vector<std::string>{path, path}));
            Q3Object_Dispose(references);
            Q3File_Close(target);
            Q3Object_Dispose(target);
        }

        // The mark ends with the file object it was made on.
        Q3File_Close(source);
        Q3Object_Dispose(source);
        const auto after = writeObjects({box}, kQ3FileModeText);
        const std::string text(after.begin(), after.end());
        EXPECT_EQ(text.find("ExternalReference"), std::string::npos) << text;
        Q3Object_Dispose(box);
        std::remove(path.c_str());
    }
}

// "Suppose E is a metafile that contains an object R that you wish to
// reference from another metafile M. E must have an entry to object R in its
// Table of Contents ... you can write E out in database mode" (the QD3D 1.5.4
// book): a Database file lists every shared object it writes, written once or
// not, with its type.
TEST_F(FileReferenceTest, ADatabaseFileListsEveryObjectSoEachCanBeReferencedExternally)
{
    TQ3Object small = makeBox(1), large = makeBox(3);
    for (TQ3FileMode encoding : {TQ3FileMode(0), TQ3FileMode(kQ3FileModeText), TQ3FileMode(kQ3FileModeSwap)}) {
        const auto database = writeObjects({small, large}, kQ3FileModeDatabase | encoding);
        const auto normal = writeObjects({small, large}, kQ3FileModeNormal | encoding);
        const auto types = tocTypes(database);
        const std::string box = (encoding & kQ3FileModeText) ? "Box" : "box ";
        ASSERT_EQ(types.size(), 1u); // both entries are boxes
        EXPECT_EQ(types.at(box), box);
        const std::string text(database.begin(), database.end());
        if (encoding & kQ3FileModeText) {
            EXPECT_NE(text.find("ref1: Box"), std::string::npos) << text;
            EXPECT_NE(text.find("ref2: Box"), std::string::npos) << text;
            EXPECT_NE(text.find("\n  2 ref2>\n  Box"), std::string::npos) << text;
        }
        // A Normal file lists nothing (nothing is referred to): no table.
        const std::string plain(normal.begin(), normal.end());
        EXPECT_EQ(plain.find((encoding & kQ3FileModeText) ? "TableOfContents" : (encoding ? " cot" : "toc ")),
                  std::string::npos);
    }

    const std::string path = tempPath("database.3dmf");
    writeFile(path, writeObjects({small, large}, kQ3FileModeDatabase | kQ3FileModeText));
    TQ3StorageObject storage = Q3UnixPathStorage_New(path.c_str());
    TQ3FileObject source = Q3File_New();
    Q3File_SetStorage(source, storage);
    Q3Object_Dispose(storage);
    TQ3FileMode mode = 0;
    ASSERT_EQ(Q3File_OpenRead(source, &mode), kQ3Success);
    EXPECT_EQ(mode, TQ3FileMode(kQ3FileModeDatabase | kQ3FileModeText));
    TQ3Object first = Q3File_ReadObject(source);
    TQ3Object second = Q3File_ReadObject(source);
    ASSERT_NE(second, nullptr);
    ASSERT_EQ(Q3File_MarkAsExternalReference(source, second), kQ3Success);
    const auto written = writeObjects({second}, kQ3FileModeNormal | kQ3FileModeText);
    const std::string text(written.begin(), written.end());
    EXPECT_NE(text.find("ExternalReference ( 2 )"), std::string::npos) << text;
    TQ3FileObject target = openBytes(written);
    ASSERT_NE(target, nullptr);
    TQ3Object again = Q3File_ReadObject(target);
    ASSERT_NE(again, nullptr);
    EXPECT_EQ(boxSize(again), 3.0f);
    Q3Object_Dispose(again);
    Q3File_Close(target);
    Q3Object_Dispose(target);
    Q3Object_Dispose(first);
    Q3Object_Dispose(second);
    Q3File_Close(source);
    Q3Object_Dispose(source);
    Q3Object_Dispose(small);
    Q3Object_Dispose(large);
    std::remove(path.c_str());
}

TEST_F(FileReferenceTest, ARelativeExternalReferenceStartsAtTheReadingFilesDirectory)
{
    const std::string source = tempPath("relative_source.3dmf");
    TQ3Object original = makeBox(2);
    writeFile(source, writeObjects({original, original}, kQ3FileModeText));
    Q3Object_Dispose(original);
    const std::string name = source.substr(source.find_last_of('/') + 1);
    const std::string target = tempPath("relative_target.3dmf");
    writeFile(target, bytesOf("3DMetafile ( 1 6 Normal )\nContainer ( ExternalReference ( 1 ) CString ( \"" + name +
                              "\" ) )\n"));
    TQ3StorageObject storage = Q3UnixPathStorage_New(target.c_str());
    TQ3FileObject file = Q3File_New();
    Q3File_SetStorage(file, storage);
    Q3Object_Dispose(storage);
    TQ3FileMode mode = 0;
    ASSERT_EQ(Q3File_OpenRead(file, &mode), kQ3Success);
    TQ3Object box = Q3File_ReadObject(file);
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(boxSize(box), 2.0f);
    Q3Object_Dispose(box);
    Q3File_Close(file);
    Q3Object_Dispose(file);
    std::remove(source.c_str());
    std::remove(target.c_str());
}

TEST_F(FileReferenceTest, MalformedExternalReferencesAreErrors)
{
    const std::string source = tempPath("malformed_source.3dmf");
    TQ3Object original = makeBox(3);
    writeFile(source, writeObjects({original, original}, kQ3FileModeNormal));
    Q3Object_Dispose(original);
    auto refer = [](const std::string& inside) {
        return bytesOf("3DMetafile ( 1 6 Normal )\nContainer ( " + inside + " )\n");
    };
    // The good one reads.
    EXPECT_EQ(readError(refer("ExternalReference ( 1 ) CString ( \"" + source + "\" )")), kQ3ErrorNone);
    // An ID the other file's table of contents lacks.
    EXPECT_READ_ERROR(refer("ExternalReference ( 7 ) CString ( \"" + source + "\" )"),
                      kQ3ErrorInvalidMetafileObject);
    // A file that is not there, a directory, an empty name, no name.
    EXPECT_READ_ERROR(refer("ExternalReference ( 1 ) CString ( \"" + tempPath("absent.3dmf") + "\" )"),
                      kQ3ErrorInvalidMetafileObject);
    EXPECT_READ_ERROR(refer("ExternalReference ( 1 ) CString ( \"" + ::testing::TempDir() + "\" )"),
                      kQ3ErrorInvalidMetafileObject);
    EXPECT_READ_ERROR(refer("ExternalReference ( 1 ) CString ( \"\" )"), kQ3ErrorInvalidMetafileObject);
    EXPECT_READ_ERROR(refer("ExternalReference ( 1 ) Box ( )"), kQ3ErrorInvalidMetafileObject);
    // Data past the ID.
    EXPECT_READ_ERROR(refer("ExternalReference ( 1 2 ) CString ( \"" + source + "\" )"),
                      kQ3ErrorInvalidMetafileObject);
    // A file whose listed object is an external reference to itself: a cycle.
    const std::string cycle = tempPath("cycle.3dmf");
    writeFile(cycle, bytesOf("3DMetafile ( 1 6 Normal toc> )\nref1: Container ( ExternalReference ( 1 ) CString ( \"" +
                             cycle + "\" ) )\ntoc: TableOfContents ( 0 2 0 0 0 1\n  1 ref1>\n)\n"));
    EXPECT_READ_ERROR(refer("ExternalReference ( 1 ) CString ( \"" + cycle + "\" )"), kQ3ErrorInvalidMetafileObject);
    std::remove(cycle.c_str());
    std::remove(source.c_str());
}

// ---- Layouts checked against the references, bytes laid by hand ------------

// DisplayGroupState (MF3D kMF3DObjDisplayGroupState): Inline 1, DoNotDraw 2,
// NoBoundingBox 4, NoBoundingSphere 8, DoNotPick 16, in a container after the
// group inside its BeginGroup.
TEST_F(FileReferenceTest, ABinaryDisplayGroupStateLaidOutAsTheReferenceSays)
{
    std::vector<unsigned char> bytes = binaryHeader();
    putTag(bytes, "bgng");
    put32(bytes, 8 + 8 + 12);
    putTag(bytes, "cntr");
    put32(bytes, 8 + 12);
    putTag(bytes, "dspg");
    put32(bytes, 0);
    putTag(bytes, "dgst");
    put32(bytes, 4);
    put32(bytes, 1 | 2 | 16);
    putTag(bytes, "endg");
    put32(bytes, 0);
    const auto objects = readAll(bytes);
    ASSERT_EQ(objects.size(), 1u);
    TQ3DisplayGroupState state = 0;
    ASSERT_EQ(Q3DisplayGroup_GetState(objects[0], &state), kQ3Success);
    EXPECT_EQ(state, TQ3DisplayGroupState(kQ3DisplayGroupStateMaskIsInline | kQ3DisplayGroupStateMaskUseBoundingBox |
                                          kQ3DisplayGroupStateMaskUseBoundingSphere |
                                          kQ3DisplayGroupStateMaskIsWritten));
    disposeAll(objects);
}

// The words: Quesa's, with the reference's "IsInline" and the "DontDraw" /
// "DontPick" Q3 wrote before also read.
TEST_F(FileReferenceTest, TextDisplayGroupStateWordsOfTheReferenceQuesaAndOlderQ3)
{
    const auto objects = readAll(bytesOf("3DMetafile ( 1 6 Normal )\n"
                                         "BeginGroup ( Container ( DisplayGroup ( ) DisplayGroupState ( IsInline | "
                                         "DoNotDraw | NoBoundingSphere ) ) )\nEndGroup ( )\n"
                                         "BeginGroup ( Container ( DisplayGroup ( ) DisplayGroupState ( Inline | "
                                         "DontDraw | DontPick | DoNotPick ) ) )\nEndGroup ( )\n"));
    ASSERT_EQ(objects.size(), 2u);
    TQ3DisplayGroupState state = 0;
    ASSERT_EQ(Q3DisplayGroup_GetState(objects[0], &state), kQ3Success);
    EXPECT_EQ(state, TQ3DisplayGroupState(kQ3DisplayGroupStateMaskIsInline | kQ3DisplayGroupStateMaskUseBoundingBox |
                                          kQ3DisplayGroupStateMaskIsPicked | kQ3DisplayGroupStateMaskIsWritten));
    ASSERT_EQ(Q3DisplayGroup_GetState(objects[1], &state), kQ3Success);
    EXPECT_EQ(state, TQ3DisplayGroupState(kQ3DisplayGroupStateMaskIsInline | kQ3DisplayGroupStateMaskUseBoundingBox |
                                          kQ3DisplayGroupStateMaskUseBoundingSphere |
                                          kQ3DisplayGroupStateMaskIsWritten));
    disposeAll(objects);
}

// Caps: a flags word after the cylinder in its container; Top 1, Bottom 2,
// Interior 4 (Quesa and QuickDraw 3D's TQ3EndCapMasks).
TEST_F(FileReferenceTest, ABinaryCapsLaidOutAsQuesaReadsIt)
{
    std::vector<unsigned char> bytes = binaryHeader();
    putTag(bytes, "cntr");
    put32(bytes, (8 + 48) + (8 + 4));
    putTag(bytes, "cyln");
    put32(bytes, 48);
    for (float v : {0.f, 0.f, 2.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 0.f})
        putFloat(bytes, v);
    putTag(bytes, "caps");
    put32(bytes, 4);
    put32(bytes, 2 | 4);
    const auto objects = readAll(bytes);
    ASSERT_EQ(objects.size(), 1u);
    TQ3CylinderData data{};
    ASSERT_EQ(Q3Cylinder_GetData(objects[0], &data), kQ3Success);
    EXPECT_EQ(data.caps, TQ3EndCap(kQ3EndCapMaskBottom | kQ3EndCapMaskInterior));
    EXPECT_EQ(data.orientation.z, 2.0f);
    Q3Cylinder_EmptyData(&data);
    disposeAll(objects);
}

// A TriMesh's AttributeArray: attributeType, a reserved 0, which array (0
// triangles), its position among them, whether a use array follows, one
// value per triangle, then one use byte per triangle.
TEST_F(FileReferenceTest, ABinaryTriMeshAttributeArrayLaidOutByHand)
{
    // withUses: the book's layout, the use bytes right after the flag;
    // without: the flag set but no use bytes, as Quesa's writer leaves it.
    // cut: values (floats) left out at the end.
    const auto file = [](bool withUses, std::uint32_t cut = 0) {
        std::vector<unsigned char> bytes = binaryHeader();
        const std::uint32_t meshSize = 24 + 4 * 3 + 3 * 12 + 28;
        const std::uint32_t arraySize = 20 + (withUses ? 4 : 0) + 4 * (12 - cut);
        putTag(bytes, "cntr");
        put32(bytes, (8 + meshSize) + (8 + arraySize));
        putTag(bytes, "tmsh");
        put32(bytes, meshSize);
        for (std::uint32_t v : {4u, 1u, 0u, 0u, 3u, 0u}) // triangles, their arrays, edges, theirs, points, theirs
            put32(bytes, v);
        for (int t = 0; t < 4; ++t) // 1-byte point indices: at most 0xFF points
            bytes.insert(bytes.end(), {0, 1, 2});
        for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
            putFloat(bytes, v);
        for (float v : {0.f, 0.f, 0.f, 1.f, 1.f, 0.f})
            putFloat(bytes, v);
        put32(bytes, 0); // isEmpty: False
        putTag(bytes, "atar");
        put32(bytes, arraySize);
        put32(bytes, kQ3AttributeTypeDiffuseColor);
        put32(bytes, 0);
        put32(bytes, 0); // triangles
        put32(bytes, 0); // the first triangle array
        put32(bytes, 1); // a use array follows, at once (before the values)
        if (withUses)
            bytes.insert(bytes.end(), {1, 0, 1, 0});
        const float values[] = {1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 1.f, 1.f, 1.f};
        for (std::uint32_t i = 0; i < 12 - cut; ++i)
            putFloat(bytes, values[i]);
        return bytes;
    };
    for (bool withUses : {true, false}) {
        SCOPED_TRACE(withUses ? "the book's layout" : "Quesa's writer");
        const auto objects = readAll(file(withUses));
        ASSERT_EQ(objects.size(), 1u);
        TQ3TriMeshData data{};
        ASSERT_EQ(Q3TriMesh_GetData(objects[0], &data), kQ3Success);
        ASSERT_EQ(data.numTriangleAttributeTypes, 1u);
        EXPECT_EQ(data.triangleAttributeTypes[0].attributeType, kQ3AttributeTypeDiffuseColor);
        const auto* colors = static_cast<const TQ3ColorRGB*>(data.triangleAttributeTypes[0].data);
        EXPECT_EQ(colors[1].g, 1.0f);
        EXPECT_EQ(colors[2].b, 1.0f);
        EXPECT_EQ(colors[3].r, 1.0f);
        if (withUses) {
            ASSERT_NE(data.triangleAttributeTypes[0].attributeUseArray, nullptr);
            EXPECT_EQ(data.triangleAttributeTypes[0].attributeUseArray[0], 1);
            EXPECT_EQ(data.triangleAttributeTypes[0].attributeUseArray[1], 0);
            EXPECT_EQ(data.triangleAttributeTypes[0].attributeUseArray[2], 1);
        } else {
            EXPECT_EQ(data.triangleAttributeTypes[0].attributeUseArray, nullptr);
        }
        EXPECT_EQ(data.points[1].x, 1.0f);
        Q3TriMesh_EmptyData(&data);
        disposeAll(objects);
    }
    // Use bytes with values cut short fit neither layout: an error, not a guess.
    EXPECT_READ_ERROR(file(true, 2), kQ3ErrorInvalidMetafileObject);
}

// A text Marker's bitmap is RawData: 0x and two hex digits a byte, possibly
// over several tokens (as Quesa reads it); Q3 writes it so and still reads
// the one decimal number a byte it wrote before.
TEST_F(FileReferenceTest, ATextMarkerBitmapIsHexRawData)
{
    auto marker = [](const std::string& image) {
        return bytesOf("3DMetafile ( 1 6 Normal )\nMarker ( 1 2 3  -4 5  8 2 1 BigEndian " + image + " )\n");
    };
    for (const char* image : {"0xF00F", "0xf0 0x0f", "240 15"}) {
        const auto objects = readAll(marker(image));
        ASSERT_EQ(objects.size(), 1u) << image;
        TQ3MarkerData data{};
        ASSERT_EQ(Q3Marker_GetData(objects[0], &data), kQ3Success);
        EXPECT_EQ(data.xOffset, -4);
        EXPECT_EQ(data.bitmap.height, 2u);
        ASSERT_NE(data.bitmap.image, nullptr);
        EXPECT_EQ(data.bitmap.image[0], 0xF0) << image;
        EXPECT_EQ(data.bitmap.image[1], 0x0F) << image;
        Q3Marker_EmptyData(&data);
        const auto written = writeObjects(objects, kQ3FileModeText);
        const std::string text(written.begin(), written.end());
        EXPECT_NE(text.find("BigEndian 0xF00F"), std::string::npos) << text;
        disposeAll(objects);
    }
    EXPECT_READ_ERROR(marker("0xF00F0F"), kQ3ErrorInvalidMetafilePrimitive); // more bytes than the bitmap
    EXPECT_READ_ERROR(marker("0xF00"), kQ3ErrorInvalidMetafilePrimitive);    // half a byte
    EXPECT_READ_ERROR(marker("0xF0"), kQ3ErrorInvalidMetafilePrimitive);     // fewer
    EXPECT_READ_ERROR(marker("0xG00F"), kQ3ErrorInvalidMetafilePrimitive);   // not hex
}

// ---- Mesh edges ('edge', MF3D's MeshEdges: nEdges, per edge two vertex
// indices; one attribute set per edge as children) ------------------------------

namespace {

// Per edge of the mesh (by its two vertex points' x + 10 y, smaller first):
// the diffuse colour's red, or -1 without a set.
std::map<std::pair<float, float>, float> edgeReds(TQ3Object mesh)
{
    std::map<std::pair<float, float>, float> reds;
    TQ3MeshIterator iterator;
    for (TQ3MeshEdge edge = Q3Mesh_FirstMeshEdge(mesh, &iterator); edge != nullptr;
         edge = Q3Mesh_NextMeshEdge(&iterator)) {
        TQ3MeshVertex a = nullptr, b = nullptr;
        Q3Mesh_GetEdgeVertices(mesh, edge, &a, &b);
        TQ3Point3D pa{}, pb{};
        Q3Mesh_GetVertexCoordinates(mesh, a, &pa);
        Q3Mesh_GetVertexCoordinates(mesh, b, &pb);
        const float ka = pa.x + 10 * pa.y, kb = pb.x + 10 * pb.y;
        TQ3AttributeSet set = nullptr;
        Q3Mesh_GetEdgeAttributeSet(mesh, edge, &set);
        float red = -1;
        if (set != nullptr) {
            TQ3ColorRGB color{};
            if (Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, &color) == kQ3Success)
                red = color.r;
            Q3Object_Dispose(set);
        }
        reds[{std::min(ka, kb), std::max(ka, kb)}] = red;
    }
    return reds;
}

std::vector<unsigned char> squareWithEdges(const std::string& edges)
{
    return bytesOf("3DMetafile ( 1 6 Normal )\nContainer (\n"
                   "  Mesh ( 4  0 0 0  1 0 0  1 1 0  0 1 0  1 0  4 0 1 2 3 )\n" +
                   edges + ")\n");
}

} // namespace

TEST_F(FileReferenceTest, MeshEdgeAttributeSetsReadAndRoundTrip)
{
    const auto objects = readAll(squareWithEdges(
        "  Container ( MeshEdges ( 2  1 2  3 0 )\n"
        "    Container ( AttributeSet ( ) DiffuseColor ( 0.5 0 0 ) )\n"
        "    Container ( AttributeSet ( ) DiffuseColor ( 0.25 0 0 ) ) )\n"));
    ASSERT_EQ(objects.size(), 1u);
    const std::map<std::pair<float, float>, float> expected = {
        {{0, 1}, -1}, {{1, 11}, 0.5f}, {{10, 11}, -1}, {{0, 10}, 0.25f}};
    EXPECT_EQ(edgeReds(objects[0]), expected);
    for (TQ3FileMode mode : {TQ3FileMode(kQ3FileModeNormal), TQ3FileMode(kQ3FileModeText),
                             TQ3FileMode(kQ3FileModeSwap)}) {
        const auto back = readAll(writeObjects(objects, mode));
        ASSERT_EQ(back.size(), 1u) << mode;
        EXPECT_EQ(edgeReds(back[0]), expected) << mode;
        disposeAll(back);
    }
    disposeAll(objects);
}

TEST_F(FileReferenceTest, MalformedMeshEdgesAreErrors)
{
    const std::string set = "    Container ( AttributeSet ( ) DiffuseColor ( 1 0 0 ) )\n";
    // A vertex past the end; two vertices no side joins (a diagonal: the
    // mesh then breaks a rule, as any mesh built from the file would).
    EXPECT_READ_ERROR(squareWithEdges("  Container ( MeshEdges ( 1  1 4 )\n" + set + "  )\n"),
                      kQ3ErrorInvalidMetafileSubObject);
    EXPECT_READ_ERROR(squareWithEdges("  Container ( MeshEdges ( 1  0 2 )\n" + set + "  )\n"),
                      kQ3ErrorInvalidMetafileObject);
    // A count the data cannot hold, a count and sets that differ, no sets.
    EXPECT_READ_ERROR(squareWithEdges("  Container ( MeshEdges ( 1000000  1 2 )\n" + set + "  )\n"),
                      kQ3ErrorInvalidMetafileObject);
    EXPECT_READ_ERROR(squareWithEdges("  Container ( MeshEdges ( 2  1 2  2 3 )\n" + set + "  )\n"),
                      kQ3ErrorInvalidMetafileSubObject);
    EXPECT_READ_ERROR(squareWithEdges("  MeshEdges ( 1  1 2 )\n"), kQ3ErrorInvalidMetafileSubObject);
    // Data past the edges.
    EXPECT_READ_ERROR(squareWithEdges("  Container ( MeshEdges ( 1  1 2 3 )\n" + set + "  )\n"),
                      kQ3ErrorInvalidMetafileSubObject);
}
