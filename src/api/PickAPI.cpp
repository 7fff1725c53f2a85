// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DPick.h"
#include "api/Entry.h"
#include "geometry/Geometry.h"
#include "group/Group.h"
#include "view/Pick.h"

#include <cstdlib>
#include <cstring>
#include <functional>

using namespace q3;
using namespace q3::api;

namespace {

template <class Data>
TQ3PickObject newPick(const char* function, const Data* data)
{
    return guard(function, TQ3PickObject{nullptr}, [&]() -> TQ3PickObject {
        requireNonNull(data, "data");
        return makeObject<Pick>(*data);
    });
}

// A pick kind and how errors name it.
struct KindOf {
    Pick::Kind kind;
    const char* name;
};

constexpr KindOf kPoint{Pick::Kind::kWindowPoint, "a window-point pick"};
constexpr KindOf kRect{Pick::Kind::kWindowRect, "a window-rect pick"};
constexpr KindOf kRay{Pick::Kind::kWorldRay, "a world-ray pick"};

// The Get and Set of one kind's value: the pick (of that kind), then the
// pointer, then *out = read(pick) or write(pick, *in).
template <class Value, class Read>
TQ3Status getOfKind(const char* function, TQ3PickObject pick, KindOf kind, Value* out, const char* outName, Read read)
{
    return guardStatus(function, [&] {
        const Pick& source = Pick::ofKind(pick, kind.kind, kind.name);
        requireNonNull(out, outName);
        *out = std::invoke(read, source);
    });
}

template <class Value>
TQ3Status setOfKind(const char* function, TQ3PickObject pick, KindOf kind, const Value* in, const char* inName,
                    void (Pick::*write)(const Value&))
{
    return guardStatus(function, [&] {
        Pick& target = Pick::ofKind(pick, kind.kind, kind.name);
        requireNonNull(in, inName);
        (target.*write)(*in);
    });
}

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
        TQ3Object object = Ref<SharedObject>(hit.object).detach();
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

// A C entry point cannot come from a template, so the five entry points every
// pick kind has are written once as a macro that defines them through the
// templates above: Q3<Kind>Pick_New, _Get/Set<Field> and _GetData/SetData.
// The kind's data is TQ3<Kind>PickData, read by Pick::<read>() and set by
// Pick::set<Kind>; its one field is the Type `field`, set by Pick::set<Field>.
// A handle of another kind is refused as `kindCheck` says.
#define Q3_PICK_KIND_ENTRY_POINTS(Kind, read, kindCheck, Field, Type, field)                                    \
    TQ3PickObject Q3##Kind##Pick_New(const TQ3##Kind##PickData* data)                                           \
    {                                                                                                           \
        return newPick(__func__, data);                                                                         \
    }                                                                                                           \
    TQ3Status Q3##Kind##Pick_Get##Field(TQ3PickObject pick, Type* field)                                        \
    {                                                                                                           \
        return getOfKind(__func__, pick, kindCheck, field, #field,                                              \
                         [](const Pick& p) { return p.read().field; });                                         \
    }                                                                                                           \
    TQ3Status Q3##Kind##Pick_Set##Field(TQ3PickObject pick, const Type* field)                                  \
    {                                                                                                           \
        return setOfKind(__func__, pick, kindCheck, field, #field, &Pick::set##Field);                          \
    }                                                                                                           \
    TQ3Status Q3##Kind##Pick_GetData(TQ3PickObject pick, TQ3##Kind##PickData* data)                             \
    {                                                                                                           \
        return getOfKind(__func__, pick, kindCheck, data, "data", &Pick::read);                                 \
    }                                                                                                           \
    TQ3Status Q3##Kind##Pick_SetData(TQ3PickObject pick, const TQ3##Kind##PickData* data)                       \
    {                                                                                                           \
        return setOfKind(__func__, pick, kindCheck, data, "data", &Pick::set##Kind);                            \
    }

extern "C" {

TQ3ObjectType Q3Pick_GetType(TQ3PickObject pick)
{
    return api::getLeafType<Pick>(__func__, pick, "pick");
}

TQ3Status Q3Pick_GetData(TQ3PickObject pick, TQ3PickData* data)
{
    return getValue<Pick>(__func__, pick, "pick", data, "data", [](const Pick& p) { return p.data(); });
}

TQ3Status Q3Pick_SetData(TQ3PickObject pick, const TQ3PickData* data)
{
    return setValue<Pick>(__func__, pick, "pick", data, "data", &Pick::setData);
}

TQ3Status Q3Pick_GetVertexTolerance(TQ3PickObject pick, float* vertexTolerance)
{
    return getValue<Pick>(__func__, pick, "pick", vertexTolerance, "vertexTolerance",
                          [](const Pick& p) { return p.vertexTolerance(); });
}

TQ3Status Q3Pick_GetEdgeTolerance(TQ3PickObject pick, float* edgeTolerance)
{
    return getValue<Pick>(__func__, pick, "pick", edgeTolerance, "edgeTolerance",
                          [](const Pick& p) { return p.edgeTolerance(); });
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
    return getValue<Pick>(__func__, pick, "pick", numHits, "numHits",
                          [](const Pick& p) { return static_cast<unsigned long>(p.hitCount()); });
}

TQ3Status Q3Pick_EmptyHitList(TQ3PickObject pick)
{
    return guardStatus(__func__, [&] { lookup<Pick>(pick, "pick").emptyHits(); });
}

TQ3Status Q3Pick_GetPickDetailValidMask(TQ3PickObject pick, unsigned long index, TQ3PickDetail* pickDetailValidMask)
{
    return getValue<Pick>(__func__, pick, "pick", pickDetailValidMask, "pickDetailValidMask",
                          [&](const Pick& source) { return source.hit(index).valid; });
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

Q3_PICK_KIND_ENTRY_POINTS(WindowPoint, windowPoint, kPoint, Point, TQ3Point2D, point)
Q3_PICK_KIND_ENTRY_POINTS(WindowRect, windowRect, kRect, Rect, TQ3Area, rect)
Q3_PICK_KIND_ENTRY_POINTS(WorldRay, worldRay, kRay, Ray, TQ3Ray3D, ray)

} // extern "C"

#undef Q3_PICK_KIND_ENTRY_POINTS
