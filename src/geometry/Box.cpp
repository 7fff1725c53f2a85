// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Box.h"

#include "geometry/DataGeometryImpl.h"

namespace q3 {

const ClassInfo kBoxClass{kQ3GeometryTypeBox, &kGeometryClass, "box"};

template class DataGeometry<Box, TQ3BoxData>;

void Box::check(const TQ3BoxData& d)
{
    requireWithinFloatRange(d.origin, {d.orientation, d.majorAxis, d.minorAxis});
}

std::string Box::degeneracy(const TQ3BoxData& d)
{
    return dependentFrame(d.orientation, d.majorAxis, d.minorAxis, "orientation, majorAxis and minorAxis");
}

quadric::Patches Box::patches(const TQ3BoxData& d)
{
    return quadric::boxPatches(
        quadric::BoxShape{toVec3(d.origin), toVec3(d.orientation), toVec3(d.majorAxis), toVec3(d.minorAxis)});
}

void Box::boundPoints(const TQ3BoxData& d, std::vector<glm::dvec3>& points)
{
    for (int corner = 0; corner < 8; ++corner)
        points.push_back(toVec3(d.origin) + ((corner & 1) ? toVec3(d.majorAxis) : glm::dvec3(0.0)) +
                         ((corner & 2) ? toVec3(d.minorAxis) : glm::dvec3(0.0)) +
                         ((corner & 4) ? toVec3(d.orientation) : glm::dvec3(0.0)));
}

std::vector<const AttributeSet*> Box::partSets() const
{
    std::vector<const AttributeSet*> sets(kFaces, nullptr);
    if (data().faceAttributeSet != nullptr)
        for (unsigned long i = 0; i < kFaces; ++i)
            sets[i] = heldAttributeSet(data().faceAttributeSet[i]);
    return sets;
}

const AttributeSet* Box::faceSet(unsigned long index) const
{
    checkIndex(index, kFaces, "face index", "the box");
    return data().faceAttributeSet != nullptr ? heldAttributeSet(data().faceAttributeSet[index]) : nullptr;
}

void Box::setFaceSet(unsigned long index, Ref<AttributeSet> set)
{
    checkIndex(index, kFaces, "face index", "the box");
    TQ3BoxData& d = editableData();
    if (d.faceAttributeSet == nullptr) {
        if (!set) {
            markEdited();
            return;
        }
        d.faceAttributeSet = layout::allocate<TQ3AttributeSet>(kFaces);
        for (unsigned long i = 0; i < kFaces; ++i)
            d.faceAttributeSet[i] = nullptr;
    }
    replaceHeldSet(d.faceAttributeSet[index], std::move(set));
    markEdited();
}

} // namespace q3
