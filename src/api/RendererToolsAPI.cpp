// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DRenderer.h's renderer tools that have a meaning without plug-in
// renderers: progress and end-of-frame reports to a view, and an attribute
// set's mask.
#include "QD3DRenderer.h"

#include "api/Entry.h"
#include "core/AttributeSet.h"
#include "view/View.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3Status Q3XView_IdleProgress(TQ3ViewObject view, unsigned long current, unsigned long completed)
{
    return guard(__func__, kQ3Failure, [&] {
        View& target = lookup<View>(view, "view");
        if (current > completed)
            fail(kQ3ErrorInvalidParameter, "current is above completed");
        return target.idleProgress(current, completed) ? kQ3Success : kQ3Failure;
    });
}

TQ3Status Q3XView_EndFrame(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").endFrame(); });
}

TQ3XAttributeMask Q3XAttributeSet_GetMask(TQ3AttributeSet attributeSet)
{
    return guard(__func__, TQ3XAttributeMask{0}, [&] {
        const AttributeSet& set = lookup<AttributeSet>(attributeSet, "attributeSet");
        TQ3XAttributeMask mask = kQ3XAttributeMaskNone;
        for (TQ3AttributeType type = set.nextType(kQ3AttributeTypeNone); type != kQ3AttributeTypeNone;
             type = set.nextType(type))
            mask |= type > kQ3AttributeTypeNone && type < kQ3AttributeTypeNumTypes
                        ? TQ3XAttributeMask{1} << (type - 1)
                        : kQ3XAttributeMaskCustomAttribute;
        return mask;
    });
}

} // extern "C"
