// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/Quadric.h"

namespace q3 {

extern const ClassInfo kEllipseClass;

/// An ellipse (a curve), possibly partial in u. Invariant: its data obeys
/// the TQ3EllipseData rules of QD3DGeometry.h.
class Ellipse final : public FieldGeometry<Ellipse, TQ3EllipseData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeEllipse;
    static constexpr const char* kName = "ellipse";
    static constexpr const char* kDataName = "ellipseData";
    static constexpr TQ3AttributeSet TQ3EllipseData::*kOwnSet = &TQ3EllipseData::ellipseAttributeSet;

    /// The TQ3EllipseData rules of QD3DGeometry.h, in their order.
    static void check(const TQ3EllipseData& data);
    /// The tolerated degenerate case of the data (Quadric.h), or "".
    static std::string degeneracy(const TQ3EllipseData& data);

    using FieldGeometry::FieldGeometry;

    const ClassInfo& classInfo() const override { return kEllipseClass; }
    /// One line strip from uMin to uMax under the view's subdivision, as a
    /// curve (quadric::tessellateCurve): constant c1 segments per turn, or
    /// segments of at most c1 world units or pixels; at most
    /// kQ3SubdivisionMaxSegmentsPerCurve (then kQ3WarningParameterOutOfRange).
    /// An empty u range draws nothing; radii that are zero or parallel draw
    /// the segment (or point) the formula gives, a curve needing no normal.
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;
    /// The box of the whole ellipse; nothing for an empty u range.
    void bound(const DecomposeContext& context, std::vector<glm::dvec3>& points) const override;

private:
    mutable std::string m_report; // under the mesh lock, as QuadricGeometry's
};

// The data description (core/DataLayout.h), with the 3DMF form its reader
// and writer come from (io/SimpleGeometryIO.cpp).
namespace layout {
template <> struct Describe<TQ3EllipseData> {
    static auto fields()
    {
        using D = TQ3EllipseData;
        return std::make_tuple(finite("origin", &D::origin), finite("majorRadius", &D::majorRadius),
                               finite("minorRadius", &D::minorRadius), finite("uMin", &D::uMin), finite("uMax", &D::uMax),
                               handle<AttributeSet>("ellipseAttributeSet", &D::ellipseAttributeSet));
    }
    // The disk's form with uMin and uMax, as Quesa reads it.
    static auto fileFields()
    {
        using D = TQ3EllipseData;
        return std::make_tuple(vector3D(&D::majorRadius, {1, 0, 0}), vector3D(&D::minorRadius, {0, 1, 0}),
                               point3D(&D::origin, {0, 0, 0}), trailing(float32(&D::uMin, 0), float32(&D::uMax, 1)));
    }
    static auto fileParts() { return std::make_tuple(ownSetPart(&TQ3EllipseData::ellipseAttributeSet)); }
};
} // namespace layout

} // namespace q3
