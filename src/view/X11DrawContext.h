// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Apple's X11 declarations, which the rest of the library is compiled
// without (src/CMakeLists.txt: Xlib's macros None, Status and Bool would
// collide with C++ names).
#undef WINDOW_SYSTEM_X11
#define WINDOW_SYSTEM_X11 1
#include "QD3DDrawContext.h"
#include "view/WindowDrawContext.h"

namespace q3 {

extern const ClassInfo kX11DrawContextClass;

/// A draw context showing its frames in an X window (QD3DDrawContext.h,
/// Apple's TQ3XDrawContextData). The view draws the frame off screen as for
/// a pixmap of the window's size and puts it into the window through
/// base/WindowSystem.h. Invariant: display is not NULL; visual is NULL or
/// TrueColor; the drawable was a window of the display when it was set (the
/// server is asked again at every frame); m_colormapData is the copy of the
/// last colormap data given, zeros when none was.
class X11DrawContext final : public WindowDrawContext {
public:
    static constexpr TQ3ObjectType kClassType = kQ3DrawContextTypeX11;

    /// Checks the data in the order of Q3XDrawContext_New
    /// (kQ3ErrorNULLParameter, kQ3ErrorInvalidData, kQ3ErrorX11Error).
    static void validate(const TQ3XDrawContextData& data);
    /// Takes validated data.
    explicit X11DrawContext(const TQ3XDrawContextData& data);

    const ClassInfo& classInfo() const override { return kX11DrawContextClass; }
    Object* duplicate() const override;

    Display* display() const { return m_display; }
    Drawable drawable() const { return m_drawable; }
    Visual* visual() const { return m_visual; }
    Colormap colormap() const { return m_colormap; }
    const TQ3XColormapData& colormapData() const { return m_colormapData; }
    NativeWindow window() const override { return NativeWindow{m_display, m_drawable}; }

    /// Each setter checks as validate does for its field (a bad visual:
    /// kQ3ErrorInvalidParameter) and changes nothing on failure.
    void setDisplay(Display* display);
    void setDrawable(Drawable drawable);
    void setVisual(Visual* visual);
    void setColormap(Colormap colormap);
    void setColormapData(const TQ3XColormapData& data);

private:
    Display* m_display;
    Drawable m_drawable;
    Visual* m_visual;
    Colormap m_colormap;
    TQ3XColormapData m_colormapData{};
};

} // namespace q3
