// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Cylinder.h"

#include "geometry/DataGeometryImpl.h"

namespace q3 {

const ClassInfo kCylinderClass{kQ3GeometryTypeCylinder, &kGeometryClass, "cylinder"};

template class DataGeometry<Cylinder, TQ3CylinderData>;

void Cylinder::boundPoints(const TQ3CylinderData& d, std::vector<glm::dvec3>& points)
{
    ellipseBoxCorners(toVec3(d.origin), toVec3(d.majorRadius), toVec3(d.minorRadius), points);
    ellipseBoxCorners(toVec3(d.origin) + toVec3(d.orientation), toVec3(d.majorRadius), toVec3(d.minorRadius), points);
}

std::vector<const AttributeSet*> Cylinder::partSets() const
{
    return {heldAttributeSet(data().faceAttributeSet), heldAttributeSet(data().bottomAttributeSet),
            heldAttributeSet(data().topAttributeSet), heldAttributeSet(data().interiorAttributeSet)};
}

} // namespace q3
