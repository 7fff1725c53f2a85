// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The OSMesa backend's context: Mesa's OSMesa renders into its own
// window-system framebuffer and copies it into our RGBA8 buffer (top row
// first, OSMESA_Y_UP = 0) at glFinish.
//
// libOSMesa.so.8 is opened with dlopen, not linked: Mesa removed OSMesa in
// 25.1, so a libq3.so linked against it would not even load where only EGL
// is installed. The GL entry points come from OSMesaGetProcAddress (GlApi.h
// says why never by global name).

#if Q3_HAVE_OSMESA

#include "render/AppGlContext.h"
#include "render/DynamicLibrary.h"
#include "render/GlApi.h"
#include "render/GlContext.h"

#include <GL/osmesa.h>

#include <string>

namespace q3 {
namespace {

struct OsMesaLibrary {
    bool loaded = false;
    decltype(&::OSMesaCreateContextAttribs) CreateContextAttribs = nullptr;
    decltype(&::OSMesaDestroyContext) DestroyContext = nullptr;
    decltype(&::OSMesaMakeCurrent) MakeCurrent = nullptr;
    decltype(&::OSMesaGetCurrentContext) GetCurrentContext = nullptr;
    decltype(&::OSMesaGetColorBuffer) GetColorBuffer = nullptr;
    decltype(&::OSMesaGetIntegerv) GetIntegerv = nullptr;
    decltype(&::OSMesaPixelStore) PixelStore = nullptr;
    decltype(&::OSMesaGetProcAddress) GetProcAddress = nullptr;
    GlApi gl;
    std::string error;
};

void* osMesaProc(const char* name, void* library)
{
    return reinterpret_cast<void*>(static_cast<OsMesaLibrary*>(library)->GetProcAddress(name));
}

// Loaded once, never unloaded (Mesa keeps process-wide state).
const OsMesaLibrary& osMesa()
{
    static const OsMesaLibrary library = [] {
        OsMesaLibrary l;
        DynamicLibrary file("libOSMesa.so.8");
        auto bind = [&](auto& function, const char* name) { file.bind(function, name); };
        bind(l.CreateContextAttribs, "OSMesaCreateContextAttribs");
        bind(l.DestroyContext, "OSMesaDestroyContext");
        bind(l.MakeCurrent, "OSMesaMakeCurrent");
        bind(l.GetCurrentContext, "OSMesaGetCurrentContext");
        bind(l.GetColorBuffer, "OSMesaGetColorBuffer");
        bind(l.GetIntegerv, "OSMesaGetIntegerv");
        bind(l.PixelStore, "OSMesaPixelStore");
        bind(l.GetProcAddress, "OSMesaGetProcAddress");
        if (!file.ok()) {
            l.error = file.error();
            return l;
        }
        l.loaded = detail::loadGlEntryPoints(l.gl, osMesaProc, &l, "OSMesaGetProcAddress", l.error);
        return l;
    }();
    return library;
}

/// Invariant: m_context is a live OSMesa context for m_width x m_height.
class OsMesaContext final : public GlContext {
public:
    OsMesaContext(OSMesaContext context, std::uint32_t width, std::uint32_t height)
        : m_context(context), m_width(width), m_height(height)
    {
    }

    ~OsMesaContext() override
    {
        if (renderingShutDown())
            return;
        std::lock_guard<std::mutex> lock(detail::contextMutex());
        osMesa().DestroyContext(m_context);
    }

    bool makeCurrent(std::uint8_t* image) override
    {
        if (renderingShutDown())
            return false;
        const OsMesaLibrary& l = osMesa();
        // With an application's EGL or GLX context current, Mesa's current
        // context is that one, which OSMesaGetCurrentContext would take for
        // an OSMesa context: it is released instead, and bound again after.
        m_foreign = releaseWindowSystemContext(true, true);
        m_previous = m_foreign.kind == WindowSystemBinding::Kind::kNone ? l.GetCurrentContext() : nullptr;
        if (m_previous != nullptr) {
            GLint format = 0;
            if (!l.GetColorBuffer(m_previous, &m_previousWidth, &m_previousHeight, &format, &m_previousBuffer))
                m_previous = nullptr;
            else
                l.GetIntegerv(OSMESA_TYPE, &m_previousType);
        }
        return l.MakeCurrent(m_context, image, GL_UNSIGNED_BYTE, GLsizei(m_width), GLsizei(m_height)) == GL_TRUE;
    }

    void restorePrevious() override
    {
        if (renderingShutDown())
            return;
        const OsMesaLibrary& l = osMesa();
        if (m_previous != nullptr)
            l.MakeCurrent(m_previous, m_previousBuffer, GLenum(m_previousType), m_previousWidth, m_previousHeight);
        else
            l.MakeCurrent(nullptr, nullptr, 0, 0, 0);
        m_previous = nullptr;
        restoreWindowSystemContext(m_foreign);
        m_foreign = WindowSystemBinding{};
    }

    bool setRowPixels(std::uint32_t rowPixels) override
    {
        osMesa().PixelStore(OSMESA_ROW_LENGTH, GLint(rowPixels));
        return true;
    }

    // glFinish makes OSMesa copy its framebuffer into the bound image.
    void finish(std::uint8_t*) override { glFinish(); }

    const GlApi& api() const override { return osMesa().gl; }

    void setRowsTopFirst() { osMesa().PixelStore(OSMESA_Y_UP, 0); }

private:
    OSMesaContext m_context;
    std::uint32_t m_width, m_height;
    OSMesaContext m_previous = nullptr;
    void* m_previousBuffer = nullptr;
    GLint m_previousWidth = 0;
    GLint m_previousHeight = 0;
    GLint m_previousType = GL_UNSIGNED_BYTE;
    WindowSystemBinding m_foreign;
};

} // namespace

namespace detail {

bool osMesaAvailable()
{
    return osMesa().loaded;
}

RenderResult createOsMesaContext(std::uint32_t width, std::uint32_t height, std::uint8_t* image, bool bgra,
                                 std::unique_ptr<GlContext>& out)
{
    const OsMesaLibrary& l = osMesa();
    if (!l.loaded)
        return RenderResult::failure(RenderStatus::kContextFailure, l.error);
    OSMesaContext raw = nullptr;
    {
        std::lock_guard<std::mutex> lock(contextMutex());
        pinMesaEnvironmentLocked();
        // A depth buffer for FrameOptions::depthTest; frames without the test
        // never touch it.
        const int attributes[] = {OSMESA_FORMAT,       bgra ? OSMESA_BGRA : OSMESA_RGBA, OSMESA_DEPTH_BITS,  24,
                                  OSMESA_STENCIL_BITS, 0,           OSMESA_ACCUM_BITS,  0,
                                  OSMESA_PROFILE,      OSMESA_COMPAT_PROFILE, 0};
        raw = l.CreateContextAttribs(attributes, nullptr);
    }
    if (raw == nullptr)
        return RenderResult::failure(RenderStatus::kContextFailure,
                                     std::string("OSMesaCreateContextAttribs failed for an ") +
                                         (bgra ? "BGRA" : "RGBA") + " compatibility context");
    auto context = std::make_unique<OsMesaContext>(raw, width, height);
    OsMesaContext* made = context.get();
    return finishNewContext(
        std::move(context), image, true, "OSMesa", [made] { made->setRowsTopFirst(); },
        [&] {
            return "OSMesaMakeCurrent failed for a " + std::to_string(width) + " x " + std::to_string(height) +
                   (bgra ? " BGRA8" : " RGBA8") + " buffer";
        },
        out);
}

} // namespace detail
} // namespace q3

#endif
