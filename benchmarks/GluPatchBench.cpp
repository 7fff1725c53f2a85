// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Q3's NURB patch tessellation against GLU's gluNurbsSurface in
// GLU_NURBS_TESSELLATOR mode, on the same patch with the same number of
// triangles, paired in one loop (BenchTiming.h) and timed in wall time over
// the whole sequence each side's user runs to get triangles out:
//   Q3:  nurbs::tessellateSurface (Bézier extraction, evaluation of every
//        vertex in double precision with its exact normal and uv, the
//        triangles), reusing its output storage;
//   GLU: gluBeginSurface, gluNurbsSurface, gluEndSurface, with BEGIN /
//        VERTEX callbacks that turn GLU's strips and fans into a triangle
//        list in a preallocated buffer (three vertices per triangle). For a
//        GL_MAP2_VERTEX_4 surface GLU hands the vertex callback x, y, z
//        already divided by w (measured: reading a fourth float gives
//        garbage), unlike its curves.
// Q3's side also makes a unit normal and a (u, v) per vertex; GLU's makes
// none (GL_AUTO_NORMAL needs a GL context). As in GluTessellateBench.cpp,
// this process may not link OSMesa, so Q3's side is src/geometry/nurbs
// built into q3_bench_nurbs; Q3Geometry_GetDecomposed is not in it.
//
// The patch: a whole torus (major radius 1, minor 0.35) as a rational
// biquadratic surface of revolution, 9 x 9 control points, four rational
// quarter circles each way (Piegl & Tiller's construction), so 16 pairs of
// spans. Its exact shape gives each side's error without any evaluator: the
// distance of every vertex from the torus, | |(rho - R, z)| - r | with
// rho = |(x, y)|, computed in long double.
//
// Same triangle count: Q3's constant method with m segments per span gives
// 2 m^2 triangles per pair of spans. GLU_DOMAIN_DISTANCE with
// GLU_U_STEP = GLU_V_STEP = s gives a surface's span of parametric width h
// floor(h s) segments each way (measured: s = 15.5 gave 15, s = 63.5 gave
// 63; unlike its curves, which get one more), so s = m + 0.5 on these spans
// of width 1. The setup checks that both made the same number of triangles
// before timing.

#include "BenchTiming.h"

#include "geometry/nurbs/SurfaceTessellate.h"

#include <GL/glu.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

namespace nurbs = q3::nurbs;

constexpr double kMajor = 1.0;
constexpr double kMinor = 0.35;

/// The torus as a rational biquadratic patch (homogeneous control points).
struct Torus {
    std::vector<float> points; // x y z w, 9 x 9, row-major (rows in v)
    std::vector<float> knots = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};

    Torus()
    {
        // The unit circle as nine rational quadratic control points.
        static const double cs[9][3] = {{1, 0, 1},  {1, 1, M_SQRT1_2},   {0, 1, 1},  {-1, 1, M_SQRT1_2}, {-1, 0, 1},
                                        {-1, -1, M_SQRT1_2}, {0, -1, 1}, {1, -1, M_SQRT1_2}, {1, 0, 1}};
        for (int row = 0; row < 9; ++row)      // v: around the tube
            for (int column = 0; column < 9; ++column) { // u: around the axis
                const double rho = kMajor + kMinor * cs[row][0], z = kMinor * cs[row][1];
                const double w = cs[row][2] * cs[column][2];
                const double x = rho * cs[column][0], y = rho * cs[column][1];
                for (double value : {x * w, y * w, z * w, w})
                    points.push_back(float(value));
            }
    }

    nurbs::PatchRef ref() const
    {
        nurbs::PatchRef patch;
        patch.surface.uOrder = patch.surface.vOrder = 3;
        patch.surface.numColumns = patch.surface.numRows = 9;
        patch.surface.points = points.data();
        patch.surface.uKnots = patch.surface.vKnots = knots.data();
        return patch;
    }

    static long double error(const float* p)
    {
        const long double x = p[0], y = p[1], z = p[2];
        const long double rho = std::sqrt(x * x + y * y);
        return std::fabs(std::hypot(rho - kMajor, z) - kMinor);
    }
};

// Where GLU's callbacks write: triangles as three vertices each. The
// callbacks carry no user pointer, so the sink is global; its buffer is
// allocated before timing.
struct TriangleSink {
    std::vector<float> xyz;     // 9 floats per triangle
    std::size_t triangles = 0;  // made (may exceed the buffer: counted only)
    GLenum mode = 0;
    float window[2][3] = {};    // the strip's or fan's last two vertices
    std::size_t inPrimitive = 0;
    GLenum error = 0;
};
TriangleSink g_sink;

void emit(const float* a, const float* b, const float* c)
{
    if (9 * (g_sink.triangles + 1) <= g_sink.xyz.size()) {
        float* out = g_sink.xyz.data() + 9 * g_sink.triangles;
        for (int k = 0; k < 3; ++k) {
            out[k] = a[k];
            out[3 + k] = b[k];
            out[6 + k] = c[k];
        }
    }
    ++g_sink.triangles;
}

void GLAPIENTRY onBegin(GLenum mode)
{
    g_sink.mode = mode;
    g_sink.inPrimitive = 0;
}

void GLAPIENTRY onVertex(GLfloat* v)
{
    const float p[3] = {v[0], v[1], v[2]};
    const std::size_t n = g_sink.inPrimitive++;
    float (&w)[2][3] = g_sink.window;
    switch (g_sink.mode) {
    case GL_TRIANGLES:
        if (n % 3 == 2)
            emit(w[0], w[1], p);
        break;
    case GL_TRIANGLE_STRIP:
        if (n >= 2)
            (n % 2 == 0) ? emit(w[0], w[1], p) : emit(w[1], w[0], p);
        break;
    case GL_TRIANGLE_FAN:
        if (n >= 2)
            emit(w[0], w[1], p);
        break;
    case GL_QUAD_STRIP:
        if (n >= 2)
            (n % 2 == 0) ? emit(w[0], w[1], p) : emit(w[1], w[0], p);
        break;
    default:
        g_sink.error = GL_INVALID_ENUM;
        return;
    }
    // Keep what the next triangle needs: a fan keeps its centre.
    if (g_sink.mode == GL_TRIANGLE_FAN) {
        if (n == 0)
            std::copy(p, p + 3, w[0]);
        else
            std::copy(p, p + 3, w[1]);
    } else if (g_sink.mode == GL_TRIANGLES) {
        if (n % 3 < 2)
            std::copy(p, p + 3, w[n % 3]);
    } else {
        std::copy(w[1], w[1] + 3, w[0]);
        std::copy(p, p + 3, w[1]);
    }
}

void GLAPIENTRY onError(GLenum error)
{
    g_sink.error = error;
}

using Callback = void(GLAPIENTRY*)();

class GluSurface {
public:
    explicit GluSurface(float step)
    {
        m_nurbs = gluNewNurbsRenderer();
        gluNurbsProperty(m_nurbs, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
        gluNurbsProperty(m_nurbs, GLU_AUTO_LOAD_MATRIX, GL_FALSE);
        gluNurbsProperty(m_nurbs, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
        gluNurbsProperty(m_nurbs, GLU_U_STEP, step);
        gluNurbsProperty(m_nurbs, GLU_V_STEP, step);
        gluNurbsCallback(m_nurbs, GLU_NURBS_BEGIN, reinterpret_cast<Callback>(onBegin));
        gluNurbsCallback(m_nurbs, GLU_NURBS_VERTEX, reinterpret_cast<Callback>(onVertex));
        gluNurbsCallback(m_nurbs, GLU_NURBS_ERROR, reinterpret_cast<Callback>(onError));
    }
    ~GluSurface() { gluDeleteNurbsRenderer(m_nurbs); }
    GluSurface(const GluSurface&) = delete;
    GluSurface& operator=(const GluSurface&) = delete;

    void run(Torus& torus)
    {
        g_sink.triangles = 0;
        gluBeginSurface(m_nurbs);
        gluNurbsSurface(m_nurbs, GLint(torus.knots.size()), torus.knots.data(), GLint(torus.knots.size()),
                        torus.knots.data(), 4, 4 * 9, torus.points.data(), 3, 3, GL_MAP2_VERTEX_4);
        gluEndSurface(m_nurbs);
    }

private:
    GLUnurbs* m_nurbs = nullptr;
};

void Glu_Surface(benchmark::State& state, std::uint32_t segments)
{
    Torus torus;
    const nurbs::PatchRef patch = torus.ref();
    nurbs::TessellationOptions how;
    how.c1 = how.c2 = segments;
    nurbs::TessellatedSurface out;
    nurbs::tessellateSurface(patch, how, out);
    const std::size_t expected = 16 * 2 * std::size_t(segments) * segments;
    if (out.triangleCount() != expected) {
        state.SkipWithError(("Q3 gave " + std::to_string(out.triangleCount()) + " triangles").c_str());
        return;
    }
    GluSurface glu(float(segments) + 0.5f);
    g_sink.xyz.assign(9 * expected + 9, 0.0f);
    glu.run(torus);
    if (g_sink.error != 0 || g_sink.triangles != expected) {
        state.SkipWithError(("GLU gave " + std::to_string(g_sink.triangles) + " triangles, error " +
                             std::to_string(g_sink.error))
                                .c_str());
        return;
    }
    long double q3Error = 0, gluError = 0;
    for (std::size_t v = 0; v < out.vertexCount(); ++v)
        q3Error = std::max(q3Error, Torus::error(&out.positions[3 * v]));
    for (std::size_t v = 0; v < 3 * g_sink.triangles; ++v)
        gluError = std::max(gluError, Torus::error(&g_sink.xyz[3 * v]));

    q3bench::runPaired(state, q3bench::Clock::kWall,
                       {{"q3", [&] {
                             nurbs::tessellateSurface(patch, how, out);
                             benchmark::DoNotOptimize(out.triangles.data());
                         }},
                        {"glu", [&] {
                             glu.run(torus);
                             benchmark::DoNotOptimize(g_sink.xyz.data());
                         }}});
    state.counters["triangles"] = double(expected);
    state.counters["q3_vertices"] = double(out.vertexCount());
    state.counters["q3_max_error"] = double(q3Error);
    state.counters["glu_max_error"] = double(gluError);
}

} // namespace

BENCHMARK_CAPTURE(Glu_Surface, torus_m16, 16)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Glu_Surface, torus_m64, 64)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
