// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/GLDrawContext.h"

#include "core/Error.h"

#include <string>

namespace q3 {

const ClassInfo kGLDrawContextClass{kQ3DrawContextTypeGL, &kDrawContextClass, "GL draw context"};

namespace {

void checkSize(TQ3Uns32 width, TQ3Uns32 height, TQ3Error code)
{
    if (width == 0 || height == 0 || width > kQ3GLDrawContextMaxSize || height > kQ3GLDrawContextMaxSize)
        fail(code, "the framebuffer size " + std::to_string(width) + " x " + std::to_string(height) +
                       " is not 1 to " + std::to_string(kQ3GLDrawContextMaxSize) + " pixels each way");
}

} // namespace

void GLDrawContext::validate(const TQ3GLDrawContextData& data)
{
    validateDrawContextData(data.drawContextData);
    checkSize(data.width, data.height, kQ3ErrorInvalidData);
}

GLDrawContext::GLDrawContext(const TQ3GLDrawContextData& data)
    : DrawContext(data.drawContextData), m_width(data.width), m_height(data.height)
{
}

Object* GLDrawContext::duplicate() const
{
    return makeShared<GLDrawContext>(TQ3GLDrawContextData{data(), m_width, m_height}).detach();
}

void GLDrawContext::setSize(TQ3Uns32 width, TQ3Uns32 height)
{
    checkSize(width, height, kQ3ErrorInvalidParameter);
    m_width = width;
    m_height = height;
    markEdited();
}

} // namespace q3
