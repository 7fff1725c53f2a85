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
using namespace q3::api;

namespace {

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
    return setHeld(__func__, viewHints, "viewHints", renderer, "renderer", &ViewHints::setRenderer);
}

TQ3Status Q3ViewHints_GetRenderer(TQ3ViewHintsObject viewHints, TQ3RendererObject* renderer)
{
    return getHeld(__func__, viewHints, "viewHints", renderer, "renderer", &ViewHints::renderer);
}

TQ3Status Q3ViewHints_SetCamera(TQ3ViewHintsObject viewHints, TQ3CameraObject camera)
{
    return setHeld(__func__, viewHints, "viewHints", camera, "camera", &ViewHints::setCamera);
}

TQ3Status Q3ViewHints_GetCamera(TQ3ViewHintsObject viewHints, TQ3CameraObject* camera)
{
    return getHeld(__func__, viewHints, "viewHints", camera, "camera", &ViewHints::camera);
}

TQ3Status Q3ViewHints_SetLightGroup(TQ3ViewHintsObject viewHints, TQ3GroupObject lightGroup)
{
    return setHeldOptional(__func__, viewHints, "viewHints", lightGroup, "lightGroup", &ViewHints::setLightGroup);
}

TQ3Status Q3ViewHints_GetLightGroup(TQ3ViewHintsObject viewHints, TQ3GroupObject* lightGroup)
{
    return getHeld(__func__, viewHints, "viewHints", lightGroup, "lightGroup", &ViewHints::lightGroup);
}

TQ3Status Q3ViewHints_SetAttributeSet(TQ3ViewHintsObject viewHints, TQ3AttributeSet attributeSet)
{
    return setHeldOptional(__func__, viewHints, "viewHints", attributeSet, "attributeSet", &ViewHints::setAttributeSet);
}

TQ3Status Q3ViewHints_GetAttributeSet(TQ3ViewHintsObject viewHints, TQ3AttributeSet* attributeSet)
{
    return getHeld(__func__, viewHints, "viewHints", attributeSet, "attributeSet", &ViewHints::attributeSet);
}

TQ3Status Q3ViewHints_SetDimensionsState(TQ3ViewHintsObject viewHints, TQ3Boolean isValid)
{
    return guardStatus(__func__, [&] { lookup<ViewHints>(viewHints, "viewHints").setDimensionsState(isValid); });
}

TQ3Status Q3ViewHints_GetDimensionsState(TQ3ViewHintsObject viewHints, TQ3Boolean* isValid)
{
    return getValue<ViewHints>(__func__, viewHints, "viewHints", isValid, "isValid",
                               [](const ViewHints& hints) { return hints.dimensionsState(); });
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
    return getValue<ViewHints>(__func__, viewHints, "viewHints", isValid, "isValid",
                               [](const ViewHints& hints) { return hints.maskState(); });
}

TQ3Status Q3ViewHints_SetMask(TQ3ViewHintsObject viewHints, const TQ3Bitmap* mask)
{
    return setValue<ViewHints>(__func__, viewHints, "viewHints", mask, "mask", &ViewHints::setMask);
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
    return getValue<ViewHints>(__func__, viewHints, "viewHints", clearMethod, "clearMethod",
                               [](const ViewHints& hints) { return hints.clearMethod(); });
}

TQ3Status Q3ViewHints_SetClearImageColor(TQ3ViewHintsObject viewHints, const TQ3ColorARGB* color)
{
    return setValue<ViewHints>(__func__, viewHints, "viewHints", color, "color", &ViewHints::setClearColor);
}

TQ3Status Q3ViewHints_GetClearImageColor(TQ3ViewHintsObject viewHints, TQ3ColorARGB* color)
{
    return getValue<ViewHints>(__func__, viewHints, "viewHints", color, "color",
                               [](const ViewHints& hints) { return hints.clearColor(); });
}

} // extern "C"
