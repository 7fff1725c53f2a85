// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Line.h"

#include "core/ShapeVisitor.h"

#include <cmath>
#include <string>

namespace q3 {

const ClassInfo kLineClass{kQ3GeometryTypeLine, &kGeometryClass, "line"};

namespace {

bool isFinite(const TQ3Point3D& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

const char* const kVertexSetNames[2] = {"vertices[0].attributeSet", "vertices[1].attributeSet"};

// The coordinate rule of TQ3LineData for end `index`, shared by
// validateLineData and setVertexPosition so the two paths cannot disagree.
void validateVertexPosition(const TQ3Point3D& point, unsigned long index)
{
    if (!isFinite(point))
        fail(kQ3ErrorInvalidData,
             "vertices[" + std::to_string(index) + "].point has a coordinate that is not finite");
}

} // namespace

void validateLineData(const TQ3LineData* data)
{
    requireNonNull(data, "line data");
    for (unsigned long i = 0; i < 2; ++i)
        validateVertexPosition(data->vertices[i].point, i);
}

Line::Line(const TQ3LineData& data)
{
    assign(data);
}

void Line::assign(const TQ3LineData& data)
{
    // Resolve all three handles before changing anything.
    std::array<Ref<AttributeSet>, 2> vertexSets;
    for (int i = 0; i < 2; ++i)
        vertexSets[i] = attributeSetFromHandle(data.vertices[i].attributeSet, kVertexSetNames[i]);
    Ref<AttributeSet> attributes = attributeSetFromHandle(data.lineAttributeSet, "lineAttributeSet");

    for (int i = 0; i < 2; ++i) {
        m_vertexSets[i] = std::move(vertexSets[i]);
        m_vertices[i] = TQ3Vertex3D{data.vertices[i].point, m_vertexSets[i].get()};
    }
    replaceAttributeSet(std::move(attributes));
}

Object* Line::duplicate() const
{
    Ref<Line> copy = Ref<Line>::adopt(new Line);
    for (int i = 0; i < 2; ++i) {
        // Keep a set shared by both ends shared in the copy.
        copy->m_vertexSets[i] = (i == 1 && m_vertexSets[1].get() == m_vertexSets[0].get())
                                    ? copy->m_vertexSets[0]
                                    : duplicateAttributeSet(m_vertexSets[i]);
        copy->m_vertices[i] = TQ3Vertex3D{m_vertices[i].point, copy->m_vertexSets[i].get()};
    }
    copy->replaceAttributeSet(duplicateAttributeSet(attributeSetRef()));
    copy->registerLive();
    return copy.detach();
}

void Line::accept(ShapeVisitor& visitor) const
{
    visitor.visitLine(*this);
}

void Line::checkIndex(unsigned long index)
{
    if (index > 1)
        fail(kQ3ErrorParameterOutOfRange,
             "line vertex index " + std::to_string(index) + " is neither 0 nor 1");
}

const TQ3Vertex3D& Line::vertex(unsigned long index) const
{
    checkIndex(index);
    return m_vertices[index];
}

const AttributeSet* Line::vertexAttributeSet(unsigned long index) const
{
    checkIndex(index);
    return m_vertexSets[index].get();
}

void Line::setVertexPosition(unsigned long index, const TQ3Point3D& position)
{
    checkIndex(index);
    validateVertexPosition(position, index);
    m_vertices[index].point = position;
    markEdited();
}

void Line::setVertexAttributeSet(unsigned long index, Ref<AttributeSet> attributes)
{
    checkIndex(index);
    m_vertexSets[index] = std::move(attributes);
    m_vertices[index].attributeSet = m_vertexSets[index].get();
    markEdited();
}

void Line::getData(TQ3LineData& out) const
{
    for (int i = 0; i < 2; ++i)
        out.vertices[i] = TQ3Vertex3D{m_vertices[i].point, attributeSetToHandle(m_vertexSets[i])};
    out.lineAttributeSet = attributeSetToHandle(attributeSetRef());
}

void Line::emptyData(TQ3LineData& data)
{
    // Check all three handles before releasing any.
    AttributeSet* handedOut[3] = {
        lookupOptional<AttributeSet>(data.vertices[0].attributeSet, kVertexSetNames[0]),
        lookupOptional<AttributeSet>(data.vertices[1].attributeSet, kVertexSetNames[1]),
        lookupOptional<AttributeSet>(data.lineAttributeSet, "lineAttributeSet")};
    for (AttributeSet* set : handedOut)
        Ref<AttributeSet>::adopt(set).reset();
    data.vertices[0].attributeSet = nullptr;
    data.vertices[1].attributeSet = nullptr;
    data.lineAttributeSet = nullptr;
}

void Line::setData(const TQ3LineData& data)
{
    validateLineData(&data);
    assign(data);
    markEdited();
}

} // namespace q3
