// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The API fuzzer's data generator, driven by the library's own description of
// each geometry's C struct (core/DataLayout.h: Describe<S>::fields()). It walks
// the description field by field, reading each value from the input in the
// field's encoding (FuzzInput.h, "described data"): floats, points and
// vectors in the `value` encoding (NaN, infinities and huge values
// included), counts from 0 to a few hundred or past kQ3GeometryMaxArrayCount,
// attribute sets NULL, shared or any handle, surface shaders and storage
// objects where the description holds one (a pixmap's image is a memory
// storage made for the call, of a size from the input), and arrays sized
// from their counts, NULL, or a one-element decoy behind a count Q3 must
// refuse before reading anything. Arrays nest as their descriptions do (a
// general polygon's contours of vertices, a patch's trim loops of curves);
// a TriMesh's attribute arrays (TriMesh.h, TriMeshAttributeArraysField) get
// an entry per type, each with a data block of its type's values and an
// optional use array. A new field in a description is generated with no
// change here; a field kind or a value type this file does not know is a
// compile error.
//
// The same walk compares two structs (sameData): every described field, each
// array element by element up to its count. The fuzzer uses it to check that
// what New or SetData accepted reads back.
//
// Every geometry whose data is one described struct is generated here: the
// descriptions are in the classes' headers (points, lines, polylines,
// triangles, polygons, the seven quadrics, general polygons, markers, pixmap
// markers, NURB curves and patches, polyhedra, triangle grids, TriMeshes).
// Some types also keep a hand-written generator for what a description
// cannot state and the code behind validation needs (Session::readCurve and
// readPatch: valid knots; readTriMesh and polygons2: indices within their
// counts; storagePixmap: a storage of exactly the pixmap's size).

#include "FuzzInput.h"

#include "core/DataLayout.h"
#include "geometry/Box.h"
#include "geometry/Cone.h"
#include "geometry/Cylinder.h"
#include "geometry/DataGeometryImpl.h"
#include "geometry/Disk.h"
#include "geometry/Ellipse.h"
#include "geometry/Ellipsoid.h"
#include "geometry/GeneralPolygon.h"
#include "geometry/Line.h"
#include "geometry/Marker.h"
#include "geometry/NURBCurve.h"
#include "geometry/NURBPatch.h"
#include "geometry/PixmapMarker.h"
#include "geometry/Point.h"
#include "geometry/PolyLine.h"
#include "geometry/Polygon.h"
#include "geometry/Polyhedron.h"
#include "geometry/Torus.h"
#include "geometry/TriGrid.h"
#include "geometry/TriMesh.h"
#include "geometry/Triangle.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace q3fuzz {

namespace layout = q3::layout;

template <class>
inline constexpr bool kAlwaysFalse = false;

/// The arrays a generated struct points at; they live as long as the arena.
/// Objects made for the struct (storage) are given back, by the cleanups
/// registered with atEnd, when it goes.
class DataArena {
public:
    DataArena() = default;
    DataArena(const DataArena&) = delete;
    DataArena& operator=(const DataArena&) = delete;
    ~DataArena()
    {
        for (auto it = m_cleanups.rbegin(); it != m_cleanups.rend(); ++it)
            (*it)();
    }

    void atEnd(std::function<void()> cleanup) { m_cleanups.push_back(std::move(cleanup)); }

    /// n value-initialized (zero) elements; at least one, so that a decoy
    /// for a count of 0 is still a real pointer.
    template <class E>
    E* allocate(std::size_t n)
    {
        auto block = std::make_shared<std::vector<E>>(n == 0 ? 1 : n);
        E* elements = block->data();
        m_blocks.push_back(std::move(block));
        return elements;
    }

private:
    std::vector<std::shared_ptr<void>> m_blocks;
    std::vector<std::function<void()>> m_cleanups;
};

/// Where the generator's objects come from (the fuzzer's session).
struct HandleSource {
    /// Any handle in the handle encoding, a held object of the given class
    /// (kQ3SharedTypeSet, kQ3ShaderTypeSurface) most often.
    std::function<TQ3Object(TQ3ObjectType)> pick;
    /// A new memory storage holding the bytes, given back when the arena
    /// goes; NULL when it could not be made.
    std::function<TQ3Object(const std::vector<unsigned char>&)> storage;
};

/// The bytes of one value of a TriMesh attribute type, by QD3DSet.h's table
/// of the standard types (0 for any other).
inline std::size_t attributeValueBytes(TQ3AttributeType type)
{
    switch (type) {
    case kQ3AttributeTypeSurfaceUV:
    case kQ3AttributeTypeShadingUV: return sizeof(TQ3Param2D);
    case kQ3AttributeTypeNormal: return sizeof(TQ3Vector3D);
    case kQ3AttributeTypeAmbientCoefficient:
    case kQ3AttributeTypeSpecularControl: return sizeof(float);
    case kQ3AttributeTypeDiffuseColor:
    case kQ3AttributeTypeSpecularColor:
    case kQ3AttributeTypeTransparencyColor: return sizeof(TQ3ColorRGB);
    case kQ3AttributeTypeSurfaceTangent: return sizeof(TQ3Tangent2D);
    case kQ3AttributeTypeHighlightState: return sizeof(TQ3Switch);
    case kQ3AttributeTypeSurfaceShader: return sizeof(TQ3SurfaceShaderObject);
    default: return 0;
    }
}

/// Fills a described struct from the input (the format: FuzzInput.h,
/// "described data"). Attribute set fields take NULL, the palette (one
/// attribute set picked for the whole struct, so that a struct's sets are
/// mostly the same live one) or a fresh pick of any handle; storage fields a
/// new memory storage, NULL or a pick.
class DataGenerator {
public:
    /// Elements one struct may allocate over all its arrays; an array that
    /// would need more is passed as NULL (its count unchanged).
    static constexpr std::size_t kElementBudget = 2048;

    /// The most bytes a storage made for a struct holds.
    static constexpr std::size_t kMaxStorageBytes = 4096;

    DataGenerator(Reader& in, DataArena& arena, HandleSource source, TQ3Object palette)
        : m_in(in), m_arena(arena), m_source(std::move(source)), m_palette(palette)
    {
    }

    /// Every field but the malloc'ed arrays in the description's order, then
    /// the arrays (their counts are known by then).
    template <class S>
    void fill(S& s)
    {
        layout::forEachField<S>([&](const auto& field) { scalar(s, field); });
        layout::forEachField<S>([&](const auto& field) { array(s, field); });
    }

private:
    // ---- First round: values, counts, handles, inline arrays, nested structs.
    template <class S, class T, bool Finite>
    void scalar(S& s, const layout::ValueField<S, T, Finite>& f)
    {
        readValue(s.*f.member);
    }
    template <class S, class N>
    void scalar(S& s, const layout::AtLeastField<S, N>& f)
    {
        s.*f.member = N(count());
    }
    template <class S, class C>
    void scalar(S& s, const layout::HandleField<S, C>& f)
    {
        // A storage comes with the arrays: its size may follow from any
        // field.
        if constexpr (!std::is_same<C, q3::Storage>::value)
            s.*f.member = handle();
    }
    template <class S, class E, std::size_t N>
    void scalar(S& s, const layout::InlineArrayField<S, E, N>& f)
    {
        for (E& e : s.*f.member)
            element(e);
    }
    template <class S, class E>
    void scalar(S& s, const layout::NestedField<S, E>& f)
    {
        fill(s.*f.member);
    }
    template <class S, class E, class Count>
    void scalar(S&, const layout::ArrayField<S, E, Count>&)
    {
    }
    template <class S, class C, class Count>
    void scalar(S&, const layout::HandleArrayField<S, C, Count>&)
    {
    }
    template <class S>
    void scalar(S& s, const q3::TriMeshAttributeArraysField& f)
    {
        s.*f.typeCount = count();
    }

    // ---- Second round: the malloc'ed arrays.
    template <class S, class F>
    void array(S&, const F&)
    {
    }
    template <class S, class E, class Count>
    void array(S& s, const layout::ArrayField<S, E, Count>& f)
    {
        s.*f.member = block<E>(f.count(s), [&](E& e) { element(e); });
    }
    template <class S, class C>
    void array(S& s, const layout::HandleField<S, C>& f)
    {
        if constexpr (std::is_same<C, q3::Storage>::value)
            s.*f.member = storage();
    }
    template <class S>
    void array(S& s, const q3::TriMeshAttributeArraysField& f)
    {
        const std::size_t elements = s.*f.elementCount;
        s.*f.member = block<TQ3TriMeshAttributeData>(s.*f.typeCount, [&](TQ3TriMeshAttributeData& entry) {
            attributeEntry(entry, elements);
        });
    }
    template <class S, class C, class Count>
    void array(S& s, const layout::HandleArrayField<S, C, Count>& f)
    {
        // A count may depend on whether the array is there (a TriGrid's
        // facets): counted as if it were.
        TQ3Object decoy = nullptr;
        s.*f.member = &decoy;
        const std::size_t n = f.count(s);
        s.*f.member = block<TQ3Object>(n, [&](TQ3Object& h) { h = handle(); });
    }

    /// One shape byte, then the elements: see FuzzInput.h. `claimed` is the
    /// count Q3 checks against kQ3GeometryMaxArrayCount (a TriMesh
    /// attribute's values, n floats each of several, are counted in
    /// elements).
    template <class E, class Fill>
    E* block(std::size_t n, Fill fillOne, std::size_t claimed)
    {
        const std::uint8_t shape = m_in.u8();
        if (claimed > kQ3GeometryMaxArrayCount)
            return (shape & 1) ? nullptr : m_arena.allocate<E>(1); // must be refused unread
        if (shape % 16 == 15 || n > m_budget)
            return nullptr;
        m_budget -= n;
        E* elements = m_arena.allocate<E>(n);
        for (std::size_t i = 0; i < n; ++i)
            fillOne(elements[i]);
        return n == 0 && (shape & 0x10) ? nullptr : elements;
    }
    template <class E, class Fill>
    E* block(std::size_t n, Fill fillOne)
    {
        return block<E>(n, fillOne, n);
    }

    // A TriMesh attribute entry for `elements` elements: its type, its data
    // block (values of the type; an unknown type's block is one decoy word,
    // as Q3 must refuse the type before reading it) and its use array.
    void attributeEntry(TQ3TriMeshAttributeData& entry, std::size_t elements)
    {
        const std::uint8_t tag = m_in.u8();
        entry.attributeType = tag < 224 ? TQ3AttributeType(tag % 13) : TQ3AttributeType(m_in.u32());
        const std::size_t bytes = attributeValueBytes(entry.attributeType);
        if (bytes == 0) {
            entry.data = (m_in.u8() & 1) ? nullptr : m_arena.allocate<std::uint64_t>(1);
        } else if (entry.attributeType == kQ3AttributeTypeSurfaceShader) {
            entry.data = block<TQ3Object>(elements, [&](TQ3Object& h) { h = shader(); });
        } else if (entry.attributeType == kQ3AttributeTypeHighlightState) {
            entry.data = block<TQ3Switch>(elements, [&](TQ3Switch& v) { readValue(v); });
        } else {
            const std::size_t floats = bytes / sizeof(float);
            entry.data = block<float>(elements * floats, [&](float& v) { v = m_in.value(); }, elements);
        }
        entry.attributeUseArray = m_in.u8() < 128 ? nullptr : block<char>(elements, [&](char& c) { readValue(c); });
    }

    // One byte t: < 32 NULL; < 48 a handle (as a handle field's pick); else
    // a new memory storage of t - 48 bytes (0 to 191), or for t >= 240 of a
    // u16 % (kMaxStorageBytes + 1); its first 16 bytes from the input.
    TQ3Object storage()
    {
        const std::uint8_t tag = m_in.u8();
        if (tag < 32)
            return nullptr;
        if (tag < 48)
            return m_source.pick(kQ3SharedTypeStorage);
        const std::size_t size = tag < 240 ? std::size_t(tag - 48) : m_in.u16() % (kMaxStorageBytes + 1);
        std::vector<unsigned char> bytes(size);
        for (std::size_t i = 0; i < size; ++i)
            bytes[i] = i < 16 ? m_in.u8() : static_cast<unsigned char>(i * 37);
        return m_source.storage(bytes);
    }

    template <class E>
    void element(E& e)
    {
        if constexpr (layout::IsDescribed<E>::value)
            fill(e);
        else
            readValue(e);
    }

    template <class T>
    void readValue(T& v)
    {
        if constexpr (std::is_same<T, float>::value) {
            v = m_in.value();
        } else if constexpr (std::is_same<T, TQ3Point3D>::value || std::is_same<T, TQ3Vector3D>::value) {
            v.x = m_in.value();
            v.y = m_in.value();
            v.z = m_in.value();
        } else if constexpr (std::is_same<T, TQ3RationalPoint4D>::value) {
            v.x = m_in.value();
            v.y = m_in.value();
            v.z = m_in.value();
            v.w = m_in.value();
        } else if constexpr (std::is_same<T, TQ3RationalPoint3D>::value) {
            v.x = m_in.value();
            v.y = m_in.value();
            v.w = m_in.value();
        } else if constexpr (std::is_array<T>::value) {
            for (auto& e : v)
                readValue(e);
        } else if constexpr (std::is_same<T, TQ3BoundingBox>::value) {
            readValue(v.min);
            readValue(v.max);
            readValue(v.isEmpty);
        } else if constexpr (std::is_same<T, TQ3TriMeshTriangleData>::value) {
            readValue(v.pointIndices);
        } else if constexpr (std::is_same<T, TQ3TriMeshEdgeData>::value) {
            readValue(v.pointIndices);
            readValue(v.triangleIndices);
        } else if constexpr (std::is_integral<T>::value) {
            v = static_cast<T>(word());
        } else if constexpr (std::is_enum<T>::value) {
            // Any int, as a C caller may store (the library reads enums
            // through core/EnumValue.h).
            static_assert(sizeof(T) == sizeof(std::int32_t), "Q3's enums are int-sized");
            const std::int32_t raw = word();
            std::memcpy(&v, &raw, sizeof raw);
        } else {
            static_assert(kAlwaysFalse<T>, "FuzzData.h has no encoding for this field's type");
        }
    }

    // One byte: below 224 a small value (modulo 16: flags and enumerations
    // in range and just past it), else four raw bytes.
    std::int32_t word()
    {
        const std::uint8_t tag = m_in.u8();
        if (tag < 224)
            return tag % 16;
        return static_cast<std::int32_t>(m_in.u32());
    }

    // One byte: 0..12, 13..268 (one more byte), or past the limit.
    unsigned long count()
    {
        const std::uint8_t tag = m_in.u8();
        if (tag < 200)
            return tag % 13;
        if (tag < 232)
            return 13UL + m_in.u8();
        if (tag < 244)
            return static_cast<unsigned long>(kQ3GeometryMaxArrayCount) + 1 + (tag - 232);
        return ~0UL - (tag - 244);
    }

    // One byte: below 128 NULL, below 240 the palette, else a pick (the
    // handle encoding: any held object, NULL, a disposed or a stray one).
    TQ3Object handle()
    {
        const std::uint8_t tag = m_in.u8();
        if (tag < 128)
            return nullptr;
        if (tag < 240)
            return m_palette;
        return m_source.pick(kQ3SharedTypeSet);
    }

    // One byte: below 128 NULL, else a pick, a surface shader most often.
    TQ3Object shader()
    {
        return m_in.u8() < 128 ? nullptr : m_source.pick(kQ3ShaderTypeSurface);
    }

    Reader& m_in;
    DataArena& m_arena;
    HandleSource m_source;
    TQ3Object m_palette;
    std::size_t m_budget = kElementBudget;
};

// ---- Comparing two described structs -------------------------------------

template <class S>
bool sameData(const S& a, const S& b);

namespace detail {

template <class E>
bool sameElement(const E& a, const E& b)
{
    if constexpr (layout::IsDescribed<E>::value)
        return sameData(a, b);
    else
        return std::memcmp(&a, &b, sizeof(E)) == 0;
}

template <class S, class T, bool Finite>
bool sameField(const S& a, const S& b, const layout::ValueField<S, T, Finite>& f)
{
    return sameElement(a.*f.member, b.*f.member);
}
template <class S, class N>
bool sameField(const S& a, const S& b, const layout::AtLeastField<S, N>& f)
{
    return a.*f.member == b.*f.member;
}
template <class S, class C>
bool sameField(const S& a, const S& b, const layout::HandleField<S, C>& f)
{
    return a.*f.member == b.*f.member;
}
template <class S, class E, std::size_t N>
bool sameField(const S& a, const S& b, const layout::InlineArrayField<S, E, N>& f)
{
    for (std::size_t i = 0; i < N; ++i)
        if (!sameElement((a.*f.member)[i], (b.*f.member)[i]))
            return false;
    return true;
}
template <class S, class E>
bool sameField(const S& a, const S& b, const layout::NestedField<S, E>& f)
{
    return sameData(a.*f.member, b.*f.member);
}

/// n elements each; an array of no elements may come back NULL, one of
/// some must be there in both or in neither.
template <class E>
bool sameArray(const E* a, const E* b, std::size_t n)
{
    if (n == 0)
        return true;
    if (a == nullptr || b == nullptr)
        return a == b;
    for (std::size_t i = 0; i < n; ++i)
        if (!sameElement(a[i], b[i]))
            return false;
    return true;
}
template <class S, class E, class Count>
bool sameField(const S& a, const S& b, const layout::ArrayField<S, E, Count>& f)
{
    const std::size_t n = f.count(a);
    return n == f.count(b) && sameArray(a.*f.member, b.*f.member, n);
}
template <class S, class C, class Count>
bool sameField(const S& a, const S& b, const layout::HandleArrayField<S, C, Count>& f)
{
    const std::size_t n = f.count(a);
    return n == f.count(b) && sameArray<TQ3Object>(a.*f.member, b.*f.member, n);
}

/// A TriMesh attribute array: the same types, the same use arrays and the
/// same values wherever the use array (if any) says an element has one.
template <class S>
bool sameField(const S& a, const S& b, const q3::TriMeshAttributeArraysField& f)
{
    const std::size_t n = a.*f.typeCount;
    const std::size_t elements = a.*f.elementCount;
    if (n != b.*f.typeCount || elements != b.*f.elementCount)
        return false;
    const TQ3TriMeshAttributeData* x = a.*f.member;
    const TQ3TriMeshAttributeData* y = b.*f.member;
    if (n == 0)
        return true;
    if (x == nullptr || y == nullptr)
        return x == y;
    for (std::size_t i = 0; i < n; ++i) {
        if (x[i].attributeType != y[i].attributeType)
            return false;
        if (elements == 0)
            continue;
        const char* use = x[i].attributeUseArray;
        if ((use == nullptr) != (y[i].attributeUseArray == nullptr) ||
            (use != nullptr && std::memcmp(use, y[i].attributeUseArray, elements) != 0))
            return false;
        const std::size_t bytes = attributeValueBytes(x[i].attributeType);
        const auto* dx = static_cast<const unsigned char*>(x[i].data);
        const auto* dy = static_cast<const unsigned char*>(y[i].data);
        for (std::size_t e = 0; e < elements; ++e)
            if ((use == nullptr || use[e] != 0) && std::memcmp(dx + e * bytes, dy + e * bytes, bytes) != 0)
                return false;
    }
    return true;
}

} // namespace detail

/// Whether two structs hold the same values, field by field as described
/// (bytes for plain values, equal handles, arrays element by element).
template <class S>
bool sameData(const S& a, const S& b)
{
    bool same = true;
    layout::forEachField<S>([&](const auto& field) { same = same && detail::sameField(a, b, field); });
    return same;
}

} // namespace q3fuzz
