// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

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

/// A traversal of a rendering loop: every geometry becomes lines and points in
/// the view's OffscreenRenderer frame, in its colour (its own attribute set's
/// diffuse colour, else the state's). NURB curves are drawn as the polyline
/// withCurvePolyline gives. The wireframe and interactive renderers draw the
/// geometry Q3 has (curves, polylines, lines, points) identically.
/// Invariant: the target has a frame open for as long as the pass lives.
class RenderPass final : public Pass {
public:
    RenderPass(OffscreenRenderer& target, const Window& window) : Pass(window), m_target(target) {}

    void visitNURBCurve(const nurbs::CurveRef& curve, const AttributeSet* attributes,
                        CurveCache* cache) override;
    void visitPolyLine(const PolyLine& polyLine) override;
    void visitLine(const Line& line) override;
    void visitPoint(const Point& point) override;

private:
    /// Hands the current local-to-clip matrix to the target if it changed.
    void loadMatrix();

    OffscreenRenderer& m_target;
    std::optional<Matrix> m_loaded;
    std::vector<float> m_scratch;
};

} // namespace q3
