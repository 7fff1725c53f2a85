// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The thirteen Q3Polyhedron_* calls against QD3DGeometry.h: the
// TQ3PolyhedronData rules in their order, handles and pointers, indices at
// their edges, triangle and edge data with their attribute sets, and the
// decomposition (its triangles exactly the data's). The wireframe (edge
// flags, edge list) is in the polygons_wireframe scene golden.

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DView.h"

#include <functional>
#include <set>
#include <utility>
#include <vector>

namespace {

using namespace q3test;

class PolyhedronApiTest : public OwningApiTest {
protected:
    void SetUp() override
    {
        OwningApiTest::SetUp();
        // A tetrahedron.
        m_vertices = {{{0, 0, 0}, nullptr}, {{2, 0, 0}, nullptr}, {{0, 2, 0}, nullptr}, {{0, 0, 2}, nullptr}};
        m_triangles = {{{0, 2, 1}, kQ3PolyhedronEdgeAll, nullptr},
                       {{0, 1, 3}, kQ3PolyhedronEdge01, nullptr},
                       {{1, 2, 3}, kQ3PolyhedronEdgeNone, nullptr},
                       {{2, 0, 3}, kQ3PolyhedronEdge12 | kQ3PolyhedronEdge20, nullptr}};
        m_edges = {{{1, 3}, {1, 2}, nullptr}, {{2, 3}, {2, (unsigned long)kQ3ArrayIndexNULL}, nullptr}};
        rebuild();
    }
    void rebuild()
    {
        m_data = TQ3PolyhedronData{4, m_vertices.data(), static_cast<unsigned long>(m_edges.size()), m_edges.data(),
                                   4, m_triangles.data(), nullptr};
    }
    std::vector<TQ3Object> notPolyhedra()
    {
        TQ3Vertex3D v[3] = {{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{0, 1, 0}, nullptr}};
        const TQ3PolygonData polygon{3, v, nullptr};
        return {own(Q3AttributeSet_New()), view(), own(Q3Polygon_New(&polygon))};
    }

    std::vector<TQ3Vertex3D> m_vertices;
    std::vector<TQ3PolyhedronTriangleData> m_triangles;
    std::vector<TQ3PolyhedronEdgeData> m_edges;
    TQ3PolyhedronData m_data{};
};

struct State {
    std::vector<TQ3Point3D> points;
    std::vector<TQ3AttributeSet> sets;
    std::vector<unsigned long> triangleValues;
    std::vector<TQ3AttributeSet> triangleSets;
    std::vector<unsigned long> edgeValues;
    std::vector<TQ3AttributeSet> edgeSets;
    unsigned long editIndex = 0;
    bool operator==(const State& o) const
    {
        if (points.size() != o.points.size())
            return false;
        for (std::size_t i = 0; i < points.size(); ++i)
            if (!samePoint(points[i], o.points[i]))
                return false;
        return sets == o.sets && triangleValues == o.triangleValues && triangleSets == o.triangleSets &&
               edgeValues == o.edgeValues && edgeSets == o.edgeSets && editIndex == o.editIndex;
    }
};

State stateOf(TQ3GeometryObject polyhedron)
{
    TQ3PolyhedronData data{};
    EXPECT_EQ(Q3Polyhedron_GetData(polyhedron, &data), kQ3Success);
    State s;
    for (unsigned long i = 0; i < data.numVertices; ++i) {
        s.points.push_back(data.vertices[i].point);
        s.sets.push_back(data.vertices[i].attributeSet);
    }
    for (unsigned long t = 0; t < data.numTriangles; ++t) {
        const TQ3PolyhedronTriangleData& tri = data.triangles[t];
        s.triangleValues.insert(s.triangleValues.end(), {tri.vertexIndices[0], tri.vertexIndices[1],
                                                         tri.vertexIndices[2], tri.edgeFlag});
        s.triangleSets.push_back(tri.triangleAttributeSet);
    }
    for (unsigned long e = 0; e < data.numEdges; ++e) {
        const TQ3PolyhedronEdgeData& edge = data.edges[e];
        s.edgeValues.insert(s.edgeValues.end(), {edge.vertexIndices[0], edge.vertexIndices[1],
                                                 edge.triangleIndices[0], edge.triangleIndices[1]});
        s.edgeSets.push_back(edge.edgeAttributeSet);
    }
    s.editIndex = Q3Shared_GetEditIndex(polyhedron);
    EXPECT_EQ(Q3Polyhedron_EmptyData(&data), kQ3Success);
    return s;
}

TEST_F(PolyhedronApiTest, NewCopiesEverythingThatGetDataReturns)
{
    TQ3AttributeSet red = own(colorSet(1, 0, 0));
    m_vertices[3].attributeSet = red;
    m_triangles[2].triangleAttributeSet = red;
    m_edges[1].edgeAttributeSet = red;
    m_data.polyhedronAttributeSet = red;
    TQ3GeometryObject polyhedron = own(Q3Polyhedron_New(&m_data));
    ASSERT_NE(polyhedron, nullptr);
    EXPECT_EQ(referenceCount(red), 5u);
    TQ3PolyhedronData out{};
    ASSERT_EQ(Q3Polyhedron_GetData(polyhedron, &out), kQ3Success);
    EXPECT_EQ(out.numVertices, 4u);
    EXPECT_EQ(out.numEdges, 2u);
    EXPECT_EQ(out.numTriangles, 4u);
    EXPECT_NE(out.triangles, m_triangles.data());
    EXPECT_EQ(out.triangles[3].edgeFlag, (unsigned long)(kQ3PolyhedronEdge12 | kQ3PolyhedronEdge20));
    EXPECT_EQ(out.triangles[2].triangleAttributeSet, red);
    EXPECT_EQ(out.edges[1].triangleIndices[1], (unsigned long)kQ3ArrayIndexNULL);
    EXPECT_EQ(out.edges[1].edgeAttributeSet, red);
    EXPECT_EQ(referenceCount(red), 9u);
    ASSERT_EQ(Q3Polyhedron_EmptyData(&out), kQ3Success);
    EXPECT_EQ(out.vertices, nullptr);
    EXPECT_EQ(out.edges, nullptr);
    EXPECT_EQ(out.triangles, nullptr);
    EXPECT_EQ(referenceCount(red), 5u);
    // Edges are optional.
    m_edges.clear();
    rebuild();
    m_data.edges = nullptr;
    EXPECT_NE(own(Q3Polyhedron_New(&m_data)), nullptr);
}

TEST_F(PolyhedronApiTest, TheRulesAreCheckedInTheirOrder)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polyhedron_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    // The fixture's data with one change.
    const auto refusedWith = [&](TQ3Error code, const std::function<void(TQ3PolyhedronData&)>& change) {
        TQ3PolyhedronData data = m_data;
        change(data);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polyhedron_New(&data), nullptr), code);
    };
    refusedWith(kQ3ErrorNULLParameter, [](TQ3PolyhedronData& d) {
        d.vertices = nullptr;
        d.numVertices = 0; // NULL comes first
    });
    refusedWith(kQ3ErrorNULLParameter, [](TQ3PolyhedronData& d) { d.triangles = nullptr; });
    refusedWith(kQ3ErrorNULLParameter, [](TQ3PolyhedronData& d) { d.edges = nullptr; });
    refusedWith(kQ3ErrorGeometryInsufficientNumberOfPoints, [](TQ3PolyhedronData& d) { d.numVertices = 2; });
    refusedWith(kQ3ErrorGeometryInsufficientNumberOfPoints, [](TQ3PolyhedronData& d) { d.numTriangles = 0; });
    for (unsigned long TQ3PolyhedronData::*count :
         {&TQ3PolyhedronData::numVertices, &TQ3PolyhedronData::numEdges, &TQ3PolyhedronData::numTriangles})
        for (unsigned long n : {(unsigned long)kQ3GeometryMaxArrayCount + 1, ~0UL})
            refusedWith(kQ3ErrorParameterOutOfRange, [&](TQ3PolyhedronData& d) { d.*count = n; });
    for (float bad : kNonFinite) {
        m_vertices[2].point.x = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polyhedron_New(&m_data), nullptr), kQ3ErrorInvalidData);
    }
    m_vertices[2].point.x = 0;
    for (unsigned long bad : indicesPastTheEnd(4)) {
        m_triangles[3].vertexIndices[2] = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polyhedron_New(&m_data), nullptr), kQ3ErrorInvalidData);
    }
    m_triangles[3].vertexIndices[2] = 3;
    m_triangles[1].edgeFlag = 8;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polyhedron_New(&m_data), nullptr), kQ3ErrorInvalidData);
    m_triangles[1].edgeFlag = kQ3PolyhedronEdgeAll;
    m_edges[0].vertexIndices[1] = 4;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polyhedron_New(&m_data), nullptr), kQ3ErrorInvalidData);
    m_edges[0].vertexIndices[1] = 3;
    m_edges[0].triangleIndices[0] = 4;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polyhedron_New(&m_data), nullptr), kQ3ErrorInvalidData);
    m_edges[0].triangleIndices[0] = 1;
    m_edges[1].edgeAttributeSet = view();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polyhedron_New(&m_data), nullptr), kQ3ErrorInvalidObjectType);
    m_edges[1].edgeAttributeSet = nullptr;
    m_triangles[0].triangleAttributeSet = deadObject();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polyhedron_New(&m_data), nullptr), kQ3ErrorInvalidObject);
    // Submit checks the view before the data.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polyhedron_Submit(&m_data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    m_triangles[0].triangleAttributeSet = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polyhedron_Submit(&m_data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
}

TEST_F(PolyhedronApiTest, FailedEditsChangeNothing)
{
    TQ3AttributeSet set = own(colorSet(0, 0, 1));
    TQ3GeometryObject polyhedron = own(Q3Polyhedron_New(&m_data));
    ASSERT_NE(polyhedron, nullptr);
    const State before = stateOf(polyhedron);
    TQ3PolyhedronData bad = m_data;
    bad.numTriangles = 0;
    EXPECT_Q3_ERROR(Q3Polyhedron_SetData(polyhedron, &bad), kQ3ErrorGeometryInsufficientNumberOfPoints);
    const TQ3Point3D p{1, 1, 1};
    for (unsigned long i : indicesPastTheEnd(4)) {
        EXPECT_Q3_ERROR(Q3Polyhedron_SetVertexPosition(polyhedron, i, &p), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(Q3Polyhedron_SetVertexAttributeSet(polyhedron, i, set), kQ3ErrorParameterOutOfRange);
        TQ3PolyhedronTriangleData t{{0, 1, 2}, 0, set};
        EXPECT_Q3_ERROR(Q3Polyhedron_SetTriangleData(polyhedron, i, &t), kQ3ErrorParameterOutOfRange);
    }
    for (unsigned long i : indicesPastTheEnd(2)) {
        TQ3PolyhedronEdgeData e{{0, 1}, {0, 1}, set};
        EXPECT_Q3_ERROR(Q3Polyhedron_SetEdgeData(polyhedron, i, &e), kQ3ErrorParameterOutOfRange);
    }
    for (float bad : kNonFinite) {
        const TQ3Point3D q{bad, 0, 0};
        EXPECT_Q3_ERROR(Q3Polyhedron_SetVertexPosition(polyhedron, 3, &q), kQ3ErrorInvalidData);
    }
    TQ3PolyhedronTriangleData t{{0, 1, 4}, 0, set};
    EXPECT_Q3_ERROR(Q3Polyhedron_SetTriangleData(polyhedron, 3, &t), kQ3ErrorInvalidData);
    t = {{0, 1, 3}, 9, set};
    EXPECT_Q3_ERROR(Q3Polyhedron_SetTriangleData(polyhedron, 3, &t), kQ3ErrorInvalidData);
    t = {{0, 1, 3}, 1, polyhedron};
    EXPECT_Q3_ERROR(Q3Polyhedron_SetTriangleData(polyhedron, 3, &t), kQ3ErrorInvalidObjectType);
    TQ3PolyhedronEdgeData e{{0, 4}, {0, 1}, set};
    EXPECT_Q3_ERROR(Q3Polyhedron_SetEdgeData(polyhedron, 1, &e), kQ3ErrorInvalidData);
    e = {{0, 1}, {0, 7}, set};
    EXPECT_Q3_ERROR(Q3Polyhedron_SetEdgeData(polyhedron, 1, &e), kQ3ErrorInvalidData);
    e = {{0, 1}, {0, 1}, strayHandle()};
    EXPECT_Q3_ERROR(Q3Polyhedron_SetEdgeData(polyhedron, 1, &e), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3Polyhedron_SetEdgeData(polyhedron, 1, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Polyhedron_SetTriangleData(polyhedron, 1, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Polyhedron_SetVertexAttributeSet(polyhedron, 0, view()), kQ3ErrorInvalidObjectType);
    EXPECT_TRUE(before == stateOf(polyhedron));
    EXPECT_EQ(referenceCount(set), 1u);
}

TEST_F(PolyhedronApiTest, AccessorsReadAndWriteAtTheEdges)
{
    TQ3AttributeSet set = own(colorSet(0, 1, 1));
    TQ3GeometryObject polyhedron = own(Q3Polyhedron_New(&m_data));
    TQ3Point3D p;
    ASSERT_EQ(Q3Polyhedron_GetVertexPosition(polyhedron, 3, &p), kQ3Success);
    EXPECT_TRUE(samePoint(p, m_vertices[3].point));
    const TQ3Point3D moved{3, 3, 3};
    ASSERT_EQ(Q3Polyhedron_SetVertexPosition(polyhedron, 0, &moved), kQ3Success);
    ASSERT_EQ(Q3Polyhedron_GetVertexPosition(polyhedron, 0, &p), kQ3Success);
    EXPECT_TRUE(samePoint(p, moved));
    ASSERT_EQ(Q3Polyhedron_SetVertexAttributeSet(polyhedron, 3, set), kQ3Success);
    TQ3AttributeSet read = nullptr;
    ASSERT_EQ(Q3Polyhedron_GetVertexAttributeSet(polyhedron, 3, &read), kQ3Success);
    EXPECT_EQ(read, set);
    Q3Object_Dispose(read);

    TQ3PolyhedronTriangleData t{};
    ASSERT_EQ(Q3Polyhedron_GetTriangleData(polyhedron, 3, &t), kQ3Success);
    EXPECT_EQ(t.vertexIndices[0], 2u);
    EXPECT_EQ(t.edgeFlag, (unsigned long)(kQ3PolyhedronEdge12 | kQ3PolyhedronEdge20));
    EXPECT_EQ(t.triangleAttributeSet, nullptr);
    const TQ3PolyhedronTriangleData replacement{{3, 2, 1}, kQ3PolyhedronEdgeAll, set};
    ASSERT_EQ(Q3Polyhedron_SetTriangleData(polyhedron, 0, &replacement), kQ3Success);
    ASSERT_EQ(Q3Polyhedron_GetTriangleData(polyhedron, 0, &t), kQ3Success);
    EXPECT_EQ(t.vertexIndices[0], 3u);
    EXPECT_EQ(t.triangleAttributeSet, set);
    Q3Object_Dispose(t.triangleAttributeSet);

    TQ3PolyhedronEdgeData e{};
    ASSERT_EQ(Q3Polyhedron_GetEdgeData(polyhedron, 1, &e), kQ3Success);
    EXPECT_EQ(e.vertexIndices[0], 2u);
    EXPECT_EQ(e.triangleIndices[1], (unsigned long)kQ3ArrayIndexNULL);
    const TQ3PolyhedronEdgeData edge{{0, 3}, {1, 3}, set};
    ASSERT_EQ(Q3Polyhedron_SetEdgeData(polyhedron, 0, &edge), kQ3Success);
    ASSERT_EQ(Q3Polyhedron_GetEdgeData(polyhedron, 0, &e), kQ3Success);
    EXPECT_EQ(e.vertexIndices[1], 3u);
    EXPECT_EQ(e.edgeAttributeSet, set);
    Q3Object_Dispose(e.edgeAttributeSet);
    EXPECT_EQ(referenceCount(set), 4u);

    for (unsigned long i : indicesPastTheEnd(4))
        EXPECT_Q3_ERROR(Q3Polyhedron_GetTriangleData(polyhedron, i, &t), kQ3ErrorParameterOutOfRange);
    for (unsigned long i : indicesPastTheEnd(2))
        EXPECT_Q3_ERROR(Q3Polyhedron_GetEdgeData(polyhedron, i, &e), kQ3ErrorParameterOutOfRange);
    EXPECT_Q3_ERROR(Q3Polyhedron_GetVertexPosition(polyhedron, 4, &p), kQ3ErrorParameterOutOfRange);
    EXPECT_Q3_ERROR(Q3Polyhedron_GetVertexAttributeSet(polyhedron, 4, &read), kQ3ErrorParameterOutOfRange);
    EXPECT_Q3_ERROR(Q3Polyhedron_GetTriangleData(polyhedron, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Polyhedron_GetEdgeData(polyhedron, 0, nullptr), kQ3ErrorNULLParameter);
    for (TQ3Object wrong : notPolyhedra()) {
        EXPECT_Q3_ERROR(Q3Polyhedron_GetTriangleData(wrong, 0, &t), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3Polyhedron_GetEdgeData(wrong, 0, &e), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3Polyhedron_GetVertexPosition(wrong, 0, &p), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3Polyhedron_GetData(wrong, &m_data), kQ3ErrorInvalidObjectType);
    }
    EXPECT_Q3_ERROR(Q3Polyhedron_EmptyData(nullptr), kQ3ErrorNULLParameter);
}

// Property: the decomposition has three vertices per triangle, exactly the
// data's points in the triangles' order, and the triangles' faces.
TEST_F(PolyhedronApiTest, TheDecompositionIsTheDataTriangleByTriangle)
{
    TQ3GeometryObject polyhedron = own(Q3Polyhedron_New(&m_data));
    const auto triangles = decomposedTriangles(view(), polyhedron);
    ASSERT_EQ(triangles.size(), 4u);
    for (unsigned long t = 0; t < 4; ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_TRUE(samePoint(triangles[t][k], m_vertices[m_triangles[t].vertexIndices[k]].point));
    const TQ3BoundingBox bounds = boundsOf([&](TQ3ViewObject v) { Q3Geometry_Submit(polyhedron, v); });
    EXPECT_EQ(bounds.max.x, 2.0f);
    EXPECT_EQ(bounds.max.z, 2.0f);
}

} // namespace
