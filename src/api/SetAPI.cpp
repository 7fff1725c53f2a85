// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DSet.h"
#include "api/Entry.h"
#include "api/SetEntry.h"
#include "core/AttributeSet.h"
#include "core/CustomClass.h"
#include "io/ClassIO.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3SetObject Q3Set_New(void)
{
    return guard(__func__, TQ3SetObject{nullptr}, []() -> TQ3SetObject { return makeShared<Set>().detach(); });
}

TQ3ObjectType Q3Set_GetType(TQ3SetObject theSet)
{
    return api::getLeafType<Set>(__func__, theSet, "theSet");
}

TQ3Status Q3Set_Add(TQ3SetObject theSet, TQ3ElementType theType, const void* data)
{
    return guardStatus(__func__, [&] {
        Set& set = lookup<Set>(theSet, "theSet");
        Set::requireElementType(theType);
        api::addElement(set, theType, data);
    });
}

TQ3Status Q3Set_Get(TQ3SetObject theSet, TQ3ElementType theType, void* data)
{
    return guardStatus(__func__, [&] {
        const Set& set = lookup<Set>(theSet, "theSet");
        Set::requireElementType(theType);
        api::getElement(set, theType, data);
    });
}

TQ3Boolean Q3Set_Contains(TQ3SetObject theSet, TQ3ElementType theType)
{
    return guard(__func__, kQ3False, [&] {
        const Set& set = lookup<Set>(theSet, "theSet");
        Set::requireElementType(theType);
        return set.contains(theType) ? kQ3True : kQ3False;
    });
}

TQ3Status Q3Set_Clear(TQ3SetObject theSet, TQ3ElementType theType)
{
    return guardStatus(__func__, [&] {
        Set& set = lookup<Set>(theSet, "theSet");
        Set::requireElementType(theType);
        set.clear(theType);
    });
}

TQ3Status Q3Set_Empty(TQ3SetObject target)
{
    return guardStatus(__func__, [&] { lookup<Set>(target, "target").empty(); });
}

TQ3Status Q3Set_GetNextElementType(TQ3SetObject theSet, TQ3ElementType* theType)
{
    return guardStatus(__func__, [&] {
        const Set& set = lookup<Set>(theSet, "theSet");
        requireNonNull(theType, "theType");
        if (*theType != kQ3ElementTypeNone)
            Set::requireElementType(*theType);
        *theType = set.nextType(*theType);
    });
}

} // extern "C"

// Custom element and attribute classes (QD3DSet.h's registration section).

namespace {

TQ3XObjectClass registerElementClass(CustomClass::Kind kind, TQ3ElementType* elementType, const char* name,
                                     const char* nameParameter, unsigned long size, TQ3XMetaHandler metaHandler)
{
    requireNonNull(elementType, kind == CustomClass::Kind::kAttribute ? "attributeType" : "elementType");
    requireNonNull(name, nameParameter);
    if (io::typeOfName(name) != 0)
        fail(kQ3ErrorInvalidParameter, std::string("a class named \"") + name + "\" is registered already");
    const TQ3ObjectType parent =
        kind == CustomClass::Kind::kAttribute ? TQ3ObjectType{kQ3ElementTypeAttribute} : kQ3ObjectTypeElement;
    std::shared_ptr<CustomClass> made =
        registerCustomClass(kind, *elementType, parent, name, size, metaHandler, nullptr);
    *elementType = made->type();
    return made->handle();
}

} // namespace

extern "C" {

TQ3XObjectClass Q3XElementClass_Register(TQ3ElementType* elementType, const char* name, unsigned long sizeOfElement,
                                         TQ3XMetaHandler metaHandler)
{
    return guard(__func__, TQ3XObjectClass{nullptr}, [&] {
        return registerElementClass(CustomClass::Kind::kElement, elementType, name, "name", sizeOfElement,
                                    metaHandler);
    });
}

TQ3Status Q3XElementType_GetElementSize(TQ3ElementType elementType, unsigned long* sizeOfElement)
{
    return guardStatus(__func__, [&] {
        const std::shared_ptr<CustomClass> custom = Set::customClass(elementType);
        if (!custom)
            fail(kQ3ErrorUnknownElementType,
                 "element type " + std::to_string(elementType) + " is no registered custom element class");
        requireNonNull(sizeOfElement, "sizeOfElement");
        *sizeOfElement = static_cast<unsigned long>(custom->size());
    });
}

TQ3XObjectClass Q3XAttributeClass_Register(TQ3AttributeType* attributeType, const char* creatorName,
                                           unsigned long sizeOfElement, TQ3XMetaHandler metaHandler)
{
    return guard(__func__, TQ3XObjectClass{nullptr}, [&] {
        return registerElementClass(CustomClass::Kind::kAttribute, attributeType, creatorName, "creatorName",
                                    sizeOfElement, metaHandler);
    });
}

} // extern "C"
