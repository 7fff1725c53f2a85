// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "core/CustomClass.h"

#include "QD3DExtension.h"
#include "QD3DGroup.h"
#include "QD3DIO.h"
#include "QD3DSet.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <mutex>
#include <vector>

namespace q3 {

const ClassInfo kElementClass{kQ3ObjectTypeElement, &kRootClass, "element"};
const ClassInfo kAttributeClass{kQ3ElementTypeAttribute, &kElementClass, "attribute"};

const TQ3XMethodType kKnownMethodTypes[] = {
    kQ3XMethodTypeObjectIsDrawable,     kQ3XMethodTypeObjectClassVersion,
    kQ3XMethodTypeObjectClassRegister, kQ3XMethodTypeObjectClassReplace,   kQ3XMethodTypeObjectClassUnregister,
    kQ3XMethodTypeObjectNew,           kQ3XMethodTypeObjectDelete,         kQ3XMethodTypeObjectDuplicate,
    kQ3XMethodTypeElementCopyAdd,      kQ3XMethodTypeElementCopyReplace,   kQ3XMethodTypeElementCopyGet,
    kQ3XMethodTypeElementCopyDuplicate, kQ3XMethodTypeElementDelete,       kQ3XMethodTypeAttributeInherit,
    kQ3XMethodTypeAttributeCopyInherit, kQ3XMethodTypeAttributeDefault,    kQ3XMethodTypeAttributeIsDefault,
    kQ3XMethodTypeObjectTraverse,       kQ3XMethodTypeObjectTraverseData,  kQ3XMethodTypeObjectWrite,
    kQ3XMethodTypeObjectRead,           kQ3XMethodTypeObjectReadData,      kQ3XMethodTypeObjectAttach,
    kQ3XMethodTypeObjectSubmitRender,   kQ3XMethodTypeObjectSubmitPick,    kQ3XMethodTypeObjectSubmitBounds,
    kQ3XMethodTypeObjectFileVersion,
    // QD3DGroup.h's group class methods (group/CustomGroup.h).
    kQ3XMethodType_GroupAcceptObject,   kQ3XMethodType_GroupAddObject,     kQ3XMethodType_GroupAddObjectBefore,
    kQ3XMethodType_GroupAddObjectAfter, kQ3XMethodType_GroupSetPositionObject, kQ3XMethodType_GroupRemovePosition,
    kQ3XMethodType_GroupGetFirstPositionOfType, kQ3XMethodType_GroupGetLastPositionOfType,
    kQ3XMethodType_GroupGetNextPositionOfType,  kQ3XMethodType_GroupGetPrevPositionOfType,
    kQ3XMethodType_GroupCountObjectsOfType,     kQ3XMethodType_GroupEmptyObjectsOfType,
    kQ3XMethodType_GroupGetFirstObjectPosition, kQ3XMethodType_GroupGetLastObjectPosition,
    kQ3XMethodType_GroupGetNextObjectPosition,  kQ3XMethodType_GroupGetPrevObjectPosition,
    kQ3XMethodType_GroupPositionSize,   kQ3XMethodType_GroupPositionNew,   kQ3XMethodType_GroupPositionCopy,
    kQ3XMethodType_GroupPositionDelete, kQ3XMethodType_GroupStartIterate,  kQ3XMethodType_GroupEndIterate,
    kQ3XMethodType_GroupEndRead,
};
const std::size_t kKnownMethodTypeCount = sizeof kKnownMethodTypes / sizeof kKnownMethodTypes[0];

namespace {

struct Registry {
    std::mutex mutex;
    std::map<TQ3ObjectType, std::shared_ptr<CustomClass>> byType;
    // Far from the small negative types a binary 3DMF file declares for
    // its own classes.
    TQ3ObjectType nextType = -0x10000;
};

Registry& registry()
{
    static auto* instance = new Registry;
    return *instance;
}

// The element types QuickDraw 3D reserves: none, the attribute types, the
// unknown and set elements.
bool reservedElementType(TQ3ObjectType type)
{
    return type >= kQ3ElementTypeNone && type <= kQ3ElementTypeSet;
}

} // namespace

CustomClass::CustomClass(Kind kind, TQ3ObjectType type, const ClassInfo* parent, std::string name,
                         std::size_t size, TQ3XMetaHandler metaHandler, TQ3XMetaHandler virtualMetaHandler,
                         const CustomClass* parentClass)
    : m_kind(kind), m_name(std::move(name)), m_size(size), m_info(type, parent, m_name.c_str())
{
    // The parent's virtual methods first, so the class's own replace them.
    if (parentClass != nullptr)
        m_methods = parentClass->m_inheritable;
    m_inheritable = m_methods;
    for (std::size_t i = 0; i < kKnownMethodTypeCount; ++i) {
        const TQ3XMethodType methodType = kKnownMethodTypes[i];
        if (virtualMetaHandler != nullptr)
            if (TQ3XFunctionPointer method = virtualMetaHandler(methodType)) {
                m_methods[methodType] = method;
                m_inheritable[methodType] = method;
            }
        if (metaHandler != nullptr)
            if (TQ3XFunctionPointer method = metaHandler(methodType))
                m_methods[methodType] = method;
    }
    const std::uintptr_t fileVersion = reinterpret_cast<std::uintptr_t>(method(kQ3XMethodTypeObjectFileVersion));
    if (fileVersion > kQ3FileVersionCurrent)
        fail(kQ3ErrorInvalidParameter,
             "the class \"" + m_name + "\" reads and writes 3DMF " + std::to_string(fileVersion >> 16) + "." +
                 std::to_string(fileVersion & 0xFFFF) + " (kQ3XMethodTypeObjectFileVersion), newer than the 1.6 Q3 "
                                                        "reads and writes");
}

TQ3XFunctionPointer CustomClass::method(TQ3XMethodType type) const
{
    const auto found = m_methods.find(type);
    return found == m_methods.end() ? nullptr : found->second;
}

unsigned long CustomClass::version() const
{
    // The metahandler returns the version itself, cast to a function
    // pointer (QD3DExtension.h, Q3_OBJECT_CLASS_VERSION).
    return static_cast<unsigned long>(reinterpret_cast<std::uintptr_t>(method(kQ3XMethodTypeObjectClassVersion)));
}

std::shared_ptr<CustomClass> findCustomClass(TQ3ObjectType type)
{
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    const auto found = r.byType.find(type);
    return found == r.byType.end() ? nullptr : found->second;
}

std::shared_ptr<CustomClass> findCustomClassNamed(const std::string& name)
{
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    for (const auto& [type, customClass] : r.byType)
        if (customClass->name() == name)
            return customClass;
    return nullptr;
}

std::shared_ptr<CustomClass> lookupCustomClass(TQ3XObjectClass handle, const char* name)
{
    if (handle == nullptr)
        fail(kQ3ErrorNULLParameter, std::string(name) + " is NULL");
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    for (const auto& [type, customClass] : r.byType)
        if (customClass.get() == handle)
            return customClass;
    fail(kQ3ErrorInvalidObjectClass,
         std::string(name) + " is no registered class (unregistered already, or never registered)");
}

std::shared_ptr<CustomClass> registerCustomClass(CustomClass::Kind kind, TQ3ObjectType type,
                                                 TQ3ObjectType parentType, const std::string& name,
                                                 std::size_t size, TQ3XMetaHandler metaHandler,
                                                 TQ3XMetaHandler virtualMetaHandler)
{
    if (name.empty())
        fail(kQ3ErrorInvalidParameter, "a class needs a name");
    if (name.size() >= kQ3StringMaximumLength)
        fail(kQ3ErrorInvalidParameter, "the class name \"" + name + "\" is longer than " +
                                           std::to_string(kQ3StringMaximumLength - 1) + " characters");
    const ClassInfo* parent = findClass(parentType);
    if (parent == nullptr)
        fail(kQ3ErrorInvalidObjectClass, "the parent type " + std::to_string(parentType) + " is no registered class");
    if (findCustomClassNamed(name) != nullptr)
        fail(kQ3ErrorInvalidParameter, "a class named \"" + name + "\" is registered already");
    const std::shared_ptr<CustomClass> parentClass = findCustomClass(parentType);
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    const bool elementKind = kind != CustomClass::Kind::kObject;
    if (type == kQ3ObjectTypeInvalid || findClass(type) != nullptr || (elementKind && reservedElementType(type))) {
        while (findClass(r.nextType) != nullptr)
            --r.nextType;
        type = r.nextType--;
    }
    auto made = std::make_shared<CustomClass>(kind, type, parent, name, size, metaHandler, virtualMetaHandler,
                                              parentClass.get());
    r.byType.emplace(type, made);
    return made;
}

void unregisterCustomClass(TQ3XObjectClass handle)
{
    std::shared_ptr<CustomClass> target = lookupCustomClass(handle, "objectClass");
    Registry& r = registry();
    {
        std::lock_guard<std::mutex> lock(r.mutex);
        for (const auto& [type, customClass] : r.byType) {
            if (customClass->instances.load() != 0 && customClass->info().isA(target->type()))
                fail(kQ3ErrorObjectClassInUse, "objects or elements of the class \"" + customClass->name() +
                                                   "\" still exist; the class stays registered");
            if (customClass != target && customClass->info().parent == &target->info())
                fail(kQ3ErrorObjectClassInUse,
                     "the class \"" + customClass->name() + "\" is registered under it; unregister it first");
        }
        r.byType.erase(target->type());
    }
    // QD3D.h's kQ3XMethodTypeObjectUnregister and QD3DExtension.h's
    // kQ3XMethodTypeObjectClassUnregister are one type ('unrg'); Q3 calls
    // the QD3DExtension.h form, with no class private block.
    if (auto unregister = target->methodAs<TQ3XObjectClassUnregisterMethod>(kQ3XMethodTypeObjectClassUnregister))
        unregister(handle, nullptr);
}

namespace {

void checkStatus(TQ3Status status, const CustomClass& elementClass, const char* method)
{
    if (status != kQ3Success)
        fail(kQ3ErrorInvalidParameter,
             "the " + std::string(method) + " method of the element class \"" + elementClass.name() + "\" failed");
}

std::unique_ptr<unsigned char[]> zeroed(std::size_t size)
{
    // Always at least one byte, so an element of size 0 has an address.
    auto data = std::make_unique<unsigned char[]>(size == 0 ? 1 : size);
    std::memset(data.get(), 0, size == 0 ? 1 : size);
    return data;
}

} // namespace

CustomElement::CustomElement(std::shared_ptr<CustomClass> elementClass, const void* apiData)
    : m_class(std::move(elementClass)), m_data(zeroed(m_class->size()))
{
    if (auto copyAdd = m_class->methodAs<TQ3XElementCopyAddMethod>(kQ3XMethodTypeElementCopyAdd))
        checkStatus(copyAdd(apiData, m_data.get()), *m_class, "copy-add");
    else
        std::memcpy(m_data.get(), apiData, m_class->size());
    ++m_class->instances;
}

CustomElement::CustomElement(const CustomElement& other)
    : m_class(other.m_class), m_data(zeroed(m_class->size()))
{
    if (auto copy = m_class->methodAs<TQ3XElementCopyDuplicateMethod>(kQ3XMethodTypeElementCopyDuplicate))
        checkStatus(copy(other.m_data.get(), m_data.get()), *m_class, "copy-duplicate");
    else
        std::memcpy(m_data.get(), other.m_data.get(), m_class->size());
    ++m_class->instances;
}

CustomElement::CustomElement(const CustomElement& other, InheritTag)
    : m_class(other.m_class), m_data(zeroed(m_class->size()))
{
    if (auto copy = m_class->methodAs<TQ3XAttributeCopyInheritMethod>(kQ3XMethodTypeAttributeCopyInherit))
        checkStatus(copy(other.m_data.get(), m_data.get()), *m_class, "copy-inherit");
    else if (auto duplicate = m_class->methodAs<TQ3XElementCopyDuplicateMethod>(kQ3XMethodTypeElementCopyDuplicate))
        checkStatus(duplicate(other.m_data.get(), m_data.get()), *m_class, "copy-duplicate");
    else
        std::memcpy(m_data.get(), other.m_data.get(), m_class->size());
    ++m_class->instances;
}

CustomElement::~CustomElement()
{
    if (auto remove = m_class->methodAs<TQ3XElementDeleteMethod>(kQ3XMethodTypeElementDelete))
        remove(m_data.get());
    --m_class->instances;
}

void CustomElement::replace(const void* apiData)
{
    if (auto copyReplace = m_class->methodAs<TQ3XElementCopyReplaceMethod>(kQ3XMethodTypeElementCopyReplace)) {
        checkStatus(copyReplace(apiData, m_data.get()), *m_class, "copy-replace");
        return;
    }
    // Without copy-replace: a new element, then the old one deleted.
    CustomElement fresh(m_class, apiData);
    std::swap(m_data, fresh.m_data);
}

void CustomElement::get(void* apiData) const
{
    if (auto copyGet = m_class->methodAs<TQ3XElementCopyGetMethod>(kQ3XMethodTypeElementCopyGet))
        checkStatus(copyGet(m_data.get(), apiData), *m_class, "copy-get");
    else
        std::memcpy(apiData, m_data.get(), m_class->size());
}

std::unique_ptr<CustomElement> CustomElement::inheritCopy() const
{
    return std::unique_ptr<CustomElement>(new CustomElement(*this, InheritTag{}));
}

bool CustomElement::inherits() const
{
    // The metahandler answers kQ3True or kQ3False in place of a function.
    return m_class->method(kQ3XMethodTypeAttributeInherit) != nullptr;
}

} // namespace q3
