// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/ViewHints.h"

#include "core/AttributeSet.h"
#include "core/DataLayout.h"
#include "core/ParameterChecks.h"
#include "geometry/Marker.h"
#include "group/Group.h"
#include "render/Renderer.h"
#include "view/Camera.h"
#include "view/DrawContext.h"
#include "view/GLDrawContext.h"
#include "view/WindowDrawContext.h"
#include "view/View.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

namespace q3 {

const ClassInfo kViewHintsClass{kQ3SharedTypeViewHints, &kSharedClass, "view hints"};

namespace {

constexpr unsigned long kMaxDimension = 0xFFFFFFFFul;

TQ3Bitmap copyOf(const TQ3Bitmap& bitmap)
{
    TQ3Bitmap copy = bitmap;
    const std::size_t bytes = std::size_t(bitmap.rowBytes) * bitmap.height;
    copy.image = layout::allocate<unsigned char>(bytes);
    std::memcpy(copy.image, bitmap.image, bytes);
    return copy;
}

// The whole pixels of a pane's extent, 0 when it has none.
unsigned long paneExtent(float from, float to)
{
    const double extent = std::floor(double(to) - double(from) + 0.5);
    if (!(extent >= 1.0))
        return 0;
    return extent > double(kMaxDimension) ? kMaxDimension : static_cast<unsigned long>(extent);
}

} // namespace

ViewHints::ViewHints() = default;

ViewHints::~ViewHints()
{
    std::free(m_mask.image);
}

Object* ViewHints::duplicate() const
{
    Ref<ViewHints> copy = makeShared<ViewHints>();
    copy->m_renderer = m_renderer;
    copy->m_camera = m_camera;
    copy->m_lightGroup = m_lightGroup;
    copy->m_attributeSet = m_attributeSet;
    copy->m_dimensionsState = m_dimensionsState;
    copy->m_width = m_width;
    copy->m_height = m_height;
    copy->m_maskState = m_maskState;
    if (m_mask.image != nullptr)
        copy->m_mask = copyOf(m_mask);
    copy->m_clearMethod = m_clearMethod;
    copy->m_clearColor = m_clearColor;
    copy->m_unknownChildren = m_unknownChildren;
    return copy.detach();
}

Ref<ViewHints> ViewHints::fromView(const View& view)
{
    Ref<ViewHints> hints = makeShared<ViewHints>();
    hints->m_renderer = view.renderer();
    hints->m_camera = view.camera();
    hints->m_lightGroup = view.lightGroup();
    hints->m_attributeSet = view.defaultAttributeSet();
    if (const DrawContext* context = view.drawContext().get()) {
        const TQ3DrawContextData& data = context->data();
        hints->m_clearMethod = data.clearImageMethod;
        hints->m_clearColor = data.clearImageColor;
        hints->m_maskState = booleanOf(data.maskState);
        if (data.mask.image != nullptr) {
            // A draw context does not check its mask; the hints keep only one
            // that obeys their rules.
            try {
                Marker::checkBitmap(data.mask);
                hints->m_mask = copyOf(data.mask);
            } catch (const Error&) {
            }
        }
        if (booleanOf(data.paneState) == kQ3True) {
            hints->m_width = paneExtent(data.pane.min.x, data.pane.max.x);
            hints->m_height = paneExtent(data.pane.min.y, data.pane.max.y);
        } else if (context->isType(kQ3DrawContextTypePixmap)) {
            const TQ3Pixmap& pixmap = static_cast<const PixmapDrawContext*>(context)->pixmap();
            hints->m_width = pixmap.width > kMaxDimension ? kMaxDimension : pixmap.width;
            hints->m_height = pixmap.height > kMaxDimension ? kMaxDimension : pixmap.height;
        } else if (context->isType(kQ3DrawContextTypeX11)) {
            // The window's size now; none when the server no longer knows it.
            std::uint32_t width = 0, height = 0;
            if (windowSize(static_cast<const WindowDrawContext*>(context)->window(), width, height)) {
                hints->m_width = width > kMaxDimension ? kMaxDimension : width;
                hints->m_height = height > kMaxDimension ? kMaxDimension : height;
            }
        } else if (context->isType(kQ3DrawContextTypeGL)) {
            const GLDrawContext* gl = static_cast<const GLDrawContext*>(context);
            hints->m_width = gl->width();
            hints->m_height = gl->height();
        }
        if (hints->m_width == 0 || hints->m_height == 0)
            hints->m_width = hints->m_height = 0;
        else
            hints->m_dimensionsState = kQ3True;
    }
    return hints;
}

void ViewHints::setRenderer(Ref<Renderer> renderer)
{
    m_renderer = std::move(renderer);
    markEdited();
}

void ViewHints::setCamera(Ref<Camera> camera)
{
    m_camera = std::move(camera);
    markEdited();
}

void ViewHints::setLightGroup(Ref<Group> lights)
{
    if (lights && !lights->isType(kQ3GroupTypeLight))
        fail(kQ3ErrorInvalidObjectType, std::string("the group is a ") + lights->classInfo().name +
                                            ", not a light group (Q3LightGroup_New)");
    m_lightGroup = std::move(lights);
    markEdited();
}

void ViewHints::setAttributeSet(Ref<AttributeSet> attributes)
{
    m_attributeSet = std::move(attributes);
    markEdited();
}

void ViewHints::setDimensionsState(const TQ3Boolean& state)
{
    m_dimensionsState = booleanOf(state);
    markEdited();
}

void ViewHints::setDimensions(unsigned long width, unsigned long height)
{
    if (width == 0 || height == 0 || width > kMaxDimension || height > kMaxDimension)
        fail(kQ3ErrorInvalidParameter, "the dimensions " + std::to_string(width) + " x " + std::to_string(height) +
                                           " are not each 1 to 4294967295 pixels");
    m_width = width;
    m_height = height;
    markEdited();
}

void ViewHints::setMaskState(const TQ3Boolean& state)
{
    m_maskState = booleanOf(state);
    markEdited();
}

void ViewHints::setMask(const TQ3Bitmap& mask)
{
    Marker::checkBitmap(mask);
    TQ3Bitmap copy = copyOf(mask);
    std::free(m_mask.image);
    m_mask = copy;
    markEdited();
}

void ViewHints::copyMask(TQ3Bitmap& out) const
{
    if (m_mask.image == nullptr) {
        out = TQ3Bitmap{};
        return;
    }
    out = copyOf(m_mask);
}

void ViewHints::setClearMethod(const TQ3DrawContextClearImageMethod& method)
{
    m_clearMethod = checkEnum(method, kQ3ClearMethodNone, kQ3ClearMethodWithColor, "clearMethod",
                              "kQ3ClearMethodNone, kQ3ClearMethodWithColor");
    markEdited();
}

void ViewHints::setClearColor(const TQ3ColorARGB& color)
{
    checkFinite(color, "color");
    m_clearColor = color;
    markEdited();
}

} // namespace q3
