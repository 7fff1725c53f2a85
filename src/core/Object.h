// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3D.h"
#include "core/Error.h"
#include "core/Ref.h"

#include <atomic>
#include <memory>
#include <string>
#include <vector>

/// The C handle type. Every q3::Object is one, so object -> handle is an
/// implicit upcast; handle -> object goes through q3::lookup().
struct OpaqueTQ3Object {
protected:
    OpaqueTQ3Object() = default;
};

namespace q3 {

class ShapeVisitor;
class Set;
struct ObjectElements;

/// A node of the QuickDraw 3D class tree: a type code, its parent and a name
/// for messages. Every ClassInfo enters the class registry when it is
/// constructed (each class file defines its own as a global), so the set of
/// classes is whatever is linked in: no file lists them.
struct ClassInfo {
    ClassInfo(TQ3ObjectType type, const ClassInfo* parent, const char* name);
    /// Leaves the registry (a class an application unregisters).
    ~ClassInfo();
    ClassInfo(const ClassInfo&) = delete;
    ClassInfo& operator=(const ClassInfo&) = delete;

    TQ3ObjectType type;
    const ClassInfo* parent;
    const char* name;

    bool isA(TQ3ObjectType other) const;
    /// The type at depth `level` of this class's chain: 1 is the child of the
    /// root (kQ3ObjectTypeShared, kQ3ObjectTypeView), 2 its child, and so on;
    /// kQ3ObjectTypeInvalid when the chain is shorter.
    TQ3ObjectType typeAtLevel(int level) const;
};

/// The registered class with this type code, or null.
const ClassInfo* findClass(TQ3ObjectType type);

/// Every registered class but the root, in ascending order of type code.
std::vector<const ClassInfo*> allClasses();

/// The root of the class tree (type kQ3ObjectTypeInvalid) and its first-level
/// classes.
extern const ClassInfo kRootClass;
extern const ClassInfo kSharedClass;
extern const ClassInfo kShapeClass;

/// Every Q3 object. Invariant: an Object is in the live-object registry from
/// the end of its construction to the start of its destruction, so a handle
/// found there points at a fully constructed object of classInfo()'s class.
class Object : public OpaqueTQ3Object {
public:
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;
    virtual ~Object();

    virtual const ClassInfo& classInfo() const = 0;

    bool isType(TQ3ObjectType type) const { return classInfo().isA(type); }
    TQ3ObjectType leafType() const { return classInfo().type; }

    /// Drops the caller's reference (shared objects) or destroys (others).
    virtual void dispose();
    /// A deep copy holding one reference for the caller.
    virtual Object* duplicate() const;
    /// duplicate(), with copies of the object's own elements
    /// (Q3Object_Duplicate, and a group's duplicate of its members).
    Object* clone() const;
    /// The elements kept on the object itself (Q3Shape_AddElement,
    /// Q3Object_AddElement; a set's own elements are the set), made when
    /// first asked for; null from the const form while there are none.
    ObjectElements& elements();
    const ObjectElements* elementsIfAny() const { return m_elements.get(); }
    virtual bool isDrawable() const { return false; }
    /// Submits the object to a view (drawables only).
    virtual void accept(ShapeVisitor& visitor) const;

    TQ3Object handle() noexcept { return this; }

    /// Enters the object in the live registry; makeShared/makeObject call it
    /// once the object is fully constructed.
    void registerLive();

protected:
    Object();

private:
    bool m_registered = false;
    std::unique_ptr<ObjectElements> m_elements;
};

/// A reference-counted object. Invariant: the edit index changes with every
/// edit (markEdited), and every cache derived from the object is dropped at the
/// same time.
///
/// The reference-count contract, stated once here for every owner of a
/// reference (a q3::Ref, a C caller, a handle held in a C data struct):
/// - A shared object is born with one reference, held by its creator:
///   makeShared() adopts it into the Ref it returns, and a New entry point
///   hands that reference to C with detach().
/// - A reference is added only by someone who already holds one on the same
///   object (a Ref being copied, lookupRef() on a handle its C caller owns), so
///   an increment never races with the deletion and has nothing to order:
///   addReference() is a relaxed fetch_add.
/// - releaseReference() drops one, and the call that takes the count from 1 to
///   0 deletes the object. The decrement is an acq_rel fetch_sub: its release
///   half puts every access a thread made through its reference before its
///   decrement, and its acquire half, in the thread that reaches 0, puts all of
///   them (every decrement heads a release sequence the last one reads from)
///   before the destructor. This is what Boost's and libstdc++'s shared
///   pointers do; one acq_rel operation rather than a release decrement and an
///   acquire fence taken only at 0, because ThreadSanitizer (scripts/test.sh
///   runs it) does not model standalone fences, and on x86 both are the same
///   locked instruction.
/// - No resurrection: a count never goes from 0 back to 1. Nothing finds an
///   object without holding a reference to it; the live registry refuses a
///   handle disposed earlier, but a handle whose last reference another thread
///   is dropping at the same moment is the program's race, as in QuickDraw 3D.
/// - referenceCount() is a snapshot for Q3Shared_IsReferenced and tests; it
///   orders nothing (relaxed), and no code decides ownership from it.
/// - Core code holds references in Ref<T> (core/Ref.h): adopt() takes over a
///   reference the pointer already carries (a new object's first one, one
///   handed in from C), retain() adds one, detach() hands one out to C without
///   releasing it, and a Ref's copy retains and its destruction releases. The
///   handle fields of C data structs hold plain counted references, which only
///   the code that fills and empties those structs takes and drops
///   (core/DataLayout.h and the fields it cannot describe).
class SharedObject : public Object {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ObjectTypeShared;

    void dispose() override { releaseReference(); }

    unsigned long referenceCount() const noexcept
    {
        return m_references.load(std::memory_order_relaxed);
    }
    unsigned long editIndex() const noexcept { return m_editIndex.load(); }
    void markEdited();
    /// Whether markEdited() ran since the object was made or since
    /// clearEditTracking() (Q3Shared_GetEditTrackingState).
    bool editedSinceTracking() const noexcept { return m_editTracked.load(); }
    void clearEditTracking() noexcept { m_editTracked = false; }

    void addReference() noexcept { m_references.fetch_add(1, std::memory_order_relaxed); }
    void releaseReference() noexcept;

protected:
    SharedObject();
    /// Drops caches derived from the object's data; called by markEdited().
    virtual void onEdited() {}

private:
    std::atomic<unsigned long> m_references{1};
    std::atomic<unsigned long> m_editIndex;
    std::atomic<bool> m_editTracked{false};
};

/// Creates a shared object, registers it, and returns its first reference.
template <class T, class... Args>
Ref<T> makeShared(Args&&... args)
{
    Ref<T> ref = Ref<T>::adopt(new T(std::forward<Args>(args)...));
    ref->registerLive();
    ref->clearEditTracking(); // what the constructor did is no edit
    return ref;
}

/// Creates and registers a non-shared object (a view); the caller owns it.
template <class T, class... Args>
T* makeObject(Args&&... args)
{
    std::unique_ptr<T> object(new T(std::forward<Args>(args)...));
    object->registerLive();
    return object.release();
}

/// The handle's object if it is a live Q3 object; throws kQ3ErrorNULLParameter
/// or kQ3ErrorInvalidObject otherwise. `name` is the parameter's name.
Object& lookupObject(TQ3Object handle, const char* name);

/// The handle's object as a T (a class with kClassType); throws as
/// lookupObject, or kQ3ErrorInvalidObjectType when it is of another class.
template <class T>
T& lookup(TQ3Object handle, const char* name)
{
    Object& object = lookupObject(handle, name);
    if (!object.isType(T::kClassType))
        fail(kQ3ErrorInvalidObjectType, std::string(name) + " is a " + object.classInfo().name +
                                            ", not the kind of object this call takes");
    return static_cast<T&>(object);
}

/// As lookup(), returning a new counted reference.
template <class T>
Ref<T> lookupRef(TQ3Object handle, const char* name)
{
    return Ref<T>::retain(&lookup<T>(handle, name));
}

/// As lookup() but NULL is allowed and gives nullptr.
template <class T>
T* lookupOptional(TQ3Object handle, const char* name)
{
    return handle == nullptr ? nullptr : &lookup<T>(handle, name);
}

/// The number of live objects (Q3Memory_CountLiveObjects).
unsigned long liveObjectCount();

/// Q3Initialize / Q3Exit nesting.
namespace system {
bool isInitialized();
bool initialize(); // false when it was already initialized
bool exit();       // false when it was not initialized
} // namespace system

} // namespace q3
