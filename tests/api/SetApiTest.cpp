// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// QD3DSet.h's Q3Set_ calls: a plain set and an attribute set (which is a
// set), every attribute type as an element type, the surface shader held by
// reference, element types Q3 has no class for, bad handles, and failed
// calls leaving the set and its edit index unchanged.

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"
#include "SetTestSupport.h"

#include <climits>
#include <cstring>
#include <limits>
#include <vector>

namespace {

using namespace q3test;

class SetApiTest : public SetApiTestBase {
protected:
    TQ3SetObject newSet() { return own(Q3Set_New()); }

    // A new set holding one diffuse colour, with that colour's bytes, the
    // set's contents and its edit index after the Add.
    struct HeldColor {
        TQ3SetObject set;
        AttributeBytes color;
        SetContents before;
        unsigned long edit;
    };
    HeldColor setHoldingAColor()
    {
        TQ3SetObject set = newSet();
        const AttributeBytes color = attributeValue(kQ3AttributeTypeDiffuseColor, 0.5f);
        EXPECT_EQ(Q3Set_Add(set, kQ3AttributeTypeDiffuseColor, color.data()), kQ3Success);
        return {set, color, contentsOf(set), Q3Shared_GetEditIndex(set)};
    }
    TQ3Object deadSet()
    {
        TQ3SetObject set = Q3Set_New();
        Q3Object_Dispose(set);
        return set;
    }
    // A live shared object that is no set.
    TQ3Object notASet() { return own(Q3PhongIllumination_New()); }
};

const TQ3ElementType kUnknownTypes[] = {kQ3ElementTypeNone, kQ3AttributeTypeNumTypes, kQ3ElementTypeUnknown,
                                        kQ3ElementTypeSet, kQ3ElementTypeAttribute, -1, LONG_MAX, LONG_MIN};

TEST_F(SetApiTest, NewGivesAnEmptySetOfTheSetType)
{
    TQ3SetObject set = newSet();
    ASSERT_NE(set, nullptr);
    EXPECT_EQ(Q3Set_GetType(set), kQ3SharedTypeSet);
    EXPECT_EQ(Q3Object_GetLeafType(set), kQ3SharedTypeSet);
    EXPECT_EQ(Q3Object_IsType(set, kQ3SharedTypeSet), kQ3True);
    EXPECT_EQ(Q3Object_IsType(set, kQ3SetTypeAttribute), kQ3False);
    EXPECT_EQ(referenceCount(set), 1UL);
    EXPECT_TRUE(elementWalk(set).empty());
    for (TQ3ElementType type = kQ3AttributeTypeSurfaceUV; type <= kQ3AttributeTypeSurfaceShader; ++type)
        EXPECT_EQ(Q3Set_Contains(set, type), kQ3False) << type;

    TQ3AttributeSet attributes = own(Q3AttributeSet_New());
    EXPECT_EQ(Q3Set_GetType(attributes), kQ3SetTypeAttribute);
}

TEST_F(SetApiTest, EveryAttributeTypeIsAnElementType)
{
    TQ3SetObject set = newSet();
    for (TQ3ElementType type = kQ3AttributeTypeSurfaceUV; type <= kQ3AttributeTypeHighlightState; ++type) {
        const AttributeBytes value = attributeValue(type, 0.75f);
        const unsigned long before = Q3Shared_GetEditIndex(set);
        EXPECT_EQ(Q3Set_Add(set, type, value.data()), kQ3Success) << type;
        EXPECT_NE(Q3Shared_GetEditIndex(set), before) << type;
        EXPECT_EQ(Q3Set_Contains(set, type), kQ3True) << type;
        AttributeBytes got{};
        EXPECT_EQ(Q3Set_Get(set, type, got.data()), kQ3Success) << type;
        EXPECT_EQ(std::memcmp(got.data(), value.data(), attributeSize(type)), 0) << type;
        // Adding again replaces the value.
        const AttributeBytes other = attributeValue(type, 0.25f);
        EXPECT_EQ(Q3Set_Add(set, type, other.data()), kQ3Success) << type;
        EXPECT_EQ(Q3Set_Get(set, type, got.data()), kQ3Success) << type;
        EXPECT_EQ(std::memcmp(got.data(), other.data(), attributeSize(type)), 0) << type;
    }
    EXPECT_EQ(elementWalk(set).size(), 10U);

    const unsigned long before = Q3Shared_GetEditIndex(set);
    EXPECT_EQ(Q3Set_Clear(set, kQ3AttributeTypeNormal), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(set), before);
    EXPECT_EQ(Q3Set_Contains(set, kQ3AttributeTypeNormal), kQ3False);
    EXPECT_EQ(Q3Set_Contains(set, kQ3AttributeTypeDiffuseColor), kQ3True);
    EXPECT_EQ(Q3Set_Empty(set), kQ3Success);
    EXPECT_TRUE(elementWalk(set).empty());
}

TEST_F(SetApiTest, GetNextElementTypeWalksInTypeOrder)
{
    TQ3SetObject set = newSet();
    TQ3ShaderObject shader = own(newTextureShader());
    const AttributeBytes highlight = attributeValue(kQ3AttributeTypeHighlightState, 1.0f);
    const AttributeBytes color = attributeValue(kQ3AttributeTypeDiffuseColor, 0.5f);
    const AttributeBytes uv = attributeValue(kQ3AttributeTypeSurfaceUV, 0.5f);
    // Added out of order; walked in increasing order of type.
    ASSERT_EQ(Q3Set_Add(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    ASSERT_EQ(Q3Set_Add(set, kQ3AttributeTypeHighlightState, highlight.data()), kQ3Success);
    ASSERT_EQ(Q3Set_Add(set, kQ3AttributeTypeDiffuseColor, color.data()), kQ3Success);
    ASSERT_EQ(Q3Set_Add(set, kQ3AttributeTypeSurfaceUV, uv.data()), kQ3Success);
    const std::vector<TQ3ElementType> expected{kQ3AttributeTypeSurfaceUV, kQ3AttributeTypeDiffuseColor,
                                               kQ3AttributeTypeHighlightState, kQ3AttributeTypeSurfaceShader};
    EXPECT_EQ(elementWalk(set), expected);

    // A type the set does not hold continues after it.
    TQ3ElementType type = kQ3AttributeTypeShadingUV;
    EXPECT_EQ(Q3Set_GetNextElementType(set, &type), kQ3Success);
    EXPECT_EQ(type, kQ3AttributeTypeDiffuseColor);
    type = kQ3AttributeTypeSurfaceShader;
    EXPECT_EQ(Q3Set_GetNextElementType(set, &type), kQ3Success);
    EXPECT_EQ(type, kQ3ElementTypeNone);

    // Refusals leave *theType alone.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_GetNextElementType(set, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    for (TQ3ElementType bad : kUnknownTypes) {
        if (bad == kQ3ElementTypeNone)
            continue;
        type = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_GetNextElementType(set, &type), kQ3Failure), kQ3ErrorUnknownElementType);
        EXPECT_EQ(type, bad);
    }
    type = kQ3ElementTypeNone;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_GetNextElementType(nullptr, &type), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_GetNextElementType(deadSet(), &type), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_GetNextElementType(notASet(), &type), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(type, kQ3ElementTypeNone);
}

TEST_F(SetApiTest, ElementTypesWithoutAClassAreRefusedAndChangeNothing)
{
    const auto [set, color, before, edit] = setHoldingAColor();
    for (TQ3ElementType type : kUnknownTypes) {
        AttributeBytes data = color;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Add(set, type, data.data()), kQ3Failure), kQ3ErrorUnknownElementType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Get(set, type, data.data()), kQ3Failure), kQ3ErrorUnknownElementType);
        EXPECT_EQ(data, color);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Contains(set, type), kQ3False), kQ3ErrorUnknownElementType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Clear(set, type), kQ3Failure), kQ3ErrorUnknownElementType);
    }
    EXPECT_EQ(Q3Shared_GetEditIndex(set), edit);
    EXPECT_TRUE(contentsOf(set) == before);
}

TEST_F(SetApiTest, BadValuesAndMissingElementsChangeNothing)
{
    const auto [set, color, before, edit] = setHoldingAColor();

    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Add(set, kQ3AttributeTypeDiffuseColor, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    const TQ3ColorRGB nan{std::numeric_limits<float>::quiet_NaN(), 0, 0};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Add(set, kQ3AttributeTypeDiffuseColor, &nan), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    const TQ3Vector3D inf{0, std::numeric_limits<float>::infinity(), 0};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Add(set, kQ3AttributeTypeNormal, &inf), kQ3Failure), kQ3ErrorInvalidParameter);
    const int badSwitch = 7;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Add(set, kQ3AttributeTypeHighlightState, &badSwitch), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Get(set, kQ3AttributeTypeDiffuseColor, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    TQ3Vector3D normal{9, 9, 9};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Get(set, kQ3AttributeTypeNormal, &normal), kQ3Failure),
                    kQ3ErrorAttributeNotContained);
    EXPECT_EQ(normal.x, 9.0f);
    TQ3Object shader = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Get(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Failure),
                    kQ3ErrorAttributeNotContained);
    EXPECT_EQ(shader, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Clear(set, kQ3AttributeTypeNormal), kQ3Failure),
                    kQ3ErrorAttributeNotContained);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Clear(set, kQ3AttributeTypeSurfaceShader), kQ3Failure),
                    kQ3ErrorAttributeNotContained);
    EXPECT_EQ(Q3Shared_GetEditIndex(set), edit);
    EXPECT_TRUE(contentsOf(set) == before);
}

TEST_F(SetApiTest, EveryCallRefusesBadSetHandles)
{
    const AttributeBytes color = attributeValue(kQ3AttributeTypeDiffuseColor, 0.5f);
    struct Bad {
        TQ3Object handle;
        TQ3Error error;
    };
    const Bad bads[] = {{nullptr, kQ3ErrorNULLParameter},
                        {deadSet(), kQ3ErrorInvalidObject},
                        {notASet(), kQ3ErrorInvalidObjectType}};
    for (const Bad& bad : bads) {
        AttributeBytes data = color;
        TQ3ElementType type = kQ3ElementTypeNone;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_GetType(bad.handle), kQ3ObjectTypeInvalid), bad.error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Add(bad.handle, kQ3AttributeTypeDiffuseColor, data.data()), kQ3Failure),
                        bad.error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Get(bad.handle, kQ3AttributeTypeDiffuseColor, data.data()), kQ3Failure),
                        bad.error);
        EXPECT_EQ(data, color);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Contains(bad.handle, kQ3AttributeTypeDiffuseColor), kQ3False), bad.error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Clear(bad.handle, kQ3AttributeTypeDiffuseColor), kQ3Failure), bad.error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_Empty(bad.handle), kQ3Failure), bad.error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Set_GetNextElementType(bad.handle, &type), kQ3Failure), bad.error);
    }
}

TEST_F(SetApiTest, TheSurfaceShaderElementIsHeldByReference)
{
    TQ3ShaderObject shader = own(newTextureShader());
    ASSERT_NE(shader, nullptr);
    EXPECT_EQ(referenceCount(shader), 1UL);
    TQ3SetObject set = Q3Set_New();
    EXPECT_EQ(Q3Set_Add(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    EXPECT_EQ(referenceCount(shader), 2UL);
    // Adding it again replaces the reference: still one held by the set.
    EXPECT_EQ(Q3Set_Add(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    EXPECT_EQ(referenceCount(shader), 2UL);
    EXPECT_EQ(Q3Set_Contains(set, kQ3AttributeTypeSurfaceShader), kQ3True);
    expectSurfaceShaderHandedOut(Q3Set_Get, set, shader); // 3 references while handed out, then 2 again

    // A duplicate shares the shader.
    TQ3SetObject copy = Q3Object_Duplicate(set);
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(Q3Set_GetType(copy), kQ3SharedTypeSet);
    EXPECT_EQ(referenceCount(shader), 3UL);
    Q3Object_Dispose(copy);
    EXPECT_EQ(referenceCount(shader), 2UL);

    EXPECT_EQ(Q3Set_Clear(set, kQ3AttributeTypeSurfaceShader), kQ3Success);
    EXPECT_EQ(referenceCount(shader), 1UL);
    EXPECT_EQ(Q3Set_Add(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    EXPECT_EQ(Q3Set_Empty(set), kQ3Success);
    EXPECT_EQ(referenceCount(shader), 1UL);
    EXPECT_EQ(Q3Set_Add(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    EXPECT_EQ(referenceCount(shader), 2UL);
    Q3Object_Dispose(set);
    EXPECT_EQ(referenceCount(shader), 1UL);
}

TEST_F(SetApiTest, OnlyASurfaceShaderIsTakenAsTheSurfaceShaderElement)
{
    expectOnlySurfaceShadersTaken(Q3Set_Add, Q3Set_Get, newSet());
}

TEST_F(SetApiTest, AnAttributeSetIsASetButASetIsNoAttributeSet)
{
    TQ3AttributeSet attributes = own(Q3AttributeSet_New());
    TQ3ShaderObject shader = own(newTextureShader());
    const TQ3ColorRGB red{1, 0, 0};
    // Q3Set_ calls on an attribute set see what Q3AttributeSet_ calls store,
    // and the other way round.
    EXPECT_EQ(Q3Set_Add(attributes, kQ3AttributeTypeDiffuseColor, &red), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Contains(attributes, kQ3AttributeTypeDiffuseColor), kQ3True);
    EXPECT_EQ(Q3AttributeSet_Add(attributes, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    EXPECT_EQ(Q3Set_Contains(attributes, kQ3AttributeTypeSurfaceShader), kQ3True);
    const std::vector<TQ3ElementType> expected{kQ3AttributeTypeDiffuseColor, kQ3AttributeTypeSurfaceShader};
    EXPECT_EQ(elementWalk(attributes), expected);
    TQ3ColorRGB got{};
    EXPECT_EQ(Q3Set_Get(attributes, kQ3AttributeTypeDiffuseColor, &got), kQ3Success);
    EXPECT_EQ(got.r, 1.0f);
    EXPECT_EQ(Q3Set_Clear(attributes, kQ3AttributeTypeDiffuseColor), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Contains(attributes, kQ3AttributeTypeDiffuseColor), kQ3False);
    EXPECT_EQ(Q3Set_Empty(attributes), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Contains(attributes, kQ3AttributeTypeSurfaceShader), kQ3False);
    EXPECT_EQ(referenceCount(shader), 1UL);
    // A duplicate of an attribute set is an attribute set.
    TQ3SetObject copy = own(Q3Object_Duplicate(attributes));
    EXPECT_EQ(Q3Set_GetType(copy), kQ3SetTypeAttribute);

    TQ3SetObject set = newSet();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &red), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Empty(set), kQ3Failure), kQ3ErrorInvalidObjectType);
    TQ3AttributeType type = kQ3AttributeTypeNone;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_GetNextAttributeType(set, &type), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Inherit(set, attributes, attributes), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    boundsOf([&](TQ3ViewObject v) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Submit(set, v), kQ3Failure), kQ3ErrorInvalidObjectType);
    });
}

} // namespace
