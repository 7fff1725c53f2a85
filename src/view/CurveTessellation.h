// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DStyle.h"
#include "geometry/Decompose.h"
#include "geometry/nurbs/Curve.h"
#include "base/RenderResult.h"
#include "base/Matrix.h"

#include <cstddef>
#include <functional>
#include <optional>

namespace q3 {

/// Where a loop's image goes: the camera's world-to-frustum matrix and the
/// pixels of the pane it maps onto (y down, as QuickDraw 3D panes are).
struct Window {
    Matrix worldToFrustum{1.0};
    PixelRect pane;
};

/// The pixel position of a frustum point (after the homogeneous divide):
/// x -1..1 across the pane from its left edge, y 1..-1 from its top edge.
glm::dvec2 frustumToPane(const PixelRect& pane, double x, double y);

/// Everything besides the curve that its polyline depends on.
struct TessellationSetting {
    /// A style that passed checkSubdivisionStyle.
    TQ3SubdivisionStyleData style{};
    Matrix localToWorld{1.0};
    /// The loop's window; without one, screen-space subdivision is done as
    /// world-space subdivision with the same c1 (QD3DView.h, bounding loops).
    /// With one, world- and screen-space curves get at most
    /// viewSegmentCap(window->pane) segments.
    std::optional<Window> window;
    /// Rendering loops: spans that cannot be seen in the window (all their
    /// control points outside one side or the hither plane of the view
    /// volume) get one segment, whatever the method. Bounding loops leave it
    /// off, so bounds cover the whole curve.
    bool cullOutsideView = false;
};

/// The most segments a world- or screen-space curve is drawn with in a
/// window onto `pane`: kQ3SubdivisionViewSegmentsPerPixel times the pane's
/// width plus height, at least that for a 1 x 1 pane and at most
/// kQ3SubdivisionMaxSegmentsPerCurve.
std::size_t viewSegmentCap(const PixelRect& pane);

/// The one place a setting becomes tessellation options (QD3DStyle.h, "CONTROLLING
/// SUBDIVISION"): constant, c1 segments per non-empty knot span (c1 and c2
/// truncated; checkSubdivisionStyle already substituted values out of range);
/// world space, no segment longer than c1 after the local-to-world transform;
/// screen space, no segment longer than c1 pixels after local -> world ->
/// frustum (with the perspective divide) -> pane, or world space without a
/// window. With a window: world- and screen-space curves get at most
/// viewSegmentCap(pane) segments, the clip is the local-to-frustum map,
/// screen-space surfaces leave what it cannot show coarse, and with
/// cullOutsideView curves cull spans outside it.
SubdivisionMeasure measureFor(const TessellationSetting& setting);

} // namespace q3
