// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// OffscreenRenderer: the drawing shared by the OSMesa and EGL backends, which
// differ only in their GlContext (GlContext.h; OsMesaContext.cpp,
// EglContext.cpp). Every gl* call goes through the current context's table
// (GlApi.h).
//
// Rendering goes into a window-system framebuffer: OSMesa's own, which OSMesa
// copies into our RGBA8 buffer (top row first, OSMESA_Y_UP = 0) at glFinish,
// or an EGL pbuffer, read back with glReadPixels; llvmpipe rasterizes both
// alike, so the two backends give the same pixels.
// That is the path every plain OSMesa program takes, so an image drawn here is
// bit-identical to one drawn by raw OpenGL calls with the same vertices and
// matrix (measured on 1,000 curves of 65 points: 0 of 127,709 lit pixels
// differ). Vertices are transformed by OpenGL, not on the CPU, for the same
// reason. (Rendering into a framebuffer object instead was tried: llvmpipe
// rasterizes it with the opposite y orientation and about 1 line pixel in 5000
// came out different, at exact ties.)
//
// Determinism. Images must be bit-reproducible across runs and across x86-64
// machines with this Mesa (22.3). What was measured, with 65,000 random
// vertices drawn as triangles, 1,000 line strips and 2.5-pixel points, comparing
// the MD5 of the image:
//   - GALLIUM_DRIVER=softpipe gives a different image from llvmpipe: the driver
//     is pinned (below) and checked through GL_RENDERER.
//   - LP_NUM_THREADS = 0, 1, 2, 3, 8, 16 all give the same image. llvmpipe bins
//     primitives into 64x64 tiles and each tile is rasterized by one thread in
//     submission order, so the thread count only changes which thread does a
//     tile. It is left alone: it is a performance knob only.
//   - LP_NATIVE_VECTOR_WIDTH = 128 or 256 and LP_FORCE_SSE2 (no AVX, no FMA)
//     give the same image as AVX2+FMA: the host's SIMD level does not matter.
//   - DRAW_USE_LLVM=0, GALLIUM_NOSSE, GALLIUM_OVERRIDE_CPU_CAPS=nosse,
//     LP_NO_RAST and GALLIUM_NOOP each change the image: they are unset.
//   - Drawing through a framebuffer object differs slightly (see above).
// GlContext.cpp pins the Mesa environment variables these measurements
// found to matter, for both backends.
// The OpenGL state that matters is pinned in initializeState(): no dithering,
// no multisampling, no smoothing or stippling, line width 1, no blending, no
// depth test, no culling, no lighting, flat shading.
//
// Threads. Mesa 22.3 keeps one OSMesa buffer per context (older Mesa shared
// buffers of equal size between contexts, which broke concurrent rendering;
// RenderOffscreen.TwoThreadsMatchSequentialRendering checks this), the GL
// dispatch is per thread, and the llvmpipe screen with its rasterizer thread
// pool is shared by all contexts and thread-safe (more contexts do not add
// threads: measured). Context creation and
// destruction are still serialized by one mutex: they are rare and they touch
// the process-wide screen and, the first time, the environment.
//
// Resizing. Mesa 22.3 leaks the old buffer's storage (width * height * 4 bytes
// per resize, measured) when a context is re-bound at a new size, so a frame of
// a new size gets a new context instead; frames of an unchanged size reuse the
// context and the image buffer.

#include "render/OffscreenRenderer.h"

#include "core/EnumValue.h"
#include "render/GlApi.h"
#include "render/GlContext.h"
#include "render/LitProgram.h"
#include "render/SingleCover.h"
#include "render/SurfaceFinish.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <utility>
#include <unordered_map>
#include <vector>

namespace q3 {
namespace {

// llvmpipe's limit for a 2D surface and a viewport (OSMESA_MAX_WIDTH,
// GL_MAX_VIEWPORT_DIMS); its viewport bounds range is [-32768, 32767], so a
// pane origin within +-kMaxImageSize keeps every viewport coordinate legal.
constexpr std::uint32_t kMaxImageSize = 16384;
constexpr int kMaxPaneOffset = 16384;

// A batch is handed to OpenGL when it would grow past this many vertices
// (24 MiB of vertex data) or indices; a typical frame of curves stays well
// below.
constexpr std::size_t kFlushVertexCount = std::size_t(1) << 20;
constexpr std::size_t kFlushIndexCount = std::size_t(1) << 21;

/// Makes a context current (with its GL table) for the lifetime of the
/// scope, then the thread's previous context again, or none.
class ContextScope {
public:
    // rowPixels: how far apart the image's rows are (0: its width).
    ContextScope(GlContext& context, std::uint8_t* image, std::uint32_t rowPixels = 0)
        : m_context(context), m_bound(context.makeCurrent(image) && context.setRowPixels(rowPixels)),
          m_api(m_bound ? &context.api() : nullptr)
    {
    }
    ~ContextScope() { m_context.restorePrevious(); }
    ContextScope(const ContextScope&) = delete;
    ContextScope& operator=(const ContextScope&) = delete;

    bool bound() const { return m_bound; }

private:
    GlContext& m_context;
    bool m_bound;
    GlApiScope m_api;
};

using Primitive = DrawMode;

// One draw call's arguments, as the public calls pass them on.
struct DrawRequest {
    Primitive primitive = Primitive::kPoints;
    const float* xyz = nullptr;
    const float* rgb = nullptr; // per vertex, or null for `color`
    const float* normals = nullptr; // lit triangles: per vertex
    const SurfaceShading* shading = nullptr; // lit triangles
    const float* st = nullptr; // texture coordinates per vertex, or null
    std::size_t vertexCount = 0;
    bool indexed = false; // else the vertices in order
    const std::uint32_t* indices = nullptr;
    std::size_t indexCount = 0;
    RgbColor color;
    float pointSize = 1.0f;
    bool smooth = false;
    bool opaquePart = false; // the opaque triangles of a split draw (drawSplit)
};

GLenum glMode(Primitive primitive)
{
    switch (primitive) {
    case Primitive::kPoints:
        return GL_POINTS;
    case Primitive::kLines:
        return GL_LINES;
    case Primitive::kLineStrip:
        return GL_LINE_STRIP;
    case Primitive::kTriangles:
        return GL_TRIANGLES;
    }
    return GL_POINTS;
}

const char* glErrorName(GLenum error)
{
    switch (error) {
    case GL_INVALID_ENUM:
        return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
        return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
        return "GL_INVALID_OPERATION";
    case GL_OUT_OF_MEMORY:
        return "GL_OUT_OF_MEMORY";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
        return "GL_INVALID_FRAMEBUFFER_OPERATION";
    default:
        return "unknown GL error";
    }
}

// Returns the first pending GL error and clears the rest.
GLenum takeGlError()
{
    GLenum first = glGetError();
    if (first != GL_NO_ERROR) {
        for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
        }
    }
    return first;
}

// A float is infinite or NaN exactly when its exponent bits are all set:
// a test of each value's bits whose results are or-ed together, which the
// compiler vectorizes in three instructions for four values (a sum of x - x,
// the earlier test, is a chain of dependent float additions: a tenth of a
// frame's main-thread time on a model of 10,000 triangles,
// benchmarks/RESULTS.md, ModelFrame).
bool allFinite(const float* values, std::size_t count)
{
    constexpr std::uint32_t kExponent = 0x7F800000u;
    std::uint32_t infinite = 0;
    for (std::size_t i = 0; i < count; ++i) {
        std::uint32_t bits;
        std::memcpy(&bits, values + i, sizeof bits);
        infinite |= std::uint32_t((bits & kExponent) == kExponent);
    }
    return infinite == 0;
}

// Whether every value of a lit draw's shading is finite.
bool shadingFinite(const SurfaceShading& s)
{
    const float values[5] = {s.ambientCoefficient, s.specularColor[0], s.specularColor[1], s.specularColor[2],
                             s.specularControl};
    return allFinite(s.localToWorld, 16) && allFinite(values, 5);
}

// Vectors whose resize leaves new elements uninitialized (the batch's
// indices are written right after; zeroing them first was a pass of its
// own).
template <class T>
struct UninitializedAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = UninitializedAllocator<U>;
    };
    UninitializedAllocator() = default;
    template <class U>
    UninitializedAllocator(const UninitializedAllocator<U>&) noexcept
    {
    }
    template <class U>
    void construct(U* at) noexcept
    {
        ::new (static_cast<void*>(at)) U;
    }
    template <class U, class... Args>
    void construct(U* at, Args&&... args)
    {
        ::new (static_cast<void*>(at)) U(std::forward<Args>(args)...);
    }
};
using IndexVector = std::vector<GLuint, UninitializedAllocator<GLuint>>;

RenderResult invalid(std::string message)
{
    return RenderResult::failure(RenderStatus::kInvalidArgument, std::move(message));
}

RenderResult outOfMemory()
{
    return RenderResult::failure(RenderStatus::kOutOfMemory, "out of memory for the render batch");
}

} // namespace

class OffscreenRenderer::Impl {
public:
    explicit Impl(const GlBackendChoice& backend);
    ~Impl();

    RenderResult beginFrame(std::uint32_t width, std::uint32_t height, const RgbaColor& clearColor,
                            const PixelRect& pane, const FrameOptions& options);
    RenderResult setMatrix(const std::array<float, 16>& matrix);
    RenderResult draw(const DrawRequest& request);
    RenderResult drawBitmap(const float* anchor, const BitmapImage& image, const RgbColor& color);
    RenderResult drawPixmap(const float* anchor, const PixmapImage& image);
    RenderResult setLighting(const LightingSetup& lighting);
    RenderResult setFaceOptions(const FaceOptions& faces);
    RenderResult setAntiAlias(const AntiAliasOptions& options);
    RenderResult addTexture(const TextureImage& texture, std::uint32_t& id);
    RenderResult useTexture(std::uint32_t id);
    RenderResult setFog(const FogSetup& fog);
    RenderResult setOpacity(const OpacitySetup& opacity);
    RenderResult endFrame();
    void cancelFrame();

    bool m_inFrame = false;
    std::uint32_t m_width = 0;
    std::uint32_t m_height = 0;
    std::vector<std::uint8_t> m_image;

private:
    // Where a width x height image anchored at `anchor` lands: its top left
    // pane pixel, the depth of the anchor, and the columns c0..c1 and rows
    // r0..r1 (ends excluded) of the image inside the pane. False when nothing
    // of it is drawn (the anchor behind the eye, outside the depth range, or
    // the image outside the pane).
    struct ScreenPlacement {
        std::int64_t left = 0, top = 0;
        double depth = 0.0;
        std::int64_t c0 = 0, c1 = 0, r0 = 0, r1 = 0;
    };
    bool place(const float* anchor, long xOffset, long yOffset, std::uint32_t width, std::uint32_t height,
               ScreenPlacement& out) const;
    // Image pixel (c, r) of a placement as a point in clip space.
    void pushPixel(const ScreenPlacement& at, std::int64_t c, std::int64_t r, std::vector<float>& points) const;
    // Draws points given in clip space (rgb per point, or null for `color`)
    // and restores the current matrix.
    RenderResult drawScreenPoints(const std::vector<float>& points, const std::vector<float>* rgb,
                                  const RgbColor& color);

    // Interleaved for glVertexPointer/glColorPointer/glNormalPointer with
    // one stride. No member initializers: storage is allocated uninitialized.
    struct Vertex {
        float x, y, z;
        float r, g, b;
        float nx, ny, nz;
        float s, t;
    };

    // A plain command's vertex (see m_positions).
    struct Position {
        float x, y, z;
    };

    static constexpr std::uint32_t kUnlit = std::numeric_limits<std::uint32_t>::max();
    static constexpr std::uint32_t kUntextured = std::numeric_limits<std::uint32_t>::max();
    static constexpr std::uint32_t kNoFog = std::numeric_limits<std::uint32_t>::max();

    // A texture decoded to RGBA8 (R, G, B, A bytes, row 0 the top row, which
    // OpenGL takes as t = 0), with its wrap modes.
    struct BatchTexture {
        std::vector<std::uint8_t> rgba;
        std::uint32_t width = 0;
        std::uint32_t height = 0;
        bool clampS = false;
        bool clampT = false;
        TextureFilter filter = TextureFilter::kNearest;
        // The mipmap chain's images after the first, decoded the same way
        // (image i + 1 is max(1, width >> (i + 1)) wide).
        std::vector<std::vector<std::uint8_t>> mipmaps;
        bool hasAlpha = false; // a texel's alpha is below 1
        // Its entry in m_gl->textureCache, or kNotCached.
        std::uint32_t cacheSlot = std::numeric_limits<std::uint32_t>::max();
    };

    // first and count are vertices, or for an indexed command indices.
    // shading indexes m_shadings (kUnlit: drawn with the colours as they are).
    // A plain command (one colour, unlit, flat) draws positions from
    // m_positions in `color`; the others draw interleaved Vertex records
    // from m_vertices.
    struct DrawCommand {
        Primitive primitive;
        bool indexed;
        bool smooth;
        bool plain;
        float pointSize;
        std::uint32_t matrixIndex;
        std::uint32_t shading;
        std::uint32_t texture; // indexes m_textures, or kUntextured
        FaceOptions faces;
        RgbColor color;
        GLint first;
        GLsizei count;
        bool multisample = false; // anti-aliased (AntiAliasOptions)
        std::uint32_t fog = kNoFog; // indexes m_fogs
        // An indexed command's smallest and largest index (glDrawRangeElements:
        // Mesa otherwise scans the indices for them at every draw from a
        // buffer the frame rewrote).
        GLuint minIndex = 0;
        GLuint maxIndex = 0;
        // Drawn from the context's kept vertex data (GlResources::kept)
        // rather than the batch's.
        bool staticArrays = false;

        bool drawsLike(const DrawCommand& other) const
        {
            return primitive == other.primitive && indexed == other.indexed && smooth == other.smooth &&
                   multisample == other.multisample && staticArrays == other.staticArrays &&
                   fog == other.fog &&
                   plain == other.plain && pointSize == other.pointSize && matrixIndex == other.matrixIndex &&
                   shading == other.shading && texture == other.texture && faces == other.faces &&
                   (!plain || (color.r == other.color.r && color.g == other.color.g && color.b == other.color.b));
        }
    };

    // Makes m_gl a context of this backend for a width x height image (and
    // m_image that image): the one held, else an idle one from the pool
    // (ContextPool), else a new one. Errors: kContextFailure,
    // kWrongRenderer, kGraphicsError.
    RenderResult acquireContext(std::uint32_t width, std::uint32_t height, bool bgra);
    // Lends m_gl to the pool (GlResources), if held.
    void lendContext();
    // Deletes the names of this renderer's own (uncached) textures, in
    // m_textureNames and m_staleTextureNames; the context must be current.
    void deleteOwnTextureNames();
    void initializeState();
    void startFrameInGl();
    RenderResult flush(bool finish);
    void resetBatch();
    // Binds m_textures[index], uploading it first if this frame has not.
    void bindTexture(std::uint32_t index);
    // Uploads a texture's images into the bound texture object and sets its
    // sampling (filter, wrap modes).
    static void uploadTexture(const BatchTexture& texture);
    // Checks and decodes the mipmap chain of `texture` into `decoded`.
    static RenderResult decodeMipmaps(const TextureImage& texture, BatchTexture& decoded);
    // Drops the frame's textures (their OpenGL names are deleted by the next
    // flush, when the context is current).
    void forgetTextures();
    // Anti-aliasing (see setAntiAlias). Before a flush draws: binds the
    // framebuffer the frame is in, the multisample one (with multisampling
    // on) when a run of anti-aliased commands left it there, else the image.
    void bindFrameFramebuffer();
    // Before a run of commands: draws into the multisample framebuffer
    // (`on`, what the image holds copied into it) or back into the image
    // (the samples resolved into it, colour and depth); false with `error`
    // set when OpenGL cannot make the framebuffer. The GL state of the batch
    // loop is kept, except the program in use and texture unit 0's binding.
    bool useMultisample(bool on, std::string& error);
    // At endFrame: resolves the multisample framebuffer into the image.
    void resolveMultisample();
    template <class T>
    static void reserve(std::unique_ptr<T[]>& storage, std::size_t& capacity, std::size_t used, std::size_t needed);

    // Translucency and fog (RenderTarget.h: OpacitySetup, FogSetup).
    //
    // A triangle draw with an opacity below 1 or a texture with alpha is
    // split (drawSplit): its translucent triangles are copied, with what
    // they are drawn with, into the frame's translucent store, which no
    // flush empties; the opaque rest is batched as usual. Opaque triangles
    // of an alpha texture are batched too, alpha-tested so that only the
    // opaque texels draw (and write depth); the store draws their other
    // texels. endFrame draws the store last (drawTranslucent): sorted back
    // to front, blended, depth-tested without writing depth.
    struct TranslucentState {
        std::array<float, 16> matrix;
        std::uint32_t shading; // indexes m_translucentShadings, or kUnlit
        std::uint32_t texture;
        std::uint32_t fog;
        FaceOptions faces;
        bool smooth;
        bool onlyTranslucentTexels; // alpha-tested: the texels below 1
        bool multisample;           // anti-aliased (AntiAliasOptions::triangles)
        // Every vertex's opacity when the draw has one grey opacity (no
        // array, r = g = b), else negative: a lit draw of one is drawn by
        // the program variant that takes it as a uniform (SurfaceFinish.h).
        float drawOpacity;
        // The range of m_translucentVertices its triangles use (its draw's
        // vertices, stored together), for glDrawRangeElements.
        GLuint firstVertex;
        GLuint lastVertex;
        // How many triangles a draw whose every triangle is translucent
        // stored, and whether they may be drawn in any order (coversOnce,
        // found as they are stored: a mesh with a serial whose boundary is
        // one loop); 0 and false for the other draws.
        std::size_t triangleCount;
        bool anyOrder;
    };
    struct TranslucentTriangle {
        double depth; // of its centre in clip space (z / w), larger is farther
        std::uint32_t state;
        // Its corners in m_translucentVertices, which holds each vertex of a
        // draw once however many of its translucent triangles share it (so
        // that the vertex shader runs once per vertex, as for opaque draws).
        std::uint32_t v[3];
    };
    // Resized without being zeroed: each is written right after.
    using TriangleVector = std::vector<TranslucentTriangle, UninitializedAllocator<TranslucentTriangle>>;
    struct FogLoad {
        int unlit = -1; // the unlit program variant in use, -1 none
        // What each program's fog uniforms hold: the lit variants, then the
        // unlit untextured and textured programs.
        std::uint32_t fog[LitProgram::kVariants + 2];
    };
    static constexpr std::uint32_t kFogUnknown = kNoFog - 1;
    static constexpr float kOpaqueAlpha = 0.998f; // between 254/255 and 1
    RenderResult drawSplit(const DrawRequest& request, bool textured);
    // Vertex i of a draw, as the batch and the translucent store hold it.
    static Vertex vertexAt(const DrawRequest& r, bool textured, std::size_t i)
    {
        static const float kNoNormal[3] = {0.0f, 0.0f, 1.0f};
        static const float kNoST[2] = {0.0f, 0.0f};
        const float* xyz = r.xyz + 3 * i;
        const float* n = r.normals != nullptr ? r.normals + 3 * i : kNoNormal;
        const float* st = textured ? r.st + 2 * i : kNoST;
        if (r.rgb != nullptr) {
            const float* c = r.rgb + 3 * i;
            return Vertex{xyz[0], xyz[1], xyz[2], c[0], c[1], c[2], n[0], n[1], n[2], st[0], st[1]};
        }
        return Vertex{xyz[0], xyz[1], xyz[2], r.color.r, r.color.g, r.color.b, n[0], n[1], n[2], st[0], st[1]};
    }
    std::uint32_t translucentState(const DrawRequest& request, bool textured, bool onlyTranslucentTexels,
                                   float drawOpacity);
    // Stores vertex i of a draw in the translucent store with its opacity
    // and its clip coordinates under the current matrix (for the depths and
    // the clusters' rectangles); returns its place there.
    std::uint32_t storeTranslucentVertex(const DrawRequest& r, bool textured, std::size_t i,
                                         const std::array<float, 4>& opacity);
    // Stores every vertex of a draw, in order, each with `opacity`.
    void storeTranslucentVertices(const DrawRequest& r, bool textured, const std::array<float, 4>& opacity);
    // Makes the store `count` vertices long, its new places unwritten.
    void growTranslucentVertices(std::size_t count);
    // Writes vertex i of a draw at place `at` of the store, sized for it.
    void writeTranslucentVertex(const DrawRequest& r, bool textured, std::size_t i,
                                const std::array<float, 4>& opacity, std::size_t at);
    // The depth of a triangle with these corners in clip space: its
    // centre's z / w, which is the corners' summed z over their summed w
    // (the thirds cancel); a centre behind the eye sorts farthest.
    static double depthOf(const std::array<double, 4>& a, const std::array<double, 4>& b,
                          const std::array<double, 4>& c)
    {
        const double z = 0.0 + a[2] + b[2] + c[2];
        const double w = 0.0 + a[3] + b[3] + c[3];
        return w > 0.0 ? z / w : std::numeric_limits<double>::max();
    }
    // After the batch loop's program choice for a run: the unlit program
    // for fogged unlit runs, and the fog uniforms of the program in use
    // (`variant`, the lit variant the loop chose; -1 unlit).
    bool loadFog(const DrawCommand& head, int variant, FogLoad& loaded, RenderResult& result);
    // Opaque runs of an alpha texture draw only its opaque texels.
    void loadOpaqueAlphaTest(std::uint32_t texture, bool& loaded);
    void drawTranslucent(RenderResult& result);
    // Orders m_translucentTriangles from `first` on farthest first, those
    // at one depth in submission order.
    void sortFarthestFirst(std::size_t first);
    struct SortKey {
        std::uint64_t key;
        std::uint32_t index;
    };
    std::vector<SortKey> m_sortKeys; // sortFarthestFirst's scratch
    std::vector<SortKey> m_sortScratch;
    // Groups the translucent states into clusters that may share pixels
    // (see the definition): m_stateCluster; false, none found (too many
    // states to compare).
    bool findClusters();
    // Moves to the front of m_translucentTriangles, in their order, those
    // of each state alone in its cluster whose triangles cover no sample
    // twice (coversOnce); returns how many.
    std::size_t placeInOrder();
    // Whether the state's triangles (its triangleCount from firstTriangle
    // in m_translucentTriangles) cover no sample twice, `loop` being its
    // mesh's boundary loop (SingleCover.h).
    bool coversOnce(const TranslucentState& state, std::size_t firstTriangle, const std::vector<std::uint32_t>& loop);
    LoopScratch m_loopScratch; // coversOnce's
    // Reorders the sorted translucent triangles from `first` on so that
    // each state's run is as long as it can be without changing a pixel.
    void groupClusters(std::size_t first);
    std::vector<std::uint32_t> m_stateCluster;     // findClusters: each state's cluster
    std::vector<std::uint32_t> m_clusterOf;        // groupClusters' scratch
    TriangleVector m_clustered;
    void forgetTranslucent();
    const FogSetup& fogOf(std::uint32_t fog) const;

    std::vector<FogSetup> m_fogs;
    std::uint32_t m_currentFog = kNoFog;
    OpacitySetup m_opacity;
    // (Resized without being zeroed: each is written right after.)
    std::vector<Vertex, UninitializedAllocator<Vertex>> m_translucentVertices;
    // The clip coordinates of each translucent vertex under its draw's
    // matrix (x y z w), computed once per vertex by drawSplit.
    std::vector<std::array<double, 4>, UninitializedAllocator<std::array<double, 4>>> m_translucentClip;
    // And its window coordinates in pixels from the pane's lower left corner
    // (x NaN for one at or behind the eye), for the clusters and coversOnce.
    std::vector<WindowPoint, UninitializedAllocator<WindowPoint>> m_translucentWindow;
    std::vector<float, UninitializedAllocator<float>> m_translucentOpacity; // r g b and their mean per vertex
    std::vector<TranslucentState> m_translucentStates;
    std::vector<SurfaceShading> m_translucentShadings;
    TriangleVector m_translucentTriangles;
    IndexVector m_translucentIndices;
    std::vector<std::uint32_t> m_splitOpaque; // drawSplit's opaque triangles
    std::vector<std::uint32_t> m_splitVertices; // drawSplit: a vertex's place in m_translucentVertices

    // The backend asked for (its result: why it cannot be used).
    GlBackendChoice m_backend;

    PixelRect m_pane;
    RgbaColor m_clearColor;
    FrameOptions m_options;
    bool m_clearedInGl = false;

    std::unique_ptr<Vertex[]> m_vertices;
    std::size_t m_vertexCount = 0;
    std::size_t m_vertexCapacity = 0;
    // Plain commands' vertices, 3 floats each: a third of a Vertex, and
    // OpenGL fetches one array for them instead of three (a constant colour
    // through glColor, as a plain OpenGL program draws; no normal, which
    // unlit drawing never reads). Profiled on a frame of 1000 line strips
    // (65,000 vertices, benchmarks/FrameBench.cpp): the three arrays cost
    // Mesa's vertex fetch about 4 ms of the main thread's 21 ms.
    std::unique_ptr<Position[]> m_positions;
    std::size_t m_positionCount = 0;
    std::size_t m_positionCapacity = 0;
    IndexVector m_indices;
    std::vector<DrawCommand> m_commands;
    std::vector<std::array<float, 16>> m_matrices;
    std::uint32_t m_currentMatrix = 0;
    std::vector<GLint> m_multiFirsts;
    std::vector<GLsizei> m_multiCounts;
    std::vector<const void*> m_multiIndices;

    LightingSetup m_lighting;
    std::vector<SurfaceShading> m_shadings;
    FaceOptions m_faces;
    // The variant a shading is drawn with, built if it is not yet (null,
    // with `result` set, when the driver refuses it).
    LitProgram* litProgram(int variant, RenderResult& result);
    // Makes variant `variant` current for `shading`: built if need be, its
    // two-sidedness set, the frame's lights loaded the first time this flush
    // uses it (lightsLoaded, one flag per variant), and `drawOpacity` set
    // when the variant takes one (DRAW_OPACITY). Null, with `result` set,
    // when the driver refuses the program.
    LitProgram* useLitProgram(int variant, const SurfaceShading& shading, bool* lightsLoaded, RenderResult& result,
                              float drawOpacity = 1.0f);
    // Two-sided colours for a lit variant that writes them (on between uses:
    // the unlit programs write both).
    static void setTwoSided(int variant)
    {
        if (LitProgram::isOneSided(variant))
            glDisable(GL_VERTEX_PROGRAM_TWO_SIDE);
        else
            glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
    }
    // The frame's textures (addTexture), kept until it ends so that a
    // texture drawn again after others, or after a flush, is neither decoded
    // nor uploaded twice; m_currentTexture is the one useTexture chose
    // (kUntextured: none).
    std::vector<BatchTexture> m_textures;
    std::uint32_t m_currentTexture = kUntextured;
    // OpenGL names of the frame's uploaded textures, by m_textures index (0:
    // not uploaded yet), and names of an earlier frame left to delete.
    std::vector<GLuint> m_textureNames;
    std::vector<GLuint> m_staleTextureNames;
    // Textures kept on the GPU from frame to frame: a texture added with
    // the very bytes, layouts, wrap modes and filter of one the previous
    // frame used is neither decoded nor uploaded again (compared byte for
    // byte, so an edited image is a new texture). The cache is the
    // context's (GlResources), shared by the renderers that draw with it: an
    // entry this renderer used last and its frame did not use is deleted at
    // the frame's end, so what is kept is what each scene draws; an entry no
    // frame of the context used for kStaleFrames frames goes too (its
    // renderer draws with another context now).
    static constexpr std::uint32_t kNotCached = std::numeric_limits<std::uint32_t>::max();
    static constexpr std::size_t kTextureCacheBytes = std::size_t(64) << 20;
    struct CachedTexture {
        std::vector<std::uint8_t> source;  // every level's bytes as given, one after the other
        std::vector<PixmapLayout> layouts; // every level's layout
        std::vector<std::uint64_t> sourceKey; // TextureImage::sourceKey, when it had one
        bool clampS = false;
        bool clampT = false;
        TextureFilter filter = TextureFilter::kNearest;
        bool hasAlpha = false;
        GLuint name = 0; // 0 until a draw uploads it
        std::uint64_t lastFrame = 0; // the context's frame that used it last
        const Impl* user = nullptr;  // the renderer that used it last
    };
    static constexpr std::uint64_t kStaleFrames = 64;
    // The slot of a cached texture with exactly these images and sampling,
    // or kNotCached.
    std::uint32_t findCachedTexture(const TextureImage& texture) const;
    // Deletes cached textures (the context must be current): kUnused at a
    // frame's end (see above), kMine this renderer's (it is going away).
    enum class Evict { kUnused, kMine };
    void evictTextures(Evict which);
    // Anti-aliasing: the current options and whether this frame draws into
    // the multisample framebuffer (GlResources holds its objects).
    AntiAliasOptions m_antiAlias;
    bool m_multisampling = false;
    // Buffer objects the arrays of a flush are uploaded into once (0: not
    // made yet in this context): interleaved vertices, plain positions,
    // indices, translucent opacity. Drawing from client arrays instead makes
    // Mesa copy the index range of every draw call into a buffer of its own;
    // a translucent store whose sorted triangles switch state often (meshes
    // interleaved in depth) then copied its whole vertex range per switch
    // (benchmarks/RESULTS.md, ModelFrame: most of the main thread's time).
    enum StreamBuffer { kStreamVertices, kStreamPositions, kStreamIndices, kStreamOpacity, kStreamBufferCount };
    // Uploads `bytes` into stream buffer `which`, leaving it bound to `target`.
    void uploadStream(StreamBuffer which, GLenum target, const void* data, std::size_t bytes);

public:
    // Static vertex data: the vertices and indices of a retained mesh's
    // opaque filled triangles, kept in the context's buffers from frame to
    // frame (GlResources::kept) so that a frame drawing the mesh again the
    // same way neither checks, assembles nor uploads them, as an OpenGL
    // program keeps its static buffers. What the batch would hold is fully
    // determined by a StaticKey: the mesh's serial (MeshView::serial: its
    // arrays), the uv transform its texture coordinates were computed with,
    // the colour and the flags that choose how Impl::draw and drawLit
    // derive the vertices. A key is kept the second time it is drawn (so a
    // mesh edited every frame, which never comes back, is uploaded once a
    // frame, not twice), from the batch that frame assembled.
    struct StaticKey {
        std::uint64_t serial = 0;
        float stTransform[6] = {};
        float color[3] = {};
        std::uint32_t vertexCount = 0;
        std::uint32_t triangleCount = 0;
        std::uint8_t flags = 0; // kKey* below
        bool operator==(const StaticKey& other) const;
    };
    static constexpr std::uint8_t kKeyColors = 1, kKeyTextured = 2, kKeyLit = 4, kKeySmooth = 8,
                                  kKeyClockwise = 16;
    // Draws the opaque filled triangles of `mesh` from kept data when the
    // context keeps them under `key` (true; an error in `result`), else
    // false: the caller draws them as usual, and the batch's copy is kept if
    // the key was drawn before (the next draw request takes the offer).
    bool drawKept(const StaticKey& key, const SurfaceShading* shading, RenderResult& result);
    void withdrawOffer()
    {
        m_offer = false;
        m_loopOffer = LoopOffer{};
    }
    std::uint64_t m_keptDraws = 0; // drawKept's draws, for tests
    // A translucent mesh with a serial, offered for the draw that follows
    // (drawFilled): if that draw's triangles are the mesh's own, all
    // translucent, its boundary loop (SingleCover.h, found once per serial
    // and kept with the context) may let them be drawn unsorted.
    struct LoopOffer {
        std::uint64_t serial = 0;
        const std::uint32_t* corners = nullptr;
        std::size_t vertexCount = 0;
        std::size_t triangleCount = 0;
    };
    void offerLoop(const LoopOffer& offer) { m_loopOffer = offer; }
    std::uint64_t m_inOrderTriangles = 0; // drawn in their own order (placeInOrder), for tests
    std::size_t m_keptLimits[2] = {kKeptVertexLimit, kKeptIndexLimit}; // setKeptLimits
    // Whether the frame's current opacity and texture let its filled
    // triangles be drawn opaque, unsplit (Impl::draw).
    bool opaqueFill(bool textured) const
    {
        if (m_opacity.rgb != nullptr || m_opacity.uniform.r < 1.0f || m_opacity.uniform.g < 1.0f ||
            m_opacity.uniform.b < 1.0f)
            return false;
        return !textured || (m_currentTexture != kUntextured && !m_textures[m_currentTexture].hasAlpha);
    }

private:
    struct KeptMesh {
        StaticKey key;
        enum class State { kSeen, kPending, kStored } state = State::kSeen;
        GLuint firstVertex = 0; // in the kept vertex buffer
        GLuint vertexCount = 0;
        GLuint firstIndex = 0;  // in the kept index buffer
        GLsizei indexCount = 0;
        std::uint64_t lastFrame = 0; // the context's frame that drew it last
    };
    // A kept mesh the batch holds this frame, to be copied into the kept
    // buffers at the flush.
    struct PendingKept {
        StaticKey key;
        GLuint streamFirstVertex;
        GLuint vertexCount;
        GLint streamFirstIndex;
        GLsizei indexCount;
    };
    std::vector<PendingKept> m_pendingKept;
    std::vector<GLuint> m_keptIndices; // storePendingKept's scratch
    StaticKey m_offerKey;
    bool m_offer = false;
    LoopOffer m_loopOffer;
    // The offered mesh's boundary loop when request `r` draws its
    // triangles, else null; takes the offer.
    const std::vector<std::uint32_t>* loopOf(const DrawRequest& r);
    struct MeshLoop {
        std::size_t vertexCount = 0;
        std::size_t triangleCount = 0;
        std::vector<std::uint32_t> loop; // empty: none (boundaryLoop false)
        std::uint64_t lastFrame = 0;
    };
    KeptMesh* findKept(const StaticKey& key);
    // At the flush, after the batch's upload: copies the pending meshes
    // into the kept buffers (those that fit).
    void storePendingKept();
    // At beginFrame: forgets meshes no frame drew for kStaleFrames frames,
    // and empties the kept buffers after one ran out of room (to be filled
    // again, larger, by the meshes drawn from then on).
    void trimKept();
    // The most vertices and indices kept per context (meshes beyond are
    // drawn from the batch each frame), and the buffers' first capacity.
    static constexpr std::size_t kKeptVertexLimit = std::size_t(1) << 20;
    static constexpr std::size_t kKeptIndexLimit = std::size_t(1) << 22;
    static constexpr std::size_t kKeptInitialVertices = std::size_t(1) << 15;
    static constexpr std::size_t kKeptInitialIndices = std::size_t(1) << 16;

public:
    // What belongs to one OpenGL context and lives as long as it: the
    // context, with what was made in it. A renderer holds one only from
    // beginFrame to endFrame (or cancelFrame) and lends it to the process's
    // pool of idle contexts (ContextPool) in between; its next frame takes
    // it back if no other renderer took it, else another idle one of its
    // backend and size, else a new one. So views drawn one after another on
    // a thread, however many there are, draw with one context and what it
    // compiled; only views drawn at the same moment need contexts of their
    // own.
    struct GlResources {
        GlBackend backend = GlBackend::kOsMesa;
        std::uint32_t width = 0;
        std::uint32_t height = 0;
        bool bgra = false; // draws B, G, R, A images (FrameOptions::bgraImage)
        std::unique_ptr<GlContext> context;
        GLint maxViewport[2] = {0, 0};
        // The lighting programs by variant (LitProgram::variant), each made
        // when a draw first needs it (a frame uses a handful of the
        // kVariants; all of them held here were half a megabyte a context).
        std::unique_ptr<LitProgram> litPrograms[LitProgram::kVariants];
        UnlitProgram unlitPrograms[2];
        // Anti-aliasing's OpenGL objects (0: not made yet in this context),
        // with the program that copies the image into the multisample
        // framebuffer.
        GLuint msFramebuffer = 0;
        GLuint msColor = 0;
        GLuint msDepth = 0;
        GLuint copyProgram = 0;
        GLuint streamBuffers[kStreamBufferCount] = {0, 0, 0, 0};
        // The bytes each stream buffer's store holds (it only grows: see
        // uploadStream).
        std::size_t streamCapacity[kStreamBufferCount] = {0, 0, 0, 0};
        std::vector<CachedTexture> textureCache;
        std::size_t textureCacheBytes = 0;
        // Static vertex data (StaticKey): the meshes by serial, and two
        // buffers (vertices, indices) filled from the front, with their
        // capacity and what is used, in vertices and in indices; keptFull
        // when a mesh did not fit (the buffers are emptied and grown at the
        // next frame's start).
        std::unordered_map<std::uint64_t, std::vector<KeptMesh>> kept;
        GLuint keptBuffers[2] = {0, 0};
        std::size_t keptCapacity[2] = {0, 0};
        std::size_t keptAllocated[2] = {0, 0};
        std::size_t keptUsed[2] = {0, 0};
        std::size_t keptDemand[2] = {0, 0}; // what did not fit
        std::size_t keptLive[2] = {0, 0};   // what the stored meshes use
        bool keptFull = false;
        // Translucent meshes' boundary loops by serial (loopOf), forgotten
        // as kept meshes are.
        std::unordered_map<std::uint64_t, MeshLoop> loops;
        std::uint64_t frameNumber = 0; // frames begun with this context
        const Impl* lender = nullptr;  // in the pool: the renderer that lent it
    };

    bool m_drewInPlace = false; // the last frame went into FrameOptions::bgraImage

private:
    // This frame's context (null between frames: lent to the pool).
    std::unique_ptr<GlResources> m_gl;
    // The image this frame draws into: m_image, or the caller's
    // (FrameOptions::bgraImage) with its rows m_frameRowPixels apart.
    std::uint8_t* m_frameImage = nullptr;
    std::uint32_t m_frameRowPixels = 0;
    bool m_direct = false;
    // The process's idle contexts (see ContextPool below).
    struct ContextPool;
    static ContextPool& contextPool();
    // Takes from the pool the oldest idle contexts beyond what it keeps,
    // for the caller to destroy outside the pool's lock (destroying one
    // takes the context mutex).
    static std::vector<std::unique_ptr<GlResources>> trimPoolLocked(ContextPool& pool);
};

namespace {

// Idle contexts: lent by renderers between their frames (GlResources) and
// kept after a renderer is gone, for the next frame of the same backend and
// size. A view's first frame otherwise pays for a new OpenGL context (about
// 5 ms with llvmpipe) and for compiling its GLSL programs and llvmpipe's
// machine code for them (about 20 ms for a textured, lit, translucent scene:
// benchmarks/RESULTS.md, FirstFrame); a context handed on keeps its linked
// programs, and llvmpipe keeps their compiled variants with them. The pool
// keeps as many idle contexts as there are live renderers, and at least
// kIdleContexts (views come and go: a window resized, a document
// reopened), dropping the oldest beyond that. It is never destroyed: an
// atexit handler may still render after static destructors ran, and the
// process's end frees what it holds.
constexpr std::size_t kIdleContexts = 2;

std::atomic<std::uint64_t> g_contextsMade{0};

} // namespace

struct OffscreenRenderer::Impl::ContextPool {
    std::mutex mutex;
    std::vector<std::unique_ptr<GlResources>> idle; // oldest first
    std::size_t renderers = 0;                      // live renderers
};

OffscreenRenderer::Impl::ContextPool& OffscreenRenderer::Impl::contextPool()
{
    static ContextPool* pool = new ContextPool;
    return *pool;
}

std::vector<std::unique_ptr<OffscreenRenderer::Impl::GlResources>>
OffscreenRenderer::Impl::trimPoolLocked(ContextPool& pool)
{
    std::vector<std::unique_ptr<GlResources>> dropped;
    const std::size_t keep = std::max(kIdleContexts, pool.renderers);
    while (pool.idle.size() > keep) {
        dropped.push_back(std::move(pool.idle.front()));
        pool.idle.erase(pool.idle.begin());
    }
    return dropped;
}

OffscreenRenderer::Impl::Impl(const GlBackendChoice& backend) : m_backend(backend)
{
    ContextPool& pool = contextPool();
    std::lock_guard<std::mutex> lock(pool.mutex);
    ++pool.renderers;
}

OffscreenRenderer::Impl::~Impl()
{
    ContextPool& pool = contextPool();
    if (m_gl == nullptr) {
        // Its context back, if no other renderer took it: to delete the
        // textures only this renderer drew.
        std::lock_guard<std::mutex> lock(pool.mutex);
        for (auto it = pool.idle.begin(); it != pool.idle.end(); ++it)
            if ((*it)->lender == this) {
                m_gl = std::move(*it);
                pool.idle.erase(it);
                break;
            }
    }
    if (m_gl != nullptr) {
        bool bound = false;
        {
            ContextScope scope(*m_gl->context, m_image.data());
            bound = scope.bound();
            if (bound) {
                evictTextures(Evict::kMine);
                deleteOwnTextureNames();
            }
        }
        if (!bound) {
            // Not handed on: a context that cannot be made current.
            m_textureNames.clear();
            m_staleTextureNames.clear();
            m_gl.reset();
        }
    }
    lendContext();
    std::vector<std::unique_ptr<GlResources>> dropped;
    {
        std::lock_guard<std::mutex> lock(pool.mutex);
        --pool.renderers;
        for (std::unique_ptr<GlResources>& idle : pool.idle)
            if (idle->lender == this)
                idle->lender = nullptr;
        dropped = trimPoolLocked(pool);
    }
}

void OffscreenRenderer::Impl::deleteOwnTextureNames()
{
    // glDeleteTextures skips the zeros (textures never uploaded).
    for (std::vector<GLuint>* names : {&m_textureNames, &m_staleTextureNames}) {
        if (!names->empty())
            glDeleteTextures(GLsizei(names->size()), names->data());
        names->clear();
    }
}

void OffscreenRenderer::Impl::lendContext()
{
    if (m_gl == nullptr)
        return;
    if (!m_textureNames.empty() || !m_staleTextureNames.empty()) {
        // A cancelled frame's own textures: deleted in the context they are
        // names of. A context that cannot be made current is not lent.
        ContextScope scope(*m_gl->context, m_image.data());
        if (!scope.bound()) {
            m_textureNames.clear();
            m_staleTextureNames.clear();
            m_gl.reset();
            return;
        }
        deleteOwnTextureNames();
    }
    m_gl->lender = this;
    std::vector<std::unique_ptr<GlResources>> dropped;
    {
        ContextPool& pool = contextPool();
        std::lock_guard<std::mutex> lock(pool.mutex);
        pool.idle.push_back(std::move(m_gl));
        dropped = trimPoolLocked(pool);
    }
}

RenderResult OffscreenRenderer::Impl::acquireContext(std::uint32_t width, std::uint32_t height, bool bgra)
{
    if (renderingShutDown())
        return RenderResult::failure(RenderStatus::kContextFailure, detail::kShutDownMessage);
    if (m_gl != nullptr && m_gl->width == width && m_gl->height == height && m_gl->bgra == bgra)
        return RenderResult::success();
    lendContext();
    if (!m_backend.result)
        return m_backend.result;
    if (width != m_width || height != m_height) {
        std::vector<std::uint8_t>().swap(m_image);
        m_width = 0;
        m_height = 0;
        m_image.resize(std::size_t(width) * height * 4);
        m_width = width;
        m_height = height;
    }
    {
        // The one this renderer lent if it is there, else the most recently
        // lent one of this backend and size.
        ContextPool& pool = contextPool();
        std::lock_guard<std::mutex> lock(pool.mutex);
        auto found = pool.idle.end();
        for (auto it = pool.idle.begin(); it != pool.idle.end(); ++it) {
            if ((*it)->backend != m_backend.backend || (*it)->width != width || (*it)->height != height ||
                (*it)->bgra != bgra)
                continue;
            found = it;
            if ((*it)->lender == this)
                break;
        }
        if (found != pool.idle.end()) {
            m_gl = std::move(*found);
            pool.idle.erase(found);
        }
    }
    if (m_gl != nullptr) {
        m_gl->lender = nullptr;
        return RenderResult::success();
    }

    auto made = std::make_unique<GlResources>();
    made->backend = m_backend.backend;
    made->width = width;
    made->height = height;
    made->bgra = bgra;
    RenderResult result = createGlContext(m_backend.backend, width, height, m_image.data(), made->context, bgra);
    if (result) {
        ContextScope scope(*made->context, m_image.data());
        if (!scope.bound()) {
            result = RenderResult::failure(RenderStatus::kContextFailure,
                                           std::string("making the ") + glBackendName(m_backend.backend) +
                                               " context current failed");
        } else {
            glGetIntegerv(GL_MAX_VIEWPORT_DIMS, made->maxViewport);
            initializeState();
            GLenum error = takeGlError();
            if (error != GL_NO_ERROR)
                result = RenderResult::failure(RenderStatus::kGraphicsError,
                                               std::string("setting up the OpenGL state failed: ") +
                                                   glErrorName(error));
        }
    }
    if (result) {
        m_gl = std::move(made);
        g_contextsMade.fetch_add(1, std::memory_order_relaxed);
    } else {
        std::vector<std::uint8_t>().swap(m_image);
        m_width = 0;
        m_height = 0;
    }
    return result;
}

// Every value here is OpenGL's default except the shade model; they are set
// anyway because reproducible images depend on them (see the file comment).
void OffscreenRenderer::Impl::initializeState()
{
    const GLenum disabled[] = {GL_DITHER,       GL_MULTISAMPLE,    GL_LINE_SMOOTH,  GL_POINT_SMOOTH,
                               GL_POLYGON_SMOOTH, GL_LINE_STIPPLE, GL_POLYGON_STIPPLE, GL_BLEND,
                               GL_DEPTH_TEST,   GL_STENCIL_TEST,   GL_ALPHA_TEST,   GL_CULL_FACE,
                               GL_LIGHTING,     GL_FOG,            GL_COLOR_LOGIC_OP, GL_TEXTURE_2D,
                               GL_VERTEX_PROGRAM_POINT_SIZE};
    for (GLenum capability : disabled)
        glDisable(capability);
    glLineWidth(1.0f);
    glPointSize(1.0f);
    glShadeModel(GL_FLAT);
    // A fragment as near as the one drawn before it wins, so primitives in one
    // plane keep their submission order under the depth test.
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_TRUE);
    glClearDepth(1.0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    // Textured triangles: the interpolated colour times the texel.
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glActiveTexture(GL_TEXTURE0);
    // The lit program gives back faces their own colour (flipped normals).
    glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    setDefaultOpacity();
}

RenderResult OffscreenRenderer::Impl::beginFrame(std::uint32_t width, std::uint32_t height,
                                                 const RgbaColor& clearColor, const PixelRect& pane,
                                                 const FrameOptions& options)
{
    if (m_inFrame)
        return RenderResult::failure(RenderStatus::kWrongState, "beginFrame called inside a frame");
    if (width == 0 || height == 0 || width > kMaxImageSize || height > kMaxImageSize)
        return invalid("image size " + std::to_string(width) + " x " + std::to_string(height) +
                       " is outside 1.." + std::to_string(kMaxImageSize));
    const float clear[4] = {clearColor.r, clearColor.g, clearColor.b, clearColor.a};
    if (!allFinite(clear, 4))
        return invalid("clear colour has a NaN or infinite channel");
    if (pane.width <= 0 || pane.height <= 0 || pane.width > int(kMaxImageSize) ||
        pane.height > int(kMaxImageSize))
        return invalid("pane size " + std::to_string(pane.width) + " x " + std::to_string(pane.height) +
                       " is outside 1.." + std::to_string(kMaxImageSize));
    if (pane.x < -kMaxPaneOffset || pane.x > kMaxPaneOffset || pane.y < -kMaxPaneOffset ||
        pane.y > kMaxPaneOffset)
        return invalid("pane origin is outside +-" + std::to_string(kMaxPaneOffset));

    // The caller's image when it offers one (OSMesa draws into it with a
    // context of that layout; EGL reads back into it in that layout): the
    // copy into the caller's pixmap is saved.
    const bool direct = options.bgraImage != nullptr && pane.x == 0 && pane.y == 0 && std::uint32_t(pane.width) == width &&
                        std::uint32_t(pane.height) == height && options.bgraRowBytes % 4 == 0 &&
                        options.bgraRowBytes / 4 >= width && options.bgraRowBytes / 4 <= kMaxImageSize;
    m_drewInPlace = false;
    RenderResult acquired = acquireContext(width, height, direct);
    if (!acquired)
        return acquired;
    m_direct = direct;
    m_frameImage = direct ? options.bgraImage : m_image.data();
    m_frameRowPixels = direct ? std::uint32_t(options.bgraRowBytes / 4) : 0;
    if (pane.width > m_gl->maxViewport[0] || pane.height > m_gl->maxViewport[1]) {
        lendContext();
        return invalid("pane is larger than the maximum viewport");
    }

    ++m_gl->frameNumber;
    trimKept();
    m_pane = pane;
    m_clearColor = clearColor;
    m_options = options;
    m_clearedInGl = false;
    m_lighting = LightingSetup{};
    m_faces = FaceOptions{};
    m_antiAlias = AntiAliasOptions{};
    m_multisampling = false;
    forgetTextures();
    forgetTranslucent();
    resetBatch();
    m_matrices.clear();
    m_matrices.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
    m_currentMatrix = 0;
    m_inFrame = true;
    return RenderResult::success();
}

RenderResult OffscreenRenderer::Impl::setMatrix(const std::array<float, 16>& matrix)
{
    if (!m_inFrame)
        return RenderResult::failure(RenderStatus::kWrongState, "setMatrix called outside a frame");
    if (!allFinite(matrix.data(), 16))
        return invalid("matrix has a NaN or infinite element (after rounding to float)");
    if (matrix == m_matrices[m_currentMatrix])
        return RenderResult::success();
    // A matrix no command refers to yet is overwritten rather than kept.
    if (!m_commands.empty() && m_commands.back().matrixIndex == m_currentMatrix) {
        m_matrices.push_back(matrix);
        m_currentMatrix = std::uint32_t(m_matrices.size() - 1);
    } else {
        m_matrices[m_currentMatrix] = matrix;
    }
    return RenderResult::success();
}

// Grows `storage` (of `capacity` elements) to hold `needed`, keeping its
// first `used`; throws std::bad_alloc.
template <class T>
void OffscreenRenderer::Impl::reserve(std::unique_ptr<T[]>& storage, std::size_t& capacity, std::size_t used,
                                      std::size_t needed)
{
    if (needed <= capacity)
        return;
    std::size_t grown = capacity < 4096 ? 4096 : capacity;
    while (grown < needed)
        grown *= 2;
    std::unique_ptr<T[]> bigger(new T[grown]);
    if (used > 0)
        std::memcpy(bigger.get(), storage.get(), used * sizeof(T));
    storage = std::move(bigger);
    capacity = grown;
}

RenderResult OffscreenRenderer::Impl::draw(const DrawRequest& r)
{
    if (!m_inFrame)
        return RenderResult::failure(RenderStatus::kWrongState, "draw call outside a frame");
    const bool indexed = r.indexed;
    const std::size_t count = indexed ? r.indexCount : r.vertexCount;
    if (count == 0)
        return RenderResult::success();
    if (r.xyz == nullptr)
        return invalid("vertex pointer is NULL");
    if (indexed && r.indices == nullptr)
        return invalid("index pointer is NULL");
    if (indexed && r.primitive == Primitive::kLineStrip)
        return invalid("a line strip cannot be drawn from indices");
    if (r.primitive == Primitive::kLines && count % 2 != 0)
        return invalid("lines need an even vertex count, got " + std::to_string(count));
    if (r.primitive == Primitive::kTriangles && count % 3 != 0)
        return invalid("triangles need a multiple of 3 vertices, got " + std::to_string(count));
    if (count > std::size_t(std::numeric_limits<GLint>::max()) ||
        r.vertexCount > std::size_t(std::numeric_limits<GLint>::max()))
        return invalid("too many vertices in one call");
    const float rgb[3] = {r.color.r, r.color.g, r.color.b};
    if (!allFinite(rgb, 3))
        return invalid("colour has a NaN or infinite channel");
    if (r.primitive == Primitive::kPoints && !(r.pointSize > 0.0f && std::isfinite(r.pointSize)))
        return invalid("point size must be positive and finite");
    if (r.primitive == Primitive::kLineStrip && count < 2)
        return RenderResult::success();
    if (!allFinite(r.xyz, r.vertexCount * 3))
        return invalid("a vertex coordinate is NaN or infinite");
    if (r.rgb != nullptr && !allFinite(r.rgb, r.vertexCount * 3))
        return invalid("a vertex colour channel is NaN or infinite");
    const bool textured = r.st != nullptr && m_currentTexture != kUntextured && r.primitive == Primitive::kTriangles;
    if (textured && !allFinite(r.st, r.vertexCount * 2))
        return invalid("a texture coordinate is NaN or infinite");
    if (r.shading != nullptr) {
        if (r.normals == nullptr)
            return invalid("lit triangles need normals");
        if (!allFinite(r.normals, r.vertexCount * 3))
            return invalid("a vertex normal is NaN or infinite");
        if (!shadingFinite(*r.shading))
            return invalid("a shading value is NaN or infinite");
    }
    if (indexed) {
        // Whether any index is too large first (a reduction the compiler
        // vectorizes), the culprit only when there is one.
        const std::uint32_t vertexCount = std::uint32_t(r.vertexCount);
        std::uint32_t outside = 0;
        for (std::size_t i = 0; i < r.indexCount; ++i)
            outside |= std::uint32_t(r.indices[i] >= vertexCount);
        if (outside != 0)
            for (std::size_t i = 0; i < r.indexCount; ++i)
                if (r.indices[i] >= r.vertexCount)
                    return invalid("index " + std::to_string(r.indices[i]) + " is not below the vertex count " +
                                   std::to_string(r.vertexCount));
    }
    if (r.primitive == Primitive::kTriangles && !r.opaquePart && !opaqueFill(textured))
        return drawSplit(r, textured);

    // One colour, no lighting, no interpolation: positions only
    // (m_positions). Interpolating a constant colour array does not always
    // give the constant itself (llvmpipe's perspective-correct interpolation
    // rounds), so smooth draws keep their colour array: same image either way.
    const bool plain = r.rgb == nullptr && r.shading == nullptr && !r.smooth && !textured;
    const std::size_t batched = plain ? m_positionCount : m_vertexCount;
    if ((batched > 0 && batched + r.vertexCount > kFlushVertexCount) ||
        (!m_indices.empty() && m_indices.size() + r.indexCount > kFlushIndexCount)) {
        RenderResult flushed = flush(false);
        if (!flushed)
            return flushed;
    }

    try {
        if (plain)
            reserve(m_positions, m_positionCapacity, m_positionCount, m_positionCount + r.vertexCount);
        else
            reserve(m_vertices, m_vertexCapacity, m_vertexCount, m_vertexCount + r.vertexCount);
        if (indexed)
            m_indices.reserve(m_indices.size() + r.indexCount);
        if (r.shading != nullptr)
            m_shadings.reserve(m_shadings.size() + 1);
        if (m_commands.size() == m_commands.capacity())
            m_commands.reserve(m_commands.empty() ? 256 : m_commands.size() * 2);
    } catch (const std::bad_alloc&) {
        return outOfMemory();
    }

    const std::size_t base = plain ? m_positionCount : m_vertexCount; // after a flush, 0
    if (plain) {
        std::memcpy(m_positions.get() + base, r.xyz, r.vertexCount * sizeof(Position));
        m_positionCount += r.vertexCount;
    } else {
        Vertex* out = m_vertices.get() + base;
        for (std::size_t i = 0; i < r.vertexCount; ++i)
            out[i] = vertexAt(r, textured, i);
        m_vertexCount += r.vertexCount;
    }

    std::uint32_t shading = kUnlit;
    if (r.shading != nullptr) {
        m_shadings.push_back(*r.shading);
        shading = std::uint32_t(m_shadings.size() - 1);
    }
    const FaceOptions faces = r.primitive == Primitive::kTriangles ? m_faces : FaceOptions{};
    DrawCommand command{r.primitive, indexed, r.smooth, plain, r.pointSize, m_currentMatrix, shading,
                        textured ? m_currentTexture : kUntextured, faces, plain ? r.color : RgbColor{}, 0,
                        GLsizei(count)};
    command.multisample = r.primitive == Primitive::kTriangles ? m_antiAlias.triangles : m_antiAlias.lines;
    command.fog = m_currentFog;
    if (indexed) {
        command.first = GLint(m_indices.size());
        m_indices.resize(m_indices.size() + r.indexCount);
        GLuint* out = m_indices.data() + command.first;
        const GLuint offset = GLuint(base);
        for (std::size_t i = 0; i < r.indexCount; ++i)
            out[i] = offset + r.indices[i];
        command.minIndex = offset;
        command.maxIndex = offset + GLuint(r.vertexCount - 1);
    } else {
        command.first = GLint(base);
    }
    if (m_offer && indexed && !plain && r.primitive == Primitive::kTriangles) {
        KeptMesh* kept = findKept(m_offerKey);
        if (kept != nullptr && kept->state == KeptMesh::State::kSeen) {
            m_pendingKept.push_back(PendingKept{m_offerKey, GLuint(base), GLuint(r.vertexCount), command.first,
                                                GLsizei(r.indexCount)});
            kept->state = KeptMesh::State::kPending;
        }
        m_offer = false;
    }
    if (r.primitive != Primitive::kLineStrip && !m_commands.empty()) {
        DrawCommand& last = m_commands.back();
        if (last.drawsLike(command) &&
            std::size_t(last.first) + std::size_t(last.count) == std::size_t(command.first) &&
            std::size_t(last.count) + count <= std::size_t(std::numeric_limits<GLsizei>::max())) {
            last.count += GLsizei(count);
            last.minIndex = std::min(last.minIndex, command.minIndex);
            last.maxIndex = std::max(last.maxIndex, command.maxIndex);
            return RenderResult::success();
        }
    }
    m_commands.push_back(command);
    return RenderResult::success();
}

bool OffscreenRenderer::Impl::place(const float* anchor, long xOffset, long yOffset, std::uint32_t width,
                                    std::uint32_t height, ScreenPlacement& out) const
{
    // The anchor in clip space (row vector times the current matrix), then
    // in pane pixels measured from the top left.
    const std::array<float, 16>& matrix = m_matrices[m_currentMatrix];
    double clip[4];
    for (int j = 0; j < 4; ++j)
        clip[j] = double(anchor[0]) * matrix[j] + double(anchor[1]) * matrix[4 + j] +
                  double(anchor[2]) * matrix[8 + j] + matrix[12 + j];
    if (!(clip[3] > 0.0) || !(clip[2] >= -clip[3] && clip[2] <= clip[3]))
        return false;
    out.depth = clip[2] / clip[3];
    const double px = (clip[0] / clip[3] + 1.0) * 0.5 * m_pane.width;
    const double py = (1.0 - clip[1] / clip[3]) * 0.5 * m_pane.height;
    constexpr double kFar = 1e12; // well past any pane, yet exact in an int64
    if (!(std::fabs(px) < kFar && std::fabs(py) < kFar))
        return false;
    // Offsets past 2^40 pixels put any image (at most 2^32 pixels wide) wholly
    // off any pane either way; clamping them keeps the sums from overflowing.
    constexpr long kFarOffset = 1L << 40;
    out.left = std::int64_t(std::floor(px)) + std::clamp(xOffset, -kFarOffset, kFarOffset);
    out.top = std::int64_t(std::floor(py)) + std::clamp(yOffset, -kFarOffset, kFarOffset);
    // Only the rows and columns that land in the pane.
    out.c0 = std::max<std::int64_t>(0, -out.left);
    out.c1 = std::min<std::int64_t>(width, std::int64_t(m_pane.width) - out.left);
    out.r0 = std::max<std::int64_t>(0, -out.top);
    out.r1 = std::min<std::int64_t>(height, std::int64_t(m_pane.height) - out.top);
    return out.c0 < out.c1 && out.r0 < out.r1;
}

void OffscreenRenderer::Impl::pushPixel(const ScreenPlacement& at, std::int64_t c, std::int64_t r,
                                        std::vector<float>& points) const
{
    const double x = double(at.left + c) + 0.5, y = double(at.top + r) + 0.5;
    points.push_back(float(x / m_pane.width * 2.0 - 1.0));
    points.push_back(float(1.0 - y / m_pane.height * 2.0));
    points.push_back(float(at.depth));
}

RenderResult OffscreenRenderer::Impl::drawScreenPoints(const std::vector<float>& points,
                                                       const std::vector<float>* rgb, const RgbColor& color)
{
    if (points.empty())
        return RenderResult::success();
    const std::array<float, 16> matrix = m_matrices[m_currentMatrix];
    static const std::array<float, 16> kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    RenderResult result = setMatrix(kIdentity);
    if (!result)
        return result;
    DrawRequest request;
    request.primitive = Primitive::kPoints;
    request.xyz = points.data();
    request.rgb = rgb != nullptr ? rgb->data() : nullptr;
    request.vertexCount = points.size() / 3;
    request.color = color;
    result = draw(request);
    const RenderResult restored = setMatrix(matrix);
    return result ? restored : result;
}

RenderResult OffscreenRenderer::Impl::drawBitmap(const float* anchor, const BitmapImage& image,
                                                 const RgbColor& color)
{
    if (!m_inFrame)
        return RenderResult::failure(RenderStatus::kWrongState, "drawBitmap called outside a frame");
    if (anchor == nullptr)
        return invalid("anchor pointer is NULL");
    if (image.width == 0 || image.height == 0)
        return RenderResult::success();
    if (image.bits == nullptr)
        return invalid("bitmap bits are NULL");
    if (image.rowBytes < image.width / 8 + (image.width % 8 != 0 ? 1 : 0))
        return invalid("bitmap rowBytes cannot hold its width");
    const float rgb[3] = {color.r, color.g, color.b};
    if (!allFinite(anchor, 3) || !allFinite(rgb, 3))
        return invalid("bitmap anchor or colour has a NaN or infinite value");

    ScreenPlacement at;
    if (!place(anchor, image.xOffset, image.yOffset, image.width, image.height, at))
        return RenderResult::success();
    std::vector<float> points;
    for (std::int64_t r = at.r0; r < at.r1; ++r) {
        const unsigned char* row = image.bits + std::size_t(r) * image.rowBytes;
        for (std::int64_t c = at.c0; c < at.c1; ++c) {
            const unsigned bit = unsigned(c % 8);
            const unsigned mask = image.lsbFirst ? (1u << bit) : (0x80u >> bit);
            if ((row[c / 8] & mask) != 0)
                pushPixel(at, c, r, points);
        }
    }
    return drawScreenPoints(points, nullptr, color);
}

RenderResult OffscreenRenderer::Impl::drawPixmap(const float* anchor, const PixmapImage& image)
{
    if (!m_inFrame)
        return RenderResult::failure(RenderStatus::kWrongState, "drawPixmap called outside a frame");
    if (anchor == nullptr)
        return invalid("anchor pointer is NULL");
    if (image.pixels == nullptr)
        return invalid("pixmap pixels are NULL");
    const RenderResult valid = validatePixmapLayout(image.layout);
    if (!valid)
        return valid;
    if (!allFinite(anchor, 3))
        return invalid("pixmap anchor has a NaN or infinite value");

    ScreenPlacement at;
    if (!place(anchor, image.xOffset, image.yOffset, image.layout.width, image.layout.height, at))
        return RenderResult::success();
    // Only the part inside the pane is decoded: at most the pane's pixels.
    // Channels go to OpenGL as fractions of their range, which it rounds to
    // the nearest 8-bit value.
    std::vector<float> points, colors;
    for (std::int64_t r = at.r0; r < at.r1; ++r)
        for (std::int64_t c = at.c0; c < at.c1; ++c) {
            const RgbaUnit p = unpackPixelUnit(
                image.layout.pixelType, pixmapWord(image.pixels, image.layout, std::uint32_t(c), std::uint32_t(r)));
            if (p.a == 0.0f)
                continue;
            pushPixel(at, c, r, points);
            colors.insert(colors.end(), {p.r, p.g, p.b});
        }
    return drawScreenPoints(points, &colors, RgbColor{});
}

void OffscreenRenderer::Impl::startFrameInGl()
{
    const std::int64_t imageWidth = m_width;
    const std::int64_t imageHeight = m_height;
    const PixelRect& pane = m_pane;
    // OpenGL window y runs upwards from the bottom row.
    glViewport(pane.x, GLint(imageHeight - (std::int64_t(pane.y) + pane.height)), pane.width, pane.height);

    const std::int64_t x0 = std::max<std::int64_t>(pane.x, 0);
    const std::int64_t y0 = std::max<std::int64_t>(pane.y, 0);
    const std::int64_t x1 = std::min<std::int64_t>(std::int64_t(pane.x) + pane.width, imageWidth);
    const std::int64_t y1 = std::min<std::int64_t>(std::int64_t(pane.y) + pane.height, imageHeight);
    const bool empty = x0 >= x1 || y0 >= y1;
    const bool coversImage = x0 == 0 && y0 == 0 && x1 == imageWidth && y1 == imageHeight;

    if (!coversImage) {
        glDisable(GL_SCISSOR_TEST);
        glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    // The scissor also keeps wide points near the pane's edge inside it.
    if (coversImage)
        glDisable(GL_SCISSOR_TEST);
    else
        glEnable(GL_SCISSOR_TEST);
    if (empty)
        glScissor(0, 0, 0, 0);
    else
        glScissor(GLint(x0), GLint(imageHeight - y1), GLsizei(x1 - x0), GLsizei(y1 - y0));
    glClearColor(m_clearColor.r, m_clearColor.g, m_clearColor.b, m_clearColor.a);
    if (m_options.depthTest) {
        glEnable(GL_DEPTH_TEST);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    } else {
        glDisable(GL_DEPTH_TEST);
        glClear(GL_COLOR_BUFFER_BIT);
    }
}

LitProgram* OffscreenRenderer::Impl::useLitProgram(int variant, const SurfaceShading& shading, bool* lightsLoaded,
                                                   RenderResult& result, float drawOpacity)
{
    LitProgram* program = litProgram(variant, result);
    if (program == nullptr)
        return nullptr;
    program->use();
    setTwoSided(variant);
    if (!lightsLoaded[variant]) {
        program->setLighting(m_lighting);
        lightsLoaded[variant] = true;
    }
    program->setShading(shading);
    program->finish().setDrawOpacity(drawOpacity);
    return program;
}

LitProgram* OffscreenRenderer::Impl::litProgram(int variant, RenderResult& result)
{
    std::unique_ptr<LitProgram>& made = m_gl->litPrograms[variant];
    if (made == nullptr) {
        try {
            made = std::make_unique<LitProgram>();
        } catch (const std::bad_alloc&) {
            result = outOfMemory();
            return nullptr;
        }
    }
    LitProgram& program = *made;
    if (!program.built()) {
        std::string error;
        if (!program.build(error, variant)) {
            result = RenderResult::failure(RenderStatus::kGraphicsError, error);
            return nullptr;
        }
    }
    return &program;
}

void OffscreenRenderer::Impl::uploadStream(StreamBuffer which, GLenum target, const void* data, std::size_t bytes)
{
    if (m_gl->streamBuffers[which] == 0)
        glGenBuffers(1, &m_gl->streamBuffers[which]);
    glBindBuffer(target, m_gl->streamBuffers[which]);
    // The store is kept and overwritten, and made anew only to grow (by
    // half again, so a frame that grows a little each time does not make
    // one each frame). A new store every flush (orphaning) made Mesa free
    // and allocate the batch's size each frame, and the C library gave the
    // memory back to the kernel and took it again: page faults and page
    // clearing were a sixth of the main thread's time
    // (benchmarks/RESULTS.md, ModelFrame). llvmpipe reads the vertices and
    // indices during the draw call, so nothing waits for the overwrite.
    std::size_t& capacity = m_gl->streamCapacity[which];
    if (bytes > capacity) {
        capacity = std::max(bytes, capacity + capacity / 2);
        glBufferData(target, GLsizeiptr(capacity), nullptr, GL_STREAM_DRAW);
    }
    if (bytes > 0)
        glBufferSubData(target, 0, GLsizeiptr(bytes), data);
}

bool OffscreenRenderer::Impl::StaticKey::operator==(const StaticKey& other) const
{
    // The floats by their bits: what was derived from them is the same
    // only for the same bits.
    return serial == other.serial && vertexCount == other.vertexCount && triangleCount == other.triangleCount &&
           flags == other.flags &&
           std::memcmp(stTransform, other.stTransform, sizeof stTransform) == 0 &&
           std::memcmp(color, other.color, sizeof color) == 0;
}

OffscreenRenderer::Impl::KeptMesh* OffscreenRenderer::Impl::findKept(const StaticKey& key)
{
    const auto found = m_gl->kept.find(key.serial);
    if (found == m_gl->kept.end())
        return nullptr;
    for (KeptMesh& mesh : found->second)
        if (mesh.key == key)
            return &mesh;
    return nullptr;
}

bool OffscreenRenderer::Impl::drawKept(const StaticKey& key, const SurfaceShading* shading, RenderResult& result)
{
    m_offer = false;
    if (!m_inFrame || m_gl == nullptr || key.serial == 0)
        return false;
    KeptMesh* kept = findKept(key);
    if (kept == nullptr) {
        // Seen once: kept if it is drawn again.
        std::vector<KeptMesh>& meshes = m_gl->kept[key.serial];
        meshes.push_back(KeptMesh{});
        meshes.back().key = key;
        meshes.back().lastFrame = m_gl->frameNumber;
        return false;
    }
    kept->lastFrame = m_gl->frameNumber;
    if (kept->state != KeptMesh::State::kStored) {
        m_offer = kept->state == KeptMesh::State::kSeen;
        m_offerKey = key;
        return false;
    }
    // A bad shading value takes the usual path, which reports it.
    if (shading != nullptr && !shadingFinite(*shading))
        return false;
    try {
        if (shading != nullptr)
            m_shadings.reserve(m_shadings.size() + 1);
        if (m_commands.size() == m_commands.capacity())
            m_commands.reserve(m_commands.empty() ? 256 : m_commands.size() * 2);
    } catch (const std::bad_alloc&) {
        result = outOfMemory();
        return true;
    }
    std::uint32_t shadingIndex = kUnlit;
    if (shading != nullptr) {
        m_shadings.push_back(*shading);
        shadingIndex = std::uint32_t(m_shadings.size() - 1);
    }
    const bool textured = (key.flags & kKeyTextured) != 0;
    DrawCommand command{Primitive::kTriangles, true, (key.flags & kKeySmooth) != 0, false, 1.0f, m_currentMatrix,
                        shadingIndex, textured ? m_currentTexture : kUntextured, m_faces, RgbColor{},
                        GLint(kept->firstIndex), kept->indexCount};
    command.multisample = m_antiAlias.triangles;
    command.fog = m_currentFog;
    command.minIndex = kept->firstVertex;
    command.maxIndex = kept->firstVertex + kept->vertexCount - 1;
    command.staticArrays = true;
    m_commands.push_back(command);
    ++m_keptDraws;
    result = RenderResult::success();
    return true;
}

const std::vector<std::uint32_t>* OffscreenRenderer::Impl::loopOf(const DrawRequest& r)
{
    const LoopOffer offer = m_loopOffer;
    m_loopOffer = LoopOffer{};
    if (offer.serial == 0 || !r.indexed || r.indices != offer.corners || r.vertexCount != offer.vertexCount ||
        r.indexCount != 3 * offer.triangleCount)
        return nullptr;
    // Only an optimization: out of memory, the draw is sorted, and what is
    // kept is a whole answer or none.
    try {
        const auto [at, made] = m_gl->loops.try_emplace(offer.serial);
        MeshLoop& mesh = at->second;
        if (made || mesh.vertexCount != offer.vertexCount || mesh.triangleCount != offer.triangleCount) {
            mesh.vertexCount = mesh.triangleCount = 0;
            mesh.loop.clear();
            std::vector<std::uint32_t> loop;
            boundaryLoop(offer.corners, offer.triangleCount, offer.vertexCount, loop);
            mesh.loop = std::move(loop);
            mesh.vertexCount = offer.vertexCount;
            mesh.triangleCount = offer.triangleCount;
        }
        mesh.lastFrame = m_gl->frameNumber;
        return mesh.loop.empty() ? nullptr : &mesh.loop;
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}

void OffscreenRenderer::Impl::storePendingKept()
{
    GlResources& gl = *m_gl;
    for (const PendingKept& pending : m_pendingKept) {
        KeptMesh* kept = findKept(pending.key);
        if (kept == nullptr || kept->state != KeptMesh::State::kPending)
            continue;
        kept->state = KeptMesh::State::kSeen;
        const std::size_t* limits = m_keptLimits;
        if (gl.keptCapacity[0] == 0) {
            gl.keptCapacity[0] = std::min(kKeptInitialVertices, limits[0]);
            gl.keptCapacity[1] = std::min(kKeptInitialIndices, limits[1]);
        }
        const std::size_t counts[2] = {pending.vertexCount, std::size_t(pending.indexCount)};
        bool fits = true;
        bool couldFit = true;
        bool grows = false; // the buffers may still grow
        bool room = true;   // emptying them would make room for it
        for (int k = 0; k < 2; ++k) {
            fits = fits && gl.keptUsed[k] + counts[k] <= gl.keptCapacity[k];
            couldFit = couldFit && counts[k] <= limits[k];
            grows = grows || gl.keptCapacity[k] < limits[k];
            room = room && gl.keptLive[k] + gl.keptDemand[k] + counts[k] <= gl.keptCapacity[k];
        }
        if (!fits) {
            // Emptied (and grown, up to the limits) at the next frame's
            // start, unless it can never fit, or the buffers are as large as
            // they get and what the stored meshes still use leaves no room
            // (forgotten meshes leave space behind that only emptying
            // reclaims): the mesh is then drawn from the batch each frame.
            if (couldFit && (grows || room)) {
                gl.keptFull = true;
                gl.keptDemand[0] += counts[0];
                gl.keptDemand[1] += counts[1];
            }
            continue;
        }
        if (gl.keptBuffers[0] == 0)
            glGenBuffers(2, gl.keptBuffers);
        if (gl.keptAllocated[0] != gl.keptCapacity[0]) {
            // Only ever when they are empty (trimKept).
            glBindBuffer(GL_ARRAY_BUFFER, gl.keptBuffers[0]);
            glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(gl.keptCapacity[0] * sizeof(Vertex)), nullptr, GL_STATIC_DRAW);
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gl.keptBuffers[1]);
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(gl.keptCapacity[1] * sizeof(GLuint)), nullptr,
                         GL_STATIC_DRAW);
            gl.keptAllocated[0] = gl.keptCapacity[0];
            gl.keptAllocated[1] = gl.keptCapacity[1];
        }
        const GLuint firstVertex = GLuint(gl.keptUsed[0]);
        glBindBuffer(GL_ARRAY_BUFFER, gl.keptBuffers[0]);
        glBufferSubData(GL_ARRAY_BUFFER, GLintptr(firstVertex * sizeof(Vertex)),
                        GLsizeiptr(pending.vertexCount * sizeof(Vertex)), m_vertices.get() + pending.streamFirstVertex);
        // The batch's indices count from the batch's first vertex.
        m_keptIndices.resize(std::size_t(pending.indexCount));
        const GLuint* in = m_indices.data() + pending.streamFirstIndex;
        for (std::size_t i = 0; i < m_keptIndices.size(); ++i)
            m_keptIndices[i] = in[i] - pending.streamFirstVertex + firstVertex;
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gl.keptBuffers[1]);
        glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, GLintptr(gl.keptUsed[1] * sizeof(GLuint)),
                        GLsizeiptr(m_keptIndices.size() * sizeof(GLuint)), m_keptIndices.data());
        kept->firstVertex = firstVertex;
        kept->vertexCount = pending.vertexCount;
        kept->firstIndex = GLuint(gl.keptUsed[1]);
        kept->indexCount = pending.indexCount;
        kept->state = KeptMesh::State::kStored;
        for (int k = 0; k < 2; ++k) {
            gl.keptUsed[k] += counts[k];
            gl.keptLive[k] += counts[k];
        }
    }
    m_pendingKept.clear();
}

void OffscreenRenderer::Impl::trimKept()
{
    GlResources& gl = *m_gl;
    if (gl.frameNumber % kStaleFrames == 0)
        for (auto it = gl.loops.begin(); it != gl.loops.end();)
            it = gl.frameNumber - it->second.lastFrame > kStaleFrames ? gl.loops.erase(it) : std::next(it);
    if (gl.keptFull) {
        // Emptied and grown to hold what was kept and what did not fit (at
        // least twice as much); the meshes it held are kept again the next
        // time they are drawn.
        for (int k = 0; k < 2; ++k) {
            gl.keptCapacity[k] =
                std::min(m_keptLimits[k], std::max(2 * gl.keptCapacity[k], gl.keptUsed[k] + gl.keptDemand[k]));
            gl.keptUsed[k] = 0;
            gl.keptDemand[k] = 0;
            gl.keptLive[k] = 0;
        }
        for (auto& [serial, meshes] : gl.kept)
            for (KeptMesh& mesh : meshes)
                mesh.state = KeptMesh::State::kSeen;
        gl.keptFull = false;
        return;
    }
    if (gl.frameNumber % kStaleFrames != 0)
        return;
    // Meshes no frame drew for kStaleFrames frames (their room is used
    // again after the next emptying, which a mesh that does not fit asks
    // for).
    for (auto it = gl.kept.begin(); it != gl.kept.end();) {
        std::vector<KeptMesh>& meshes = it->second;
        const auto stale = [&](const KeptMesh& mesh) {
            if (gl.frameNumber - mesh.lastFrame <= kStaleFrames)
                return false;
            if (mesh.state == KeptMesh::State::kStored) {
                gl.keptLive[0] -= mesh.vertexCount;
                gl.keptLive[1] -= std::size_t(mesh.indexCount);
            }
            return true;
        };
        meshes.erase(std::remove_if(meshes.begin(), meshes.end(), stale), meshes.end());
        it = meshes.empty() ? gl.kept.erase(it) : std::next(it);
    }
}

namespace {

// A byte offset into the bound buffer object, as gl*Pointer and
// glDrawElements take it.
const void* bufferOffset(std::size_t bytes)
{
    return reinterpret_cast<const void*>(bytes);
}

} // namespace

RenderResult OffscreenRenderer::Impl::flush(bool finish)
{
    RenderResult result;
    {
        ContextScope scope(*m_gl->context, m_frameImage, m_frameRowPixels);
        if (!scope.bound()) {
            resetBatch();
            return RenderResult::failure(RenderStatus::kContextFailure,
                                         renderingShutDown() ? detail::kShutDownMessage
                                                             : "making the OpenGL context current failed");
        }
        bindFrameFramebuffer();
        if (!m_clearedInGl) {
            startFrameInGl();
            m_clearedInGl = true;
        }
        if (!m_staleTextureNames.empty()) {
            glDeleteTextures(GLsizei(m_staleTextureNames.size()), m_staleTextureNames.data());
            m_staleTextureNames.clear();
        }
        if (!m_commands.empty() && result) {
            // Which arrays are bound: -1 none yet, 0 m_vertices, 1 m_positions.
            int loadedArrays = -1;
            RgbColor loadedColor;
            std::uint32_t loadedMatrix = std::numeric_limits<std::uint32_t>::max();
            float loadedPointSize = -1.0f;
            int loadedShading = -1;
            std::uint32_t loadedSurface = kUnlit;
            bool lightsLoaded[LitProgram::kVariants] = {};
            int loadedVariant = -1;
            std::uint32_t loadedTexture = kUntextured;
            FaceOptions loadedFaces;
            FogLoad fogLoad;
            std::fill(std::begin(fogLoad.fog), std::end(fogLoad.fog), kFogUnknown);
            bool loadedAlphaTest = false;
            glDisable(GL_CULL_FACE);
            glFrontFace(GL_CCW);
            if (m_vertexCount != 0)
                uploadStream(kStreamVertices, GL_ARRAY_BUFFER, m_vertices.get(), m_vertexCount * sizeof(Vertex));
            if (m_positionCount != 0)
                uploadStream(kStreamPositions, GL_ARRAY_BUFFER, m_positions.get(),
                             m_positionCount * sizeof(Position));
            if (!m_indices.empty())
                uploadStream(kStreamIndices, GL_ELEMENT_ARRAY_BUFFER, m_indices.data(),
                             m_indices.size() * sizeof(GLuint));
            storePendingKept();
            const std::size_t commandCount = m_commands.size();
            std::size_t i = 0;
            while (i < commandCount) {
                const DrawCommand& head = m_commands[i];
                std::size_t end = i + 1;
                while (end < commandCount && m_commands[end].drawsLike(head))
                    ++end;
                if (head.multisample != m_multisampling) {
                    std::string error;
                    if (!useMultisample(head.multisample, error)) {
                        result = RenderResult::failure(RenderStatus::kGraphicsError, error);
                        break;
                    }
                    // The switch used a program of its own and texture unit 0.
                    loadedVariant = -2;
                    loadedTexture = kUntextured - 1;
                    fogLoad.unlit = -1;
                }
                const int arrays = head.plain ? 1 : head.staticArrays ? 2 : 0;
                if (arrays != loadedArrays) {
                    if (head.plain) {
                        glDisableClientState(GL_COLOR_ARRAY);
                        glDisableClientState(GL_NORMAL_ARRAY);
                        glBindBuffer(GL_ARRAY_BUFFER, m_gl->streamBuffers[kStreamPositions]);
                        glVertexPointer(3, GL_FLOAT, sizeof(Position), bufferOffset(offsetof(Position, x)));
                    } else {
                        glEnableClientState(GL_COLOR_ARRAY);
                        glEnableClientState(GL_NORMAL_ARRAY);
                        glBindBuffer(GL_ARRAY_BUFFER,
                                     head.staticArrays ? m_gl->keptBuffers[0] : m_gl->streamBuffers[kStreamVertices]);
                        glVertexPointer(3, GL_FLOAT, sizeof(Vertex), bufferOffset(offsetof(Vertex, x)));
                        glColorPointer(3, GL_FLOAT, sizeof(Vertex), bufferOffset(offsetof(Vertex, r)));
                        glNormalPointer(GL_FLOAT, sizeof(Vertex), bufferOffset(offsetof(Vertex, nx)));
                        glTexCoordPointer(2, GL_FLOAT, sizeof(Vertex), bufferOffset(offsetof(Vertex, s)));
                    }
                    // The kept meshes' indices are in a buffer of their own.
                    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER,
                                 head.staticArrays ? m_gl->keptBuffers[1] : m_gl->streamBuffers[kStreamIndices]);
                    loadedArrays = arrays;
                    // The current colour is undefined after drawing with a
                    // colour array: set it again.
                    if (head.plain)
                        glColor3f(head.color.r, head.color.g, head.color.b);
                    loadedColor = head.color;
                } else if (head.plain && (head.color.r != loadedColor.r || head.color.g != loadedColor.g ||
                                          head.color.b != loadedColor.b)) {
                    glColor3f(head.color.r, head.color.g, head.color.b);
                    loadedColor = head.color;
                }
                if (head.matrixIndex != loadedMatrix) {
                    glLoadMatrixf(m_matrices[head.matrixIndex].data());
                    loadedMatrix = head.matrixIndex;
                }
                if (head.primitive == Primitive::kPoints && head.pointSize != loadedPointSize) {
                    glPointSize(head.pointSize);
                    loadedPointSize = head.pointSize;
                }
                if (int(head.smooth) != loadedShading) {
                    glShadeModel(head.smooth ? GL_SMOOTH : GL_FLAT);
                    loadedShading = int(head.smooth);
                }
                if (!(head.faces == loadedFaces)) {
                    if (head.faces.cullBack)
                        glEnable(GL_CULL_FACE);
                    else
                        glDisable(GL_CULL_FACE);
                    glFrontFace(head.faces.clockwiseFront ? GL_CW : GL_CCW);
                    loadedFaces = head.faces;
                }
                if (head.texture != loadedTexture) {
                    if (head.texture == kUntextured) {
                        glDisable(GL_TEXTURE_2D);
                        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
                    } else {
                        // (Its coordinates' pointer is set with the arrays: a
                        // textured command is never plain.)
                        bindTexture(head.texture);
                        glEnable(GL_TEXTURE_2D);
                        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
                    }
                    loadedTexture = head.texture;
                }
                loadOpaqueAlphaTest(head.texture, loadedAlphaTest);
                const bool texturedProgram = head.texture != kUntextured;
                const int variant = head.shading == kUnlit ? -1
                                                           : LitProgram::variant(texturedProgram, m_shadings[head.shading],
                                                                                 head.fog != kNoFog, m_lighting, true);
                if (head.shading != loadedSurface || variant != loadedVariant) {
                    if (head.shading == kUnlit) {
                        glUseProgram(0);
                    } else {
                        if (useLitProgram(variant, m_shadings[head.shading], lightsLoaded, result) == nullptr)
                            break;
                    }
                    loadedVariant = variant;
                    loadedSurface = head.shading;
                }
                if (!loadFog(head, variant, fogLoad, result))
                    break;
                if (end - i == 1) {
                    if (head.indexed)
                        glDrawRangeElements(glMode(head.primitive), head.minIndex, head.maxIndex, head.count,
                                            GL_UNSIGNED_INT, bufferOffset(sizeof(GLuint) * std::size_t(head.first)));
                    else
                        glDrawArrays(glMode(head.primitive), head.first, head.count);
                } else {
                    m_multiFirsts.clear();
                    m_multiCounts.clear();
                    m_multiIndices.clear();
                    for (std::size_t k = i; k < end; ++k) {
                        m_multiFirsts.push_back(m_commands[k].first);
                        m_multiCounts.push_back(m_commands[k].count);
                        if (head.indexed)
                            m_multiIndices.push_back(bufferOffset(sizeof(GLuint) * std::size_t(m_commands[k].first)));
                    }
                    if (head.indexed)
                        glMultiDrawElements(glMode(head.primitive), m_multiCounts.data(), GL_UNSIGNED_INT,
                                            m_multiIndices.data(), GLsizei(end - i));
                    else
                        glMultiDrawArrays(glMode(head.primitive), m_multiFirsts.data(), m_multiCounts.data(),
                                          GLsizei(end - i));
                }
                i = end;
            }
            glDisable(GL_ALPHA_TEST);
            glBindBuffer(GL_ARRAY_BUFFER, 0);
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
        }
        if (finish && result)
            drawTranslucent(result);
        glUseProgram(0);
        glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
        glDisable(GL_TEXTURE_2D);
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        glBindTexture(GL_TEXTURE_2D, 0);
        if (finish && !m_textureNames.empty()) {
            glDeleteTextures(GLsizei(m_textureNames.size()), m_textureNames.data());
            m_textureNames.clear();
        }
        if (finish)
            evictTextures(Evict::kUnused);
        glDisable(GL_CULL_FACE);
        glFrontFace(GL_CCW);
        glEnableClientState(GL_COLOR_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        glDisable(GL_MULTISAMPLE);
        if (finish && m_multisampling)
            resolveMultisample();
        // The finished image into m_frameImage.
        if (finish)
            m_gl->context->finish(m_frameImage);
        const GLenum error = takeGlError();
        if (error != GL_NO_ERROR && result)
            result = RenderResult::failure(RenderStatus::kGraphicsError,
                                           std::string("OpenGL reported ") + glErrorName(error));
    }
    resetBatch();
    if (finish && result)
        detail::watchProcessExit(detail::ExitWatch::kFirstFrame);
    return result;
}

void OffscreenRenderer::Impl::bindTexture(std::uint32_t index)
{
    const BatchTexture& texture = m_textures[index];
    if (texture.cacheSlot != kNotCached) {
        CachedTexture& cached = m_gl->textureCache[texture.cacheSlot];
        if (cached.name != 0) {
            glBindTexture(GL_TEXTURE_2D, cached.name);
            return;
        }
        glGenTextures(1, &cached.name);
        glBindTexture(GL_TEXTURE_2D, cached.name);
        uploadTexture(texture);
        return;
    }
    if (m_textureNames.size() < m_textures.size())
        m_textureNames.resize(m_textures.size(), 0);
    GLuint& name = m_textureNames[index];
    if (name != 0) {
        glBindTexture(GL_TEXTURE_2D, name);
        return;
    }
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    uploadTexture(m_textures[index]);
}

// The filters are OpenGL's own (RenderTarget.h gives their formulas):
// llvmpipe computes the weights in fixed point (8 bits of fraction), which
// is reproducible run after run and which the tests allow for. Only the
// trilinear filter uploads the mipmaps; the others read the first image, so
// GL_TEXTURE_MAX_LEVEL is 0 for them (a texture is then complete with one
// image).
//
// A texture whose every texel drawn is opaque is stored without alpha
// (GL_RGB8): sampled, its alpha is 1 as before, and llvmpipe's fragment code
// then reads no alpha from it and multiplies by none (a sixtieth of the
// opaque fragments' instructions on the ModelFrame model, benchmarks/
// RESULTS.md, ninth round).
namespace {

// Whether every texel of an RGBA8 image has alpha 255.
bool allOpaque(const std::vector<std::uint8_t>& rgba)
{
    for (std::size_t i = 3; i < rgba.size(); i += 4)
        if (rgba[i] != 255)
            return false;
    return true;
}

} // namespace

void OffscreenRenderer::Impl::uploadTexture(const BatchTexture& texture)
{
    const bool mipmapped = texture.filter == TextureFilter::kTrilinear && !texture.mipmaps.empty();
    bool opaque = !texture.hasAlpha;
    for (std::size_t i = 0; mipmapped && opaque && i < texture.mipmaps.size(); ++i)
        opaque = allOpaque(texture.mipmaps[i]);
    const GLint stored = opaque ? GL_RGB8 : GL_RGBA8;
    const GLint magnify = texture.filter == TextureFilter::kNearest ? GL_NEAREST : GL_LINEAR;
    const GLint minify = mipmapped ? GL_LINEAR_MIPMAP_LINEAR : magnify;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, minify);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, magnify);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, texture.clampS ? GL_CLAMP_TO_EDGE : GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, texture.clampT ? GL_CLAMP_TO_EDGE : GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, mipmapped ? GLint(texture.mipmaps.size()) : 0);
    glTexImage2D(GL_TEXTURE_2D, 0, stored, GLsizei(texture.width), GLsizei(texture.height), 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, texture.rgba.data());
    if (!mipmapped)
        return;
    for (std::size_t i = 0; i < texture.mipmaps.size(); ++i) {
        const unsigned shift = unsigned(i + 1);
        glTexImage2D(GL_TEXTURE_2D, GLint(shift), stored, GLsizei(std::max(1u, texture.width >> shift)),
                     GLsizei(std::max(1u, texture.height >> shift)), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     texture.mipmaps[i].data());
    }
}

RenderResult OffscreenRenderer::Impl::decodeMipmaps(const TextureImage& texture, BatchTexture& decoded)
{
    const long filter = enumValue(texture.filter);
    if (filter < long(TextureFilter::kNearest) || filter > long(TextureFilter::kTrilinear))
        return invalid("texture filter " + std::to_string(filter) + " is not a TextureFilter");
    decoded.filter = texture.filter;
    if (texture.mipmaps.empty())
        return RenderResult::success();
    std::uint32_t width = decoded.width, height = decoded.height;
    for (std::size_t i = 0; i < texture.mipmaps.size(); ++i) {
        const TextureLevel& level = texture.mipmaps[i];
        const std::string name = "mipmap " + std::to_string(i + 1);
        if (width == 1 && height == 1)
            return invalid(name + " follows a 1 x 1 image");
        width = std::max(1u, width / 2);
        height = std::max(1u, height / 2);
        if (level.pixels == nullptr)
            return invalid(name + "'s pixels are NULL");
        const RenderResult valid = validatePixmapLayout(level.layout);
        if (!valid)
            return invalid(name + ": " + valid.message);
        if (level.layout.width != width || level.layout.height != height)
            return invalid(name + " is " + std::to_string(level.layout.width) + " x " +
                           std::to_string(level.layout.height) + ", not " + std::to_string(width) + " x " +
                           std::to_string(height));
    }
    if (width != 1 || height != 1)
        return invalid("the mipmap chain stops before a 1 x 1 image");
    // Only the trilinear filter reads them.
    if (texture.filter != TextureFilter::kTrilinear)
        return RenderResult::success();
    decoded.mipmaps.resize(texture.mipmaps.size());
    for (std::size_t i = 0; i < texture.mipmaps.size(); ++i) {
        const TextureLevel& level = texture.mipmaps[i];
        decoded.mipmaps[i].resize(std::size_t(level.layout.width) * level.layout.height * 4);
        const PixelRect all{0, 0, int(level.layout.width), int(level.layout.height)};
        const RenderResult read = readPixmapToRgba8(level.pixels, level.layout, all, decoded.mipmaps[i].data(),
                                                    std::size_t(level.layout.width) * 4);
        if (!read)
            return read;
    }
    return RenderResult::success();
}

std::uint32_t OffscreenRenderer::Impl::findCachedTexture(const TextureImage& texture) const
{
    // The caller's enumerations are not validated yet (a mipmap's layout,
    // the filter): read as numbers (core/EnumValue.h).
    const auto sameLayout = [](const PixmapLayout& known, const PixmapLayout& given) {
        return known.width == given.width && known.height == given.height && known.rowBytes == given.rowBytes &&
               long(known.pixelType) == enumValue(given.pixelType) && long(known.byteOrder) == enumValue(given.byteOrder);
    };
    for (std::size_t slot = 0; slot < m_gl->textureCache.size(); ++slot) {
        const CachedTexture& cached = m_gl->textureCache[slot];
        if (cached.clampS != texture.clampS || cached.clampT != texture.clampT ||
            long(cached.filter) != enumValue(texture.filter) ||
            cached.layouts.size() != texture.mipmaps.size() + 1 || !sameLayout(cached.layouts[0], texture.layout))
            continue;
        bool same = true;
        for (std::size_t i = 0; same && i < texture.mipmaps.size(); ++i)
            same = texture.mipmaps[i].pixels != nullptr && sameLayout(cached.layouts[i + 1], texture.mipmaps[i].layout);
        if (same && !texture.sourceKey.empty() && texture.sourceKey == cached.sourceKey)
            return std::uint32_t(slot); // the same bytes, by their source
        std::size_t at = 0;
        for (std::size_t i = 0; same && i < cached.layouts.size(); ++i) {
            const PixmapLayout& layout = cached.layouts[i];
            const std::size_t bytes = std::size_t(layout.rowBytes) * (layout.height - 1) +
                                      std::size_t(layout.width) * bytesPerPixel(layout.pixelType);
            const void* pixels = i == 0 ? texture.pixels : texture.mipmaps[i - 1].pixels;
            same = std::memcmp(cached.source.data() + at, pixels, bytes) == 0;
            at += bytes;
        }
        if (same)
            return std::uint32_t(slot);
    }
    return kNotCached;
}

void OffscreenRenderer::Impl::evictTextures(Evict which)
{
    std::vector<GLuint> names;
    std::size_t kept = 0;
    const std::uint64_t now = m_gl->frameNumber;
    for (std::size_t slot = 0; slot < m_gl->textureCache.size(); ++slot) {
        CachedTexture& cached = m_gl->textureCache[slot];
        const bool evicted = which == Evict::kMine
                                 ? cached.user == this
                                 : (cached.user == this && cached.lastFrame != now) || now - cached.lastFrame > kStaleFrames;
        if (evicted) {
            if (cached.name != 0)
                names.push_back(cached.name);
            m_gl->textureCacheBytes -= cached.source.size();
            continue;
        }
        if (kept != slot)
            m_gl->textureCache[kept] = std::move(cached);
        ++kept;
    }
    m_gl->textureCache.resize(kept);
    if (!names.empty())
        glDeleteTextures(GLsizei(names.size()), names.data());
}

RenderResult OffscreenRenderer::Impl::addTexture(const TextureImage& texture, std::uint32_t& id)
{
    if (!m_inFrame)
        return RenderResult::failure(RenderStatus::kWrongState, "a texture added outside a frame");
    if (texture.pixels == nullptr)
        return invalid("texture pixels are NULL");
    const RenderResult valid = validatePixmapLayout(texture.layout);
    if (!valid)
        return valid;
    if (texture.layout.width > kMaxImageSize || texture.layout.height > kMaxImageSize)
        return invalid("texture is larger than " + std::to_string(kMaxImageSize) + " pixels");
    if (m_textures.size() == kUntextured)
        return invalid("too many textures in one frame");
    const std::uint32_t slot = findCachedTexture(texture);
    if (slot != kNotCached && m_gl->textureCache[slot].name != 0) {
        // Uploaded already: only what drawing asks of it.
        CachedTexture& cached = m_gl->textureCache[slot];
        cached.lastFrame = m_gl->frameNumber;
        cached.user = this;
        cached.sourceKey = texture.sourceKey; // (found by its bytes, it is known by this key now)
        BatchTexture known;
        known.width = texture.layout.width;
        known.height = texture.layout.height;
        known.clampS = cached.clampS;
        known.clampT = cached.clampT;
        known.filter = cached.filter;
        known.hasAlpha = cached.hasAlpha;
        known.cacheSlot = slot;
        m_textures.push_back(std::move(known));
        id = std::uint32_t(m_textures.size() - 1);
        return RenderResult::success();
    }
    BatchTexture decoded;
    decoded.width = texture.layout.width;
    decoded.height = texture.layout.height;
    decoded.clampS = texture.clampS;
    decoded.clampT = texture.clampT;
    decoded.rgba.resize(std::size_t(decoded.width) * decoded.height * 4);
    const PixelRect all{0, 0, int(decoded.width), int(decoded.height)};
    const RenderResult read = readPixmapToRgba8(texture.pixels, texture.layout, all, decoded.rgba.data(),
                                                std::size_t(decoded.width) * 4);
    if (!read)
        return read;
    const RenderResult mipmaps = decodeMipmaps(texture, decoded);
    if (!mipmaps)
        return mipmaps;
    decoded.hasAlpha = !allOpaque(decoded.rgba);
    if (slot != kNotCached) {
        m_gl->textureCache[slot].lastFrame = m_gl->frameNumber;
        m_gl->textureCache[slot].user = this;
        m_gl->textureCache[slot].sourceKey = texture.sourceKey;
        decoded.cacheSlot = slot;
    } else {
        // Kept for the frames after this one (uploaded when first drawn).
        CachedTexture cached;
        const auto keep = [&cached](const void* pixels, const PixmapLayout& layout) {
            const std::size_t bytes = std::size_t(layout.rowBytes) * (layout.height - 1) +
                                      std::size_t(layout.width) * bytesPerPixel(layout.pixelType);
            const std::uint8_t* from = static_cast<const std::uint8_t*>(pixels);
            cached.source.insert(cached.source.end(), from, from + bytes);
            cached.layouts.push_back(layout);
        };
        keep(texture.pixels, texture.layout);
        for (const TextureLevel& level : texture.mipmaps)
            keep(level.pixels, level.layout);
        if (m_gl->textureCacheBytes + cached.source.size() <= kTextureCacheBytes) {
            cached.clampS = texture.clampS;
            cached.clampT = texture.clampT;
            cached.filter = texture.filter;
            cached.sourceKey = texture.sourceKey;
            cached.hasAlpha = decoded.hasAlpha;
            cached.lastFrame = m_gl->frameNumber;
            cached.user = this;
            m_gl->textureCacheBytes += cached.source.size();
            m_gl->textureCache.push_back(std::move(cached));
            decoded.cacheSlot = std::uint32_t(m_gl->textureCache.size() - 1);
        }
    }
    m_textures.push_back(std::move(decoded));
    id = std::uint32_t(m_textures.size() - 1);
    return RenderResult::success();
}

RenderResult OffscreenRenderer::Impl::useTexture(std::uint32_t id)
{
    if (!m_inFrame)
        return RenderResult::failure(RenderStatus::kWrongState, "a texture chosen outside a frame");
    if (id != kUntextured && id >= m_textures.size())
        return invalid("texture " + std::to_string(id) + " was not added in this frame");
    m_currentTexture = id;
    return RenderResult::success();
}

void OffscreenRenderer::Impl::forgetTextures()
{
    m_staleTextureNames.insert(m_staleTextureNames.end(), m_textureNames.begin(), m_textureNames.end());
    m_textureNames.clear();
    m_textures.clear();
    m_currentTexture = kUntextured;
}

void OffscreenRenderer::Impl::resetBatch()
{
    m_vertexCount = 0;
    m_positionCount = 0;
    m_indices.clear();
    m_commands.clear();
    m_shadings.clear();
    // Pending meshes a flush did not store go back to being seen.
    for (const PendingKept& pending : m_pendingKept) {
        KeptMesh* kept = m_gl != nullptr ? findKept(pending.key) : nullptr;
        if (kept != nullptr && kept->state == KeptMesh::State::kPending)
            kept->state = KeptMesh::State::kSeen;
    }
    m_pendingKept.clear();
    m_offer = false;
    if (!m_matrices.empty()) {
        m_matrices[0] = m_matrices[m_currentMatrix];
        m_matrices.resize(1);
    }
    m_currentMatrix = 0;
}

RenderResult OffscreenRenderer::Impl::endFrame()
{
    if (!m_inFrame)
        return RenderResult::failure(RenderStatus::kWrongState, "endFrame called outside a frame");
    m_inFrame = false;
    const RenderResult result = flush(true);
    forgetTextures();
    forgetTranslucent();
    lendContext();
    m_drewInPlace = result && m_direct;
    return result;
}

RenderResult OffscreenRenderer::Impl::setLighting(const LightingSetup& lighting)
{
    if (!m_inFrame)
        return RenderResult::failure(RenderStatus::kWrongState, "setLighting called outside a frame");
    if (lighting.lights.size() > kMaxLights)
        return invalid("more than " + std::to_string(kMaxLights) + " lights");
    for (const RenderLight& light : lighting.lights) {
        const float values[11] = {light.color[0],     light.color[1],     light.color[2],    light.position[0],
                                  light.position[1],  light.position[2],  light.direction[0], light.direction[1],
                                  light.direction[2], light.hotAngle,     light.outerAngle};
        if (!allFinite(values, 11))
            return invalid("a light has a NaN or infinite value");
    }
    if (!allFinite(lighting.eye, 3) || !allFinite(lighting.viewDirection, 3))
        return invalid("the eye has a NaN or infinite value");
    // Draws already batched were made under the old lights.
    if (!m_commands.empty()) {
        RenderResult flushed = flush(false);
        if (!flushed)
            return flushed;
    }
    m_lighting = lighting;
    return RenderResult::success();
}

RenderResult OffscreenRenderer::Impl::setFaceOptions(const FaceOptions& faces)
{
    if (!m_inFrame)
        return RenderResult::failure(RenderStatus::kWrongState, "setFaceOptions called outside a frame");
    m_faces = faces;
    return RenderResult::success();
}

RenderResult OffscreenRenderer::Impl::setAntiAlias(const AntiAliasOptions& options)
{
    if (!m_inFrame)
        return RenderResult::failure(RenderStatus::kWrongState, "setAntiAlias called outside a frame");
    m_antiAlias = options;
    return RenderResult::success();
}

namespace {

// Copies the window-system image (colour and depth, bound as textures 0 and
// 1) into the multisample framebuffer, texel (x, y) to pixel (x, y), every
// sample of a pixel alike (a quad over the whole image covers every sample).
const char* const kCopyVertexShader = R"(#version 130
void main() { gl_Position = gl_Vertex; }
)";
const char* const kCopyFragmentShader = R"(#version 130
uniform sampler2D colour;
uniform sampler2D depth;
void main()
{
    ivec2 texel = ivec2(gl_FragCoord.xy);
    gl_FragColor = texelFetch(colour, texel, 0);
    gl_FragDepth = texelFetch(depth, texel, 0).r;
}
)";

GLuint compileCopyProgram(std::string& error)
{
    const char* sources[2] = {kCopyVertexShader, kCopyFragmentShader};
    const GLenum kinds[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
    const GLuint program = glCreateProgram();
    for (int i = 0; i < 2; ++i) {
        const GLuint shader = glCreateShader(kinds[i]);
        glShaderSource(shader, 1, &sources[i], nullptr);
        glCompileShader(shader);
        GLint ok = GL_FALSE;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (ok != GL_TRUE) {
            char log[512] = {0};
            glGetShaderInfoLog(shader, sizeof log, nullptr, log);
            error = std::string("the anti-aliasing copy shader does not compile: ") + log;
            glDeleteShader(shader);
            glDeleteProgram(program);
            return 0;
        }
        glAttachShader(program, shader);
        glDeleteShader(shader);
    }
    glLinkProgram(program);
    GLint linked = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE) {
        error = "the anti-aliasing copy program does not link";
        glDeleteProgram(program);
        return 0;
    }
    glUseProgram(program);
    glUniform1i(glGetUniformLocation(program, "colour"), 0);
    glUniform1i(glGetUniformLocation(program, "depth"), 1);
    glUseProgram(0);
    return program;
}

} // namespace

// Only the commands drawn under an anti-alias style are multisampled; the
// image (the window-system framebuffer) holds the frame everywhere else.
// A run of anti-aliased commands is drawn into the multisample framebuffer,
// into which the image, colour and depth, is first copied (every sample of
// a pixel alike); when a command that is not anti-aliased follows, the
// samples are resolved back into the image: colour as the mean of a
// pixel's samples, depth as one sample's (glBlitFramebuffer's rule for
// depth), so that later primitives are hidden by the smoothed ones. The
// aliased commands are thus drawn exactly as in a frame without
// anti-aliasing. (They cannot be drawn into the multisample framebuffer with
// GL_MULTISAMPLE off: llvmpipe, Mesa 22.3, measured, then writes a
// fragment's colour to all of a pixel's samples but its depth to one only,
// so such a primitive would not hide what is drawn behind it later.)
void OffscreenRenderer::Impl::bindFrameFramebuffer()
{
    if (!m_multisampling) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, m_gl->msFramebuffer);
    glEnable(GL_MULTISAMPLE);
}

bool OffscreenRenderer::Impl::useMultisample(bool on, std::string& error)
{
    if (on == m_multisampling)
        return true;
    const GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
    if (!on) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, m_gl->msFramebuffer);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glDisable(GL_SCISSOR_TEST);
        glBlitFramebuffer(0, 0, GLint(m_width), GLint(m_height), 0, 0, GLint(m_width), GLint(m_height),
                          GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBlitFramebuffer(0, 0, GLint(m_width), GLint(m_height), 0, 0, GLint(m_width), GLint(m_height),
                          GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (scissor)
            glEnable(GL_SCISSOR_TEST);
        glDisable(GL_MULTISAMPLE);
        m_multisampling = false;
        return true;
    }
    // Made once per context, which has one size.
    if (m_gl->msFramebuffer == 0) {
        glGenFramebuffers(1, &m_gl->msFramebuffer);
        glGenRenderbuffers(1, &m_gl->msColor);
        glGenRenderbuffers(1, &m_gl->msDepth);
        glBindRenderbuffer(GL_RENDERBUFFER, m_gl->msColor);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, kAntiAliasSamples, GL_RGBA8, GLsizei(m_width),
                                         GLsizei(m_height));
        glBindRenderbuffer(GL_RENDERBUFFER, m_gl->msDepth);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, kAntiAliasSamples, GL_DEPTH_COMPONENT24,
                                         GLsizei(m_width), GLsizei(m_height));
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, m_gl->msFramebuffer);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_gl->msColor);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m_gl->msDepth);
        const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            error = "the multisample framebuffer for anti-aliasing is incomplete";
            return false;
        }
    }
    if (m_gl->copyProgram == 0) {
        m_gl->copyProgram = compileCopyProgram(error);
        if (m_gl->copyProgram == 0)
            return false;
    }

    // The image as it is, colour and depth, into two textures.
    GLuint copies[2] = {0, 0};
    glGenTextures(2, copies);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, copies[1]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 0, 0, GLsizei(m_width), GLsizei(m_height), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, copies[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, GLsizei(m_width), GLsizei(m_height), 0);

    // Drawn over the whole multisample image, every sample written, with
    // whatever the caller's run had set that would drop or blend a
    // fragment of the copy put aside.
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    const GLboolean depthTest = glIsEnabled(GL_DEPTH_TEST);
    const GLboolean alphaTest = glIsEnabled(GL_ALPHA_TEST);
    const GLboolean blend = glIsEnabled(GL_BLEND);
    const GLboolean cull = glIsEnabled(GL_CULL_FACE);
    GLint depthMask = GL_TRUE;
    glGetIntegerv(GL_DEPTH_WRITEMASK, &depthMask);
    glBindFramebuffer(GL_FRAMEBUFFER, m_gl->msFramebuffer);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glEnable(GL_MULTISAMPLE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glViewport(0, 0, GLsizei(m_width), GLsizei(m_height));
    glUseProgram(m_gl->copyProgram);
    glBegin(GL_TRIANGLE_STRIP);
    glVertex2f(-1.0f, -1.0f);
    glVertex2f(1.0f, -1.0f);
    glVertex2f(-1.0f, 1.0f);
    glVertex2f(1.0f, 1.0f);
    glEnd();
    glUseProgram(0);
    glDepthFunc(GL_LEQUAL);
    if (!depthTest)
        glDisable(GL_DEPTH_TEST);
    if (scissor)
        glEnable(GL_SCISSOR_TEST);
    if (alphaTest)
        glEnable(GL_ALPHA_TEST);
    if (blend)
        glEnable(GL_BLEND);
    if (cull)
        glEnable(GL_CULL_FACE);
    glDepthMask(depthMask != 0 ? GL_TRUE : GL_FALSE);
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glDeleteTextures(2, copies);
    m_multisampling = true;
    return true;
}

void OffscreenRenderer::Impl::resolveMultisample()
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_gl->msFramebuffer);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glDisable(GL_SCISSOR_TEST);
    glBlitFramebuffer(0, 0, GLint(m_width), GLint(m_height), 0, 0, GLint(m_width), GLint(m_height),
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    m_multisampling = false;
}

RenderResult OffscreenRenderer::Impl::setFog(const FogSetup& fog)
{
    if (!m_inFrame)
        return RenderResult::failure(RenderStatus::kWrongState, "setFog called outside a frame");
    switch (fog.mode) {
    case FogSetup::Mode::kOff:
    case FogSetup::Mode::kLinear:
    case FogSetup::Mode::kExponential:
    case FogSetup::Mode::kExponentialSquared:
    case FogSetup::Mode::kAlpha:
        break;
    default:
        return invalid("unknown fog mode");
    }
    const float values[14] = {fog.start,         fog.end,           fog.density,       fog.color[0],
                              fog.color[1],      fog.color[2],      fog.depthPlane[0], fog.depthPlane[1],
                              fog.depthPlane[2], fog.depthPlane[3], fog.wPlane[0],     fog.wPlane[1],
                              fog.wPlane[2],     fog.wPlane[3]};
    if (!allFinite(values, 14))
        return invalid("a fog value is NaN or infinite");
    if (fog.density < 0.0f)
        return invalid("fog density is negative");
    if (fog.mode == FogSetup::Mode::kLinear && !(fog.start < fog.end))
        return invalid("linear fog needs start below end");
    if (fog.mode == FogSetup::Mode::kOff) {
        m_currentFog = kNoFog;
        return RenderResult::success();
    }
    if (m_currentFog != kNoFog && std::memcmp(&m_fogs[m_currentFog], &fog, sizeof fog) == 0)
        return RenderResult::success();
    m_fogs.push_back(fog);
    m_currentFog = std::uint32_t(m_fogs.size() - 1);
    return RenderResult::success();
}

RenderResult OffscreenRenderer::Impl::setOpacity(const OpacitySetup& opacity)
{
    if (!m_inFrame)
        return RenderResult::failure(RenderStatus::kWrongState, "setOpacity called outside a frame");
    const RgbColor& u = opacity.uniform;
    if (!(u.r >= 0.0f && u.r <= 1.0f && u.g >= 0.0f && u.g <= 1.0f && u.b >= 0.0f && u.b <= 1.0f))
        return invalid("opacity must lie in 0..1");
    m_opacity = opacity;
    return RenderResult::success();
}

const FogSetup& OffscreenRenderer::Impl::fogOf(std::uint32_t fog) const
{
    static const FogSetup kOff;
    return fog == kNoFog ? kOff : m_fogs[fog];
}

void OffscreenRenderer::Impl::forgetTranslucent()
{
    m_fogs.clear();
    m_currentFog = kNoFog;
    m_opacity = OpacitySetup{};
    m_translucentVertices.clear();
    m_translucentOpacity.clear();
    m_translucentStates.clear();
    m_translucentShadings.clear();
    m_translucentTriangles.clear();
    m_translucentIndices.clear();
    m_translucentClip.clear();
    m_translucentWindow.clear();
}

std::uint32_t OffscreenRenderer::Impl::translucentState(const DrawRequest& r, bool textured,
                                                        bool onlyTranslucentTexels, float drawOpacity)
{
    TranslucentState state;
    state.matrix = m_matrices[m_currentMatrix];
    state.shading = kUnlit;
    if (r.shading != nullptr) {
        m_translucentShadings.push_back(*r.shading);
        state.shading = std::uint32_t(m_translucentShadings.size() - 1);
    }
    state.texture = textured ? m_currentTexture : kUntextured;
    state.fog = m_currentFog;
    state.faces = m_faces;
    state.smooth = r.smooth;
    state.onlyTranslucentTexels = onlyTranslucentTexels;
    state.multisample = m_antiAlias.triangles;
    state.drawOpacity = drawOpacity;
    state.firstVertex = state.lastVertex = 0; // drawSplit sets them
    state.triangleCount = 0;
    state.anyOrder = false;
    m_translucentStates.push_back(state);
    return std::uint32_t(m_translucentStates.size() - 1);
}

namespace {

// A vertex's opacity as the translucent programs take it (SurfaceFinish.h):
// r, g, b clamped to 0..1, and their mean, the opacity of the alpha channel.
// A grey one has the mean in all four, so that grey transparency blends with
// the very value it did when Q3 drew every pixel with the mean alone.
std::array<float, 4> opacityOf(const float* rgb)
{
    std::array<float, 4> o;
    for (int c = 0; c < 3; ++c)
        o[c] = std::clamp(rgb[c], 0.0f, 1.0f);
    o[3] = (o[0] + o[1] + o[2]) / 3.0f;
    if (o[0] == o[1] && o[1] == o[2])
        o[0] = o[1] = o[2] = o[3];
    return o;
}

} // namespace

void OffscreenRenderer::Impl::writeTranslucentVertex(const DrawRequest& r, bool textured, std::size_t i,
                                                    const std::array<float, 4>& opacity, std::size_t at)
{
    const std::array<float, 16>& m = m_matrices[m_currentMatrix];
    const float* p = r.xyz + 3 * i;
    std::array<double, 4>& clip = m_translucentClip[at];
    for (int j = 0; j < 4; ++j)
        clip[j] = double(p[0]) * m[j] + double(p[1]) * m[4 + j] + double(p[2]) * m[8 + j] + m[12 + j];
    const double w = clip[3], toWindow = 1.0 / w;
    const double x = clip[0] * toWindow, y = clip[1] * toWindow;
    const double halfWidth = 0.5 * double(m_pane.width), halfHeight = 0.5 * double(m_pane.height);
    m_translucentWindow[at] = w > 1e-6 && std::isfinite(x) && std::isfinite(y)
                                  ? WindowPoint{(x + 1.0) * halfWidth, (y + 1.0) * halfHeight}
                                  : WindowPoint{std::numeric_limits<double>::quiet_NaN(), 0.0};
    m_translucentVertices[at] = vertexAt(r, textured, i);
    std::copy(opacity.begin(), opacity.end(), m_translucentOpacity.begin() + std::ptrdiff_t(4 * at));
}

void OffscreenRenderer::Impl::growTranslucentVertices(std::size_t count)
{
    // Room in all three first (by half again at least, so that growing a
    // vertex at a time costs no more than push_back), so that running out
    // of memory leaves them the same length.
    const auto room = [count](auto& values, std::size_t perVertex) {
        const std::size_t needed = perVertex * count;
        if (values.capacity() < needed)
            values.reserve(std::max(needed, values.capacity() + values.capacity() / 2));
    };
    room(m_translucentClip, 1);
    room(m_translucentWindow, 1);
    room(m_translucentVertices, 1);
    room(m_translucentOpacity, 4);
    m_translucentClip.resize(count);
    m_translucentWindow.resize(count);
    m_translucentVertices.resize(count);
    m_translucentOpacity.resize(4 * count);
}

std::uint32_t OffscreenRenderer::Impl::storeTranslucentVertex(const DrawRequest& r, bool textured, std::size_t i,
                                                               const std::array<float, 4>& opacity)
{
    const std::size_t at = m_translucentVertices.size();
    growTranslucentVertices(at + 1);
    writeTranslucentVertex(r, textured, i, opacity, at);
    return std::uint32_t(at);
}

void OffscreenRenderer::Impl::storeTranslucentVertices(const DrawRequest& r, bool textured,
                                                       const std::array<float, 4>& opacity)
{
    const std::size_t first = m_translucentVertices.size();
    growTranslucentVertices(first + r.vertexCount);
    for (std::size_t i = 0; i < r.vertexCount; ++i)
        writeTranslucentVertex(r, textured, i, opacity, first + i);
}

RenderResult OffscreenRenderer::Impl::drawSplit(const DrawRequest& r, bool textured)
{
    const float* rgb = m_opacity.rgb;
    if (rgb != nullptr && m_opacity.count != r.vertexCount)
        return invalid("the opacity array has " + std::to_string(m_opacity.count) + " values for " +
                       std::to_string(r.vertexCount) + " vertices");
    if (rgb != nullptr && !allFinite(rgb, 3 * r.vertexCount))
        return invalid("a vertex opacity is NaN or infinite");
    const float uniform[3] = {m_opacity.uniform.r, m_opacity.uniform.g, m_opacity.uniform.b};
    const bool alphaTexture = textured && m_textures[m_currentTexture].hasAlpha;
    const std::size_t count = r.indexed ? r.indexCount : r.vertexCount;
    std::vector<std::uint32_t>& opaque = m_splitOpaque;
    opaque.clear();
    constexpr std::uint32_t kNoState = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t states[2] = {kNoState, kNoState}; // translucent, only translucent texels
    m_splitVertices.assign(r.vertexCount, kNoState);
    const std::size_t firstVertex = m_translucentVertices.size();
    // Without an opacity per vertex every corner has the same one.
    const std::array<float, 4> uniformOpacity = opacityOf(uniform);
    const bool grey = uniformOpacity[0] == uniformOpacity[3] && uniformOpacity[1] == uniformOpacity[3] &&
                      uniformOpacity[2] == uniformOpacity[3];
    const float drawOpacity = rgb == nullptr && grey ? uniformOpacity[3] : -1.0f;
    if (rgb == nullptr && uniformOpacity[3] < 1.0f) {
        // Every triangle is translucent: the draw's vertices are stored in
        // their order, each transformed once, without looking each corner
        // up (drawn in the same order, the same pixels).
        if (count < 3)
            return RenderResult::success();
        const std::uint32_t state = translucentState(r, textured, false, drawOpacity);
        storeTranslucentVertices(r, textured, uniformOpacity);
        // Written in place, through pointers the loop's stores cannot
        // change (a triangle built on the stack and pushed back went
        // through memory: a fifth of the batch's time on the calling thread).
        const std::size_t firstTriangle = m_translucentTriangles.size();
        m_translucentTriangles.resize(firstTriangle + count / 3);
        TranslucentTriangle* out = m_translucentTriangles.data() + firstTriangle;
        const std::array<double, 4>* clip = m_translucentClip.data();
        const std::uint32_t* indices = r.indexed ? r.indices : nullptr;
        const std::uint32_t first = std::uint32_t(firstVertex);
        for (std::size_t t = 0; t + 2 < count; t += 3, ++out) {
            std::uint32_t v[3];
            for (int k = 0; k < 3; ++k)
                v[k] = first + (indices != nullptr ? indices[t + k] : std::uint32_t(t + k));
            out->state = state;
            out->v[0] = v[0];
            out->v[1] = v[1];
            out->v[2] = v[2];
            out->depth = depthOf(clip[v[0]], clip[v[1]], clip[v[2]]);
        }
        TranslucentState& stored = m_translucentStates[state];
        stored.firstVertex = GLuint(firstVertex);
        stored.lastVertex = GLuint(m_translucentVertices.size() - 1);
        stored.triangleCount = count / 3;
        const std::vector<std::uint32_t>* loop = loopOf(r);
        // Tested now, while its vertices and triangles are in the cache
        // (out of memory for the test's arrays: sorted).
        try {
            stored.anyOrder = loop != nullptr && coversOnce(stored, firstTriangle, *loop);
        } catch (const std::bad_alloc&) {
            stored.anyOrder = false;
        }
        return RenderResult::success();
    }
    for (std::size_t t = 0; t + 2 < count; t += 3) {
        std::uint32_t v[3];
        std::array<float, 4> a[3];
        bool allOpaque = true;
        for (int k = 0; k < 3; ++k) {
            v[k] = r.indexed ? r.indices[t + k] : std::uint32_t(t + k);
            a[k] = rgb != nullptr ? opacityOf(rgb + 3 * std::size_t(v[k])) : uniformOpacity;
            allOpaque = allOpaque && a[k][3] >= 1.0f;
        }
        if (allOpaque)
            opaque.insert(opaque.end(), v, v + 3);
        if (allOpaque && !alphaTexture)
            continue;
        std::uint32_t& state = states[allOpaque ? 1 : 0];
        if (state == kNoState)
            state = translucentState(r, textured, allOpaque, drawOpacity);
        TranslucentTriangle triangle;
        triangle.state = state;
        for (int k = 0; k < 3; ++k) {
            // A vertex's first triangle stores it.
            std::uint32_t& stored = m_splitVertices[v[k]];
            if (stored == kNoState)
                stored = storeTranslucentVertex(r, textured, v[k], a[k]);
            triangle.v[k] = stored;
        }
        triangle.depth = depthOf(m_translucentClip[triangle.v[0]], m_translucentClip[triangle.v[1]],
                                 m_translucentClip[triangle.v[2]]);
        m_translucentTriangles.push_back(triangle);
    }
    for (std::uint32_t state : states)
        if (state != kNoState) {
            m_translucentStates[state].firstVertex = GLuint(firstVertex);
            m_translucentStates[state].lastVertex = GLuint(m_translucentVertices.size() - 1);
        }
    if (opaque.empty())
        return RenderResult::success();
    DrawRequest rest = r;
    rest.indexed = true;
    rest.indices = opaque.data();
    rest.indexCount = opaque.size();
    rest.opaquePart = true;
    return draw(rest);
}

bool OffscreenRenderer::Impl::loadFog(const DrawCommand& head, int variant, FogLoad& loaded, RenderResult& result)
{
    const bool textured = head.texture != kUntextured;
    if (head.shading == kUnlit) {
        if (head.fog == kNoFog) {
            if (loaded.unlit >= 0)
                glUseProgram(0);
            loaded.unlit = -1;
            return true;
        }
        UnlitProgram& program = m_gl->unlitPrograms[textured ? 1 : 0];
        if (!program.built()) {
            std::string error;
            if (!program.build(error, textured)) {
                result = RenderResult::failure(RenderStatus::kGraphicsError, error);
                return false;
            }
        }
        if (loaded.unlit != int(textured)) {
            program.use();
            loaded.unlit = int(textured);
        }
        std::uint32_t& set = loaded.fog[LitProgram::kVariants + (textured ? 1 : 0)];
        if (set != head.fog) {
            program.finish().setFog(fogOf(head.fog));
            set = head.fog;
        }
        return true;
    }
    // The batch loop has made the lit program current.
    loaded.unlit = -1;
    std::uint32_t& set = loaded.fog[variant];
    if (set != head.fog) {
        m_gl->litPrograms[variant]->finish().setFog(fogOf(head.fog));
        set = head.fog;
    }
    return true;
}

void OffscreenRenderer::Impl::loadOpaqueAlphaTest(std::uint32_t texture, bool& loaded)
{
    const bool tested = texture != kUntextured && m_textures[texture].hasAlpha;
    if (tested == loaded)
        return;
    if (tested) {
        glEnable(GL_ALPHA_TEST);
        glAlphaFunc(GL_GEQUAL, kOpaqueAlpha);
    } else {
        glDisable(GL_ALPHA_TEST);
    }
    loaded = tested;
}

// The back-to-front order matters only where triangles cover the same
// pixels: blending is order dependent there and nowhere else (translucent
// triangles write no depth, and the depth test reads only what the opaque
// ones wrote). So the states (each one draw's translucent triangles) are
// grouped into clusters whose screen rectangles overlap, transitively; the
// triangles of different clusters touch disjoint pixels, so drawing cluster
// after cluster, each in the sorted order, gives the very pixels of the
// sorted order, with one draw call per state where a cluster is one state
// (separate translucent objects) instead of one per switch between
// interleaved depths. A state's rectangle is the window coordinates of its
// draw's vertices widened by two pixels (covering whatever the rasterizer,
// multisampled or not, can touch); a vertex at or behind the eye (w <= 0,
// its triangles clipped into a larger area) makes its state cover
// everything. Beyond kMaxClusteredStates states the pairwise test is not
// worth it and the order stays as sorted.
bool OffscreenRenderer::Impl::findClusters()
{
    constexpr std::size_t kMaxClusteredStates = 256;
    const std::size_t stateCount = m_translucentStates.size();
    if (stateCount > kMaxClusteredStates)
        return false;
    struct Box {
        double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
        double x1 = -x0, y1 = -x0;
        bool used = false;
    };
    std::vector<Box> boxes(stateCount);
    constexpr double kMargin = 2.0;
    // (Every vertex of the draw, those of the state's triangles among them:
    // a larger rectangle only merges clusters, whose triangles then keep the
    // sorted order.)
    for (const TranslucentTriangle& triangle : m_translucentTriangles)
        boxes[triangle.state].used = true;
    for (std::size_t state = 0; state < stateCount; ++state) {
        Box& box = boxes[state];
        if (!box.used)
            continue;
        const TranslucentState& drawn = m_translucentStates[state];
        for (std::size_t v = drawn.firstVertex; v <= drawn.lastVertex; ++v) {
            const WindowPoint& at = m_translucentWindow[v];
            if (std::isnan(at[0])) {
                box.x0 = box.y0 = -std::numeric_limits<double>::infinity();
                box.x1 = box.y1 = std::numeric_limits<double>::infinity();
                break;
            }
            box.x0 = std::min(box.x0, at[0]);
            box.x1 = std::max(box.x1, at[0]);
            box.y0 = std::min(box.y0, at[1]);
            box.y1 = std::max(box.y1, at[1]);
        }
        box.x0 -= kMargin;
        box.x1 += kMargin;
        box.y0 -= kMargin;
        box.y1 += kMargin;
    }
    // Union-find over the states whose rectangles overlap.
    std::vector<std::uint32_t>& parent = m_stateCluster;
    parent.resize(stateCount);
    for (std::uint32_t i = 0; i < stateCount; ++i)
        parent[i] = i;
    const auto root = [&parent](std::uint32_t i) {
        while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
        return i;
    };
    for (std::uint32_t i = 0; i < stateCount; ++i)
        for (std::uint32_t j = i + 1; j < stateCount && boxes[i].used; ++j)
            if (boxes[j].used && boxes[i].x0 <= boxes[j].x1 && boxes[j].x0 <= boxes[i].x1 &&
                boxes[i].y0 <= boxes[j].y1 && boxes[j].y0 <= boxes[i].y1) {
                const std::uint32_t a = root(i), b = root(j);
                if (a != b)
                    parent[std::max(a, b)] = std::min(a, b);
            }
    // Each state's cluster named by its root.
    for (std::uint32_t i = 0; i < stateCount; ++i)
        parent[i] = root(i);
    return true;
}

// The rasterizer places each vertex where its float arithmetic puts it:
// llvmpipe computes the clip coordinates as a float product of the matrix
// and the position (each within 4 units in the last place of the sum of
// its terms' magnitudes; kFloatError allows twice that), divides by w and
// snaps to 1/256 of a pixel, which with the viewport's float rounding moves
// a point by less than 1/128 of a pixel on the largest viewport
// (kMaxImageSize); kSnapSlack allows four times that. The clip coordinates
// here are exact to double precision. A vertex moved by dx and dw has its
// window x moved by at most halfWidth * 2 (|dx| + |dw|) / w while
// |x| <= w and |dw| <= w / 2.
bool OffscreenRenderer::Impl::coversOnce(const TranslucentState& state, std::size_t firstTriangle,
                                         const std::vector<std::uint32_t>& loop)
{
    constexpr double kFloatError = 1.0 / double(1 << 21);
    constexpr double kSnapSlack = 1.0 / 32.0;
    // In one pass: the largest position magnitudes (for each clip
    // coordinate's error), how far each vertex is inside the view volume
    // (w less the largest of |x|, |y|, |z|, each with its own error added
    // below), and the nearest w.
    double reach[3] = {0.0, 0.0, 0.0};
    double outside[3] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity()};
    double nearestW = std::numeric_limits<double>::infinity();
    for (std::size_t v = state.firstVertex; v <= state.lastVertex; ++v) {
        const Vertex& p = m_translucentVertices[v];
        reach[0] = std::max(reach[0], double(std::fabs(p.x)));
        reach[1] = std::max(reach[1], double(std::fabs(p.y)));
        reach[2] = std::max(reach[2], double(std::fabs(p.z)));
        const std::array<double, 4>& clip = m_translucentClip[v];
        for (int k = 0; k < 3; ++k)
            outside[k] = std::max(outside[k], std::fabs(clip[k]) - clip[3]);
        nearestW = std::min(nearestW, clip[3]);
    }
    const std::array<float, 16>& m = state.matrix;
    double error[4];
    for (int k = 0; k < 4; ++k)
        error[k] = kFloatError * (std::fabs(m[k]) * reach[0] + std::fabs(m[4 + k]) * reach[1] +
                                  std::fabs(m[8 + k]) * reach[2] + std::fabs(m[12 + k]));
    // Every vertex well inside, so that nothing is clipped (clipping makes
    // vertices of its own), and in front of the eye by more than twice
    // w's error. (A NaN fails every comparison.)
    if (!(nearestW > 3.0 * error[3]))
        return false;
    for (int k = 0; k < 3; ++k)
        if (!(outside[k] + error[k] + error[3] < 0.0))
            return false;
    const double slack =
        kSnapSlack + 2.0 * std::max(0.5 * double(m_pane.width) * (error[0] + error[3]),
                                    0.5 * double(m_pane.height) * (error[1] + error[3])) / nearestW;
    int turn = 0;
    const TranslucentTriangle* triangle = m_translucentTriangles.data() + firstTriangle;
    for (std::size_t t = 0; t < state.triangleCount; ++t, ++triangle) {
        const int way = turnWithSlack(m_translucentWindow[triangle->v[0]], m_translucentWindow[triangle->v[1]],
                                      m_translucentWindow[triangle->v[2]], slack);
        if (way == 0 || (turn != 0 && way != turn))
            return false;
        turn = way;
    }
    return simpleWithSlack(m_translucentWindow.data(), state.firstVertex, loop, slack, m_loopScratch);
}

std::size_t OffscreenRenderer::Impl::placeInOrder()
{
    const std::size_t stateCount = m_translucentStates.size();
    // How many states each cluster has (every state has triangles).
    m_clusterOf.assign(stateCount, 0);
    for (std::size_t state = 0; state < stateCount; ++state)
        ++m_clusterOf[m_stateCluster[state]];
    std::vector<bool> inOrder(stateCount, false);
    std::size_t count = 0;
    for (std::size_t state = 0; state < stateCount; ++state) {
        const TranslucentState& drawn = m_translucentStates[state];
        if (drawn.anyOrder && m_clusterOf[m_stateCluster[state]] == 1) {
            inOrder[state] = true;
            count += drawn.triangleCount;
        }
    }
    m_inOrderTriangles += count;
    const std::size_t total = m_translucentTriangles.size();
    if (count == 0 || count == total)
        return count;
    // A stable partition: those first, the rest after, each in its order.
    m_clustered.resize(total);
    std::size_t front = 0, back = count;
    for (const TranslucentTriangle& triangle : m_translucentTriangles)
        m_clustered[inOrder[triangle.state] ? front++ : back++] = triangle;
    m_translucentTriangles.swap(m_clustered);
    return count;
}

void OffscreenRenderer::Impl::groupClusters(std::size_t first)
{
    // Clusters numbered by first appearance in the sorted order; a stable
    // counting sort by cluster keeps the sorted order inside each.
    constexpr std::uint32_t kUnnumbered = std::numeric_limits<std::uint32_t>::max();
    m_clusterOf.assign(m_translucentStates.size(), kUnnumbered);
    std::vector<std::size_t> counts;
    const std::size_t total = m_translucentTriangles.size();
    for (std::size_t i = first; i < total; ++i) {
        std::uint32_t& cluster = m_clusterOf[m_stateCluster[m_translucentTriangles[i].state]];
        if (cluster == kUnnumbered) {
            cluster = std::uint32_t(counts.size());
            counts.push_back(0);
        }
        ++counts[cluster];
    }
    if (counts.size() < 2)
        return;
    std::vector<std::size_t> next(counts.size(), first);
    for (std::size_t c = 1; c < counts.size(); ++c)
        next[c] = next[c - 1] + counts[c - 1];
    m_clustered.resize(total);
    std::copy(m_translucentTriangles.begin(), m_translucentTriangles.begin() + std::ptrdiff_t(first),
              m_clustered.begin());
    for (std::size_t i = first; i < total; ++i) {
        const TranslucentTriangle& triangle = m_translucentTriangles[i];
        m_clustered[next[m_clusterOf[m_stateCluster[triangle.state]]]++] = triangle;
    }
    m_translucentTriangles.swap(m_clustered);
}

// A stable radix sort, least significant byte first, on the upper half of
// a key per triangle that orders as its depth does, reversed, then the runs
// that half leaves tied by the whole key: the bits of a non-negative double
// order as its value, a negative one's as its value reversed, so flipping
// the sign bit of the first and every bit of the second gives an unsigned
// key in the doubles' order (-0, which a depth that underflows can be,
// counted as +0, so that the two stay equal).
// A pass over a byte every key shares moves nothing and is skipped (the
// exponent's bytes, for depths close together).
void OffscreenRenderer::Impl::sortFarthestFirst(std::size_t first)
{
    const std::size_t total = m_translucentTriangles.size();
    if (total - first < 2)
        return;
    const TranslucentTriangle* triangles = m_translucentTriangles.data() + first;
    const std::size_t count = total - first;
    m_sortKeys.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const double depth = triangles[i].depth + 0.0;
        std::uint64_t bits;
        std::memcpy(&bits, &depth, sizeof bits);
        constexpr std::uint64_t kSign = std::uint64_t(1) << 63;
        const std::uint64_t ascending = (bits & kSign) != 0 ? ~bits : bits | kSign;
        m_sortKeys[i] = SortKey{~ascending, std::uint32_t(i)};
    }
    // By the keys' upper halves first: least significant byte first, each
    // byte's counts taken in one pass over the keys (a key's bytes do not
    // change as the passes reorder them), a byte every key shares skipped;
    // four passes at most. Keys equal in their upper halves are then in
    // submission order.
    std::array<std::array<std::uint32_t, 256>, 4> counts{};
    for (const SortKey& key : m_sortKeys)
        for (int byte = 0; byte < 4; ++byte)
            ++counts[byte][(key.key >> (32 + 8 * byte)) & 0xFF];
    m_sortScratch.resize(count);
    for (int byte = 0; byte < 4; ++byte) {
        std::array<std::uint32_t, 256>& place = counts[byte];
        const int shift = 32 + 8 * byte;
        if (place[(m_sortKeys[0].key >> shift) & 0xFF] == count)
            continue;
        std::uint32_t next = 0;
        for (std::uint32_t& c : place) {
            const std::uint32_t n = c;
            c = next;
            next += n;
        }
        for (const SortKey& key : m_sortKeys)
            m_sortScratch[place[(key.key >> shift) & 0xFF]++] = key;
        m_sortKeys.swap(m_sortScratch);
    }
    // Then each run of keys equal in their upper halves (depths within
    // about a millionth of each other: few, and short) by the whole key,
    // keeping submission order on ties: by insertion up to kShortRun keys,
    // else by a stable merge sort, so that no run costs more than
    // n log n.
    constexpr std::size_t kShortRun = 16;
    const auto byKey = [](const SortKey& a, const SortKey& b) { return a.key < b.key; };
    for (std::size_t i = 0; i < count;) {
        const std::uint64_t upper = m_sortKeys[i].key >> 32;
        std::size_t end = i + 1;
        while (end < count && m_sortKeys[end].key >> 32 == upper)
            ++end;
        if (end - i > kShortRun) {
            std::stable_sort(m_sortKeys.begin() + std::ptrdiff_t(i), m_sortKeys.begin() + std::ptrdiff_t(end), byKey);
        } else {
            for (std::size_t j = i + 1; j < end; ++j) {
                const SortKey moved = m_sortKeys[j];
                std::size_t k = j;
                for (; k > i && moved.key < m_sortKeys[k - 1].key; --k)
                    m_sortKeys[k] = m_sortKeys[k - 1];
                m_sortKeys[k] = moved;
            }
        }
        i = end;
    }
    m_clustered.resize(total);
    std::copy(m_translucentTriangles.begin(), m_translucentTriangles.begin() + std::ptrdiff_t(first),
              m_clustered.begin());
    for (std::size_t i = 0; i < count; ++i)
        m_clustered[first + i] = triangles[m_sortKeys[i].index];
    m_translucentTriangles.swap(m_clustered);
}

void OffscreenRenderer::Impl::drawTranslucent(RenderResult& result)
{
    if (m_translucentTriangles.empty())
        return;
    // The triangles of a state alone in its cluster that cover no sample
    // twice first, in their order (any order gives their pixels); the
    // rest farthest first, triangles at one depth in submission order,
    // then cluster by cluster.
    const bool clustered = findClusters();
    const std::size_t inOrder = clustered ? placeInOrder() : 0;
    sortFarthestFirst(inOrder);
    if (clustered)
        groupClusters(inOrder);
    m_translucentIndices.resize(3 * m_translucentTriangles.size());
    GLuint* index = m_translucentIndices.data();
    for (const TranslucentTriangle& triangle : m_translucentTriangles) {
        index[0] = triangle.v[0];
        index[1] = triangle.v[1];
        index[2] = triangle.v[2];
        index += 3;
    }

    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    uploadStream(kStreamVertices, GL_ARRAY_BUFFER, m_translucentVertices.data(),
                 m_translucentVertices.size() * sizeof(Vertex));
    glVertexPointer(3, GL_FLOAT, sizeof(Vertex), bufferOffset(offsetof(Vertex, x)));
    glColorPointer(3, GL_FLOAT, sizeof(Vertex), bufferOffset(offsetof(Vertex, r)));
    glNormalPointer(GL_FLOAT, sizeof(Vertex), bufferOffset(offsetof(Vertex, nx)));
    glTexCoordPointer(2, GL_FLOAT, sizeof(Vertex), bufferOffset(offsetof(Vertex, s)));
    uploadStream(kStreamOpacity, GL_ARRAY_BUFFER, m_translucentOpacity.data(),
                 m_translucentOpacity.size() * sizeof(float));
    glEnableVertexAttribArray(kOpacityAttribute);
    glVertexAttribPointer(kOpacityAttribute, 4, GL_FLOAT, GL_FALSE, 0, bufferOffset(0));
    uploadStream(kStreamIndices, GL_ELEMENT_ARRAY_BUFFER, m_translucentIndices.data(),
                 m_translucentIndices.size() * sizeof(GLuint));
    // Each colour channel by its own opacity, the programs' second output
    // (dual-source blending, SurfaceFinish.h); alpha by the mean, output 0's
    // alpha. The factors are complementary, so llvmpipe blends colour as it
    // does with (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) for the same values,
    // which is how a lit state of one grey opacity blends (its program has
    // no second output).
    glEnable(GL_BLEND);
    int blendSources = 0; // 1 or 2 once set
    glDepthMask(GL_FALSE);

    bool lightsLoaded[LitProgram::kVariants] = {};
    const std::size_t count = m_translucentTriangles.size();
    std::size_t i = 0;
    while (i < count) {
        const std::uint32_t stateIndex = m_translucentTriangles[i].state;
        std::size_t end = i + 1;
        while (end < count && m_translucentTriangles[end].state == stateIndex)
            ++end;
        const TranslucentState& state = m_translucentStates[stateIndex];
        if (state.multisample != m_multisampling) {
            std::string error;
            if (!useMultisample(state.multisample, error)) {
                result = RenderResult::failure(RenderStatus::kGraphicsError, error);
                break;
            }
        }
        glLoadMatrixf(state.matrix.data());
        glShadeModel(state.smooth ? GL_SMOOTH : GL_FLAT);
        if (state.faces.cullBack)
            glEnable(GL_CULL_FACE);
        else
            glDisable(GL_CULL_FACE);
        glFrontFace(state.faces.clockwiseFront ? GL_CW : GL_CCW);
        const bool textured = state.texture != kUntextured;
        if (textured) {
            bindTexture(state.texture);
            glEnable(GL_TEXTURE_2D);
            glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        } else {
            glDisable(GL_TEXTURE_2D);
            glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        }
        if (state.onlyTranslucentTexels) {
            glEnable(GL_ALPHA_TEST);
            glAlphaFunc(GL_LESS, kOpaqueAlpha);
        } else {
            glDisable(GL_ALPHA_TEST);
        }
        const bool oneOpacity = state.shading != kUnlit && state.drawOpacity >= 0.0f;
        if (blendSources != (oneOpacity ? 1 : 2)) {
            if (oneOpacity)
                glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            else
                glBlendFuncSeparate(GL_SRC1_COLOR, GL_ONE_MINUS_SRC1_COLOR, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            blendSources = oneOpacity ? 1 : 2;
        }
        std::string error;
        if (state.shading == kUnlit) {
            UnlitProgram& program = m_gl->unlitPrograms[textured ? 1 : 0];
            if (!program.built() && !program.build(error, textured)) {
                result = RenderResult::failure(RenderStatus::kGraphicsError, error);
                break;
            }
            program.use();
            program.finish().setFog(fogOf(state.fog));
        } else {
            const SurfaceShading& shading = m_translucentShadings[state.shading];
            const int variant = LitProgram::variant(textured, shading, state.fog != kNoFog, m_lighting, oneOpacity);
            LitProgram* program =
                useLitProgram(variant, shading, lightsLoaded, result, oneOpacity ? state.drawOpacity : 1.0f);
            if (program == nullptr)
                break;
            program->finish().setFog(fogOf(state.fog));
        }
        glDrawRangeElements(GL_TRIANGLES, state.firstVertex, state.lastVertex, GLsizei(3 * (end - i)), GL_UNSIGNED_INT,
                            bufferOffset(sizeof(GLuint) * 3 * i));
        i = end;
    }

    glDisable(GL_ALPHA_TEST);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDisableVertexAttribArray(kOpacityAttribute);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    setDefaultOpacity();
    glShadeModel(GL_FLAT);
}

void OffscreenRenderer::Impl::cancelFrame()
{
    m_inFrame = false;
    resetBatch();
    forgetTextures();
    forgetTranslucent();
    lendContext();
}

OffscreenRenderer::OffscreenRenderer() : m_impl(std::make_unique<Impl>(chooseGlBackendFromEnvironment())) {}

OffscreenRenderer::OffscreenRenderer(GlBackend backend) : m_impl(std::make_unique<Impl>(GlBackendChoice{backend, {}}))
{
}

OffscreenRenderer::~OffscreenRenderer() = default;

RenderResult OffscreenRenderer::beginFrame(std::uint32_t width, std::uint32_t height,
                                           const RgbaColor& clearColor, const PixelRect& pane,
                                           const FrameOptions& options)
{
    try {
        return m_impl->beginFrame(width, height, clearColor, pane, options);
    } catch (const std::bad_alloc&) {
        return RenderResult::failure(RenderStatus::kOutOfMemory,
                                     "out of memory for a " + std::to_string(width) + " x " +
                                         std::to_string(height) + " image");
    }
}

RenderResult OffscreenRenderer::setMatrix(const float m[16])
{
    if (m == nullptr)
        return invalid("matrix pointer is NULL");
    std::array<float, 16> matrix;
    std::memcpy(matrix.data(), m, sizeof(float) * 16);
    try {
        return m_impl->setMatrix(matrix);
    } catch (const std::bad_alloc&) {
        return outOfMemory();
    }
}

RenderResult OffscreenRenderer::setMatrix(const double m[16])
{
    if (m == nullptr)
        return invalid("matrix pointer is NULL");
    std::array<float, 16> matrix;
    for (int i = 0; i < 16; ++i)
        matrix[i] = float(m[i]);
    try {
        return m_impl->setMatrix(matrix);
    } catch (const std::bad_alloc&) {
        return outOfMemory();
    }
}

namespace {

// A template so that the private Impl type is deduced, never named here.
template <class Impl>
RenderResult drawGuarded(Impl& impl, const DrawRequest& request)
{
    try {
        return impl.draw(request);
    } catch (const std::bad_alloc&) {
        return outOfMemory();
    }
}

DrawRequest arrays(Primitive primitive, const float* xyz, const float* rgb, std::size_t count,
                   const RgbColor& color, float pointSize, bool smooth)
{
    DrawRequest request;
    request.primitive = primitive;
    request.xyz = xyz;
    request.rgb = rgb;
    request.vertexCount = count;
    request.color = color;
    request.pointSize = pointSize;
    request.smooth = smooth;
    return request;
}

} // namespace

RenderResult OffscreenRenderer::drawLineStrip(const float* xyz, std::size_t count, const RgbColor& color)
{
    return drawGuarded(*m_impl, arrays(Primitive::kLineStrip, xyz, nullptr, count, color, 1.0f, false));
}

RenderResult OffscreenRenderer::drawLines(const float* xyz, std::size_t count, const RgbColor& color)
{
    return drawGuarded(*m_impl, arrays(Primitive::kLines, xyz, nullptr, count, color, 1.0f, false));
}

RenderResult OffscreenRenderer::drawPoints(const float* xyz, std::size_t count, const RgbColor& color,
                                           float pointSize)
{
    return drawGuarded(*m_impl, arrays(Primitive::kPoints, xyz, nullptr, count, color, pointSize, false));
}

RenderResult OffscreenRenderer::drawTriangles(const float* xyz, std::size_t count, const RgbColor& color)
{
    return drawGuarded(*m_impl, arrays(Primitive::kTriangles, xyz, nullptr, count, color, 1.0f, false));
}

RenderResult OffscreenRenderer::drawBitmap(const float* anchor, const BitmapImage& image, const RgbColor& color)
{
    try {
        return m_impl->drawBitmap(anchor, image, color);
    } catch (const std::bad_alloc&) {
        return outOfMemory();
    }
}

RenderResult OffscreenRenderer::drawPixmap(const float* anchor, const PixmapImage& image)
{
    try {
        return m_impl->drawPixmap(anchor, image);
    } catch (const std::bad_alloc&) {
        return outOfMemory();
    }
}

RenderResult OffscreenRenderer::drawElements(DrawMode mode, const float* xyz, const float* rgb,
                                             std::size_t vertexCount, const std::uint32_t* indices,
                                             std::size_t indexCount, const RgbColor& color, bool smooth,
                                             const float* st)
{
    DrawRequest request = arrays(mode, xyz, rgb, vertexCount, color, 1.0f, smooth);
    request.st = st;
    request.indexed = true;
    request.indices = indices;
    request.indexCount = indexCount;
    return drawGuarded(*m_impl, request);
}

RenderResult OffscreenRenderer::drawArrays(DrawMode mode, const float* xyz, const float* rgb, std::size_t count,
                                           const RgbColor& color, bool smooth)
{
    return drawGuarded(*m_impl, arrays(mode, xyz, rgb, count, color, 1.0f, smooth));
}

RenderResult OffscreenRenderer::drawLitTriangles(const float* xyz, const float* normals, const float* rgb,
                                                 std::size_t vertexCount, const std::uint32_t* indices,
                                                 std::size_t indexCount, const RgbColor& color,
                                                 const SurfaceShading& shading, const float* st)
{
    DrawRequest request = arrays(Primitive::kTriangles, xyz, rgb, vertexCount, color, 1.0f, shading.interpolation != 0);
    request.indexed = true;
    request.indices = indices;
    request.indexCount = indexCount;
    request.normals = normals;
    request.shading = &shading;
    request.st = st;
    return drawGuarded(*m_impl, request);
}

RenderResult OffscreenRenderer::setLighting(const LightingSetup& lighting)
{
    try {
        return m_impl->setLighting(lighting);
    } catch (const std::bad_alloc&) {
        return outOfMemory();
    }
}

RenderResult OffscreenRenderer::setTexture(const TextureImage* texture)
{
    RenderResult none = m_impl->useTexture(kNoTexture);
    if (!none || texture == nullptr)
        return none;
    std::uint32_t id = kNoTexture;
    RenderResult added = addTexture(*texture, id);
    if (!added)
        return added;
    return m_impl->useTexture(id);
}

RenderResult OffscreenRenderer::addTexture(const TextureImage& texture, std::uint32_t& id)
{
    try {
        return m_impl->addTexture(texture, id);
    } catch (const std::bad_alloc&) {
        return outOfMemory();
    }
}

RenderResult OffscreenRenderer::useTexture(std::uint32_t id)
{
    return m_impl->useTexture(id);
}

RenderResult OffscreenRenderer::setFaceOptions(const FaceOptions& faces)
{
    return m_impl->setFaceOptions(faces);
}

RenderResult OffscreenRenderer::setAntiAlias(const AntiAliasOptions& options)
{
    return m_impl->setAntiAlias(options);
}

RenderResult OffscreenRenderer::setFog(const FogSetup& fog)
{
    try {
        return m_impl->setFog(fog);
    } catch (const std::bad_alloc&) {
        return outOfMemory();
    }
}

RenderResult OffscreenRenderer::setOpacity(const OpacitySetup& opacity)
{
    return m_impl->setOpacity(opacity);
}

RenderResult OffscreenRenderer::endFrame()
{
    try {
        return m_impl->endFrame();
    } catch (const std::bad_alloc&) {
        return outOfMemory();
    }
}

void OffscreenRenderer::cancelFrame()
{
    m_impl->cancelFrame();
}

bool OffscreenRenderer::inFrame() const
{
    return m_impl->m_inFrame;
}

std::uint32_t OffscreenRenderer::width() const
{
    return m_impl->m_width;
}

std::uint32_t OffscreenRenderer::height() const
{
    return m_impl->m_height;
}

std::size_t OffscreenRenderer::rowBytes() const
{
    return std::size_t(m_impl->m_width) * 4;
}

bool OffscreenRenderer::drewInPlace() const
{
    return m_impl->m_drewInPlace;
}

std::uint64_t OffscreenRenderer::keptDraws() const
{
    return m_impl->m_keptDraws;
}

std::uint64_t OffscreenRenderer::translucentInOrder() const
{
    return m_impl->m_inOrderTriangles;
}

void OffscreenRenderer::setKeptLimits(std::size_t vertices, std::size_t indices)
{
    m_impl->m_keptLimits[0] = std::max<std::size_t>(vertices, 1);
    m_impl->m_keptLimits[1] = std::max<std::size_t>(indices, 1);
}

bool OffscreenRenderer::drawKept(const MeshView& mesh, const Shading& shading, bool textured, RenderResult& result)
{
    constexpr std::size_t kMax = std::numeric_limits<std::uint32_t>::max();
    if (mesh.serial == 0 || mesh.triangleCount == 0 || mesh.vertexCount > kMax || mesh.triangleCount > kMax / 3 ||
        !m_impl->m_inFrame)
        return false;
    // Only opaque, unsplit draws (translucent triangles are sorted per
    // frame).
    if (!m_impl->opaqueFill(textured))
        return false;
    Impl::StaticKey key;
    key.serial = mesh.serial;
    key.vertexCount = std::uint32_t(mesh.vertexCount);
    key.triangleCount = std::uint32_t(mesh.triangleCount);
    if (textured)
        std::copy(std::begin(shading.stTransform), std::end(shading.stTransform), std::begin(key.stTransform));
    key.color[0] = shading.color.r;
    key.color[1] = shading.color.g;
    key.color[2] = shading.color.b;
    key.flags = std::uint8_t((shading.rgb != nullptr ? Impl::kKeyColors : 0) | (textured ? Impl::kKeyTextured : 0));
    if (shading.lit) {
        // drawLit's normals follow the front's winding and whether the
        // interpolation is flat (lit at the vertices or at every pixel,
        // the vertices are the same).
        key.flags |= Impl::kKeyLit | (shading.clockwiseFront ? Impl::kKeyClockwise : 0) |
                     (shading.surface.interpolation != 0 ? Impl::kKeySmooth : 0);
    } else if (shading.smooth) {
        key.flags |= Impl::kKeySmooth;
    }
    try {
        return m_impl->drawKept(key, shading.lit ? &shading.surface : nullptr, result);
    } catch (const std::bad_alloc&) {
        result = outOfMemory();
        return true;
    }
}

void OffscreenRenderer::endKeptOffer()
{
    m_impl->withdrawOffer();
}

void OffscreenRenderer::offerLoop(const MeshView& mesh, bool textured)
{
    if (mesh.serial != 0 && m_impl->m_inFrame && !m_impl->opaqueFill(textured))
        m_impl->offerLoop(Impl::LoopOffer{mesh.serial, mesh.triangles, mesh.vertexCount, mesh.triangleCount});
}

std::uint64_t OffscreenRenderer::contextsMade()
{
    return g_contextsMade.load(std::memory_order_relaxed);
}

const std::uint8_t* OffscreenRenderer::pixels() const
{
    return m_impl->m_width == 0 ? nullptr : m_impl->m_image.data();
}

} // namespace q3
