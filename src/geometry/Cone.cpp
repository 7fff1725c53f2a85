// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Cone.h"

#include "geometry/DataGeometryImpl.h"

namespace q3 {

const ClassInfo kConeClass{kQ3GeometryTypeCone, &kGeometryClass, "cone"};

namespace layout {
template <> struct Describe<TQ3ConeData> {
    static auto fields()
    {
        using D = TQ3ConeData;
        return std::make_tuple(value("origin", &D::origin), value("orientation", &D::orientation),
                               value("majorRadius", &D::majorRadius), value("minorRadius", &D::minorRadius),
                               value("uMin", &D::uMin), value("uMax", &D::uMax), value("vMin", &D::vMin),
                               value("vMax", &D::vMax), value("caps", &D::caps),
                               handle<AttributeSet>("interiorAttributeSet", &D::interiorAttributeSet),
                               handle<AttributeSet>("faceAttributeSet", &D::faceAttributeSet),
                               handle<AttributeSet>("bottomAttributeSet", &D::bottomAttributeSet),
                               handle<AttributeSet>("coneAttributeSet", &D::coneAttributeSet));
    }
};
} // namespace layout

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
