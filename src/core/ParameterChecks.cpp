// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "core/ParameterChecks.h"

#include "core/Error.h"

#include <cmath>
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

} // namespace

void checkFinite(float value, const char* name)
{
    if (!std::isfinite(value))
        invalid(std::string(name) + " is not a finite number");
}

void checkFinite(const TQ3Point3D& point, const char* name)
{
    checkComponent(point.x, name, "x");
    checkComponent(point.y, name, "y");
    checkComponent(point.z, name, "z");
}

void checkFinite(const TQ3Vector3D& vector, const char* name)
{
    checkComponent(vector.x, name, "x");
    checkComponent(vector.y, name, "y");
    checkComponent(vector.z, name, "z");
}

void checkFinite(const TQ3ColorRGB& color, const char* name)
{
    checkComponent(color.r, name, "r");
    checkComponent(color.g, name, "g");
    checkComponent(color.b, name, "b");
}

void checkFinite(const TQ3ColorARGB& color, const char* name)
{
    checkComponent(color.a, name, "a");
    checkComponent(color.r, name, "r");
    checkComponent(color.g, name, "g");
    checkComponent(color.b, name, "b");
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
