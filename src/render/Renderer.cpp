// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "render/Renderer.h"

#include "core/EnumValue.h"

#include <string>

namespace q3 {

const ClassInfo kRendererClass{kQ3SharedTypeRenderer, &kSharedClass, "renderer"};
const ClassInfo kWireFrameRendererClass{kQ3RendererTypeWireFrame, &kRendererClass,
                                        "wireframe renderer"};
const ClassInfo kInteractiveRendererClass{kQ3RendererTypeInteractive, &kRendererClass,
                                          "interactive renderer"};

Ref<Renderer> Renderer::newFromType(TQ3ObjectType type)
{
    switch (type) {
    case kQ3RendererTypeWireFrame:
        return makeShared<WireFrameRenderer>();
    case kQ3RendererTypeInteractive:
        return makeShared<InteractiveRenderer>();
    default:
        fail(kQ3ErrorInvalidObjectType,
             "type " + std::to_string(type) +
                 " is not a renderer Q3 provides (kQ3RendererTypeWireFrame, kQ3RendererTypeInteractive)");
    }
}

Object* WireFrameRenderer::duplicate() const
{
    return makeShared<WireFrameRenderer>().detach();
}

Object* InteractiveRenderer::duplicate() const
{
    Ref<InteractiveRenderer> copy = makeShared<InteractiveRenderer>();
    copy->m_settings = m_settings;
    return copy.detach();
}

void InteractiveRenderer::setCSGEquation(TQ3CSGEquation equation)
{
    m_settings.csgEquation = equation;
    markEdited();
}

void InteractiveRenderer::setPreferences(long vendorID, long engineID)
{
    m_settings.vendorID = vendorID;
    m_settings.engineID = engineID;
    markEdited();
}

void InteractiveRenderer::setDoubleBufferBypass(const TQ3Boolean& bypass)
{
    m_settings.doubleBufferBypass = enumValue(bypass) != kQ3False ? kQ3True : kQ3False;
    markEdited();
}

void InteractiveRenderer::setRAVEContextHints(unsigned long hints)
{
    m_settings.raveContextHints = hints;
    markEdited();
}

TextureFilter InteractiveRenderer::textureFilter() const
{
    // RAVE's kQATextureFilter_Fast, _Mid and _Best (RAVE.h).
    switch (m_settings.raveTextureFilter) {
    case 1:
        return TextureFilter::kBilinear;
    case 2:
        return TextureFilter::kTrilinear;
    default:
        return TextureFilter::kNearest;
    }
}

void InteractiveRenderer::setRAVETextureFilter(unsigned long filter)
{
    m_settings.raveTextureFilter = filter;
    markEdited();
}

} // namespace q3
