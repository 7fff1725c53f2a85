// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Ellipsoid.h"

#include "geometry/DataGeometryImpl.h"

#include <cmath>

namespace q3 {

const ClassInfo kEllipsoidClass{kQ3GeometryTypeEllipsoid, &kGeometryClass, "ellipsoid"};

template class DataGeometry<Ellipsoid, TQ3EllipsoidData>;

void Ellipsoid::boundPoints(const TQ3EllipsoidData& d, std::vector<glm::dvec3>& points)
{
    const glm::dvec3 x = toVec3(d.majorRadius), y = toVec3(d.minorRadius), z = toVec3(d.orientation);
    const glm::dvec3 half(std::sqrt(x.x * x.x + y.x * y.x + z.x * z.x), std::sqrt(x.y * x.y + y.y * y.y + z.y * z.y),
                          std::sqrt(x.z * x.z + y.z * y.z + z.z * z.z));
    const glm::dvec3 centre = toVec3(d.origin);
    points.push_back(centre - half);
    points.push_back(centre + half);
}

std::vector<const AttributeSet*> Ellipsoid::partSets() const
{
    const AttributeSet* interior = heldAttributeSet(data().interiorAttributeSet);
    return {nullptr, interior, interior, interior};
}

} // namespace q3
