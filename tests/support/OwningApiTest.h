// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Q3ApiTest plus ownership of the objects a test creates (disposed before the
// leak check) and a lazily created view for bounding loops.

#include "Q3ApiTest.h"

#include "QD3DView.h"

#include <functional>
#include <vector>

namespace q3test {

class OwningApiTest : public Q3ApiTest {
protected:
    void TearDown() override
    {
        for (TQ3Object object : m_owned)
            Q3Object_Dispose(object);
        m_owned.clear();
        m_view = nullptr;
        Q3ApiTest::TearDown();
    }

    /// Disposed by TearDown (before the leak check).
    template <class T>
    T own(T object)
    {
        m_owned.push_back(object);
        return object;
    }

    /// A view with nothing set, created on first use.
    TQ3ViewObject view()
    {
        if (m_view == nullptr)
            m_view = own(Q3View_New());
        return m_view;
    }

    /// The bounding box of what `scene` submits, from an exact bounding loop.
    TQ3BoundingBox boundsOf(const std::function<void(TQ3ViewObject)>& scene)
    {
        TQ3BoundingBox box{};
        EXPECT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
        do
            scene(view());
        while (Q3View_EndBoundingBox(view(), &box) == kQ3ViewStatusRetraverse);
        return box;
    }

private:
    std::vector<TQ3Object> m_owned;
    TQ3ViewObject m_view = nullptr;
};

} // namespace q3test
