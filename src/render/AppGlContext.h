// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The application's EGL or GLX context, as Q3's own backends see it
// (AppGlContext.cpp). While Q3's context draws, a context the application
// has current on the thread is released, and afterwards bound again with the
// same display, surfaces or drawables and (EGL) client API: two OpenGL
// libraries current on one thread at once do not mix (OSMesa takes Mesa's
// current context for one of its own and writes through it; GLVND refuses
// an EGL context while a GLX one is current), and releasing and binding
// again keeps every GL state of the context.

namespace q3 {

/// One thread's binding of an EGL or GLX context; kind kNone when there was
/// none.
struct WindowSystemBinding {
    enum class Kind { kNone, kEgl, kGlx };
    Kind kind = Kind::kNone;
    void* display = nullptr;
    void* context = nullptr;
    void* eglDraw = nullptr;
    void* eglRead = nullptr;
    unsigned eglApi = 0;
    unsigned long glxDraw = 0;
    unsigned long glxRead = 0;
};

/// Releases the thread's current EGL context (when `egl`; of the client API
/// bound now) or GLX context (when `glx`), looked for only in a libEGL or
/// libGLX the process has loaded, and returns its binding (kNone when none
/// was current or released).
WindowSystemBinding releaseWindowSystemContext(bool egl, bool glx);

/// Binds `binding` again (nothing for kNone).
void restoreWindowSystemContext(const WindowSystemBinding& binding);

} // namespace q3
