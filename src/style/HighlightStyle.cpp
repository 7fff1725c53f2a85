// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "style/HighlightStyle.h"

namespace q3 {

const ClassInfo kHighlightStyleClass{kQ3StyleTypeHighlight, &kStyleClass, "highlight style"};

Object* HighlightStyle::duplicate() const
{
    Ref<AttributeSet> copy;
    if (m_attributes)
        copy = Ref<AttributeSet>::adopt(static_cast<AttributeSet*>(m_attributes->duplicate()));
    return makeShared<HighlightStyle>(std::move(copy)).detach();
}

void HighlightStyle::setAttributes(Ref<AttributeSet> attributes)
{
    m_attributes = std::move(attributes);
    markEdited();
}

} // namespace q3
