// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "view/DrawContext.h"
#include "base/WindowSystem.h"

namespace q3 {

/// What the view needs of a draw context that shows its frames in an X
/// window (X11DrawContext, which alone sees Xlib's types): the window. The
/// view draws the frame as into a pixmap of the window's size and shows it
/// through base/WindowSystem.h.
class WindowDrawContext : public DrawContext {
public:
    static constexpr TQ3ObjectType kClassType = kQ3DrawContextTypeX11;
    virtual NativeWindow window() const = 0;

protected:
    using DrawContext::DrawContext;
};

} // namespace q3
