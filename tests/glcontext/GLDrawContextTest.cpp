// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The GL draw context (Q3GLDrawContext.h), headless: the test is the
// application. It makes its own EGL context current (a core-profile OpenGL
// 3.3 context on Mesa's software EGL device, a pbuffer of its own), sets GL
// state of its own, draws a background, has Q3 render a scene into its
// framebuffer, then draws an overlay with its own program. Checked: the
// scene's pixels are those of a pixmap draw context given the same data
// (byte for byte: both are the same llvmpipe frame), the background outside
// the pane and the overlay are there, every GL state value the test reads is
// as it set it, its context and surfaces are still current, and a GL error it
// had not fetched is still pending. Bad input posts a QuickDraw 3D error.

#include "AppGlTest.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace q3test;

// The application's EGL context: core profile 3.3, RGBA8 and a depth
// buffer, on Mesa's software device, with a pbuffer of its own.
struct AppContext {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    EGLSurface surface = EGL_NO_SURFACE;
    std::string why;

    bool create(int width, int height)
    {
        auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        auto deviceString =
            reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
        if (queryDevices == nullptr || deviceString == nullptr)
            return fail("libEGL has no EGL_EXT_device_enumeration");
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        queryDevices(16, devices, &count);
        EGLDeviceEXT software = EGL_NO_DEVICE_EXT;
        for (EGLint i = 0; i < count; ++i) {
            const char* extensions = deviceString(devices[i], EGL_EXTENSIONS);
            if (extensions != nullptr && std::strstr(extensions, "EGL_MESA_device_software") != nullptr)
                software = devices[i];
        }
        if (software == EGL_NO_DEVICE_EXT)
            return fail("no software EGL device");
        display = eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, software, nullptr);
        if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr))
            return fail("eglInitialize failed");
        const EGLint wanted[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                 EGL_RED_SIZE,     8,               EGL_GREEN_SIZE,      8,
                                 EGL_BLUE_SIZE,    8,               EGL_ALPHA_SIZE,      8,
                                 EGL_DEPTH_SIZE,   24,              EGL_NONE};
        EGLConfig config = nullptr;
        EGLint matched = 0;
        if (!eglChooseConfig(display, wanted, &config, 1, &matched) || matched == 0)
            return fail("no RGBA8 pbuffer config");
        eglBindAPI(EGL_OPENGL_API);
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
        if (context == EGL_NO_CONTEXT)
            return fail("no core-profile 3.3 context");
        const EGLint size[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
        surface = eglCreatePbufferSurface(display, config, size);
        if (surface == EGL_NO_SURFACE)
            return fail("no pbuffer");
        return eglMakeCurrent(display, surface, surface, context) || fail("eglMakeCurrent failed");
    }

    bool fail(const char* reason)
    {
        why = reason;
        return false;
    }

    ~AppContext()
    {
        if (display == EGL_NO_DISPLAY)
            return;
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (surface != EGL_NO_SURFACE)
            eglDestroySurface(display, surface);
        if (context != EGL_NO_CONTEXT)
            eglDestroyContext(display, context);
    }
};

class GLDrawContextTest : public AppGlTest {
protected:
    void SetUp() override
    {
        AppGlTest::SetUp();
        if (!m_app.create(kWidth, kHeight))
            GTEST_SKIP() << "no EGL context for the application: " << m_app.why;
    }

    void expectApplicationContextCurrent() override
    {
        EXPECT_EQ(eglGetCurrentContext(), m_app.context);
        EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), m_app.surface);
        EXPECT_EQ(eglGetCurrentSurface(EGL_READ), m_app.surface);
        EXPECT_EQ(eglGetCurrentDisplay(), m_app.display);
        EXPECT_EQ(eglQueryAPI(), EGLenum(EGL_OPENGL_API));
    }

    AppContext m_app;
};

TEST_F(GLDrawContextTest, FrameInTheWindowFramebufferIsThePixmapsAndKeepsTheApplicationsState)
{
    const std::vector<std::uint32_t> app = applicationFrame(kQ3ClearMethodWithColor);
    expectPicture(app, pixmapPicture(kQ3ClearMethodWithColor));
}

TEST_F(GLDrawContextTest, WithoutAClearTheApplicationsBackgroundStays)
{
    const std::vector<std::uint32_t> app = applicationFrame(kQ3ClearMethodNone);
    const std::vector<std::uint32_t> pixmap = pixmapPicture(kQ3ClearMethodNone);
    expectPicture(app, pixmap);
    // The scene does not cover the whole pane: some of it is background.
    std::size_t background = 0;
    for (int y = kPaneY0; y < kPaneY1; ++y)
        for (int x = kPaneX0; x < kPaneX1; ++x)
            background += app[std::size_t(y) * kWidth + x] == kBackground;
    EXPECT_GT(background, 100u);
}

TEST_F(GLDrawContextTest, FrameGoesIntoTheApplicationsFramebufferObject)
{
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    GLuint framebuffer = 0, colour = 0;
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kWidth, kHeight);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    const std::vector<std::uint32_t> app = applicationFrame(kQ3ClearMethodNone);
    EXPECT_EQ(GlState::integer(GL_DRAW_FRAMEBUFFER_BINDING), GLint(framebuffer));
    expectPicture(app, pixmapPicture(kQ3ClearMethodNone));
    // The window's framebuffer was not drawn into: still transparent black.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const std::vector<std::uint32_t> window = readFramebuffer(kWidth, kHeight);
    EXPECT_EQ(std::count(window.begin(), window.end(), 0u), std::ptrdiff_t(window.size()));
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteRenderbuffers(1, &colour);
}

TEST_F(GLDrawContextTest, OpenGLESContextGetsThePixmapsPicture)
{
    const EGLint wanted[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT,
                             EGL_RED_SIZE,     8,               EGL_GREEN_SIZE,      8,
                             EGL_BLUE_SIZE,    8,               EGL_ALPHA_SIZE,      8,
                             EGL_NONE};
    EGLConfig config = nullptr;
    EGLint matched = 0;
    if (!eglChooseConfig(m_app.display, wanted, &config, 1, &matched) || matched == 0)
        GTEST_SKIP() << "no OpenGL ES 3 pbuffer config";
    eglBindAPI(EGL_OPENGL_ES_API);
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
    EGLContext es = eglCreateContext(m_app.display, config, EGL_NO_CONTEXT, attributes);
    const EGLint size[] = {EGL_WIDTH, kWidth, EGL_HEIGHT, kHeight, EGL_NONE};
    EGLSurface surface = eglCreatePbufferSurface(m_app.display, config, size);
    ASSERT_NE(es, EGL_NO_CONTEXT);
    ASSERT_NE(surface, EGL_NO_SURFACE);
    ASSERT_TRUE(eglMakeCurrent(m_app.display, surface, surface, es));

    glClearColor(0x33 / 255.0f, 0x66 / 255.0f, 0xCC / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(3, 4, 5, 6);
    const GLint scissorBefore = GlState::integer(GL_SCISSOR_TEST);
    const TQ3GLDrawContextData data = glData();
    TQ3DrawContextObject context = Q3GLDrawContext_New(&data);
    EXPECT_EQ(render(context), kQ3ViewStatusDone);
    Q3Object_Dispose(context);
    EXPECT_EQ(eglGetCurrentContext(), es);
    EXPECT_EQ(eglQueryAPI(), EGLenum(EGL_OPENGL_ES_API));
    EXPECT_EQ(GlState::integer(GL_SCISSOR_TEST), scissorBefore);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    // The overlay, as a scissored clear.
    glScissor(kOverlayX0, kHeight - kOverlayY1, kOverlayX1 - kOverlayX0, kOverlayY1 - kOverlayY0);
    glClearColor(1.0f, 0xCC / 255.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    expectPicture(readFramebuffer(kWidth, kHeight), pixmapPicture(kQ3ClearMethodWithColor));

    eglMakeCurrent(m_app.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroySurface(m_app.display, surface);
    eglDestroyContext(m_app.display, es);
    eglBindAPI(EGL_OPENGL_API);
}

TEST_F(GLDrawContextTest, NoCurrentContextIsAnError)
{
    eglMakeCurrent(m_app.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    const TQ3GLDrawContextData data = glData();
    TQ3DrawContextObject context = Q3GLDrawContext_New(&data);
    ASSERT_NE(context, nullptr);
    {
        SceneView scene(context);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_StartRendering(scene.view), kQ3Failure), kQ3ErrorBadDrawContext);
    }
    EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
    Q3Object_Dispose(context);
}

TEST_F(GLDrawContextTest, MultisampledFramebufferIsAnError)
{
    GLuint framebuffer = 0, colour = 0;
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, kWidth, kHeight);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    const TQ3GLDrawContextData data = glData();
    TQ3DrawContextObject context = Q3GLDrawContext_New(&data);
    {
        SceneView scene(context);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_StartRendering(scene.view), kQ3Failure), kQ3ErrorBadDrawContext);
    }
    Q3Object_Dispose(context);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteRenderbuffers(1, &colour);
}

TEST_F(GLDrawContextTest, NewChecksItsData)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GLDrawContext_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    for (const auto& size : {std::array<TQ3Uns32, 2>{0, 10}, {10, 0}, {16385, 10}, {10, 16385}, {UINT32_MAX, 1}}) {
        TQ3GLDrawContextData data = glData();
        data.width = size[0];
        data.height = size[1];
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3GLDrawContext_New(&data), nullptr), kQ3ErrorInvalidData);
    }
    TQ3GLDrawContextData data = glData();
    data.drawContextData.pane = {{50.0f, 10.0f}, {20.0f, 100.0f}}; // min.x > max.x
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GLDrawContext_New(&data), nullptr), kQ3ErrorInvalidData);
    data = glData();
    data.drawContextData.pane.max.x = NAN;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GLDrawContext_New(&data), nullptr), kQ3ErrorInvalidData);
    data = glData();
    data.drawContextData.clearImageMethod = static_cast<TQ3DrawContextClearImageMethod>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GLDrawContext_New(&data), nullptr), kQ3ErrorInvalidData);
    data.width = data.height = 16384;
    data.drawContextData.clearImageMethod = kQ3ClearMethodNone;
    TQ3DrawContextObject largest = Q3GLDrawContext_New(&data);
    EXPECT_NE(largest, nullptr);
    Q3Object_Dispose(largest);
}

TEST_F(GLDrawContextTest, SizeAndTypeAndDuplicate)
{
    const TQ3GLDrawContextData data = glData();
    TQ3DrawContextObject context = Q3GLDrawContext_New(&data);
    ASSERT_NE(context, nullptr);
    EXPECT_EQ(Q3DrawContext_GetType(context), kQ3DrawContextTypeGL);
    TQ3Uns32 width = 0, height = 0;
    EXPECT_EQ(Q3GLDrawContext_GetSize(context, &width, &height), kQ3Success);
    EXPECT_EQ(width, TQ3Uns32(kWidth));
    EXPECT_EQ(height, TQ3Uns32(kHeight));
    EXPECT_EQ(Q3GLDrawContext_SetSize(context, 640, 480), kQ3Success);
    for (const auto& size : {std::array<TQ3Uns32, 2>{0, 1}, {1, 0}, {16385, 1}, {1, UINT32_MAX}})
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3GLDrawContext_SetSize(context, size[0], size[1]), kQ3Failure),
                        kQ3ErrorInvalidParameter);
    TQ3DrawContextObject copy = Q3Object_Duplicate(context);
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(Q3GLDrawContext_GetSize(copy, &width, &height), kQ3Success);
    EXPECT_EQ(width, 640u);
    EXPECT_EQ(height, 480u);
    TQ3DrawContextData copied{};
    EXPECT_EQ(Q3DrawContext_GetData(copy, &copied), kQ3Success);
    EXPECT_EQ(copied.pane.min.x, float(kPaneX0));
    EXPECT_EQ(copied.pane.max.y, float(kPaneY1));

    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GLDrawContext_GetSize(context, nullptr, &height), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GLDrawContext_GetSize(context, &width, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GLDrawContext_GetSize(nullptr, &width, &height), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GLDrawContext_SetSize(nullptr, 1, 1), kQ3Failure), kQ3ErrorNULLParameter);
    Pixmap image(4, 4);
    const TQ3PixmapDrawContextData pixmapData{contextData(kQ3ClearMethodNone), image.pixmap()};
    TQ3DrawContextObject pixmap = Q3PixmapDrawContext_New(&pixmapData);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GLDrawContext_SetSize(pixmap, 1, 1), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GLDrawContext_GetSize(pixmap, &width, &height), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    for (TQ3Object object : {context, copy, pixmap})
        Q3Object_Dispose(object);
}

} // namespace
