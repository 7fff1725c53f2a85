// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The API fuzzer's data generator, driven by the library's own description of
// each geometry's C struct (core/DataLayout.h: Describe<S>::fields()). It walks
// the description field by field, reading each value from the input in the
// field's encoding (FuzzInput.h, "described data"): floats, points and
// vectors in the `value` encoding (NaN, infinities and huge values
// included), counts from 0 to a few hundred or past kQ3GeometryMaxArrayCount,
// attribute sets NULL, shared or any handle, and arrays sized from their
// counts, NULL, or a one-element decoy behind a count Q3 must refuse before
// reading anything. A new field in a description is generated with no change
// here; a field kind this file does not know is a compile error.
//
// The same walk compares two structs (sameData): every described field, each
// array element by element up to its count. The fuzzer uses it to check that
// what New or SetData accepted reads back.
//
// The descriptions reachable here are the ones in the classes' headers:
// points, lines, polylines, triangles, polygons, boxes, cones, cylinders,
// disks, ellipses, ellipsoids and tori. The other types keep hand-written
// generators (Session::readCurve, readPatch, readTriMesh, polygons2,
// storagePixmap), which say why.

#include "FuzzInput.h"

#include "core/DataLayout.h"
#include "geometry/Box.h"
#include "geometry/Cone.h"
#include "geometry/Cylinder.h"
#include "geometry/DataGeometryImpl.h"
#include "geometry/Disk.h"
#include "geometry/Ellipse.h"
#include "geometry/Ellipsoid.h"
#include "geometry/Line.h"
#include "geometry/Point.h"
#include "geometry/PolyLine.h"
#include "geometry/Polygon.h"
#include "geometry/Torus.h"
#include "geometry/Triangle.h"

#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <type_traits>
#include <vector>

namespace q3fuzz {

namespace layout = q3::layout;

template <class>
inline constexpr bool kAlwaysFalse = false;

/// The arrays a generated struct points at; they live as long as the arena.
class DataArena {
public:
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
};

/// Fills a described struct from the input (the format: FuzzInput.h,
/// "described data"). Handle fields take NULL, the palette (one attribute set
/// picked for the whole struct, so that a struct's sets are mostly the same
/// live one) or a fresh pick of any handle.
class DataGenerator {
public:
    /// Elements one struct may allocate over all its arrays; an array that
    /// would need more is passed as NULL (its count unchanged).
    static constexpr std::size_t kElementBudget = 2048;

    DataGenerator(Reader& in, DataArena& arena, std::function<TQ3Object()> pick, TQ3Object palette)
        : m_in(in), m_arena(arena), m_pick(std::move(pick)), m_palette(palette)
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

    /// One shape byte, then the elements: see FuzzInput.h.
    template <class E, class Fill>
    E* block(std::size_t n, Fill fillOne)
    {
        const std::uint8_t shape = m_in.u8();
        if (n > kQ3GeometryMaxArrayCount)
            return (shape & 1) ? nullptr : m_arena.allocate<E>(1); // must be refused unread
        if (shape % 16 == 15 || n > m_budget)
            return nullptr;
        m_budget -= n;
        E* elements = m_arena.allocate<E>(n);
        for (std::size_t i = 0; i < n; ++i)
            fillOne(elements[i]);
        return n == 0 && (shape & 0x10) ? nullptr : elements;
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
        return m_pick();
    }

    Reader& m_in;
    DataArena& m_arena;
    std::function<TQ3Object()> m_pick;
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
