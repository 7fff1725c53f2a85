// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DTransform.h"
#include "api/Entry.h"
#include "view/Transform.h"
#include "view/View.h"

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
