// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "Q3GLDrawContext.h"
#include "api/Entry.h"
#include "view/GLDrawContext.h"

// Q3 extension: the draw context of the application's own OpenGL context.

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3DrawContextObject Q3GLDrawContext_New(const TQ3GLDrawContextData* contextData)
{
    return guard(__func__, TQ3DrawContextObject{nullptr}, [&] {
        requireNonNull(contextData, "contextData");
        GLDrawContext::validate(*contextData);
        return makeShared<GLDrawContext>(*contextData).detach();
    });
}

TQ3Status Q3GLDrawContext_SetSize(TQ3DrawContextObject drawContext, TQ3Uns32 width, TQ3Uns32 height)
{
    return guardStatus(__func__,
                       [&] { lookup<GLDrawContext>(drawContext, "drawContext").setSize(width, height); });
}

TQ3Status Q3GLDrawContext_GetSize(TQ3DrawContextObject drawContext, TQ3Uns32* width, TQ3Uns32* height)
{
    return guardStatus(__func__, [&] {
        const GLDrawContext& source = lookup<GLDrawContext>(drawContext, "drawContext");
        requireNonNull(width, "width");
        requireNonNull(height, "height");
        *width = source.width();
        *height = source.height();
    });
}

} // extern "C"
