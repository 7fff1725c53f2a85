// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Bytes a retained NURB curve holds, relative to the size of its data (the
// TQ3NURBCurveData arrays: 16 bytes per control point, 4 per knot).
//
// Every C++ allocation in the process goes through the operator new below,
// which keeps a count of live blocks and of their usable bytes
// (malloc_usable_size: what the block really occupies, minus glibc's 8-byte
// chunk header). Q3 allocates with operator new for retained objects, except
// the arrays of QuickDraw 3D data structs (the curve's control points and
// knots), which are malloc blocks (src/core/LargeBlocks.h): their usable
// sizes are added to created_bytes from the curve itself.
// For each kind of curve, after a warm-up that renders an identical set (so
// llvmpipe's shader compilation and the view's batch buffers are already
// allocated), K curves are created and then rendered twice under constant
// subdivision with c1 = 64:
//   created_bytes   per curve after Q3NURBCurve_New (object, copies, registry)
//   cache_bytes     per curve added by the first frame (expected 0: a retained
//                   curve keeps no tessellation, src/geometry/NURBCurve.h)
//   second_frame    per curve added by the second frame (expected 0)
//   held_over_data  (created + cache) / data bytes: issue 16's target is <= 4
//   view_scratch_bytes  the view's one curve buffer (View::curveScratchBytes),
//                   which every frame subdivides into: it belongs to the view,
//                   not to any curve, and grows to the largest curve drawn
//   evaluations_per_frame  NURBCurve::tessellations added per curve by a frame
// The timed loop is Q3NURBCurve_New + Q3Object_Dispose of one such curve.

#include "BenchCurves.h"
#include "BenchView.h"

#include "core/Object.h"
#include "geometry/NURBCurve.h"
#include "view/View.h"

#include <benchmark/benchmark.h>

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

namespace {

std::atomic<long long> g_liveBytes{0};
std::atomic<long long> g_liveBlocks{0};

void* countedAllocate(std::size_t size)
{
    void* p = std::malloc(size == 0 ? 1 : size);
    if (p != nullptr) {
        g_liveBytes.fetch_add((long long)malloc_usable_size(p), std::memory_order_relaxed);
        g_liveBlocks.fetch_add(1, std::memory_order_relaxed);
    }
    return p;
}

void countedFree(void* p) noexcept
{
    if (p == nullptr)
        return;
    g_liveBytes.fetch_sub((long long)malloc_usable_size(p), std::memory_order_relaxed);
    g_liveBlocks.fetch_sub(1, std::memory_order_relaxed);
    std::free(p);
}

} // namespace

void* operator new(std::size_t size)
{
    if (void* p = countedAllocate(size))
        return p;
    throw std::bad_alloc();
}

void* operator new[](std::size_t size)
{
    return ::operator new(size);
}

void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
    return countedAllocate(size);
}

void* operator new[](std::size_t size, const std::nothrow_t&) noexcept
{
    return countedAllocate(size);
}

void operator delete(void* p) noexcept
{
    countedFree(p);
}

void operator delete[](void* p) noexcept
{
    countedFree(p);
}

void operator delete(void* p, std::size_t) noexcept
{
    countedFree(p);
}

void operator delete[](void* p, std::size_t) noexcept
{
    countedFree(p);
}

void operator delete(void* p, const std::nothrow_t&) noexcept
{
    countedFree(p);
}

void operator delete[](void* p, const std::nothrow_t&) noexcept
{
    countedFree(p);
}

namespace {

using q3bench::BenchCurve;

struct Live {
    long long bytes;
    long long blocks;
};

Live live()
{
    return Live{g_liveBytes.load(), g_liveBlocks.load()};
}

BenchCurve bezier4()
{
    BenchCurve curve;
    curve.order = 4;
    q3bench::Random random(11);
    for (int i = 0; i < 4; ++i)
        curve.points.insert(curve.points.end(),
                            {float(random.uniform(-1, 1)), float(random.uniform(-1, 1)), 0.0f, 1.0f});
    curve.knots = {0, 0, 0, 0, 1, 1, 1, 1};
    return curve;
}

const BenchCurve& curveNamed(int which)
{
    static const BenchCurve bezier = bezier4();
    static const BenchCurve cubic = q3bench::rationalCubic();
    static const BenchCurve sixteen = q3bench::orderSixteen();
    if (which == 3) {
        static const BenchCurve large = q3bench::makeCurve(16, 100000, 3);
        return large;
    }
    return which == 0 ? bezier : which == 1 ? cubic : sixteen;
}

std::vector<TQ3GeometryObject> makeCurves(const BenchCurve& curve, std::size_t count)
{
    const TQ3NURBCurveData data = q3bench::curveData(curve);
    std::vector<TQ3GeometryObject> curves;
    curves.reserve(count);
    for (std::size_t i = 0; i < count; ++i)
        curves.push_back(Q3NURBCurve_New(&data));
    return curves;
}

bool render(const q3bench::BenchView& view, const std::vector<TQ3GeometryObject>& curves)
{
    const TQ3SubdivisionStyleData style = q3bench::constantStyle(float(q3bench::kSegmentsPerSpan));
    if (Q3View_StartRendering(view.view()) != kQ3Success)
        return false;
    bool ok = Q3SubdivisionStyle_Submit(&style, view.view()) == kQ3Success;
    for (TQ3GeometryObject curve : curves)
        ok = Q3Geometry_Submit(curve, view.view()) == kQ3Success && ok;
    return Q3View_EndRendering(view.view()) == kQ3ViewStatusDone && ok;
}

void disposeAll(const std::vector<TQ3GeometryObject>& curves)
{
    for (TQ3GeometryObject curve : curves)
        if (curve != nullptr)
            Q3Object_Dispose(curve);
}

// which: 0 a 4-point cubic Bezier (K = 1000), 1 the 1000-point rational cubic
// and 2 the 1000-point order-16 curve (K = 10 each), 3 a 100,000-point order-16
// curve (K = 1): c1 = 64 is lowered to the segment cap, with the article's
// warning, and its polyline (2^20 segments) is the largest the view's buffer holds.
void Q3_RetainedCurve(benchmark::State& state, int which)
{
    const BenchCurve& curve = curveNamed(which);
    const std::size_t count = which == 0 ? 1000 : which == 3 ? 1 : 10;
    q3bench::Q3Session session;
    q3bench::BenchView view(64, 64);

    const std::vector<TQ3GeometryObject> warm = makeCurves(curve, count);
    const bool warmed = render(view, warm) && render(view, warm);
    const Live start = live();
    const std::vector<TQ3GeometryObject> curves = makeCurves(curve, count);
    const Live created = live();
    const bool first = render(view, curves);
    const Live cached = live();
    const bool second = render(view, curves);
    const Live again = live();
    if (!warmed || !first || !second) {
        state.SkipWithError("a frame failed");
        disposeAll(curves);
        disposeAll(warm);
        return;
    }

    const q3::NURBCurve& counted = q3::lookup<q3::NURBCurve>(curves.front(), "curve");

    const double k = double(count);
    const double dataBytes = double(curve.numPoints() * sizeof(TQ3RationalPoint4D) + curve.knots.size() * sizeof(float));
    const TQ3NURBCurveData& held = q3::lookup<q3::NURBCurve>(curves.front(), "curve").data();
    const double arrayBytes = double(malloc_usable_size(held.controlPoints) + malloc_usable_size(held.knots));
    const double createdBytes = double(created.bytes - start.bytes) / k + arrayBytes;
    const double cacheBytes = double(cached.bytes - created.bytes) / k;
    state.counters["data_bytes"] = dataBytes;
    state.counters["created_bytes"] = createdBytes;
    state.counters["cache_bytes"] = cacheBytes;
    state.counters["second_frame_bytes"] = double(again.bytes - cached.bytes) / k;
    state.counters["blocks"] = double(cached.blocks - start.blocks) / k + 2.0;
    state.counters["held_over_data"] = (createdBytes + cacheBytes) / dataBytes;
    state.counters["view_scratch_bytes"] =
        double(q3::lookup<q3::View>(view.view(), "view").curveScratchBytes());
    state.counters["evaluations_per_frame"] = double(counted.tessellations()) / 2.0;

    const TQ3NURBCurveData data = q3bench::curveData(curve);
    for (auto _ : state) {
        TQ3GeometryObject one = Q3NURBCurve_New(&data);
        benchmark::DoNotOptimize(one);
        Q3Object_Dispose(one);
    }
    disposeAll(curves);
    disposeAll(warm);
}

BENCHMARK_CAPTURE(Q3_RetainedCurve, bezier4, 0)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(Q3_RetainedCurve, cubic, 1)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(Q3_RetainedCurve, order16, 2)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(Q3_RetainedCurve, order16_large, 3)->Unit(benchmark::kMicrosecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
