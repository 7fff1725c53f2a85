// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Whole frames through Q3 against the same drawing done with raw OpenGL on an
// OSMesa context of the same size in the same process, paired in one loop
// (BenchTiming.h) on the wall clock: llvmpipe rasterizes on threads of its own.
//
// Scene: 1000 retained cubic Bezier curves (one span each, control points
// random in [-1, 1]^2 at z = 0) under constant subdivision with c1 = 64, so
// every curve is a 65-vertex line strip.
//
//   Frame/N        q3: Q3View_StartRendering, the style, 1000
//                  Q3Geometry_Submit, Q3View_EndRendering writing the N x N
//                  ARGB32 pixmap (B, G, R, A in memory);
//                  raw: the identical polylines (taken from
//                  Q3Geometry_GetDecomposed) in one client array, glClear,
//                  one glDrawArrays(GL_LINE_STRIP) per curve, glFinish,
//                  glReadPixels(GL_BGRA) into a buffer of the pixmap's format;
//                  rawmulti: the same with one glMultiDrawArrays;
//                  rawdirect: rawmulti on a BGRA context whose own buffer is
//                  the image (top row first), so no read-back at all
//                  (informational; llvmpipe draws lines into BGRA more slowly
//                  than into RGBA, so this bounds empty frames only).
//   FrameDepth/N   q3 as in Frame/N; rawmulti; rawdepth: rawmulti with the
//                  hidden-line removal Q3's interactive renderer (the bench
//                  view's) does since 2026-11-24: a 24-bit depth buffer
//                  cleared every frame, glDepthFunc(GL_LEQUAL). The same work
//                  as Q3's frame; the raw peers of Frame/N skip the depth
//                  test, which gives the same image here because every curve
//                  lies in the plane z = 0 but costs llvmpipe's threads less
//                  (informational).
//   FrameEdited/N  q3edited: every curve edited (Q3NURBCurve_SetKnot to its
//                  own value) and the frame drawn, so all 1000 are
//                  tessellated again; against raw (informational).
//   FrameCpu/N/S   the main thread's CPU time of a Q3 frame (S = 0 constant,
//                  1 screen space): for comparing builds, not paired.
//   FrameCpuRaw/N/M  the main thread's CPU time of the raw frame (M = 0 one
//                  glDrawArrays per strip, 1 glMultiDrawArrays), to compare
//                  with FrameCpu/N/0.
//   EmptyFrame/N   q3: StartRendering, EndRendering (pixmap written);
//                  raw: glClear, glFinish, glReadPixels;
//                  rawdirect: glClear, glFinish into a BGRA buffer (informational).
//
//   FrameScreenSpace/N  q3screen: the same 1000 curves under the default
//                  style (screen space, c1 = 20 pixels), so the adaptive
//                  method places every vertex; against raw (the constant
//                  polylines, a fixed yardstick for comparing builds).
//
// Before timing, Frame/N checks with the curves' NURBCurve::tessellations
// counters that after an edit the first frame subdivides all 1000 curves,
// and reports how many an unchanged second frame subdivides
// (evaluated_second_frame: 1000 since retained curves keep no polyline, issue
// 16's memory target; 0 with the polyline cache that came before, so the
// same source measures both), and compares the raw images with Q3's
// (pixels_differing, _multi, _direct; FrameDepth/N: _depth).
//
// Every timed frame follows an untimed frame by the same contender (see
// q3Contender below); the counters <contender>_ms are timed frames only.

#include "BenchCurves.h"
#include "BenchTiming.h"
#include "BenchView.h"

#include "core/Object.h"
#include "geometry/NURBCurve.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

constexpr std::size_t kCurveCount = 1000;
constexpr std::uint32_t kSegments = 64;

/// The retained curves, their polylines as Q3 draws them, and one Q3 view
/// per image size. Built once, on first use, and kept to the end of the run.
class Scene {
public:
    Scene()
    {
        q3bench::Random random(7);
        const float knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
        for (std::size_t i = 0; i < kCurveCount; ++i) {
            TQ3RationalPoint4D points[4];
            for (TQ3RationalPoint4D& p : points)
                p = {float(random.uniform(-1, 1)), float(random.uniform(-1, 1)), 0.0f, 1.0f};
            const TQ3NURBCurveData data{4, 4, points, const_cast<float*>(knots), nullptr};
            TQ3GeometryObject curve = Q3NURBCurve_New(&data);
            if (curve == nullptr)
                throw std::runtime_error("Q3NURBCurve_New failed");
            m_curves.push_back(curve);
        }
        collectPolylines();
    }

    ~Scene()
    {
        m_views.clear();
        for (TQ3GeometryObject curve : m_curves)
            Q3Object_Dispose(curve);
    }

    const std::vector<TQ3GeometryObject>& curves() const { return m_curves; }
    const std::vector<float>& xyz() const { return m_xyz; }
    const std::vector<GLint>& firsts() const { return m_firsts; }
    const std::vector<GLsizei>& counts() const { return m_counts; }

    q3bench::BenchView& view(unsigned long size)
    {
        std::unique_ptr<q3bench::BenchView>& view = m_views[size];
        if (!view)
            view = std::make_unique<q3bench::BenchView>(size, size);
        return *view;
    }

    /// One Q3 frame of the whole scene; false if any call failed. With
    /// `constant` false, the default style (screen space) is left in place.
    bool renderQ3(q3bench::BenchView& view, bool constant = true) const
    {
        const TQ3SubdivisionStyleData style = q3bench::constantStyle(float(kSegments));
        if (Q3View_StartRendering(view.view()) != kQ3Success)
            return false;
        bool ok = !constant || Q3SubdivisionStyle_Submit(&style, view.view()) == kQ3Success;
        for (TQ3GeometryObject curve : m_curves)
            ok = Q3Geometry_Submit(curve, view.view()) == kQ3Success && ok;
        return Q3View_EndRendering(view.view()) == kQ3ViewStatusDone && ok;
    }

    /// Edits every curve without changing it (a knot set to its own value),
    /// which empties its cache.
    void editAll() const
    {
        for (TQ3GeometryObject curve : m_curves)
            Q3NURBCurve_SetKnot(curve, 4, 1.0f);
    }

    /// The sum of every curve's NURBCurve::tessellations.
    std::uint64_t tessellations() const
    {
        std::uint64_t total = 0;
        for (TQ3GeometryObject curve : m_curves) {
            const std::uint64_t count = q3::lookup<q3::NURBCurve>(curve, "curve").tessellations();
            total += count;
        }
        return total;
    }

private:
    // The polylines the raw peer draws: exactly the vertices Q3 draws.
    void collectPolylines()
    {
        q3bench::BenchView& small = view(64);
        const TQ3SubdivisionStyleData style = q3bench::constantStyle(float(kSegments));
        if (Q3View_StartRendering(small.view()) != kQ3Success)
            throw std::runtime_error("Q3View_StartRendering failed");
        Q3SubdivisionStyle_Submit(&style, small.view());
        for (TQ3GeometryObject curve : m_curves) {
            TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(curve, small.view());
            TQ3PolyLineData data{};
            if (polyLine == nullptr || Q3PolyLine_GetData(polyLine, &data) != kQ3Success)
                throw std::runtime_error("Q3Geometry_GetDecomposed failed");
            m_firsts.push_back(GLint(m_xyz.size() / 3));
            m_counts.push_back(GLsizei(data.numVertices));
            for (unsigned long i = 0; i < data.numVertices; ++i) {
                const TQ3Point3D& p = data.vertices[i].point;
                m_xyz.insert(m_xyz.end(), {p.x, p.y, p.z});
            }
            Q3PolyLine_EmptyData(&data);
            Q3Object_Dispose(polyLine);
        }
        Q3View_EndRendering(small.view());
    }

    q3bench::Q3Session m_session;
    std::vector<TQ3GeometryObject> m_curves;
    std::vector<float> m_xyz;
    std::vector<GLint> m_firsts;
    std::vector<GLsizei> m_counts;
    std::map<unsigned long, std::unique_ptr<q3bench::BenchView>> m_views;
};

Scene& scene()
{
    static Scene instance;
    return instance;
}

/// How the raw peer gets its image into the pixmap's format.
enum class ReadBack {
    kReadPixels, ///< an RGBA context, then glReadPixels(GL_BGRA) into a buffer (the issue's peer)
    kDirect,     ///< a BGRA context whose buffer is the image, top row first: no read-back at all
};

/// Whether the raw peer removes hidden lines as Q3's interactive renderer
/// does (OffscreenRenderer.cpp, FrameOptions::depthTest): a 24-bit depth
/// buffer, cleared every frame, glDepthFunc(GL_LEQUAL).
enum class Depth { kNone, kTested };

/// A plain OSMesa program's rendering state: a context bound to its own
/// buffer, the camera's matrix loaded, flat shading without dithering, the
/// vertex array enabled.
class RawGl {
public:
    RawGl(unsigned long size, const TQ3Matrix4x4& clip, ReadBack readBack, Depth depth = Depth::kNone)
        : m_size(GLsizei(size)), m_readBack(readBack), m_depth(depth), m_buffer(size * size * 4),
          m_readPixels(readBack == ReadBack::kReadPixels ? size * size * 4 : 0)
    {
        m_context = OSMesaCreateContextExt(readBack == ReadBack::kDirect ? OSMESA_BGRA : OSMESA_RGBA,
                                           depth == Depth::kTested ? 24 : 0, 0, 0, nullptr);
        if (m_context == nullptr || !bind())
            throw std::runtime_error("creating the raw OSMesa context failed");
        if (readBack == ReadBack::kDirect)
            OSMesaPixelStore(OSMESA_Y_UP, 0);
        glViewport(0, 0, m_size, m_size);
        glMatrixMode(GL_PROJECTION);
        glLoadMatrixf(&clip.value[0][0]);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        // The state Q3 pins (OffscreenRenderer.cpp) where it differs from
        // OpenGL's defaults, so that both draw with the same pipeline.
        glDisable(GL_DITHER);
        glShadeModel(GL_FLAT);
        if (depth == Depth::kTested) {
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LEQUAL);
        }
        glEnableClientState(GL_VERTEX_ARRAY);
        release();
    }
    ~RawGl() { OSMesaDestroyContext(m_context); }
    RawGl(const RawGl&) = delete;
    RawGl& operator=(const RawGl&) = delete;

    bool bind() { return OSMesaMakeCurrent(m_context, m_buffer.data(), GL_UNSIGNED_BYTE, m_size, m_size); }
    void release() { OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0); }

    /// Clears, draws the scene's strips (or nothing), finishes (which is when
    /// OSMesa fills its buffer) and, for kReadPixels, reads back.
    void frame(const Scene* drawn, bool multiDraw)
    {
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(m_depth == Depth::kTested ? GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT : GL_COLOR_BUFFER_BIT);
        if (drawn != nullptr) {
            glColor3f(1.0f, 1.0f, 1.0f);
            glVertexPointer(3, GL_FLOAT, 0, drawn->xyz().data());
            if (multiDraw) {
                glMultiDrawArrays(GL_LINE_STRIP, drawn->firsts().data(), drawn->counts().data(),
                                  GLsizei(drawn->counts().size()));
            } else {
                for (std::size_t i = 0; i < drawn->counts().size(); ++i)
                    glDrawArrays(GL_LINE_STRIP, drawn->firsts()[i], drawn->counts()[i]);
            }
        }
        glFinish();
        if (m_readBack == ReadBack::kReadPixels)
            glReadPixels(0, 0, m_size, m_size, GL_BGRA, GL_UNSIGNED_BYTE, m_readPixels.data());
    }

    /// The image: B, G, R, A per pixel; rows bottom first after glReadPixels
    /// (OpenGL's order), top first in the direct buffer.
    const std::vector<std::uint8_t>& image() const
    {
        return m_readBack == ReadBack::kReadPixels ? m_readPixels : m_buffer;
    }
    bool bottomRowFirst() const { return m_readBack == ReadBack::kReadPixels; }

private:
    GLsizei m_size;
    ReadBack m_readBack;
    Depth m_depth;
    std::vector<std::uint8_t> m_buffer;
    std::vector<std::uint8_t> m_readPixels;
    OSMesaContext m_context = nullptr;
};

// The matrix Q3 hands OpenGL: world to frustum (Q3Camera_GetWorldToFrustum)
// then z_clip = -2 z - w (view/RenderPass.h, frustumToClip), row-vector form,
// whose memory is OpenGL's column-major layout of the same map.
TQ3Matrix4x4 clipMatrix(TQ3CameraObject camera)
{
    TQ3Matrix4x4 worldToFrustum;
    Q3Camera_GetWorldToFrustum(camera, &worldToFrustum);
    TQ3Matrix4x4 frustumToClip;
    Q3Matrix4x4_SetIdentity(&frustumToClip);
    frustumToClip.value[2][2] = -2.0f;
    frustumToClip.value[3][2] = -1.0f;
    TQ3Matrix4x4 clip;
    Q3Matrix4x4_Multiply(&worldToFrustum, &frustumToClip, &clip);
    return clip;
}

RawGl& raw(unsigned long size, ReadBack readBack = ReadBack::kReadPixels, Depth depth = Depth::kNone)
{
    static std::map<std::tuple<unsigned long, ReadBack, Depth>, std::unique_ptr<RawGl>> contexts;
    std::unique_ptr<RawGl>& context = contexts[{size, readBack, depth}];
    if (!context) {
        // Q3 makes the process's first OSMesa context (it pins the driver).
        Scene& s = scene();
        context = std::make_unique<RawGl>(size, clipMatrix(s.view(size).camera()), readBack, depth);
    }
    return *context;
}

// Pixels whose B, G, R differ between Q3's pixmap (top row first) and the
// raw image.
double differingPixels(const std::vector<std::uint8_t>& q3, const RawGl& gl, unsigned long size)
{
    std::size_t differing = 0;
    for (unsigned long y = 0; y < size; ++y) {
        const std::uint8_t* a = q3.data() + y * size * 4;
        const std::uint8_t* b = gl.image().data() + (gl.bottomRowFirst() ? size - 1 - y : y) * size * 4;
        for (unsigned long x = 0; x < size; ++x)
            differing += a[4 * x] != b[4 * x] || a[4 * x + 1] != b[4 * x + 1] || a[4 * x + 2] != b[4 * x + 2];
    }
    return double(differing);
}

double litPixels(const std::vector<std::uint8_t>& bgra)
{
    std::size_t lit = 0;
    for (std::size_t i = 0; i < bgra.size(); i += 4)
        lit += bgra[i + 2] > 127;
    return double(lit);
}

// Every contender's timed frame follows an untimed frame of its own. A frame
// drawn right after another OSMesa context drew costs far more than a steady
// one (measured here at 512 x 512: about 41 ms instead of 23 for Q3 and for
// raw alike), whoever draws it; that penalty belongs to alternating contexts,
// not to either contender, so it is kept out of both times.
q3bench::Contender q3Contender(const char* name, std::function<void()> frame, std::function<void()> warmUp)
{
    q3bench::Contender contender{name, std::move(frame)};
    contender.before = std::move(warmUp);
    return contender;
}

// The raw peer's turn: a raw program keeps its context current, so binding
// it (and releasing it, so that Q3 runs as it would in an application with
// no context of its own) is left out of its time, with its warm-up frame.
q3bench::Contender rawContender(const char* name, RawGl& gl, const Scene* drawn, bool multiDraw)
{
    q3bench::Contender contender{name, [&gl, drawn, multiDraw] { gl.frame(drawn, multiDraw); }};
    contender.before = [&gl, drawn, multiDraw] {
        gl.bind();
        gl.frame(drawn, multiDraw);
    };
    contender.after = [&gl] { gl.release(); };
    return contender;
}

// Checks the scene's caching and the peer's image before timing; false (with
// the benchmark skipped) if anything is off.
bool checkScene(benchmark::State& state, Scene& s, q3bench::BenchView& view, RawGl& gl, RawGl& direct)
{
    s.editAll();
    const std::uint64_t before = s.tessellations();
    const bool first = s.renderQ3(view);
    const std::uint64_t afterFirst = s.tessellations();
    const bool second = s.renderQ3(view);
    const std::uint64_t again = s.tessellations() - afterFirst;
    if (!first || !second || afterFirst - before != kCurveCount || (again != 0 && again != kCurveCount)) {
        state.SkipWithError(("after an edit the first frame subdivided " + std::to_string(afterFirst - before) +
                             " curves and an unchanged second frame " + std::to_string(again) +
                             " (or a frame failed)")
                                .c_str());
        return false;
    }
    state.counters["evaluated_first_frame"] = double(afterFirst - before);
    state.counters["evaluated_second_frame"] = double(again);
    state.counters["lit_pixels"] = litPixels(view.pixels());
    const unsigned long size = static_cast<unsigned long>(state.range(0));
    if (!gl.bind()) {
        state.SkipWithError("OSMesaMakeCurrent failed");
        return false;
    }
    gl.frame(&s, false);
    state.counters["pixels_differing"] = differingPixels(view.pixels(), gl, size);
    gl.frame(&s, true);
    state.counters["pixels_differing_multi"] = differingPixels(view.pixels(), gl, size);
    gl.release();
    if (!direct.bind()) {
        state.SkipWithError("OSMesaMakeCurrent failed");
        return false;
    }
    direct.frame(&s, true);
    state.counters["pixels_differing_direct"] = differingPixels(view.pixels(), direct, size);
    direct.release();
    return true;
}

void Frame(benchmark::State& state)
{
    const unsigned long size = static_cast<unsigned long>(state.range(0));
    Scene& s = scene();
    q3bench::BenchView& view = s.view(size);
    RawGl& gl = raw(size);
    RawGl& direct = raw(size, ReadBack::kDirect);
    if (!checkScene(state, s, view, gl, direct))
        return;
    const auto frame = [&] { s.renderQ3(view); };
    q3bench::runPaired(state, q3bench::Clock::kWall,
                       {q3Contender("q3", frame, frame), rawContender("raw", gl, &s, false),
                        rawContender("rawmulti", gl, &s, true), rawContender("rawdirect", direct, &s, true)});
}

// Frame/N's Q3 frame against raw OpenGL doing the same hidden-line removal
// (rawdepth) and, in the same loop, without it (rawmulti). A benchmark of its
// own so that Frame/N keeps the contenders it had for comparing builds.
void FrameDepth(benchmark::State& state)
{
    const unsigned long size = static_cast<unsigned long>(state.range(0));
    Scene& s = scene();
    q3bench::BenchView& view = s.view(size);
    RawGl& gl = raw(size);
    RawGl& depth = raw(size, ReadBack::kReadPixels, Depth::kTested);
    if (!s.renderQ3(view) || !depth.bind()) {
        state.SkipWithError("a frame failed");
        return;
    }
    depth.frame(&s, true);
    state.counters["pixels_differing_depth"] = differingPixels(view.pixels(), depth, size);
    depth.release();
    const auto frame = [&] { s.renderQ3(view); };
    q3bench::runPaired(state, q3bench::Clock::kWall,
                       {q3Contender("q3", frame, frame), rawContender("rawmulti", gl, &s, true),
                        rawContender("rawdepth", depth, &s, true)});
}

void FrameEdited(benchmark::State& state)
{
    const unsigned long size = static_cast<unsigned long>(state.range(0));
    Scene& s = scene();
    q3bench::BenchView& view = s.view(size);
    RawGl& gl = raw(size);
    const std::uint64_t before = s.tessellations();
    q3bench::runPaired(state, q3bench::Clock::kWall,
                       {q3Contender(
                            "q3edited",
                            [&] {
                                s.editAll();
                                s.renderQ3(view);
                            },
                            [&] { s.renderQ3(view); }),
                        rawContender("raw", gl, &s, false)});
    state.counters["tessellated_per_frame"] =
        double(s.tessellations() - before) / double(std::max<benchmark::IterationCount>(state.iterations(), 1));
}

void FrameScreenSpace(benchmark::State& state)
{
    const unsigned long size = static_cast<unsigned long>(state.range(0));
    Scene& s = scene();
    q3bench::BenchView& view = s.view(size);
    RawGl& gl = raw(size);
    if (!s.renderQ3(view, false)) {
        state.SkipWithError("a screen-space frame failed");
        return;
    }
    const std::uint64_t before = s.tessellations();
    const auto frame = [&] { s.renderQ3(view, false); };
    q3bench::runPaired(state, q3bench::Clock::kWall,
                       {q3Contender("q3screen", frame, frame), rawContender("raw", gl, &s, false)});
    // Timed and warm-up frames alike.
    state.counters["evaluated_per_frame"] =
        double(s.tessellations() - before) / double(std::max<benchmark::IterationCount>(2 * state.iterations(), 1));
}

// The main thread's CPU time of a Q3 frame of the 1000 retained curves
// (Google Benchmark's default clock: this thread only, so llvmpipe's
// rasterizer threads and the machine's other load are left out): what Q3
// itself spends per frame subdividing, batching and writing the pixmap.
// Arg 0: constant c1 = 64; 1: the default style (screen space, 20 px). Not
// paired: compare builds by running them alternately.
void FrameCpu(benchmark::State& state)
{
    const unsigned long size = static_cast<unsigned long>(state.range(0));
    const bool constant = state.range(1) == 0;
    Scene& s = scene();
    q3bench::BenchView& view = s.view(size);
    if (!s.renderQ3(view, constant)) {
        state.SkipWithError("a frame failed");
        return;
    }
    for (auto _ : state)
        s.renderQ3(view, constant);
}

// The main thread's CPU time of the raw peer's frame (one glMultiDrawArrays
// of the same polylines, glFinish, glReadPixels), as FrameCpu/N/0 measures
// Q3's: what a plain OpenGL program spends on the CPU that submits. Arg 1:
// 0 one glDrawArrays per strip, 1 glMultiDrawArrays.
void FrameCpuRaw(benchmark::State& state)
{
    const unsigned long size = static_cast<unsigned long>(state.range(0));
    const bool multiDraw = state.range(1) != 0;
    Scene& s = scene();
    RawGl& gl = raw(size);
    if (!gl.bind()) {
        state.SkipWithError("OSMesaMakeCurrent failed");
        return;
    }
    gl.frame(&s, multiDraw);
    for (auto _ : state)
        gl.frame(&s, multiDraw);
    gl.release();
}

void EmptyFrame(benchmark::State& state)
{
    const unsigned long size = static_cast<unsigned long>(state.range(0));
    q3bench::BenchView& view = scene().view(size);
    RawGl& gl = raw(size);
    RawGl& direct = raw(size, ReadBack::kDirect);
    const auto frame = [&] {
        Q3View_StartRendering(view.view());
        Q3View_EndRendering(view.view());
    };
    q3bench::runPaired(state, q3bench::Clock::kWall,
                       {q3Contender("q3", frame, frame), rawContender("raw", gl, nullptr, false),
                        rawContender("rawdirect", direct, nullptr, false)});
}

// Issue 16's misuse frame: a 128 x 128 pane (the bench camera shows
// [-1.1, 1.1]^2), 16 immediate-mode curves of 4 to 24 control points, every
// fourth with alternate control points 1000 times farther out (far outside the
// view), drawn under styles a user may submit, each paired with the same frame
// under the default style (screen space, 20 pixels). Immediate mode, so every
// frame subdivides every curve; warnings the styles cause are part of the
// frame (no handler is registered).
struct MisuseCurves {
    std::vector<std::vector<TQ3RationalPoint4D>> points;
    std::vector<std::vector<float>> knots;
    std::vector<TQ3NURBCurveData> data;

    MisuseCurves()
    {
        std::mt19937 rng(16u);
        std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
        std::uniform_int_distribution<int> count(4, 24);
        for (int c = 0; c < 16; ++c) {
            const unsigned long n = static_cast<unsigned long>(count(rng));
            const unsigned long order = std::min<unsigned long>(4, n);
            std::vector<TQ3RationalPoint4D> p;
            for (unsigned long i = 0; i < n; ++i) {
                const float far = (c % 4 == 3 && i % 2 == 1) ? 1000.0f : 1.0f;
                p.push_back({far * coordinate(rng), far * coordinate(rng), 0.0f, 1.0f});
            }
            std::vector<float> k;
            for (unsigned long i = 0; i < n + order; ++i)
                k.push_back(float(std::min(std::max<long>(long(i) - long(order) + 1, 0), long(n - order + 1))));
            points.push_back(std::move(p));
            knots.push_back(std::move(k));
        }
        for (std::size_t c = 0; c < points.size(); ++c)
            data.push_back({static_cast<unsigned long>(knots[c].size() - points[c].size()), points[c].size(),
                            points[c].data(), knots[c].data(), nullptr});
    }

    bool frame(TQ3ViewObject view, const TQ3SubdivisionStyleData* style) const
    {
        if (Q3View_StartRendering(view) != kQ3Success)
            return false;
        bool ok = true;
        if (style != nullptr)
            Q3SubdivisionStyle_Submit(style, view); // may warn: part of the frame
        for (const TQ3NURBCurveData& d : data)
            ok = Q3NURBCurve_Submit(&d, view) == kQ3Success && ok;
        return Q3View_EndRendering(view) == kQ3ViewStatusDone && ok;
    }
};

void MisuseFrame(benchmark::State& state)
{
    static const MisuseCurves curves;
    static q3bench::Q3Session session;
    static q3bench::BenchView view(128, 128);
    static const TQ3SubdivisionStyleData styles[] = {
        {kQ3SubdivisionMethodScreenSpace, 0.5f, 0.5f},   {kQ3SubdivisionMethodScreenSpace, 0.01f, 0.01f},
        {kQ3SubdivisionMethodScreenSpace, 1e-6f, 1e-6f}, {kQ3SubdivisionMethodWorldSpace, 1e-6f, 1e-6f},
        {kQ3SubdivisionMethodConstant, 1024.0f, 1024.0f}};
    static const char* names[] = {"screen0_5", "screen0_01", "screen1e_6", "world1e_6", "constant1024"};
    std::vector<q3bench::Contender> contenders;
    const auto byDefault = [&] { curves.frame(view.view(), nullptr); };
    // One view, one context: no warm-up frame is needed between contenders.
    contenders.push_back({"default", byDefault});
    for (std::size_t i = 0; i < std::size(styles); ++i) {
        const auto frame = [&, i] { curves.frame(view.view(), &styles[i]); };
        contenders.push_back({names[i], frame});
    }
    if (!curves.frame(view.view(), nullptr)) {
        state.SkipWithError("the misuse frame failed");
        return;
    }
    q3bench::runPaired(state, q3bench::Clock::kWall, contenders);
}

// Names: Frame/512 is the 512 x 512 image. The reported time covers every
// contender; the counters hold each one's.
BENCHMARK(Frame)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.5);
BENCHMARK(FrameDepth)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.5);
BENCHMARK(FrameEdited)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.5);
BENCHMARK(FrameScreenSpace)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.5);
BENCHMARK(FrameCpu)->Args({512, 0})->Args({512, 1})->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(FrameCpuRaw)->Args({512, 0})->Args({512, 1})->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(EmptyFrame)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(MisuseFrame)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

} // namespace

BENCHMARK_MAIN();
