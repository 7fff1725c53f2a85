// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Apple's per-field calls of the quadrics and solids (Q3Cone_SetOrigin,
// Q3Cylinder_GetTopAttributeSet, ...), written once for any FieldGeometry T
// (geometry/Quadric.h). Each checks in the order QD3DGeometry.h states: the
// handle, then the pointer, then the data's rules.

#include "api/GeometryEntry.h"

namespace q3::api {

/// Q3Xxx_GetOrigin and the like: *out = the field.
template <class T, class Value>
TQ3Status getField(const char* function, TQ3GeometryObject geometry, Value T::DataType::*field, Value* out,
                   const char* outName)
{
    return guardStatus(function, [&] {
        readInto<T>(geometry, T::kName, out, outName, [&](const T& source) { return source.data().*field; });
    });
}

/// Q3Xxx_SetOrigin and the like, given a pointer.
template <class T, class Value>
TQ3Status setField(const char* function, TQ3GeometryObject geometry, Value T::DataType::*field, const Value* value,
                   const char* name)
{
    return guardStatus(function, [&] {
        T& target = lookup<T>(geometry, T::kName);
        requireNonNull(value, name);
        target.setField(field, *value);
    });
}

/// Q3Cone_SetCaps, Q3Torus_SetRatio: the value itself.
template <class T, class Value>
TQ3Status setFieldValue(const char* function, TQ3GeometryObject geometry, Value T::DataType::*field, Value value)
{
    return guardStatus(function, [&] { lookup<T>(geometry, T::kName).setField(field, value); });
}

/// Q3Cone_GetFaceAttributeSet and the like: a new reference, or NULL.
template <class T>
TQ3Status getPartSet(const char* function, TQ3GeometryObject geometry, TQ3AttributeSet T::DataType::*field,
                     TQ3AttributeSet* out, const char* outName)
{
    return guardStatus(function, [&] {
        readInto<T>(geometry, T::kName, out, outName,
                    [&](const T& source) { return attributeSetToHandle(heldAttributeSet(source.data().*field)); });
    });
}

/// Q3Cone_SetFaceAttributeSet and the like (NULL removes the set).
template <class T>
TQ3Status setPartSet(const char* function, TQ3GeometryObject geometry, TQ3AttributeSet T::DataType::*field,
                     TQ3AttributeSet set, const char* name)
{
    return guardStatus(function, [&] {
        T& target = lookup<T>(geometry, T::kName);
        target.setPartSet(field, attributeSetFromHandle(set, name));
    });
}

} // namespace q3::api
