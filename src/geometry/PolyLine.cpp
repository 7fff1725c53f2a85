// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/PolyLine.h"

#include "geometry/DataGeometryImpl.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace q3 {

const ClassInfo kPolyLineClass{kQ3GeometryTypePolyLine, &kGeometryClass, "polyline"};

template class DataGeometry<PolyLine, TQ3PolyLineData>;

namespace {

// The fields of an IEEE 754 single's bits, for fromPoints' check.
constexpr std::uint32_t kExponent = 0x7F800000u;
constexpr std::uint32_t kExponentOne = 0x00800000u;
constexpr std::uint32_t kSign = 0x80000000u;

} // namespace

Ref<PolyLine> PolyLine::fromPoints(const float* xyz, std::size_t count, const AttributeSet* attributes)
{
    requireNonNull(xyz, "xyz");
    if (count < 2)
        fail(kQ3ErrorGeometryInsufficientNumberOfPoints,
             "a polyline needs at least 2 points, not " + std::to_string(count));
    layout::checkCount(count, layout::Path{nullptr, "points"});

    TQ3PolyLineData owned{};
    owned.numVertices = static_cast<unsigned long>(count);
    owned.vertices = layout::allocate<TQ3Vertex3D>(count);
    // Copied and checked a block at a time, while the block is in cache. A
    // float is not finite when its exponent bits are all ones; adding one to
    // the exponent field then carries into the sign bit, which the OR
    // collects: a loop over the bits the compiler vectorizes (a curve at 64
    // segments per span hands over some 64,000 points per call, so a call to
    // requireFinite per point was most of this function's time). The first
    // point that is not finite is then named as requireFinite words it.
    constexpr std::size_t kBlock = 1024;
    std::uint32_t carries = 0;
    for (std::size_t first = 0; first < count; first += kBlock) {
        const std::size_t n = std::min(kBlock, count - first);
        const float* in = xyz + 3 * first;
        for (std::size_t k = 0; k < 3 * n; ++k) {
            std::uint32_t bits;
            std::memcpy(&bits, in + k, sizeof bits);
            carries |= (bits & kExponent) + kExponentOne;
        }
        TQ3Vertex3D* out = owned.vertices + first;
        for (std::size_t i = 0; i < n; ++i) {
            std::memcpy(&out[i].point, in + 3 * i, sizeof(TQ3Point3D));
            out[i].attributeSet = nullptr;
        }
    }
    if ((carries & kSign) != 0) {
        try {
            for (std::size_t i = 0; i < count; ++i)
                requireFinite(TQ3Point3D{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}, "points", i);
        } catch (...) {
            memory::release(owned.vertices);
            throw;
        }
    }
    // A reference count is bookkeeping, not part of the set's value, so a
    // const set may gain a holder.
    owned.polyLineAttributeSet = Ref<AttributeSet>::retain(const_cast<AttributeSet*>(attributes)).detach();
    try {
        Ref<PolyLine> polyLine = Ref<PolyLine>::adopt(new PolyLine(AdoptData{}, owned));
        polyLine->m_verticesWithoutSetsAt = polyLine->editIndex();
        polyLine->registerLive();
        return polyLine;
    } catch (...) {
        layout::release(owned);
        throw;
    }
}

PolyLine::~PolyLine()
{
    // Vertices without sets have nothing to release one by one: the array
    // is freed here, and DataGeometry's destructor releases the rest.
    if (!borrowed() && verticesWithoutSets()) {
        TQ3PolyLineData& d = editableData();
        memory::release(d.vertices);
        d.vertices = nullptr;
    }
}

void PolyLine::getData(TQ3PolyLineData& out) const
{
    const TQ3PolyLineData& d = data();
    if (!verticesWithoutSets() || d.segmentAttributeSet != nullptr) {
        DataGeometry::getData(out);
        return;
    }
    TQ3Vertex3D* vertices = layout::allocate<TQ3Vertex3D>(d.numVertices);
    std::memcpy(static_cast<void*>(vertices), d.vertices, sizeof(TQ3Vertex3D) * d.numVertices);
    out = d;
    out.vertices = vertices;
    if (out.polyLineAttributeSet != nullptr)
        layout::heldObject(out.polyLineAttributeSet)->addReference();
}

void PolyLine::emptyData(TQ3PolyLineData& data)
{
    bool anySet = false;
    if (data.vertices != nullptr)
        for (std::size_t i = 0; i < data.numVertices; ++i)
            anySet |= data.vertices[i].attributeSet != nullptr;
    if (anySet) {
        DataGeometry::emptyData(data);
        return;
    }
    // The other handles go through the generic walk on a copy without the
    // vertices: if one is bad, nothing is released and data is unchanged.
    TQ3PolyLineData rest = data;
    rest.vertices = nullptr;
    DataGeometry::emptyData(rest);
    memory::release(data.vertices);
    data = rest;
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
