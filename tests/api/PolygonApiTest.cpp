// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The nine Q3Polygon_* calls against QD3DGeometry.h: the TQ3PolygonData rules
// in their order (NULL, too few, too many, coordinates, attribute sets),
// handles and pointers, indices, references, deep copies and duplicates,
// immediate mode and bounds.

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

    /// Handles of the wrong class for a polygon: an attribute set, a view, a
    /// triangle.
    std::vector<TQ3Object> notPolygons()
    {
        const TQ3TriangleData triangle{{{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{0, 1, 0}, nullptr}}, nullptr};
        return {own(Q3AttributeSet_New()), view(), own(Q3Triangle_New(&triangle))};
    }

    std::vector<TQ3Vertex3D> m_vertices;
    TQ3PolygonData m_data{};
};

struct PolygonState {
    std::vector<TQ3Point3D> points;
    std::vector<TQ3AttributeSet> vertexSets;
    TQ3AttributeSet whole = nullptr;
    unsigned long editIndex = 0;
};

PolygonState stateOf(TQ3GeometryObject polygon)
{
    TQ3PolygonData data{};
    EXPECT_EQ(Q3Polygon_GetData(polygon, &data), kQ3Success);
    PolygonState state;
    for (unsigned long i = 0; i < data.numVertices; ++i) {
        state.points.push_back(data.vertices[i].point);
        state.vertexSets.push_back(data.vertices[i].attributeSet);
    }
    state.whole = data.polygonAttributeSet;
    state.editIndex = Q3Shared_GetEditIndex(polygon);
    EXPECT_EQ(Q3Polygon_EmptyData(&data), kQ3Success);
    return state;
}

void expectSameState(const PolygonState& before, const PolygonState& after)
{
    ASSERT_EQ(before.points.size(), after.points.size());
    for (std::size_t i = 0; i < before.points.size(); ++i) {
        EXPECT_TRUE(samePoint(before.points[i], after.points[i])) << "vertex " << i;
        EXPECT_EQ(before.vertexSets[i], after.vertexSets[i]) << "vertex " << i;
    }
    EXPECT_EQ(before.whole, after.whole);
    EXPECT_EQ(before.editIndex, after.editIndex);
}

// ---- New, GetData, EmptyData ----------------------------------------------------

TEST_F(PolygonApiTest, NewMakesAPolygonThatGetDataReturns)
{
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    ASSERT_NE(polygon, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(polygon), kQ3GeometryTypePolygon);
    EXPECT_EQ(Q3Geometry_GetType(polygon), kQ3GeometryTypePolygon);
    EXPECT_EQ(Q3Shape_GetType(polygon), kQ3ShapeTypeGeometry);
    EXPECT_EQ(Q3Object_IsDrawable(polygon), kQ3True);
    TQ3PolygonData out{};
    ASSERT_EQ(Q3Polygon_GetData(polygon, &out), kQ3Success);
    ASSERT_EQ(out.numVertices, 5u);
    ASSERT_NE(out.vertices, nullptr);
    EXPECT_NE(out.vertices, m_vertices.data());
    for (unsigned long i = 0; i < 5; ++i) {
        EXPECT_TRUE(samePoint(out.vertices[i].point, m_vertices[i].point)) << i;
        EXPECT_EQ(out.vertices[i].attributeSet, nullptr);
    }
    EXPECT_EQ(out.polygonAttributeSet, nullptr);
    EXPECT_EQ(Q3Polygon_EmptyData(&out), kQ3Success);
    EXPECT_EQ(out.vertices, nullptr);
    EXPECT_EQ(out.numVertices, 5u); // the count is left alone
    EXPECT_EQ(Q3Polygon_EmptyData(&out), kQ3Success); // a second call does nothing
}

TEST_F(PolygonApiTest, NewAndGetDataCopyTheArrays)
{
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    ASSERT_NE(polygon, nullptr);
    m_vertices[0].point.x = 100; // the caller's array after New
    TQ3PolygonData first{}, second{};
    ASSERT_EQ(Q3Polygon_GetData(polygon, &first), kQ3Success);
    ASSERT_EQ(Q3Polygon_GetData(polygon, &second), kQ3Success);
    EXPECT_EQ(first.vertices[0].point.x, 0.0f);
    EXPECT_NE(first.vertices, second.vertices);
    first.vertices[1].point.y = -50; // one GetData's array
    EXPECT_EQ(second.vertices[1].point.y, 0.0f);
    EXPECT_EQ(stateOf(polygon).points[1].y, 0.0f);
    Q3Polygon_EmptyData(&first);
    Q3Polygon_EmptyData(&second);
}

TEST_F(PolygonApiTest, AttributeSetsAreHeldByReferenceAndGetDataHandsOutNewOnes)
{
    TQ3AttributeSet shared = own(colorSet(1, 0, 0));
    TQ3AttributeSet whole = own(colorSet(0, 0, 1));
    m_vertices[1].attributeSet = shared;
    m_vertices[4].attributeSet = shared;
    m_data.polygonAttributeSet = whole;
    TQ3GeometryObject polygon = Q3Polygon_New(&m_data);
    ASSERT_NE(polygon, nullptr);
    EXPECT_EQ(referenceCount(shared), 3u);
    EXPECT_EQ(referenceCount(whole), 2u);

    TQ3PolygonData out{};
    ASSERT_EQ(Q3Polygon_GetData(polygon, &out), kQ3Success);
    EXPECT_EQ(out.vertices[1].attributeSet, shared);
    EXPECT_EQ(out.vertices[4].attributeSet, shared);
    EXPECT_EQ(out.vertices[0].attributeSet, nullptr);
    EXPECT_EQ(out.polygonAttributeSet, whole);
    EXPECT_EQ(referenceCount(shared), 5u);
    Q3Object_Dispose(polygon);
    EXPECT_EQ(referenceCount(shared), 3u);
    EXPECT_EQ(referenceCount(whole), 2u);
    ASSERT_EQ(Q3Polygon_EmptyData(&out), kQ3Success);
    EXPECT_EQ(out.vertices, nullptr);
    EXPECT_EQ(out.polygonAttributeSet, nullptr);
    EXPECT_EQ(referenceCount(shared), 1u);
    EXPECT_EQ(referenceCount(whole), 1u);
    EXPECT_EQ(Q3Polygon_EmptyData(&out), kQ3Success);
}

TEST_F(PolygonApiTest, TheSmallestPolygonHasThreeVertices)
{
    m_data.numVertices = 3;
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    ASSERT_NE(polygon, nullptr);
    EXPECT_EQ(stateOf(polygon).points.size(), 3u);
}

// ---- The TQ3PolygonData rules, in their order ---------------------------------------

TEST_F(PolygonApiTest, NewRejectsNullDataAndNullVertices)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    m_data.vertices = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_New(&m_data), nullptr), kQ3ErrorNULLParameter);
    // NULL comes first: before too few vertices and before too many.
    for (unsigned long count : {0UL, 2UL, (unsigned long)kQ3GeometryMaxArrayCount + 1, ~0UL}) {
        m_data.numVertices = count;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_New(&m_data), nullptr), kQ3ErrorNULLParameter);
    }
}

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

TEST_F(PolygonApiTest, NewRejectsMoreThanTheMaximumCountWithoutReadingTheArray)
{
    // The array holds five vertices; a count above the limit must be refused
    // before any vertex past them is read (ASan would see it).
    m_vertices[0].point.x = kNaN; // a later rule fails too
    for (unsigned long count : {(unsigned long)kQ3GeometryMaxArrayCount + 1, ~0UL}) {
        m_data.numVertices = count;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_New(&m_data), nullptr), kQ3ErrorParameterOutOfRange);
    }
}

TEST_F(PolygonApiTest, NewRejectsANonFiniteCoordinateInAnyVertex)
{
    for (std::size_t vertex : {std::size_t{0}, std::size_t{2}, std::size_t{4}})
        for (int axis = 0; axis < 3; ++axis)
            for (float bad : kNonFinite) {
                std::vector<TQ3Vertex3D> vertices = m_vertices;
                float* coordinates[] = {&vertices[vertex].point.x, &vertices[vertex].point.y,
                                        &vertices[vertex].point.z};
                *coordinates[axis] = bad;
                m_data.vertices = vertices.data();
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_New(&m_data), nullptr), kQ3ErrorInvalidData);
            }
}

TEST_F(PolygonApiTest, NewRejectsBadAttributeSetsAfterCoordinatesAndKeepsNoReference)
{
    TQ3AttributeSet good = own(Q3AttributeSet_New());
    const std::vector<TQ3Object> wrongClass = notPolygons();
    for (std::size_t slot = 0; slot <= m_vertices.size(); ++slot) {
        std::vector<TQ3Vertex3D> vertices = m_vertices;
        for (TQ3Vertex3D& vertex : vertices)
            vertex.attributeSet = good;
        TQ3PolygonData data{5, vertices.data(), good};
        TQ3AttributeSet* field = slot < vertices.size() ? &vertices[slot].attributeSet : &data.polygonAttributeSet;
        for (TQ3Object wrong : {wrongClass[1], wrongClass[2]}) {
            *field = wrong;
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_New(&data), nullptr), kQ3ErrorInvalidObjectType);
        }
        *field = strayHandle();
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_New(&data), nullptr), kQ3ErrorInvalidObject);
        *field = deadObject();
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_New(&data), nullptr), kQ3ErrorInvalidObject);
        // The coordinate rule comes before the attribute set rule.
        vertices[(slot + 2) % vertices.size()].point.z = -kInf;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_New(&data), nullptr), kQ3ErrorInvalidData);
        EXPECT_EQ(referenceCount(good), 1u) << "slot " << slot;
    }
}

// ---- SetData ------------------------------------------------------------------------

TEST_F(PolygonApiTest, SetDataReplacesEverythingBumpsTheEditIndexAndReleasesTheOldSets)
{
    TQ3AttributeSet oldSet = own(Q3AttributeSet_New());
    TQ3AttributeSet newSet = own(Q3AttributeSet_New());
    m_vertices[2].attributeSet = oldSet;
    m_data.polygonAttributeSet = oldSet;
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    ASSERT_NE(polygon, nullptr);
    const unsigned long edit = Q3Shared_GetEditIndex(polygon);
    TQ3Vertex3D square[4] = {{{0, 0, 0}, newSet}, {{1, 0, 0}, nullptr}, {{1, 1, 0}, nullptr}, {{0, 1, 0}, newSet}};
    const TQ3PolygonData replacement{4, square, newSet};
    ASSERT_EQ(Q3Polygon_SetData(polygon, &replacement), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(polygon), edit);
    EXPECT_EQ(referenceCount(oldSet), 1u);
    EXPECT_EQ(referenceCount(newSet), 4u);
    square[1].point.x = 7; // the caller's array after SetData
    const PolygonState state = stateOf(polygon);
    ASSERT_EQ(state.points.size(), 4u);
    EXPECT_EQ(state.points[1].x, 1.0f);
    EXPECT_EQ(state.points[2].y, 1.0f);
    EXPECT_EQ(state.vertexSets[0], newSet);
    EXPECT_EQ(state.vertexSets[1], nullptr);
    EXPECT_EQ(state.vertexSets[3], newSet);
    EXPECT_EQ(state.whole, newSet);
}

TEST_F(PolygonApiTest, FailedSetDataChangesNothing)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    TQ3AttributeSet other = own(Q3AttributeSet_New());
    m_vertices[3].attributeSet = set;
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    ASSERT_NE(polygon, nullptr);
    const PolygonState before = stateOf(polygon);

    std::vector<TQ3Vertex3D> vertices(4, TQ3Vertex3D{{1, 2, 3}, other});
    vertices[1].point.x = 2;
    vertices[2].point.y = 5;
    TQ3PolygonData data{4, vertices.data(), other};
    data.vertices = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetData(polygon, &data), kQ3Failure), kQ3ErrorNULLParameter);
    data.vertices = vertices.data();
    data.numVertices = 2;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetData(polygon, &data), kQ3Failure),
                    kQ3ErrorGeometryInsufficientNumberOfPoints);
    data.numVertices = kQ3GeometryMaxArrayCount + 1;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetData(polygon, &data), kQ3Failure), kQ3ErrorParameterOutOfRange);
    data.numVertices = 4;
    for (float bad : kNonFinite) {
        vertices[3].point.y = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetData(polygon, &data), kQ3Failure), kQ3ErrorInvalidData);
    }
    vertices[3].point.y = 0;
    vertices[3].attributeSet = polygon; // after three good sets
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetData(polygon, &data), kQ3Failure), kQ3ErrorInvalidObjectType);
    vertices[3].attributeSet = other;
    data.polygonAttributeSet = deadObject();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetData(polygon, &data), kQ3Failure), kQ3ErrorInvalidObject);

    expectSameState(before, stateOf(polygon));
    EXPECT_EQ(referenceCount(set), 2u);
    EXPECT_EQ(referenceCount(other), 1u);
}

TEST_F(PolygonApiTest, SetDataGetDataAndEmptyDataRejectBadArgumentsInOrder)
{
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    TQ3PolygonData out{7, nullptr, nullptr};
    TQ3PolygonData bad = m_data;
    bad.vertices = nullptr;
    for (TQ3Object wrong : notPolygons()) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetData(wrong, &m_data), kQ3Failure), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_GetData(wrong, &out), kQ3Failure), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3Polygon_SetData(wrong, nullptr), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3Polygon_SetData(wrong, &bad), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3Polygon_GetData(wrong, nullptr), kQ3ErrorInvalidObjectType);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetData(nullptr, &m_data), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetData(polygon, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_GetData(nullptr, &out), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_GetData(polygon, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_EmptyData(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_GetData(strayHandle(), &out), kQ3Failure), kQ3ErrorInvalidObject);
    TQ3GeometryObject dead = Q3Polygon_New(&m_data);
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_GetData(dead, &out), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetData(dead, &m_data), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_EQ(out.numVertices, 7u); // never written by a failed GetData
    EXPECT_EQ(out.vertices, nullptr);
}

TEST_F(PolygonApiTest, EmptyDataWithABadHandleReleasesNothing)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    m_vertices[0].attributeSet = set;
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    TQ3PolygonData out{};
    ASSERT_EQ(Q3Polygon_GetData(polygon, &out), kQ3Success);
    TQ3Vertex3D* const array = out.vertices;
    for (TQ3Object bad : {view(), strayHandle()}) {
        out.polygonAttributeSet = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_EmptyData(&out), kQ3Failure),
                        bad == view() ? kQ3ErrorInvalidObjectType : kQ3ErrorInvalidObject);
        EXPECT_EQ(out.vertices, array); // not freed
        EXPECT_EQ(referenceCount(set), 3u);
    }
    out.polygonAttributeSet = nullptr;
    out.vertices[4].attributeSet = strayHandle(); // deep inside the array
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_EmptyData(&out), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_EQ(referenceCount(set), 3u);
    out.vertices[4].attributeSet = nullptr;
    EXPECT_EQ(Q3Polygon_EmptyData(&out), kQ3Success);
    EXPECT_EQ(referenceCount(set), 2u);
}

// ---- Duplicate ----------------------------------------------------------------------

TEST_F(PolygonApiTest, DuplicateCopiesDeeplyAndKeepsSharedSetsShared)
{
    TQ3AttributeSet shared = own(colorSet(1, 0, 0));
    TQ3AttributeSet whole = own(colorSet(0, 0, 1));
    m_vertices[0].attributeSet = shared;
    m_vertices[3].attributeSet = shared;
    m_data.polygonAttributeSet = whole;
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    ASSERT_NE(polygon, nullptr);
    const unsigned long live = Q3Memory_CountLiveObjects();
    TQ3GeometryObject copy = Q3Object_Duplicate(polygon);
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live + 3);
    EXPECT_EQ(Q3Geometry_GetType(copy), kQ3GeometryTypePolygon);
    EXPECT_EQ(referenceCount(shared), 3u);
    EXPECT_EQ(referenceCount(whole), 2u);

    const PolygonState state = stateOf(copy);
    ASSERT_EQ(state.points.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i)
        EXPECT_TRUE(samePoint(state.points[i], m_vertices[i].point)) << i;
    ASSERT_NE(state.vertexSets[0], nullptr);
    EXPECT_NE(state.vertexSets[0], shared);
    EXPECT_EQ(state.vertexSets[3], state.vertexSets[0]);
    EXPECT_EQ(state.vertexSets[1], nullptr);
    EXPECT_NE(state.whole, whole);
    EXPECT_EQ(colorOf(state.vertexSets[0]).r, 1.0f);
    EXPECT_EQ(colorOf(state.whole).b, 1.0f);
    EXPECT_EQ(referenceCount(state.vertexSets[0]), 2u);

    const TQ3Point3D moved{-1, -1, -1};
    ASSERT_EQ(Q3Polygon_SetVertexPosition(copy, 4, &moved), kQ3Success);
    EXPECT_TRUE(samePoint(stateOf(polygon).points[4], m_vertices[4].point));
    Q3Object_Dispose(copy);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live);
}

// ---- Submit and bounds --------------------------------------------------------------

TEST_F(PolygonApiTest, SubmitRejectsBadArgumentsInOrder)
{
    TQ3PolygonData bad = m_data;
    bad.numVertices = 1;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_Submit(nullptr, view()), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_Submit(&m_data, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_Submit(&bad, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    TQ3AttributeSet notAView = own(Q3AttributeSet_New());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_Submit(&bad, notAView), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_Submit(&m_data, strayHandle()), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_Submit(&m_data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_Submit(&bad, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_Submit(polygon, view()), kQ3Failure), kQ3ErrorViewNotStarted);
}

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

// ---- Per-vertex calls -------------------------------------------------------------

TEST_F(PolygonApiTest, GetVertexPositionReadsEveryVertexAndRejectsOtherIndices)
{
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    ASSERT_NE(polygon, nullptr);
    for (unsigned long index = 0; index < 5; ++index) {
        TQ3Point3D position{};
        ASSERT_EQ(Q3Polygon_GetVertexPosition(polygon, index, &position), kQ3Success);
        EXPECT_TRUE(samePoint(position, m_vertices[index].point)) << index;
    }
    for (unsigned long index : indicesPastTheEnd(5)) {
        TQ3Point3D position{42, 42, 42};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_GetVertexPosition(polygon, index, &position), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_EQ(position.x, 42.0f);
    }
}

TEST_F(PolygonApiTest, SetVertexPositionMovesOneVertexKeepsItsSetAndBumpsTheEditIndex)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    m_vertices[4].attributeSet = set;
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    ASSERT_NE(polygon, nullptr);
    for (unsigned long index : {0UL, 4UL}) {
        const unsigned long edit = Q3Shared_GetEditIndex(polygon);
        const TQ3Point3D moved{float(index) + 0.5f, -8, 9};
        ASSERT_EQ(Q3Polygon_SetVertexPosition(polygon, index, &moved), kQ3Success);
        EXPECT_NE(Q3Shared_GetEditIndex(polygon), edit);
        const PolygonState state = stateOf(polygon);
        EXPECT_TRUE(samePoint(state.points[index], moved));
        EXPECT_TRUE(samePoint(state.points[2], m_vertices[2].point));
        EXPECT_EQ(state.vertexSets[4], set);
    }
}

TEST_F(PolygonApiTest, SetVertexPositionRejectsBadIndicesAndNonFiniteCoordinatesAndChangesNothing)
{
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    ASSERT_NE(polygon, nullptr);
    const PolygonState before = stateOf(polygon);
    const TQ3Point3D fine{1, 1, 1};
    for (unsigned long index : indicesPastTheEnd(5))
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetVertexPosition(polygon, index, &fine), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
    for (unsigned long index : {0UL, 4UL})
        for (int axis = 0; axis < 3; ++axis)
            for (float value : kNonFinite) {
                TQ3Point3D position = fine;
                float* coordinates[] = {&position.x, &position.y, &position.z};
                *coordinates[axis] = value;
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetVertexPosition(polygon, index, &position), kQ3Failure),
                                kQ3ErrorInvalidData);
            }
    const TQ3Point3D nan{0, kNaN, 0};
    EXPECT_Q3_ERROR(Q3Polygon_SetVertexPosition(polygon, 5, &nan), kQ3ErrorParameterOutOfRange);
    EXPECT_Q3_ERROR(Q3Polygon_SetVertexPosition(polygon, 5, nullptr), kQ3ErrorNULLParameter);
    expectSameState(before, stateOf(polygon));
}

TEST_F(PolygonApiTest, VertexAttributeSetsAreReadAndReplacedWithBalancedReferences)
{
    TQ3AttributeSet first = own(Q3AttributeSet_New());
    TQ3AttributeSet second = own(Q3AttributeSet_New());
    m_vertices[4].attributeSet = first;
    TQ3GeometryObject polygon = Q3Polygon_New(&m_data);
    ASSERT_NE(polygon, nullptr);

    TQ3AttributeSet got = second;
    ASSERT_EQ(Q3Polygon_GetVertexAttributeSet(polygon, 0, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    ASSERT_EQ(Q3Polygon_GetVertexAttributeSet(polygon, 4, &got), kQ3Success);
    EXPECT_EQ(got, first);
    EXPECT_EQ(referenceCount(first), 3u);
    Q3Object_Dispose(got);

    unsigned long edit = Q3Shared_GetEditIndex(polygon);
    EXPECT_EQ(Q3Polygon_SetVertexAttributeSet(polygon, 4, second), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(polygon), edit);
    EXPECT_EQ(referenceCount(first), 1u);
    EXPECT_EQ(Q3Polygon_SetVertexAttributeSet(polygon, 0, second), kQ3Success);
    EXPECT_EQ(Q3Polygon_SetVertexAttributeSet(polygon, 0, second), kQ3Success);
    EXPECT_EQ(referenceCount(second), 3u);
    const PolygonState state = stateOf(polygon);
    EXPECT_EQ(state.vertexSets[0], second);
    EXPECT_EQ(state.vertexSets[4], second);
    EXPECT_EQ(state.vertexSets[2], nullptr);

    edit = Q3Shared_GetEditIndex(polygon);
    EXPECT_EQ(Q3Polygon_SetVertexAttributeSet(polygon, 4, nullptr), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(polygon), edit);
    ASSERT_EQ(Q3Polygon_GetVertexAttributeSet(polygon, 4, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    EXPECT_EQ(referenceCount(second), 2u);
    Q3Object_Dispose(polygon);
    EXPECT_EQ(referenceCount(second), 1u);
}

TEST_F(PolygonApiTest, PerVertexCallsRejectBadHandlesPointersAndIndicesAndChangeNothing)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    m_vertices[0].attributeSet = set;
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    ASSERT_NE(polygon, nullptr);
    const PolygonState before = stateOf(polygon);

    for (unsigned long index : indicesPastTheEnd(5)) {
        TQ3AttributeSet got = set;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_GetVertexAttributeSet(polygon, index, &got), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_EQ(got, set);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetVertexAttributeSet(polygon, index, nullptr), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetVertexAttributeSet(polygon, index, set), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
    }
    TQ3Point3D position{};
    TQ3AttributeSet got = nullptr;
    std::vector<std::pair<TQ3Object, TQ3Error>> wrongs = {{nullptr, kQ3ErrorNULLParameter},
                                                          {strayHandle(), kQ3ErrorInvalidObject}};
    for (TQ3Object wrong : notPolygons())
        wrongs.emplace_back(wrong, kQ3ErrorInvalidObjectType);
    for (const auto& [wrong, code] : wrongs) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_GetVertexPosition(wrong, 0, &position), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetVertexPosition(wrong, 0, &position), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_GetVertexAttributeSet(wrong, 0, &got), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetVertexAttributeSet(wrong, 0, set), kQ3Failure), code);
        EXPECT_Q3_ERROR(Q3Polygon_GetVertexPosition(wrong, 70, nullptr), code);
    }
    TQ3GeometryObject dead = Q3Polygon_New(&m_data);
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(Q3Polygon_GetVertexAttributeSet(dead, 0, &got), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3Polygon_SetVertexPosition(dead, 0, &position), kQ3ErrorInvalidObject);

    EXPECT_Q3_ERROR(Q3Polygon_GetVertexPosition(polygon, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Polygon_GetVertexPosition(polygon, 9, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Polygon_SetVertexPosition(polygon, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Polygon_GetVertexAttributeSet(polygon, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Polygon_GetVertexAttributeSet(polygon, 9, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetVertexAttributeSet(polygon, 1, view()), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetVertexAttributeSet(polygon, 9, polygon), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetVertexAttributeSet(polygon, 5, strayHandle()), kQ3Failure),
                    kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_SetVertexAttributeSet(polygon, 1, deadObject()), kQ3Failure),
                    kQ3ErrorInvalidObject);
    expectSameState(before, stateOf(polygon));
    EXPECT_EQ(referenceCount(set), 2u);
}

// ---- Q3Geometry_* on a polygon -------------------------------------------------------

TEST_F(PolygonApiTest, TheGeometryAttributeSetIsThePolygonAttributeSet)
{
    TQ3AttributeSet first = own(Q3AttributeSet_New());
    TQ3AttributeSet second = own(Q3AttributeSet_New());
    m_data.polygonAttributeSet = first;
    TQ3GeometryObject polygon = own(Q3Polygon_New(&m_data));
    TQ3AttributeSet got = nullptr;
    ASSERT_EQ(Q3Geometry_GetAttributeSet(polygon, &got), kQ3Success);
    EXPECT_EQ(got, first);
    Q3Object_Dispose(got);
    const unsigned long edit = Q3Shared_GetEditIndex(polygon);
    ASSERT_EQ(Q3Geometry_SetAttributeSet(polygon, second), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(polygon), edit);
    EXPECT_EQ(stateOf(polygon).whole, second);
    EXPECT_EQ(referenceCount(first), 1u);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_SetAttributeSet(polygon, strayHandle()), kQ3Failure),
                    kQ3ErrorInvalidObject);
    ASSERT_EQ(Q3Geometry_SetAttributeSet(polygon, nullptr), kQ3Success);
    ASSERT_EQ(Q3Geometry_GetAttributeSet(polygon, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    EXPECT_EQ(referenceCount(second), 1u);
}

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
