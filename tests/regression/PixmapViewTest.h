// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The view the subdivision and patch regression tests draw through: the
// interactive renderer into an ARGB32 pixmap of their size, cleared to opaque
// black. Each test gives the view its own camera.

#include "Q3ApiTest.h"

#include "QD3DDrawContext.h"
#include "QD3DRenderer.h"
#include "QD3DView.h"

#include <vector>

namespace q3test {

class PixmapViewTest : public Q3ApiTest {
protected:
    PixmapViewTest(unsigned long width, unsigned long height) : m_width(width), m_height(height) {}

    void SetUp() override
    {
        Q3ApiTest::SetUp();
        m_memory.assign(m_width * m_height * 4, 0);
        TQ3PixmapDrawContextData data{};
        data.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
        data.drawContextData.clearImageColor = {1, 0, 0, 0};
        data.pixmap = {m_memory.data(), m_width, m_height, m_width * 4, 32, kQ3PixelTypeARGB32, kQ3EndianBig,
                       kQ3EndianBig};
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

    std::vector<unsigned char> m_memory;
    TQ3DrawContextObject m_context = nullptr;
    TQ3ViewObject m_view = nullptr;

private:
    unsigned long m_width;
    unsigned long m_height;
};

} // namespace q3test
