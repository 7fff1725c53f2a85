// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DSet.h"
#include "api/Entry.h"
#include "api/SetEntry.h"
#include "core/AttributeSet.h"
#include "view/View.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3Status Q3Attribute_Submit(TQ3AttributeType attributeType, const void* data, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        // A one-attribute set submitted in its place: one path for both.
        Ref<AttributeSet> set = makeShared<AttributeSet>();
        api::addElement(*set, attributeType, data);
        set->accept(lookup<View>(view, "view").submitTarget());
    });
}

TQ3AttributeSet Q3AttributeSet_New(void)
{
    return guard(__func__, TQ3AttributeSet{nullptr},
                 []() -> TQ3AttributeSet { return makeShared<AttributeSet>().detach(); });
}

TQ3Status Q3AttributeSet_Add(TQ3AttributeSet attributeSet, TQ3AttributeType theType, const void* data)
{
    return guardStatus(__func__, [&] {
        api::addElement(lookup<AttributeSet>(attributeSet, "attributeSet"), theType, data);
    });
}

TQ3Boolean Q3AttributeSet_Contains(TQ3AttributeSet attributeSet, TQ3AttributeType attributeType)
{
    return guard(__func__, kQ3False, [&] {
        return lookup<AttributeSet>(attributeSet, "attributeSet").contains(attributeType) ? kQ3True
                                                                                          : kQ3False;
    });
}

TQ3Status Q3AttributeSet_Get(TQ3AttributeSet attributeSet, TQ3AttributeType theType, void* data)
{
    return guardStatus(__func__, [&] {
        api::getElement(lookup<AttributeSet>(attributeSet, "attributeSet"), theType, data);
    });
}

TQ3Status Q3AttributeSet_Clear(TQ3AttributeSet attributeSet, TQ3AttributeType theType)
{
    return guardStatus(__func__,
                       [&] { lookup<AttributeSet>(attributeSet, "attributeSet").clear(theType); });
}

TQ3Status Q3AttributeSet_Empty(TQ3AttributeSet target)
{
    return guardStatus(__func__, [&] { lookup<AttributeSet>(target, "target").empty(); });
}

TQ3Status Q3AttributeSet_GetNextAttributeType(TQ3AttributeSet source, TQ3AttributeType* theType)
{
    return getValue<AttributeSet>(__func__, source, "source", theType, "theType",
                                  [&](const AttributeSet& set) { return set.nextType(*theType); });
}

TQ3Status Q3AttributeSet_Submit(TQ3AttributeSet attributeSet, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        const AttributeSet& set = lookup<AttributeSet>(attributeSet, "attributeSet");
        set.accept(lookup<View>(view, "view").submitTarget());
    });
}

TQ3Status Q3AttributeSet_Inherit(TQ3AttributeSet parent, TQ3AttributeSet child, TQ3AttributeSet result)
{
    return guardStatus(__func__, [&] {
        const AttributeSet& from = lookup<AttributeSet>(parent, "parent");
        const AttributeSet& over = lookup<AttributeSet>(child, "child");
        lookup<AttributeSet>(result, "result").inherit(from, over);
    });
}

} // extern "C"
