// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DTransform.h"
#include "api/Entry.h"
#include "view/Transform.h"
#include "view/View.h"

#include <cstring>

using namespace q3;
using namespace q3::api;

namespace {

// Immediate mode: the checks of _New, then the view sees a transient object
// that lives for the call only.
template <class T, class Data>
void submitTransient(const Data* data, const char* name, TQ3ViewObject view)
{
    requireNonNull(data, name);
    ShapeVisitor& target = lookup<View>(view, "view").submitTarget();
    const Ref<T> transform = makeShared<T>(*data);
    target.visitTransform(*transform);
}

// A field setter: the transform's data with one field changed, through the
// class's setData (the whole-data checks, nothing changed on failure).
template <class T, class Change>
void changeData(TQ3TransformObject transform, Change change)
{
    T& target = lookup<T>(transform, "transform");
    auto data = target.value();
    change(data);
    target.setValue(data);
}

// A Get of one field of a transform's data: the handle, then the pointer.
template <class T, class Data, class Value>
TQ3Status getField(const char* function, TQ3TransformObject transform, Value* out, const char* outName,
                   Value Data::*field)
{
    return getValue<T>(function, transform, "transform", out, outName,
                       [&](const T& source) { return source.value().*field; });
}

// A Set of one field given by value, through changeData. Copied as bytes: a
// C caller may pass any int for an enumeration (core/EnumValue.h), which
// the class's checks then refuse.
template <class T, class Data, class Value>
TQ3Status setField(const char* function, TQ3TransformObject transform, const Value& value, Value Data::*field)
{
    return guardStatus(function, [&] {
        changeData<T>(transform, [&](Data& d) { std::memcpy(&(d.*field), &value, sizeof value); });
    });
}

// A Set of one field given through a pointer: the handle, then the pointer,
// then changeData.
template <class T, class Data, class Value>
TQ3Status setFieldFrom(const char* function, TQ3TransformObject transform, const Value* in, const char* inName,
                       Value Data::*field)
{
    return guardStatus(function, [&] {
        lookup<T>(transform, "transform");
        requireNonNull(in, inName);
        changeData<T>(transform, [&](Data& d) { d.*field = *in; });
    });
}

// A Set of a rotate transform's axis or angle, through the member function
// that checks it.
template <class Value, class Param>
TQ3Status setRotate(const char* function, TQ3TransformObject transform, const Value& value,
                    void (RotateTransform::*write)(Param))
{
    return guardStatus(function, [&] { (lookup<RotateTransform>(transform, "transform").*write)(value); });
}

} // namespace

// A C entry point cannot come from a template, so each family of entry points
// below is written once as a macro that defines them through the templates
// above. Name names the class (q3::<Name>Transform) and the C prefix
// (Q3<Name>Transform_); the parameter names are QD3DTransform.h's, so the
// error messages name them as every other call does.

/// Q3<Name>Transform_New, _Submit, _Set and _Get of a transform whose state
/// is one Type, called `param` in Apple's declarations.
#define Q3_VALUE_TRANSFORM_ENTRY_POINTS(Name, Type, param)                                                      \
    Q3_TRANSFORM_STATE_ENTRY_POINTS(Name, Set, Get, Type, param)

/// Q3<Name>Transform_New, _Submit, _SetData and _GetData of a transform whose
/// state is a TQ3<Name>TransformData, called `data`.
#define Q3_DATA_TRANSFORM_ENTRY_POINTS(Name)                                                                    \
    Q3_TRANSFORM_STATE_ENTRY_POINTS(Name, SetData, GetData, TQ3##Name##TransformData, data)

#define Q3_TRANSFORM_STATE_ENTRY_POINTS(Name, Set, Get, Type, param)                                            \
    TQ3TransformObject Q3##Name##Transform_New(const Type* param)                                               \
    {                                                                                                           \
        return newShared<Name##Transform>(__func__, param, #param);                                             \
    }                                                                                                           \
    TQ3Status Q3##Name##Transform_Submit(const Type* param, TQ3ViewObject view)                                 \
    {                                                                                                           \
        return guardStatus(__func__, [&] { submitTransient<Name##Transform>(param, #param, view); });          \
    }                                                                                                           \
    TQ3Status Q3##Name##Transform_##Set(TQ3TransformObject transform, const Type* param)                        \
    {                                                                                                           \
        return setValue<Name##Transform>(__func__, transform, "transform", param, #param,                       \
                                         &Name##Transform::setValue);                                           \
    }                                                                                                           \
    TQ3Status Q3##Name##Transform_##Get(TQ3TransformObject transform, Type* param)                              \
    {                                                                                                           \
        return getValue<Name##Transform>(__func__, transform, "transform", param, #param,                       \
                                         &Name##Transform::value);                                              \
    }

/// Q3<Name>Transform_Set<Field> and _Get<Field> of the member `member` of
/// TQ3<Name>TransformData, a Type that Set takes by value (an axis, an
/// angle), called `param` in Apple's declarations.
#define Q3_TRANSFORM_VALUE_FIELD_ENTRY_POINTS(Name, Field, Type, param, member)                                 \
    TQ3Status Q3##Name##Transform_Set##Field(TQ3TransformObject transform, Type param)                          \
    {                                                                                                           \
        return setField<Name##Transform>(__func__, transform, param, &TQ3##Name##TransformData::member);        \
    }                                                                                                           \
    TQ3Status Q3##Name##Transform_Get##Field(TQ3TransformObject transform, Type* param)                         \
    {                                                                                                           \
        return getField<Name##Transform>(__func__, transform, param, #param, &TQ3##Name##TransformData::member); \
    }

/// The same for a member that Set takes through a pointer (a point, a
/// vector).
#define Q3_TRANSFORM_POINTER_FIELD_ENTRY_POINTS(Name, Field, Type, param, member)                               \
    TQ3Status Q3##Name##Transform_Set##Field(TQ3TransformObject transform, const Type* param)                   \
    {                                                                                                           \
        return setFieldFrom<Name##Transform>(__func__, transform, param, #param,                                \
                                             &TQ3##Name##TransformData::member);                                \
    }                                                                                                           \
    TQ3Status Q3##Name##Transform_Get##Field(TQ3TransformObject transform, Type* param)                         \
    {                                                                                                           \
        return getField<Name##Transform>(__func__, transform, param, #param, &TQ3##Name##TransformData::member); \
    }

extern "C" {

TQ3ObjectType Q3Transform_GetType(TQ3TransformObject transform)
{
    return api::getLeafType<Transform>(__func__, transform, "transform");
}

TQ3Matrix4x4* Q3Transform_GetMatrix(TQ3TransformObject transform, TQ3Matrix4x4* matrix)
{
    return guard(__func__, static_cast<TQ3Matrix4x4*>(nullptr), [&] {
        readInto<Transform>(transform, "transform", matrix, "matrix",
                            [](const Transform& t) { return t.matrix(); });
        return matrix;
    });
}

TQ3Status Q3Transform_Submit(TQ3TransformObject transform, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        const Transform& source = lookup<Transform>(transform, "transform");
        lookup<View>(view, "view").submit(source);
    });
}

Q3_VALUE_TRANSFORM_ENTRY_POINTS(Matrix, TQ3Matrix4x4, matrix)
Q3_VALUE_TRANSFORM_ENTRY_POINTS(Translate, TQ3Vector3D, translate)
Q3_VALUE_TRANSFORM_ENTRY_POINTS(Scale, TQ3Vector3D, scale)
Q3_VALUE_TRANSFORM_ENTRY_POINTS(Quaternion, TQ3Quaternion, quaternion)
Q3_DATA_TRANSFORM_ENTRY_POINTS(Rotate)

// A rotate transform's axis and angle are set through its own checks (the
// axis by reference: it may hold any int until setAxis checks it).
TQ3Status Q3RotateTransform_SetAxis(TQ3TransformObject transform, TQ3Axis axis)
{
    return setRotate(__func__, transform, axis, &RotateTransform::setAxis);
}

TQ3Status Q3RotateTransform_GetAxis(TQ3TransformObject transform, TQ3Axis* axis)
{
    return getField<RotateTransform>(__func__, transform, axis, "axis", &TQ3RotateTransformData::axis);
}

TQ3Status Q3RotateTransform_SetAngle(TQ3TransformObject transform, float radians)
{
    return setRotate(__func__, transform, radians, &RotateTransform::setAngle);
}

TQ3Status Q3RotateTransform_GetAngle(TQ3TransformObject transform, float* radians)
{
    return getField<RotateTransform>(__func__, transform, radians, "radians", &TQ3RotateTransformData::radians);
}

Q3_DATA_TRANSFORM_ENTRY_POINTS(RotateAboutPoint)
Q3_TRANSFORM_VALUE_FIELD_ENTRY_POINTS(RotateAboutPoint, Axis, TQ3Axis, axis, axis)
Q3_TRANSFORM_VALUE_FIELD_ENTRY_POINTS(RotateAboutPoint, Angle, float, radians, radians)
Q3_TRANSFORM_POINTER_FIELD_ENTRY_POINTS(RotateAboutPoint, AboutPoint, TQ3Point3D, about, about)

Q3_DATA_TRANSFORM_ENTRY_POINTS(RotateAboutAxis)
Q3_TRANSFORM_POINTER_FIELD_ENTRY_POINTS(RotateAboutAxis, Orientation, TQ3Vector3D, axis, orientation)
Q3_TRANSFORM_VALUE_FIELD_ENTRY_POINTS(RotateAboutAxis, Angle, float, radians, radians)
Q3_TRANSFORM_POINTER_FIELD_ENTRY_POINTS(RotateAboutAxis, Origin, TQ3Point3D, origin, origin)

TQ3TransformObject Q3ResetTransform_New(void)
{
    return guard(__func__, TQ3TransformObject{nullptr},
                 []() -> TQ3TransformObject { return makeShared<ResetTransform>().detach(); });
}

TQ3Status Q3ResetTransform_Submit(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        ShapeVisitor& target = lookup<View>(view, "view").submitTarget();
        target.visitTransform(*makeShared<ResetTransform>());
    });
}

} // extern "C"

#undef Q3_VALUE_TRANSFORM_ENTRY_POINTS
#undef Q3_DATA_TRANSFORM_ENTRY_POINTS
#undef Q3_TRANSFORM_STATE_ENTRY_POINTS
#undef Q3_TRANSFORM_VALUE_FIELD_ENTRY_POINTS
#undef Q3_TRANSFORM_POINTER_FIELD_ENTRY_POINTS
