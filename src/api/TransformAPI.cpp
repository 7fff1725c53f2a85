// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DTransform.h"
#include "api/Entry.h"
#include "view/Transform.h"
#include "view/View.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

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
