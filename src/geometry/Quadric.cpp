// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Quadric.h"

#include "core/AttributeSet.h"
#include "core/ParameterChecks.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <string>

namespace q3 {

static_assert(unsigned(kQ3EndCapMaskTop) == quadric::kCapTop && unsigned(kQ3EndCapMaskBottom) == quadric::kCapBottom &&
                  unsigned(kQ3EndCapMaskInterior) == quadric::kCapInterior,
              "quadric::Caps are QuickDraw 3D's TQ3EndCapMasks");

void requireWithinFloatRange(const TQ3Point3D& origin, std::initializer_list<TQ3Vector3D> vectors, double lastScale)
{
    double reach = 0.0;
    std::size_t i = 0;
    for (const TQ3Vector3D& v : vectors)
        reach += glm::length(toVec3(v)) * (++i == vectors.size() ? lastScale : 1.0);
    const double largest =
        std::max({std::fabs(double(origin.x)), std::fabs(double(origin.y)), std::fabs(double(origin.z))});
    if (!(largest + reach <= double(FLT_MAX)))
        fail(kQ3ErrorInvalidData, "the shape reaches " + numberText(largest + reach) +
                                      " from the local origin, beyond the range of float (" + numberText(FLT_MAX) +
                                      ")");
}

void requireUnitParameter(float value, const char* name)
{
    if (!(value >= 0.0f && value <= 1.0f))
        fail(kQ3ErrorInvalidData, std::string(name) + " is " + numberText(value) + ", outside 0 to 1");
}

void requireOrdered(float min, float max, const char* minName, const char* maxName)
{
    if (min > max)
        fail(kQ3ErrorInvalidData,
             std::string(minName) + " (" + numberText(min) + ") is above " + maxName + " (" + numberText(max) + ")");
}

void requireCapBits(TQ3EndCap caps)
{
    const TQ3EndCap known = kQ3EndCapMaskTop | kQ3EndCapMaskBottom | kQ3EndCapMaskInterior;
    if ((caps & ~known) != 0)
        fail(kQ3ErrorInvalidData, "caps is " + std::to_string(caps) +
                                      ": only kQ3EndCapMaskTop, kQ3EndCapMaskBottom and kQ3EndCapMaskInterior "
                                      "are end cap bits");
}

std::string dependentFrame(const TQ3Vector3D& x, const TQ3Vector3D& y, const TQ3Vector3D& z, const char* what)
{
    if (quadric::independence(toVec3(x), toVec3(y), toVec3(z)) > quadric::kDegenerateFrame)
        return {};
    return std::string(what) + " are zero or lie in one plane: the shape is flat";
}

std::string dependentFrame(const TQ3Vector3D& x, const TQ3Vector3D& y, const char* what)
{
    if (quadric::independence(toVec3(x), toVec3(y)) > quadric::kDegenerateFrame)
        return {};
    return std::string(what) + " are zero or parallel: the shape is a line or a point";
}

std::string emptyAngle(float min, float max, const char* minName, const char* maxName)
{
    if (min != max && !(min == 1.0f && max == 0.0f))
        return {};
    return std::string(minName) + " " + numberText(min) + " and " + maxName + " " + numberText(max) +
           " select no angle";
}

std::string emptyRange(float min, float max, const char* minName, const char* maxName)
{
    if (min != max)
        return {};
    return std::string(minName) + " and " + maxName + " are both " + numberText(min) + ": the range is empty";
}

std::string firstCase(std::initializer_list<std::string> cases)
{
    for (const std::string& c : cases)
        if (!c.empty())
            return c;
    return {};
}

quadric::Subdivision subdivisionFor(const SubdivisionMeasure& measure, std::size_t maxTriangles)
{
    quadric::Subdivision s;
    s.maxTriangles = maxTriangles;
    s.c1 = measure.options.c1;
    s.c2 = measure.options.c2;
    if (measure.options.method == nurbs::Method::kConstant) {
        s.method = quadric::Method::kConstant;
        return s;
    }
    s.method = quadric::Method::kMeasured;
    s.map = [map = measure.options.mapping](const quadric::Vec3& local, quadric::Vec3& mapped) {
        nurbs::Point3 out;
        if (!map(nurbs::Point3{local.x, local.y, local.z}, out))
            return false;
        mapped = quadric::Vec3(out.x, out.y, out.z);
        return true;
    };
    return s;
}

std::string buildSurface(Mesh& mesh, const quadric::Patches& patches, const SubdivisionMeasure& measure,
                         const std::vector<const AttributeSet*>& sets, const char* shape)
{
    const quadric::Tessellation t =
        quadric::tessellate(patches, subdivisionFor(measure, limits::kMaxTrianglesPerSurface));
    mesh.reserveVertices(t.positions.size());
    for (std::size_t i = 0; i < t.positions.size(); ++i) {
        VertexAttributes attributes;
        attributes.normal = TQ3Vector3D{float(t.normals[i].x), float(t.normals[i].y), float(t.normals[i].z)};
        attributes.uv = TQ3Param2D{float(t.uvs[i].x), float(t.uvs[i].y)};
        const std::size_t part = std::size_t(t.parts[i]);
        attributes.inheritFrom(part < sets.size() ? sets[part] : nullptr);
        mesh.addVertex(TQ3Point3D{float(t.positions[i].x), float(t.positions[i].y), float(t.positions[i].z)},
                       attributes);
    }
    for (std::size_t k = 0; k < t.triangles.size(); k += 3)
        mesh.addTriangle(t.triangles[k], t.triangles[k + 1], t.triangles[k + 2]);
    mesh.edgesFromTriangles();
    if (!t.reduced)
        return {};
    SubdivisionShortfall shortfall;
    shortfall.shape = std::string(std::strchr("aeiou", shape[0]) != nullptr ? "an " : "a ") + shape;
    shortfall.limit =
        "kQ3SubdivisionMaxTrianglesPerSurface (" + std::to_string(limits::kMaxTrianglesPerSurface) + ") triangles";
    shortfall.withC2 = measure.options.method == nurbs::Method::kConstant;
    shortfall.used = shortfall.withC2 ? "c1 = " + numberText(t.effectiveC1) + " and c2 = " + numberText(t.effectiveC2) +
                                            " are used"
                                      : "edges up to " + numberText(t.effectiveC1) + " long are used";
    return subdivisionWarning(measure, shortfall);
}

void ellipseBoxCorners(const quadric::Vec3& centre, const quadric::Vec3& x, const quadric::Vec3& y,
                       std::vector<glm::dvec3>& points)
{
    const glm::dvec3 half(std::hypot(x.x, y.x), std::hypot(x.y, y.y), std::hypot(x.z, y.z));
    for (int corner = 0; corner < 8; ++corner)
        points.emplace_back(centre.x + ((corner & 1) ? half.x : -half.x), centre.y + ((corner & 2) ? half.y : -half.y),
                            centre.z + ((corner & 4) ? half.z : -half.z));
}

} // namespace q3
