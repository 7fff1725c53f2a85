// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The API fuzzer's operations on groups.

#include "FuzzSession.h"

#include <cstdint>
#include <cstdio>

namespace q3fuzz {

namespace {

// Group classes (QD3DGroup.h): one per group class Q3 defines, registered
// the first time a group of it is asked for and kept for the process. Their
// methods check that each position's block goes through new, copy and
// delete exactly as documented; a broken block is remembered and reported.
constexpr std::uint32_t kLive = 0x51334750, kDeleted = 0xDEADDEAD;
struct FuzzPosition {
    std::uint32_t state;
    std::uint32_t copies;
};
thread_local bool t_badBlock = false;

TQ3Status fuzzPositionNew(void* gPos, TQ3Object, const void*)
{
    auto* block = static_cast<FuzzPosition*>(gPos);
    t_badBlock |= block->state != 0 || block->copies != 0; // Q3 hands out zeroed blocks
    block->state = kLive;
    return kQ3Success;
}

TQ3Status fuzzPositionCopy(void* srcGPos, void* dstGPos)
{
    auto* from = static_cast<FuzzPosition*>(srcGPos);
    auto* to = static_cast<FuzzPosition*>(dstGPos);
    t_badBlock |= from->state != kLive || to->state != 0;
    *to = *from;
    ++to->copies;
    return kQ3Success;
}

void fuzzPositionDelete(void* gPos)
{
    auto* block = static_cast<FuzzPosition*>(gPos);
    t_badBlock |= block->state != kLive;
    block->state = kDeleted;
}

// Refuses boxes, whatever the parent would say.
TQ3Boolean fuzzAccept(TQ3GroupObject, TQ3Object object)
{
    return Q3Object_IsType(object, kQ3GeometryTypeBox) == kQ3True ? kQ3False : kQ3True;
}

// Draws the group's objects in order, through its positions.
TQ3Status fuzzStartIterate(TQ3GroupObject group, TQ3GroupPosition* iterator, TQ3Object* object, TQ3ViewObject)
{
    *object = nullptr;
    if (Q3Group_GetFirstPosition(group, iterator) != kQ3Success || *iterator == nullptr)
        return kQ3Success;
    return Q3Group_GetPositionObject(group, *iterator, object);
}

TQ3Status fuzzEndIterate(TQ3GroupObject group, TQ3GroupPosition* iterator, TQ3Object* object, TQ3ViewObject)
{
    Q3Object_Dispose(*object);
    *object = nullptr;
    if (Q3Group_GetNextPosition(group, iterator) != kQ3Success || *iterator == nullptr)
        return kQ3Success;
    return Q3Group_GetPositionObject(group, *iterator, object);
}

TQ3XFunctionPointer fuzzGroupMetaHandler(TQ3XMethodType type)
{
    switch (type) {
    case kQ3XMethodType_GroupPositionSize:
        return reinterpret_cast<TQ3XFunctionPointer>(static_cast<std::uintptr_t>(sizeof(FuzzPosition)));
    case kQ3XMethodType_GroupPositionNew: return reinterpret_cast<TQ3XFunctionPointer>(&fuzzPositionNew);
    case kQ3XMethodType_GroupPositionCopy: return reinterpret_cast<TQ3XFunctionPointer>(&fuzzPositionCopy);
    case kQ3XMethodType_GroupPositionDelete: return reinterpret_cast<TQ3XFunctionPointer>(&fuzzPositionDelete);
    case kQ3XMethodType_GroupAcceptObject: return reinterpret_cast<TQ3XFunctionPointer>(&fuzzAccept);
    case kQ3XMethodType_GroupStartIterate: return reinterpret_cast<TQ3XFunctionPointer>(&fuzzStartIterate);
    case kQ3XMethodType_GroupEndIterate: return reinterpret_cast<TQ3XFunctionPointer>(&fuzzEndIterate);
    default: return nullptr;
    }
}

// The class registered under parents[index], or null (not initialized).
TQ3XObjectClass fuzzGroupClass(unsigned index)
{
    static const TQ3ObjectType kParents[] = {kQ3ShapeTypeGroup,         kQ3GroupTypeDisplay,
                                             kQ3DisplayGroupTypeOrdered, kQ3DisplayGroupTypeIOProxy,
                                             kQ3GroupTypeLight,         kQ3GroupTypeInfo};
    static TQ3XObjectClass s_classes[6] = {};
    index %= 6;
    if (s_classes[index] == nullptr) {
        char name[32];
        std::snprintf(name, sizeof name, "Fuzz:Group%u", index);
        TQ3ObjectType type = 0;
        s_classes[index] =
            Q3XObjectHierarchy_RegisterClass(kParents[index], &type, name, fuzzGroupMetaHandler, nullptr, 0, 0);
    }
    return s_classes[index];
}

} // namespace

std::vector<TQ3Object> Session::objectsOf(TQ3Object group)
{
    const Posts saved = g_posts;
    std::vector<TQ3Object> objects;
    TQ3GroupPosition position = nullptr;
    if (Q3Object_IsType(group, kQ3ShapeTypeGroup) == kQ3True)
        Q3Group_GetFirstPosition(group, &position);
    while (position != nullptr && objects.size() <= kMaxGroupReach) {
        TQ3Object object = nullptr;
        if (Q3Group_GetPositionObject(group, position, &object) != kQ3Success)
            break;
        objects.push_back(object);
        Q3Object_Dispose(object);
        if (Q3Group_GetNextPosition(group, &position) != kQ3Success)
            break;
    }
    g_posts = saved;
    return objects;
}

bool Session::groupIsSmall(TQ3Object group)
{
    unsigned long met = 0, lines = 0;
    std::vector<TQ3Object> pending{group};
    while (!pending.empty()) {
        const TQ3Object current = pending.back();
        pending.pop_back();
        for (TQ3Object object : objectsOf(current)) {
            if (++met > kMaxGroupReach)
                return false;
            const Posts saved = g_posts;
            if (Q3Object_IsType(object, kQ3ShapeTypeGroup) == kQ3True)
                pending.push_back(object);
            else if (Q3Object_IsType(object, kQ3GeometryTypeNURBCurve) == kQ3True ||
                     Q3Object_IsType(object, kQ3GeometryTypePolyLine) == kQ3True)
                ++lines;
            g_posts = saved;
            if (lines > 1)
                return false;
        }
    }
    return true;
}

TQ3GroupPosition Session::positionIn(TQ3Object group)
{
    const std::uint8_t how = m_in.u8();
    if (how < 200 && holdsKind(group, Kind::kGroup)) {
        TQ3GroupPosition position = nullptr;
        const Posts saved = g_posts;
        Q3Group_GetFirstPosition(group, &position);
        for (int steps = m_in.u8() % 16; steps > 0 && position != nullptr; --steps) {
            TQ3GroupPosition next = position;
            Q3Group_GetNextPosition(group, &next);
            if (next == nullptr)
                break;
            position = next;
        }
        g_posts = saved;
        if (position != nullptr && m_positions.size() < 64)
            m_positions.push_back(position);
        return position;
    }
    if (how < 230 && !m_positions.empty())
        return m_positions[m_in.u8() % m_positions.size()]; // perhaps removed, perhaps another group's
    if (how < 245)
        return nullptr;
    static unsigned char neverAPosition[32];
    return reinterpret_cast<TQ3GroupPosition>(neverAPosition + 8 * (m_in.u8() % 4));
}

TQ3ObjectType Session::typeToCount()
{
    static const TQ3ObjectType kTypes[] = {kQ3ObjectTypeInvalid,  kQ3ShapeTypeGeometry,    kQ3GeometryTypePoint,
                                           kQ3ShapeTypeTransform, kQ3ShapeTypeStyle,       kQ3SetTypeAttribute,
                                           kQ3ShapeTypeGroup,     kQ3GroupTypeDisplay,     kQ3SharedTypeShape,
                                           kQ3ShapeTypeLight,     kQ3ShapeTypeStateOperator};
    const std::uint8_t which = m_in.u8();
    return which < 250 ? kTypes[which % 11] : TQ3ObjectType(m_in.u32());
}

void Session::checkGroup(TQ3Object group)
{
    if (!holdsKind(group, Kind::kGroup) || Q3Object_IsType(group, kQ3ShapeTypeGroup) != kQ3True)
        return;
    const std::vector<TQ3Object> forward = objectsOf(group);
    if (forward.size() > kMaxGroupReach)
        return;
    std::vector<TQ3Object> backward;
    TQ3GroupPosition position = nullptr;
    STATUS(Q3Group_GetLastPosition(group, &position));
    while (position != nullptr) {
        TQ3Object object = nullptr;
        STATUS(Q3Group_GetPositionObject(group, position, &object));
        backward.insert(backward.begin(), object);
        STATUS(Q3Object_Dispose(object));
        STATUS(Q3Group_GetPreviousPosition(group, &position));
    }
    unsigned long count = 0;
    STATUS(Q3Group_CountObjects(group, &count));
    require(forward == backward && count == forward.size(), "Q3Group_GetNextPosition",
            "walking forwards and backwards and counting disagree");
    const TQ3ObjectType type = typeToCount();
    unsigned long ofType = 0, walked = 0;
    if (STATUS(Q3Group_CountObjectsOfType(group, type, &ofType)) == kQ3Success) {
        STATUS(Q3Group_GetFirstPositionOfType(group, type, &position));
        while (position != nullptr && walked <= count) {
            ++walked;
            STATUS(Q3Group_GetNextPositionOfType(group, type, &position));
        }
        require(walked == ofType, "Q3Group_CountObjectsOfType", "disagrees with walking that type");
    }
}

void Session::groups()
{
    const std::uint8_t action = m_in.u8() % 11;
    require(!t_badBlock, "a group class's position methods", "a position block was not made, copied or deleted once");
    const TQ3Object group = pick(Kind::kGroup);
    switch (action) {
    case 0: {
        TQ3Object made = nullptr;
        switch (m_in.u8() % 9) {
        case 8: {
            // Registration (outside the call checked) fails only before
            // Q3Initialize; the new object must come then.
            const Posts saved = g_posts;
            const TQ3XObjectClass groupClass = fuzzGroupClass(m_in.u8());
            g_posts = saved;
            made = OBJECT(Q3XObjectHierarchy_NewObject(groupClass, nullptr));
            require((made != nullptr) == (groupClass != nullptr && m_initialized != 0),
                    "Q3XObjectHierarchy_NewObject", "a registered group class made no group");
            break;
        }
        case 0: made = OBJECT(Q3Group_New()); break;
        case 1: made = OBJECT(Q3DisplayGroup_New()); break;
        case 2: made = OBJECT(Q3OrderedDisplayGroup_New()); break;
        case 3: made = OBJECT(Q3IOProxyDisplayGroup_New()); break;
        case 4: made = OBJECT(Q3LightGroup_New()); break;
        case 5: made = OBJECT(Q3InfoGroup_New()); break;
        case 6: made = OBJECT(Q3Push_New()); break;
        default: made = OBJECT(Q3Pop_New()); break;
        }
        if (made != nullptr)
            hold(made, Kind::kGroup);
        break;
    }
    case 1: {
        const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
        const std::uint8_t where = m_in.u8() % 3;
        const TQ3GroupPosition position = where == 0 ? nullptr : positionIn(group);
        if (holdsKind(group, Kind::kGroup) && objectsOf(group).size() >= kMaxGroupSize)
            return;
        TQ3GroupPosition added = nullptr;
        if (where == 0)
            added = POINTER(Q3Group_AddObject(group, object));
        else if (where == 1)
            added = POINTER(Q3Group_AddObjectBefore(group, position, object));
        else
            added = POINTER(Q3Group_AddObjectAfter(group, position, object));
        require(added == nullptr || object != group, "Q3Group_AddObject", "a group took itself");
        checkGroup(group);
        break;
    }
    case 2: {
        const TQ3GroupPosition position = positionIn(group);
        const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
        const TQ3Status status = STATUS(Q3Group_SetPositionObject(group, position, object));
        require(status == kQ3Failure || object != group, "Q3Group_SetPositionObject", "a group took itself");
        checkGroup(group);
        break;
    }
    case 3: {
        // Remove positions while walking: every `stride`-th, taking the
        // next position first (as the header says to).
        const unsigned stride = 1 + m_in.u8() % 4;
        if (!holdsKind(group, Kind::kGroup)) {
            const TQ3Object removed = OBJECT(Q3Group_RemovePosition(group, positionIn(group)));
            if (removed != nullptr)
                STATUS(Q3Object_Dispose(removed));
        }
        TQ3GroupPosition position = nullptr;
        if (holdsKind(group, Kind::kGroup) && STATUS(Q3Group_GetFirstPosition(group, &position)) == kQ3Success)
            for (unsigned index = 0; position != nullptr; ++index) {
                TQ3GroupPosition next = position;
                STATUS(Q3Group_GetNextPosition(group, &next));
                if (index % stride == 0) {
                    const TQ3Object removed = OBJECT(Q3Group_RemovePosition(group, position));
                    if (removed != nullptr)
                        STATUS(Q3Object_Dispose(removed));
                }
                position = next;
            }
        checkGroup(group);
        break;
    }
    case 4: checkGroup(group); break;
    case 10: {
        // A block of the class's, or none (Q3's classes keep none).
        const auto* block = static_cast<const FuzzPosition*>(POINTER(Q3XGroup_GetPositionPrivate(group, positionIn(group))));
        require(block == nullptr || block->state == kLive, "Q3XGroup_GetPositionPrivate", "a block not made by the new method");
        break;
    }
    case 5: {
        const TQ3ObjectType type = typeToCount();
        if (m_in.u8() & 1)
            STATUS(Q3Group_EmptyObjectsOfType(group, type));
        else
            STATUS(Q3Group_EmptyObjects(group));
        checkGroup(group);
        break;
    }
    case 6: {
        TQ3DisplayGroupState state = 0;
        const std::uint8_t which = m_in.u8() % 5;
        TQ3BoundingBox box{point3(), point3(), (m_in.u8() & 1) ? kQ3True : kQ3False};
        if (which == 0)
            STATUS(Q3DisplayGroup_SetState(group, m_in.u8()));
        else if (which == 1)
            STATUS(Q3DisplayGroup_GetState(group, &state));
        else if (which == 2)
            STATUS(Q3DisplayGroup_SetAndUseBoundingBox(group, &box));
        else if (which == 3)
            STATUS(Q3DisplayGroup_GetBoundingBox(group, &box));
        else
            STATUS(Q3DisplayGroup_RemoveBoundingBox(group));
        break;
    }
    case 7: {
        const TQ3Object view = pick(Kind::kView);
        if (!groupIsSmall(group) || !drawAllowed())
            return;
        const DrawTimer timer(m_drawSeconds);
        if (m_in.u8() & 1)
            STATUS(Q3DisplayGroup_Submit(group, view));
        else
            STATUS(Q3StateOperator_Submit(group, view));
        break;
    }
    case 8: {
        const TQ3Object view = pick(Kind::kView);
        // Through C: any int, a value outside TQ3ComputeBounds included
        // (which C++ may not even hold in the enum).
        const int bounds = enumValue(2);
        if (!groupIsSmall(group) || !drawAllowed())
            return;
        const DrawTimer timer(m_drawSeconds);
        STATUS(q3fuzz_CalcAndUseBoundingBox(group, bounds, view));
        break;
    }
    default: {
        // Every position of one object, forwards or backwards.
        const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
        const bool forwards = m_in.u8() & 1;
        TQ3GroupPosition position = nullptr;
        TQ3Status status = forwards ? STATUS(Q3Group_GetFirstObjectPosition(group, object, &position))
                                    : STATUS(Q3Group_GetLastObjectPosition(group, object, &position));
        for (unsigned long n = 0; status == kQ3Success && position != nullptr; ++n) {
            require(n <= kMaxGroupReach, "Q3Group_GetNextObjectPosition", "walked more positions than objects");
            TQ3Object there = nullptr;
            STATUS(Q3Group_GetPositionObject(group, position, &there));
            require(there == object, "Q3Group_GetFirstObjectPosition", "a position of another object");
            STATUS(Q3Object_Dispose(there));
            status = forwards ? STATUS(Q3Group_GetNextObjectPosition(group, object, &position))
                              : STATUS(Q3Group_GetPreviousObjectPosition(group, object, &position));
        }
        break;
    }
    }
}

} // namespace q3fuzz
