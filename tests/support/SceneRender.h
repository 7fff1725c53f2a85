// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// One scene set-up for the golden tests that draw a few objects in
// perspective: a pixmap draw context, a view-angle-aspect camera, a renderer,
// optionally an ambient and a directional light and Phong illumination. The
// test gives what it submits; the picture comes back as RGBA.

#include "Golden.h"

#include "QD3D.h"
#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DRenderer.h"
#include "QD3DShader.h"
#include "QD3DView.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace q3test {

struct SceneSetup {
    int width = 160;
    int height = 120;
    TQ3ColorARGB clear{1.0f, 0.1f, 0.1f, 0.12f};
    TQ3Point3D eye{0.0f, 0.0f, 5.0f};
    TQ3Point3D target{0.0f, 0.0f, 0.0f};
    float hither = 0.5f;
    float yon = 50.0f;
    float fov = 0.8f;
    TQ3ObjectType renderer = kQ3RendererTypeInteractive;
    /// The interactive renderer's RAVE texture filter; none: its default.
    std::optional<unsigned long> textureFilter;
    /// Lights: an ambient light of this brightness when above 0, and a
    /// directional light of 0.8 along (-1, -1.5, -2) when `sun`.
    float ambient = 0.35f;
    bool sun = true;
    /// Phong illumination submitted before the scene.
    bool phong = false;
    /// The pixmap's alpha in the result; otherwise every pixel is opaque.
    bool keepAlpha = false;
};

/// A width x height setup cleared to `clear`, the eye at `eye` looking at
/// `target`; the rest as SceneSetup's defaults.
inline SceneSetup sceneLookingAt(int width, int height, const TQ3ColorARGB& clear, const TQ3Point3D& eye,
                                 const TQ3Point3D& target = {0.0f, 0.0f, 0.0f})
{
    SceneSetup setup;
    setup.width = width;
    setup.height = height;
    setup.clear = clear;
    setup.eye = eye;
    setup.target = target;
    return setup;
}

/// Renders what `submit` submits (once per pass) under `setup` into an
/// ARGB32 pixmap of `byteOrder`; expects the frame to start and end
/// without error.
inline std::vector<unsigned char> renderScenePixmap(const SceneSetup& setup,
                                                   const std::function<void(TQ3ViewObject)>& submit,
                                                   TQ3Endian byteOrder)
{
    const std::size_t pixels = std::size_t(setup.width) * std::size_t(setup.height);
    std::vector<unsigned char> argb(pixels * 4, 0);
    TQ3PixmapDrawContextData contextData{};
    contextData.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
    contextData.drawContextData.clearImageColor = setup.clear;
    contextData.pixmap = TQ3Pixmap{argb.data(), (unsigned long)setup.width, (unsigned long)setup.height,
                                   (unsigned long)setup.width * 4, 32, kQ3PixelTypeARGB32, byteOrder,
                                   byteOrder};
    TQ3DrawContextObject context = Q3PixmapDrawContext_New(&contextData);
    TQ3ViewAngleAspectCameraData cameraData{};
    cameraData.cameraData.placement = {setup.eye, setup.target, {0.0f, 1.0f, 0.0f}};
    cameraData.cameraData.range = {setup.hither, setup.yon};
    cameraData.cameraData.viewPort = {{-1.0f, 1.0f}, 2.0f, 2.0f};
    cameraData.fov = setup.fov;
    cameraData.aspectRatioXToY = float(setup.width) / float(setup.height);
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&cameraData);
    TQ3RendererObject renderer = Q3Renderer_NewFromType(setup.renderer);
    if (setup.textureFilter)
        EXPECT_EQ(Q3InteractiveRenderer_SetRAVETextureFilter(renderer, *setup.textureFilter), kQ3Success);
    TQ3ViewObject view = Q3View_New();
    Q3View_SetDrawContext(view, context);
    Q3View_SetCamera(view, camera);
    Q3View_SetRenderer(view, renderer);
    TQ3GroupObject lights = Q3LightGroup_New();
    if (setup.ambient > 0.0f) {
        const TQ3LightData ambientData{kQ3True, setup.ambient, {1.0f, 1.0f, 1.0f}};
        TQ3LightObject ambient = Q3AmbientLight_New(&ambientData);
        Q3Group_AddObject(lights, ambient);
        Q3Object_Dispose(ambient);
    }
    if (setup.sun) {
        const TQ3DirectionalLightData sunData{{kQ3True, 0.8f, {1.0f, 1.0f, 1.0f}}, kQ3False, {-1.0f, -1.5f, -2.0f}};
        TQ3LightObject sun = Q3DirectionalLight_New(&sunData);
        Q3Group_AddObject(lights, sun);
        Q3Object_Dispose(sun);
    }
    Q3View_SetLightGroup(view, lights);
    TQ3ShaderObject phong = setup.phong ? Q3PhongIllumination_New() : nullptr;
    EXPECT_EQ(Q3View_StartRendering(view), kQ3Success);
    TQ3ViewStatus status;
    do {
        if (phong != nullptr)
            Q3Shader_Submit(phong, view);
        submit(view);
        status = Q3View_EndRendering(view);
    } while (status == kQ3ViewStatusRetraverse);
    EXPECT_EQ(status, kQ3ViewStatusDone);
    if (phong != nullptr)
        Q3Object_Dispose(phong);
    Q3Object_Dispose(lights);
    Q3Object_Dispose(view);
    Q3Object_Dispose(renderer);
    Q3Object_Dispose(camera);
    Q3Object_Dispose(context);
    return argb;
}

/// Renders what `submit` submits (once per pass) under `setup`, into a
/// big-endian ARGB32 pixmap (the image returned) and again into a
/// little-endian one, which the backend may draw in place of its own image
/// (FrameOptions::bgraImage): the two must hold the same pixels, byte for
/// byte.
inline RgbaImage renderScene(const SceneSetup& setup, const std::function<void(TQ3ViewObject)>& submit)
{
    const std::vector<unsigned char> argb = renderScenePixmap(setup, submit, kQ3EndianBig);
    const std::vector<unsigned char> bgra = renderScenePixmap(setup, submit, kQ3EndianLittle);
    const std::size_t pixels = std::size_t(setup.width) * std::size_t(setup.height);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < pixels; ++i)
        for (int k = 0; k < 4; ++k)
            differing += argb[4 * i + std::size_t(k)] != bgra[4 * i + std::size_t(3 - k)];
    EXPECT_EQ(differing, 0u) << "channels differing between the big-endian ARGB32 pixmap and the little-endian one";
    RgbaImage image(setup.width, setup.height);
    for (std::size_t i = 0; i < pixels; ++i) {
        image.pixels[4 * i] = argb[4 * i + 1];
        image.pixels[4 * i + 1] = argb[4 * i + 2];
        image.pixels[4 * i + 2] = argb[4 * i + 3];
        image.pixels[4 * i + 3] = setup.keepAlpha ? argb[4 * i] : 255;
    }
    return image;
}

} // namespace q3test
