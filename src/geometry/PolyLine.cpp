// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/PolyLine.h"

#include "geometry/DataGeometryImpl.h"

namespace q3 {

const ClassInfo kPolyLineClass{kQ3GeometryTypePolyLine, &kGeometryClass, "polyline"};

template class DataGeometry<PolyLine, TQ3PolyLineData>;

Ref<PolyLine> PolyLine::fromPoints(const float* xyz, std::size_t count, const AttributeSet* attributes)
{
    requireNonNull(xyz, "xyz");
    if (count < 2)
        fail(kQ3ErrorGeometryInsufficientNumberOfPoints,
             "a polyline needs at least 2 points, not " + std::to_string(count));
    layout::checkCount(count, layout::Path{nullptr, "points"});
    for (std::size_t i = 0; i < count; ++i)
        requireFinite(TQ3Point3D{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}, "points", i);

    TQ3PolyLineData owned{};
    owned.numVertices = static_cast<unsigned long>(count);
    owned.vertices = layout::allocate<TQ3Vertex3D>(count);
    for (std::size_t i = 0; i < count; ++i)
        owned.vertices[i] = TQ3Vertex3D{{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}, nullptr};
    // A reference count is bookkeeping, not part of the set's value, so a
    // const set may gain a holder.
    owned.polyLineAttributeSet = Ref<AttributeSet>::retain(const_cast<AttributeSet*>(attributes)).detach();
    try {
        Ref<PolyLine> polyLine = Ref<PolyLine>::adopt(new PolyLine(AdoptData{}, owned));
        polyLine->registerLive();
        return polyLine;
    } catch (...) {
        layout::release(owned);
        throw;
    }
}

void PolyLine::decompose(const DecomposeContext&, PrimitiveSink& sink) const
{
    const TQ3PolyLineData& d = data();
    std::vector<double> key;
    appendVertexSetKeys(key, d.vertices, d.numVertices);
    if (d.segmentAttributeSet != nullptr) {
        std::vector<const AttributeSet*> sets;
        for (std::size_t i = 0; i < segmentCount(d); ++i)
            sets.push_back(heldAttributeSet(d.segmentAttributeSet[i]));
        appendEditIndices(key, sets);
    }
    withMesh(
        std::move(key),
        [&](Mesh& mesh) {
            auto vertexAttributes = [&](std::size_t i, const AttributeSet* segment) {
                VertexAttributes attributes;
                attributes.inheritFrom(heldAttributeSet(d.vertices[i].attributeSet));
                attributes.inheritFrom(segment);
                return attributes;
            };
            if (d.segmentAttributeSet == nullptr) {
                addVertices(mesh, d.vertices, d.numVertices);
                mesh.addStrip(0, static_cast<std::uint32_t>(d.numVertices));
                return;
            }
            // A segment's attributes apply to it alone: each segment gets its
            // own two vertices (a vertex's own attributes still win).
            for (std::size_t i = 0; i < segmentCount(d); ++i) {
                const AttributeSet* segment = heldAttributeSet(d.segmentAttributeSet[i]);
                const std::uint32_t a = mesh.addVertex(d.vertices[i].point, vertexAttributes(i, segment));
                const std::uint32_t b = mesh.addVertex(d.vertices[i + 1].point, vertexAttributes(i + 1, segment));
                mesh.addLine(a, b);
            }
        },
        [&](const Mesh& mesh) { sink.draw(mesh.view(), attributeSet()); });
}

void PolyLine::checkSegmentIndex(std::size_t index) const
{
    // Written without index + 1, which wraps to 0 for the largest index.
    checkIndex(index, segmentCount(data()), "segment index", "the polyline");
}

const TQ3Vertex3D& PolyLine::vertex(std::size_t index) const
{
    return vertexAt(data().vertices, data().numVertices, index, "the polyline");
}

const AttributeSet* PolyLine::vertexAttributeSet(std::size_t index) const
{
    return heldAttributeSet(vertex(index).attributeSet);
}

const AttributeSet* PolyLine::segmentAttributeSet(std::size_t index) const
{
    checkSegmentIndex(index);
    return hasSegmentAttributeSets() ? heldAttributeSet(data().segmentAttributeSet[index]) : nullptr;
}

void PolyLine::setVertexPosition(std::size_t index, const TQ3Point3D& position)
{
    moveVertex(editableData().vertices, data().numVertices, index, position, "the polyline");
    markEdited();
}

void PolyLine::setVertexAttributeSet(std::size_t index, Ref<AttributeSet> attributes)
{
    replaceVertexSet(editableData().vertices, data().numVertices, index, std::move(attributes), "the polyline");
    markEdited();
}

void PolyLine::setSegmentAttributeSet(std::size_t index, Ref<AttributeSet> attributes)
{
    checkSegmentIndex(index);
    TQ3PolyLineData& d = editableData();
    if (d.segmentAttributeSet == nullptr && attributes) {
        // Allocate before changing anything, so running out of memory leaves
        // the polyline as it was.
        const std::size_t count = segmentCount(d);
        d.segmentAttributeSet = layout::allocate<TQ3AttributeSet>(count);
        for (std::size_t i = 0; i < count; ++i)
            d.segmentAttributeSet[i] = nullptr;
    }
    if (d.segmentAttributeSet != nullptr)
        replaceHeldSet(d.segmentAttributeSet[index], std::move(attributes));
    markEdited();
}

} // namespace q3
