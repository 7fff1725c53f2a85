// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/DataGeometry.h"

namespace q3 {

extern const ClassInfo kTriangleClass;

/// A triangle. Invariant: its three vertices are finite.
class Triangle final : public DataGeometry<Triangle, TQ3TriangleData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeTriangle;
    static constexpr const char* kName = "triangle";
    static constexpr const char* kDataName = "triangleData";
    static constexpr TQ3AttributeSet TQ3TriangleData::*kOwnSet = &TQ3TriangleData::triangleAttributeSet;

    // The TQ3TriangleData rules of QD3DGeometry.h are all in the description below.

    using DataGeometry::DataGeometry;

    const ClassInfo& classInfo() const override { return kTriangleClass; }
    /// One triangle (its three sides as the wireframe), each vertex with its
    /// own attributes.
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;
    bool isPrimitive() const override { return true; }

    /// Vertex `index`, 0 to 2 (kQ3ErrorParameterOutOfRange otherwise).
    const TQ3Vertex3D& vertex(unsigned long index) const;
    /// Moves vertex `index`: kQ3ErrorParameterOutOfRange, then
    /// kQ3ErrorInvalidData for a coordinate that is not finite.
    void setVertexPosition(unsigned long index, const TQ3Point3D& position);
    /// Replaces the attribute set of vertex `index` (null removes it).
    void setVertexAttributeSet(unsigned long index, Ref<AttributeSet> attributes);
};

// The data description (core/DataLayout.h), with the 3DMF form its reader
// and writer come from (io/SimpleGeometryIO.cpp).
namespace layout {
template <>
struct Describe<TQ3TriangleData> {
    static auto fields()
    {
        return std::make_tuple(
            inlineArray("vertices", &TQ3TriangleData::vertices),
            handle<AttributeSet>("triangleAttributeSet", &TQ3TriangleData::triangleAttributeSet));
    }
    static auto fileFields() { return std::make_tuple(vertexPoints(&TQ3TriangleData::vertices)); }
    static auto fileParts()
    {
        return std::make_tuple(ownSetPart(&TQ3TriangleData::triangleAttributeSet),
                               vertexSetsPart(&TQ3TriangleData::vertices));
    }
};
} // namespace layout

} // namespace q3
