// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The EGL backend's context: an OpenGL (compatibility profile) context on an
// EGL device (EGL_EXT_platform_device), no window system, drawing into a
// pbuffer surface of the image's size; the finished image is read back with
// glReadPixels and its rows turned top row first.
//
// Why a pbuffer and not a framebuffer object on a surfaceless context: a
// pbuffer is a window-system framebuffer, which llvmpipe rasterizes with the
// same orientation as OSMesa's, so both backends give the same pixels (a
// framebuffer object is rasterized upside down relative to it and about 1
// line pixel in 5000 differs, at exact ties: OffscreenRenderer.cpp).
//
// The device. Q3_EGL_DEVICE unset or "software": Mesa's software device
// (EGL_MESA_device_software), llvmpipe under the settings GlContext.cpp pins,
// the device whose images match the goldens. "gpu": the first device that is
// not the software one (a GPU's render node), for speed; its pixels are the
// GPU's own. Any other value is refused.
//
// libEGL.so.1 is opened with dlopen, not linked, so that a libq3.so built
// with both backends still loads where only one is installed. The GL entry
// points come from eglGetProcAddress (GlApi.h says why never by global
// name), which EGL_KHR_client_get_all_proc_addresses lets resolve core
// functions too.

#if Q3_HAVE_EGL

#include "render/AppGlContext.h"
#include "render/DynamicLibrary.h"
#include "render/GlApi.h"
#include "render/GlContext.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace q3 {
namespace {

struct EglLibrary {
    bool loaded = false;
    decltype(&::eglGetProcAddress) GetProcAddress = nullptr;
    decltype(&::eglGetError) GetError = nullptr;
    decltype(&::eglQueryString) QueryString = nullptr;
    decltype(&::eglGetPlatformDisplay) GetPlatformDisplay = nullptr;
    decltype(&::eglInitialize) Initialize = nullptr;
    decltype(&::eglChooseConfig) ChooseConfig = nullptr;
    decltype(&::eglGetConfigAttrib) GetConfigAttrib = nullptr;
    decltype(&::eglBindAPI) BindAPI = nullptr;
    decltype(&::eglQueryAPI) QueryAPI = nullptr;
    decltype(&::eglCreateContext) CreateContext = nullptr;
    decltype(&::eglDestroyContext) DestroyContext = nullptr;
    decltype(&::eglCreatePbufferSurface) CreatePbufferSurface = nullptr;
    decltype(&::eglDestroySurface) DestroySurface = nullptr;
    decltype(&::eglMakeCurrent) MakeCurrent = nullptr;
    decltype(&::eglGetCurrentContext) GetCurrentContext = nullptr;
    decltype(&::eglGetCurrentDisplay) GetCurrentDisplay = nullptr;
    decltype(&::eglGetCurrentSurface) GetCurrentSurface = nullptr;
    PFNEGLQUERYDEVICESEXTPROC QueryDevices = nullptr;
    PFNEGLQUERYDEVICESTRINGEXTPROC QueryDeviceString = nullptr;
    GlApi gl;
    std::string error;
};

void* eglProc(const char* name, void* library)
{
    return reinterpret_cast<void*>(static_cast<EglLibrary*>(library)->GetProcAddress(name));
}

// Loaded once, never unloaded (the vendor library keeps process-wide state).
const EglLibrary& egl()
{
    static const EglLibrary library = [] {
        EglLibrary l;
        DynamicLibrary file("libEGL.so.1");
        auto bind = [&](auto& function, const char* name) { file.bind(function, name); };
        bind(l.GetProcAddress, "eglGetProcAddress");
        bind(l.GetError, "eglGetError");
        bind(l.QueryString, "eglQueryString");
        bind(l.GetPlatformDisplay, "eglGetPlatformDisplay");
        bind(l.Initialize, "eglInitialize");
        bind(l.ChooseConfig, "eglChooseConfig");
        bind(l.GetConfigAttrib, "eglGetConfigAttrib");
        bind(l.BindAPI, "eglBindAPI");
        bind(l.QueryAPI, "eglQueryAPI");
        bind(l.CreateContext, "eglCreateContext");
        bind(l.DestroyContext, "eglDestroyContext");
        bind(l.CreatePbufferSurface, "eglCreatePbufferSurface");
        bind(l.DestroySurface, "eglDestroySurface");
        bind(l.MakeCurrent, "eglMakeCurrent");
        bind(l.GetCurrentContext, "eglGetCurrentContext");
        bind(l.GetCurrentDisplay, "eglGetCurrentDisplay");
        bind(l.GetCurrentSurface, "eglGetCurrentSurface");
        if (!file.ok()) {
            l.error = file.error();
            return l;
        }
        const char* extensions = l.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        const std::string client = extensions != nullptr ? extensions : "";
        for (const char* needed : {"EGL_EXT_platform_device", "EGL_EXT_device_enumeration",
                                   "EGL_KHR_client_get_all_proc_addresses"})
            if (client.find(needed) == std::string::npos) {
                l.error = std::string("libEGL.so.1 lacks ") + needed;
                return l;
            }
        l.QueryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(l.GetProcAddress("eglQueryDevicesEXT"));
        l.QueryDeviceString =
            reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(l.GetProcAddress("eglQueryDeviceStringEXT"));
        if (l.QueryDevices == nullptr || l.QueryDeviceString == nullptr) {
            l.error = "libEGL.so.1 does not resolve eglQueryDevicesEXT";
            return l;
        }
        l.loaded = detail::loadGlEntryPoints(l.gl, eglProc, &l, "eglGetProcAddress", l.error);
        return l;
    }();
    return library;
}

std::string eglErrorText(const EglLibrary& l)
{
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", unsigned(l.GetError()));
    return std::string(" (EGL error ") + code + ")";
}

/// An initialized display on one device, with the config Q3 draws with.
struct EglDevice {
    bool ready = false;
    bool software = true;
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLConfig config = nullptr;
    std::string error;
};

// With contextMutex() held. Each kind of device is initialized once and
// never terminated: eglTerminate would destroy every other renderer's
// contexts on the display.
const EglDevice& eglDevice(const EglLibrary& l, bool software)
{
    static EglDevice devices[2];
    EglDevice& device = devices[software ? 0 : 1];
    if (device.ready || !device.error.empty())
        return device;
    device.software = software;
    EGLint count = 0;
    if (!l.QueryDevices(0, nullptr, &count) || count <= 0) {
        device.error = "EGL lists no device" + eglErrorText(l);
        return device;
    }
    std::vector<EGLDeviceEXT> all(static_cast<std::size_t>(count));
    l.QueryDevices(count, all.data(), &count);
    EGLDeviceEXT chosen = EGL_NO_DEVICE_EXT;
    for (EGLint i = 0; i < count && chosen == EGL_NO_DEVICE_EXT; ++i) {
        const char* extensions = l.QueryDeviceString(all[std::size_t(i)], EGL_EXTENSIONS);
        const bool isSoftware =
            extensions != nullptr && std::strstr(extensions, "EGL_MESA_device_software") != nullptr;
        if (isSoftware == software)
            chosen = all[std::size_t(i)];
    }
    if (chosen == EGL_NO_DEVICE_EXT) {
        device.error = software ? "EGL has no software device (Mesa's EGL_MESA_device_software)"
                                : "EGL has no GPU device (Q3_EGL_DEVICE=gpu)";
        return device;
    }
    device.display = l.GetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, chosen, nullptr);
    EGLint major = 0, minor = 0;
    if (device.display == EGL_NO_DISPLAY || !l.Initialize(device.display, &major, &minor)) {
        device.error = "eglInitialize failed on the EGL device" + eglErrorText(l);
        return device;
    }
    // RGBA8 and a 24-bit depth buffer, as the OSMesa backend's context.
    const EGLint wanted[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                             EGL_RED_SIZE,     8,               EGL_GREEN_SIZE,      8,
                             EGL_BLUE_SIZE,    8,               EGL_ALPHA_SIZE,      8,
                             EGL_DEPTH_SIZE,   24,              EGL_SAMPLE_BUFFERS,  0,
                             EGL_NONE};
    EGLint matched = 0;
    l.ChooseConfig(device.display, wanted, nullptr, 0, &matched);
    std::vector<EGLConfig> configs(static_cast<std::size_t>(std::max<EGLint>(matched, 0)));
    if (matched > 0)
        l.ChooseConfig(device.display, wanted, configs.data(), matched, &matched);
    for (EGLConfig config : configs) {
        EGLint red = 0, green = 0, blue = 0, alpha = 0, depth = 0;
        l.GetConfigAttrib(device.display, config, EGL_RED_SIZE, &red);
        l.GetConfigAttrib(device.display, config, EGL_GREEN_SIZE, &green);
        l.GetConfigAttrib(device.display, config, EGL_BLUE_SIZE, &blue);
        l.GetConfigAttrib(device.display, config, EGL_ALPHA_SIZE, &alpha);
        l.GetConfigAttrib(device.display, config, EGL_DEPTH_SIZE, &depth);
        if (red == 8 && green == 8 && blue == 8 && alpha == 8 && depth == 24) {
            device.config = config;
            break;
        }
    }
    if (device.config == nullptr) {
        device.error = "the EGL device has no RGBA8 pbuffer config with a 24-bit depth buffer";
        return device;
    }
    device.ready = true;
    return device;
}

/// Invariant: m_context and m_surface are live on m_display, the surface
/// m_width x m_height.
class EglContext final : public GlContext {
public:
    EglContext(EGLDisplay display, EGLContext context, EGLSurface surface, std::uint32_t width,
               std::uint32_t height, bool bgra)
        : m_display(display), m_context(context), m_surface(surface), m_width(width), m_height(height), m_bgra(bgra)
    {
    }

    ~EglContext() override
    {
        if (renderingShutDown())
            return;
        std::lock_guard<std::mutex> lock(detail::contextMutex());
        egl().DestroySurface(m_display, m_surface);
        egl().DestroyContext(m_display, m_context);
    }

    // EGL keeps one current context per thread and client API: the one of
    // the API bound now is remembered (an application drawing with OpenGL
    // ES has that API bound), with its display and surfaces.
    bool makeCurrent(std::uint8_t*) override
    {
        if (renderingShutDown())
            return false;
        const EglLibrary& l = egl();
        // GLVND refuses an EGL context while a GLX one is current.
        m_foreign = releaseWindowSystemContext(false, true);
        m_previousApi = l.QueryAPI();
        m_previousContext = l.GetCurrentContext();
        m_previousDisplay = l.GetCurrentDisplay();
        m_previousDraw = l.GetCurrentSurface(EGL_DRAW);
        m_previousRead = l.GetCurrentSurface(EGL_READ);
        return l.BindAPI(EGL_OPENGL_API) && l.MakeCurrent(m_display, m_surface, m_surface, m_context);
    }

    void restorePrevious() override
    {
        if (renderingShutDown())
            return;
        const EglLibrary& l = egl();
        if (m_previousContext != EGL_NO_CONTEXT) {
            l.BindAPI(m_previousApi);
            l.MakeCurrent(m_previousDisplay, m_previousDraw, m_previousRead, m_previousContext);
        } else {
            l.MakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            l.BindAPI(m_previousApi);
        }
        m_previousContext = EGL_NO_CONTEXT;
        restoreWindowSystemContext(m_foreign);
        m_foreign = WindowSystemBinding{};
    }

    // glReadPixels waits for the drawing; OpenGL's rows start at the bottom.
    bool setRowPixels(std::uint32_t rowPixels) override
    {
        m_rowPixels = rowPixels;
        return true;
    }

    // Read back bottom row first, as OpenGL gives it, in the context's
    // layout, then the rows swapped top to bottom.
    void finish(std::uint8_t* image) override
    {
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glPixelStorei(GL_PACK_ROW_LENGTH, GLint(m_rowPixels));
        glReadPixels(0, 0, GLsizei(m_width), GLsizei(m_height), m_bgra ? GL_BGRA : GL_RGBA, GL_UNSIGNED_BYTE, image);
        glPixelStorei(GL_PACK_ROW_LENGTH, 0);
        const std::size_t rowBytes = std::size_t(m_rowPixels != 0 ? m_rowPixels : m_width) * 4;
        const std::size_t usedBytes = std::size_t(m_width) * 4;
        for (std::uint32_t top = 0, bottom = m_height - 1; top < bottom; ++top, --bottom)
            std::swap_ranges(image + top * rowBytes, image + top * rowBytes + usedBytes, image + bottom * rowBytes);
    }

    const GlApi& api() const override { return egl().gl; }

private:
    EGLDisplay m_display;
    EGLContext m_context;
    EGLSurface m_surface;
    std::uint32_t m_width, m_height;
    bool m_bgra;                  // finish reads B, G, R, A
    std::uint32_t m_rowPixels = 0; // the image's rows apart (0: the width)
    EGLenum m_previousApi = EGL_OPENGL_ES_API;
    EGLContext m_previousContext = EGL_NO_CONTEXT;
    EGLDisplay m_previousDisplay = EGL_NO_DISPLAY;
    EGLSurface m_previousDraw = EGL_NO_SURFACE;
    EGLSurface m_previousRead = EGL_NO_SURFACE;
    WindowSystemBinding m_foreign;
};

} // namespace

namespace detail {

bool eglAvailable()
{
    return egl().loaded;
}

RenderResult createEglContext(std::uint32_t width, std::uint32_t height, std::uint8_t* image, bool bgra,
                              std::unique_ptr<GlContext>& out)
{
    const EglLibrary& l = egl();
    if (!l.loaded)
        return RenderResult::failure(RenderStatus::kContextFailure, l.error);
    const char* deviceName = std::getenv("Q3_EGL_DEVICE");
    bool software = true;
    if (deviceName != nullptr && deviceName[0] != '\0' && std::strcmp(deviceName, "software") != 0) {
        if (std::strcmp(deviceName, "gpu") != 0)
            return RenderResult::failure(RenderStatus::kContextFailure,
                                         std::string("Q3_EGL_DEVICE='") + deviceName +
                                             "' is not an EGL device kind: use software or gpu, or unset it");
        software = false;
    }
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext raw = EGL_NO_CONTEXT;
    EGLSurface surface = EGL_NO_SURFACE;
    {
        std::lock_guard<std::mutex> lock(contextMutex());
        pinMesaEnvironmentLocked();
        const EglDevice& device = eglDevice(l, software);
        if (!device.ready)
            return RenderResult::failure(RenderStatus::kContextFailure, device.error);
        display = device.display;
        const EGLenum previousApi = l.QueryAPI();
        l.BindAPI(EGL_OPENGL_API);
        raw = l.CreateContext(display, device.config, EGL_NO_CONTEXT, nullptr);
        l.BindAPI(previousApi);
        if (raw == EGL_NO_CONTEXT)
            return RenderResult::failure(RenderStatus::kContextFailure,
                                         "eglCreateContext failed for an OpenGL context" + eglErrorText(l));
        const EGLint size[] = {EGL_WIDTH, EGLint(width), EGL_HEIGHT, EGLint(height), EGL_NONE};
        surface = l.CreatePbufferSurface(display, device.config, size);
        if (surface == EGL_NO_SURFACE) {
            const std::string why = eglErrorText(l);
            l.DestroyContext(display, raw);
            return RenderResult::failure(RenderStatus::kContextFailure,
                                         "eglCreatePbufferSurface failed for " + std::to_string(width) + " x " +
                                             std::to_string(height) + " pixels" + why);
        }
    }
    auto context = std::make_unique<EglContext>(display, raw, surface, width, height, bgra);
    return finishNewContext(
        std::move(context), image, software, "EGL", [] {}, [&] { return "eglMakeCurrent failed" + eglErrorText(l); },
        out);
}

} // namespace detail
} // namespace q3

#endif
