// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The fixture of the transform API tests: one view, made when first asked
// for, and the local-to-world matrix a bounding loop leaves.

#include "Q3ApiTest.h"

#include "QD3DMath.h"
#include "QD3DView.h"

#include <functional>

namespace q3test {

class TransformStateTest : public Q3ApiTest {
protected:
    void TearDown() override
    {
        if (m_view != nullptr)
            Q3Object_Dispose(m_view);
        Q3ApiTest::TearDown();
    }

    TQ3ViewObject view()
    {
        if (m_view == nullptr)
            m_view = Q3View_New();
        return m_view;
    }

    /// One bounding loop calling `scene` in every traversal: the
    /// local-to-world matrix it leaves and, if asked, the box of what it
    /// submitted.
    TQ3Matrix4x4 stateAfter(const std::function<void(TQ3ViewObject)>& scene, TQ3BoundingBox* box = nullptr)
    {
        TQ3Matrix4x4 state{};
        TQ3BoundingBox bounds{};
        EXPECT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
        do {
            scene(view());
            EXPECT_EQ(Q3View_GetLocalToWorldMatrixState(view(), &state), kQ3Success);
        } while (Q3View_EndBoundingBox(view(), &bounds) == kQ3ViewStatusRetraverse);
        if (box != nullptr)
            *box = bounds;
        return state;
    }

private:
    TQ3ViewObject m_view = nullptr;
};

} // namespace q3test
