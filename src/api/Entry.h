// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/Error.h"
#include "core/ErrorManager.h"
#include "core/Object.h"

#include <cstdlib>
#include <cstring>
#include <functional>
#include <new>
#include <string>

namespace q3::api {

/// Runs the body of a C entry point: forgets what the previous call posted,
/// refuses to run before Q3Initialize, and turns every exception into a posted
/// error and the fallback result, so no exception ever crosses the C boundary.
/// `function` names the entry point in the error message.
template <class Result, class Body>
Result guard(const char* function, Result fallback, Body&& body) noexcept
{
    errors::beginCall();
    if (!system::isInitialized()) {
        errors::postError(kQ3ErrorNotInitialized,
                          std::string(function) + ": Q3Initialize has not been called");
        return fallback;
    }
    try {
        return body();
    } catch (const Error& error) {
        errors::postError(error.code(), std::string(function) + ": " + error.what());
    } catch (const std::bad_alloc&) {
        errors::postError(kQ3ErrorOutOfMemory, std::string(function) + ": out of memory");
    } catch (const std::exception& error) {
        errors::postError(kQ3ErrorInternalError, std::string(function) + ": " + error.what());
    } catch (...) {
        errors::postError(kQ3ErrorInternalError, std::string(function) + ": unexpected exception");
    }
    return fallback;
}

/// For the TQ3Status entry points whose body returns nothing.
template <class Body>
TQ3Status guardStatus(const char* function, Body&& body) noexcept
{
    return guard(function, kQ3Failure, [&] {
        body();
        return kQ3Success;
    });
}

/// A malloc'ed, NUL-terminated copy of text for a C caller to free() (or to
/// hand to the Q3 call that frees it); std::bad_alloc when memory runs out.
inline char* mallocCopy(const std::string& text)
{
    char* copy = static_cast<char*>(std::malloc(text.size() + 1));
    if (copy == nullptr)
        throw std::bad_alloc();
    std::memcpy(copy, text.c_str(), text.size() + 1);
    return copy;
}

/// The Get half of a single-value accessor, in the order every Get checks:
/// the handle (as a T, called `handleName` in errors), then the output pointer
/// (`outName`), then *out = read(object). Nothing is written on failure.
/// `read` may be a member function of T (`&T::data`): the value is then
/// assigned straight from what it returns, as `*out = object.data()` would.
template <class T, class Value, class Read>
void readInto(TQ3Object handle, const char* handleName, Value* out, const char* outName, Read read)
{
    const T& source = lookup<T>(handle, handleName);
    requireNonNull(out, outName);
    *out = std::invoke(read, source);
}

/// A whole Q3<Family>_GetType entry point: the leaf type of the T that
/// `handle` is (called `handleName` in errors), or kQ3ObjectTypeInvalid when
/// it is none.
template <class T>
TQ3ObjectType getLeafType(const char* function, TQ3Object handle, const char* handleName) noexcept
{
    return guard(function, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookup<T>(handle, handleName).leafType(); });
}

/// A whole New entry point of a shared T made from one value given through a
/// pointer (`dataName` in errors); T's constructor checks the value. The
/// caller owns the one reference of the new object.
template <class T, class Value>
TQ3Object newShared(const char* function, const Value* data, const char* dataName) noexcept
{
    return guard(function, TQ3Object{nullptr}, [&]() -> TQ3Object {
        requireNonNull(data, dataName);
        return makeShared<T>(*data).detach();
    });
}

/// A whole Get entry point of one value: readInto under guardStatus.
template <class T, class Value, class Read>
TQ3Status getValue(const char* function, TQ3Object handle, const char* handleName, Value* out, const char* outName,
                   Read read) noexcept
{
    return guardStatus(function, [&] { readInto<T>(handle, handleName, out, outName, read); });
}

/// A whole Set entry point of one value given through a pointer, in the order
/// every Set checks: the handle (as a T), then the pointer (`inName`), then
/// write(object, *in), a member function of T that checks the value.
template <class T, class Value, class Write>
TQ3Status setValue(const char* function, TQ3Object handle, const char* handleName, const Value* in,
                   const char* inName, Write write) noexcept
{
    return guardStatus(function, [&] {
        T& target = lookup<T>(handle, handleName);
        requireNonNull(in, inName);
        std::invoke(write, target, *in);
    });
}

/// A whole Set entry point of one value given by value (a Boolean, an
/// enumeration, a handle): the handle (as a T), then write(object, value), a
/// member function of T that checks the value. The value goes on by
/// reference, so an enumeration may hold any int until write checks it.
template <class T, class Value, class Write>
TQ3Status setDirect(const char* function, TQ3Object handle, const char* handleName, const Value& value,
                    Write write) noexcept
{
    return guardStatus(function, [&] { std::invoke(write, lookup<T>(handle, handleName), value); });
}

/// A new reference for the caller to an object held, or NULL when none is.
template <class T>
TQ3Object handOut(const Ref<T>& held)
{
    return Ref<T>(held).detach();
}

/// The Get and Set entry points of an object a T holds (a view's camera, its
/// light group). Get hands out a new reference (NULL when none is held); Set
/// looks the object up, required or optional (NULL clears it), and hands the
/// T a reference of its own.
template <class T, class Held>
TQ3Status getHeld(const char* function, TQ3Object handle, const char* handleName, TQ3Object* out,
                  const char* outName, const Ref<Held>& (T::*read)() const) noexcept
{
    return getValue<T>(function, handle, handleName, out, outName,
                       [&](const T& source) { return handOut((source.*read)()); });
}

template <class T, class Held>
TQ3Status setHeld(const char* function, TQ3Object handle, const char* handleName, TQ3Object object,
                  const char* objectName, void (T::*write)(Ref<Held>)) noexcept
{
    return guardStatus(function, [&] {
        T& target = lookup<T>(handle, handleName);
        (target.*write)(lookupRef<Held>(object, objectName));
    });
}

template <class T, class Held>
TQ3Status setHeldOptional(const char* function, TQ3Object handle, const char* handleName, TQ3Object object,
                          const char* objectName, void (T::*write)(Ref<Held>)) noexcept
{
    return guardStatus(function, [&] {
        T& target = lookup<T>(handle, handleName);
        (target.*write)(Ref<Held>::retain(lookupOptional<Held>(object, objectName)));
    });
}

} // namespace q3::api

// A C entry point cannot come from a template, so the Get/Set pairs that
// differ only in names are written once as the macros below, through the
// templates above. Prefix is the C prefix (Q3XDrawContext), Class the q3 class
// the handle must be, `handle` and `param` Apple's parameter names (the error
// messages name them as every other call does); Set goes through
// Class::set<Field> and Get reads Class::<param>().

/// Prefix_Set<Field> and _Get<Field> of a Type given through a pointer.
#define Q3_POINTER_VALUE_ENTRY_POINTS(Prefix, Class, HandleType, handle, Field, Type, param)                    \
    TQ3Status Prefix##_Set##Field(HandleType handle, const Type* param)                                         \
    {                                                                                                           \
        return q3::api::setValue<Class>(__func__, handle, #handle, param, #param, &Class::set##Field);          \
    }                                                                                                           \
    TQ3Status Prefix##_Get##Field(HandleType handle, Type* param)                                               \
    {                                                                                                           \
        return q3::api::getValue<Class>(__func__, handle, #handle, param, #param, &Class::param);               \
    }

/// Prefix_Set<Field> and _Get<Field> of a Type given by value (setDirect).
#define Q3_DIRECT_VALUE_ENTRY_POINTS(Prefix, Class, HandleType, handle, Field, Type, param)                     \
    TQ3Status Prefix##_Set##Field(HandleType handle, Type param)                                                \
    {                                                                                                           \
        return q3::api::setDirect<Class>(__func__, handle, #handle, param, &Class::set##Field);                 \
    }                                                                                                           \
    TQ3Status Prefix##_Get##Field(HandleType handle, Type* param)                                               \
    {                                                                                                           \
        return q3::api::getValue<Class>(__func__, handle, #handle, param, #param, &Class::param);               \
    }

/// Prefix_Set<Field> and _Get<Field> of an object the Class holds (a Type
/// called `param`): Set through `store` (setHeld, or setHeldOptional where
/// NULL clears it) and Class::set<Field>, Get through getHeld and
/// Class::<param>().
#define Q3_HELD_ENTRY_POINTS(Prefix, Class, HandleType, handle, Field, Type, param, store)                      \
    TQ3Status Prefix##_Set##Field(HandleType handle, Type param)                                                \
    {                                                                                                           \
        return q3::api::store(__func__, handle, #handle, param, #param, &Class::set##Field);                    \
    }                                                                                                           \
    TQ3Status Prefix##_Get##Field(HandleType handle, Type* param)                                               \
    {                                                                                                           \
        return q3::api::getHeld(__func__, handle, #handle, param, #param, &Class::param);                       \
    }
