// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include <cstddef>
#include <utility>

namespace q3 {

/// An owning reference to a shared object, following the reference-count
/// contract stated on SharedObject (core/Object.h), which also says what
/// adopt(), retain() and detach() mean. There is no implicit construction from
/// a raw pointer, so every Ref says which of the two it does.
template <class T>
class Ref {
public:
    Ref() = default;
    Ref(std::nullptr_t) {}
    Ref(const Ref& other) : m_ptr(other.m_ptr) { acquire(); }
    Ref(Ref&& other) noexcept : m_ptr(std::exchange(other.m_ptr, nullptr)) {}
    template <class U>
    Ref(const Ref<U>& other) : m_ptr(other.get()) { acquire(); }
    template <class U>
    Ref(Ref<U>&& other) noexcept : m_ptr(other.detach()) {}
    ~Ref() { reset(); }

    Ref& operator=(Ref other) noexcept
    {
        std::swap(m_ptr, other.m_ptr);
        return *this;
    }

    static Ref adopt(T* pointer)
    {
        Ref ref;
        ref.m_ptr = pointer;
        return ref;
    }

    static Ref retain(T* pointer)
    {
        Ref ref;
        ref.m_ptr = pointer;
        ref.acquire();
        return ref;
    }

    T* detach() noexcept { return std::exchange(m_ptr, nullptr); }

    void reset() noexcept
    {
        if (T* pointer = std::exchange(m_ptr, nullptr))
            pointer->releaseReference();
    }

    T* get() const noexcept { return m_ptr; }
    T* operator->() const noexcept { return m_ptr; }
    T& operator*() const noexcept { return *m_ptr; }
    explicit operator bool() const noexcept { return m_ptr != nullptr; }

private:
    void acquire() const noexcept
    {
        if (m_ptr != nullptr)
            m_ptr->addReference();
    }

    T* m_ptr = nullptr;
};

} // namespace q3
