// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Per-thread state that outlives the thread's own thread_local objects.
//
// When a thread ends, and when the process exits, the C++ runtime destroys
// the thread's thread_local objects before it runs atexit handlers and the
// destructors of static objects (glibc: __call_tls_dtors, then
// __run_exit_handlers). A QuickDraw 3D program that disposes of its objects
// in such a handler would then reach destroyed state. threadLocal<T, Tag>()
// gives the thread's value while it lives and, after it is destroyed, a value
// of the thread's own made for the rest of its life (one heap block per thread
// that calls the API that late, kept reachable from a thread_local pointer).

namespace q3 {

/// The calling thread's T (value-initialized), one per Tag.
template <class T, class Tag>
T& threadLocal()
{
    thread_local bool gone = false;
    thread_local T* late = nullptr;
    struct Owner {
        T value{};
        ~Owner() { gone = true; }
    };
    if (gone) {
        if (late == nullptr)
            late = new T{};
        return *late;
    }
    thread_local Owner owner;
    return owner.value;
}

} // namespace q3
