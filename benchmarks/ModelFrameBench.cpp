// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// A frame of a real-world-like model through Q3 against an optimized raw
// OpenGL program drawing the same triangles, textures and blending in the
// same process (issue 26, item 8), paired in one loop (BenchTiming.h) on the
// wall clock; and the first frame of a new view.
//
// Model: 20 retained TriMeshes of 512 triangles each (a wavy 17 x 17 grid
// with a normal and a uv per point), 10,240 triangles in all, laid out 5 x 4
// over the camera's square; 4 pixmap textures of 128 x 128 (ARGB32, opaque),
// mesh k taking texture k % 4; every mesh has its own diffuse, specular
// colour and control; the meshes of the last column are translucent
// (transparency colour 0.5). The view has a Phong illumination shader and two
// directional lights, 512 x 512 ARGB32 pixmap, interactive renderer.
//
//   ModelFrame    q3: Q3View_StartRendering, the Phong shader and the 20
//                 meshes submitted, Q3View_EndRendering leaving the image
//                 in the view's little-endian ARGB32 pixmap;
//                 raw: the same triangles from static vertex and index
//                 buffers uploaded once (one per mesh), one program lighting
//                 at the vertices as Q3 does (diffuse times texel plus
//                 specular), one draw per material, opaque meshes first then
//                 the translucent ones back to front, blended without depth
//                 writes; glFinish, the image delivered into a little-endian
//                 ARGB32 pixmap of its own as Q3 delivers it (OSMesa: drawn
//                 there in place, by a context of B, G, R, A layout; EGL:
//                 glReadPixels in that layout). The peer uses Q3's context
//                 kind (Q3_RENDER_BACKEND) and loader (render/GlApi.h).
//   ModelFrameQ3Only, ModelFrameRawOnly  each side's frames alone, for a
//                 profiler (perf record --benchmark_filter=...Only), with
//                 the CPU time of the calling thread and of llvmpipe's
//                 rasterizer threads per frame;
//   FirstFrame    a new view (draw context, camera, renderer) and its first
//                 frame of the model, timed together; the view is disposed
//                 of untimed, so the next one finds its context idle
//                 (OffscreenRenderer.cpp, ContextPool). ModelFrame's
//                 process_first_frame_ms is the process's very first view
//                 and frame: a new context, every program compiled.
//   ProcessFirstFrame  first frames, each case alone in a process (below).
//
// pixels_differing counts pixels whose colour differs by more than 2 in a
// channel between the two images (informational: both light at the
// vertices, but the GLSL and llvmpipe paths round differently).

#include "BenchTiming.h"
#include "BenchView.h"

#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"

#include "render/GlApi.h"
#include "render/GlContext.h"

#include <benchmark/benchmark.h>

#include <dirent.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace q3 {
namespace bench {

constexpr unsigned long kSize = 512;
constexpr unsigned long kMeshes = 20;
constexpr unsigned long kColumns = 5;
constexpr unsigned long kSide = 17; // 289 points, 512 triangles a mesh
constexpr unsigned long kTextures = 4;
constexpr unsigned long kTextureSize = 128;
constexpr float kOpacity = 0.5f;

// One mesh as both sides draw it.
struct MeshData {
    std::vector<float> vertices; // x y z nx ny nz u v per point
    std::vector<GLuint> indices;
    TQ3ColorRGB diffuse{};
    TQ3ColorRGB specular{};
    float control = 0.0f;
    bool translucent = false;
    unsigned long texture = 0;
    float depth = 0.0f; // of its centre, for the peer's back-to-front order
};

// Directional lights: the way each travels and its colour.
constexpr float kLightDirections[2][3] = {{-0.4f, -0.3f, -0.866f}, {0.6f, 0.2f, -0.77f}};
constexpr float kLightColors[2][3] = {{0.8f, 0.8f, 0.75f}, {0.35f, 0.35f, 0.45f}};

class ModelScene {
public:
    ModelScene()
    {
        for (unsigned long t = 0; t < kTextures; ++t) {
            std::vector<std::uint8_t>& texels = m_texels.emplace_back(kTextureSize * kTextureSize * 4);
            for (unsigned long y = 0; y < kTextureSize; ++y)
                for (unsigned long x = 0; x < kTextureSize; ++x) {
                    std::uint8_t* p = texels.data() + 4 * (y * kTextureSize + x);
                    const bool check = ((x / (8 << t)) + (y / 16)) % 2 == 0;
                    // ARGB32, big-endian: A, R, G, B in memory.
                    p[0] = 0xFF;
                    p[1] = std::uint8_t(check ? 255 - 40 * t : 60 + 30 * t);
                    p[2] = std::uint8_t((x * 2 + 50 * t) & 0xFF);
                    p[3] = std::uint8_t((y * 2) & 0xFF);
                }
            TQ3StorageObject storage = Q3MemoryStorage_New(texels.data(), static_cast<unsigned long>(texels.size()));
            TQ3StoragePixmap pixmap{storage, kTextureSize, kTextureSize, kTextureSize * 4, 32,
                                    kQ3PixelTypeARGB32, kQ3EndianBig, kQ3EndianBig};
            TQ3TextureObject texture = Q3PixmapTexture_New(&pixmap);
            Q3Object_Dispose(storage);
            m_shaders.push_back(Q3TextureShader_New(texture));
            Q3Object_Dispose(texture);
        }
        const float cell = 2.1f / float(kColumns);
        for (unsigned long k = 0; k < kMeshes; ++k) {
            MeshData mesh;
            const float x0 = -1.05f + cell * float(k % kColumns), y0 = -1.05f + cell * float(k / kColumns) * 1.25f;
            std::vector<TQ3Point3D> points;
            std::vector<TQ3Vector3D> normals;
            std::vector<TQ3Param2D> uvs;
            for (unsigned long y = 0; y < kSide; ++y)
                for (unsigned long x = 0; x < kSide; ++x) {
                    const float u = float(x) / float(kSide - 1), v = float(y) / float(kSide - 1);
                    const float a = 6.0f * u + float(k), b = 5.0f * v;
                    const float z = 0.08f * std::sin(a) * std::cos(b) + 0.05f * float(k % kColumns);
                    // The normal of z(u, v) over the cell's x and y.
                    const float dzdx = 0.08f * 6.0f * std::cos(a) * std::cos(b) / (cell * 0.95f);
                    const float dzdy = -0.08f * 5.0f * std::sin(a) * std::sin(b) / (cell * 1.15f);
                    const float length = std::sqrt(dzdx * dzdx + dzdy * dzdy + 1.0f);
                    points.push_back({x0 + cell * 0.95f * u, y0 + cell * 1.15f * v, z});
                    normals.push_back({-dzdx / length, -dzdy / length, 1.0f / length});
                    uvs.push_back({u, v});
                    mesh.vertices.insert(mesh.vertices.end(), {points.back().x, points.back().y, points.back().z,
                                                               normals.back().x, normals.back().y, normals.back().z,
                                                               u, v});
                }
            std::vector<TQ3TriMeshTriangleData> triangles;
            for (unsigned long y = 0; y + 1 < kSide; ++y)
                for (unsigned long x = 0; x + 1 < kSide; ++x) {
                    const unsigned long a = y * kSide + x;
                    triangles.push_back({{a, a + 1, a + kSide + 1}});
                    triangles.push_back({{a, a + kSide + 1, a + kSide}});
                }
            for (const TQ3TriMeshTriangleData& t : triangles)
                for (unsigned long index : t.pointIndices)
                    mesh.indices.push_back(GLuint(index));
            mesh.diffuse = {0.6f + 0.02f * float(k), 0.9f - 0.02f * float(k), 0.8f};
            mesh.specular = {0.5f, 0.5f, 0.4f + 0.01f * float(k)};
            mesh.control = 8.0f + float(k);
            mesh.translucent = k % kColumns == kColumns - 1;
            mesh.texture = k % kTextures;
            mesh.depth = -0.05f * float(k % kColumns);

            TQ3AttributeSet set = Q3AttributeSet_New();
            Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &mesh.diffuse);
            Q3AttributeSet_Add(set, kQ3AttributeTypeSpecularColor, &mesh.specular);
            Q3AttributeSet_Add(set, kQ3AttributeTypeSpecularControl, &mesh.control);
            if (mesh.translucent) {
                const TQ3ColorRGB transparency{kOpacity, kOpacity, kOpacity};
                Q3AttributeSet_Add(set, kQ3AttributeTypeTransparencyColor, &transparency);
            }
            Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, &m_shaders[mesh.texture]);
            TQ3TriMeshAttributeData vertexArrays[2] = {{kQ3AttributeTypeNormal, normals.data(), nullptr},
                                                      {kQ3AttributeTypeSurfaceUV, uvs.data(), nullptr}};
            TQ3TriMeshData data{};
            data.triMeshAttributeSet = set;
            data.numTriangles = triangles.size();
            data.triangles = triangles.data();
            data.numPoints = points.size();
            data.points = points.data();
            data.numVertexAttributeTypes = 2;
            data.vertexAttributeTypes = vertexArrays;
            Q3BoundingBox_SetFromPoints3D(&data.bBox, points.data(), points.size(), sizeof(TQ3Point3D));
            m_sets.push_back(set);
            m_meshes.push_back(Q3TriMesh_New(&data));
            if (m_meshes.back() == nullptr)
                throw std::runtime_error("Q3TriMesh_New failed");
            m_data.push_back(std::move(mesh));
        }
        m_illumination = Q3PhongIllumination_New();
        m_lights = Q3LightGroup_New();
        for (int i = 0; i < 2; ++i) {
            TQ3DirectionalLightData light{};
            light.lightData.isOn = kQ3True;
            light.lightData.brightness = 1.0f;
            light.lightData.color = {kLightColors[i][0], kLightColors[i][1], kLightColors[i][2]};
            light.castsShadows = kQ3False;
            light.direction = {kLightDirections[i][0], kLightDirections[i][1], kLightDirections[i][2]};
            TQ3LightObject object = Q3DirectionalLight_New(&light);
            Q3Group_AddObject(m_lights, object);
            Q3Object_Dispose(object);
        }
    }

    ~ModelScene()
    {
        for (TQ3Object object : m_meshes)
            Q3Object_Dispose(object);
        for (TQ3Object object : m_sets)
            Q3Object_Dispose(object);
        for (TQ3Object object : m_shaders)
            Q3Object_Dispose(object);
        Q3Object_Dispose(m_illumination);
        Q3Object_Dispose(m_lights);
    }

    std::unique_ptr<q3bench::BenchView> newView() const
    {
        auto view = std::make_unique<q3bench::BenchView>(kSize, kSize);
        if (Q3View_SetLightGroup(view->view(), m_lights) != kQ3Success)
            throw std::runtime_error("Q3View_SetLightGroup failed");
        return view;
    }

    bool renderQ3(q3bench::BenchView& view) const
    {
        if (Q3View_StartRendering(view.view()) != kQ3Success)
            return false;
        bool ok = Q3Shader_Submit(m_illumination, view.view()) == kQ3Success;
        for (TQ3Object mesh : m_meshes)
            ok = Q3Geometry_Submit(mesh, view.view()) == kQ3Success && ok;
        return Q3View_EndRendering(view.view()) == kQ3ViewStatusDone && ok;
    }

    const std::vector<MeshData>& data() const { return m_data; }
    /// Texture t as R, G, B, A bytes, top row first.
    std::vector<std::uint8_t> textureRgba(unsigned long t) const
    {
        std::vector<std::uint8_t> rgba(m_texels[t].size());
        for (std::size_t i = 0; i < rgba.size(); i += 4) {
            rgba[i] = m_texels[t][i + 1];
            rgba[i + 1] = m_texels[t][i + 2];
            rgba[i + 2] = m_texels[t][i + 3];
            rgba[i + 3] = m_texels[t][i];
        }
        return rgba;
    }

private:
    q3bench::Q3Session m_session;
    std::vector<MeshData> m_data;
    std::vector<TQ3GeometryObject> m_meshes;
    std::vector<TQ3AttributeSet> m_sets;
    std::vector<std::vector<std::uint8_t>> m_texels;
    std::vector<TQ3ShaderObject> m_shaders;
    TQ3ShaderObject m_illumination = nullptr;
    TQ3GroupObject m_lights = nullptr;
};

ModelScene& scene()
{
    static ModelScene instance;
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

// Lit at the vertices as Q3's LitProgram is (RenderTarget.h's
// SurfaceShading): diffuse light clamped, times the texel (which takes the
// place of the diffuse colour), plus specular.
const char* const kVertexShader = R"(#version 130
uniform mat4 clip;
uniform vec3 lightDirection[2];
uniform vec3 lightColor[2];
uniform vec3 toEye;
uniform vec3 diffuse;
uniform vec3 specular;
uniform float control;
in vec3 position;
in vec3 normal;
in vec2 uv;
out vec3 lit;
out vec3 highlight;
out vec2 st;
void main()
{
    gl_Position = clip * vec4(position, 1.0);
    vec3 n = normalize(normal);
    vec3 d = vec3(0.0);
    vec3 s = vec3(0.0);
    for (int i = 0; i < 2; ++i) {
        vec3 l = -lightDirection[i];
        float nl = dot(n, l);
        if (nl > 0.0) {
            d += lightColor[i] * diffuse * nl;
            vec3 r = reflect(-l, n);
            s += lightColor[i] * specular * pow(max(dot(r, toEye), 0.0), control);
        }
    }
    lit = clamp(d, 0.0, 1.0);
    highlight = s;
    st = vec2(uv.x, 1.0 - uv.y);
}
)";
const char* const kFragmentShader = R"(#version 130
uniform sampler2D image;
uniform float opacity;
in vec3 lit;
in vec3 highlight;
in vec2 st;
void main()
{
    gl_FragColor = vec4(lit * texture2D(image, st).rgb + highlight, opacity);
}
)";

/// The raw OpenGL peer: one context of Q3's backend, static buffers, one
/// program, one draw per mesh (each mesh is one material).
class RawModel {
public:
    RawModel(const ModelScene& s, const TQ3Matrix4x4& clip) : m_pixmap(kSize * kSize * 4)
    {
        const GlBackendChoice choice = chooseGlBackendFromEnvironment();
        // Delivered straight into the pixmap, B, G, R, A, as Q3 delivers a
        // little-endian ARGB32 pixmap: OSMesa draws there, EGL reads back
        // there.
        if (!choice.result || !createGlContext(choice.backend, kSize, kSize, m_pixmap.data(), m_context, true))
            throw std::runtime_error("creating the raw OpenGL context failed");
        if (!bind())
            throw std::runtime_error("making the raw OpenGL context current failed");
        glViewport(0, 0, GLsizei(kSize), GLsizei(kSize));
        glDisable(GL_DITHER);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        m_program = buildProgram();
        glUseProgram(m_program);
        glUniformMatrix4fv(glGetUniformLocation(m_program, "clip"), 1, GL_FALSE, &clip.value[0][0]);
        glUniform3fv(glGetUniformLocation(m_program, "lightDirection"), 2, &kLightDirections[0][0]);
        glUniform3fv(glGetUniformLocation(m_program, "lightColor"), 2, &kLightColors[0][0]);
        const float toEye[3] = {0.0f, 0.0f, 1.0f};
        glUniform3fv(glGetUniformLocation(m_program, "toEye"), 1, toEye);
        glUniform1i(glGetUniformLocation(m_program, "image"), 0);
        m_diffuse = glGetUniformLocation(m_program, "diffuse");
        m_specular = glGetUniformLocation(m_program, "specular");
        m_control = glGetUniformLocation(m_program, "control");
        m_opacity = glGetUniformLocation(m_program, "opacity");

        m_textures.resize(kTextures);
        glGenTextures(GLsizei(kTextures), m_textures.data());
        for (unsigned long t = 0; t < kTextures; ++t) {
            const std::vector<std::uint8_t> rgba = s.textureRgba(t);
            glBindTexture(GL_TEXTURE_2D, m_textures[t]);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, GLsizei(kTextureSize), GLsizei(kTextureSize), 0, GL_RGBA,
                         GL_UNSIGNED_BYTE, rgba.data());
        }
        for (const MeshData& mesh : s.data()) {
            Buffers buffers;
            glGenBuffers(1, &buffers.vertices);
            glGenBuffers(1, &buffers.indices);
            glBindBuffer(GL_ARRAY_BUFFER, buffers.vertices);
            glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(float)), mesh.vertices.data(),
                         GL_STATIC_DRAW);
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers.indices);
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(GLuint)),
                         mesh.indices.data(), GL_STATIC_DRAW);
            buffers.count = GLsizei(mesh.indices.size());
            m_buffers.push_back(buffers);
        }
        for (std::size_t k = 0; k < s.data().size(); ++k)
            (s.data()[k].translucent ? m_translucent : m_opaque).push_back(k);
        glEnableVertexAttribArray(0);
        glEnableVertexAttribArray(1);
        glEnableVertexAttribArray(2);
        release();
    }
    ~RawModel()
    {
        if (bind()) {
            for (const Buffers& buffers : m_buffers) {
                glDeleteBuffers(1, &buffers.vertices);
                glDeleteBuffers(1, &buffers.indices);
            }
            glDeleteTextures(GLsizei(m_textures.size()), m_textures.data());
            glDeleteProgram(m_program);
            release();
        }
    }
    RawModel(const RawModel&) = delete;
    RawModel& operator=(const RawModel&) = delete;

    bool bind()
    {
        if (!m_context->makeCurrent(m_pixmap.data()))
            return false;
        m_scope = std::make_unique<GlApiScope>(&m_context->api());
        return true;
    }
    void release()
    {
        m_scope.reset();
        m_context->restorePrevious();
    }

    void frame(const ModelScene& s)
    {
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        for (std::size_t k : m_opaque)
            drawMesh(s.data()[k], m_buffers[k]);
        // Back to front: the translucent meshes sorted by their centres'
        // depth each frame, as an application would.
        std::sort(m_translucent.begin(), m_translucent.end(),
                  [&](std::size_t a, std::size_t b) { return s.data()[a].depth < s.data()[b].depth; });
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        for (std::size_t k : m_translucent)
            drawMesh(s.data()[k], m_buffers[k]);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
        m_context->finish(m_pixmap.data());
    }

    /// B, G, R, A per pixel, top row first.
    const std::vector<std::uint8_t>& pixmap() const { return m_pixmap; }

private:
    struct Buffers {
        GLuint vertices = 0;
        GLuint indices = 0;
        GLsizei count = 0;
    };

    void drawMesh(const MeshData& mesh, const Buffers& buffers)
    {
        glBindTexture(GL_TEXTURE_2D, m_textures[mesh.texture]);
        // The texture takes the place of the diffuse colour (QD3DShader.h).
        const float white[3] = {1.0f, 1.0f, 1.0f};
        glUniform3fv(m_diffuse, 1, white);
        glUniform3fv(m_specular, 1, &mesh.specular.r);
        glUniform1f(m_control, mesh.control);
        glUniform1f(m_opacity, mesh.translucent ? kOpacity : 1.0f);
        glBindBuffer(GL_ARRAY_BUFFER, buffers.vertices);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 8 * sizeof(float), nullptr);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 8 * sizeof(float),
                              reinterpret_cast<const void*>(3 * sizeof(float)));
        glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, 8 * sizeof(float),
                              reinterpret_cast<const void*>(6 * sizeof(float)));
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers.indices);
        glDrawElements(GL_TRIANGLES, buffers.count, GL_UNSIGNED_INT, nullptr);
    }

    static GLuint buildProgram()
    {
        const GLuint program = glCreateProgram();
        const char* sources[2] = {kVertexShader, kFragmentShader};
        const GLenum kinds[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
        for (int i = 0; i < 2; ++i) {
            const GLuint shader = glCreateShader(kinds[i]);
            glShaderSource(shader, 1, &sources[i], nullptr);
            glCompileShader(shader);
            GLint ok = GL_FALSE;
            glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
            if (ok != GL_TRUE) {
                char log[1024] = {};
                glGetShaderInfoLog(shader, sizeof log, nullptr, log);
                throw std::runtime_error(std::string("the peer's shader does not compile: ") + log);
            }
            glAttachShader(program, shader);
            glDeleteShader(shader);
        }
        glBindAttribLocation(program, 0, "position");
        glBindAttribLocation(program, 1, "normal");
        glBindAttribLocation(program, 2, "uv");
        glLinkProgram(program);
        GLint linked = GL_FALSE;
        glGetProgramiv(program, GL_LINK_STATUS, &linked);
        if (linked != GL_TRUE)
            throw std::runtime_error("the peer's program does not link");
        return program;
    }

    std::vector<std::uint8_t> m_pixmap;
    std::unique_ptr<GlContext> m_context;
    std::unique_ptr<GlApiScope> m_scope;
    GLuint m_program = 0;
    GLint m_diffuse = -1, m_specular = -1, m_control = -1, m_opacity = -1;
    std::vector<GLuint> m_textures;
    std::vector<Buffers> m_buffers;
    std::vector<std::size_t> m_opaque;
    std::vector<std::size_t> m_translucent;
};

double differingPixels(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b)
{
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.size(); i += 4)
        differing += std::abs(a[i] - b[i]) > 2 || std::abs(a[i + 1] - b[i + 1]) > 2 ||
                     std::abs(a[i + 2] - b[i + 2]) > 2;
    return double(differing);
}

// CPU time (nanoseconds, /proc/self/task/*/schedstat) of the process's
// threads: the calling thread's, and the sum of Mesa's llvmpipe rasterizer
// threads'.
struct ThreadCpu {
    double mainNs = 0.0;
    double rasterNs = 0.0;
};

ThreadCpu threadCpu()
{
    ThreadCpu cpu;
    const std::string self = std::to_string(long(::syscall(SYS_gettid)));
    DIR* tasks = ::opendir("/proc/self/task");
    if (tasks == nullptr)
        return cpu;
    while (const dirent* entry = ::readdir(tasks)) {
        const std::string tid = entry->d_name;
        if (tid == "." || tid == "..")
            continue;
        std::ifstream comm("/proc/self/task/" + tid + "/comm");
        std::string name;
        std::getline(comm, name);
        std::ifstream stat("/proc/self/task/" + tid + "/schedstat");
        double ns = 0.0;
        stat >> ns;
        if (tid == self)
            cpu.mainNs = ns;
        else if (name.rfind("llvmpipe-", 0) == 0)
            cpu.rasterNs += ns;
    }
    ::closedir(tasks);
    return cpu;
}

void ModelFrame(benchmark::State& state)
{
    ModelScene& s = scene();
    // The process's very first frame: a new context and every program
    // compiled (nothing in the pool of idle contexts yet).
    static double processFirstFrame = 0.0;
    static std::unique_ptr<q3bench::BenchView> view = [&] {
        const double start = q3bench::now(q3bench::Clock::kWall);
        std::unique_ptr<q3bench::BenchView> made = s.newView();
        s.renderQ3(*made);
        processFirstFrame = q3bench::now(q3bench::Clock::kWall) - start;
        return made;
    }();
    static std::unique_ptr<RawModel> gl = std::make_unique<RawModel>(s, clipMatrix(view->camera()));
    state.counters["process_first_frame_ms"] = 1e3 * processFirstFrame;

    if (!s.renderQ3(*view) || !s.renderQ3(*view)) {
        state.SkipWithError("a Q3 frame failed");
        return;
    }
    if (!gl->bind()) {
        state.SkipWithError("binding the raw context failed");
        return;
    }
    gl->frame(s);
    gl->release();
    state.counters["triangles"] = double(kMeshes * 2 * (kSide - 1) * (kSide - 1));
    state.counters["pixels_differing"] = differingPixels(view->pixels(), gl->pixmap());
    if (const char* path = std::getenv("Q3_BENCH_DUMP")) {
        // Both images side by side as a binary PPM, for a look.
        std::FILE* file = std::fopen(path, "wb");
        if (file != nullptr) {
            std::fprintf(file, "P6 %lu %lu 255\n", 2 * kSize, kSize);
            for (unsigned long y = 0; y < kSize; ++y)
                for (const std::vector<std::uint8_t>* image : {&view->pixels(), &gl->pixmap()})
                    for (unsigned long x = 0; x < kSize; ++x) {
                        const std::uint8_t* p = image->data() + 4 * (y * kSize + x);
                        const std::uint8_t rgb[3] = {p[2], p[1], p[0]};
                        std::fwrite(rgb, 1, 3, file);
                    }
            std::fclose(file);
        }
    }

    // As in MeshFrameBench.cpp: each timed turn follows an untimed one by
    // the same contender, so switching contexts stays out of both.
    // Where each side's timed turns spend CPU (outside the timing: the
    // snapshots end the untimed step before a turn and start the one
    // after): the calling thread, and llvmpipe's rasterizer threads.
    ThreadCpu cpu[2][2];
    double spent[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
    const auto account = [&](int side) {
        spent[side][0] += cpu[side][1].mainNs - cpu[side][0].mainNs;
        spent[side][1] += cpu[side][1].rasterNs - cpu[side][0].rasterNs;
    };
    const auto q3Frame = [&] { s.renderQ3(*view); };
    q3bench::Contender q3{"q3", q3Frame};
    q3.before = [&] {
        q3Frame();
        cpu[0][0] = threadCpu();
    };
    q3.after = [&] {
        cpu[0][1] = threadCpu();
        account(0);
    };
    q3bench::Contender raw{"raw", [&] { gl->frame(s); }};
    raw.before = [&] {
        gl->bind();
        gl->frame(s);
        cpu[1][0] = threadCpu();
    };
    raw.after = [&] {
        cpu[1][1] = threadCpu();
        account(1);
        gl->release();
    };
    q3bench::runPaired(state, q3bench::Clock::kWall, {q3, raw});
    const double frames = double(std::max<benchmark::IterationCount>(state.iterations(), 1));
    const char* const names[2] = {"q3", "raw"};
    for (int side = 0; side < 2; ++side) {
        state.counters[std::string(names[side]) + "_main_cpu_ms"] = 1e-6 * spent[side][0] / frames;
        state.counters[std::string(names[side]) + "_raster_cpu_ms"] = 1e-6 * spent[side][1] / frames;
    }
}

// Each side's frames alone (no peer in the process's turns): what perf
// profiles, and where each side's CPU time goes per frame (main_cpu_ms: the
// thread that calls; raster_cpu_ms: llvmpipe's rasterizer threads), after
// 5 untimed frames.
template <class Frame>
void framesAlone(benchmark::State& state, Frame&& frame)
{
    for (int i = 0; i < 5; ++i)
        if (!frame()) {
            state.SkipWithError("a frame failed");
            return;
        }
    const ThreadCpu before = threadCpu();
    for (auto _ : state)
        if (!frame()) {
            state.SkipWithError("a frame failed");
            return;
        }
    const ThreadCpu after = threadCpu();
    const double frames = double(std::max<benchmark::IterationCount>(state.iterations(), 1));
    state.counters["main_cpu_ms"] = 1e-6 * (after.mainNs - before.mainNs) / frames;
    state.counters["raster_cpu_ms"] = 1e-6 * (after.rasterNs - before.rasterNs) / frames;
}

void ModelFrameQ3Only(benchmark::State& state)
{
    ModelScene& s = scene();
    static std::unique_ptr<q3bench::BenchView> view = s.newView();
    framesAlone(state, [&] { return s.renderQ3(*view); });
}

// The peer's frames alone.
void ModelFrameRawOnly(benchmark::State& state)
{
    ModelScene& s = scene();
    static std::unique_ptr<q3bench::BenchView> view = s.newView();
    static std::unique_ptr<RawModel> gl = std::make_unique<RawModel>(s, clipMatrix(view->camera()));
    gl->bind();
    framesAlone(state, [&] {
        gl->frame(s);
        return true;
    });
    gl->release();
}

void FirstFrame(benchmark::State& state)
{
    ModelScene& s = scene();
    double total = 0.0;
    for (auto _ : state) {
        const double start = q3bench::now(q3bench::Clock::kWall);
        std::unique_ptr<q3bench::BenchView> view = s.newView();
        const bool ok = s.renderQ3(*view);
        total += q3bench::now(q3bench::Clock::kWall) - start;
        if (!ok) {
            state.SkipWithError("a Q3 frame failed");
            return;
        }
        state.PauseTiming();
        view.reset();
        state.ResumeTiming();
    }
    state.counters["first_frame_ms"] = 1e3 * total / double(std::max<benchmark::IterationCount>(state.iterations(), 1));
}

// The process's very first view and frame, with nothing of OpenGL made
// before it in the process (run alone: --benchmark_filter=ProcessFirstFrame/0
// for Q3, /1 for the peer, each in a process of its own): Q3's new view and
// first frame against the peer's context, program, buffers, textures and
// first frame. Both pay for what Mesa does once per process (loading
// llvmpipe and LLVM, starting the rasterizer threads, compiling shaders or
// finding them in Mesa's on-disk cache). /2: a second view's first frame
// while the first view (made and drawn untimed) lives: it draws with the
// context the first lent between its frames. /3: the same while the first
// view's frame is open (begun untimed, ended after), so that the second
// view makes a context of its own, as views drawn at the same moment on two
// threads do.
void ProcessFirstFrame(benchmark::State& state)
{
    static bool ran = false;
    if (ran) {
        state.SkipWithError("run ProcessFirstFrame alone, one argument per process");
        return;
    }
    ran = true;
    ModelScene& s = scene();
    double elapsed = 0.0;
    for (auto _ : state) {
        if (state.range(0) != 1) {
            // /2 and /3: the first view made and drawn before, and alive
            // (/3: in a frame).
            std::unique_ptr<q3bench::BenchView> first = state.range(0) >= 2 ? s.newView() : nullptr;
            if (first != nullptr && !s.renderQ3(*first)) {
                state.SkipWithError("a Q3 frame failed");
                return;
            }
            if (state.range(0) == 3 && Q3View_StartRendering(first->view()) != kQ3Success) {
                state.SkipWithError("starting the first view's frame failed");
                return;
            }
            const double start = q3bench::now(q3bench::Clock::kWall);
            std::unique_ptr<q3bench::BenchView> view = s.newView();
            const bool ok = s.renderQ3(*view);
            elapsed = q3bench::now(q3bench::Clock::kWall) - start;
            if (state.range(0) == 3 && Q3View_EndRendering(first->view()) != kQ3ViewStatusDone)
                state.SkipWithError("ending the first view's frame failed");
            if (!ok)
                state.SkipWithError("a Q3 frame failed");
        } else {
            std::unique_ptr<q3bench::BenchView> view = s.newView();
            const double start = q3bench::now(q3bench::Clock::kWall);
            RawModel gl(s, clipMatrix(view->camera()));
            if (!gl.bind()) {
                state.SkipWithError("binding the raw context failed");
                return;
            }
            gl.frame(s);
            gl.release();
            elapsed = q3bench::now(q3bench::Clock::kWall) - start;
        }
    }
    state.counters["first_frame_ms"] = 1e3 * elapsed;
}

BENCHMARK(ModelFrame)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(ModelFrameQ3Only)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(300);
BENCHMARK(ModelFrameRawOnly)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(300);
BENCHMARK(FirstFrame)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);
BENCHMARK(ProcessFirstFrame)->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

} // namespace bench
} // namespace q3

BENCHMARK_MAIN();
