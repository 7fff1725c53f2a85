// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/NURBPatch.h"

#include "core/ErrorManager.h"
#include "core/ParameterChecks.h"
#include "geometry/DataGeometryImpl.h"
#include "geometry/nurbs/ToolResult.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace q3 {

const ClassInfo kNURBPatchClass{kQ3GeometryTypeNURBPatch, &kGeometryClass, "NURB patch"};

// The NURB rules, in QD3DGeometry.h's order, check the orders and counts
// before the arrays: validateNURBPatchData runs before the description's check.
template <>
struct ChecksItsOwnStructure<NURBPatch> : std::true_type {};

template class DataGeometry<NURBPatch, TQ3NURBPatchData>;

namespace {

using nurbs::formatMessage;

std::string num(double value)
{
    return numberText(value);
}

// a + b and a * b of counts, saturating.
unsigned long sum(unsigned long a, unsigned long b)
{
    return a > ~0UL - b ? ~0UL : a + b;
}
unsigned long product(unsigned long a, unsigned long b)
{
    return b != 0 && a > ~0UL / b ? ~0UL : a * b;
}

void requireCount(unsigned long count, const std::string& what)
{
    if (count > limits::kMaxArrayCount)
        fail(kQ3ErrorParameterOutOfRange, what + " is " + std::to_string(count) +
                                              ", more than kQ3GeometryMaxArrayCount (" +
                                              std::to_string(limits::kMaxArrayCount) + ")");
}

void requirePresent(const void* pointer, const std::string& what)
{
    if (pointer == nullptr)
        fail(kQ3ErrorNULLParameter, what + " is NULL");
}

// The knot rules for one vector: `path` names it in full ("uKnots",
// "trimLoops[1].trimCurves[0].knots"), `name` in the second half of a
// sentence ("uKnots", "knots").
void checkKnotVector(const float* knots, unsigned long numPoints, unsigned long order, const std::string& path,
                     const std::string& name)
{
    const nurbs::KnotCheck check = nurbs::checkKnots(knots, numPoints, unsigned(order));
    const std::size_t i = check.index;
    switch (check.rule) {
    case nurbs::KnotRule::kValid:
        return;
    case nurbs::KnotRule::kNotFinite:
        fail(kQ3ErrorInvalidData, formatMessage("%s[%zu] is %s; knots must be finite", path.c_str(), i,
                                                num(knots[i]).c_str()));
    case nurbs::KnotRule::kDecreasing:
        fail(kQ3ErrorInvalidData, formatMessage("%s[%zu] = %s is less than %s[%zu] = %s; knots must never decrease",
                                                path.c_str(), i, num(knots[i]).c_str(), name.c_str(), i - 1,
                                                num(knots[i - 1]).c_str()));
    case nurbs::KnotRule::kRunTooLong:
        fail(kQ3ErrorInvalidData,
             formatMessage("%s[%zu..%zu] are all %s: %zu equal knots where at most %zu are allowed (order - 1 inside "
                           "the vector, order at either end)",
                           path.c_str(), i, i + check.run - 1, num(knots[i]).c_str(), check.run, check.limit));
    case nurbs::KnotRule::kEmptyDomain:
        fail(kQ3ErrorInvalidData,
             formatMessage("%s[%zu] and %s[%lu] are both %s, so the domain is empty", path.c_str(), i, name.c_str(),
                           numPoints, num(knots[numPoints]).c_str()));
    }
}

// The largest of the domain's sides and end magnitudes, times 1e-5: how far
// a trim curve may stray outside the domain and how far apart the ends of a
// loop's curves may be (QD3DGeometry.h).
double trimTolerance(const nurbs::SurfaceDomain& d)
{
    const double largest = std::max({d.u1 - d.u0, d.v1 - d.v0, std::fabs(d.u0), std::fabs(d.u1),
                                     std::fabs(d.v0), std::fabs(d.v1)});
    return 1e-5 * largest;
}

void checkTrimCurve(const TQ3NURBPatchTrimCurveData& curve, const std::string& path,
                    const nurbs::SurfaceDomain& domain, double tolerance)
{
    if (curve.order < nurbs::kMinOrder || curve.order > nurbs::kMaxOrder)
        fail(kQ3ErrorParameterOutOfRange, formatMessage("%s.order %lu is outside 2 to %u (kQ3NURBCurveMaxOrder)",
                                                        path.c_str(), curve.order, nurbs::kMaxOrder));
    if (curve.numPoints < curve.order)
        fail(kQ3ErrorGeometryInsufficientNumberOfPoints,
             formatMessage("%s.numPoints %lu is less than its order %lu", path.c_str(), curve.numPoints,
                           curve.order));
    requireCount(sum(curve.numPoints, curve.order), path + ".numPoints + order");
    requirePresent(curve.controlPoints, path + ".controlPoints");
    requirePresent(curve.knots, path + ".knots");
    checkKnotVector(curve.knots, curve.numPoints, curve.order, path + ".knots", "knots");
    for (unsigned long i = 0; i < curve.numPoints; ++i) {
        const TQ3RationalPoint3D& p = curve.controlPoints[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.w))
            fail(kQ3ErrorInvalidData, formatMessage("%s.controlPoints[%lu] = (%s, %s, %s) has a value that is not "
                                                    "finite; control points must be finite",
                                                    path.c_str(), i, num(p.x).c_str(), num(p.y).c_str(),
                                                    num(p.w).c_str()));
        if (!(p.w > 0.0f))
            fail(kQ3ErrorInvalidData, formatMessage("%s.controlPoints[%lu] has w = %s; weights must be positive",
                                                    path.c_str(), i, num(p.w).c_str()));
    }
    for (unsigned long i = 0; i < curve.numPoints; ++i) {
        const TQ3RationalPoint3D& p = curve.controlPoints[i];
        const double u = double(p.x) / p.w, v = double(p.y) / p.w;
        if (u < domain.u0 - tolerance || u > domain.u1 + tolerance || v < domain.v0 - tolerance ||
            v > domain.v1 + tolerance)
            fail(kQ3ErrorInvalidData,
                 formatMessage("%s.controlPoints[%lu] is at (u, v) = (%s, %s), outside the patch's domain [%s, %s] x "
                               "[%s, %s]; trim curves must lie in the domain",
                               path.c_str(), i, num(u).c_str(), num(v).c_str(), num(domain.u0).c_str(),
                               num(domain.u1).c_str(), num(domain.v0).c_str(), num(domain.v1).c_str()));
    }
}

nurbs::TrimCurveRef trimRefOf(const TQ3NURBPatchTrimCurveData& curve)
{
    nurbs::TrimCurveRef ref;
    ref.order = unsigned(curve.order);
    ref.numPoints = std::size_t(curve.numPoints);
    ref.points = reinterpret_cast<const float*>(curve.controlPoints);
    ref.knots = curve.knots;
    return ref;
}

void checkTrimLoop(const TQ3NURBPatchTrimLoopData& loop, unsigned long index, const nurbs::SurfaceDomain& domain,
                   double tolerance)
{
    const std::string path = "trimLoops[" + std::to_string(index) + "]";
    if (loop.numTrimCurves == 0)
        fail(kQ3ErrorInvalidData, path + ".numTrimCurves is 0; a trim loop needs at least one curve");
    requireCount(loop.numTrimCurves, path + ".numTrimCurves");
    requirePresent(loop.trimCurves, path + ".trimCurves");
    for (unsigned long c = 0; c < loop.numTrimCurves; ++c)
        checkTrimCurve(loop.trimCurves[c], path + ".trimCurves[" + std::to_string(c) + "]", domain, tolerance);
    for (unsigned long c = 0; c < loop.numTrimCurves; ++c) {
        const unsigned long next = (c + 1) % loop.numTrimCurves;
        const nurbs::TrimEnds here = nurbs::trimCurveEnds(trimRefOf(loop.trimCurves[c]));
        const nurbs::TrimEnds there = nurbs::trimCurveEnds(trimRefOf(loop.trimCurves[next]));
        const double gap = std::hypot(there.startU - here.endU, there.startV - here.endV);
        if (!(gap <= tolerance))
            fail(kQ3ErrorInvalidData,
                 formatMessage("%s is not closed: trimCurves[%lu] ends at (u, v) = (%s, %s) but trimCurves[%lu] "
                               "starts at (%s, %s), %s away (the tolerance is %s)",
                               path.c_str(), c, num(here.endU).c_str(), num(here.endV).c_str(), next,
                               num(there.startU).c_str(), num(there.startV).c_str(), num(gap).c_str(),
                               num(tolerance).c_str()));
    }
}

std::string describeIndex(unsigned long index, unsigned long count, const char* what, const char* plural)
{
    return std::string(what) + " " + std::to_string(index) + " is out of range (the patch has " +
           std::to_string(count) + " " + plural + ")";
}

} // namespace

void validateNURBPatchData(const TQ3NURBPatchData* data)
{
    requireNonNull(data, "nurbPatchData");
    const TQ3NURBPatchData& d = *data;
    for (const auto& [order, name] : {std::pair{d.uOrder, "uOrder"}, std::pair{d.vOrder, "vOrder"}})
        if (order < nurbs::kMinPatchOrder || order > nurbs::kMaxPatchOrder)
            fail(kQ3ErrorParameterOutOfRange, formatMessage("%s %lu is outside 2 to %u (kQ3NURBPatchMaxOrder)", name,
                                                            order, nurbs::kMaxPatchOrder));
    if (d.numColumns < d.uOrder)
        fail(kQ3ErrorGeometryInsufficientNumberOfPoints,
             formatMessage("numColumns %lu is less than uOrder %lu: a row needs at least uOrder control points",
                           d.numColumns, d.uOrder));
    if (d.numRows < d.vOrder)
        fail(kQ3ErrorGeometryInsufficientNumberOfPoints,
             formatMessage("numRows %lu is less than vOrder %lu: there must be at least vOrder rows", d.numRows,
                           d.vOrder));
    requireCount(product(d.numRows, d.numColumns), "numRows * numColumns");
    requireCount(sum(d.uOrder, d.numColumns), "uOrder + numColumns");
    requireCount(sum(d.vOrder, d.numRows), "vOrder + numRows");
    requireCount(d.numTrimLoops, "numTrimLoops");
    requirePresent(d.controlPoints, "controlPoints");
    requirePresent(d.uKnots, "uKnots");
    requirePresent(d.vKnots, "vKnots");
    if (d.numTrimLoops > 0)
        requirePresent(d.trimLoops, "trimLoops");
    checkKnotVector(d.uKnots, d.numColumns, d.uOrder, "uKnots", "uKnots");
    checkKnotVector(d.vKnots, d.numRows, d.vOrder, "vKnots", "vKnots");
    const unsigned long count = d.numRows * d.numColumns;
    for (unsigned long i = 0; i < count; ++i) {
        const TQ3RationalPoint4D& p = d.controlPoints[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(p.w))
            fail(kQ3ErrorInvalidData,
                 formatMessage("controlPoints[%lu] (row %lu, column %lu) = (%s, %s, %s, %s) has a value that is not "
                               "finite; control points must be finite",
                               i, i / d.numColumns, i % d.numColumns, num(p.x).c_str(), num(p.y).c_str(),
                               num(p.z).c_str(), num(p.w).c_str()));
        if (!(p.w > 0.0f))
            fail(kQ3ErrorInvalidData,
                 formatMessage("controlPoints[%lu] (row %lu, column %lu) has w = %s; weights must be positive", i,
                               i / d.numColumns, i % d.numColumns, num(p.w).c_str()));
    }
    const nurbs::SurfaceDomain domain = nurbs::surfaceDomain(surfaceRefOf(d));
    const double tolerance = trimTolerance(domain);
    for (unsigned long l = 0; l < d.numTrimLoops; ++l)
        checkTrimLoop(d.trimLoops[l], l, domain, tolerance);
}

nurbs::SurfaceRef surfaceRefOf(const TQ3NURBPatchData& data)
{
    nurbs::SurfaceRef ref;
    ref.uOrder = unsigned(data.uOrder);
    ref.vOrder = unsigned(data.vOrder);
    ref.numColumns = std::size_t(data.numColumns);
    ref.numRows = std::size_t(data.numRows);
    ref.points = reinterpret_cast<const float*>(data.controlPoints);
    ref.uKnots = data.uKnots;
    ref.vKnots = data.vKnots;
    return ref;
}

nurbs::PatchRef patchRefOf(const TQ3NURBPatchData& data)
{
    nurbs::PatchRef ref;
    ref.surface = surfaceRefOf(data);
    ref.loops.resize(data.numTrimLoops);
    for (unsigned long l = 0; l < data.numTrimLoops; ++l) {
        const TQ3NURBPatchTrimLoopData& loop = data.trimLoops[l];
        for (unsigned long c = 0; c < loop.numTrimCurves; ++c)
            ref.loops[l].push_back(trimRefOf(loop.trimCurves[c]));
    }
    return ref;
}

namespace {

// The warning for triangles the cap made coarser than the style asks for;
// empty when they are not.
std::string warningFor(const SubdivisionMeasure& measure, const nurbs::TessellatedSurface& result)
{
    const bool constant = measure.options.method == nurbs::Method::kConstant;
    if (!result.substituted && (constant || !result.capped))
        return {};
    SubdivisionShortfall shortfall;
    shortfall.shape = "a NURB patch";
    shortfall.withC2 = constant;
    shortfall.limit =
        "kQ3SubdivisionMaxTrianglesPerPatch (" + std::to_string(limits::kMaxTrianglesPerPatch) + ") triangles";
    if (constant)
        shortfall.used =
            formatMessage("%u x %u segments per pair of spans are used", result.uSegments, result.vSegments);
    else if (result.substituted)
        shortfall.used = "edges up to " + num(result.effectiveValue) + " long are used";
    else {
        shortfall.limit += " (or splits finer than the parameter grid)";
        shortfall.used = "some edges are longer than c1";
    }
    return subdivisionWarning(measure, shortfall);
}

} // namespace

void NURBPatch::decompose(const DecomposeContext& context, PrimitiveSink& sink) const
{
    const SubdivisionMeasure measure = context.subdivisionMeasure();
    std::string warning;
    withMesh(
        measure.key(),
        [&](Mesh& mesh) {
            nurbs::TessellatedSurface result;
            nurbs::tessellateSurface(patchRefOf(data()), measure.options, result);
            if (result.crossing) {
                const std::string loops =
                    result.crossingLoop == result.crossingOther
                        ? "trimLoops[" + std::to_string(result.crossingLoop) + "] crosses or touches itself"
                        : "trimLoops[" + std::to_string(result.crossingLoop) + "] and trimLoops[" +
                              std::to_string(result.crossingOther) + "] cross or touch";
                fail(kQ3ErrorInvalidData, loops + " near (u, v) = (" + num(result.crossingU) + ", " +
                                              num(result.crossingV) +
                                              "); trim loops must not cross, so the patch is not drawn");
            }
            m_warning = warningFor(measure, result);
            const std::size_t n = result.vertexCount();
            mesh.reserveVertices(n);
            for (std::size_t i = 0; i < n; ++i) {
                VertexAttributes attributes;
                const float* normal = &result.normals[3 * i];
                if (normal[0] != 0.0f || normal[1] != 0.0f || normal[2] != 0.0f)
                    attributes.normal = TQ3Vector3D{normal[0], normal[1], normal[2]};
                attributes.uv = TQ3Param2D{result.uvs[2 * i], result.uvs[2 * i + 1]};
                const float* p = &result.positions[3 * i];
                mesh.addVertex(TQ3Point3D{p[0], p[1], p[2]}, attributes);
            }
            for (std::size_t t = 0; t < result.triangleCount(); ++t)
                mesh.addTriangle(result.triangles[3 * t], result.triangles[3 * t + 1], result.triangles[3 * t + 2]);
            mesh.edgesFromTriangles();
        },
        [&](const Mesh& mesh) {
            warning = m_warning;
            sink.draw(mesh.view(), attributeSet());
        });
    if (!warning.empty())
        errors::postWarning(kQ3WarningParameterOutOfRange, warning);
}

void NURBPatch::bound(const DecomposeContext&, std::vector<glm::dvec3>& points) const
{
    const TQ3NURBPatchData& d = data();
    const unsigned long count = d.numRows * d.numColumns;
    for (unsigned long i = 0; i < count; ++i) {
        const TQ3RationalPoint4D& p = d.controlPoints[i];
        points.emplace_back(double(p.x) / p.w, double(p.y) / p.w, double(p.z) / p.w);
    }
}

TQ3RationalPoint4D NURBPatch::controlPoint(unsigned long row, unsigned long column) const
{
    if (row >= data().numRows)
        fail(kQ3ErrorParameterOutOfRange, describeIndex(row, data().numRows, "row", "rows"));
    if (column >= data().numColumns)
        fail(kQ3ErrorParameterOutOfRange, describeIndex(column, data().numColumns, "column", "columns"));
    return data().controlPoints[row * data().numColumns + column];
}

void NURBPatch::setControlPoint(unsigned long row, unsigned long column, const TQ3RationalPoint4D& point)
{
    controlPoint(row, column);
    const std::string where =
        formatMessage("controlPoints[%lu] (row %lu, column %lu)", row * data().numColumns + column, row, column);
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z) || !std::isfinite(point.w))
        fail(kQ3ErrorInvalidParameter, "the new " + where + " has a value that is not finite");
    if (!(point.w > 0.0f))
        fail(kQ3ErrorInvalidParameter,
             "the new " + where + " has w = " + num(point.w) + "; weights must be positive");
    editableData().controlPoints[row * data().numColumns + column] = point;
    markEdited();
}

float NURBPatch::uKnot(unsigned long index) const
{
    const unsigned long count = data().uOrder + data().numColumns;
    if (index >= count)
        fail(kQ3ErrorParameterOutOfRange, describeIndex(index, count, "u knot index", "u knots"));
    return data().uKnots[index];
}

float NURBPatch::vKnot(unsigned long index) const
{
    const unsigned long count = data().vOrder + data().numRows;
    if (index >= count)
        fail(kQ3ErrorParameterOutOfRange, describeIndex(index, count, "v knot index", "v knots"));
    return data().vKnots[index];
}

void NURBPatch::setUKnot(unsigned long index, float value)
{
    setKnot(true, index, value);
}

void NURBPatch::setVKnot(unsigned long index, float value)
{
    setKnot(false, index, value);
}

void NURBPatch::setKnot(bool inU, unsigned long index, float value)
{
    inU ? uKnot(index) : vKnot(index);
    const TQ3NURBPatchData& d = data();
    const float* knots = inU ? d.uKnots : d.vKnots;
    const unsigned long count = inU ? d.uOrder + d.numColumns : d.vOrder + d.numRows;
    std::vector<float> candidate(knots, knots + count);
    candidate[index] = value;
    TQ3NURBPatchData changed = d;
    (inU ? changed.uKnots : changed.vKnots) = candidate.data();
    try {
        validateNURBPatchData(&changed);
    } catch (const Error& error) {
        fail(kQ3ErrorInvalidParameter, formatMessage("setting %s[%lu] to %s would break a rule: ",
                                                     inU ? "uKnots" : "vKnots", index, num(value).c_str()) +
                                           error.what());
    }
    (inU ? editableData().uKnots : editableData().vKnots)[index] = value;
    markEdited();
}

} // namespace q3
