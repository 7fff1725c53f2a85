// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Bounding volumes. The box is the running min/max of the world points. The
// sphere is grown shape by shape: each shape's sphere is centred on its own
// box with the radius reaching its farthest point, and two spheres merge
// into the smallest sphere holding both (centre on the line through the two
// centres). That is not the minimal sphere of everything, which QD3DView.h
// does not promise, but it always encloses every point and costs O(1)
// memory across shapes.

#include "view/BoundsPass.h"

#include "core/EnumValue.h"
#include "geometry/Geometry.h"
#include "base/BoundsMath.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace q3 {

using math::roundDown;
using math::roundUp;

namespace {

glm::dvec3 toVec(const TQ3Point3D& p)
{
    return glm::dvec3(p.x, p.y, p.z);
}

} // namespace

void BoundsPass::visitGeometry(const Geometry& geometry)
{
    m_local.clear();
    geometry.bound(*this, m_local);
    addShape();
}

bool BoundsPass::enterBoundedGroup(const DisplayGroup& group, const TQ3BoundingBox& box)
{
    if (enumValue(box.isEmpty) == kQ3False) {
        m_local.clear();
        for (int corner = 0; corner < 8; ++corner)
            m_local.emplace_back((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                                 (corner & 4) ? box.max.z : box.min.z);
        addShape();
    }
    return false;
}

void BoundsPass::addShape()
{
    if (m_local.empty())
        return;
    if (m_mode == kQ3ComputeBoundsApproximate) {
        glm::dvec3 low = m_local.front();
        glm::dvec3 high = low;
        for (const glm::dvec3& p : m_local) {
            low = glm::min(low, p);
            high = glm::max(high, p);
        }
        m_local.clear();
        for (int corner = 0; corner < 8; ++corner)
            m_local.emplace_back((corner & 1) ? high.x : low.x, (corner & 2) ? high.y : low.y,
                                 (corner & 4) ? high.z : low.z);
    }
    m_world.clear();
    for (const glm::dvec3& p : m_local) {
        const glm::dvec4 v = transformPoint(state().localToWorld, p);
        const glm::dvec3 world = glm::dvec3(v) / v.w;
        // A point the transform sends to infinity has no place in a bound.
        if (v.w != 0.0 && std::isfinite(world.x) && std::isfinite(world.y) && std::isfinite(world.z))
            m_world.push_back(world);
    }
    if (m_world.empty())
        return;

    glm::dvec3 low = m_world.front();
    glm::dvec3 high = low;
    for (const glm::dvec3& p : m_world) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    const glm::dvec3 center = (low + high) / 2.0;
    double radius = 0.0;
    for (const glm::dvec3& p : m_world)
        radius = std::max(radius, glm::distance(center, p));

    if (m_empty) {
        m_empty = false;
        m_min = low;
        m_max = high;
        m_center = center;
        m_radius = radius;
        return;
    }
    m_min = glm::min(m_min, low);
    m_max = glm::max(m_max, high);
    const double apart = glm::distance(m_center, center);
    if (apart + radius <= m_radius)
        return;
    if (apart + m_radius <= radius) {
        m_center = center;
        m_radius = radius;
        return;
    }
    const double merged = (apart + m_radius + radius) / 2.0;
    m_center += (center - m_center) * ((merged - m_radius) / apart);
    m_radius = merged;
}

TQ3BoundingBox BoundsPass::box() const
{
    TQ3BoundingBox box{};
    box.isEmpty = m_empty ? kQ3True : kQ3False;
    if (!m_empty) {
        box.min = TQ3Point3D{roundDown(m_min.x), roundDown(m_min.y), roundDown(m_min.z)};
        box.max = TQ3Point3D{roundUp(m_max.x), roundUp(m_max.y), roundUp(m_max.z)};
    }
    return box;
}

TQ3BoundingSphere BoundsPass::sphere() const
{
    TQ3BoundingSphere sphere{};
    sphere.isEmpty = m_empty ? kQ3True : kQ3False;
    if (!m_empty) {
        sphere.origin = TQ3Point3D{float(m_center.x), float(m_center.y), float(m_center.z)};
        // The centre moved by rounding; the radius grows by as much.
        const double shift = glm::distance(m_center, toVec(sphere.origin));
        sphere.radius = roundUp(m_radius + shift);
    }
    return sphere;
}

} // namespace q3
