// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "base/Primitives.h"
#include "light/Light.h"
#include "base/RenderTarget.h"
#include "view/Pass.h"

#include <optional>
#include <vector>

namespace q3 {

/// Turns a failed RenderTarget call into the QuickDraw 3D error the view posts:
/// kOutOfMemory -> kQ3ErrorOutOfMemory, kInvalidArgument ->
/// kQ3ErrorInvalidParameter, anything else -> kQ3ErrorRenderingLoopFailed.
/// `what` names the step for the message. Does nothing on success.
void throwIfFailed(const RenderResult& result, const char* what);

/// The row-vector matrix from QuickDraw 3D frustum coordinates (z from 0 at
/// hither to -1 at yon) to the render target's clip coordinates (z from -w to w):
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
    /// How textures are sampled (the interactive renderer's RAVE texture
    /// filter); trilinear reads a mipmap texture's whole chain.
    TextureFilter textureFilter = TextureFilter::kNearest;
};

/// A traversal of a rendering loop: every geometry decomposes itself
/// (Geometry::decompose) into this pass, which resolves what each mesh is
/// drawn with (colours, opacity, texture, illumination, fill style: a
/// Shading) and hands the mesh to the view's RenderTarget frame, one draw per
/// surface shader of its filled triangles and one for the rest; the target
/// decides how to draw it. A vertex's colour is its own (after
/// inheritance from its face), else its geometry's attribute set's diffuse
/// colour, else the state's; colours given per vertex are interpolated.
/// Under a Lambert or Phong illumination shader, filled triangles are lit by
/// the view's lights (RenderTarget.h, SurfaceShading, gives the equations), with the
/// geometry's normals or, where it has none, its faces'; lines and points
/// are drawn in their colours. Under a texture shader, filled triangles
/// whose vertices all have a uv take their diffuse colour from its texture
/// (QD3DShader.h, Q3TextureShader_New). The texture shader of a triangle is
/// the highlight style's surface shader where the geometry is highlighted,
/// else the one its own attribute sets give it (MeshView::triangleShaders),
/// else its geometry's attribute set's, else the view's (submitted as a
/// shader or in an attribute set, whichever came later); each texture is
/// handed to the target once per frame. The styles apply as QD3DStyle.h says: fill
/// (filled, edges, points), backfacing (both, remove, flip), interpolation
/// (none: one colour per triangle, vertex, pixel), orientation (which
/// winding is the front), highlight (the highlight style's attributes over a
/// geometry whose highlight state is on).
/// Invariant: the target has a frame open for as long as the pass lives.
class RenderPass final : public Pass, private PrimitiveSink {
public:
    RenderPass(RenderTarget& target, const Window& window, const AttributeValues& attributes,
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
    /// Hands the target the anti-alias style (once it differs from none).
    void loadAntiAlias();
    /// Hands the target the state's fog style if it changed.
    void loadFog();
    /// The opacity of the mesh's vertices (m_opacity): each vertex's
    /// transparency colour, else the attributes' (the highlight's over all
    /// where it has one), as the mean of its three channels.
    void prepareOpacity(const MeshView& mesh, const AttributeValues& attributes, bool highlightTransparency);
    /// Hands the target the frame's lights, the first time a draw is lit.
    void loadLights();
    /// The illumination shader's parameters for the current state.
    SurfaceShading surfaceShading(const AttributeValues& attributes) const;

    /// What a texture shader draws with: its texture (a q3::Texture; null
    /// for none), uv transform and boundaries.
    struct TextureChoice {
        const SharedObject* texture = nullptr;
        TQ3Matrix3x3 uvTransform{};
        bool clampS = false;
        bool clampT = false;
    };
    static TextureChoice textureOf(const DrawState& state);
    /// A surface shader's (one held by an attribute set).
    static TextureChoice textureOf(const SharedObject* shader);
    /// Draws the mesh's filled triangles as `base` says, with `texture` (or
    /// untextured where it has none or a vertex lacks a uv), lit or not as
    /// the state says.
    void drawFilled(const MeshView& mesh, const Shading& base, const AttributeValues& attributes,
                    const TextureChoice& texture);
    /// The target's number for the texture, handing it over the first time
    /// this frame draws it (with those boundaries, at that edit); kNoTexture
    /// when there is none. Throws kQ3ErrorInvalidData when the texture's
    /// storage no longer holds its image.
    std::uint32_t loadTexture(const TextureChoice& texture);
    /// The uvs of the mesh's vertices for the target to put through the uv
    /// transform (Shading::uvs), with the target's number for `texture` in
    /// `id`: the mesh's own, or where a vertex no triangle uses has none, a
    /// copy with (0, 0) there. Null (untextured, id kNoTexture) without a
    /// texture or when a triangle's vertex has no uv.
    const float* textureCoordinates(const MeshView& mesh, const TextureChoice& texture, std::uint32_t& id);

    RenderTarget& m_target;
    RenderStyle m_style;
    std::optional<Matrix> m_loaded;
    std::optional<FaceOptions> m_loadedFaces;
    std::optional<AntiAliasOptions> m_loadedAntiAlias;
    std::optional<TQ3FogStyleData> m_loadedFog;
    /// The eye distance as a function of clip coordinates (FogSetup's
    /// planes), computed when fog is first drawn.
    std::optional<FogSetup> m_fogPlanes;
    /// The opacity of the mesh being drawn (r g b per vertex in m_opacityRgb).
    OpacitySetup m_opacity;
    std::vector<float> m_opacityRgb;
    bool m_lightsLoaded = false;
    std::vector<float> m_colors;
    std::vector<float> m_uvs; // textureCoordinates: uvs with the missing ones (0, 0)
    /// The triangles of a mesh grouped by surface shader, where each group
    /// starts, and where each is filled next.
    std::vector<std::uint32_t> m_runs;
    std::vector<std::size_t> m_runStarts;
    std::vector<std::size_t> m_runNext;
    /// The textures handed to the target this frame (held, so that none is
    /// freed and its address reused while the frame lasts).
    struct LoadedTexture {
        Ref<SharedObject> texture;
        unsigned long edit = 0;
        bool clampS = false;
        bool clampT = false;
        std::uint32_t id = 0;
    };
    std::vector<LoadedTexture> m_textures;
};

} // namespace q3
