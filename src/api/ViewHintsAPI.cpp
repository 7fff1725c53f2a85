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

extern "C" {

TQ3ViewHintsObject Q3ViewHints_New(TQ3ViewObject view)
{
    return guard(__func__, TQ3ViewHintsObject{nullptr}, [&]() -> TQ3ViewHintsObject {
        return ViewHints::fromView(lookup<View>(view, "view")).detach();
    });
}

Q3_HELD_ENTRY_POINTS(Q3ViewHints, ViewHints, TQ3ViewHintsObject, viewHints, Renderer, TQ3RendererObject, renderer,
                     setHeld)

Q3_HELD_ENTRY_POINTS(Q3ViewHints, ViewHints, TQ3ViewHintsObject, viewHints, Camera, TQ3CameraObject, camera, setHeld)

Q3_HELD_ENTRY_POINTS(Q3ViewHints, ViewHints, TQ3ViewHintsObject, viewHints, LightGroup, TQ3GroupObject, lightGroup,
                     setHeldOptional)

Q3_HELD_ENTRY_POINTS(Q3ViewHints, ViewHints, TQ3ViewHintsObject, viewHints, AttributeSet, TQ3AttributeSet, attributeSet,
                     setHeldOptional)

TQ3Status Q3ViewHints_SetDimensionsState(TQ3ViewHintsObject viewHints, TQ3Boolean isValid)
{
    return setDirect<ViewHints>(__func__, viewHints, "viewHints", isValid, &ViewHints::setDimensionsState);
}

TQ3Status Q3ViewHints_GetDimensionsState(TQ3ViewHintsObject viewHints, TQ3Boolean* isValid)
{
    return getValue<ViewHints>(__func__, viewHints, "viewHints", isValid, "isValid", &ViewHints::dimensionsState);
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
    return setDirect<ViewHints>(__func__, viewHints, "viewHints", isValid, &ViewHints::setMaskState);
}

TQ3Status Q3ViewHints_GetMaskState(TQ3ViewHintsObject viewHints, TQ3Boolean* isValid)
{
    return getValue<ViewHints>(__func__, viewHints, "viewHints", isValid, "isValid", &ViewHints::maskState);
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

TQ3Status Q3ViewHints_SetClearImageColor(TQ3ViewHintsObject viewHints, const TQ3ColorARGB* color)
{
    return setValue<ViewHints>(__func__, viewHints, "viewHints", color, "color", &ViewHints::setClearColor);
}

TQ3Status Q3ViewHints_GetClearImageColor(TQ3ViewHintsObject viewHints, TQ3ColorARGB* color)
{
    return getValue<ViewHints>(__func__, viewHints, "viewHints", color, "color", &ViewHints::clearColor);
}

TQ3Status Q3ViewHints_SetClearImageMethod(TQ3ViewHintsObject viewHints, TQ3DrawContextClearImageMethod clearMethod)
{
    return setDirect<ViewHints>(__func__, viewHints, "viewHints", clearMethod, &ViewHints::setClearMethod);
}

TQ3Status Q3ViewHints_GetClearImageMethod(TQ3ViewHintsObject viewHints, TQ3DrawContextClearImageMethod* clearMethod)
{
    return getValue<ViewHints>(__func__, viewHints, "viewHints", clearMethod, "clearMethod", &ViewHints::clearMethod);
}

} // extern "C"
