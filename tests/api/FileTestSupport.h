// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Writing objects to a 3DMF file in memory and reading them back, through
// the public API only.

#include "QD3D.h"
#include "QD3DIO.h"
#include "QD3DStorage.h"
#include "QD3DView.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace q3test {

/// The bytes of a file holding `objects`, written in `mode`.
inline std::vector<unsigned char> writeObjects(const std::vector<TQ3Object>& objects, TQ3FileMode mode)
{
    std::vector<unsigned char> bytes;
    TQ3StorageObject storage = Q3MemoryStorage_New(nullptr, 0);
    TQ3FileObject file = Q3File_New();
    TQ3ViewObject view = Q3View_New();
    EXPECT_EQ(Q3File_SetStorage(file, storage), kQ3Success);
    EXPECT_EQ(Q3File_OpenWrite(file, mode), kQ3Success);
    EXPECT_EQ(Q3View_StartWriting(view, file), kQ3Success);
    TQ3ViewStatus status;
    do {
        for (TQ3Object object : objects)
            EXPECT_EQ(Q3Object_Submit(object, view), kQ3Success);
        status = Q3View_EndWriting(view);
    } while (status == kQ3ViewStatusRetraverse);
    EXPECT_EQ(status, kQ3ViewStatusDone);
    EXPECT_EQ(Q3File_Close(file), kQ3Success);
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    EXPECT_EQ(Q3MemoryStorage_GetBuffer(storage, &buffer, &size, nullptr), kQ3Success);
    if (buffer != nullptr)
        bytes.assign(buffer, buffer + size);
    Q3Object_Dispose(view);
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
    return bytes;
}

/// A file open for reading on a copy of the bytes (NULL if OpenRead
/// failed); the caller closes and disposes it.
inline TQ3FileObject openBytes(const std::vector<unsigned char>& bytes, TQ3FileMode* mode = nullptr)
{
    TQ3StorageObject storage = Q3MemoryStorage_New(bytes.data(), static_cast<unsigned long>(bytes.size()));
    TQ3FileObject file = Q3File_New();
    Q3File_SetStorage(file, storage);
    Q3Object_Dispose(storage);
    TQ3FileMode opened = 0;
    if (Q3File_OpenRead(file, &opened) != kQ3Success) {
        Q3Object_Dispose(file);
        return nullptr;
    }
    if (mode != nullptr)
        *mode = opened;
    return file;
}

inline std::vector<unsigned char> bytesOf(const std::string& text)
{
    return std::vector<unsigned char>(text.begin(), text.end());
}

/// Every object of the file (stops at the first failure).
inline std::vector<TQ3Object> readAll(const std::vector<unsigned char>& bytes)
{
    std::vector<TQ3Object> objects;
    TQ3FileObject file = openBytes(bytes);
    if (file == nullptr)
        return objects;
    while (Q3File_IsEndOfFile(file) == kQ3False) {
        TQ3Object object = Q3File_ReadObject(file);
        if (object == nullptr)
            break;
        objects.push_back(object);
    }
    Q3File_Close(file);
    Q3Object_Dispose(file);
    return objects;
}

inline void disposeAll(const std::vector<TQ3Object>& objects)
{
    for (TQ3Object object : objects)
        Q3Object_Dispose(object);
}

} // namespace q3test
