// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The element calls of QD3D.h on shapes (Q3Shape_...Element, GetSet,
// SetSet) and Quesa's on any object (Q3Object_...Element). On a set both are
// the Q3Set_ calls; any other object keeps its elements itself
// (core/AttributeSet.h, ObjectElements): its own set of elements and the
// set attached as kQ3ElementTypeSet.
#include "QD3D.h"
#include "QD3DSet.h"
#include "api/Entry.h"
#include "api/ElementEntry.h"
#include "api/SetEntry.h"
#include "core/AttributeSet.h"

using namespace q3;
using namespace q3::api::elements;
using q3::api::guard;
using q3::api::guardStatus;

namespace q3::api::elements {

static Object& target(TQ3Object handle, Family family)
{
    const char* name = family == Family::kShape ? "shape" : "object";
    Object& object = lookupObject(handle, name);
    if (family == Family::kShape && !object.isType(kQ3SharedTypeShape) && !object.isType(kQ3SharedTypeSet))
        fail(kQ3ErrorInvalidObjectType,
             std::string(name) + " is a " + object.classInfo().name + ", neither a shape nor a set");
    return object;
}

static Set* asSet(Object& object)
{
    return object.isType(kQ3SharedTypeSet) ? static_cast<Set*>(&object) : nullptr;
}

static void edited(Object& object)
{
    if (object.isType(kQ3ObjectTypeShared))
        static_cast<SharedObject&>(object).markEdited();
}

static void requireType(Object& object, TQ3ElementType type)
{
    if (type != kQ3ElementTypeSet || asSet(object) != nullptr)
        Set::requireElementType(type);
}

void addElement(TQ3Object handle, Family family, TQ3ElementType type, const void* data)
{
    Object& object = target(handle, family);
    requireType(object, type);
    if (Set* set = asSet(object))
        return api::addElement(*set, type, data);
    requireNonNull(data, "data");
    ObjectElements& elements = object.elements();
    if (type == kQ3ElementTypeSet) {
        TQ3Object setHandle;
        std::memcpy(&setHandle, data, sizeof setHandle);
        elements.attached = lookupRef<Set>(setHandle, "*data (the set)");
    } else {
        api::addElement(elements.ownSet(), type, data);
    }
    edited(object);
}

void getElement(TQ3Object handle, Family family, TQ3ElementType type, void* data)
{
    Object& object = target(handle, family);
    requireType(object, type);
    if (Set* set = asSet(object))
        return api::getElement(*set, type, data);
    requireNonNull(data, "data");
    const ObjectElements* elements = object.elementsIfAny();
    if (type == kQ3ElementTypeSet) {
        if (elements == nullptr || !elements->attached)
            fail(kQ3ErrorAttributeNotContained, "no set is attached");
        TQ3Object setHandle = Ref<Set>(elements->attached).detach();
        std::memcpy(data, &setHandle, sizeof setHandle);
        return;
    }
    if (elements == nullptr || !elements->own)
        fail(kQ3ErrorAttributeNotContained, "there is no element of type " + std::to_string(type));
    api::getElement(*elements->own, type, data);
}

bool containsElement(TQ3Object handle, Family family, TQ3ElementType type)
{
    Object& object = target(handle, family);
    requireType(object, type);
    if (Set* set = asSet(object))
        return set->contains(type);
    const ObjectElements* elements = object.elementsIfAny();
    if (elements == nullptr)
        return false;
    if (type == kQ3ElementTypeSet)
        return static_cast<bool>(elements->attached);
    return elements->own && elements->own->contains(type);
}

void nextElementType(TQ3Object handle, Family family, TQ3ElementType* type)
{
    Object& object = target(handle, family);
    requireNonNull(type, "theType");
    if (*type != kQ3ElementTypeNone)
        requireType(object, *type);
    if (Set* set = asSet(object)) {
        *type = set->nextType(*type);
        return;
    }
    const ObjectElements* elements = object.elementsIfAny();
    if (*type == kQ3ElementTypeSet || elements == nullptr) {
        *type = kQ3ElementTypeNone;
        return;
    }
    const TQ3ElementType next =
        elements->own ? elements->own->nextType(*type) : TQ3ElementType{kQ3ElementTypeNone};
    *type = next == kQ3ElementTypeNone && elements->attached ? TQ3ElementType{kQ3ElementTypeSet} : next;
}

void emptyElements(TQ3Object handle, Family family)
{
    Object& object = target(handle, family);
    if (Set* set = asSet(object))
        return set->empty();
    if (object.elementsIfAny() == nullptr)
        return;
    ObjectElements& elements = object.elements();
    elements.own = Ref<Set>();
    elements.attached = Ref<Set>();
    edited(object);
}

void clearElement(TQ3Object handle, Family family, TQ3ElementType type)
{
    Object& object = target(handle, family);
    requireType(object, type);
    if (Set* set = asSet(object))
        return set->clear(type);
    if (!containsElement(handle, family, type))
        fail(kQ3ErrorAttributeNotContained, "there is no element of type " + std::to_string(type));
    ObjectElements& elements = object.elements();
    if (type == kQ3ElementTypeSet)
        elements.attached = Ref<Set>();
    else
        elements.own->clear(type);
    edited(object);
}

} // namespace q3::api::elements

namespace {

Object& shapeOnly(TQ3ShapeObject shape)
{
    Object& object = lookupObject(shape, "shape");
    if (!object.isType(kQ3SharedTypeShape))
        fail(kQ3ErrorInvalidObjectType, std::string("shape is a ") + object.classInfo().name + ", not a shape");
    return object;
}

} // namespace

extern "C" {

TQ3Status Q3Shape_GetSet(TQ3ShapeObject shape, TQ3SetObject* theSet)
{
    return guardStatus(__func__, [&] {
        const Object& object = shapeOnly(shape);
        requireNonNull(theSet, "theSet");
        const ObjectElements* elements = object.elementsIfAny();
        *theSet = elements != nullptr && elements->attached ? Ref<Set>(elements->attached).detach() : nullptr;
    });
}

TQ3Status Q3Shape_SetSet(TQ3ShapeObject shape, TQ3SetObject theSet)
{
    return guardStatus(__func__, [&] {
        Object& object = shapeOnly(shape);
        Ref<Set> set = theSet == nullptr ? Ref<Set>() : lookupRef<Set>(theSet, "theSet");
        object.elements().attached = std::move(set);
        edited(object);
    });
}

TQ3Status Q3Shape_AddElement(TQ3ShapeObject shape, TQ3ElementType theType, const void* data)
{
    return guardStatus(__func__, [&] { addElement(shape, Family::kShape, theType, data); });
}

TQ3Status Q3Shape_GetElement(TQ3ShapeObject shape, TQ3ElementType theType, void* data)
{
    return guardStatus(__func__, [&] { getElement(shape, Family::kShape, theType, data); });
}

TQ3Boolean Q3Shape_ContainsElement(TQ3ShapeObject shape, TQ3ElementType theType)
{
    return guard(__func__, kQ3False,
                 [&] { return containsElement(shape, Family::kShape, theType) ? kQ3True : kQ3False; });
}

TQ3Status Q3Shape_GetNextElementType(TQ3ShapeObject shape, TQ3ElementType* theType)
{
    return guardStatus(__func__, [&] { nextElementType(shape, Family::kShape, theType); });
}

TQ3Status Q3Shape_EmptyElements(TQ3ShapeObject shape)
{
    return guardStatus(__func__, [&] { emptyElements(shape, Family::kShape); });
}

TQ3Status Q3Shape_ClearElement(TQ3ShapeObject shape, TQ3ElementType theType)
{
    return guardStatus(__func__, [&] { clearElement(shape, Family::kShape, theType); });
}

TQ3Status Q3Object_AddElement(TQ3Object object, TQ3ElementType theType, const void* data)
{
    return guardStatus(__func__, [&] { addElement(object, Family::kObject, theType, data); });
}

TQ3Status Q3Object_GetElement(TQ3Object object, TQ3ElementType theType, void* data)
{
    return guardStatus(__func__, [&] { getElement(object, Family::kObject, theType, data); });
}

TQ3Boolean Q3Object_ContainsElement(TQ3Object object, TQ3ElementType theType)
{
    return guard(__func__, kQ3False,
                 [&] { return containsElement(object, Family::kObject, theType) ? kQ3True : kQ3False; });
}

TQ3Status Q3Object_GetNextElementType(TQ3Object object, TQ3ElementType* theType)
{
    return guardStatus(__func__, [&] { nextElementType(object, Family::kObject, theType); });
}

TQ3Status Q3Object_EmptyElements(TQ3Object object)
{
    return guardStatus(__func__, [&] { emptyElements(object, Family::kObject); });
}

TQ3Status Q3Object_ClearElement(TQ3Object object, TQ3ElementType theType)
{
    return guardStatus(__func__, [&] { clearElement(object, Family::kObject, theType); });
}

} // extern "C"
