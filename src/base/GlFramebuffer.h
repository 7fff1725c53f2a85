// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The calls the application-context draw context (Q3GLDrawContext.h) needs,
// beside base/RenderTarget.h: whether the calling thread has an OpenGL
// context current, and reading and writing pixels of the framebuffer that
// context has bound. The view draws the frame through a RenderTarget like
// any other (in Q3's own context) and puts it into the application's
// framebuffer with writeGlFramebuffer. render/AppGlContext.cpp implements
// them, and says which GL state they touch and how they restore it; nothing
// here names an OpenGL type.

#include "base/RenderResult.h"

#include <cstddef>
#include <cstdint>

namespace q3 {

/// Success when the calling thread has an OpenGL or OpenGL ES context
/// current, through EGL or GLX, that Q3 can put a frame into (OpenGL 3.0 or
/// OpenGL ES 3.0 at least, its bound draw framebuffer single-sample);
/// kContextFailure with the reason otherwise.
/// Touches no GL state.
RenderResult checkCurrentGlContext();

/// Pixels are 32-bit 0xAARRGGBB values, rowPixels apart; element (x, y) is
/// pixels[y * rowPixels + x], with y measured from the top of a framebuffer
/// `framebufferHeight` pixels high (OpenGL's rows count from the bottom).
/// `rect` lies inside the framebuffer. Both calls use the thread's current
/// context (as checkCurrentGlContext) and leave every GL state they change
/// as they found it. Errors: kContextFailure (no usable
/// current context, no colour buffer to read, an incomplete framebuffer).

/// Reads `rect` of the framebuffer bound to GL_DRAW_FRAMEBUFFER (its first
/// draw buffer) into pixels.
RenderResult readGlFramebuffer(const PixelRect& rect, std::uint32_t framebufferHeight, std::uint32_t* pixels,
                               std::size_t rowPixels);
/// Copies `rect` of pixels into the framebuffer bound to GL_DRAW_FRAMEBUFFER
/// (every draw buffer), at the same place.
RenderResult writeGlFramebuffer(const PixelRect& rect, std::uint32_t framebufferHeight,
                                const std::uint32_t* pixels, std::size_t rowPixels);

} // namespace q3
