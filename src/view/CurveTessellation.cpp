// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// From a view's state to the nurbs module's tessellators (Tessellate.h). A
// setting resolves to a Plan: the method, c1, and the matrix segment lengths
// are measured through (local -> world for world space; local -> frustum,
// then the perspective divide and the pane's pixel scale, for screen space:
// the article's "measured in screen space"). The plan's values are also the
// key surfaces cache their meshes under (measureFor).
//
// Curves keep nothing between passes (geometry/CurveCache.h): each pass
// subdivides into the view's scratch buffer. Per curve that costs the
// kernel (a few ns per vertex for the constant method) and no heap block of
// this file's own: the mapping and culling functions capture a pointer to
// the plan, which fits std::function's inline storage.

#include "view/CurveTessellation.h"

#include "core/ErrorManager.h"
#include "core/Limits.h"
#include "geometry/nurbs/Tessellate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace q3 {

namespace {

enum class Measure { kConstant, kWorld, kScreen };

// What one subdivision is made under, resolved from a setting.
struct Plan {
    Measure measure = Measure::kConstant;
    double c1 = 0.0;
    Matrix through{1.0}; // local -> world (world space) or local -> frustum (screen space)
    PixelRect pane;
    bool cull = false;
    Matrix toFrustum{1.0}; // local -> frustum, for culling
    std::size_t maxSegments = limits::kMaxSegmentsPerCurve;

    // The cache key: every value the polyline depends on. The pane's origin
    // is left out on purpose: moving the pane does not change any length.
    std::vector<double> key() const
    {
        std::vector<double> values{double(measure), c1};
        if (measure != Measure::kConstant)
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    values.push_back(through[i][j]);
        if (measure == Measure::kScreen) {
            values.push_back(pane.width);
            values.push_back(pane.height);
        }
        values.push_back(double(maxSegments));
        return values;
    }
};

Plan planFor(const TessellationSetting& setting)
{
    Plan plan;
    plan.c1 = setting.style.c1;
    switch (setting.style.method) {
    case kQ3SubdivisionMethodConstant:
        // QD3DStyle.h: a fractional segment count is truncated when used.
        plan.measure = Measure::kConstant;
        plan.c1 = std::floor(plan.c1);
        break;
    case kQ3SubdivisionMethodWorldSpace:
        plan.measure = Measure::kWorld;
        plan.through = setting.localToWorld;
        break;
    case kQ3SubdivisionMethodScreenSpace:
        if (setting.window) {
            plan.measure = Measure::kScreen;
            plan.through = then(setting.localToWorld, setting.window->worldToFrustum);
            plan.pane = setting.window->pane;
        } else {
            plan.measure = Measure::kWorld;
            plan.through = setting.localToWorld;
        }
        break;
    }
    if (setting.window) {
        if (plan.measure != Measure::kConstant)
            plan.maxSegments = viewSegmentCap(setting.window->pane);
        if (setting.cullOutsideView) {
            plan.cull = true;
            plan.toFrustum = then(setting.localToWorld, setting.window->worldToFrustum);
        }
    }
    return plan;
}

// Whether every control point lies strictly outside one plane of the view
// volume in homogeneous frustum coordinates (x = +-w, y = +-w, the hither
// plane z = 0). Each test is linear in the homogeneous point, and the span's
// points are positive combinations of its control points (weights > 0), so
// the whole span, and every chord between two of its points, is outside that
// plane too. The yon plane is not used: culling there would depend on the
// renderer's depth range.
bool outsideView(const Matrix& m, const nurbs::Point4* points, unsigned order)
{
    unsigned outside[5] = {0, 0, 0, 0, 0};
    for (unsigned i = 0; i < order; ++i) {
        const glm::dvec4 v = m * glm::dvec4(points[i].x, points[i].y, points[i].z, points[i].w);
        outside[0] += v.x > v.w ? 1 : 0;
        outside[1] += -v.x > v.w ? 1 : 0;
        outside[2] += v.y > v.w ? 1 : 0;
        outside[3] += -v.y > v.w ? 1 : 0;
        outside[4] += v.z > 0.0 ? 1 : 0;
    }
    for (unsigned count : outside)
        if (count == order)
            return true;
    return false;
}

// The plan must outlive the result (it is captured by address).
nurbs::SpanCulling cullingFor(const Plan& plan)
{
    if (!plan.cull)
        return {};
    return [p = &plan](const nurbs::Point4* points, unsigned order) { return outsideView(p->toFrustum, points, order); };
}

// The space segment lengths are measured in, as a projective map
// (Tessellate.h's ProjectiveMapping): local -> world for world space; local ->
// frustum, then onto the pane's pixels, for screen space, where w is the
// distance in front of the eye for a perspective camera (points at or behind
// the eye have no image) and frustum z above 0 is nearer than the hither
// plane: clipped away, and for a perspective camera its image grows without
// bound towards the eye plane, so measuring it there would spend segments (up
// to the cap, with a coarser c1 for the whole curve) on nothing that is drawn
// (Tessellate.h, PointMapping).
nurbs::ProjectiveMapping projectiveFor(const Plan& plan)
{
    nurbs::ProjectiveMapping map;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            map.matrix[r][c] = plan.through[c][r];
    if (plan.measure == Measure::kWorld)
        return map;
    // frustumToPane as a scale and offset of x / w and y / w.
    map.scale[0] = 0.5 * plan.pane.width;
    map.offset[0] = plan.pane.x + 0.5 * plan.pane.width;
    map.scale[1] = -0.5 * plan.pane.height;
    map.offset[1] = plan.pane.y + 0.5 * plan.pane.height;
    map.scale[2] = 0.0;
    map.offset[2] = 0.0;
    map.requirePositiveW = true;
    map.clipNearer = true;
    return map;
}

nurbs::PointMapping mappingFor(const Plan& plan)
{
    return [map = projectiveFor(plan)](const nurbs::Point3& p, nurbs::Point3& out) { return map(p, out); };
}

template <class Source>
void subdivide(const Plan& plan, const Source& source, nurbs::TessellatedCurve& out)
{
    nurbs::ViewLimits limits;
    limits.maxSegments = plan.maxSegments;
    limits.hidden = cullingFor(plan);
    if (plan.measure == Measure::kConstant)
        nurbs::tessellateConstant(source, static_cast<std::uint32_t>(plan.c1), out, limits);
    else
        nurbs::tessellateAdaptive(source, plan.c1, projectiveFor(plan), out, limits);
}

// Why the subdivision gave in, for the warning; empty when it did not.
std::string substitutionReport(const Plan& plan, const nurbs::TessellatedCurve& result)
{
    if (!result.substituted && !result.capped)
        return {};
    const std::string limit =
        plan.maxSegments < limits::kMaxSegmentsPerCurve
            ? " would need more than the " + std::to_string(plan.maxSegments) +
                  " segments a curve gets in this pane (kQ3SubdivisionViewSegmentsPerPixel per pixel of its width "
                  "plus height)"
            : " would need more than kQ3SubdivisionMaxSegmentsPerCurve (" +
                  std::to_string(limits::kMaxSegmentsPerCurve) + ") segments";
    if (plan.measure == Measure::kConstant && result.substituted)
        return "constant subdivision with c1 = " + std::to_string(plan.c1) + limit + "; " +
               std::to_string(result.effectiveValue) + " segments per span are used";
    const char* space = plan.measure == Measure::kWorld ? "world-space" : "screen-space";
    if (result.substituted)
        return std::string(space) + " subdivision with c1 = " + std::to_string(plan.c1) + limit +
               "; segments up to " + std::to_string(result.effectiveValue) + " long are used";
    if (result.capped)
        return std::string(space) + " subdivision with c1 = " + std::to_string(plan.c1) + limit +
               "; some segments are longer than c1";
    return {};
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
    const Plan plan = planFor(setting);
    SubdivisionMeasure measure;
    measure.c1 = plan.c1;
    measure.c2 = setting.style.c2;
    if (plan.measure == Measure::kConstant) {
        measure.method = kQ3SubdivisionMethodConstant;
        measure.c2 = std::floor(measure.c2);
    } else {
        measure.method =
            plan.measure == Measure::kWorld ? kQ3SubdivisionMethodWorldSpace : kQ3SubdivisionMethodScreenSpace;
        measure.map = mappingFor(plan);
    }
    measure.key = plan.key();
    measure.key.push_back(measure.c2);
    return measure;
}

glm::dvec2 frustumToPane(const PixelRect& pane, double x, double y)
{
    return glm::dvec2(pane.x + (x + 1.0) * 0.5 * pane.width, pane.y + (1.0 - y) * 0.5 * pane.height);
}

void withCurvePolyline(const nurbs::CurveRef& curve, CurveCache* cache,
                       const TessellationSetting& setting, const PolylineUser& use,
                       nurbs::TessellatedCurve* scratch)
{
    const Plan plan = planFor(setting);
    nurbs::TessellatedCurve own;
    nurbs::TessellatedCurve& result = scratch != nullptr ? *scratch : own;
    subdivide(plan, curve, result);
    if (cache != nullptr)
        cache->tessellations.fetch_add(1, std::memory_order_relaxed);
    use(result.vertices.data(), result.vertexCount());
    const std::string report = substitutionReport(plan, result);
    if (!report.empty())
        errors::postWarning(kQ3WarningParameterOutOfRange, report);
}

} // namespace q3
