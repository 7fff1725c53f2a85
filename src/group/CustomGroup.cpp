// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "group/CustomGroup.h"

#include "QD3DExtension.h"
#include "core/CustomObject.h"
#include "core/EnumValue.h"
#include "core/ShapeVisitor.h"

#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace q3 {

namespace {

// Bytes of private data a position may have: far above what a record of a
// few fields needs, and low enough that a class giving a garbage size is
// refused rather than allocating without bound.
constexpr std::size_t kMaxPositionSize = 1u << 16;

struct Running {
    const Group* group;
    TQ3XMethodType type;
};
thread_local std::vector<Running> t_running;

// A zeroed block (make_unique value-initializes its array), never of size
// 0, so a position's data always has an address.
std::unique_ptr<unsigned char[]> zeroed(std::size_t size)
{
    return std::make_unique<unsigned char[]>(size == 0 ? 1 : size);
}

template <class G, bool Display = std::is_base_of_v<DisplayGroup, G>>
class CustomGroupObjectOf;

/// A new group of the class, registered live, no method run yet.
template <class G>
CustomGroupObjectOf<G>* makeGroupOf(std::shared_ptr<CustomClass> leaf)
{
    auto* made = new CustomGroupObjectOf<G>(std::move(leaf));
    made->registerLive();
    return made;
}

/// A group of a class an application registered under G (a group class Q3
/// defines). Invariant: every node has private data exactly when the class
/// keeps any (a position size or a position new method), made by the
/// class's position methods and deleted by its delete method once.
template <class G>
class CustomGroupObject : public G, public CustomInstance {
public:
    explicit CustomGroupObject(std::shared_ptr<CustomClass> leaf) : CustomInstance(std::move(leaf))
    {
        const auto size = reinterpret_cast<std::uintptr_t>(customClass().method(kQ3XMethodType_GroupPositionSize));
        if (size > kMaxPositionSize)
            fail(kQ3ErrorInvalidParameter, "the class \"" + customClass().name() + "\" asks for " +
                                               std::to_string(size) +
                                               " bytes per group position (kQ3XMethodType_GroupPositionSize); Q3 "
                                               "gives at most " +
                                               std::to_string(kMaxPositionSize));
        m_positionSize = static_cast<std::size_t>(size);
        m_keepsPositionData = m_positionSize != 0 || customClass().method(kQ3XMethodType_GroupPositionNew) != nullptr;
    }

    ~CustomGroupObject() override
    {
        destroy(this);
        for (const Group::Node& node : this->nodes())
            positionRemoving(const_cast<Group::Node&>(node));
    }

    const ClassInfo& classInfo() const override { return customClass().info(); }

    Object* duplicate() const override
    {
        // The class cannot have been unregistered while this group lives.
        auto* made = makeGroupOf<G>(findCustomClass(customClass().type()));
        std::unique_ptr<Object, void (*)(Object*)> copy{made, [](Object* object) { object->dispose(); }};
        // Its objects first, so the class's duplicate method sees them.
        if constexpr (std::is_base_of_v<DisplayGroup, G>)
            made->copyDisplayGroup(*this);
        else
            made->copyFrom(*this);
        copyInto(const_cast<CustomGroupObject*>(this), *made, made);
        return copy.release();
    }

    bool accepts(const Object& object) const override
    {
        const auto accept = customClass().template methodAs<TQ3XGroupAcceptObjectMethod>(kQ3XMethodType_GroupAcceptObject);
        if (accept == nullptr)
            return G::accepts(object);
        // Whatever the class says, a group holds shared objects only.
        if (!object.isType(kQ3ObjectTypeShared))
            return false;
        const TQ3Boolean answer = accept(self(), const_cast<Object&>(object).handle());
        return enumValue(answer) == kQ3True;
    }

    void endRead() override
    {
        if (const auto end = customClass().template methodAs<TQ3XGroupEndReadMethod>(kQ3XMethodType_GroupEndRead))
            if (end(self()) != kQ3Success)
                fail(kQ3ErrorInvalidMetafileObject,
                     "the end-read method of the group class \"" + customClass().name() + "\" failed");
    }

protected:
    TQ3Object self() const { return const_cast<CustomGroupObject*>(this)->handle(); }

    void positionAdded(Group::Node& node) override
    {
        if (!m_keepsPositionData)
            return;
        node.privateData = zeroed(m_positionSize);
        if (const auto make = customClass().template methodAs<TQ3XGroupPositionNewMethod>(kQ3XMethodType_GroupPositionNew))
            if (make(node.privateData.get(), node.object->handle(), leafData()) != kQ3Success) {
                node.privateData.reset();
                fail(kQ3ErrorInvalidParameter,
                     "the position new method of the group class \"" + customClass().name() + "\" failed");
            }
    }

    void positionRemoving(Group::Node& node) noexcept override
    {
        if (!node.privateData)
            return;
        if (const auto remove =
                customClass().template methodAs<TQ3XGroupPositionDeleteMethod>(kQ3XMethodType_GroupPositionDelete))
            remove(node.privateData.get());
        node.privateData.reset();
    }

    void positionCopied(const Group::Node& from, Group::Node& to) override
    {
        if (!m_keepsPositionData || !from.privateData)
            return;
        auto block = zeroed(m_positionSize);
        if (const auto copy =
                customClass().template methodAs<TQ3XGroupPositionCopyMethod>(kQ3XMethodType_GroupPositionCopy)) {
            if (copy(from.privateData.get(), block.get()) != kQ3Success)
                fail(kQ3ErrorInvalidParameter,
                     "the position copy method of the group class \"" + customClass().name() + "\" failed");
        } else {
            std::memcpy(block.get(), from.privateData.get(), m_positionSize);
        }
        to.privateData = std::move(block);
    }

private:
    std::size_t m_positionSize = 0;
    /// A position size or a position new method: every node has data.
    bool m_keepsPositionData = false;
};

/// The concrete classes: display groups also draw through the class's
/// iterate methods.
template <class G>
class CustomGroupObjectOf<G, false> final : public CustomGroupObject<G> {
public:
    using CustomGroupObject<G>::CustomGroupObject;
};

template <class G>
class CustomGroupObjectOf<G, true> final : public CustomGroupObject<G> {
public:
    using CustomGroupObject<G>::CustomGroupObject;

    void submitContents(ShapeVisitor& visitor) const override
    {
        // QD3DGroup.h: the start method passes back the first object to
        // draw (NULL: nothing, and no end method call); the end method gets
        // the object drawn and passes back the next, NULL after the last.
        // The objects are the class's: Q3 draws them and never releases them.
        const CustomClass& leaf = this->customClass();
        const auto start = leaf.template methodAs<TQ3XGroupStartIterateMethod>(kQ3XMethodType_GroupStartIterate);
        const auto end = leaf.template methodAs<TQ3XGroupEndIterateMethod>(kQ3XMethodType_GroupEndIterate);
        const TQ3Object view = customSubmitView();
        if (start == nullptr || end == nullptr || view == nullptr) {
            G::submitContents(visitor);
            return;
        }
        TQ3GroupPosition iterator = nullptr;
        TQ3Object object = nullptr;
        if (start(this->self(), &iterator, &object, view) != kQ3Success)
            fail(kQ3ErrorInvalidParameter, "the start-iterate method of the group class \"" + leaf.name() + "\" failed");
        while (object != nullptr) {
            const Object& member = lookupObject(object, "the object the group's iterate method passed back");
            if (member.isDrawable()) {
                if (iterator != nullptr && this->owns(iterator))
                    visitor.atGroupPosition(iterator);
                member.accept(visitor);
            }
            if (end(this->self(), &iterator, &object, view) != kQ3Success)
                fail(kQ3ErrorInvalidParameter,
                     "the end-iterate method of the group class \"" + leaf.name() + "\" failed");
        }
    }
};

template <class G>
Object* makeGroupObject(std::shared_ptr<CustomClass> leaf)
{
    return makeGroupOf<G>(std::move(leaf));
}

template <class G>
bool allowSubclasses()
{
    return registerCustomBase(G::kClassType, makeGroupObject<G>);
}

// Applications may register classes under each group class Q3 defines.
const bool kRegistered = allowSubclasses<Group>() && allowSubclasses<DisplayGroup>() &&
                         allowSubclasses<OrderedDisplayGroup>() && allowSubclasses<IOProxyDisplayGroup>() &&
                         allowSubclasses<LightGroup>() && allowSubclasses<InfoGroup>();

} // namespace

TQ3XFunctionPointer groupMethod(const Group& group, TQ3XMethodType type)
{
    CustomInstance* instance = customInstanceOf(const_cast<Group&>(group));
    if (instance == nullptr)
        return nullptr;
    for (const Running& running : t_running)
        if (running.group == &group && running.type == type)
            return nullptr;
    return instance->customClass().method(type);
}

GroupMethodCall::GroupMethodCall(const Group& group, TQ3XMethodType type)
{
    t_running.push_back({&group, type});
}

GroupMethodCall::~GroupMethodCall()
{
    t_running.pop_back();
}

void* positionPrivate(Group& group, TQ3GroupPosition position)
{
    Group::Node& node = group.nodeAt(position);
    if (!node.privateData)
        fail(kQ3ErrorInvalidObjectClass, std::string("the ") + group.classInfo().name +
                                             "'s class keeps no private data per position "
                                             "(kQ3XMethodType_GroupPositionSize, kQ3XMethodType_GroupPositionNew)");
    return node.privateData.get();
}

} // namespace q3
