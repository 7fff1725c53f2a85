// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Classes registered at run time (QD3DExtension.h, QD3DSet.h): an
// application's element and attribute classes and its object classes. Each
// joins the class registry of core/Object.h through its own ClassInfo while
// it is registered, so the object-hierarchy queries see it like a class Q3
// defines; nothing lists them. A class keeps the methods its metahandler
// gave when it was registered (the metahandler itself is never called
// again, as QD3D.h promises).

#include "QD3D.h"
#include "core/Object.h"

#include <atomic>
#include <cstddef>
#include <map>
#include <memory>
#include <string>

struct OpaqueTQ3XObjectClass {
protected:
    OpaqueTQ3XObjectClass() = default;
};

namespace q3 {

/// The parents of custom element and attribute classes (QD3D.h's
/// kQ3ObjectTypeElement and kQ3ElementTypeAttribute).
extern const ClassInfo kElementClass;
extern const ClassInfo kAttributeClass;

/// A registered class. Invariant: while it is registered its ClassInfo is in
/// the class registry under type(), and `instances` counts the objects and
/// elements of the class alive (an unregister is refused while any is).
class CustomClass : public OpaqueTQ3XObjectClass {
public:
    enum class Kind { kElement, kAttribute, kObject };

    CustomClass(Kind kind, TQ3ObjectType type, const ClassInfo* parent, std::string name, std::size_t size,
                TQ3XMetaHandler metaHandler, TQ3XMetaHandler virtualMetaHandler, const CustomClass* parentClass);
    CustomClass(const CustomClass&) = delete;
    CustomClass& operator=(const CustomClass&) = delete;
    virtual ~CustomClass() = default;

    Kind kind() const { return m_kind; }
    TQ3ObjectType type() const { return m_info.type; }
    const std::string& name() const { return m_name; }
    const ClassInfo& info() const { return m_info; }
    /// The element's internal size (elements) or the instance data size
    /// (objects).
    std::size_t size() const { return m_size; }
    /// The method of that type the metahandlers gave (the class's own first,
    /// then the one a parent class's virtual metahandler gave), or null.
    TQ3XFunctionPointer method(TQ3XMethodType type) const;
    template <class F>
    F methodAs(TQ3XMethodType type) const
    {
        return reinterpret_cast<F>(method(type));
    }
    unsigned long version() const;
    TQ3XObjectClass handle() { return this; }

    std::atomic<long> instances{0};

private:
    Kind m_kind;
    std::string m_name;
    std::size_t m_size;
    std::map<TQ3XMethodType, TQ3XFunctionPointer> m_methods;
    /// What subclasses inherit: the parent's and this class's virtual methods.
    std::map<TQ3XMethodType, TQ3XFunctionPointer> m_inheritable;
    ClassInfo m_info;
};

/// The registered class with that type, or null (a class Q3 defines is none).
std::shared_ptr<CustomClass> findCustomClass(TQ3ObjectType type);
/// The class a handle names; throws kQ3ErrorNULLParameter or
/// kQ3ErrorInvalidObjectClass (no registered class).
std::shared_ptr<CustomClass> lookupCustomClass(TQ3XObjectClass handle, const char* name);

/// Registers a class. `type` is the type asked for, kept when no class has
/// it (elements: and it is none of the reserved element types 0 to 33),
/// else a new negative type is given. Throws kQ3ErrorInvalidParameter (an
/// empty name, a name too long for TQ3ObjectClassNameString, a name a class
/// has already), kQ3ErrorInvalidObjectClass (an unknown parent).
std::shared_ptr<CustomClass> registerCustomClass(CustomClass::Kind kind, TQ3ObjectType type,
                                                 TQ3ObjectType parentType, const std::string& name,
                                                 std::size_t size, TQ3XMetaHandler metaHandler,
                                                 TQ3XMetaHandler virtualMetaHandler);
/// Unregisters a class: kQ3ErrorObjectClassInUse while objects or elements
/// of it (or subclasses) live; the class's unregister method is called.
void unregisterCustomClass(TQ3XObjectClass handle);
/// The custom class of that name, or null.
std::shared_ptr<CustomClass> findCustomClassNamed(const std::string& name);

/// The element value of a custom element class in a set: the class's
/// internal data, made and copied by its methods (QD3DSet.h's copy
/// methods; a plain byte copy where the class gives none) and deleted by
/// its delete method. Invariant: m_data holds size() bytes built by the
/// class; the class stays alive (and registered) as long as the element.
class CustomElement {
public:
    /// Builds an element from the application's data (copy-add).
    CustomElement(std::shared_ptr<CustomClass> elementClass, const void* apiData);
    CustomElement(const CustomElement& other); ///< copy-duplicate
    CustomElement& operator=(const CustomElement&) = delete;
    ~CustomElement();

    const CustomClass& elementClass() const { return *m_class; }
    /// Copies the application's data over this element (copy-replace).
    void replace(const void* apiData);
    /// Copies the element to the application's data (copy-get).
    void get(void* apiData) const;
    /// A copy for attribute inheritance (copy-inherit, else copy-duplicate).
    std::unique_ptr<CustomElement> inheritCopy() const;
    /// Whether the class lets its attribute be inherited
    /// (kQ3XMethodTypeAttributeInherit).
    bool inherits() const;
    const void* data() const { return m_data.get(); }
    void* data() { return m_data.get(); }

private:
    struct InheritTag {};
    CustomElement(const CustomElement& other, InheritTag);
    std::shared_ptr<CustomClass> m_class;
    std::unique_ptr<unsigned char[]> m_data;
};

/// The method types Q3 asks a metahandler for.
extern const TQ3XMethodType kKnownMethodTypes[];
extern const std::size_t kKnownMethodTypeCount;

} // namespace q3
