// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "core/Object.h"

#include "core/AttributeSet.h"

#include <algorithm>
#include <mutex>
#include <unordered_map>
#include <unordered_set>

namespace q3 {

namespace {

// Every ClassInfo, by type code. Filled during static initialization (from
// any translation unit, hence the function-local static), and at run time by
// the classes applications register (core/CustomClass.h), hence the mutex.
// Never destroyed, so class infos ending at exit can still leave it.
std::unordered_map<TQ3ObjectType, const ClassInfo*>& classRegistry()
{
    static auto* classes = new std::unordered_map<TQ3ObjectType, const ClassInfo*>;
    return *classes;
}

std::mutex& classRegistryMutex()
{
    static auto* mutex = new std::mutex;
    return *mutex;
}

} // namespace

ClassInfo::ClassInfo(TQ3ObjectType type_, const ClassInfo* parent_, const char* name_)
    : type(type_), parent(parent_), name(name_)
{
    std::lock_guard<std::mutex> lock(classRegistryMutex());
    classRegistry().emplace(type, this);
}

ClassInfo::~ClassInfo()
{
    std::lock_guard<std::mutex> lock(classRegistryMutex());
    auto& classes = classRegistry();
    const auto found = classes.find(type);
    if (found != classes.end() && found->second == this)
        classes.erase(found);
}

const ClassInfo* findClass(TQ3ObjectType type)
{
    std::lock_guard<std::mutex> lock(classRegistryMutex());
    const auto& classes = classRegistry();
    const auto found = classes.find(type);
    return found == classes.end() ? nullptr : found->second;
}

std::vector<const ClassInfo*> allClasses()
{
    std::vector<const ClassInfo*> result;
    std::lock_guard<std::mutex> lock(classRegistryMutex());
    for (const auto& [type, info] : classRegistry())
        if (type != kQ3ObjectTypeInvalid)
            result.push_back(info);
    std::sort(result.begin(), result.end(),
              [](const ClassInfo* a, const ClassInfo* b) { return a->type < b->type; });
    return result;
}

const ClassInfo kRootClass{kQ3ObjectTypeInvalid, nullptr, "object"};
const ClassInfo kSharedClass{kQ3ObjectTypeShared, &kRootClass, "shared object"};
const ClassInfo kShapeClass{kQ3SharedTypeShape, &kSharedClass, "shape"};

namespace {

// The live-object registry: a handle is trusted only if it is in here, which
// catches disposed handles and stray pointers before any memory behind them
// is read. A mutex keeps it consistent when views render on several threads.
struct Registry {
    std::mutex mutex;
    std::unordered_set<const OpaqueTQ3Object*> live;
};

Registry& registry()
{
    // Never destroyed, so objects released during static destruction are safe.
    static Registry* instance = new Registry;
    return *instance;
}

std::atomic<unsigned long> g_editCounter{0};
std::atomic<int> g_initializeCount{0};

} // namespace

bool ClassInfo::isA(TQ3ObjectType other) const
{
    for (const ClassInfo* info = this; info != nullptr; info = info->parent)
        if (info->type == other)
            return true;
    return false;
}

TQ3ObjectType ClassInfo::typeAtLevel(int level) const
{
    int depth = 0;
    for (const ClassInfo* info = this; info->parent != nullptr; info = info->parent)
        ++depth;
    if (level < 1 || level > depth)
        return kQ3ObjectTypeInvalid;
    const ClassInfo* info = this;
    for (int i = depth; i > level; --i)
        info = info->parent;
    return info->type;
}

Object::Object() = default;

Object::~Object()
{
    if (m_registered) {
        Registry& r = registry();
        std::lock_guard<std::mutex> lock(r.mutex);
        r.live.erase(this);
    }
}

void Object::registerLive()
{
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    r.live.insert(this);
    m_registered = true;
}

void Object::dispose()
{
    delete this;
}

ObjectElements& Object::elements()
{
    if (!m_elements)
        m_elements = std::make_unique<ObjectElements>();
    return *m_elements;
}

Object* Object::clone() const
{
    Object* copy = duplicate();
    if (m_elements == nullptr || copy == nullptr)
        return copy;
    // The own elements are copied (custom ones by their copy-duplicate
    // method); an attached set is shared, as Q3Shape_SetSet shares it.
    try {
        ObjectElements& target = copy->elements();
        if (m_elements->own)
            target.own = Ref<Set>::adopt(static_cast<Set*>(m_elements->own->duplicate()));
        target.attached = m_elements->attached;
    } catch (...) {
        copy->dispose();
        throw;
    }
    return copy;
}

Object* Object::duplicate() const
{
    fail(kQ3ErrorInvalidObjectType, std::string("a ") + classInfo().name + " cannot be duplicated");
}

void Object::accept(ShapeVisitor&) const
{
    fail(kQ3ErrorInvalidObjectType, std::string("a ") + classInfo().name + " cannot be submitted");
}

SharedObject::SharedObject() : m_editIndex(++g_editCounter) {}

void SharedObject::markEdited()
{
    m_editIndex = ++g_editCounter;
    m_editTracked = true;
    onEdited();
}

void SharedObject::releaseReference() noexcept
{
    // acq_rel: the contract in Object.h says why.
    if (m_references.fetch_sub(1, std::memory_order_acq_rel) == 1)
        delete this;
}

Object& lookupObject(TQ3Object handle, const char* name)
{
    if (handle == nullptr)
        fail(kQ3ErrorNULLParameter, std::string(name) + " is NULL");
    Registry& r = registry();
    {
        std::lock_guard<std::mutex> lock(r.mutex);
        if (r.live.count(handle) == 0)
            fail(kQ3ErrorInvalidObject,
                 std::string(name) + " is not a live Q3 object (disposed already, or never created)");
    }
    return static_cast<Object&>(*handle);
}

unsigned long liveObjectCount()
{
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    return static_cast<unsigned long>(r.live.size());
}

namespace system {

bool isInitialized()
{
    return g_initializeCount.load() > 0;
}

bool initialize()
{
    return g_initializeCount.fetch_add(1) == 0;
}

bool exit()
{
    int count = g_initializeCount.load();
    while (count > 0)
        if (g_initializeCount.compare_exchange_weak(count, count - 1))
            return true;
    return false;
}

} // namespace system

} // namespace q3
