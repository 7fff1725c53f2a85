// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGroup.h"
#include "core/Object.h"

#include <cstddef>
#include <list>
#include <memory>
#include <optional>
#include <unordered_set>
#include <vector>

/// The C position type. A position is a node of a group's list; the group
/// checks that a position it is given is one of its own live nodes before
/// it reads anything behind it.
struct OpaqueTQ3GroupPosition {
protected:
    OpaqueTQ3GroupPosition() = default;
};

namespace q3 {

extern const ClassInfo kGroupClass;
extern const ClassInfo kDisplayGroupClass;
extern const ClassInfo kOrderedDisplayGroupClass;
extern const ClassInfo kIOProxyDisplayGroupClass;
extern const ClassInfo kLightGroupClass;
extern const ClassInfo kInfoGroupClass;

/// A QuickDraw 3D group (QD3DGroup.h): an ordered list of shared objects,
/// each held by one reference, addressed by positions. Invariant: every node
/// holds a live object the group accepts; m_live holds exactly the nodes of
/// m_nodes; no group contains itself, directly or through other groups.
class Group : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapeTypeGroup;

    struct Node : OpaqueTQ3GroupPosition {
        explicit Node(Ref<SharedObject> o) : object(std::move(o)) {}
        Ref<SharedObject> object;
        std::list<Node>::iterator self; ///< where the node is in its list
        /// The position's private data, for a group class an application
        /// registered with kQ3XMethodType_GroupPositionSize (else null).
        std::unique_ptr<unsigned char[]> privateData;
    };

    Group() = default;
    ~Group() override;

    const ClassInfo& classInfo() const override;
    Object* duplicate() const override;

    /// Whether the group may hold the object (kQ3ErrorInvalidObjectForGroup
    /// otherwise): any shared object for a plain group, drawables and shapes
    /// for display groups, lights for light groups, strings for info groups.
    virtual bool accepts(const Object& object) const;

    /// Adds at the end (an ordered display group: at the end of the object's
    /// kind). Throws kQ3ErrorInvalidObjectForGroup for an object the group
    /// does not accept or one that contains the group (a cycle).
    TQ3GroupPosition add(Ref<SharedObject> object);
    /// Adds before / after `position` (kQ3ErrorInvalidPositionForGroup unless
    /// it is one of this group's; an ordered group also refuses with
    /// kQ3ErrorInvalidObjectForPosition a position of another kind).
    TQ3GroupPosition addBefore(TQ3GroupPosition position, Ref<SharedObject> object);
    TQ3GroupPosition addAfter(TQ3GroupPosition position, Ref<SharedObject> object);

    SharedObject& objectAt(TQ3GroupPosition position) const;
    /// Replaces the object at position; the group's rules as for add.
    void setObjectAt(TQ3GroupPosition position, Ref<SharedObject> object);
    /// Removes the position and hands back the group's reference.
    Ref<SharedObject> remove(TQ3GroupPosition position);

    /// First, last, next and previous positions, optionally only those
    /// whose object is of `type` (or a subclass of it), or holds `object`:
    /// null when there is none. next/previous throw
    /// kQ3ErrorInvalidPositionForGroup for a position not of this group.
    TQ3GroupPosition first(TQ3ObjectType type = kQ3ObjectTypeInvalid) const;
    TQ3GroupPosition last(TQ3ObjectType type = kQ3ObjectTypeInvalid) const;
    TQ3GroupPosition next(TQ3GroupPosition position, TQ3ObjectType type = kQ3ObjectTypeInvalid) const;
    TQ3GroupPosition previous(TQ3GroupPosition position, TQ3ObjectType type = kQ3ObjectTypeInvalid) const;
    TQ3GroupPosition firstOf(const Object& object) const;
    TQ3GroupPosition lastOf(const Object& object) const;
    TQ3GroupPosition nextOf(TQ3GroupPosition position, const Object& object) const;
    TQ3GroupPosition previousOf(TQ3GroupPosition position, const Object& object) const;

    std::size_t count(TQ3ObjectType type = kQ3ObjectTypeInvalid) const;
    /// Removes every object (of `type`, when one is given).
    void empty(TQ3ObjectType type = kQ3ObjectTypeInvalid);

    const std::list<Node>& nodes() const { return m_nodes; }
    /// Objects a file gave the group beside its state that Q3 has no class
    /// for (an element such as Apple's name element, read as an unknown
    /// object), in file order: kept, shared by duplicates, written back.
    const std::vector<Ref<SharedObject>>& otherElements() const { return m_others; }
    void addOtherElement(Ref<SharedObject> element) { m_others.push_back(std::move(element)); }
    /// Whether `object` is this group or inside it, at any depth.
    bool reaches(const Object& object) const;
    /// The node a position names; kQ3ErrorInvalidPositionForGroup unless it
    /// is one of this group's.
    Node& nodeAt(TQ3GroupPosition position) { return *find(position); }
    /// Whether the position is one of this group's.
    bool owns(TQ3GroupPosition position) const { return m_live.count(position) != 0; }

    /// Called when a file has given the group all its objects (a group class
    /// an application registered validates itself then).
    virtual void endRead() {}

protected:
    /// A position was made (`node` holds its object, already in the list),
    /// is about to go, or was copied from another group's in a duplicate.
    /// A group class an application registers keeps its position data so;
    /// positionAdded may throw (the position is taken out again).
    virtual void positionAdded(Node&) {}
    virtual void positionRemoving(Node&) noexcept {}
    virtual void positionCopied(const Node&, Node&) {}
    /// Where a new object of this kind goes when added without a position.
    virtual std::list<Node>::iterator insertionPoint(const Object& object);
    /// Whether object may stand at `where` (ordered groups check its kind).
    virtual void checkPlace(std::list<Node>::const_iterator where, const Object& object, bool before) const;
    /// Copies the nodes of `source` (each object duplicated) into this group.
    void copyFrom(const Group& source);

private:
    std::list<Node>::iterator find(TQ3GroupPosition position);
    std::list<Node>::const_iterator find(TQ3GroupPosition position) const;
    void check(const Object& object) const;
    TQ3GroupPosition insert(std::list<Node>::iterator where, Ref<SharedObject> object);

    std::list<Node> m_nodes;
    std::unordered_set<const OpaqueTQ3GroupPosition*> m_live;
    std::vector<Ref<SharedObject>> m_others;
};

/// A group that may be drawn: submitting it submits its objects in order,
/// with the graphics state pushed before and popped after unless it is
/// inline. Invariant: the state is a combination of
/// TQ3DisplayGroupStateMasks; the bounding box is used only when one is set.
class DisplayGroup : public Group {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GroupTypeDisplay;

    const ClassInfo& classInfo() const override;
    Object* duplicate() const override;
    bool isDrawable() const override { return true; }
    void accept(ShapeVisitor& visitor) const override;
    bool accepts(const Object& object) const override;

    TQ3DisplayGroupState state() const { return m_state; }
    void setState(TQ3DisplayGroupState state);
    /// The box set by setBoundingBox (or CalcAndUse), if any.
    const std::optional<TQ3BoundingBox>& boundingBox() const { return m_box; }
    /// Sets the box and turns kQ3DisplayGroupStateMaskUseBoundingBox on;
    /// kQ3ErrorInvalidParameter for a box (not marked empty) with a
    /// non-finite corner or min above max. An empty box bounds nothing.
    void setBoundingBox(const TQ3BoundingBox& box);
    void removeBoundingBox();

    /// Submits the objects the group draws (an I/O proxy: the first it
    /// can), without the group's own handling (its state, its box, the
    /// push and pop around it): what Q3DisplayGroup_CalcAndUseBoundingBox
    /// bounds.
    virtual void submitContents(ShapeVisitor& visitor) const;

protected:
    /// Copies another display group's objects (duplicated), state and box.
    void copyDisplayGroup(const DisplayGroup& source);

private:
    TQ3DisplayGroupState m_state = kQ3DisplayGroupStateMaskIsDrawn | kQ3DisplayGroupStateMaskUseBoundingBox |
                                   kQ3DisplayGroupStateMaskUseBoundingSphere | kQ3DisplayGroupStateMaskIsPicked |
                                   kQ3DisplayGroupStateMaskIsWritten;
    std::optional<TQ3BoundingBox> m_box;
};

/// A display group kept in QuickDraw 3D's order of kinds: transforms,
/// styles, attribute sets, shaders, cameras, lights, geometries, groups,
/// unknown objects (QD3DGroup.h); within a kind, in the order added.
class OrderedDisplayGroup : public DisplayGroup {
public:
    static constexpr TQ3ObjectType kClassType = kQ3DisplayGroupTypeOrdered;

    const ClassInfo& classInfo() const override;
    Object* duplicate() const override;

    /// The object's rank in the order (1 transforms ... 9 unknown, 10 other).
    static int rank(const Object& object);

protected:
    std::list<Node>::iterator insertionPoint(const Object& object) override;
    void checkPlace(std::list<Node>::const_iterator where, const Object& object, bool before) const override;
};

/// Alternative representations of one object, the most preferred first:
/// drawing uses the first that is not an unknown object.
class IOProxyDisplayGroup : public DisplayGroup {
public:
    static constexpr TQ3ObjectType kClassType = kQ3DisplayGroupTypeIOProxy;

    const ClassInfo& classInfo() const override;
    Object* duplicate() const override;
    void submitContents(ShapeVisitor& visitor) const override;
};

/// The lights a view is lit by (Q3View_SetLightGroup). Holds lights only.
class LightGroup : public Group {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GroupTypeLight;

    const ClassInfo& classInfo() const override;
    Object* duplicate() const override;
    bool accepts(const Object& object) const override;
};

/// Strings describing a model. Holds string objects only.
class InfoGroup : public Group {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GroupTypeInfo;

    const ClassInfo& classInfo() const override;
    Object* duplicate() const override;
    bool accepts(const Object& object) const override;
};

} // namespace q3
