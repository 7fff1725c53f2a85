// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/PickPass.h"

#include "geometry/Geometry.h"
#include "group/Group.h"
#include "view/PickMath.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <limits>

namespace q3 {

namespace {

bool finite(const glm::dvec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool inDepthRange(const glm::dvec4& v)
{
    return v.w > 0.0 && v.z <= 0.0 && v.z >= -v.w;
}

TQ3Point3D toPoint(const glm::dvec3& v)
{
    return TQ3Point3D{float(v.x), float(v.y), float(v.z)};
}

} // namespace

PickPass::PickPass(const Pick& pick, std::optional<Window> window, const AttributeValues& attributes)
    : Pass(std::move(window), attributes), m_kind(pick.kind()), m_data(pick.data())
{
    switch (m_kind) {
    case Pick::Kind::kWindowPoint: {
        const TQ3WindowPointPickData& d = pick.windowPoint();
        m_point = glm::dvec2(d.point.x, d.point.y);
        m_vertexTolerance = d.vertexTolerance;
        m_edgeTolerance = d.edgeTolerance;
        // The ray under the point, from the hither plane to the yon plane;
        // a point off the pane sees nothing, as nothing is drawn there.
        const PixelRect& pane = this->window()->pane;
        if (m_point.x < pane.x || m_point.x > double(pane.x) + pane.width || m_point.y < pane.y ||
            m_point.y > double(pane.y) + pane.height || pane.width <= 0 || pane.height <= 0)
            break;
        const double fx = (m_point.x - pane.x) / (0.5 * pane.width) - 1.0;
        const double fy = 1.0 - (m_point.y - pane.y) / (0.5 * pane.height);
        const Matrix toWorld = glm::inverse(this->window()->worldToFrustum);
        const glm::dvec4 nearH = toWorld * glm::dvec4(fx, fy, 0.0, 1.0);
        const glm::dvec4 farH = toWorld * glm::dvec4(fx, fy, -1.0, 1.0);
        const glm::dvec3 nearP = glm::dvec3(nearH) / nearH.w;
        const glm::dvec3 farP = glm::dvec3(farH) / farH.w;
        m_origin = nearP;
        m_reach = glm::distance(nearP, farP);
        m_direction = (farP - nearP) / m_reach;
        m_rayValid = finite(m_origin) && finite(m_direction) && m_reach > 0.0 && std::isfinite(m_reach);
        break;
    }
    case Pick::Kind::kWindowRect: {
        const TQ3Area& r = pick.windowRect().rect;
        m_rectMin = glm::dvec2(r.min.x, r.min.y);
        m_rectMax = glm::dvec2(r.max.x, r.max.y);
        break;
    }
    case Pick::Kind::kWorldRay: {
        const TQ3WorldRayPickData& d = pick.worldRay();
        m_origin = glm::dvec3(d.ray.origin.x, d.ray.origin.y, d.ray.origin.z);
        m_direction = glm::normalize(glm::dvec3(d.ray.direction.x, d.ray.direction.y, d.ray.direction.z));
        m_reach = std::numeric_limits<double>::infinity();
        m_vertexTolerance = d.vertexTolerance;
        m_edgeTolerance = d.edgeTolerance;
        m_rayValid = finite(m_direction);
        break;
    }
    }
}

bool PickPass::beginGroup(const DisplayGroup& group)
{
    if ((group.state() & kQ3DisplayGroupStateMaskIsPicked) == 0)
        return false;
    if (!Pass::beginGroup(group))
        return false;
    m_path.push_back(Level{&group, nullptr});
    return true;
}

void PickPass::endGroup(const DisplayGroup& group)
{
    m_path.pop_back();
    Pass::endGroup(group);
}

void PickPass::atGroupPosition(OpaqueTQ3GroupPosition* position)
{
    if (!m_path.empty())
        m_path.back().position = position;
}

bool PickPass::wants(Slot slot) const
{
    const TQ3PickParts parts = state().draw.pickParts;
    if (parts == kQ3PickPartsObject)
        return true;
    switch (slot) {
    case kFace:
        return (parts & kQ3PickPartsMaskFace) != 0;
    case kEdge:
        return (parts & kQ3PickPartsMaskEdge) != 0;
    case kVertex:
        return (parts & kQ3PickPartsMaskVertex) != 0;
    default:
        return false;
    }
}

void PickPass::offer(Slot slot, const Candidate& candidate)
{
    if (state().draw.pickParts == kQ3PickPartsObject)
        slot = kObject;
    Candidate& best = m_best[slot];
    if (!best.found || candidate.distance < best.distance)
        best = candidate;
}

glm::dvec3 PickPass::world(const MeshView& mesh, std::uint32_t v) const
{
    const float* p = mesh.positions + 3 * std::size_t(v);
    const glm::dvec4 h = transformPoint(m_toWorld, glm::dvec3(p[0], p[1], p[2]));
    return glm::dvec3(h) / h.w;
}

glm::dvec4 PickPass::clip(const MeshView& mesh, std::uint32_t v) const
{
    const float* p = mesh.positions + 3 * std::size_t(v);
    return transformPoint(m_toClip, glm::dvec3(p[0], p[1], p[2]));
}

glm::dvec2 PickPass::toPane(const glm::dvec4& c) const
{
    return frustumToPane(window()->pane, c.x / c.w, c.y / c.w);
}

void PickPass::visitGeometry(const Geometry& geometry)
{
    if (m_kind != Pick::Kind::kWindowRect && !m_rayValid)
        return;
    m_toWorld = state().localToWorld;
    if (window())
        m_toClip = then(m_toWorld, window()->worldToFrustum);
    for (Candidate& c : m_best)
        c = Candidate{};
    geometry.decompose(*this, *this);

    if (m_custom.depth > 0) {
        // Part of a custom object: the nearest of each kind over all it submits.
        for (int slot = 0; slot < kSlots; ++slot) {
            const Candidate& c = m_best[slot];
            Candidate& best = m_custom.best[slot];
            if (c.found && (!best.found || c.distance < best.distance))
                best = c;
        }
        return;
    }
    const GraphicsState& s = state();
    addHits(m_best, Source{geometry.isRetained() ? &geometry : nullptr, geometry.isRetained() ? &geometry : nullptr,
                           s.draw.pickParts, s.draw.pickID, s.localToWorld});
}

void PickPass::beginCustomObject(const Object&)
{
    if (m_custom.depth++ > 0)
        return;
    const GraphicsState& s = state();
    m_custom.pickParts = s.draw.pickParts;
    m_custom.pickID = s.draw.pickID;
    m_custom.localToWorld = s.localToWorld;
    for (Candidate& c : m_custom.best)
        c = Candidate{};
}

void PickPass::endCustomObject(const Object& object, bool submitted)
{
    if (--m_custom.depth > 0 || !submitted)
        return;
    const SharedObject* shared =
        object.isType(kQ3ObjectTypeShared) ? static_cast<const SharedObject*>(&object) : nullptr;
    addHits(m_custom.best, Source{shared, nullptr, m_custom.pickParts, m_custom.pickID, m_custom.localToWorld});
}

void PickPass::addHits(const Candidate (&best)[kSlots], const Source& source)
{
    const TQ3PickDetail mask = m_data.mask;
    const TQ3PickParts parts = source.pickParts;
    const struct {
        Slot slot;
        TQ3PickParts part;
    } kinds[] = {{kObject, kQ3PickPartsObject},
                 {kFace, kQ3PickPartsMaskFace},
                 {kEdge, kQ3PickPartsMaskEdge},
                 {kVertex, kQ3PickPartsMaskVertex}};
    for (const auto& kind : kinds) {
        const Candidate& c = best[kind.slot];
        if (!c.found || (kind.slot == kObject) != (parts == kQ3PickPartsObject))
            continue;
        PickHit hit;
        hit.valid = mask & (kQ3PickDetailMaskPickID | kQ3PickDetailMaskLocalToWorldMatrix | kQ3PickDetailMaskPickPart);
        hit.pickID = source.pickID;
        hit.localToWorld = toQ3(source.localToWorld);
        hit.part = kind.part;
        if ((mask & kQ3PickDetailMaskPath) != 0 && !m_path.empty()) {
            hit.valid |= kQ3PickDetailMaskPath;
            hit.rootGroup = Ref<Group>::retain(const_cast<DisplayGroup*>(m_path.front().group));
            for (const Level& level : m_path)
                hit.positions.push_back(level.position);
        }
        if ((mask & kQ3PickDetailMaskObject) != 0 && source.object != nullptr) {
            hit.valid |= kQ3PickDetailMaskObject;
            hit.object = Ref<SharedObject>::retain(const_cast<SharedObject*>(source.object));
        }
        if (m_kind != Pick::Kind::kWindowRect) {
            hit.valid |= mask & (kQ3PickDetailMaskXYZ | kQ3PickDetailMaskDistance);
            hit.xyz = toPoint(c.xyz);
            hit.distance = float(c.distance);
            hit.sortDistance = c.distance;
        }
        if (c.normal) {
            hit.valid |= mask & kQ3PickDetailMaskNormal;
            hit.normal = TQ3Vector3D{float(c.normal->x), float(c.normal->y), float(c.normal->z)};
        }
        if (c.uv) {
            hit.valid |= mask & kQ3PickDetailMaskUV;
            hit.uv = TQ3Param2D{float(c.uv->x), float(c.uv->y)};
        }
        // The shape part: where the hit lies in the geometry's own
        // coordinates, asked of the geometry (a mesh names its face, edge or
        // vertex there). Window-rect hits have no point to ask about.
        if ((mask & kQ3PickDetailMaskShapePart) != 0 && kind.slot != kObject && source.parts != nullptr &&
            m_kind != Pick::Kind::kWindowRect) {
            const glm::dvec4 h = transformPoint(glm::inverse(source.localToWorld), c.xyz);
            const glm::dvec3 local = glm::dvec3(h) / h.w;
            if (finite(local)) {
                hit.shapePart = source.parts->shapePartAt(kind.part, toPoint(local));
                if (hit.shapePart)
                    hit.valid |= kQ3PickDetailMaskShapePart;
            }
        }
        m_hits.push_back(std::move(hit));
    }
}

void PickPass::draw(const MeshView& mesh, const AttributeSet*)
{
    const bool byParts = state().draw.pickParts != kQ3PickPartsObject;
    if (mesh.triangleCount != 0 && wants(kFace))
        testTriangles(mesh);
    if (wants(kEdge)) {
        for (std::size_t i = 0; i < mesh.lineCount; ++i)
            testSegment(mesh, mesh.lines[2 * i], mesh.lines[2 * i + 1]);
        for (std::size_t s = 0; s < mesh.stripCount; ++s)
            for (std::uint32_t k = 1; k < mesh.strips[s].count; ++k)
                testSegment(mesh, mesh.strips[s].first + k - 1, mesh.strips[s].first + k);
        if (byParts) {
            if (mesh.edgeCount != 0) {
                for (std::size_t i = 0; i < mesh.edgeCount; ++i)
                    testSegment(mesh, mesh.edges[2 * i], mesh.edges[2 * i + 1]);
            } else {
                for (std::size_t t = 0; t < mesh.triangleCount; ++t)
                    for (int k = 0; k < 3; ++k)
                        testSegment(mesh, mesh.triangles[3 * t + k], mesh.triangles[3 * t + (k + 1) % 3]);
            }
        }
    }
    if (wants(kVertex)) {
        if (byParts) {
            for (std::uint32_t v = 0; v < mesh.vertexCount; ++v)
                testVertex(mesh, v);
        } else {
            for (std::size_t i = 0; i < mesh.pointCount; ++i)
                testVertex(mesh, mesh.points[i]);
        }
    }
    if (wants(kFace) && m_kind != Pick::Kind::kWorldRay) {
        for (std::size_t b = 0; b < mesh.bitmapCount; ++b) {
            const ScreenBitmap& bitmap = mesh.bitmaps[b];
            testScreenRect(mesh, bitmap.vertex, bitmap.xOffset, bitmap.yOffset, bitmap.width, bitmap.height);
        }
        for (std::size_t p = 0; p < mesh.pixmapCount; ++p) {
            const ScreenPixmap& pixmap = mesh.pixmaps[p];
            testScreenRect(mesh, pixmap.vertex, pixmap.xOffset, pixmap.yOffset, pixmap.width, pixmap.height);
        }
    }
}

void PickPass::testTriangles(const MeshView& mesh)
{
    if (m_kind == Pick::Kind::kWindowRect) {
        std::vector<glm::dvec2> projected;
        for (std::size_t t = 0; t < mesh.triangleCount; ++t) {
            m_polygon.clear();
            for (int k = 0; k < 3; ++k)
                m_polygon.push_back(clip(mesh, mesh.triangles[3 * t + k]));
            pickmath::clipPolygon(m_polygon);
            projected.clear();
            for (const glm::dvec4& c : m_polygon)
                projected.push_back(toPane(c));
            if (pickmath::convexOverlapsRect(projected.data(), projected.size(), m_rectMin, m_rectMax)) {
                Candidate hit;
                hit.found = true;
                offer(kFace, hit);
                return;
            }
        }
        return;
    }
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(m_toWorld)));
    const bool clockwise = state().draw.orientation == kQ3OrientationStyleClockwise;
    for (std::size_t t = 0; t < mesh.triangleCount; ++t) {
        const std::uint32_t* idx = mesh.triangles + 3 * t;
        const glm::dvec3 a = world(mesh, idx[0]);
        const glm::dvec3 b = world(mesh, idx[1]);
        const glm::dvec3 c = world(mesh, idx[2]);
        const std::optional<pickmath::TriangleHit> found = pickmath::rayTriangle(m_origin, m_direction, a, b, c);
        if (!found || found->t > m_reach)
            continue;
        const double w[3] = {1.0 - found->u - found->v, found->u, found->v};
        Candidate hit;
        hit.found = true;
        hit.distance = found->t;
        hit.xyz = m_origin + found->t * m_direction;
        if (mesh.normals != nullptr) {
            glm::dvec3 n(0.0);
            for (int k = 0; k < 3; ++k) {
                const float* v = mesh.normals + 3 * std::size_t(idx[k]);
                n += w[k] * glm::dvec3(v[0], v[1], v[2]);
            }
            n = normalMatrix * n;
            const double length = glm::length(n);
            if (length > 0.0 && std::isfinite(length))
                hit.normal = n / length;
        }
        if (!hit.normal) {
            glm::dvec3 n = glm::cross(b - a, c - a);
            if (clockwise)
                n = -n;
            const double length = glm::length(n);
            if (length > 0.0 && std::isfinite(length))
                hit.normal = n / length;
        }
        if (mesh.uvs != nullptr) {
            glm::dvec2 uv(0.0);
            for (int k = 0; k < 3; ++k) {
                const float* v = mesh.uvs + 2 * std::size_t(idx[k]);
                uv += w[k] * glm::dvec2(v[0], v[1]);
            }
            // NaN where a corner has no uv.
            if (std::isfinite(uv.x) && std::isfinite(uv.y))
                hit.uv = uv;
        }
        offer(kFace, hit);
    }
}

void PickPass::testSegment(const MeshView& mesh, std::uint32_t a, std::uint32_t b)
{
    Candidate hit;
    hit.found = true;
    if (m_kind == Pick::Kind::kWorldRay) {
        const glm::dvec3 pa = world(mesh, a);
        const glm::dvec3 pb = world(mesh, b);
        const pickmath::Approach near = pickmath::raySegment(m_origin, m_direction, pa, pb);
        if (!(near.distance <= m_edgeTolerance))
            return;
        hit.xyz = pa + near.s * (pb - pa);
        hit.distance = glm::distance(hit.xyz, m_origin);
        offer(kEdge, hit);
        return;
    }
    pickmath::ClipVertex ca{clip(mesh, a), 0.0};
    pickmath::ClipVertex cb{clip(mesh, b), 1.0};
    if (!pickmath::clipSegment(ca, cb))
        return;
    const glm::dvec2 sa = toPane(ca.clip);
    const glm::dvec2 sb = toPane(cb.clip);
    if (m_kind == Pick::Kind::kWindowRect) {
        const glm::dvec2 ends[2] = {sa, sb};
        if (pickmath::convexOverlapsRect(ends, 2, m_rectMin, m_rectMax))
            offer(kEdge, hit);
        return;
    }
    const pickmath::SegmentClosest near = pickmath::pointSegment2D(m_point, sa, sb);
    if (!(near.distance <= m_edgeTolerance))
        return;
    const double h = pickmath::screenToHomogeneous(near.s, ca.clip.w, cb.clip.w);
    const double s = ca.s + h * (cb.s - ca.s);
    const float* p = mesh.positions + 3 * std::size_t(a);
    const float* q = mesh.positions + 3 * std::size_t(b);
    const glm::dvec4 wa = transformPoint(m_toWorld, glm::dvec3(p[0], p[1], p[2]));
    const glm::dvec4 wb = transformPoint(m_toWorld, glm::dvec3(q[0], q[1], q[2]));
    const glm::dvec4 wh = wa + s * (wb - wa);
    hit.xyz = glm::dvec3(wh) / wh.w;
    hit.distance = glm::distance(hit.xyz, m_origin);
    offer(kEdge, hit);
}

void PickPass::testVertex(const MeshView& mesh, std::uint32_t v)
{
    Candidate hit;
    hit.found = true;
    hit.xyz = world(mesh, v);
    if (m_kind == Pick::Kind::kWorldRay) {
        if (!(pickmath::rayPoint(m_origin, m_direction, hit.xyz).distance <= m_vertexTolerance))
            return;
        hit.distance = glm::distance(hit.xyz, m_origin);
        offer(kVertex, hit);
        return;
    }
    const glm::dvec4 c = clip(mesh, v);
    if (!inDepthRange(c))
        return;
    const glm::dvec2 at = toPane(c);
    if (m_kind == Pick::Kind::kWindowRect) {
        if (pickmath::convexOverlapsRect(&at, 1, m_rectMin, m_rectMax))
            offer(kVertex, hit);
        return;
    }
    if (!(glm::distance(at, m_point) <= m_vertexTolerance))
        return;
    hit.distance = glm::distance(hit.xyz, m_origin);
    offer(kVertex, hit);
}

void PickPass::testScreenRect(const MeshView& mesh, std::uint32_t anchor, long xOffset, long yOffset,
                              std::uint32_t width, std::uint32_t height)
{
    const glm::dvec4 c = clip(mesh, anchor);
    if (!inDepthRange(c) || width == 0 || height == 0)
        return;
    const glm::dvec2 at = toPane(c);
    const glm::dvec2 lo(std::floor(at.x) + double(xOffset), std::floor(at.y) + double(yOffset));
    const glm::dvec2 hi = lo + glm::dvec2(width, height);
    const glm::dvec2 corners[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
    Candidate hit;
    hit.found = true;
    hit.xyz = world(mesh, anchor);
    if (m_kind == Pick::Kind::kWindowRect) {
        if (pickmath::convexOverlapsRect(corners, 4, m_rectMin, m_rectMax))
            offer(kFace, hit);
        return;
    }
    if (m_point.x < lo.x || m_point.x > hi.x || m_point.y < lo.y || m_point.y > hi.y)
        return;
    hit.distance = glm::distance(hit.xyz, m_origin);
    offer(kFace, hit);
}

} // namespace q3
