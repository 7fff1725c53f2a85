// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Apple's X11 draw context under a private Xvfb: a scene drawn into a window
// and read back with XGetImage is the scene drawn into a pixmap of the
// window's size, with and without a pane; a resized window is filled by the
// next frame; bad displays, drawables and visuals are errors, never a crash.

#include <gtest/gtest.h>

// Apple's X11 declarations (this tree builds C++ without them, for GoogleTest
// whose names Xlib's macros would break: src/CMakeLists.txt).
#undef WINDOW_SYSTEM_X11
#define WINDOW_SYSTEM_X11 1
#include "BoxAndTriangle.h"
#include "RenderTestSupport.h"
#include "XvfbServer.h"

#include "QD3DGroup.h"
#include "QD3DIO.h"
#include "QD3DPick.h"
#include "QD3DLight.h"
#include "QD3DSet.h"

#include <X11/Xutil.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace {

using namespace q3test;
// Xlib has a Pixmap too.
using Image = q3test::Pixmap;

// One server for the whole program: starting Xvfb takes a while.
XvfbServer* server()
{
    static std::unique_ptr<XvfbServer> instance(new XvfbServer);
    return instance.get();
}

class X11DrawContextTest : public Q3ApiTest {
protected:
    void SetUp() override
    {
        Q3ApiTest::SetUp();
        m_display = server()->display();
        if (m_display == nullptr)
            GTEST_SKIP() << "no X server for the X11 draw context tests: " << server()->why();
    }
    void TearDown() override
    {
        for (Window window : m_windows)
            XDestroyWindow(m_display, window);
        if (m_display != nullptr)
            XSync(m_display, False);
        Q3ApiTest::TearDown();
    }

    // A mapped window at the screen's origin, black, of the default visual.
    Window makeWindow(unsigned width, unsigned height)
    {
        const int screen = DefaultScreen(m_display);
        const Window window = XCreateSimpleWindow(m_display, RootWindow(m_display, screen), 0, 0, width, height, 0,
                                                  BlackPixel(m_display, screen), BlackPixel(m_display, screen));
        XSelectInput(m_display, window, StructureNotifyMask);
        XMapWindow(m_display, window);
        XEvent event;
        do
            XWindowEvent(m_display, window, StructureNotifyMask, &event);
        while (event.type != MapNotify);
        m_windows.push_back(window);
        return window;
    }

    static TQ3DrawContextData contextData()
    {
        TQ3DrawContextData data{};
        data.clearImageMethod = kQ3ClearMethodWithColor;
        data.clearImageColor = {1.0f, 0.2f, 0.6f, 0.4f};
        data.paneState = kQ3False;
        data.maskState = kQ3False;
        data.doubleBufferState = kQ3True;
        return data;
    }

    TQ3XDrawContextData xData(Window window) const
    {
        TQ3XDrawContextData data{};
        data.contextData = contextData();
        data.display = m_display;
        data.drawable = window;
        data.visual = nullptr;
        data.cmap = 0;
        data.colorMapData = nullptr;
        return data;
    }

    // The test scene: a lit box and a triangle with a colour per vertex,
    // seen in perspective.
    static void submitScene(TQ3ViewObject view) { q3test::submitBoxAndTriangle(view); }

    // Renders the scene through a view with `context`, a perspective camera
    // for width x height and a directional light.
    static void render(TQ3DrawContextObject context, unsigned width, unsigned height)
    {
        TQ3ViewObject view = Q3View_New();
        const TQ3ViewAngleAspectCameraData cameraData =
            viewAngleCamera({2.0, 1.5, 4.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0.8, double(width) / height);
        TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&cameraData);
        TQ3RendererObject renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
        TQ3GroupObject lights = Q3LightGroup_New();
        TQ3DirectionalLightData lightData{{kQ3True, 1.0f, {1.0f, 1.0f, 1.0f}}, kQ3False, {-0.3f, -0.5f, -1.0f}};
        TQ3LightObject light = Q3DirectionalLight_New(&lightData);
        Q3Group_AddObject(lights, light);
        Q3View_SetDrawContext(view, context);
        Q3View_SetCamera(view, camera);
        Q3View_SetRenderer(view, renderer);
        Q3View_SetLightGroup(view, lights);
        ASSERT_EQ(Q3View_StartRendering(view), kQ3Success);
        TQ3ViewStatus status;
        do {
            submitScene(view);
            status = Q3View_EndRendering(view);
        } while (status == kQ3ViewStatusRetraverse);
        EXPECT_EQ(status, kQ3ViewStatusDone);
        for (TQ3Object object : {view, camera, renderer, lights, light})
            Q3Object_Dispose(object);
    }

    // The window's pixels as 0xRRGGBB, read with XGetImage (24-bit TrueColor).
    std::vector<std::uint32_t> readWindow(Window window, unsigned width, unsigned height) const
    {
        XImage* image = XGetImage(m_display, window, 0, 0, width, height, AllPlanes, ZPixmap);
        std::vector<std::uint32_t> pixels;
        if (image == nullptr)
            return pixels;
        for (unsigned y = 0; y < height; ++y)
            for (unsigned x = 0; x < width; ++x)
                pixels.push_back(std::uint32_t(XGetPixel(image, int(x), int(y))) & 0xFFFFFFu);
        XDestroyImage(image);
        return pixels;
    }

    static std::vector<std::uint32_t> rgbOf(const Image& pixmap)
    {
        std::vector<std::uint32_t> pixels;
        for (unsigned long y = 0; y < pixmap.height(); ++y)
            for (unsigned long x = 0; x < pixmap.width(); ++x)
                pixels.push_back(pixmap.word(x, y) & 0xFFFFFFu);
        return pixels;
    }

    // After a frame into `window`: the same frame drawn into a pixmap with
    // `contextData` (starting black, as a new window does, if `fromBlack`)
    // matches the window pixel for pixel. Returns the window's pixels.
    std::vector<std::uint32_t> expectWindowMatchesPixmap(Window window, const TQ3DrawContextData& contextData,
                                                         unsigned width, unsigned height, bool fromBlack)
    {
        XSync(m_display, False);
        Image pixmap(width, height);
        if (fromBlack)
            pixmap.fill(0);
        TQ3PixmapDrawContextData pixmapData{contextData, pixmap.pixmap()};
        TQ3DrawContextObject pixmapContext = Q3PixmapDrawContext_New(&pixmapData);
        render(pixmapContext, width, height);
        Q3Object_Dispose(pixmapContext);
        const std::vector<std::uint32_t> shown = readWindow(window, width, height);
        expectSamePicture(shown, rgbOf(pixmap));
        return shown;
    }

    // How many pixels differ, and that the picture is not one colour.
    static void expectSamePicture(const std::vector<std::uint32_t>& window, const std::vector<std::uint32_t>& pixmap)
    {
        ASSERT_EQ(window.size(), pixmap.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < window.size(); ++i)
            differing += window[i] != pixmap[i];
        EXPECT_EQ(differing, 0u) << "of " << window.size() << " pixels";
        std::vector<std::uint32_t> colours(pixmap);
        std::sort(colours.begin(), colours.end());
        EXPECT_GT(std::unique(colours.begin(), colours.end()) - colours.begin(), 100)
            << "the scene should have many colours";
    }

    Display* m_display = nullptr;
    std::vector<Window> m_windows;
};

TEST_F(X11DrawContextTest, WindowShowsThePixmapPicture)
{
    const unsigned width = 240, height = 180;
    const Window window = makeWindow(width, height);
    const TQ3XDrawContextData data = xData(window);
    TQ3DrawContextObject context = Q3XDrawContext_New(&data);
    ASSERT_NE(context, nullptr);
    EXPECT_EQ(Q3DrawContext_GetType(context), kQ3DrawContextTypeX11);
    render(context, width, height);
    expectWindowMatchesPixmap(window, contextData(), width, height, false);
    Q3Object_Dispose(context);
}

TEST_F(X11DrawContextTest, PaneAndNoClearLeaveTheRestOfTheWindow)
{
    const unsigned width = 200, height = 160;
    const Window window = makeWindow(width, height);
    TQ3XDrawContextData data = xData(window);
    data.contextData.paneState = kQ3True;
    data.contextData.pane = {{30.0f, 20.0f}, {170.0f, 130.0f}};
    data.contextData.clearImageMethod = kQ3ClearMethodNone;
    TQ3DrawContextObject context = Q3XDrawContext_New(&data);
    ASSERT_NE(context, nullptr);
    render(context, width, height);
    // The pixmap starts as the window did: black.
    const std::vector<std::uint32_t> shown = expectWindowMatchesPixmap(window, data.contextData, width, height, true);
    // Outside the pane the window is still black.
    ASSERT_EQ(shown.size(), std::size_t(width) * height);
    EXPECT_EQ(shown[5 * width + 5], 0u);
    EXPECT_EQ(shown[150 * width + 190], 0u);
    Q3Object_Dispose(context);
}

TEST_F(X11DrawContextTest, MaskKeepsTheWindowWhereItsBitsAreClear)
{
    const unsigned width = 160, height = 120;
    const Window window = makeWindow(width, height);
    // Bits set in the left half of each row only.
    const unsigned long rowBytes = width / 8;
    std::vector<unsigned char> bits(rowBytes * height, 0);
    for (unsigned y = 0; y < height; ++y)
        for (unsigned long x = 0; x < rowBytes / 2; ++x)
            bits[y * rowBytes + x] = 0xFF;
    TQ3XDrawContextData data = xData(window);
    data.contextData.mask = TQ3Bitmap{bits.data(), width, height, rowBytes, kQ3EndianBig};
    data.contextData.maskState = kQ3True;
    TQ3DrawContextObject context = Q3XDrawContext_New(&data);
    ASSERT_NE(context, nullptr);
    render(context, width, height);
    const std::vector<std::uint32_t> shown = expectWindowMatchesPixmap(window, data.contextData, width, height, true);
    ASSERT_EQ(shown.size(), std::size_t(width) * height);
    EXPECT_EQ(shown[0], 0x339966u);              // masked in: the clear colour
    EXPECT_EQ(shown[width - 1], 0u);             // masked out: still black
    EXPECT_EQ(shown[(height - 1) * width + width / 2], 0u);
    Q3Object_Dispose(context);
}

TEST_F(X11DrawContextTest, NextFrameFillsAResizedWindow)
{
    const Window window = makeWindow(160, 120);
    const TQ3XDrawContextData data = xData(window);
    TQ3DrawContextObject context = Q3XDrawContext_New(&data);
    ASSERT_NE(context, nullptr);
    render(context, 160, 120);

    const unsigned width = 300, height = 220;
    XResizeWindow(m_display, window, width, height);
    XEvent event;
    do
        XWindowEvent(m_display, window, StructureNotifyMask, &event);
    while (event.type != ConfigureNotify || event.xconfigure.width != int(width));
    render(context, width, height);
    const std::vector<std::uint32_t> shown = expectWindowMatchesPixmap(window, contextData(), width, height, false);
    // The clear colour reaches the far corner: the frame fills the window.
    ASSERT_FALSE(shown.empty());
    EXPECT_EQ(shown.back(), 0x339966u); // (0.2, 0.6, 0.4) * 255
    Q3Object_Dispose(context);
}

TEST_F(X11DrawContextTest, PicksAndViewHintsUseTheWindowsSize)
{
    const unsigned width = 200, height = 100;
    const Window window = makeWindow(width, height);
    const TQ3XDrawContextData data = xData(window);
    TQ3DrawContextObject context = Q3XDrawContext_New(&data);
    ASSERT_NE(context, nullptr);
    TQ3ViewObject view = Q3View_New();
    const TQ3ViewAngleAspectCameraData cameraData =
        viewAngleCamera({0.0, 0.0, 4.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0.8, double(width) / height);
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&cameraData);
    TQ3RendererObject renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    Q3View_SetDrawContext(view, context);
    Q3View_SetCamera(view, camera);
    Q3View_SetRenderer(view, renderer);

    TQ3ViewHintsObject hints = Q3ViewHints_New(view);
    ASSERT_NE(hints, nullptr);
    unsigned long hintWidth = 0, hintHeight = 0;
    EXPECT_EQ(Q3ViewHints_GetDimensions(hints, &hintWidth, &hintHeight), kQ3Success);
    EXPECT_EQ(hintWidth, width);
    EXPECT_EQ(hintHeight, height);

    // The window's centre sees the box the camera looks at; a corner does not.
    const auto hitsAt = [&](float x, float y) {
        const TQ3WindowPointPickData pickData{{kQ3PickSortNone, kQ3PickDetailNone, 0}, {x, y}, 2.0f, 2.0f};
        TQ3PickObject pick = Q3WindowPointPick_New(&pickData);
        unsigned long hits = 0;
        EXPECT_EQ(Q3View_StartPicking(view, pick), kQ3Success);
        TQ3ViewStatus status;
        do {
            submitScene(view);
            status = Q3View_EndPicking(view);
        } while (status == kQ3ViewStatusRetraverse);
        EXPECT_EQ(Q3Pick_GetNumHits(pick, &hits), kQ3Success);
        Q3Object_Dispose(pick);
        return hits;
    };
    EXPECT_GT(hitsAt(width / 2.0f, height / 2.0f), 0ul);
    EXPECT_EQ(hitsAt(2.0f, 2.0f), 0ul);
    for (TQ3Object object : {TQ3Object(hints), view, camera, renderer, context})
        Q3Object_Dispose(object);
}

TEST_F(X11DrawContextTest, GettersReturnWhatWasSet)
{
    const Window window = makeWindow(64, 64);
    TQ3XColormapData colormapData{1, 2, 3, 4, 5, 6, 7};
    TQ3XDrawContextData data = xData(window);
    data.visual = DefaultVisual(m_display, DefaultScreen(m_display));
    data.cmap = DefaultColormap(m_display, DefaultScreen(m_display));
    data.colorMapData = &colormapData;
    TQ3DrawContextObject context = Q3XDrawContext_New(&data);
    ASSERT_NE(context, nullptr);

    Display* display = nullptr;
    Drawable drawable = 0;
    Visual* visual = nullptr;
    Colormap colormap = 0;
    TQ3XColormapData readData{};
    EXPECT_EQ(Q3XDrawContext_GetDisplay(context, &display), kQ3Success);
    EXPECT_EQ(display, m_display);
    EXPECT_EQ(Q3XDrawContext_GetDrawable(context, &drawable), kQ3Success);
    EXPECT_EQ(drawable, window);
    EXPECT_EQ(Q3XDrawContext_GetVisual(context, &visual), kQ3Success);
    EXPECT_EQ(visual, data.visual);
    EXPECT_EQ(Q3XDrawContext_GetColormap(context, &colormap), kQ3Success);
    EXPECT_EQ(colormap, data.cmap);
    EXPECT_EQ(Q3XDrawContext_GetColormapData(context, &readData), kQ3Success);
    EXPECT_EQ(readData.multBlue, 7);
    EXPECT_EQ(readData.baseEntry, 1);

    const Window other = makeWindow(32, 32);
    const TQ3XColormapData otherData{9, 8, 7, 6, 5, 4, 3};
    EXPECT_EQ(Q3XDrawContext_SetDrawable(context, other), kQ3Success);
    EXPECT_EQ(Q3XDrawContext_SetColormap(context, 77), kQ3Success);
    EXPECT_EQ(Q3XDrawContext_SetColormapData(context, &otherData), kQ3Success);
    EXPECT_EQ(Q3XDrawContext_SetDisplay(context, m_display), kQ3Success);
    EXPECT_EQ(Q3XDrawContext_SetVisual(context, data.visual), kQ3Success);
    EXPECT_EQ(Q3XDrawContext_GetDrawable(context, &drawable), kQ3Success);
    EXPECT_EQ(drawable, other);
    EXPECT_EQ(Q3XDrawContext_GetColormap(context, &colormap), kQ3Success);
    EXPECT_EQ(colormap, 77u);
    EXPECT_EQ(Q3XDrawContext_GetColormapData(context, &readData), kQ3Success);
    EXPECT_EQ(readData.baseEntry, 9);

    // A duplicate holds the same window.
    TQ3Object copy = Q3Object_Duplicate(context);
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(Q3XDrawContext_GetDrawable(copy, &drawable), kQ3Success);
    EXPECT_EQ(drawable, other);
    Q3Object_Dispose(copy);
    Q3Object_Dispose(context);
}

TEST_F(X11DrawContextTest, BadDisplayDrawableOrVisualIsAnError)
{
    const Window window = makeWindow(64, 64);
    TQ3XDrawContextData data = xData(window);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XDrawContext_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    data.display = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XDrawContext_New(&data), nullptr), kQ3ErrorNULLParameter);
    data.display = m_display;

    // A pixmap is a drawable but not a window; an unknown XID is neither.
    // Xlib would print and exit on BadWindow with its default handler.
    const ::Pixmap pixmap = XCreatePixmap(m_display, window, 16, 16, 24);
    data.drawable = pixmap;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XDrawContext_New(&data), nullptr), kQ3ErrorX11Error);
    data.drawable = 0x7FFFFF0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XDrawContext_New(&data), nullptr), kQ3ErrorX11Error);
    data.drawable = window;

    // A visual that is not TrueColor.
    Visual pseudo = *DefaultVisual(m_display, DefaultScreen(m_display));
    pseudo.c_class = PseudoColor;
    data.visual = &pseudo;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XDrawContext_New(&data), nullptr), kQ3ErrorInvalidData);
    data.visual = nullptr;
    data.contextData.clearImageColor.r = NAN;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XDrawContext_New(&data), nullptr), kQ3ErrorInvalidData);
    data.contextData = contextData();

    TQ3DrawContextObject context = Q3XDrawContext_New(&data);
    ASSERT_NE(context, nullptr);
    const unsigned long edits = Q3Shared_GetEditIndex(context);
    EXPECT_Q3_ERROR(Q3XDrawContext_SetDrawable(context, pixmap), kQ3ErrorX11Error);
    EXPECT_Q3_ERROR(Q3XDrawContext_SetDisplay(context, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3XDrawContext_SetVisual(context, &pseudo), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3XDrawContext_SetVisual(context, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3XDrawContext_GetDisplay(context, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3XDrawContext_SetColormapData(context, nullptr), kQ3ErrorNULLParameter);
    EXPECT_EQ(Q3Shared_GetEditIndex(context), edits);
    Drawable drawable = 0;
    EXPECT_EQ(Q3XDrawContext_GetDrawable(context, &drawable), kQ3Success);
    EXPECT_EQ(drawable, window);

    // A pixmap draw context is not an X11 one.
    Image image(8, 8);
    TQ3PixmapDrawContextData pixmapData{contextData(), image.pixmap()};
    TQ3DrawContextObject pixmapContext = Q3PixmapDrawContext_New(&pixmapData);
    EXPECT_Q3_ERROR(Q3XDrawContext_GetDrawable(pixmapContext, &drawable), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(pixmapContext);

    // The window goes away: the next frame fails, the process goes on.
    XDestroyWindow(m_display, window);
    m_windows.erase(std::find(m_windows.begin(), m_windows.end(), window));
    XSync(m_display, False);
    TQ3ViewObject view = Q3View_New();
    const TQ3OrthographicCameraData cameraData = listing1OrthographicCamera();
    TQ3CameraObject camera = Q3OrthographicCamera_New(&cameraData);
    TQ3RendererObject renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    Q3View_SetDrawContext(view, context);
    Q3View_SetCamera(view, camera);
    Q3View_SetRenderer(view, renderer);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_StartRendering(view), kQ3Failure), kQ3ErrorX11Error);
    for (TQ3Object object : {view, camera, renderer, context})
        Q3Object_Dispose(object);
    XFreePixmap(m_display, pixmap);
}

TEST_F(X11DrawContextTest, VisualInfoListsTrueColorVisuals)
{
    XVisualInfo* info = Q3X_GetVisualInfo(m_display, DefaultScreenOfDisplay(m_display));
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->c_class, TrueColor);
    EXPECT_EQ(info->depth, 24);
    XFree(info);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3X_GetVisualInfo(nullptr, DefaultScreenOfDisplay(m_display)), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3X_GetVisualInfo(m_display, nullptr), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(X11DrawContextTest, BuffersAreOnePerWindowAndSwapFlushes)
{
    const Window window = makeWindow(32, 32);
    long colours[8] = {};
    TQ3XBufferObject buffers = Q3XBuffers_New(m_display, 2, window);
    ASSERT_NE(buffers, nullptr);
    EXPECT_EQ(Q3XBuffers_New(m_display, 1, window), buffers);
    Q3XBuffers_Swap(m_display, buffers);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XBuffers_New(nullptr, 2, window), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XBuffers_New(m_display, 3, window), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XBuffers_New(m_display, 2, 0x7FFFFF0), nullptr), kQ3ErrorX11Error);
    EXPECT_Q3_ERROR(Q3XBuffers_Swap(nullptr, buffers), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3XBuffers_Swap(m_display, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3XBuffers_Swap(m_display, reinterpret_cast<TQ3XBufferObject>(&colours)),
                    kQ3ErrorInvalidParameter);
}

} // namespace
