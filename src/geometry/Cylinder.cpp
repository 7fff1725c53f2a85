// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Cylinder.h"

#include "geometry/DataGeometryImpl.h"

namespace q3 {

const ClassInfo kCylinderClass{kQ3GeometryTypeCylinder, &kGeometryClass, "cylinder"};

namespace layout {
template <> struct Describe<TQ3CylinderData> {
    static auto fields()
    {
        using D = TQ3CylinderData;
        return std::make_tuple(value("origin", &D::origin), value("orientation", &D::orientation),
                               value("majorRadius", &D::majorRadius), value("minorRadius", &D::minorRadius),
                               value("uMin", &D::uMin), value("uMax", &D::uMax), value("vMin", &D::vMin),
                               value("vMax", &D::vMax), value("caps", &D::caps),
                               handle<AttributeSet>("interiorAttributeSet", &D::interiorAttributeSet),
                               handle<AttributeSet>("topAttributeSet", &D::topAttributeSet),
                               handle<AttributeSet>("faceAttributeSet", &D::faceAttributeSet),
                               handle<AttributeSet>("bottomAttributeSet", &D::bottomAttributeSet),
                               handle<AttributeSet>("cylinderAttributeSet", &D::cylinderAttributeSet));
    }
};
} // namespace layout

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
