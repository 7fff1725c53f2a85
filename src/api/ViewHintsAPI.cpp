// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DIO.h"
#include "api/Entry.h"
#include "core/AttributeSet.h"
#include "group/Group.h"
#include "render/Renderer.h"
#include "view/Camera.h"
#include "view/View.h"
#include "view/ViewHints.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;
using q3::api::readInto;

namespace {

// A new reference for the caller, or NULL when the hints hold none.
template <class T>
TQ3Object handOut(const Ref<T>& held)
{
    return Ref<T>(held).detach();
}

} // namespace

extern "C" {

TQ3ViewHintsObject Q3ViewHints_New(TQ3ViewObject view)
{
    return guard(__func__, TQ3ViewHintsObject{nullptr}, [&]() -> TQ3ViewHintsObject {
        return ViewHints::fromView(lookup<View>(view, "view")).detach();
    });
}

TQ3Status Q3ViewHints_SetRenderer(TQ3ViewHintsObject viewHints, TQ3RendererObject renderer)
{
    return guardStatus(__func__, [&] {
        ViewHints& target = lookup<ViewHints>(viewHints, "viewHints");
        target.setRenderer(lookupRef<Renderer>(renderer, "renderer"));
    });
}

TQ3Status Q3ViewHints_GetRenderer(TQ3ViewHintsObject viewHints, TQ3RendererObject* renderer)
{
    return guardStatus(__func__, [&] {
        readInto<ViewHints>(viewHints, "viewHints", renderer, "renderer",
                            [](const ViewHints& hints) { return handOut(hints.renderer()); });
    });
}

TQ3Status Q3ViewHints_SetCamera(TQ3ViewHintsObject viewHints, TQ3CameraObject camera)
{
    return guardStatus(__func__, [&] {
        ViewHints& target = lookup<ViewHints>(viewHints, "viewHints");
        target.setCamera(lookupRef<Camera>(camera, "camera"));
    });
}

TQ3Status Q3ViewHints_GetCamera(TQ3ViewHintsObject viewHints, TQ3CameraObject* camera)
{
    return guardStatus(__func__, [&] {
        readInto<ViewHints>(viewHints, "viewHints", camera, "camera",
                            [](const ViewHints& hints) { return handOut(hints.camera()); });
    });
}

TQ3Status Q3ViewHints_SetLightGroup(TQ3ViewHintsObject viewHints, TQ3GroupObject lightGroup)
{
    return guardStatus(__func__, [&] {
        ViewHints& target = lookup<ViewHints>(viewHints, "viewHints");
        target.setLightGroup(Ref<Group>::retain(lookupOptional<Group>(lightGroup, "lightGroup")));
    });
}

TQ3Status Q3ViewHints_GetLightGroup(TQ3ViewHintsObject viewHints, TQ3GroupObject* lightGroup)
{
    return guardStatus(__func__, [&] {
        readInto<ViewHints>(viewHints, "viewHints", lightGroup, "lightGroup",
                            [](const ViewHints& hints) { return handOut(hints.lightGroup()); });
    });
}

TQ3Status Q3ViewHints_SetAttributeSet(TQ3ViewHintsObject viewHints, TQ3AttributeSet attributeSet)
{
    return guardStatus(__func__, [&] {
        ViewHints& target = lookup<ViewHints>(viewHints, "viewHints");
        target.setAttributeSet(Ref<AttributeSet>::retain(lookupOptional<AttributeSet>(attributeSet, "attributeSet")));
    });
}

TQ3Status Q3ViewHints_GetAttributeSet(TQ3ViewHintsObject viewHints, TQ3AttributeSet* attributeSet)
{
    return guardStatus(__func__, [&] {
        readInto<ViewHints>(viewHints, "viewHints", attributeSet, "attributeSet",
                            [](const ViewHints& hints) { return handOut(hints.attributeSet()); });
    });
}

TQ3Status Q3ViewHints_SetDimensionsState(TQ3ViewHintsObject viewHints, TQ3Boolean isValid)
{
    return guardStatus(__func__, [&] { lookup<ViewHints>(viewHints, "viewHints").setDimensionsState(isValid); });
}

TQ3Status Q3ViewHints_GetDimensionsState(TQ3ViewHintsObject viewHints, TQ3Boolean* isValid)
{
    return guardStatus(__func__, [&] {
        readInto<ViewHints>(viewHints, "viewHints", isValid, "isValid",
                            [](const ViewHints& hints) { return hints.dimensionsState(); });
    });
}

TQ3Status Q3ViewHints_SetDimensions(TQ3ViewHintsObject viewHints, unsigned long width, unsigned long height)
{
    return guardStatus(__func__, [&] { lookup<ViewHints>(viewHints, "viewHints").setDimensions(width, height); });
}

TQ3Status Q3ViewHints_GetDimensions(TQ3ViewHintsObject viewHints, unsigned long* width, unsigned long* height)
{
    return guardStatus(__func__, [&] {
        const ViewHints& source = lookup<ViewHints>(viewHints, "viewHints");
        requireNonNull(width, "width");
        requireNonNull(height, "height");
        *width = source.width();
        *height = source.height();
    });
}

TQ3Status Q3ViewHints_SetMaskState(TQ3ViewHintsObject viewHints, TQ3Boolean isValid)
{
    return guardStatus(__func__, [&] { lookup<ViewHints>(viewHints, "viewHints").setMaskState(isValid); });
}

TQ3Status Q3ViewHints_GetMaskState(TQ3ViewHintsObject viewHints, TQ3Boolean* isValid)
{
    return guardStatus(__func__, [&] {
        readInto<ViewHints>(viewHints, "viewHints", isValid, "isValid",
                            [](const ViewHints& hints) { return hints.maskState(); });
    });
}

TQ3Status Q3ViewHints_SetMask(TQ3ViewHintsObject viewHints, const TQ3Bitmap* mask)
{
    return guardStatus(__func__, [&] {
        ViewHints& target = lookup<ViewHints>(viewHints, "viewHints");
        requireNonNull(mask, "mask");
        target.setMask(*mask);
    });
}

TQ3Status Q3ViewHints_GetMask(TQ3ViewHintsObject viewHints, TQ3Bitmap* mask)
{
    return guardStatus(__func__, [&] {
        const ViewHints& source = lookup<ViewHints>(viewHints, "viewHints");
        requireNonNull(mask, "mask");
        source.copyMask(*mask);
    });
}

TQ3Status Q3ViewHints_SetClearImageMethod(TQ3ViewHintsObject viewHints, TQ3DrawContextClearImageMethod clearMethod)
{
    return guardStatus(__func__, [&] { lookup<ViewHints>(viewHints, "viewHints").setClearMethod(clearMethod); });
}

TQ3Status Q3ViewHints_GetClearImageMethod(TQ3ViewHintsObject viewHints, TQ3DrawContextClearImageMethod* clearMethod)
{
    return guardStatus(__func__, [&] {
        readInto<ViewHints>(viewHints, "viewHints", clearMethod, "clearMethod",
                            [](const ViewHints& hints) { return hints.clearMethod(); });
    });
}

TQ3Status Q3ViewHints_SetClearImageColor(TQ3ViewHintsObject viewHints, const TQ3ColorARGB* color)
{
    return guardStatus(__func__, [&] {
        ViewHints& target = lookup<ViewHints>(viewHints, "viewHints");
        requireNonNull(color, "color");
        target.setClearColor(*color);
    });
}

TQ3Status Q3ViewHints_GetClearImageColor(TQ3ViewHintsObject viewHints, TQ3ColorARGB* color)
{
    return guardStatus(__func__, [&] {
        readInto<ViewHints>(viewHints, "viewHints", color, "color",
                            [](const ViewHints& hints) { return hints.clearColor(); });
    });
}

} // extern "C"
