// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DStyle.h"
#include "geometry/CurveCache.h"
#include "geometry/Decompose.h"
#include "geometry/nurbs/Curve.h"
#include "base/RenderResult.h"
#include "base/Matrix.h"

#include <cstddef>
#include <functional>
#include <optional>

namespace q3 {

namespace nurbs {
struct TessellatedCurve;
}

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

/// Subdivides a valid curve as the setting says and hands the polyline to
/// `use`. The methods are the article's ("CONTROLLING SUBDIVISION"):
/// constant, c1 segments per non-empty knot span; world space, no segment
/// longer than c1 after the local-to-world transform; screen space, no
/// segment longer than c1 pixels after local -> world -> frustum (with the
/// perspective divide) -> pane.
///
/// Every call subdivides, retained curve or not: a retained curve keeps no
/// polyline (CurveCache says why); its `cache`, when given, only counts the
/// call in `tessellations`. The polyline is written into `scratch` when
/// given (a view passes one it owns, so a frame of retained curves allocates
/// nothing once the scratch has grown to the largest curve) and into a
/// buffer of the call's own otherwise; `use` must not keep the pointer.
///
/// When the subdivision had to give in to its cap (kQ3SubdivisionMaxSegmentsPerCurve,
/// or in a view for world and screen space the pane's cap set by
/// kQ3SubdivisionViewSegmentsPerPixel, both in QD3DStyle.h),
/// kQ3WarningParameterOutOfRange is posted after `use` returns.
void withCurvePolyline(const nurbs::CurveRef& curve, CurveCache* cache,
                       const TessellationSetting& setting, const PolylineUser& use,
                       nurbs::TessellatedCurve* scratch = nullptr);

/// What a setting means for surfaces (geometry/Decompose.h): the method, c1
/// and c2 as checkSubdivisionStyle left them (constant values truncated),
/// and for world and screen space the same local-to-measured map and cache
/// key that curves use. Screen space without a window is world space.
SubdivisionMeasure measureFor(const TessellationSetting& setting);

} // namespace q3
