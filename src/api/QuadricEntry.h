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

// A C entry point cannot come from a template, so each Get/Set pair of a
// quadric's field is written once below as a macro that defines it through
// the templates above. Name names the class (q3::<Name>), its data
// (TQ3<Name>Data) and the C prefix (Q3<Name>_); `field` is the data's member
// and Apple's parameter name (the error messages name it as every other call
// does).

/// Q3<Name>_Set<Field> and _Get<Field> of a Type given through a pointer (an
/// origin, an axis).
#define Q3_QUADRIC_FIELD_ENTRY_POINTS(Name, Field, Type, field)                                                 \
    TQ3Status Q3##Name##_Set##Field(TQ3GeometryObject geometry, const Type* field)                              \
    {                                                                                                           \
        return q3::api::setField<q3::Name>(__func__, geometry, &TQ3##Name##Data::field, field, #field);         \
    }                                                                                                           \
    Q3_QUADRIC_GET_FIELD_ENTRY_POINT(Name, Field, Type, field)

/// The same for a Type given by value (the caps, a torus's ratio).
#define Q3_QUADRIC_VALUE_FIELD_ENTRY_POINTS(Name, Field, Type, field)                                           \
    TQ3Status Q3##Name##_Set##Field(TQ3GeometryObject geometry, Type field)                                     \
    {                                                                                                           \
        return q3::api::setFieldValue<q3::Name>(__func__, geometry, &TQ3##Name##Data::field, field);            \
    }                                                                                                           \
    Q3_QUADRIC_GET_FIELD_ENTRY_POINT(Name, Field, Type, field)

#define Q3_QUADRIC_GET_FIELD_ENTRY_POINT(Name, Field, Type, field)                                              \
    TQ3Status Q3##Name##_Get##Field(TQ3GeometryObject geometry, Type* field)                                    \
    {                                                                                                           \
        return q3::api::getField<q3::Name>(__func__, geometry, &TQ3##Name##Data::field, field, #field);         \
    }

/// The frame of a planar quadric (disk, ellipse): Q3<Name>_Get/SetOrigin,
/// _Get/SetMajorRadius and _Get/SetMinorRadius.
#define Q3_QUADRIC_PLANE_ENTRY_POINTS(Name)                                                                     \
    Q3_QUADRIC_FIELD_ENTRY_POINTS(Name, Origin, TQ3Point3D, origin)                                             \
    Q3_QUADRIC_FIELD_ENTRY_POINTS(Name, MajorRadius, TQ3Vector3D, majorRadius)                                  \
    Q3_QUADRIC_FIELD_ENTRY_POINTS(Name, MinorRadius, TQ3Vector3D, minorRadius)

/// The frame of a solid quadric (cone, cylinder, ellipsoid, torus): the
/// planar frame and Q3<Name>_Get/SetOrientation.
#define Q3_QUADRIC_FRAME_ENTRY_POINTS(Name)                                                                     \
    Q3_QUADRIC_PLANE_ENTRY_POINTS(Name)                                                                         \
    Q3_QUADRIC_FIELD_ENTRY_POINTS(Name, Orientation, TQ3Vector3D, orientation)

/// Q3<Name>_Set<Part> and _Get<Part> of the attribute set of a part (the
/// face, a cap): Set takes a reference of its own (NULL removes the set), Get
/// hands out a new one (NULL for none).
#define Q3_QUADRIC_PART_SET_ENTRY_POINTS(Name, Part, field)                                                     \
    TQ3Status Q3##Name##_Set##Part(TQ3GeometryObject geometry, TQ3AttributeSet field)                           \
    {                                                                                                           \
        return q3::api::setPartSet<q3::Name>(__func__, geometry, &TQ3##Name##Data::field, field, #field);       \
    }                                                                                                           \
    TQ3Status Q3##Name##_Get##Part(TQ3GeometryObject geometry, TQ3AttributeSet* field)                          \
    {                                                                                                           \
        return q3::api::getPartSet<q3::Name>(__func__, geometry, &TQ3##Name##Data::field, field, #field);       \
    }

/// The caps of a cone or cylinder: Q3<Name>_Get/SetCaps and the attribute
/// sets of its bottom and its face (_Get/SetBottomAttributeSet,
/// _Get/SetFaceAttributeSet).
#define Q3_QUADRIC_CAPS_ENTRY_POINTS(Name)                                                                      \
    Q3_QUADRIC_VALUE_FIELD_ENTRY_POINTS(Name, Caps, TQ3EndCap, caps)                                            \
    Q3_QUADRIC_PART_SET_ENTRY_POINTS(Name, BottomAttributeSet, bottomAttributeSet)                              \
    Q3_QUADRIC_PART_SET_ENTRY_POINTS(Name, FaceAttributeSet, faceAttributeSet)
