// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// What is the point's own among the Q3Point_* calls: bounds, Get and
// SetPosition, and the calls before Q3Initialize. New, GetData, SetData,
// EmptyData, Submit and Duplicate are tried by the contract suite
// (GeometryContractTest.cpp).

#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DView.h"

#include <functional>
#include <limits>
#include <vector>

namespace {

using q3test::Q3ApiTest;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
const float kNonFinite[] = {kNaN, kInf, -kInf};

class PointApiTest : public q3test::OwningApiTest {
protected:
    TQ3PointData m_data{{1.5f, -2, 3}, nullptr};
};

TEST_F(PointApiTest, PointsBoundTheirPositions)
{
    const TQ3PointData other{{-1, 4, 0}, nullptr};
    TQ3GeometryObject point = own(Q3Point_New(&other));
    const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
        EXPECT_EQ(Q3Point_Submit(&m_data, v), kQ3Success);
        EXPECT_EQ(Q3Geometry_Submit(point, v), kQ3Success);
    });
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_FLOAT_EQ(box.min.x, -1);
    EXPECT_FLOAT_EQ(box.min.y, -2);
    EXPECT_FLOAT_EQ(box.min.z, 0);
    EXPECT_FLOAT_EQ(box.max.x, 1.5f);
    EXPECT_FLOAT_EQ(box.max.y, 4);
    EXPECT_FLOAT_EQ(box.max.z, 3);
}

// ---- Position access (QuickDraw 3D 1.6) ---------------------------------------

TEST_F(PointApiTest, SetPositionMovesThePointKeepsItsSetAndBumpsTheEditIndex)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    m_data.pointAttributeSet = set;
    TQ3GeometryObject point = own(Q3Point_New(&m_data));
    ASSERT_NE(point, nullptr);
    TQ3Point3D position{};
    ASSERT_EQ(Q3Point_GetPosition(point, &position), kQ3Success);
    EXPECT_EQ(position.x, 1.5f);
    EXPECT_EQ(position.y, -2.0f);
    EXPECT_EQ(position.z, 3.0f);

    const unsigned long edit = Q3Shared_GetEditIndex(point);
    const TQ3Point3D moved{-4, 5, -6};
    EXPECT_EQ(Q3Point_SetPosition(point, &moved), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(point), edit);
    ASSERT_EQ(Q3Point_GetPosition(point, &position), kQ3Success);
    EXPECT_EQ(position.x, -4.0f);
    EXPECT_EQ(position.y, 5.0f);
    EXPECT_EQ(position.z, -6.0f);
    TQ3PointData out{};
    ASSERT_EQ(Q3Point_GetData(point, &out), kQ3Success);
    EXPECT_EQ(out.point.x, -4.0f);
    EXPECT_EQ(out.pointAttributeSet, set);
    EXPECT_EQ(Q3Point_EmptyData(&out), kQ3Success);
}

TEST_F(PointApiTest, SetPositionRejectsNonFiniteCoordinatesAndChangesNothing)
{
    TQ3GeometryObject point = own(Q3Point_New(&m_data));
    ASSERT_NE(point, nullptr);
    const unsigned long edit = Q3Shared_GetEditIndex(point);
    for (int axis = 0; axis < 3; ++axis)
        for (float bad : kNonFinite) {
            TQ3Point3D position{0, 0, 0};
            float* coordinates[] = {&position.x, &position.y, &position.z};
            *coordinates[axis] = bad;
            // The same code New and SetData post for the same coordinate.
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point_SetPosition(point, &position), kQ3Failure),
                            kQ3ErrorInvalidData);
        }
    EXPECT_EQ(Q3Shared_GetEditIndex(point), edit);
    TQ3PointData out{};
    ASSERT_EQ(Q3Point_GetData(point, &out), kQ3Success);
    EXPECT_EQ(out.point.x, 1.5f);
    EXPECT_EQ(out.point.y, -2.0f);
    EXPECT_EQ(out.point.z, 3.0f);
    EXPECT_EQ(out.pointAttributeSet, nullptr);
}

TEST_F(PointApiTest, GetAndSetPositionRejectBadArguments)
{
    TQ3GeometryObject point = own(Q3Point_New(&m_data));
    const TQ3LineData lineData{{{{0, 0, 0}, nullptr}, {{1, 1, 1}, nullptr}}, nullptr};
    TQ3GeometryObject notAPoint = own(Q3Line_New(&lineData));
    int notAnObject = 0;
    TQ3GeometryObject stray = reinterpret_cast<TQ3GeometryObject>(&notAnObject);
    const unsigned long edit = Q3Shared_GetEditIndex(point);
    TQ3Point3D position{9, 9, 9};
    for (TQ3GeometryObject wrong : {static_cast<TQ3GeometryObject>(nullptr), notAPoint, stray}) {
        const TQ3Error code = wrong == nullptr     ? kQ3ErrorNULLParameter
                              : wrong == notAPoint ? kQ3ErrorInvalidObjectType
                                                   : kQ3ErrorInvalidObject;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point_GetPosition(wrong, &position), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point_SetPosition(wrong, &position), kQ3Failure), code);
    }
    EXPECT_EQ(position.x, 9.0f); // unchanged on failure
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point_GetPosition(point, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point_SetPosition(point, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_EQ(Q3Shared_GetEditIndex(point), edit);
}

TEST_F(PointApiTest, AMovedPointIsBoundedWhereItNowIs)
{
    TQ3GeometryObject point = own(Q3Point_New(&m_data));
    const TQ3Point3D moved{-8, 0.5f, 2};
    ASSERT_EQ(Q3Point_SetPosition(point, &moved), kQ3Success);
    const TQ3BoundingBox box =
        boundsOf([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(point, v), kQ3Success); });
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_FLOAT_EQ(box.min.x, -8);
    EXPECT_FLOAT_EQ(box.min.y, 0.5f);
    EXPECT_FLOAT_EQ(box.min.z, 2);
    EXPECT_FLOAT_EQ(box.max.x, -8);
    EXPECT_FLOAT_EQ(box.max.y, 0.5f);
    EXPECT_FLOAT_EQ(box.max.z, 2);
}

TEST(PointApiUninitialized, EveryFunctionFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    TQ3PointData data{};
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    EXPECT_EQ(Q3Point_New(&data), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Point_Submit(&data, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Point_GetData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Point_SetData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    TQ3Point3D position{};
    EXPECT_EQ(Q3Point_GetPosition(nullptr, &position), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Point_SetPosition(nullptr, &position), kQ3Failure);
    EXPECT_TRUE(failed());
}

} // namespace
