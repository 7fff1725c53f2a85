// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// RenderTarget::draw for the OpenGL backends: a mesh and its Shading turned
// into the renderer's primitive calls (OffscreenRenderer.h). The view hands
// over whole meshes with everything resolved (colours, opacity, texture
// coordinates, illumination, fill style); how they become OpenGL draws is
// decided here: triangles filled (lit or not, textured or not), as edges or
// as points, then lines, line strips and points.

#include "render/OffscreenRenderer.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace q3 {

namespace {

glm::vec3 at(const float* values, std::size_t i)
{
    return glm::vec3(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
}

// A unit vector, or +z for one that has no direction.
glm::vec3 unit(const glm::vec3& v)
{
    const float length = glm::length(v);
    return length > 0.0f && std::isfinite(length) ? v / length : glm::vec3(0.0f, 0.0f, 1.0f);
}

bool isNaN(float value)
{
    return value != value;
}

} // namespace

RenderResult OffscreenRenderer::draw(const MeshView& mesh, const Shading& shading)
{
    if (!inFrame())
        return RenderResult::failure(RenderStatus::kWrongState, "draw called outside a frame");
    if (mesh.positions == nullptr && mesh.vertexCount != 0)
        return RenderResult::failure(RenderStatus::kInvalidArgument, "a mesh with vertices has no positions");
    const float* rgb = shading.rgb;
    const RgbColor& color = shading.color;
    RenderResult result;
    if (mesh.triangleCount != 0) {
        switch (shading.fill) {
        case Shading::Fill::kPoints:
            m_indices.resize(mesh.vertexCount);
            for (std::size_t i = 0; i < mesh.vertexCount; ++i)
                m_indices[i] = std::uint32_t(i);
            result = drawElements(DrawMode::kPoints, mesh.positions, rgb, mesh.vertexCount, m_indices.data(),
                                  m_indices.size(), color, false);
            break;
        case Shading::Fill::kEdges:
            if (mesh.edgeCount != 0) {
                result = drawSegments(mesh, shading, mesh.edges, mesh.edgeCount);
                break;
            }
            m_indices.clear();
            for (std::size_t t = 0; t < mesh.triangleCount; ++t)
                for (int k = 0; k < 3; ++k) {
                    m_indices.push_back(mesh.triangles[3 * t + k]);
                    m_indices.push_back(mesh.triangles[3 * t + (k + 1) % 3]);
                }
            result = drawSegments(mesh, shading, m_indices.data(), 3 * mesh.triangleCount);
            break;
        default:
            result = drawFilled(mesh, shading);
            break;
        }
    } else if (shading.edgesAlone && mesh.edgeCount != 0) {
        result = drawSegments(mesh, shading, mesh.edges, mesh.edgeCount);
    }
    if (!result)
        return result;
    if (!(result = drawSegments(mesh, shading, mesh.lines, mesh.lineCount)))
        return result;
    for (std::size_t s = 0; s < mesh.stripCount; ++s) {
        const Strip& strip = mesh.strips[s];
        if (std::size_t(strip.first) + strip.count > mesh.vertexCount)
            return RenderResult::failure(RenderStatus::kInvalidArgument, "a line strip runs past the vertices");
        const float* xyz = mesh.positions + 3 * std::size_t(strip.first);
        result = rgb != nullptr ? drawArrays(DrawMode::kLineStrip, xyz, rgb + 3 * std::size_t(strip.first), strip.count,
                                             color, true)
                                : drawLineStrip(xyz, strip.count, color);
        if (!result)
            return result;
    }
    if (mesh.pointCount != 0) {
        if (rgb != nullptr)
            return drawElements(DrawMode::kPoints, mesh.positions, rgb, mesh.vertexCount, mesh.points, mesh.pointCount,
                                color, false);
        m_scratch.clear();
        for (std::size_t i = 0; i < mesh.pointCount; ++i) {
            if (mesh.points[i] >= mesh.vertexCount)
                return RenderResult::failure(RenderStatus::kInvalidArgument,
                                             "a point index is not below the vertex count");
            const float* p = mesh.positions + 3 * std::size_t(mesh.points[i]);
            m_scratch.insert(m_scratch.end(), p, p + 3);
        }
        return drawPoints(m_scratch.data(), mesh.pointCount, color);
    }
    return result;
}

RenderResult OffscreenRenderer::drawSegments(const MeshView& mesh, const Shading& shading, const std::uint32_t* pairs,
                                             std::size_t count)
{
    if (count == 0)
        return RenderResult::success();
    if (shading.rgb != nullptr)
        return drawElements(DrawMode::kLines, mesh.positions, shading.rgb, mesh.vertexCount, pairs, 2 * count,
                            shading.color, true);
    m_scratch.clear();
    for (std::size_t i = 0; i < 2 * count; ++i) {
        if (pairs[i] >= mesh.vertexCount)
            return RenderResult::failure(RenderStatus::kInvalidArgument, "an edge index is not below the vertex count");
        const float* p = mesh.positions + 3 * std::size_t(pairs[i]);
        m_scratch.insert(m_scratch.end(), p, p + 3);
    }
    return drawLines(m_scratch.data(), 2 * count, shading.color);
}

RenderResult OffscreenRenderer::drawFilled(const MeshView& mesh, const Shading& shading)
{
    const bool textured = shading.texture != kNoTexture && (shading.st != nullptr || shading.uvs != nullptr);
    if (textured) {
        const RenderResult used = useTexture(shading.texture);
        if (!used)
            return used;
    }
    const RenderResult opacity = setOpacity(shading.opacity);
    if (!opacity)
        return opacity;
    RenderResult kept;
    if (drawKept(mesh, shading, textured, kept))
        return kept;
    offerLoop(mesh, textured);
    const float* st = textured ? shading.st : nullptr;
    if (textured && st == nullptr) {
        // Shading::uvs through the uv transform, as the view would have.
        const float* m = shading.stTransform;
        m_uvST.resize(2 * mesh.vertexCount);
        for (std::size_t i = 0; i < mesh.vertexCount; ++i) {
            const float u = shading.uvs[2 * i], v = shading.uvs[2 * i + 1];
            m_uvST[2 * i] = u * m[0] + v * m[2] + m[4];
            m_uvST[2 * i + 1] = 1.0f - (u * m[1] + v * m[3] + m[5]);
        }
        st = m_uvST.data();
    }
    const RenderResult drawn =
        shading.lit ? drawLit(mesh, shading, st)
                    : drawElements(DrawMode::kTriangles, mesh.positions, shading.rgb, mesh.vertexCount, mesh.triangles,
                                   3 * mesh.triangleCount, shading.color, shading.smooth, st);
    endKeptOffer();
    return drawn;
}

// Normals: the vertices' own where every vertex has one and the
// interpolation uses them; otherwise each triangle gets its own three
// vertices, with its face normal where a vertex has none (and always for
// flat shading), turned to the front clockwiseFront names.
RenderResult OffscreenRenderer::drawLit(const MeshView& mesh, const Shading& shading, const float* st)
{
    const float* rgb = shading.rgb;
    const int interpolation = shading.surface.interpolation;
    const float sign = shading.clockwiseFront ? -1.0f : 1.0f;
    bool shared = interpolation != 0 && mesh.normals != nullptr;
    if (shared) {
        // Unit normals, until a vertex turns out to have none.
        m_normals.resize(3 * mesh.vertexCount);
        for (std::size_t i = 0; shared && i < mesh.vertexCount; ++i) {
            shared = !isNaN(mesh.normals[3 * i]);
            const glm::vec3 n = unit(at(mesh.normals, i));
            m_normals[3 * i] = n.x;
            m_normals[3 * i + 1] = n.y;
            m_normals[3 * i + 2] = n.z;
        }
    }
    if (shared) {
        return drawLitTriangles(mesh.positions, m_normals.data(), rgb, mesh.vertexCount, mesh.triangles,
                                3 * mesh.triangleCount, shading.color, shading.surface, st);
    }
    const std::size_t corners = 3 * mesh.triangleCount;
    for (std::size_t i = 0; i < corners; ++i)
        if (mesh.triangles[i] >= mesh.vertexCount)
            return RenderResult::failure(RenderStatus::kInvalidArgument,
                                         "a triangle index is not below the vertex count");
    m_litPositions.resize(3 * corners);
    m_normals.resize(3 * corners);
    m_litColors.resize(rgb != nullptr ? 3 * corners : 0);
    m_litST.resize(st != nullptr ? 2 * corners : 0);
    m_indices.resize(corners);
    for (std::size_t t = 0; t < mesh.triangleCount; ++t) {
        const std::uint32_t* v = mesh.triangles + 3 * t;
        const glm::vec3 a = at(mesh.positions, v[0]), b = at(mesh.positions, v[1]), c = at(mesh.positions, v[2]);
        glm::vec3 face = unit(sign * glm::cross(b - a, c - a));
        if (interpolation == 0 && mesh.normals != nullptr) {
            // A flat face keeps the side its vertices' normals point to.
            glm::vec3 sum(0.0f);
            for (int k = 0; k < 3; ++k)
                if (!isNaN(mesh.normals[3 * v[k]]))
                    sum += at(mesh.normals, v[k]);
            if (glm::dot(sum, face) < 0.0f)
                face = -face;
        }
        for (int k = 0; k < 3; ++k) {
            const std::size_t corner = 3 * t + k;
            glm::vec3 n = face;
            if (interpolation != 0 && mesh.normals != nullptr && !isNaN(mesh.normals[3 * v[k]]))
                n = unit(at(mesh.normals, v[k]));
            for (int d = 0; d < 3; ++d) {
                m_litPositions[3 * corner + d] = mesh.positions[3 * v[k] + d];
                m_normals[3 * corner + d] = n[d];
                if (rgb != nullptr)
                    m_litColors[3 * corner + d] = rgb[3 * v[k] + d];
            }
            if (st != nullptr) {
                m_litST[2 * corner] = st[2 * v[k]];
                m_litST[2 * corner + 1] = st[2 * v[k] + 1];
            }
            m_indices[corner] = std::uint32_t(corner);
        }
    }
    const OpacitySetup& opacity = shading.opacity;
    if (opacity.rgb != nullptr) {
        if (opacity.count != mesh.vertexCount)
            return RenderResult::failure(RenderStatus::kInvalidArgument,
                                         "the opacity array's length is not the vertex count");
        // The opacity follows the vertices to their corners.
        m_litOpacity.resize(3 * corners);
        for (std::size_t corner = 0; corner < corners; ++corner)
            for (std::size_t c = 0; c < 3; ++c)
                m_litOpacity[3 * corner + c] = opacity.rgb[3 * std::size_t(mesh.triangles[corner]) + c];
        const RenderResult set = setOpacity(OpacitySetup{m_litOpacity.data(), corners, opacity.uniform});
        if (!set)
            return set;
    }
    return drawLitTriangles(m_litPositions.data(), m_normals.data(), rgb != nullptr ? m_litColors.data() : nullptr,
                            corners, m_indices.data(), corners, shading.color, shading.surface,
                            st != nullptr ? m_litST.data() : nullptr);
}

} // namespace q3
