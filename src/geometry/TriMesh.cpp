// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/TriMesh.h"

#include "geometry/DataGeometryImpl.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>

namespace q3 {

const ClassInfo kTriMeshClass{kQ3GeometryTypeTriMesh, &kGeometryClass, "trimesh"};

namespace {

using D = TQ3TriMeshData;

// An index that means "none" in a TriMesh edge: kQ3ArrayIndexNULL, as a
// 32-bit or a full unsigned long (C code writes either).
bool isNullIndex(unsigned long index)
{
    return index == static_cast<unsigned long>(kQ3ArrayIndexNULL) || index == 0xFFFFFFFFUL;
}

// Calls f(type, value) for every value element `index` has in an attribute
// array (those its attributeUseArray does not switch off).
template <class F>
void forEachValue(const TQ3TriMeshAttributeData* entries, std::size_t types, std::size_t index, F&& f)
{
    for (std::size_t i = 0; i < types; ++i) {
        const TQ3TriMeshAttributeData& entry = entries[i];
        if (entry.attributeUseArray != nullptr && entry.attributeUseArray[index] == 0)
            continue;
        const std::size_t size = AttributeSet::dataSize(entry.attributeType);
        f(entry.attributeType, static_cast<const unsigned char*>(entry.data) + index * size);
    }
}

void checkValues(const TQ3TriMeshAttributeData* entries, std::size_t types, std::size_t count, const char* name)
{
    for (std::size_t e = 0; e < count; ++e)
        forEachValue(entries, types, e, [&](TQ3AttributeType type, const void* value) {
            const std::string problem = AttributeSet::valueProblem(type, value);
            if (!problem.empty())
                fail(kQ3ErrorInvalidData, std::string(name) + " value " + std::to_string(e) + ": " + problem);
        });
}

void checkIndexValue(unsigned long value, unsigned long count, const std::string& where, const char* countName)
{
    if (value >= count)
        fail(kQ3ErrorInvalidData, where + " is " + std::to_string(value) + ", not below " + countName + " (" +
                                      std::to_string(count) + ")");
}

} // namespace

TQ3Object TriMeshAttributeArraysField::shaderAt(const TQ3TriMeshAttributeData& entry, std::size_t index)
{
    if (entry.attributeUseArray != nullptr && entry.attributeUseArray[index] == 0)
        return nullptr;
    TQ3Object handle;
    std::memcpy(&handle, static_cast<const unsigned char*>(entry.data) + index * sizeof handle, sizeof handle);
    return handle;
}

// The class is found by its type code, so the geometry layer names no shader
// class.
SharedObject& TriMeshAttributeArraysField::lookupSurfaceShader(TQ3Object handle, const layout::Path& where)
{
    try {
        Object& object = lookupObject(handle, "it");
        if (!object.isType(kQ3ShaderTypeSurface))
            fail(kQ3ErrorInvalidObjectType,
                 std::string("it is a ") + object.classInfo().name + ", not a surface shader");
        return static_cast<SharedObject&>(object);
    } catch (const Error& error) {
        fail(error.code(), where.str() + ": " + error.what());
    }
}

std::size_t TriMeshAttributeArraysField::valueSize(const TQ3TriMeshAttributeData& entry, const layout::Path& where)
{
    try {
        return AttributeSet::dataSize(entry.attributeType);
    } catch (const Error& error) {
        fail(error.code(), where.child("attributeType").str() + ": " + error.what());
    }
}

// Presence: the entries, and each entry's data block unless there are no
// elements (entries are read only within the limit); maximum: the entries'
// count; values: each entry's type is one Q3 stores.
void TriMeshAttributeArraysField::check(const TQ3TriMeshData& s, const layout::Path& path, layout::Pass pass) const
{
    const layout::Path here = path.child(name);
    const std::size_t n = s.*typeCount;
    const TQ3TriMeshAttributeData* entries = s.*member;
    switch (pass) {
    case layout::Pass::kPresence:
        if (entries == nullptr) {
            if (n != 0)
                fail(kQ3ErrorNULLParameter, here.str() + " is NULL but should hold " + std::to_string(n) + " entries");
            return;
        }
        if (n > limits::kMaxArrayCount || s.*elementCount == 0)
            return;
        for (std::size_t i = 0; i < n; ++i)
            if (entries[i].data == nullptr)
                fail(kQ3ErrorNULLParameter, here.element(i).child("data").str() + " is NULL");
        return;
    case layout::Pass::kMinimum:
        return;
    case layout::Pass::kMaximum:
        layout::checkCount(n, here);
        return;
    case layout::Pass::kValues:
        if (entries != nullptr)
            for (std::size_t i = 0; i < n; ++i)
                valueSize(entries[i], here.element(i));
        return;
    }
}

void TriMeshAttributeArraysField::release(TQ3TriMeshData& s) const
{
    TQ3TriMeshAttributeData* entries = std::exchange(s.*member, nullptr);
    if (entries == nullptr)
        return;
    for (std::size_t i = 0; i < s.*typeCount; ++i) {
        if (entries[i].attributeType == kQ3AttributeTypeSurfaceShader && entries[i].data != nullptr)
            for (std::size_t e = 0; e < s.*elementCount; ++e)
                if (const TQ3Object handle = shaderAt(entries[i], e))
                    layout::heldObject(handle)->releaseReference();
        memory::release(entries[i].data);
        memory::release(entries[i].attributeUseArray);
    }
    memory::release(entries);
}

void TriMeshAttributeArraysField::checkHandles(const TQ3TriMeshData& s, const layout::Path& path) const
{
    forEachShader(s, [&](TQ3Object handle, std::size_t i, std::size_t e) {
        lookupSurfaceShader(handle, path.child(name).element(i).child("data").element(e));
    });
}

template class DataGeometry<TriMesh, TQ3TriMeshData>;

void TriMesh::check(const TQ3TriMeshData& data)
{
    // The description has found every array present, every count within the
    // limit, every attribute type known and every point finite, so the
    // indices and values below may be read.
    for (unsigned long t = 0; t < data.numTriangles; ++t)
        for (int k = 0; k < 3; ++k)
            if (data.triangles[t].pointIndices[k] >= data.numPoints)
                checkIndexValue(data.triangles[t].pointIndices[k], data.numPoints,
                                "triangles[" + std::to_string(t) + "].pointIndices[" + std::to_string(k) + "]",
                                "numPoints");
    for (unsigned long e = 0; e < data.numEdges; ++e) {
        const TQ3TriMeshEdgeData& edge = data.edges[e];
        for (int k = 0; k < 2; ++k) {
            const std::string where = "edges[" + std::to_string(e) + "]";
            if (edge.pointIndices[k] >= data.numPoints)
                checkIndexValue(edge.pointIndices[k], data.numPoints, where + ".pointIndices[" + std::to_string(k) + "]",
                                "numPoints");
            if (!isNullIndex(edge.triangleIndices[k]) && edge.triangleIndices[k] >= data.numTriangles)
                checkIndexValue(edge.triangleIndices[k], data.numTriangles,
                                where + ".triangleIndices[" + std::to_string(k) + "]", "numTriangles");
        }
    }
    checkValues(data.triangleAttributeTypes, data.numTriangleAttributeTypes, data.numTriangles, "triangleAttributeTypes");
    checkValues(data.edgeAttributeTypes, data.numEdgeAttributeTypes, data.numEdges, "edgeAttributeTypes");
    checkValues(data.vertexAttributeTypes, data.numVertexAttributeTypes, data.numPoints, "vertexAttributeTypes");
}

void TriMesh::decompose(const DecomposeContext&, PrimitiveSink& sink) const
{
    withMesh(
        {},
        [&](Mesh& mesh) {
            const D& d = data();
            auto pointAttributes = [&](std::size_t p) {
                VertexAttributes attributes;
                forEachValue(d.vertexAttributeTypes, d.numVertexAttributeTypes, p,
                             [&](TQ3AttributeType type, const void* value) { attributes.inherit(type, value); });
                return attributes;
            };
            if (d.numTriangleAttributeTypes == 0) {
                mesh.reserveVertices(d.numPoints);
                for (std::size_t p = 0; p < d.numPoints; ++p)
                    mesh.addVertex(d.points[p], pointAttributes(p));
                for (std::size_t t = 0; t < d.numTriangles; ++t) {
                    const unsigned long* v = d.triangles[t].pointIndices;
                    mesh.addTriangle(std::uint32_t(v[0]), std::uint32_t(v[1]), std::uint32_t(v[2]));
                }
            } else {
                mesh.reserveVertices(3 * std::size_t(d.numTriangles));
                for (std::size_t t = 0; t < d.numTriangles; ++t) {
                    std::uint32_t corners[3];
                    for (int k = 0; k < 3; ++k) {
                        const unsigned long p = d.triangles[t].pointIndices[k];
                        VertexAttributes attributes = pointAttributes(p);
                        forEachValue(d.triangleAttributeTypes, d.numTriangleAttributeTypes, t,
                                     [&](TQ3AttributeType type, const void* value) { attributes.inherit(type, value); });
                        corners[k] = mesh.addVertex(d.points[p], attributes);
                    }
                    mesh.addTriangle(corners[0], corners[1], corners[2]);
                }
            }
            mesh.edgesFromTriangles();
            for (std::size_t e = 0; e < d.numEdges; ++e) {
                VertexAttributes edge;
                forEachValue(d.edgeAttributeTypes, d.numEdgeAttributeTypes, e,
                             [&](TQ3AttributeType type, const void* value) { edge.inherit(type, value); });
                if (!edge.hasColor())
                    continue;
                std::uint32_t ends[2];
                for (int k = 0; k < 2; ++k) {
                    const unsigned long p = d.edges[e].pointIndices[k];
                    VertexAttributes attributes = pointAttributes(p);
                    attributes.inherit(kQ3AttributeTypeDiffuseColor, &edge.color);
                    ends[k] = mesh.addVertex(d.points[p], attributes);
                }
                mesh.addEdge(ends[0], ends[1]);
            }
        },
        [&](const Mesh& mesh) { sink.draw(mesh.view(), attributeSet()); });
}

void TriMesh::bound(const DecomposeContext&, std::vector<glm::dvec3>& points) const
{
    const D& d = data();
    points.reserve(points.size() + d.numPoints);
    for (unsigned long i = 0; i < d.numPoints; ++i)
        points.emplace_back(d.points[i].x, d.points[i].y, d.points[i].z);
}

Ref<TriMesh> TriMesh::fromMesh(const Mesh& mesh, const AttributeSet* own)
{
    const MeshView view = mesh.view();
    layout::checkCount(view.vertexCount, layout::Path{nullptr, "points"});
    layout::checkCount(view.triangleCount, layout::Path{nullptr, "triangles"});
    struct Channel {
        TQ3AttributeType type;
        const float* values;
        std::size_t width;
    };
    std::vector<Channel> channels;
    const Channel candidates[] = {{kQ3AttributeTypeDiffuseColor, view.colors, 3},
                                  {kQ3AttributeTypeTransparencyColor, view.transparency, 3},
                                  {kQ3AttributeTypeNormal, view.normals, 3},
                                  {kQ3AttributeTypeSurfaceUV, view.uvs, 2}};
    for (const Channel& channel : candidates)
        if (channel.values != nullptr)
            channels.push_back(channel);

    // Built in the form the library owns (malloc'ed arrays, a reference per
    // handle); every array is in place, NULL-filled, before it is filled, so
    // a failure anywhere can release what exists.
    D owned{};
    try {
        const std::size_t n = view.vertexCount;
        owned.numPoints = static_cast<unsigned long>(n);
        owned.points = layout::allocate<TQ3Point3D>(n);
        for (std::size_t i = 0; i < n; ++i)
            owned.points[i] = TQ3Point3D{view.positions[3 * i], view.positions[3 * i + 1], view.positions[3 * i + 2]};
        owned.numTriangles = static_cast<unsigned long>(view.triangleCount);
        owned.triangles = layout::allocate<TQ3TriMeshTriangleData>(view.triangleCount);
        for (std::size_t t = 0; t < view.triangleCount; ++t)
            for (int k = 0; k < 3; ++k)
                owned.triangles[t].pointIndices[k] = view.triangles[3 * t + k];
        owned.vertexAttributeTypes = layout::allocate<TQ3TriMeshAttributeData>(channels.size());
        for (std::size_t c = 0; c < channels.size(); ++c)
            owned.vertexAttributeTypes[c] = TQ3TriMeshAttributeData{channels[c].type, nullptr, nullptr};
        owned.numVertexAttributeTypes = static_cast<unsigned long>(channels.size());
        for (std::size_t c = 0; c < channels.size(); ++c) {
            // A vertex without the attribute (NaN) is switched off in the
            // use array, which exists only when some vertex lacks it.
            const Channel& channel = channels[c];
            TQ3TriMeshAttributeData& entry = owned.vertexAttributeTypes[c];
            float* values = layout::allocate<float>(n * channel.width);
            entry.data = values;
            bool partial = false;
            for (std::size_t i = 0; i < n; ++i) {
                const float* from = channel.values + channel.width * i;
                const bool present = from[0] == from[0];
                partial = partial || !present;
                for (std::size_t k = 0; k < channel.width; ++k)
                    values[channel.width * i + k] = present ? from[k] : 0.0f;
            }
            if (partial) {
                entry.attributeUseArray = layout::allocate<char>(n);
                for (std::size_t i = 0; i < n; ++i)
                    entry.attributeUseArray[i] = channel.values[channel.width * i] == channel.values[channel.width * i];
            }
        }
        if (view.triangleShaders != nullptr) {
            // The triangles' own surface shaders as a triangle attribute
            // array, one reference per triangle that has one; the others
            // are NULL and switched off.
            const std::size_t count = view.triangleCount;
            owned.triangleAttributeTypes = layout::allocate<TQ3TriMeshAttributeData>(1);
            owned.triangleAttributeTypes[0] = TQ3TriMeshAttributeData{kQ3AttributeTypeSurfaceShader, nullptr, nullptr};
            owned.numTriangleAttributeTypes = 1;
            TQ3TriMeshAttributeData& entry = owned.triangleAttributeTypes[0];
            TQ3Object* handles = layout::allocate<TQ3Object>(count);
            for (std::size_t t = 0; t < count; ++t)
                handles[t] = nullptr;
            entry.data = handles;
            entry.attributeUseArray = layout::allocate<char>(count);
            for (std::size_t t = 0; t < count; ++t)
                entry.attributeUseArray[t] = view.triangleShaders[t] != 0;
            for (std::size_t t = 0; t < count; ++t)
                if (view.triangleShaders[t] != 0)
                    handles[t] = Ref<SharedObject>(view.shaders[view.triangleShaders[t] - 1]).detach();
        }
        // A reference count is bookkeeping, not part of the set's value, so a
        // const set may gain a holder.
        owned.triMeshAttributeSet = Ref<AttributeSet>::retain(const_cast<AttributeSet*>(own)).detach();
        Ref<TriMesh> triMesh = Ref<TriMesh>::adopt(new TriMesh(AdoptData{}, owned));
        triMesh->registerLive();
        return triMesh;
    } catch (...) {
        layout::release(owned);
        throw;
    }
}

void TriMesh::getData(TQ3TriMeshData& out) const
{
    DataGeometry::getData(out);
    TQ3BoundingBox box{};
    box.isEmpty = out.numPoints == 0 ? kQ3True : kQ3False;
    for (unsigned long i = 0; i < out.numPoints; ++i) {
        const TQ3Point3D& p = out.points[i];
        if (i == 0) {
            box.min = box.max = p;
            continue;
        }
        box.min = TQ3Point3D{std::min(box.min.x, p.x), std::min(box.min.y, p.y), std::min(box.min.z, p.z)};
        box.max = TQ3Point3D{std::max(box.max.x, p.x), std::max(box.max.y, p.y), std::max(box.max.z, p.z)};
    }
    out.bBox = box;
}

} // namespace q3
