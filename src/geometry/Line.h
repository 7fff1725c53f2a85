// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "geometry/Geometry.h"

#include <array>

namespace q3 {

extern const ClassInfo kLineClass;

/// Checks a caller's TQ3LineData against the rules in QD3DGeometry.h:
/// kQ3ErrorNULLParameter (data is NULL), kQ3ErrorInvalidData (a coordinate is
/// not finite). The one routine behind Q3Line_New, _SetData and _Submit; the
/// attribute set handles are checked when the line resolves them.
void validateLineData(const TQ3LineData* data);

/// A retained line segment. Invariant: both end points are finite; the line
/// holds one reference to each end's attribute set (its own is held by
/// Geometry), and the attributeSet field of m_vertices[i] is the object
/// m_vertexSets[i] holds, so vertex() hands out handles that stay valid while
/// the line lives.
class Line final : public Geometry {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeLine;

    /// Copies valid data (validate first). Throws kQ3ErrorInvalidObject or
    /// kQ3ErrorInvalidObjectType for a bad attribute set handle.
    explicit Line(const TQ3LineData& data);

    const ClassInfo& classInfo() const override { return kLineClass; }
    Object* duplicate() const override;
    void accept(ShapeVisitor& visitor) const override;

    /// Fills `out` with the vertices and one new reference per attribute set
    /// (see emptyData).
    void getData(TQ3LineData& out) const;
    void setData(const TQ3LineData& data);
    /// Releases the three references getData handed out and sets them to NULL.
    static void emptyData(TQ3LineData& data);

    /// End point `index`, 0 or 1 (kQ3ErrorParameterOutOfRange otherwise).
    const TQ3Vertex3D& vertex(unsigned long index) const;
    /// The attribute set of end point `index` (0 or 1), or null.
    const AttributeSet* vertexAttributeSet(unsigned long index) const;

    /// Moves end point `index`: kQ3ErrorParameterOutOfRange unless it is 0 or
    /// 1, then kQ3ErrorInvalidData for a coordinate that is not finite (the
    /// TQ3LineData rule); nothing changes on failure.
    void setVertexPosition(unsigned long index, const TQ3Point3D& position);
    /// Replaces the attribute set of end point `index` (null removes it);
    /// kQ3ErrorParameterOutOfRange unless index is 0 or 1.
    void setVertexAttributeSet(unsigned long index, Ref<AttributeSet> attributes);

private:
    Line() = default;
    void assign(const TQ3LineData& data);
    static void checkIndex(unsigned long index);

    std::array<TQ3Vertex3D, 2> m_vertices{};
    std::array<Ref<AttributeSet>, 2> m_vertexSets;
};

} // namespace q3
