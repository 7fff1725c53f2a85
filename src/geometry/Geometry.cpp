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

TQ3AttributeSet attributeSetToHandle(const Ref<AttributeSet>& set)
{
    return Ref<AttributeSet>(set).detach();
}

Ref<AttributeSet> duplicateAttributeSet(const Ref<AttributeSet>& set)
{
    if (!set)
        return nullptr;
    return Ref<AttributeSet>::adopt(static_cast<AttributeSet*>(set->duplicate()));
}

} // namespace q3
