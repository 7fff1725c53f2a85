// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DTransform.h"
#include "api/Entry.h"
#include "view/Transform.h"
#include "view/View.h"

#include <cstring>

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;
using q3::api::readInto;

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
    auto data = target.data();
    change(data);
    target.setData(data);
}

} // namespace

extern "C" {

TQ3ObjectType Q3Transform_GetType(TQ3TransformObject transform)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookup<Transform>(transform, "transform").leafType(); });
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
    return guard(__func__, TQ3TransformObject{nullptr}, [&]() -> TQ3TransformObject {
        requireNonNull(matrix, "matrix");
        return makeShared<MatrixTransform>(*matrix).detach();
    });
}

TQ3Status Q3MatrixTransform_Submit(const TQ3Matrix4x4* matrix, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { submitTransient<MatrixTransform>(matrix, "matrix", view); });
}

TQ3Status Q3MatrixTransform_Set(TQ3TransformObject transform, const TQ3Matrix4x4* matrix)
{
    return guardStatus(__func__, [&] {
        MatrixTransform& target = lookup<MatrixTransform>(transform, "transform");
        requireNonNull(matrix, "matrix");
        target.setMatrix(*matrix);
    });
}

TQ3Status Q3MatrixTransform_Get(TQ3TransformObject transform, TQ3Matrix4x4* matrix)
{
    return guardStatus(__func__, [&] {
        readInto<MatrixTransform>(transform, "transform", matrix, "matrix",
                                  [](const MatrixTransform& t) { return t.matrix(); });
    });
}

TQ3TransformObject Q3TranslateTransform_New(const TQ3Vector3D* translate)
{
    return guard(__func__, TQ3TransformObject{nullptr}, [&]() -> TQ3TransformObject {
        requireNonNull(translate, "translate");
        return makeShared<TranslateTransform>(*translate).detach();
    });
}

TQ3Status Q3TranslateTransform_Submit(const TQ3Vector3D* translate, TQ3ViewObject view)
{
    return guardStatus(__func__,
                       [&] { submitTransient<TranslateTransform>(translate, "translate", view); });
}

TQ3Status Q3TranslateTransform_Set(TQ3TransformObject transform, const TQ3Vector3D* translate)
{
    return guardStatus(__func__, [&] {
        TranslateTransform& target = lookup<TranslateTransform>(transform, "transform");
        requireNonNull(translate, "translate");
        target.setTranslate(*translate);
    });
}

TQ3Status Q3TranslateTransform_Get(TQ3TransformObject transform, TQ3Vector3D* translate)
{
    return guardStatus(__func__, [&] {
        readInto<TranslateTransform>(transform, "transform", translate, "translate",
                                     [](const TranslateTransform& t) { return t.translate(); });
    });
}

TQ3TransformObject Q3ScaleTransform_New(const TQ3Vector3D* scale)
{
    return guard(__func__, TQ3TransformObject{nullptr}, [&]() -> TQ3TransformObject {
        requireNonNull(scale, "scale");
        return makeShared<ScaleTransform>(*scale).detach();
    });
}

TQ3Status Q3ScaleTransform_Submit(const TQ3Vector3D* scale, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { submitTransient<ScaleTransform>(scale, "scale", view); });
}

TQ3Status Q3ScaleTransform_Set(TQ3TransformObject transform, const TQ3Vector3D* scale)
{
    return guardStatus(__func__, [&] {
        ScaleTransform& target = lookup<ScaleTransform>(transform, "transform");
        requireNonNull(scale, "scale");
        target.setScale(*scale);
    });
}

TQ3Status Q3ScaleTransform_Get(TQ3TransformObject transform, TQ3Vector3D* scale)
{
    return guardStatus(__func__, [&] {
        readInto<ScaleTransform>(transform, "transform", scale, "scale",
                                 [](const ScaleTransform& t) { return t.scale(); });
    });
}

TQ3TransformObject Q3RotateTransform_New(const TQ3RotateTransformData* data)
{
    return guard(__func__, TQ3TransformObject{nullptr}, [&]() -> TQ3TransformObject {
        requireNonNull(data, "data");
        return makeShared<RotateTransform>(*data).detach();
    });
}

TQ3Status Q3RotateTransform_Submit(const TQ3RotateTransformData* data, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { submitTransient<RotateTransform>(data, "data", view); });
}

TQ3Status Q3RotateTransform_SetData(TQ3TransformObject transform,
                                    const TQ3RotateTransformData* data)
{
    return guardStatus(__func__, [&] {
        RotateTransform& target = lookup<RotateTransform>(transform, "transform");
        requireNonNull(data, "data");
        target.setData(*data);
    });
}

TQ3Status Q3RotateTransform_GetData(TQ3TransformObject transform, TQ3RotateTransformData* data)
{
    return guardStatus(__func__, [&] {
        readInto<RotateTransform>(transform, "transform", data, "data",
                                  [](const RotateTransform& t) { return t.data(); });
    });
}

TQ3Status Q3RotateTransform_SetAxis(TQ3TransformObject transform, TQ3Axis axis)
{
    // axis goes on by reference: it may hold any int until setAxis checks it.
    return guardStatus(__func__,
                       [&] { lookup<RotateTransform>(transform, "transform").setAxis(axis); });
}

TQ3Status Q3RotateTransform_GetAxis(TQ3TransformObject transform, TQ3Axis* axis)
{
    return guardStatus(__func__, [&] {
        readInto<RotateTransform>(transform, "transform", axis, "axis",
                                  [](const RotateTransform& t) { return t.data().axis; });
    });
}

TQ3Status Q3RotateTransform_SetAngle(TQ3TransformObject transform, float radians)
{
    return guardStatus(__func__,
                       [&] { lookup<RotateTransform>(transform, "transform").setAngle(radians); });
}

TQ3Status Q3RotateTransform_GetAngle(TQ3TransformObject transform, float* radians)
{
    return guardStatus(__func__, [&] {
        readInto<RotateTransform>(transform, "transform", radians, "radians",
                                  [](const RotateTransform& t) { return t.data().radians; });
    });
}

TQ3TransformObject Q3QuaternionTransform_New(const TQ3Quaternion* quaternion)
{
    return guard(__func__, TQ3TransformObject{nullptr}, [&]() -> TQ3TransformObject {
        requireNonNull(quaternion, "quaternion");
        return makeShared<QuaternionTransform>(*quaternion).detach();
    });
}

TQ3Status Q3QuaternionTransform_Submit(const TQ3Quaternion* quaternion, TQ3ViewObject view)
{
    return guardStatus(__func__,
                       [&] { submitTransient<QuaternionTransform>(quaternion, "quaternion", view); });
}

TQ3Status Q3QuaternionTransform_Set(TQ3TransformObject transform, const TQ3Quaternion* quaternion)
{
    return guardStatus(__func__, [&] {
        QuaternionTransform& target = lookup<QuaternionTransform>(transform, "transform");
        requireNonNull(quaternion, "quaternion");
        target.setQuaternion(*quaternion);
    });
}

TQ3Status Q3QuaternionTransform_Get(TQ3TransformObject transform, TQ3Quaternion* quaternion)
{
    return guardStatus(__func__, [&] {
        readInto<QuaternionTransform>(transform, "transform", quaternion, "quaternion",
                                      [](const QuaternionTransform& t) { return t.quaternion(); });
    });
}

TQ3TransformObject Q3RotateAboutPointTransform_New(const TQ3RotateAboutPointTransformData* data)
{
    return guard(__func__, TQ3TransformObject{nullptr}, [&]() -> TQ3TransformObject {
        requireNonNull(data, "data");
        return makeShared<RotateAboutPointTransform>(*data).detach();
    });
}

TQ3Status Q3RotateAboutPointTransform_Submit(const TQ3RotateAboutPointTransformData* data, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { submitTransient<RotateAboutPointTransform>(data, "data", view); });
}

TQ3Status Q3RotateAboutPointTransform_SetData(TQ3TransformObject transform,
                                              const TQ3RotateAboutPointTransformData* data)
{
    return guardStatus(__func__, [&] {
        RotateAboutPointTransform& target = lookup<RotateAboutPointTransform>(transform, "transform");
        requireNonNull(data, "data");
        target.setData(*data);
    });
}

TQ3Status Q3RotateAboutPointTransform_GetData(TQ3TransformObject transform, TQ3RotateAboutPointTransformData* data)
{
    return guardStatus(__func__, [&] {
        readInto<RotateAboutPointTransform>(transform, "transform", data, "data",
                                            [](const RotateAboutPointTransform& t) { return t.data(); });
    });
}

TQ3Status Q3RotateAboutPointTransform_SetAxis(TQ3TransformObject transform, TQ3Axis axis)
{
    return guardStatus(__func__, [&] {
        // Copied as bytes: a C caller may pass any int (core/EnumValue.h).
        changeData<RotateAboutPointTransform>(
            transform, [&](TQ3RotateAboutPointTransformData& d) { std::memcpy(&d.axis, &axis, sizeof axis); });
    });
}

TQ3Status Q3RotateAboutPointTransform_GetAxis(TQ3TransformObject transform, TQ3Axis* axis)
{
    return guardStatus(__func__, [&] {
        readInto<RotateAboutPointTransform>(transform, "transform", axis, "axis",
                                            [](const RotateAboutPointTransform& t) { return t.data().axis; });
    });
}

TQ3Status Q3RotateAboutPointTransform_SetAngle(TQ3TransformObject transform, float radians)
{
    return guardStatus(__func__, [&] {
        changeData<RotateAboutPointTransform>(transform,
                                              [&](TQ3RotateAboutPointTransformData& d) { d.radians = radians; });
    });
}

TQ3Status Q3RotateAboutPointTransform_GetAngle(TQ3TransformObject transform, float* radians)
{
    return guardStatus(__func__, [&] {
        readInto<RotateAboutPointTransform>(transform, "transform", radians, "radians",
                                            [](const RotateAboutPointTransform& t) { return t.data().radians; });
    });
}

TQ3Status Q3RotateAboutPointTransform_SetAboutPoint(TQ3TransformObject transform, const TQ3Point3D* about)
{
    return guardStatus(__func__, [&] {
        lookup<RotateAboutPointTransform>(transform, "transform");
        requireNonNull(about, "about");
        changeData<RotateAboutPointTransform>(transform,
                                              [&](TQ3RotateAboutPointTransformData& d) { d.about = *about; });
    });
}

TQ3Status Q3RotateAboutPointTransform_GetAboutPoint(TQ3TransformObject transform, TQ3Point3D* about)
{
    return guardStatus(__func__, [&] {
        readInto<RotateAboutPointTransform>(transform, "transform", about, "about",
                                            [](const RotateAboutPointTransform& t) { return t.data().about; });
    });
}

TQ3TransformObject Q3RotateAboutAxisTransform_New(const TQ3RotateAboutAxisTransformData* data)
{
    return guard(__func__, TQ3TransformObject{nullptr}, [&]() -> TQ3TransformObject {
        requireNonNull(data, "data");
        return makeShared<RotateAboutAxisTransform>(*data).detach();
    });
}

TQ3Status Q3RotateAboutAxisTransform_Submit(const TQ3RotateAboutAxisTransformData* data, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { submitTransient<RotateAboutAxisTransform>(data, "data", view); });
}

TQ3Status Q3RotateAboutAxisTransform_SetData(TQ3TransformObject transform,
                                             const TQ3RotateAboutAxisTransformData* data)
{
    return guardStatus(__func__, [&] {
        RotateAboutAxisTransform& target = lookup<RotateAboutAxisTransform>(transform, "transform");
        requireNonNull(data, "data");
        target.setData(*data);
    });
}

TQ3Status Q3RotateAboutAxisTransform_GetData(TQ3TransformObject transform, TQ3RotateAboutAxisTransformData* data)
{
    return guardStatus(__func__, [&] {
        readInto<RotateAboutAxisTransform>(transform, "transform", data, "data",
                                           [](const RotateAboutAxisTransform& t) { return t.data(); });
    });
}

TQ3Status Q3RotateAboutAxisTransform_SetOrientation(TQ3TransformObject transform, const TQ3Vector3D* axis)
{
    return guardStatus(__func__, [&] {
        lookup<RotateAboutAxisTransform>(transform, "transform");
        requireNonNull(axis, "axis");
        changeData<RotateAboutAxisTransform>(transform,
                                             [&](TQ3RotateAboutAxisTransformData& d) { d.orientation = *axis; });
    });
}

TQ3Status Q3RotateAboutAxisTransform_GetOrientation(TQ3TransformObject transform, TQ3Vector3D* axis)
{
    return guardStatus(__func__, [&] {
        readInto<RotateAboutAxisTransform>(transform, "transform", axis, "axis",
                                           [](const RotateAboutAxisTransform& t) { return t.data().orientation; });
    });
}

TQ3Status Q3RotateAboutAxisTransform_SetAngle(TQ3TransformObject transform, float radians)
{
    return guardStatus(__func__, [&] {
        changeData<RotateAboutAxisTransform>(transform,
                                             [&](TQ3RotateAboutAxisTransformData& d) { d.radians = radians; });
    });
}

TQ3Status Q3RotateAboutAxisTransform_GetAngle(TQ3TransformObject transform, float* radians)
{
    return guardStatus(__func__, [&] {
        readInto<RotateAboutAxisTransform>(transform, "transform", radians, "radians",
                                           [](const RotateAboutAxisTransform& t) { return t.data().radians; });
    });
}

TQ3Status Q3RotateAboutAxisTransform_SetOrigin(TQ3TransformObject transform, const TQ3Point3D* origin)
{
    return guardStatus(__func__, [&] {
        lookup<RotateAboutAxisTransform>(transform, "transform");
        requireNonNull(origin, "origin");
        changeData<RotateAboutAxisTransform>(transform,
                                             [&](TQ3RotateAboutAxisTransformData& d) { d.origin = *origin; });
    });
}

TQ3Status Q3RotateAboutAxisTransform_GetOrigin(TQ3TransformObject transform, TQ3Point3D* origin)
{
    return guardStatus(__func__, [&] {
        readInto<RotateAboutAxisTransform>(transform, "transform", origin, "origin",
                                           [](const RotateAboutAxisTransform& t) { return t.data().origin; });
    });
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
