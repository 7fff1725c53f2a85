// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/PolyLine.h"

#include "core/ShapeVisitor.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <new>
#include <string>

namespace q3 {

const ClassInfo kPolyLineClass{kQ3GeometryTypePolyLine, &kGeometryClass, "polyline"};

namespace {

bool isFinite(const TQ3Point3D& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

template <class T>
T* mallocArray(std::size_t count)
{
    T* array = static_cast<T*>(std::malloc(count * sizeof(T)));
    if (array == nullptr)
        throw std::bad_alloc();
    return array;
}

std::string indexed(const char* what, std::size_t index)
{
    return std::string(what) + "[" + std::to_string(index) + "]";
}

// The attribute set an array entry names (null stays null). The entry's name
// goes into the message only on failure, so large arrays cost no strings.
AttributeSet* lookupEntry(TQ3AttributeSet handle, const char* array, std::size_t index, const char* field)
{
    try {
        return lookupOptional<AttributeSet>(handle, "the attribute set");
    } catch (const Error& error) {
        fail(error.code(), indexed(array, index) + field + ": " + error.what());
    }
}

Ref<AttributeSet> retainEntry(TQ3AttributeSet handle, const char* array, std::size_t index, const char* field)
{
    return Ref<AttributeSet>::retain(lookupEntry(handle, array, index, field));
}

// Deep copies for duplicate(): a set named in several places is copied once
// and the copy is shared the same way, as the original's sharing was.
class SetCopier {
public:
    Ref<AttributeSet> copy(const Ref<AttributeSet>& set)
    {
        if (!set)
            return nullptr;
        auto found = m_copies.find(set.get());
        if (found != m_copies.end())
            return found->second;
        Ref<AttributeSet> copied = duplicateAttributeSet(set);
        m_copies.emplace(set.get(), copied);
        return copied;
    }

private:
    std::map<const AttributeSet*, Ref<AttributeSet>> m_copies;
};

// The coordinate rule of TQ3PolyLineData for vertex `index`, shared by
// validatePolyLineData and setVertexPosition so the two paths cannot disagree.
void validateVertexPosition(const TQ3Point3D& point, std::size_t index)
{
    if (!isFinite(point))
        fail(kQ3ErrorInvalidData, indexed("vertices", index) + ".point has a coordinate that is not finite");
}

} // namespace

void validatePolyLineData(const TQ3PolyLineData* data)
{
    requireNonNull(data, "polyline data");
    requireNonNull(data->vertices, "vertices");
    if (data->numVertices < 2)
        fail(kQ3ErrorGeometryInsufficientNumberOfPoints,
             "numVertices is " + std::to_string(data->numVertices) + "; a polyline needs at least 2");
    for (unsigned long i = 0; i < data->numVertices; ++i)
        validateVertexPosition(data->vertices[i].point, i);
}

PolyLine::PolyLine(const TQ3PolyLineData& data)
{
    assign(data);
}

Ref<PolyLine> PolyLine::fromPoints(const float* xyz, std::size_t count, const AttributeSet* attributes)
{
    requireNonNull(xyz, "xyz");
    if (count < 2)
        fail(kQ3ErrorGeometryInsufficientNumberOfPoints,
             "a polyline needs at least 2 points, not " + std::to_string(count));
    Ref<PolyLine> polyLine = Ref<PolyLine>::adopt(new PolyLine);
    polyLine->m_vertices.resize(count);
    polyLine->m_vertexSets.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const TQ3Point3D point{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
        if (!isFinite(point))
            fail(kQ3ErrorInvalidData, "point " + std::to_string(i) + " has a coordinate that is not finite");
        polyLine->m_vertices[i] = TQ3Vertex3D{point, nullptr};
    }
    // A reference count is bookkeeping, not part of the set's value, so a
    // const set may gain a holder.
    polyLine->replaceAttributeSet(Ref<AttributeSet>::retain(const_cast<AttributeSet*>(attributes)));
    polyLine->registerLive();
    return polyLine;
}

void PolyLine::assign(const TQ3PolyLineData& data)
{
    // Resolve every handle and build every copy before touching the members,
    // so a bad handle or a failed allocation changes nothing.
    const std::size_t count = data.numVertices;
    std::vector<TQ3Vertex3D> vertices(data.vertices, data.vertices + count);
    std::vector<Ref<AttributeSet>> vertexSets(count);
    for (std::size_t i = 0; i < count; ++i) {
        vertexSets[i] = retainEntry(data.vertices[i].attributeSet, "vertices", i, ".attributeSet");
        vertices[i].attributeSet = vertexSets[i].get();
    }
    std::vector<Ref<AttributeSet>> segmentSets;
    if (data.segmentAttributeSet != nullptr) {
        segmentSets.resize(count - 1);
        for (std::size_t i = 0; i + 1 < count; ++i)
            segmentSets[i] = retainEntry(data.segmentAttributeSet[i], "segmentAttributeSet", i, "");
    }
    Ref<AttributeSet> attributes = attributeSetFromHandle(data.polyLineAttributeSet, "polyLineAttributeSet");

    m_vertices.swap(vertices);
    m_vertexSets.swap(vertexSets);
    m_segmentSets.swap(segmentSets);
    replaceAttributeSet(std::move(attributes));
}

Object* PolyLine::duplicate() const
{
    SetCopier copier;
    Ref<PolyLine> copy = Ref<PolyLine>::adopt(new PolyLine);
    copy->m_vertices = m_vertices;
    copy->m_vertexSets.reserve(m_vertexSets.size());
    for (std::size_t i = 0; i < m_vertexSets.size(); ++i) {
        copy->m_vertexSets.push_back(copier.copy(m_vertexSets[i]));
        copy->m_vertices[i].attributeSet = copy->m_vertexSets[i].get();
    }
    copy->m_segmentSets.reserve(m_segmentSets.size());
    for (const Ref<AttributeSet>& set : m_segmentSets)
        copy->m_segmentSets.push_back(copier.copy(set));
    copy->replaceAttributeSet(copier.copy(attributeSetRef()));
    copy->registerLive();
    return copy.detach();
}

void PolyLine::accept(ShapeVisitor& visitor) const
{
    visitor.visitPolyLine(*this);
}

void PolyLine::checkVertexIndex(std::size_t index) const
{
    if (index >= m_vertices.size())
        fail(kQ3ErrorParameterOutOfRange, "vertex index " + std::to_string(index) +
                                              " is out of range (the polyline has " +
                                              std::to_string(m_vertices.size()) + ")");
}

void PolyLine::checkSegmentIndex(std::size_t index) const
{
    // Written without index + 1, which wraps to 0 for the largest index.
    if (index >= m_vertices.size() - 1)
        fail(kQ3ErrorParameterOutOfRange, "segment index " + std::to_string(index) +
                                              " is out of range (the polyline has " +
                                              std::to_string(m_vertices.size() - 1) + ")");
}

const TQ3Vertex3D& PolyLine::vertex(std::size_t index) const
{
    checkVertexIndex(index);
    return m_vertices[index];
}

const AttributeSet* PolyLine::vertexAttributeSet(std::size_t index) const
{
    checkVertexIndex(index);
    return m_vertexSets[index].get();
}

const AttributeSet* PolyLine::segmentAttributeSet(std::size_t index) const
{
    checkSegmentIndex(index);
    return m_segmentSets.empty() ? nullptr : m_segmentSets[index].get();
}

void PolyLine::setVertexPosition(std::size_t index, const TQ3Point3D& position)
{
    checkVertexIndex(index);
    validateVertexPosition(position, index);
    m_vertices[index].point = position;
    markEdited();
}

void PolyLine::setVertexAttributeSet(std::size_t index, Ref<AttributeSet> attributes)
{
    checkVertexIndex(index);
    m_vertexSets[index] = std::move(attributes);
    m_vertices[index].attributeSet = m_vertexSets[index].get();
    markEdited();
}

void PolyLine::setSegmentAttributeSet(std::size_t index, Ref<AttributeSet> attributes)
{
    checkSegmentIndex(index);
    if (m_segmentSets.empty() && attributes) {
        // Allocate before changing anything, so running out of memory leaves
        // the polyline as it was.
        std::vector<Ref<AttributeSet>> segmentSets(m_vertices.size() - 1);
        m_segmentSets.swap(segmentSets);
    }
    if (!m_segmentSets.empty())
        m_segmentSets[index] = std::move(attributes);
    markEdited();
}

void PolyLine::getData(TQ3PolyLineData& out) const
{
    // Allocate everything first; handing out references cannot fail.
    TQ3Vertex3D* vertices = mallocArray<TQ3Vertex3D>(m_vertices.size());
    TQ3AttributeSet* segments = nullptr;
    if (!m_segmentSets.empty()) {
        try {
            segments = mallocArray<TQ3AttributeSet>(m_segmentSets.size());
        } catch (...) {
            std::free(vertices);
            throw;
        }
    }
    for (std::size_t i = 0; i < m_vertices.size(); ++i)
        vertices[i] = TQ3Vertex3D{m_vertices[i].point, attributeSetToHandle(m_vertexSets[i])};
    for (std::size_t i = 0; i < m_segmentSets.size(); ++i)
        segments[i] = attributeSetToHandle(m_segmentSets[i]);
    out.numVertices = static_cast<unsigned long>(m_vertices.size());
    out.vertices = vertices;
    out.segmentAttributeSet = segments;
    out.polyLineAttributeSet = attributeSetToHandle(attributeSetRef());
}

void PolyLine::emptyData(TQ3PolyLineData& data)
{
    // Check every handle before releasing any, so a failure releases nothing;
    // then take back the references GetData handed out (one per entry).
    std::vector<AttributeSet*> handedOut;
    if (data.vertices != nullptr)
        for (unsigned long i = 0; i < data.numVertices; ++i)
            handedOut.push_back(lookupEntry(data.vertices[i].attributeSet, "vertices", i, ".attributeSet"));
    if (data.segmentAttributeSet != nullptr)
        for (unsigned long i = 0; i + 1 < data.numVertices; ++i)
            handedOut.push_back(lookupEntry(data.segmentAttributeSet[i], "segmentAttributeSet", i, ""));
    handedOut.push_back(lookupOptional<AttributeSet>(data.polyLineAttributeSet, "polyLineAttributeSet"));
    for (AttributeSet* set : handedOut)
        Ref<AttributeSet>::adopt(set).reset();
    std::free(data.vertices);
    std::free(data.segmentAttributeSet);
    data.vertices = nullptr;
    data.segmentAttributeSet = nullptr;
    data.polyLineAttributeSet = nullptr;
}

void PolyLine::setData(const TQ3PolyLineData& data)
{
    validatePolyLineData(&data);
    assign(data);
    markEdited();
}

} // namespace q3
