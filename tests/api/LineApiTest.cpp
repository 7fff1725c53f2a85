// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// What is the line's own among the Q3Line_* calls: its bounds, also after a
// move, and the calls before Q3Initialize. New, GetData, SetData, EmptyData,
// Submit, Duplicate and the per-vertex calls are tried by the contract
// suites (GeometryContractTest.cpp).

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

class LineApiTest : public q3test::OwningApiTest {
protected:
    TQ3LineData m_data{{{{1, -2, 3}, nullptr}, {{-4, 5, 6}, nullptr}}, nullptr};
};

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

// ---- Per-vertex access (QuickDraw 3D 1.6) -------------------------------------

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
