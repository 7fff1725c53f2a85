// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Objects of the classes applications register (QD3DExtension.h). An
// object holds one block of instance data per custom class in its chain;
// the classes' own methods make, copy and delete what is in them.

#include "core/CustomClass.h"
#include "core/Object.h"

#include <memory>
#include <utility>
#include <vector>

namespace q3 {

/// What every custom object has, whatever Q3 class it derives from.
/// Invariant: m_blocks lists the custom classes of the chain from the top
/// down, each with its instance data (null for size 0); the first
/// m_constructed of them had their new method run (or were copied), and only
/// those get their delete method.
class CustomInstance {
public:
    CustomInstance(const CustomInstance&) = delete;
    CustomInstance& operator=(const CustomInstance&) = delete;

    const CustomClass& customClass() const { return *m_leaf; }
    /// The instance data of `forClass`; throws kQ3ErrorInvalidObjectType when
    /// the class is not in the object's chain.
    void* privateData(const CustomClass& forClass) const;

    /// Makes an object of a registered object class and runs the new
    /// methods; throws kQ3ErrorInvalidParameter when one fails (the object
    /// is gone again). A class under a class Q3 defines that has a factory
    /// (registerCustomBase) is made by that factory.
    static Object* make(const std::shared_ptr<CustomClass>& leaf, void* parameters);

    /// The instance data of the leaf class (null for size 0).
    void* leafData() const;

protected:
    explicit CustomInstance(std::shared_ptr<CustomClass> leaf);
    virtual ~CustomInstance();
    /// Runs the delete methods, from the leaf up (each object's destructor).
    void destroy(TQ3Object self) noexcept;
    /// Fills `to` (just made, zeroed) from this object by each class's
    /// duplicate method, or a byte copy.
    void copyInto(TQ3Object self, CustomInstance& to, TQ3Object toHandle) const;
    void construct(TQ3Object self, void* parameters);
    /// Calls the class's submit method for the running CustomSubmitScope,
    /// if it has one (kQ3ErrorInvalidParameter when it fails).
    void submitThroughMethod(TQ3Object self) const;

private:
    std::shared_ptr<CustomClass> m_leaf;
    std::vector<std::pair<std::shared_ptr<CustomClass>, std::unique_ptr<unsigned char[]>>> m_blocks;
    std::size_t m_constructed = 0;
};

/// The custom object found from a handle, or null when the object is of a
/// class Q3 defines.
CustomInstance* customInstanceOf(Object& object);

/// Makes a bare object (registered live, no new method run yet) of a custom
/// class whose nearest class Q3 defines is the one the factory was
/// registered for; CustomInstance::make runs the new methods.
using CustomBaseFactory = Object* (*)(std::shared_ptr<CustomClass> leaf);
/// Lets applications register classes under the class of type `base` (one
/// an upper layer defines, as group/ does for its groups); called once per
/// class at static initialisation, so no list names them (a type, not a
/// ClassInfo: another file's ClassInfo may not be constructed yet).
bool registerCustomBase(TQ3ObjectType base, CustomBaseFactory factory);
/// Whether an object class may be registered under parentType: TQ3Object,
/// kQ3ObjectTypeShared, kQ3SharedTypeShape, a class with a factory, or a
/// registered object class under one of them.
bool acceptsCustomSubclasses(TQ3ObjectType parentType);
/// The nearest class of the chain that no application registered.
const ClassInfo& builtInBaseOf(const CustomClass& leaf);

/// The view a CustomSubmitScope on this thread submits to, or null.
TQ3Object customSubmitView();

/// While a view submits a retained object (View::submit): the view's handle
/// and the submit method type its loop calls (kQ3XMethodTypeObjectSubmitRender,
/// ...Pick, ...Bounds; 0 for none), so that a custom object's accept() can
/// call its class's submit method with them, also as a member of a group.
/// Scopes nest (a submit method may submit other objects).
class CustomSubmitScope {
public:
    CustomSubmitScope(TQ3Object view, TQ3XMethodType method);
    ~CustomSubmitScope();
    CustomSubmitScope(const CustomSubmitScope&) = delete;
    CustomSubmitScope& operator=(const CustomSubmitScope&) = delete;

private:
    TQ3Object m_view;
    TQ3XMethodType m_method;
};

} // namespace q3
