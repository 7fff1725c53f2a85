// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3D.h"
#include "core/EnumValue.h"

#include <cstring>
#include <string>

namespace q3 {

// The value rules that styles, shaders and lights share (QD3DStyle.h,
// QD3DShader.h, QD3DLight.h). Each check throws kQ3ErrorInvalidParameter
// naming the value (`name`, e.g. "data->fogStart") and what was wrong.

/// A number as the messages write it (printf's %g: 0.5, 1e+30, nan).
std::string numberText(double value);

void checkFinite(float value, const char* name);
void checkFinite(const TQ3Point3D& point, const char* name);
void checkFinite(const TQ3Vector3D& vector, const char* name);
void checkFinite(const TQ3ColorRGB& color, const char* name);
void checkFinite(const TQ3ColorARGB& color, const char* name);

/// The integer in an enum-typed value, which must lie in first..last
/// (`names` lists the enumerators for the message).
long checkEnumRange(long value, long first, long last, const char* name, const char* names);

/// An enum value read safely (enumValue) and checked to be first..last; the
/// result is the same value, now safe to copy as the enum type.
template <class Enum>
Enum checkEnum(const Enum& value, long first, long last, const char* name, const char* names)
{
    return static_cast<Enum>(checkEnumRange(enumValue(value), first, last, name, names));
}

/// QuickDraw 3D callers pass any nonzero int as true (QD3DDrawContext.h
/// states the rule for every TQ3Boolean Q3 takes): kQ3False stays kQ3False,
/// anything else becomes kQ3True.
inline TQ3Boolean booleanOf(const TQ3Boolean& value)
{
    return enumValue(value) != kQ3False ? kQ3True : kQ3False;
}

/// A TQ3Switch must be kQ3On or kQ3Off (the rule attribute sets use for the
/// highlight state).
TQ3Switch checkSwitch(const TQ3Switch& value, const char* name);

/// Stores an argument into a field of its type without reading it as that
/// type: an enum-typed argument may hold any int until it is checked.
template <class T>
void storeRaw(T& field, const T& value)
{
    std::memcpy(&field, &value, sizeof field);
}

} // namespace q3
