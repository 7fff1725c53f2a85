// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DSet.h"
#include "core/Object.h"

#include <array>
#include <cstddef>
#include <cstring>
#include <optional>
#include <string>

namespace q3 {

extern const ClassInfo kSetClass;
extern const ClassInfo kAttributeSetClass;

/// A set of QuickDraw 3D attributes (colors, normals, UVs, ...), at most one
/// of each type. Invariant: every stored value is well formed (finite floats,
/// a switch that is kQ3On or kQ3Off); add() checks before it stores.
class AttributeSet final : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SetTypeAttribute;

    /// The first and last attribute types Q3 stores: the plain-data types
    /// (surface shaders, type 11, are objects Q3 does not have).
    static constexpr TQ3AttributeType kFirstType = kQ3AttributeTypeSurfaceUV;
    static constexpr TQ3AttributeType kLastType = kQ3AttributeTypeHighlightState;

    AttributeSet() = default;

    const ClassInfo& classInfo() const override { return kAttributeSetClass; }
    Object* duplicate() const override;
    bool isDrawable() const override { return true; }
    void accept(ShapeVisitor& visitor) const override;

    /// Bytes of data of one attribute type; throws kQ3ErrorAttributeInvalidType
    /// for a type Q3 does not store.
    static std::size_t dataSize(TQ3AttributeType type);
    /// Why a value of that (stored) type is not well formed (a component
    /// that is not finite, a switch that is neither kQ3On nor kQ3Off), or an
    /// empty string when it is.
    static std::string valueProblem(TQ3AttributeType type, const void* data);

    void add(TQ3AttributeType type, const void* data);
    void get(TQ3AttributeType type, void* data) const;
    bool contains(TQ3AttributeType type) const;
    void clear(TQ3AttributeType type);
    void empty();

    /// Copies into this set every attribute of `other` (others' values win).
    void inheritFrom(const AttributeSet& other);
    /// The value of one attribute, or nullopt when the set has none.
    std::optional<TQ3ColorRGB> diffuseColor() const { return find<TQ3ColorRGB>(kQ3AttributeTypeDiffuseColor); }
    std::optional<TQ3ColorRGB> transparencyColor() const
    {
        return find<TQ3ColorRGB>(kQ3AttributeTypeTransparencyColor);
    }
    std::optional<TQ3Vector3D> normal() const { return find<TQ3Vector3D>(kQ3AttributeTypeNormal); }
    std::optional<TQ3Param2D> surfaceUV() const { return find<TQ3Param2D>(kQ3AttributeTypeSurfaceUV); }

private:
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

    using Slot = std::array<unsigned char, 24>;
    static std::size_t slotIndex(TQ3AttributeType type);

    std::array<std::optional<Slot>, kLastType> m_slots;
};

} // namespace q3
