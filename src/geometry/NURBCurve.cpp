// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/NURBCurve.h"

#include "core/Limits.h"
#include "geometry/DataGeometryImpl.h"
#include "geometry/PolyLine.h"
#include "geometry/nurbs/Knots.h"
#include "geometry/nurbs/Tessellate.h"

#include <cmath>
#include <string>
#include <vector>

namespace q3 {

const ClassInfo kNURBCurveClass{kQ3GeometryTypeNURBCurve, &kGeometryClass, "NURB curve"};

namespace {

std::string describe(unsigned long index, unsigned long count, const char* what)
{
    return std::string(what) + " index " + std::to_string(index) + " is out of range (the curve has " +
           std::to_string(count) + ")";
}

} // namespace

// The NURB rules, in QD3DGeometry.h's order, check the orders and counts
// before the arrays: validateNURBCurveData runs before the description's
// check.
template <>
struct ChecksItsOwnStructure<NURBCurve> : std::true_type {};

template class DataGeometry<NURBCurve, TQ3NURBCurveData>;

nurbs::CurveRef curveRefOf(const TQ3NURBCurveData& data)
{
    nurbs::CurveRef ref;
    ref.order = static_cast<unsigned>(data.order);
    ref.numPoints = static_cast<std::size_t>(data.numPoints);
    ref.points = reinterpret_cast<const float*>(data.controlPoints);
    ref.knots = data.knots;
    return ref;
}

void validateNURBCurveData(const TQ3NURBCurveData* data)
{
    requireNonNull(data, "curve data");
    if (data->order < nurbs::kMinOrder || data->order > nurbs::kMaxOrder)
        fail(kQ3ErrorParameterOutOfRange,
             "order " + std::to_string(data->order) + " is outside 2 to " + std::to_string(nurbs::kMaxOrder));
    if (data->numPoints < data->order)
        fail(kQ3ErrorGeometryInsufficientNumberOfPoints,
             "numPoints " + std::to_string(data->numPoints) + " is less than the order " +
                 std::to_string(data->order));
    if (data->numPoints > limits::kMaxArrayCount)
        fail(kQ3ErrorParameterOutOfRange,
             "numPoints " + std::to_string(data->numPoints) +
                 " is more than kQ3GeometryMaxArrayCount (" + std::to_string(limits::kMaxArrayCount) + ")");
    requireNonNull(data->controlPoints, "controlPoints");
    requireNonNull(data->knots, "knots");
    const nurbs::CurveValidation result = nurbs::validateCurve(curveRefOf(*data));
    if (!result.ok())
        fail(kQ3ErrorInvalidData, result.message);
}

namespace {

// The warning for a polyline the caps made coarser than c1 asks for.
void warnIfShort(const SubdivisionMeasure& measure, const nurbs::TessellatedCurve& result)
{
    if (!result.substituted && !result.capped)
        return;
    const std::size_t cap = measure.options.maxSegments;
    SubdivisionShortfall shortfall;
    shortfall.shape = "a NURB curve";
    shortfall.limit = cap < limits::kMaxSegmentsPerCurve
                          ? "the " + std::to_string(cap) +
                                " segments a curve gets in this pane (kQ3SubdivisionViewSegmentsPerPixel per pixel "
                                "of its width plus height)"
                          : "kQ3SubdivisionMaxSegmentsPerCurve (" + std::to_string(limits::kMaxSegmentsPerCurve) +
                                ") segments";
    if (measure.options.method == nurbs::Method::kConstant)
        shortfall.used = std::to_string(std::uint64_t(result.effectiveValue)) + " segments per span are used";
    else if (result.substituted)
        shortfall.used = "segments up to " + std::to_string(result.effectiveValue) + " long are used";
    else
        shortfall.used = "some segments are longer than c1";
    postSubdivisionWarning(measure, shortfall);
}

} // namespace

const nurbs::TessellatedCurve& NURBCurve::tessellate(const SubdivisionMeasure& measure, bool count,
                                                     nurbs::TessellatedCurve& own) const
{
    nurbs::TessellatedCurve& result = measure.curveScratch != nullptr ? *measure.curveScratch : own;
    nurbs::tessellate(curve(), measure.options, result);
    if (count)
        m_tessellations.fetch_add(1, std::memory_order_relaxed);
    return result;
}

void NURBCurve::decompose(const DecomposeContext& context, PrimitiveSink& sink) const
{
    const SubdivisionMeasure measure = context.subdivisionMeasure();
    nurbs::TessellatedCurve own;
    const nurbs::TessellatedCurve& polyline = tessellate(measure, !borrowed(), own);
    static const std::uint32_t kFirst = 0;
    const std::size_t count = polyline.vertexCount();
    const Strip strip{0, static_cast<std::uint32_t>(count)};
    MeshView mesh;
    mesh.positions = polyline.vertices.data();
    mesh.vertexCount = count;
    // A curve that subdivides to one point is drawn as that point.
    if (count == 1) {
        mesh.points = &kFirst;
        mesh.pointCount = 1;
    } else {
        mesh.strips = &strip;
        mesh.stripCount = 1;
    }
    sink.draw(mesh, attributeSet());
    warnIfShort(measure, polyline);
}

void NURBCurve::bound(const DecomposeContext&, std::vector<glm::dvec3>& points) const
{
    const nurbs::CurveRef ref = curve();
    for (std::size_t i = 0; i < ref.numPoints; ++i) {
        const float* p = ref.points + 4 * i;
        points.emplace_back(double(p[0]) / p[3], double(p[1]) / p[3], double(p[2]) / p[3]);
    }
}

Ref<Geometry> NURBCurve::decomposed(const DecomposeContext& context) const
{
    const SubdivisionMeasure measure = context.subdivisionMeasure();
    nurbs::TessellatedCurve own;
    const nurbs::TessellatedCurve& polyline = tessellate(measure, true, own);
    const float* xyz = polyline.vertices.data();
    Ref<PolyLine> result;
    if (polyline.vertexCount() == 1) {
        const float twice[6] = {xyz[0], xyz[1], xyz[2], xyz[0], xyz[1], xyz[2]};
        result = PolyLine::fromPoints(twice, 2, attributeSet());
    } else {
        result = PolyLine::fromPoints(xyz, polyline.vertexCount(), attributeSet());
    }
    warnIfShort(measure, polyline);
    return result;
}

TQ3RationalPoint4D NURBCurve::controlPoint(unsigned long index) const
{
    if (index >= data().numPoints)
        fail(kQ3ErrorParameterOutOfRange, describe(index, data().numPoints, "control point"));
    return data().controlPoints[index];
}

void NURBCurve::setControlPoint(unsigned long index, const TQ3RationalPoint4D& point)
{
    if (index >= data().numPoints)
        fail(kQ3ErrorParameterOutOfRange, describe(index, data().numPoints, "control point"));
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z) ||
        !std::isfinite(point.w))
        fail(kQ3ErrorInvalidParameter,
             "control point " + std::to_string(index) + " has a component that is not finite");
    if (!(point.w > 0.0f))
        fail(kQ3ErrorInvalidParameter, "control point " + std::to_string(index) + " has weight w = " +
                                           std::to_string(point.w) + "; weights must be positive");
    editableData().controlPoints[index] = point;
    markEdited();
}

float NURBCurve::knot(unsigned long index) const
{
    const unsigned long count = data().numPoints + data().order;
    if (index >= count)
        fail(kQ3ErrorParameterOutOfRange, describe(index, count, "knot"));
    return data().knots[index];
}

void NURBCurve::setKnot(unsigned long index, float value)
{
    const unsigned long count = data().numPoints + data().order;
    if (index >= count)
        fail(kQ3ErrorParameterOutOfRange, describe(index, count, "knot"));
    std::vector<float> knots(data().knots, data().knots + count);
    knots[index] = value;
    nurbs::CurveRef candidate = curve();
    candidate.knots = knots.data();
    const nurbs::CurveValidation result = nurbs::validateCurve(candidate);
    if (!result.ok())
        fail(kQ3ErrorInvalidParameter, "setting knot " + std::to_string(index) + " to " + std::to_string(value) +
                                           " would break a rule: " + result.message);
    editableData().knots[index] = value;
    markEdited();
}

} // namespace q3
