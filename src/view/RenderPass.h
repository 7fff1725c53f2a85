// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/Primitives.h"
#include "light/Light.h"
#include "render/OffscreenRenderer.h"
#include "view/Pass.h"

#include <optional>
#include <vector>

namespace q3 {

/// Turns a failed render/ call into the QuickDraw 3D error the view posts:
/// kOutOfMemory -> kQ3ErrorOutOfMemory, kInvalidArgument ->
/// kQ3ErrorInvalidParameter, anything else -> kQ3ErrorRenderingLoopFailed.
/// `what` names the step for the message. Does nothing on success.
void throwIfFailed(const RenderResult& result, const char* what);

/// The row-vector matrix from QuickDraw 3D frustum coordinates (z from 0 at
/// hither to -1 at yon) to OpenGL clip coordinates (z from -w to w):
/// z_clip = -2 z - w; x, y and w are unchanged.
Matrix frustumToClip();

/// The view's lights and the camera's eye, in world coordinates, as a
/// rendering loop starts.
struct SceneLighting {
    std::vector<LightSource> lights;
    glm::dvec3 eye{0.0};
    bool orthographic = false;
    glm::dvec3 viewDirection{0.0, 0.0, -1.0};
};

/// How a renderer draws what geometries decompose into.
struct RenderStyle {
    /// Triangles filled (the interactive renderer) or drawn as their edges
    /// (the wireframe renderer).
    bool fillTriangles = false;
    SceneLighting lighting;
};

/// A traversal of a rendering loop: every geometry decomposes itself
/// (Geometry::decompose) into this pass, which draws the primitives into the
/// view's OffscreenRenderer frame. A vertex's colour is its own (after
/// inheritance from its face), else its geometry's attribute set's diffuse
/// colour, else the state's; colours given per vertex are interpolated.
/// Under a Lambert or Phong illumination shader, filled triangles are lit by
/// the view's lights (render/LitProgram.cpp gives the equations), with the
/// geometry's normals or, where it has none, its faces'; lines and points
/// are drawn in their colours. Under a texture shader, filled triangles
/// whose vertices all have a uv take their diffuse colour from its texture
/// (QD3DShader.h, Q3TextureShader_New). The styles apply as QD3DStyle.h says: fill
/// (filled, edges, points), backfacing (both, remove, flip), interpolation
/// (none: one colour per triangle, vertex, pixel), orientation (which
/// winding is the front), highlight (the highlight style's attributes over a
/// geometry whose highlight state is on).
/// Invariant: the target has a frame open for as long as the pass lives.
class RenderPass final : public Pass, private PrimitiveSink {
public:
    RenderPass(OffscreenRenderer& target, const Window& window, const AttributeValues& attributes,
               const RenderStyle& style)
        : Pass(window, attributes), m_target(target), m_style(style)
    {
    }

    void visitGeometry(const Geometry& geometry) override;

private:
    void draw(const MeshView& mesh, const AttributeSet* own) override;
    /// Hands the current local-to-clip matrix to the target if it changed.
    void loadMatrix();
    /// Hands the target the backfacing and orientation styles.
    void loadFaces();
    /// Draws pairs of indices as lines (uniform colour, or per vertex).
    void drawSegments(const MeshView& mesh, const float* rgb, const std::uint32_t* pairs, std::size_t count,
                      const RgbColor& color, const char* what);
    /// Every vertex of the mesh as a point.
    void drawVertices(const MeshView& mesh, const float* rgb, const RgbColor& color);
    /// The triangles as their edges (the mesh's, else every side).
    void drawTriangleEdges(const MeshView& mesh, const float* rgb, const RgbColor& color);
    /// The triangles lit under the state's illumination shader (textured
    /// with st, as textureCoordinates gives them, or not with null).
    void drawLit(const MeshView& mesh, const float* rgb, const RgbColor& color, const AttributeValues& attributes,
                 const float* st);
    /// Hands the target the state's texture if it is not the one loaded
    /// already; false when the state has none. Throws kQ3ErrorInvalidData
    /// when the texture's storage no longer holds its image.
    bool loadTexture();
    /// The texture coordinates of the mesh's vertices under the state's
    /// texture shader: each vertex's uv through the uv transform, v turned
    /// to run down the image; null (untextured) without a texture shader or
    /// when a vertex has no uv.
    const float* textureCoordinates(const MeshView& mesh);

    OffscreenRenderer& m_target;
    RenderStyle m_style;
    std::optional<Matrix> m_loaded;
    std::optional<FaceOptions> m_loadedFaces;
    bool m_lightsLoaded = false;
    std::vector<float> m_scratch;
    std::vector<float> m_colors;
    std::vector<float> m_normals;
    std::vector<float> m_litPositions;
    std::vector<float> m_litColors;
    std::vector<std::uint32_t> m_indices;
    std::vector<float> m_st;
    std::vector<float> m_litST;
    const void* m_loadedTexture = nullptr;
    unsigned long m_loadedTextureEdit = 0;
    bool m_loadedClampS = false;
    bool m_loadedClampT = false;
};

} // namespace q3
