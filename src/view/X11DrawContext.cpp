// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/X11DrawContext.h"

#include "core/Error.h"

#include <string>

namespace q3 {

const ClassInfo kX11DrawContextClass{kQ3DrawContextTypeX11, &kDrawContextClass, "X11 draw context"};

namespace {

// A visual Q3 can put pixels through: TrueColor (its pixel values are the
// colour channels under the masks; other classes need a colormap Q3 would
// have to fill).
bool usableVisual(const Visual* visual)
{
    return visual == nullptr || visual->c_class == TrueColor;
}

void checkWindow(Display* display, Drawable drawable)
{
    std::uint32_t width = 0, height = 0;
    const RenderResult result = windowSize(NativeWindow{display, drawable}, width, height);
    if (!result)
        fail(kQ3ErrorX11Error, "drawable " + std::to_string(drawable) + ": " + result.message);
}

} // namespace

void X11DrawContext::validate(const TQ3XDrawContextData& data)
{
    validateDrawContextData(data.contextData);
    if (data.display == nullptr)
        fail(kQ3ErrorNULLParameter, "xContextData->display is NULL");
    if (!usableVisual(data.visual))
        fail(kQ3ErrorInvalidData, "xContextData->visual is not a TrueColor visual");
    checkWindow(data.display, data.drawable);
}

X11DrawContext::X11DrawContext(const TQ3XDrawContextData& data)
    : WindowDrawContext(data.contextData), m_display(data.display), m_drawable(data.drawable), m_visual(data.visual),
      m_colormap(data.cmap)
{
    if (data.colorMapData != nullptr)
        m_colormapData = *data.colorMapData;
}

Object* X11DrawContext::duplicate() const
{
    TQ3XColormapData colormapData = m_colormapData;
    const TQ3XDrawContextData data{this->data(), m_display, m_drawable, m_visual, m_colormap, &colormapData};
    return makeShared<X11DrawContext>(data).detach();
}

void X11DrawContext::setDisplay(Display* display)
{
    if (display == nullptr)
        fail(kQ3ErrorNULLParameter, "display is NULL");
    m_display = display;
    markEdited();
}

void X11DrawContext::setDrawable(Drawable drawable)
{
    checkWindow(m_display, drawable);
    m_drawable = drawable;
    markEdited();
}

void X11DrawContext::setVisual(Visual* visual)
{
    if (!usableVisual(visual))
        fail(kQ3ErrorInvalidParameter, "the visual is not a TrueColor visual");
    m_visual = visual;
    markEdited();
}

void X11DrawContext::setColormap(Colormap colormap)
{
    m_colormap = colormap;
    markEdited();
}

void X11DrawContext::setColormapData(const TQ3XColormapData& data)
{
    m_colormapData = data;
    markEdited();
}

} // namespace q3
