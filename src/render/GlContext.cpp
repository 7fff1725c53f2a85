// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Choosing the backend, and the Mesa settings both backends pin.
//
// Pinned settings. Images must be bit-reproducible across runs and across
// x86-64 machines with this Mesa (22.3), whichever backend draws them
// (OffscreenRenderer.cpp lists what was measured). Mesa reads the variables
// below once, when the process's first context creates the llvmpipe screen:
// OSMesa's first OSMesaCreateContextAttribs, or eglInitialize of EGL's
// software device. The two backends share that screen code, so the same
// variables are pinned for both, for the same reasons: GALLIUM_DRIVER is
// forced rather than set only when absent, since Q3 refuses any other
// driver (the GL_RENDERER check), so honouring a different value would only
// turn a working setup into an error (softpipe draws different pixels); the
// others are Mesa debugging switches measured to change the image. EGL needs
// no variable of its own: the device is chosen explicitly (EglContext.cpp),
// so EGL_PLATFORM and LIBGL_ALWAYS_SOFTWARE play no part.

#include "render/GlContext.h"

#include "render/GlApi.h"

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace q3 {
namespace {

struct PinnedVariable {
    const char* name;
    const char* value; // nullptr: unset
};

constexpr PinnedVariable kPinnedEnvironment[] = {
    {"GALLIUM_DRIVER", "llvmpipe"},
    {"DRAW_USE_LLVM", nullptr},
    {"GALLIUM_NOSSE", nullptr},
    {"GALLIUM_OVERRIDE_CPU_CAPS", nullptr},
    {"LP_NO_RAST", nullptr},
    {"GALLIUM_NOOP", nullptr},
};

std::atomic<bool> g_shutDown{false};

void markRenderingShutDown()
{
    g_shutDown.store(true, std::memory_order_release);
}

} // namespace

bool renderingShutDown()
{
    return g_shutDown.load(std::memory_order_acquire);
}

namespace detail {

const char* const kShutDownMessage =
    "the process is exiting and the rendering library has shut down (an exit handler or static object made "
    "before Q3 first drew runs after it)";

void watchProcessExit(ExitWatch stage)
{
    static std::once_flag registered[2];
    // Two registrations at most: the list of exit handlers does not grow.
    std::call_once(registered[stage == ExitWatch::kFirstContext ? 0 : 1],
                   [] { std::atexit(markRenderingShutDown); });
}

std::mutex& contextMutex()
{
    static std::mutex mutex;
    return mutex;
}

// If the process created a Mesa context before (outside Q3), Mesa has already
// chosen its driver and the GL_RENDERER check reports it.
void pinMesaEnvironmentLocked()
{
    static bool pinned = false;
    if (pinned)
        return;
    for (const PinnedVariable& variable : kPinnedEnvironment) {
        if (variable.value != nullptr)
            setenv(variable.name, variable.value, 1);
        else
            unsetenv(variable.name);
    }
    pinned = true;
}

bool loadGlEntryPoints(GlApi& gl, void* (*proc)(const char*, void*), void* library, const char* procName,
                       std::string& error)
{
    const char* missing = nullptr;
    if (gl.load(proc, library, missing))
        return true;
    error = std::string(procName) + " does not know " + missing;
    return false;
}

namespace {

RenderResult checkRenderer(const char* renderer, bool softwareExpected, const char* backend)
{
    if (renderer == nullptr)
        return RenderResult::failure(RenderStatus::kContextFailure,
                                     std::string(backend) + " context reports no GL_RENDERER");
    if (softwareExpected && std::strncmp(renderer, "llvmpipe", 8) != 0)
        return RenderResult::failure(
            RenderStatus::kWrongRenderer,
            std::string("OpenGL renderer is '") + renderer + "', not llvmpipe: Q3 pins GALLIUM_DRIVER=llvmpipe " +
                "for reproducible images, but Mesa chose its driver earlier (a " + backend +
                " context created before Q3's?)");
    return RenderResult::success();
}

} // namespace

RenderResult finishNewContext(std::unique_ptr<GlContext> context, std::uint8_t* image, bool softwareExpected,
                              const char* backend, const std::function<void()>& prepare,
                              const std::function<std::string()>& whyNotCurrent, std::unique_ptr<GlContext>& out)
{
    if (!context->makeCurrent(image)) {
        const std::string why = whyNotCurrent();
        context->restorePrevious();
        return RenderResult::failure(RenderStatus::kContextFailure, why);
    }
    RenderResult result;
    {
        GlApiScope api(&context->api());
        prepare();
        result = checkRenderer(reinterpret_cast<const char*>(glGetString(GL_RENDERER)), softwareExpected, backend);
    }
    context->restorePrevious();
    if (result) {
        out = std::move(context);
        watchProcessExit(ExitWatch::kFirstContext);
    }
    return result;
}

#if !Q3_HAVE_OSMESA
bool osMesaAvailable()
{
    return false;
}

RenderResult createOsMesaContext(std::uint32_t, std::uint32_t, std::uint8_t*, bool, std::unique_ptr<GlContext>&)
{
    return RenderResult::failure(RenderStatus::kContextFailure, "this Q3 was built without OSMesa (Q3_WITH_OSMESA)");
}
#endif

#if !Q3_HAVE_EGL
bool eglAvailable()
{
    return false;
}

RenderResult createEglContext(std::uint32_t, std::uint32_t, std::uint8_t*, bool, std::unique_ptr<GlContext>&)
{
    return RenderResult::failure(RenderStatus::kContextFailure, "this Q3 was built without EGL (Q3_WITH_EGL)");
}
#endif

} // namespace detail

void pinRenderingEnvironment()
{
    std::lock_guard<std::mutex> lock(detail::contextMutex());
    detail::pinMesaEnvironmentLocked();
}

const char* glBackendName(GlBackend backend)
{
    return backend == GlBackend::kEgl ? "egl" : "osmesa";
}

bool glBackendAvailable(GlBackend backend)
{
    return backend == GlBackend::kEgl ? detail::eglAvailable() : detail::osMesaAvailable();
}

GlBackendChoice chooseGlBackend(const char* value, bool osmesaAvailable, bool eglAvailable)
{
    GlBackendChoice choice;
    if (value == nullptr || value[0] == '\0') {
        if (osmesaAvailable || !eglAvailable) {
            choice.backend = GlBackend::kOsMesa;
            if (!osmesaAvailable)
                choice.result = RenderResult::failure(
                    RenderStatus::kContextFailure,
                    "no rendering backend: neither libOSMesa.so.8 nor libEGL.so.1 could be loaded");
        } else {
            choice.backend = GlBackend::kEgl;
        }
        return choice;
    }
    if (std::strcmp(value, "osmesa") == 0) {
        choice.backend = GlBackend::kOsMesa;
        if (!osmesaAvailable)
            choice.result = RenderResult::failure(RenderStatus::kContextFailure,
                                                  "Q3_RENDER_BACKEND=osmesa, but OSMesa is not available "
                                                  "(libOSMesa.so.8 missing, or Q3 built without it)");
    } else if (std::strcmp(value, "egl") == 0) {
        choice.backend = GlBackend::kEgl;
        if (!eglAvailable)
            choice.result = RenderResult::failure(RenderStatus::kContextFailure,
                                                  "Q3_RENDER_BACKEND=egl, but EGL is not available "
                                                  "(libEGL.so.1 missing, or Q3 built without it)");
    } else {
        choice.result = RenderResult::failure(RenderStatus::kContextFailure,
                                              std::string("Q3_RENDER_BACKEND='") + value +
                                                  "' is not a rendering backend: use osmesa or egl, or unset it");
    }
    return choice;
}

GlBackendChoice chooseGlBackendFromEnvironment()
{
    const char* value = std::getenv("Q3_RENDER_BACKEND");
    const bool asked = value != nullptr && value[0] != '\0';
    // Only the libraries that matter are loaded.
    const bool osmesa = (!asked || std::strcmp(value, "osmesa") == 0) && detail::osMesaAvailable();
    const bool egl = (asked ? std::strcmp(value, "egl") == 0 : !osmesa) && detail::eglAvailable();
    return chooseGlBackend(value, osmesa, egl);
}

RenderResult createGlContext(GlBackend backend, std::uint32_t width, std::uint32_t height, std::uint8_t* image,
                             std::unique_ptr<GlContext>& context, bool bgra)
{
    context.reset();
    if (renderingShutDown())
        return RenderResult::failure(RenderStatus::kContextFailure, detail::kShutDownMessage);
    return backend == GlBackend::kEgl ? detail::createEglContext(width, height, image, bgra, context)
                                      : detail::createOsMesaContext(width, height, image, bgra, context);
}

} // namespace q3
