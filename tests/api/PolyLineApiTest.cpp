// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// What is the polyline's own among the Q3PolyLine_* calls: its two vertices
// at least, its rules in their order, the per-segment calls (and the
// per-vertex calls beside them), and the calls before Q3Initialize. New,
// GetData, SetData, EmptyData, Submit, Duplicate, bounds and the per-vertex
// calls are tried by the contract suites (GeometryContractTest.cpp).

#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <vector>

namespace {

using q3test::Q3ApiTest;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

TQ3AttributeSet colorSet(float r, float g, float b)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB color{r, g, b};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color);
    return set;
}

class PolyLineApiTest : public q3test::OwningApiTest {
protected:
    void SetUp() override
    {
        Q3ApiTest::SetUp();
        m_vertices = {{{1, 2, 3}, nullptr}, {{4, -5, 6}, nullptr}, {{-7, 8, 0}, nullptr}};
        m_data = TQ3PolyLineData{3, m_vertices.data(), nullptr, nullptr};
    }

    std::vector<TQ3Vertex3D> m_vertices;
    TQ3PolyLineData m_data{};
};

// Everything GetData reports, copied out so that a failed call can be shown to
// have changed nothing.
struct PolyLineState {
    std::vector<TQ3Point3D> points;
    std::vector<TQ3AttributeSet> vertexSets;
    std::vector<TQ3AttributeSet> segmentSets; // empty when there is no segment array
    TQ3AttributeSet whole = nullptr;
    unsigned long editIndex = 0;
};

PolyLineState stateOf(TQ3GeometryObject polyLine)
{
    PolyLineState state;
    TQ3PolyLineData data{};
    EXPECT_EQ(Q3PolyLine_GetData(polyLine, &data), kQ3Success);
    for (unsigned long i = 0; i < data.numVertices; ++i) {
        state.points.push_back(data.vertices[i].point);
        state.vertexSets.push_back(data.vertices[i].attributeSet);
    }
    if (data.segmentAttributeSet != nullptr)
        state.segmentSets.assign(data.segmentAttributeSet, data.segmentAttributeSet + data.numVertices - 1);
    state.whole = data.polyLineAttributeSet;
    EXPECT_EQ(Q3PolyLine_EmptyData(&data), kQ3Success);
    state.editIndex = Q3Shared_GetEditIndex(polyLine);
    return state;
}

void expectSameState(const PolyLineState& before, const PolyLineState& after)
{
    ASSERT_EQ(before.points.size(), after.points.size());
    for (std::size_t i = 0; i < before.points.size(); ++i) {
        EXPECT_EQ(before.points[i].x, after.points[i].x) << "vertex " << i;
        EXPECT_EQ(before.points[i].y, after.points[i].y) << "vertex " << i;
        EXPECT_EQ(before.points[i].z, after.points[i].z) << "vertex " << i;
    }
    EXPECT_EQ(before.vertexSets, after.vertexSets);
    EXPECT_EQ(before.segmentSets, after.segmentSets);
    EXPECT_EQ(before.whole, after.whole);
    EXPECT_EQ(before.editIndex, after.editIndex);
}

// ---- Its size ----------------------------------------------------------

TEST_F(PolyLineApiTest, TheSmallestPolyLineHasTwoVertices)
{
    m_data.numVertices = 2;
    TQ3GeometryObject polyLine = own(Q3PolyLine_New(&m_data));
    ASSERT_NE(polyLine, nullptr);
    EXPECT_EQ(stateOf(polyLine).points.size(), 2u);
}

// ---- The TQ3PolyLineData rules ----------------------------------------------------

TEST_F(PolyLineApiTest, NewRejectsNullDataAndNullVertices)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PolyLine_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    m_data.vertices = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PolyLine_New(&m_data), nullptr), kQ3ErrorNULLParameter);
    // NULL vertices is reported before too few of them.
    m_data.numVertices = 1;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PolyLine_New(&m_data), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(PolyLineApiTest, NewRejectsFewerThanTwoVertices)
{
    for (unsigned long count : {0UL, 1UL}) {
        m_data.numVertices = count;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PolyLine_New(&m_data), nullptr),
                        kQ3ErrorGeometryInsufficientNumberOfPoints);
    }
}

// ---- Submit and bounds -------------------------------------------------------------------

TEST_F(PolyLineApiTest, SubmitInsideALoopChecksTheDataRules)
{
    const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
        TQ3PolyLineData bad = m_data;
        bad.numVertices = 0;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PolyLine_Submit(&bad, v), kQ3Failure),
                        kQ3ErrorGeometryInsufficientNumberOfPoints);
        bad = m_data;
        bad.vertices = nullptr;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PolyLine_Submit(&bad, v), kQ3Failure), kQ3ErrorNULLParameter);
        std::vector<TQ3Vertex3D> nan = m_vertices;
        nan[2].point.z = kNaN;
        bad = m_data;
        bad.vertices = nan.data();
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PolyLine_Submit(&bad, v), kQ3Failure), kQ3ErrorInvalidData);
        bad = m_data;
        bad.polyLineAttributeSet = v;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PolyLine_Submit(&bad, v), kQ3Failure), kQ3ErrorInvalidObjectType);
    });
    EXPECT_EQ(box.isEmpty, kQ3True);
}

// ---- Per-vertex and per-segment access (QuickDraw 3D 1.6) ---------------------------

// Indices every index-taking call is tried at besides the valid ones: one past
// the end, UINT32_MAX, and the largest unsigned long (where index + 1 wraps).
constexpr unsigned long kHugeIndices[] = {std::numeric_limits<std::uint32_t>::max(),
                                          std::numeric_limits<unsigned long>::max()};

TEST_F(PolyLineApiTest, SegmentAttributeSetsAreReadAndReplacedWithBalancedReferences)
{
    TQ3AttributeSet green = own(colorSet(0, 1, 0));
    TQ3AttributeSet blue = own(colorSet(0, 0, 1));
    TQ3AttributeSet segments[2] = {green, nullptr};
    m_data.segmentAttributeSet = segments;
    TQ3GeometryObject polyLine = Q3PolyLine_New(&m_data);
    ASSERT_NE(polyLine, nullptr);

    TQ3AttributeSet got = blue;
    ASSERT_EQ(Q3PolyLine_GetSegmentAttributeSet(polyLine, 1, &got), kQ3Success); // the last segment
    EXPECT_EQ(got, nullptr);
    ASSERT_EQ(Q3PolyLine_GetSegmentAttributeSet(polyLine, 0, &got), kQ3Success);
    EXPECT_EQ(got, green);
    Q3Object_Dispose(got);

    const unsigned long edit = Q3Shared_GetEditIndex(polyLine);
    EXPECT_EQ(Q3PolyLine_SetSegmentAttributeSet(polyLine, 1, blue), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(polyLine), edit);
    EXPECT_EQ(Q3PolyLine_SetSegmentAttributeSet(polyLine, 0, blue), kQ3Success);
    EXPECT_EQ(Q3Shared_IsReferenced(green), kQ3False);
    const PolyLineState state = stateOf(polyLine);
    EXPECT_EQ(state.segmentSets, (std::vector<TQ3AttributeSet>{blue, blue}));
    EXPECT_EQ(state.vertexSets, std::vector<TQ3AttributeSet>(3, nullptr));

    EXPECT_EQ(Q3PolyLine_SetSegmentAttributeSet(polyLine, 0, nullptr), kQ3Success);
    ASSERT_EQ(Q3PolyLine_GetSegmentAttributeSet(polyLine, 0, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    EXPECT_EQ(Q3Shared_IsReferenced(blue), kQ3True); // segment 1 still holds it
    Q3Object_Dispose(polyLine);
    EXPECT_EQ(Q3Shared_IsReferenced(blue), kQ3False);
}

TEST_F(PolyLineApiTest, APolyLineWithoutSegmentSetsGainsAnArrayOnlyWhenGivenASet)
{
    TQ3AttributeSet set = own(colorSet(1, 1, 0));
    TQ3GeometryObject polyLine = own(Q3PolyLine_New(&m_data));
    ASSERT_NE(polyLine, nullptr);
    for (unsigned long index : {0UL, 1UL}) {
        TQ3AttributeSet got = set;
        ASSERT_EQ(Q3PolyLine_GetSegmentAttributeSet(polyLine, index, &got), kQ3Success);
        EXPECT_EQ(got, nullptr);
    }
    unsigned long edit = Q3Shared_GetEditIndex(polyLine);
    EXPECT_EQ(Q3PolyLine_SetSegmentAttributeSet(polyLine, 1, nullptr), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(polyLine), edit);
    EXPECT_TRUE(stateOf(polyLine).segmentSets.empty());

    edit = Q3Shared_GetEditIndex(polyLine);
    EXPECT_EQ(Q3PolyLine_SetSegmentAttributeSet(polyLine, 1, set), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(polyLine), edit);
    const PolyLineState state = stateOf(polyLine);
    EXPECT_EQ(state.segmentSets, (std::vector<TQ3AttributeSet>{nullptr, set}));
}

TEST_F(PolyLineApiTest, IndexedAttributeSetCallsRejectBadIndicesAndChangeNothing)
{
    TQ3AttributeSet set = own(colorSet(0, 1, 1));
    TQ3AttributeSet segments[2] = {set, set};
    m_vertices[1].attributeSet = set;
    m_data.segmentAttributeSet = segments;
    TQ3GeometryObject polyLine = own(Q3PolyLine_New(&m_data));
    ASSERT_NE(polyLine, nullptr);
    const PolyLineState before = stateOf(polyLine);

    // One past the end and the huge indices.
    const auto pastTheEnd = [](unsigned long onePast) {
        std::vector<unsigned long> bad = {onePast};
        bad.insert(bad.end(), std::begin(kHugeIndices), std::end(kHugeIndices));
        return bad;
    };
    // Past the end, the get leaves its result as it was and the set (of
    // `value`) is refused too.
    const auto expectPastTheEndRefused = [&](auto get, auto put, unsigned long onePast, TQ3AttributeSet value) {
        for (unsigned long index : pastTheEnd(onePast)) {
            TQ3AttributeSet got = set;
            EXPECT_Q3_ERROR(EXPECT_EQ(get(polyLine, index, &got), kQ3Failure), kQ3ErrorParameterOutOfRange);
            EXPECT_EQ(got, set); // unchanged on failure
            EXPECT_Q3_ERROR(EXPECT_EQ(put(polyLine, index, value), kQ3Failure), kQ3ErrorParameterOutOfRange);
        }
    };
    expectPastTheEndRefused(Q3PolyLine_GetVertexAttributeSet, Q3PolyLine_SetVertexAttributeSet, 3, nullptr);
    expectPastTheEndRefused(Q3PolyLine_GetSegmentAttributeSet, Q3PolyLine_SetSegmentAttributeSet, 2, set);
    expectSameState(before, stateOf(polyLine));

    // Without a segment array the segment count still bounds the index.
    m_data.segmentAttributeSet = nullptr;
    TQ3GeometryObject plain = own(Q3PolyLine_New(&m_data));
    for (unsigned long index : pastTheEnd(2)) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PolyLine_SetSegmentAttributeSet(plain, index, set), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
    }
    EXPECT_TRUE(stateOf(plain).segmentSets.empty());
}

TEST_F(PolyLineApiTest, PerVertexCallsRejectBadArgumentsAndChangeNothing)
{
    TQ3AttributeSet set = own(colorSet(1, 0, 1));
    TQ3GeometryObject polyLine = own(Q3PolyLine_New(&m_data));
    ASSERT_NE(polyLine, nullptr);
    const TQ3Vector3D offset{1, 1, 1};
    TQ3TransformObject notASet = own(Q3TranslateTransform_New(&offset));
    const TQ3LineData lineData{{{{0, 0, 0}, nullptr}, {{1, 1, 1}, nullptr}}, nullptr};
    TQ3GeometryObject notAPolyLine = own(Q3Line_New(&lineData));
    int notAnObject = 0;
    TQ3GeometryObject stray = reinterpret_cast<TQ3GeometryObject>(&notAnObject);
    const PolyLineState before = stateOf(polyLine);
    TQ3Point3D position{};
    TQ3AttributeSet got = nullptr;

    for (TQ3GeometryObject wrong : {static_cast<TQ3GeometryObject>(nullptr), notAPolyLine, stray}) {
        const TQ3Error code = wrong == nullptr       ? kQ3ErrorNULLParameter
                              : wrong == notAPolyLine ? kQ3ErrorInvalidObjectType
                                                      : kQ3ErrorInvalidObject;
        EXPECT_Q3_ERROR(Q3PolyLine_GetVertexPosition(wrong, 0, &position), code);
        EXPECT_Q3_ERROR(Q3PolyLine_SetVertexPosition(wrong, 0, &position), code);
        EXPECT_Q3_ERROR(Q3PolyLine_GetVertexAttributeSet(wrong, 0, &got), code);
        EXPECT_Q3_ERROR(Q3PolyLine_SetVertexAttributeSet(wrong, 0, set), code);
        EXPECT_Q3_ERROR(Q3PolyLine_GetSegmentAttributeSet(wrong, 0, &got), code);
        EXPECT_Q3_ERROR(Q3PolyLine_SetSegmentAttributeSet(wrong, 0, set), code);
    }
    const auto fails = [&](TQ3Status status, TQ3Error code) {
        EXPECT_Q3_ERROR(EXPECT_EQ(status, kQ3Failure), code);
    };
    fails(Q3PolyLine_GetVertexPosition(polyLine, 0, nullptr), kQ3ErrorNULLParameter);
    fails(Q3PolyLine_SetVertexPosition(polyLine, 0, nullptr), kQ3ErrorNULLParameter);
    fails(Q3PolyLine_GetVertexAttributeSet(polyLine, 0, nullptr), kQ3ErrorNULLParameter);
    fails(Q3PolyLine_GetSegmentAttributeSet(polyLine, 0, nullptr), kQ3ErrorNULLParameter);
    // A NULL pointer is reported before a bad index.
    EXPECT_Q3_ERROR(Q3PolyLine_SetVertexPosition(polyLine, 99, nullptr), kQ3ErrorNULLParameter);
    // A bad attribute set handle is reported before a bad index.
    fails(Q3PolyLine_SetVertexAttributeSet(polyLine, 0, notASet), kQ3ErrorInvalidObjectType);
    fails(Q3PolyLine_SetSegmentAttributeSet(polyLine, 99, notASet), kQ3ErrorInvalidObjectType);
    fails(Q3PolyLine_SetVertexAttributeSet(polyLine, 0, stray), kQ3ErrorInvalidObject);
    fails(Q3PolyLine_SetSegmentAttributeSet(polyLine, 0, stray), kQ3ErrorInvalidObject);
    expectSameState(before, stateOf(polyLine));
}

TEST(PolyLineApiUninitialized, EveryFunctionFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    TQ3PolyLineData data{};
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    EXPECT_EQ(Q3PolyLine_New(&data), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3PolyLine_Submit(&data, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3PolyLine_GetData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3PolyLine_SetData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3PolyLine_EmptyData(&data), kQ3Failure);
    EXPECT_TRUE(failed());
    TQ3Point3D position{};
    TQ3AttributeSet set = nullptr;
    EXPECT_EQ(Q3PolyLine_GetVertexPosition(nullptr, 0, &position), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3PolyLine_SetVertexPosition(nullptr, 0, &position), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3PolyLine_GetVertexAttributeSet(nullptr, 0, &set), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3PolyLine_SetVertexAttributeSet(nullptr, 0, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3PolyLine_GetSegmentAttributeSet(nullptr, 0, &set), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3PolyLine_SetSegmentAttributeSet(nullptr, 0, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
}

} // namespace
