// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Little-endian binary files (kQ3FileModeSwap): written, read back, and
// compared byte for byte with the files tests/data/make_binary.py lays out by
// hand from the 3D Metafile Reference.
#include "FileTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DGroup.h"

#include <fstream>
#include <iterator>

using namespace q3test;

namespace {

class FileByteOrderTest : public Q3ApiTest {};

std::vector<unsigned char> dataFile(const char* name)
{
    std::ifstream in(std::string(Q3_TEST_DATA_DIR) + "/" + name, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The file's objects written again in `mode`.
std::vector<unsigned char> rewrite(const std::vector<unsigned char>& bytes, TQ3FileMode mode)
{
    const std::vector<TQ3Object> objects = readAll(bytes);
    EXPECT_FALSE(objects.empty());
    const std::vector<unsigned char> out = writeObjects(objects, mode);
    disposeAll(objects);
    return out;
}

} // namespace

TEST_F(FileByteOrderTest, SwapModeWritesTheHandLaidLittleEndianFiles)
{
    const struct {
        const char* big;
        const char* little;
    } pairs[] = {{"triangle_be.3dmf", "triangle_le.3dmf"}, {"references_be.3dmf", "references_le.3dmf"}};
    for (const auto& pair : pairs) {
        SCOPED_TRACE(pair.little);
        const std::vector<unsigned char> little = dataFile(pair.little);
        ASSERT_GT(little.size(), 24u);
        EXPECT_EQ(rewrite(dataFile(pair.big), kQ3FileModeSwap), little);
        EXPECT_EQ(rewrite(little, kQ3FileModeSwap), little);
        // And back to big-endian.
        EXPECT_EQ(rewrite(little, kQ3FileModeNormal), dataFile(pair.big));
    }
}

TEST_F(FileByteOrderTest, LittleEndianFilesReportSwapAndRoundTripInEveryMode)
{
    const TQ3TriangleData triangle = {{{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{0, 1, 0.5f}, nullptr}},
                                      nullptr};
    TQ3GeometryObject shape = Q3Triangle_New(&triangle);
    TQ3GroupObject group = Q3DisplayGroup_New();
    Q3Group_AddObject(group, shape);
    Q3Group_AddObject(group, shape);
    for (const TQ3FileMode mode : {TQ3FileMode{kQ3FileModeSwap}, TQ3FileMode{kQ3FileModeSwap | kQ3FileModeStream},
                                   TQ3FileMode{kQ3FileModeSwap | kQ3FileModeDatabase}}) {
        SCOPED_TRACE(mode);
        const std::vector<unsigned char> bytes = writeObjects({group}, mode);
        ASSERT_GT(bytes.size(), 24u);
        EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 8), std::string("FMD3\x10\0\0\0", 8));
        EXPECT_EQ(bytes[12], mode & 3); // the mode, least significant byte first
        TQ3FileMode opened = 0;
        TQ3FileObject file = openBytes(bytes, &opened);
        ASSERT_NE(file, nullptr);
        EXPECT_EQ(opened, mode);
        TQ3FileMode got = 0;
        ASSERT_EQ(Q3File_GetMode(file, &got), kQ3Success);
        EXPECT_EQ(got, mode);
        TQ3Object back = Q3File_ReadObject(file);
        ASSERT_NE(back, nullptr);
        unsigned long count = 0;
        ASSERT_EQ(Q3Group_CountObjects(back, &count), kQ3Success);
        ASSERT_EQ(count, 2u);
        TQ3GroupPosition position = nullptr;
        Q3Group_GetFirstPosition(back, &position);
        TQ3Object first = nullptr, second = nullptr;
        Q3Group_GetPositionObject(back, position, &first);
        Q3Group_GetNextPosition(back, &position);
        Q3Group_GetPositionObject(back, position, &second);
        // Normal and Database files refer to the one triangle; Stream ones repeat it.
        EXPECT_EQ(first == second, (mode & kQ3FileModeStream) == 0);
        TQ3TriangleData data;
        ASSERT_EQ(Q3Triangle_GetData(second, &data), kQ3Success);
        EXPECT_EQ(data.vertices[2].point.z, 0.5f);
        EXPECT_EQ(data.vertices[1].point.x, 1.0f);
        Q3Triangle_EmptyData(&data);
        Q3Object_Dispose(first);
        Q3Object_Dispose(second);
        Q3Object_Dispose(back);
        Q3File_Close(file);
        Q3Object_Dispose(file);
    }
    Q3Object_Dispose(group);
    Q3Object_Dispose(shape);
}

TEST_F(FileByteOrderTest, PrimitivesFollowTheFilesByteOrder)
{
    TQ3StorageObject storage = Q3MemoryStorage_New(nullptr, 0);
    TQ3FileObject file = Q3File_New();
    ASSERT_EQ(Q3File_SetStorage(file, storage), kQ3Success);
    EXPECT_Q3_ERROR(Q3File_OpenWrite(file, kQ3FileModeSwap | kQ3FileModeText), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3File_OpenWrite(file, 1 << 4), kQ3ErrorInvalidParameter);
    ASSERT_EQ(Q3File_OpenWrite(file, kQ3FileModeSwap), kQ3Success);
    ASSERT_EQ(Q3Uns32_Write(Q3_OBJECT_TYPE('m', 'i', 'n', 'e'), file), kQ3Success);
    ASSERT_EQ(Q3Uns32_Write(8, file), kQ3Success);
    ASSERT_EQ(Q3Uns32_Write(0x01020304ul, file), kQ3Success);
    ASSERT_EQ(Q3Int16_Write(-2, file), kQ3Success);
    ASSERT_EQ(Q3Uns16_Write(0x0A0B, file), kQ3Success);
    ASSERT_EQ(Q3File_Close(file), kQ3Success);
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    ASSERT_EQ(Q3MemoryStorage_GetBuffer(storage, &buffer, &size, nullptr), kQ3Success);
    const std::vector<unsigned char> bytes(buffer, buffer + size);
    const std::vector<unsigned char> expected = {
        'F', 'M', 'D', '3', 16, 0, 0, 0, 1, 0, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, // header
        'e', 'n', 'i', 'm', 8, 0, 0, 0, 4, 3, 2, 1, 0xFE, 0xFF, 0x0B, 0x0A};
    EXPECT_EQ(bytes, expected);

    TQ3FileObject in = openBytes(bytes);
    ASSERT_NE(in, nullptr);
    EXPECT_EQ(Q3File_GetNextObjectType(in), kQ3ShapeTypeUnknown);
    TQ3Uns32 value = 0;
    TQ3Int16 negative = 0;
    TQ3Uns16 small = 0;
    ASSERT_EQ(Q3Uns32_Read(&value, in), kQ3Success);
    ASSERT_EQ(Q3Int16_Read(&negative, in), kQ3Success);
    ASSERT_EQ(Q3Uns16_Read(&small, in), kQ3Success);
    EXPECT_EQ(value, 0x01020304ul);
    EXPECT_EQ(negative, -2);
    EXPECT_EQ(small, 0x0A0B);
    Q3File_Close(in);
    Q3Object_Dispose(in);
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
}

TEST_F(FileByteOrderTest, UnknownObjectsKeepTheirByteOrderOrAreLeftOut)
{
    const std::vector<TQ3Object> objects = readAll(dataFile("unknown_be.3dmf"));
    ASSERT_EQ(objects.size(), 3u);
    ASSERT_EQ(Q3Object_GetLeafType(objects[1]), kQ3UnknownTypeBinary);
    std::vector<unsigned char> little;
    EXPECT_Q3_WARNING(little = writeObjects(objects, kQ3FileModeSwap), kQ3WarningNoObjectSupportForWriteMethod);
    const std::vector<TQ3Object> back = readAll(little);
    EXPECT_EQ(back.size(), 2u); // the two points
    disposeAll(back);
    // Written big-endian again, the unknown object is the same bytes.
    EXPECT_EQ(writeObjects(objects, kQ3FileModeStream), dataFile("unknown_be.3dmf"));
    disposeAll(objects);
}
