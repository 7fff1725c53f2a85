// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DRenderer.h"
#include "api/Entry.h"
#include "render/Renderer.h"

#include <cstring>
#include <string>

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

namespace {

using Settings = InteractiveRenderer::Settings;

// A Get of one interactive renderer setting: the handle, then the pointer.
template <class Value>
TQ3Status getSetting(const char* function, TQ3RendererObject renderer, Value* out, const char* outName,
                     Value Settings::*field)
{
    return api::getValue<InteractiveRenderer>(function, renderer, "renderer", out, outName,
                                              [&](const InteractiveRenderer& r) { return r.settings().*field; });
}

// A Set of one interactive renderer setting: the handle, then the setter.
template <class Write>
TQ3Status setSetting(const char* function, TQ3RendererObject renderer, Write write)
{
    return guardStatus(function, [&] { write(lookup<InteractiveRenderer>(renderer, "renderer")); });
}

} // namespace

// A C entry point cannot come from a template, so the Get/Set pairs of the
// interactive renderer's settings are written once as a macro that defines
// them through the templates above: Q3InteractiveRenderer_Set<Field> through
// InteractiveRenderer::set<Field>, _Get<Field> of the Settings member
// `member`, a Type called `param` in QD3DRenderer.h (the error messages name
// it as every other call does).
#define Q3_INTERACTIVE_SETTING_ENTRY_POINTS(Field, Type, param, member)                                         \
    TQ3Status Q3InteractiveRenderer_Set##Field(TQ3RendererObject renderer, Type param)                          \
    {                                                                                                           \
        return setSetting(__func__, renderer, [&](InteractiveRenderer& r) { r.set##Field(param); });            \
    }                                                                                                           \
    TQ3Status Q3InteractiveRenderer_Get##Field(TQ3RendererObject renderer, Type* param)                         \
    {                                                                                                           \
        return getSetting(__func__, renderer, param, #param, &Settings::member);                                \
    }

extern "C" {

TQ3RendererObject Q3Renderer_NewFromType(TQ3ObjectType rendererObjectType)
{
    return guard(__func__, TQ3RendererObject{nullptr}, [&]() -> TQ3RendererObject {
        return Renderer::newFromType(rendererObjectType).detach();
    });
}

TQ3ObjectType Q3Renderer_GetType(TQ3RendererObject renderer)
{
    return api::getLeafType<Renderer>(__func__, renderer, "renderer");
}

TQ3Boolean Q3Renderer_IsInteractive(TQ3RendererObject renderer)
{
    return guard(__func__, kQ3False, [&] {
        lookup<Renderer>(renderer, "renderer");
        return kQ3True; // both of Q3's renderers draw each frame at once
    });
}

TQ3Status Q3RendererClass_GetNickNameString(TQ3ObjectType rendererClassType,
                                            TQ3ObjectClassNameString rendererClassString)
{
    return guardStatus(__func__, [&] {
        const char* name = nullptr;
        if (rendererClassType == kQ3RendererTypeInteractive)
            name = "Interactive";
        else if (rendererClassType == kQ3RendererTypeWireFrame)
            name = "Wireframe";
        else
            fail(kQ3ErrorInvalidParameter, "rendererClassType " + std::to_string(rendererClassType) +
                                               " is not a renderer Q3 provides");
        requireNonNull(rendererClassString, "rendererClassString");
        std::strcpy(rendererClassString, name);
    });
}

Q3_INTERACTIVE_SETTING_ENTRY_POINTS(CSGEquation, TQ3CSGEquation, equation, csgEquation)

TQ3Status Q3InteractiveRenderer_SetPreferences(TQ3RendererObject renderer, long vendorID,
                                               long engineID)
{
    return setSetting(__func__, renderer, [&](InteractiveRenderer& r) { r.setPreferences(vendorID, engineID); });
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

Q3_INTERACTIVE_SETTING_ENTRY_POINTS(DoubleBufferBypass, TQ3Boolean, bypass, doubleBufferBypass)

Q3_INTERACTIVE_SETTING_ENTRY_POINTS(RAVEContextHints, unsigned long, RAVEContextHints, raveContextHints)

Q3_INTERACTIVE_SETTING_ENTRY_POINTS(RAVETextureFilter, unsigned long, RAVEtextureFilterValue, raveTextureFilter)

TQ3Status Q3InteractiveRenderer_CountRAVEDrawContexts(TQ3RendererObject renderer, unsigned long* numRAVEContexts)
{
    return guardStatus(__func__, [&] {
        lookup<InteractiveRenderer>(renderer, "renderer");
        requireNonNull(numRAVEContexts, "numRAVEContexts");
        *numRAVEContexts = 0; // Q3 has no RAVE
    });
}

TQ3Status Q3InteractiveRenderer_GetRAVEDrawContexts(TQ3RendererObject renderer, TQADrawContext** raveDrawContextList,
                                                    TQAEngine** raveDrawingEnginesList, unsigned long* numRAVEContexts,
                                                    TQ3RaveDestroyCallback raveDestroyCallback)
{
    return guardStatus(__func__, [&] {
        lookup<InteractiveRenderer>(renderer, "renderer");
        requireNonNull(numRAVEContexts, "numRAVEContexts");
        *numRAVEContexts = 0; // nothing to list, and nothing will be destroyed
    });
}

} // extern "C"

extern "C" {

TQ3Boolean Q3Renderer_HasModalConfigure(TQ3RendererObject renderer)
{
    return guard(__func__, kQ3False, [&] {
        lookup<Renderer>(renderer, "renderer");
        return kQ3False; // Q3's renderers have no settings dialog
    });
}

TQ3Status Q3Renderer_ModalConfigure(TQ3RendererObject renderer, TQ3DialogAnchor, TQ3Boolean* canceled)
{
    return guardStatus(__func__, [&] {
        lookup<Renderer>(renderer, "renderer");
        requireNonNull(canceled, "canceled");
        *canceled = kQ3True;
    });
}

TQ3Status Q3Renderer_GetConfigurationData(TQ3RendererObject renderer, unsigned char*, unsigned long,
                                          unsigned long* actualDataSize)
{
    return guardStatus(__func__, [&] {
        lookup<Renderer>(renderer, "renderer");
        requireNonNull(actualDataSize, "actualDataSize");
        *actualDataSize = 0;
    });
}

TQ3Status Q3Renderer_SetConfigurationData(TQ3RendererObject renderer, unsigned char* dataBuffer,
                                          unsigned long bufferSize)
{
    return guardStatus(__func__, [&] {
        lookup<Renderer>(renderer, "renderer");
        if (bufferSize > 0)
            requireNonNull(dataBuffer, "dataBuffer");
        if (bufferSize > 0)
            fail(kQ3ErrorInvalidParameter,
                 "Q3's renderers keep no configuration data, so none can be handed back (bufferSize must be 0)");
    });
}

} // extern "C"

#undef Q3_INTERACTIVE_SETTING_ENTRY_POINTS
