// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStorage.h"

#include "api/Entry.h"
#include "base/Storage.h"

using namespace q3;
using namespace q3::api;

TQ3ObjectType Q3Storage_GetType(TQ3StorageObject storage)
{
    return api::getLeafType<Storage>(__func__, storage, "storage");
}

TQ3Status Q3Storage_GetSize(TQ3StorageObject storage, unsigned long* size)
{
    return guardStatus(__func__, [&] {
        readInto<Storage>(storage, "storage", size, "size",
                          [](const Storage& s) { return static_cast<unsigned long>(s.size()); });
    });
}

TQ3Status Q3Storage_GetData(TQ3StorageObject storage, unsigned long offset, unsigned long dataSize,
                            unsigned char* data, unsigned long* sizeRead)
{
    return guardStatus(__func__, [&] {
        const Storage& source = lookup<Storage>(storage, "storage");
        requireNonNull(data, "data");
        requireNonNull(sizeRead, "sizeRead");
        *sizeRead = static_cast<unsigned long>(source.read(offset, dataSize, data));
    });
}

TQ3Status Q3Storage_SetData(TQ3StorageObject storage, unsigned long offset, unsigned long dataSize,
                            const unsigned char* data, unsigned long* sizeWritten)
{
    return guardStatus(__func__, [&] {
        Storage& target = lookup<Storage>(storage, "storage");
        requireNonNull(data, "data");
        requireNonNull(sizeWritten, "sizeWritten");
        target.requireNotInUse();
        *sizeWritten = static_cast<unsigned long>(target.write(offset, dataSize, data));
    });
}

TQ3StorageObject Q3MemoryStorage_New(const unsigned char* buffer, unsigned long validSize)
{
    return guard(__func__, TQ3StorageObject{nullptr},
                 [&]() -> TQ3StorageObject { return makeShared<MemoryStorage>(buffer, validSize).detach(); });
}

TQ3ObjectType Q3MemoryStorage_GetType(TQ3StorageObject storage)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid}, [&] {
        lookup<MemoryStorage>(storage, "storage");
        return TQ3ObjectType{kQ3ObjectTypeInvalid}; // no subclass: Q3 has no Mac handle storage
    });
}

TQ3Status Q3MemoryStorage_Set(TQ3StorageObject storage, const unsigned char* buffer, unsigned long validSize)
{
    return guardStatus(__func__, [&] {
        MemoryStorage& target = lookup<MemoryStorage>(storage, "storage");
        target.requireNotInUse();
        target.set(buffer, validSize);
    });
}

TQ3StorageObject Q3MemoryStorage_NewBuffer(unsigned char* buffer, unsigned long validSize, unsigned long bufferSize)
{
    return guard(__func__, TQ3StorageObject{nullptr}, [&]() -> TQ3StorageObject {
        return makeShared<MemoryStorage>(buffer, validSize, bufferSize).detach();
    });
}

TQ3Status Q3MemoryStorage_SetBuffer(TQ3StorageObject storage, unsigned char* buffer, unsigned long validSize,
                                    unsigned long bufferSize)
{
    return guardStatus(__func__, [&] {
        MemoryStorage& target = lookup<MemoryStorage>(storage, "storage");
        target.requireNotInUse();
        target.setBuffer(buffer, validSize, bufferSize);
    });
}

TQ3Status Q3MemoryStorage_GetBuffer(TQ3StorageObject storage, unsigned char** buffer, unsigned long* validSize,
                                    unsigned long* bufferSize)
{
    return guardStatus(__func__, [&] {
        MemoryStorage& source = lookup<MemoryStorage>(storage, "storage");
        if (buffer != nullptr)
            *buffer = source.exposeBuffer();
        if (validSize != nullptr)
            *validSize = static_cast<unsigned long>(source.size());
        if (bufferSize != nullptr)
            *bufferSize = static_cast<unsigned long>(source.capacity());
    });
}

TQ3StorageObject Q3UnixPathStorage_New(const char* pathName)
{
    return guard(__func__, TQ3StorageObject{nullptr}, [&]() -> TQ3StorageObject {
        requireNonNull(pathName, "pathName");
        return makeShared<UnixPathStorage>(pathName).detach();
    });
}

TQ3StorageObject Q3PathStorage_New(const char* pathName)
{
    return guard(__func__, TQ3StorageObject{nullptr}, [&]() -> TQ3StorageObject {
        requireNonNull(pathName, "pathName");
        return makeShared<UnixPathStorage>(pathName).detach();
    });
}

TQ3Status Q3UnixPathStorage_Set(TQ3StorageObject storage, const char* pathName)
{
    return guardStatus(__func__, [&] {
        UnixPathStorage& target = lookup<UnixPathStorage>(storage, "storage");
        requireNonNull(pathName, "pathName");
        target.requireNotInUse();
        target.setPath(pathName);
    });
}

TQ3Status Q3UnixPathStorage_Get(TQ3StorageObject storage, char* pathName)
{
    return guardStatus(__func__, [&] {
        const UnixPathStorage& source = lookup<UnixPathStorage>(storage, "storage");
        requireNonNull(pathName, "pathName");
        const std::string& path = source.path();
        std::copy(path.c_str(), path.c_str() + path.size() + 1, pathName);
    });
}
