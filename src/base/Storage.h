// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3D.h"
#include "core/Object.h"

#include <cstddef>
#include <string>
#include <vector>

namespace q3 {

extern const ClassInfo kStorageClass;
extern const ClassInfo kMemoryStorageClass;
extern const ClassInfo kUnixStorageClass;
extern const ClassInfo kUnixPathStorageClass;

/// Where a file object's bytes live (QD3DStorage.h). Invariant: while a file
/// object has the storage open (inUse), its identity (buffer, path) does not
/// change; reads never go past size().
class Storage : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SharedTypeStorage;

    virtual std::size_t size() const = 0;
    /// Copies up to `count` bytes from `offset`; the number copied.
    virtual std::size_t read(std::size_t offset, std::size_t count, unsigned char* out) const = 0;
    /// The `count` bytes from `offset` where they already lie in memory,
    /// valid until the storage next changes; null where they do not (a
    /// file) or are not all there.
    virtual const unsigned char* inPlace(std::size_t, std::size_t) const { return nullptr; }
    /// A number that no other storage, and no other contents of this one,
    /// ever has (its edit index), or 0 where the bytes can change without Q3
    /// knowing: a file, the caller's buffer, or an owned buffer whose address
    /// was handed out (exposeBuffer).
    virtual unsigned long contentVersion() const { return 0; }
    /// Writes `count` bytes at `offset`, growing the storage; the number
    /// written (fewer only for a caller's buffer that is full).
    virtual std::size_t write(std::size_t offset, std::size_t count, const unsigned char* in) = 0;
    /// Replaces the whole contents (what a file object writes when it closes).
    virtual void replaceAll(const std::vector<unsigned char>& bytes) = 0;

    /// The whole contents.
    std::vector<unsigned char> readAll() const;

    bool inUse() const { return m_users > 0; }
    void acquire() { ++m_users; }
    void releaseUse() { --m_users; }
    /// Throws kQ3ErrorStorageInUse while a file object has the storage open.
    void requireNotInUse() const;

private:
    int m_users = 0;
};

/// Bytes in memory: owned (and grown as written) or the caller's buffer used
/// in place. Invariant: m_valid <= capacity; an owned buffer is m_owned.
class MemoryStorage final : public Storage {
public:
    static constexpr TQ3ObjectType kClassType = kQ3StorageTypeMemory;

    MemoryStorage(const unsigned char* bytes, std::size_t validSize) { set(bytes, validSize); }
    MemoryStorage(unsigned char* buffer, std::size_t validSize, std::size_t bufferSize)
    {
        setBuffer(buffer, validSize, bufferSize);
    }

    const ClassInfo& classInfo() const override { return kMemoryStorageClass; }
    Object* duplicate() const override;

    std::size_t size() const override { return m_valid; }
    std::size_t read(std::size_t offset, std::size_t count, unsigned char* out) const override;
    const unsigned char* inPlace(std::size_t offset, std::size_t count) const override;
    std::size_t write(std::size_t offset, std::size_t count, const unsigned char* in) override;
    void replaceAll(const std::vector<unsigned char>& bytes) override;

    void set(const unsigned char* bytes, std::size_t validSize);
    /// Throws kQ3ErrorInvalidParameter when validSize > bufferSize.
    void setBuffer(unsigned char* buffer, std::size_t validSize, std::size_t bufferSize);
    unsigned char* buffer() { return m_borrowed != nullptr ? m_borrowed : m_owned.data(); }
    /// buffer() for a caller that may write through it
    /// (Q3MemoryStorage_GetBuffer): from then on the contents have no version.
    unsigned char* exposeBuffer()
    {
        m_exposed = true;
        return buffer();
    }
    unsigned long contentVersion() const override
    {
        return m_borrowed != nullptr || m_exposed ? 0 : editIndex();
    }
    std::size_t capacity() const { return m_borrowed != nullptr ? m_borrowedSize : m_owned.size(); }

private:
    std::vector<unsigned char> m_owned;
    unsigned char* m_borrowed = nullptr;
    std::size_t m_borrowedSize = 0;
    std::size_t m_valid = 0;
    bool m_exposed = false;
};

/// A file named by a path, opened for each access (so nothing stays open
/// between calls). Invariant: m_path is not empty.
class UnixPathStorage final : public Storage {
public:
    static constexpr TQ3ObjectType kClassType = kQ3UnixStorageTypePath;

    explicit UnixPathStorage(std::string path);

    const ClassInfo& classInfo() const override { return kUnixPathStorageClass; }
    Object* duplicate() const override;

    std::size_t size() const override;
    std::size_t read(std::size_t offset, std::size_t count, unsigned char* out) const override;
    std::size_t write(std::size_t offset, std::size_t count, const unsigned char* in) override;
    void replaceAll(const std::vector<unsigned char>& bytes) override;

    const std::string& path() const { return m_path; }
    /// Throws kQ3ErrorInvalidParameter for an empty path.
    void setPath(std::string path);

private:
    std::string m_path;
};

} // namespace q3
