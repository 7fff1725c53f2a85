// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The thirteen Q3TriGrid_* calls against QD3DGeometry.h: the TQ3TriGridData
// rules in their order, handles and pointers, row, column and facet indices
// at their edges, facet attribute sets, and the decomposition: every facet
// the header's triangle, its vertices exactly the data's.

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DView.h"

#include <array>
#include <vector>

namespace {

using namespace q3test;

constexpr unsigned long kRows = 3, kColumns = 4, kFacets = 2 * (kRows - 1) * (kColumns - 1);

class TriGridApiTest : public OwningApiTest {
protected:
    void SetUp() override
    {
        OwningApiTest::SetUp();
        for (unsigned long r = 0; r < kRows; ++r)
            for (unsigned long c = 0; c < kColumns; ++c)
                m_vertices.push_back({{float(c), -float(r), 0.1f * float(r * c)}, nullptr});
        m_data = TQ3TriGridData{kRows, kColumns, m_vertices.data(), nullptr, nullptr};
    }
    std::vector<TQ3Object> notGrids()
    {
        TQ3Vertex3D v[3] = {{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{0, 1, 0}, nullptr}};
        const TQ3PolygonData polygon{3, v, nullptr};
        return {own(Q3AttributeSet_New()), view(), own(Q3Polygon_New(&polygon))};
    }
    std::vector<TQ3Vertex3D> m_vertices;
    TQ3TriGridData m_data{};
};

// The header's facets, written out: vertex (row, column) of facet f.
std::array<unsigned long, 3> expectedFacet(unsigned long f)
{
    const unsigned long cell = f / 2, row = cell / (kColumns - 1), c = cell % (kColumns - 1);
    auto v = [](unsigned long r, unsigned long col) { return r * kColumns + col; };
    if (c % 2 == 0)
        return f % 2 == 0 ? std::array<unsigned long, 3>{v(row, c), v(row, c + 1), v(row + 1, c)}
                          : std::array<unsigned long, 3>{v(row + 1, c), v(row, c + 1), v(row + 1, c + 1)};
    return f % 2 == 0 ? std::array<unsigned long, 3>{v(row, c), v(row + 1, c + 1), v(row + 1, c)}
                      : std::array<unsigned long, 3>{v(row, c), v(row, c + 1), v(row + 1, c + 1)};
}

TEST_F(TriGridApiTest, NewCopiesTheGridAndItsFacetSets)
{
    TQ3AttributeSet red = own(colorSet(1, 0, 0));
    std::vector<TQ3AttributeSet> facets(kFacets, nullptr);
    facets[0] = red;
    facets[kFacets - 1] = red;
    m_data.facetAttributeSet = facets.data();
    m_vertices[5].attributeSet = red;
    TQ3GeometryObject grid = own(Q3TriGrid_New(&m_data));
    ASSERT_NE(grid, nullptr);
    EXPECT_EQ(referenceCount(red), 4u);
    TQ3TriGridData out{};
    ASSERT_EQ(Q3TriGrid_GetData(grid, &out), kQ3Success);
    EXPECT_EQ(out.numRows, kRows);
    EXPECT_EQ(out.numColumns, kColumns);
    EXPECT_NE(out.facetAttributeSet, facets.data());
    EXPECT_EQ(out.facetAttributeSet[kFacets - 1], red);
    EXPECT_EQ(out.facetAttributeSet[1], nullptr);
    EXPECT_EQ(out.vertices[5].attributeSet, red);
    ASSERT_EQ(Q3TriGrid_EmptyData(&out), kQ3Success);
    EXPECT_EQ(out.facetAttributeSet, nullptr);
    EXPECT_EQ(out.vertices, nullptr);
    EXPECT_EQ(referenceCount(red), 4u);
}

TEST_F(TriGridApiTest, TheRulesAreCheckedInTheirOrder)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriGrid_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    TQ3TriGridData data = m_data;
    data.vertices = nullptr;
    data.numRows = 1;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriGrid_New(&data), nullptr), kQ3ErrorNULLParameter);
    for (unsigned long rows : {0UL, 1UL}) {
        data = m_data;
        data.numRows = rows;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriGrid_New(&data), nullptr), kQ3ErrorGeometryInsufficientNumberOfPoints);
        data = m_data;
        data.numColumns = rows;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriGrid_New(&data), nullptr), kQ3ErrorGeometryInsufficientNumberOfPoints);
    }
    for (unsigned long n : {(unsigned long)kQ3GeometryMaxArrayCount / 2 + 1, ~0UL}) {
        data = m_data;
        data.numRows = n; // n x 4 vertices: refused before the array is read
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriGrid_New(&data), nullptr), kQ3ErrorParameterOutOfRange);
    }
    for (float bad : kNonFinite) {
        m_vertices[kRows * kColumns - 1].point.z = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriGrid_New(&m_data), nullptr), kQ3ErrorInvalidData);
    }
    m_vertices[kRows * kColumns - 1].point.z = 0;
    std::vector<TQ3AttributeSet> facets(kFacets, nullptr);
    facets[kFacets - 1] = view();
    m_data.facetAttributeSet = facets.data();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriGrid_New(&m_data), nullptr), kQ3ErrorInvalidObjectType);
    facets[kFacets - 1] = deadObject();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriGrid_New(&m_data), nullptr), kQ3ErrorInvalidObject);
    // Submit checks the view before the data.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriGrid_Submit(&m_data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    m_data.facetAttributeSet = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriGrid_Submit(&m_data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
}

TEST_F(TriGridApiTest, AccessorsCheckRowsColumnsAndFacetsAndChangeNothingOnFailure)
{
    TQ3AttributeSet set = own(colorSet(0, 1, 0));
    TQ3GeometryObject grid = own(Q3TriGrid_New(&m_data));
    const unsigned long edit = Q3Shared_GetEditIndex(grid);
    TQ3Point3D p{9, 9, 9};
    TQ3AttributeSet read = set;
    const TQ3Point3D moved{5, 5, 5};
    for (unsigned long bad : indicesPastTheEnd(kRows)) {
        EXPECT_Q3_ERROR(Q3TriGrid_GetVertexPosition(grid, bad, 0, &p), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(Q3TriGrid_SetVertexPosition(grid, bad, 0, &moved), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(Q3TriGrid_GetVertexAttributeSet(grid, bad, 0, &read), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(Q3TriGrid_SetVertexAttributeSet(grid, bad, 0, set), kQ3ErrorParameterOutOfRange);
    }
    for (unsigned long bad : indicesPastTheEnd(kColumns)) {
        EXPECT_Q3_ERROR(Q3TriGrid_GetVertexPosition(grid, kRows - 1, bad, &p), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(Q3TriGrid_SetVertexPosition(grid, kRows - 1, bad, &moved), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(Q3TriGrid_SetVertexAttributeSet(grid, 0, bad, set), kQ3ErrorParameterOutOfRange);
    }
    for (unsigned long bad : indicesPastTheEnd(kFacets)) {
        EXPECT_Q3_ERROR(Q3TriGrid_GetFacetAttributeSet(grid, bad, &read), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(Q3TriGrid_SetFacetAttributeSet(grid, bad, set), kQ3ErrorParameterOutOfRange);
    }
    for (float bad : kNonFinite) {
        const TQ3Point3D q{0, bad, 0};
        EXPECT_Q3_ERROR(Q3TriGrid_SetVertexPosition(grid, 1, 1, &q), kQ3ErrorInvalidData);
    }
    EXPECT_Q3_ERROR(Q3TriGrid_SetFacetAttributeSet(grid, 0, view()), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3TriGrid_SetVertexAttributeSet(grid, 0, 0, strayHandle()), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3TriGrid_SetVertexPosition(grid, 0, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3TriGrid_GetVertexPosition(grid, 0, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3TriGrid_GetFacetAttributeSet(grid, 0, nullptr), kQ3ErrorNULLParameter);
    for (TQ3Object wrong : notGrids()) {
        EXPECT_Q3_ERROR(Q3TriGrid_GetVertexPosition(wrong, 0, 0, &p), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3TriGrid_SetFacetAttributeSet(wrong, 0, nullptr), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3TriGrid_GetData(wrong, &m_data), kQ3ErrorInvalidObjectType);
    }
    EXPECT_Q3_ERROR(Q3TriGrid_EmptyData(nullptr), kQ3ErrorNULLParameter);
    EXPECT_EQ(Q3Shared_GetEditIndex(grid), edit);
    EXPECT_EQ(p.x, 9.0f);
    EXPECT_EQ(read, set);
    EXPECT_EQ(referenceCount(set), 1u);

    ASSERT_EQ(Q3TriGrid_GetVertexPosition(grid, kRows - 1, kColumns - 1, &p), kQ3Success);
    EXPECT_TRUE(samePoint(p, m_vertices.back().point));
    ASSERT_EQ(Q3TriGrid_SetVertexPosition(grid, 2, 1, &moved), kQ3Success);
    ASSERT_EQ(Q3TriGrid_GetVertexPosition(grid, 2, 1, &p), kQ3Success);
    EXPECT_TRUE(samePoint(p, moved));
    ASSERT_EQ(Q3TriGrid_SetVertexAttributeSet(grid, 0, kColumns - 1, set), kQ3Success);
    ASSERT_EQ(Q3TriGrid_GetVertexAttributeSet(grid, 0, kColumns - 1, &read), kQ3Success);
    EXPECT_EQ(read, set);
    Q3Object_Dispose(read);
    // A grid without facet sets gets the array on the first set.
    ASSERT_EQ(Q3TriGrid_GetFacetAttributeSet(grid, kFacets - 1, &read), kQ3Success);
    EXPECT_EQ(read, nullptr);
    ASSERT_EQ(Q3TriGrid_SetFacetAttributeSet(grid, kFacets - 1, set), kQ3Success);
    ASSERT_EQ(Q3TriGrid_GetFacetAttributeSet(grid, kFacets - 1, &read), kQ3Success);
    EXPECT_EQ(read, set);
    Q3Object_Dispose(read);
    ASSERT_EQ(Q3TriGrid_GetFacetAttributeSet(grid, 0, &read), kQ3Success);
    EXPECT_EQ(read, nullptr);
    EXPECT_EQ(referenceCount(set), 3u);
    ASSERT_EQ(Q3TriGrid_SetFacetAttributeSet(grid, kFacets - 1, nullptr), kQ3Success);
    EXPECT_EQ(referenceCount(set), 2u);
    EXPECT_GT(Q3Shared_GetEditIndex(grid), edit);
}

// Property: the decomposition is the header's facets in order, each with the
// data's exact vertices.
TEST_F(TriGridApiTest, TheDecompositionIsTheHeadersFacets)
{
    TQ3GeometryObject grid = own(Q3TriGrid_New(&m_data));
    const auto triangles = decomposedTriangles(view(), grid);
    ASSERT_EQ(triangles.size(), kFacets);
    for (unsigned long f = 0; f < kFacets; ++f) {
        const std::array<unsigned long, 3> corners = expectedFacet(f);
        for (int k = 0; k < 3; ++k)
            EXPECT_TRUE(samePoint(triangles[f][k], m_vertices[corners[k]].point)) << "facet " << f << " corner " << k;
    }
    const TQ3BoundingBox bounds = boundsOf([&](TQ3ViewObject v) { Q3Geometry_Submit(grid, v); });
    EXPECT_EQ(bounds.min.y, -2.0f);
    EXPECT_EQ(bounds.max.x, 3.0f);
}

} // namespace
