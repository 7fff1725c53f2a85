// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DSet.h"
#include "api/Entry.h"
#include "core/AttributeSet.h"
#include "shader/TextureShader.h"
#include "view/View.h"

#include <cstring>

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3AttributeSet Q3AttributeSet_New(void)
{
    return guard(__func__, TQ3AttributeSet{nullptr},
                 []() -> TQ3AttributeSet { return makeShared<AttributeSet>().detach(); });
}

TQ3Status Q3AttributeSet_Add(TQ3AttributeSet attributeSet, TQ3AttributeType theType, const void* data)
{
    return guardStatus(__func__, [&] {
        AttributeSet& set = lookup<AttributeSet>(attributeSet, "attributeSet");
        if (theType != kQ3AttributeTypeSurfaceShader)
            return set.add(theType, data);
        requireNonNull(data, "data");
        TQ3Object handle;
        std::memcpy(&handle, data, sizeof handle);
        set.addShader(Ref<SharedObject>(lookupRef<SurfaceShader>(handle, "*data (the surface shader)")));
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
        const AttributeSet& set = lookup<AttributeSet>(attributeSet, "attributeSet");
        if (theType != kQ3AttributeTypeSurfaceShader)
            return set.get(theType, data);
        requireNonNull(data, "data");
        if (set.shader() == nullptr)
            fail(kQ3ErrorAttributeNotContained, "the set holds no surface shader");
        TQ3Object handle = Ref<SharedObject>::retain(set.shader()).detach();
        std::memcpy(data, &handle, sizeof handle);
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

TQ3Status Q3AttributeSet_Submit(TQ3AttributeSet attributeSet, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        const AttributeSet& set = lookup<AttributeSet>(attributeSet, "attributeSet");
        set.accept(lookup<View>(view, "view").submitTarget());
    });
}

} // extern "C"
