// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DErrors.h"

#include <exception>
#include <string>

namespace q3 {

/// What the core throws when a call cannot be carried out. The API boundary
/// (api/Entry.h) turns it into a posted QuickDraw 3D error and a fallback
/// return value; nothing has been changed when it is thrown.
class Error : public std::exception {
public:
    Error(TQ3Error code, std::string message) : m_code(code), m_message(std::move(message)) {}
    TQ3Error code() const noexcept { return m_code; }
    const char* what() const noexcept override { return m_message.c_str(); }

private:
    TQ3Error m_code;
    std::string m_message;
};

[[noreturn]] inline void fail(TQ3Error code, std::string message)
{
    throw Error(code, std::move(message));
}

/// Throws kQ3ErrorNULLParameter naming the parameter when pointer is null.
template <class T>
inline void requireNonNull(const T* pointer, const char* name)
{
    if (pointer == nullptr)
        fail(kQ3ErrorNULLParameter, std::string(name) + " is NULL");
}

} // namespace q3
