// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/DataGeometry.h"

#include <array>

namespace q3 {

extern const ClassInfo kTriGridClass;

/// A triangle grid. Invariant: its data obeys the TQ3TriGridData rules of
/// QD3DGeometry.h (at least 2 x 2 finite vertices, at most
/// kQ3GeometryMaxArrayCount); facetAttributeSet is NULL or one set (each may
/// be NULL) per facet.
class TriGrid final : public DataGeometry<TriGrid, TQ3TriGridData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeTriGrid;
    static constexpr const char* kName = "triangle grid";
    static constexpr const char* kDataName = "triGridData";
    static constexpr TQ3AttributeSet TQ3TriGridData::*kOwnSet = &TQ3TriGridData::triGridAttributeSet;

    /// 2 (rows - 1) (columns - 1), saturating (0 for fewer than 2 of either).
    static std::size_t facetCount(const TQ3TriGridData& data);
    /// The vertex indices (row * numColumns + column) of facet `facet`, in
    /// the order QD3DGeometry.h gives: the diagonal alternates by column.
    static std::array<std::size_t, 3> facetVertices(std::size_t numColumns, std::size_t facet);

    using DataGeometry::DataGeometry;

    const ClassInfo& classInfo() const override { return kTriGridClass; }
    /// Each facet with its own three vertices (a vertex's attributes, then
    /// its facet's); every side of every facet in the wireframe.
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;

    const TQ3Vertex3D& vertex(unsigned long row, unsigned long column) const;
    void setVertexPosition(unsigned long row, unsigned long column, const TQ3Point3D& position);
    void setVertexAttributeSet(unsigned long row, unsigned long column, Ref<AttributeSet> attributes);
    /// Facet `index`'s set or null (kQ3ErrorParameterOutOfRange past the end).
    const AttributeSet* facetSet(unsigned long index) const;
    /// Replaces the set of facet `index`, making the array when there is none.
    void setFacetSet(unsigned long index, Ref<AttributeSet> set);

private:
    std::size_t vertexIndex(unsigned long row, unsigned long column) const;
};

// The data description (core/DataLayout.h).
namespace layout {
template <>
struct Describe<TQ3TriGridData> {
    static auto fields()
    {
        using D = TQ3TriGridData;
        return std::make_tuple(
            atLeast("numRows", &D::numRows, 2), atLeast("numColumns", &D::numColumns, 2),
            requiredArray("vertices", &D::vertices, countProduct(&D::numRows, &D::numColumns)),
            optionalHandleArray<AttributeSet>("facetAttributeSet", &D::facetAttributeSet,
                                              [](const D& d) { return d.facetAttributeSet != nullptr ? TriGrid::facetCount(d) : 0; }),
            handle<AttributeSet>("triGridAttributeSet", &D::triGridAttributeSet));
    }
};
} // namespace layout

} // namespace q3
