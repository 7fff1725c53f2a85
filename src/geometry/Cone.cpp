// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Cone.h"

#include "geometry/DataGeometryImpl.h"

namespace q3 {

const ClassInfo kConeClass{kQ3GeometryTypeCone, &kGeometryClass, "cone"};

template class DataGeometry<Cone, TQ3ConeData>;

void Cone::boundPoints(const TQ3ConeData& d, std::vector<glm::dvec3>& points)
{
    ellipseBoxCorners(toVec3(d.origin), toVec3(d.majorRadius), toVec3(d.minorRadius), points);
    points.push_back(toVec3(d.origin) + toVec3(d.orientation));
}

std::vector<const AttributeSet*> Cone::partSets() const
{
    return {heldAttributeSet(data().faceAttributeSet), heldAttributeSet(data().bottomAttributeSet), nullptr,
            heldAttributeSet(data().interiorAttributeSet)};
}

} // namespace q3
