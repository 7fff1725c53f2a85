// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "core/CustomObject.h"

#include "QD3DExtension.h"
#include "core/Limits.h"
#include "core/ShapeVisitor.h"

#include <cstring>
#include <map>
#include <mutex>

namespace q3 {

namespace {

/// A custom object over Base: Object (a class registered under TQ3Object,
/// disposed at once) or SharedObject (under kQ3ObjectTypeShared or a shape:
/// counted references).
template <class Base>
class CustomObject final : public Base, public CustomInstance {
public:
    explicit CustomObject(std::shared_ptr<CustomClass> leaf) : CustomInstance(std::move(leaf)) {}
    ~CustomObject() override { destroy(this); }

    const ClassInfo& classInfo() const override { return customClass().info(); }
    bool isDrawable() const override
    {
        // The metahandler answers kQ3True in place of a function.
        const CustomClass& leaf = customClass();
        return leaf.method(kQ3XMethodTypeObjectIsDrawable) != nullptr ||
               leaf.method(kQ3XMethodTypeObjectSubmitRender) != nullptr ||
               leaf.method(kQ3XMethodTypeObjectSubmitPick) != nullptr ||
               leaf.method(kQ3XMethodTypeObjectSubmitBounds) != nullptr;
    }
    void accept(ShapeVisitor& visitor) const override
    {
        // The object draws, picks and bounds through its class's submit
        // methods, which submit to the view (and so reach the visitor).
        if (!isDrawable())
            fail(kQ3ErrorInvalidObjectType, "a " + customClass().name() +
                                                " cannot be submitted (its class is not drawable)");
        visitor.beginCustomObject(*this);
        try {
            submitThroughMethod(const_cast<CustomObject*>(this));
        } catch (...) {
            visitor.endCustomObject(*this, false);
            throw;
        }
        visitor.endCustomObject(*this, true);
    }
    Object* duplicate() const override;
};

std::shared_ptr<CustomClass> requireRegistered(const CustomClass& leaf)
{
    std::shared_ptr<CustomClass> found = findCustomClass(leaf.type());
    if (found.get() != &leaf)
        fail(kQ3ErrorInvalidObjectClass, "the class \"" + leaf.name() + "\" is no longer registered");
    return found;
}

template <class Base>
std::unique_ptr<Base, void (*)(Base*)> fresh(const std::shared_ptr<CustomClass>& leaf)
{
    auto* made = new CustomObject<Base>(leaf);
    made->registerLive();
    return {made, [](Base* object) { object->dispose(); }};
}

template <class Base>
Object* CustomObject<Base>::duplicate() const
{
    // The class cannot have been unregistered while this object lives.
    auto copy = fresh<Base>(requireRegistered(customClass()));
    auto& target = static_cast<CustomObject<Base>&>(*copy);
    copyInto(const_cast<CustomObject*>(this), target, copy.get());
    return copy.release();
}

} // namespace

CustomInstance::CustomInstance(std::shared_ptr<CustomClass> leaf) : m_leaf(std::move(leaf))
{
    std::vector<std::shared_ptr<CustomClass>> chain;
    for (const ClassInfo* info = &m_leaf->info(); info != nullptr; info = info->parent)
        if (std::shared_ptr<CustomClass> custom = findCustomClass(info->type))
            if (&custom->info() == info)
                chain.insert(chain.begin(), std::move(custom));
    for (std::shared_ptr<CustomClass>& custom : chain) {
        std::unique_ptr<unsigned char[]> block;
        if (custom->size() != 0) {
            block = std::make_unique<unsigned char[]>(custom->size());
            std::memset(block.get(), 0, custom->size());
        }
        m_blocks.emplace_back(std::move(custom), std::move(block));
    }
    for (auto& block : m_blocks)
        ++block.first->instances;
}

CustomInstance::~CustomInstance()
{
    for (auto& block : m_blocks)
        --block.first->instances;
}

void* CustomInstance::privateData(const CustomClass& forClass) const
{
    for (const auto& [custom, block] : m_blocks)
        if (custom.get() == &forClass)
            return block.get();
    fail(kQ3ErrorInvalidObjectType,
         "the object is a " + m_leaf->name() + ", not of the class \"" + forClass.name() + "\"");
}

void CustomInstance::construct(TQ3Object self, void* parameters)
{
    for (; m_constructed < m_blocks.size(); ++m_constructed) {
        auto& [custom, block] = m_blocks[m_constructed];
        if (auto make = custom->methodAs<TQ3XObjectNewMethod>(kQ3XMethodTypeObjectNew))
            if (make(self, block.get(), parameters) != kQ3Success)
                fail(kQ3ErrorInvalidParameter, "the new method of the class \"" + custom->name() + "\" failed");
    }
}

void CustomInstance::destroy(TQ3Object self) noexcept
{
    while (m_constructed > 0) {
        auto& [custom, block] = m_blocks[--m_constructed];
        if (auto remove = custom->methodAs<TQ3XObjectDeleteMethod>(kQ3XMethodTypeObjectDelete))
            remove(self, block.get());
    }
}

void CustomInstance::copyInto(TQ3Object self, CustomInstance& to, TQ3Object toHandle) const
{
    for (; to.m_constructed < m_blocks.size(); ++to.m_constructed) {
        const auto& [custom, block] = m_blocks[to.m_constructed];
        void* target = to.m_blocks[to.m_constructed].second.get();
        if (auto copy = custom->methodAs<TQ3XObjectDuplicateMethod>(kQ3XMethodTypeObjectDuplicate)) {
            if (copy(self, block.get(), toHandle, target) != kQ3Success)
                fail(kQ3ErrorInvalidParameter,
                     "the duplicate method of the class \"" + custom->name() + "\" failed");
        } else if (custom->size() != 0) {
            std::memcpy(target, block.get(), custom->size());
        }
    }
}

namespace {

struct Factories {
    std::mutex mutex;
    std::map<TQ3ObjectType, CustomBaseFactory> byBase;
};

Factories& factories()
{
    static auto* instance = new Factories;
    return *instance;
}

CustomBaseFactory factoryFor(TQ3ObjectType base)
{
    Factories& all = factories();
    std::lock_guard<std::mutex> lock(all.mutex);
    const auto found = all.byBase.find(base);
    return found == all.byBase.end() ? nullptr : found->second;
}

} // namespace

bool registerCustomBase(TQ3ObjectType base, CustomBaseFactory factory)
{
    Factories& all = factories();
    std::lock_guard<std::mutex> lock(all.mutex);
    all.byBase[base] = factory;
    return true;
}

const ClassInfo& builtInBaseOf(const CustomClass& leaf)
{
    const ClassInfo* info = &leaf.info();
    while (info->parent != nullptr) {
        const std::shared_ptr<CustomClass> custom = findCustomClass(info->type);
        if (!custom || &custom->info() != info)
            break;
        info = info->parent;
    }
    return *info;
}

bool acceptsCustomSubclasses(TQ3ObjectType parentType)
{
    if (parentType == kQ3ObjectTypeInvalid || parentType == kQ3ObjectTypeShared || parentType == kQ3SharedTypeShape)
        return true;
    if (const std::shared_ptr<CustomClass> parent = findCustomClass(parentType))
        return parent->kind() == CustomClass::Kind::kObject;
    return factoryFor(parentType) != nullptr;
}

void* CustomInstance::leafData() const
{
    return m_blocks.empty() ? nullptr : m_blocks.back().second.get();
}

Object* CustomInstance::make(const std::shared_ptr<CustomClass>& leaf, void* parameters)
{
    if (leaf->kind() != CustomClass::Kind::kObject)
        fail(kQ3ErrorInvalidObjectClass,
             "the class \"" + leaf->name() + "\" is an element class: Q3Set_Add makes its elements");
    if (CustomBaseFactory factory = factoryFor(builtInBaseOf(*leaf).type)) {
        std::unique_ptr<Object, void (*)(Object*)> made{factory(leaf), [](Object* object) { object->dispose(); }};
        customInstanceOf(*made)->construct(made.get(), parameters);
        if (made->isType(kQ3ObjectTypeShared))
            static_cast<SharedObject&>(*made).clearEditTracking();
        return made.release();
    }
    if (leaf->info().isA(kQ3ObjectTypeShared)) {
        auto made = fresh<SharedObject>(leaf);
        static_cast<CustomObject<SharedObject>&>(*made).construct(made.get(), parameters);
        static_cast<SharedObject&>(*made).clearEditTracking();
        return made.release();
    }
    auto made = fresh<Object>(leaf);
    static_cast<CustomObject<Object>&>(*made).construct(made.get(), parameters);
    return made.release();
}

namespace {

struct SubmitState {
    TQ3Object view = nullptr;
    TQ3XMethodType method = 0;
    std::size_t depth = 0; ///< submit methods running
};
thread_local SubmitState t_submit;

} // namespace

CustomSubmitScope::CustomSubmitScope(TQ3Object view, TQ3XMethodType method)
    : m_view(t_submit.view), m_method(t_submit.method)
{
    t_submit.view = view;
    t_submit.method = method;
}

CustomSubmitScope::~CustomSubmitScope()
{
    t_submit.view = m_view;
    t_submit.method = m_method;
}

void CustomInstance::submitThroughMethod(TQ3Object self) const
{
    if (t_submit.view == nullptr || t_submit.method == 0)
        return;
    auto submit = m_leaf->methodAs<TQ3XObjectSubmitMethod>(t_submit.method);
    if (submit == nullptr)
        return;
    if (t_submit.depth >= limits::kMaxGroupNesting)
        fail(kQ3ErrorInvalidObject, "a " + m_leaf->name() + " submits objects nested deeper than " +
                                        std::to_string(limits::kMaxGroupNesting) + " levels");
    const void* data = leafData();
    ++t_submit.depth;
    TQ3Status status;
    try {
        status = submit(t_submit.view, m_leaf->type(), self, data);
    } catch (...) {
        --t_submit.depth;
        throw;
    }
    --t_submit.depth;
    if (status != kQ3Success)
        fail(kQ3ErrorInvalidParameter, "the submit method of the class \"" + m_leaf->name() + "\" failed");
}

TQ3Object customSubmitView()
{
    return t_submit.method == 0 ? nullptr : t_submit.view;
}

CustomInstance* customInstanceOf(Object& object)
{
    return dynamic_cast<CustomInstance*>(&object);
}

} // namespace q3
