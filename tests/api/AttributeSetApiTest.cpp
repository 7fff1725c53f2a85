// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "Q3ApiTest.h"

#include "QD3DSet.h"

#include <limits>

namespace {

using AttributeSetApiTest = q3test::Q3ApiTest;

TEST_F(AttributeSetApiTest, AddGetContainsClearAndEmpty)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    ASSERT_NE(set, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(set), kQ3SetTypeAttribute);
    EXPECT_EQ(Q3Shared_GetType(set), kQ3SharedTypeSet);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeDiffuseColor), kQ3False);
    const TQ3ColorRGB color{0.25f, 0.5f, 0.75f};
    const unsigned long before = Q3Shared_GetEditIndex(set);
    EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(set), before);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeDiffuseColor), kQ3True);
    TQ3ColorRGB got{};
    EXPECT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, &got), kQ3Success);
    EXPECT_EQ(got.r, 0.25f);
    EXPECT_EQ(got.g, 0.5f);
    EXPECT_EQ(got.b, 0.75f);
    const float coefficient = 0.5f;
    EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeAmbientCoefficient, &coefficient), kQ3Success);
    const TQ3Switch highlight = kQ3On;
    EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeHighlightState, &highlight), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Clear(set, kQ3AttributeTypeDiffuseColor), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeDiffuseColor), kQ3False);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, &got), kQ3Failure),
                    kQ3ErrorAttributeNotContained);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Clear(set, kQ3AttributeTypeDiffuseColor), kQ3Failure),
                    kQ3ErrorAttributeNotContained);
    EXPECT_EQ(Q3AttributeSet_Empty(set), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeAmbientCoefficient), kQ3False);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeHighlightState), kQ3False);
    Q3Object_Dispose(set);
}

TEST_F(AttributeSetApiTest, RejectsBadTypesPointersAndValues)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB color{1, 1, 1};
    for (TQ3AttributeType type : {TQ3AttributeType{kQ3AttributeTypeNone},
                                  TQ3AttributeType{kQ3AttributeTypeSurfaceShader}, TQ3AttributeType{99},
                                  TQ3AttributeType{-1}}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Add(set, type, &color), kQ3Failure),
                        kQ3ErrorAttributeInvalidType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Contains(set, type), kQ3False), kQ3ErrorAttributeInvalidType);
    }
    EXPECT_Q3_ERROR(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, nullptr), kQ3ErrorNULLParameter);
    TQ3ColorRGB out{};
    EXPECT_Q3_ERROR(Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, nullptr), kQ3ErrorNULLParameter);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (TQ3ColorRGB bad : {TQ3ColorRGB{nan, 0, 0}, TQ3ColorRGB{0, inf, 0}, TQ3ColorRGB{0, 0, -inf}})
        EXPECT_Q3_ERROR(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &bad), kQ3ErrorInvalidParameter);
    const int badSwitch = 7;
    EXPECT_Q3_ERROR(Q3AttributeSet_Add(set, kQ3AttributeTypeHighlightState, &badSwitch),
                    kQ3ErrorInvalidParameter);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeDiffuseColor), kQ3False);
    EXPECT_Q3_ERROR(Q3AttributeSet_Get(nullptr, kQ3AttributeTypeDiffuseColor, &out), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3AttributeSet_Empty(nullptr), kQ3ErrorNULLParameter);
    Q3Object_Dispose(set);
    EXPECT_Q3_ERROR(Q3AttributeSet_Empty(set), kQ3ErrorInvalidObject);
}

TEST_F(AttributeSetApiTest, DuplicateCopiesValuesIndependently)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB red{1, 0, 0};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &red);
    TQ3AttributeSet copy = Q3Object_Duplicate(set);
    ASSERT_NE(copy, nullptr);
    ASSERT_NE(copy, set);
    Q3AttributeSet_Clear(set, kQ3AttributeTypeDiffuseColor);
    TQ3ColorRGB got{};
    EXPECT_EQ(Q3AttributeSet_Get(copy, kQ3AttributeTypeDiffuseColor, &got), kQ3Success);
    EXPECT_EQ(got.r, 1.0f);
    Q3Object_Dispose(copy);
    Q3Object_Dispose(set);
}

} // namespace
