// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include <cstring>
#include <type_traits>

namespace q3 {

/// The integer a caller stored in an enum-typed field or argument. C callers
/// may put any int there (QuickDraw 3D code often passes a plain nonzero int
/// as a TQ3Boolean), and in C++ reading a value outside an enum's range as
/// the enum type is undefined behaviour (UBSan's -fsanitize=enum stops on
/// it), so validation reads the bytes instead. Take such arguments by
/// reference until this has checked them.
template <class Enum>
long enumValue(const Enum& value)
{
    static_assert(std::is_enum<Enum>::value, "enumValue reads enums");
    std::underlying_type_t<Enum> raw;
    std::memcpy(&raw, &value, sizeof raw);
    return static_cast<long>(raw);
}

} // namespace q3
