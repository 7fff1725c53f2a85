// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The GL draw context with a GLX application under a private Xvfb: the test
// links libGL, creates an X window and a core-profile GLX context of its own
// (double-buffered, as SDL or GLFW would), and in a loop of frames draws its
// background, has Q3 render the scene into the window's back buffer and also
// into a pixmap, draws its overlay with its own state, reads the back buffer
// and swaps. Each frame's picture is the pixmap's where Q3 drew; the GL state
// and the current GLX context, display and drawables are as the application
// left them, with either of Q3's backends (Q3's EGL context cannot be current
// while a GLX one is: it is released and bound again around Q3's drawing).

#include "AppGlTest.h"
#include "XvfbServer.h"

#include <GL/glx.h>

#include <memory>
#include <string>

namespace {

using namespace q3test;

XvfbServer* server()
{
    static std::unique_ptr<XvfbServer> instance(new XvfbServer);
    return instance.get();
}

// The application's own connection to the server, opened once and never
// closed, as an application keeps its display open while its window lives.
// Closing the last GLX connection makes Mesa unload its DRI driver before
// LeakSanitizer looks at exit, and memory that only the driver's globals
// still pointed to then shows as leaked from an unknown module (measured:
// 240 bytes in 3 blocks with the OSMesa backend; with the driver kept
// loaded, by this connection or by the EGL backend's libEGL, none).
Display* applicationDisplay()
{
    static Display* display =
        server()->display() != nullptr ? XOpenDisplay(XDisplayString(server()->display())) : nullptr;
    return display;
}

class GlxDrawContextTest : public AppGlTest {
protected:
    void SetUp() override
    {
        AppGlTest::SetUp();
        m_display = applicationDisplay();
        if (m_display == nullptr)
            GTEST_SKIP() << "no X server for the GLX test: " << server()->why();
        const std::string why = createWindowAndContext();
        if (!why.empty())
            GTEST_SKIP() << "no GLX context for the application: " << why;
    }

    void TearDown() override
    {
        if (m_display != nullptr) {
            glXMakeContextCurrent(m_display, 0, 0, nullptr);
            if (m_context != nullptr)
                glXDestroyContext(m_display, m_context);
            if (m_window != 0)
                XDestroyWindow(m_display, m_window);
            if (m_colormap != 0)
                XFreeColormap(m_display, m_colormap);
            XSync(m_display, False);
        }
        AppGlTest::TearDown();
    }

    std::string createWindowAndContext()
    {
        const int screen = DefaultScreen(m_display);
        const int wanted[] = {GLX_X_RENDERABLE, True,      GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, GLX_RENDER_TYPE,
                              GLX_RGBA_BIT,     GLX_RED_SIZE, 8,              GLX_GREEN_SIZE, 8,
                              GLX_BLUE_SIZE,    8,         GLX_ALPHA_SIZE,    8,              GLX_DEPTH_SIZE,
                              24,               GLX_DOUBLEBUFFER, True,       None};
        int count = 0;
        GLXFBConfig* configs = glXChooseFBConfig(m_display, screen, wanted, &count);
        if (configs == nullptr || count == 0)
            return "no RGBA8 double-buffered GLX config";
        const GLXFBConfig config = configs[0];
        XFree(configs);
        XVisualInfo* visual = glXGetVisualFromFBConfig(m_display, config);
        if (visual == nullptr)
            return "no visual for the GLX config";
        const Window root = RootWindow(m_display, screen);
        m_colormap = XCreateColormap(m_display, root, visual->visual, AllocNone);
        XSetWindowAttributes attributes{};
        attributes.colormap = m_colormap;
        attributes.event_mask = StructureNotifyMask;
        m_window = XCreateWindow(m_display, root, 0, 0, kWidth, kHeight, 0, visual->depth, InputOutput,
                                 visual->visual, CWColormap | CWEventMask, &attributes);
        XFree(visual);
        XMapWindow(m_display, m_window);
        XEvent event;
        do
            XWindowEvent(m_display, m_window, StructureNotifyMask, &event);
        while (event.type != MapNotify);
        auto createContext = reinterpret_cast<PFNGLXCREATECONTEXTATTRIBSARBPROC>(
            glXGetProcAddressARB(reinterpret_cast<const GLubyte*>("glXCreateContextAttribsARB")));
        if (createContext == nullptr)
            return "no glXCreateContextAttribsARB";
        const int contextAttributes[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 3,
                                         GLX_CONTEXT_PROFILE_MASK_ARB, GLX_CONTEXT_CORE_PROFILE_BIT_ARB, None};
        m_context = createContext(m_display, config, nullptr, True, contextAttributes);
        if (m_context == nullptr)
            return "no core-profile 3.3 GLX context";
        if (!glXMakeContextCurrent(m_display, m_window, m_window, m_context))
            return "glXMakeContextCurrent failed";
        return {};
    }

    void expectApplicationContextCurrent() override
    {
        EXPECT_EQ(glXGetCurrentContext(), m_context);
        EXPECT_EQ(glXGetCurrentDisplay(), m_display);
        EXPECT_EQ(glXGetCurrentDrawable(), m_window);
        EXPECT_EQ(glXGetCurrentReadDrawable(), m_window);
    }

    Display* m_display = nullptr;
    Window m_window = 0;
    Colormap m_colormap = 0;
    GLXContext m_context = nullptr;
};

TEST_F(GlxDrawContextTest, FramesInTheWindowAreThePixmapsAndKeepTheApplicationsState)
{
    for (int frame = 0; frame < 3; ++frame) {
        const TQ3DrawContextClearImageMethod clear = frame == 1 ? kQ3ClearMethodNone : kQ3ClearMethodWithColor;
        const std::vector<std::uint32_t> pixmap = pixmapPicture(clear);
        const std::vector<std::uint32_t> window = applicationFrame(clear);
        expectPicture(window, pixmap);
        glXSwapBuffers(m_display, m_window);
    }
}

} // namespace
