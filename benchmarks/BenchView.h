// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// A Q3 view as an application sets one up, through the public API only:
// a caller-owned ARGB32 pixmap (little-endian, so B, G, R, A in memory, the
// layout GL_BGRA reads back), cleared to opaque black, an orthographic camera
// on the square x, y in [-1.1, 1.1] (every benchmark curve fits), and the
// interactive renderer.

#include "BenchCurves.h"

#include "QD3D.h"
#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DMath.h"
#include "QD3DRenderer.h"
#include "QD3DStyle.h"
#include "QD3DView.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace q3bench {

/// Owns Q3's initialization for its lifetime (calls nest).
class Q3Session {
public:
    Q3Session()
    {
        if (Q3Initialize() != kQ3Success)
            throw std::runtime_error("Q3Initialize failed");
    }
    ~Q3Session() { Q3Exit(); }
    Q3Session(const Q3Session&) = delete;
    Q3Session& operator=(const Q3Session&) = delete;
};

/// The camera: eye at z = 5 looking down -z, y up, showing [-1.1, 1.1]^2.
inline TQ3OrthographicCameraData benchCameraData()
{
    TQ3OrthographicCameraData data{};
    data.cameraData.placement = {{0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
    data.cameraData.range = {1.0f, 10.0f};
    data.cameraData.viewPort = {{-1.0f, 1.0f}, 2.0f, 2.0f};
    data.left = -1.1f;
    data.right = 1.1f;
    data.top = 1.1f;
    data.bottom = -1.1f;
    return data;
}

class BenchView {
public:
    BenchView(unsigned long width, unsigned long height) : m_memory(std::size_t(width) * height * 4, 0)
    {
        TQ3PixmapDrawContextData contextData{};
        contextData.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
        contextData.drawContextData.clearImageColor = {1.0f, 0.0f, 0.0f, 0.0f};
        contextData.drawContextData.paneState = kQ3False;
        contextData.drawContextData.maskState = kQ3False;
        contextData.drawContextData.doubleBufferState = kQ3False;
        contextData.pixmap = {m_memory.data(), width,           height,           width * 4, 32,
                              kQ3PixelTypeARGB32, kQ3EndianLittle, kQ3EndianLittle};
        const TQ3OrthographicCameraData cameraData = benchCameraData();
        m_context = Q3PixmapDrawContext_New(&contextData);
        m_camera = Q3OrthographicCamera_New(&cameraData);
        m_renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
        m_view = Q3View_New();
        if (!m_context || !m_camera || !m_renderer || !m_view ||
            Q3View_SetDrawContext(m_view, m_context) != kQ3Success ||
            Q3View_SetCamera(m_view, m_camera) != kQ3Success ||
            Q3View_SetRenderer(m_view, m_renderer) != kQ3Success)
            throw std::runtime_error("setting up the Q3 view failed");
    }
    ~BenchView()
    {
        for (TQ3Object object : {m_view, m_renderer, m_camera, m_context})
            if (object)
                Q3Object_Dispose(object);
    }
    BenchView(const BenchView&) = delete;
    BenchView& operator=(const BenchView&) = delete;

    TQ3ViewObject view() const { return m_view; }
    TQ3CameraObject camera() const { return m_camera; }
    /// The pixmap's bytes: B, G, R, A per pixel, top row first.
    const std::vector<std::uint8_t>& pixels() const { return m_memory; }

private:
    std::vector<std::uint8_t> m_memory;
    TQ3DrawContextObject m_context = nullptr;
    TQ3CameraObject m_camera = nullptr;
    TQ3RendererObject m_renderer = nullptr;
    TQ3ViewObject m_view = nullptr;
};

/// The style every constant-method benchmark submits.
inline TQ3SubdivisionStyleData constantStyle(float segmentsPerSpan)
{
    return TQ3SubdivisionStyleData{kQ3SubdivisionMethodConstant, segmentsPerSpan, segmentsPerSpan};
}

/// A benchmark curve as the NURB curve data Q3NURBCurve_New copies
/// (TQ3RationalPoint4D is the same x, y, z, w layout of floats).
inline TQ3NURBCurveData curveData(const BenchCurve& curve)
{
    TQ3NURBCurveData data{};
    data.order = curve.order;
    data.numPoints = curve.numPoints();
    data.controlPoints = reinterpret_cast<TQ3RationalPoint4D*>(const_cast<float*>(curve.points.data()));
    data.knots = const_cast<float*>(curve.knots.data());
    data.curveAttributeSet = nullptr;
    return data;
}

} // namespace q3bench
