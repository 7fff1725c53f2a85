// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The window-system calls a window draw context needs, beside
// base/RenderTarget.h: the size of a window, reading and writing its pixels.
// The view draws a window's frame through a RenderTarget like any other and
// shows it with writeWindow. render/X11Window.cpp implements them for X11
// (libX11 opened with dlopen); nothing here names an X11 type, so the view
// and the API pass Xlib's handles as void pointers and XIDs.

#include "base/RenderResult.h"

#include <cstddef>
#include <cstdint>

namespace q3 {

/// An X window: `display` is a Display*, `drawable` its XID.
struct NativeWindow {
    void* display = nullptr;
    unsigned long drawable = 0;
};

/// Every call reports an X protocol error (caught by an error handler
/// installed around the call, so the process goes on) or a missing libX11
/// as kContextFailure with a message naming the request and the error.
/// Pixels are 0x00RRGGBB values, rowPixels apart, 8 bits per channel.

/// The window's size. kContextFailure also when the drawable is not a
/// window (a pixmap, an InputOnly window) or its visual is not TrueColor.
RenderResult windowSize(const NativeWindow& window, std::uint32_t& width, std::uint32_t& height);
/// Reads the pixels of `rect` (inside the window) into pixels, whose
/// element (x, y) is pixels[y * rowPixels + x] in window coordinates.
RenderResult readWindow(const NativeWindow& window, const PixelRect& rect, std::uint32_t* pixels,
                        std::size_t rowPixels);
/// Puts `rect` of pixels (same addressing) at the same place in the window.
RenderResult writeWindow(const NativeWindow& window, const PixelRect& rect, const std::uint32_t* pixels,
                         std::size_t rowPixels);
/// XFlush.
RenderResult flushDisplay(void* display);
/// XGetVisualInfo's list of `screen`'s (a Screen*) TrueColor depth-24
/// visuals (an XVisualInfo*, freed with XFree); kContextFailure when empty.
RenderResult trueColorVisuals(void* display, void* screen, void*& visuals);

} // namespace q3
