// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "Q3GLDrawContext.h"
#include "view/DrawContext.h"

namespace q3 {

extern const ClassInfo kGLDrawContextClass;

/// A draw context putting its frames into the framebuffer of the
/// application's current OpenGL context (Q3GLDrawContext.h). The view draws
/// the frame as for a pixmap of width x height and hands the pixels to
/// base/GlFramebuffer.h. Invariant: 1 <= width, height <=
/// kQ3GLDrawContextMaxSize.
class GLDrawContext final : public DrawContext {
public:
    static constexpr TQ3ObjectType kClassType = kQ3DrawContextTypeGL;

    /// Checks the data in the order of Q3GLDrawContext_New
    /// (kQ3ErrorInvalidData).
    static void validate(const TQ3GLDrawContextData& data);
    /// Takes validated data.
    explicit GLDrawContext(const TQ3GLDrawContextData& data);

    const ClassInfo& classInfo() const override { return kGLDrawContextClass; }
    Object* duplicate() const override;

    std::uint32_t width() const { return m_width; }
    std::uint32_t height() const { return m_height; }
    /// Checks as validate does (kQ3ErrorInvalidParameter); changes nothing
    /// on failure.
    void setSize(TQ3Uns32 width, TQ3Uns32 height);

private:
    std::uint32_t m_width;
    std::uint32_t m_height;
};

} // namespace q3
