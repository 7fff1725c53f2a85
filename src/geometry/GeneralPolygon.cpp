// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/GeneralPolygon.h"

#include "core/EnumValue.h"
#include "geometry/DataGeometryImpl.h"
#include "geometry/mesh/Triangulate.h"

namespace q3 {

const ClassInfo kGeneralPolygonClass{kQ3GeometryTypeGeneralPolygon, &kGeometryClass, "general polygon"};

template class DataGeometry<GeneralPolygon, TQ3GeneralPolygonData>;

void GeneralPolygon::checkShapeHint(const TQ3GeneralPolygonShapeHint& hint, TQ3Error code)
{
    const long value = enumValue(hint);
    if (value < kQ3GeneralPolygonShapeHintComplex || value > kQ3GeneralPolygonShapeHintConvex)
        fail(code, "shapeHint " + std::to_string(value) + " is not a TQ3GeneralPolygonShapeHint");
}

void GeneralPolygon::check(const TQ3GeneralPolygonData& data)
{
    checkShapeHint(data.shapeHint, kQ3ErrorInvalidData);
    // Each contour is within the limit (the description); all of them
    // together must be too, as the decomposition holds them in one mesh.
    std::size_t total = 0;
    for (unsigned long c = 0; c < data.numContours; ++c) {
        total += data.contours[c].numVertices;
        layout::checkCount(total, layout::Path{nullptr, "the vertices of all contours"});
    }
}

void GeneralPolygon::decompose(const DecomposeContext&, PrimitiveSink& sink) const
{
    const TQ3GeneralPolygonData& d = data();
    std::vector<double> key;
    for (unsigned long c = 0; c < d.numContours; ++c)
        appendVertexSetKeys(key, d.contours[c].vertices, d.contours[c].numVertices);
    withMesh(
        std::move(key),
        [&](Mesh& mesh) {
            std::vector<glm::dvec3> points;
            std::vector<std::size_t> starts;
            for (unsigned long c = 0; c < d.numContours; ++c) {
                const TQ3GeneralPolygonContourData& contour = d.contours[c];
                const std::uint32_t first = addVertices(mesh, contour.vertices, contour.numVertices);
                starts.push_back(first);
                for (unsigned long i = 0; i < contour.numVertices; ++i) {
                    const TQ3Point3D& p = contour.vertices[i].point;
                    points.emplace_back(p.x, p.y, p.z);
                    mesh.addEdge(first + std::uint32_t(i), first + std::uint32_t((i + 1) % contour.numVertices));
                }
            }
            // The plane: Newell's normal of the first contour, else of all of
            // them (a first contour that encloses no area).
            glm::dvec3 normal = mesh::newellNormal(points.data(), d.contours[0].numVertices);
            if (normal == glm::dvec3(0.0))
                normal = mesh::newellNormal(points.data(), points.size());
            if (normal == glm::dvec3(0.0))
                normal = mesh::spanNormal(points.data(), points.size());
            if (normal == glm::dvec3(0.0))
                return;
            // The even-odd rule over contours that may overlap (the QD3D
            // Book, "General Polygons"); points where sides cross are added
            // with their attributes interpolated along one of the sides.
            const mesh::Triangulation triangulation =
                mesh::triangulateEvenOdd(mesh::projectToPlane(points.data(), points.size(), normal), starts);
            std::vector<std::uint32_t> index(points.size() + triangulation.added.size());
            for (std::size_t i = 0; i < points.size(); ++i)
                index[i] = std::uint32_t(i);
            for (std::size_t i = 0; i < triangulation.added.size(); ++i) {
                const mesh::EdgePoint& e = triangulation.added[i];
                index[points.size() + i] = mesh.addBetween(e.a, e.b, e.t);
            }
            const std::vector<std::uint32_t>& triangles = triangulation.triangles;
            for (std::size_t t = 0; t < triangles.size(); t += 3)
                mesh.addTriangle(index[triangles[t]], index[triangles[t + 1]], index[triangles[t + 2]]);
        },
        [&](const Mesh& mesh) { sink.draw(mesh.view(), attributeSet()); });
}

const TQ3GeneralPolygonContourData& GeneralPolygon::contour(unsigned long index) const
{
    checkIndex(index, data().numContours, "contour index", "the general polygon");
    return data().contours[index];
}

const TQ3Vertex3D& GeneralPolygon::vertex(unsigned long contourIndex, unsigned long index) const
{
    const TQ3GeneralPolygonContourData& c = contour(contourIndex);
    return vertexAt(c.vertices, c.numVertices, index, "the contour");
}

void GeneralPolygon::setVertexPosition(unsigned long contourIndex, unsigned long index, const TQ3Point3D& position)
{
    const TQ3GeneralPolygonContourData& c = contour(contourIndex);
    moveVertex(c.vertices, c.numVertices, index, position, "the contour");
    markEdited();
}

void GeneralPolygon::setVertexAttributeSet(unsigned long contourIndex, unsigned long index,
                                           Ref<AttributeSet> attributes)
{
    const TQ3GeneralPolygonContourData& c = contour(contourIndex);
    replaceVertexSet(c.vertices, c.numVertices, index, std::move(attributes), "the contour");
    markEdited();
}

void GeneralPolygon::setShapeHint(const TQ3GeneralPolygonShapeHint& hint)
{
    checkShapeHint(hint, kQ3ErrorInvalidParameter);
    editableData().shapeHint = hint;
    markEdited();
}

} // namespace q3
