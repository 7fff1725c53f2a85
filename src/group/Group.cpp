// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "group/Group.h"

#include "core/EnumValue.h"
#include "core/Limits.h"
#include "core/ShapeVisitor.h"
#include "core/ThreadLocal.h"

#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

namespace q3 {

const ClassInfo kGroupClass{kQ3ShapeTypeGroup, &kShapeClass, "group"};
const ClassInfo kDisplayGroupClass{kQ3GroupTypeDisplay, &kGroupClass, "display group"};
const ClassInfo kOrderedDisplayGroupClass{kQ3DisplayGroupTypeOrdered, &kDisplayGroupClass, "ordered display group"};
const ClassInfo kIOProxyDisplayGroupClass{kQ3DisplayGroupTypeIOProxy, &kDisplayGroupClass,
                                          "I/O proxy display group"};
const ClassInfo kLightGroupClass{kQ3GroupTypeLight, &kGroupClass, "light group"};
const ClassInfo kInfoGroupClass{kQ3GroupTypeInfo, &kGroupClass, "info group"};

namespace {

bool matches(const Object& object, TQ3ObjectType type)
{
    return type == kQ3ObjectTypeInvalid || object.isType(type);
}

} // namespace

// ---- Group ------------------------------------------------------------------

Group::~Group()
{
    // A group may hold the last reference to a group holding the last
    // reference to another, and so on, as deep as a caller builds. Releasing
    // them recursively could exhaust the stack, so the outermost group being
    // destroyed on a thread releases everything below it in a loop instead.
    struct PendingTag;
    std::vector<Ref<SharedObject>>& pending = threadLocal<std::vector<Ref<SharedObject>>, PendingTag>();
    thread_local bool draining = false;
    for (Node& node : m_nodes)
        pending.push_back(std::move(node.object));
    m_nodes.clear();
    m_live.clear();
    if (draining)
        return;
    draining = true;
    while (!pending.empty()) {
        Ref<SharedObject> object = std::move(pending.back());
        pending.pop_back();
        object.reset();
    }
    draining = false;
}

const ClassInfo& Group::classInfo() const
{
    return kGroupClass;
}

Object* Group::duplicate() const
{
    Ref<Group> copy = makeShared<Group>();
    copy->copyFrom(*this);
    return copy.detach();
}

void Group::copyFrom(const Group& source)
{
    // Duplicating a group duplicates its groups in turn; past the nesting
    // limit (the one drawing enforces) that recursion stops with an error.
    // Within one duplication an object met twice (a subgroup shared by two
    // parents, or one object at two positions) is copied once, so the copy
    // has the original's sharing and the work stays proportional to the
    // number of distinct objects, not to the number of paths to them.
    thread_local std::size_t depth = 0;
    thread_local std::unordered_map<const SharedObject*, Ref<SharedObject>>* copies = nullptr;
    if (depth >= limits::kMaxGroupNesting)
        fail(kQ3ErrorInvalidObject, "groups nest deeper than kQ3GroupMaxNesting (" +
                                        std::to_string(limits::kMaxGroupNesting) + "): not duplicated");
    std::unordered_map<const SharedObject*, Ref<SharedObject>> outermost;
    if (depth == 0)
        copies = &outermost;
    ++depth;
    try {
        for (const Node& node : source.m_nodes) {
            Ref<SharedObject>& copy = (*copies)[node.object.get()];
            if (!copy)
                copy = Ref<SharedObject>::adopt(static_cast<SharedObject*>(node.object->clone()));
            auto it = m_nodes.emplace(m_nodes.end(), copy);
            it->self = it;
            m_live.insert(&*it);
            try {
                positionCopied(node, *it);
            } catch (...) {
                m_live.erase(&*it);
                m_nodes.erase(it);
                throw;
            }
        }
    } catch (...) {
        if (--depth == 0)
            copies = nullptr;
        throw;
    }
    if (--depth == 0)
        copies = nullptr;
    m_others = source.m_others;
}

bool Group::accepts(const Object& object) const
{
    return object.isType(kQ3ObjectTypeShared);
}

bool Group::reaches(const Object& object) const
{
    // Depth first over the groups below this one, each visited once (groups
    // may be shared by many parents).
    std::vector<const Group*> pending{this};
    std::unordered_set<const Group*> seen{this};
    while (!pending.empty()) {
        const Group* group = pending.back();
        pending.pop_back();
        if (group == &object)
            return true;
        for (const Node& node : group->m_nodes) {
            if (node.object.get() == &object)
                return true;
            if (node.object->isType(kQ3ShapeTypeGroup)) {
                const Group* child = static_cast<const Group*>(node.object.get());
                if (seen.insert(child).second)
                    pending.push_back(child);
            }
        }
    }
    return false;
}

void Group::check(const Object& object) const
{
    if (!accepts(object))
        fail(kQ3ErrorInvalidObjectForGroup, std::string("a ") + classInfo().name + " cannot hold a " +
                                                object.classInfo().name);
    if (object.isType(kQ3ShapeTypeGroup) && static_cast<const Group&>(object).reaches(*this))
        fail(kQ3ErrorInvalidObjectForGroup,
             "the group would contain itself (the object is the group, or a group that contains it)");
}

std::list<Group::Node>::iterator Group::insertionPoint(const Object&)
{
    return m_nodes.end();
}

void Group::checkPlace(std::list<Node>::const_iterator, const Object&, bool) const {}

std::list<Group::Node>::iterator Group::find(TQ3GroupPosition position)
{
    if (position == nullptr)
        fail(kQ3ErrorNULLParameter, "position is NULL");
    if (m_live.count(position) == 0)
        fail(kQ3ErrorInvalidPositionForGroup, "position is not a position of this group (removed, or another group's)");
    return static_cast<Node*>(position)->self;
}

std::list<Group::Node>::const_iterator Group::find(TQ3GroupPosition position) const
{
    return const_cast<Group*>(this)->find(position);
}

TQ3GroupPosition Group::insert(std::list<Node>::iterator where, Ref<SharedObject> object)
{
    auto it = m_nodes.emplace(where, std::move(object));
    it->self = it;
    m_live.insert(&*it);
    try {
        positionAdded(*it);
    } catch (...) {
        m_live.erase(&*it);
        m_nodes.erase(it);
        throw;
    }
    markEdited();
    return &*it;
}

TQ3GroupPosition Group::add(Ref<SharedObject> object)
{
    check(*object);
    // Separate statements: the order arguments are evaluated in is unspecified.
    const auto where = insertionPoint(*object);
    return insert(where, std::move(object));
}

TQ3GroupPosition Group::addBefore(TQ3GroupPosition position, Ref<SharedObject> object)
{
    const auto where = find(position);
    check(*object);
    checkPlace(where, *object, true);
    return insert(where, std::move(object));
}

TQ3GroupPosition Group::addAfter(TQ3GroupPosition position, Ref<SharedObject> object)
{
    const auto where = find(position);
    check(*object);
    checkPlace(where, *object, false);
    return insert(std::next(where), std::move(object));
}

SharedObject& Group::objectAt(TQ3GroupPosition position) const
{
    return *find(position)->object;
}

void Group::setObjectAt(TQ3GroupPosition position, Ref<SharedObject> object)
{
    const auto where = find(position);
    check(*object);
    checkPlace(where, *object, true);
    // The position stays, with its private data.
    where->object = std::move(object);
    markEdited();
}

Ref<SharedObject> Group::remove(TQ3GroupPosition position)
{
    const auto where = find(position);
    positionRemoving(*where);
    Ref<SharedObject> object = std::move(where->object);
    m_live.erase(&*where);
    m_nodes.erase(where);
    markEdited();
    return object;
}

TQ3GroupPosition Group::first(TQ3ObjectType type) const
{
    for (const Node& node : m_nodes)
        if (matches(*node.object, type))
            return const_cast<Node*>(&node);
    return nullptr;
}

TQ3GroupPosition Group::last(TQ3ObjectType type) const
{
    for (auto it = m_nodes.rbegin(); it != m_nodes.rend(); ++it)
        if (matches(*it->object, type))
            return const_cast<Node*>(&*it);
    return nullptr;
}

TQ3GroupPosition Group::next(TQ3GroupPosition position, TQ3ObjectType type) const
{
    for (auto it = std::next(find(position)); it != m_nodes.end(); ++it)
        if (matches(*it->object, type))
            return const_cast<Node*>(&*it);
    return nullptr;
}

TQ3GroupPosition Group::previous(TQ3GroupPosition position, TQ3ObjectType type) const
{
    auto it = find(position);
    while (it != m_nodes.begin()) {
        --it;
        if (matches(*it->object, type))
            return const_cast<Node*>(&*it);
    }
    return nullptr;
}

TQ3GroupPosition Group::firstOf(const Object& object) const
{
    for (const Node& node : m_nodes)
        if (node.object.get() == &object)
            return const_cast<Node*>(&node);
    return nullptr;
}

TQ3GroupPosition Group::lastOf(const Object& object) const
{
    for (auto it = m_nodes.rbegin(); it != m_nodes.rend(); ++it)
        if (it->object.get() == &object)
            return const_cast<Node*>(&*it);
    return nullptr;
}

TQ3GroupPosition Group::nextOf(TQ3GroupPosition position, const Object& object) const
{
    for (auto it = std::next(find(position)); it != m_nodes.end(); ++it)
        if (it->object.get() == &object)
            return const_cast<Node*>(&*it);
    return nullptr;
}

TQ3GroupPosition Group::previousOf(TQ3GroupPosition position, const Object& object) const
{
    auto it = find(position);
    while (it != m_nodes.begin()) {
        --it;
        if (it->object.get() == &object)
            return const_cast<Node*>(&*it);
    }
    return nullptr;
}

std::size_t Group::count(TQ3ObjectType type) const
{
    std::size_t n = 0;
    for (const Node& node : m_nodes)
        n += matches(*node.object, type);
    return n;
}

void Group::empty(TQ3ObjectType type)
{
    // Objects are released after the list is consistent again.
    std::vector<Ref<SharedObject>> released;
    for (auto it = m_nodes.begin(); it != m_nodes.end();) {
        if (matches(*it->object, type)) {
            positionRemoving(*it);
            released.push_back(std::move(it->object));
            m_live.erase(&*it);
            it = m_nodes.erase(it);
        } else {
            ++it;
        }
    }
    markEdited();
}

// ---- Display groups -------------------------------------------------------

const ClassInfo& DisplayGroup::classInfo() const
{
    return kDisplayGroupClass;
}

Object* DisplayGroup::duplicate() const
{
    Ref<DisplayGroup> copy = makeShared<DisplayGroup>();
    copy->copyDisplayGroup(*this);
    return copy.detach();
}

void DisplayGroup::copyDisplayGroup(const DisplayGroup& source)
{
    copyFrom(source);
    m_state = source.m_state;
    m_box = source.m_box;
}

bool DisplayGroup::accepts(const Object& object) const
{
    // Drawables, and the shapes an ordered group lists (lights and cameras
    // are accepted and do nothing when drawn, as in QuickDraw 3D).
    return object.isDrawable() || object.isType(kQ3SharedTypeShape);
}

void DisplayGroup::setState(TQ3DisplayGroupState state)
{
    m_state = state;
    markEdited();
}

void DisplayGroup::setBoundingBox(const TQ3BoundingBox& box)
{
    TQ3BoundingBox kept = box;
    if (enumValue(box.isEmpty) != kQ3False) {
        kept = TQ3BoundingBox{};
        kept.isEmpty = kQ3True;
    } else {
        const float values[6] = {box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z};
        for (float v : values)
            if (!std::isfinite(v))
                fail(kQ3ErrorInvalidParameter, "the bounding box has a corner that is not finite");
        if (box.min.x > box.max.x || box.min.y > box.max.y || box.min.z > box.max.z)
            fail(kQ3ErrorInvalidParameter, "the bounding box's min is above its max");
    }
    m_box = kept;
    m_state |= kQ3DisplayGroupStateMaskUseBoundingBox;
    markEdited();
}

void DisplayGroup::removeBoundingBox()
{
    m_box.reset();
    markEdited();
}

void DisplayGroup::accept(ShapeVisitor& visitor) const
{
    if (!visitor.beginGroup(*this))
        return;
    try {
        submitContents(visitor);
    } catch (...) {
        visitor.endGroup(*this);
        throw;
    }
    visitor.endGroup(*this);
}

void DisplayGroup::submitContents(ShapeVisitor& visitor) const
{
    for (const Node& node : nodes()) {
        const SharedObject& object = *node.object;
        // Lights, cameras and other shapes that are not drawable do nothing.
        if (object.isDrawable()) {
            visitor.atGroupPosition(const_cast<Node*>(&node));
            object.accept(visitor);
        }
    }
}

const ClassInfo& OrderedDisplayGroup::classInfo() const
{
    return kOrderedDisplayGroupClass;
}

Object* OrderedDisplayGroup::duplicate() const
{
    Ref<OrderedDisplayGroup> copy = makeShared<OrderedDisplayGroup>();
    copy->copyDisplayGroup(*this);
    return copy.detach();
}

int OrderedDisplayGroup::rank(const Object& object)
{
    static const TQ3ObjectType kOrder[] = {kQ3ShapeTypeTransform, kQ3ShapeTypeStyle,    kQ3SetTypeAttribute,
                                           kQ3ShapeTypeShader,    kQ3ShapeTypeCamera,   kQ3ShapeTypeLight,
                                           kQ3ShapeTypeGeometry,  kQ3ShapeTypeGroup,    kQ3ShapeTypeUnknown};
    for (int i = 0; i < 9; ++i)
        if (object.isType(kOrder[i]))
            return i + 1;
    return 10;
}

std::list<Group::Node>::iterator OrderedDisplayGroup::insertionPoint(const Object& object)
{
    // After the last object of the same or an earlier kind.
    const int r = rank(object);
    auto& list = const_cast<std::list<Node>&>(nodes());
    auto it = list.end();
    while (it != list.begin() && rank(*std::prev(it)->object) > r)
        --it;
    return it;
}

void OrderedDisplayGroup::checkPlace(std::list<Node>::const_iterator where, const Object& object, bool before) const
{
    // The new object must stay in order: not after a later kind, not before
    // an earlier one.
    const int r = rank(object);
    const int here = rank(*where->object);
    const bool fits = before ? (here >= r && (where == nodes().begin() || rank(*std::prev(where)->object) <= r))
                             : (here <= r && (std::next(where) == nodes().end() || rank(*std::next(where)->object) >= r));
    if (!fits)
        fail(kQ3ErrorInvalidObjectForPosition, std::string("a ") + object.classInfo().name +
                                                   " there would break the order of an ordered display group");
}

const ClassInfo& IOProxyDisplayGroup::classInfo() const
{
    return kIOProxyDisplayGroupClass;
}

Object* IOProxyDisplayGroup::duplicate() const
{
    Ref<IOProxyDisplayGroup> copy = makeShared<IOProxyDisplayGroup>();
    copy->copyDisplayGroup(*this);
    return copy.detach();
}

void IOProxyDisplayGroup::submitContents(ShapeVisitor& visitor) const
{
    for (const Node& node : nodes())
        if (!node.object->isType(kQ3ShapeTypeUnknown)) {
            if (node.object->isDrawable()) {
                visitor.atGroupPosition(const_cast<Node*>(&node));
                node.object->accept(visitor);
            }
            return;
        }
}

// ---- Light and info groups -------------------------------------------------

const ClassInfo& LightGroup::classInfo() const
{
    return kLightGroupClass;
}

Object* LightGroup::duplicate() const
{
    Ref<LightGroup> copy = makeShared<LightGroup>();
    copy->copyFrom(*this);
    return copy.detach();
}

bool LightGroup::accepts(const Object& object) const
{
    return object.isType(kQ3ShapeTypeLight);
}

const ClassInfo& InfoGroup::classInfo() const
{
    return kInfoGroupClass;
}

Object* InfoGroup::duplicate() const
{
    Ref<InfoGroup> copy = makeShared<InfoGroup>();
    copy->copyFrom(*this);
    return copy.detach();
}

bool InfoGroup::accepts(const Object& object) const
{
    return object.isType(kQ3SharedTypeString);
}

} // namespace q3
