// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Polygon.h"

#include "geometry/DataGeometryImpl.h"
#include "geometry/mesh/Triangulate.h"

namespace q3 {

const ClassInfo kPolygonClass{kQ3GeometryTypePolygon, &kGeometryClass, "polygon"};

template class DataGeometry<Polygon, TQ3PolygonData>;

void Polygon::decompose(const DecomposeContext&, PrimitiveSink& sink) const
{
    const TQ3PolygonData& d = data();
    std::vector<double> key;
    appendVertexSetKeys(key, d.vertices, d.numVertices);
    withMesh(
        std::move(key),
        [&](Mesh& mesh) {
            const std::size_t n = d.numVertices;
            addVertices(mesh, d.vertices, n);
            std::vector<glm::dvec3> outline(n);
            for (std::size_t i = 0; i < n; ++i)
                outline[i] = glm::dvec3(d.vertices[i].point.x, d.vertices[i].point.y, d.vertices[i].point.z);
            const glm::dvec3 normal = mesh::newellNormal(outline.data(), n);
            if (normal != glm::dvec3(0.0)) {
                const std::vector<std::uint32_t> triangles =
                    mesh::triangulate(mesh::projectToPlane(outline.data(), n, normal), {0});
                for (std::size_t t = 0; t < triangles.size(); t += 3)
                    mesh.addTriangle(triangles[t], triangles[t + 1], triangles[t + 2]);
            }
            for (std::size_t i = 0; i < n; ++i)
                mesh.addEdge(std::uint32_t(i), std::uint32_t((i + 1) % n));
        },
        [&](const Mesh& mesh) { sink.draw(mesh.view(), attributeSet()); });
}

const TQ3Vertex3D& Polygon::vertex(std::size_t index) const
{
    return vertexAt(data().vertices, data().numVertices, index, "the polygon");
}

void Polygon::setVertexPosition(std::size_t index, const TQ3Point3D& position)
{
    moveVertex(editableData().vertices, data().numVertices, index, position, "the polygon");
    markEdited();
}

void Polygon::setVertexAttributeSet(std::size_t index, Ref<AttributeSet> attributes)
{
    replaceVertexSet(editableData().vertices, data().numVertices, index, std::move(attributes), "the polygon");
    markEdited();
}

} // namespace q3
