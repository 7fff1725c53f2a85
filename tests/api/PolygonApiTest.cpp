// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// What is the polygon's own among the nine Q3Polygon_* calls of
// QD3DGeometry.h: its three vertices at least and the TQ3PolygonData rules in
// their order. What every geometry shares (NULL and bad handles, every
// array's limits, NaN and Inf in every coordinate, references, Duplicate,
// bounds, the per-vertex calls, the calls before Q3Initialize) is tried by
// the contract suites (GeometryContractTest.cpp).

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DView.h"

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

} // namespace
