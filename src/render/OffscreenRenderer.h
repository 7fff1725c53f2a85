// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "base/Primitives.h"
#include "base/RenderTarget.h"
#include "render/GlContext.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace q3
{

/// Draws points, lines and filled triangles into its own RGBA8 image, headless.
/// One per QuickDraw 3D view. This header is deliberately free of OpenGL: the
/// implementation (OffscreenRenderer.cpp) draws through a GlContext of the
/// backend it was made for: OSMesa or EGL, with llvmpipe (same pixels) or
/// EGL on a GPU.
///
/// A frame is beginFrame(), any number of setMatrix() and draw calls, then
/// endFrame(); afterwards pixels() holds the finished image. Draw calls only
/// copy their vertices into a CPU-side batch; the batch is handed to OpenGL in
/// a few multi-draw calls at endFrame() (or when it grows past a threshold),
/// so the cost per call is a copy, not an OpenGL round trip.
///
/// Primitives are painted in submission order, later ones over earlier ones,
/// unless the frame has the depth test (FrameOptions); only translucent
/// triangles blend (OpacitySetup), drawn last, sorted back to front, at
/// endFrame(); lines are 1 pixel wide, aliased.
///
/// Threads: the renderer's OpenGL context is current on the calling thread
/// only inside beginFrame() (the first time, or when the size changes),
/// inside endFrame(), and inside a draw call that flushes a full batch. On
/// return from each of these, whatever context of the backend the thread had
/// current before is current again, or none (for EGL: the context of the
/// client API bound before). Hence separate renderers may render on
/// separate threads at the same time, and frames of two renderers may even be
/// interleaved on one thread. One renderer must not be used by two threads at
/// once.
///
/// Invariant: outside a frame the batch is empty and no OpenGL context is
/// held; pixels() has width() * height() * 4 bytes, valid after a
/// successful endFrame() that did not draw in place (drewInPlace).
class OffscreenRenderer final : public RenderTarget
{
public:
    /// Draws with the backend Q3_RENDER_BACKEND chooses (chooseGlBackend);
    /// when that choice fails, beginFrame reports why (kContextFailure).
    OffscreenRenderer();
    /// Draws with `backend`.
    explicit OffscreenRenderer(GlBackend backend);
    ~OffscreenRenderer() override;
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    /// Starts a frame on an image of width x height pixels. The pane is the
    /// part of the image the view draws into (y measured from the top): its
    /// pixels are cleared to clearColor and the viewport maps clip space onto
    /// it; pixels outside the pane become (0, 0, 0, 0). The pane may extend
    /// beyond the image (that part is simply not stored). The matrix is reset
    /// to identity. The image is made by the first frame and by a frame of a
    /// new size. The OpenGL context is the process's, not the renderer's: a
    /// frame takes an idle one of its backend and size (the one this
    /// renderer drew its last frame with, if no other renderer took it) and
    /// endFrame or cancelFrame gives it back, with its compiled programs and
    /// kept textures; only a frame begun while every such context is in a
    /// frame makes a new one (contextsMade).
    /// Errors: kWrongState if a frame is open; kInvalidArgument if width or
    /// height is 0 or above the implementation limit (16384 for llvmpipe),
    /// the pane is empty, wider or taller than 16384 or has its origin
    /// beyond +-16384, or a colour channel is NaN/infinite;
    /// kOutOfMemory; kContextFailure if the backend was chosen wrongly
    /// (Q3_RENDER_BACKEND, Q3_EGL_DEVICE), is missing or refuses a context;
    /// kWrongRenderer if it is not llvmpipe (except EGL on a GPU; see
    /// GlContext.cpp for the pinned Mesa settings).
    RenderResult beginFrame(std::uint32_t width, std::uint32_t height, const RgbaColor& clearColor,
                            const PixelRect& pane, const FrameOptions& options = FrameOptions{}) override;

    /// Sets the matrix for the following draw calls: it maps the caller's 3D
    /// points straight to OpenGL clip space (homogeneous, before the divide).
    /// Convention: QuickDraw 3D's row-vector form, p' = p * M, with the 16
    /// values in row-major order m[row * 4 + column], exactly the memory
    /// layout of a TQ3Matrix4x4. (That memory is also OpenGL's column-major
    /// layout of the column-vector matrix M^T, so it is passed to OpenGL
    /// as is.) Doubles are rounded to float, as OpenGL stores matrices.
    /// Errors: kWrongState outside a frame; kInvalidArgument if m is NULL or
    /// holds NaN/infinity (the previous matrix stays).
    RenderResult setMatrix(const float m[16]) override;
    RenderResult setMatrix(const double m[16]) override;

    /// Draws a mesh as RenderTarget::draw says, through the primitive calls
    /// below.
    RenderResult draw(const MeshView& mesh, const Shading& shading) override;

    // The backend's primitive calls, which draw() is made of (and its unit
    // tests call directly): not part of RenderTarget.

    /// Draws one connected polyline through `count` points (xyz: 3 floats per
    /// point, tightly packed). Fewer than 2 points draw nothing.
    RenderResult drawLineStrip(const float* xyz, std::size_t count, const RgbColor& color);
    /// Draws count / 2 separate segments; count must be even.
    RenderResult drawLines(const float* xyz, std::size_t count, const RgbColor& color);
    /// Draws count square points of pointSize pixels (aliased; OpenGL clamps
    /// the size to its range, 1..255 for llvmpipe).
    RenderResult drawPoints(const float* xyz, std::size_t count, const RgbColor& color,
                            float pointSize = 1.0f);
    /// Draws count / 3 filled, unlit, single-coloured triangles (both faces);
    /// count must be a multiple of 3.
    /// Errors (all four draw calls): kWrongState outside a frame;
    /// kInvalidArgument if xyz is NULL while count > 0, a count does not fit
    /// the primitive, any coordinate or colour channel is NaN/infinite, or
    /// pointSize is not a positive finite number; kOutOfMemory; and, if the
    /// call flushed a full batch, the endFrame() errors. On error nothing of
    /// the call is drawn.
    RenderResult drawTriangles(const float* xyz, std::size_t count, const RgbColor& color);

    /// Draws indexed primitives over a pool of vertexCount vertices: xyz
    /// holds 3 floats per vertex, rgb 3 per vertex or is null (then every
    /// vertex is `color`). Each index refers to the pool; indexCount must fit
    /// the mode (even for lines, a multiple of 3 for triangles; a line strip
    /// is not accepted). With smooth, colours are interpolated across each
    /// line and triangle; without, each takes the colour of its last vertex.
    /// Errors: those of the calls above, and kInvalidArgument for an index
    /// not below vertexCount or a non-finite rgb value.
    /// With st (2 floats per vertex) and a current texture (setTexture),
    /// triangles are textured: each pixel is its interpolated colour times
    /// the texel (OpenGL's modulate); st is ignored for other primitives or
    /// without a texture. Errors also: kInvalidArgument for a non-finite st.
    RenderResult drawElements(DrawMode mode, const float* xyz, const float* rgb, std::size_t vertexCount,
                              const std::uint32_t* indices, std::size_t indexCount, const RgbColor& color, bool smooth,
                              const float* st = nullptr);
    /// Draws count consecutive vertices as one primitive list (or one line
    /// strip), with per-vertex colours as drawElements.
    RenderResult drawArrays(DrawMode mode, const float* xyz, const float* rgb, std::size_t count, const RgbColor& color,
                            bool smooth);

    /// Draws the set bits of `image` as pixels of `color`, parallel to the
    /// pane, placed by the image of `anchor` (3 floats) under the current
    /// matrix and depth-tested (when the frame is) at its depth. Nothing is
    /// drawn when the anchor is behind the eye or outside the depth range;
    /// bits outside the pane are skipped, so the work is at most the pane's
    /// pixels. Errors: kWrongState outside a frame; kInvalidArgument for a
    /// NULL anchor, NULL bits with a non-empty image, rowBytes too small for
    /// the width, or a non-finite anchor or colour; kOutOfMemory.
    RenderResult drawBitmap(const float* anchor, const BitmapImage& image, const RgbColor& color) override;
    /// Draws `image` as drawBitmap draws a bitmap's set bits, each pixel in
    /// its own colour, unlit; only the pixels inside the pane are decoded.
    /// Errors: kWrongState outside a frame; kInvalidArgument for a NULL
    /// anchor or pixels, an invalid layout or a non-finite anchor;
    /// kOutOfMemory.
    RenderResult drawPixmap(const float* anchor, const PixmapImage& image) override;

    /// The lights for the frame's lit draws (kWrongState outside a frame;
    /// kInvalidArgument for more than kMaxLights or a non-finite value).
    RenderResult setLighting(const LightingSetup& lighting) override;
    /// How the following triangles are rasterized (kWrongState outside a
    /// frame).
    RenderResult setFaceOptions(const FaceOptions& faces) override;
    RenderResult setAntiAlias(const AntiAliasOptions& options) override;
    /// Draws indexed triangles lit by the frame's lights as `shading` says:
    /// normals holds a unit normal per vertex (3 floats, local coordinates),
    /// rgb the diffuse colours (or null: `color`). Errors as drawElements,
    /// and kInvalidArgument for a non-finite normal or shading value.
    /// With st and a current texture, the texel takes the place of the
    /// diffuse colour Od: lit at the vertices, a pixel is the interpolated
    /// ambient and diffuse light (computed with rgb, clamped to 0..1) times
    /// the texel plus the interpolated specular light; lit at every pixel,
    /// the equations are evaluated with Od = rgb times the texel.
    RenderResult drawLitTriangles(const float* xyz, const float* normals, const float* rgb, std::size_t vertexCount,
                                  const std::uint32_t* indices, std::size_t indexCount, const RgbColor& color,
                                  const SurfaceShading& shading, const float* st = nullptr);

    /// The texture for the following draws that pass texture coordinates
    /// (null: none): addTexture, then useTexture. The image is decoded and
    /// copied now, so the caller's pixels may go away after the call.
    /// Errors: kWrongState outside a frame; kInvalidArgument for NULL pixels
    /// or an invalid layout (the current texture is then none); kOutOfMemory.
    RenderResult setTexture(const TextureImage* texture);

    /// Keeps a texture for the rest of the frame and sets `id` to its
    /// number for useTexture; the current texture does not change. The image
    /// is decoded and copied now (the caller's pixels may go away after the
    /// call) and uploaded to OpenGL once, when a draw first uses it, however
    /// often the frame switches to it. Errors: kWrongState outside a frame;
    /// kInvalidArgument for NULL pixels or an invalid layout; kOutOfMemory
    /// (id is then unchanged).
    RenderResult addTexture(const TextureImage& texture, std::uint32_t& id) override;
    /// Makes texture `id` of this frame (addTexture) the one for the
    /// following draws that pass texture coordinates, or none with
    /// kNoTexture. Errors: kWrongState outside a frame; kInvalidArgument for
    /// an id this frame has not given (the current texture is unchanged).
    RenderResult useTexture(std::uint32_t id);

    /// The fog of the following draws (RenderTarget::setFog).
    RenderResult setFog(const FogSetup& fog) override;
    /// The opacity of the following filled triangles
    /// (RenderTarget::setOpacity).
    RenderResult setOpacity(const OpacitySetup& opacity);

    /// Renders everything batched since beginFrame() and stores the image.
    /// Errors: kWrongState if no frame is open; kContextFailure;
    /// kGraphicsError if OpenGL reported an error. The frame is closed even
    /// on failure (pixels() is then unspecified).
    RenderResult endFrame() override;

    /// Discards an open frame without rendering it (no effect otherwise);
    /// pixels() is unspecified until the next successful endFrame().
    void cancelFrame() override;

    bool inFrame() const override;
    std::uint32_t width() const override;
    std::uint32_t height() const override;
    /// Bytes from one row to the next: always width() * 4 (tightly packed).
    std::size_t rowBytes() const override;
    /// RGBA8 pixels, R first in memory, top row first; null before the first frame.
    const std::uint8_t* pixels() const override;
    /// Whether the last frame went into FrameOptions::bgraImage: it does
    /// whenever one is offered for a pane that is the whole image (OSMesa
    /// draws there with a context of B, G, R, A layout; EGL reads back
    /// there in that layout).
    bool drewInPlace() const override;

    /// How many OpenGL contexts this process's renderers have made so far.
    static std::uint64_t contextsMade();
    /// How many of this renderer's draws drew a retained mesh's filled
    /// triangles from vertex data its context kept from an earlier frame
    /// (OffscreenRenderer.cpp, StaticKey), for tests.
    std::uint64_t keptDraws() const;
    /// How many translucent triangles this renderer drew in their own
    /// order, unsorted, because no two of them could cover one sample
    /// (render/SingleCover.h), for tests.
    std::uint64_t translucentInOrder() const;
    /// For tests: the most vertices and indices this renderer keeps in its
    /// context (at least 1 each; 2^20 and 2^22 unless set), so that a test
    /// reaches the limits with small meshes.
    void setKeptLimits(std::size_t vertices, std::size_t indices);

private:
    class Impl;
    std::unique_ptr<Impl> m_impl;
    // draw() (OffscreenRendererDraw.cpp): a mesh's primitives as the calls
    // above take them; the arrays keep their capacity from draw to draw.
    RenderResult drawSegments(const MeshView& mesh, const Shading& shading, const std::uint32_t* pairs,
                              std::size_t count);
    RenderResult drawFilled(const MeshView& mesh, const Shading& shading);
    // Draws the filled triangles of a mesh with a serial from the vertex
    // data its context kept (true, the outcome in `result`), else offers
    // the draw that follows to be kept (false).
    bool drawKept(const MeshView& mesh, const Shading& shading, bool textured, RenderResult& result);
    // Withdraws an offer the draw did not take.
    void endKeptOffer();
    // Offers a translucent mesh with a serial to the draw that follows, to
    // be drawn unsorted where that gives the pixels of the sorted order
    // (OffscreenRenderer.cpp, placeInOrder); endKeptOffer withdraws it.
    void offerLoop(const MeshView& mesh, bool textured);
    RenderResult drawLit(const MeshView& mesh, const Shading& shading, const float* st);
    std::vector<float> m_scratch;
    std::vector<std::uint32_t> m_indices;
    std::vector<float> m_normals;
    std::vector<float> m_litPositions;
    std::vector<float> m_litColors;
    std::vector<float> m_litST;
    std::vector<float> m_litOpacity;
    std::vector<float> m_uvST; // drawFilled: Shading::uvs through the uv transform
};

} // namespace q3
