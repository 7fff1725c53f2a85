// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// A frame of one large retained TriMesh through Q3 against the same triangles
// drawn with raw OpenGL on an OSMesa context of the same size in the same
// process, paired in one loop (BenchTiming.h) on the wall clock.
//
// Scene: a 225 x 225 grid of points over [-1, 1]^2, a gentle wave in z, every
// point with its own diffuse colour: 100,352 triangles in one
// Q3TriMesh_New, drawn by the interactive renderer (filled, depth-tested,
// colours interpolated).
//
//   MeshFrame/N   q3: Q3View_StartRendering, Q3Geometry_Submit of the
//                 trimesh, Q3View_EndRendering writing the N x N ARGB32
//                 pixmap;
//                 raw: glClear of colour and depth, one glDrawElements of the
//                 same triangles from client arrays (positions and colours
//                 interleaved, 32-bit indices) with the same matrix, depth
//                 test and smooth shading, glFinish, glReadPixels(GL_BGRA);
//                 rawdirect: the same into a BGRA context whose own buffer is
//                 the image, top row first, so no read-back (informational:
//                 it bounds what any OSMesa program can do).
//
// Before timing it checks that the raw image equals Q3's (pixels_differing)
// and that an unchanged second frame reuses the trimesh's mesh
// (mesh_builds_second_frame must be 0).

#include "BenchTiming.h"
#include "BenchView.h"

#include "core/Object.h"
#include "geometry/TriMesh.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr unsigned long kGrid = 225;

class MeshScene {
public:
    MeshScene()
    {
        std::vector<TQ3Point3D> points;
        std::vector<TQ3ColorRGB> colors;
        for (unsigned long row = 0; row < kGrid; ++row)
            for (unsigned long column = 0; column < kGrid; ++column) {
                const float u = float(column) / float(kGrid - 1), v = float(row) / float(kGrid - 1);
                const float x = 2.0f * u - 1.0f, y = 2.0f * v - 1.0f;
                points.push_back({x, y, 0.2f * std::sin(6.0f * x) * std::cos(5.0f * y)});
                colors.push_back({u, v, 1.0f - 0.5f * (u + v)});
            }
        std::vector<TQ3TriMeshTriangleData> triangles;
        for (unsigned long row = 0; row + 1 < kGrid; ++row)
            for (unsigned long column = 0; column + 1 < kGrid; ++column) {
                const unsigned long a = row * kGrid + column, b = a + 1, c = a + kGrid, d = c + 1;
                triangles.push_back({{a, b, d}});
                triangles.push_back({{a, d, c}});
            }
        TQ3TriMeshAttributeData vertexColors{kQ3AttributeTypeDiffuseColor, colors.data(), nullptr};
        TQ3TriMeshData data{};
        data.numTriangles = triangles.size();
        data.triangles = triangles.data();
        data.numPoints = points.size();
        data.points = points.data();
        data.numVertexAttributeTypes = 1;
        data.vertexAttributeTypes = &vertexColors;
        m_mesh = Q3TriMesh_New(&data);
        if (m_mesh == nullptr)
            throw std::runtime_error("Q3TriMesh_New failed");
        for (std::size_t i = 0; i < points.size(); ++i)
            m_vertices.insert(m_vertices.end(), {points[i].x, points[i].y, points[i].z, colors[i].r, colors[i].g,
                                                 colors[i].b});
        for (const TQ3TriMeshTriangleData& t : triangles)
            for (unsigned long index : t.pointIndices)
                m_indices.push_back(GLuint(index));
        m_triangles = triangles.size();
    }

    ~MeshScene()
    {
        m_views.clear();
        Q3Object_Dispose(m_mesh);
    }

    q3bench::BenchView& view(unsigned long size)
    {
        std::unique_ptr<q3bench::BenchView>& view = m_views[size];
        if (!view)
            view = std::make_unique<q3bench::BenchView>(size, size);
        return *view;
    }

    bool renderQ3(q3bench::BenchView& view) const
    {
        if (Q3View_StartRendering(view.view()) != kQ3Success)
            return false;
        const bool ok = Q3Geometry_Submit(m_mesh, view.view()) == kQ3Success;
        return Q3View_EndRendering(view.view()) == kQ3ViewStatusDone && ok;
    }

    std::uint64_t meshBuilds() const { return q3::lookup<q3::TriMesh>(m_mesh, "mesh").meshBuilds(); }
    const std::vector<float>& vertices() const { return m_vertices; }
    const std::vector<GLuint>& indices() const { return m_indices; }
    std::size_t triangles() const { return m_triangles; }

private:
    q3bench::Q3Session m_session;
    TQ3GeometryObject m_mesh = nullptr;
    std::vector<float> m_vertices; // x y z r g b
    std::vector<GLuint> m_indices;
    std::size_t m_triangles = 0;
    std::map<unsigned long, std::unique_ptr<q3bench::BenchView>> m_views;
};

MeshScene& scene()
{
    static MeshScene instance;
    return instance;
}

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

/// A plain OSMesa program drawing the mesh: RGBA context with a depth
/// buffer, the camera's matrix, Q3's pinned state (no dithering) with the
/// depth test and smooth shading the interactive renderer uses.
class RawMesh {
public:
    RawMesh(unsigned long size, const TQ3Matrix4x4& clip, bool direct)
        : m_size(GLsizei(size)), m_direct(direct), m_buffer(size * size * 4), m_readPixels(size * size * 4)
    {
        m_context = OSMesaCreateContextExt(direct ? OSMESA_BGRA : OSMESA_RGBA, 24, 0, 0, nullptr);
        if (m_context == nullptr || !bind())
            throw std::runtime_error("creating the raw OSMesa context failed");
        if (direct)
            OSMesaPixelStore(OSMESA_Y_UP, 0);
        glViewport(0, 0, m_size, m_size);
        glMatrixMode(GL_PROJECTION);
        glLoadMatrixf(&clip.value[0][0]);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glDisable(GL_DITHER);
        glShadeModel(GL_SMOOTH);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        release();
    }
    ~RawMesh() { OSMesaDestroyContext(m_context); }
    RawMesh(const RawMesh&) = delete;
    RawMesh& operator=(const RawMesh&) = delete;

    bool bind() { return OSMesaMakeCurrent(m_context, m_buffer.data(), GL_UNSIGNED_BYTE, m_size, m_size); }
    void release() { OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0); }

    void frame(const MeshScene& s)
    {
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glVertexPointer(3, GL_FLOAT, 6 * sizeof(float), s.vertices().data());
        glColorPointer(3, GL_FLOAT, 6 * sizeof(float), s.vertices().data() + 3);
        glDrawElements(GL_TRIANGLES, GLsizei(s.indices().size()), GL_UNSIGNED_INT, s.indices().data());
        glFinish();
        if (!m_direct)
            glReadPixels(0, 0, m_size, m_size, GL_BGRA, GL_UNSIGNED_BYTE, m_readPixels.data());
    }

    /// B, G, R, A per pixel: bottom row first after glReadPixels, top row
    /// first in the direct buffer.
    const std::vector<std::uint8_t>& image() const { return m_direct ? m_buffer : m_readPixels; }
    bool bottomRowFirst() const { return !m_direct; }

private:
    GLsizei m_size;
    bool m_direct;
    std::vector<std::uint8_t> m_buffer;
    std::vector<std::uint8_t> m_readPixels;
    OSMesaContext m_context = nullptr;
};

RawMesh& raw(unsigned long size, bool direct)
{
    static std::map<std::pair<unsigned long, bool>, std::unique_ptr<RawMesh>> contexts;
    std::unique_ptr<RawMesh>& context = contexts[{size, direct}];
    if (!context)
        context = std::make_unique<RawMesh>(size, clipMatrix(scene().view(size).camera()), direct);
    return *context;
}

double differingPixels(const std::vector<std::uint8_t>& q3, const RawMesh& gl, unsigned long size)
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

void MeshFrame(benchmark::State& state)
{
    const unsigned long size = static_cast<unsigned long>(state.range(0));
    MeshScene& s = scene();
    q3bench::BenchView& view = s.view(size);
    RawMesh& gl = raw(size, false);
    RawMesh& direct = raw(size, true);

    const bool first = s.renderQ3(view);
    const std::uint64_t builds = s.meshBuilds();
    const bool second = s.renderQ3(view);
    if (!first || !second) {
        state.SkipWithError("a Q3 frame failed");
        return;
    }
    state.counters["triangles"] = double(s.triangles());
    state.counters["mesh_builds_second_frame"] = double(s.meshBuilds() - builds);
    if (!gl.bind()) {
        state.SkipWithError("OSMesaMakeCurrent failed");
        return;
    }
    gl.frame(s);
    state.counters["pixels_differing"] = differingPixels(view.pixels(), gl, size);
    gl.release();
    if (!direct.bind()) {
        state.SkipWithError("OSMesaMakeCurrent failed");
        return;
    }
    direct.frame(s);
    state.counters["pixels_differing_direct"] = differingPixels(view.pixels(), direct, size);
    direct.release();

    // As in FrameBench.cpp: each timed turn follows an untimed one by the same
    // contender, so the cost of switching OSMesa contexts stays out of both.
    const auto q3Frame = [&] { s.renderQ3(view); };
    q3bench::Contender q3{"q3", q3Frame};
    q3.before = q3Frame;
    auto peer = [&](const char* name, RawMesh& context) {
        q3bench::Contender contender{name, [&] { context.frame(s); }};
        contender.before = [&] {
            context.bind();
            context.frame(s);
        };
        contender.after = [&] { context.release(); };
        return contender;
    };
    q3bench::runPaired(state, q3bench::Clock::kWall, {q3, peer("raw", gl), peer("rawdirect", direct)});
}

BENCHMARK(MeshFrame)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.5);

} // namespace

BENCHMARK_MAIN();
