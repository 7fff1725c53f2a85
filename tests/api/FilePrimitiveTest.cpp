// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The primitive read and write calls (Q3Uns32_Read, ...), Q3File_IsEndOfData,
// Q3File_IsEndOfContainer and Q3File_SetIdleMethod. Expected bytes are
// spelled out by hand from the 3DMF layout (big-endian two's complement and
// IEEE 754), never taken from Q3's own output.
#include "FileTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DGeometry.h"

#include <cstring>

using namespace q3test;

namespace {

class FilePrimitiveTest : public Q3ApiTest {};

/// A file open for writing on a new memory storage.
struct Writer {
    TQ3StorageObject storage = Q3MemoryStorage_New(nullptr, 0);
    TQ3FileObject file = Q3File_New();

    explicit Writer(TQ3FileMode mode)
    {
        EXPECT_EQ(Q3File_SetStorage(file, storage), kQ3Success);
        EXPECT_EQ(Q3File_OpenWrite(file, mode), kQ3Success);
    }
    ~Writer()
    {
        Q3Object_Dispose(file);
        Q3Object_Dispose(storage);
    }
    /// Closes the file and gives its bytes.
    std::vector<unsigned char> close()
    {
        EXPECT_EQ(Q3File_Close(file), kQ3Success);
        unsigned char* buffer = nullptr;
        unsigned long size = 0;
        EXPECT_EQ(Q3MemoryStorage_GetBuffer(storage, &buffer, &size, nullptr), kQ3Success);
        return std::vector<unsigned char>(buffer, buffer + size);
    }
};

std::vector<unsigned char> header(std::uint32_t mode = 0)
{
    return {'3', 'D', 'M', 'F', 0, 0, 0, 16, 0, 1, 0, 6, 0, 0, 0, static_cast<unsigned char>(mode), 0, 0, 0, 0,
            0, 0, 0, 0};
}

struct Counter {
    int calls = 0;
    int failAt = 0; ///< the call that returns kQ3Failure (0: none)
};

TQ3Status countingIdle(TQ3FileObject, const void* data)
{
    Counter* counter = const_cast<Counter*>(static_cast<const Counter*>(data));
    ++counter->calls;
    return counter->calls == counter->failAt ? kQ3Failure : kQ3Success;
}

// Reads one value with `read` and checks that it is `expected`.
template <class T, class Expected>
void expectRead(TQ3Status (*read)(T*, TQ3FileObject), TQ3FileObject file, Expected expected, const char* what)
{
    T value{};
    ASSERT_EQ(read(&value, file), kQ3Success) << what;
    EXPECT_EQ(value, expected) << what;
}

// Reads one 64-bit value with `read` and checks its two halves.
template <class T, class Hi, class Lo>
void expectReadHalves(TQ3Status (*read)(T*, TQ3FileObject), TQ3FileObject file, Hi hi, Lo lo, const char* what)
{
    T value{};
    ASSERT_EQ(read(&value, file), kQ3Success) << what;
    EXPECT_EQ(value.hi, hi) << what;
    EXPECT_EQ(value.lo, lo) << what;
}

TQ3GeometryObject newPoint(float x)
{
    const TQ3PointData data = {{x, 0, 0}, nullptr};
    return Q3Point_New(&data);
}

} // namespace

TEST_F(FilePrimitiveTest, BinaryObjectWrittenByHandHasTheExpectedBytesAndReadsBack)
{
    Writer out(kQ3FileModeNormal);
    ASSERT_EQ(Q3Uns32_Write(Q3_OBJECT_TYPE('c', 'u', 's', 't'), out.file), kQ3Success);
    ASSERT_EQ(Q3Uns32_Write(64, out.file), kQ3Success); // the size of the data below
    ASSERT_EQ(Q3Uns32_Write(7, out.file), kQ3Success);
    ASSERT_EQ(Q3Int16_Write(-2, out.file), kQ3Success);
    ASSERT_EQ(Q3Int8_Write(-3, out.file), kQ3Success);
    ASSERT_EQ(Q3Uns8_Write(200, out.file), kQ3Success);
    ASSERT_EQ(Q3Float32_Write(1.5f, out.file), kQ3Success);
    ASSERT_EQ(Q3Float64_Write(-2.25, out.file), kQ3Success);
    TQ3Uns64 u64;
    u64.hi = 1;
    u64.lo = 2;
    ASSERT_EQ(Q3Uns64_Write(u64, out.file), kQ3Success);
    TQ3Int64 i64;
    i64.hi = -1;
    i64.lo = 0xFFFFFFFBul; // -5
    ASSERT_EQ(Q3Int64_Write(i64, out.file), kQ3Success);
    ASSERT_EQ(Q3String_Write("hi", out.file), kQ3Success);
    const unsigned char raw[3] = {0xAA, 0xBB, 0xCC};
    ASSERT_EQ(Q3RawData_Write(raw, 3, out.file), kQ3Success);
    const TQ3Point3D point = {1, 2, 3};
    ASSERT_EQ(Q3Point3D_Write(&point, out.file), kQ3Success);
    const TQ3Vector2D vector = {0.5f, -0.5f};
    ASSERT_EQ(Q3Vector2D_Write(&vector, out.file), kQ3Success);
    ASSERT_EQ(Q3Comment_Write(const_cast<char*>("not in binary"), out.file), kQ3Success);
    ASSERT_EQ(Q3NewLine_Write(out.file), kQ3Success);
    const std::vector<unsigned char> bytes = out.close();

    std::vector<unsigned char> expected = header();
    const unsigned char body[] = {
        'c', 'u', 's', 't', 0, 0, 0, 64,                 // type, size
        0, 0, 0, 7,                                      // Uns32 7
        0xFF, 0xFE, 0xFD, 200,                           // Int16 -2, Int8 -3, Uns8 200
        0x3F, 0xC0, 0, 0,                                // Float32 1.5
        0xC0, 0x02, 0, 0, 0, 0, 0, 0,                    // Float64 -2.25
        0, 0, 0, 1, 0, 0, 0, 2,                          // Uns64 hi 1 lo 2
        0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFB,  // Int64 -5
        'h', 'i', 0, 0,                                  // String, padded
        0xAA, 0xBB, 0xCC, 0,                             // RawData, padded
        0x3F, 0x80, 0, 0, 0x40, 0, 0, 0, 0x40, 0x40, 0, 0, // Point3D 1 2 3
        0x3F, 0, 0, 0, 0xBF, 0, 0, 0};                   // Vector2D 0.5 -0.5
    static_assert(sizeof body == 72, "8 bytes of type and size, 64 of data");
    expected.insert(expected.end(), body, body + sizeof body);
    ASSERT_EQ(bytes, expected);

    TQ3FileObject file = openBytes(bytes);
    ASSERT_NE(file, nullptr);
    EXPECT_EQ(Q3File_GetNextObjectType(file), kQ3ShapeTypeUnknown);
    EXPECT_EQ(Q3File_IsEndOfData(file), kQ3False);
    expectRead(Q3Uns32_Read, file, 7u, "Q3Uns32_Read");
    expectRead(Q3Int16_Read, file, -2, "Q3Int16_Read");
    expectRead(Q3Int8_Read, file, -3, "Q3Int8_Read");
    expectRead(Q3Uns8_Read, file, 200, "Q3Uns8_Read");
    expectRead(Q3Float32_Read, file, 1.5f, "Q3Float32_Read");
    expectRead(Q3Float64_Read, file, -2.25, "Q3Float64_Read");
    expectReadHalves(Q3Uns64_Read, file, 1ul, 2ul, "Q3Uns64_Read");
    expectReadHalves(Q3Int64_Read, file, -1, 0xFFFFFFFBul, "Q3Int64_Read");
    unsigned long length = 0;
    ASSERT_EQ(Q3String_Read(nullptr, &length, file), kQ3Success); // peeks
    EXPECT_EQ(length, 2ul);
    char text[kQ3StringMaximumLength];
    ASSERT_EQ(Q3String_Read(text, &length, file), kQ3Success);
    EXPECT_STREQ(text, "hi");
    unsigned char rawIn[3] = {};
    ASSERT_EQ(Q3RawData_Read(rawIn, 3, file), kQ3Success);
    EXPECT_EQ(std::memcmp(rawIn, raw, 3), 0);
    TQ3Point3D pointIn = {};
    ASSERT_EQ(Q3Point3D_Read(&pointIn, file), kQ3Success);
    EXPECT_EQ(pointIn.z, 3.0f);
    EXPECT_EQ(Q3File_IsEndOfData(file), kQ3False);
    TQ3Vector2D vectorIn = {};
    ASSERT_EQ(Q3Vector2D_Read(&vectorIn, file), kQ3Success);
    EXPECT_EQ(vectorIn.y, -0.5f);
    EXPECT_EQ(Q3File_IsEndOfData(file), kQ3True);
    TQ3Uns8 u8 = 200;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Uns8_Read(&u8, file), kQ3Failure), kQ3ErrorReadMoreThanSize);
    EXPECT_EQ(u8, 200);
    EXPECT_EQ(Q3File_IsEndOfContainer(file, nullptr), kQ3True);
    EXPECT_EQ(Q3File_IsEndOfFile(file), kQ3True);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_ReadObject(file), nullptr), kQ3ErrorEndOfFile);
    Q3File_Close(file);
    Q3Object_Dispose(file);
}

TEST_F(FilePrimitiveTest, TextWritesWordsCommentsAndLineBreaks)
{
    Writer out(kQ3FileModeText);
    ASSERT_EQ(Q3Comment_Write(const_cast<char*>("a\nnote"), out.file), kQ3Success);
    ASSERT_EQ(Q3Uns32_Write(7, out.file), kQ3Success);
    ASSERT_EQ(Q3Float32_Write(0.1f, out.file), kQ3Success);
    ASSERT_EQ(Q3String_Write("a\"b", out.file), kQ3Success);
    const unsigned char raw[3] = {1, 2, 0xFF};
    ASSERT_EQ(Q3RawData_Write(raw, 3, out.file), kQ3Success);
    ASSERT_EQ(Q3NewLine_Write(out.file), kQ3Success);
    ASSERT_EQ(Q3Int8_Write(-3, out.file), kQ3Success);
    const std::vector<unsigned char> bytes = out.close();
    EXPECT_EQ(std::string(bytes.begin(), bytes.end()),
              "3DMetafile ( 1 6 Normal )\n# a note\n 7 0.1 \"a\\\"b\" 0x0102FF\n -3");
}

TEST_F(FilePrimitiveTest, TextObjectReadsBackEveryKind)
{
    TQ3FileObject file = openBytes(bytesOf("3DMetafile ( 1 6 Normal )\n"
                                           "Custom ( 4294967295 -32768 -128 255 0.25 1e300 18446744073709551615\n"
                                           "  -9223372036854775808 \"say \\\"hi\\\"\" 0x0A0b 1 2 3 4 5 6 7 8 9 )\n"));
    ASSERT_NE(file, nullptr);
    expectRead(Q3Uns32_Read, file, 4294967295ul, "Q3Uns32_Read");
    expectRead(Q3Int16_Read, file, -32768, "Q3Int16_Read");
    expectRead(Q3Int8_Read, file, -128, "Q3Int8_Read");
    expectRead(Q3Uns8_Read, file, 255, "Q3Uns8_Read");
    expectRead(Q3Float32_Read, file, 0.25f, "Q3Float32_Read");
    expectRead(Q3Float64_Read, file, 1e300, "Q3Float64_Read");
    expectReadHalves(Q3Uns64_Read, file, 0xFFFFFFFFul, 0xFFFFFFFFul, "Q3Uns64_Read");
    expectReadHalves(Q3Int64_Read, file, INT32_MIN, 0ul, "Q3Int64_Read");
    char text[kQ3StringMaximumLength];
    unsigned long length = 0;
    ASSERT_EQ(Q3String_Read(text, &length, file), kQ3Success);
    EXPECT_STREQ(text, "say \"hi\"");
    EXPECT_EQ(length, 8ul);
    unsigned char raw[2] = {};
    ASSERT_EQ(Q3RawData_Read(raw, 2, file), kQ3Success);
    EXPECT_EQ(raw[0], 0x0A);
    EXPECT_EQ(raw[1], 0x0B);
    TQ3Tangent3D tangent = {};
    ASSERT_EQ(Q3Tangent3D_Read(&tangent, file), kQ3Success);
    EXPECT_EQ(tangent.uTangent.x, 1.0f);
    EXPECT_EQ(tangent.vTangent.y, 5.0f);
    EXPECT_EQ(tangent.wTangent.z, 9.0f);
    EXPECT_EQ(Q3File_IsEndOfData(file), kQ3True);
    Q3File_Close(file);
    Q3Object_Dispose(file);
}

TEST_F(FilePrimitiveTest, EveryStructRoundTripsInBothEncodings)
{
    for (const TQ3FileMode mode : {TQ3FileMode{kQ3FileModeNormal}, TQ3FileMode{kQ3FileModeText}}) {
        SCOPED_TRACE(mode);
        Writer out(mode);
        const bool text = mode == kQ3FileModeText;
        // Binary needs the object's type and size written first; text
        // cannot be given a name by primitives, so the object is a
        // hand-written prefix there.
        if (!text) {
            Q3Uns32_Write(Q3_OBJECT_TYPE('s', 't', 'r', 'c'), out.file);
            Q3Uns32_Write(4 * (2 + 3 + 3 + 4 + 2 + 16 + 6), out.file);
        }
        const TQ3Point2D p2 = {1, 2};
        const TQ3RationalPoint3D r3 = {3, 4, 0.5f};
        const TQ3Point3D p3 = {-1, -2, -3};
        const TQ3RationalPoint4D r4 = {5, 6, 7, 2};
        const TQ3Vector2D v2 = {0.125f, 8};
        TQ3Matrix4x4 m;
        for (int i = 0; i < 16; ++i)
            m.value[i / 4][i % 4] = static_cast<float>(i) / 3.0f;
        const TQ3Tangent2D t2 = {{1, 0, 0}, {0, 1, 0.1f}};
        ASSERT_EQ(Q3Point2D_Write(&p2, out.file), kQ3Success);
        ASSERT_EQ(Q3RationalPoint3D_Write(&r3, out.file), kQ3Success);
        ASSERT_EQ(Q3Vector3D_Write(reinterpret_cast<const TQ3Vector3D*>(&p3), out.file), kQ3Success);
        ASSERT_EQ(Q3RationalPoint4D_Write(&r4, out.file), kQ3Success);
        ASSERT_EQ(Q3Vector2D_Write(&v2, out.file), kQ3Success);
        ASSERT_EQ(Q3Matrix4x4_Write(&m, out.file), kQ3Success);
        ASSERT_EQ(Q3Tangent2D_Write(&t2, out.file), kQ3Success);
        std::vector<unsigned char> bytes = out.close();
        if (text) {
            std::string words(bytes.begin(), bytes.end());
            words.insert(words.find('\n') + 1, "Struct (");
            words += " )\n";
            bytes = bytesOf(words);
        }
        TQ3FileObject file = openBytes(bytes);
        ASSERT_NE(file, nullptr);
        TQ3Point2D p2In;
        TQ3RationalPoint3D r3In;
        TQ3Vector3D v3In;
        TQ3RationalPoint4D r4In;
        TQ3Vector2D v2In;
        TQ3Matrix4x4 mIn;
        TQ3Tangent2D t2In;
        ASSERT_EQ(Q3Point2D_Read(&p2In, file), kQ3Success);
        ASSERT_EQ(Q3RationalPoint3D_Read(&r3In, file), kQ3Success);
        ASSERT_EQ(Q3Vector3D_Read(&v3In, file), kQ3Success);
        ASSERT_EQ(Q3RationalPoint4D_Read(&r4In, file), kQ3Success);
        ASSERT_EQ(Q3Vector2D_Read(&v2In, file), kQ3Success);
        ASSERT_EQ(Q3Matrix4x4_Read(&mIn, file), kQ3Success);
        ASSERT_EQ(Q3Tangent2D_Read(&t2In, file), kQ3Success);
        EXPECT_EQ(Q3File_IsEndOfData(file), kQ3True);
        EXPECT_EQ(std::memcmp(&p2In, &p2, sizeof p2), 0);
        EXPECT_EQ(std::memcmp(&r3In, &r3, sizeof r3), 0);
        EXPECT_EQ(std::memcmp(&v3In, &p3, sizeof p3), 0);
        EXPECT_EQ(std::memcmp(&r4In, &r4, sizeof r4), 0);
        EXPECT_EQ(std::memcmp(&v2In, &v2, sizeof v2), 0);
        EXPECT_EQ(std::memcmp(&mIn, &m, sizeof m), 0);
        EXPECT_EQ(std::memcmp(&t2In, &t2, sizeof t2), 0);
        Q3File_Close(file);
        Q3Object_Dispose(file);
    }
}

TEST_F(FilePrimitiveTest, ContainerSubobjectsAreReadAfterTheRootsData)
{
    TQ3FileObject file = openBytes(bytesOf("3DMetafile ( 1 6 Normal )\n"
                                           "Container ( Custom ( 5 ) Point ( 1 2 3 ) Point ( 0 0 1 ) )\n"
                                           "Point ( 4 5 6 )\n"));
    ASSERT_NE(file, nullptr);
    EXPECT_EQ(Q3File_IsEndOfContainer(file, nullptr), kQ3True); // no data read yet
    EXPECT_EQ(Q3File_IsEndOfData(file), kQ3False);
    expectRead(Q3Uns32_Read, file, 5u, "Q3Uns32_Read");
    EXPECT_EQ(Q3File_IsEndOfData(file), kQ3True);
    EXPECT_EQ(Q3File_IsEndOfContainer(file, nullptr), kQ3False);
    EXPECT_EQ(Q3File_GetNextObjectType(file), kQ3GeometryTypePoint);
    TQ3Object first = Q3File_ReadObject(file);
    ASSERT_NE(first, nullptr);
    TQ3PointData data;
    ASSERT_EQ(Q3Point_GetData(first, &data), kQ3Success);
    EXPECT_EQ(data.point.y, 2.0f);
    Q3Point_EmptyData(&data);
    EXPECT_EQ(Q3File_IsEndOfContainer(file, nullptr), kQ3False);
    ASSERT_EQ(Q3File_SkipObject(file), kQ3Success);
    EXPECT_EQ(Q3File_IsEndOfContainer(file, first), kQ3True);
    EXPECT_EQ(Q3File_IsEndOfFile(file), kQ3False);
    TQ3Object after = Q3File_ReadObject(file);
    ASSERT_NE(after, nullptr);
    ASSERT_EQ(Q3Point_GetData(after, &data), kQ3Success);
    EXPECT_EQ(data.point.x, 4.0f);
    Q3Point_EmptyData(&data);
    EXPECT_EQ(Q3File_IsEndOfFile(file), kQ3True);
    EXPECT_EQ(Q3File_IsEndOfData(file), kQ3True);
    Q3Object_Dispose(first);
    Q3Object_Dispose(after);
    Q3File_Close(file);
    Q3Object_Dispose(file);
}

TEST_F(FilePrimitiveTest, ReadsOutsideAReadingFileOrPastTheDataFail)
{
    TQ3Uns32 value = 99;
    TQ3FileObject closed = Q3File_New();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Uns32_Read(&value, closed), kQ3Failure), kQ3ErrorReadStateInactive);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Uns32_Write(1, closed), kQ3Failure), kQ3ErrorWriteStateInactive);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NewLine_Write(closed), kQ3Failure), kQ3ErrorWriteStateInactive);
    EXPECT_EQ(Q3File_IsEndOfData(closed), kQ3True);
    EXPECT_EQ(Q3File_IsEndOfContainer(closed, nullptr), kQ3True);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Uns32_Read(&value, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Uns32_Read(nullptr, closed), kQ3Failure), kQ3ErrorNULLParameter);
    Q3Object_Dispose(closed);

    TQ3FileObject file = openBytes(bytesOf("3DMetafile ( 1 6 Normal )\n"
                                           "Custom ( \"s\" 300 1 2 )\n"
                                           "BeginGroup ( Group ( ) ) EndGroup ( )\n"));
    ASSERT_NE(file, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Uns32_Write(1, file), kQ3Failure), kQ3ErrorWriteStateInactive);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Uns32_Read(&value, file), kQ3Failure), kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_EQ(value, 99u);
    char text[kQ3StringMaximumLength];
    unsigned long length = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3String_Read(text, nullptr, file), kQ3Failure), kQ3ErrorNULLParameter);
    ASSERT_EQ(Q3String_Read(text, &length, file), kQ3Success); // the failed read moved nothing
    EXPECT_STREQ(text, "s");
    TQ3Int8 small = 7;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Int8_Read(&small, file), kQ3Failure), kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_EQ(small, 7);
    expectRead(Q3Int16_Read, file, 300, "Q3Int16_Read");
    TQ3Point3D point = {9, 9, 9};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_Read(&point, file), kQ3Failure), kQ3ErrorReadMoreThanSize);
    EXPECT_EQ(point.x, 9.0f);
    TQ3Point2D pair = {};
    ASSERT_EQ(Q3Point2D_Read(&pair, file), kQ3Success);
    EXPECT_EQ(pair.y, 2.0f);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Uns32_Read(&value, file), kQ3Failure), kQ3ErrorReadMoreThanSize);
    EXPECT_EQ(Q3File_IsEndOfData(file), kQ3True);
    ASSERT_EQ(Q3File_SkipObject(file), kQ3Success);
    EXPECT_EQ(Q3File_IsEndOfData(file), kQ3True);
    Q3File_Close(file);
    Q3Object_Dispose(file);

    file = openBytes(bytesOf("3DMetafile ( 1 6 Normal ) BeginGroup ( Group ( ) ) EndGroup ( )"));
    ASSERT_NE(file, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Uns32_Read(&value, file), kQ3Failure), kQ3ErrorInvalidMetafileObject);
    ASSERT_EQ(Q3File_SkipObject(file), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Uns32_Read(&value, file), kQ3Failure), kQ3ErrorEndOfFile);
    Q3File_Close(file);
    Q3Object_Dispose(file);
}

TEST_F(FilePrimitiveTest, BinaryStringWithoutItsNulIsRefused)
{
    std::vector<unsigned char> bytes = header();
    const unsigned char body[] = {'s', 't', 'r', 'g', 0, 0, 0, 4, 'a', 'b', 'c', 'd'};
    bytes.insert(bytes.end(), body, body + sizeof body);
    TQ3FileObject file = openBytes(bytes);
    ASSERT_NE(file, nullptr);
    char text[kQ3StringMaximumLength] = "kept";
    unsigned long length = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3String_Read(text, &length, file), kQ3Failure), kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_STREQ(text, "kept");
    unsigned char raw[5];
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RawData_Read(raw, 5, file), kQ3Failure), kQ3ErrorReadMoreThanSize);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RawData_Read(raw, 0xFFFFFFFFul, file), kQ3Failure), kQ3ErrorReadMoreThanSize);
    ASSERT_EQ(Q3RawData_Read(raw, 4, file), kQ3Success);
    EXPECT_EQ(raw[3], 'd');
    Q3File_Close(file);
    Q3Object_Dispose(file);
}

TEST_F(FilePrimitiveTest, LongStringsAreCutToTheBuffer)
{
    const std::string longText(2000, 'x');
    TQ3FileObject file = openBytes(bytesOf("3DMetafile ( 1 6 Normal ) S ( \"" + longText + "\" )"));
    ASSERT_NE(file, nullptr);
    unsigned long length = 0;
    ASSERT_EQ(Q3String_Read(nullptr, &length, file), kQ3Success);
    EXPECT_EQ(length, 2000ul);
    std::vector<char> buffer(kQ3StringMaximumLength + 16, '#');
    ASSERT_EQ(Q3String_Read(buffer.data(), &length, file), kQ3Success);
    EXPECT_EQ(length, static_cast<unsigned long>(kQ3StringMaximumLength - 1));
    EXPECT_EQ(buffer[kQ3StringMaximumLength - 1], '\0');
    EXPECT_EQ(buffer[kQ3StringMaximumLength], '#');
    Q3File_Close(file);
    Q3Object_Dispose(file);

    Writer out(kQ3FileModeNormal);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3String_Write(longText.c_str(), out.file), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3String_Write(nullptr, out.file), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_Write(nullptr, out.file), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_EQ(out.close(), header());
}

TEST_F(FilePrimitiveTest, SizePadRoundsUpToFour)
{
    EXPECT_EQ(Q3Size_Pad(0), 0ul);
    EXPECT_EQ(Q3Size_Pad(1), 4ul);
    EXPECT_EQ(Q3Size_Pad(4), 4ul);
    EXPECT_EQ(Q3Size_Pad(5), 8ul);
    EXPECT_EQ(Q3Size_Pad(0xFFFFFFFCul), 0xFFFFFFFCul);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Size_Pad(0xFFFFFFFDul), 0ul), kQ3ErrorInvalidParameter);
}

TEST_F(FilePrimitiveTest, IdleMethodFailureCancelsWriting)
{
    Counter counter;
    counter.failAt = 2;
    Writer out(kQ3FileModeNormal);
    ASSERT_EQ(Q3File_SetIdleMethod(out.file, countingIdle, &counter), kQ3Success);
    TQ3ViewObject view = Q3View_New();
    TQ3GeometryObject points[3] = {newPoint(1), newPoint(2), newPoint(3)};
    ASSERT_EQ(Q3View_StartWriting(view, out.file), kQ3Success);
    for (TQ3GeometryObject point : points)
        EXPECT_EQ(Q3Object_Submit(point, view), kQ3Success);
    EXPECT_EQ(Q3View_EndWriting(view), kQ3ViewStatusCancelled);
    EXPECT_EQ(counter.calls, 2); // nothing asked after the cancel
    const std::vector<unsigned char> bytes = out.close();
    const std::vector<TQ3Object> read = readAll(bytes);
    ASSERT_EQ(read.size(), 1u);
    TQ3PointData data;
    ASSERT_EQ(Q3Point_GetData(read[0], &data), kQ3Success);
    EXPECT_EQ(data.point.x, 1.0f);
    Q3Point_EmptyData(&data);
    disposeAll(read);
    for (TQ3GeometryObject point : points)
        Q3Object_Dispose(point);
    Q3Object_Dispose(view);
}

TEST_F(FilePrimitiveTest, IdleMethodFailureCancelsAReadAndTheNextReadTriesAgain)
{
    TQ3GeometryObject point = newPoint(5);
    const std::vector<unsigned char> bytes = writeObjects({point, point}, kQ3FileModeStream);
    Q3Object_Dispose(point);
    TQ3FileObject file = openBytes(bytes);
    ASSERT_NE(file, nullptr);
    Counter counter;
    counter.failAt = 1;
    ASSERT_EQ(Q3File_SetIdleMethod(file, countingIdle, &counter), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_ReadObject(file), nullptr), kQ3ErrorFileCancelled);
    EXPECT_EQ(Q3File_SkipObject(file), kQ3Success); // the cancelled read left the first point

    TQ3Object object = Q3File_ReadObject(file);
    EXPECT_NE(object, nullptr);
    EXPECT_EQ(counter.calls, 3);
    ASSERT_EQ(Q3File_SetIdleMethod(file, nullptr, nullptr), kQ3Success);
    EXPECT_EQ(Q3File_IsEndOfFile(file), kQ3True);
    Q3Object_Dispose(object);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_SetIdleMethod(nullptr, countingIdle, &counter), kQ3Failure),
                    kQ3ErrorNULLParameter);
    Q3File_Close(file);
    Q3Object_Dispose(file);
}
