// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <cstdint>
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

// ---- Per-vertex access (QuickDraw 3D 1.6) -------------------------------------

// Bad end indices: one past the last end, UINT32_MAX, and the largest unsigned
// long (which a narrowing to int would turn into 0 or -1).
const unsigned long kBadIndices[] = {2, std::numeric_limits<std::uint32_t>::max(),
                                     std::numeric_limits<unsigned long>::max()};

struct LineState {
    TQ3Point3D points[2];
    TQ3AttributeSet vertexSets[2];
    TQ3AttributeSet whole;
    unsigned long editIndex;
};

LineState stateOf(TQ3GeometryObject line)
{
    TQ3LineData data{};
    EXPECT_EQ(Q3Line_GetData(line, &data), kQ3Success);
    const LineState state{{data.vertices[0].point, data.vertices[1].point},
                          {data.vertices[0].attributeSet, data.vertices[1].attributeSet},
                          data.lineAttributeSet,
                          Q3Shared_GetEditIndex(line)};
    EXPECT_EQ(Q3Line_EmptyData(&data), kQ3Success);
    return state;
}

void expectSameState(const LineState& before, const LineState& after)
{
    for (int i = 0; i < 2; ++i) {
        EXPECT_EQ(before.points[i].x, after.points[i].x) << "end " << i;
        EXPECT_EQ(before.points[i].y, after.points[i].y) << "end " << i;
        EXPECT_EQ(before.points[i].z, after.points[i].z) << "end " << i;
        EXPECT_EQ(before.vertexSets[i], after.vertexSets[i]) << "end " << i;
    }
    EXPECT_EQ(before.whole, after.whole);
    EXPECT_EQ(before.editIndex, after.editIndex);
}

TEST_F(LineApiTest, GetVertexPositionReadsEitherEndAndRejectsOtherIndices)
{
    TQ3GeometryObject line = own(Q3Line_New(&m_data));
    ASSERT_NE(line, nullptr);
    for (unsigned long index : {0UL, 1UL}) {
        TQ3Point3D position{};
        ASSERT_EQ(Q3Line_GetVertexPosition(line, index, &position), kQ3Success);
        EXPECT_EQ(position.x, m_data.vertices[index].point.x);
        EXPECT_EQ(position.y, m_data.vertices[index].point.y);
        EXPECT_EQ(position.z, m_data.vertices[index].point.z);
    }
    for (unsigned long index : kBadIndices) {
        TQ3Point3D position{42, 42, 42};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_GetVertexPosition(line, index, &position), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_EQ(position.x, 42.0f); // unchanged on failure
    }
}

TEST_F(LineApiTest, SetVertexPositionMovesOneEndKeepsItsSetAndBumpsTheEditIndex)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    m_data.vertices[1].attributeSet = set;
    TQ3GeometryObject line = own(Q3Line_New(&m_data));
    ASSERT_NE(line, nullptr);
    const unsigned long edit = Q3Shared_GetEditIndex(line);
    const TQ3Point3D moved{7, 8, -9};
    EXPECT_EQ(Q3Line_SetVertexPosition(line, 1, &moved), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(line), edit);
    const LineState state = stateOf(line);
    EXPECT_EQ(state.points[1].x, 7.0f);
    EXPECT_EQ(state.points[1].y, 8.0f);
    EXPECT_EQ(state.points[1].z, -9.0f);
    EXPECT_EQ(state.points[0].x, 1.0f); // the other end stays put
    EXPECT_EQ(state.vertexSets[1], set);
    EXPECT_EQ(Q3Line_SetVertexPosition(line, 0, &moved), kQ3Success);
    TQ3Point3D position{};
    ASSERT_EQ(Q3Line_GetVertexPosition(line, 0, &position), kQ3Success);
    EXPECT_EQ(position.z, -9.0f);
}

TEST_F(LineApiTest, SetVertexPositionRejectsBadIndicesAndNonFiniteCoordinatesAndChangesNothing)
{
    TQ3GeometryObject line = own(Q3Line_New(&m_data));
    ASSERT_NE(line, nullptr);
    const LineState before = stateOf(line);
    const TQ3Point3D fine{1, 1, 1};
    for (unsigned long index : kBadIndices)
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_SetVertexPosition(line, index, &fine), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
    for (unsigned long index : {0UL, 1UL})
        for (int axis = 0; axis < 3; ++axis)
            for (float value : kNonFinite) {
                TQ3Point3D position = fine;
                float* coordinates[] = {&position.x, &position.y, &position.z};
                *coordinates[axis] = value;
                // The same code New and SetData post for the same coordinate.
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_SetVertexPosition(line, index, &position), kQ3Failure),
                                kQ3ErrorInvalidData);
            }
    const TQ3Point3D nan{kNaN, 0, 0};
    EXPECT_Q3_ERROR(Q3Line_SetVertexPosition(line, 2, &nan), kQ3ErrorParameterOutOfRange); // index first
    expectSameState(before, stateOf(line));
}

TEST_F(LineApiTest, VertexAttributeSetsAreReadAndReplacedWithBalancedReferences)
{
    TQ3AttributeSet first = own(Q3AttributeSet_New());
    TQ3AttributeSet second = own(Q3AttributeSet_New());
    m_data.vertices[0].attributeSet = first;
    TQ3GeometryObject line = Q3Line_New(&m_data);
    ASSERT_NE(line, nullptr);

    TQ3AttributeSet got = second;
    ASSERT_EQ(Q3Line_GetVertexAttributeSet(line, 1, &got), kQ3Success);
    EXPECT_EQ(got, nullptr); // none is NULL, and still a success
    ASSERT_EQ(Q3Line_GetVertexAttributeSet(line, 0, &got), kQ3Success);
    EXPECT_EQ(got, first);
    Q3Object_Dispose(got); // Get handed out a reference of the caller's own

    const unsigned long edit = Q3Shared_GetEditIndex(line);
    EXPECT_EQ(Q3Line_SetVertexAttributeSet(line, 0, second), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(line), edit);
    EXPECT_EQ(Q3Shared_IsReferenced(first), kQ3False); // the line let go of it
    EXPECT_EQ(Q3Line_SetVertexAttributeSet(line, 1, second), kQ3Success);
    EXPECT_EQ(Q3Line_SetVertexAttributeSet(line, 1, second), kQ3Success); // same set again
    const LineState state = stateOf(line);
    EXPECT_EQ(state.vertexSets[0], second);
    EXPECT_EQ(state.vertexSets[1], second);
    EXPECT_EQ(state.points[0].x, 1.0f); // positions are left alone

    EXPECT_EQ(Q3Line_SetVertexAttributeSet(line, 0, nullptr), kQ3Success);
    ASSERT_EQ(Q3Line_GetVertexAttributeSet(line, 0, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    EXPECT_EQ(Q3Shared_IsReferenced(second), kQ3True); // end 1 still holds it
    Q3Object_Dispose(line);
    EXPECT_EQ(Q3Shared_IsReferenced(second), kQ3False); // one reference per end, no more
}

TEST_F(LineApiTest, VertexAttributeSetCallsRejectBadIndicesAndArgumentsAndChangeNothing)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    m_data.vertices[0].attributeSet = set;
    TQ3GeometryObject line = own(Q3Line_New(&m_data));
    ASSERT_NE(line, nullptr);
    const TQ3PointData pointData{{0, 0, 0}, nullptr};
    TQ3GeometryObject notALine = own(Q3Point_New(&pointData));
    int notAnObject = 0;
    TQ3GeometryObject stray = reinterpret_cast<TQ3GeometryObject>(&notAnObject);
    const LineState before = stateOf(line);

    for (unsigned long index : kBadIndices) {
        TQ3AttributeSet got = set;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_GetVertexAttributeSet(line, index, &got), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_EQ(got, set); // unchanged on failure
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_SetVertexAttributeSet(line, index, nullptr), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
    }
    TQ3Point3D position{};
    TQ3AttributeSet got = nullptr;
    for (TQ3GeometryObject wrong : {static_cast<TQ3GeometryObject>(nullptr), notALine, stray}) {
        const TQ3Error code = wrong == nullptr    ? kQ3ErrorNULLParameter
                              : wrong == notALine ? kQ3ErrorInvalidObjectType
                                                  : kQ3ErrorInvalidObject;
        EXPECT_Q3_ERROR(Q3Line_GetVertexPosition(wrong, 0, &position), code);
        EXPECT_Q3_ERROR(Q3Line_SetVertexPosition(wrong, 0, &position), code);
        EXPECT_Q3_ERROR(Q3Line_GetVertexAttributeSet(wrong, 0, &got), code);
        EXPECT_Q3_ERROR(Q3Line_SetVertexAttributeSet(wrong, 0, set), code);
    }
    EXPECT_Q3_ERROR(Q3Line_GetVertexPosition(line, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Line_SetVertexPosition(line, 5, nullptr), kQ3ErrorNULLParameter); // before the index
    EXPECT_Q3_ERROR(Q3Line_GetVertexAttributeSet(line, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_SetVertexAttributeSet(line, 1, notALine), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Line_SetVertexAttributeSet(line, 5, stray), kQ3Failure),
                    kQ3ErrorInvalidObject);
    expectSameState(before, stateOf(line));
}

TEST_F(LineApiTest, AMovedEndIsBoundedWhereItNowIs)
{
    TQ3GeometryObject line = own(Q3Line_New(&m_data));
    ASSERT_NE(line, nullptr);
    const TQ3Point3D moved{10, -10, 0};
    ASSERT_EQ(Q3Line_SetVertexPosition(line, 0, &moved), kQ3Success);
    const TQ3BoundingBox box =
        boundsOf([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(line, v), kQ3Success); });
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_FLOAT_EQ(box.min.x, -4);
    EXPECT_FLOAT_EQ(box.min.y, -10);
    EXPECT_FLOAT_EQ(box.min.z, 0);
    EXPECT_FLOAT_EQ(box.max.x, 10);
    EXPECT_FLOAT_EQ(box.max.y, 5);
    EXPECT_FLOAT_EQ(box.max.z, 6);
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
    TQ3Point3D position{};
    TQ3AttributeSet set = nullptr;
    EXPECT_EQ(Q3Line_GetVertexPosition(nullptr, 0, &position), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Line_SetVertexPosition(nullptr, 0, &position), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Line_GetVertexAttributeSet(nullptr, 0, &set), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Line_SetVertexAttributeSet(nullptr, 0, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
}

} // namespace
