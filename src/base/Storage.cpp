// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "base/Storage.h"

#include "core/Limits.h"

#include <climits>
#include <cstdio>
#include <cstring>
#include <memory>

namespace q3 {

const ClassInfo kStorageClass{kQ3SharedTypeStorage, &kSharedClass, "storage"};
const ClassInfo kMemoryStorageClass{kQ3StorageTypeMemory, &kStorageClass, "memory storage"};
const ClassInfo kUnixStorageClass{kQ3StorageTypeUnix, &kStorageClass, "Unix storage"};
const ClassInfo kUnixPathStorageClass{kQ3UnixStorageTypePath, &kUnixStorageClass, "Unix path storage"};

namespace {

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

[[noreturn]] void failFile(const std::string& path, const char* what)
{
    fail(kQ3ErrorFileNotOpen, "cannot " + std::string(what) + " the file " + path);
}

} // namespace

std::vector<unsigned char> Storage::readAll() const
{
    std::vector<unsigned char> bytes(size());
    bytes.resize(read(0, bytes.size(), bytes.data()));
    return bytes;
}

void Storage::requireNotInUse() const
{
    if (inUse())
        fail(kQ3ErrorStorageInUse, "a file object has the storage open");
}

Object* MemoryStorage::duplicate() const
{
    const unsigned char* bytes = m_borrowed != nullptr ? m_borrowed : m_owned.data();
    return makeShared<MemoryStorage>(bytes, m_valid).detach();
}

std::size_t MemoryStorage::read(std::size_t offset, std::size_t count, unsigned char* out) const
{
    if (offset >= m_valid)
        return 0;
    const std::size_t n = std::min(count, m_valid - offset);
    const unsigned char* bytes = m_borrowed != nullptr ? m_borrowed : m_owned.data();
    std::memcpy(out, bytes + offset, n);
    return n;
}

const unsigned char* MemoryStorage::inPlace(std::size_t offset, std::size_t count) const
{
    if (offset > m_valid || count > m_valid - offset)
        return nullptr;
    const unsigned char* bytes = m_borrowed != nullptr ? m_borrowed : m_owned.data();
    return bytes + offset;
}

std::size_t MemoryStorage::write(std::size_t offset, std::size_t count, const unsigned char* in)
{
    if (count == 0)
        return 0;
    if (m_borrowed != nullptr) {
        if (offset >= m_borrowedSize)
            return 0;
        const std::size_t n = std::min(count, m_borrowedSize - offset);
        if (offset > m_valid)
            std::memset(m_borrowed + m_valid, 0, offset - m_valid);
        std::memcpy(m_borrowed + offset, in, n);
        m_valid = std::max(m_valid, offset + n);
        markEdited();
        return n;
    }
    if (offset > limits::kMaxStorageBytes || count > limits::kMaxStorageBytes - offset)
        fail(kQ3ErrorOutOfMemory, "the memory storage would grow past " +
                                      std::to_string(limits::kMaxStorageBytes) + " bytes");
    if (offset + count > m_owned.size())
        m_owned.resize(offset + count);
    std::memcpy(m_owned.data() + offset, in, count);
    m_valid = std::max(m_valid, offset + count);
    markEdited();
    return count;
}

void MemoryStorage::replaceAll(const std::vector<unsigned char>& bytes)
{
    if (m_borrowed != nullptr) {
        if (bytes.size() > m_borrowedSize)
            fail(kQ3ErrorOutOfMemory, "the caller's buffer of " + std::to_string(m_borrowedSize) +
                                          " bytes cannot hold the " + std::to_string(bytes.size()) +
                                          " bytes written");
        std::memcpy(m_borrowed, bytes.data(), bytes.size());
        m_valid = bytes.size();
    } else {
        m_owned = bytes;
        m_valid = bytes.size();
    }
    markEdited();
}

void MemoryStorage::set(const unsigned char* bytes, std::size_t validSize)
{
    std::vector<unsigned char> copy;
    if (bytes != nullptr)
        copy.assign(bytes, bytes + validSize);
    m_owned = std::move(copy);
    m_borrowed = nullptr;
    m_borrowedSize = 0;
    m_valid = m_owned.size();
    markEdited();
}

void MemoryStorage::setBuffer(unsigned char* buffer, std::size_t validSize, std::size_t bufferSize)
{
    if (validSize > bufferSize)
        fail(kQ3ErrorInvalidParameter, "validSize " + std::to_string(validSize) + " exceeds bufferSize " +
                                           std::to_string(bufferSize));
    if (buffer == nullptr) {
        if (bufferSize > limits::kMaxStorageBytes)
            fail(kQ3ErrorOutOfMemory, "bufferSize " + std::to_string(bufferSize) + " is past the limit");
        m_owned.assign(bufferSize, 0);
        m_borrowed = nullptr;
        m_borrowedSize = 0;
        m_valid = validSize;
    } else {
        m_owned.clear();
        m_borrowed = buffer;
        m_borrowedSize = bufferSize;
        m_valid = validSize;
    }
    markEdited();
}

UnixPathStorage::UnixPathStorage(std::string path)
{
    setPath(std::move(path));
}

Object* UnixPathStorage::duplicate() const
{
    return makeShared<UnixPathStorage>(m_path).detach();
}

void UnixPathStorage::setPath(std::string path)
{
    if (path.empty())
        fail(kQ3ErrorInvalidParameter, "pathName is empty");
    m_path = std::move(path);
    markEdited();
}

std::size_t UnixPathStorage::size() const
{
    FilePtr file(std::fopen(m_path.c_str(), "rb"));
    if (!file)
        return 0;
    if (std::fseek(file.get(), 0, SEEK_END) != 0)
        failFile(m_path, "measure");
    const long end = std::ftell(file.get());
    if (end < 0)
        failFile(m_path, "measure");
    return static_cast<std::size_t>(end);
}

std::size_t UnixPathStorage::read(std::size_t offset, std::size_t count, unsigned char* out) const
{
    FilePtr file(std::fopen(m_path.c_str(), "rb"));
    if (!file)
        failFile(m_path, "open");
    if (offset > static_cast<std::size_t>(LONG_MAX) || std::fseek(file.get(), static_cast<long>(offset), SEEK_SET) != 0)
        return 0;
    return std::fread(out, 1, count, file.get());
}

std::size_t UnixPathStorage::write(std::size_t offset, std::size_t count, const unsigned char* in)
{
    FilePtr file(std::fopen(m_path.c_str(), "r+b"));
    if (!file)
        file.reset(std::fopen(m_path.c_str(), "w+b"));
    if (!file)
        failFile(m_path, "create");
    if (offset > static_cast<std::size_t>(LONG_MAX) || std::fseek(file.get(), 0, SEEK_END) != 0)
        failFile(m_path, "write");
    const long end = std::ftell(file.get());
    if (end >= 0 && static_cast<std::size_t>(end) < offset) {
        std::vector<unsigned char> zeros(offset - static_cast<std::size_t>(end), 0);
        std::fwrite(zeros.data(), 1, zeros.size(), file.get());
    }
    if (std::fseek(file.get(), static_cast<long>(offset), SEEK_SET) != 0)
        failFile(m_path, "write");
    const std::size_t n = std::fwrite(in, 1, count, file.get());
    markEdited();
    return n;
}

void UnixPathStorage::replaceAll(const std::vector<unsigned char>& bytes)
{
    FilePtr file(std::fopen(m_path.c_str(), "wb"));
    if (!file)
        failFile(m_path, "create");
    if (std::fwrite(bytes.data(), 1, bytes.size(), file.get()) != bytes.size())
        failFile(m_path, "write");
    if (std::fclose(file.release()) != 0)
        failFile(m_path, "write");
    markEdited();
}

} // namespace q3
