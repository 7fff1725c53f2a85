// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The peer of TessellateBench.cpp: the same curves tessellated by GLU's NURBS
// tessellator (SGI's sample implementation as Mesa ships it). It runs in a
// process of its own because libGLU links the GL dispatch library, whose gl*
// entry points would clash with OSMesa's in one process; benchmarks/run.sh
// reads both processes' JSON and forms the ratios.
//
// No GL context exists here, and none is needed: in GLU_NURBS_TESSELLATOR mode
// GLU evaluates the curve itself and hands vertices to callbacks. Traced with
// LD_DEBUG=bindings, gluNurbsCurve resolves only glEnable(GL_MAP1_VERTEX_4)
// (a no-op without a current context) once GLU_AUTO_LOAD_MATRIX is off; with
// it on, GLU would also read the matrices and viewport with glGetFloatv and
// glGetIntegerv. The screen-space method gets its matrices from
// gluLoadSamplingMatrices instead.
//
// GLU's step rule for GLU_DOMAIN_DISTANCE, measured: a span of width h gets
// floor(h * GLU_U_STEP) + 1 segments (h * step = 64 gives 65), and each span
// is its own line strip that repeats the joint vertex. So GLU_U_STEP =
// 63.5 / h gives the 64 segments per span Q3 makes, with half a step of
// margin against rounding; the setup checks the vertex count.

#include "BenchCurves.h"

#include <GL/glu.h>
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace {

using q3bench::BenchCurve;
using q3bench::Space;

// Where GLU's callbacks write. GLU_NURBS_VERTEX carries no user pointer, so
// the sink is global; the buffer is allocated before timing starts.
struct VertexSink {
    std::vector<float> xyz;
    std::size_t count = 0;   // vertices delivered
    std::size_t strips = 0;  // GLU_NURBS_BEGIN calls
    GLenum error = 0;
};
VertexSink g_sink;

void GLAPIENTRY onBegin(GLenum)
{
    ++g_sink.strips;
}

// For GL_MAP1_VERTEX_4 GLU delivers the homogeneous x, y, z, w (what
// glVertex4fv takes); the polyline Q3 makes is the projected point, so the
// sink divides, in float as the GL pipeline would.
void GLAPIENTRY onVertex(GLfloat* v)
{
    if (3 * (g_sink.count + 1) <= g_sink.xyz.size()) {
        float* out = g_sink.xyz.data() + 3 * g_sink.count;
        out[0] = v[0] / v[3];
        out[1] = v[1] / v[3];
        out[2] = v[2] / v[3];
    }
    ++g_sink.count;
}

void GLAPIENTRY onError(GLenum error)
{
    g_sink.error = error;
}

using Callback = void(GLAPIENTRY*)();

/// One GLU NURBS object in tessellator mode, set up for one sampling method.
class GluTessellator {
public:
    GluTessellator()
    {
        m_nurbs = gluNewNurbsRenderer();
        gluNurbsProperty(m_nurbs, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
        gluNurbsProperty(m_nurbs, GLU_AUTO_LOAD_MATRIX, GL_FALSE);
        gluNurbsCallback(m_nurbs, GLU_NURBS_BEGIN, reinterpret_cast<Callback>(onBegin));
        gluNurbsCallback(m_nurbs, GLU_NURBS_VERTEX, reinterpret_cast<Callback>(onVertex));
        gluNurbsCallback(m_nurbs, GLU_NURBS_ERROR, reinterpret_cast<Callback>(onError));
    }
    ~GluTessellator() { gluDeleteNurbsRenderer(m_nurbs); }
    GluTessellator(const GluTessellator&) = delete;
    GluTessellator& operator=(const GluTessellator&) = delete;

    void constant(float uStep)
    {
        gluNurbsProperty(m_nurbs, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
        gluNurbsProperty(m_nurbs, GLU_U_STEP, uStep);
    }

    /// GLU_OBJECT_PATH_LENGTH (world) or GLU_PATH_LENGTH through the
    /// benchmark's projection (screen), with `tolerance` as the longest edge.
    void adaptive(Space space, float tolerance)
    {
        if (space == Space::kWorld) {
            gluNurbsProperty(m_nurbs, GLU_SAMPLING_METHOD, GLU_OBJECT_PATH_LENGTH);
        } else {
            const q3bench::Projection projection;
            gluNurbsProperty(m_nurbs, GLU_SAMPLING_METHOD, GLU_PATH_LENGTH);
            gluLoadSamplingMatrices(m_nurbs, projection.model, projection.proj, projection.viewport);
        }
        gluNurbsProperty(m_nurbs, GLU_SAMPLING_TOLERANCE, tolerance);
    }

    /// Tessellates the curve into g_sink (emptied first).
    void run(const BenchCurve& curve)
    {
        g_sink.count = 0;
        g_sink.strips = 0;
        gluBeginCurve(m_nurbs);
        gluNurbsCurve(m_nurbs, GLint(curve.knots.size()), const_cast<float*>(curve.knots.data()), 4,
                      const_cast<float*>(curve.points.data()), GLint(curve.order), GL_MAP1_VERTEX_4);
        gluEndCurve(m_nurbs);
    }

private:
    GLUnurbs* m_nurbs = nullptr;
};

const BenchCurve& curveNamed(int which)
{
    static const BenchCurve cubic = q3bench::rationalCubic();
    static const BenchCurve sixteen = q3bench::orderSixteen();
    return which == 0 ? cubic : sixteen;
}

void prepareSink(std::size_t vertices)
{
    g_sink = VertexSink{};
    g_sink.xyz.assign(3 * vertices, 0.0f);
}

// Constant method, 64 segments per span. Items are distinct vertices
// (spans * 64 + 1), the count Q3 produces, so the rates compare equal work.
void GLU_Constant(benchmark::State& state, int which)
{
    const BenchCurve& curve = curveNamed(which);
    const std::uint32_t m = q3bench::kSegmentsPerSpan;
    const std::size_t spans = curve.spanCount();
    prepareSink(spans * (m + 1));
    GluTessellator glu;
    glu.constant(float((m - 0.5) / q3bench::kKnotSpacing));
    glu.run(curve);
    if (g_sink.error != 0 || g_sink.count != spans * (m + 1) || g_sink.strips != spans) {
        state.SkipWithError(("GLU gave " + std::to_string(g_sink.count) + " vertices in " +
                             std::to_string(g_sink.strips) + " strips, error " + std::to_string(g_sink.error))
                                .c_str());
        return;
    }
    const double error = q3bench::maxSampleError(curve, g_sink.xyz.data(), m, [&](std::size_t s, std::uint32_t j) {
        return s * (m + 1) + j;
    });
    for (auto _ : state) {
        glu.run(curve);
        benchmark::DoNotOptimize(g_sink.xyz.data());
        benchmark::ClobberMemory();
    }
    const double vertices = double(spans * m + 1);
    state.SetItemsProcessed(std::int64_t(state.iterations() * vertices));
    state.counters["vertices"] = vertices;
    state.counters["max_error"] = error;
    state.counters["rel_error"] = error / q3bench::curveScale(curve);
}

// World space (GLU_OBJECT_PATH_LENGTH) and screen space (GLU_PATH_LENGTH)
// with the c1 the Q3 side uses. Items are distinct vertices.
void GLU_Adaptive(benchmark::State& state, Space space, int which)
{
    const BenchCurve& curve = curveNamed(which);
    const double length = q3bench::arcLength(curve, space);
    const double c1 = q3bench::adaptiveLength(curve, length);
    prepareSink(std::size_t(1) << 23);
    GluTessellator glu;
    glu.adaptive(space, float(c1));
    glu.run(curve);
    if (g_sink.error != 0 || 3 * g_sink.count > g_sink.xyz.size() || g_sink.strips == 0) {
        state.SkipWithError(("GLU gave " + std::to_string(g_sink.count) + " vertices, error " +
                             std::to_string(g_sink.error))
                                .c_str());
        return;
    }
    // Each strip starts with the previous one's last vertex: a zero chord, so
    // the whole stream has the same longest chord as the strips.
    const std::size_t segments = g_sink.count - g_sink.strips;
    const double longest = q3bench::longestChord(g_sink.xyz.data(), g_sink.count, space);
    for (auto _ : state) {
        glu.run(curve);
        benchmark::DoNotOptimize(g_sink.xyz.data());
        benchmark::ClobberMemory();
    }
    const double vertices = double(segments + 1);
    state.SetItemsProcessed(std::int64_t(state.iterations() * vertices));
    state.counters["vertices"] = vertices;
    state.counters["segments_per_ideal"] = double(segments) / (length / c1);
    state.counters["longest_over_c1"] = longest / c1;
    state.counters["c1"] = c1;
}

// Names end in the curve: cubic is the rational cubic, order16 the order-16
// curve (1000 control points each).
BENCHMARK_CAPTURE(GLU_Constant, cubic, 0)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(GLU_Constant, order16, 1)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(GLU_Adaptive, world_cubic, Space::kWorld, 0)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(GLU_Adaptive, world_order16, Space::kWorld, 1)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(GLU_Adaptive, screen_cubic, Space::kScreen, 0)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(GLU_Adaptive, screen_order16, Space::kScreen, 1)->Unit(benchmark::kMicrosecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
