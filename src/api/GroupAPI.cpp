// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGroup.h"
#include "api/Entry.h"
#include "group/CustomGroup.h"
#include "group/Group.h"
#include "view/View.h"

#include <optional>

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

// What the method `type` of the group's class returns when it gives one
// (group/CustomGroup.h): it then replaces Q3's own code for the call.
template <class Method, class Call>
auto byClass(const Group& group, TQ3XMethodType type, Call call)
    -> std::optional<decltype(call(std::declval<Method>()))>
{
    const auto method = reinterpret_cast<Method>(groupMethod(group, type));
    if (method == nullptr)
        return std::nullopt;
    GroupMethodCall running(group, type);
    return call(method);
}

// The entry points that return a position or an object: the class's method,
// else `own`.
template <class Method, class Result, class Call, class Own>
Result replaceable(const char* function, TQ3GroupObject group, TQ3XMethodType type, Call call, Own own)
{
    return guard(function, Result{nullptr}, [&]() -> Result {
        Group& target = lookup<Group>(group, "group");
        if (const auto done = byClass<Method>(target, type, call))
            return *done;
        return own(target);
    });
}

// The position walks and counts: *out replaced by what `step` gives, or
// by the class's method.
template <class Method, class Out, class Call, class Step>
TQ3Status walk(const char* function, TQ3GroupObject group, Out* out, const char* outName, TQ3XMethodType type,
               Call call, Step step)
{
    return guard(function, kQ3Failure, [&] {
        const Group& target = lookup<Group>(group, "group");
        requireNonNull(out, outName);
        if (const auto done = byClass<Method>(target, type, call))
            return *done;
        *out = step(target);
        return kQ3Success;
    });
}

// The position walks over objects of a type.
template <class Method, class Step>
TQ3Status walkOfType(const char* function, TQ3GroupObject group, TQ3ObjectType isType, TQ3GroupPosition* position,
                     TQ3XMethodType type, Step step)
{
    return walk<Method>(
        function, group, position, "position", type, [&](Method m) { return m(group, isType, position); }, step);
}

// The position walks over one object's positions.
template <class Method, class Step>
TQ3Status walkOfObject(const char* function, TQ3GroupObject group, TQ3Object object, TQ3GroupPosition* position,
                       TQ3XMethodType type, Step step)
{
    return walk<Method>(
        function, group, position, "position", type, [&](Method m) { return m(group, object, position); },
        [&](const Group& g) { return step(g, lookupObject(object, "object")); });
}

// Counting (of a type): the class's method or Q3's.
TQ3Status countOfType(const char* function, TQ3GroupObject group, TQ3ObjectType isType, TQ3ObjectType ownType,
                      unsigned long* nObjects)
{
    using Method = TQ3XGroupCountObjectsOfTypeMethod;
    return walk<Method>(
        function, group, nObjects, "nObjects", kQ3XMethodType_GroupCountObjectsOfType,
        [&](Method m) { return m(group, isType, nObjects); },
        [&](const Group& g) { return static_cast<unsigned long>(g.count(ownType)); });
}

// Emptying (of a type): the class's method or Q3's.
TQ3Status emptyOfType(const char* function, TQ3GroupObject group, TQ3ObjectType isType, TQ3ObjectType ownType)
{
    return guard(function, kQ3Failure, [&] {
        Group& target = lookup<Group>(group, "group");
        if (const auto done = byClass<TQ3XGroupEmptyObjectsOfTypeMethod>(
                target, kQ3XMethodType_GroupEmptyObjectsOfType,
                [&](TQ3XGroupEmptyObjectsOfTypeMethod m) { return m(group, isType); }))
            return *done;
        target.empty(ownType);
        return kQ3Success;
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
    using Method = TQ3XGroupAddObjectMethod;
    return replaceable<Method, TQ3GroupPosition>(
        __func__, group, kQ3XMethodType_GroupAddObject, [&](Method m) { return m(group, object); },
        [&](Group& g) { return g.add(member(object)); });
}

TQ3GroupPosition Q3Group_AddObjectBefore(TQ3GroupObject group, TQ3GroupPosition position, TQ3Object object)
{
    using Method = TQ3XGroupAddObjectBeforeMethod;
    return replaceable<Method, TQ3GroupPosition>(
        __func__, group, kQ3XMethodType_GroupAddObjectBefore, [&](Method m) { return m(group, position, object); },
        [&](Group& g) { return g.addBefore(position, member(object)); });
}

TQ3GroupPosition Q3Group_AddObjectAfter(TQ3GroupObject group, TQ3GroupPosition position, TQ3Object object)
{
    using Method = TQ3XGroupAddObjectAfterMethod;
    return replaceable<Method, TQ3GroupPosition>(
        __func__, group, kQ3XMethodType_GroupAddObjectAfter, [&](Method m) { return m(group, position, object); },
        [&](Group& g) { return g.addAfter(position, member(object)); });
}

TQ3Status Q3Group_GetPositionObject(TQ3GroupObject group, TQ3GroupPosition position, TQ3Object* object)
{
    return getValue<Group>(__func__, group, "group", object, "object", [&](const Group& source) {
        return Ref<SharedObject>::retain(&source.objectAt(position)).detach();
    });
}

TQ3Status Q3Group_SetPositionObject(TQ3GroupObject group, TQ3GroupPosition position, TQ3Object object)
{
    using Method = TQ3XGroupSetPositionObjectMethod;
    return guard(__func__, kQ3Failure, [&] {
        Group& target = lookup<Group>(group, "group");
        if (const auto done = byClass<Method>(target, kQ3XMethodType_GroupSetPositionObject,
                                              [&](Method m) { return m(group, position, object); }))
            return *done;
        target.setObjectAt(position, member(object));
        return kQ3Success;
    });
}

TQ3Object Q3Group_RemovePosition(TQ3GroupObject group, TQ3GroupPosition position)
{
    using Method = TQ3XGroupRemovePositionMethod;
    return replaceable<Method, TQ3Object>(
        __func__, group, kQ3XMethodType_GroupRemovePosition, [&](Method m) { return m(group, position); },
        [&](Group& g) -> TQ3Object { return g.remove(position).detach(); });
}

// The calls without a type are the OfType calls for kQ3ObjectTypeShared
// (every object in a group is one): a class's OfType method answers both.

TQ3Status Q3Group_GetFirstPosition(TQ3GroupObject group, TQ3GroupPosition* position)
{
    return walkOfType<TQ3XGroupGetFirstPositionOfTypeMethod>(
        __func__, group, kQ3ObjectTypeShared, position, kQ3XMethodType_GroupGetFirstPositionOfType,
        [&](const Group& g) { return g.first(); });
}

TQ3Status Q3Group_GetLastPosition(TQ3GroupObject group, TQ3GroupPosition* position)
{
    return walkOfType<TQ3XGroupGetLastPositionOfTypeMethod>(
        __func__, group, kQ3ObjectTypeShared, position, kQ3XMethodType_GroupGetLastPositionOfType,
        [&](const Group& g) { return g.last(); });
}

TQ3Status Q3Group_GetNextPosition(TQ3GroupObject group, TQ3GroupPosition* position)
{
    return walkOfType<TQ3XGroupGetNextPositionOfTypeMethod>(
        __func__, group, kQ3ObjectTypeShared, position, kQ3XMethodType_GroupGetNextPositionOfType,
        [&](const Group& g) { return g.next(*position); });
}

TQ3Status Q3Group_GetPreviousPosition(TQ3GroupObject group, TQ3GroupPosition* position)
{
    return walkOfType<TQ3XGroupGetPrevPositionOfTypeMethod>(
        __func__, group, kQ3ObjectTypeShared, position, kQ3XMethodType_GroupGetPrevPositionOfType,
        [&](const Group& g) { return g.previous(*position); });
}

TQ3Status Q3Group_CountObjects(TQ3GroupObject group, unsigned long* nObjects)
{
    return countOfType(__func__, group, kQ3ObjectTypeShared, kQ3ObjectTypeInvalid, nObjects);
}

TQ3Status Q3Group_CountObjectsOfType(TQ3GroupObject group, TQ3ObjectType isType, unsigned long* nObjects)
{
    return countOfType(__func__, group, isType, isType, nObjects);
}

TQ3Status Q3Group_EmptyObjects(TQ3GroupObject group)
{
    return emptyOfType(__func__, group, kQ3ObjectTypeShared, kQ3ObjectTypeInvalid);
}

TQ3Status Q3Group_EmptyObjectsOfType(TQ3GroupObject group, TQ3ObjectType isType)
{
    return emptyOfType(__func__, group, isType, isType);
}

TQ3Status Q3Group_GetFirstPositionOfType(TQ3GroupObject group, TQ3ObjectType isType, TQ3GroupPosition* position)
{
    return walkOfType<TQ3XGroupGetFirstPositionOfTypeMethod>(__func__, group, isType, position,
                                                             kQ3XMethodType_GroupGetFirstPositionOfType,
                                                             [&](const Group& g) { return g.first(isType); });
}

TQ3Status Q3Group_GetLastPositionOfType(TQ3GroupObject group, TQ3ObjectType isType, TQ3GroupPosition* position)
{
    return walkOfType<TQ3XGroupGetLastPositionOfTypeMethod>(__func__, group, isType, position,
                                                            kQ3XMethodType_GroupGetLastPositionOfType,
                                                            [&](const Group& g) { return g.last(isType); });
}

TQ3Status Q3Group_GetNextPositionOfType(TQ3GroupObject group, TQ3ObjectType isType, TQ3GroupPosition* position)
{
    return walkOfType<TQ3XGroupGetNextPositionOfTypeMethod>(
        __func__, group, isType, position, kQ3XMethodType_GroupGetNextPositionOfType,
        [&](const Group& g) { return g.next(*position, isType); });
}

TQ3Status Q3Group_GetPreviousPositionOfType(TQ3GroupObject group, TQ3ObjectType isType,
                                            TQ3GroupPosition* position)
{
    return walkOfType<TQ3XGroupGetPrevPositionOfTypeMethod>(
        __func__, group, isType, position, kQ3XMethodType_GroupGetPrevPositionOfType,
        [&](const Group& g) { return g.previous(*position, isType); });
}

TQ3Status Q3Group_GetFirstObjectPosition(TQ3GroupObject group, TQ3Object object, TQ3GroupPosition* position)
{
    return walkOfObject<TQ3XGroupGetFirstObjectPositionMethod>(
        __func__, group, object, position, kQ3XMethodType_GroupGetFirstObjectPosition,
        [&](const Group& g, const Object& o) { return g.firstOf(o); });
}

TQ3Status Q3Group_GetLastObjectPosition(TQ3GroupObject group, TQ3Object object, TQ3GroupPosition* position)
{
    return walkOfObject<TQ3XGroupGetLastObjectPositionMethod>(
        __func__, group, object, position, kQ3XMethodType_GroupGetLastObjectPosition,
        [&](const Group& g, const Object& o) { return g.lastOf(o); });
}

TQ3Status Q3Group_GetNextObjectPosition(TQ3GroupObject group, TQ3Object object, TQ3GroupPosition* position)
{
    return walkOfObject<TQ3XGroupGetNextObjectPositionMethod>(
        __func__, group, object, position, kQ3XMethodType_GroupGetNextObjectPosition,
        [&](const Group& g, const Object& o) { return g.nextOf(*position, o); });
}

TQ3Status Q3Group_GetPreviousObjectPosition(TQ3GroupObject group, TQ3Object object, TQ3GroupPosition* position)
{
    return walkOfObject<TQ3XGroupGetPrevObjectPositionMethod>(
        __func__, group, object, position, kQ3XMethodType_GroupGetPrevObjectPosition,
        [&](const Group& g, const Object& o) { return g.previousOf(*position, o); });
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

void* Q3XGroup_GetPositionPrivate(TQ3GroupObject group, TQ3GroupPosition position)
{
    return guard(__func__, static_cast<void*>(nullptr),
                 [&] { return positionPrivate(lookup<Group>(group, "group"), position); });
}

} // extern "C"
