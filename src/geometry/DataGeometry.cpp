// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/DataGeometry.h"

#include <cmath>
#include <utility>

namespace q3 {

void replaceHeldSet(TQ3AttributeSet& slot, Ref<AttributeSet> set)
{
    const Ref<AttributeSet> old = Ref<AttributeSet>::adopt(const_cast<AttributeSet*>(heldAttributeSet(slot)));
    slot = set.detach();
}

const TQ3Vertex3D& vertexAt(const TQ3Vertex3D* vertices, std::size_t count, std::size_t index, const char* owner)
{
    checkIndex(index, count, "vertex index", owner);
    return vertices[index];
}

void moveVertex(TQ3Vertex3D* vertices, std::size_t count, std::size_t index, const TQ3Point3D& position,
                const char* owner)
{
    checkIndex(index, count, "vertex index", owner);
    requireFinite(position, "vertices", index);
    vertices[index].point = position;
}

void replaceVertexSet(TQ3Vertex3D* vertices, std::size_t count, std::size_t index, Ref<AttributeSet> set,
                      const char* owner)
{
    checkIndex(index, count, "vertex index", owner);
    replaceHeldSet(vertices[index].attributeSet, std::move(set));
}

void appendVertexSetKeys(std::vector<double>& key, const TQ3Vertex3D* vertices, std::size_t count)
{
    for (std::size_t i = 0; i < count; ++i)
        if (vertices[i].attributeSet != nullptr)
            key.push_back(double(heldAttributeSet(vertices[i].attributeSet)->editIndex()));
}

std::uint32_t addVertices(Mesh& mesh, const TQ3Vertex3D* vertices, std::size_t count)
{
    const std::uint32_t first = static_cast<std::uint32_t>(mesh.vertexCount());
    mesh.reserveVertices(mesh.vertexCount() + count);
    for (std::size_t i = 0; i < count; ++i)
        addVertex(mesh, vertices[i], nullptr);
    return first;
}

std::uint32_t addVertex(Mesh& mesh, const TQ3Vertex3D& vertex, const AttributeSet* part)
{
    VertexAttributes attributes;
    attributes.inheritFrom(heldAttributeSet(vertex.attributeSet));
    attributes.inheritFrom(part);
    return mesh.addVertex(vertex.point, attributes);
}

void checkIndex(std::size_t index, std::size_t count, const char* what, const char* owner)
{
    if (index >= count)
        fail(kQ3ErrorParameterOutOfRange, std::string(what) + " " + std::to_string(index) +
                                              " is out of range (" + owner + " has " +
                                              std::to_string(count) + ")");
}

void requireFinite(const TQ3Point3D& point, const std::string& where)
{
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z))
        fail(kQ3ErrorInvalidData, where + " has a coordinate that is not finite");
}

void requireFinite(const TQ3Point3D& point, const char* where, std::size_t index)
{
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z))
        requireFinite(point, std::string(where) + "[" + std::to_string(index) + "].point");
}

} // namespace q3
