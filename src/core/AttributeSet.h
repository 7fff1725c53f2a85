// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DSet.h"
#include "core/CustomClass.h"
#include "core/Object.h"

#include <array>
#include <cstddef>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/Ref.h"

namespace q3 {

extern const ClassInfo kSetClass;
extern const ClassInfo kAttributeSetClass;

/// The attributes Q3 stores, at most one of each: the plain-data standard
/// types (surface UV to highlight state) as values, and the surface shader
/// (type 11) as a reference to a shader object. What an attribute set
/// holds, and what a traversal's graphics state holds after attribute sets
/// were submitted. Invariant: every stored value is well formed; the
/// shader, when present, is a surface shader.
class AttributeValues {
public:
    static constexpr TQ3AttributeType kFirstType = kQ3AttributeTypeSurfaceUV;
    /// The last plain-data type; the surface shader follows it.
    static constexpr TQ3AttributeType kLastType = kQ3AttributeTypeHighlightState;

    bool contains(TQ3AttributeType type) const
    {
        if (type == kQ3AttributeTypeSurfaceShader)
            return static_cast<bool>(m_surfaceShader);
        return m_slots[type - kFirstType].has_value();
    }
    /// Copies a plain-data value out (data holds AttributeSet::dataSize(type)
    /// bytes); false when there is none.
    bool copy(TQ3AttributeType type, void* data, std::size_t size) const;
    /// Every attribute `other` has replaces this one's.
    void overlay(const AttributeValues& other);
    /// The surface shader (a texture shader, say), or null.
    SharedObject* surfaceShader() const { return m_surfaceShader.get(); }
    void setSurfaceShader(Ref<SharedObject> shader) { m_surfaceShader = std::move(shader); }

    template <class T>
    std::optional<T> find(TQ3AttributeType type) const
    {
        const auto& slot = m_slots[type - kFirstType];
        if (!slot)
            return std::nullopt;
        T value;
        static_assert(sizeof(T) <= sizeof(Slot), "attribute values fit a slot");
        std::memcpy(&value, slot->data(), sizeof value);
        return value;
    }

    std::optional<TQ3ColorRGB> diffuseColor() const { return find<TQ3ColorRGB>(kQ3AttributeTypeDiffuseColor); }
    std::optional<TQ3ColorRGB> specularColor() const { return find<TQ3ColorRGB>(kQ3AttributeTypeSpecularColor); }
    std::optional<TQ3ColorRGB> transparencyColor() const
    {
        return find<TQ3ColorRGB>(kQ3AttributeTypeTransparencyColor);
    }
    std::optional<float> ambientCoefficient() const { return find<float>(kQ3AttributeTypeAmbientCoefficient); }
    std::optional<float> specularControl() const { return find<float>(kQ3AttributeTypeSpecularControl); }
    std::optional<TQ3Vector3D> normal() const { return find<TQ3Vector3D>(kQ3AttributeTypeNormal); }
    std::optional<TQ3Param2D> surfaceUV() const { return find<TQ3Param2D>(kQ3AttributeTypeSurfaceUV); }
    std::optional<TQ3Param2D> shadingUV() const { return find<TQ3Param2D>(kQ3AttributeTypeShadingUV); }
    std::optional<TQ3Switch> highlightState() const { return find<TQ3Switch>(kQ3AttributeTypeHighlightState); }

private:
    friend class Set;
    using Slot = std::array<unsigned char, 24>;
    std::array<std::optional<Slot>, kLastType - kFirstType + 1> m_slots;
    Ref<SharedObject> m_surfaceShader;
};

/// A QuickDraw 3D set (Q3Set_New): elements by element type, at most one
/// of each. The element types Q3 has classes for are the standard attribute
/// types (surface UV to highlight state as values, the surface shader as a
/// reference to a shader object) and the custom element and attribute
/// classes registered (core/CustomClass.h: their data made by their own
/// methods), so a set stores what an attribute set stores, and the elements
/// a file gave it that Q3 has no class for (kept to be written back).
/// Invariant: every stored value is well formed (finite floats, a switch
/// that is kQ3On or kQ3Off, a live surface shader); add() checks before it
/// stores.
class Set : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SharedTypeSet;

    /// The first and last plain-data attribute types; the surface shader
    /// (kQ3AttributeTypeSurfaceShader, 11) is stored beside them as a
    /// reference.
    static constexpr TQ3AttributeType kFirstType = AttributeValues::kFirstType;
    static constexpr TQ3AttributeType kLastType = AttributeValues::kLastType;
    /// Every type a set can hold, in Q3AttributeSet_GetNextAttributeType's
    /// and Q3Set_GetNextElementType's order.
    static constexpr TQ3AttributeType kLastStoredType = kQ3AttributeTypeSurfaceShader;

    Set() = default;

    const ClassInfo& classInfo() const override { return kSetClass; }
    Object* duplicate() const override;

    /// Bytes of data of one attribute type (a handle's size for the surface
    /// shader, whose arrays hold a reference per element); throws
    /// kQ3ErrorAttributeInvalidType for a type Q3 does not store.
    static std::size_t dataSize(TQ3AttributeType type);
    /// Why a value of that (stored) type is not well formed (a component
    /// that is not finite, a switch that is neither kQ3On nor kQ3Off), or an
    /// empty string when it is.
    static std::string valueProblem(TQ3AttributeType type, const void* data);
    /// Throws kQ3ErrorUnknownElementType unless `type` is an element type Q3
    /// has a class for (the attribute types it stores, a registered custom
    /// class's): what the Q3Set_ calls check first, where the
    /// Q3AttributeSet_ calls report kQ3ErrorAttributeInvalidType.
    static void requireElementType(TQ3ElementType type);
    /// The registered custom element or attribute class of that type, or null.
    static std::shared_ptr<CustomClass> customClass(TQ3ElementType type);
    /// Throws kQ3ErrorAttributeInvalidType unless `type` is kQ3AttributeTypeNone
    /// or a type Q3 stores: where a walk over the types may start or go on.
    static void requireWalkType(TQ3AttributeType type);

    /// Stores a plain-data attribute (not the surface shader: addShader).
    void add(TQ3AttributeType type, const void* data);
    /// Copies a plain-data attribute out (not the surface shader: shader()).
    void get(TQ3AttributeType type, void* data) const;
    /// Stores the surface shader (the caller has checked it is one); the
    /// set holds a reference.
    void addShader(Ref<SharedObject> shader);
    SharedObject* shader() const { return m_values.surfaceShader(); }
    /// The next type the set holds after `type` (kQ3AttributeTypeNone starts
    /// the walk), or kQ3AttributeTypeNone after the last one: the standard
    /// types in their order, then the custom ones in ascending order.
    TQ3AttributeType nextType(TQ3AttributeType type) const;
    bool contains(TQ3AttributeType type) const;
    /// Removes one attribute; kQ3ErrorAttributeNotContained when there is none.
    void clear(TQ3AttributeType type);
    void empty();

    const AttributeValues& values() const { return m_values; }
    /// Objects a file held in the set that Q3 has no attribute for (unknown
    /// elements), in file order: kept and written back unchanged.
    const std::vector<Ref<SharedObject>>& otherElements() const { return m_others; }
    void addOtherElement(Ref<SharedObject> element);
    /// The custom elements, by type.
    const std::map<TQ3ElementType, std::unique_ptr<CustomElement>>& customElements() const { return m_custom; }
    /// Stores a custom element made elsewhere (a file's).
    void addCustomElement(std::unique_ptr<CustomElement> element);
    /// Hands every custom element over to the caller (the set keeps none):
    /// a file's elements, read into a set of their own, move to their object.
    std::vector<std::unique_ptr<CustomElement>> takeCustomElements();

protected:
    /// Gives `copy` this set's values and unknown elements (shared).
    void copyContentsTo(Set& copy) const;

    AttributeValues m_values;
    std::vector<Ref<SharedObject>> m_others;
    std::map<TQ3ElementType, std::unique_ptr<CustomElement>> m_custom;

private:
    static std::size_t slotIndex(TQ3AttributeType type);
    /// The custom class of `type` when it is one, null when it is a standard
    /// type; throws as slotIndex for any other.
    static std::shared_ptr<CustomClass> checkedType(TQ3AttributeType type);
};

/// A set of QuickDraw 3D attributes (colors, normals, UVs, a surface
/// shader, ...): the set a view draws with (submitted, it overlays the
/// traversal's attributes). Invariant: as Set's.
class AttributeSet final : public Set {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SetTypeAttribute;

    AttributeSet() = default;

    const ClassInfo& classInfo() const override { return kAttributeSetClass; }
    Object* duplicate() const override;
    bool isDrawable() const override { return true; }
    void accept(ShapeVisitor& visitor) const override;

    /// Copies into this set every attribute of `other` (others' values win).
    void inheritFrom(const AttributeSet& other);
    /// Replaces this set's contents by child's attributes and those of
    /// parent's that child lacks (Q3AttributeSet_Inherit); either may be
    /// this set. Unknown elements are not attributes: none is inherited,
    /// and this set's own are dropped.
    void inherit(const AttributeSet& parent, const AttributeSet& child);
    /// A new set holding these values.
    static Ref<AttributeSet> fromValues(const AttributeValues& values);

    /// The value of one attribute, or nullopt when the set has none.
    std::optional<TQ3ColorRGB> diffuseColor() const { return m_values.diffuseColor(); }
    std::optional<TQ3ColorRGB> transparencyColor() const { return m_values.transparencyColor(); }
    std::optional<TQ3Vector3D> normal() const { return m_values.normal(); }
    std::optional<TQ3Param2D> surfaceUV() const { return m_values.surfaceUV(); }
    std::optional<TQ3Param2D> shadingUV() const { return m_values.shadingUV(); }
};

/// The elements an object keeps itself (QD3D.h: a shape's elements are
/// attached to it directly, not through a set): a set holding them, and the
/// set attached as the element kQ3ElementTypeSet (Q3Shape_SetSet).
struct ObjectElements {
    Ref<Set> own;
    Ref<Set> attached;
    /// The set of own elements, made when first needed.
    Set& ownSet();
};

} // namespace q3
