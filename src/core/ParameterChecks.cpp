// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "core/ParameterChecks.h"

#include "core/Error.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace q3 {

namespace {

[[noreturn]] void invalid(const std::string& message)
{
    fail(kQ3ErrorInvalidParameter, message);
}

void checkComponent(float value, const char* name, const char* component)
{
    if (!std::isfinite(value))
        invalid(std::string(name) + "." + component + " is not a finite number");
}

// Points and vectors; RGB and ARGB colours (a checked first).
template <class XYZ>
void checkXYZ(const XYZ& v, const char* name)
{
    checkComponent(v.x, name, "x");
    checkComponent(v.y, name, "y");
    checkComponent(v.z, name, "z");
}

template <class Color>
void checkRGB(const Color& color, const char* name)
{
    checkComponent(color.r, name, "r");
    checkComponent(color.g, name, "g");
    checkComponent(color.b, name, "b");
}

} // namespace

std::string numberText(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

void checkFinite(float value, const char* name)
{
    if (!std::isfinite(value))
        invalid(std::string(name) + " is not a finite number");
}

void checkFinite(const TQ3Point3D& point, const char* name)
{
    checkXYZ(point, name);
}

void checkFinite(const TQ3Vector3D& vector, const char* name)
{
    checkXYZ(vector, name);
}

void checkFinite(const TQ3ColorRGB& color, const char* name)
{
    checkRGB(color, name);
}

void checkFinite(const TQ3ColorARGB& color, const char* name)
{
    checkComponent(color.a, name, "a");
    checkRGB(color, name);
}

long checkEnumRange(long value, long first, long last, const char* name, const char* names)
{
    if (value < first || value > last)
        invalid(std::string(name) + " " + std::to_string(value) + " is none of " + names);
    return value;
}

TQ3Switch checkSwitch(const TQ3Switch& value, const char* name)
{
    return checkEnum(value, kQ3Off, kQ3On, name, "kQ3Off, kQ3On");
}

} // namespace q3
