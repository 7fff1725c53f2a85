// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/DataGeometry.h"

namespace q3 {

extern const ClassInfo kLineClass;

/// A line segment. Invariant: both end points are finite.
class Line final : public DataGeometry<Line, TQ3LineData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeLine;
    static constexpr const char* kName = "line";
    static constexpr const char* kDataName = "lineData";
    static constexpr TQ3AttributeSet TQ3LineData::*kOwnSet = &TQ3LineData::lineAttributeSet;

    // The TQ3LineData rules of QD3DGeometry.h are all in the description below.

    using DataGeometry::DataGeometry;

    const ClassInfo& classInfo() const override { return kLineClass; }
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;
    bool isPrimitive() const override { return true; }

    /// End point `index`, 0 or 1 (kQ3ErrorParameterOutOfRange otherwise).
    const TQ3Vertex3D& vertex(unsigned long index) const;
    /// The attribute set of end point `index` (0 or 1), or null.
    const AttributeSet* vertexAttributeSet(unsigned long index) const;
    /// Moves end point `index`: kQ3ErrorParameterOutOfRange unless it is 0 or
    /// 1, then kQ3ErrorInvalidData for a coordinate that is not finite;
    /// nothing changes on failure.
    void setVertexPosition(unsigned long index, const TQ3Point3D& position);
    /// Replaces the attribute set of end point `index` (null removes it);
    /// kQ3ErrorParameterOutOfRange unless index is 0 or 1.
    void setVertexAttributeSet(unsigned long index, Ref<AttributeSet> attributes);

private:
    static void checkEnd(unsigned long index);
};

// The data description (core/DataLayout.h), with the 3DMF form its reader
// and writer come from (io/SimpleGeometryIO.cpp).
namespace layout {
template <>
struct Describe<TQ3LineData> {
    static auto fields()
    {
        return std::make_tuple(inlineArray("vertices", &TQ3LineData::vertices),
                               handle<AttributeSet>("lineAttributeSet", &TQ3LineData::lineAttributeSet));
    }
    static auto fileFields() { return std::make_tuple(vertexPoints(&TQ3LineData::vertices)); }
    static auto fileParts()
    {
        return std::make_tuple(ownSetPart(&TQ3LineData::lineAttributeSet), vertexSetsPart(&TQ3LineData::vertices));
    }
};
} // namespace layout

} // namespace q3
