// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DDrawContext.h"
#include "api/Entry.h"
#include "view/DrawContext.h"

using namespace q3;
using namespace q3::api;

// A C entry point cannot come from a template, so each family of entry points
// below is written once as a macro that defines them through api/Entry.h's
// templates; the parameter names are QD3DDrawContext.h's, so the error
// messages name them as every other call does.

/// Q3DrawContext_Set<Field> and _Get<Field> of the member `member` of
/// TQ3DrawContextData, a Type given through a pointer (called `param`) and set
/// through DrawContext::set<Field>.
#define Q3_DRAW_CONTEXT_MEMBER_ENTRY_POINTS(Field, Type, param, member)                                         \
    TQ3Status Q3DrawContext_Set##Field(TQ3DrawContextObject context, const Type* param)                         \
    {                                                                                                           \
        return setValue<DrawContext>(__func__, context, "context", param, #param, &DrawContext::set##Field);    \
    }                                                                                                           \
    TQ3Status Q3DrawContext_Get##Field(TQ3DrawContextObject context, Type* param)                               \
    {                                                                                                           \
        return getValue<DrawContext>(__func__, context, "context", param, #param,                               \
                                     [&](const DrawContext& source) -> const Type& {                            \
                                         return source.data().member;                                           \
                                     });                                                                        \
    }

/// The same for a TQ3Boolean state given by value, called `state`.
#define Q3_DRAW_CONTEXT_STATE_ENTRY_POINTS(Field, member)                                                       \
    TQ3Status Q3DrawContext_Set##Field(TQ3DrawContextObject context, TQ3Boolean state)                          \
    {                                                                                                           \
        return setDirect<DrawContext>(__func__, context, "context", state, &DrawContext::set##Field);           \
    }                                                                                                           \
    TQ3Status Q3DrawContext_Get##Field(TQ3DrawContextObject context, TQ3Boolean* state)                         \
    {                                                                                                           \
        return getValue<DrawContext>(__func__, context, "context", state, "state",                              \
                                     [&](const DrawContext& source) { return source.data().member; });          \
    }

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

Q3_DRAW_CONTEXT_MEMBER_ENTRY_POINTS(ClearImageColor, TQ3ColorARGB, color, clearImageColor)
Q3_DRAW_CONTEXT_MEMBER_ENTRY_POINTS(Pane, TQ3Area, pane, pane)
Q3_DRAW_CONTEXT_STATE_ENTRY_POINTS(PaneState, paneState)

TQ3Status Q3DrawContext_SetClearImageMethod(TQ3DrawContextObject context, TQ3DrawContextClearImageMethod method)
{
    return setDirect<DrawContext>(__func__, context, "context", method, &DrawContext::setClearImageMethod);
}

TQ3Status Q3DrawContext_GetClearImageMethod(TQ3DrawContextObject context, TQ3DrawContextClearImageMethod* method)
{
    return getValue<DrawContext>(__func__, context, "context", method, "method",
                                 [&](const DrawContext& source) { return source.data().clearImageMethod; });
}

Q3_DRAW_CONTEXT_MEMBER_ENTRY_POINTS(Mask, TQ3Bitmap, mask, mask)
Q3_DRAW_CONTEXT_STATE_ENTRY_POINTS(MaskState, maskState)
Q3_DRAW_CONTEXT_STATE_ENTRY_POINTS(DoubleBufferState, doubleBufferState)

TQ3DrawContextObject Q3PixmapDrawContext_New(const TQ3PixmapDrawContextData* contextData)
{
    return guard(__func__, TQ3DrawContextObject{nullptr}, [&]() -> TQ3DrawContextObject {
        requireNonNull(contextData, "contextData");
        PixmapDrawContext::validate(*contextData);
        return makeShared<PixmapDrawContext>(*contextData).detach();
    });
}

Q3_POINTER_VALUE_ENTRY_POINTS(Q3PixmapDrawContext, PixmapDrawContext, TQ3DrawContextObject, drawContext, Pixmap,
                              TQ3Pixmap, pixmap)

} // extern "C"

#undef Q3_DRAW_CONTEXT_MEMBER_ENTRY_POINTS
#undef Q3_DRAW_CONTEXT_STATE_ENTRY_POINTS
