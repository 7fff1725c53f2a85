// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/Quadric.h"

namespace q3 {

extern const ClassInfo kBoxClass;

/// A box (a parallelepiped). Invariant: its data obeys the TQ3BoxData rules
/// of QD3DGeometry.h; faceAttributeSet is NULL or six sets (each may be NULL).
class Box final : public QuadricGeometry<Box, TQ3BoxData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeBox;
    static constexpr const char* kName = "box";
    static constexpr const char* kDataName = "boxData";
    static constexpr TQ3AttributeSet TQ3BoxData::*kOwnSet = &TQ3BoxData::boxAttributeSet;
    static constexpr unsigned long kFaces = 6;

    /// The TQ3BoxData rules of QD3DGeometry.h, in their order.
    static void check(const TQ3BoxData& data);
    /// The tolerated degenerate case of the data (Quadric.h), or "".
    static std::string degeneracy(const TQ3BoxData& data);
    static quadric::Patches patches(const TQ3BoxData& data);
    /// The eight corners.
    static void boundPoints(const TQ3BoxData& data, std::vector<glm::dvec3>& points);

    using QuadricGeometry::QuadricGeometry;

    const ClassInfo& classInfo() const override { return kBoxClass; }
    /// The face sets in face order (null where there are none).
    std::vector<const AttributeSet*> partSets() const;

    /// Face `index` (0 to 5: kQ3ErrorParameterOutOfRange otherwise): its
    /// set, or null.
    const AttributeSet* faceSet(unsigned long index) const;
    /// Replaces the set of face `index` (kQ3ErrorParameterOutOfRange for an
    /// index above 5), making the array of six when the box has none.
    void setFaceSet(unsigned long index, Ref<AttributeSet> set);
};

// The data description (core/DataLayout.h), with the 3DMF form its reader
// and writer come from (io/SimpleGeometryIO.cpp).
namespace layout {
template <> struct Describe<TQ3BoxData> {
    static auto fields()
    {
        using D = TQ3BoxData;
        return std::make_tuple(
            finite("origin", &D::origin), finite("orientation", &D::orientation), finite("majorAxis", &D::majorAxis),
            finite("minorAxis", &D::minorAxis),
            optionalHandleArray<AttributeSet>("faceAttributeSet", &D::faceAttributeSet, fixedCount<Box::kFaces>()),
            handle<AttributeSet>("boxAttributeSet", &D::boxAttributeSet));
    }
    // An empty Box ( ) is the unit box at the origin (MF3D's MF3DBoxData).
    static auto fileFields()
    {
        using D = TQ3BoxData;
        return std::make_tuple(vector3D(&D::orientation, {1, 0, 0}), vector3D(&D::majorAxis, {0, 1, 0}),
                               vector3D(&D::minorAxis, {0, 0, 1}), point3D(&D::origin, {0, 0, 0}));
    }
    // The six faces' sets in face order (left, right, front, back, top, bottom).
    static auto fileParts()
    {
        using D = TQ3BoxData;
        return std::make_tuple(setListPart(SetList::kFaces, &D::faceAttributeSet, fixedCount<Box::kFaces>()),
                               ownSetPart(&D::boxAttributeSet));
    }
};
} // namespace layout

} // namespace q3
