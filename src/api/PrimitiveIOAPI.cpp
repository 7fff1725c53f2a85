// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The primitive read and write calls of QD3DIO.h (Q3Uns32_Read, ...): each
// is the file lookup, the output check and one DataReader or Encoder call.
#include "QD3DIO.h"

#include "api/Entry.h"
#include "core/Limits.h"
#include "io/File.h"

#include <algorithm>
#include <vector>

#include <cstring>

using namespace q3;
using namespace q3::api;

namespace {

/// A read of one value: room for `bytes` (binary) or `tokens` (text), then
/// *out = read(reader).
template <class Value, class Read>
TQ3Status readValue(const char* function, Value* out, TQ3FileObject theFile, std::size_t bytes, std::size_t tokens,
                    Read read)
{
    return guardStatus(function, [&] {
        File& file = lookup<File>(theFile, "theFile");
        requireNonNull(out, "data");
        *out = file.readPrimitive(bytes, tokens, function, read);
    });
}

/// A read of `count` values of `bytes` bytes (binary) or one token (text)
/// each, all or nothing.
template <class Value, class Read>
TQ3Status readArray(const char* function, TQ3Uns32 count, Value* out, TQ3FileObject theFile, std::size_t bytes,
                    Read read)
{
    return guardStatus(function, [&] {
        File& file = lookup<File>(theFile, "theFile");
        if (count == 0)
            return;
        requireNonNull(out, "the array");
        const std::vector<Value> values =
            file.readPrimitive(std::size_t{count} * bytes, count, function, [&](io::DataReader& in) {
                std::vector<Value> read_;
                read_.reserve(count);
                for (TQ3Uns32 i = 0; i < count; ++i)
                    read_.push_back(read(in));
                return read_;
            });
        std::copy(values.begin(), values.end(), out);
    });
}

/// A write: write(encoder).
template <class Write>
TQ3Status writeValue(const char* function, TQ3FileObject theFile, Write write)
{
    return guardStatus(function, [&] { write(lookup<File>(theFile, "theFile").dataWriter()); });
}

/// A write of the struct `value` points to.
template <class Value, class Write>
TQ3Status writePointed(const char* function, const Value* value, TQ3FileObject theFile, Write write)
{
    return guardStatus(function, [&] {
        File& file = lookup<File>(theFile, "theFile");
        requireNonNull(value, "data");
        write(file.dataWriter(), *value);
    });
}

TQ3Vector2D vector2D(io::DataReader& in)
{
    TQ3Vector2D v;
    v.x = in.f32();
    v.y = in.f32();
    return v;
}

} // namespace

TQ3Status Q3NewLine_Write(TQ3FileObject theFile)
{
    return writeValue(__func__, theFile, [](io::Encoder& out) { out.newLine(); });
}

TQ3Status Q3Comment_Write(char* comment, TQ3FileObject theFile)
{
    return guardStatus(__func__, [&] {
        File& file = lookup<File>(theFile, "theFile");
        requireNonNull(comment, "comment");
        file.dataWriter().comment(comment);
    });
}

TQ3Status Q3Uns8_Read(TQ3Uns8* data, TQ3FileObject theFile)
{
    return readValue(__func__, data, theFile, 1, 1, [](io::DataReader& in) { return in.u8(); });
}

TQ3Status Q3Uns8_Write(TQ3Uns8 data, TQ3FileObject theFile)
{
    return writeValue(__func__, theFile, [&](io::Encoder& out) { out.u8(data); });
}

TQ3Status Q3Uns16_Read(TQ3Uns16* data, TQ3FileObject theFile)
{
    return readValue(__func__, data, theFile, 2, 1, [](io::DataReader& in) { return in.u16(); });
}

TQ3Status Q3Uns16_Write(TQ3Uns16 data, TQ3FileObject theFile)
{
    return writeValue(__func__, theFile, [&](io::Encoder& out) { out.u16(data); });
}

TQ3Status Q3Uns32_Read(TQ3Uns32* data, TQ3FileObject theFile)
{
    return readValue(__func__, data, theFile, 4, 1, [](io::DataReader& in) { return TQ3Uns32{in.u32()}; });
}

TQ3Status Q3Uns32_Write(TQ3Uns32 data, TQ3FileObject theFile)
{
    return writeValue(__func__, theFile, [&](io::Encoder& out) { out.u32(data); });
}

TQ3Status Q3Int8_Read(TQ3Int8* data, TQ3FileObject theFile)
{
    return readValue(__func__, data, theFile, 1, 1, [](io::DataReader& in) { return in.i8(); });
}

TQ3Status Q3Int8_Write(TQ3Int8 data, TQ3FileObject theFile)
{
    return writeValue(__func__, theFile, [&](io::Encoder& out) {
        if (out.encoding() == io::Encoding::kText)
            out.i32(data);
        else
            out.u8(static_cast<std::uint8_t>(data));
    });
}

TQ3Status Q3Int16_Read(TQ3Int16* data, TQ3FileObject theFile)
{
    return readValue(__func__, data, theFile, 2, 1, [](io::DataReader& in) { return in.i16(); });
}

TQ3Status Q3Int16_Write(TQ3Int16 data, TQ3FileObject theFile)
{
    return writeValue(__func__, theFile, [&](io::Encoder& out) {
        if (out.encoding() == io::Encoding::kText)
            out.i32(data);
        else
            out.u16(static_cast<std::uint16_t>(data));
    });
}

TQ3Status Q3Int32_Read(TQ3Int32* data, TQ3FileObject theFile)
{
    return readValue(__func__, data, theFile, 4, 1, [](io::DataReader& in) { return TQ3Int32{in.i32()}; });
}

TQ3Status Q3Int32_Write(TQ3Int32 data, TQ3FileObject theFile)
{
    return writeValue(__func__, theFile, [&](io::Encoder& out) { out.i32(data); });
}

TQ3Status Q3Uns64_Read(TQ3Uns64* data, TQ3FileObject theFile)
{
    return readValue(__func__, data, theFile, 8, 1, [](io::DataReader& in) {
        const std::uint64_t value = in.u64();
        TQ3Uns64 out;
        out.hi = static_cast<TQ3Uns32>(value >> 32);
        out.lo = static_cast<TQ3Uns32>(value & 0xFFFFFFFFu);
        return out;
    });
}

TQ3Status Q3Uns64_Write(TQ3Uns64 data, TQ3FileObject theFile)
{
    return writeValue(__func__, theFile,
                      [&](io::Encoder& out) { out.u64(std::uint64_t{data.hi} << 32 | data.lo); });
}

TQ3Status Q3Int64_Read(TQ3Int64* data, TQ3FileObject theFile)
{
    return readValue(__func__, data, theFile, 8, 1, [](io::DataReader& in) {
        const std::uint64_t value = static_cast<std::uint64_t>(in.i64());
        TQ3Int64 out;
        out.hi = static_cast<TQ3Int32>(static_cast<TQ3Uns32>(value >> 32));
        out.lo = static_cast<TQ3Uns32>(value & 0xFFFFFFFFu);
        return out;
    });
}

TQ3Status Q3Int64_Write(TQ3Int64 data, TQ3FileObject theFile)
{
    return guardStatus(__func__, [&] {
        File& file = lookup<File>(theFile, "theFile");
        const std::uint64_t bits = std::uint64_t{static_cast<std::uint32_t>(data.hi)} << 32 | data.lo;
        io::Encoder& out = file.dataWriter();
        if (out.encoding() == io::Encoding::kText)
            out.raw(std::to_string(static_cast<std::int64_t>(bits)));
        else
            out.u64(bits);
    });
}

TQ3Status Q3Float32_Read(TQ3Float32* data, TQ3FileObject theFile)
{
    return readValue(__func__, data, theFile, 4, 1, [](io::DataReader& in) { return in.f32(); });
}

TQ3Status Q3Float32_Write(TQ3Float32 data, TQ3FileObject theFile)
{
    return writeValue(__func__, theFile, [&](io::Encoder& out) { out.f32(data); });
}

TQ3Status Q3Float64_Read(TQ3Float64* data, TQ3FileObject theFile)
{
    return readValue(__func__, data, theFile, 8, 1, [](io::DataReader& in) { return in.f64(); });
}

TQ3Status Q3Float64_Write(TQ3Float64 data, TQ3FileObject theFile)
{
    return writeValue(__func__, theFile, [&](io::Encoder& out) { out.f64(data); });
}

TQ3Size Q3Size_Pad(TQ3Size size)
{
    return guard(__func__, TQ3Size{0}, [&] {
        if (size > 0xFFFFFFFCul)
            fail(kQ3ErrorInvalidParameter, "size " + std::to_string(size) + " cannot be padded in 32 bits");
        return (size + 3) & ~TQ3Size{3};
    });
}

TQ3Status Q3String_Read(char* data, unsigned long* length, TQ3FileObject theFile)
{
    return guardStatus(__func__, [&] {
        File& file = lookup<File>(theFile, "theFile");
        requireNonNull(length, "length");
        const bool peek = data == nullptr; // Quesa's extension: the length only
        const std::string text = file.readPrimitive(1, 1, __func__, [peek](io::DataReader& in) {
            const std::size_t at = in.tell();
            std::string read = in.string();
            if (peek)
                in.seek(at);
            return read;
        });
        if (peek) {
            *length = text.size();
            return;
        }
        const std::size_t n = std::min<std::size_t>(text.size(), kQ3StringMaximumLength - 1);
        std::memcpy(data, text.data(), n);
        data[n] = '\0';
        *length = n;
    });
}

TQ3Status Q3String_Write(const char* data, TQ3FileObject theFile)
{
    return guardStatus(__func__, [&] {
        File& file = lookup<File>(theFile, "theFile");
        requireNonNull(data, "data");
        const std::size_t n = std::strlen(data);
        if (n >= kQ3StringMaximumLength)
            fail(kQ3ErrorInvalidParameter, "the string is " + std::to_string(n) + " characters long; at most " +
                                               std::to_string(kQ3StringMaximumLength - 1) + " are written");
        file.dataWriter().string(std::string(data, n));
    });
}

TQ3Status Q3RawData_Read(unsigned char* data, unsigned long size, TQ3FileObject theFile)
{
    return guardStatus(__func__, [&] {
        File& file = lookup<File>(theFile, "theFile");
        requireNonNull(data, "data");
        if (size > limits::kMaxStorageBytes)
            fail(kQ3ErrorReadMoreThanSize, "size " + std::to_string(size) + " is more than any object holds");
        const std::string bytes =
            file.readPrimitive(size, size == 0 ? 0 : 1, __func__,
                               [size](io::DataReader& in) { return size == 0 ? std::string() : in.rawData(size); });
        std::memcpy(data, bytes.data(), bytes.size());
    });
}

TQ3Status Q3RawData_Write(const unsigned char* data, unsigned long size, TQ3FileObject theFile)
{
    return guardStatus(__func__, [&] {
        File& file = lookup<File>(theFile, "theFile");
        if (size == 0)
            return;
        requireNonNull(data, "data");
        if (size > limits::kMaxStorageBytes)
            fail(kQ3ErrorInvalidParameter, "size " + std::to_string(size) + " is more than a file holds");
        file.dataWriter().rawData(data, size);
    });
}

TQ3Status Q3Point2D_Read(TQ3Point2D* point2D, TQ3FileObject theFile)
{
    return readValue(__func__, point2D, theFile, 8, 2, [](io::DataReader& in) {
        const TQ3Vector2D v = vector2D(in);
        return TQ3Point2D{v.x, v.y};
    });
}

TQ3Status Q3Point2D_Write(const TQ3Point2D* point2D, TQ3FileObject theFile)
{
    return writePointed(__func__, point2D, theFile, [](io::Encoder& out, const TQ3Point2D& p) {
        out.f32(p.x);
        out.f32(p.y);
    });
}

TQ3Status Q3Point3D_Read(TQ3Point3D* point3D, TQ3FileObject theFile)
{
    return readValue(__func__, point3D, theFile, 12, 3, [](io::DataReader& in) { return in.point3D(); });
}

TQ3Status Q3Point3D_Write(const TQ3Point3D* point3D, TQ3FileObject theFile)
{
    return writePointed(__func__, point3D, theFile, [](io::Encoder& out, const TQ3Point3D& p) { out.point3D(p); });
}

TQ3Status Q3RationalPoint3D_Read(TQ3RationalPoint3D* point3D, TQ3FileObject theFile)
{
    return readValue(__func__, point3D, theFile, 12, 3, [](io::DataReader& in) {
        const TQ3Point3D p = in.point3D();
        return TQ3RationalPoint3D{p.x, p.y, p.z};
    });
}

TQ3Status Q3RationalPoint3D_Write(const TQ3RationalPoint3D* point3D, TQ3FileObject theFile)
{
    return writePointed(__func__, point3D, theFile,
                        [](io::Encoder& out, const TQ3RationalPoint3D& p) { out.point3D({p.x, p.y, p.w}); });
}

TQ3Status Q3RationalPoint4D_Read(TQ3RationalPoint4D* point4D, TQ3FileObject theFile)
{
    return readValue(__func__, point4D, theFile, 16, 4, [](io::DataReader& in) { return in.point4D(); });
}

TQ3Status Q3RationalPoint4D_Write(const TQ3RationalPoint4D* point4D, TQ3FileObject theFile)
{
    return writePointed(__func__, point4D, theFile,
                        [](io::Encoder& out, const TQ3RationalPoint4D& p) { out.point4D(p); });
}

TQ3Status Q3Vector2D_Read(TQ3Vector2D* vector2DOut, TQ3FileObject theFile)
{
    return readValue(__func__, vector2DOut, theFile, 8, 2, [](io::DataReader& in) { return vector2D(in); });
}

TQ3Status Q3Vector2D_Write(const TQ3Vector2D* vector2DIn, TQ3FileObject theFile)
{
    return writePointed(__func__, vector2DIn, theFile, [](io::Encoder& out, const TQ3Vector2D& v) {
        out.f32(v.x);
        out.f32(v.y);
    });
}

TQ3Status Q3Vector3D_Read(TQ3Vector3D* vector3D, TQ3FileObject theFile)
{
    return readValue(__func__, vector3D, theFile, 12, 3, [](io::DataReader& in) { return in.vector3D(); });
}

TQ3Status Q3Vector3D_Write(const TQ3Vector3D* vector3D, TQ3FileObject theFile)
{
    return writePointed(__func__, vector3D, theFile, [](io::Encoder& out, const TQ3Vector3D& v) { out.vector3D(v); });
}

TQ3Status Q3Matrix4x4_Read(TQ3Matrix4x4* matrix4x4, TQ3FileObject theFile)
{
    return readValue(__func__, matrix4x4, theFile, 64, 16, [](io::DataReader& in) {
        TQ3Matrix4x4 m;
        for (auto& row : m.value)
            for (float& v : row)
                v = in.f32();
        return m;
    });
}

TQ3Status Q3Matrix4x4_Write(const TQ3Matrix4x4* matrix4x4, TQ3FileObject theFile)
{
    return writePointed(__func__, matrix4x4, theFile, [](io::Encoder& out, const TQ3Matrix4x4& m) {
        for (const auto& row : m.value)
            for (const float v : row)
                out.f32(v);
    });
}

TQ3Status Q3Tangent2D_Read(TQ3Tangent2D* tangent2D, TQ3FileObject theFile)
{
    return readValue(__func__, tangent2D, theFile, 24, 6, [](io::DataReader& in) {
        TQ3Tangent2D t;
        t.uTangent = in.vector3D();
        t.vTangent = in.vector3D();
        return t;
    });
}

TQ3Status Q3Tangent2D_Write(const TQ3Tangent2D* tangent2D, TQ3FileObject theFile)
{
    return writePointed(__func__, tangent2D, theFile, [](io::Encoder& out, const TQ3Tangent2D& t) {
        out.vector3D(t.uTangent);
        out.vector3D(t.vTangent);
    });
}

TQ3Status Q3Tangent3D_Read(TQ3Tangent3D* tangent3D, TQ3FileObject theFile)
{
    return readValue(__func__, tangent3D, theFile, 36, 9, [](io::DataReader& in) {
        TQ3Tangent3D t;
        t.uTangent = in.vector3D();
        t.vTangent = in.vector3D();
        t.wTangent = in.vector3D();
        return t;
    });
}

TQ3Status Q3Tangent3D_Write(const TQ3Tangent3D* tangent3D, TQ3FileObject theFile)
{
    return writePointed(__func__, tangent3D, theFile, [](io::Encoder& out, const TQ3Tangent3D& t) {
        out.vector3D(t.uTangent);
        out.vector3D(t.vTangent);
        out.vector3D(t.wTangent);
    });
}

TQ3Status Q3Uns8_ReadArray(TQ3Uns32 numNums, TQ3Uns8* intArray, TQ3FileObject theFile)
{
    return readArray(__func__, numNums, intArray, theFile, 1, [](io::DataReader& in) { return in.u8(); });
}

TQ3Status Q3Uns16_ReadArray(TQ3Uns32 numNums, TQ3Uns16* intArray, TQ3FileObject theFile)
{
    return readArray(__func__, numNums, intArray, theFile, 2, [](io::DataReader& in) { return in.u16(); });
}

TQ3Status Q3Uns32_ReadArray(TQ3Uns32 numNums, TQ3Uns32* intArray, TQ3FileObject theFile)
{
    return readArray(__func__, numNums, intArray, theFile, 4, [](io::DataReader& in) { return in.u32(); });
}

TQ3Status Q3Float32_ReadArray(TQ3Uns32 numFloats, TQ3Float32* floatArray, TQ3FileObject theFile)
{
    return readArray(__func__, numFloats, floatArray, theFile, 4, [](io::DataReader& in) { return in.f32(); });
}
