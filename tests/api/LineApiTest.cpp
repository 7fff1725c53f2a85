// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <functional>
#include <limits>
#include <vector>

namespace {

using q3test::Q3ApiTest;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
const float kNonFinite[] = {kNaN, kInf, -kInf};

class LineApiTest : public q3test::OwningApiTest {
protected:
    TQ3LineData m_data{{{{1, -2, 3}, nullptr}, {{-4, 5, 6}, nullptr}}, nullptr};
};

TEST_F(LineApiTest, NewMakesALineThatGetDataReturns)
{
    TQ3GeometryObject line = own(Q3Line_New(&m_data));
    ASSERT_NE(line, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(line), kQ3GeometryTypeLine);
    EXPECT_EQ(Q3Geometry_GetType(line), kQ3GeometryTypeLine);
    EXPECT_EQ(Q3Object_IsDrawable(line), kQ3True);
    TQ3LineData out{};
    ASSERT_EQ(Q3Line_GetData(line, &out), kQ3Success);
    EXPECT_EQ(out.vertices[0].point.y, -2.0f);
    EXPECT_EQ(out.vertices[1].point.x, -4.0f);
    EXPECT_EQ(out.vertices[1].point.z, 6.0f);
    EXPECT_EQ(out.vertices[0].attributeSet, nullptr);
    EXPECT_EQ(out.lineAttributeSet, nullptr);
    EXPECT_EQ(Q3Line_EmptyData(&out), kQ3Success);
}

TEST_F(LineApiTest, AttributeSetsAreHeldByReferenceAndHandedOutWithNewOnes)
{
    TQ3AttributeSet end = own(Q3AttributeSet_New());
    TQ3AttributeSet whole = own(Q3AttributeSet_New());
    m_data.vertices[1].attributeSet = end;
    m_data.lineAttributeSet = whole;
    TQ3GeometryObject line = Q3Line_New(&m_data);
    ASSERT_NE(line, nullptr);
    EXPECT_EQ(Q3Shared_IsReferenced(end), kQ3True);
    EXPECT_EQ(Q3Shared_IsReferenced(whole), kQ3True);

    TQ3LineData out{};
    ASSERT_EQ(Q3Line_GetData(line, &out), kQ3Success);
    Q3Object_Dispose(line);
    EXPECT_EQ(out.vertices[0].attributeSet, nullptr);
    EXPECT_EQ(out.vertices[1].attributeSet, end);
    EXPECT_EQ(out.lineAttributeSet, whole);
    EXPECT_EQ(Q3Shared_IsReferenced(end), kQ3True); // GetData's reference
    ASSERT_EQ(Q3Line_EmptyData(&out), kQ3Success);
    EXPECT_EQ(out.vertices[1].attributeSet, nullptr);
    EXPECT_EQ(out.lineAttributeSet, nullptr);
    EXPECT_EQ(out.vertices[1].point.x, -4.0f); // the points are left alone
    EXPECT_EQ(Q3Line_EmptyData(&out), kQ3Success);
    EXPECT_EQ(Q3Shared_IsReferenced(end), kQ3False);
    EXPECT_EQ(Q3Shared_IsReferenced(whole), kQ3False);
}

TEST_F(LineApiTest, NewRejectsNullData)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_New(nullptr), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(LineApiTest, NewRejectsANonFiniteCoordinateInEitherEnd)
{
    for (int end = 0; end < 2; ++end)
        for (int axis = 0; axis < 3; ++axis)
            for (float bad : kNonFinite) {
                TQ3LineData data = m_data;
                float* coordinates[] = {&data.vertices[end].point.x, &data.vertices[end].point.y,
                                        &data.vertices[end].point.z};
                *coordinates[axis] = bad;
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_New(&data), nullptr), kQ3ErrorInvalidData);
            }
}

TEST_F(LineApiTest, NewRejectsBadAttributeSetHandlesAfterCoordinates)
{
    TQ3GeometryObject notASet = own(Q3Line_New(&m_data));
    int notAnObject = 0;
    TQ3AttributeSet stray = reinterpret_cast<TQ3AttributeSet>(&notAnObject);
    for (int slot = 0; slot < 3; ++slot) {
        TQ3LineData data = m_data;
        TQ3AttributeSet* field = slot < 2 ? &data.vertices[slot].attributeSet : &data.lineAttributeSet;
        *field = notASet;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_New(&data), nullptr), kQ3ErrorInvalidObjectType);
        *field = stray;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_New(&data), nullptr), kQ3ErrorInvalidObject);
        data.vertices[0].point.x = kNaN;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_New(&data), nullptr), kQ3ErrorInvalidData);
    }
}

TEST_F(LineApiTest, SetDataReplacesTheLineAndBumpsTheEditIndex)
{
    TQ3GeometryObject line = own(Q3Line_New(&m_data));
    ASSERT_NE(line, nullptr);
    const unsigned long edit = Q3Shared_GetEditIndex(line);
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    const TQ3LineData replacement{{{{0, 0, 0}, set}, {{9, 9, 9}, set}}, set};
    EXPECT_EQ(Q3Line_SetData(line, &replacement), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(line), edit);
    TQ3LineData out{};
    ASSERT_EQ(Q3Line_GetData(line, &out), kQ3Success);
    EXPECT_EQ(out.vertices[1].point.y, 9.0f);
    EXPECT_EQ(out.vertices[0].attributeSet, set);
    EXPECT_EQ(out.vertices[1].attributeSet, set);
    EXPECT_EQ(out.lineAttributeSet, set);
    Q3Line_EmptyData(&out);
}

TEST_F(LineApiTest, FailedSetDataChangesNothing)
{
    TQ3GeometryObject line = own(Q3Line_New(&m_data));
    ASSERT_NE(line, nullptr);
    const unsigned long edit = Q3Shared_GetEditIndex(line);
    TQ3LineData bad = m_data;
    bad.vertices[1].point.z = kInf;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_SetData(line, &bad), kQ3Failure), kQ3ErrorInvalidData);
    bad = m_data;
    bad.vertices[0].point.x = 50;
    bad.lineAttributeSet = line;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_SetData(line, &bad), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(Q3Shared_GetEditIndex(line), edit);
    TQ3LineData out{};
    ASSERT_EQ(Q3Line_GetData(line, &out), kQ3Success);
    EXPECT_EQ(out.vertices[0].point.x, 1.0f);
    EXPECT_EQ(out.vertices[1].point.z, 6.0f);
    Q3Line_EmptyData(&out);
}

TEST_F(LineApiTest, SetDataGetDataAndEmptyDataRejectBadArguments)
{
    TQ3GeometryObject line = own(Q3Line_New(&m_data));
    TQ3AttributeSet notALine = own(Q3AttributeSet_New());
    TQ3LineData out{};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_SetData(nullptr, &m_data), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_SetData(line, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_SetData(notALine, &m_data), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_GetData(nullptr, &out), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_GetData(line, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_GetData(notALine, &out), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_EmptyData(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
}

TEST_F(LineApiTest, DuplicateCopiesDeeplyAndKeepsASharedEndSetShared)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    m_data.vertices[0].attributeSet = set;
    m_data.vertices[1].attributeSet = set;
    TQ3GeometryObject line = own(Q3Line_New(&m_data));
    TQ3GeometryObject copy = own(static_cast<TQ3GeometryObject>(Q3Object_Duplicate(line)));
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(copy), kQ3GeometryTypeLine);
    TQ3LineData out{};
    ASSERT_EQ(Q3Line_GetData(copy, &out), kQ3Success);
    EXPECT_EQ(out.vertices[0].point.x, 1.0f);
    ASSERT_NE(out.vertices[0].attributeSet, nullptr);
    EXPECT_NE(out.vertices[0].attributeSet, set);
    EXPECT_EQ(out.vertices[0].attributeSet, out.vertices[1].attributeSet);
    EXPECT_EQ(out.lineAttributeSet, nullptr);
    Q3Line_EmptyData(&out);
}

TEST_F(LineApiTest, SubmitOutsideALoopFailsWithViewNotStarted)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_Submit(&m_data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    TQ3GeometryObject line = own(Q3Line_New(&m_data));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_Submit(line, view()), kQ3Failure), kQ3ErrorViewNotStarted);
}

TEST_F(LineApiTest, SubmitRejectsBadArguments)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_Submit(nullptr, view()), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_Submit(&m_data, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    TQ3AttributeSet notAView = own(Q3AttributeSet_New());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_Submit(&m_data, notAView), kQ3Failure), kQ3ErrorInvalidObjectType);
}

TEST_F(LineApiTest, ImmediateAndRetainedLinesBoundTheirEnds)
{
    TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) { EXPECT_EQ(Q3Line_Submit(&m_data, v), kQ3Success); });
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_FLOAT_EQ(box.min.x, -4);
    EXPECT_FLOAT_EQ(box.min.y, -2);
    EXPECT_FLOAT_EQ(box.min.z, 3);
    EXPECT_FLOAT_EQ(box.max.x, 1);
    EXPECT_FLOAT_EQ(box.max.y, 5);
    EXPECT_FLOAT_EQ(box.max.z, 6);
    TQ3GeometryObject line = own(Q3Line_New(&m_data));
    box = boundsOf([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(line, v), kQ3Success); });
    EXPECT_FLOAT_EQ(box.min.x, -4);
    EXPECT_FLOAT_EQ(box.max.y, 5);
}

TEST_F(LineApiTest, SubmitInsideALoopChecksTheDataRules)
{
    const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
        TQ3LineData bad = m_data;
        bad.vertices[0].point.y = -kInf;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_Submit(&bad, v), kQ3Failure), kQ3ErrorInvalidData);
        bad = m_data;
        bad.lineAttributeSet = v;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_Submit(&bad, v), kQ3Failure), kQ3ErrorInvalidObjectType);
    });
    EXPECT_EQ(box.isEmpty, kQ3True);
}

TEST(LineApiUninitialized, EveryFunctionFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    TQ3LineData data{};
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    EXPECT_EQ(Q3Line_New(&data), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Line_Submit(&data, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Line_GetData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Line_SetData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Line_EmptyData(&data), kQ3Failure);
    EXPECT_TRUE(failed());
}

} // namespace
