// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// What is the triangle's own among the nine Q3Triangle_* calls of
// QD3DGeometry.h: its bounds and the calls before Q3Initialize. New,
// GetData, SetData, EmptyData, Submit, Duplicate and the per-vertex calls are
// tried by the contract suites (GeometryContractTest.cpp).

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <algorithm>

namespace {

using namespace q3test;

class TriangleApiTest : public OwningApiTest {
protected:
    TQ3TriangleData m_data{{{{1, -2, 3}, nullptr}, {{-4, 5, 6}, nullptr}, {{7, 8, -9}, nullptr}}, nullptr};
};

// ---- Bounds --------------------------------------------------------------

TEST_F(TriangleApiTest, ImmediateAndRetainedTrianglesBoundTheirTransformedVertices)
{
    // Scale by (2, 1, -1), then translate by (10, 0, 1): world = (2x + 10, y, 1 - z).
    const TQ3Vector3D translate{10, 0, 1};
    const TQ3Vector3D scale{2, 1, -1};
    auto transformed = [](const TQ3Point3D& p) { return TQ3Point3D{2 * p.x + 10, p.y, 1 - p.z}; };
    TQ3Point3D low{1e9f, 1e9f, 1e9f}, high{-1e9f, -1e9f, -1e9f};
    for (const TQ3Vertex3D& vertex : m_data.vertices) {
        const TQ3Point3D p = transformed(vertex.point);
        low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    for (bool retained : {false, true}) {
        const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
            Q3TranslateTransform_Submit(&translate, v);
            Q3ScaleTransform_Submit(&scale, v);
            EXPECT_EQ(retained ? Q3Geometry_Submit(triangle, v) : Q3Triangle_Submit(&m_data, v), kQ3Success);
        });
        SCOPED_TRACE(retained ? "retained" : "immediate");
        EXPECT_EQ(box.isEmpty, kQ3False);
        EXPECT_FLOAT_EQ(box.min.x, low.x);
        EXPECT_FLOAT_EQ(box.min.y, low.y);
        EXPECT_FLOAT_EQ(box.min.z, low.z);
        EXPECT_FLOAT_EQ(box.max.x, high.x);
        EXPECT_FLOAT_EQ(box.max.y, high.y);
        EXPECT_FLOAT_EQ(box.max.z, high.z);
    }
}

// ---- Before Q3Initialize -------------------------------------------------------

TEST(TriangleApiUninitialized, EveryFunctionFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    TQ3TriangleData data{};
    TQ3Point3D position{};
    TQ3AttributeSet set = nullptr;
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    EXPECT_EQ(Q3Triangle_New(&data), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Triangle_Submit(&data, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Triangle_SetData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Triangle_GetData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Triangle_EmptyData(&data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Triangle_GetVertexPosition(nullptr, 0, &position), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Triangle_SetVertexPosition(nullptr, 0, &position), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Triangle_GetVertexAttributeSet(nullptr, 0, &set), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Triangle_SetVertexAttributeSet(nullptr, 0, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
}

} // namespace
