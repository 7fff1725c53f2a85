// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// libFuzzer target over the 3DMF reader: the input is a file. It is opened,
// every object read (a failed read must post an error and the reading goes
// on), each object read written back in text and binary and read again, and
// everything disposed. Aborts when a call breaks the error contract (a NULL
// object or kQ3Failure with no error posted) or when objects are left alive
// at the end: the sanitizers catch the rest (overflows, leaks, undefined
// behaviour). One input in three is also read through the primitive calls
// (Q3Uns32_Read, Q3String_Read, ...), object by object. Seeds:
// tests/fuzz/corpus-3dmf (the files of tests/data).

#include "QD3D.h"
#include "QD3DErrors.h"
#include "QD3DIO.h"
#include "QD3DStorage.h"
#include "QD3DView.h"

#include "../support/MemoryFile.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

void require(bool condition, const char* what)
{
    if (!condition) {
        std::fprintf(stderr, "3DMF fuzzer: %s\n", what);
        std::abort();
    }
}

// Every object of the bytes; reading stops after kMaxObjects.
std::vector<TQ3Object> readAll(const unsigned char* data, std::size_t size)
{
    constexpr std::size_t kMaxObjects = 256;
    std::vector<TQ3Object> objects;
    TQ3StorageObject storage = Q3MemoryStorage_New(data, static_cast<unsigned long>(size));
    TQ3FileObject file = Q3File_New();
    require(storage != nullptr && file != nullptr, "cannot make a storage and a file");
    require(Q3File_SetStorage(file, storage) == kQ3Success, "SetStorage failed");
    TQ3FileMode mode = 0;
    if (Q3File_OpenRead(file, &mode) == kQ3Success) {
        // Half the inputs read groups one object at a time.
        if (size % 2 == 1)
            require(Q3File_SetReadInGroup(file, kQ3FileReadObjectsInGroup) == kQ3Success, "SetReadInGroup failed");
        std::size_t attempts = 0;
        while (Q3File_IsEndOfFile(file) == kQ3False && attempts++ < kMaxObjects) {
            Q3File_GetNextObjectType(file);
            TQ3Object object = Q3File_ReadObject(file);
            if (object == nullptr)
                require(Q3Error_Get(nullptr) != kQ3ErrorNone, "ReadObject returned NULL and posted no error");
            else
                objects.push_back(object);
        }
        require(Q3File_Close(file) == kQ3Success, "Close after reading failed");
    } else {
        require(Q3Error_Get(nullptr) != kQ3ErrorNone, "OpenRead failed and posted no error");
    }
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
    return objects;
}

// Reads every object's data with primitive calls chosen by the data's bytes.
void readPrimitives(const unsigned char* data, std::size_t size)
{
    TQ3StorageObject storage = Q3MemoryStorage_New(data, static_cast<unsigned long>(size));
    TQ3FileObject file = Q3File_New();
    Q3File_SetStorage(file, storage);
    if (Q3File_OpenRead(file, nullptr) == kQ3Success) {
        for (std::size_t step = 0; step < 512 && Q3File_IsEndOfFile(file) == kQ3False; ++step) {
            TQ3Status status = kQ3Success;
            if (Q3File_IsEndOfData(file) == kQ3True && Q3File_IsEndOfContainer(file, nullptr) == kQ3True) {
                status = Q3File_SkipObject(file);
            } else if (Q3File_IsEndOfData(file) == kQ3False) {
                char text[kQ3StringMaximumLength];
                unsigned long length = 0;
                TQ3Uns32 u32;
                TQ3Float64 f64;
                TQ3Matrix4x4 matrix;
                unsigned char raw[16];
                switch (data[step % size] % 5) {
                case 0: status = Q3Uns32_Read(&u32, file); break;
                case 1: status = Q3String_Read(text, &length, file); break;
                case 2: status = Q3Float64_Read(&f64, file); break;
                case 3: status = Q3Matrix4x4_Read(&matrix, file); break;
                default: status = Q3RawData_Read(raw, data[step % size] % 17, file); break;
                }
                if (status == kQ3Failure)
                    status = Q3File_SkipObject(file);
            } else {
                TQ3Object object = Q3File_ReadObject(file);
                if (object != nullptr)
                    Q3Object_Dispose(object);
                else
                    status = kQ3Failure;
            }
            if (status == kQ3Failure)
                require(Q3Error_Get(nullptr) != kQ3ErrorNone, "a primitive read failed and posted no error");
        }
        Q3File_Close(file);
    }
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
}

std::vector<unsigned char> writeAll(const std::vector<TQ3Object>& objects, TQ3FileMode mode)
{
    const auto submitAll = [&](TQ3ViewObject view) {
        for (TQ3Object object : objects)
            require(Q3Object_Submit(object, view) == kQ3Success, "a read object cannot be written");
    };
    return q3test::writeMemoryFile(mode, submitAll, [](bool ok, const char* what) { require(ok, what); });
}

void disposeAll(const std::vector<TQ3Object>& objects)
{
    for (TQ3Object object : objects)
        Q3Object_Dispose(object);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const bool initialized = Q3Initialize() == kQ3Success;
    require(initialized, "Q3Initialize failed");
    const unsigned long liveAtStart = Q3Memory_CountLiveObjects();
    {
        const std::vector<TQ3Object> objects = readAll(data, size);
        if (!objects.empty()) {
            for (TQ3FileMode mode : {TQ3FileMode(kQ3FileModeNormal), TQ3FileMode(kQ3FileModeText),
                                     TQ3FileMode(kQ3FileModeSwap)}) {
                const std::vector<unsigned char> again = writeAll(objects, mode);
                // What Q3 wrote it must read back: every object, no failure.
                const std::vector<TQ3Object> back = readAll(again.data(), again.size());
                disposeAll(back);
            }
        }
        disposeAll(objects);
        if (size > 0 && size % 3 == 2)
            readPrimitives(data, size);
    }
    require(Q3Memory_CountLiveObjects() == liveAtStart, "objects left alive after everything was disposed");
    return 0;
}
