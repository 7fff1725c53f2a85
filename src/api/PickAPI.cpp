// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DPick.h"
#include "api/Entry.h"
#include "geometry/Geometry.h"
#include "group/Group.h"
#include "view/Pick.h"

#include <cstdlib>
#include <cstring>

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;
using q3::api::readInto;

namespace {

template <class Data>
TQ3PickObject newPick(const char* function, const Data* data)
{
    return guard(function, TQ3PickObject{nullptr}, [&]() -> TQ3PickObject {
        requireNonNull(data, "data");
        return makeObject<Pick>(*data);
    });
}

constexpr const char* kPointName = "a window-point pick";
constexpr const char* kRectName = "a window-rect pick";
constexpr const char* kRayName = "a world-ray pick";

// Writes one detail of a hit to detailData, as its type.
void writeDetail(const PickHit& hit, TQ3PickDetail detail, void* detailData)
{
    switch (detail) {
    case kQ3PickDetailMaskPickID:
        std::memcpy(detailData, &hit.pickID, sizeof hit.pickID);
        return;
    case kQ3PickDetailMaskPath: {
        TQ3HitPath path{nullptr, hit.positions.size(), nullptr};
        const std::size_t bytes = hit.positions.size() * sizeof(TQ3GroupPosition);
        path.positions = static_cast<TQ3GroupPosition*>(std::malloc(bytes == 0 ? 1 : bytes));
        if (path.positions == nullptr)
            fail(kQ3ErrorOutOfMemory, "no memory for the hit path's positions");
        if (bytes != 0)
            std::memcpy(path.positions, hit.positions.data(), bytes);
        path.rootGroup = Ref<Group>(hit.rootGroup).detach();
        std::memcpy(detailData, &path, sizeof path);
        return;
    }
    case kQ3PickDetailMaskObject: {
        TQ3Object object = Ref<Geometry>(hit.object).detach();
        std::memcpy(detailData, &object, sizeof object);
        return;
    }
    case kQ3PickDetailMaskLocalToWorldMatrix:
        std::memcpy(detailData, &hit.localToWorld, sizeof hit.localToWorld);
        return;
    case kQ3PickDetailMaskXYZ:
        std::memcpy(detailData, &hit.xyz, sizeof hit.xyz);
        return;
    case kQ3PickDetailMaskDistance:
        std::memcpy(detailData, &hit.distance, sizeof hit.distance);
        return;
    case kQ3PickDetailMaskNormal:
        std::memcpy(detailData, &hit.normal, sizeof hit.normal);
        return;
    case kQ3PickDetailMaskPickPart:
        std::memcpy(detailData, &hit.part, sizeof hit.part);
        return;
    case kQ3PickDetailMaskUV:
        std::memcpy(detailData, &hit.uv, sizeof hit.uv);
        return;
    case kQ3PickDetailMaskShapePart: {
        TQ3Object part = Ref<SharedObject>(hit.shapePart).detach();
        std::memcpy(detailData, &part, sizeof part);
        return;
    }
    default:
        fail(kQ3ErrorInternalError, "a detail without a case");
    }
}

} // namespace

extern "C" {

TQ3ObjectType Q3Pick_GetType(TQ3PickObject pick)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookup<Pick>(pick, "pick").leafType(); });
}

TQ3Status Q3Pick_GetData(TQ3PickObject pick, TQ3PickData* data)
{
    return guardStatus(__func__,
                       [&] { readInto<Pick>(pick, "pick", data, "data", [](const Pick& p) { return p.data(); }); });
}

TQ3Status Q3Pick_SetData(TQ3PickObject pick, const TQ3PickData* data)
{
    return guardStatus(__func__, [&] {
        Pick& target = lookup<Pick>(pick, "pick");
        requireNonNull(data, "data");
        target.setData(*data);
    });
}

TQ3Status Q3Pick_GetVertexTolerance(TQ3PickObject pick, float* vertexTolerance)
{
    return guardStatus(__func__, [&] {
        readInto<Pick>(pick, "pick", vertexTolerance, "vertexTolerance",
                       [](const Pick& p) { return p.vertexTolerance(); });
    });
}

TQ3Status Q3Pick_GetEdgeTolerance(TQ3PickObject pick, float* edgeTolerance)
{
    return guardStatus(__func__, [&] {
        readInto<Pick>(pick, "pick", edgeTolerance, "edgeTolerance",
                       [](const Pick& p) { return p.edgeTolerance(); });
    });
}

TQ3Status Q3Pick_SetVertexTolerance(TQ3PickObject pick, float vertexTolerance)
{
    return guardStatus(__func__, [&] { lookup<Pick>(pick, "pick").setVertexTolerance(vertexTolerance); });
}

TQ3Status Q3Pick_SetEdgeTolerance(TQ3PickObject pick, float edgeTolerance)
{
    return guardStatus(__func__, [&] { lookup<Pick>(pick, "pick").setEdgeTolerance(edgeTolerance); });
}

TQ3Status Q3Pick_GetNumHits(TQ3PickObject pick, unsigned long* numHits)
{
    return guardStatus(__func__, [&] {
        readInto<Pick>(pick, "pick", numHits, "numHits", [](const Pick& p) { return static_cast<unsigned long>(p.hitCount()); });
    });
}

TQ3Status Q3Pick_EmptyHitList(TQ3PickObject pick)
{
    return guardStatus(__func__, [&] { lookup<Pick>(pick, "pick").emptyHits(); });
}

TQ3Status Q3Pick_GetPickDetailValidMask(TQ3PickObject pick, unsigned long index, TQ3PickDetail* pickDetailValidMask)
{
    return guardStatus(__func__, [&] {
        const Pick& source = lookup<Pick>(pick, "pick");
        requireNonNull(pickDetailValidMask, "pickDetailValidMask");
        *pickDetailValidMask = source.hit(index).valid;
    });
}

TQ3Status Q3Pick_GetPickDetailData(TQ3PickObject pick, unsigned long index, TQ3PickDetail pickDetailValue,
                                   void* detailData)
{
    return guardStatus(__func__, [&] {
        const Pick& source = lookup<Pick>(pick, "pick");
        requireNonNull(detailData, "detailData");
        const PickHit& hit = source.hit(index);
        const bool oneBit = pickDetailValue != 0 && (pickDetailValue & (pickDetailValue - 1)) == 0 &&
                            pickDetailValue <= kQ3PickDetailMaskUV;
        if (!oneBit)
            fail(kQ3ErrorInvalidParameter, "pickDetailValue " + std::to_string(pickDetailValue) +
                                               " is not one kQ3PickDetailMask* bit");
        if ((hit.valid & pickDetailValue) == 0)
            fail(kQ3ErrorDataNotAvailable, "hit " + std::to_string(index) + " has no detail " +
                                               std::to_string(pickDetailValue) +
                                               " (see Q3Pick_GetPickDetailValidMask)");
        writeDetail(hit, pickDetailValue, detailData);
    });
}

TQ3Status Q3HitPath_EmptyData(TQ3HitPath* hitPath)
{
    return guardStatus(__func__, [&] {
        requireNonNull(hitPath, "hitPath");
        Group* root = lookupOptional<Group>(hitPath->rootGroup, "hitPath->rootGroup");
        if (hitPath->depth != 0 && hitPath->positions == nullptr)
            fail(kQ3ErrorInvalidParameter, "hitPath->depth is not 0 but hitPath->positions is NULL");
        if (root != nullptr)
            root->dispose();
        std::free(hitPath->positions);
        *hitPath = TQ3HitPath{nullptr, 0, nullptr};
    });
}

TQ3PickObject Q3WindowPointPick_New(const TQ3WindowPointPickData* data)
{
    return newPick(__func__, data);
}

TQ3Status Q3WindowPointPick_GetPoint(TQ3PickObject pick, TQ3Point2D* point)
{
    return guardStatus(__func__, [&] {
        const Pick& source = Pick::ofKind(pick, Pick::Kind::kWindowPoint, kPointName);
        requireNonNull(point, "point");
        *point = source.windowPoint().point;
    });
}

TQ3Status Q3WindowPointPick_SetPoint(TQ3PickObject pick, const TQ3Point2D* point)
{
    return guardStatus(__func__, [&] {
        Pick& target = Pick::ofKind(pick, Pick::Kind::kWindowPoint, kPointName);
        requireNonNull(point, "point");
        target.setPoint(*point);
    });
}

TQ3Status Q3WindowPointPick_GetData(TQ3PickObject pick, TQ3WindowPointPickData* data)
{
    return guardStatus(__func__, [&] {
        const Pick& source = Pick::ofKind(pick, Pick::Kind::kWindowPoint, kPointName);
        requireNonNull(data, "data");
        *data = source.windowPoint();
    });
}

TQ3Status Q3WindowPointPick_SetData(TQ3PickObject pick, const TQ3WindowPointPickData* data)
{
    return guardStatus(__func__, [&] {
        Pick& target = Pick::ofKind(pick, Pick::Kind::kWindowPoint, kPointName);
        requireNonNull(data, "data");
        target.setWindowPoint(*data);
    });
}

TQ3PickObject Q3WindowRectPick_New(const TQ3WindowRectPickData* data)
{
    return newPick(__func__, data);
}

TQ3Status Q3WindowRectPick_GetRect(TQ3PickObject pick, TQ3Area* rect)
{
    return guardStatus(__func__, [&] {
        const Pick& source = Pick::ofKind(pick, Pick::Kind::kWindowRect, kRectName);
        requireNonNull(rect, "rect");
        *rect = source.windowRect().rect;
    });
}

TQ3Status Q3WindowRectPick_SetRect(TQ3PickObject pick, const TQ3Area* rect)
{
    return guardStatus(__func__, [&] {
        Pick& target = Pick::ofKind(pick, Pick::Kind::kWindowRect, kRectName);
        requireNonNull(rect, "rect");
        target.setRect(*rect);
    });
}

TQ3Status Q3WindowRectPick_GetData(TQ3PickObject pick, TQ3WindowRectPickData* data)
{
    return guardStatus(__func__, [&] {
        const Pick& source = Pick::ofKind(pick, Pick::Kind::kWindowRect, kRectName);
        requireNonNull(data, "data");
        *data = source.windowRect();
    });
}

TQ3Status Q3WindowRectPick_SetData(TQ3PickObject pick, const TQ3WindowRectPickData* data)
{
    return guardStatus(__func__, [&] {
        Pick& target = Pick::ofKind(pick, Pick::Kind::kWindowRect, kRectName);
        requireNonNull(data, "data");
        target.setWindowRect(*data);
    });
}

TQ3PickObject Q3WorldRayPick_New(const TQ3WorldRayPickData* data)
{
    return newPick(__func__, data);
}

TQ3Status Q3WorldRayPick_GetRay(TQ3PickObject pick, TQ3Ray3D* ray)
{
    return guardStatus(__func__, [&] {
        const Pick& source = Pick::ofKind(pick, Pick::Kind::kWorldRay, kRayName);
        requireNonNull(ray, "ray");
        *ray = source.worldRay().ray;
    });
}

TQ3Status Q3WorldRayPick_SetRay(TQ3PickObject pick, const TQ3Ray3D* ray)
{
    return guardStatus(__func__, [&] {
        Pick& target = Pick::ofKind(pick, Pick::Kind::kWorldRay, kRayName);
        requireNonNull(ray, "ray");
        target.setRay(*ray);
    });
}

TQ3Status Q3WorldRayPick_GetData(TQ3PickObject pick, TQ3WorldRayPickData* data)
{
    return guardStatus(__func__, [&] {
        const Pick& source = Pick::ofKind(pick, Pick::Kind::kWorldRay, kRayName);
        requireNonNull(data, "data");
        *data = source.worldRay();
    });
}

TQ3Status Q3WorldRayPick_SetData(TQ3PickObject pick, const TQ3WorldRayPickData* data)
{
    return guardStatus(__func__, [&] {
        Pick& target = Pick::ofKind(pick, Pick::Kind::kWorldRay, kRayName);
        requireNonNull(data, "data");
        target.setWorldRay(*data);
    });
}

} // extern "C"
