// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The nine Q3Triangle_* calls against QD3DGeometry.h: the TQ3TriangleData
// rules in their order, handles and pointers, indices, references, deep
// copies and duplicates, immediate mode and bounds.

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

class TriangleApiTest : public OwningApiTest {
protected:
    TQ3TriangleData m_data{{{{1, -2, 3}, nullptr}, {{-4, 5, 6}, nullptr}, {{7, 8, -9}, nullptr}}, nullptr};

    TQ3GeometryObject somePolygon()
    {
        TQ3Vertex3D vertices[3] = {{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{0, 1, 0}, nullptr}};
        const TQ3PolygonData data{3, vertices, nullptr};
        return own(Q3Polygon_New(&data));
    }

    /// Handles of the wrong class for a triangle: an attribute set, a view, a
    /// polygon.
    std::vector<TQ3Object> notTriangles()
    {
        return {own(Q3AttributeSet_New()), view(), somePolygon()};
    }
};

// Everything a triangle holds, as GetData reports it, and its edit index.
struct TriangleState {
    TQ3Point3D points[3];
    TQ3AttributeSet vertexSets[3];
    TQ3AttributeSet whole;
    unsigned long editIndex;
};

TriangleState stateOf(TQ3GeometryObject triangle)
{
    TQ3TriangleData data{};
    EXPECT_EQ(Q3Triangle_GetData(triangle, &data), kQ3Success);
    TriangleState state{};
    for (int i = 0; i < 3; ++i) {
        state.points[i] = data.vertices[i].point;
        state.vertexSets[i] = data.vertices[i].attributeSet;
    }
    state.whole = data.triangleAttributeSet;
    state.editIndex = Q3Shared_GetEditIndex(triangle);
    EXPECT_EQ(Q3Triangle_EmptyData(&data), kQ3Success);
    return state;
}

void expectSameState(const TriangleState& before, const TriangleState& after)
{
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(samePoint(before.points[i], after.points[i])) << "vertex " << i;
        EXPECT_EQ(before.vertexSets[i], after.vertexSets[i]) << "vertex " << i;
    }
    EXPECT_EQ(before.whole, after.whole);
    EXPECT_EQ(before.editIndex, after.editIndex);
}

// ---- New, GetData, EmptyData ----------------------------------------------------

TEST_F(TriangleApiTest, NewMakesATriangleThatGetDataReturns)
{
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    ASSERT_NE(triangle, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(triangle), kQ3GeometryTypeTriangle);
    EXPECT_EQ(Q3Geometry_GetType(triangle), kQ3GeometryTypeTriangle);
    EXPECT_EQ(Q3Shape_GetType(triangle), kQ3ShapeTypeGeometry);
    EXPECT_EQ(Q3Object_IsDrawable(triangle), kQ3True);
    TQ3TriangleData out{};
    ASSERT_EQ(Q3Triangle_GetData(triangle, &out), kQ3Success);
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(samePoint(out.vertices[i].point, m_data.vertices[i].point)) << i;
        EXPECT_EQ(out.vertices[i].attributeSet, nullptr);
    }
    EXPECT_EQ(out.triangleAttributeSet, nullptr);
    EXPECT_EQ(Q3Triangle_EmptyData(&out), kQ3Success);
}

TEST_F(TriangleApiTest, NewCopiesTheCallersData)
{
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    ASSERT_NE(triangle, nullptr);
    m_data.vertices[1].point.x = 100;
    EXPECT_EQ(stateOf(triangle).points[1].x, -4.0f);
}

TEST_F(TriangleApiTest, AttributeSetsAreHeldByReferenceAndGetDataHandsOutNewOnes)
{
    TQ3AttributeSet shared = own(colorSet(1, 0, 0));
    TQ3AttributeSet whole = own(colorSet(0, 0, 1));
    m_data.vertices[0].attributeSet = shared;
    m_data.vertices[2].attributeSet = shared;
    m_data.triangleAttributeSet = whole;
    TQ3GeometryObject triangle = Q3Triangle_New(&m_data);
    ASSERT_NE(triangle, nullptr);
    EXPECT_EQ(referenceCount(shared), 3u); // the caller's and one per vertex
    EXPECT_EQ(referenceCount(whole), 2u);

    TQ3TriangleData out{};
    ASSERT_EQ(Q3Triangle_GetData(triangle, &out), kQ3Success);
    EXPECT_EQ(out.vertices[0].attributeSet, shared);
    EXPECT_EQ(out.vertices[1].attributeSet, nullptr);
    EXPECT_EQ(out.vertices[2].attributeSet, shared);
    EXPECT_EQ(out.triangleAttributeSet, whole);
    EXPECT_EQ(referenceCount(shared), 5u);
    EXPECT_EQ(referenceCount(whole), 3u);
    Q3Object_Dispose(triangle);
    EXPECT_EQ(referenceCount(shared), 3u); // the caller's and GetData's two

    ASSERT_EQ(Q3Triangle_EmptyData(&out), kQ3Success);
    for (int i = 0; i < 3; ++i)
        EXPECT_EQ(out.vertices[i].attributeSet, nullptr);
    EXPECT_EQ(out.triangleAttributeSet, nullptr);
    EXPECT_EQ(out.vertices[2].point.z, -9.0f); // the points are left alone
    EXPECT_EQ(referenceCount(shared), 1u);
    EXPECT_EQ(referenceCount(whole), 1u);
    // A second EmptyData finds nothing to release.
    EXPECT_EQ(Q3Triangle_EmptyData(&out), kQ3Success);
    EXPECT_EQ(referenceCount(shared), 1u);
}

TEST_F(TriangleApiTest, TheTriangleOutlivesTheCallersReferences)
{
    TQ3AttributeSet set = colorSet(0.25f, 0.5f, 0.75f);
    m_data.vertices[1].attributeSet = set;
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    ASSERT_NE(triangle, nullptr);
    const unsigned long live = Q3Memory_CountLiveObjects();
    Q3Object_Dispose(set);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live); // the triangle still holds it
    TQ3AttributeSet got = nullptr;
    ASSERT_EQ(Q3Triangle_GetVertexAttributeSet(triangle, 1, &got), kQ3Success);
    EXPECT_EQ(colorOf(got).b, 0.75f);
    Q3Object_Dispose(got);
}

// ---- The TQ3TriangleData rules, in their order ------------------------------------

TEST_F(TriangleApiTest, NewRejectsNullData)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_New(nullptr), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(TriangleApiTest, NewRejectsANonFiniteCoordinateInAnyVertex)
{
    const unsigned long live = Q3Memory_CountLiveObjects();
    for (int vertex = 0; vertex < 3; ++vertex)
        for (int axis = 0; axis < 3; ++axis)
            for (float bad : kNonFinite) {
                TQ3TriangleData data = m_data;
                float* coordinates[] = {&data.vertices[vertex].point.x, &data.vertices[vertex].point.y,
                                        &data.vertices[vertex].point.z};
                *coordinates[axis] = bad;
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_New(&data), nullptr), kQ3ErrorInvalidData);
            }
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live);
}

TEST_F(TriangleApiTest, NewRejectsBadAttributeSetsInEverySlotAndKeepsNoReference)
{
    TQ3AttributeSet good = own(Q3AttributeSet_New());
    const std::vector<TQ3Object> wrongClass = notTriangles(); // none is an attribute set but the first
    for (int slot = 0; slot < 4; ++slot) {
        TQ3TriangleData data = m_data;
        // Good sets in every other slot: a failure must give their references back.
        for (int i = 0; i < 3; ++i)
            data.vertices[i].attributeSet = good;
        data.triangleAttributeSet = good;
        TQ3AttributeSet* field = slot < 3 ? &data.vertices[slot].attributeSet : &data.triangleAttributeSet;
        for (TQ3Object wrong : {wrongClass[1], wrongClass[2]}) {
            *field = wrong;
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_New(&data), nullptr), kQ3ErrorInvalidObjectType);
        }
        *field = strayHandle();
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_New(&data), nullptr), kQ3ErrorInvalidObject);
        *field = deadObject();
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_New(&data), nullptr), kQ3ErrorInvalidObject);
        EXPECT_EQ(referenceCount(good), 1u) << "slot " << slot;
    }
}

TEST_F(TriangleApiTest, CoordinatesAreCheckedBeforeAttributeSets)
{
    TQ3TriangleData data = m_data;
    data.triangleAttributeSet = view();
    data.vertices[0].attributeSet = strayHandle();
    data.vertices[2].point.y = kNaN;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_New(&data), nullptr), kQ3ErrorInvalidData);
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetData(triangle, &data), kQ3Failure), kQ3ErrorInvalidData);
}

// ---- SetData ----------------------------------------------------------------------

TEST_F(TriangleApiTest, SetDataReplacesEverythingBumpsTheEditIndexAndReleasesTheOldSets)
{
    TQ3AttributeSet oldSet = own(Q3AttributeSet_New());
    TQ3AttributeSet newSet = own(Q3AttributeSet_New());
    m_data.vertices[0].attributeSet = oldSet;
    m_data.triangleAttributeSet = oldSet;
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    ASSERT_NE(triangle, nullptr);
    const unsigned long edit = Q3Shared_GetEditIndex(triangle);
    const TQ3TriangleData replacement{{{{0, 0, 0}, nullptr}, {{2, 0, 0}, newSet}, {{0, 2, 1}, newSet}}, nullptr};
    ASSERT_EQ(Q3Triangle_SetData(triangle, &replacement), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(triangle), edit);
    EXPECT_EQ(referenceCount(oldSet), 1u);
    EXPECT_EQ(referenceCount(newSet), 3u);
    const TriangleState state = stateOf(triangle);
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(samePoint(state.points[i], replacement.vertices[i].point)) << i;
        EXPECT_EQ(state.vertexSets[i], replacement.vertices[i].attributeSet) << i;
    }
    EXPECT_EQ(state.whole, nullptr);
}

TEST_F(TriangleApiTest, FailedSetDataChangesNothing)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    TQ3AttributeSet other = own(Q3AttributeSet_New());
    m_data.vertices[1].attributeSet = set;
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    ASSERT_NE(triangle, nullptr);
    const TriangleState before = stateOf(triangle);

    for (float bad : kNonFinite) {
        TQ3TriangleData data = m_data;
        data.vertices[0].attributeSet = other;
        data.vertices[2].point.x = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetData(triangle, &data), kQ3Failure), kQ3ErrorInvalidData);
    }
    TQ3TriangleData data = m_data;
    data.vertices[0].attributeSet = other; // a good set before the bad one
    data.vertices[0].point.x = 50;
    data.triangleAttributeSet = triangle;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetData(triangle, &data), kQ3Failure), kQ3ErrorInvalidObjectType);
    data.triangleAttributeSet = deadObject();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetData(triangle, &data), kQ3Failure), kQ3ErrorInvalidObject);

    expectSameState(before, stateOf(triangle));
    EXPECT_EQ(referenceCount(set), 2u);
    EXPECT_EQ(referenceCount(other), 1u);
}

TEST_F(TriangleApiTest, SetDataGetDataAndEmptyDataRejectBadArgumentsInOrder)
{
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    TQ3TriangleData out{};
    out.vertices[0].point.x = 42;
    TQ3TriangleData bad = m_data;
    bad.vertices[0].point.x = kNaN;
    for (TQ3Object wrong : notTriangles()) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetData(wrong, &m_data), kQ3Failure), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_GetData(wrong, &out), kQ3Failure), kQ3ErrorInvalidObjectType);
        // The handle is checked before the pointer and the data.
        EXPECT_Q3_ERROR(Q3Triangle_SetData(wrong, nullptr), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3Triangle_SetData(wrong, &bad), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3Triangle_GetData(wrong, nullptr), kQ3ErrorInvalidObjectType);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetData(nullptr, &m_data), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetData(triangle, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_GetData(nullptr, &out), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_GetData(triangle, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_EmptyData(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_GetData(strayHandle(), &out), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetData(strayHandle(), &m_data), kQ3Failure), kQ3ErrorInvalidObject);
    TQ3GeometryObject dead = Q3Triangle_New(&m_data);
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_GetData(dead, &out), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetData(dead, &m_data), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_EQ(out.vertices[0].point.x, 42.0f); // never written by a failed GetData
}

TEST_F(TriangleApiTest, EmptyDataWithABadHandleReleasesNothing)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    m_data.vertices[0].attributeSet = set;
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    TQ3TriangleData out{};
    ASSERT_EQ(Q3Triangle_GetData(triangle, &out), kQ3Success);
    ASSERT_EQ(referenceCount(set), 3u);
    for (TQ3Object bad : {view(), strayHandle()}) {
        out.vertices[2].attributeSet = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_EmptyData(&out), kQ3Failure),
                        bad == view() ? kQ3ErrorInvalidObjectType : kQ3ErrorInvalidObject);
        EXPECT_EQ(out.vertices[0].attributeSet, set); // nothing cleared
        EXPECT_EQ(referenceCount(set), 3u);            // nothing released
    }
    out.vertices[2].attributeSet = nullptr;
    EXPECT_EQ(Q3Triangle_EmptyData(&out), kQ3Success);
    EXPECT_EQ(referenceCount(set), 2u);
}

// ---- Duplicate --------------------------------------------------------------------

TEST_F(TriangleApiTest, DuplicateCopiesDeeplyAndKeepsSharedSetsShared)
{
    TQ3AttributeSet shared = own(colorSet(1, 0, 0));
    TQ3AttributeSet single = own(colorSet(0, 1, 0));
    m_data.vertices[0].attributeSet = shared;
    m_data.vertices[1].attributeSet = shared;
    m_data.vertices[2].attributeSet = single;
    m_data.triangleAttributeSet = shared;
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    ASSERT_NE(triangle, nullptr);
    const unsigned long live = Q3Memory_CountLiveObjects();
    TQ3GeometryObject copy = Q3Object_Duplicate(triangle);
    ASSERT_NE(copy, nullptr);
    // The copy and one copy of each distinct set.
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live + 3);
    EXPECT_EQ(Q3Geometry_GetType(copy), kQ3GeometryTypeTriangle);
    EXPECT_EQ(referenceCount(shared), 4u); // untouched by the duplicate
    EXPECT_EQ(referenceCount(single), 2u);

    const TriangleState state = stateOf(copy);
    for (int i = 0; i < 3; ++i)
        EXPECT_TRUE(samePoint(state.points[i], m_data.vertices[i].point)) << i;
    ASSERT_NE(state.vertexSets[0], nullptr);
    EXPECT_NE(state.vertexSets[0], shared);
    EXPECT_EQ(state.vertexSets[1], state.vertexSets[0]);
    EXPECT_EQ(state.whole, state.vertexSets[0]);
    EXPECT_NE(state.vertexSets[2], single);
    EXPECT_NE(state.vertexSets[2], state.vertexSets[0]);
    EXPECT_EQ(colorOf(state.vertexSets[0]).r, 1.0f);
    EXPECT_EQ(colorOf(state.vertexSets[2]).g, 1.0f);
    EXPECT_EQ(referenceCount(state.vertexSets[0]), 3u); // held once per use in the copy

    // Editing the copy leaves the original alone.
    const TQ3Point3D moved{-1, -1, -1};
    ASSERT_EQ(Q3Triangle_SetVertexPosition(copy, 0, &moved), kQ3Success);
    EXPECT_TRUE(samePoint(stateOf(triangle).points[0], m_data.vertices[0].point));
    Q3Object_Dispose(copy);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live); // the copied sets went with it
}

// ---- Submit and bounds --------------------------------------------------------------

TEST_F(TriangleApiTest, SubmitRejectsBadArgumentsInOrder)
{
    TQ3TriangleData bad = m_data;
    bad.vertices[1].point.z = kInf;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_Submit(nullptr, view()), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_Submit(&m_data, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_Submit(nullptr, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    // The view is checked before the data's rules.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_Submit(&bad, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    TQ3AttributeSet notAView = own(Q3AttributeSet_New());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_Submit(&bad, notAView), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_Submit(&m_data, strayHandle()), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_Submit(&m_data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_Submit(&bad, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_Submit(triangle, view()), kQ3Failure), kQ3ErrorViewNotStarted);
}

TEST_F(TriangleApiTest, SubmitInsideALoopChecksTheDataRulesAndKeepsNoReference)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
        for (float value : kNonFinite) {
            TQ3TriangleData bad = m_data;
            bad.vertices[2].point.y = value;
            bad.triangleAttributeSet = v; // a later rule fails too
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_Submit(&bad, v), kQ3Failure), kQ3ErrorInvalidData);
        }
        TQ3TriangleData bad = m_data;
        bad.vertices[1].attributeSet = v;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_Submit(&bad, v), kQ3Failure), kQ3ErrorInvalidObjectType);
        bad.vertices[1].attributeSet = deadObject();
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_Submit(&bad, v), kQ3Failure), kQ3ErrorInvalidObject);
        bad.vertices[1].attributeSet = set;
        EXPECT_EQ(Q3Triangle_Submit(&bad, v), kQ3Success);
    });
    EXPECT_EQ(box.isEmpty, kQ3False); // only the good submit was bounded
    EXPECT_EQ(box.min.x, -4.0f);
    EXPECT_EQ(box.max.z, 6.0f);
    EXPECT_EQ(referenceCount(set), 1u);
}

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

// ---- Per-vertex calls -------------------------------------------------------------

TEST_F(TriangleApiTest, GetVertexPositionReadsEveryVertexAndRejectsOtherIndices)
{
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    ASSERT_NE(triangle, nullptr);
    for (unsigned long index : {0UL, 1UL, 2UL}) {
        TQ3Point3D position{};
        ASSERT_EQ(Q3Triangle_GetVertexPosition(triangle, index, &position), kQ3Success);
        EXPECT_TRUE(samePoint(position, m_data.vertices[index].point)) << index;
    }
    for (unsigned long index : indicesPastTheEnd(3)) {
        TQ3Point3D position{42, 42, 42};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_GetVertexPosition(triangle, index, &position), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_EQ(position.x, 42.0f);
    }
}

TEST_F(TriangleApiTest, SetVertexPositionMovesOneVertexKeepsItsSetAndBumpsTheEditIndex)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    m_data.vertices[2].attributeSet = set;
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    ASSERT_NE(triangle, nullptr);
    for (unsigned long index : {0UL, 2UL}) {
        const unsigned long edit = Q3Shared_GetEditIndex(triangle);
        const TQ3Point3D moved{float(index) + 0.5f, -8, 9};
        ASSERT_EQ(Q3Triangle_SetVertexPosition(triangle, index, &moved), kQ3Success);
        EXPECT_NE(Q3Shared_GetEditIndex(triangle), edit);
        const TriangleState state = stateOf(triangle);
        EXPECT_TRUE(samePoint(state.points[index], moved));
        EXPECT_TRUE(samePoint(state.points[1], m_data.vertices[1].point)); // the others stay
        EXPECT_EQ(state.vertexSets[2], set);
    }
}

TEST_F(TriangleApiTest, SetVertexPositionRejectsBadIndicesAndNonFiniteCoordinatesAndChangesNothing)
{
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    ASSERT_NE(triangle, nullptr);
    const TriangleState before = stateOf(triangle);
    const TQ3Point3D fine{1, 1, 1};
    for (unsigned long index : indicesPastTheEnd(3))
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetVertexPosition(triangle, index, &fine), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
    for (unsigned long index : {0UL, 1UL, 2UL})
        for (int axis = 0; axis < 3; ++axis)
            for (float value : kNonFinite) {
                TQ3Point3D position = fine;
                float* coordinates[] = {&position.x, &position.y, &position.z};
                *coordinates[axis] = value;
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetVertexPosition(triangle, index, &position), kQ3Failure),
                                kQ3ErrorInvalidData);
            }
    const TQ3Point3D nan{kNaN, 0, 0};
    EXPECT_Q3_ERROR(Q3Triangle_SetVertexPosition(triangle, 3, &nan), kQ3ErrorParameterOutOfRange); // index first
    EXPECT_Q3_ERROR(Q3Triangle_SetVertexPosition(triangle, 3, nullptr), kQ3ErrorNULLParameter);  // pointer first
    expectSameState(before, stateOf(triangle));
}

TEST_F(TriangleApiTest, VertexAttributeSetsAreReadAndReplacedWithBalancedReferences)
{
    TQ3AttributeSet first = own(Q3AttributeSet_New());
    TQ3AttributeSet second = own(Q3AttributeSet_New());
    m_data.vertices[0].attributeSet = first;
    TQ3GeometryObject triangle = Q3Triangle_New(&m_data);
    ASSERT_NE(triangle, nullptr);

    TQ3AttributeSet got = second;
    ASSERT_EQ(Q3Triangle_GetVertexAttributeSet(triangle, 2, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    ASSERT_EQ(Q3Triangle_GetVertexAttributeSet(triangle, 0, &got), kQ3Success);
    EXPECT_EQ(got, first);
    EXPECT_EQ(referenceCount(first), 3u); // the caller's, the triangle's, Get's
    Q3Object_Dispose(got);

    unsigned long edit = Q3Shared_GetEditIndex(triangle);
    EXPECT_EQ(Q3Triangle_SetVertexAttributeSet(triangle, 0, second), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(triangle), edit);
    EXPECT_EQ(referenceCount(first), 1u);
    EXPECT_EQ(Q3Triangle_SetVertexAttributeSet(triangle, 2, second), kQ3Success);
    EXPECT_EQ(Q3Triangle_SetVertexAttributeSet(triangle, 2, second), kQ3Success); // the same set again
    EXPECT_EQ(referenceCount(second), 3u);
    const TriangleState state = stateOf(triangle);
    EXPECT_EQ(state.vertexSets[0], second);
    EXPECT_EQ(state.vertexSets[1], nullptr);
    EXPECT_EQ(state.vertexSets[2], second);
    EXPECT_TRUE(samePoint(state.points[0], m_data.vertices[0].point));

    edit = Q3Shared_GetEditIndex(triangle);
    EXPECT_EQ(Q3Triangle_SetVertexAttributeSet(triangle, 0, nullptr), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(triangle), edit);
    ASSERT_EQ(Q3Triangle_GetVertexAttributeSet(triangle, 0, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    EXPECT_EQ(referenceCount(second), 2u);
    Q3Object_Dispose(triangle);
    EXPECT_EQ(referenceCount(second), 1u);
}

TEST_F(TriangleApiTest, PerVertexCallsRejectBadHandlesPointersAndIndicesAndChangeNothing)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    m_data.vertices[0].attributeSet = set;
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    ASSERT_NE(triangle, nullptr);
    const TriangleState before = stateOf(triangle);

    for (unsigned long index : indicesPastTheEnd(3)) {
        TQ3AttributeSet got = set;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_GetVertexAttributeSet(triangle, index, &got), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_EQ(got, set);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetVertexAttributeSet(triangle, index, nullptr), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetVertexAttributeSet(triangle, index, set), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
    }
    TQ3Point3D position{};
    TQ3AttributeSet got = nullptr;
    std::vector<std::pair<TQ3Object, TQ3Error>> wrongs = {{nullptr, kQ3ErrorNULLParameter},
                                                          {strayHandle(), kQ3ErrorInvalidObject}};
    for (TQ3Object wrong : notTriangles())
        wrongs.emplace_back(wrong, kQ3ErrorInvalidObjectType);
    for (const auto& [wrong, code] : wrongs) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_GetVertexPosition(wrong, 0, &position), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetVertexPosition(wrong, 0, &position), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_GetVertexAttributeSet(wrong, 0, &got), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetVertexAttributeSet(wrong, 0, set), kQ3Failure), code);
        // The handle comes before the pointer and the index.
        EXPECT_Q3_ERROR(Q3Triangle_GetVertexPosition(wrong, 7, nullptr), code);
    }
    TQ3GeometryObject dead = Q3Triangle_New(&m_data);
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(Q3Triangle_GetVertexPosition(dead, 0, &position), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3Triangle_SetVertexAttributeSet(dead, 0, nullptr), kQ3ErrorInvalidObject);

    EXPECT_Q3_ERROR(Q3Triangle_GetVertexPosition(triangle, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Triangle_GetVertexPosition(triangle, 9, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Triangle_SetVertexPosition(triangle, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Triangle_GetVertexAttributeSet(triangle, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Triangle_GetVertexAttributeSet(triangle, 9, nullptr), kQ3ErrorNULLParameter);
    // The attribute set argument comes before the index.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetVertexAttributeSet(triangle, 1, view()), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetVertexAttributeSet(triangle, 1, triangle), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetVertexAttributeSet(triangle, 5, strayHandle()), kQ3Failure),
                    kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_SetVertexAttributeSet(triangle, 1, deadObject()), kQ3Failure),
                    kQ3ErrorInvalidObject);
    expectSameState(before, stateOf(triangle));
    EXPECT_EQ(referenceCount(set), 2u);
}

// ---- Q3Geometry_* on a triangle -------------------------------------------------------

TEST_F(TriangleApiTest, TheGeometryAttributeSetIsTheTriangleAttributeSet)
{
    TQ3AttributeSet first = own(Q3AttributeSet_New());
    TQ3AttributeSet second = own(Q3AttributeSet_New());
    m_data.triangleAttributeSet = first;
    TQ3GeometryObject triangle = own(Q3Triangle_New(&m_data));
    TQ3AttributeSet got = nullptr;
    ASSERT_EQ(Q3Geometry_GetAttributeSet(triangle, &got), kQ3Success);
    EXPECT_EQ(got, first);
    Q3Object_Dispose(got);
    const unsigned long edit = Q3Shared_GetEditIndex(triangle);
    ASSERT_EQ(Q3Geometry_SetAttributeSet(triangle, second), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(triangle), edit);
    EXPECT_EQ(stateOf(triangle).whole, second);
    EXPECT_EQ(referenceCount(first), 1u);
    EXPECT_EQ(referenceCount(second), 2u);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_SetAttributeSet(triangle, view()), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_EQ(stateOf(triangle).whole, second);
    ASSERT_EQ(Q3Geometry_SetAttributeSet(triangle, nullptr), kQ3Success);
    ASSERT_EQ(Q3Geometry_GetAttributeSet(triangle, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    EXPECT_EQ(referenceCount(second), 1u);
}

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
