// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/RenderPass.h"

#include "geometry/Geometry.h"

#include <string>

namespace q3 {

namespace {

RgbColor toRgb(const TQ3ColorRGB& color)
{
    return RgbColor{color.r, color.g, color.b};
}

} // namespace

void throwIfFailed(const RenderResult& result, const char* what)
{
    switch (result.status) {
    case RenderStatus::kOk:
        return;
    case RenderStatus::kOutOfMemory:
        fail(kQ3ErrorOutOfMemory, std::string(what) + ": " + result.message);
    case RenderStatus::kInvalidArgument:
        fail(kQ3ErrorInvalidParameter, std::string(what) + ": " + result.message);
    default:
        fail(kQ3ErrorRenderingLoopFailed, std::string(what) + ": " + result.message);
    }
}

Matrix frustumToClip()
{
    Matrix m(1.0);
    m[2][2] = -2.0;
    m[3][2] = -1.0;
    return m;
}

void RenderPass::loadMatrix()
{
    const Matrix localToClip =
        then(then(state().localToWorld, window()->worldToFrustum), frustumToClip());
    if (m_loaded && *m_loaded == localToClip)
        return;
    throwIfFailed(m_target.setMatrix(&localToClip[0][0]), "setting the drawing matrix");
    m_loaded = localToClip;
}

void RenderPass::visitGeometry(const Geometry& geometry)
{
    geometry.decompose(*this, *this);
}

void RenderPass::drawSegments(const MeshView& mesh, const float* rgb, const std::uint32_t* pairs,
                              std::size_t count, const RgbColor& color, const char* what)
{
    if (count == 0)
        return;
    if (rgb != nullptr) {
        throwIfFailed(m_target.drawElements(DrawMode::kLines, mesh.positions, rgb, mesh.vertexCount, pairs,
                                            2 * count, color, true),
                      what);
        return;
    }
    m_scratch.clear();
    for (std::size_t i = 0; i < 2 * count; ++i) {
        const float* p = mesh.positions + 3 * std::size_t(pairs[i]);
        m_scratch.insert(m_scratch.end(), p, p + 3);
    }
    throwIfFailed(m_target.drawLines(m_scratch.data(), 2 * count, color), what);
}

void RenderPass::draw(const MeshView& mesh, const AttributeSet* own)
{
    const RgbColor color = toRgb(colorOf(own));
    loadMatrix();

    // Per-vertex colours, with what a vertex lacks taken from its geometry
    // or the state.
    const float* rgb = nullptr;
    if (mesh.colors != nullptr) {
        m_colors.assign(mesh.colors, mesh.colors + 3 * mesh.vertexCount);
        for (std::size_t i = 0; i < mesh.vertexCount; ++i)
            if (m_colors[3 * i] != m_colors[3 * i]) {
                m_colors[3 * i] = color.r;
                m_colors[3 * i + 1] = color.g;
                m_colors[3 * i + 2] = color.b;
            }
        rgb = m_colors.data();
    }

    if (m_style.fillTriangles) {
        if (mesh.triangleCount != 0)
            throwIfFailed(m_target.drawElements(DrawMode::kTriangles, mesh.positions, rgb, mesh.vertexCount,
                                                mesh.triangles, 3 * mesh.triangleCount, color, true),
                          "drawing triangles");
    } else {
        if (mesh.edgeCount != 0) {
            drawSegments(mesh, rgb, mesh.edges, mesh.edgeCount, color, "drawing edges");
        } else if (mesh.triangleCount != 0) {
            m_indices.clear();
            for (std::size_t t = 0; t < mesh.triangleCount; ++t)
                for (int k = 0; k < 3; ++k) {
                    m_indices.push_back(mesh.triangles[3 * t + k]);
                    m_indices.push_back(mesh.triangles[3 * t + (k + 1) % 3]);
                }
            drawSegments(mesh, rgb, m_indices.data(), 3 * mesh.triangleCount, color, "drawing edges");
        }
    }
    drawSegments(mesh, rgb, mesh.lines, mesh.lineCount, color, "drawing lines");
    for (std::size_t s = 0; s < mesh.stripCount; ++s) {
        const Strip& strip = mesh.strips[s];
        const float* xyz = mesh.positions + 3 * std::size_t(strip.first);
        if (rgb != nullptr)
            throwIfFailed(m_target.drawArrays(DrawMode::kLineStrip, xyz, rgb + 3 * std::size_t(strip.first),
                                              strip.count, color, true),
                          "drawing a line strip");
        else
            throwIfFailed(m_target.drawLineStrip(xyz, strip.count, color), "drawing a line strip");
    }
    if (mesh.pointCount != 0) {
        if (rgb != nullptr) {
            throwIfFailed(m_target.drawElements(DrawMode::kPoints, mesh.positions, rgb, mesh.vertexCount,
                                                mesh.points, mesh.pointCount, color, false),
                          "drawing points");
        } else {
            m_scratch.clear();
            for (std::size_t i = 0; i < mesh.pointCount; ++i) {
                const float* p = mesh.positions + 3 * std::size_t(mesh.points[i]);
                m_scratch.insert(m_scratch.end(), p, p + 3);
            }
            throwIfFailed(m_target.drawPoints(m_scratch.data(), mesh.pointCount, color), "drawing points");
        }
    }
}

} // namespace q3
