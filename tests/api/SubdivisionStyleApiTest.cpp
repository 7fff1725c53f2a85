// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "Q3ApiTest.h"

#include "QD3DSet.h"
#include "QD3DStyle.h"

#include <limits>

namespace {

using SubdivisionStyleApiTest = q3test::Q3ApiTest;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TQ3SubdivisionStyleData dataOf(TQ3StyleObject style)
{
    TQ3SubdivisionStyleData data{};
    EXPECT_EQ(Q3SubdivisionStyle_GetData(style, &data), kQ3Success);
    return data;
}

TEST_F(SubdivisionStyleApiTest, ReasonableValuesAreKeptAsGiven)
{
    const TQ3SubdivisionStyleData article{kQ3SubdivisionMethodConstant, 5, 5};
    TQ3StyleObject style = Q3SubdivisionStyle_New(&article);
    ASSERT_NE(style, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(style), kQ3StyleTypeSubdivision);
    EXPECT_EQ(Q3Shape_GetType(style), kQ3ShapeTypeStyle);
    EXPECT_EQ(Q3Object_IsDrawable(style), kQ3True);
    TQ3SubdivisionStyleData got = dataOf(style);
    EXPECT_EQ(got.method, kQ3SubdivisionMethodConstant);
    EXPECT_EQ(got.c1, 5.0f);
    EXPECT_EQ(got.c2, 5.0f);
    const TQ3SubdivisionStyleData world{kQ3SubdivisionMethodWorldSpace, 0.125f, 3.5f};
    const unsigned long before = Q3Shared_GetEditIndex(style);
    EXPECT_EQ(Q3SubdivisionStyle_SetData(style, &world), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(style), before);
    got = dataOf(style);
    EXPECT_EQ(got.method, kQ3SubdivisionMethodWorldSpace);
    EXPECT_EQ(got.c1, 0.125f);
    EXPECT_EQ(got.c2, 3.5f);
    TQ3StyleObject copy = Q3Object_Duplicate(style);
    EXPECT_EQ(dataOf(copy).c2, 3.5f);
    Q3Object_Dispose(copy);
    Q3Object_Dispose(style);
}

TEST_F(SubdivisionStyleApiTest, UnreasonableValuesAreSubstitutedWithAWarning)
{
    struct Case {
        TQ3SubdivisionStyleData in;
        float c1;
        float c2;
    };
    const float big = static_cast<float>(kQ3SubdivisionMaxConstantSegments);
    for (const Case& c : {
             Case{{kQ3SubdivisionMethodConstant, 0.0f, 5}, 1, 5},
             Case{{kQ3SubdivisionMethodConstant, 0.5f, 5}, 1, 5},
             Case{{kQ3SubdivisionMethodConstant, -3, 5}, 1, 5},
             Case{{kQ3SubdivisionMethodConstant, 1e6f, 5}, big, 5},
             Case{{kQ3SubdivisionMethodConstant, kNaN, 5}, kQ3SubdivisionDefaultC1, 5},
             Case{{kQ3SubdivisionMethodConstant, 5, kInf}, 5, kQ3SubdivisionDefaultC1},
             Case{{kQ3SubdivisionMethodWorldSpace, 0, 1}, kQ3SubdivisionDefaultC1, 1},
             Case{{kQ3SubdivisionMethodWorldSpace, -kInf, 1}, kQ3SubdivisionDefaultC1, 1},
             Case{{kQ3SubdivisionMethodScreenSpace, 4, -2}, 4, kQ3SubdivisionDefaultC1},
             Case{{kQ3SubdivisionMethodScreenSpace, kNaN, kNaN}, kQ3SubdivisionDefaultC1,
                  kQ3SubdivisionDefaultC1},
         }) {
        TQ3StyleObject style = nullptr;
        EXPECT_Q3_WARNING(style = Q3SubdivisionStyle_New(&c.in), kQ3WarningParameterOutOfRange);
        ASSERT_NE(style, nullptr);
        EXPECT_STRNE(Q3Warning_GetMessage(), "");
        TQ3SubdivisionStyleData got = dataOf(style);
        EXPECT_EQ(got.c1, c.c1) << "c1 in " << c.in.c1;
        EXPECT_EQ(got.c2, c.c2) << "c2 in " << c.in.c2;
        // SetData applies the same rule.
        EXPECT_Q3_WARNING(EXPECT_EQ(Q3SubdivisionStyle_SetData(style, &c.in), kQ3Success),
                          kQ3WarningParameterOutOfRange);
        Q3Object_Dispose(style);
    }
}

TEST_F(SubdivisionStyleApiTest, AMethodOutsideTheEnumIsAnErrorThatChangesNothing)
{
    const TQ3SubdivisionStyleData good{kQ3SubdivisionMethodScreenSpace, 10, 10};
    TQ3StyleObject style = Q3SubdivisionStyle_New(&good);
    const unsigned long before = Q3Shared_GetEditIndex(style);
    for (int method : {-1, 3, 1000}) {
        TQ3SubdivisionStyleData bad = good;
        bad.method = static_cast<TQ3SubdivisionMethod>(method);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3SubdivisionStyle_New(&bad), nullptr), kQ3ErrorInvalidData);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3SubdivisionStyle_SetData(style, &bad), kQ3Failure), kQ3ErrorInvalidData);
    }
    EXPECT_EQ(Q3Shared_GetEditIndex(style), before);
    EXPECT_EQ(dataOf(style).method, kQ3SubdivisionMethodScreenSpace);
    EXPECT_Q3_ERROR(Q3SubdivisionStyle_New(nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SubdivisionStyle_SetData(style, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3SubdivisionStyle_GetData(style, nullptr), kQ3ErrorNULLParameter);
    TQ3SubdivisionStyleData out{};
    EXPECT_Q3_ERROR(Q3SubdivisionStyle_GetData(nullptr, &out), kQ3ErrorNULLParameter);
    TQ3AttributeSet notAStyle = Q3AttributeSet_New();
    EXPECT_Q3_ERROR(Q3SubdivisionStyle_GetData(notAStyle, &out), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(notAStyle);
    Q3Object_Dispose(style);
}

} // namespace
