// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "Q3ApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DStorage.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <unistd.h>

using q3test::Q3ApiTest;

namespace {

class StorageApiTest : public Q3ApiTest {};

std::string tempPath(const char* name)
{
    return std::string(::testing::TempDir()) + "q3_storage_" + std::to_string(::getpid()) + "_" + name;
}

} // namespace

TEST_F(StorageApiTest, MemoryStorageCopiesGrowsAndReadsBack)
{
    const unsigned char bytes[] = {1, 2, 3, 4};
    TQ3StorageObject storage = Q3MemoryStorage_New(bytes, 4);
    ASSERT_NE(storage, nullptr);
    EXPECT_EQ(Q3Storage_GetType(storage), kQ3StorageTypeMemory);
    unsigned long size = 0;
    ASSERT_EQ(Q3Storage_GetSize(storage, &size), kQ3Success);
    EXPECT_EQ(size, 4u);

    const unsigned char more[] = {9, 8};
    unsigned long written = 0;
    ASSERT_EQ(Q3Storage_SetData(storage, 6, 2, more, &written), kQ3Success);
    EXPECT_EQ(written, 2u);
    ASSERT_EQ(Q3Storage_GetSize(storage, &size), kQ3Success);
    EXPECT_EQ(size, 8u);

    unsigned char out[16] = {};
    unsigned long read = 0;
    ASSERT_EQ(Q3Storage_GetData(storage, 2, 16, out, &read), kQ3Success);
    EXPECT_EQ(read, 6u); // the end of the storage
    const unsigned char expected[] = {3, 4, 0, 0, 9, 8};
    EXPECT_EQ(std::memcmp(out, expected, 6), 0);
    ASSERT_EQ(Q3Storage_GetData(storage, 100, 4, out, &read), kQ3Success);
    EXPECT_EQ(read, 0u);

    unsigned char* buffer = nullptr;
    unsigned long valid = 0, capacity = 0;
    ASSERT_EQ(Q3MemoryStorage_GetBuffer(storage, &buffer, &valid, &capacity), kQ3Success);
    EXPECT_EQ(valid, 8u);
    EXPECT_GE(capacity, 8u);
    EXPECT_EQ(buffer[7], 8);

    ASSERT_EQ(Q3MemoryStorage_Set(storage, nullptr, 0), kQ3Success);
    ASSERT_EQ(Q3Storage_GetSize(storage, &size), kQ3Success);
    EXPECT_EQ(size, 0u);
    Q3Object_Dispose(storage);
}

TEST_F(StorageApiTest, CallerBuffersAreUsedInPlaceAndNeverGrown)
{
    unsigned char buffer[4] = {7, 7, 0, 0};
    TQ3StorageObject storage = Q3MemoryStorage_NewBuffer(buffer, 2, 4);
    ASSERT_NE(storage, nullptr);
    const unsigned char data[] = {1, 2, 3, 4};
    unsigned long written = 0;
    ASSERT_EQ(Q3Storage_SetData(storage, 1, 4, data, &written), kQ3Success);
    EXPECT_EQ(written, 3u); // what fitted
    EXPECT_EQ(buffer[0], 7);
    EXPECT_EQ(buffer[3], 3);
    unsigned char* inPlace = nullptr;
    ASSERT_EQ(Q3MemoryStorage_GetBuffer(storage, &inPlace, nullptr, nullptr), kQ3Success);
    EXPECT_EQ(inPlace, buffer);

    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MemoryStorage_SetBuffer(storage, buffer, 5, 4), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MemoryStorage_NewBuffer(buffer, 5, 4), nullptr), kQ3ErrorInvalidParameter);
    ASSERT_EQ(Q3MemoryStorage_SetBuffer(storage, nullptr, 0, 16), kQ3Success);
    unsigned long capacity = 0;
    ASSERT_EQ(Q3MemoryStorage_GetBuffer(storage, &inPlace, nullptr, &capacity), kQ3Success);
    EXPECT_NE(inPlace, buffer);
    EXPECT_EQ(capacity, 16u);
    Q3Object_Dispose(storage);
}

TEST_F(StorageApiTest, PathStorageWritesAndReadsAFile)
{
    const std::string path = tempPath("path.bin");
    std::remove(path.c_str());
    TQ3StorageObject storage = Q3UnixPathStorage_New(path.c_str());
    ASSERT_NE(storage, nullptr);
    EXPECT_EQ(Q3Storage_GetType(storage), kQ3UnixStorageTypePath);
    unsigned long size = 99;
    ASSERT_EQ(Q3Storage_GetSize(storage, &size), kQ3Success);
    EXPECT_EQ(size, 0u); // not there yet
    const unsigned char data[] = {'3', 'D', 'M', 'F'};
    unsigned long written = 0;
    ASSERT_EQ(Q3Storage_SetData(storage, 0, 4, data, &written), kQ3Success);
    EXPECT_EQ(written, 4u);
    unsigned char out[4] = {};
    unsigned long read = 0;
    ASSERT_EQ(Q3Storage_GetData(storage, 0, 4, out, &read), kQ3Success);
    EXPECT_EQ(read, 4u);
    EXPECT_EQ(std::memcmp(out, data, 4), 0);

    char name[1024] = {};
    ASSERT_EQ(Q3UnixPathStorage_Get(storage, name), kQ3Success);
    EXPECT_EQ(path, name);
    const std::string other = tempPath("other.bin");
    ASSERT_EQ(Q3UnixPathStorage_Set(storage, other.c_str()), kQ3Success);
    ASSERT_EQ(Q3UnixPathStorage_Get(storage, name), kQ3Success);
    EXPECT_EQ(other, name);
    Q3Object_Dispose(storage);

    TQ3StorageObject quesa = Q3PathStorage_New(path.c_str());
    ASSERT_NE(quesa, nullptr);
    EXPECT_EQ(Q3Storage_GetType(quesa), kQ3UnixStorageTypePath);
    ASSERT_EQ(Q3Storage_GetSize(quesa, &size), kQ3Success);
    EXPECT_EQ(size, 4u);
    Q3Object_Dispose(quesa);
    std::remove(path.c_str());
}

TEST_F(StorageApiTest, BadHandlesAndPointersAreRejected)
{
    unsigned long size = 5;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Storage_GetSize(nullptr, &size), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_EQ(size, 5u);
    TQ3StorageObject storage = Q3MemoryStorage_New(nullptr, 0);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Storage_GetSize(storage, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    unsigned long n = 0;
    EXPECT_Q3_ERROR(Q3Storage_GetData(storage, 0, 1, nullptr, &n), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Storage_SetData(storage, 0, 1, nullptr, &n), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3UnixPathStorage_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PathStorage_New(""), nullptr), kQ3ErrorInvalidParameter);
    char name[8];
    EXPECT_Q3_ERROR(Q3UnixPathStorage_Get(storage, name), kQ3ErrorInvalidObjectType);

    TQ3PointData data = {{0, 0, 0}, nullptr};
    TQ3GeometryObject point = Q3Point_New(&data);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Storage_GetType(point), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3MemoryStorage_Set(point, nullptr, 0), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(point);
    Q3Object_Dispose(storage);

    const std::string missing = tempPath("no/such/dir/file");
    TQ3StorageObject absent = Q3UnixPathStorage_New(missing.c_str());
    unsigned char byte = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Storage_GetData(absent, 0, 1, &byte, &n), kQ3Failure), kQ3ErrorFileNotOpen);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Storage_SetData(absent, 0, 1, &byte, &n), kQ3Failure), kQ3ErrorFileNotOpen);
    Q3Object_Dispose(absent);
}

TEST(StorageApiUninitialized, CallsFailWithNotInitialized)
{
    EXPECT_EQ(Q3MemoryStorage_New(nullptr, 0), nullptr);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3UnixPathStorage_New("x"), nullptr);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
}

TEST_F(StorageApiTest, MemoryStorageGetTypeNamesNoSubclass)
{
    TQ3StorageObject memory = Q3MemoryStorage_New(nullptr, 0);
    unsigned char buffer[8] = {};
    TQ3StorageObject inPlace = Q3MemoryStorage_NewBuffer(buffer, 0, sizeof buffer);
    EXPECT_EQ(Q3MemoryStorage_GetType(memory), kQ3ObjectTypeInvalid);
    EXPECT_EQ(Q3MemoryStorage_GetType(inPlace), kQ3ObjectTypeInvalid);
    EXPECT_EQ(Q3Storage_GetType(memory), kQ3StorageTypeMemory);

    const std::string path = tempPath("gettype");
    TQ3StorageObject file = Q3UnixPathStorage_New(path.c_str());
    TQ3StorageObject dead = Q3MemoryStorage_New(nullptr, 0);
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MemoryStorage_GetType(nullptr), kQ3ObjectTypeInvalid), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MemoryStorage_GetType(dead), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MemoryStorage_GetType(file), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(memory);
    Q3Object_Dispose(inPlace);
    Q3Object_Dispose(file);
}
