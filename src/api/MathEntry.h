// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The shapes QD3DMath.h's entry points share (QD3DMath.h states the
// contract): check every pointer argument for NULL in argument order, then
// compute the whole result before storing it, so that a result may alias an
// input and a failed call leaves it unchanged; and the rules for the arrays
// that come with a count and a stride.

#include "api/Entry.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <string>

namespace q3::api {

/// A pointer argument and its name in QD3DMath.h, for the NULL check.
struct Arg {
    const void* pointer;
    const char* name;
};

inline void requireNonNull(std::initializer_list<Arg> args)
{
    for (const Arg& arg : args)
        q3::requireNonNull(arg.pointer, arg.name);
}

/// *result = compute() after the NULL checks (result among args, in its
/// argument position); returns result, or NULL after posting the error.
template <class T, class Compute>
T* computeInto(const char* function, std::initializer_list<Arg> args, T* result, Compute&& compute) noexcept
{
    return guard(function, static_cast<T*>(nullptr), [&] {
        requireNonNull(args);
        *result = compute();
        return result;
    });
}

/// compute() after the NULL checks; fallback (0, kQ3False) on failure.
template <class T, class Compute>
T computeValue(const char* function, T fallback, std::initializer_list<Arg> args, Compute&& compute) noexcept
{
    return guard(function, fallback, [&] {
        requireNonNull(args);
        return compute();
    });
}

/// An array argument with a stride: `count` elements of `elementSize`
/// bytes, each `stride` bytes after the one before. The checks, in order:
/// the array may be NULL only when count is 0 (kQ3ErrorNULLParameter); the
/// stride is at least the element size (kQ3ErrorParameterOutOfRange); the
/// bytes the elements span are no more than an object can have and fit in
/// the address space after the array's first byte: no array could hold more
/// (kQ3ErrorParameterOutOfRange).
struct StridedArray {
    const void* pointer;
    const char* name;
    std::size_t elementSize;
    unsigned long stride;
    const char* strideName;
};

/// The NULL check alone, for the pass over the pointers in argument order.
inline void requireArray(const void* pointer, unsigned long count, const char* name)
{
    if (pointer == nullptr && count != 0)
        fail(kQ3ErrorNULLParameter, std::string(name) + " is NULL and the count is " + std::to_string(count));
}

inline void checkArray(const StridedArray& array, unsigned long count, const char* countName)
{
    requireArray(array.pointer, count, array.name);
    if (array.stride < array.elementSize)
        fail(kQ3ErrorParameterOutOfRange, std::string(array.strideName) + " " + std::to_string(array.stride) +
                                              " is smaller than an element (" +
                                              std::to_string(array.elementSize) + " bytes)");
    if (count == 0)
        return;
    // No object is larger than PTRDIFF_MAX bytes, nor runs past the end of
    // the address space.
    const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(array.pointer);
    const std::uintptr_t room = std::min<std::uintptr_t>(UINTPTR_MAX - start, PTRDIFF_MAX);
    const std::uintptr_t steps = count - 1;
    if (room < array.elementSize - 1 || steps > (room - (array.elementSize - 1)) / array.stride)
        fail(kQ3ErrorParameterOutOfRange, std::string(countName) + " " + std::to_string(count) + " elements of " +
                                              std::to_string(array.stride) + " bytes are more than any " +
                                              array.name + " array could hold");
}

/// The element at index of a checked array, copied out (a stride need not
/// keep elements aligned).
template <class T>
T elementAt(const void* base, unsigned long stride, std::size_t index)
{
    T value;
    std::memcpy(&value, static_cast<const unsigned char*>(base) + index * stride, sizeof value);
    return value;
}

template <class T>
void storeAt(void* base, unsigned long stride, std::size_t index, const T& value)
{
    std::memcpy(static_cast<unsigned char*>(base) + index * stride, &value, sizeof value);
}

} // namespace q3::api
