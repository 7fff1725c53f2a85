// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Writing objects to a 3DMF file in memory and reading them back, through
// the public API only.

#include "QD3D.h"
#include "QD3DErrors.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DIO.h"
#include "QD3DSet.h"
#include "QD3DStorage.h"
#include "QD3DView.h"
#include "MemoryFile.h"
#include "RenderTestSupport.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace q3test {

/// A unit box at the origin, the object the file and custom-class tests
/// write and attach things to.
inline TQ3GeometryObject newBox()
{
    TQ3BoxData data{};
    data.orientation = {1, 0, 0};
    data.majorAxis = {0, 1, 0};
    data.minorAxis = {0, 0, 1};
    return Q3Box_New(&data);
}

/// The bytes of a file written in `mode` by a writing loop whose every pass
/// calls `submit(view)`.
template <class Submit>
std::vector<unsigned char> writeFileWith(TQ3FileMode mode, Submit&& submit)
{
    return writeMemoryFile(mode, std::forward<Submit>(submit), [](bool ok, const char* what) { EXPECT_TRUE(ok) << what; });
}

/// The bytes of a file holding `objects`, written in `mode`.
inline std::vector<unsigned char> writeObjects(const std::vector<TQ3Object>& objects, TQ3FileMode mode)
{
    return writeFileWith(mode, [&](TQ3ViewObject view) {
        for (TQ3Object object : objects)
            EXPECT_EQ(Q3Object_Submit(object, view), kQ3Success);
    });
}

/// The bytes of a Normal file after `refuse(view)` (a submit the caller
/// expects to fail, checking its error) and then a submit of `kept`: what a
/// refused object leaves in the file.
template <class Refuse>
std::vector<unsigned char> writeAfterRefusal(Refuse&& refuse, TQ3Object kept)
{
    return writeFileWith(kQ3FileModeNormal, [&](TQ3ViewObject view) {
        refuse(view);
        EXPECT_EQ(Q3Object_Submit(kept, view), kQ3Success);
    });
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

/// Every object of a file open for reading (stops at the first failure);
/// closes and disposes the file.
inline std::vector<TQ3Object> readAllAndClose(TQ3FileObject file)
{
    std::vector<TQ3Object> objects;
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

/// Every object of the file (stops at the first failure).
inline std::vector<TQ3Object> readAll(const std::vector<unsigned char>& bytes)
{
    TQ3FileObject file = openBytes(bytes);
    if (file == nullptr)
        return {};
    return readAllAndClose(file);
}

/// A group's objects in order (each a new reference: disposeAll them).
inline std::vector<TQ3Object> membersOf(TQ3GroupObject group)
{
    std::vector<TQ3Object> members;
    TQ3GroupPosition position = nullptr;
    for (Q3Group_GetFirstPosition(group, &position); position != nullptr; Q3Group_GetNextPosition(group, &position)) {
        TQ3Object member = nullptr;
        EXPECT_EQ(Q3Group_GetPositionObject(group, position, &member), kQ3Success);
        members.push_back(member);
    }
    return members;
}

inline void disposeAll(const std::vector<TQ3Object>& objects)
{
    for (TQ3Object object : objects)
        Q3Object_Dispose(object);
}

/// Whether two points are equal to the bit (round trips must give back the same numbers).
inline bool samePoint(const TQ3Point3D& a, const TQ3Point3D& b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

/// Whether two attribute sets hold the same attributes with the same values
/// (both absent counts as the same).
inline bool sameSet(TQ3AttributeSet a, TQ3AttributeSet b)
{
    for (TQ3AttributeType type = kQ3AttributeTypeSurfaceUV; type <= kQ3AttributeTypeHighlightState; ++type) {
        const bool inA = a != nullptr && Q3AttributeSet_Contains(a, type) == kQ3True;
        const bool inB = b != nullptr && Q3AttributeSet_Contains(b, type) == kQ3True;
        if (inA != inB)
            return false;
        if (inA) {
            unsigned char va[32] = {}, vb[32] = {};
            Q3AttributeSet_Get(a, type, va);
            Q3AttributeSet_Get(b, type, vb);
            if (std::memcmp(va, vb, sizeof va) != 0)
                return false;
        }
    }
    return true;
}

/// Whether two vertex arrays have the same points and attribute sets.
inline bool sameVertices(const TQ3Vertex3D* a, const TQ3Vertex3D* b, unsigned long n)
{
    for (unsigned long i = 0; i < n; ++i)
        if (!samePoint(a[i].point, b[i].point) || !sameSet(a[i].attributeSet, b[i].attributeSet))
            return false;
    return true;
}

/// The first error of reading every object of the bytes in turn, or
/// kQ3ErrorNone when all of them read. (Later calls clear Q3Error_Get, so
/// the code is taken as soon as a call fails.)
/// Where each top-level object of a binary file ends (a BeginGroup's at its
/// EndGroup, unless `eachObject`: then every object at the file's top level,
/// the BeginGroup, its members and the EndGroup each), walking the sizes
/// after the 24-byte header.
inline std::vector<std::size_t> topLevelEnds(const std::vector<unsigned char>& bytes, bool little,
                                             bool eachObject = false)
{
    std::vector<std::size_t> ends;
    std::size_t at = 24;
    int depth = 0;
    while (at + 8 <= bytes.size()) {
        std::uint32_t word[2] = {0, 0};
        for (int w = 0; w < 2; ++w)
            for (int i = 0; i < 4; ++i)
                word[w] |= std::uint32_t{bytes[at + 4 * w + i]} << (little ? 8 * i : 24 - 8 * i);
        if (word[0] == 0x62676E67) // 'bgng'
            ++depth;
        else if (word[0] == 0x656E6467) // 'endg'
            --depth;
        at += 8 + word[1];
        if (depth == 0 || eachObject)
            ends.push_back(at);
    }
    return ends;
}

/// Whether a binary file cut at `cut` leaves fewer bytes than a type and a
/// size after its last whole object at the file's top level (or after the
/// header; the objects of a group stand at the top level too): bytes
/// Q3 reads past with kQ3WarningInvalidMetafileObject, as QuickDraw 3D read
/// the objects before them (docs/3dmf.md, "Bytes after the last object").
inline bool cutLeavesJunk(const std::vector<unsigned char>& whole, std::size_t cut, bool little)
{
    std::size_t last = 24;
    for (std::size_t end : topLevelEnds(whole, little, true))
        if (end <= cut)
            last = end;
    return cut > last && cut - last < 8;
}

inline TQ3Error readError(const std::vector<unsigned char>& bytes)
{
    TQ3StorageObject storage = Q3MemoryStorage_New(bytes.data(), static_cast<unsigned long>(bytes.size()));
    TQ3FileObject file = Q3File_New();
    Q3File_SetStorage(file, storage);
    Q3Object_Dispose(storage);
    TQ3Error error = kQ3ErrorNone;
    TQ3FileMode mode;
    if (Q3File_OpenRead(file, &mode) != kQ3Success) {
        error = Q3Error_Get(nullptr);
    } else {
        while (Q3File_IsEndOfFile(file) == kQ3False) {
            TQ3Object object = Q3File_ReadObject(file);
            if (object == nullptr) {
                error = Q3Error_Get(nullptr);
                break;
            }
            Q3Object_Dispose(object);
        }
        Q3File_Close(file);
    }
    Q3Object_Dispose(file);
    return error;
}

// readError's later calls clear Q3Error_Get, so the code it returns is
// compared, and the posted error consumed (inside a Q3ApiTest).
#define EXPECT_READ_ERROR(bytes, code)                                                        \
    do {                                                                                      \
        EXPECT_EQ(q3test::readError(bytes), (code));                                          \
        consume(q3test::Kind::Error, (code), #bytes, __FILE__, __LINE__);                     \
    } while (0)

// Big-endian binary building blocks for hand-laid files.

/// Appends v as a big-endian Uns32.
inline void put32(std::vector<unsigned char>& out, std::uint32_t v)
{
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(static_cast<unsigned char>(v >> shift));
}

/// Appends f as a big-endian Float32.
inline void putFloat(std::vector<unsigned char>& out, float f)
{
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, sizeof bits);
    put32(out, bits);
}

/// Appends a four-character tag.
inline void putTag(std::vector<unsigned char>& out, const char* tag)
{
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<unsigned char>(tag[i]));
}

/// A big-endian binary header: 3DMF, version 1.6, Normal, no table of contents.
inline std::vector<unsigned char> binaryHeader()
{
    std::vector<unsigned char> out;
    putTag(out, "3DMF");
    put32(out, 16);
    put32(out, 0x00010006);
    put32(out, 0);
    put32(out, 0);
    put32(out, 0);
    return out;
}

/// The pixels (ARGB32 words, top row first) of `object` drawn alone by the
/// interactive renderer into 96 x 72 through one fixed camera: round trips
/// compare these for the object written and the object read back.
inline std::vector<std::uint32_t> renderedWords(TQ3Object object)
{
    Pixmap image(96, 72);
    const TQ3ViewAngleAspectCameraData cameraData =
        viewAngleCamera({3, 4, 8}, {0, 0, 0}, {0, 1, 0}, 0.8, 96.0 / 72.0);
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&cameraData);
    std::vector<std::uint32_t> words;
    {
        TestView view(image.pixmap(), kQ3RendererTypeInteractive, camera);
        EXPECT_EQ(view.render([&](TQ3ViewObject v) { Q3Object_Submit(object, v); }), kQ3ViewStatusDone);
    }
    Q3Object_Dispose(camera);
    for (unsigned long y = 0; y < image.height(); ++y)
        for (unsigned long x = 0; x < image.width(); ++x)
            words.push_back(image.word(x, y));
    return words;
}

/// The six ways a file is written: Normal, Stream and Database, each binary
/// and text.
const TQ3FileMode kEveryFileMode[] = {kQ3FileModeNormal,   kQ3FileModeNormal | kQ3FileModeText,
                                      kQ3FileModeStream,   kQ3FileModeStream | kQ3FileModeText,
                                      kQ3FileModeDatabase, kQ3FileModeDatabase | kQ3FileModeText};

/// Whether an image (renderedWords) has more than one colour.
inline bool drawsSomething(const std::vector<std::uint32_t>& words)
{
    for (std::uint32_t w : words)
        if (w != words.front())
            return true;
    return false;
}

/// An object a round-trip test writes, and how to tell whether what is read
/// back holds the same.
struct RoundTripCase {
    std::string name;
    std::function<TQ3Object()> make;
    std::function<bool(TQ3Object, TQ3Object)> same;
};

/// Writes the case's object alone in each of kEveryFileMode and reads it
/// back: the file opens in that mode, names the object's type first (a
/// geometry, if `isGeometry`) and holds that one object, which is of the same
/// leaf type, the same by the case's comparison, and drawn to the same
/// pixels; if `mustDraw`, the object draws something at all.
inline void expectRoundTripInEveryMode(const RoundTripCase& c, bool isGeometry, bool mustDraw)
{
    SCOPED_TRACE(c.name);
    TQ3Object original = c.make();
    ASSERT_NE(original, nullptr);
    const auto expected = renderedWords(original);
    if (mustDraw)
        EXPECT_TRUE(drawsSomething(expected));
    for (TQ3FileMode mode : kEveryFileMode) {
        SCOPED_TRACE(mode);
        const auto bytes = writeObjects({original}, mode);
        TQ3FileMode readMode = 0;
        TQ3FileObject file = openBytes(bytes, &readMode);
        ASSERT_NE(file, nullptr);
        EXPECT_EQ(readMode, mode);
        EXPECT_EQ(Q3File_GetNextObjectType(file), Q3Object_GetLeafType(original));
        if (isGeometry)
            EXPECT_EQ(Q3File_IsNextObjectOfType(file, kQ3ShapeTypeGeometry), kQ3True);
        TQ3Object back = Q3File_ReadObject(file);
        ASSERT_NE(back, nullptr);
        EXPECT_EQ(Q3File_IsEndOfFile(file), kQ3True);
        Q3File_Close(file);
        Q3Object_Dispose(file);
        EXPECT_EQ(Q3Object_GetLeafType(back), Q3Object_GetLeafType(original));
        EXPECT_TRUE(c.same(original, back));
        EXPECT_TRUE(renderedWords(back) == expected);
        Q3Object_Dispose(back);
    }
    Q3Object_Dispose(original);
}

} // namespace q3test
