// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The application's own OpenGL context, for the GL draw context
// (Q3GLDrawContext.h; base/GlFramebuffer.h declares these calls).
//
// Design. The frame is drawn as for a pixmap, in Q3's own context (OSMesa
// or EGL, OffscreenRenderer), and only the finished pixels go through the
// application's context: uploaded into a texture of Q3's and blitted
// (glBlitFramebuffer) into the framebuffer the application has bound to
// GL_DRAW_FRAMEBUFFER. Drawing with the application's context itself was
// not chosen: Q3's drawing needs a compatibility-profile context (client
// arrays, fixed-function calls) where SDL, GLFW and Qt programs often have a
// core-profile or OpenGL ES one; its programs, buffers and textures would
// live among the application's objects; it would touch nearly every piece of
// GL state; and the picture would depend on the application's driver,
// where this way it is the pixmap draw context's picture, pixel for pixel.
// The price is one upload per frame.
//
// Which context. The one current on the calling thread, through EGL
// (eglGetCurrentContext, for the API bound now) or else GLX
// (glXGetCurrentContext). Neither library is loaded by Q3 for this: only a
// libEGL.so.1, libGLX.so.0 or libGL.so.1 the application has loaded is
// looked at (RTLD_NOLOAD). The GL functions come from that library's
// eglGetProcAddress or glXGetProcAddressARB (GlApi.h says why never by
// global name). While Q3's own context draws, the application's is released
// and then bound again (releaseWindowSystemContext, AppGlContext.h), so it
// is current, with all its state, whenever the application or this file
// calls OpenGL.
//
// GL state. Only what the calls below need is changed, saved first with
// glGet* and set back afterwards, in reverse order:
//   writing: GL_READ_FRAMEBUFFER_BINDING (Q3's framebuffer holding the
//     texture), GL_TEXTURE_BINDING_2D of the active texture unit (the
//     active unit itself is not changed), GL_PIXEL_UNPACK_BUFFER_BINDING,
//     GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS,
//     GL_UNPACK_SKIP_PIXELS, and the enables that affect a blit (the only
//     fragment operations that do, by the OpenGL specification, 18.3.2):
//     GL_SCISSOR_TEST and, on desktop OpenGL, GL_FRAMEBUFFER_SRGB.
//   reading (kQ3ClearMethodNone, a mask): GL_READ_FRAMEBUFFER_BINDING (the
//     draw framebuffer), that framebuffer's GL_READ_BUFFER (its first draw
//     buffer), GL_PIXEL_PACK_BUFFER_BINDING, GL_PACK_ALIGNMENT,
//     GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS.
// The texture and framebuffer object are created and deleted within the
// call; every other binding, the viewport, programs, vertex arrays, blend,
// depth and stencil state, masks and clear values are never touched.
// glGetError is never called, so an error the application has not yet
// fetched stays for it to fetch.

#include "base/GlFramebuffer.h"
#include "render/AppGlContext.h"

#include "render/DynamicLibrary.h"
#include "render/GlApi.h"

#include <link.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

namespace q3 {
namespace {

// EGL and GLX are declared here by their ABI (handles are pointers or XIDs)
// so that this file builds without their headers.
using ProcAddress = void (*)();
constexpr int kEglDraw = 0x3059; // EGL_DRAW
constexpr int kEglRead = 0x305A; // EGL_READ

// Each library's calls are listed once, as X(result, name, parameters):
// the list declares a Calls struct's function pointers and binds each to the
// library's symbol, kPrefix followed by its name.
#define Q3_CALL_MEMBER(Result, Name, Parameters) Result(*Name) Parameters = nullptr;
#define Q3_BIND_CALL(Result, Name, Parameters) file.bind(Name, (std::string(kPrefix) + #Name).c_str());

#define Q3_EGL_CALLS(X)                                                                                         \
    X(ProcAddress, GetProcAddress, (const char*)) X(void*, GetCurrentContext, ()) X(void*, GetCurrentDisplay, ()) \
    X(void*, GetCurrentSurface, (int)) X(unsigned, MakeCurrent, (void*, void*, void*, void*))                   \
    X(unsigned, QueryAPI, ()) X(unsigned, BindAPI, (unsigned))

struct EglCalls {
    static constexpr const char* kPrefix = "egl";
    Q3_EGL_CALLS(Q3_CALL_MEMBER)
    void bind(DynamicLibrary& file) { Q3_EGL_CALLS(Q3_BIND_CALL) }
};

#define Q3_GLX_CALLS(X)                                                                                         \
    X(ProcAddress, GetProcAddressARB, (const unsigned char*)) X(void*, GetCurrentContext, ())                   \
    X(void*, GetCurrentDisplay, ()) X(unsigned long, GetCurrentDrawable, ())                                    \
    X(unsigned long, GetCurrentReadDrawable, ())                                                                \
    X(int, MakeContextCurrent, (void*, unsigned long, unsigned long, void*))

struct GlxCalls {
    static constexpr const char* kPrefix = "glX";
    Q3_GLX_CALLS(Q3_CALL_MEMBER)
    void bind(DynamicLibrary& file) { Q3_GLX_CALLS(Q3_BIND_CALL) }
};

#undef Q3_CALL_MEMBER
#undef Q3_BIND_CALL
#undef Q3_EGL_CALLS
#undef Q3_GLX_CALLS

/// A window-system library the application has loaded, with the GL table
/// its loader resolves. Invariant once `ready`: every call and gl is bound,
/// and stay so.
template <class Calls>
struct Loader {
    std::atomic<bool> ready{false};
    /// The process's load count (loadCount) when the library was last
    /// looked for in vain.
    unsigned long long missingAt = ~0ull;
    Calls calls;
    GlApi gl;
};

void* eglProc(const char* name, void* calls)
{
    return reinterpret_cast<void*>(static_cast<EglCalls*>(calls)->GetProcAddress(name));
}

void* glxProc(const char* name, void* calls)
{
    return reinterpret_cast<void*>(
        static_cast<GlxCalls*>(calls)->GetProcAddressARB(reinterpret_cast<const unsigned char*>(name)));
}

std::mutex& loaderMutex()
{
    static std::mutex mutex;
    return mutex;
}

// How many shared objects the process has loaded so far (glibc's
// dlpi_adds, read from the first object only). A dlopen with RTLD_NOLOAD
// that finds nothing still searches the library path (9 system calls, 23
// microseconds measured), and the backends ask at every context switch;
// so a library found missing is looked for again only once the process has
// loaded something since.
unsigned long long loadCount()
{
    unsigned long long adds = 0;
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t size, void* out) {
            if (size >= offsetof(dl_phdr_info, dlpi_adds) + sizeof info->dlpi_adds)
                *static_cast<unsigned long long*>(out) = info->dlpi_adds;
            return 1;
        },
        &adds);
    return adds;
}

// Looks for the library with `find` (true: bound) unless it was found, or
// found missing with nothing loaded since.
template <class Calls, class Find>
const Loader<Calls>* loaderOf(Loader<Calls>& loader, Find find)
{
    if (loader.ready.load(std::memory_order_acquire))
        return &loader;
    std::lock_guard<std::mutex> lock(loaderMutex());
    if (loader.ready.load(std::memory_order_relaxed))
        return &loader;
    const unsigned long long adds = loadCount();
    if (adds == loader.missingAt || !find(loader)) {
        loader.missingAt = adds;
        return nullptr;
    }
    loader.ready.store(true, std::memory_order_release);
    return &loader;
}

// Bound once the application has loaded libEGL (it may do so late).
const Loader<EglCalls>* eglLoader()
{
    static Loader<EglCalls> loader;
    return loaderOf(loader, [](Loader<EglCalls>& l) {
        DynamicLibrary file("libEGL.so.1", true);
        l.calls.bind(file);
        const char* missing = nullptr;
        return file.ok() && l.gl.load(eglProc, &l.calls, missing);
    });
}

const Loader<GlxCalls>* glxLoader()
{
    static Loader<GlxCalls> loader;
    return loaderOf(loader, [](Loader<GlxCalls>& l) {
        // GLVND's libGLX.so.0, which its libGL.so.1 loads; else a libGL.so.1
        // of its own.
        for (const char* name : {"libGLX.so.0", "libGL.so.1"}) {
            DynamicLibrary file(name, true);
            l.calls.bind(file);
            const char* missing = nullptr;
            if (file.ok() && l.gl.load(glxProc, &l.calls, missing))
                return true;
        }
        return false;
    });
}

/// The thread's current context's GL table.
struct CurrentContext {
    const GlApi* gl = nullptr;
    bool es = false;
};

RenderResult contextFailure(const std::string& why)
{
    return RenderResult::failure(RenderStatus::kContextFailure, why);
}

// Whether "OpenGL ES 3.2 Mesa ..." or "4.5 (Compatibility Profile) Mesa
// ..." is version 3.0 or later.
bool versionAtLeast3(const char* version, bool& es)
{
    const char* prefix = "OpenGL ES ";
    es = std::strncmp(version, prefix, std::strlen(prefix)) == 0;
    const char* number = es ? version + std::strlen(prefix) : version;
    return std::atoi(number) >= 3;
}

GLint integer(GLenum name)
{
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value;
}

RenderResult currentContext(CurrentContext& current)
{
    const GlApi* gl = nullptr;
    if (const Loader<EglCalls>* egl = eglLoader())
        if (egl->calls.GetCurrentContext() != nullptr)
            gl = &egl->gl;
    if (gl == nullptr)
        if (const Loader<GlxCalls>* glx = glxLoader())
            if (glx->calls.GetCurrentContext() != nullptr)
                gl = &glx->gl;
    if (gl == nullptr)
        return contextFailure("no OpenGL context is current on this thread (through EGL or GLX): make the "
                              "application's context current before rendering");
    GlApiScope scope(gl);
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    bool es = false;
    if (version == nullptr || !versionAtLeast3(version, es))
        return contextFailure(std::string("the current context is OpenGL ") + (version ? version : "(no version)") +
                              "; Q3 needs OpenGL 3.0 or OpenGL ES 3.0 to blit into its framebuffer");
    // A blit into a multisampled framebuffer is an error (OpenGL 4.6,
    // 18.3.2), as is reading one.
    if (integer(GL_SAMPLE_BUFFERS) != 0)
        return contextFailure("the bound draw framebuffer is multisampled: Q3 copies its frame into single-sample "
                              "framebuffers only (bind one, such as a framebuffer object, then blit it to the "
                              "window)");
    current.gl = gl;
    current.es = es;
    return RenderResult::success();
}

/// The pixel-store parameters of one direction: reading pixels back (pack)
/// or sending them (unpack), and the buffer binding that would redirect them.
struct PixelStore {
    GLenum bufferBinding;
    GLenum buffer;
    GLenum names[4]; ///< alignment, row length, skip rows, skip pixels
};
constexpr PixelStore kPack{GL_PIXEL_PACK_BUFFER_BINDING,
                           GL_PIXEL_PACK_BUFFER,
                           {GL_PACK_ALIGNMENT, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS}};
constexpr PixelStore kUnpack{GL_PIXEL_UNPACK_BUFFER_BINDING,
                             GL_PIXEL_UNPACK_BUFFER,
                             {GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS}};

/// Sets one direction's pixel store to tightly packed rows of the client's
/// memory (alignment 4, no row length, no skips, no buffer bound) and puts
/// the previous values back.
class PixelStoreScope {
public:
    explicit PixelStoreScope(const PixelStore& store) : m_store(store), m_savedBuffer(integer(store.bufferBinding))
    {
        const GLint values[4] = {4, 0, 0, 0};
        for (int i = 0; i < 4; ++i) {
            m_saved[i] = integer(store.names[i]);
            glPixelStorei(store.names[i], values[i]);
        }
        glBindBuffer(store.buffer, 0);
    }
    ~PixelStoreScope()
    {
        glBindBuffer(m_store.buffer, GLuint(m_savedBuffer));
        for (int i = 3; i >= 0; --i)
            glPixelStorei(m_store.names[i], m_saved[i]);
    }
    PixelStoreScope(const PixelStoreScope&) = delete;
    PixelStoreScope& operator=(const PixelStoreScope&) = delete;

private:
    const PixelStore& m_store;
    GLint m_savedBuffer;
    GLint m_saved[4];
};

/// Turns a capability off and, if it was on, back on.
class DisableScope {
public:
    explicit DisableScope(GLenum capability, bool applies = true)
        : m_capability(capability), m_wasOn(applies && glIsEnabled(capability))
    {
        if (m_wasOn)
            glDisable(capability);
    }
    ~DisableScope()
    {
        if (m_wasOn)
            glEnable(m_capability);
    }
    DisableScope(const DisableScope&) = delete;
    DisableScope& operator=(const DisableScope&) = delete;

private:
    GLenum m_capability;
    bool m_wasOn;
};

// OpenGL's y of the bottom row of `rect` (y measured from the top).
GLint glBottom(const PixelRect& rect, std::uint32_t framebufferHeight)
{
    return GLint(framebufferHeight) - rect.y - rect.height;
}

} // namespace

WindowSystemBinding releaseWindowSystemContext(bool egl, bool glx)
{
    WindowSystemBinding binding;
    if (egl)
        if (const Loader<EglCalls>* loader = eglLoader()) {
            const EglCalls& c = loader->calls;
            if (void* context = c.GetCurrentContext()) {
                binding.kind = WindowSystemBinding::Kind::kEgl;
                binding.display = c.GetCurrentDisplay();
                binding.context = context;
                binding.eglDraw = c.GetCurrentSurface(kEglDraw);
                binding.eglRead = c.GetCurrentSurface(kEglRead);
                binding.eglApi = c.QueryAPI();
                c.MakeCurrent(binding.display, nullptr, nullptr, nullptr);
                return binding;
            }
        }
    if (glx)
        if (const Loader<GlxCalls>* loader = glxLoader()) {
            const GlxCalls& c = loader->calls;
            if (void* context = c.GetCurrentContext()) {
                binding.kind = WindowSystemBinding::Kind::kGlx;
                binding.display = c.GetCurrentDisplay();
                binding.context = context;
                binding.glxDraw = c.GetCurrentDrawable();
                binding.glxRead = c.GetCurrentReadDrawable();
                c.MakeContextCurrent(binding.display, 0, 0, nullptr);
            }
        }
    return binding;
}

void restoreWindowSystemContext(const WindowSystemBinding& binding)
{
    if (binding.kind == WindowSystemBinding::Kind::kEgl) {
        // Bound once already, so the loader is ready.
        const EglCalls& c = eglLoader()->calls;
        c.BindAPI(binding.eglApi);
        c.MakeCurrent(binding.display, binding.eglDraw, binding.eglRead, binding.context);
    } else if (binding.kind == WindowSystemBinding::Kind::kGlx) {
        const GlxCalls& c = glxLoader()->calls;
        c.MakeContextCurrent(binding.display, binding.glxDraw, binding.glxRead, binding.context);
    }
}

RenderResult checkCurrentGlContext()
{
    CurrentContext current;
    return currentContext(current);
}

RenderResult readGlFramebuffer(const PixelRect& rect, std::uint32_t framebufferHeight, std::uint32_t* pixels,
                               std::size_t rowPixels)
{
    CurrentContext current;
    RenderResult result = currentContext(current);
    if (!result || rect.width <= 0 || rect.height <= 0)
        return result;
    std::vector<std::uint8_t> rgba(std::size_t(rect.width) * std::size_t(rect.height) * 4);
    {
        GlApiScope scope(current.gl);
        const GLint savedRead = integer(GL_READ_FRAMEBUFFER_BINDING);
        const GLint draw = integer(GL_DRAW_FRAMEBUFFER_BINDING);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(draw));
        const GLint savedReadBuffer = integer(GL_READ_BUFFER);
        const GLint drawBuffer = integer(GL_DRAW_BUFFER0);
        if (drawBuffer == GL_NONE) {
            result = contextFailure("the bound framebuffer draws into no colour buffer (GL_DRAW_BUFFER0 is GL_NONE)");
        } else {
            glReadBuffer(GLenum(drawBuffer == GL_FRONT_AND_BACK ? GL_BACK : drawBuffer));
            if (glCheckFramebufferStatus(GL_READ_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
                result = contextFailure("the bound framebuffer is not complete");
            } else {
                const PixelStoreScope store(kPack);
                glReadPixels(rect.x, glBottom(rect, framebufferHeight), rect.width, rect.height, GL_RGBA,
                             GL_UNSIGNED_BYTE, rgba.data());
            }
            glReadBuffer(GLenum(savedReadBuffer));
        }
        glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(savedRead));
    }
    if (!result)
        return result;
    for (int row = 0; row < rect.height; ++row) {
        const std::uint8_t* from = rgba.data() + std::size_t(rect.height - 1 - row) * std::size_t(rect.width) * 4;
        std::uint32_t* to = pixels + std::size_t(rect.y + row) * rowPixels + std::size_t(rect.x);
        for (int x = 0; x < rect.width; ++x, from += 4)
            to[x] = std::uint32_t(from[3]) << 24 | std::uint32_t(from[0]) << 16 | std::uint32_t(from[1]) << 8 |
                    std::uint32_t(from[2]);
    }
    return result;
}

RenderResult writeGlFramebuffer(const PixelRect& rect, std::uint32_t framebufferHeight,
                                const std::uint32_t* pixels, std::size_t rowPixels)
{
    CurrentContext current;
    RenderResult result = currentContext(current);
    if (!result || rect.width <= 0 || rect.height <= 0)
        return result;
    // OpenGL's rows start at the bottom.
    std::vector<std::uint8_t> rgba(std::size_t(rect.width) * std::size_t(rect.height) * 4);
    for (int row = 0; row < rect.height; ++row) {
        const std::uint32_t* from = pixels + std::size_t(rect.y + row) * rowPixels + std::size_t(rect.x);
        std::uint8_t* to = rgba.data() + std::size_t(rect.height - 1 - row) * std::size_t(rect.width) * 4;
        for (int x = 0; x < rect.width; ++x, to += 4) {
            to[0] = std::uint8_t(from[x] >> 16);
            to[1] = std::uint8_t(from[x] >> 8);
            to[2] = std::uint8_t(from[x]);
            to[3] = std::uint8_t(from[x] >> 24);
        }
    }
    GlApiScope scope(current.gl);
    const GLint savedRead = integer(GL_READ_FRAMEBUFFER_BINDING);
    const GLint savedTexture = integer(GL_TEXTURE_BINDING_2D);
    GLuint texture = 0, framebuffer = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    {
        const PixelStoreScope store(kUnpack);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, rect.width, rect.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     rgba.data());
    }
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    if (glCheckFramebufferStatus(GL_READ_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        result = contextFailure("the framebuffer holding Q3's frame is not complete in the application's context");
    } else {
        const DisableScope scissor(GL_SCISSOR_TEST);
        const DisableScope srgb(GL_FRAMEBUFFER_SRGB, !current.es);
        const GLint bottom = glBottom(rect, framebufferHeight);
        glBlitFramebuffer(0, 0, rect.width, rect.height, rect.x, bottom, rect.x + rect.width, bottom + rect.height,
                          GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(savedRead));
    glDeleteFramebuffers(1, &framebuffer);
    glBindTexture(GL_TEXTURE_2D, GLuint(savedTexture));
    glDeleteTextures(1, &texture);
    return result;
}

} // namespace q3
