// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// One description per QuickDraw 3D data structure, and everything derived
// from it. A class describes its C struct S once, by specializing Describe<S>
// with a fields() function returning a tuple of field descriptors:
//
//   value("point", &S::point)                plain data, copied as it is
//   finite("origin", &S::origin)             the same, every coordinate
//                                            finite (float, point, vector)
//   atLeast("numVertices", &S::numVertices, 3)
//                                            a count with a minimum
//   handle<AttributeSet>("set", &S::set)     an object the struct holds one
//                                            reference to (NULL allowed)
//   requiredHandle<Storage>(...)             the same, never NULL
//   inlineArray("vertices", &S::vertices)    a fixed array inside the struct
//   array("points", &S::points, countOf(&S::numPoints))
//                                            a malloc'ed array and the
//                                            expression that counts it,
//                                            NULL allowed when that is 0
//   requiredArray(...)                       the same, never NULL
//   optionalArray(...)                       the same, NULL allowed
//   finiteElements(array(...))               an array of points or floats,
//                                            each finite
//   nested("bitmap", &S::bitmap)             a described struct inside S
//   any type with the FieldKind members      (e.g. TriMesh's attribute arrays)
//
// Elements of arrays are either plain (trivially copyable, copied with
// memcpy) or described themselves, which makes the description recursive
// (TQ3PolyLineData -> TQ3Vertex3D -> its attribute set).
//
// From the description come the operations every geometry needs: the
// structural check (four passes over the whole struct, each finished before
// the next starts: every required array and handle present, every count at
// least its minimum, every count within limits::kMaxArrayCount, every finite
// field finite; so a class's own rules, which run after it, may read every
// array), deep copies with three policies for the handles
// inside (retain after checking them: New and SetData; retain trusted ones:
// GetData; duplicate each distinct object once: Duplicate), checking the
// handles without keeping them (immediate mode), releasing (EmptyData and
// destruction) and visiting every handle (cache keys). A copy gives the
// strong guarantee: if any step throws, everything it allocated or retained
// is given back and the destination holds nothing.
//
// A struct the library owns is a deep copy made by copyData with malloc'ed
// arrays, exactly like the ones GetData hands out, so one release routine
// serves both.

#include "QD3D.h"
#include "core/Error.h"
#include "core/LargeBlocks.h"
#include "core/Limits.h"
#include "core/Object.h"

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <map>
#include <new>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

namespace q3::layout {

/// Where a field is, for error messages ("vertices[3].attributeSet"). Lives on
/// the stack of the walk; formatted only when something fails.
struct Path {
    static constexpr std::size_t kNoIndex = ~std::size_t{0};

    const Path* parent = nullptr;
    const char* name = nullptr;
    std::size_t index = kNoIndex;

    Path child(const char* field) const { return Path{this, field, kNoIndex}; }
    Path element(std::size_t i) const { return Path{parent, name, i}; }
    std::string str() const;
};

inline std::string Path::str() const
{
    std::string prefix = parent != nullptr && parent->name != nullptr ? parent->str() + "." : "";
    prefix += name != nullptr ? name : "data";
    if (index != kNoIndex)
        prefix += "[" + std::to_string(index) + "]";
    return prefix;
}

/// Specialized once per described struct, with `static auto fields()`.
template <class S>
struct Describe;

template <class S, class = void>
struct IsDescribed : std::false_type {};
template <class S>
struct IsDescribed<S, std::void_t<decltype(Describe<S>::fields())>> : std::true_type {};

/// The Object behind a handle the library holds (checked when it was taken).
inline SharedObject* heldObject(TQ3Object handle)
{
    return static_cast<SharedObject*>(static_cast<Object*>(handle));
}

// ---- Handle policies -----------------------------------------------------

/// New and SetData: a caller's handle must be a live object of class C; the
/// copy takes a reference.
struct RetainChecked {
    template <class C>
    TQ3Object take(TQ3Object handle, const Path& where)
    {
        try {
            return Ref<C>::retain(&lookup<C>(handle, "it")).detach();
        } catch (const Error& error) {
            fail(error.code(), where.str() + ": " + error.what());
        }
    }
};

/// GetData: the handles are the library's own, known to be live.
struct RetainTrusted {
    template <class C>
    TQ3Object take(TQ3Object handle, const Path&)
    {
        heldObject(handle)->addReference();
        return handle;
    }
};

/// Duplicate: every distinct object is duplicated once and its copy shared
/// wherever the original was.
class DuplicateEach {
public:
    template <class C>
    TQ3Object take(TQ3Object handle, const Path&)
    {
        auto found = m_copies.find(handle);
        if (found == m_copies.end()) {
            Object* copy = static_cast<Object*>(handle)->duplicate();
            found = m_copies.emplace(handle, Ref<SharedObject>::adopt(static_cast<SharedObject*>(copy))).first;
        }
        found->second->addReference();
        return found->second.get();
    }

private:
    std::map<TQ3Object, Ref<SharedObject>> m_copies;
};

// ---- Counts --------------------------------------------------------------

/// The count kept in a field of the struct.
template <class S, class N>
auto countOf(N S::*field)
{
    return [field](const S& s) { return std::size_t(s.*field); };
}

/// A count fixed by the struct's definition (a box's six faces).
template <std::size_t N>
auto fixedCount()
{
    return [](const auto&) { return N; };
}

/// a + b, saturating, so that a huge pair fails the limit instead of wrapping.
template <class S, class A, class B>
auto countSum(A S::*a, B S::*b)
{
    return [a, b](const S& s) {
        const std::size_t x = std::size_t(s.*a), y = std::size_t(s.*b);
        return x > ~std::size_t{0} - y ? ~std::size_t{0} : x + y;
    };
}

/// a * b, saturating.
template <class S, class A, class B>
auto countProduct(A S::*a, B S::*b)
{
    return [a, b](const S& s) {
        const std::size_t x = std::size_t(s.*a), y = std::size_t(s.*b);
        return y != 0 && x > ~std::size_t{0} / y ? ~std::size_t{0} : x * y;
    };
}

/// Throws kQ3ErrorParameterOutOfRange when an array would exceed the limit.
inline void checkCount(std::size_t count, const Path& where)
{
    if (count > limits::kMaxArrayCount)
        fail(kQ3ErrorParameterOutOfRange, where.str() + " would have " + std::to_string(count) +
                                              " entries, more than kQ3GeometryMaxArrayCount (" +
                                              std::to_string(limits::kMaxArrayCount) + ")");
}

/// The passes of the structural check, in their order: every required array
/// and handle present (kQ3ErrorNULLParameter), every count at least its
/// minimum (kQ3ErrorGeometryInsufficientNumberOfPoints), every count within
/// kQ3GeometryMaxArrayCount (kQ3ErrorParameterOutOfRange), every finite
/// field finite (kQ3ErrorInvalidData). Each walks the whole struct; the
/// elements of an array are visited only when it is present and its count
/// within the limit, so no pass reads past what the caller gave.
enum class Pass { kPresence, kMinimum, kMaximum, kValues };

/// True when every coordinate of a value a finite() field names is finite.
inline bool isFinite(float v)
{
    return std::isfinite(v);
}
inline bool isFinite(const TQ3Point3D& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}
inline bool isFinite(const TQ3Vector3D& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool isFinite(const TQ3RationalPoint4D& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

/// Throws kQ3ErrorInvalidData naming `where` unless `v` is finite.
template <class T>
void checkFinite(const T& v, const Path& where)
{
    if (!isFinite(v))
        fail(kQ3ErrorInvalidData, where.str() + (std::is_same<T, float>::value ? " is not finite"
                                                                               : " has a coordinate that is not finite"));
}

/// malloc for count elements (nullptr for none), large blocks recycled
/// (core/LargeBlocks.h); throws std::bad_alloc.
template <class E>
E* allocate(std::size_t count)
{
    if (count == 0)
        return nullptr;
    void* block = memory::allocate(count * sizeof(E));
    if (block == nullptr)
        throw std::bad_alloc();
    return static_cast<E*>(block);
}

// ---- The walks over a described struct ---------------------------------

template <class S, class F>
void forEachField(F&& f)
{
    std::apply([&](const auto&... field) { (f(field), ...); }, Describe<S>::fields());
}

template <class S>
void checkStructure(const S& s, const Path& path);
template <class S>
void checkPass(const S& s, const Path& path, Pass pass);
template <class S>
void clearOwned(S& s);
template <class S, class Policy>
void fill(S& dst, const S& src, Policy& policy, const Path& path);
template <class S>
void release(S& s);
template <class S>
void checkHandles(const S& s, const Path& path);
template <class S, class F>
void forEachHandle(const S& s, F&& f);

// Element helpers: described elements recurse, plain ones are bytes.
template <class E>
void checkElement(const E& e, const Path& path, Pass pass)
{
    if constexpr (IsDescribed<E>::value)
        checkPass(e, path, pass);
}

template <class E>
void clearElement(E& e)
{
    if constexpr (IsDescribed<E>::value)
        clearOwned(e);
}

template <class E, class Policy>
void fillElement(E& dst, const E& src, Policy& policy, const Path& path)
{
    if constexpr (IsDescribed<E>::value)
        fill(dst, src, policy, path);
}

template <class E>
void releaseElement(E& e)
{
    if constexpr (IsDescribed<E>::value)
        release(e);
}

template <class E>
void checkElementHandles(const E& e, const Path& path)
{
    if constexpr (IsDescribed<E>::value)
        checkHandles(e, path);
}

template <class E, class F>
void forEachElementHandle(const E& e, F& f)
{
    if constexpr (IsDescribed<E>::value)
        forEachHandle(e, f);
}

/// Copies `count` elements from src into fresh storage: bytes first, then
/// (for described elements) every element's owned parts cleared, then filled
/// one by one, so a failure midway leaves every element releasable.
template <class E, class Policy>
E* copyElements(const E* src, std::size_t count, Policy& policy, const Path& path)
{
    static_assert(std::is_trivially_copyable<E>::value, "QuickDraw 3D data is plain C");
    E* dst = allocate<E>(count);
    if (count != 0)
        std::memcpy(static_cast<void*>(dst), src, count * sizeof(E));
    if constexpr (IsDescribed<E>::value) {
        for (std::size_t i = 0; i < count; ++i)
            clearOwned(dst[i]);
        try {
            for (std::size_t i = 0; i < count; ++i)
                fill(dst[i], src[i], policy, path.element(i));
        } catch (...) {
            for (std::size_t i = 0; i < count; ++i)
                release(dst[i]);
            memory::release(dst);
            throw;
        }
    }
    return dst;
}

template <class E>
void releaseElements(E* elements, std::size_t count)
{
    if (elements == nullptr)
        return;
    if constexpr (IsDescribed<E>::value)
        for (std::size_t i = 0; i < count; ++i)
            release(elements[i]);
    memory::release(elements);
}

// ---- Field kinds ---------------------------------------------------------
//
// A field kind has: check(s, path, pass) (structure, one Pass), clear(s) (owned parts to
// NULL), fill(dst, src, policy, path) (dst cleared, counts copied),
// release(s), checkHandles(s, path), forEachHandle(s, f).

/// The parts of a field kind that holds plain data only: nothing owned to
/// clear, copy, release or walk for handles.
template <class S>
struct PlainDataField {
    void clear(S&) const {}
    template <class Policy>
    void fill(S&, const S&, Policy&, const Path&) const
    {
    }
    void release(S&) const {}
    void checkHandles(const S&, const Path&) const {}
    template <class F>
    void forEachHandle(const S&, F&) const
    {
    }
};

template <class S, class T, bool Finite = false>
struct ValueField : PlainDataField<S> {
    const char* name;
    T S::*member;

    void check(const S& s, const Path& path, Pass pass) const
    {
        if constexpr (Finite)
            if (pass == Pass::kValues)
                checkFinite(s.*member, path.child(name));
        (void)s, (void)path, (void)pass;
    }
};

/// A count field with a minimum (a polygon's three vertices): plain data,
/// checked in the minimum pass.
template <class S, class N>
struct AtLeastField : PlainDataField<S> {
    const char* name;
    N S::*member;
    unsigned long minimum;

    void check(const S& s, const Path& path, Pass pass) const
    {
        if (pass == Pass::kMinimum && (unsigned long)(s.*member) < minimum)
            fail(kQ3ErrorGeometryInsufficientNumberOfPoints, path.child(name).str() + " is " +
                                                                 std::to_string(s.*member) + ", fewer than " +
                                                                 std::to_string(minimum));
    }
};

template <class S, class C>
struct HandleField {
    const char* name;
    TQ3Object S::*member;
    bool required;

    void check(const S& s, const Path& path, Pass pass) const
    {
        if (pass == Pass::kPresence && required && s.*member == nullptr)
            fail(kQ3ErrorNULLParameter, path.child(name).str() + " is NULL");
    }
    void clear(S& s) const { s.*member = nullptr; }
    template <class Policy>
    void fill(S& dst, const S& src, Policy& policy, const Path& path) const
    {
        if (src.*member != nullptr)
            dst.*member = policy.template take<C>(src.*member, path.child(name));
    }
    void release(S& s) const
    {
        if (TQ3Object handle = std::exchange(s.*member, nullptr))
            heldObject(handle)->releaseReference();
    }
    void checkHandles(const S& s, const Path& path) const
    {
        if (s.*member == nullptr)
            return;
        try {
            lookup<C>(s.*member, "it");
        } catch (const Error& error) {
            fail(error.code(), path.child(name).str() + ": " + error.what());
        }
    }
    template <class F>
    void forEachHandle(const S& s, F& f) const
    {
        if (s.*member != nullptr)
            f(s.*member);
    }
};

template <class S, class E, std::size_t N>
struct InlineArrayField {
    const char* name;
    E (S::*member)[N];

    void check(const S& s, const Path& path, Pass pass) const
    {
        for (std::size_t i = 0; i < N; ++i)
            checkElement((s.*member)[i], path.child(name).element(i), pass);
    }
    void clear(S& s) const
    {
        for (std::size_t i = 0; i < N; ++i)
            clearElement((s.*member)[i]);
    }
    template <class Policy>
    void fill(S& dst, const S& src, Policy& policy, const Path& path) const
    {
        const Path here = path.child(name);
        for (std::size_t i = 0; i < N; ++i)
            fillElement((dst.*member)[i], (src.*member)[i], policy, here.element(i));
    }
    void release(S& s) const
    {
        for (std::size_t i = 0; i < N; ++i)
            releaseElement((s.*member)[i]);
    }
    void checkHandles(const S& s, const Path& path) const
    {
        for (std::size_t i = 0; i < N; ++i)
            checkElementHandles((s.*member)[i], path.child(name).element(i));
    }
    template <class F>
    void forEachHandle(const S& s, F& f) const
    {
        for (std::size_t i = 0; i < N; ++i)
            forEachElementHandle((s.*member)[i], f);
    }
};

/// Whether an array may be NULL: never, when its count is 0, always.
enum class Presence { kAlways, kWhenCounted, kOptional };

template <class S, class E, class Count>
struct ArrayField {
    const char* name;
    E* S::*member;
    Count count;
    Presence presence;
    bool finite = false;

    void check(const S& s, const Path& path, Pass pass) const
    {
        const Path here = path.child(name);
        const std::size_t n = count(s);
        const E* elements = s.*member;
        if (pass == Pass::kPresence && elements == nullptr &&
            (presence == Presence::kAlways || (n != 0 && presence == Presence::kWhenCounted)))
            fail(kQ3ErrorNULLParameter, here.str() + " is NULL but should hold " + std::to_string(n) + " entries");
        if (pass == Pass::kMaximum)
            checkCount(n, here);
        // Elements are read only within the limit (the maximum pass reports
        // a larger count).
        if (elements == nullptr || n > limits::kMaxArrayCount)
            return;
        if constexpr (IsDescribed<E>::value) {
            for (std::size_t i = 0; i < n; ++i)
                checkPass(elements[i], here.element(i), pass);
        } else if constexpr (std::is_same<E, float>::value || std::is_same<E, TQ3Point3D>::value ||
                             std::is_same<E, TQ3RationalPoint4D>::value) {
            if (finite && pass == Pass::kValues)
                for (std::size_t i = 0; i < n; ++i)
                    checkFinite(elements[i], here.element(i));
        }
    }
    void clear(S& s) const { s.*member = nullptr; }
    template <class Policy>
    void fill(S& dst, const S& src, Policy& policy, const Path& path) const
    {
        if (src.*member != nullptr)
            dst.*member = copyElements(src.*member, count(src), policy, path.child(name));
    }
    void release(S& s) const
    {
        releaseElements(s.*member, count(s));
        s.*member = nullptr;
    }
    void checkHandles(const S& s, const Path& path) const
    {
        if constexpr (IsDescribed<E>::value) {
            if (s.*member == nullptr)
                return;
            const std::size_t n = count(s);
            for (std::size_t i = 0; i < n; ++i)
                layout::checkHandles((s.*member)[i], path.child(name).element(i));
        }
    }
    template <class F>
    void forEachHandle(const S& s, F& f) const
    {
        if constexpr (IsDescribed<E>::value) {
            if (s.*member == nullptr)
                return;
            const std::size_t n = count(s);
            for (std::size_t i = 0; i < n; ++i)
                layout::forEachHandle((s.*member)[i], f);
        }
    }
};

/// A struct inside the struct, described itself (a marker's TQ3Bitmap).
template <class S, class E>
struct NestedField {
    const char* name;
    E S::*member;

    void check(const S& s, const Path& path, Pass pass) const { checkElement(s.*member, path.child(name), pass); }
    void clear(S& s) const { clearElement(s.*member); }
    template <class Policy>
    void fill(S& dst, const S& src, Policy& policy, const Path& path) const
    {
        fillElement(dst.*member, src.*member, policy, path.child(name));
    }
    void release(S& s) const { releaseElement(s.*member); }
    void checkHandles(const S& s, const Path& path) const { checkElementHandles(s.*member, path.child(name)); }
    template <class F>
    void forEachHandle(const S& s, F& f) const
    {
        forEachElementHandle(s.*member, f);
    }
};

/// An array of object handles, each holding one reference (NULL entries
/// allowed).
template <class S, class C, class Count>
struct HandleArrayField {
    const char* name;
    TQ3Object* S::*member;
    Count count;
    bool optional;

    void check(const S& s, const Path& path, Pass pass) const
    {
        const Path here = path.child(name);
        const std::size_t n = count(s);
        if (pass == Pass::kPresence && s.*member == nullptr && n != 0 && !optional)
            fail(kQ3ErrorNULLParameter, here.str() + " is NULL but should hold " + std::to_string(n) + " entries");
        if (pass == Pass::kMaximum)
            checkCount(n, here);
    }
    void clear(S& s) const { s.*member = nullptr; }
    template <class Policy>
    void fill(S& dst, const S& src, Policy& policy, const Path& path) const
    {
        const TQ3Object* from = src.*member;
        if (from == nullptr)
            return;
        const std::size_t n = count(src);
        TQ3Object* to = allocate<TQ3Object>(n);
        for (std::size_t i = 0; i < n; ++i)
            to[i] = nullptr;
        dst.*member = to;
        const Path here = path.child(name);
        for (std::size_t i = 0; i < n; ++i)
            if (from[i] != nullptr)
                to[i] = policy.template take<C>(from[i], here.element(i));
    }
    void release(S& s) const
    {
        // Counted first: a count may depend on whether the array is there.
        const std::size_t n = count(s);
        TQ3Object* handles = std::exchange(s.*member, nullptr);
        if (handles == nullptr)
            return;
        for (std::size_t i = 0; i < n; ++i)
            if (handles[i] != nullptr)
                heldObject(handles[i])->releaseReference();
        memory::release(handles);
    }
    void checkHandles(const S& s, const Path& path) const
    {
        const TQ3Object* handles = s.*member;
        if (handles == nullptr)
            return;
        const std::size_t n = count(s);
        for (std::size_t i = 0; i < n; ++i) {
            if (handles[i] == nullptr)
                continue;
            try {
                lookup<C>(handles[i], "it");
            } catch (const Error& error) {
                fail(error.code(), path.child(name).element(i).str() + ": " + error.what());
            }
        }
    }
    template <class F>
    void forEachHandle(const S& s, F& f) const
    {
        const TQ3Object* handles = s.*member;
        if (handles == nullptr)
            return;
        const std::size_t n = count(s);
        for (std::size_t i = 0; i < n; ++i)
            if (handles[i] != nullptr)
                f(handles[i]);
    }
};

template <class S, class T>
ValueField<S, T> value(const char* name, T S::*member)
{
    return {{}, name, member};
}

/// A count that must be at least `minimum`:
/// kQ3ErrorGeometryInsufficientNumberOfPoints in the minimum pass.
template <class S, class N>
AtLeastField<S, N> atLeast(const char* name, N S::*member, unsigned long minimum)
{
    return {{}, name, member, minimum};
}

/// A value that must be finite: kQ3ErrorInvalidData in the values pass.
template <class S, class T>
ValueField<S, T, true> finite(const char* name, T S::*member)
{
    return {{}, name, member};
}

template <class C, class S>
HandleField<S, C> handle(const char* name, TQ3Object S::*member)
{
    return {name, member, false};
}

/// A handle that must not be NULL: kQ3ErrorNULLParameter in the presence pass.
template <class C, class S>
HandleField<S, C> requiredHandle(const char* name, TQ3Object S::*member)
{
    return {name, member, true};
}

template <class S, class E, std::size_t N>
InlineArrayField<S, E, N> inlineArray(const char* name, E (S::*member)[N])
{
    return {name, member};
}

template <class S, class E, class Count>
ArrayField<S, E, Count> array(const char* name, E* S::*member, Count count)
{
    return {name, member, count, Presence::kWhenCounted};
}

template <class S, class E, class Count>
ArrayField<S, E, Count> requiredArray(const char* name, E* S::*member, Count count)
{
    return {name, member, count, Presence::kAlways};
}

template <class S, class E, class Count>
ArrayField<S, E, Count> optionalArray(const char* name, E* S::*member, Count count)
{
    return {name, member, count, Presence::kOptional};
}

/// The array with every element (a float or a point) required to be finite.
template <class S, class E, class Count>
ArrayField<S, E, Count> finiteElements(ArrayField<S, E, Count> field)
{
    field.finite = true;
    return field;
}

template <class S, class E>
NestedField<S, E> nested(const char* name, E S::*member)
{
    return {name, member};
}

template <class C, class S, class Count>
HandleArrayField<S, C, Count> optionalHandleArray(const char* name, TQ3Object* S::*member, Count count)
{
    return {name, member, count, true};
}

// ---- The walks -----------------------------------------------------------

template <class S>
void checkPass(const S& s, const Path& path, Pass pass)
{
    forEachField<S>([&](const auto& field) { field.check(s, path, pass); });
}

/// The structural check: the presence pass over the whole struct, then the
/// minimum counts, the maximum counts and the finite values (see Pass).
template <class S>
void checkStructure(const S& s, const Path& path)
{
    for (Pass pass : {Pass::kPresence, Pass::kMinimum, Pass::kMaximum, Pass::kValues})
        checkPass(s, path, pass);
}

template <class S>
void clearOwned(S& s)
{
    forEachField<S>([&](const auto& field) { field.clear(s); });
}

template <class S, class Policy>
void fill(S& dst, const S& src, Policy& policy, const Path& path)
{
    forEachField<S>([&](const auto& field) { field.fill(dst, src, policy, path); });
}

template <class S>
void release(S& s)
{
    forEachField<S>([&](const auto& field) { field.release(s); });
}

template <class S>
void checkHandles(const S& s, const Path& path)
{
    forEachField<S>([&](const auto& field) { field.checkHandles(s, path); });
}

template <class S, class F>
void forEachHandle(const S& s, F&& f)
{
    forEachField<S>([&](const auto& field) { field.forEachHandle(s, f); });
}

/// A deep copy of src into dst (whose old contents are overwritten, not
/// released): plain fields and counts as they are, arrays newly malloc'ed,
/// every handle taken through the policy. On failure dst holds nothing
/// owned and the exception propagates.
template <class S, class Policy>
void copyData(S& dst, const S& src, Policy& policy)
{
    static_assert(std::is_trivially_copyable<S>::value, "QuickDraw 3D data is plain C");
    std::memcpy(static_cast<void*>(&dst), &src, sizeof(S));
    clearOwned(dst);
    try {
        fill(dst, src, policy, Path{});
    } catch (...) {
        release(dst);
        throw;
    }
}

template <class S, class Policy>
void copyData(S& dst, const S& src, Policy&& policy)
{
    Policy p = std::forward<Policy>(policy);
    copyData(dst, src, p);
}

/// What EmptyData does: checks every handle first (a failure releases
/// nothing), then releases the handles and frees the arrays, leaving NULLs.
template <class S>
void emptyData(S& s)
{
    checkHandles(s, Path{});
    release(s);
}

// ---- The 3DMF file order (optional) ---------------------------------------
//
// A simple geometry's 3DMF object is a fixed sequence of its struct's fields,
// in the 3D Metafile Reference's order, which is not the struct's (a file's
// Cone starts with its orientation, TQ3ConeData with its origin), followed by
// its subobjects. Describe<S> gives that form with two more functions:
//
//   static auto fileFields()   the data, in file order:
//     point3D(&S::m), vector3D(&S::m), float32(&S::m)   one primitive each
//     point3D(&S::m, {0, 0, 0}) ...   with the default Apple's metafile
//                                     parser gives an object with no data
//                                     (MF3D's "0-sized objects"): when every
//                                     field outside trailing() has one, an
//                                     object with no data takes them all
//     vertexPoints(&S::vertices)      a fixed array of TQ3Vertex3D: the points
//     vertexPoints(&S::numVertices, &S::vertices)
//                                     a counted array: the count, the points
//     trailing(float32(&S::uMin, 0), ...)   optional at the end: read when
//                                     data is left, written unless every one
//                                     is its default
//   static auto fileParts()    the subobjects, in the order they are written
//                              (a reader finds them by type, and takes the
//                              geometry's own set last):
//     ownSetPart(&S::set)             the geometry's attribute set
//     vertexSetsPart(&S::vertices)    the vertices' sets, as a list (also
//                                     with the count, as vertexPoints)
//     setListPart(SetList::kFaces, &S::faces, fixedCount<6>())
//                                     an array of sets (NULL when none has
//                                     one) for the faces, or for other parts
//                                     (kOtherParts: a polyline's segments),
//                                     as a list
//     endCapsPart(&S::caps)           the end caps mask
//     capSetPart(CapPart::kTop, &S::topAttributeSet)   a part's set
//
// The kinds are plain: src/io maps each to its reads, writes and tags
// (io/SimpleGeometryIO.cpp), so src/geometry never names the format.

/// The 3DMF primitive a field is written as.
enum class Primitive { kPoint3D, kVector3D, kFloat32 };

template <class S, class T, Primitive K>
struct FileField {
    static constexpr Primitive kKind = K;
    T S::*member;
    bool hasDefault;
    T fallback;
};

/// The points of a fixed array of vertices (their sets are a part).
template <class S, class E, std::size_t N>
struct VertexPointsField {
    E (S::*member)[N];
};

/// The count and the points of a malloc'ed array of vertices.
template <class S, class N, class E>
struct CountedVertexPointsField {
    N S::*count;
    E* S::*member;
};

template <class... F>
struct Trailing {
    std::tuple<F...> fields;
};

template <class S>
FileField<S, TQ3Point3D, Primitive::kPoint3D> point3D(TQ3Point3D S::*member)
{
    return {member, false, {}};
}

template <class S>
FileField<S, TQ3Point3D, Primitive::kPoint3D> point3D(TQ3Point3D S::*member, TQ3Point3D fallback)
{
    return {member, true, fallback};
}

template <class S>
FileField<S, TQ3Vector3D, Primitive::kVector3D> vector3D(TQ3Vector3D S::*member, TQ3Vector3D fallback)
{
    return {member, true, fallback};
}

template <class S>
FileField<S, float, Primitive::kFloat32> float32(float S::*member, float fallback)
{
    return {member, true, fallback};
}

template <class S, class E, std::size_t N>
VertexPointsField<S, E, N> vertexPoints(E (S::*member)[N])
{
    return {member};
}

template <class S, class N, class E>
CountedVertexPointsField<S, N, E> vertexPoints(N S::*count, E* S::*member)
{
    return {count, member};
}

template <class... F>
Trailing<F...> trailing(F... fields)
{
    return {std::make_tuple(fields...)};
}

/// A quadric's part that has its own attribute set in a file.
enum class CapPart { kTop, kBottom, kFace, kInterior };

template <class S>
struct OwnSetPart {
    TQ3Object S::*member;
};

template <class S>
struct CapSetPart {
    CapPart part;
    TQ3Object S::*member;
};

template <class S, class E, std::size_t N>
struct VertexSetsPart {
    E (S::*member)[N];
};

template <class S, class N, class E>
struct CountedVertexSetsPart {
    N S::*count;
    E* S::*member;
};

/// Which parts an array of sets belongs to.
enum class SetList { kFaces, kOtherParts };

template <class S, class Count>
struct SetListPart {
    SetList list;
    TQ3Object* S::*member;
    Count count;
};

template <class S, class T>
struct EndCapsPart {
    T S::*member;
};

template <class S>
OwnSetPart<S> ownSetPart(TQ3Object S::*member)
{
    return {member};
}

template <class S>
CapSetPart<S> capSetPart(CapPart part, TQ3Object S::*member)
{
    return {part, member};
}

template <class S, class E, std::size_t N>
VertexSetsPart<S, E, N> vertexSetsPart(E (S::*member)[N])
{
    return {member};
}

template <class S, class N, class E>
CountedVertexSetsPart<S, N, E> vertexSetsPart(N S::*count, E* S::*member)
{
    return {count, member};
}

template <class S, class Count>
SetListPart<S, Count> setListPart(SetList list, TQ3Object* S::*member, Count count)
{
    return {list, member, count};
}

template <class S, class T>
EndCapsPart<S, T> endCapsPart(T S::*member)
{
    return {member};
}

} // namespace q3::layout
