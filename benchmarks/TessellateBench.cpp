// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The public tessellation call against Q3's own kernel, in one process with
// a view (OSMesa), so no GLU here: GluTessellateBench.cpp pairs the kernel
// with GLU, and run.sh chains the two ratios. Wall time throughout (steady clock, as every benchmark here).
//
//   Q3_GetDecomposed   paired: inside a rendering loop of a 64 x 64 view,
//                      Q3NURBCurve_SetKnot (to the knot's own value) empties
//                      the curve's cache, Q3Geometry_GetDecomposed rebuilds it
//                      (Bezier form, tessellation) and makes a PolyLine,
//                      Q3Object_Dispose frees that; against the kernel,
//                      nurbs::tessellate (constant) from the control points into
//                      reused storage. Constant method, 64 segments per span.
//   Q3_Constant        the kernel alone (informational).
//   Q3_ConstantForm    the same from a prebuilt BezierForm, what a retained
//                      curve's cache holds (informational).

#include "BenchCurves.h"
#include "BenchTiming.h"
#include "BenchView.h"

#include "geometry/nurbs/Bezier.h"
#include "geometry/nurbs/Tessellate.h"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using q3bench::BenchCurve;
namespace nurbs = q3::nurbs;

const BenchCurve& curveNamed(int which)
{
    static const BenchCurve cubic = q3bench::rationalCubic();
    static const BenchCurve sixteen = q3bench::orderSixteen();
    return which == 0 ? cubic : sixteen;
}

nurbs::CurveRef refOf(const BenchCurve& curve)
{
    nurbs::CurveRef ref;
    ref.order = curve.order;
    ref.numPoints = curve.numPoints();
    ref.points = curve.points.data();
    ref.knots = curve.knots.data();
    return ref;
}

// Checks the vertex count and records the accuracy counters.
bool checkConstant(benchmark::State& state, const BenchCurve& curve, const nurbs::TessellatedCurve& out)
{
    const std::uint32_t m = q3bench::kSegmentsPerSpan;
    if (out.vertexCount() != curve.spanCount() * m + 1) {
        state.SkipWithError(("Q3 gave " + std::to_string(out.vertexCount()) + " vertices").c_str());
        return false;
    }
    const double error = q3bench::maxSampleError(curve, out.vertices.data(), m,
                                                 [&](std::size_t s, std::uint32_t j) { return s * m + j; });
    state.counters["max_error"] = error;
    state.counters["rel_error"] = error / q3bench::curveScale(curve);
    return true;
}

void finishItems(benchmark::State& state, double vertices)
{
    state.SetItemsProcessed(std::int64_t(double(state.iterations()) * vertices));
    state.counters["vertices"] = vertices;
}

// The constant method at kSegmentsPerSpan, as a view passes it.
const nurbs::TessellationOptions& constantOptions()
{
    static const nurbs::TessellationOptions options = [] {
        nurbs::TessellationOptions o;
        o.c1 = q3bench::kSegmentsPerSpan;
        return o;
    }();
    return options;
}

void Q3_Constant(benchmark::State& state, int which)
{
    const BenchCurve& curve = curveNamed(which);
    const nurbs::CurveRef ref = refOf(curve);
    nurbs::TessellatedCurve out;
    nurbs::tessellate(ref, constantOptions(), out);
    if (!checkConstant(state, curve, out))
        return;
    for (auto _ : state) {
        nurbs::tessellate(ref, constantOptions(), out);
        benchmark::DoNotOptimize(out.vertices.data());
        benchmark::ClobberMemory();
    }
    finishItems(state, double(out.vertexCount()));
}

void Q3_ConstantForm(benchmark::State& state, int which)
{
    const BenchCurve& curve = curveNamed(which);
    const nurbs::BezierForm form(refOf(curve));
    nurbs::TessellatedCurve out;
    nurbs::tessellate(form, constantOptions(), out);
    if (!checkConstant(state, curve, out))
        return;
    for (auto _ : state) {
        nurbs::tessellate(form, constantOptions(), out);
        benchmark::DoNotOptimize(out.vertices.data());
        benchmark::ClobberMemory();
    }
    finishItems(state, double(out.vertexCount()));
}

// A retained curve inside a rendering loop under the constant style at
// kSegmentsPerSpan, for the benchmarks of the public decomposition path;
// edit() changes nothing but the curve's edit index, so nothing is reused.
class DecomposingCurve {
public:
    explicit DecomposingCurve(const BenchCurve& curve)
        : m_view(64, 64), m_knotIndex(curve.knots.size() / 2), m_knot(curve.knots[m_knotIndex])
    {
        const TQ3NURBCurveData data = q3bench::curveData(curve);
        m_nurb = Q3NURBCurve_New(&data);
        m_rendering = m_nurb != nullptr && Q3View_StartRendering(m_view.view()) == kQ3Success;
        if (m_rendering) {
            const TQ3SubdivisionStyleData style = q3bench::constantStyle(float(q3bench::kSegmentsPerSpan));
            Q3SubdivisionStyle_Submit(&style, m_view.view());
        }
    }
    ~DecomposingCurve()
    {
        if (m_rendering)
            Q3View_EndRendering(m_view.view());
        if (m_nurb != nullptr)
            Q3Object_Dispose(m_nurb);
    }
    DecomposingCurve(const DecomposingCurve&) = delete;
    DecomposingCurve& operator=(const DecomposingCurve&) = delete;

    bool ready() const { return m_rendering; }
    TQ3GeometryObject nurb() const { return m_nurb; }
    TQ3ViewObject view() const { return m_view.view(); }
    void edit() const { Q3NURBCurve_SetKnot(m_nurb, m_knotIndex, m_knot); }

private:
    q3bench::BenchView m_view;
    unsigned long m_knotIndex;
    float m_knot;
    TQ3GeometryObject m_nurb = nullptr;
    bool m_rendering = false;
};

void Q3_GetDecomposed(benchmark::State& state, int which)
{
    const BenchCurve& curve = curveNamed(which);
    q3bench::Q3Session session;
    const DecomposingCurve subject(curve);
    if (!subject.ready()) {
        state.SkipWithError("creating the curve or starting the rendering loop failed");
        return;
    }
    TQ3GeometryObject nurb = subject.nurb();

    // The polyline must have every vertex the kernel makes.
    TQ3GeometryObject first = Q3Geometry_GetDecomposed(nurb, subject.view());
    TQ3PolyLineData polyLine{};
    const bool complete = first != nullptr && Q3PolyLine_GetData(first, &polyLine) == kQ3Success &&
                          polyLine.numVertices == curve.spanCount() * q3bench::kSegmentsPerSpan + 1;
    if (first != nullptr) {
        Q3PolyLine_EmptyData(&polyLine);
        Q3Object_Dispose(first);
    }
    if (!complete) {
        state.SkipWithError("Q3Geometry_GetDecomposed did not give spans * 64 + 1 vertices");
        return;
    }

    const nurbs::CurveRef ref = refOf(curve);
    nurbs::TessellatedCurve out;
    q3bench::runPaired(state, q3bench::Clock::kWall,
                       {{"decomposed",
                         [&] {
                             subject.edit();
                             TQ3GeometryObject decomposed = Q3Geometry_GetDecomposed(nurb, subject.view());
                             benchmark::DoNotOptimize(decomposed);
                             Q3Object_Dispose(decomposed);
                         }},
                        {"kernel", [&] {
                             nurbs::tessellate(ref, constantOptions(), out);
                             benchmark::DoNotOptimize(out.vertices.data());
                             benchmark::ClobberMemory();
                         }}});
    state.counters["vertices"] = double(curve.spanCount() * q3bench::kSegmentsPerSpan + 1);
}

// The whole sequence a program runs to get a curve's vertices out, in wall
// time (system time included: page faults, memory returned to the kernel):
// an edit so that nothing is reused, Q3Geometry_GetDecomposed,
// Q3PolyLine_GetData, every vertex read, Q3PolyLine_EmptyData,
// Q3Object_Dispose. Its peer is Glu_WallPeer in GluTessellateBench.cpp (GLU's
// tessellation with every vertex delivered into the program's buffer).
void Q3_PublicPath(benchmark::State& state, int which)
{
    const BenchCurve& curve = curveNamed(which);
    q3bench::Q3Session session;
    const DecomposingCurve subject(curve);
    if (!subject.ready()) {
        state.SkipWithError("creating the curve or starting the rendering loop failed");
        return;
    }
    TQ3GeometryObject nurb = subject.nurb();
    std::vector<float> user(3 * (curve.spanCount() * q3bench::kSegmentsPerSpan + 1));
    std::size_t delivered = 0;
    for (auto _ : state) {
        subject.edit();
        TQ3GeometryObject decomposed = Q3Geometry_GetDecomposed(nurb, subject.view());
        TQ3PolyLineData polyLine{};
        if (decomposed != nullptr && Q3PolyLine_GetData(decomposed, &polyLine) == kQ3Success) {
            delivered = std::min<std::size_t>(polyLine.numVertices, user.size() / 3);
            for (std::size_t i = 0; i < delivered; ++i) {
                user[3 * i] = polyLine.vertices[i].point.x;
                user[3 * i + 1] = polyLine.vertices[i].point.y;
                user[3 * i + 2] = polyLine.vertices[i].point.z;
            }
            Q3PolyLine_EmptyData(&polyLine);
        }
        if (decomposed != nullptr)
            Q3Object_Dispose(decomposed);
        benchmark::DoNotOptimize(user.data());
        benchmark::ClobberMemory();
    }
    if (delivered != curve.spanCount() * q3bench::kSegmentsPerSpan + 1)
        state.SkipWithError("the public path did not deliver spans * 64 + 1 vertices");
    state.counters["vertices"] = double(delivered);
}

// Names end in the curve, as in GluTessellateBench.cpp: cubic is the rational
// cubic, order16 the order-16 curve (1000 control points each).
BENCHMARK_CAPTURE(Q3_Constant, cubic, 0)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(Q3_Constant, order16, 1)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(Q3_ConstantForm, cubic, 0)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(Q3_ConstantForm, order16, 1)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(Q3_GetDecomposed, cubic, 0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Q3_GetDecomposed, order16, 1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Q3_PublicPath, cubic, 0)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
