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

using PointData = TQ3RotateAboutPointTransformData;
using AxisData = TQ3RotateAboutAxisTransformData;

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

} // namespace

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

TQ3TransformObject Q3MatrixTransform_New(const TQ3Matrix4x4* matrix)
{
    return newShared<MatrixTransform>(__func__, matrix, "matrix");
}

TQ3Status Q3MatrixTransform_Submit(const TQ3Matrix4x4* matrix, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { submitTransient<MatrixTransform>(matrix, "matrix", view); });
}

TQ3Status Q3MatrixTransform_Set(TQ3TransformObject transform, const TQ3Matrix4x4* matrix)
{
    return setValue<MatrixTransform>(__func__, transform, "transform", matrix, "matrix", &MatrixTransform::setValue);
}

TQ3Status Q3MatrixTransform_Get(TQ3TransformObject transform, TQ3Matrix4x4* matrix)
{
    return getValue<MatrixTransform>(__func__, transform, "transform", matrix, "matrix",
                                     &MatrixTransform::value);
}

TQ3TransformObject Q3TranslateTransform_New(const TQ3Vector3D* translate)
{
    return newShared<TranslateTransform>(__func__, translate, "translate");
}

TQ3Status Q3TranslateTransform_Submit(const TQ3Vector3D* translate, TQ3ViewObject view)
{
    return guardStatus(__func__,
                       [&] { submitTransient<TranslateTransform>(translate, "translate", view); });
}

TQ3Status Q3TranslateTransform_Set(TQ3TransformObject transform, const TQ3Vector3D* translate)
{
    return setValue<TranslateTransform>(__func__, transform, "transform", translate, "translate",
                                        &TranslateTransform::setValue);
}

TQ3Status Q3TranslateTransform_Get(TQ3TransformObject transform, TQ3Vector3D* translate)
{
    return getValue<TranslateTransform>(__func__, transform, "transform", translate, "translate",
                                        &TranslateTransform::value);
}

TQ3TransformObject Q3ScaleTransform_New(const TQ3Vector3D* scale)
{
    return newShared<ScaleTransform>(__func__, scale, "scale");
}

TQ3Status Q3ScaleTransform_Submit(const TQ3Vector3D* scale, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { submitTransient<ScaleTransform>(scale, "scale", view); });
}

TQ3Status Q3ScaleTransform_Set(TQ3TransformObject transform, const TQ3Vector3D* scale)
{
    return setValue<ScaleTransform>(__func__, transform, "transform", scale, "scale", &ScaleTransform::setValue);
}

TQ3Status Q3ScaleTransform_Get(TQ3TransformObject transform, TQ3Vector3D* scale)
{
    return getValue<ScaleTransform>(__func__, transform, "transform", scale, "scale",
                                    &ScaleTransform::value);
}

TQ3TransformObject Q3RotateTransform_New(const TQ3RotateTransformData* data)
{
    return newShared<RotateTransform>(__func__, data, "data");
}

TQ3Status Q3RotateTransform_Submit(const TQ3RotateTransformData* data, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { submitTransient<RotateTransform>(data, "data", view); });
}

TQ3Status Q3RotateTransform_SetData(TQ3TransformObject transform,
                                    const TQ3RotateTransformData* data)
{
    return setValue<RotateTransform>(__func__, transform, "transform", data, "data", &RotateTransform::setValue);
}

TQ3Status Q3RotateTransform_GetData(TQ3TransformObject transform, TQ3RotateTransformData* data)
{
    return getValue<RotateTransform>(__func__, transform, "transform", data, "data",
                                     &RotateTransform::value);
}

TQ3Status Q3RotateTransform_SetAxis(TQ3TransformObject transform, TQ3Axis axis)
{
    // axis goes on by reference: it may hold any int until setAxis checks it.
    return guardStatus(__func__,
                       [&] { lookup<RotateTransform>(transform, "transform").setAxis(axis); });
}

TQ3Status Q3RotateTransform_GetAxis(TQ3TransformObject transform, TQ3Axis* axis)
{
    return getValue<RotateTransform>(__func__, transform, "transform", axis, "axis",
                                     [](const RotateTransform& t) { return t.value().axis; });
}

TQ3Status Q3RotateTransform_SetAngle(TQ3TransformObject transform, float radians)
{
    return guardStatus(__func__,
                       [&] { lookup<RotateTransform>(transform, "transform").setAngle(radians); });
}

TQ3Status Q3RotateTransform_GetAngle(TQ3TransformObject transform, float* radians)
{
    return getValue<RotateTransform>(__func__, transform, "transform", radians, "radians",
                                     [](const RotateTransform& t) { return t.value().radians; });
}

TQ3TransformObject Q3QuaternionTransform_New(const TQ3Quaternion* quaternion)
{
    return newShared<QuaternionTransform>(__func__, quaternion, "quaternion");
}

TQ3Status Q3QuaternionTransform_Submit(const TQ3Quaternion* quaternion, TQ3ViewObject view)
{
    return guardStatus(__func__,
                       [&] { submitTransient<QuaternionTransform>(quaternion, "quaternion", view); });
}

TQ3Status Q3QuaternionTransform_Set(TQ3TransformObject transform, const TQ3Quaternion* quaternion)
{
    return setValue<QuaternionTransform>(__func__, transform, "transform", quaternion, "quaternion",
                                         &QuaternionTransform::setValue);
}

TQ3Status Q3QuaternionTransform_Get(TQ3TransformObject transform, TQ3Quaternion* quaternion)
{
    return getValue<QuaternionTransform>(__func__, transform, "transform", quaternion, "quaternion",
                                         &QuaternionTransform::value);
}

TQ3TransformObject Q3RotateAboutPointTransform_New(const TQ3RotateAboutPointTransformData* data)
{
    return newShared<RotateAboutPointTransform>(__func__, data, "data");
}

TQ3Status Q3RotateAboutPointTransform_Submit(const TQ3RotateAboutPointTransformData* data, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { submitTransient<RotateAboutPointTransform>(data, "data", view); });
}

TQ3Status Q3RotateAboutPointTransform_SetData(TQ3TransformObject transform,
                                              const TQ3RotateAboutPointTransformData* data)
{
    return setValue<RotateAboutPointTransform>(__func__, transform, "transform", data, "data",
                                               &RotateAboutPointTransform::setValue);
}

TQ3Status Q3RotateAboutPointTransform_GetData(TQ3TransformObject transform, TQ3RotateAboutPointTransformData* data)
{
    return getValue<RotateAboutPointTransform>(__func__, transform, "transform", data, "data",
                                               &RotateAboutPointTransform::value);
}

TQ3Status Q3RotateAboutPointTransform_SetAxis(TQ3TransformObject transform, TQ3Axis axis)
{
    return setField<RotateAboutPointTransform>(__func__, transform, axis, &PointData::axis);
}

TQ3Status Q3RotateAboutPointTransform_GetAxis(TQ3TransformObject transform, TQ3Axis* axis)
{
    return getField<RotateAboutPointTransform>(__func__, transform, axis, "axis", &PointData::axis);
}

TQ3Status Q3RotateAboutPointTransform_SetAngle(TQ3TransformObject transform, float radians)
{
    return setField<RotateAboutPointTransform>(__func__, transform, radians, &PointData::radians);
}

TQ3Status Q3RotateAboutPointTransform_GetAngle(TQ3TransformObject transform, float* radians)
{
    return getField<RotateAboutPointTransform>(__func__, transform, radians, "radians", &PointData::radians);
}

TQ3Status Q3RotateAboutPointTransform_SetAboutPoint(TQ3TransformObject transform, const TQ3Point3D* about)
{
    return setFieldFrom<RotateAboutPointTransform>(__func__, transform, about, "about", &PointData::about);
}

TQ3Status Q3RotateAboutPointTransform_GetAboutPoint(TQ3TransformObject transform, TQ3Point3D* about)
{
    return getField<RotateAboutPointTransform>(__func__, transform, about, "about", &PointData::about);
}

TQ3TransformObject Q3RotateAboutAxisTransform_New(const TQ3RotateAboutAxisTransformData* data)
{
    return newShared<RotateAboutAxisTransform>(__func__, data, "data");
}

TQ3Status Q3RotateAboutAxisTransform_Submit(const TQ3RotateAboutAxisTransformData* data, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { submitTransient<RotateAboutAxisTransform>(data, "data", view); });
}

TQ3Status Q3RotateAboutAxisTransform_SetData(TQ3TransformObject transform,
                                             const TQ3RotateAboutAxisTransformData* data)
{
    return setValue<RotateAboutAxisTransform>(__func__, transform, "transform", data, "data",
                                              &RotateAboutAxisTransform::setValue);
}

TQ3Status Q3RotateAboutAxisTransform_GetData(TQ3TransformObject transform, TQ3RotateAboutAxisTransformData* data)
{
    return getValue<RotateAboutAxisTransform>(__func__, transform, "transform", data, "data",
                                              &RotateAboutAxisTransform::value);
}

TQ3Status Q3RotateAboutAxisTransform_SetOrientation(TQ3TransformObject transform, const TQ3Vector3D* axis)
{
    return setFieldFrom<RotateAboutAxisTransform>(__func__, transform, axis, "axis", &AxisData::orientation);
}

TQ3Status Q3RotateAboutAxisTransform_GetOrientation(TQ3TransformObject transform, TQ3Vector3D* axis)
{
    return getField<RotateAboutAxisTransform>(__func__, transform, axis, "axis", &AxisData::orientation);
}

TQ3Status Q3RotateAboutAxisTransform_SetAngle(TQ3TransformObject transform, float radians)
{
    return setField<RotateAboutAxisTransform>(__func__, transform, radians, &AxisData::radians);
}

TQ3Status Q3RotateAboutAxisTransform_GetAngle(TQ3TransformObject transform, float* radians)
{
    return getField<RotateAboutAxisTransform>(__func__, transform, radians, "radians", &AxisData::radians);
}

TQ3Status Q3RotateAboutAxisTransform_SetOrigin(TQ3TransformObject transform, const TQ3Point3D* origin)
{
    return setFieldFrom<RotateAboutAxisTransform>(__func__, transform, origin, "origin", &AxisData::origin);
}

TQ3Status Q3RotateAboutAxisTransform_GetOrigin(TQ3TransformObject transform, TQ3Point3D* origin)
{
    return getField<RotateAboutAxisTransform>(__func__, transform, origin, "origin", &AxisData::origin);
}

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
