// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The part of a rendering backend that differs between OSMesa and EGL: making
// an OpenGL context that draws into an RGBA8 image, making it current (and
// the thread's previous context current again) and reading the finished
// image. OffscreenRenderer draws through this interface, so every backend
// shares its drawing code. Free of OpenGL types: GlApi is only named.

#include "base/RenderResult.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

namespace q3 {

struct GlApi;

/// The OpenGL implementations Q3 can draw with.
enum class GlBackend {
    kOsMesa, ///< Mesa's OSMesa (libOSMesa.so.8), llvmpipe
    kEgl,    ///< EGL on a device (libEGL.so.1): Mesa's software device (llvmpipe) or a GPU
};

/// "osmesa" or "egl": the values of Q3_RENDER_BACKEND.
const char* glBackendName(GlBackend backend);

/// Whether this build has the backend and its library loads in this process
/// (loaded at most once, then remembered). Thread-safe.
bool glBackendAvailable(GlBackend backend);

/// The backend Q3_RENDER_BACKEND asks for (`value`: the variable, or null
/// when it is unset), given which are available. Unset or empty: OSMesa when
/// it is available, else EGL. "osmesa" or "egl" (case-sensitive): that one,
/// and a failure naming the library when it is not available. Any other
/// value: a failure listing the valid ones. Never silently another backend
/// than the one asked for.
struct GlBackendChoice {
    GlBackend backend = GlBackend::kOsMesa;
    RenderResult result;
};
GlBackendChoice chooseGlBackend(const char* value, bool osmesaAvailable, bool eglAvailable);
/// chooseGlBackend for this process's environment and libraries.
GlBackendChoice chooseGlBackendFromEnvironment();

/// An OpenGL context of one backend bound to one image size, RGBA8 colour
/// and a 24-bit depth buffer, no stencil. Rows are stored top row first.
/// Invariant: api() resolves every function of GlApi.h for this context.
class GlContext {
public:
    virtual ~GlContext() = default;
    /// Makes the context current on the calling thread, drawing into
    /// `image` (width * height * 4 bytes; OSMesa draws into it directly,
    /// EGL ignores it), and remembers the thread's previous context of the
    /// same API. False when the backend refuses; nothing is current then.
    virtual bool makeCurrent(std::uint8_t* image) = 0;
    /// With the context current: the rows of the image makeCurrent bound
    /// (OSMesa) or finish fills (EGL) are rowPixels pixels apart (0: its
    /// width, as after creation).
    virtual bool setRowPixels(std::uint32_t rowPixels) = 0;
    /// Makes the remembered previous context current again, or none.
    virtual void restorePrevious() = 0;
    /// With the context current: finishes the drawing and leaves the image
    /// in `image`, top row first.
    virtual void finish(std::uint8_t* image) = 0;
    virtual const GlApi& api() const = 0;
};

/// Creates a context of `backend` for width x height pixels drawing into
/// `image` (as makeCurrent), R, G, B, A bytes per pixel or with `bgra` B,
/// G, R, A, and checks that
/// it renders with llvmpipe (EGL on a GPU device: with that GPU); the
/// context is not current afterwards. Errors: kContextFailure (the library
/// is missing or refuses, a GL function is missing), kWrongRenderer.
RenderResult createGlContext(GlBackend backend, std::uint32_t width, std::uint32_t height, std::uint8_t* image,
                             std::unique_ptr<GlContext>& context, bool bgra = false);

/// Sets the environment variables Mesa reads when the process's first
/// context is created (GlContext.cpp says which and why). Only the first
/// call changes the environment, with setenv/unsetenv, which the C library
/// does not make safe against other threads using the environment at the
/// same time: so Q3Initialize calls it, at program start as QuickDraw 3D
/// requires, and the first context creation calls it again in case it was
/// skipped. Thread-safe otherwise.
void pinRenderingEnvironment();

/// True once the process's exit has reached Q3's exit handler (see
/// detail::watchProcessExit): the rendering libraries' own exit handlers
/// run next, after which no OpenGL call is safe. From then on no context is
/// created, made current or destroyed (a context left is reclaimed by the
/// exit itself), and a frame fails with kContextFailure.
bool renderingShutDown();

namespace detail {
// Registers Q3's exit handler (renderingShutDown) once per `stage`: after
// the process's first context is made (finishNewContext) and after its
// first frame (OffscreenRenderer's flush), the two moments at which Mesa
// registers its own (at screen creation, and lazily at a first draw).
// Handlers run in the reverse order of registration, so Q3's runs before
// Mesa's, and an application's handler registered before Q3 first drew
// (a static C++ object made before main, an atexit call before
// Q3Initialize) runs after both: its Q3 calls then fail cleanly instead of
// calling into a library that has shut down.
enum class ExitWatch { kFirstContext, kFirstFrame };
void watchProcessExit(ExitWatch stage);
// The message of a context refused by renderingShutDown.
extern const char* const kShutDownMessage;
// Serializes context creation and destruction, which touch the process-wide
// llvmpipe screen (and the first time the environment).
std::mutex& contextMutex();
// With contextMutex() held.
void pinMesaEnvironmentLocked();
// The backends' factories (OsMesaContext.cpp, EglContext.cpp); available()
// loads the library once.
bool osMesaAvailable();
bool eglAvailable();
RenderResult createOsMesaContext(std::uint32_t width, std::uint32_t height, std::uint8_t* image, bool bgra,
                                 std::unique_ptr<GlContext>& context);
RenderResult createEglContext(std::uint32_t width, std::uint32_t height, std::uint8_t* image, bool bgra,
                              std::unique_ptr<GlContext>& context);
// The last step of loading a backend's library: every GL entry point of
// `gl` through `proc` (with `library`); false, with `error` naming the one
// `procName` does not know.
bool loadGlEntryPoints(GlApi& gl, void* (*proc)(const char*, void*), void* library, const char* procName,
                       std::string& error);
// The last step both factories share: the new context made current on
// `image` (else kContextFailure, `whyNotCurrent()` saying why), `prepare()`
// run in it, GL_RENDERER checked (llvmpipe when `softwareExpected`, else
// kWrongRenderer), then released; `out` takes it only if all went well.
RenderResult finishNewContext(std::unique_ptr<GlContext> context, std::uint8_t* image, bool softwareExpected,
                              const char* backend, const std::function<void()>& prepare,
                              const std::function<std::string()>& whyNotCurrent, std::unique_ptr<GlContext>& out);
} // namespace detail

} // namespace q3
