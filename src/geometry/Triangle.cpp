// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Triangle.h"

#include "geometry/DataGeometryImpl.h"

namespace q3 {

const ClassInfo kTriangleClass{kQ3GeometryTypeTriangle, &kGeometryClass, "triangle"};

template class DataGeometry<Triangle, TQ3TriangleData>;

void Triangle::decompose(const DecomposeContext&, PrimitiveSink& sink) const
{
    drawVertexMesh(
        data().vertices, 3,
        [](Mesh& mesh) {
            mesh.addTriangle(0, 1, 2);
            mesh.edgesFromTriangles();
        },
        sink);
}

const TQ3Vertex3D& Triangle::vertex(unsigned long index) const
{
    return vertexAt(data().vertices, 3, index, "the triangle");
}

void Triangle::setVertexPosition(unsigned long index, const TQ3Point3D& position)
{
    moveVertex(editableData().vertices, 3, index, position, "the triangle");
    markEdited();
}

void Triangle::setVertexAttributeSet(unsigned long index, Ref<AttributeSet> attributes)
{
    replaceVertexSet(editableData().vertices, 3, index, std::move(attributes), "the triangle");
    markEdited();
}

} // namespace q3
