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

// A C entry point cannot come from a template, so each group of entry points
// a light kind shares is written once below as a macro that defines them
// through the templates above. Kind names the class (q3::<Kind>Light) and the
// C prefix (Q3<Kind>Light_); the parameter names are QD3DLight.h's, so the
// error messages name them as every other call does.

/// Q3<Kind>Light_New, _GetData and _SetData, whose data is a DataType named
/// `data` in Apple's declarations.
#define Q3_LIGHT_DATA_ENTRY_POINTS(Kind, DataType, data)                                                        \
    TQ3LightObject Q3##Kind##Light_New(const DataType* data)                                                    \
    {                                                                                                           \
        return q3::api::newLight<q3::Kind##Light>(__func__, data, #data);                                       \
    }                                                                                                           \
    TQ3Status Q3##Kind##Light_GetData(TQ3LightObject light, DataType* data)                                     \
    {                                                                                                           \
        return q3::api::getLightData<q3::Kind##Light>(__func__, light, data, #data);                            \
    }                                                                                                           \
    TQ3Status Q3##Kind##Light_SetData(TQ3LightObject light, const DataType* data)                               \
    {                                                                                                           \
        return q3::api::setLightData<q3::Kind##Light>(__func__, light, data, #data);                            \
    }

/// Q3<Kind>Light_Get<Name> and _Set<Name> of the field `field` of
/// TQ3<Kind>LightData, a Type that Set takes by value (a float, an
/// enumeration, a Boolean).
#define Q3_LIGHT_VALUE_FIELD_ENTRY_POINTS(Kind, Name, Type, field)                                              \
    TQ3Status Q3##Kind##Light_Get##Name(TQ3LightObject light, Type* field)                                      \
    {                                                                                                           \
        return q3::api::getLightField<q3::Kind##Light>(__func__, light, field, #field,                          \
                                                       &TQ3##Kind##LightData::field);                           \
    }                                                                                                           \
    TQ3Status Q3##Kind##Light_Set##Name(TQ3LightObject light, Type field)                                       \
    {                                                                                                           \
        return q3::api::setLightField<q3::Kind##Light>(__func__, light, field, &TQ3##Kind##LightData::field);   \
    }

/// The same for a field that Set takes through a pointer (a location, a
/// direction).
#define Q3_LIGHT_POINTER_FIELD_ENTRY_POINTS(Kind, Name, Type, field)                                            \
    TQ3Status Q3##Kind##Light_Get##Name(TQ3LightObject light, Type* field)                                      \
    {                                                                                                           \
        return q3::api::getLightField<q3::Kind##Light>(__func__, light, field, #field,                          \
                                                       &TQ3##Kind##LightData::field);                           \
    }                                                                                                           \
    TQ3Status Q3##Kind##Light_Set##Name(TQ3LightObject light, const Type* field)                                \
    {                                                                                                           \
        return q3::api::setLightField<q3::Kind##Light>(__func__, light, field, #field,                          \
                                                       &TQ3##Kind##LightData::field);                           \
    }

/// The fields of a light at a location, point and spot lights alike
/// (Q3<Kind>Light_Get/SetCastShadowsState, _Get/SetAttenuation,
/// _Get/SetLocation).
#define Q3_LOCATED_LIGHT_ENTRY_POINTS(Kind)                                                                     \
    Q3_LIGHT_VALUE_FIELD_ENTRY_POINTS(Kind, CastShadowsState, TQ3Boolean, castsShadows)                         \
    Q3_LIGHT_VALUE_FIELD_ENTRY_POINTS(Kind, Attenuation, TQ3AttenuationType, attenuation)                       \
    Q3_LIGHT_POINTER_FIELD_ENTRY_POINTS(Kind, Location, TQ3Point3D, location)
