// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DView.h"
#include "api/Entry.h"
#include "render/Renderer.h"
#include "view/Camera.h"
#include "view/DrawContext.h"
#include "view/View.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

namespace {

// A new reference for the caller, or NULL when the view holds none.
template <class T>
TQ3Object handOut(const Ref<T>& held)
{
    return Ref<T>(held).detach();
}

} // namespace

extern "C" {

TQ3ViewObject Q3View_New(void)
{
    return guard(__func__, TQ3ViewObject{nullptr},
                 []() -> TQ3ViewObject { return makeObject<View>(); });
}

TQ3Status Q3View_Cancel(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").cancel(); });
}

TQ3Status Q3View_SetRendererByType(TQ3ViewObject view, TQ3ObjectType theType)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").setRendererByType(theType); });
}

TQ3Status Q3View_SetRenderer(TQ3ViewObject view, TQ3RendererObject renderer)
{
    return guardStatus(__func__, [&] {
        View& target = lookup<View>(view, "view");
        target.setRenderer(lookupRef<Renderer>(renderer, "renderer"));
    });
}

TQ3Status Q3View_GetRenderer(TQ3ViewObject view, TQ3RendererObject* renderer)
{
    return guardStatus(__func__, [&] {
        const View& source = lookup<View>(view, "view");
        requireNonNull(renderer, "renderer");
        *renderer = handOut(source.renderer());
    });
}

TQ3Status Q3View_StartRendering(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").startRendering(); });
}

TQ3ViewStatus Q3View_EndRendering(TQ3ViewObject view)
{
    return guard(__func__, kQ3ViewStatusError, [&] { return lookup<View>(view, "view").endRendering(); });
}

TQ3Status Q3View_Sync(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").sync(); });
}

TQ3Status Q3View_StartBoundingBox(TQ3ViewObject view, TQ3ComputeBounds computeBounds)
{
    return guardStatus(__func__,
                       [&] { lookup<View>(view, "view").startBoundingBox(computeBounds); });
}

TQ3ViewStatus Q3View_EndBoundingBox(TQ3ViewObject view, TQ3BoundingBox* result)
{
    return guard(__func__, kQ3ViewStatusError, [&] {
        View& target = lookup<View>(view, "view");
        requireNonNull(result, "result");
        return target.endBoundingBox(*result);
    });
}

TQ3Status Q3View_StartBoundingSphere(TQ3ViewObject view, TQ3ComputeBounds computeBounds)
{
    return guardStatus(__func__,
                       [&] { lookup<View>(view, "view").startBoundingSphere(computeBounds); });
}

TQ3ViewStatus Q3View_EndBoundingSphere(TQ3ViewObject view, TQ3BoundingSphere* result)
{
    return guard(__func__, kQ3ViewStatusError, [&] {
        View& target = lookup<View>(view, "view");
        requireNonNull(result, "result");
        return target.endBoundingSphere(*result);
    });
}

TQ3Status Q3View_GetCamera(TQ3ViewObject view, TQ3CameraObject* camera)
{
    return guardStatus(__func__, [&] {
        const View& source = lookup<View>(view, "view");
        requireNonNull(camera, "camera");
        *camera = handOut(source.camera());
    });
}

TQ3Status Q3View_SetCamera(TQ3ViewObject view, TQ3CameraObject camera)
{
    return guardStatus(__func__, [&] {
        View& target = lookup<View>(view, "view");
        target.setCamera(lookupRef<Camera>(camera, "camera"));
    });
}

TQ3Status Q3View_SetDrawContext(TQ3ViewObject view, TQ3DrawContextObject drawContext)
{
    return guardStatus(__func__, [&] {
        View& target = lookup<View>(view, "view");
        target.setDrawContext(lookupRef<DrawContext>(drawContext, "drawContext"));
    });
}

TQ3Status Q3View_GetDrawContext(TQ3ViewObject view, TQ3DrawContextObject* drawContext)
{
    return guardStatus(__func__, [&] {
        const View& source = lookup<View>(view, "view");
        requireNonNull(drawContext, "drawContext");
        *drawContext = handOut(source.drawContext());
    });
}

TQ3Status Q3View_GetLocalToWorldMatrixState(TQ3ViewObject view, TQ3Matrix4x4* matrix)
{
    return guardStatus(__func__, [&] {
        View& source = lookup<View>(view, "view");
        requireNonNull(matrix, "matrix");
        *matrix = source.localToWorldState();
    });
}

TQ3Status Q3View_GetSubdivisionStyleState(TQ3ViewObject view,
                                          TQ3SubdivisionStyleData* subdivisionStyle)
{
    return guardStatus(__func__, [&] {
        View& source = lookup<View>(view, "view");
        requireNonNull(subdivisionStyle, "subdivisionStyle");
        *subdivisionStyle = source.subdivisionStyleState();
    });
}

TQ3Status Q3Push_Submit(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").push(); });
}

TQ3Status Q3Pop_Submit(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").pop(); });
}

} // extern "C"
