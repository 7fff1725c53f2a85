// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// A shared library opened with dlopen and its functions bound with dlsym,
// for the libraries Q3 must not link: libOSMesa.so.8 and libEGL.so.1 (a
// libq3.so linked against either would not load where it is missing) and
// the application's libEGL/libGLX (render/AppGlContext.cpp), which Q3 only
// looks at when the application has loaded them. A library is never closed:
// the GL vendor libraries keep process-wide state and thread-local
// dispatch that outlive any one caller.

#include <dlfcn.h>

#include <string>
#include <type_traits>

namespace q3 {

/// Invariant: error() is empty while every bind() so far found its symbol
/// in an opened library; otherwise it names the first failure.
class DynamicLibrary {
public:
    /// Opens `name` (RTLD_NOW | RTLD_LOCAL). With `onlyIfLoaded`, only a
    /// library the process has loaded already is opened (RTLD_NOLOAD), so
    /// asking does not load one.
    explicit DynamicLibrary(const char* name, bool onlyIfLoaded = false)
        : m_name(name), m_handle(dlopen(name, RTLD_NOW | RTLD_LOCAL | (onlyIfLoaded ? RTLD_NOLOAD : 0)))
    {
        if (m_handle == nullptr) {
            const char* why = dlerror();
            m_error = onlyIfLoaded ? m_name + " is not loaded"
                                   : "cannot load " + m_name + ": " + (why ? why : "unknown reason");
        }
    }

    bool opened() const { return m_handle != nullptr; }
    /// Empty when the library opened and every bind found its symbol.
    const std::string& error() const { return m_error; }
    bool ok() const { return m_error.empty(); }

    /// Sets `function` to the library's `symbol`, or to null (and, the
    /// first time, error() to "<library> has no <symbol>").
    template <class Function>
    bool bind(Function& function, const char* symbol)
    {
        static_assert(std::is_pointer_v<Function>, "bind a function pointer");
        function = m_handle != nullptr ? reinterpret_cast<Function>(dlsym(m_handle, symbol)) : nullptr;
        if (function == nullptr && m_error.empty())
            m_error = m_name + " has no " + symbol;
        return function != nullptr;
    }

private:
    std::string m_name;
    void* m_handle;
    std::string m_error;
};

} // namespace q3
