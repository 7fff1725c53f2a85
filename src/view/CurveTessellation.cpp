// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// From a view's state to the nurbs module's tessellators (Tessellate.h),
// with the retained curve's cache in between. A setting resolves to a Plan:
// the method, c1, and the matrix segment lengths are measured through
// (local -> world for world space; local -> frustum, then the perspective
// divide and the pane's pixel scale, for screen space: the article's
// "measured in screen space"). The plan's values are the cache key, so a
// polyline is reused exactly when everything it was made from is unchanged.

#include "view/CurveTessellation.h"

#include "core/ErrorManager.h"
#include "core/Limits.h"
#include "geometry/nurbs/Tessellate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
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
nurbs::SpanCulling cullingFor(const Plan& plan)
{
    if (!plan.cull)
        return {};
    return [m = plan.toFrustum](const nurbs::Point4* points, unsigned order) {
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
    };
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

template <class Source>
nurbs::TessellatedCurve subdivide(const Plan& plan, const Source& source)
{
    nurbs::TessellatedCurve out;
    subdivide(plan, source, out);
    return out;
}

// Why the subdivision gave in, for the warning; empty when it did not.
std::string substitutionReport(const Plan& plan, const nurbs::TessellatedCurve& result)
{
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

// Retained curves drawn by views on several threads share their cache; a
// few striped locks keep that safe without a lock in every curve.
std::mutex& lockFor(const CurveCache* cache)
{
    static std::array<std::mutex, 64> stripes;
    const auto address = reinterpret_cast<std::uintptr_t>(cache);
    return stripes[(address / alignof(CurveCache)) % stripes.size()];
}

// Culling makes the polyline depend on which spans are hidden, not on the
// camera as such: with the Bezier form at hand, the key gets the hidden spans
// (32 to a value, exact in a double) when there are any, so a camera move
// that hides nothing new reuses the polyline, and a curve hidden nowhere
// shares it with bounding loops. Without the form, the key gets the matrix.
void appendCulling(const Plan& plan, const CurveCache& cache, std::vector<double>& key)
{
    if (!plan.cull)
        return;
    if (!cache.bezier) {
        key.push_back(-1.0);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                key.push_back(plan.toFrustum[i][j]);
        return;
    }
    const nurbs::SpanCulling hidden = cullingFor(plan);
    const nurbs::BezierForm& form = *cache.bezier;
    std::vector<double> mask((form.spanCount() + 31) / 32, 0.0);
    bool any = false;
    for (std::size_t s = 0; s < form.spanCount(); ++s)
        if (hidden(form.spanPoints(s), form.order())) {
            mask[s / 32] += double(std::uint32_t{1} << (s % 32));
            any = true;
        }
    if (any) {
        key.push_back(-2.0);
        key.insert(key.end(), mask.begin(), mask.end());
    }
}

// Reuses or rebuilds a cache's polyline; returns the warning to post (a
// reused polyline that was capped warns again, as its first drawing did).
std::string useCache(const nurbs::CurveRef& curve, CurveCache& cache, const Plan& plan,
                     const PolylineUser& use)
{
    // A large curve keeps no Bezier form: the tessellators convert it span by
    // span, so the cache holds only the polyline (Tessellate.h, kWholeFormLimit).
    if (!cache.bezier && nurbs::fitsWholeBezierForm(curve))
        cache.bezier = std::make_shared<const nurbs::BezierForm>(curve);
    std::vector<double> key = plan.key();
    appendCulling(plan, cache, key);
    std::string report;
    if (!cache.valid || cache.key != key) {
        // Into the cache's polyline (invalidate keeps its capacity) and this
        // thread's parameter scratch: re-tessellating a curve at a similar
        // size allocates nothing and faults no new pages in.
        thread_local std::vector<double> parameterScratch;
        nurbs::TessellatedCurve result;
        result.vertices.swap(cache.polyline);
        result.parameters.swap(parameterScratch);
        if (cache.bezier)
            subdivide(plan, *cache.bezier, result);
        else
            subdivide(plan, curve, result);
        report = substitutionReport(plan, result);
        cache.polyline.swap(result.vertices);
        parameterScratch.swap(result.parameters);
        cache.key = std::move(key);
        cache.capped = !report.empty();
        cache.valid = true;
        ++cache.tessellations;
    } else if (cache.capped) {
        report = "the curve's " + std::string(plan.measure == Measure::kConstant ? "constant" : "adaptive") +
                 " subdivision with c1 = " + std::to_string(plan.c1) +
                 " would need more segments than " + std::to_string(plan.maxSegments) +
                 " (the most it may have here); it is drawn with fewer";
    }
    use(cache.polyline.data(), cache.polyline.size() / 3);
    return report;
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
                       const TessellationSetting& setting, const PolylineUser& use)
{
    const Plan plan = planFor(setting);
    std::string report;
    if (cache != nullptr) {
        std::lock_guard<std::mutex> lock(lockFor(cache));
        report = useCache(curve, *cache, plan, use);
    } else {
        const nurbs::TessellatedCurve result = subdivide(plan, curve);
        use(result.vertices.data(), result.vertexCount());
        report = substitutionReport(plan, result);
    }
    if (!report.empty())
        errors::postWarning(kQ3WarningParameterOutOfRange, report);
}

} // namespace q3
