// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// What is the polygon's own among the nine Q3Polygon_* calls of
// QD3DGeometry.h: its three vertices at least, the TQ3PolygonData rules in
// their order, bounds, and the calls before Q3Initialize. What every
// geometry shares (NULL and bad handles, every array's limits, NaN and Inf in
// every coordinate, references, Duplicate, the per-vertex calls) is tried by
// the contract suites (GeometryContractTest.cpp).

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <algorithm>
#include <vector>

namespace {

using namespace q3test;

class PolygonApiTest : public OwningApiTest {
protected:
    void SetUp() override
    {
        OwningApiTest::SetUp();
        // A concave pentagon (an arrow head), not in a coordinate plane.
        m_vertices = {{{0, 0, 1}, nullptr},
                      {{4, 0, 2}, nullptr},
                      {{4, 3, -1}, nullptr},
                      {{2, 1, 0}, nullptr},
                      {{-1, 3, 5}, nullptr}};
        m_data = TQ3PolygonData{5, m_vertices.data(), nullptr};
    }

    std::vector<TQ3Vertex3D> m_vertices;
    TQ3PolygonData m_data{};
};

// ---- Its size ----------------------------------------------------

TEST_F(PolygonApiTest, TheSmallestPolygonHasThreeVertices)
{
    m_data.numVertices = 3;
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    ASSERT_NE(polygon, nullptr);
    TQ3PolygonData out{};
    ASSERT_EQ(Q3Polygon_GetData(polygon, &out), kQ3Success);
    EXPECT_EQ(out.numVertices, 3u);
    EXPECT_EQ(Q3Polygon_EmptyData(&out), kQ3Success);
}

// ---- The TQ3PolygonData rules, in their order ---------------------------------------

TEST_F(PolygonApiTest, NewRejectsFewerThanThreeVertices)
{
    for (unsigned long count : {0UL, 1UL, 2UL}) {
        m_data.numVertices = count;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_New(&m_data), nullptr), kQ3ErrorGeometryInsufficientNumberOfPoints);
    }
    // Too few comes before a bad coordinate among the vertices counted.
    m_vertices[0].point.x = kNaN;
    m_data.numVertices = 2;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_New(&m_data), nullptr), kQ3ErrorGeometryInsufficientNumberOfPoints);
}

// ---- Submit and bounds --------------------------------------------------------------

TEST_F(PolygonApiTest, SubmitInsideALoopChecksTheDataRulesInOrder)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
        std::vector<TQ3Vertex3D> vertices = m_vertices;
        vertices[1].point.x = kNaN;
        vertices[2].attributeSet = v;
        TQ3PolygonData bad{5, nullptr, nullptr};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_Submit(&bad, v), kQ3Failure), kQ3ErrorNULLParameter);
        bad.vertices = vertices.data();
        bad.numVertices = 2;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_Submit(&bad, v), kQ3Failure), kQ3ErrorGeometryInsufficientNumberOfPoints);
        bad.numVertices = kQ3GeometryMaxArrayCount + 1;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_Submit(&bad, v), kQ3Failure), kQ3ErrorParameterOutOfRange);
        bad.numVertices = 5;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_Submit(&bad, v), kQ3Failure), kQ3ErrorInvalidData);
        vertices[1].point.x = 4;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_Submit(&bad, v), kQ3Failure), kQ3ErrorInvalidObjectType);
        vertices[2].attributeSet = deadObject();
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_Submit(&bad, v), kQ3Failure), kQ3ErrorInvalidObject);
        vertices[2].attributeSet = set;
        EXPECT_EQ(Q3Polygon_Submit(&bad, v), kQ3Success);
    });
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_EQ(box.min.x, -1.0f);
    EXPECT_EQ(box.max.z, 5.0f);
    EXPECT_EQ(referenceCount(set), 1u);
}

TEST_F(PolygonApiTest, ImmediateAndRetainedPolygonsBoundTheirTransformedVertices)
{
    const TQ3Vector3D translate{-3, 2, 0.5f};
    const TQ3Vector3D scale{1, -2, 3};
    auto transformed = [](const TQ3Point3D& p) { return TQ3Point3D{p.x - 3, -2 * p.y + 2, 3 * p.z + 0.5f}; };
    TQ3Point3D low{1e9f, 1e9f, 1e9f}, high{-1e9f, -1e9f, -1e9f};
    for (const TQ3Vertex3D& vertex : m_vertices) {
        const TQ3Point3D p = transformed(vertex.point);
        low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    for (bool retained : {false, true}) {
        const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
            Q3TranslateTransform_Submit(&translate, v);
            Q3ScaleTransform_Submit(&scale, v);
            EXPECT_EQ(retained ? Q3Geometry_Submit(polygon, v) : Q3Polygon_Submit(&m_data, v), kQ3Success);
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

TEST(PolygonApiUninitialized, EveryFunctionFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    TQ3PolygonData data{};
    TQ3Point3D position{};
    TQ3AttributeSet set = nullptr;
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    EXPECT_EQ(Q3Polygon_New(&data), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Polygon_Submit(&data, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Polygon_SetData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Polygon_GetData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Polygon_EmptyData(&data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Polygon_GetVertexPosition(nullptr, 0, &position), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Polygon_SetVertexPosition(nullptr, 0, &position), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Polygon_GetVertexAttributeSet(nullptr, 0, &set), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Polygon_SetVertexAttributeSet(nullptr, 0, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
}

} // namespace
