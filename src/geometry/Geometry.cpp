// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Geometry.h"

namespace q3 {

const ClassInfo kGeometryClass{kQ3ShapeTypeGeometry, &kShapeClass, "geometry"};

Ref<AttributeSet> attributeSetFromHandle(TQ3AttributeSet handle, const char* name)
{
    if (handle == nullptr)
        return nullptr;
    return lookupRef<AttributeSet>(handle, name);
}

void Geometry::setAttributeSet(Ref<AttributeSet> attributes)
{
    m_attributes = std::move(attributes);
    markEdited();
}

TQ3AttributeSet attributeSetToHandle(const Ref<AttributeSet>& set)
{
    return Ref<AttributeSet>(set).detach();
}

TQ3AttributeSet attributeSetToHandle(const AttributeSet* set)
{
    // A reference count is bookkeeping, not part of the set's value, so a
    // const set may gain a holder.
    return Ref<AttributeSet>::retain(const_cast<AttributeSet*>(set)).detach();
}

Ref<AttributeSet> duplicateAttributeSet(const Ref<AttributeSet>& set)
{
    if (!set)
        return nullptr;
    return Ref<AttributeSet>::adopt(static_cast<AttributeSet*>(set->duplicate()));
}

} // namespace q3
