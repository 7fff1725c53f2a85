// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DSet.h"
#include "api/Entry.h"
#include "api/SetEntry.h"
#include "core/AttributeSet.h"

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
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookup<Set>(theSet, "theSet").leafType(); });
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
