// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DDrawContext.h"
#include "api/Entry.h"
#include "view/DrawContext.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3ObjectType Q3DrawContext_GetType(TQ3DrawContextObject drawContext)
{
    return api::getLeafType<DrawContext>(__func__, drawContext, "drawContext");
}

TQ3Status Q3DrawContext_SetData(TQ3DrawContextObject context, const TQ3DrawContextData* contextData)
{
    return setValue<DrawContext>(__func__, context, "context", contextData, "contextData", &DrawContext::setData);
}

TQ3Status Q3DrawContext_GetData(TQ3DrawContextObject context, TQ3DrawContextData* contextData)
{
    return getValue<DrawContext>(__func__, context, "context", contextData, "contextData", &DrawContext::data);
}

TQ3Status Q3DrawContext_SetClearImageColor(TQ3DrawContextObject context, const TQ3ColorARGB* color)
{
    return setValue<DrawContext>(__func__, context, "context", color, "color", &DrawContext::setClearImageColor);
}

TQ3Status Q3DrawContext_GetClearImageColor(TQ3DrawContextObject context, TQ3ColorARGB* color)
{
    return getValue<DrawContext>(__func__, context, "context", color, "color",
                                 [&](const DrawContext& source) { return source.data().clearImageColor; });
}

TQ3Status Q3DrawContext_SetPane(TQ3DrawContextObject context, const TQ3Area* pane)
{
    return setValue<DrawContext>(__func__, context, "context", pane, "pane", &DrawContext::setPane);
}

TQ3Status Q3DrawContext_GetPane(TQ3DrawContextObject context, TQ3Area* pane)
{
    return getValue<DrawContext>(__func__, context, "context", pane, "pane",
                                 [&](const DrawContext& source) { return source.data().pane; });
}

TQ3Status Q3DrawContext_SetPaneState(TQ3DrawContextObject context, TQ3Boolean state)
{
    return guardStatus(__func__,
                       [&] { lookup<DrawContext>(context, "context").setPaneState(state); });
}

TQ3Status Q3DrawContext_GetPaneState(TQ3DrawContextObject context, TQ3Boolean* state)
{
    return getValue<DrawContext>(__func__, context, "context", state, "state",
                                 [&](const DrawContext& source) { return source.data().paneState; });
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
    return getValue<DrawContext>(__func__, context, "context", method, "method",
                                 [&](const DrawContext& source) { return source.data().clearImageMethod; });
}

TQ3Status Q3DrawContext_SetMask(TQ3DrawContextObject context, const TQ3Bitmap* mask)
{
    return setValue<DrawContext>(__func__, context, "context", mask, "mask", &DrawContext::setMask);
}

TQ3Status Q3DrawContext_GetMask(TQ3DrawContextObject context, TQ3Bitmap* mask)
{
    return getValue<DrawContext>(__func__, context, "context", mask, "mask",
                                 [&](const DrawContext& source) -> const TQ3Bitmap& { return source.data().mask; });
}

TQ3Status Q3DrawContext_SetMaskState(TQ3DrawContextObject context, TQ3Boolean state)
{
    return guardStatus(__func__, [&] { lookup<DrawContext>(context, "context").setMaskState(state); });
}

TQ3Status Q3DrawContext_GetMaskState(TQ3DrawContextObject context, TQ3Boolean* state)
{
    return getValue<DrawContext>(__func__, context, "context", state, "state",
                                 [&](const DrawContext& source) { return source.data().maskState; });
}

TQ3Status Q3DrawContext_SetDoubleBufferState(TQ3DrawContextObject context, TQ3Boolean state)
{
    return guardStatus(__func__,
                       [&] { lookup<DrawContext>(context, "context").setDoubleBufferState(state); });
}

TQ3Status Q3DrawContext_GetDoubleBufferState(TQ3DrawContextObject context, TQ3Boolean* state)
{
    return getValue<DrawContext>(__func__, context, "context", state, "state",
                                 [&](const DrawContext& source) { return source.data().doubleBufferState; });
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
    return setValue<PixmapDrawContext>(__func__, drawContext, "drawContext", pixmap, "pixmap",
                                       &PixmapDrawContext::setPixmap);
}

TQ3Status Q3PixmapDrawContext_GetPixmap(TQ3DrawContextObject drawContext, TQ3Pixmap* pixmap)
{
    return getValue<PixmapDrawContext>(__func__, drawContext, "drawContext", pixmap, "pixmap",
                                       &PixmapDrawContext::pixmap);
}

} // extern "C"
