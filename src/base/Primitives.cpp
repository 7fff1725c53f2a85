// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "base/Primitives.h"

#include "core/AttributeSet.h"
#include "core/DataLayout.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <utility>

namespace q3 {

namespace {

// Appends `count` values to a per-vertex channel, creating the channel (NaN
// for every earlier vertex) the first time a vertex has the attribute.
void appendChannel(std::vector<float>& channel, bool has, const float* values, std::size_t count,
                   std::size_t earlierVertices)
{
    if (channel.empty()) {
        if (!has)
            return;
        channel.assign(earlierVertices * count, VertexAttributes::kNone);
    }
    channel.insert(channel.end(), values, values + count);
}

} // namespace

void VertexAttributes::inheritFrom(const AttributeSet* set)
{
    if (set == nullptr)
        return;
    if (!hasColor())
        if (const auto value = set->diffuseColor())
            color = *value;
    if (!hasTransparency())
        if (const auto value = set->transparencyColor())
            transparency = *value;
    if (!hasNormal())
        if (const auto value = set->normal())
            normal = *value;
    if (!hasShader())
        shader = set->shader();
    if (!hasUV() || uvIsShading) {
        if (const auto value = set->surfaceUV()) {
            uv = *value;
            uvIsShading = false;
        } else if (!hasUV()) {
            if (const auto shading = set->shadingUV()) {
                uv = *shading;
                uvIsShading = true;
            }
        }
    }
}

void VertexAttributes::inherit(TQ3AttributeType type, const void* value)
{
    switch (type) {
    case kQ3AttributeTypeDiffuseColor:
        if (!hasColor())
            std::memcpy(&color, value, sizeof color);
        break;
    case kQ3AttributeTypeTransparencyColor:
        if (!hasTransparency())
            std::memcpy(&transparency, value, sizeof transparency);
        break;
    case kQ3AttributeTypeNormal:
        if (!hasNormal())
            std::memcpy(&normal, value, sizeof normal);
        break;
    case kQ3AttributeTypeSurfaceUV:
        if (!hasUV() || uvIsShading) {
            std::memcpy(&uv, value, sizeof uv);
            uvIsShading = false;
        }
        break;
    case kQ3AttributeTypeShadingUV:
        if (!hasUV()) {
            std::memcpy(&uv, value, sizeof uv);
            uvIsShading = true;
        }
        break;
    case kQ3AttributeTypeSurfaceShader:
        if (!hasShader()) {
            TQ3Object handle;
            std::memcpy(&handle, value, sizeof handle);
            if (handle != nullptr)
                shader = layout::heldObject(handle);
        }
        break;
    default:
        break;
    }
}

std::uint32_t Mesh::addVertex(const TQ3Point3D& position, const VertexAttributes& attributes)
{
    const std::size_t index = vertexCount();
    m_positions.insert(m_positions.end(), {position.x, position.y, position.z});
    const TQ3ColorRGB& c = attributes.color;
    const TQ3ColorRGB& t = attributes.transparency;
    const TQ3Vector3D& n = attributes.normal;
    const float color[3] = {c.r, c.g, c.b};
    const float transparency[3] = {t.r, t.g, t.b};
    const float normal[3] = {n.x, n.y, n.z};
    const float uv[2] = {attributes.uv.u, attributes.uv.v};
    appendChannel(m_colors, attributes.hasColor(), color, 3, index);
    appendChannel(m_transparency, attributes.hasTransparency(), transparency, 3, index);
    appendChannel(m_normals, attributes.hasNormal(), normal, 3, index);
    appendChannel(m_uvs, attributes.hasUV(), uv, 2, index);
    if (attributes.hasShader() || !m_vertexShaders.empty()) {
        // Created by the first vertex with a shader, then following every one.
        m_vertexShaders.resize(index, 0);
        m_vertexShaders.push_back(shaderNumber(attributes.shader));
    }
    return static_cast<std::uint32_t>(index);
}

std::uint32_t Mesh::addBetween(std::uint32_t a, std::uint32_t b, double t)
{
    // A channel's value at t, NaN (none) where the channel is missing or
    // either end lacks it.
    const auto between = [&](const std::vector<float>& channel, std::size_t count, std::size_t k) {
        if (channel.empty())
            return VertexAttributes::kNone;
        const double x = channel[count * a + k], y = channel[count * b + k];
        return float(x + (y - x) * t);
    };
    const TQ3Point3D position{between(m_positions, 3, 0), between(m_positions, 3, 1), between(m_positions, 3, 2)};
    VertexAttributes attributes;
    attributes.color = TQ3ColorRGB{between(m_colors, 3, 0), between(m_colors, 3, 1), between(m_colors, 3, 2)};
    attributes.transparency =
        TQ3ColorRGB{between(m_transparency, 3, 0), between(m_transparency, 3, 1), between(m_transparency, 3, 2)};
    TQ3Vector3D normal{between(m_normals, 3, 0), between(m_normals, 3, 1), between(m_normals, 3, 2)};
    const float length = std::sqrt(normal.x * normal.x + normal.y * normal.y + normal.z * normal.z);
    if (length > 0.0f)
        normal = TQ3Vector3D{normal.x / length, normal.y / length, normal.z / length};
    attributes.normal = normal;
    attributes.uv = TQ3Param2D{between(m_uvs, 2, 0), between(m_uvs, 2, 1)};
    if (!m_vertexShaders.empty()) {
        const std::uint32_t nearer = t < 0.5 ? a : b;
        const std::uint32_t number = nearer < m_vertexShaders.size() ? m_vertexShaders[nearer] : 0;
        attributes.shader = number == 0 ? nullptr : m_shaders[number - 1].get();
    }
    return addVertex(position, attributes);
}

std::uint32_t Mesh::shaderNumber(const SharedObject* shader)
{
    if (shader == nullptr)
        return 0;
    for (std::size_t i = 0; i < m_shaders.size(); ++i)
        if (m_shaders[i].get() == shader)
            return std::uint32_t(i + 1);
    // A reference count is bookkeeping, not part of the shader's value, so a
    // const shader may gain a holder.
    m_shaders.push_back(Ref<SharedObject>::retain(const_cast<SharedObject*>(shader)));
    return std::uint32_t(m_shaders.size());
}

void Mesh::setLastTriangleShader(std::uint32_t number)
{
    // The array starts with the first triangle that has a shader (the ones
    // before it have none) and then follows every triangle.
    if (number == 0 && m_triangleShaders.empty())
        return;
    m_triangleShaders.resize(m_triangles.size() / 3 - 1, 0);
    m_triangleShaders.push_back(number);
}

void Mesh::reserveVertices(std::size_t count)
{
    m_positions.reserve(3 * count);
}

void Mesh::addLine(std::uint32_t a, std::uint32_t b)
{
    m_lines.insert(m_lines.end(), {a, b});
}

void Mesh::addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c)
{
    m_triangles.insert(m_triangles.end(), {a, b, c});
    if (m_vertexShaders.empty())
        return setLastTriangleShader(0);
    const std::uint32_t sa = m_vertexShaders[a], sb = m_vertexShaders[b], sc = m_vertexShaders[c];
    setLastTriangleShader(sa == sb || sa == sc ? sa : sb == sc ? sb : 0);
}

void Mesh::addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, const SharedObject* shader)
{
    m_triangles.insert(m_triangles.end(), {a, b, c});
    setLastTriangleShader(shaderNumber(shader));
}

void Mesh::addEdge(std::uint32_t a, std::uint32_t b)
{
    m_edges.insert(m_edges.end(), {a, b});
}

void Mesh::edgesFromTriangles()
{
    // Each side is filed under its smaller vertex by a counting sort, so the
    // work is linear in the triangles (a surface at the triangle limit has
    // three million sides). Each vertex's sides are then sorted by their
    // larger vertex and by corner, and duplicates dropped: each side comes
    // out once, in (smaller, larger) order, running the way the first
    // triangle that had it runs.
    const std::size_t corners = m_triangles.size();
    m_edges.clear();
    if (corners == 0)
        return;
    const std::uint32_t highest = *std::max_element(m_triangles.begin(), m_triangles.end());
    std::vector<std::uint32_t> start(std::size_t(highest) + 2, 0);
    auto sideAt = [&](std::size_t corner) {
        const std::size_t t = corner - corner % 3;
        return std::make_pair(m_triangles[corner], m_triangles[t + (corner - t + 1) % 3]);
    };
    for (std::size_t corner = 0; corner < corners; ++corner) {
        const auto [a, b] = sideAt(corner);
        ++start[std::size_t(std::min(a, b)) + 1];
    }
    for (std::size_t v = 1; v < start.size(); ++v)
        start[v] += start[v - 1];
    // (larger vertex << 32 | corner), grouped by smaller vertex.
    std::vector<std::uint64_t> filed(corners);
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::size_t corner = 0; corner < corners; ++corner) {
        const auto [a, b] = sideAt(corner);
        filed[next[std::min(a, b)]++] = (std::uint64_t(std::max(a, b)) << 32) | std::uint32_t(corner);
    }
    for (std::size_t v = 0; v + 1 < start.size(); ++v) {
        const auto first = filed.begin() + start[v], last = filed.begin() + start[v + 1];
        std::sort(first, last); // a few sides; n log n at a fan's hub
        for (auto i = first; i != last; ++i)
            if (i == first || (*i >> 32) != (*(i - 1) >> 32)) {
                const auto [a, b] = sideAt(std::size_t(*i & 0xffffffffu));
                addEdge(a, b);
            }
    }
}

MeshView Mesh::view() const
{
    MeshView view;
    view.positions = m_positions.data();
    view.vertexCount = vertexCount();
    view.colors = m_colors.empty() ? nullptr : m_colors.data();
    view.transparency = m_transparency.empty() ? nullptr : m_transparency.data();
    view.normals = m_normals.empty() ? nullptr : m_normals.data();
    view.uvs = m_uvs.empty() ? nullptr : m_uvs.data();
    view.points = m_points.data();
    view.pointCount = m_points.size();
    view.lines = m_lines.data();
    view.lineCount = m_lines.size() / 2;
    view.strips = m_strips.data();
    view.stripCount = m_strips.size();
    view.triangles = m_triangles.data();
    view.triangleCount = m_triangles.size() / 3;
    view.edges = m_edges.data();
    view.edgeCount = m_edges.size() / 2;
    if (!m_triangleShaders.empty()) {
        view.triangleShaders = m_triangleShaders.data();
        view.shaders = m_shaders.data();
        view.shaderCount = m_shaders.size();
    }
    view.serial = m_serial.value;
    view.uvsComplete = m_serial.value != 0 && m_serial.uvsComplete;
    return view;
}

void Mesh::setSerial(std::uint64_t serial)
{
    m_serial.value = serial;
    bool complete = !m_uvs.empty();
    for (std::size_t i = 0; i < m_uvs.size(); i += 2)
        complete &= m_uvs[i] == m_uvs[i];
    m_serial.uvsComplete = complete;
}

std::uint64_t Mesh::newSerial()
{
    static std::atomic<std::uint64_t> last{0};
    return last.fetch_add(1, std::memory_order_relaxed) + 1;
}

void Mesh::clear()
{
    *this = Mesh();
}

} // namespace q3
