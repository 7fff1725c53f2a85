// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/TriGrid.h"

#include "geometry/DataGeometryImpl.h"

namespace q3 {

const ClassInfo kTriGridClass{kQ3GeometryTypeTriGrid, &kGeometryClass, "triangle grid"};

std::size_t TriGrid::facetCount(const TQ3TriGridData& data)
{
    if (data.numRows < 2 || data.numColumns < 2)
        return 0;
    const std::size_t cells = std::size_t(data.numRows - 1);
    const std::size_t columns = std::size_t(data.numColumns - 1);
    if (cells > (~std::size_t{0} / 2) / columns)
        return ~std::size_t{0};
    return 2 * cells * columns;
}

template class DataGeometry<TriGrid, TQ3TriGridData>;

std::array<std::size_t, 3> TriGrid::facetVertices(std::size_t numColumns, std::size_t facet)
{
    const std::size_t cell = facet / 2;
    const std::size_t row = cell / (numColumns - 1);
    const std::size_t column = cell % (numColumns - 1);
    const std::size_t v = row * numColumns + column; // (row, column)
    const std::size_t right = v + 1, below = v + numColumns, diagonal = v + numColumns + 1;
    const bool second = facet % 2 == 1;
    if (column % 2 == 0)
        return second ? std::array<std::size_t, 3>{below, right, diagonal}
                      : std::array<std::size_t, 3>{v, right, below};
    return second ? std::array<std::size_t, 3>{v, right, diagonal} : std::array<std::size_t, 3>{v, diagonal, below};
}

void TriGrid::decompose(const DecomposeContext&, PrimitiveSink& sink) const
{
    const TQ3TriGridData& d = data();
    const std::size_t facets = facetCount(d);
    std::vector<double> key;
    appendVertexSetKeys(key, d.vertices, std::size_t(d.numRows) * d.numColumns);
    if (d.facetAttributeSet != nullptr) {
        std::vector<const AttributeSet*> sets;
        for (std::size_t f = 0; f < facets; ++f)
            sets.push_back(heldAttributeSet(d.facetAttributeSet[f]));
        appendEditIndices(key, sets);
    }
    withMesh(
        std::move(key),
        [&](Mesh& mesh) {
            mesh.reserveVertices(3 * facets);
            for (std::size_t f = 0; f < facets; ++f) {
                const AttributeSet* face = d.facetAttributeSet != nullptr ? heldAttributeSet(d.facetAttributeSet[f])
                                                                         : nullptr;
                const std::array<std::size_t, 3> corners = facetVertices(d.numColumns, f);
                std::uint32_t added[3];
                for (int k = 0; k < 3; ++k)
                    added[k] = addVertex(mesh, d.vertices[corners[k]], face);
                mesh.addTriangle(added[0], added[1], added[2]);
                for (int k = 0; k < 3; ++k)
                    mesh.addEdge(added[k], added[(k + 1) % 3]);
            }
        },
        [&](const Mesh& mesh) { sink.draw(mesh.view(), attributeSet()); });
}

std::size_t TriGrid::vertexIndex(unsigned long row, unsigned long column) const
{
    checkIndex(row, data().numRows, "row index", "the triangle grid");
    checkIndex(column, data().numColumns, "column index", "the triangle grid");
    return std::size_t(row) * data().numColumns + column;
}

const TQ3Vertex3D& TriGrid::vertex(unsigned long row, unsigned long column) const
{
    return data().vertices[vertexIndex(row, column)];
}

void TriGrid::setVertexPosition(unsigned long row, unsigned long column, const TQ3Point3D& position)
{
    const std::size_t index = vertexIndex(row, column);
    moveVertex(editableData().vertices, index + 1, index, position, "the triangle grid");
    markEdited();
}

void TriGrid::setVertexAttributeSet(unsigned long row, unsigned long column, Ref<AttributeSet> attributes)
{
    const std::size_t index = vertexIndex(row, column);
    replaceVertexSet(editableData().vertices, index + 1, index, std::move(attributes), "the triangle grid");
    markEdited();
}

const AttributeSet* TriGrid::facetSet(unsigned long index) const
{
    checkIndex(index, facetCount(data()), "facet index", "the triangle grid");
    return data().facetAttributeSet != nullptr ? heldAttributeSet(data().facetAttributeSet[index]) : nullptr;
}

void TriGrid::setFacetSet(unsigned long index, Ref<AttributeSet> set)
{
    const std::size_t facets = facetCount(data());
    checkIndex(index, facets, "facet index", "the triangle grid");
    TQ3TriGridData& d = editableData();
    if (d.facetAttributeSet == nullptr) {
        if (!set) {
            markEdited();
            return;
        }
        d.facetAttributeSet = layout::allocate<TQ3AttributeSet>(facets);
        for (std::size_t i = 0; i < facets; ++i)
            d.facetAttributeSet[i] = nullptr;
    }
    replaceHeldSet(d.facetAttributeSet[index], std::move(set));
    markEdited();
}

} // namespace q3
