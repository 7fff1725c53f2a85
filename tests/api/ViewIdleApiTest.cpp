// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The view's idle, idle-progress and end-frame methods: when they are
// called during a rendering loop, that kQ3Failure from an idle method
// cancels the render, and bad input.

#include "RenderTestSupport.h"

#include "QD3DGeometry.h"

#include <vector>

namespace {

using namespace q3test;

struct Calls {
    int idle = 0;
    int progress = 0;
    int endFrame = 0;
    int failAt = -1; // the idle call that returns kQ3Failure (-1: none)
    std::vector<unsigned long> current, completed;
    TQ3ViewObject view = nullptr;
};

TQ3Status countIdle(TQ3ViewObject view, const void* data)
{
    Calls& calls = *static_cast<Calls*>(const_cast<void*>(data));
    calls.view = view;
    return calls.idle++ == calls.failAt ? kQ3Failure : kQ3Success;
}

TQ3Status countProgress(TQ3ViewObject view, const void* data, unsigned long current, unsigned long completed)
{
    Calls& calls = *static_cast<Calls*>(const_cast<void*>(data));
    calls.view = view;
    calls.current.push_back(current);
    calls.completed.push_back(completed);
    return calls.progress++ == calls.failAt ? kQ3Failure : kQ3Success;
}

void countEndFrame(TQ3ViewObject view, void* data)
{
    Calls& calls = *static_cast<Calls*>(data);
    calls.view = view;
    ++calls.endFrame;
}

class ViewIdleApiTest : public Q3ApiTest {
protected:
    // Three points far apart, each submitted on its own.
    TQ3ViewStatus renderThreePoints(TestView& view)
    {
        return view.render([&](TQ3ViewObject v) {
            for (float x : {0.0f, 1.5f, 3.0f}) {
                const TQ3PointData point{{x, 0.5f, 0.0f}, nullptr};
                Q3Point_Submit(&point, v);
            }
        });
    }
    int litPixels(const Pixmap& image)
    {
        int count = 0;
        for (unsigned long y = 0; y < image.height(); ++y)
            for (unsigned long x = 0; x < image.width(); ++x)
                count += image.lit(x, y) ? 1 : 0;
        return count;
    }
};

TEST_F(ViewIdleApiTest, TheIdleMethodIsCalledBeforeEachObjectAndTheEndFrameMethodAtTheEnd)
{
    Pixmap image(64, 48);
    TestView view(image.pixmap());
    Calls calls;
    ASSERT_EQ(Q3View_SetIdleMethod(view.view(), countIdle, &calls), kQ3Success);
    ASSERT_EQ(Q3View_SetEndFrameMethod(view.view(), countEndFrame, &calls), kQ3Success);
    EXPECT_EQ(renderThreePoints(view), kQ3ViewStatusDone);
    EXPECT_EQ(calls.idle, 3);
    EXPECT_EQ(calls.endFrame, 1);
    EXPECT_EQ(calls.view, view.view());

    // Removed methods are not called.
    ASSERT_EQ(Q3View_SetIdleMethod(view.view(), nullptr, nullptr), kQ3Success);
    ASSERT_EQ(Q3View_SetEndFrameMethod(view.view(), nullptr, nullptr), kQ3Success);
    EXPECT_EQ(renderThreePoints(view), kQ3ViewStatusDone);
    EXPECT_EQ(calls.idle, 3);
    EXPECT_EQ(calls.endFrame, 1);
}

TEST_F(ViewIdleApiTest, FailureFromTheIdleMethodCancelsTheRender)
{
    Pixmap full(64, 48), cancelled(64, 48);
    {
        TestView view(full.pixmap());
        EXPECT_EQ(renderThreePoints(view), kQ3ViewStatusDone);
    }
    TestView view(cancelled.pixmap());
    Calls calls;
    calls.failAt = 1; // the second object
    ASSERT_EQ(Q3View_SetIdleMethod(view.view(), countIdle, &calls), kQ3Success);
    ASSERT_EQ(Q3View_SetEndFrameMethod(view.view(), countEndFrame, &calls), kQ3Success);
    EXPECT_EQ(renderThreePoints(view), kQ3ViewStatusCancelled);
    EXPECT_EQ(calls.idle, 2); // a cancelled loop asks no more
    EXPECT_EQ(calls.endFrame, 0);
    // Only the first point was drawn.
    EXPECT_GT(litPixels(full), 0);
    EXPECT_GT(litPixels(cancelled), 0);
    EXPECT_LT(litPixels(cancelled), litPixels(full));

    // The next loop starts afresh.
    calls.failAt = -1;
    EXPECT_EQ(renderThreePoints(view), kQ3ViewStatusDone);
    EXPECT_EQ(calls.endFrame, 1);
}

TEST_F(ViewIdleApiTest, TheProgressMethodIsPreferredAndReportsNoProgress)
{
    Pixmap image(64, 48);
    TestView view(image.pixmap());
    Calls calls;
    ASSERT_EQ(Q3View_SetIdleMethod(view.view(), countIdle, &calls), kQ3Success);
    ASSERT_EQ(Q3View_SetIdleProgressMethod(view.view(), countProgress, &calls), kQ3Success);
    EXPECT_EQ(renderThreePoints(view), kQ3ViewStatusDone);
    EXPECT_EQ(calls.idle, 0);
    EXPECT_EQ(calls.progress, 3);
    EXPECT_EQ(calls.current, (std::vector<unsigned long>{0, 0, 0}));
    EXPECT_EQ(calls.completed, (std::vector<unsigned long>{0, 0, 0}));

    calls.failAt = 3; // the first object of the next loop
    EXPECT_EQ(renderThreePoints(view), kQ3ViewStatusCancelled);
    EXPECT_EQ(calls.progress, 4);
}

TEST_F(ViewIdleApiTest, BoundingLoopsDoNotCallThem)
{
    Pixmap image(64, 48);
    TestView view(image.pixmap());
    Calls calls;
    ASSERT_EQ(Q3View_SetIdleMethod(view.view(), countIdle, &calls), kQ3Success);
    ASSERT_EQ(Q3View_SetEndFrameMethod(view.view(), countEndFrame, &calls), kQ3Success);
    ASSERT_EQ(Q3View_StartBoundingBox(view.view(), kQ3ComputeBoundsExact), kQ3Success);
    const TQ3PointData point{{1.0f, 2.0f, 3.0f}, nullptr};
    ASSERT_EQ(Q3Point_Submit(&point, view.view()), kQ3Success);
    TQ3BoundingBox box{};
    EXPECT_EQ(Q3View_EndBoundingBox(view.view(), &box), kQ3ViewStatusDone);
    EXPECT_EQ(calls.idle, 0);
    EXPECT_EQ(calls.endFrame, 0);
}

TEST_F(ViewIdleApiTest, BadViewsFail)
{
    Calls calls;
    TQ3RendererObject renderer = Q3Renderer_NewFromType(kQ3RendererTypeWireFrame);
    TQ3ViewObject dead = Q3View_New();
    ASSERT_EQ(Q3Object_Dispose(dead), kQ3Success);
    const struct {
        TQ3Object view;
        TQ3Error code;
    } bad[] = {{nullptr, kQ3ErrorNULLParameter}, {renderer, kQ3ErrorInvalidObjectType}, {dead, kQ3ErrorInvalidObject}};
    for (const auto& b : bad) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_SetIdleMethod(b.view, countIdle, &calls), kQ3Failure), b.code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_SetIdleProgressMethod(b.view, countProgress, &calls), kQ3Failure), b.code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_SetEndFrameMethod(b.view, countEndFrame, &calls), kQ3Failure), b.code);
    }
    Q3Object_Dispose(renderer);
}

TEST_F(ViewIdleApiTest, AFailedSetLeavesTheRegisteredMethods)
{
    Pixmap image(64, 48);
    TestView view(image.pixmap());
    Calls calls;
    ASSERT_EQ(Q3View_SetIdleMethod(view.view(), countIdle, &calls), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_SetIdleMethod(view.context(), nullptr, nullptr), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_EQ(renderThreePoints(view), kQ3ViewStatusDone);
    EXPECT_EQ(calls.idle, 3);
}

} // namespace
