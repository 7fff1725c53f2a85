// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Q3's tessellation kernel against GLU's NURBS tessellator (SGI's sample
// implementation as Mesa ships it) on the curves of BenchCurves.h, paired in
// one loop (BenchTiming.h), in wall time like every benchmark here (both
// sides are single-threaded).
//
// This process holds libGLU, which links the GL dispatch library; its gl*
// entry points would clash with OSMesa's, so nothing here may link OSMesa.
// Q3's side is therefore only src/geometry/nurbs, pure math built into
// q3_bench_nurbs (benchmarks/CMakeLists.txt) from the same sources and flags
// as the library; everything that needs a view is in TessellateBench.cpp.
//
// GLU without a GL context: in GLU_NURBS_TESSELLATOR mode GLU evaluates the
// curve itself and hands vertices to callbacks. Traced with LD_DEBUG=bindings,
// gluNurbsCurve then resolves only glEnable(GL_MAP1_VERTEX_4), a no-op without
// a current context, once GLU_AUTO_LOAD_MATRIX is off (with it on GLU also
// reads the matrices and viewport with glGetFloatv and glGetIntegerv). The
// screen-space method gets its matrices from gluLoadSamplingMatrices. For
// GL_MAP1_VERTEX_4 the vertex callback receives homogeneous x, y, z, w.
//
// What GLU does with each sampling property, measured on these curves:
//   GLU_DOMAIN_DISTANCE   a span of width h gets floor(h * GLU_U_STEP) + 1
//                         segments (h * step = 64 gives 65) and is a line strip
//                         of its own that repeats the joint vertex; so
//                         GLU_U_STEP = 63.5 / h gives Q3's 64 per span, half a
//                         step away from rounding (the setup checks the count).
//   GLU_OBJECT_PATH_LENGTH  not implemented for curves: GLU falls back to
//                         GLU_U_STEP samples per span whatever the tolerance
//                         (U_STEP = 1e6 gave 10^6 segments per span), 100 by
//                         default. It is still the only object-space method
//                         GLU offers, so it is the world-space peer.
//   GLU_PATH_LENGTH       bounds the chord in pixels through a derivative
//                         bound on the projected control points.

#include "BenchCurves.h"
#include "BenchTiming.h"

#include "geometry/nurbs/Tessellate.h"

#include <GL/glu.h>
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace {

using q3bench::BenchCurve;
using q3bench::Space;
namespace nurbs = q3::nurbs;

// Where GLU's callbacks write. GLU_NURBS_VERTEX carries no user pointer, so
// the sink is global; the buffer is allocated before timing starts.
struct VertexSink {
    std::vector<float> xyz;
    std::size_t count = 0;  // vertices delivered
    std::size_t strips = 0; // GLU_NURBS_BEGIN calls
    GLenum error = 0;
};
VertexSink g_sink;

void GLAPIENTRY onBegin(GLenum)
{
    ++g_sink.strips;
}

// The polyline Q3 makes holds projected points, so the sink divides by w,
// in float as the GL pipeline would.
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

nurbs::CurveRef refOf(const BenchCurve& curve)
{
    nurbs::CurveRef ref;
    ref.order = curve.order;
    ref.numPoints = curve.numPoints();
    ref.points = curve.points.data();
    ref.knots = curve.knots.data();
    return ref;
}

void prepareSink(std::size_t vertices)
{
    g_sink = VertexSink{};
    g_sink.xyz.assign(3 * vertices, 0.0f);
}

std::string describeSink()
{
    return "GLU gave " + std::to_string(g_sink.count) + " vertices in " + std::to_string(g_sink.strips) +
           " strips, error " + std::to_string(g_sink.error);
}

// Constant method, 64 segments per span: GLU from the control points against
// nurbs::tessellate (constant) from the control points (Bezier conversion included,
// the output's storage reused as GLU reuses its own). Both make the same
// spans * 64 + 1 distinct vertices, so glu_over_q3 is the speed-up in
// vertices per second. The errors are the largest distance of a vertex from
// the long-double curve at the vertex's parameter.
//
// isa: the instruction set Q3's kernels use (the library picks AVX2 at run
// time where the CPU has it; kBaseline shows what baseline x86-64 SSE2 gives,
// the instruction set Debian's libGLU is built for).
void Glu_Constant(benchmark::State& state, int which, nurbs::KernelIsa isa)
{
    struct RestoreIsa {
        ~RestoreIsa() { nurbs::forceKernelIsa(nurbs::supportedKernelIsa()); }
    } restore;
    if (!nurbs::forceKernelIsa(isa)) {
        state.SkipWithError("this CPU does not support the requested kernel instruction set");
        return;
    }
    const BenchCurve& curve = curveNamed(which);
    const std::uint32_t m = q3bench::kSegmentsPerSpan;
    const std::size_t spans = curve.spanCount();
    prepareSink(spans * (m + 1));
    GluTessellator glu;
    glu.constant(float((m - 0.5) / q3bench::kKnotSpacing));
    glu.run(curve);
    if (g_sink.error != 0 || g_sink.count != spans * (m + 1) || g_sink.strips != spans) {
        state.SkipWithError(describeSink().c_str());
        return;
    }
    const double gluError = q3bench::maxSampleError(
        curve, g_sink.xyz.data(), m, [&](std::size_t s, std::uint32_t j) { return s * (m + 1) + j; });

    const nurbs::CurveRef ref = refOf(curve);
    nurbs::TessellatedCurve out;
    nurbs::TessellationOptions options;
    options.c1 = m;
    nurbs::tessellate(ref, options, out);
    if (out.vertexCount() != spans * m + 1) {
        state.SkipWithError(("Q3 gave " + std::to_string(out.vertexCount()) + " vertices").c_str());
        return;
    }
    const double q3Error = q3bench::maxSampleError(curve, out.vertices.data(), m,
                                                   [&](std::size_t s, std::uint32_t j) { return s * m + j; });

    q3bench::runPaired(state, q3bench::Clock::kWall,
                       {{"glu",
                         [&] {
                             glu.run(curve);
                             benchmark::DoNotOptimize(g_sink.xyz.data());
                             benchmark::ClobberMemory();
                         }},
                        {"q3", [&] {
                             nurbs::tessellate(ref, options, out);
                             benchmark::DoNotOptimize(out.vertices.data());
                             benchmark::ClobberMemory();
                         }}});
    const double scale = q3bench::curveScale(curve);
    state.counters["vertices"] = double(spans * m + 1);
    state.counters["q3_rel_error"] = q3Error / scale;
    state.counters["glu_rel_error"] = gluError / scale;
}

// GLU alone in wall time, every vertex delivered into the program's buffer
// (the callback writes it there): the peer of Q3_PublicPath in
// TessellateBench.cpp, which runs in the other process of the same run.
void Glu_WallPeer(benchmark::State& state, int which)
{
    const BenchCurve& curve = curveNamed(which);
    const std::uint32_t m = q3bench::kSegmentsPerSpan;
    const std::size_t spans = curve.spanCount();
    prepareSink(spans * (m + 1));
    GluTessellator glu;
    glu.constant(float((m - 0.5) / q3bench::kKnotSpacing));
    for (auto _ : state) {
        glu.run(curve);
        benchmark::DoNotOptimize(g_sink.xyz.data());
        benchmark::ClobberMemory();
    }
    if (g_sink.error != 0 || g_sink.count != spans * (m + 1))
        state.SkipWithError(describeSink().c_str());
    state.counters["vertices"] = double(g_sink.count);
}

// The benchmark's projection (BenchCurves.h, Projection::toPixels) as one
// matrix, model then projection, with the viewport as scale and offset.
nurbs::ProjectiveMapping projectiveOf(const q3bench::Projection& projection)
{
    nurbs::ProjectiveMapping map;
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            double sum = 0.0;
            for (int k = 0; k < 4; ++k)
                sum += double(projection.proj[4 * k + r]) * double(projection.model[4 * c + k]);
            map.matrix[r][c] = sum;
        }
    }
    map.scale[0] = 0.5 * projection.viewport[2];
    map.scale[1] = 0.5 * projection.viewport[3];
    map.scale[2] = 0.0;
    map.offset[0] = projection.viewport[0] + 0.5 * projection.viewport[2];
    map.offset[1] = projection.viewport[1] + 0.5 * projection.viewport[3];
    map.requirePositiveW = true;
    return map;
}

// Adaptive methods with c1 = arc length / (16 * spans) in the space: Q3's
// nurbs::tessellate (adaptive; world: identity mapping; screen: BenchCurves.h's
// projection to pixels) against GLU_OBJECT_PATH_LENGTH / GLU_PATH_LENGTH with
// the same tolerance. They make different vertex counts, reported with how
// close each comes to the fewest segments (segments / (L / c1)) and whether
// it keeps the bound (longest chord / c1).
void Glu_Adaptive(benchmark::State& state, Space space, int which)
{
    const BenchCurve& curve = curveNamed(which);
    const double length = q3bench::arcLength(curve, space);
    const double c1 = q3bench::adaptiveLength(curve, length);
    prepareSink(std::size_t(1) << 23);
    GluTessellator glu;
    glu.adaptive(space, float(c1));
    glu.run(curve);
    if (g_sink.error != 0 || 3 * g_sink.count > g_sink.xyz.size() || g_sink.strips == 0) {
        state.SkipWithError(describeSink().c_str());
        return;
    }
    // Each strip starts with the previous one's last vertex: a zero chord, so
    // the whole stream has the same longest chord as the strips.
    const std::size_t gluSegments = g_sink.count - g_sink.strips;
    const double gluLongest = q3bench::longestChord(g_sink.xyz.data(), g_sink.count, space);

    const q3bench::Projection projection;
    // As a view does it: the mapping handed over as a matrix
    // (nurbs::ProjectiveMapping, the form CurveTessellation.cpp passes; the
    // identity for world space), so Q3 can map each span's control points
    // once.
    const nurbs::ProjectiveMapping projective = projectiveOf(projection);
    const nurbs::CurveRef ref = refOf(curve);
    nurbs::TessellatedCurve out;
    nurbs::TessellationOptions options;
    options.method = nurbs::Method::kAdaptive;
    options.c1 = c1;
    if (space != Space::kWorld)
        options.mapping = projective; // the identity for world space
    const auto tessellate = [&] { nurbs::tessellate(ref, options, out); };
    tessellate();
    if (out.vertexCount() < 2 || out.substituted || out.capped) {
        state.SkipWithError("Q3's adaptive tessellation substituted or capped c1");
        return;
    }
    const double q3Segments = double(out.vertexCount() - 1);
    const double q3Longest = q3bench::longestChord(out.vertices.data(), out.vertexCount(), space);

    q3bench::runPaired(state, q3bench::Clock::kWall,
                       {{"glu",
                         [&] {
                             glu.run(curve);
                             benchmark::DoNotOptimize(g_sink.xyz.data());
                             benchmark::ClobberMemory();
                         }},
                        {"q3", [&] {
                             tessellate();
                             benchmark::DoNotOptimize(out.vertices.data());
                             benchmark::ClobberMemory();
                         }}});
    const double ideal = length / c1;
    state.counters["c1"] = c1;
    state.counters["q3_vertices"] = q3Segments + 1.0;
    state.counters["glu_vertices"] = double(gluSegments + 1);
    state.counters["q3_segments_per_ideal"] = q3Segments / ideal;
    state.counters["glu_segments_per_ideal"] = double(gluSegments) / ideal;
    state.counters["q3_longest_over_c1"] = q3Longest / c1;
    state.counters["glu_longest_over_c1"] = gluLongest / c1;
}

// Names end in the curve: cubic is the rational cubic, order16 the order-16
// curve (1000 control points each). The reported time covers both contenders;
// the counters hold each one's time.
BENCHMARK_CAPTURE(Glu_Constant, cubic, 0, nurbs::supportedKernelIsa())->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Glu_Constant, order16, 1, nurbs::supportedKernelIsa())->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Glu_Constant, cubic_baseline, 0, nurbs::KernelIsa::kBaseline)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Glu_Constant, order16_baseline, 1, nurbs::KernelIsa::kBaseline)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Glu_WallPeer, cubic, 0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Glu_Adaptive, world_cubic, Space::kWorld, 0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Glu_Adaptive, world_order16, Space::kWorld, 1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Glu_Adaptive, screen_cubic, Space::kScreen, 0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Glu_Adaptive, screen_order16, Space::kScreen, 1)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
