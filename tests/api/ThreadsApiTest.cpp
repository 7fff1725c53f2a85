// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// What docs/threads.md promises, tested: views with their own objects render
// on separate threads at once, pixel for pixel as they do one after another;
// retained objects nobody changes may be drawn by several threads at once;
// each thread has its own error state; callbacks run on the posting thread.
// CI also runs these tests under ThreadSanitizer (scripts/test.sh).

#include "RenderTestSupport.h"

#include "QD3DMath.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace q3test;

constexpr int kThreads = 4;
constexpr int kFrames = 24;

using Image = std::vector<unsigned char>;

/// Holds threads at a line until all have reached it, so that their work
/// overlaps as much as possible.
class StartLine {
public:
    explicit StartLine(int count) : m_waiting(count) {}
    void arriveAndWait()
    {
        std::unique_lock<std::mutex> lock(m_mutex);
        if (--m_waiting == 0)
            m_released.notify_all();
        else
            m_released.wait(lock, [&] { return m_waiting == 0; });
    }

private:
    std::mutex m_mutex;
    std::condition_variable m_released;
    int m_waiting;
};

/// Objects that several threads draw at once and nobody changes meanwhile.
struct SharedScene {
    TQ3GeometryObject curve = nullptr;
    TQ3GeometryObject polyLine = nullptr;
    TQ3GeometryObject line = nullptr;
    TQ3GeometryObject point = nullptr;
    TQ3StyleObject style = nullptr;
    TQ3TransformObject transform = nullptr;
    TQ3AttributeSet color = nullptr;
};

/// A zigzag NURB curve of order 3 through 12 points: several spans, so the
/// subdivision styles make a difference.
struct Zigzag {
    TQ3RationalPoint4D points[12];
    float knots[15];

    explicit Zigzag(float phase)
    {
        for (int i = 0; i < 12; ++i)
            points[i] = {-0.4f + 0.35f * i, (i % 2 ? 1.6f : -0.6f) + phase, 0.0f, 1.0f + 0.5f * (i % 3)};
        for (int i = 0; i < 15; ++i)
            knots[i] = float(std::min(std::max(i - 2, 0), 10));
    }
    TQ3NURBCurveData data() { return TQ3NURBCurveData{3, 12, points, knots, nullptr}; }
};

/// Everything one thread renders with: its own view, pixmap, camera,
/// renderer and curves; which kind of each depends on the thread's number.
/// Counts the calls that did not succeed.
class ThreadScene {
public:
    explicit ThreadScene(int number)
        : m_number(number),
          m_image(64, 48, kPixelTypes[number % 4]),
          m_zigzag(0.1f * number)
    {
        TQ3CameraObject camera = nullptr;
        if (number % 2 == 0) {
            const TQ3OrthographicCameraData data = listing1OrthographicCamera();
            camera = Q3OrthographicCamera_New(&data);
        } else {
            TQ3ViewAngleAspectCameraData data{};
            data.cameraData.placement = {{1.5f, 0.5f, 4.0f + number}, {1.5f, 0.5f, 0.0f}, {0.0f, 1.0f, 0.0f}};
            data.cameraData.range = {0.5f, 50.0f};
            data.cameraData.viewPort = {{-1.0f, 1.0f}, 2.0f, 2.0f};
            data.fov = 0.9f;
            data.aspectRatioXToY = 64.0f / 48.0f;
            camera = Q3ViewAngleAspectCamera_New(&data);
        }
        count(camera != nullptr);
        m_view = std::make_unique<TestView>(
            m_image.pixmap(), number % 3 == 2 ? kQ3RendererTypeWireFrame : kQ3RendererTypeInteractive, camera);
        Q3Object_Dispose(camera);
        const TQ3NURBCurveData listing = m_listing.data();
        m_curve = Q3NURBCurve_New(&listing);
        count(m_curve != nullptr);
        m_color = Q3AttributeSet_New();
        const TQ3ColorRGB color{1.0f, 0.25f * number, 0.5f};
        count(Q3AttributeSet_Add(m_color, kQ3AttributeTypeDiffuseColor, &color) == kQ3Success);
    }

    ~ThreadScene()
    {
        Q3Object_Dispose(m_curve);
        Q3Object_Dispose(m_color);
    }

    ThreadScene(const ThreadScene&) = delete;
    ThreadScene& operator=(const ThreadScene&) = delete;

    /// Frame `frame`: the thread's own curves under a rotation, a style and a
    /// colour that change from frame to frame, then the shared objects (if
    /// any) under their own state.
    Image render(int frame, const SharedScene* shared)
    {
        const TQ3ViewStatus status = m_view->render([&](TQ3ViewObject view) {
            const TQ3RotateTransformData rotate{kQ3AxisZ, 0.03f * frame - 0.1f * m_number};
            const TQ3SubdivisionStyleData style =
                frame % 2 ? TQ3SubdivisionStyleData{kQ3SubdivisionMethodConstant, float(1 + frame % 7), 1.0f}
                          : TQ3SubdivisionStyleData{kQ3SubdivisionMethodScreenSpace, float(1 + frame % 5), 1.0f};
            count(Q3Push_Submit(view) == kQ3Success);
            count(Q3RotateTransform_Submit(&rotate, view) == kQ3Success);
            count(Q3SubdivisionStyle_Submit(&style, view) == kQ3Success);
            count(Q3AttributeSet_Submit(m_color, view) == kQ3Success);
            count(Q3Geometry_Submit(m_curve, view) == kQ3Success);
            const TQ3NURBCurveData zigzag = m_zigzag.data();
            count(Q3NURBCurve_Submit(&zigzag, view) == kQ3Success);
            count(Q3Pop_Submit(view) == kQ3Success);
            if (shared != nullptr) {
                count(Q3Object_Submit(shared->transform, view) == kQ3Success);
                count(Q3Object_Submit(shared->style, view) == kQ3Success);
                count(Q3AttributeSet_Submit(shared->color, view) == kQ3Success);
                count(Q3Geometry_Submit(shared->curve, view) == kQ3Success);
                count(Q3Geometry_Submit(shared->polyLine, view) == kQ3Success);
                count(Q3Geometry_Submit(shared->line, view) == kQ3Success);
                count(Q3Geometry_Submit(shared->point, view) == kQ3Success);
                TQ3GeometryObject decomposed = Q3Geometry_GetDecomposed(shared->curve, view);
                count(decomposed != nullptr);
                if (decomposed != nullptr)
                    Q3Object_Dispose(decomposed);
            }
        });
        count(status == kQ3ViewStatusDone);
        return m_image.bytes();
    }

    int failures() const { return m_failures; }

private:
    static constexpr TQ3PixelType kPixelTypes[4] = {kQ3PixelTypeARGB32, kQ3PixelTypeRGB16_565,
                                                    kQ3PixelTypeRGB24, kQ3PixelTypeARGB16};

    void count(bool succeeded)
    {
        if (!succeeded)
            ++m_failures;
    }

    int m_number;
    Pixmap m_image;
    Listing1 m_listing;
    Zigzag m_zigzag;
    std::unique_ptr<TestView> m_view;
    TQ3GeometryObject m_curve = nullptr;
    TQ3AttributeSet m_color = nullptr;
    int m_failures = 0;
};

/// Renders kFrames frames of thread `number`'s scene; creates and disposes
/// every object of its own on the calling thread.
std::vector<Image> renderFrames(int number, const SharedScene* shared, int& failures)
{
    std::vector<Image> frames;
    ThreadScene scene(number);
    for (int frame = 0; frame < kFrames; ++frame)
        frames.push_back(scene.render(frame, shared));
    failures = scene.failures();
    return frames;
}

/// The frames of every thread's scene rendered first one thread after
/// another on this thread, then by kThreads threads at once.
struct Runs {
    std::vector<std::vector<Image>> sequential;
    std::vector<std::vector<Image>> concurrent;
    int failures = 0;
};

Runs renderSequentiallyThenConcurrently(const SharedScene* shared)
{
    Runs runs;
    runs.sequential.resize(kThreads);
    runs.concurrent.resize(kThreads);
    for (int t = 0; t < kThreads; ++t) {
        int failures = 0;
        runs.sequential[t] = renderFrames(t, shared, failures);
        runs.failures += failures;
    }
    StartLine start(kThreads);
    std::vector<int> failures(kThreads, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            start.arriveAndWait();
            runs.concurrent[t] = renderFrames(t, shared, failures[t]);
        });
    for (std::thread& thread : threads)
        thread.join();
    for (int f : failures)
        runs.failures += f;
    return runs;
}

void expectSameFrames(const Runs& runs)
{
    for (int t = 0; t < kThreads; ++t) {
        ASSERT_EQ(runs.concurrent[t].size(), runs.sequential[t].size());
        int differing = 0;
        for (std::size_t f = 0; f < runs.sequential[t].size(); ++f)
            if (runs.concurrent[t][f] != runs.sequential[t][f])
                ++differing;
        EXPECT_EQ(differing, 0) << "thread " << t << ": frames rendered concurrently differ from the same "
                                   "frames rendered alone";
    }
}

/// At least one lit pixel in every frame, so the comparison means something.
void expectEveryFrameShowsSomething(const Runs& runs)
{
    for (int t = 0; t < kThreads; ++t)
        for (const Image& image : runs.sequential[t]) {
            const bool drawn = std::any_of(image.begin(), image.end(), [&](unsigned char byte) {
                return byte != image.front();
            });
            EXPECT_TRUE(drawn) << "thread " << t << " rendered an empty frame";
        }
}

class ThreadsApiTest : public Q3ApiTest {};

TEST_F(ThreadsApiTest, SeparateViewsRenderAtOnceExactlyAsOneAfterAnother)
{
    const Runs runs = renderSequentiallyThenConcurrently(nullptr);
    EXPECT_EQ(runs.failures, 0) << "calls failed; see the errors posted";
    expectEveryFrameShowsSomething(runs);
    expectSameFrames(runs);
}

TEST_F(ThreadsApiTest, UnchangedRetainedObjectsMayBeDrawnByManyThreadsAtOnce)
{
    Zigzag zigzag(0.3f);
    const TQ3NURBCurveData curve = zigzag.data();
    const TQ3SubdivisionStyleData style{kQ3SubdivisionMethodScreenSpace, 2.0f, 2.0f};
    const TQ3Vector3D offset{0.1f, -0.2f, 0.0f};
    const TQ3ColorRGB green{0.0f, 1.0f, 0.0f};
    TQ3Vertex3D vertices[3] = {{{-0.5f, -1.0f, 0.0f}, nullptr}, {{1.5f, 2.0f, 0.0f}, nullptr},
                               {{3.5f, -1.0f, 0.0f}, nullptr}};
    const TQ3PolyLineData polyLine{3, vertices, nullptr, nullptr};
    const TQ3LineData line{{{{-0.5f, 1.8f, 0.0f}, nullptr}, {{3.5f, 1.8f, 0.0f}, nullptr}}, nullptr};
    const TQ3PointData point{{1.5f, -0.8f, 0.0f}, nullptr};
    SharedScene shared;
    shared.curve = Q3NURBCurve_New(&curve);
    shared.polyLine = Q3PolyLine_New(&polyLine);
    shared.line = Q3Line_New(&line);
    shared.point = Q3Point_New(&point);
    shared.style = Q3SubdivisionStyle_New(&style);
    shared.transform = Q3TranslateTransform_New(&offset);
    shared.color = Q3AttributeSet_New();
    ASSERT_EQ(Q3AttributeSet_Add(shared.color, kQ3AttributeTypeDiffuseColor, &green), kQ3Success);

    const Runs runs = renderSequentiallyThenConcurrently(&shared);
    EXPECT_EQ(runs.failures, 0) << "calls failed; see the errors posted";
    expectEveryFrameShowsSomething(runs);
    expectSameFrames(runs);

    Q3Object_Dispose(shared.curve);
    Q3Object_Dispose(shared.polyLine);
    Q3Object_Dispose(shared.line);
    Q3Object_Dispose(shared.point);
    Q3Object_Dispose(shared.style);
    Q3Object_Dispose(shared.transform);
    Q3Object_Dispose(shared.color);
}

// Threads taking and dropping their own references to one shared curve, and
// creating, duplicating and disposing objects of their own, all at once:
// the reference count and the live-object registry stay exact.
TEST_F(ThreadsApiTest, ReferencesAndObjectsMayBeMadeAndDroppedOnManyThreadsAtOnce)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    const unsigned long liveBefore = Q3Memory_CountLiveObjects();
    StartLine start(kThreads);
    std::atomic<int> failures{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&] {
            start.arriveAndWait();
            for (int i = 0; i < 500; ++i) {
                TQ3SharedObject reference = Q3Shared_GetReference(curve);
                TQ3Object copy = Q3Object_Duplicate(curve);
                TQ3Object own = Q3NURBCurve_New(&data);
                float knot = 0.0f;
                if (reference != curve || copy == nullptr || own == nullptr ||
                    Q3NURBCurve_GetKnot(curve, 4, &knot) != kQ3Success || knot != 1.0f ||
                    Q3NURBCurve_SetKnot(own, 4, 0.5f) != kQ3Success || Q3Object_Dispose(copy) != kQ3Success ||
                    Q3Object_Dispose(own) != kQ3Success || Q3Object_Dispose(reference) != kQ3Success)
                    ++failures;
            }
        });
    for (std::thread& thread : threads)
        thread.join();
    EXPECT_EQ(failures.load(), 0);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), liveBefore);
    EXPECT_EQ(Q3Shared_IsReferenced(curve), kQ3False);
    Q3Object_Dispose(curve);
}

// Q3Error_Get reports the previous call on the calling thread only: another
// thread's failure in between neither shows up nor clears it.
TEST_F(ThreadsApiTest, ErrorStateIsPerThread)
{
    std::mutex mutex;
    std::condition_variable changed;
    int stage = 0;
    auto waitFor = [&](int wanted) {
        std::unique_lock<std::mutex> lock(mutex);
        changed.wait(lock, [&] { return stage == wanted; });
    };
    auto advance = [&] {
        std::lock_guard<std::mutex> lock(mutex);
        ++stage;
        changed.notify_all();
    };

    TQ3Error failingSaw = kQ3ErrorNone, succeedingSaw = kQ3ErrorInternalError;
    std::string failingMessage;
    std::thread failing([&] {
        Q3Object_Dispose(nullptr);  // posts kQ3ErrorNULLParameter on this thread
        advance();                  // 1
        waitFor(2);
        failingSaw = Q3Error_Get(nullptr);
        failingMessage = Q3Error_GetMessage();
    });
    std::thread succeeding([&] {
        waitFor(1);
        unsigned long major = 0, minor = 0;
        Q3GetVersion(&major, &minor);  // succeeds on this thread
        succeedingSaw = Q3Error_Get(nullptr);
        advance();                     // 2
    });
    failing.join();
    succeeding.join();
    EXPECT_EQ(failingSaw, kQ3ErrorNULLParameter);
    EXPECT_NE(failingMessage, "");
    EXPECT_EQ(succeedingSaw, kQ3ErrorNone);
    // This thread made neither call.
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNone);
    consume(Kind::Error, kQ3ErrorNULLParameter, "Q3Object_Dispose(nullptr) on another thread", __FILE__,
            __LINE__);
}

// The callbacks are process-wide: registered once, called for posts from any
// thread, on the thread that posted.
std::mutex g_callbackMutex;
std::vector<std::thread::id> g_callbackThreads;

void recordCallbackThread(TQ3Error, TQ3Error, long)
{
    std::lock_guard<std::mutex> lock(g_callbackMutex);
    g_callbackThreads.push_back(std::this_thread::get_id());
}

TEST(ThreadsApiCallbacks, RunOnThePostingThread)
{
    {
        std::lock_guard<std::mutex> lock(g_callbackMutex);
        g_callbackThreads.clear();
    }
    ASSERT_EQ(Q3Initialize(), kQ3Success);
    Q3Error_Register(&recordCallbackThread, 0);
    std::vector<std::thread> threads;
    std::vector<std::thread::id> ids(kThreads);
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            ids[t] = std::this_thread::get_id();
            Q3Object_Dispose(nullptr);
        });
    for (std::thread& thread : threads)
        thread.join();
    Q3Error_Register(nullptr, 0);
    Q3Exit();
    std::vector<std::thread::id> seen = g_callbackThreads;
    std::sort(seen.begin(), seen.end());
    std::sort(ids.begin(), ids.end());
    EXPECT_EQ(seen, ids);
}

} // namespace
