// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/Error.h"
#include "core/ErrorManager.h"
#include "core/Object.h"

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

/// The Get half of a single-value accessor, in the order every Get checks:
/// the handle (as a T, called `handleName` in errors), then the output pointer
/// (`outName`), then *out = read(object). Nothing is written on failure.
template <class T, class Value, class Read>
void readInto(TQ3Object handle, const char* handleName, Value* out, const char* outName, Read read)
{
    const T& source = lookup<T>(handle, handleName);
    requireNonNull(out, outName);
    *out = read(source);
}

} // namespace q3::api
