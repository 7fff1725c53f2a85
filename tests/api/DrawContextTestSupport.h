// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The fixture of the draw context API tests: a pixmap draw context on a
// 16 x 8 ARGB32 image of the test's own, made for each test, and a snapshot
// of its state.

#include "RenderTestSupport.h"

#include "QD3DDrawContext.h"

#include <cstring>

namespace q3test {

class PixmapContextApiTest : public Q3ApiTest {
protected:
    void SetUp() override
    {
        Q3ApiTest::SetUp();
        const TQ3PixmapDrawContextData data = pixmapContextData(m_image.pixmap());
        m_context = Q3PixmapDrawContext_New(&data);
        ASSERT_NE(m_context, nullptr);
    }
    void TearDown() override
    {
        Q3Object_Dispose(m_context);
        Q3ApiTest::TearDown();
    }

    /// The whole state of the draw context, to show a failed call changed
    /// nothing.
    struct Snapshot {
        TQ3DrawContextData data;
        TQ3Pixmap pixmap;
        unsigned long editIndex;
    };
    Snapshot snapshot()
    {
        Snapshot s{};
        EXPECT_EQ(Q3DrawContext_GetData(m_context, &s.data), kQ3Success);
        EXPECT_EQ(Q3PixmapDrawContext_GetPixmap(m_context, &s.pixmap), kQ3Success);
        s.editIndex = Q3Shared_GetEditIndex(m_context);
        return s;
    }
    void expectUnchanged(const Snapshot& before)
    {
        const Snapshot now = snapshot();
        EXPECT_EQ(std::memcmp(&now.data, &before.data, sizeof now.data), 0);
        EXPECT_EQ(std::memcmp(&now.pixmap, &before.pixmap, sizeof now.pixmap), 0);
        EXPECT_EQ(now.editIndex, before.editIndex);
    }

    Pixmap m_image{16, 8};
    TQ3DrawContextObject m_context = nullptr;
};

} // namespace q3test
