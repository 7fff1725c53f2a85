// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DDrawContext.h"
#include "api/Entry.h"
#include "view/DrawContext.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3ObjectType Q3DrawContext_GetType(TQ3DrawContextObject drawContext)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookup<DrawContext>(drawContext, "drawContext").leafType(); });
}

TQ3Status Q3DrawContext_SetData(TQ3DrawContextObject context, const TQ3DrawContextData* contextData)
{
    return guardStatus(__func__, [&] {
        DrawContext& target = lookup<DrawContext>(context, "context");
        requireNonNull(contextData, "contextData");
        target.setData(*contextData);
    });
}

TQ3Status Q3DrawContext_GetData(TQ3DrawContextObject context, TQ3DrawContextData* contextData)
{
    return guardStatus(__func__, [&] {
        const DrawContext& source = lookup<DrawContext>(context, "context");
        requireNonNull(contextData, "contextData");
        *contextData = source.data();
    });
}

TQ3Status Q3DrawContext_SetClearImageColor(TQ3DrawContextObject context, const TQ3ColorARGB* color)
{
    return guardStatus(__func__, [&] {
        DrawContext& target = lookup<DrawContext>(context, "context");
        requireNonNull(color, "color");
        target.setClearImageColor(*color);
    });
}

TQ3Status Q3DrawContext_GetClearImageColor(TQ3DrawContextObject context, TQ3ColorARGB* color)
{
    return guardStatus(__func__, [&] {
        const DrawContext& source = lookup<DrawContext>(context, "context");
        requireNonNull(color, "color");
        *color = source.data().clearImageColor;
    });
}

TQ3Status Q3DrawContext_SetPane(TQ3DrawContextObject context, const TQ3Area* pane)
{
    return guardStatus(__func__, [&] {
        DrawContext& target = lookup<DrawContext>(context, "context");
        requireNonNull(pane, "pane");
        target.setPane(*pane);
    });
}

TQ3Status Q3DrawContext_GetPane(TQ3DrawContextObject context, TQ3Area* pane)
{
    return guardStatus(__func__, [&] {
        const DrawContext& source = lookup<DrawContext>(context, "context");
        requireNonNull(pane, "pane");
        *pane = source.data().pane;
    });
}

TQ3Status Q3DrawContext_SetPaneState(TQ3DrawContextObject context, TQ3Boolean state)
{
    return guardStatus(__func__,
                       [&] { lookup<DrawContext>(context, "context").setPaneState(state); });
}

TQ3Status Q3DrawContext_GetPaneState(TQ3DrawContextObject context, TQ3Boolean* state)
{
    return guardStatus(__func__, [&] {
        const DrawContext& source = lookup<DrawContext>(context, "context");
        requireNonNull(state, "state");
        *state = source.data().paneState;
    });
}

TQ3Status Q3DrawContext_SetClearImageMethod(TQ3DrawContextObject context,
                                            TQ3DrawContextClearImageMethod method)
{
    return guardStatus(__func__,
                       [&] { lookup<DrawContext>(context, "context").setClearImageMethod(method); });
}

TQ3Status Q3DrawContext_GetClearImageMethod(TQ3DrawContextObject context,
                                            TQ3DrawContextClearImageMethod* method)
{
    return guardStatus(__func__, [&] {
        const DrawContext& source = lookup<DrawContext>(context, "context");
        requireNonNull(method, "method");
        *method = source.data().clearImageMethod;
    });
}

TQ3Status Q3DrawContext_SetMask(TQ3DrawContextObject context, const TQ3Bitmap* mask)
{
    return guardStatus(__func__, [&] {
        DrawContext& target = lookup<DrawContext>(context, "context");
        requireNonNull(mask, "mask");
        target.setMask(*mask);
    });
}

TQ3Status Q3DrawContext_GetMask(TQ3DrawContextObject context, TQ3Bitmap* mask)
{
    return guardStatus(__func__, [&] {
        const DrawContext& source = lookup<DrawContext>(context, "context");
        requireNonNull(mask, "mask");
        *mask = source.data().mask;
    });
}

TQ3Status Q3DrawContext_SetMaskState(TQ3DrawContextObject context, TQ3Boolean state)
{
    return guardStatus(__func__, [&] { lookup<DrawContext>(context, "context").setMaskState(state); });
}

TQ3Status Q3DrawContext_GetMaskState(TQ3DrawContextObject context, TQ3Boolean* state)
{
    return guardStatus(__func__, [&] {
        const DrawContext& source = lookup<DrawContext>(context, "context");
        requireNonNull(state, "state");
        *state = source.data().maskState;
    });
}

TQ3Status Q3DrawContext_SetDoubleBufferState(TQ3DrawContextObject context, TQ3Boolean state)
{
    return guardStatus(__func__,
                       [&] { lookup<DrawContext>(context, "context").setDoubleBufferState(state); });
}

TQ3Status Q3DrawContext_GetDoubleBufferState(TQ3DrawContextObject context, TQ3Boolean* state)
{
    return guardStatus(__func__, [&] {
        const DrawContext& source = lookup<DrawContext>(context, "context");
        requireNonNull(state, "state");
        *state = source.data().doubleBufferState;
    });
}

TQ3DrawContextObject Q3PixmapDrawContext_New(const TQ3PixmapDrawContextData* contextData)
{
    return guard(__func__, TQ3DrawContextObject{nullptr}, [&]() -> TQ3DrawContextObject {
        requireNonNull(contextData, "contextData");
        PixmapDrawContext::validate(*contextData);
        return makeShared<PixmapDrawContext>(*contextData).detach();
    });
}

TQ3Status Q3PixmapDrawContext_SetPixmap(TQ3DrawContextObject drawContext, const TQ3Pixmap* pixmap)
{
    return guardStatus(__func__, [&] {
        PixmapDrawContext& target = lookup<PixmapDrawContext>(drawContext, "drawContext");
        requireNonNull(pixmap, "pixmap");
        target.setPixmap(*pixmap);
    });
}

TQ3Status Q3PixmapDrawContext_GetPixmap(TQ3DrawContextObject drawContext, TQ3Pixmap* pixmap)
{
    return guardStatus(__func__, [&] {
        const PixmapDrawContext& source = lookup<PixmapDrawContext>(drawContext, "drawContext");
        requireNonNull(pixmap, "pixmap");
        *pixmap = source.pixmap();
    });
}

} // extern "C"
