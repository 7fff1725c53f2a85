// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Polyhedron.h"

#include "geometry/DataGeometryImpl.h"

namespace q3 {

const ClassInfo kPolyhedronClass{kQ3GeometryTypePolyhedron, &kGeometryClass, "polyhedron"};

template class DataGeometry<Polyhedron, TQ3PolyhedronData>;

namespace {

// An edge's triangle index may also be kQ3ArrayIndexNULL ("no triangle").
constexpr unsigned long kNoTriangle = static_cast<unsigned long>(static_cast<TQ3Uns32>(kQ3ArrayIndexNULL));

void checkIndexValue(unsigned long value, unsigned long count, const std::string& where, const char* countName)
{
    if (value >= count)
        fail(kQ3ErrorInvalidData, where + " is " + std::to_string(value) + ", not below " + countName + " (" +
                                      std::to_string(count) + ")");
}

void checkTriangle(const TQ3PolyhedronTriangleData& t, unsigned long numVertices, const std::string& where)
{
    for (int k = 0; k < 3; ++k)
        checkIndexValue(t.vertexIndices[k], numVertices, where + ".vertexIndices[" + std::to_string(k) + "]",
                        "numVertices");
    if ((t.edgeFlag & ~static_cast<unsigned long>(kQ3PolyhedronEdgeAll)) != 0)
        fail(kQ3ErrorInvalidData, where + ".edgeFlag " + std::to_string(t.edgeFlag) +
                                      " has bits outside kQ3PolyhedronEdgeAll");
}

void checkEdge(const TQ3PolyhedronEdgeData& e, unsigned long numVertices, unsigned long numTriangles,
               const std::string& where)
{
    for (int k = 0; k < 2; ++k)
        checkIndexValue(e.vertexIndices[k], numVertices, where + ".vertexIndices[" + std::to_string(k) + "]",
                        "numVertices");
    for (int k = 0; k < 2; ++k)
        if (e.triangleIndices[k] != kNoTriangle && e.triangleIndices[k] != ~0ul)
            checkIndexValue(e.triangleIndices[k], numTriangles,
                            where + ".triangleIndices[" + std::to_string(k) + "]", "numTriangles");
}

} // namespace

void Polyhedron::check(const TQ3PolyhedronData& data)
{
    for (unsigned long t = 0; t < data.numTriangles; ++t)
        checkTriangle(data.triangles[t], data.numVertices, "triangles[" + std::to_string(t) + "]");
    for (unsigned long e = 0; e < data.numEdges; ++e)
        checkEdge(data.edges[e], data.numVertices, data.numTriangles, "edges[" + std::to_string(e) + "]");
}

void Polyhedron::decompose(const DecomposeContext&, PrimitiveSink& sink) const
{
    const TQ3PolyhedronData& d = data();
    std::vector<double> key;
    appendVertexSetKeys(key, d.vertices, d.numVertices);
    std::vector<const AttributeSet*> sets;
    for (unsigned long t = 0; t < d.numTriangles; ++t)
        sets.push_back(heldAttributeSet(d.triangles[t].triangleAttributeSet));
    for (unsigned long e = 0; e < d.numEdges; ++e)
        sets.push_back(heldAttributeSet(d.edges[e].edgeAttributeSet));
    appendEditIndices(key, sets);
    withMesh(
        std::move(key),
        [&](Mesh& mesh) {
            mesh.reserveVertices(3 * std::size_t(d.numTriangles) + 2 * std::size_t(d.numEdges));
            for (unsigned long t = 0; t < d.numTriangles; ++t) {
                const TQ3PolyhedronTriangleData& triangle = d.triangles[t];
                const AttributeSet* face = heldAttributeSet(triangle.triangleAttributeSet);
                std::uint32_t corner[3];
                for (int k = 0; k < 3; ++k)
                    corner[k] = addVertex(mesh, d.vertices[triangle.vertexIndices[k]], face);
                mesh.addTriangle(corner[0], corner[1], corner[2]);
                for (int k = 0; k < 3; ++k)
                    if ((triangle.edgeFlag & (1ul << k)) != 0)
                        mesh.addEdge(corner[k], corner[(k + 1) % 3]);
            }
            for (unsigned long e = 0; e < d.numEdges; ++e) {
                const TQ3PolyhedronEdgeData& edge = d.edges[e];
                const AttributeSet* own = heldAttributeSet(edge.edgeAttributeSet);
                std::uint32_t end[2];
                for (int k = 0; k < 2; ++k)
                    end[k] = addVertex(mesh, d.vertices[edge.vertexIndices[k]], own);
                mesh.addEdge(end[0], end[1]);
            }
        },
        [&](const Mesh& mesh) { sink.draw(mesh.view(), attributeSet()); });
}

const TQ3Vertex3D& Polyhedron::vertex(unsigned long index) const
{
    return vertexAt(data().vertices, data().numVertices, index, "the polyhedron");
}

void Polyhedron::setVertexPosition(unsigned long index, const TQ3Point3D& position)
{
    moveVertex(editableData().vertices, data().numVertices, index, position, "the polyhedron");
    markEdited();
}

void Polyhedron::setVertexAttributeSet(unsigned long index, Ref<AttributeSet> attributes)
{
    replaceVertexSet(editableData().vertices, data().numVertices, index, std::move(attributes), "the polyhedron");
    markEdited();
}

TQ3PolyhedronTriangleData Polyhedron::triangle(unsigned long index) const
{
    checkIndex(index, data().numTriangles, "triangle index", "the polyhedron");
    TQ3PolyhedronTriangleData copy = data().triangles[index];
    copy.triangleAttributeSet = attributeSetToHandle(heldAttributeSet(copy.triangleAttributeSet));
    return copy;
}

void Polyhedron::setTriangle(unsigned long index, const TQ3PolyhedronTriangleData& triangle)
{
    checkIndex(index, data().numTriangles, "triangle index", "the polyhedron");
    Ref<AttributeSet> set = attributeSetFromHandle(triangle.triangleAttributeSet, "triangleAttributeSet");
    checkTriangle(triangle, data().numVertices, "triangleData");
    TQ3PolyhedronTriangleData& slot = editableData().triangles[index];
    replaceHeldSet(slot.triangleAttributeSet, std::move(set));
    for (int k = 0; k < 3; ++k)
        slot.vertexIndices[k] = triangle.vertexIndices[k];
    slot.edgeFlag = triangle.edgeFlag;
    markEdited();
}

TQ3PolyhedronEdgeData Polyhedron::edge(unsigned long index) const
{
    checkIndex(index, data().numEdges, "edge index", "the polyhedron");
    TQ3PolyhedronEdgeData copy = data().edges[index];
    copy.edgeAttributeSet = attributeSetToHandle(heldAttributeSet(copy.edgeAttributeSet));
    return copy;
}

void Polyhedron::setEdge(unsigned long index, const TQ3PolyhedronEdgeData& edge)
{
    checkIndex(index, data().numEdges, "edge index", "the polyhedron");
    Ref<AttributeSet> set = attributeSetFromHandle(edge.edgeAttributeSet, "edgeAttributeSet");
    checkEdge(edge, data().numVertices, data().numTriangles, "edgeData");
    TQ3PolyhedronEdgeData& slot = editableData().edges[index];
    replaceHeldSet(slot.edgeAttributeSet, std::move(set));
    for (int k = 0; k < 2; ++k) {
        slot.vertexIndices[k] = edge.vertexIndices[k];
        slot.triangleIndices[k] = edge.triangleIndices[k];
    }
    markEdited();
}

} // namespace q3
