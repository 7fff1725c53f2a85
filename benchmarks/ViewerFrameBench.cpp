// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// q3view's frame (issue 28: at least 30 frames a second on a 10,000-triangle
// model at 800 x 600 on llvmpipe), through the public API as q3view draws:
// an X window on an Xvfb the benchmark starts itself (tests/x11/XvfbServer.h;
// skipped with a message where Xvfb cannot start), Apple's X11 draw context
// (Q3X_GetVisualInfo, Q3XDrawContext_New), a view angle aspect camera that
// turns a little every frame (as an orbit drag does), an ambient and a
// directional light, a Phong illumination shader, the interactive renderer.
//
// Model: a latitude-longitude sphere of 50 x 100 quads, 10,000 triangles in
// one TriMesh with vertex normals.
//
//   ViewerFrame/window   a whole frame into the 800 x 600 window, with an
//                        XSync after it (the frame is on the screen);
//                        counter fps
//   ViewerFrame/pixmap   the same frame into an 800 x 600 pixmap draw
//                        context (no X server involved): the difference is
//                        what showing the frame in the window costs
//
// Counters: fps (frames per wall-clock second) and process_cpu_ms, the CPU
// time of all the process's threads per frame (llvmpipe's included), which
// does not depend on what else the machine runs: on 2 cores a frame takes
// at least half of it.
//
// Wall time (UseRealTime): what a user of the viewer waits for.

#include <benchmark/benchmark.h>

// Apple's X11 declarations, which this tree's C++ is built without (for
// GoogleTest and Google Benchmark, whose names Xlib's macros would break:
// src/CMakeLists.txt); included after benchmark.h for that reason.
#undef WINDOW_SYSTEM_X11
#define WINDOW_SYSTEM_X11 1
#include "XvfbServer.h"

#include "QD3D.h"
#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DMath.h"
#include "QD3DRenderer.h"
#include "QD3DShader.h"
#include "QD3DView.h"

#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

#include <sys/resource.h>

namespace {

constexpr unsigned long kWidth = 800;
constexpr unsigned long kHeight = 600;
constexpr unsigned long kRings = 50;    // quads from pole to pole
constexpr unsigned long kSegments = 100; // quads around

TQ3GeometryObject newSphere()
{
    std::vector<TQ3Point3D> points;
    std::vector<TQ3Vector3D> normals;
    for (unsigned long ring = 0; ring <= kRings; ++ring)
        for (unsigned long segment = 0; segment <= kSegments; ++segment) {
            const float theta = 3.14159265f * float(ring) / float(kRings);
            const float phi = 2 * 3.14159265f * float(segment) / float(kSegments);
            const TQ3Vector3D n{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
            points.push_back({n.x, n.y, n.z});
            normals.push_back(n);
        }
    std::vector<TQ3TriMeshTriangleData> triangles;
    const unsigned long row = kSegments + 1;
    for (unsigned long ring = 0; ring < kRings; ++ring)
        for (unsigned long segment = 0; segment < kSegments; ++segment) {
            const unsigned long a = ring * row + segment;
            triangles.push_back({{a, a + row, a + 1}});
            triangles.push_back({{a + 1, a + row, a + row + 1}});
        }
    TQ3TriMeshAttributeData vertexNormals{kQ3AttributeTypeNormal, normals.data(), nullptr};
    TQ3TriMeshData data{};
    data.numTriangles = triangles.size();
    data.triangles = triangles.data();
    data.numPoints = points.size();
    data.points = points.data();
    data.numVertexAttributeTypes = 1;
    data.vertexAttributeTypes = &vertexNormals;
    data.bBox = {{-1, -1, -1}, {1, 1, 1}, kQ3False};
    return Q3TriMesh_New(&data);
}

TQ3CameraObject newCamera()
{
    TQ3ViewAngleAspectCameraData data{};
    data.cameraData.placement.cameraLocation = {0, 0, 4};
    data.cameraData.placement.upVector = {0, 1, 0};
    data.cameraData.range = {1, 10};
    data.cameraData.viewPort = {{-1, 1}, 2, 2};
    data.fov = 0.8f;
    data.aspectRatioXToY = float(kWidth) / float(kHeight);
    return Q3ViewAngleAspectCamera_New(&data);
}

TQ3GroupObject newLights()
{
    TQ3GroupObject group = Q3LightGroup_New();
    const TQ3LightData ambient{kQ3True, 0.3f, {1, 1, 1}};
    const TQ3DirectionalLightData directional{{kQ3True, 1.0f, {1, 1, 1}}, kQ3False, {-0.3f, -0.5f, -1}};
    TQ3LightObject a = Q3AmbientLight_New(&ambient), d = Q3DirectionalLight_New(&directional);
    Q3Group_AddObject(group, a);
    Q3Group_AddObject(group, d);
    Q3Object_Dispose(a);
    Q3Object_Dispose(d);
    return group;
}

// A view drawing the sphere into a draw context, the camera turning by a
// degree a frame.
class Scene {
public:
    explicit Scene(TQ3DrawContextObject context)
        : m_view(Q3View_New()), m_camera(newCamera()), m_lights(newLights()), m_sphere(newSphere()),
          m_phong(Q3PhongIllumination_New())
    {
        Q3View_SetDrawContext(m_view, context);
        Q3View_SetCamera(m_view, m_camera);
        Q3View_SetLightGroup(m_view, m_lights);
        Q3View_SetRendererByType(m_view, kQ3RendererTypeInteractive);
    }
    ~Scene()
    {
        for (TQ3Object object : {m_view, m_camera, m_lights, m_sphere, m_phong})
            Q3Object_Dispose(object);
    }
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    bool frame()
    {
        m_angle += 0.0174533f;
        TQ3CameraPlacement placement{{4 * std::sin(m_angle), 0, 4 * std::cos(m_angle)}, {0, 0, 0}, {0, 1, 0}};
        Q3Camera_SetPlacement(m_camera, &placement);
        if (Q3View_StartRendering(m_view) != kQ3Success)
            return false;
        TQ3ViewStatus status;
        do {
            Q3Object_Submit(m_phong, m_view);
            Q3Object_Submit(m_sphere, m_view);
            status = Q3View_EndRendering(m_view);
        } while (status == kQ3ViewStatusRetraverse);
        return status == kQ3ViewStatusDone;
    }

private:
    TQ3ViewObject m_view;
    TQ3CameraObject m_camera;
    TQ3GroupObject m_lights;
    TQ3GeometryObject m_sphere;
    TQ3ShaderObject m_phong;
    float m_angle = 0;
};

// CPU seconds of every thread of this process so far (llvmpipe rasterizes
// on threads of its own).
double processCpuSeconds()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
}

void runFrames(benchmark::State& state, Scene& scene, Display* display)
{
    const double cpuStart = processCpuSeconds();
    for (auto _ : state) {
        if (!scene.frame()) {
            state.SkipWithError("a frame failed");
            break;
        }
        if (display != nullptr)
            XSync(display, False);
    }
    const double cpu = processCpuSeconds() - cpuStart;
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    // The load-independent cost: CPU milliseconds of all the process's
    // threads per frame (the X server's work for the window is not in it).
    state.counters["process_cpu_ms"] = state.iterations() > 0 ? 1000.0 * cpu / double(state.iterations()) : 0.0;
    state.counters["triangles"] = double(2 * kRings * kSegments);
}

void ViewerFrameWindow(benchmark::State& state)
{
    q3test::XvfbServer server;
    Display* display = server.display();
    if (display == nullptr) {
        state.SkipWithError(("skipped: " + server.why()).c_str());
        return;
    }
    Q3Initialize();
    {
        XVisualInfo* visual = Q3X_GetVisualInfo(display, DefaultScreenOfDisplay(display));
        XSetWindowAttributes attributes{};
        attributes.colormap = XCreateColormap(display, RootWindow(display, visual->screen), visual->visual, AllocNone);
        const Window window = XCreateWindow(display, RootWindow(display, visual->screen), 0, 0, kWidth, kHeight, 0,
                                            visual->depth, InputOutput, visual->visual, CWColormap, &attributes);
        XMapWindow(display, window);
        XSync(display, False);
        TQ3XDrawContextData data{};
        data.contextData.clearImageMethod = kQ3ClearMethodWithColor;
        data.contextData.clearImageColor = {1, 0.5f, 0.5f, 0.5f};
        data.contextData.doubleBufferState = kQ3True;
        data.display = display;
        data.drawable = window;
        data.visual = visual->visual;
        data.cmap = attributes.colormap;
        TQ3DrawContextObject context = Q3XDrawContext_New(&data);
        {
            Scene scene(context);
            runFrames(state, scene, display);
        }
        Q3Object_Dispose(context);
        XDestroyWindow(display, window);
        XFreeColormap(display, attributes.colormap);
        XFree(visual);
    }
    Q3Exit();
}

void ViewerFramePixmap(benchmark::State& state)
{
    Q3Initialize();
    {
        std::vector<unsigned char> image(kWidth * kHeight * 4);
        TQ3PixmapDrawContextData data{};
        data.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
        data.drawContextData.clearImageColor = {1, 0.5f, 0.5f, 0.5f};
        data.pixmap.image = image.data();
        data.pixmap.width = kWidth;
        data.pixmap.height = kHeight;
        data.pixmap.rowBytes = kWidth * 4;
        data.pixmap.pixelSize = 32;
        data.pixmap.pixelType = kQ3PixelTypeARGB32;
        data.pixmap.bitOrder = kQ3EndianBig;
        data.pixmap.byteOrder = kQ3EndianBig;
        TQ3DrawContextObject context = Q3PixmapDrawContext_New(&data);
        {
            Scene scene(context);
            runFrames(state, scene, nullptr);
        }
        Q3Object_Dispose(context);
    }
    Q3Exit();
}

} // namespace

BENCHMARK(ViewerFrameWindow)->Name("ViewerFrame/window")->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(ViewerFramePixmap)->Name("ViewerFrame/pixmap")->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

BENCHMARK_MAIN();
