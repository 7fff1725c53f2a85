// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The eleven Q3GeneralPolygon_* calls against QD3DGeometry.h: the
// TQ3GeneralPolygonData rules in their order, handles and pointers, both
// indices at their edges, references and deep copies, and the even-odd fill
// of the decomposition checked against a crossing-number test written here.

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DView.h"

#include <cmath>
#include <vector>

namespace {

using namespace q3test;

std::vector<TQ3Vertex3D> square(float cx, float cy, float h)
{
    return {{{cx - h, cy - h, 0}, nullptr},
            {{cx + h, cy - h, 0}, nullptr},
            {{cx + h, cy + h, 0}, nullptr},
            {{cx - h, cy + h, 0}, nullptr}};
}

class GeneralPolygonApiTest : public OwningApiTest {
protected:
    void SetUp() override
    {
        OwningApiTest::SetUp();
        // An outer square, a square hole, a concave (L-shaped) island in it.
        m_contours = {square(0, 0, 4), square(0, 0, 3),
                      {{{-2, -2, 0}, nullptr},
                       {{2, -2, 0}, nullptr},
                       {{2, -1, 0}, nullptr},
                       {{-1, -1, 0}, nullptr},
                       {{-1, 2, 0}, nullptr},
                       {{-2, 2, 0}, nullptr}}};
        rebuild();
    }

    void rebuild()
    {
        m_contourData.clear();
        for (std::vector<TQ3Vertex3D>& c : m_contours)
            m_contourData.push_back({static_cast<unsigned long>(c.size()), c.data()});
        m_data = TQ3GeneralPolygonData{static_cast<unsigned long>(m_contourData.size()), m_contourData.data(),
                                       kQ3GeneralPolygonShapeHintComplex, nullptr};
    }

    std::vector<TQ3Object> notGeneralPolygons()
    {
        TQ3Vertex3D v[3] = {{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{0, 1, 0}, nullptr}};
        const TQ3PolygonData polygon{3, v, nullptr};
        return {own(Q3AttributeSet_New()), view(), own(Q3Polygon_New(&polygon))};
    }

    /// The decomposition as a TriMesh, from a bounding loop.
    TQ3TriMeshData decomposed(TQ3GeometryObject geometry)
    {
        TQ3TriMeshData out{};
        TQ3GeometryObject mesh = nullptr;
        EXPECT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
        mesh = Q3Geometry_GetDecomposed(geometry, view());
        TQ3BoundingBox box;
        EXPECT_EQ(Q3View_EndBoundingBox(view(), &box), kQ3ViewStatusDone);
        EXPECT_NE(mesh, nullptr);
        if (mesh != nullptr) {
            EXPECT_EQ(Q3TriMesh_GetData(mesh, &out), kQ3Success);
            Q3Object_Dispose(mesh);
        }
        return out;
    }

    std::vector<std::vector<TQ3Vertex3D>> m_contours;
    std::vector<TQ3GeneralPolygonContourData> m_contourData;
    TQ3GeneralPolygonData m_data{};
};

// The crossing number of (x, y) against every contour, each closed: odd is
// inside under QuickDraw 3D's even-odd rule.
bool insideEvenOdd(const std::vector<std::vector<TQ3Vertex3D>>& contours, double x, double y)
{
    bool inside = false;
    for (const std::vector<TQ3Vertex3D>& c : contours)
        for (std::size_t i = 0, j = c.size() - 1; i < c.size(); j = i++) {
            const double xi = c[i].point.x, yi = c[i].point.y, xj = c[j].point.x, yj = c[j].point.y;
            if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi)
                inside = !inside;
        }
    return inside;
}

// How many of the mesh's triangles hold (x, y) in the plane z = 0.
int coverage(const TQ3TriMeshData& mesh, double x, double y)
{
    int count = 0;
    for (unsigned long t = 0; t < mesh.numTriangles; ++t) {
        const TQ3Point3D* p[3];
        for (int k = 0; k < 3; ++k)
            p[k] = &mesh.points[mesh.triangles[t].pointIndices[k]];
        double sign[3];
        for (int k = 0; k < 3; ++k) {
            const TQ3Point3D& a = *p[k];
            const TQ3Point3D& b = *p[(k + 1) % 3];
            sign[k] = (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
        }
        const bool allPositive = sign[0] > 0 && sign[1] > 0 && sign[2] > 0;
        const bool allNegative = sign[0] < 0 && sign[1] < 0 && sign[2] < 0;
        count += allPositive || allNegative;
    }
    return count;
}

struct State {
    std::vector<std::vector<TQ3Point3D>> points;
    std::vector<std::vector<TQ3AttributeSet>> sets;
    TQ3GeneralPolygonShapeHint hint = kQ3GeneralPolygonShapeHintComplex;
    TQ3AttributeSet whole = nullptr;
    unsigned long editIndex = 0;
};

State stateOf(TQ3GeometryObject polygon)
{
    TQ3GeneralPolygonData data{};
    EXPECT_EQ(Q3GeneralPolygon_GetData(polygon, &data), kQ3Success);
    State state;
    for (unsigned long c = 0; c < data.numContours; ++c) {
        state.points.emplace_back();
        state.sets.emplace_back();
        for (unsigned long i = 0; i < data.contours[c].numVertices; ++i) {
            state.points.back().push_back(data.contours[c].vertices[i].point);
            state.sets.back().push_back(data.contours[c].vertices[i].attributeSet);
        }
    }
    state.hint = data.shapeHint;
    state.whole = data.generalPolygonAttributeSet;
    state.editIndex = Q3Shared_GetEditIndex(polygon);
    EXPECT_EQ(Q3GeneralPolygon_EmptyData(&data), kQ3Success);
    return state;
}

void expectSame(const State& a, const State& b)
{
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t c = 0; c < a.points.size(); ++c) {
        ASSERT_EQ(a.points[c].size(), b.points[c].size());
        for (std::size_t i = 0; i < a.points[c].size(); ++i) {
            EXPECT_TRUE(samePoint(a.points[c][i], b.points[c][i]));
            EXPECT_EQ(a.sets[c][i], b.sets[c][i]);
        }
    }
    EXPECT_EQ(a.hint, b.hint);
    EXPECT_EQ(a.whole, b.whole);
    EXPECT_EQ(a.editIndex, b.editIndex);
}

TEST_F(GeneralPolygonApiTest, NewCopiesTheContoursThatGetDataReturnsAndEmptyDataReleases)
{
    TQ3AttributeSet set = own(colorSet(1, 0, 0));
    m_contours[1][2].attributeSet = set;
    m_data.generalPolygonAttributeSet = set;
    m_data.shapeHint = kQ3GeneralPolygonShapeHintConcave;
    TQ3GeometryObject polygon = own(Q3GeneralPolygon_New(&m_data));
    ASSERT_NE(polygon, nullptr);
    EXPECT_EQ(Q3Geometry_GetType(polygon), kQ3GeometryTypeGeneralPolygon);
    EXPECT_EQ(referenceCount(set), 3u);
    m_contours[2][0].point.x = 99; // the caller's array after New
    TQ3GeneralPolygonData out{};
    ASSERT_EQ(Q3GeneralPolygon_GetData(polygon, &out), kQ3Success);
    ASSERT_EQ(out.numContours, 3u);
    EXPECT_NE(out.contours, m_contourData.data());
    EXPECT_EQ(out.contours[2].numVertices, 6u);
    EXPECT_EQ(out.contours[2].vertices[0].point.x, -2.0f);
    EXPECT_EQ(out.contours[1].vertices[2].attributeSet, set);
    EXPECT_EQ(out.shapeHint, kQ3GeneralPolygonShapeHintConcave);
    EXPECT_EQ(out.generalPolygonAttributeSet, set);
    EXPECT_EQ(referenceCount(set), 5u);
    ASSERT_EQ(Q3GeneralPolygon_EmptyData(&out), kQ3Success);
    EXPECT_EQ(out.contours, nullptr);
    EXPECT_EQ(out.generalPolygonAttributeSet, nullptr);
    EXPECT_EQ(referenceCount(set), 3u);
    EXPECT_EQ(Q3GeneralPolygon_EmptyData(&out), kQ3Success);
}

TEST_F(GeneralPolygonApiTest, TheRulesAreCheckedInTheirOrder)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    TQ3GeneralPolygonData data = m_data;
    data.contours = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_New(&data), nullptr), kQ3ErrorNULLParameter);
    data = m_data;
    data.numContours = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_New(&data), nullptr), kQ3ErrorGeometryInsufficientNumberOfPoints);
    for (unsigned long count : {(unsigned long)kQ3GeometryMaxArrayCount + 1, ~0UL}) {
        data.numContours = count; // refused before any contour past the third is read
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_New(&data), nullptr), kQ3ErrorParameterOutOfRange);
    }
    data = m_data;
    for (int hint : {-1, 3, 1000}) {
        const TQ3GeneralPolygonShapeHint bad = static_cast<TQ3GeneralPolygonShapeHint>(hint);
        data.shapeHint = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_New(&data), nullptr), kQ3ErrorInvalidData);
    }
    data = m_data;
    m_contourData[1].vertices = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_New(&data), nullptr), kQ3ErrorNULLParameter);
    rebuild();
    for (unsigned long count : {0UL, 2UL}) {
        m_contourData[2].numVertices = count;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_New(&m_data), nullptr),
                        kQ3ErrorGeometryInsufficientNumberOfPoints);
    }
    m_contourData[2].numVertices = kQ3GeometryMaxArrayCount + 1;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_New(&m_data), nullptr), kQ3ErrorParameterOutOfRange);
    rebuild();
    for (float bad : kNonFinite) {
        m_contours[2][5].point.y = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_New(&m_data), nullptr), kQ3ErrorInvalidData);
    }
    m_contours[2][5].point.y = 2;
    m_contours[0][1].attributeSet = view();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_New(&m_data), nullptr), kQ3ErrorInvalidObjectType);
    m_contours[0][1].attributeSet = nullptr;
    m_data.generalPolygonAttributeSet = deadObject();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_New(&m_data), nullptr), kQ3ErrorInvalidObject);
    m_data.generalPolygonAttributeSet = strayHandle();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_New(&m_data), nullptr), kQ3ErrorInvalidObject);
    // Submit checks the view before the data.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_Submit(&m_data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
}

TEST_F(GeneralPolygonApiTest, FailedSetDataChangesNothingAndSetDataReplacesEverything)
{
    TQ3GeometryObject polygon = own(Q3GeneralPolygon_New(&m_data));
    ASSERT_NE(polygon, nullptr);
    const State before = stateOf(polygon);
    TQ3GeneralPolygonData bad = m_data;
    bad.numContours = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_SetData(polygon, &bad), kQ3Failure),
                    kQ3ErrorGeometryInsufficientNumberOfPoints);
    m_contours[1][0].point.z = kNaN;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_SetData(polygon, &m_data), kQ3Failure), kQ3ErrorInvalidData);
    m_contours[1][0].point.z = 0;
    m_contours[1][1].attributeSet = polygon;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_SetData(polygon, &m_data), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GeneralPolygon_SetData(polygon, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    expectSame(before, stateOf(polygon));

    m_contours[1][1].attributeSet = nullptr;
    m_contours.resize(1);
    rebuild();
    m_data.shapeHint = kQ3GeneralPolygonShapeHintConvex;
    ASSERT_EQ(Q3GeneralPolygon_SetData(polygon, &m_data), kQ3Success);
    const State after = stateOf(polygon);
    EXPECT_NE(after.editIndex, before.editIndex);
    ASSERT_EQ(after.points.size(), 1u);
    EXPECT_EQ(after.hint, kQ3GeneralPolygonShapeHintConvex);
}

TEST_F(GeneralPolygonApiTest, HandlesArePassedInTheHeadersOrder)
{
    TQ3GeometryObject polygon = own(Q3GeneralPolygon_New(&m_data));
    TQ3GeneralPolygonData out{};
    TQ3Point3D point{7, 7, 7};
    TQ3AttributeSet set = nullptr;
    TQ3GeneralPolygonShapeHint hint = kQ3GeneralPolygonShapeHintConvex;
    for (TQ3Object wrong : notGeneralPolygons()) {
        EXPECT_Q3_ERROR(Q3GeneralPolygon_GetData(wrong, &out), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3GeneralPolygon_SetData(wrong, &m_data), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3GeneralPolygon_GetVertexPosition(wrong, 0, 0, &point), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3GeneralPolygon_SetVertexPosition(wrong, 0, 0, &point), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3GeneralPolygon_GetVertexAttributeSet(wrong, 0, 0, &set), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3GeneralPolygon_SetVertexAttributeSet(wrong, 0, 0, nullptr), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3GeneralPolygon_GetShapeHint(wrong, &hint), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3GeneralPolygon_SetShapeHint(wrong, kQ3GeneralPolygonShapeHintComplex),
                        kQ3ErrorInvalidObjectType);
    }
    EXPECT_Q3_ERROR(Q3GeneralPolygon_GetData(nullptr, &out), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3GeneralPolygon_GetData(polygon, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3GeneralPolygon_EmptyData(nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3GeneralPolygon_GetVertexPosition(polygon, 0, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3GeneralPolygon_SetVertexPosition(polygon, 0, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3GeneralPolygon_GetVertexAttributeSet(polygon, 0, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3GeneralPolygon_GetShapeHint(polygon, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3GeneralPolygon_GetShapeHint(strayHandle(), &hint), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3GeneralPolygon_Submit(nullptr, view()), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3GeneralPolygon_Submit(&m_data, view()), kQ3ErrorViewNotStarted);
    EXPECT_EQ(out.contours, nullptr);
    EXPECT_EQ(point.x, 7.0f);
    EXPECT_EQ(hint, kQ3GeneralPolygonShapeHintConvex);
}

TEST_F(GeneralPolygonApiTest, VertexCallsCheckBothIndicesAtTheirEdgesAndChangeNothingOnFailure)
{
    TQ3AttributeSet set = own(colorSet(0, 1, 0));
    TQ3GeometryObject polygon = own(Q3GeneralPolygon_New(&m_data));
    TQ3Point3D point;
    ASSERT_EQ(Q3GeneralPolygon_GetVertexPosition(polygon, 0, 0, &point), kQ3Success);
    EXPECT_TRUE(samePoint(point, m_contours[0][0].point));
    ASSERT_EQ(Q3GeneralPolygon_GetVertexPosition(polygon, 2, 5, &point), kQ3Success);
    EXPECT_TRUE(samePoint(point, m_contours[2][5].point));
    const State before = stateOf(polygon);
    const TQ3Point3D moved{5, 6, 0};
    TQ3AttributeSet read = set;
    for (unsigned long bad : indicesPastTheEnd(3)) {
        EXPECT_Q3_ERROR(Q3GeneralPolygon_GetVertexPosition(polygon, bad, 0, &point), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(Q3GeneralPolygon_SetVertexPosition(polygon, bad, 0, &moved), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(Q3GeneralPolygon_GetVertexAttributeSet(polygon, bad, 0, &read), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(Q3GeneralPolygon_SetVertexAttributeSet(polygon, bad, 0, set), kQ3ErrorParameterOutOfRange);
    }
    for (unsigned long bad : indicesPastTheEnd(6)) {
        EXPECT_Q3_ERROR(Q3GeneralPolygon_GetVertexPosition(polygon, 2, bad, &point), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(Q3GeneralPolygon_SetVertexPosition(polygon, 2, bad, &moved), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(Q3GeneralPolygon_SetVertexAttributeSet(polygon, 2, bad, set), kQ3ErrorParameterOutOfRange);
    }
    EXPECT_Q3_ERROR(Q3GeneralPolygon_GetVertexPosition(polygon, 0, 4, &point), kQ3ErrorParameterOutOfRange);
    for (float bad : kNonFinite) {
        const TQ3Point3D p{1, bad, 0};
        EXPECT_Q3_ERROR(Q3GeneralPolygon_SetVertexPosition(polygon, 1, 3, &p), kQ3ErrorInvalidData);
    }
    EXPECT_Q3_ERROR(Q3GeneralPolygon_SetVertexAttributeSet(polygon, 1, 3, view()), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3GeneralPolygon_SetVertexAttributeSet(polygon, 1, 3, deadObject()), kQ3ErrorInvalidObject);
    for (int hint : {-1, 3}) {
        const TQ3GeneralPolygonShapeHint badHint = static_cast<TQ3GeneralPolygonShapeHint>(hint);
        EXPECT_Q3_ERROR(Q3GeneralPolygon_SetShapeHint(polygon, badHint), kQ3ErrorInvalidParameter);
    }
    expectSame(before, stateOf(polygon));
    EXPECT_EQ(read, set);

    ASSERT_EQ(Q3GeneralPolygon_SetVertexPosition(polygon, 2, 5, &moved), kQ3Success);
    ASSERT_EQ(Q3GeneralPolygon_SetVertexAttributeSet(polygon, 1, 3, set), kQ3Success);
    ASSERT_EQ(Q3GeneralPolygon_SetShapeHint(polygon, kQ3GeneralPolygonShapeHintConcave), kQ3Success);
    ASSERT_EQ(Q3GeneralPolygon_GetVertexPosition(polygon, 2, 5, &point), kQ3Success);
    EXPECT_TRUE(samePoint(point, moved));
    ASSERT_EQ(Q3GeneralPolygon_GetVertexAttributeSet(polygon, 1, 3, &read), kQ3Success);
    EXPECT_EQ(read, set);
    Q3Object_Dispose(read);
    ASSERT_EQ(Q3GeneralPolygon_GetVertexAttributeSet(polygon, 1, 2, &read), kQ3Success);
    EXPECT_EQ(read, nullptr);
    TQ3GeneralPolygonShapeHint hint;
    ASSERT_EQ(Q3GeneralPolygon_GetShapeHint(polygon, &hint), kQ3Success);
    EXPECT_EQ(hint, kQ3GeneralPolygonShapeHintConcave);
    EXPECT_EQ(referenceCount(set), 2u);
    ASSERT_EQ(Q3GeneralPolygon_SetVertexAttributeSet(polygon, 1, 3, nullptr), kQ3Success);
    EXPECT_EQ(referenceCount(set), 1u);
    EXPECT_GT(Q3Shared_GetEditIndex(polygon), before.editIndex);
}

// Property: the decomposition covers each sample point of a fine grid once
// where the crossing-number test says it is inside, and never elsewhere
// (points on a contour's line are skipped). Its vertices are the data's.
TEST_F(GeneralPolygonApiTest, TheDecompositionFillsExactlyTheEvenOddInside)
{
    // A second shape: a concave comb with two holes, one of them concave.
    std::vector<std::vector<TQ3Vertex3D>> comb = {
        {{{-5, -3, 0}, nullptr}, {{5, -3, 0}, nullptr}, {{5, 3, 0}, nullptr}, {{3, 3, 0}, nullptr},
         {{3, -1, 0}, nullptr},  {{1, -1, 0}, nullptr}, {{1, 3, 0}, nullptr}, {{-5, 3, 0}, nullptr}},
        {{{-4, -2, 0}, nullptr}, {{-2, -2, 0}, nullptr}, {{-3, 2, 0}, nullptr}},
        {{{-1.5f, -2.5f, 0}, nullptr}, {{0.5f, -2.5f, 0}, nullptr}, {{0.5f, 2.5f, 0}, nullptr},
         {{0, 2.5f, 0}, nullptr}, {{0, -2, 0}, nullptr}, {{-1.5f, -2, 0}, nullptr}}};
    for (int shape = 0; shape < 2; ++shape) {
        if (shape == 1) {
            m_contours = comb;
            rebuild();
        }
        TQ3GeometryObject polygon = own(Q3GeneralPolygon_New(&m_data));
        ASSERT_NE(polygon, nullptr);
        TQ3TriMeshData mesh = decomposed(polygon);
        std::size_t total = 0;
        for (const auto& c : m_contours)
            total += c.size();
        ASSERT_EQ(mesh.numPoints, total);
        std::size_t at = 0;
        for (const auto& c : m_contours)
            for (const TQ3Vertex3D& v : c)
                EXPECT_TRUE(samePoint(mesh.points[at++], v.point));
        int inside = 0;
        for (double y = -5.03; y < 5; y += 0.1)
            for (double x = -5.07; x < 5; x += 0.1) {
                const int expected = insideEvenOdd(m_contours, x, y) ? 1 : 0;
                inside += expected;
                EXPECT_EQ(coverage(mesh, x, y), expected) << "shape " << shape << " at " << x << ", " << y;
            }
        EXPECT_GT(inside, 500);
        Q3TriMesh_EmptyData(&mesh);
    }
}

TEST_F(GeneralPolygonApiTest, BoundsHoldEveryContour)
{
    TQ3GeometryObject polygon = own(Q3GeneralPolygon_New(&m_data));
    const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) { Q3Geometry_Submit(polygon, v); });
    EXPECT_EQ(box.min.x, -4.0f);
    EXPECT_EQ(box.max.y, 4.0f);
    EXPECT_EQ(box.min.z, 0.0f);
}

} // namespace
