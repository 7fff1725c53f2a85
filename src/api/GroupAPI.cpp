// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGroup.h"
#include "api/Entry.h"
#include "group/Group.h"
#include "view/View.h"

using namespace q3;
using namespace q3::api;

namespace {

Ref<SharedObject> member(TQ3Object object)
{
    Object& found = lookupObject(object, "object");
    if (!found.isType(kQ3ObjectTypeShared))
        fail(kQ3ErrorInvalidObjectForGroup, std::string("a ") + found.classInfo().name +
                                                " is not a shared object and cannot be in a group");
    return Ref<SharedObject>::retain(&static_cast<SharedObject&>(found));
}

template <class Make>
TQ3GroupObject newGroup(const char* function, Make make)
{
    return guard(function, TQ3GroupObject{nullptr}, [&]() -> TQ3GroupObject { return make().detach(); });
}

// The position walks: *position replaced by what `step` gives.
template <class Step>
TQ3Status walk(const char* function, TQ3GroupObject group, TQ3GroupPosition* position, Step step)
{
    return guardStatus(function, [&] {
        const Group& target = lookup<Group>(group, "group");
        requireNonNull(position, "position");
        *position = step(target);
    });
}

} // namespace

extern "C" {

TQ3GroupObject Q3Group_New(void)
{
    return newGroup(__func__, [] { return makeShared<Group>(); });
}

TQ3GroupObject Q3LightGroup_New(void)
{
    return newGroup(__func__, [] { return makeShared<LightGroup>(); });
}

TQ3GroupObject Q3InfoGroup_New(void)
{
    return newGroup(__func__, [] { return makeShared<InfoGroup>(); });
}

TQ3GroupObject Q3DisplayGroup_New(void)
{
    return newGroup(__func__, [] { return makeShared<DisplayGroup>(); });
}

TQ3GroupObject Q3OrderedDisplayGroup_New(void)
{
    return newGroup(__func__, [] { return makeShared<OrderedDisplayGroup>(); });
}

TQ3GroupObject Q3IOProxyDisplayGroup_New(void)
{
    return newGroup(__func__, [] { return makeShared<IOProxyDisplayGroup>(); });
}

TQ3ObjectType Q3Group_GetType(TQ3GroupObject group)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookup<Group>(group, "group").classInfo().typeAtLevel(4); });
}

TQ3GroupPosition Q3Group_AddObject(TQ3GroupObject group, TQ3Object object)
{
    return guard(__func__, TQ3GroupPosition{nullptr}, [&] {
        Group& target = lookup<Group>(group, "group");
        return target.add(member(object));
    });
}

TQ3GroupPosition Q3Group_AddObjectBefore(TQ3GroupObject group, TQ3GroupPosition position, TQ3Object object)
{
    return guard(__func__, TQ3GroupPosition{nullptr}, [&] {
        Group& target = lookup<Group>(group, "group");
        return target.addBefore(position, member(object));
    });
}

TQ3GroupPosition Q3Group_AddObjectAfter(TQ3GroupObject group, TQ3GroupPosition position, TQ3Object object)
{
    return guard(__func__, TQ3GroupPosition{nullptr}, [&] {
        Group& target = lookup<Group>(group, "group");
        return target.addAfter(position, member(object));
    });
}

TQ3Status Q3Group_GetPositionObject(TQ3GroupObject group, TQ3GroupPosition position, TQ3Object* object)
{
    return getValue<Group>(__func__, group, "group", object, "object", [&](const Group& source) {
        return Ref<SharedObject>::retain(&source.objectAt(position)).detach();
    });
}

TQ3Status Q3Group_SetPositionObject(TQ3GroupObject group, TQ3GroupPosition position, TQ3Object object)
{
    return guardStatus(__func__, [&] {
        Group& target = lookup<Group>(group, "group");
        target.setObjectAt(position, member(object));
    });
}

TQ3Object Q3Group_RemovePosition(TQ3GroupObject group, TQ3GroupPosition position)
{
    return guard(__func__, TQ3Object{nullptr}, [&]() -> TQ3Object {
        return lookup<Group>(group, "group").remove(position).detach();
    });
}

TQ3Status Q3Group_GetFirstPosition(TQ3GroupObject group, TQ3GroupPosition* position)
{
    return walk(__func__, group, position, [&](const Group& g) { return g.first(); });
}

TQ3Status Q3Group_GetLastPosition(TQ3GroupObject group, TQ3GroupPosition* position)
{
    return walk(__func__, group, position, [&](const Group& g) { return g.last(); });
}

TQ3Status Q3Group_GetNextPosition(TQ3GroupObject group, TQ3GroupPosition* position)
{
    return walk(__func__, group, position, [&](const Group& g) { return g.next(*position); });
}

TQ3Status Q3Group_GetPreviousPosition(TQ3GroupObject group, TQ3GroupPosition* position)
{
    return walk(__func__, group, position, [&](const Group& g) { return g.previous(*position); });
}

TQ3Status Q3Group_CountObjects(TQ3GroupObject group, unsigned long* nObjects)
{
    return getValue<Group>(__func__, group, "group", nObjects, "nObjects",
                           [](const Group& g) { return static_cast<unsigned long>(g.count()); });
}

TQ3Status Q3Group_CountObjectsOfType(TQ3GroupObject group, TQ3ObjectType isType, unsigned long* nObjects)
{
    return getValue<Group>(__func__, group, "group", nObjects, "nObjects",
                           [&](const Group& g) { return static_cast<unsigned long>(g.count(isType)); });
}

TQ3Status Q3Group_EmptyObjects(TQ3GroupObject group)
{
    return guardStatus(__func__, [&] { lookup<Group>(group, "group").empty(); });
}

TQ3Status Q3Group_EmptyObjectsOfType(TQ3GroupObject group, TQ3ObjectType isType)
{
    return guardStatus(__func__, [&] { lookup<Group>(group, "group").empty(isType); });
}

TQ3Status Q3Group_GetFirstPositionOfType(TQ3GroupObject group, TQ3ObjectType isType, TQ3GroupPosition* position)
{
    return walk(__func__, group, position, [&](const Group& g) { return g.first(isType); });
}

TQ3Status Q3Group_GetLastPositionOfType(TQ3GroupObject group, TQ3ObjectType isType, TQ3GroupPosition* position)
{
    return walk(__func__, group, position, [&](const Group& g) { return g.last(isType); });
}

TQ3Status Q3Group_GetNextPositionOfType(TQ3GroupObject group, TQ3ObjectType isType, TQ3GroupPosition* position)
{
    return walk(__func__, group, position, [&](const Group& g) { return g.next(*position, isType); });
}

TQ3Status Q3Group_GetPreviousPositionOfType(TQ3GroupObject group, TQ3ObjectType isType,
                                            TQ3GroupPosition* position)
{
    return walk(__func__, group, position, [&](const Group& g) { return g.previous(*position, isType); });
}

TQ3Status Q3Group_GetFirstObjectPosition(TQ3GroupObject group, TQ3Object object, TQ3GroupPosition* position)
{
    return walk(__func__, group, position,
                [&](const Group& g) { return g.firstOf(lookupObject(object, "object")); });
}

TQ3Status Q3Group_GetLastObjectPosition(TQ3GroupObject group, TQ3Object object, TQ3GroupPosition* position)
{
    return walk(__func__, group, position,
                [&](const Group& g) { return g.lastOf(lookupObject(object, "object")); });
}

TQ3Status Q3Group_GetNextObjectPosition(TQ3GroupObject group, TQ3Object object, TQ3GroupPosition* position)
{
    return walk(__func__, group, position,
                [&](const Group& g) { return g.nextOf(*position, lookupObject(object, "object")); });
}

TQ3Status Q3Group_GetPreviousObjectPosition(TQ3GroupObject group, TQ3Object object, TQ3GroupPosition* position)
{
    return walk(__func__, group, position,
                [&](const Group& g) { return g.previousOf(*position, lookupObject(object, "object")); });
}

TQ3ObjectType Q3DisplayGroup_GetType(TQ3GroupObject group)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookup<DisplayGroup>(group, "group").classInfo().typeAtLevel(5); });
}

TQ3Status Q3DisplayGroup_GetState(TQ3GroupObject group, TQ3DisplayGroupState* state)
{
    return getValue<DisplayGroup>(__func__, group, "group", state, "state",
                                  [](const DisplayGroup& g) { return g.state(); });
}

TQ3Status Q3DisplayGroup_SetState(TQ3GroupObject group, TQ3DisplayGroupState state)
{
    return guardStatus(__func__, [&] { lookup<DisplayGroup>(group, "group").setState(state); });
}

TQ3Status Q3DisplayGroup_Submit(TQ3GroupObject group, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        const DisplayGroup& shape = lookup<DisplayGroup>(group, "group");
        lookup<View>(view, "view").submit(shape);
    });
}

TQ3Status Q3DisplayGroup_SetAndUseBoundingBox(TQ3GroupObject group, TQ3BoundingBox* bBox)
{
    return setValue<DisplayGroup>(__func__, group, "group", bBox, "bBox", &DisplayGroup::setBoundingBox);
}

TQ3Status Q3DisplayGroup_GetBoundingBox(TQ3GroupObject group, TQ3BoundingBox* bBox)
{
    return guardStatus(__func__, [&] {
        readInto<DisplayGroup>(group, "group", bBox, "bBox", [](const DisplayGroup& g) {
            if (!g.boundingBox())
                fail(kQ3ErrorInvalidParameter, "the display group has no bounding box");
            return *g.boundingBox();
        });
    });
}

TQ3Status Q3DisplayGroup_RemoveBoundingBox(TQ3GroupObject group)
{
    return guardStatus(__func__, [&] { lookup<DisplayGroup>(group, "group").removeBoundingBox(); });
}

TQ3Status Q3DisplayGroup_CalcAndUseBoundingBox(TQ3GroupObject group, TQ3ComputeBounds computeBounds,
                                              TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        DisplayGroup& target = lookup<DisplayGroup>(group, "group");
        View& bounding = lookup<View>(view, "view");
        target.setBoundingBox(bounding.boundingBoxOf(target, computeBounds));
    });
}

} // extern "C"
