// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/Primitives.h"
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

/// How a renderer draws what geometries decompose into.
struct RenderStyle {
    /// Triangles filled (the interactive renderer) or drawn as their edges
    /// (the wireframe renderer).
    bool fillTriangles = false;
};

/// A traversal of a rendering loop: every geometry decomposes itself
/// (Geometry::decompose) into this pass, which draws the primitives into the
/// view's OffscreenRenderer frame. A vertex's colour is its own (after
/// inheritance from its face), else its geometry's attribute set's diffuse
/// colour, else the state's; colours given per vertex are interpolated.
/// Invariant: the target has a frame open for as long as the pass lives.
class RenderPass final : public Pass, private PrimitiveSink {
public:
    RenderPass(OffscreenRenderer& target, const Window& window, const RenderStyle& style)
        : Pass(window), m_target(target), m_style(style)
    {
    }

    void visitGeometry(const Geometry& geometry) override;

private:
    void draw(const MeshView& mesh, const AttributeSet* own) override;
    /// Hands the current local-to-clip matrix to the target if it changed.
    void loadMatrix();
    /// Draws pairs of indices as lines (uniform colour, or per vertex).
    void drawSegments(const MeshView& mesh, const float* rgb, const std::uint32_t* pairs, std::size_t count,
                      const RgbColor& color, const char* what);

    OffscreenRenderer& m_target;
    RenderStyle m_style;
    std::optional<Matrix> m_loaded;
    std::vector<float> m_scratch;
    std::vector<float> m_colors;
    std::vector<std::uint32_t> m_indices;
};

} // namespace q3
