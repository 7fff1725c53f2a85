// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "geometry/Geometry.h"

#include <cstddef>
#include <vector>

namespace q3 {

extern const ClassInfo kPolyLineClass;

/// Checks a caller's TQ3PolyLineData against the rules in QD3DGeometry.h, in
/// their order: kQ3ErrorNULLParameter (data or vertices is NULL),
/// kQ3ErrorGeometryInsufficientNumberOfPoints (numVertices < 2),
/// kQ3ErrorInvalidData (a coordinate is not finite). The one routine behind
/// Q3PolyLine_New, _SetData and _Submit. The attribute set handles are checked
/// when the polyline resolves them (after this, as the rules list them).
void validatePolyLineData(const TQ3PolyLineData* data);

/// A retained polyline. Invariant: at least two vertices, every coordinate
/// finite; the polyline holds one reference to every attribute set it names
/// (m_vertexSets, m_segmentSets, and its own through Geometry), and the
/// attributeSet field of each entry of m_vertices is the same object as the
/// matching m_vertexSets entry, so vertices() hands out handles that stay
/// valid while the polyline lives. m_segmentSets is empty when no segment
/// array was given (nor made by setSegmentAttributeSet), else holds
/// numVertices - 1 entries (each possibly null).
class PolyLine final : public Geometry {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypePolyLine;

    /// Copies valid data (validate first). Throws kQ3ErrorInvalidObject or
    /// kQ3ErrorInvalidObjectType for a bad attribute set handle.
    explicit PolyLine(const TQ3PolyLineData& data);

    /// A polyline through `count` points given as x y z triples, without
    /// vertex or segment attribute sets; `attributes` (may be null) becomes
    /// its polyLineAttributeSet, with a reference of its own. This is how the
    /// view hands out Q3Geometry_GetDecomposed results. Throws
    /// kQ3ErrorNULLParameter (xyz is null),
    /// kQ3ErrorGeometryInsufficientNumberOfPoints (count < 2) or
    /// kQ3ErrorInvalidData (a coordinate is not finite).
    static Ref<PolyLine> fromPoints(const float* xyz, std::size_t count,
                                    const AttributeSet* attributes = nullptr);

    const ClassInfo& classInfo() const override { return kPolyLineClass; }
    Object* duplicate() const override;
    void accept(ShapeVisitor& visitor) const override;

    /// Fills `out` with malloc'ed copies of the arrays and one new reference
    /// per attribute set named in them (see emptyData).
    void getData(TQ3PolyLineData& out) const;
    void setData(const TQ3PolyLineData& data);
    /// Gives back what getData handed out: releases every reference, frees
    /// both arrays, sets the pointers to NULL. Does nothing to emptied data.
    static void emptyData(TQ3PolyLineData& data);

    const std::vector<TQ3Vertex3D>& vertices() const { return m_vertices; }
    /// Vertex `index` (kQ3ErrorParameterOutOfRange unless < vertices().size()).
    const TQ3Vertex3D& vertex(std::size_t index) const;
    /// The attribute set of vertex `index` (< vertices().size()), or null.
    const AttributeSet* vertexAttributeSet(std::size_t index) const;
    bool hasSegmentAttributeSets() const { return !m_segmentSets.empty(); }
    /// The attribute set of the segment from vertex `index` to `index + 1`,
    /// or null (also when the polyline has no segment array); throws
    /// kQ3ErrorParameterOutOfRange unless index < vertices().size() - 1.
    const AttributeSet* segmentAttributeSet(std::size_t index) const;

    /// Moves vertex `index`: kQ3ErrorParameterOutOfRange for a bad index, then
    /// kQ3ErrorInvalidData for a coordinate that is not finite (the
    /// TQ3PolyLineData rule); nothing changes on failure.
    void setVertexPosition(std::size_t index, const TQ3Point3D& position);
    /// Replaces the attribute set of vertex `index` (null removes it).
    void setVertexAttributeSet(std::size_t index, Ref<AttributeSet> attributes);
    /// Replaces the attribute set of segment `index` (null removes it). A
    /// polyline without a segment array gains one (all other entries null)
    /// when given a set; removing a set from it changes nothing.
    void setSegmentAttributeSet(std::size_t index, Ref<AttributeSet> attributes);

private:
    PolyLine() = default;
    void assign(const TQ3PolyLineData& data);
    void checkVertexIndex(std::size_t index) const;
    void checkSegmentIndex(std::size_t index) const;

    std::vector<TQ3Vertex3D> m_vertices;
    std::vector<Ref<AttributeSet>> m_vertexSets;
    std::vector<Ref<AttributeSet>> m_segmentSets;
};

} // namespace q3
