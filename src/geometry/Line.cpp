// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Line.h"

#include "geometry/DataGeometryImpl.h"

namespace q3 {

const ClassInfo kLineClass{kQ3GeometryTypeLine, &kGeometryClass, "line"};

template class DataGeometry<Line, TQ3LineData>;

void Line::decompose(const DecomposeContext&, PrimitiveSink& sink) const
{
    drawVertexMesh(data().vertices, 2, [](Mesh& mesh) { mesh.addLine(0, 1); }, sink);
}

void Line::checkEnd(unsigned long index)
{
    if (index > 1)
        fail(kQ3ErrorParameterOutOfRange, "line vertex index " + std::to_string(index) + " is neither 0 nor 1");
}

const TQ3Vertex3D& Line::vertex(unsigned long index) const
{
    checkEnd(index);
    return data().vertices[index];
}

const AttributeSet* Line::vertexAttributeSet(unsigned long index) const
{
    return heldAttributeSet(vertex(index).attributeSet);
}

void Line::setVertexPosition(unsigned long index, const TQ3Point3D& position)
{
    checkEnd(index);
    moveVertex(editableData().vertices, 2, index, position, "the line");
    markEdited();
}

void Line::setVertexAttributeSet(unsigned long index, Ref<AttributeSet> attributes)
{
    checkEnd(index);
    replaceVertexSet(editableData().vertices, 2, index, std::move(attributes), "the line");
    markEdited();
}

} // namespace q3
