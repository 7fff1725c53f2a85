// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/AttributeSet.h"
#include "core/Object.h"

namespace q3 {

extern const ClassInfo kGeometryClass;

/// Every QuickDraw 3D geometry: a drawable shared object.
class Geometry : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapeTypeGeometry;
    bool isDrawable() const override { return true; }

protected:
    Geometry() = default;
};

/// The attribute set a geometry's data names: null stays null; a handle must
/// be a live attribute set (kQ3ErrorInvalidObject / kQ3ErrorInvalidObjectType
/// otherwise). `name` is the field's name for the message.
Ref<AttributeSet> attributeSetFromHandle(TQ3AttributeSet handle, const char* name);

/// A new reference to a geometry's attribute set, for GetData (NULL stays NULL).
TQ3AttributeSet attributeSetToHandle(const Ref<AttributeSet>& set);

/// Deep copy of an attribute set for Duplicate (null stays null).
Ref<AttributeSet> duplicateAttributeSet(const Ref<AttributeSet>& set);

} // namespace q3
