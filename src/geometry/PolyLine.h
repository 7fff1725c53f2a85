// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/DataGeometry.h"

#include <cstddef>

namespace q3 {

extern const ClassInfo kPolyLineClass;

/// A polyline. Invariant: at least two vertices, every coordinate finite;
/// the segment attribute array is NULL or holds numVertices - 1 entries.
class PolyLine final : public DataGeometry<PolyLine, TQ3PolyLineData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypePolyLine;
    static constexpr const char* kName = "polyLine";
    static constexpr const char* kDataName = "polyLineData";
    static constexpr TQ3AttributeSet TQ3PolyLineData::*kOwnSet = &TQ3PolyLineData::polyLineAttributeSet;

    // The TQ3PolyLineData rules of QD3DGeometry.h are all in the description below.

    /// numVertices - 1, or 0 without vertices.
    static std::size_t segmentCount(const TQ3PolyLineData& data)
    {
        return data.numVertices == 0 ? 0 : std::size_t(data.numVertices) - 1;
    }

    using DataGeometry::DataGeometry;
    ~PolyLine() override;

    /// A polyline through `count` points given as x y z triples, without
    /// vertex or segment attribute sets; `attributes` (may be null) becomes
    /// its polyLineAttributeSet. How decompositions are handed out. Throws
    /// kQ3ErrorNULLParameter (xyz is null),
    /// kQ3ErrorGeometryInsufficientNumberOfPoints (count < 2) or
    /// kQ3ErrorInvalidData (a coordinate is not finite).
    static Ref<PolyLine> fromPoints(const float* xyz, std::size_t count, const AttributeSet* attributes = nullptr);

    /// Q3PolyLine_GetData: DataGeometry::getData's copy, made with one
    /// memcpy of the vertices while they are known to hold no attribute sets.
    void getData(TQ3PolyLineData& out) const;
    /// Q3PolyLine_EmptyData: DataGeometry::emptyData (every handle checked,
    /// then released), with one pass over vertices that hold no sets.
    static void emptyData(TQ3PolyLineData& data);

    const ClassInfo& classInfo() const override { return kPolyLineClass; }
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;
    bool isPrimitive() const override { return true; }

    std::size_t vertexCount() const { return data().numVertices; }
    /// Vertex `index` (kQ3ErrorParameterOutOfRange unless < vertexCount()).
    const TQ3Vertex3D& vertex(std::size_t index) const;
    /// The attribute set of vertex `index` (< vertexCount()), or null.
    const AttributeSet* vertexAttributeSet(std::size_t index) const;
    bool hasSegmentAttributeSets() const { return data().segmentAttributeSet != nullptr; }
    /// The attribute set of the segment from vertex `index` to `index + 1`,
    /// or null (also when the polyline has no segment array); throws
    /// kQ3ErrorParameterOutOfRange unless index < vertexCount() - 1.
    const AttributeSet* segmentAttributeSet(std::size_t index) const;

    /// Moves vertex `index`: kQ3ErrorParameterOutOfRange for a bad index, then
    /// kQ3ErrorInvalidData for a coordinate that is not finite; nothing
    /// changes on failure.
    void setVertexPosition(std::size_t index, const TQ3Point3D& position);
    /// Replaces the attribute set of vertex `index` (null removes it).
    void setVertexAttributeSet(std::size_t index, Ref<AttributeSet> attributes);
    /// Replaces the attribute set of segment `index` (null removes it). A
    /// polyline without a segment array gains one (all other entries null)
    /// when given a set; removing a set from it changes nothing.
    void setSegmentAttributeSet(std::size_t index, Ref<AttributeSet> attributes);

private:
    void checkSegmentIndex(std::size_t index) const;
    /// Whether no vertex holds an attribute set: so since fromPoints made the
    /// polyline, until its first edit (every change of the data bumps the
    /// edit index).
    bool verticesWithoutSets() const { return m_verticesWithoutSetsAt == editIndex(); }

    /// The edit index at which fromPoints made the polyline, 0 (no index) for
    /// one made any other way.
    unsigned long m_verticesWithoutSetsAt = 0;
};

// The data description (core/DataLayout.h), with the 3DMF form its reader
// and writer come from (io/SimpleGeometryIO.cpp).
namespace layout {
template <>
struct Describe<TQ3PolyLineData> {
    static auto fields()
    {
        return std::make_tuple(
            atLeast("numVertices", &TQ3PolyLineData::numVertices, 2),
            requiredArray("vertices", &TQ3PolyLineData::vertices, countOf(&TQ3PolyLineData::numVertices)),
            optionalHandleArray<AttributeSet>("segmentAttributeSet", &TQ3PolyLineData::segmentAttributeSet,
                                              PolyLine::segmentCount),
            handle<AttributeSet>("polyLineAttributeSet", &TQ3PolyLineData::polyLineAttributeSet));
    }
    static auto fileFields()
    {
        return std::make_tuple(vertexPoints(&TQ3PolyLineData::numVertices, &TQ3PolyLineData::vertices));
    }
    // The segments' sets: a GeometryAttributeSetList of numVertices - 1
    // elements, as Quesa reads them.
    static auto fileParts()
    {
        using D = TQ3PolyLineData;
        return std::make_tuple(ownSetPart(&D::polyLineAttributeSet), vertexSetsPart(&D::numVertices, &D::vertices),
                               setListPart(SetList::kOtherParts, &D::segmentAttributeSet, PolyLine::segmentCount));
    }
};
} // namespace layout

} // namespace q3
