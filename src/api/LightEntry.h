// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The entry points every light kind has (New, GetData, SetData, and Get/Set
// of one field; QD3DLight.h), written once for any DataLight L. A field
// setter edits a copy of the light's data and stores it through SetData's
// check, so it accepts and rejects exactly what SetData does. Checks run in
// QD3DLight.h's order: the handle, the pointer, then the data's rules.

#include "api/Entry.h"
#include "core/ParameterChecks.h"
#include "light/Light.h"

namespace q3::api {

template <class L>
TQ3LightObject newLight(const char* function, const typename L::DataType* data, const char* dataName)
{
    return newShared<L>(function, data, dataName);
}

template <class L>
TQ3Status getLightData(const char* function, TQ3LightObject light, typename L::DataType* data,
                       const char* dataName)
{
    return guardStatus(function, [&] {
        readInto<L>(light, "light", data, dataName, [](const L& source) { return source.data(); });
    });
}

template <class L>
TQ3Status setLightData(const char* function, TQ3LightObject light, const typename L::DataType* data,
                       const char* dataName)
{
    return guardStatus(function, [&] {
        L& target = lookup<L>(light, "light");
        requireNonNull(data, dataName);
        target.setData(*data);
    });
}

template <class L, class Value>
TQ3Status getLightField(const char* function, TQ3LightObject light, Value* value, const char* valueName,
                        Value L::DataType::*field)
{
    return guardStatus(function, [&] {
        readInto<L>(light, "light", value, valueName, [&](const L& source) { return source.data().*field; });
    });
}

/// A field given by value (a float, an enumeration, a Boolean).
template <class L, class Value>
TQ3Status setLightField(const char* function, TQ3LightObject light, const Value& value,
                        Value L::DataType::*field)
{
    return guardStatus(function, [&] {
        lookup<L>(light, "light").edit([&](typename L::DataType& next) { storeRaw(next.*field, value); });
    });
}

/// A field given through a pointer (a location, a direction).
template <class L, class Value>
TQ3Status setLightField(const char* function, TQ3LightObject light, const Value* value, const char* valueName,
                        Value L::DataType::*field)
{
    return guardStatus(function, [&] {
        L& target = lookup<L>(light, "light");
        requireNonNull(value, valueName);
        target.edit([&](typename L::DataType& next) { next.*field = *value; });
    });
}

} // namespace q3::api
