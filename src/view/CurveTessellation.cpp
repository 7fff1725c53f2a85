// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// From a view's state to the nurbs module's tessellation options
// (nurbs::TessellationOptions): the method, c1 and c2, and the map segment
// lengths are measured through (local -> world for world space; local ->
// frustum, then the perspective divide and the pane's pixel scale, for screen
// space: the article's "measured in screen space"), with the view's limits.
// Geometries tessellate themselves under the result (geometry/Decompose.h);
// curves keep nothing between passes and tessellate into the view's scratch
// buffer, so a frame of retained curves allocates nothing of this file's own.

#include "view/CurveTessellation.h"

#include "core/Limits.h"

#include <algorithm>
#include <cmath>

namespace q3 {

namespace {

// A glm matrix (column-major, row vectors transformed as m * v) as the
// row-major array the options hold.
std::array<double, 16> rowMajor(const Matrix& m)
{
    std::array<double, 16> out{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            out[4 * i + j] = m[j][i];
    return out;
}

// The space segment lengths are measured in, as a projective map: local ->
// world for world space; local -> frustum, then onto the pane's pixels, for
// screen space, where w is the distance in front of the eye for a perspective
// camera (points at or behind the eye have no image) and frustum z above 0 is
// nearer than the hither plane: clipped away, and for a perspective camera its
// image grows without bound towards the eye plane, so measuring it there would
// spend segments (up to the cap, with a coarser c1 for the whole curve) on
// nothing that is drawn (Tessellate.h, PointMapping).
nurbs::ProjectiveMapping projectiveFor(const Matrix& through, const PixelRect* pane)
{
    nurbs::ProjectiveMapping map;
    const std::array<double, 16> rows = rowMajor(through);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            map.matrix[r][c] = rows[4 * r + c];
    if (pane == nullptr)
        return map;
    // frustumToPane as a scale and offset of x / w and y / w.
    map.scale[0] = 0.5 * pane->width;
    map.offset[0] = pane->x + 0.5 * pane->width;
    map.scale[1] = -0.5 * pane->height;
    map.offset[1] = pane->y + 0.5 * pane->height;
    map.scale[2] = 0.0;
    map.offset[2] = 0.0;
    map.requirePositiveW = true;
    map.clipNearer = true;
    return map;
}

} // namespace

std::size_t viewSegmentCap(const PixelRect& pane)
{
    const double side = std::max(double(pane.width), 1.0) + std::max(double(pane.height), 1.0);
    const double cap = double(limits::kViewSegmentsPerPixel) * side;
    return cap < double(limits::kMaxSegmentsPerCurve) ? std::size_t(cap) : limits::kMaxSegmentsPerCurve;
}

SubdivisionMeasure measureFor(const TessellationSetting& setting)
{
    SubdivisionMeasure measure;
    nurbs::TessellationOptions& o = measure.options;
    o.c1 = setting.style.c1;
    o.c2 = setting.style.c2;
    const Window* window = setting.window ? &*setting.window : nullptr;
    switch (setting.style.method) {
    case kQ3SubdivisionMethodConstant:
        // QD3DStyle.h: a fractional segment count is truncated when used.
        measure.method = kQ3SubdivisionMethodConstant;
        o.method = nurbs::Method::kConstant;
        o.c1 = std::floor(o.c1);
        o.c2 = std::floor(o.c2);
        break;
    case kQ3SubdivisionMethodWorldSpace:
        measure.method = kQ3SubdivisionMethodWorldSpace;
        o.method = nurbs::Method::kAdaptive;
        o.mapping = projectiveFor(setting.localToWorld, nullptr);
        break;
    case kQ3SubdivisionMethodScreenSpace:
        o.method = nurbs::Method::kAdaptive;
        if (window != nullptr) {
            measure.method = kQ3SubdivisionMethodScreenSpace;
            o.mapping = projectiveFor(then(setting.localToWorld, window->worldToFrustum), &window->pane);
        } else {
            measure.method = kQ3SubdivisionMethodWorldSpace;
            o.mapping = projectiveFor(setting.localToWorld, nullptr);
        }
        break;
    }
    if (window != nullptr) {
        if (o.method == nurbs::Method::kAdaptive)
            o.maxSegments = viewSegmentCap(window->pane);
        o.hasClip = true;
        o.clip = rowMajor(then(setting.localToWorld, window->worldToFrustum));
        o.cullHiddenSpans = setting.cullOutsideView;
        o.coarseOutsideClip = measure.method == kQ3SubdivisionMethodScreenSpace;
    }
    return measure;
}

glm::dvec2 frustumToPane(const PixelRect& pane, double x, double y)
{
    return glm::dvec2(pane.x + (x + 1.0) * 0.5 * pane.width, pane.y + (1.0 - y) * 0.5 * pane.height);
}

} // namespace q3
