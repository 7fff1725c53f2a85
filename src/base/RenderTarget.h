// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The one seam between the view and whatever draws its pixels. Every backend
// call is listed here once (Filament's DriverAPI.inc is the model): frame
// control (beginFrame, endFrame, cancelFrame, the finished image), state
// (matrix, lights, face options, anti-aliasing, textures, fog), one draw call
// for a mesh (draw: a MeshView and the Shading the view resolved for it,
// the backend deciding how to upload and draw it) and the two screen-space
// images that are not meshes (drawBitmap, drawPixmap). A backend
// (render/: OSMesa today) implements it; the view holds a RenderTarget made
// by makeRenderTarget() and never names the backend, so another one (or
// NullRenderTarget in the unit tests) can take its place.

#include "base/PixelConvert.h"
#include "base/Primitives.h"
#include "base/RenderResult.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace q3
{

/// A colour with float channels, nominally in [0, 1] (OpenGL clamps).
struct RgbColor {
    float r = 0.0f;
    float g = 0.0f;
    float b = 0.0f;
};

struct RgbaColor {
    float r = 0.0f;
    float g = 0.0f;
    float b = 0.0f;
    float a = 0.0f;
};

/// The primitive of a backend's drawElements or drawArrays call
/// (render/OffscreenRenderer.h).
enum class DrawMode { kPoints, kLines, kLineStrip, kTriangles };

/// What a frame is drawn with besides its size and pane.
struct FrameOptions {
    /// Hidden-surface removal: every primitive is depth-tested against what
    /// was drawn before it (a fragment is kept when it is no farther, so of
    /// two at the same depth the later wins, as without the test) and writes
    /// its depth. Without it primitives are painted in submission order.
    bool depthTest = false;
    /// Where the frame may be drawn straight into instead of the target's
    /// own image: the caller's image of the frame's width x height, rows
    /// `bgraRowBytes` apart (top row first), each pixel B, G, R, A bytes
    /// (QuickDraw 3D's ARGB32 pixmap in little-endian order). A target uses
    /// it only for a frame whose pane is the whole image and whose rows are
    /// whole pixels apart, and then says so (drewInPlace: the image holds
    /// exactly what pixels() would have, in that order); otherwise, or if
    /// it cannot, it ignores it. Null: not offered.
    std::uint8_t* bgraImage = nullptr;
    std::size_t bgraRowBytes = 0;
};

/// A 1-bit image drawn in screen space (a QuickDraw 3D marker): `height`
/// rows of `rowBytes` bytes, top row first; pixel x of a row is bit x % 8 of
/// byte x / 8, counted from the most significant bit unless lsbFirst. Its
/// top left pixel lies xOffset pixels right of and yOffset pixels below the
/// pixel its anchor projects to.
struct BitmapImage {
    const unsigned char* bits = nullptr;
    std::size_t rowBytes = 0;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    bool lsbFirst = false;
    long xOffset = 0;
    long yOffset = 0;
};

/// A colour image drawn in screen space (a QuickDraw 3D pixmap marker):
/// `pixels` laid out as `layout` says (base/PixelConvert.h). Its top left
/// pixel lies xOffset pixels right of and yOffset pixels below the pixel its
/// anchor projects to. Each pixel keeps its colour; one whose alpha is 0 is
/// not drawn, any other alpha is drawn opaque.
struct PixmapImage {
    const void* pixels = nullptr;
    PixmapLayout layout;
    long xOffset = 0;
    long yOffset = 0;
};

/// How a texture's texels are sampled (QuickDraw 3D's RAVE texture filter,
/// Q3InteractiveRenderer_SetRAVETextureFilter). With (s, t) a pixel's texture
/// coordinate and (u, v) = (s * width, t * height) in texels of an image:
///   kNearest:   the texel in column floor(u) and row floor(v);
///   kBilinear:  the four texels around (u - 1/2, v - 1/2), weighted by the
///               fractions of those coordinates (OpenGL's GL_LINEAR);
///   kTrilinear: bilinear in the two images around the level of detail
///               lambda = log2 of the larger rate at which u or v changes per
///               pixel, mixed by lambda's fraction (GL_LINEAR_MIPMAP_LINEAR;
///               below lambda 0, bilinear in the first image).
/// kNearest and kBilinear read the first image only.
enum class TextureFilter { kNearest, kBilinear, kTrilinear };

/// One image of a texture: `pixels` laid out as `layout` says
/// (base/PixelConvert.h), row 0 at the top.
struct TextureLevel {
    const void* pixels = nullptr;
    PixmapLayout layout;
};

/// A texture for filled triangles (a QuickDraw 3D texture shader's image):
/// `pixels` laid out as `layout` says (base/PixelConvert.h), row 0 at the
/// top. A triangle vertex's texture coordinate (s, t) is sampled as `filter`
/// says, t counted down from the top row; outside 0..1 a coordinate wraps
/// (repeats) or, when clamped, takes the edge texel. `mipmaps` holds the
/// smaller images of a mipmap chain after this one, image i (from 1) being
/// max(1, width >> i) x max(1, height >> i), down to 1 x 1; kTrilinear uses
/// them (without them it is kBilinear). The texel's alpha multiplies the
/// triangle's opacity (OpacitySetup).
struct TextureImage {
    const void* pixels = nullptr;
    PixmapLayout layout;
    bool clampS = false;
    bool clampT = false;
    TextureFilter filter = TextureFilter::kNearest;
    std::vector<TextureLevel> mipmaps;
    /// Empty, or what the bytes of every level are known by: two textures
    /// with the same non-empty key and the same layouts have the same bytes,
    /// so the target need not compare them (a key names an unchanged source,
    /// such as a storage's version and each level's offset in it).
    std::vector<std::uint64_t> sourceKey;
};

/// The most lights a frame is lit by (kQ3ViewMaxLights).
constexpr std::size_t kMaxLights = 32;

/// A light for lit drawing, in world coordinates.
struct RenderLight {
    enum class Kind { kAmbient, kDirectional, kPoint, kSpot };
    Kind kind = Kind::kAmbient;
    float color[3] = {0.0f, 0.0f, 0.0f};      ///< colour times brightness; zero for a light that is off
    float position[3] = {0.0f, 0.0f, 0.0f};   ///< point and spot
    float direction[3] = {0.0f, 0.0f, -1.0f}; ///< directional and spot: unit, the way the light travels
    int attenuation = 0;                      ///< 0 none, 1 by 1/d, 2 by 1/d^2 (point and spot)
    float hotAngle = 0.0f;                    ///< spot: half-angles, radians
    float outerAngle = 0.0f;
    int fallOff = 0; ///< spot, between the angles: 0 none, 1 linear, 2 exponential, 3 cosine
};

/// The lights of a frame and where the eye is, in world coordinates.
struct LightingSetup {
    std::vector<RenderLight> lights; ///< at most kMaxLights
    float eye[3] = {0.0f, 0.0f, 0.0f};
    bool orthographic = false;
    float viewDirection[3] = {0.0f, 0.0f, -1.0f}; ///< unit, the way the camera looks
};

/// How the triangles of one lit draw are shaded (QuickDraw 3D's illumination
/// shaders, QD3DShader.h): for a point p with unit normal N and diffuse
/// colour Od, ambient light Ia and lights Ii (each attenuated by f),
///   Lambert: ka Ia Od + sum_i f Ii Od (N . Li)          (N . Li > 0)
///   Phong:   Lambert + sum_i f Ii Os (Ri . V)^n         (N . Li > 0)
/// with Li the unit vector towards light i, Ri its reflection about N, V the
/// unit vector towards the eye, ka the ambient coefficient, Os the specular
/// colour and n the specular control.
struct SurfaceShading {
    float localToWorld[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; ///< as setMatrix's layout
    int illumination = 1;                                                      ///< 1 Lambert, 2 Phong
    float ambientCoefficient = 1.0f;
    float specularColor[3] = {0.5f, 0.5f, 0.5f};
    float specularControl = 4.0f;
    /// 0: one colour per triangle (its last vertex's); 1: lit at the vertices
    /// and interpolated; 2: lit at every pixel from interpolated normals.
    int interpolation = 1;
    /// Back faces are lit with their normal reversed.
    bool flipBackFaces = false;
};

/// How triangles are rasterized: back faces dropped or not, and which
/// winding is the front.
struct FaceOptions {
    bool cullBack = false;
    bool clockwiseFront = false;
    bool operator==(const FaceOptions& other) const
    {
        return cullBack == other.cullBack && clockwiseFront == other.clockwiseFront;
    }
};

/// Which of the following draws are anti-aliased (QuickDraw 3D's
/// anti-alias style): points and lines (the edges mode), filled triangles
/// (the filled mode). An anti-aliased primitive is rasterized at
/// kAntiAliasSamples sample points in every pixel, each covered sample
/// taking its colour and depth, and the pixel is the mean of its samples
/// (OpenGL multisampling). Only those draws are: the others give exactly
/// the pixels they give in a frame without anti-aliasing, before and after
/// the anti-aliased ones, and are hidden by them where these are nearer
/// (a pixel's depth after an anti-aliased draw is one of its samples').
struct AntiAliasOptions {
    bool lines = false;
    bool triangles = false;
    bool operator==(const AntiAliasOptions& other) const
    {
        return lines == other.lines && triangles == other.triangles;
    }
};

/// The samples per pixel of anti-aliased drawing, whatever the style's
/// quality: llvmpipe multisamples with 4 and no other count (GL_MAX_SAMPLES
/// is 4, and 4 is the one count GL_SAMPLES lists for RGBA8).
constexpr int kAntiAliasSamples = 4;

/// Fog for the following draws (QD3DStyle.h's fog style). A pixel at
/// eye-space distance z (the distance from the camera plane along the
/// viewing direction) keeps the fraction f of its colour and takes 1 - f of
/// `color`: linear (end - z) / (end - start), exponential exp(-density z),
/// exponential-squared exp(-(density z)^2), each clamped to 0..1; alpha: the
/// pixel's own alpha. Alpha is not fogged. z comes from the clip
/// coordinates c that setMatrix maps a point to, as
/// (c . depthPlane) / (c . wPlane), which holds for every point drawn
/// whatever its matrix (a clip point is the world point times one fixed
/// world-to-clip matrix, so both planes are that matrix's inverse applied
/// to the eye's plane and to w).
struct FogSetup {
    enum class Mode { kOff, kLinear, kExponential, kExponentialSquared, kAlpha };
    Mode mode = Mode::kOff;
    float start = 1.0f;
    float end = 1000.0f;
    float density = 1.0f;
    float color[3] = {1.0f, 1.0f, 1.0f};
    float depthPlane[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    float wPlane[4] = {0.0f, 0.0f, 0.0f, 1.0f};
};

/// The opacity of the vertices of a draw's filled triangles (its Shading;
/// the backend's setOpacity), per colour channel: QuickDraw 3D's
/// transparency colour T. `rgb` holds r g b per vertex (`count` vertices,
/// 3 * count floats), or is null, when every vertex has `uniform`. 1 is
/// opaque, 0 invisible; each channel of the triangle's pixels is blended over
/// what is behind it as (the QD3D Book's rule)
///     result.c = t.c * colour.c + (1 - t.c) * behind.c     for c = r, g, b
///     result.alpha = a + (1 - a) * behind.alpha,  a = (t.r + t.g + t.b) / 3
/// with t the interpolated opacity times the texel's alpha. Triangles with
/// a vertex below 1 in some channel, or textured with a texture that has a
/// texel below 1, are translucent: they are drawn after every opaque
/// primitive of the frame, sorted back to front by the depth of their
/// centres (in clip space under their own matrix), depth-tested but without
/// writing depth. Where such a texture's texel is opaque (alpha 1) on an
/// opaque triangle, the pixel is drawn with the opaque primitives and writes
/// depth (an alpha test), so cut-outs hide what lies behind them exactly.
/// Translucent lit triangles are lit by the frame's lights as they are at
/// endFrame (the view sets them once per frame). Lines and points are drawn
/// opaque.
struct OpacitySetup {
    const float* rgb = nullptr;
    std::size_t count = 0;
    RgbColor uniform{1.0f, 1.0f, 1.0f};
};

/// Shading's "no texture".
constexpr std::uint32_t kNoTexture = 0xFFFFFFFFu;

/// How RenderTarget::draw draws one mesh: what the view resolved from its
/// state and the geometry's attributes, so that the backend needs nothing
/// else. The arrays hold one entry per vertex of the mesh drawn, and are
/// read during the call only.
struct Shading {
    /// How the mesh's triangles are drawn (QuickDraw 3D's fill style, with
    /// the wireframe renderer's edges for filled): filled; as their edges
    /// (MeshView::edges, else every side of every triangle); or every vertex
    /// of the mesh as a point.
    enum class Fill { kFilled, kEdges, kPoints };
    Fill fill = Fill::kFilled;
    /// A mesh without triangles draws its edges (the wireframe renderer).
    bool edgesAlone = false;
    /// The colour of every vertex (r g b per vertex), or null for `color`.
    const float* rgb = nullptr;
    RgbColor color{1.0f, 1.0f, 1.0f};
    /// Unlit filled triangles: colours interpolated across each, or the
    /// colour of its last vertex. (Lines interpolate per-vertex colours;
    /// points never do.)
    bool smooth = true;
    /// Filled triangles lit by the frame's lights (setLighting) as
    /// `surface` says, with the mesh's normals (unit length after
    /// normalizing; a vertex whose normal is NaN, or every vertex under
    /// flat interpolation, takes its triangle's face normal, turned to the
    /// side clockwiseFront names the front, or for flat interpolation to
    /// the side its vertices' normals point to); otherwise unlit.
    /// Lit at the vertices, a textured pixel is the interpolated ambient
    /// and diffuse light (computed with the colour, clamped to 0..1) times
    /// the texel plus the interpolated specular light; lit at every pixel,
    /// the equations are evaluated with Od = colour times the texel.
    bool lit = false;
    SurfaceShading surface;
    bool clockwiseFront = false;
    /// Filled triangles textured with texture `texture` (addTexture) at
    /// these coordinates (s t per vertex, t down from the image's top row),
    /// each pixel its colour times the texel (OpenGL's modulate); null or
    /// kNoTexture: untextured.
    const float* st = nullptr;
    std::uint32_t texture = kNoTexture;
    /// Instead of `st` (which wins when both are set): the mesh's own uvs
    /// (u v per vertex, every one finite), from which the backend computes
    /// the coordinates itself with `stTransform`, exactly as
    /// s = u m[0] + v m[2] + m[4], t = 1 - (u m[1] + v m[3] + m[5]) in
    /// float; so a backend drawing a mesh from the vertex data it kept need
    /// not compute them at all.
    const float* uvs = nullptr;
    /// The uv transform `st` was computed with from the mesh's uvs, or
    /// `uvs` are to be (the first two columns of QuickDraw 3D's 3 x 3
    /// matrix, row by row: s and t of (u, v, 1) times it, before t is
    /// counted down): with the mesh's serial (MeshView::serial) and the
    /// other fields here, it says all that the arrays were derived from, so
    /// that a backend may keep its vertex data for a mesh drawn again the
    /// same way.
    float stTransform[6] = {1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f};
    /// The opacity of the filled triangles' vertices (OpacitySetup: `rgb`
    /// null or r g b per vertex of the mesh).
    OpacitySetup opacity;
};

/// Draws points, lines, filled triangles and screen-space images into an
/// RGBA8 image of its own, one per QuickDraw 3D view.
///
/// A frame is beginFrame(), any number of state and draw calls, then
/// endFrame(); afterwards pixels() holds the finished image. Primitives are
/// painted in submission order, later ones over earlier ones, unless the
/// frame has the depth test (FrameOptions); only translucent triangles
/// blend (OpacitySetup); lines are 1 pixel wide, aliased. The calls neither throw nor post errors: each
/// returns a RenderResult and the view decides what it becomes.
///
/// Invariant: pixels() has width() * height() * 4 bytes, valid after a
/// successful endFrame(). One target must not be used by two threads at once.
class RenderTarget
{
public:
    RenderTarget() = default;
    virtual ~RenderTarget() = default;
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;

    /// Starts a frame on an image of width x height pixels. The pane is the
    /// part of the image the view draws into (y measured from the top): its
    /// pixels are cleared to clearColor and the viewport maps clip space onto
    /// it; pixels outside the pane become (0, 0, 0, 0). The pane may extend
    /// beyond the image (that part is simply not stored). The matrix is reset
    /// to identity. The first frame, or a frame of a new size, creates the
    /// OpenGL context and image; frames of an unchanged size reuse both.
    /// Errors: kWrongState if a frame is open; kInvalidArgument if width or
    /// height is 0 or above the implementation limit (16384 for llvmpipe),
    /// the pane is empty, wider or taller than 16384 or has its origin
    /// beyond +-16384, or a colour channel is NaN/infinite;
    /// kOutOfMemory; kContextFailure or kWrongRenderer if no llvmpipe context
    /// could be made (see the .cpp for the pinned Mesa settings).
    virtual RenderResult beginFrame(std::uint32_t width, std::uint32_t height, const RgbaColor& clearColor,
                                    const PixelRect& pane, const FrameOptions& options = FrameOptions{}) = 0;

    /// Sets the matrix for the following draw calls: it maps the caller's 3D
    /// points straight to OpenGL clip space (homogeneous, before the divide).
    /// Convention: QuickDraw 3D's row-vector form, p' = p * M, with the 16
    /// values in row-major order m[row * 4 + column], exactly the memory
    /// layout of a TQ3Matrix4x4. (That memory is also OpenGL's column-major
    /// layout of the column-vector matrix M^T, so it is passed to OpenGL
    /// as is.) Doubles are rounded to float, as OpenGL stores matrices.
    /// Errors: kWrongState outside a frame; kInvalidArgument if m is NULL or
    /// holds NaN/infinity (the previous matrix stays).
    virtual RenderResult setMatrix(const float m[16]) = 0;
    virtual RenderResult setMatrix(const double m[16]) = 0;

    /// Draws a mesh under the current matrix as `shading` says (Shading): its
    /// triangles as the fill style says, then its lines, line strips and
    /// points; edges only under Shading::edgesAlone when it has no
    /// triangles. Bitmaps and pixmaps of the view are not drawn (drawBitmap,
    /// drawPixmap). The arrays are read during the call only.
    /// Errors: kWrongState outside a frame; kInvalidArgument for a NULL
    /// positions array with vertices, an index not below vertexCount, a
    /// NaN or infinite coordinate, colour, normal, texture coordinate or
    /// shading value, an opacity array of another length than vertexCount,
    /// an opacity outside 0..1, or a texture id this frame has not given;
    /// kOutOfMemory; and, if the call flushed a full batch, the endFrame()
    /// errors. On error what the call drew before the failing primitive
    /// may stay.
    virtual RenderResult draw(const MeshView& mesh, const Shading& shading) = 0;

    /// Draws the set bits of `image` as pixels of `color`, parallel to the
    /// pane, placed by the image of `anchor` (3 floats) under the current
    /// matrix and depth-tested (when the frame is) at its depth. Nothing is
    /// drawn when the anchor is behind the eye or outside the depth range;
    /// bits outside the pane are skipped, so the work is at most the pane's
    /// pixels. Errors: kWrongState outside a frame; kInvalidArgument for a
    /// NULL anchor, NULL bits with a non-empty image, rowBytes too small for
    /// the width, or a non-finite anchor or colour; kOutOfMemory.
    virtual RenderResult drawBitmap(const float* anchor, const BitmapImage& image, const RgbColor& color) = 0;
    /// Draws `image` as drawBitmap draws a bitmap's set bits, each pixel in
    /// its own colour, unlit; only the pixels inside the pane are decoded.
    /// Errors: kWrongState outside a frame; kInvalidArgument for a NULL
    /// anchor or pixels, an invalid layout or a non-finite anchor;
    /// kOutOfMemory.
    virtual RenderResult drawPixmap(const float* anchor, const PixmapImage& image) = 0;

    /// The lights for the frame's lit draws (kWrongState outside a frame;
    /// kInvalidArgument for more than kMaxLights or a non-finite value).
    virtual RenderResult setLighting(const LightingSetup& lighting) = 0;
    /// How the following triangles are rasterized (kWrongState outside a
    /// frame).
    virtual RenderResult setFaceOptions(const FaceOptions& faces) = 0;
    /// Which of the following draws are anti-aliased (none at beginFrame;
    /// AntiAliasOptions). Errors: kWrongState outside a frame.
    virtual RenderResult setAntiAlias(const AntiAliasOptions& options) = 0;
    /// Shading's "no texture" (kept here for the backend's own calls).
    static constexpr std::uint32_t kNoTexture = q3::kNoTexture;
    /// Keeps a texture for the rest of the frame and sets `id` to its
    /// number for Shading::texture; the current texture does not change. The image
    /// (with its mipmaps) is decoded and copied now (the caller's pixels may
    /// go away after the call) and uploaded to OpenGL once, when a draw first
    /// uses it, however often the frame switches to it. Errors: kWrongState
    /// outside a frame; kInvalidArgument for NULL pixels or an invalid layout
    /// (of any image), a mipmap chain whose sizes do not halve down to 1 x 1
    /// or a filter outside TextureFilter; kOutOfMemory (id is then
    /// unchanged).
    virtual RenderResult addTexture(const TextureImage& texture, std::uint32_t& id) = 0;
    /// The fog of the following draws (FogSetup). Errors: kWrongState
    /// outside a frame; kInvalidArgument for an unknown mode or a NaN or
    /// infinite value, a negative density or, for linear fog, start not
    /// below end (the fog stays as it was).
    virtual RenderResult setFog(const FogSetup& fog) = 0;
    /// Renders everything batched since beginFrame() and stores the image.
    /// Errors: kWrongState if no frame is open; kContextFailure;
    /// kGraphicsError if OpenGL reported an error. The frame is closed even
    /// on failure (pixels() is then unspecified).
    virtual RenderResult endFrame() = 0;

    /// Discards an open frame without rendering it (no effect otherwise);
    /// pixels() is unspecified until the next successful endFrame().
    virtual void cancelFrame() = 0;

    virtual bool inFrame() const = 0;
    virtual std::uint32_t width() const = 0;
    virtual std::uint32_t height() const = 0;
    /// Bytes from one row to the next: always width() * 4 (tightly packed).
    virtual std::size_t rowBytes() const = 0;
    /// RGBA8 pixels, R first in memory, top row first; null before the first frame.
    virtual const std::uint8_t* pixels() const = 0;
    /// Whether the last successful frame went into FrameOptions::bgraImage
    /// (pixels() is then unspecified).
    virtual bool drewInPlace() const { return false; }
};

/// A new target of the backend the library was built with (render/ defines
/// it). Never null; a backend that cannot start reports so at beginFrame.
std::unique_ptr<RenderTarget> makeRenderTarget();

/// Prepares the backend once per process before any target is made
/// (Q3Initialize calls it; render/ defines it). Safe to call again.
void initializeRenderBackend();

} // namespace q3
