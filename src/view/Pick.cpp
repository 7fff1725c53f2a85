// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/Pick.h"

#include "core/Error.h"
#include "core/ParameterChecks.h"
#include "geometry/Geometry.h"
#include "group/Group.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace q3 {

const ClassInfo kPickClass{kQ3ObjectTypePick, &kRootClass, "pick"};
const ClassInfo kWindowPointPickClass{kQ3PickTypeWindowPoint, &kPickClass, "window-point pick"};
const ClassInfo kWindowRectPickClass{kQ3PickTypeWindowRect, &kPickClass, "window-rect pick"};
const ClassInfo kWorldRayPickClass{kQ3PickTypeWorldRay, &kPickClass, "world-ray pick"};

namespace {

constexpr TQ3PickDetail kAllDetails = (kQ3PickDetailMaskUV << 1) - 1;

void checkTolerance(float value, const char* name)
{
    checkFinite(value, name);
    if (value < 0.0f)
        fail(kQ3ErrorInvalidParameter, std::string(name) + " is negative");
}

void checkPoint(const TQ3Point2D& point, const char* name)
{
    if (!std::isfinite(point.x) || !std::isfinite(point.y))
        fail(kQ3ErrorInvalidParameter, std::string(name) + " has a NaN or infinite coordinate");
}

} // namespace

Pick::Pick(const TQ3WindowPointPickData& data) : m_kind(Kind::kWindowPoint)
{
    check(data);
    m_point = data;
    m_data = data.data;
}

Pick::Pick(const TQ3WindowRectPickData& data) : m_kind(Kind::kWindowRect)
{
    check(data);
    m_rect = data;
    m_data = data.data;
}

Pick::Pick(const TQ3WorldRayPickData& data) : m_kind(Kind::kWorldRay)
{
    check(data);
    m_ray = data;
    m_data = data.data;
}

const ClassInfo& Pick::classInfo() const
{
    switch (m_kind) {
    case Kind::kWindowPoint:
        return kWindowPointPickClass;
    case Kind::kWindowRect:
        return kWindowRectPickClass;
    default:
        return kWorldRayPickClass;
    }
}

Pick& Pick::ofKind(TQ3Object handle, Kind kind, const char* what)
{
    Pick& pick = lookup<Pick>(handle, "pick");
    if (pick.kind() != kind)
        fail(kQ3ErrorInvalidObjectType, std::string("pick is a ") + pick.classInfo().name + ", not " + what);
    return pick;
}

void Pick::check(const TQ3PickData& data)
{
    checkEnum(data.sort, kQ3PickSortNone, kQ3PickSortFarToNear, "data->sort",
              "kQ3PickSortNone, kQ3PickSortNearToFar, kQ3PickSortFarToNear");
    if ((data.mask & ~kAllDetails) != 0)
        fail(kQ3ErrorInvalidParameter, "data->mask has bits above kQ3PickDetailMaskUV");
}

void Pick::check(const TQ3WindowPointPickData& data)
{
    check(data.data);
    checkPoint(data.point, "data->point");
    checkTolerance(data.vertexTolerance, "data->vertexTolerance");
    checkTolerance(data.edgeTolerance, "data->edgeTolerance");
}

void Pick::check(const TQ3WindowRectPickData& data)
{
    check(data.data);
    checkPoint(data.rect.min, "data->rect.min");
    checkPoint(data.rect.max, "data->rect.max");
    if (data.rect.min.x > data.rect.max.x || data.rect.min.y > data.rect.max.y)
        fail(kQ3ErrorInvalidParameter, "data->rect.min exceeds data->rect.max");
}

void Pick::check(const TQ3WorldRayPickData& data)
{
    check(data.data);
    checkFinite(data.ray.origin, "data->ray.origin");
    checkFinite(data.ray.direction, "data->ray.direction");
    const TQ3Vector3D& d = data.ray.direction;
    if (d.x == 0.0f && d.y == 0.0f && d.z == 0.0f)
        fail(kQ3ErrorInvalidParameter, "data->ray.direction is the zero vector");
    checkTolerance(data.vertexTolerance, "data->vertexTolerance");
    checkTolerance(data.edgeTolerance, "data->edgeTolerance");
}

void Pick::setData(const TQ3PickData& data)
{
    check(data);
    m_data = data;
    m_point.data = data;
    m_rect.data = data;
    m_ray.data = data;
    setHits(std::move(m_hits));
}

float Pick::vertexTolerance() const
{
    if (m_kind == Kind::kWindowRect)
        fail(kQ3ErrorInvalidObjectType, "a window-rect pick has no tolerances");
    return m_kind == Kind::kWindowPoint ? m_point.vertexTolerance : m_ray.vertexTolerance;
}

float Pick::edgeTolerance() const
{
    if (m_kind == Kind::kWindowRect)
        fail(kQ3ErrorInvalidObjectType, "a window-rect pick has no tolerances");
    return m_kind == Kind::kWindowPoint ? m_point.edgeTolerance : m_ray.edgeTolerance;
}

void Pick::setVertexTolerance(float tolerance)
{
    vertexTolerance();
    checkTolerance(tolerance, "vertexTolerance");
    (m_kind == Kind::kWindowPoint ? m_point.vertexTolerance : m_ray.vertexTolerance) = tolerance;
}

void Pick::setEdgeTolerance(float tolerance)
{
    edgeTolerance();
    checkTolerance(tolerance, "edgeTolerance");
    (m_kind == Kind::kWindowPoint ? m_point.edgeTolerance : m_ray.edgeTolerance) = tolerance;
}

void Pick::setWindowPoint(const TQ3WindowPointPickData& data)
{
    check(data);
    m_point = data;
    m_data = data.data;
    setHits(std::move(m_hits));
}

void Pick::setWindowRect(const TQ3WindowRectPickData& data)
{
    check(data);
    m_rect = data;
    m_data = data.data;
    setHits(std::move(m_hits));
}

void Pick::setWorldRay(const TQ3WorldRayPickData& data)
{
    check(data);
    m_ray = data;
    m_data = data.data;
    setHits(std::move(m_hits));
}

void Pick::setPoint(const TQ3Point2D& point)
{
    checkPoint(point, "point");
    m_point.point = point;
}

void Pick::setRect(const TQ3Area& rect)
{
    TQ3WindowRectPickData data = m_rect;
    data.rect = rect;
    check(data);
    m_rect = data;
}

void Pick::setRay(const TQ3Ray3D& ray)
{
    TQ3WorldRayPickData data = m_ray;
    data.ray = ray;
    check(data);
    m_ray = data;
}

void Pick::setHits(std::vector<PickHit> hits)
{
    // Window-rect hits have no distance: they keep submission order.
    const TQ3PickSort sort = m_data.sort;
    if (sort != kQ3PickSortNone && m_kind != Kind::kWindowRect)
        std::stable_sort(hits.begin(), hits.end(), [sort](const PickHit& a, const PickHit& b) {
            return sort == kQ3PickSortNearToFar ? a.sortDistance < b.sortDistance
                                                : a.sortDistance > b.sortDistance;
        });
    if (m_data.numHitsToReturn != kQ3ReturnAllHits && hits.size() > m_data.numHitsToReturn)
        hits.resize(m_data.numHitsToReturn);
    // The pick's data as it is now rules, as for the sort and the count: a
    // Q3Pick_SetData during the picking loop may have dropped details the
    // loop's start asked for, and a hit reports only what the pick asks.
    for (PickHit& hit : hits)
        hit.valid &= m_data.mask;
    m_hits = std::move(hits);
}

const PickHit& Pick::hit(unsigned long index) const
{
    if (index >= m_hits.size())
        fail(kQ3ErrorParameterOutOfRange, "index " + std::to_string(index) + " is not below the " +
                                              std::to_string(m_hits.size()) + " hits");
    return m_hits[index];
}

} // namespace q3
