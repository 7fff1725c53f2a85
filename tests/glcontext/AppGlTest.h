// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// What the GL draw context tests share, whichever window system made the
// application's context (EGL in GLDrawContextTest.cpp, GLX under Xvfb in
// GlxDrawContextTest.cpp): the application's overlay and the GL state it
// sets, reading that state and its pixels back, the Q3 scene, and a frame of
// the application with Q3's picture in the middle, checked against a pixmap
// draw context's.

#include "BoxAndTriangle.h"
#include "Q3ApiTest.h"
#include "RenderTestSupport.h"

#include "Q3GLDrawContext.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DSet.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace q3test {

// The application's overlay: a program drawing a rectangle (two triangles
// of a vertex array of its own) in a uniform colour.
struct Overlay {
    GLuint program = 0, vertexArray = 0, buffer = 0;
    GLint colour = -1;

    static GLuint shader(GLenum kind, const char* source)
    {
        const GLuint s = glCreateShader(kind);
        glShaderSource(s, 1, &source, nullptr);
        glCompileShader(s);
        return s;
    }

    // The rectangle [x0, x1) x [y0, y1) in pixels of a width x height
    // framebuffer, y from the bottom as OpenGL counts.
    void create(int x0, int y0, int x1, int y1, int width, int height)
    {
        const GLuint vs = shader(GL_VERTEX_SHADER, "#version 330 core\n"
                                                   "layout(location = 0) in vec2 p;\n"
                                                   "void main() { gl_Position = vec4(p, 0.0, 1.0); }\n");
        const GLuint fs = shader(GL_FRAGMENT_SHADER, "#version 330 core\n"
                                                     "uniform vec4 colour;\n"
                                                     "out vec4 result;\n"
                                                     "void main() { result = colour; }\n");
        program = glCreateProgram();
        glAttachShader(program, vs);
        glAttachShader(program, fs);
        glLinkProgram(program);
        glDeleteShader(vs);
        glDeleteShader(fs);
        colour = glGetUniformLocation(program, "colour");
        auto nx = [&](int x) { return 2.0f * float(x) / float(width) - 1.0f; };
        auto ny = [&](int y) { return 2.0f * float(y) / float(height) - 1.0f; };
        const float corners[12] = {nx(x0), ny(y0), nx(x1), ny(y0), nx(x1), ny(y1),
                                   nx(x0), ny(y0), nx(x1), ny(y1), nx(x0), ny(y1)};
        glGenVertexArrays(1, &vertexArray);
        glBindVertexArray(vertexArray);
        glGenBuffers(1, &buffer);
        glBindBuffer(GL_ARRAY_BUFFER, buffer);
        glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
        glEnableVertexAttribArray(0);
    }

    ~Overlay()
    {
        glDeleteBuffers(1, &buffer);
        glDeleteVertexArrays(1, &vertexArray);
        glDeleteProgram(program);
    }
};

// Every piece of GL state the test sets or that Q3 touches, read back.
struct GlState {
    std::vector<GLint> integers;
    std::vector<GLboolean> enables;
    std::array<GLfloat, 4> clearColour{};
    std::array<GLboolean, 4> colourMask{};

    static GlState read()
    {
        GlState s;
        for (GLenum name :
             {GL_DRAW_FRAMEBUFFER_BINDING, GL_READ_FRAMEBUFFER_BINDING, GL_READ_BUFFER, GL_DRAW_BUFFER0,
              GL_CURRENT_PROGRAM, GL_VERTEX_ARRAY_BINDING, GL_ARRAY_BUFFER_BINDING, GL_ELEMENT_ARRAY_BUFFER_BINDING,
              GL_ACTIVE_TEXTURE, GL_TEXTURE_BINDING_2D, GL_RENDERBUFFER_BINDING, GL_PIXEL_PACK_BUFFER_BINDING,
              GL_PIXEL_UNPACK_BUFFER_BINDING, GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS,
              GL_UNPACK_SKIP_PIXELS, GL_PACK_ALIGNMENT, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS,
              GL_PACK_SKIP_PIXELS, GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA,
              GL_BLEND_EQUATION_RGB, GL_DEPTH_FUNC, GL_DEPTH_WRITEMASK, GL_CULL_FACE_MODE, GL_FRONT_FACE,
              GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_WRITEMASK})
            s.integers.push_back(integer(name));
        std::array<GLint, 4> box{};
        glGetIntegerv(GL_VIEWPORT, box.data());
        s.integers.insert(s.integers.end(), box.begin(), box.end());
        glGetIntegerv(GL_SCISSOR_BOX, box.data());
        s.integers.insert(s.integers.end(), box.begin(), box.end());
        for (GLenum capability : {GL_BLEND, GL_DEPTH_TEST, GL_CULL_FACE, GL_SCISSOR_TEST, GL_STENCIL_TEST,
                                  GL_FRAMEBUFFER_SRGB, GL_DITHER, GL_POLYGON_OFFSET_FILL, GL_RASTERIZER_DISCARD})
            s.enables.push_back(glIsEnabled(capability));
        glGetFloatv(GL_COLOR_CLEAR_VALUE, s.clearColour.data());
        glGetBooleanv(GL_COLOR_WRITEMASK, s.colourMask.data());
        return s;
    }

    static GLint integer(GLenum name)
    {
        GLint value = -12345;
        glGetIntegerv(name, &value);
        return value;
    }

    bool operator==(const GlState& other) const
    {
        return integers == other.integers && enables == other.enables && clearColour == other.clearColour &&
               colourMask == other.colourMask;
    }
};

// The application's pixels as 0xAARRGGBB, top row first.
inline std::vector<std::uint32_t> readFramebuffer(int width, int height)
{
    std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    std::vector<std::uint32_t> pixels(std::size_t(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::uint8_t* p = &rgba[(std::size_t(height - 1 - y) * width + x) * 4];
            pixels[std::size_t(y) * width + x] =
                std::uint32_t(p[3]) << 24 | std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2];
        }
    return pixels;
}

class AppGlTest : public Q3ApiTest {
protected:
    static constexpr int kWidth = 200, kHeight = 150;
    // The pane, y from the top, and the overlay, both in pixels.
    static constexpr int kPaneX0 = 20, kPaneY0 = 10, kPaneX1 = 180, kPaneY1 = 130;
    static constexpr int kOverlayX0 = 150, kOverlayY0 = 100, kOverlayX1 = 196, kOverlayY1 = 146;
    static constexpr std::uint32_t kBackground = 0xFF3366CCu; // the application's clear
    static constexpr std::uint32_t kOverlay = 0xFFFFCC00u;

    static TQ3DrawContextData contextData(TQ3DrawContextClearImageMethod clear)
    {
        TQ3DrawContextData data{};
        data.clearImageMethod = clear;
        data.clearImageColor = {1.0f, 0.1f, 0.2f, 0.3f};
        data.pane = {{float(kPaneX0), float(kPaneY0)}, {float(kPaneX1), float(kPaneY1)}};
        data.paneState = kQ3True;
        data.maskState = kQ3False;
        data.doubleBufferState = kQ3True;
        return data;
    }

    static TQ3GLDrawContextData glData(TQ3DrawContextClearImageMethod clear = kQ3ClearMethodWithColor)
    {
        return TQ3GLDrawContextData{contextData(clear), TQ3Uns32(kWidth), TQ3Uns32(kHeight)};
    }

    // A view on `context` with a perspective camera, the interactive
    // renderer and a directional light; disposes of them all.
    struct SceneView {
        TQ3ViewObject view = Q3View_New();
        TQ3CameraObject camera = nullptr;
        TQ3RendererObject renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
        TQ3GroupObject lights = Q3LightGroup_New();
        TQ3LightObject light = nullptr;

        explicit SceneView(TQ3DrawContextObject context)
        {
            const TQ3ViewAngleAspectCameraData cameraData =
                viewAngleCamera({2.0, 1.5, 4.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0.8,
                                double(kPaneX1 - kPaneX0) / double(kPaneY1 - kPaneY0));
            camera = Q3ViewAngleAspectCamera_New(&cameraData);
            TQ3DirectionalLightData lightData{{kQ3True, 1.0f, {1.0f, 1.0f, 1.0f}}, kQ3False, {-0.3f, -0.5f, -1.0f}};
            light = Q3DirectionalLight_New(&lightData);
            Q3Group_AddObject(lights, light);
            Q3View_SetDrawContext(view, context);
            Q3View_SetCamera(view, camera);
            Q3View_SetRenderer(view, renderer);
            Q3View_SetLightGroup(view, lights);
        }
        ~SceneView()
        {
            for (TQ3Object object : {view, camera, renderer, lights, light})
                Q3Object_Dispose(object);
        }
    };

    // A lit box and a triangle with a colour per vertex, in perspective,
    // through a view on `context`. Returns the last view status.
    static TQ3ViewStatus render(TQ3DrawContextObject context)
    {
        SceneView scene(context);
        if (Q3View_StartRendering(scene.view) != kQ3Success)
            return kQ3ViewStatusError;
        TQ3ViewStatus status;
        do {
            submitScene(scene.view);
            status = Q3View_EndRendering(scene.view);
        } while (status == kQ3ViewStatusRetraverse);
        return status;
    }

    static void submitScene(TQ3ViewObject view) { q3test::submitBoxAndTriangle(view); }

    // The scene through a pixmap draw context of the same data, the pixmap
    // first filled with the application's background.
    static std::vector<std::uint32_t> pixmapPicture(TQ3DrawContextClearImageMethod clear)
    {
        // ARGB32, big-endian: A, R, G, B in memory.
        std::vector<unsigned char> memory(std::size_t(kWidth) * kHeight * 4);
        for (std::size_t i = 0; i < memory.size(); ++i)
            memory[i] = std::uint8_t(kBackground >> (24 - 8 * (i % 4)));
        TQ3Pixmap image{memory.data(), TQ3Uns32(kWidth), TQ3Uns32(kHeight), TQ3Uns32(kWidth * 4), 32,
                        kQ3PixelTypeARGB32, kQ3EndianBig, kQ3EndianBig};
        const TQ3PixmapDrawContextData data{contextData(clear), image};
        TQ3DrawContextObject context = Q3PixmapDrawContext_New(&data);
        EXPECT_EQ(render(context), kQ3ViewStatusDone);
        Q3Object_Dispose(context);
        std::vector<std::uint32_t> pixels;
        for (std::size_t i = 0; i < memory.size(); i += 4)
            pixels.push_back(std::uint32_t(memory[i]) << 24 | std::uint32_t(memory[i + 1]) << 16 |
                             std::uint32_t(memory[i + 2]) << 8 | memory[i + 3]);
        return pixels;
    }

    // The application's own state, set before each frame: as unlike
    // OpenGL's defaults as the test can make it.
    void setApplicationState(Overlay& overlay, GLuint& texture)
    {
        overlay.create(kOverlayX0, kHeight - kOverlayY1, kOverlayX1, kHeight - kOverlayY0, kWidth, kHeight);
        glUseProgram(overlay.program);
        glActiveTexture(GL_TEXTURE3);
        glGenTextures(1, &texture);
        glBindTexture(GL_TEXTURE_2D, texture);
        glViewport(3, 5, 17, 19);
        glScissor(1, 2, 30, 40);
        glEnable(GL_SCISSOR_TEST);
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(GL_FALSE);
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
        glFrontFace(GL_CW);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_GREATER, 7, 0x0F);
        glEnable(GL_FRAMEBUFFER_SRGB);
        glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
        glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
        glPixelStorei(GL_PACK_ALIGNMENT, 2);
        glPixelStorei(GL_PACK_SKIP_PIXELS, 3);
    }

    // The background: the whole framebuffer in kBackground.
    static void drawBackground()
    {
        glDisable(GL_SCISSOR_TEST);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glClearColor(0x33 / 255.0f, 0x66 / 255.0f, 0xCC / 255.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }

    // The overlay with the program, vertex array and blending still bound
    // from before the frame: only the pieces the test had made unfit for
    // drawing are switched off.
    static void drawOverlay(const Overlay& overlay)
    {
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_FRAMEBUFFER_SRGB);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glViewport(0, 0, kWidth, kHeight);
        glUniform4f(overlay.colour, 1.0f, 0xCC / 255.0f, 0.0f, 1.0f);
        glDrawArrays(GL_TRIANGLES, 0, 6);
    }

    // Renders into the application's framebuffer between its background
    // and its overlay; checks state, currency and the pending error, and
    // returns the pixels.
    std::vector<std::uint32_t> applicationFrame(TQ3DrawContextClearImageMethod clear)
    {
        Overlay overlay;
        GLuint texture = 0;
        drawBackground();
        setApplicationState(overlay, texture);
        glEnable(0xFFFF); // an error the application has not fetched yet
        const GlState before = GlState::read();

        const TQ3GLDrawContextData data = glData(clear);
        TQ3DrawContextObject context = Q3GLDrawContext_New(&data);
        EXPECT_NE(context, nullptr);
        EXPECT_EQ(render(context), kQ3ViewStatusDone);
        Q3Object_Dispose(context);

        expectApplicationContextCurrent();
        EXPECT_TRUE(GlState::read() == before) << "the frame changed the application's GL state";
        EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM)) << "the application's pending error is gone";
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

        drawOverlay(overlay);
        glDeleteTextures(1, &texture);
        return readFramebuffer(kWidth, kHeight);
    }

    // Inside the overlay the overlay's colour, elsewhere in the pane the
    // pixmap's picture, outside the pane the background.
    static void expectPicture(const std::vector<std::uint32_t>& app, const std::vector<std::uint32_t>& pixmap)
    {
        ASSERT_EQ(app.size(), pixmap.size());
        std::size_t differing = 0, overlayWrong = 0, backgroundWrong = 0, sceneColours = 0;
        std::vector<std::uint32_t> seen;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const std::uint32_t got = app[std::size_t(y) * kWidth + x];
                const bool inOverlay = x >= kOverlayX0 && x < kOverlayX1 && y >= kOverlayY0 && y < kOverlayY1;
                const bool inPane = x >= kPaneX0 && x < kPaneX1 && y >= kPaneY0 && y < kPaneY1;
                if (inOverlay)
                    overlayWrong += got != kOverlay;
                else if (inPane) {
                    differing += got != pixmap[std::size_t(y) * kWidth + x];
                    seen.push_back(got);
                } else
                    backgroundWrong += got != kBackground;
            }
        EXPECT_EQ(differing, 0u) << "pane pixels differ from the pixmap's";
        EXPECT_EQ(overlayWrong, 0u);
        EXPECT_EQ(backgroundWrong, 0u);
        std::sort(seen.begin(), seen.end());
        sceneColours = std::size_t(std::unique(seen.begin(), seen.end()) - seen.begin());
        EXPECT_GT(sceneColours, 100u) << "the scene should have many colours";
    }

    /// Checks that the application's context, display and surfaces or
    /// drawables are current as before the frame.
    virtual void expectApplicationContextCurrent() = 0;
};

} // namespace q3test
