// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Torus.h"

#include "geometry/DataGeometryImpl.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace q3 {

const ClassInfo kTorusClass{kQ3GeometryTypeTorus, &kGeometryClass, "torus"};

template class DataGeometry<Torus, TQ3TorusData>;

void Torus::check(const TQ3TorusData& d)
{
    requireWithinFloatRange(d.origin, {d.majorRadius, d.minorRadius, d.orientation}, 1.0 + std::fabs(double(d.ratio)));
    requireUnitParameter(d.uMin, "uMin");
    requireUnitParameter(d.uMax, "uMax");
    requireUnitParameter(d.vMin, "vMin");
    requireUnitParameter(d.vMax, "vMax");
    if (!(d.ratio >= 0.0f))
        fail(kQ3ErrorInvalidData, "ratio is " + std::to_string(d.ratio) + "; a torus's ratio must not be negative");
    requireCapBits(d.caps);
}

std::string Torus::degeneracy(const TQ3TorusData& d)
{
    return firstCase({dependentFrame(d.orientation, d.majorRadius, d.minorRadius,
                                     "orientation, majorRadius and minorRadius"),
                      d.ratio == 0.0f ? "ratio is 0: the tube has no thickness" : "",
                      emptyAngle(d.uMin, d.uMax, "uMin", "uMax"), emptyAngle(d.vMin, d.vMax, "vMin", "vMax")});
}

quadric::Patches Torus::patches(const TQ3TorusData& d)
{
    quadric::TorusShape shape;
    shape.origin = toVec3(d.origin);
    shape.orientation = toVec3(d.orientation);
    shape.majorRadius = toVec3(d.majorRadius);
    shape.minorRadius = toVec3(d.minorRadius);
    shape.ratio = d.ratio;
    shape.u = quadric::angularRange(d.uMin, d.uMax);
    shape.v = quadric::angularRange(d.vMin, d.vMax);
    shape.caps = unsigned(d.caps);
    return quadric::torusPatches(shape);
}

void Torus::boundPoints(const TQ3TorusData& d, std::vector<glm::dvec3>& points)
{
    // A point is origin + ring + (-sin psi z - cos psi k ahat), ahat a unit
    // vector in the ring's plane: |ahat_i| <= sqrt(p_i^2 + q_i^2) for an
    // orthonormal basis p, q of that plane.
    const glm::dvec3 x = toVec3(d.majorRadius), y = toVec3(d.minorRadius), z = toVec3(d.orientation);
    const glm::dvec3 p = glm::normalize(x);
    const glm::dvec3 q = glm::normalize(y - glm::dot(y, p) * p);
    const double k = double(d.ratio) * glm::length(z);
    glm::dvec3 half;
    for (int i = 0; i < 3; ++i)
        half[i] = std::hypot(x[i], y[i]) + std::sqrt(z[i] * z[i] + k * k * (p[i] * p[i] + q[i] * q[i]));
    const glm::dvec3 centre = toVec3(d.origin);
    points.push_back(centre - half);
    points.push_back(centre + half);
}

std::vector<const AttributeSet*> Torus::partSets() const
{
    return {nullptr, nullptr, nullptr, heldAttributeSet(data().interiorAttributeSet)};
}

} // namespace q3
