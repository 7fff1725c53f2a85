// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DRenderer.h"
#include "api/Entry.h"
#include "render/Renderer.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3RendererObject Q3Renderer_NewFromType(TQ3ObjectType rendererObjectType)
{
    return guard(__func__, TQ3RendererObject{nullptr}, [&]() -> TQ3RendererObject {
        return Renderer::newFromType(rendererObjectType).detach();
    });
}

TQ3ObjectType Q3Renderer_GetType(TQ3RendererObject renderer)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookup<Renderer>(renderer, "renderer").leafType(); });
}

TQ3Status Q3InteractiveRenderer_SetCSGEquation(TQ3RendererObject renderer, TQ3CSGEquation equation)
{
    return guardStatus(__func__, [&] {
        lookup<InteractiveRenderer>(renderer, "renderer").setCSGEquation(equation);
    });
}

TQ3Status Q3InteractiveRenderer_GetCSGEquation(TQ3RendererObject renderer, TQ3CSGEquation* equation)
{
    return guardStatus(__func__, [&] {
        const InteractiveRenderer& source = lookup<InteractiveRenderer>(renderer, "renderer");
        requireNonNull(equation, "equation");
        *equation = source.settings().csgEquation;
    });
}

TQ3Status Q3InteractiveRenderer_SetPreferences(TQ3RendererObject renderer, long vendorID,
                                               long engineID)
{
    return guardStatus(__func__, [&] {
        lookup<InteractiveRenderer>(renderer, "renderer").setPreferences(vendorID, engineID);
    });
}

TQ3Status Q3InteractiveRenderer_GetPreferences(TQ3RendererObject renderer, long* vendorID,
                                               long* engineID)
{
    return guardStatus(__func__, [&] {
        const InteractiveRenderer& source = lookup<InteractiveRenderer>(renderer, "renderer");
        requireNonNull(vendorID, "vendorID");
        requireNonNull(engineID, "engineID");
        *vendorID = source.settings().vendorID;
        *engineID = source.settings().engineID;
    });
}

TQ3Status Q3InteractiveRenderer_SetDoubleBufferBypass(TQ3RendererObject renderer, TQ3Boolean bypass)
{
    return guardStatus(__func__, [&] {
        lookup<InteractiveRenderer>(renderer, "renderer").setDoubleBufferBypass(bypass);
    });
}

TQ3Status Q3InteractiveRenderer_GetDoubleBufferBypass(TQ3RendererObject renderer, TQ3Boolean* bypass)
{
    return guardStatus(__func__, [&] {
        const InteractiveRenderer& source = lookup<InteractiveRenderer>(renderer, "renderer");
        requireNonNull(bypass, "bypass");
        *bypass = source.settings().doubleBufferBypass;
    });
}

TQ3Status Q3InteractiveRenderer_SetRAVEContextHints(TQ3RendererObject renderer,
                                                    unsigned long RAVEContextHints)
{
    return guardStatus(__func__, [&] {
        lookup<InteractiveRenderer>(renderer, "renderer").setRAVEContextHints(RAVEContextHints);
    });
}

TQ3Status Q3InteractiveRenderer_GetRAVEContextHints(TQ3RendererObject renderer,
                                                    unsigned long* RAVEContextHints)
{
    return guardStatus(__func__, [&] {
        const InteractiveRenderer& source = lookup<InteractiveRenderer>(renderer, "renderer");
        requireNonNull(RAVEContextHints, "RAVEContextHints");
        *RAVEContextHints = source.settings().raveContextHints;
    });
}

TQ3Status Q3InteractiveRenderer_SetRAVETextureFilter(TQ3RendererObject renderer,
                                                     unsigned long RAVEtextureFilterValue)
{
    return guardStatus(__func__, [&] {
        lookup<InteractiveRenderer>(renderer, "renderer").setRAVETextureFilter(RAVEtextureFilterValue);
    });
}

TQ3Status Q3InteractiveRenderer_GetRAVETextureFilter(TQ3RendererObject renderer,
                                                     unsigned long* RAVEtextureFilterValue)
{
    return guardStatus(__func__, [&] {
        const InteractiveRenderer& source = lookup<InteractiveRenderer>(renderer, "renderer");
        requireNonNull(RAVEtextureFilterValue, "RAVEtextureFilterValue");
        *RAVEtextureFilterValue = source.settings().raveTextureFilter;
    });
}

} // extern "C"
