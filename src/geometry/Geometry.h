// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/AttributeSet.h"
#include "core/Object.h"

namespace q3 {

extern const ClassInfo kGeometryClass;

/// Every QuickDraw 3D geometry: a drawable shared object. Invariant: it holds
/// one reference to its own attribute set (the curveAttributeSet,
/// polyLineAttributeSet, lineAttributeSet or pointAttributeSet of its data),
/// if it has one.
class Geometry : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapeTypeGeometry;
    bool isDrawable() const override { return true; }

    /// The geometry's own attribute set, or null.
    const AttributeSet* attributeSet() const { return m_attributes.get(); }
    /// Replaces the geometry's own attribute set (null removes it); an edit.
    void setAttributeSet(Ref<AttributeSet> attributes);

protected:
    Geometry() = default;

    const Ref<AttributeSet>& attributeSetRef() const { return m_attributes; }
    /// As setAttributeSet but not an edit by itself: for constructors,
    /// duplicate() and the assign() step of setData, which marks the edit.
    void replaceAttributeSet(Ref<AttributeSet> attributes) { m_attributes = std::move(attributes); }

private:
    Ref<AttributeSet> m_attributes;
};

/// The attribute set a geometry's data names: null stays null; a handle must
/// be a live attribute set (kQ3ErrorInvalidObject / kQ3ErrorInvalidObjectType
/// otherwise). `name` is the field's name for the message.
Ref<AttributeSet> attributeSetFromHandle(TQ3AttributeSet handle, const char* name);

/// A new reference to a geometry's attribute set, for GetData (NULL stays NULL).
TQ3AttributeSet attributeSetToHandle(const Ref<AttributeSet>& set);
TQ3AttributeSet attributeSetToHandle(const AttributeSet* set);

/// Deep copy of an attribute set for Duplicate (null stays null).
Ref<AttributeSet> duplicateAttributeSet(const Ref<AttributeSet>& set);

} // namespace q3
