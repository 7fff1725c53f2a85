// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/Entry.h"
#include "style/HighlightStyle.h"
#include "view/View.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

namespace {

// NULL is allowed: a highlight style without an attribute set.
Ref<AttributeSet> optionalSet(TQ3AttributeSet set)
{
    AttributeSet* found = lookupOptional<AttributeSet>(set, "highlightAttribute");
    return found == nullptr ? Ref<AttributeSet>() : Ref<AttributeSet>::retain(found);
}

} // namespace

extern "C" {

TQ3StyleObject Q3HighlightStyle_New(TQ3AttributeSet highlightAttribute)
{
    return guard(__func__, TQ3StyleObject{nullptr}, [&]() -> TQ3StyleObject {
        return makeShared<HighlightStyle>(optionalSet(highlightAttribute)).detach();
    });
}

TQ3Status Q3HighlightStyle_Submit(TQ3AttributeSet highlightAttribute, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        Ref<AttributeSet> attributes = optionalSet(highlightAttribute);
        ShapeVisitor& target = lookup<View>(view, "view").submitTarget();
        const HighlightStyle transient(std::move(attributes));
        target.visitStyle(transient);
    });
}

TQ3Status Q3HighlightStyle_Get(TQ3StyleObject highlight, TQ3AttributeSet* highlightAttribute)
{
    return api::getHeld(__func__, highlight, "highlight", highlightAttribute, "highlightAttribute",
                        &HighlightStyle::attributes);
}

TQ3Status Q3HighlightStyle_Set(TQ3StyleObject highlight, TQ3AttributeSet highlightAttribute)
{
    return api::setHeldOptional(__func__, highlight, "highlight", highlightAttribute, "highlightAttribute",
                                &HighlightStyle::setAttributes);
}

} // extern "C"
