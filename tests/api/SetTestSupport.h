// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Helpers shared by the set and attribute set tests: a texture shader to
// store as the surface shader attribute, one well-formed value of every
// plain-data attribute type, a set's contents read back through the C
// calls, and the surface shader checks both kinds of set share.

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"

#include <array>
#include <cstring>
#include <optional>
#include <vector>

namespace q3test {

/// A 1 x 1 texture shader; the caller owns the one reference it is born with
/// (the shader holds the texture, the texture its storage).
inline TQ3ShaderObject newTextureShader()
{
    const unsigned char bytes[3] = {10, 20, 30};
    TQ3StorageObject storage = Q3MemoryStorage_New(bytes, 3);
    const TQ3StoragePixmap pixmap{storage, 1, 1, 3, 24, kQ3PixelTypeRGB24, kQ3EndianBig, kQ3EndianBig};
    TQ3TextureObject texture = Q3PixmapTexture_New(&pixmap);
    TQ3ShaderObject shader = Q3TextureShader_New(texture);
    Q3Object_Dispose(texture);
    Q3Object_Dispose(storage);
    return shader;
}

/// The bytes of one plain-data attribute value (24 hold the largest,
/// TQ3Tangent2D).
using AttributeBytes = std::array<unsigned char, 24>;

inline std::size_t attributeSize(TQ3AttributeType type)
{
    switch (type) {
    case kQ3AttributeTypeSurfaceUV:
    case kQ3AttributeTypeShadingUV:
        return sizeof(TQ3Param2D);
    case kQ3AttributeTypeNormal:
        return sizeof(TQ3Vector3D);
    case kQ3AttributeTypeAmbientCoefficient:
    case kQ3AttributeTypeSpecularControl:
        return sizeof(float);
    case kQ3AttributeTypeDiffuseColor:
    case kQ3AttributeTypeSpecularColor:
    case kQ3AttributeTypeTransparencyColor:
        return sizeof(TQ3ColorRGB);
    case kQ3AttributeTypeSurfaceTangent:
        return sizeof(TQ3Tangent2D);
    case kQ3AttributeTypeHighlightState:
        return sizeof(TQ3Switch);
    default:
        return 0;
    }
}

/// A well-formed value of a plain-data type (1 to 10); `seed` varies it.
inline AttributeBytes attributeValue(TQ3AttributeType type, float seed)
{
    AttributeBytes bytes{};
    if (type == kQ3AttributeTypeHighlightState) {
        const TQ3Switch value = seed > 0.5f ? kQ3On : kQ3Off;
        std::memcpy(bytes.data(), &value, sizeof value);
        return bytes;
    }
    float floats[6];
    for (int i = 0; i < 6; ++i)
        floats[i] = seed + 0.125f * float(i) + 0.0625f * float(type);
    std::memcpy(bytes.data(), floats, attributeSize(type));
    return bytes;
}

/// What a set holds, read through Q3Set_Contains and Q3Set_Get: for each
/// type 1 to 11 its bytes (a handle's for the surface shader, whose new
/// reference is released at once), or nothing.
struct SetContents {
    std::array<std::optional<AttributeBytes>, kQ3AttributeTypeNumTypes> values;
    bool operator==(const SetContents& other) const { return values == other.values; }
};

inline SetContents contentsOf(TQ3SetObject set)
{
    SetContents contents;
    for (TQ3AttributeType type = kQ3AttributeTypeSurfaceUV; type <= kQ3AttributeTypeSurfaceShader; ++type) {
        if (Q3Set_Contains(set, type) != kQ3True)
            continue;
        AttributeBytes bytes{};
        if (Q3Set_Get(set, type, bytes.data()) != kQ3Success)
            continue;
        if (type == kQ3AttributeTypeSurfaceShader) {
            TQ3Object shader;
            std::memcpy(&shader, bytes.data(), sizeof shader);
            Q3Object_Dispose(shader);
        }
        contents.values[type] = bytes;
    }
    return contents;
}

/// The types Q3Set_GetNextElementType walks through, in its order.
inline std::vector<TQ3ElementType> elementWalk(TQ3SetObject set)
{
    std::vector<TQ3ElementType> types;
    TQ3ElementType type = kQ3ElementTypeNone;
    while (Q3Set_GetNextElementType(set, &type) == kQ3Success && type != kQ3ElementTypeNone &&
           types.size() <= kQ3AttributeTypeNumTypes)
        types.push_back(type);
    return types;
}

/// The set and attribute set tests' fixture.
class SetApiTestBase : public OwningApiTest {
protected:
    using AddCall = TQ3Status (*)(TQ3Object, TQ3ElementType, const void*);
    using GetCall = TQ3Status (*)(TQ3Object, TQ3ElementType, void*);

    /// `set` (a set or an attribute set, used through its own `add` and
    /// `get`) takes a texture shader as its surface shader element; every
    /// value that is no live surface shader is refused with its code, keeps
    /// no reference and changes nothing.
    void expectOnlySurfaceShadersTaken(AddCall add, GetCall get, TQ3Object set)
    {
        TQ3ShaderObject texture = own(newTextureShader());
        ASSERT_EQ(add(set, kQ3AttributeTypeSurfaceShader, &texture), kQ3Success);
        const unsigned long edit = Q3Shared_GetEditIndex(set);
        for (TQ3ShaderObject illumination : {own(Q3LambertIllumination_New()), own(Q3PhongIllumination_New())}) {
            EXPECT_Q3_ERROR(EXPECT_EQ(add(set, kQ3AttributeTypeSurfaceShader, &illumination), kQ3Failure),
                            kQ3ErrorInvalidObjectType);
            EXPECT_EQ(referenceCount(illumination), 1UL);
        }
        EXPECT_Q3_ERROR(EXPECT_EQ(add(set, kQ3AttributeTypeSurfaceShader, &set), kQ3Failure),
                        kQ3ErrorInvalidObjectType);
        TQ3Object dead = newTextureShader();
        Q3Object_Dispose(dead);
        EXPECT_Q3_ERROR(EXPECT_EQ(add(set, kQ3AttributeTypeSurfaceShader, &dead), kQ3Failure), kQ3ErrorInvalidObject);
        TQ3Object none = nullptr;
        EXPECT_Q3_ERROR(EXPECT_EQ(add(set, kQ3AttributeTypeSurfaceShader, &none), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(add(set, kQ3AttributeTypeSurfaceShader, nullptr), kQ3Failure),
                        kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(get(set, kQ3AttributeTypeSurfaceShader, nullptr), kQ3Failure),
                        kQ3ErrorNULLParameter);
        EXPECT_EQ(Q3Shared_GetEditIndex(set), edit);
        EXPECT_EQ(referenceCount(texture), 2UL);
        expectSurfaceShaderHandedOut(get, set, texture);
    }

    /// `get` hands out `shader`, the surface shader element of `set`, with a
    /// reference of its own that disposing gives back.
    void expectSurfaceShaderHandedOut(GetCall get, TQ3Object set, TQ3ShaderObject shader)
    {
        const unsigned long held = referenceCount(shader);
        TQ3Object got = nullptr;
        EXPECT_EQ(get(set, kQ3AttributeTypeSurfaceShader, &got), kQ3Success);
        EXPECT_EQ(got, shader);
        EXPECT_EQ(referenceCount(shader), held + 1);
        Q3Object_Dispose(got);
        EXPECT_EQ(referenceCount(shader), held);
    }
};

} // namespace q3test
