// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// QD3DIO.h's array reads (Q3 extension, Quesa's names): Q3Uns8_ReadArray,
// Q3Uns16_ReadArray, Q3Uns32_ReadArray and Q3Float32_ReadArray read what the
// single reads would, in both encodings, and fail whole.

#include "Q3ApiTest.h"

#include "FileTestSupport.h"
#include "QD3DIO.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace {

using namespace q3test;

class FileReadArrayTest : public Q3ApiTest {};

// A binary file holding one object of type 'arry' with `data`.
std::vector<unsigned char> binaryWith(const std::vector<unsigned char>& data)
{
    std::vector<unsigned char> bytes = {'3', 'D', 'M', 'F', 0, 0, 0, 16, 0, 1, 0, 6, 0, 0, 0, 0,
                                        0,   0,   0,   0,   0, 0, 0, 0,  'a', 'r', 'r', 'y'};
    const std::uint32_t size = static_cast<std::uint32_t>(data.size());
    for (int shift = 24; shift >= 0; shift -= 8)
        bytes.push_back(static_cast<unsigned char>(size >> shift));
    bytes.insert(bytes.end(), data.begin(), data.end());
    return bytes;
}

TEST_F(FileReadArrayTest, ArraysReadWhatSingleReadsWouldInBinary)
{
    // 3 bytes, then 2 16-bit values, then 2 32-bit values, then 2 floats,
    // big-endian: 1.5f is 0x3FC00000, -2.0f 0xC0000000.
    const std::vector<unsigned char> data = {1,    2,    3,    0x12, 0x34, 0xAB, 0xCD, 0,    0,    0,
                                             7,    0xFF, 0xFF, 0xFF, 0xFF, 0x3F, 0xC0, 0,    0,    0xC0,
                                             0,    0,    0};
    TQ3FileObject file = openBytes(binaryWith(data));
    ASSERT_NE(file, nullptr);
    TQ3Uns8 bytes[3] = {};
    ASSERT_EQ(Q3Uns8_ReadArray(3, bytes, file), kQ3Success);
    EXPECT_EQ(bytes[0], 1);
    EXPECT_EQ(bytes[2], 3);
    TQ3Uns16 shorts[2] = {};
    ASSERT_EQ(Q3Uns16_ReadArray(2, shorts, file), kQ3Success);
    EXPECT_EQ(shorts[0], 0x1234);
    EXPECT_EQ(shorts[1], 0xABCD);
    TQ3Uns32 longs[2] = {};
    ASSERT_EQ(Q3Uns32_ReadArray(2, longs, file), kQ3Success);
    EXPECT_EQ(longs[0], 7u);
    EXPECT_EQ(longs[1], 0xFFFFFFFFu);
    // Two floats are left: asking for three fails and changes nothing.
    TQ3Float32 floats[3] = {9, 9, 9};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Float32_ReadArray(3, floats, file), kQ3Failure), kQ3ErrorReadMoreThanSize);
    EXPECT_EQ(floats[0], 9.0f);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Float32_ReadArray(std::numeric_limits<TQ3Uns32>::max(), floats, file), kQ3Failure),
                    kQ3ErrorReadMoreThanSize);
    ASSERT_EQ(Q3Float32_ReadArray(2, floats, file), kQ3Success);
    EXPECT_EQ(floats[0], 1.5f);
    EXPECT_EQ(floats[1], -2.0f);
    EXPECT_EQ(floats[2], 9.0f);
    EXPECT_EQ(Q3File_IsEndOfData(file), kQ3True);
    EXPECT_EQ(Q3Uns32_ReadArray(0, nullptr, file), kQ3Success);
    Q3File_Close(file);
    Q3Object_Dispose(file);
}

TEST_F(FileReadArrayTest, ArraysReadWordsInTextAndRefuseBadInput)
{
    TQ3FileObject file = openBytes(bytesOf("3DMetafile ( 1 6 Normal )\nArry ( 1 2 3 0.5 x 4 )\n"));
    ASSERT_NE(file, nullptr);
    TQ3Uns32 values[3] = {};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Uns32_ReadArray(2, nullptr, file), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Uns32_ReadArray(2, values, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    ASSERT_EQ(Q3Uns32_ReadArray(3, values, file), kQ3Success);
    EXPECT_EQ(values[0], 1u);
    EXPECT_EQ(values[2], 3u);
    // "0.5 x": the word x is no number; the position stays at 0.5.
    TQ3Float32 floats[2] = {7, 7};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Float32_ReadArray(2, floats, file), kQ3Failure), kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_EQ(floats[0], 7.0f);
    ASSERT_EQ(Q3Float32_ReadArray(1, floats, file), kQ3Success);
    EXPECT_EQ(floats[0], 0.5f);
    Q3File_Close(file);
    TQ3Uns16 one = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Uns16_ReadArray(1, &one, file), kQ3Failure), kQ3ErrorReadStateInactive);
    Q3Object_Dispose(file);
}

} // namespace
