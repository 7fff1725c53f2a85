// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/RenderPass.h"

#include "geometry/Line.h"
#include "geometry/Point.h"
#include "geometry/PolyLine.h"

#include <string>

namespace q3 {

namespace {

RgbColor toRgb(const TQ3ColorRGB& color)
{
    return RgbColor{color.r, color.g, color.b};
}

void appendPoint(std::vector<float>& xyz, const TQ3Point3D& p)
{
    xyz.push_back(p.x);
    xyz.push_back(p.y);
    xyz.push_back(p.z);
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

void RenderPass::visitNURBCurve(const nurbs::CurveRef& curve, const AttributeSet* attributes,
                                CurveCache* cache)
{
    const RgbColor color = toRgb(colorOf(attributes));
    loadMatrix();
    withCurvePolyline(curve, cache, tessellationSetting(), [&](const float* xyz, std::size_t count) {
        // A curve that subdivides to one point is drawn as that point.
        if (count == 1)
            throwIfFailed(m_target.drawPoints(xyz, 1, color), "drawing a NURB curve");
        else
            throwIfFailed(m_target.drawLineStrip(xyz, count, color), "drawing a NURB curve");
    });
}

void RenderPass::visitPolyLine(const PolyLine& polyLine)
{
    const TQ3ColorRGB own = colorOf(polyLine.attributeSet());
    const std::vector<TQ3Vertex3D>& vertices = polyLine.vertices();
    loadMatrix();
    m_scratch.clear();
    for (const TQ3Vertex3D& vertex : vertices)
        appendPoint(m_scratch, vertex.point);
    if (!polyLine.hasSegmentAttributeSets()) {
        throwIfFailed(m_target.drawLineStrip(m_scratch.data(), vertices.size(), toRgb(own)),
                      "drawing a polyline");
        return;
    }
    // A segment's own diffuse colour wins over the polyline's.
    for (std::size_t i = 0; i + 1 < vertices.size(); ++i) {
        TQ3ColorRGB color = own;
        if (const AttributeSet* set = polyLine.segmentAttributeSet(i))
            color = set->diffuseColor().value_or(own);
        throwIfFailed(m_target.drawLines(m_scratch.data() + 3 * i, 2, toRgb(color)),
                      "drawing a polyline segment");
    }
}

void RenderPass::visitLine(const Line& line)
{
    loadMatrix();
    m_scratch.clear();
    appendPoint(m_scratch, line.vertex(0).point);
    appendPoint(m_scratch, line.vertex(1).point);
    throwIfFailed(m_target.drawLines(m_scratch.data(), 2, toRgb(colorOf(line.attributeSet()))),
                  "drawing a line");
}

void RenderPass::visitPoint(const Point& point)
{
    loadMatrix();
    m_scratch.clear();
    appendPoint(m_scratch, point.point());
    throwIfFailed(m_target.drawPoints(m_scratch.data(), 1, toRgb(colorOf(point.attributeSet()))),
                  "drawing a point");
}

} // namespace q3
