// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The byte format the API fuzzer (ApiFuzzer.cpp) reads and the seed maker
// (MakeSeeds.cpp) writes. An input is a sequence of operations; each starts
// with one byte, taken modulo kOpCount, followed by that operation's
// arguments. Numbers are little-endian. Every read past the end yields zeros,
// and the fuzzer stops at the first operation that starts past the end, so
// every byte string is a valid input.
//
// Common argument encodings (see Reader below):
//   handle    a selector byte and a `which` byte. Selector < 160: held
//             reference number `which` among those of the kind the call wants
//             (among all held ones if there is none); < 200: among all held
//             references; < 215: NULL; < 235: a handle disposed earlier in
//             the input (checked dead first, else NULL); otherwise a stray
//             pointer into memory that never held an object.
//   value     one tag byte, then: tag % 16 < 6: an int8 / 4; == 6: four raw
//             bytes (any float, NaN and infinities included); == 7: one byte
//             indexing kSpecialValues; otherwise an int16 / 256.
//   index     one tag byte, then: tag % 8 == 0: four raw bytes (UINT32_MAX
//             and friends); == 1: the last valid index; == 2: one past it;
//             otherwise a byte modulo the count + 2.
//
// Described data (FuzzData.h): a geometry's data struct read by walking the
// library's description of it. First a handle, the palette; then every field
// but the malloc'ed arrays, in the description's order; then those arrays,
// in that order. An element of an array that is itself described (a
// TQ3Vertex3D) is read the same way, its own arrays after its other fields.
//   float     a value; points, vectors and rational 2D points three,
//             rational points four; a fixed array (an edge's vertexIndices)
//             or a plain struct (TQ3BoundingBox, a TriMesh triangle or
//             edge) its members in order.
//   integer   or enumeration: one byte t, < 224: t % 16; else four raw bytes.
//   count     (a count with a minimum): one byte t, < 200: t % 13; < 232:
//             13 + one more byte; < 244: kQ3GeometryMaxArrayCount + 1 +
//             (t - 232); else ULONG_MAX - (t - 244).
//   handle    one byte, < 128: NULL; < 240: the palette; else a handle
//             (two more bytes, as above).
//   storage   (a pixmap's image, read with the arrays): one byte t, < 32:
//             NULL; < 48: a handle; else a new memory storage of t - 48
//             bytes, or for t >= 240 of a u16 % 4097 bytes, followed by its
//             first 16 bytes (the rest a pattern).
//   array     one shape byte s. For a count past kQ3GeometryMaxArrayCount no
//             element follows, and the array is NULL (s odd) or a decoy of
//             one element. Otherwise s % 16 == 15 or a count past the
//             generator's element budget: NULL, nothing follows; else the
//             count's elements follow (an array of none is NULL when s &
//             0x10). Arrays are never shorter than their counts claim.
//   attribute arrays  (a TriMesh's, TriMeshAttributeArraysField): the
//             number of types as a count with the other fields; with the
//             arrays, an array of that many entries, each: one byte t, < 224:
//             the type t % 13 (0 and 12 unknown), else four raw bytes; its
//             data, an array of its type's values for every element (floats
//             as values, a highlight state as an integer, a surface shader a
//             byte < 128 for NULL, else a handle), or for an unknown type
//             one byte, odd for NULL, else a one-word decoy; one byte, < 128
//             for no use array, else an array of a char per element.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace q3fuzz {

enum class Op : std::uint8_t {
    kNewCurve,
    kCurveSetData,
    kCurveGetData,
    kSetKnot,
    kGetKnot,
    kSetControlPoint,
    kGetControlPoint,
    kDuplicate,
    kDispose,
    kGetReference,
    kNewStyle,
    kStyleSetGet,
    kNewTransform,
    kNewAttributeSet,
    kNewOtherGeometry,
    kNewCamera,
    kCameraEdit,
    kNewDrawContext,
    kDrawContextEdit,
    kNewRenderer,
    kNewView,
    kViewSet,
    kViewGet,
    kStartRendering,
    kEndRendering,
    kStartBounding,
    kEndBounding,
    kSubmitRetained,
    kSubmitCurveImmediate,
    kSubmitStyleImmediate,
    kSubmitTransformImmediate,
    kPushPop,
    kDecompose,
    kViewState,
    kCancelSync,
    kObjectQueries,
    kInitializeExit,
    kOtherGeometryEdit,
    kMath,
    kAccessors,
    kSurfaces,
    kStylesShadersLights,
    kGroups,
    kCurveTools,
    kQuadrics,
    kMeshes,
    kPatches,
    kPolygons2,
    kPixmapMarkers,
    kViewHints,
    kPicking,
    kControllers,
    kElements,
    kDescribed,
    kPortable,
    kCount
};
constexpr unsigned kOpCount = static_cast<unsigned>(Op::kCount);

/// Curve data modes (the low two bits of a curve's flag byte).
enum CurveMode : std::uint8_t {
    kCurveRaw = 0,       ///< every value read from the input
    kCurveGenerated = 1, ///< a clamped uniform curve of a given size, then patches
    kCurveListing1 = 2,  ///< the article's Listing 1, then patches
    kCurveRawKnots = 3,  ///< generated points, knots read raw
};
/// Curve flag bits above the mode.
constexpr std::uint8_t kCurveRawOrder = 0x04;     ///< order is four raw bytes
constexpr std::uint8_t kCurveShortCount = 0x08;   ///< numPoints claims fewer points than given
constexpr std::uint8_t kCurveHugeCount = 0x10;    ///< numPoints claims more than a size_t can address
constexpr std::uint8_t kCurveAttributes = 0x20;   ///< an attribute set handle follows
constexpr std::uint8_t kCurveNullPoints = 0x40;
constexpr std::uint8_t kCurveNullKnots = 0x80;

/// Values the `value` encoding can name with one byte.
inline const std::vector<float>& specialValues()
{
    static const std::vector<float> values = {
        std::numeric_limits<float>::quiet_NaN(),
        std::numeric_limits<float>::infinity(),
        -std::numeric_limits<float>::infinity(),
        0.0f,
        -0.0f,
        std::numeric_limits<float>::max(),
        -std::numeric_limits<float>::max(),
        std::numeric_limits<float>::min(),
        std::numeric_limits<float>::denorm_min(),
        -std::numeric_limits<float>::denorm_min(),
        1e-6f,
        1e-3f,
        1.0f,
        1e6f,
        1e20f,
        -1e20f,
        16777216.0f,
        1024.0f,
        1025.0f,
        0.5f,
        -1.0f,
        3.14159265f,
        1e-30f,
        -std::numeric_limits<float>::signaling_NaN(),
    };
    return values;
}

/// Reads the format above; past the end every read gives zeros.
class Reader {
public:
    Reader(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}

    bool atEnd() const { return m_offset >= m_size; }
    std::size_t remaining() const { return m_offset < m_size ? m_size - m_offset : 0; }

    std::uint8_t u8() { return m_offset < m_size ? m_data[m_offset++] : 0; }
    std::uint16_t u16()
    {
        const std::uint16_t low = u8();
        return static_cast<std::uint16_t>(low | (u8() << 8));
    }
    std::uint32_t u32()
    {
        const std::uint32_t low = u16();
        return low | (std::uint32_t(u16()) << 16);
    }
    float rawFloat()
    {
        const std::uint32_t bits = u32();
        float value;
        std::memcpy(&value, &bits, sizeof value);
        return value;
    }

    float value()
    {
        const std::uint8_t tag = u8() % 16;
        if (tag < 6)
            return float(static_cast<std::int8_t>(u8())) / 4.0f;
        if (tag == 6)
            return rawFloat();
        if (tag == 7) {
            const std::vector<float>& special = specialValues();
            return special[u8() % special.size()];
        }
        return float(static_cast<std::int16_t>(u16())) / 256.0f;
    }

    /// An index into something of `count` elements, biased to the boundaries.
    unsigned long index(unsigned long count)
    {
        const std::uint8_t tag = u8() % 8;
        if (tag == 0)
            return u32();
        if (tag == 1)
            return count == 0 ? 0 : count - 1;
        if (tag == 2)
            return count;
        return u8() % (count + 2);
    }

private:
    const std::uint8_t* m_data;
    std::size_t m_size;
    std::size_t m_offset = 0;
};

/// Builds inputs for the seed corpus, mirroring Reader. Self is the class
/// deriving from it, so that chained calls keep its own methods in reach.
template <class Self>
class BasicWriter {
public:
    Self& op(Op value) { return u8(static_cast<std::uint8_t>(value)); }
    Self& u8(std::uint8_t value)
    {
        m_bytes.push_back(value);
        return self();
    }
    Self& u16(std::uint16_t value) { return u8(value & 0xFF).u8(value >> 8); }
    Self& u32(std::uint32_t value) { return u16(value & 0xFFFF).u16(value >> 16); }
    Self& rawFloat(float value)
    {
        std::uint32_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        return u32(bits);
    }
    /// A value read back exactly: quarter steps from -32 to 31.75 take the
    /// int8 form, anything else four raw bytes.
    Self& value(float v)
    {
        const float quarter = v * 4.0f;
        if (quarter >= -128.0f && quarter <= 127.0f && float(int(quarter)) == quarter)
            return u8(0).u8(static_cast<std::uint8_t>(static_cast<std::int8_t>(int(quarter))));
        return u8(6).rawFloat(v);
    }
    Self& special(std::uint8_t which) { return u8(7).u8(which); }
    /// The handle selectors.
    Self& held(std::uint8_t which = 0) { return u8(0).u8(which); }
    Self& anyHeld(std::uint8_t which) { return u8(160).u8(which); }
    Self& null() { return u8(200).u8(0); }
    Self& stale(std::uint8_t which = 0) { return u8(220).u8(which); }
    Self& stray(std::uint8_t which = 0) { return u8(240).u8(which); }
    /// Described data (see above): a field's pieces.
    Self& xyz(float x, float y, float z) { return value(x).value(y).value(z); }
    Self& count(std::uint8_t n) { return u8(n); } ///< n <= 12
    Self& noSet() { return u8(0); }
    Self& paletteSet() { return u8(128); }
    Self& vertex(float x, float y, float z, bool set = false) { return xyz(x, y, z).u8(set ? 128 : 0); }
    Self& array() { return u8(0); }   ///< the elements follow
    Self& noArray() { return u8(15); } ///< NULL, nothing follows
    /// An index given as a plain byte (tag 3), or as four raw bytes.
    Self& smallIndex(std::uint8_t i) { return u8(3).u8(i); }
    Self& rawIndex(std::uint32_t i) { return u8(0).u32(i); }

    const std::vector<std::uint8_t>& bytes() const { return m_bytes; }

private:
    Self& self() { return static_cast<Self&>(*this); }

    std::vector<std::uint8_t> m_bytes;
};

} // namespace q3fuzz
