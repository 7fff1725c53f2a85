// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The view the subdivision and patch regression tests draw through: the
// interactive renderer into an ARGB32 pixmap of their size, cleared to opaque
// black. Each test gives the view its own camera.

#include "CameraTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DRenderer.h"
#include "QD3DView.h"

#include <vector>

namespace q3test {

/// A pixmap draw context's data: `memory` as a big-endian ARGB32 image of
/// width x height, cleared to opaque black.
inline TQ3PixmapDrawContextData argb32ContextData(std::vector<unsigned char>& memory, unsigned long width,
                                                  unsigned long height)
{
    TQ3PixmapDrawContextData data{};
    data.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
    data.drawContextData.clearImageColor = {1, 0, 0, 0};
    data.pixmap = {memory.data(), width, height, width * 4, 32, kQ3PixelTypeARGB32, kQ3EndianBig, kQ3EndianBig};
    return data;
}

class PixmapViewTest : public Q3ApiTest {
protected:
    PixmapViewTest(unsigned long width, unsigned long height) : m_width(width), m_height(height) {}

    void SetUp() override
    {
        Q3ApiTest::SetUp();
        m_memory.assign(m_width * m_height * 4, 0);
        const TQ3PixmapDrawContextData data = argb32ContextData(m_memory, m_width, m_height);
        m_context = Q3PixmapDrawContext_New(&data);
        m_view = Q3View_New();
        ASSERT_NE(m_context, nullptr);
        ASSERT_NE(m_view, nullptr);
        ASSERT_EQ(Q3View_SetDrawContext(m_view, m_context), kQ3Success);
        ASSERT_EQ(Q3View_SetRendererByType(m_view, kQ3RendererTypeInteractive), kQ3Success);
    }

    void TearDown() override
    {
        Q3Object_Dispose(m_view);
        Q3Object_Dispose(m_context);
        Q3ApiTest::TearDown();
    }

    /// Makes `camera` the view's camera and disposes the caller's reference.
    void useCamera(TQ3CameraObject camera)
    {
        ASSERT_NE(camera, nullptr);
        ASSERT_EQ(Q3View_SetCamera(m_view, camera), kQ3Success);
        Q3Object_Dispose(camera);
    }

    /// A view angle aspect camera with the eye at the origin looking down -z,
    /// y up, range hither to 100, fov 1.2, the pixmap's aspect ratio.
    TQ3ViewAngleAspectCameraData eyeAtOrigin(float hither) const
    {
        TQ3ViewAngleAspectCameraData data{};
        data.cameraData.placement = {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}};
        data.cameraData.range = {hither, 100.0f};
        data.cameraData.viewPort = {{-1, 1}, 2, 2};
        data.fov = 1.2f;
        data.aspectRatioXToY = float(m_width) / float(m_height);
        return data;
    }

    std::vector<unsigned char> m_memory;
    TQ3DrawContextObject m_context = nullptr;
    TQ3ViewObject m_view = nullptr;

private:
    unsigned long m_width;
    unsigned long m_height;
};

} // namespace q3test
