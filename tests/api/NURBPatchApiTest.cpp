// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Every Q3NURBPatch_* call, at every index edge (0, the last, one past,
// ULONG_MAX) and with NaN and infinities, NULL, dead and wrong-class handles;
// every rule of TQ3NURBPatchData refused alike by New, SetData and Submit,
// with the rule and the place named; a failed edit leaves the patch and its
// edit index as they were; drawing, decomposing and bounding a patch.

#include "RenderTestSupport.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"

#include <climits>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

using namespace q3test;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A trim curve that owns its arrays.
struct TrimCurve {
    unsigned long order = 2;
    std::vector<TQ3RationalPoint3D> points;
    std::vector<float> knots;
};

// A straight trim curve from (u0, v0) to (u1, v1).
TrimCurve segment(float u0, float v0, float u1, float v1)
{
    return TrimCurve{2, {{u0, v0, 1}, {u1, v1, 1}}, {0, 0, 1, 1}};
}

// A closed polygon as a loop of straight curves.
std::vector<TrimCurve> polygon(const std::vector<std::pair<float, float>>& corners)
{
    std::vector<TrimCurve> loop;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const auto& a = corners[i];
        const auto& b = corners[(i + 1) % corners.size()];
        loop.push_back(segment(a.first, a.second, b.first, b.second));
    }
    return loop;
}

// A patch that owns its arrays, so each test can break one thing: by default
// a bicubic 4 x 5 patch (5 columns in u, 4 rows in v) over [0, 2] x [0, 1]
// with an interior u knot, lying over x 0..3, y 0..1 (the view of Listing 1).
struct PatchArrays {
    unsigned long uOrder = 4;
    unsigned long vOrder = 4;
    unsigned long numRows = 4;
    unsigned long numColumns = 5;
    std::vector<TQ3RationalPoint4D> points;
    std::vector<float> uKnots{0, 0, 0, 0, 1, 2, 2, 2, 2};
    std::vector<float> vKnots{0, 0, 0, 0, 1, 1, 1, 1};
    std::vector<std::vector<TrimCurve>> loops;
    TQ3AttributeSet attributes = nullptr;

    std::vector<TQ3NURBPatchTrimLoopData> loopData;
    std::vector<std::vector<TQ3NURBPatchTrimCurveData>> curveData;

    PatchArrays()
    {
        for (unsigned long r = 0; r < numRows; ++r)
            for (unsigned long c = 0; c < numColumns; ++c) {
                const float w = (r + c) % 2 == 0 ? 1.0f : 0.8f;
                const float z = (r == 1 || r == 2) && (c == 2) ? 0.5f : 0.0f;
                points.push_back({0.75f * c * w, r / 3.0f * w, z * w, w});
            }
    }

    TQ3NURBPatchData data()
    {
        loopData.clear();
        curveData.assign(loops.size(), {});
        for (std::size_t l = 0; l < loops.size(); ++l) {
            for (TrimCurve& c : loops[l])
                curveData[l].push_back(TQ3NURBPatchTrimCurveData{c.order, c.points.size(), c.points.data(),
                                                                 c.knots.data()});
            loopData.push_back(TQ3NURBPatchTrimLoopData{curveData[l].size(), curveData[l].data()});
        }
        return TQ3NURBPatchData{uOrder,        vOrder,        numRows,        numColumns,
                                points.data(), uKnots.data(), vKnots.data(),  loopData.size(),
                                loopData.empty() ? nullptr : loopData.data(), attributes};
    }
};

// A patch with an outer counterclockwise square and a clockwise square hole.
PatchArrays trimmed()
{
    PatchArrays p;
    p.loops.push_back(polygon({{0.1f, 0.1f}, {1.9f, 0.1f}, {1.9f, 0.9f}, {0.1f, 0.9f}}));
    p.loops.push_back(polygon({{0.5f, 0.3f}, {0.5f, 0.7f}, {1.5f, 0.7f}, {1.5f, 0.3f}}));
    return p;
}

class NURBPatchApiTest : public Q3ApiTest {
protected:
    // The whole state of a patch, to prove a failed call changed nothing.
    struct Snapshot {
        std::vector<float> values;
        unsigned long editIndex = 0;
        bool operator==(const Snapshot& o) const { return values == o.values && editIndex == o.editIndex; }
    };

    Snapshot snapshot(TQ3GeometryObject patch)
    {
        TQ3NURBPatchData d{};
        EXPECT_EQ(Q3NURBPatch_GetData(patch, &d), kQ3Success);
        Snapshot s;
        for (unsigned long v : {d.uOrder, d.vOrder, d.numRows, d.numColumns, d.numTrimLoops})
            s.values.push_back(float(v));
        for (unsigned long i = 0; i < d.numRows * d.numColumns; ++i) {
            const TQ3RationalPoint4D& p = d.controlPoints[i];
            s.values.insert(s.values.end(), {p.x, p.y, p.z, p.w});
        }
        s.values.insert(s.values.end(), d.uKnots, d.uKnots + d.uOrder + d.numColumns);
        s.values.insert(s.values.end(), d.vKnots, d.vKnots + d.vOrder + d.numRows);
        for (unsigned long l = 0; l < d.numTrimLoops; ++l)
            for (unsigned long c = 0; c < d.trimLoops[l].numTrimCurves; ++c) {
                const TQ3NURBPatchTrimCurveData& curve = d.trimLoops[l].trimCurves[c];
                s.values.push_back(float(curve.order));
                for (unsigned long i = 0; i < curve.numPoints; ++i)
                    s.values.insert(s.values.end(),
                                    {curve.controlPoints[i].x, curve.controlPoints[i].y, curve.controlPoints[i].w});
                s.values.insert(s.values.end(), curve.knots, curve.knots + curve.numPoints + curve.order);
            }
        s.values.push_back(d.patchAttributeSet == nullptr ? 0.0f : 1.0f);
        EXPECT_EQ(Q3NURBPatch_EmptyData(&d), kQ3Success);
        s.editIndex = Q3Shared_GetEditIndex(patch);
        return s;
    }

    TQ3GeometryObject newPatch(PatchArrays arrays = PatchArrays())
    {
        const TQ3NURBPatchData data = arrays.data();
        TQ3GeometryObject patch = Q3NURBPatch_New(&data);
        EXPECT_NE(patch, nullptr);
        return patch;
    }

    // New, SetData and immediate Submit must all refuse the data with `code`
    // and a message containing `where`; nothing is created or changed.
    void expectRejected(PatchArrays arrays, TQ3Error code, const std::string& where)
    {
        const TQ3NURBPatchData data = arrays.data();
        const unsigned long live = Q3Memory_CountLiveObjects();
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_New(&data), nullptr), code);
        EXPECT_NE(std::string(Q3Error_GetMessage()).find(where), std::string::npos)
            << "the message \"" << Q3Error_GetMessage() << "\" does not name " << where;
        EXPECT_EQ(Q3Memory_CountLiveObjects(), live);

        TQ3GeometryObject patch = newPatch();
        const Snapshot before = snapshot(patch);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_SetData(patch, &data), kQ3Failure), code);
        EXPECT_EQ(snapshot(patch), before);
        Q3Object_Dispose(patch);

        Pixmap image(32, 32);
        TestView view(image.pixmap());
        ASSERT_EQ(Q3View_StartRendering(view.view()), kQ3Success);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_Submit(&data, view.view()), kQ3Failure), code);
        Q3View_Cancel(view.view());
        EXPECT_EQ(Q3View_EndRendering(view.view()), kQ3ViewStatusCancelled);
    }

    // Runs `body` in a rendering loop of a size x size view under `style`
    // (none: the view's default), then cancels the loop.
    void whileRendering(const TQ3SubdivisionStyleData* style, unsigned long size,
                        const std::function<void(TQ3ViewObject)>& body)
    {
        Pixmap image(size, size);
        TestView view(image.pixmap());
        ASSERT_EQ(Q3View_StartRendering(view.view()), kQ3Success);
        if (style != nullptr)
            EXPECT_EQ(Q3SubdivisionStyle_Submit(style, view.view()), kQ3Success);
        body(view.view());
        Q3View_Cancel(view.view());
        Q3View_EndRendering(view.view());
    }

    // Decomposes `patch` in a rendering loop under `style` (none: the
    // view's default) and returns the TriMesh's data (caller empties it).
    TQ3TriMeshData decompose(TQ3GeometryObject patch, const TQ3SubdivisionStyleData* style)
    {
        TQ3TriMeshData mesh{};
        Pixmap image(64, 64);
        TestView view(image.pixmap());
        EXPECT_EQ(Q3View_StartRendering(view.view()), kQ3Success);
        if (style != nullptr)
            EXPECT_EQ(Q3SubdivisionStyle_Submit(style, view.view()), kQ3Success);
        TQ3GeometryObject triMesh = Q3Geometry_GetDecomposed(patch, view.view());
        EXPECT_NE(triMesh, nullptr);
        if (triMesh != nullptr) {
            EXPECT_EQ(Q3Geometry_GetType(triMesh), kQ3GeometryTypeTriMesh);
            EXPECT_EQ(Q3TriMesh_GetData(triMesh, &mesh), kQ3Success);
            Q3Object_Dispose(triMesh);
        }
        Q3View_Cancel(view.view());
        Q3View_EndRendering(view.view());
        return mesh;
    }
};

// ---- New, GetData, EmptyData, SetData, Duplicate --------------------------

TEST_F(NURBPatchApiTest, NewCopiesEveryArrayAndGetDataGivesThemBack)
{
    PatchArrays arrays = trimmed();
    TQ3GeometryObject patch = newPatch(arrays);
    EXPECT_EQ(Q3Geometry_GetType(patch), kQ3GeometryTypeNURBPatch);
    arrays.points[0].x = 99.0f;
    arrays.uKnots[4] = 1.5f;
    arrays.loops[1][0].points[0].x = 0.6f;
    TQ3NURBPatchData got{};
    ASSERT_EQ(Q3NURBPatch_GetData(patch, &got), kQ3Success);
    const PatchArrays original = trimmed();
    EXPECT_EQ(got.uOrder, 4u);
    EXPECT_EQ(got.vOrder, 4u);
    EXPECT_EQ(got.numRows, 4u);
    EXPECT_EQ(got.numColumns, 5u);
    EXPECT_EQ(std::memcmp(got.controlPoints, original.points.data(), 20 * sizeof(TQ3RationalPoint4D)), 0);
    EXPECT_EQ(std::memcmp(got.uKnots, original.uKnots.data(), 9 * sizeof(float)), 0);
    EXPECT_EQ(std::memcmp(got.vKnots, original.vKnots.data(), 8 * sizeof(float)), 0);
    ASSERT_EQ(got.numTrimLoops, 2u);
    ASSERT_EQ(got.trimLoops[1].numTrimCurves, 4u);
    EXPECT_EQ(got.trimLoops[1].trimCurves[0].controlPoints[0].x, 0.5f);
    EXPECT_EQ(got.trimLoops[1].trimCurves[0].knots[3], 1.0f);
    EXPECT_EQ(got.patchAttributeSet, nullptr);
    EXPECT_EQ(Q3NURBPatch_EmptyData(&got), kQ3Success);
    EXPECT_EQ(got.controlPoints, nullptr);
    EXPECT_EQ(got.uKnots, nullptr);
    EXPECT_EQ(got.vKnots, nullptr);
    EXPECT_EQ(got.trimLoops, nullptr);
    EXPECT_EQ(Q3NURBPatch_EmptyData(&got), kQ3Success); // a second time does nothing
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, SetDataReplacesEverythingAndBumpsTheEditIndex)
{
    TQ3GeometryObject patch = newPatch();
    const unsigned long before = Q3Shared_GetEditIndex(patch);
    PatchArrays other = trimmed();
    other.uOrder = 2;
    other.numColumns = 3;
    other.points.resize(12);
    other.uKnots = {0, 0, 1, 2, 2};
    TQ3NURBPatchData data = other.data();
    EXPECT_EQ(Q3NURBPatch_SetData(patch, &data), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(patch), before);
    TQ3NURBPatchData got{};
    ASSERT_EQ(Q3NURBPatch_GetData(patch, &got), kQ3Success);
    EXPECT_EQ(got.uOrder, 2u);
    EXPECT_EQ(got.numColumns, 3u);
    EXPECT_EQ(got.numTrimLoops, 2u);
    Q3NURBPatch_EmptyData(&got);
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, DuplicateIsADeepCopy)
{
    TQ3GeometryObject patch = newPatch(trimmed());
    TQ3GeometryObject copy = Q3Object_Duplicate(patch);
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(snapshot(copy).values, snapshot(patch).values);
    const TQ3RationalPoint4D moved = {5, 5, 5, 1};
    EXPECT_EQ(Q3NURBPatch_SetControlPoint(patch, 0, 0, &moved), kQ3Success);
    TQ3RationalPoint4D point{};
    EXPECT_EQ(Q3NURBPatch_GetControlPoint(copy, 0, 0, &point), kQ3Success);
    EXPECT_EQ(point.x, 0.0f);
    Q3Object_Dispose(copy);
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, TheAttributeSetIsHeldAndGivenBack)
{
    PatchArrays arrays;
    arrays.attributes = Q3AttributeSet_New();
    const TQ3ColorRGB red = {1, 0, 0};
    Q3AttributeSet_Add(arrays.attributes, kQ3AttributeTypeDiffuseColor, &red);
    TQ3GeometryObject patch = newPatch(arrays);
    TQ3AttributeSet set = nullptr;
    EXPECT_EQ(Q3Geometry_GetAttributeSet(patch, &set), kQ3Success);
    EXPECT_EQ(set, arrays.attributes);
    Q3Object_Dispose(set);
    Q3Object_Dispose(arrays.attributes);
    Q3Object_Dispose(patch);
}

// ---- The rules, in their order ---------------------------------------------

TEST_F(NURBPatchApiTest, OrdersOutsideTwoToElevenAreRefused)
{
    for (unsigned long order : {0UL, 1UL, 12UL, ULONG_MAX}) {
        PatchArrays u;
        u.uOrder = order;
        expectRejected(u, kQ3ErrorParameterOutOfRange, "uOrder");
        PatchArrays v;
        v.vOrder = order;
        expectRejected(v, kQ3ErrorParameterOutOfRange, "vOrder");
    }
    EXPECT_EQ(kQ3NURBPatchMaxOrder, 11);
}

TEST_F(NURBPatchApiTest, FewerPointsThanTheOrderAreRefused)
{
    PatchArrays u;
    u.uOrder = 6;
    expectRejected(u, kQ3ErrorGeometryInsufficientNumberOfPoints, "numColumns 5 is less than uOrder 6");
    PatchArrays v;
    v.vOrder = 5;
    expectRejected(v, kQ3ErrorGeometryInsufficientNumberOfPoints, "numRows 4 is less than vOrder 5");
}

TEST_F(NURBPatchApiTest, CountsNoArrayCouldHoldAreRefusedBeforeAnythingIsRead)
{
    PatchArrays rows;
    rows.numRows = ULONG_MAX;
    rows.points.clear(); // Q3 must not read them
    expectRejected(rows, kQ3ErrorParameterOutOfRange, "numRows * numColumns");
    PatchArrays columns;
    columns.numColumns = (1UL << 28) + 1;
    expectRejected(columns, kQ3ErrorParameterOutOfRange, "kQ3GeometryMaxArrayCount");
    PatchArrays loops;
    loops.loops.push_back(polygon({{0.1f, 0.1f}, {1, 0.1f}, {1, 0.9f}}));
    TQ3NURBPatchData data = loops.data();
    data.numTrimLoops = ULONG_MAX;
    const unsigned long live = Q3Memory_CountLiveObjects();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_New(&data), nullptr), kQ3ErrorParameterOutOfRange);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live);
}

TEST_F(NURBPatchApiTest, NullArraysAreRefused)
{
    for (int which = 0; which < 4; ++which) {
        PatchArrays p = which == 3 ? trimmed() : PatchArrays();
        TQ3NURBPatchData data = p.data();
        const char* name = "controlPoints";
        if (which == 0)
            data.controlPoints = nullptr;
        else if (which == 1) {
            data.uKnots = nullptr;
            name = "uKnots";
        } else if (which == 2) {
            data.vKnots = nullptr;
            name = "vKnots";
        } else {
            data.trimLoops = nullptr;
            name = "trimLoops";
        }
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_New(&data), nullptr), kQ3ErrorNULLParameter);
        EXPECT_NE(std::string(Q3Error_GetMessage()).find(name), std::string::npos);
    }
}

TEST_F(NURBPatchApiTest, KnotRulesNameTheKnotAndItsValue)
{
    PatchArrays decreasing;
    decreasing.uKnots = {0, 0, 0, 0, 1, 0.5f, 2, 2, 2};
    expectRejected(decreasing, kQ3ErrorInvalidData, "uKnots[5] = 0.5 is less than uKnots[4] = 1");
    PatchArrays nan;
    nan.vKnots[2] = kNaN;
    expectRejected(nan, kQ3ErrorInvalidData, "vKnots[2] is nan");
    PatchArrays inf;
    inf.uKnots[8] = kInf;
    expectRejected(inf, kQ3ErrorInvalidData, "uKnots[8] is inf");
    PatchArrays minusInf;
    minusInf.uKnots[0] = -kInf;
    expectRejected(minusInf, kQ3ErrorInvalidData, "uKnots[0] is -inf");
    PatchArrays run;
    run.uKnots = {0, 0, 0, 0, 1, 1, 1, 1, 2};
    run.uKnots = {0, 0, 0, 0, 2, 2, 2, 2, 2};
    expectRejected(run, kQ3ErrorInvalidData, "uKnots[4..8] are all 2");
    PatchArrays inside;
    inside.numColumns = 6;
    inside.points.resize(24, {0, 0, 0, 1});
    inside.uKnots = {0, 0, 0, 0, 1, 1, 1, 1, 2, 2};
    expectRejected(inside, kQ3ErrorInvalidData, "uKnots[4..7] are all 1");
    PatchArrays empty;
    empty.vKnots = {1, 1, 1, 1, 1, 1, 1, 1};
    expectRejected(empty, kQ3ErrorInvalidData, "vKnots[0..7] are all 1");
}

TEST_F(NURBPatchApiTest, ControlPointsMustBeFiniteWithPositiveWeights)
{
    const float bad[] = {kNaN, kInf, -kInf};
    for (int component = 0; component < 4; ++component)
        for (float value : bad) {
            PatchArrays p;
            (&p.points[7].x)[component] = value;
            expectRejected(p, kQ3ErrorInvalidData, "controlPoints[7] (row 1, column 2)");
        }
    for (float w : {0.0f, -0.0f, -1.0f}) {
        PatchArrays p;
        p.points[19].w = w;
        expectRejected(p, kQ3ErrorInvalidData, "controlPoints[19] (row 3, column 4) has w =");
    }
}

TEST_F(NURBPatchApiTest, TrimCurveRulesNameTheLoopTheCurveAndTheValue)
{
    {
        PatchArrays p = trimmed();
        p.loops[1][0].knots = {0, 0.5f, 0.3f, 1};
        expectRejected(p, kQ3ErrorInvalidData, "trimLoops[1].trimCurves[0].knots[2] = 0.3 is less than knots[1] = 0.5");
    }
    {
        PatchArrays p = trimmed();
        p.loops[0].clear();
        expectRejected(p, kQ3ErrorInvalidData, "trimLoops[0].numTrimCurves is 0");
    }
    for (unsigned long order : {1UL, 17UL, ULONG_MAX}) {
        PatchArrays p = trimmed();
        p.loops[1][2].order = order;
        expectRejected(p, kQ3ErrorParameterOutOfRange, "trimLoops[1].trimCurves[2].order");
    }
    {
        PatchArrays p = trimmed();
        p.loops[1][2].order = 3;
        p.loops[1][2].knots.push_back(1);
        expectRejected(p, kQ3ErrorGeometryInsufficientNumberOfPoints, "trimLoops[1].trimCurves[2].numPoints 2");
    }
    {
        PatchArrays p = trimmed();
        p.loops[0][1].points[1].w = 0;
        expectRejected(p, kQ3ErrorInvalidData, "trimLoops[0].trimCurves[1].controlPoints[1] has w = 0");
    }
    {
        PatchArrays p = trimmed();
        p.loops[0][1].points[0].y = kNaN;
        expectRejected(p, kQ3ErrorInvalidData, "trimLoops[0].trimCurves[1].controlPoints[0]");
    }
    {
        PatchArrays p = trimmed();
        p.loops[0][0].knots[3] = kInf;
        expectRejected(p, kQ3ErrorInvalidData, "trimLoops[0].trimCurves[0].knots[3] is inf");
    }
    {
        // Outside the domain [0, 2] x [0, 1].
        PatchArrays p = trimmed();
        p.loops[0] = polygon({{0.1f, 0.1f}, {2.5f, 0.1f}, {1.9f, 0.9f}});
        expectRejected(p, kQ3ErrorInvalidData, "trimLoops[0].trimCurves[0].controlPoints[1] is at (u, v) = (2.5, 0.1)");
    }
    {
        // Not closed: the last side ends short of the first corner.
        PatchArrays p = trimmed();
        p.loops[1][3].points[1].x = 0.55f;
        expectRejected(p, kQ3ErrorInvalidData, "trimLoops[1] is not closed: trimCurves[3] ends at");
    }
    {
        PatchArrays p = trimmed();
        TQ3NURBPatchData data = p.data();
        p.curveData[1][0].controlPoints = nullptr;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_New(&data), nullptr), kQ3ErrorNULLParameter);
        EXPECT_NE(std::string(Q3Error_GetMessage()).find("trimLoops[1].trimCurves[0].controlPoints"),
                  std::string::npos);
        p.curveData[1][0].controlPoints = p.loops[1][0].points.data();
        p.loopData[0].trimCurves = nullptr;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_New(&data), nullptr), kQ3ErrorNULLParameter);
        p.loopData[0].trimCurves = p.curveData[0].data();
        p.loopData[0].numTrimCurves = ULONG_MAX;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_New(&data), nullptr), kQ3ErrorParameterOutOfRange);
    }
}

TEST_F(NURBPatchApiTest, ALoopClosedWithinTheToleranceIsAccepted)
{
    PatchArrays p = trimmed();
    // 1e-5 of the domain's larger side (2) is 2e-5: a gap of 1e-5 passes.
    p.loops[1][3].points[1].x = 0.5f + 1e-5f;
    TQ3GeometryObject patch = newPatch(p);
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, ADeadOrForeignAttributeSetIsRefused)
{
    PatchArrays p;
    p.attributes = Q3AttributeSet_New();
    TQ3AttributeSet dead = p.attributes;
    Q3Object_Dispose(dead);
    expectRejected(p, kQ3ErrorInvalidObject, "patchAttributeSet");
    TQ3GeometryObject notASet = newPatch();
    p.attributes = notASet;
    expectRejected(p, kQ3ErrorInvalidObjectType, "patchAttributeSet");
    Q3Object_Dispose(notASet);
}

// ---- Control points ---------------------------------------------------------

TEST_F(NURBPatchApiTest, ControlPointsAreAddressedByRowAndColumn)
{
    TQ3GeometryObject patch = newPatch();
    const PatchArrays arrays;
    TQ3RationalPoint4D point{};
    EXPECT_EQ(Q3NURBPatch_GetControlPoint(patch, 0, 0, &point), kQ3Success);
    EXPECT_EQ(std::memcmp(&point, &arrays.points[0], sizeof point), 0);
    EXPECT_EQ(Q3NURBPatch_GetControlPoint(patch, 3, 4, &point), kQ3Success);
    EXPECT_EQ(std::memcmp(&point, &arrays.points[19], sizeof point), 0);
    EXPECT_EQ(Q3NURBPatch_GetControlPoint(patch, 1, 3, &point), kQ3Success);
    EXPECT_EQ(std::memcmp(&point, &arrays.points[1 * 5 + 3], sizeof point), 0);

    const TQ3RationalPoint4D moved = {1, 2, 3, 2};
    const unsigned long before = Q3Shared_GetEditIndex(patch);
    EXPECT_EQ(Q3NURBPatch_SetControlPoint(patch, 3, 4, &moved), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(patch), before);
    EXPECT_EQ(Q3NURBPatch_GetControlPoint(patch, 3, 4, &point), kQ3Success);
    EXPECT_EQ(std::memcmp(&point, &moved, sizeof point), 0);
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, ControlPointIndicesOutOfRangeAreRefusedAndChangeNothing)
{
    TQ3GeometryObject patch = newPatch();
    const Snapshot before = snapshot(patch);
    const TQ3RationalPoint4D moved = {1, 2, 3, 1};
    const std::pair<unsigned long, unsigned long> bad[] = {{4, 0}, {0, 5}, {ULONG_MAX, 0}, {0, ULONG_MAX},
                                                           {4, 5}, {ULONG_MAX, ULONG_MAX}};
    for (const auto& index : bad) {
        TQ3RationalPoint4D point = {7, 7, 7, 7};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_GetControlPoint(patch, index.first, index.second, &point), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_EQ(point.x, 7.0f);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_SetControlPoint(patch, index.first, index.second, &moved), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
    }
    EXPECT_EQ(snapshot(patch), before);
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, ANonFiniteOrNonPositiveControlPointIsRefused)
{
    TQ3GeometryObject patch = newPatch();
    const Snapshot before = snapshot(patch);
    for (int component = 0; component < 4; ++component)
        for (float value : {kNaN, kInf, -kInf}) {
            TQ3RationalPoint4D point = {1, 1, 1, 1};
            (&point.x)[component] = value;
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_SetControlPoint(patch, 0, 0, &point), kQ3Failure),
                            kQ3ErrorInvalidParameter);
        }
    for (float w : {0.0f, -0.0f, -2.0f}) {
        const TQ3RationalPoint4D point = {1, 1, 1, w};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_SetControlPoint(patch, 3, 4, &point), kQ3Failure),
                        kQ3ErrorInvalidParameter);
    }
    EXPECT_EQ(snapshot(patch), before);
    Q3Object_Dispose(patch);
}

// ---- Knots ----------------------------------------------------------------

TEST_F(NURBPatchApiTest, KnotsAreReadAndWrittenAtTheirIndices)
{
    TQ3GeometryObject patch = newPatch();
    float value = -1.0f;
    EXPECT_EQ(Q3NURBPatch_GetUKnot(patch, 0, &value), kQ3Success);
    EXPECT_EQ(value, 0.0f);
    EXPECT_EQ(Q3NURBPatch_GetUKnot(patch, 8, &value), kQ3Success); // last: uOrder + numColumns - 1
    EXPECT_EQ(value, 2.0f);
    EXPECT_EQ(Q3NURBPatch_GetVKnot(patch, 7, &value), kQ3Success); // last: vOrder + numRows - 1
    EXPECT_EQ(value, 1.0f);
    const unsigned long before = Q3Shared_GetEditIndex(patch);
    EXPECT_EQ(Q3NURBPatch_SetUKnot(patch, 4, 1.25f), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(patch), before);
    EXPECT_EQ(Q3NURBPatch_GetUKnot(patch, 4, &value), kQ3Success);
    EXPECT_EQ(value, 1.25f);
    // The first knot may move down freely: it is outside the domain.
    EXPECT_EQ(Q3NURBPatch_SetVKnot(patch, 0, -3.0f), kQ3Success);
    EXPECT_EQ(Q3NURBPatch_GetVKnot(patch, 0, &value), kQ3Success);
    EXPECT_EQ(value, -3.0f);
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, KnotIndicesOutOfRangeAreRefused)
{
    TQ3GeometryObject patch = newPatch();
    const Snapshot before = snapshot(patch);
    for (unsigned long index : {9UL, ULONG_MAX}) {
        float value = 7.0f;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_GetUKnot(patch, index, &value), kQ3Failure), kQ3ErrorParameterOutOfRange);
        EXPECT_EQ(value, 7.0f);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_SetUKnot(patch, index, 1.0f), kQ3Failure), kQ3ErrorParameterOutOfRange);
    }
    for (unsigned long index : {8UL, ULONG_MAX}) {
        float value = 7.0f;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_GetVKnot(patch, index, &value), kQ3Failure), kQ3ErrorParameterOutOfRange);
        EXPECT_EQ(value, 7.0f);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_SetVKnot(patch, index, 1.0f), kQ3Failure), kQ3ErrorParameterOutOfRange);
    }
    EXPECT_EQ(snapshot(patch), before);
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, AKnotThatBreaksARuleIsRefusedAndChangesNothing)
{
    TQ3GeometryObject patch = newPatch(trimmed());
    const Snapshot before = snapshot(patch);
    for (float value : {kNaN, kInf, -kInf})
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_SetUKnot(patch, 4, value), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_SetUKnot(patch, 4, 2.5f), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_NE(std::string(Q3Error_GetMessage()).find("setting uKnots[4] to 2.5 would break a rule: uKnots[5] = 2 is "
                                                     "less than uKnots[4] = 2.5"),
              std::string::npos)
        << Q3Error_GetMessage();
    // Moving the domain's end inwards leaves the trim loops outside it.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_SetUKnot(patch, 5, 1.5f), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_NE(std::string(Q3Error_GetMessage()).find("outside the patch's domain"), std::string::npos);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_SetVKnot(patch, 3, 1.0f), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_EQ(snapshot(patch), before);
    Q3Object_Dispose(patch);
}

// ---- Handles and pointers ---------------------------------------------------

TEST_F(NURBPatchApiTest, NullDeadAndForeignHandlesAreRefused)
{
    TQ3GeometryObject patch = newPatch();
    TQ3GeometryObject dead = newPatch();
    Q3Object_Dispose(dead);
    const TQ3NURBCurveData curveData = {2, 2, nullptr, nullptr, nullptr};
    (void)curveData;
    TQ3AttributeSet foreign = Q3AttributeSet_New();
    TQ3RationalPoint4D point{};
    float knot = 0.0f;
    PatchArrays arrays;
    const TQ3NURBPatchData data = arrays.data();
    TQ3NURBPatchData out{};
    const std::pair<TQ3Object, TQ3Error> cases[] = {{nullptr, kQ3ErrorNULLParameter},
                                                    {dead, kQ3ErrorInvalidObject},
                                                    {foreign, kQ3ErrorInvalidObjectType}};
    for (const auto& [handle, code] : cases) {
        EXPECT_Q3_ERROR(Q3NURBPatch_SetData(handle, &data), code);
        EXPECT_Q3_ERROR(Q3NURBPatch_GetData(handle, &out), code);
        EXPECT_Q3_ERROR(Q3NURBPatch_SetControlPoint(handle, 0, 0, &point), code);
        EXPECT_Q3_ERROR(Q3NURBPatch_GetControlPoint(handle, 0, 0, &point), code);
        EXPECT_Q3_ERROR(Q3NURBPatch_SetUKnot(handle, 0, 0.0f), code);
        EXPECT_Q3_ERROR(Q3NURBPatch_SetVKnot(handle, 0, 0.0f), code);
        EXPECT_Q3_ERROR(Q3NURBPatch_GetUKnot(handle, 0, &knot), code);
        EXPECT_Q3_ERROR(Q3NURBPatch_GetVKnot(handle, 0, &knot), code);
    }
    EXPECT_Q3_ERROR(Q3NURBPatch_GetData(patch, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3NURBPatch_SetData(patch, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3NURBPatch_SetControlPoint(patch, 0, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3NURBPatch_GetControlPoint(patch, 0, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3NURBPatch_GetUKnot(patch, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3NURBPatch_GetVKnot(patch, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3NURBPatch_EmptyData(nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3NURBPatch_Submit(nullptr, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3NURBPatch_Submit(&data, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3NURBPatch_Submit(&data, foreign), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(foreign);
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, SubmitOutsideALoopIsRefused)
{
    PatchArrays arrays;
    const TQ3NURBPatchData data = arrays.data();
    Pixmap image(16, 16);
    TestView view(image.pixmap());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_Submit(&data, view.view()), kQ3Failure), kQ3ErrorViewNotStarted);
}

// ---- Drawing, decomposing, bounding ------------------------------------------

TEST_F(NURBPatchApiTest, DecomposingGivesATriMeshWithNormalsAndSurfaceUV)
{
    TQ3GeometryObject patch = newPatch();
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, 3, 2};
    TQ3TriMeshData mesh = decompose(patch, &style);
    // Two u spans and one v span: 2 x 3 x 2 quadrilaterals, 2 triangles each.
    EXPECT_EQ(mesh.numTriangles, 24u);
    EXPECT_EQ(mesh.numPoints, 7u * 3u);
    bool normals = false, uvs = false;
    for (unsigned long i = 0; i < mesh.numVertexAttributeTypes; ++i) {
        const TQ3TriMeshAttributeData& a = mesh.vertexAttributeTypes[i];
        if (a.attributeType == kQ3AttributeTypeNormal) {
            normals = true;
            const TQ3Vector3D* n = static_cast<const TQ3Vector3D*>(a.data);
            for (unsigned long v = 0; v < mesh.numPoints; ++v)
                EXPECT_NEAR(std::sqrt(n[v].x * n[v].x + n[v].y * n[v].y + n[v].z * n[v].z), 1.0, 1e-6);
        }
        if (a.attributeType == kQ3AttributeTypeSurfaceUV) {
            uvs = true;
            const TQ3Param2D* uv = static_cast<const TQ3Param2D*>(a.data);
            for (unsigned long v = 0; v < mesh.numPoints; ++v) {
                EXPECT_GE(uv[v].u, 0.0f);
                EXPECT_LE(uv[v].u, 2.0f);
                EXPECT_GE(uv[v].v, 0.0f);
                EXPECT_LE(uv[v].v, 1.0f);
            }
        }
    }
    EXPECT_TRUE(normals);
    EXPECT_TRUE(uvs);
    Q3TriMesh_EmptyData(&mesh);
    Q3Object_Dispose(patch);
}

// A rational patch that is exactly half the unit cylinder around the z axis
// (two rational quadratic quarter circles in u, a line in v): every vertex
// of its TriMesh is on the cylinder to float rounding, and every normal is
// the radial direction, under each method.
TEST_F(NURBPatchApiTest, ARationalHalfCylinderDecomposesOntoTheCylinder)
{
    static float uKnots[8] = {0, 0, 0, 1, 1, 2, 2, 2};
    static float vKnots[4] = {0, 0, 1, 1};
    const float s = 0.70710678f;
    const float arc[5][3] = {{1, 0, 1}, {1, 1, s}, {0, 1, 1}, {-1, 1, s}, {-1, 0, 1}};
    TQ3RationalPoint4D points[10];
    for (int row = 0; row < 2; ++row)
        for (int column = 0; column < 5; ++column) {
            const float w = arc[column][2], z = row == 0 ? -2.0f : 2.0f;
            points[row * 5 + column] = {arc[column][0] * w, arc[column][1] * w, z * w, w};
        }
    TQ3NURBPatchData data{};
    data.uOrder = 3;
    data.vOrder = 2;
    data.numColumns = 5;
    data.numRows = 2;
    data.controlPoints = points;
    data.uKnots = uKnots;
    data.vKnots = vKnots;
    TQ3GeometryObject patch = Q3NURBPatch_New(&data);
    ASSERT_NE(patch, nullptr);
    const TQ3SubdivisionStyleData styles[] = {{kQ3SubdivisionMethodConstant, 7, 3},
                                              {kQ3SubdivisionMethodWorldSpace, 0.05f, 0.05f}};
    for (const TQ3SubdivisionStyleData& style : styles) {
        TQ3TriMeshData mesh = decompose(patch, &style);
        ASSERT_GT(mesh.numTriangles, 10u);
        const TQ3Vector3D* normals = nullptr;
        for (unsigned long i = 0; i < mesh.numVertexAttributeTypes; ++i)
            if (mesh.vertexAttributeTypes[i].attributeType == kQ3AttributeTypeNormal)
                normals = static_cast<const TQ3Vector3D*>(mesh.vertexAttributeTypes[i].data);
        ASSERT_NE(normals, nullptr);
        for (unsigned long v = 0; v < mesh.numPoints; ++v) {
            const TQ3Point3D& p = mesh.points[v];
            const double radius = std::hypot(double(p.x), double(p.y));
            EXPECT_NEAR(radius, 1.0, 4e-7) << "vertex " << v;
            EXPECT_GE(p.y, -1e-7f);
            EXPECT_NEAR(normals[v].x, p.x / radius, 1e-5);
            EXPECT_NEAR(normals[v].y, p.y / radius, 1e-5);
            EXPECT_NEAR(normals[v].z, 0.0, 1e-5);
        }
        Q3TriMesh_EmptyData(&mesh);
    }
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, RetainedAndImmediatePatchesDrawAlike)
{
    PatchArrays arrays = trimmed();
    const TQ3NURBPatchData data = arrays.data();
    TQ3GeometryObject patch = newPatch(arrays);
    Pixmap a(96, 64), b(96, 64);
    TestView viewA(a.pixmap()), viewB(b.pixmap());
    EXPECT_EQ(viewA.render([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(patch, v), kQ3Success); }),
              kQ3ViewStatusDone);
    EXPECT_EQ(viewB.render([&](TQ3ViewObject v) { EXPECT_EQ(Q3NURBPatch_Submit(&data, v), kQ3Success); }),
              kQ3ViewStatusDone);
    EXPECT_EQ(a.bytes(), b.bytes());
    std::size_t lit = 0;
    for (unsigned long y = 0; y < 64; ++y)
        for (unsigned long x = 0; x < 96; ++x)
            lit += a.at(x, y).r + a.at(x, y).g + a.at(x, y).b > 0;
    EXPECT_GT(lit, 200u);
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, CrossingTrimLoopsAreRefusedWhenDrawn)
{
    PatchArrays arrays;
    arrays.loops.push_back(polygon({{0.1f, 0.1f}, {1.2f, 0.1f}, {1.2f, 0.6f}, {0.1f, 0.6f}}));
    arrays.loops.push_back(polygon({{0.8f, 0.4f}, {1.9f, 0.4f}, {1.9f, 0.9f}, {0.8f, 0.9f}}));
    const TQ3NURBPatchData data = arrays.data();
    TQ3GeometryObject patch = newPatch(arrays); // not found when made
    whileRendering(nullptr, 32, [&](TQ3ViewObject view) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_Submit(patch, view), kQ3Failure), kQ3ErrorInvalidData);
        EXPECT_NE(std::string(Q3Error_GetMessage()).find("trimLoops[0] and trimLoops[1] cross"), std::string::npos)
            << Q3Error_GetMessage();
        // Again: the refusal is not cached away.
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_Submit(patch, view), kQ3Failure), kQ3ErrorInvalidData);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBPatch_Submit(&data, view), kQ3Failure), kQ3ErrorInvalidData);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_GetDecomposed(patch, view), nullptr), kQ3ErrorInvalidData);
    });
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, ALoopCrossingItselfIsRefusedWhenDrawn)
{
    PatchArrays arrays;
    arrays.loops.push_back(polygon({{0.1f, 0.1f}, {1.5f, 0.9f}, {1.5f, 0.1f}, {0.1f, 0.9f}}));
    TQ3GeometryObject patch = newPatch(arrays);
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, 2, 2};
    whileRendering(&style, 32, [&](TQ3ViewObject view) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_Submit(patch, view), kQ3Failure), kQ3ErrorInvalidData);
        EXPECT_NE(std::string(Q3Error_GetMessage()).find("trimLoops[0] crosses or touches itself"),
                  std::string::npos)
            << Q3Error_GetMessage();
    });
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, MoreTrianglesThanTheCapWarnEveryTimeThePatchIsDrawn)
{
    PatchArrays arrays;
    TQ3GeometryObject patch = newPatch(arrays);
    // 2 spans x 1024 x 1024 x 2 triangles = 4 million, over the 2^20 cap.
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, 1024, 1024};
    whileRendering(&style, 16, [&](TQ3ViewObject view) {
        EXPECT_Q3_WARNING(EXPECT_EQ(Q3Geometry_Submit(patch, view), kQ3Success), kQ3WarningParameterOutOfRange);
        EXPECT_Q3_WARNING(EXPECT_EQ(Q3Geometry_Submit(patch, view), kQ3Success), kQ3WarningParameterOutOfRange);
        TQ3GeometryObject mesh = nullptr;
        EXPECT_Q3_WARNING(mesh = Q3Geometry_GetDecomposed(patch, view), kQ3WarningParameterOutOfRange);
        ASSERT_NE(mesh, nullptr);
        TQ3TriMeshData data{};
        EXPECT_EQ(Q3TriMesh_GetData(mesh, &data), kQ3Success);
        EXPECT_LE(data.numTriangles, static_cast<unsigned long>(kQ3SubdivisionMaxTrianglesPerPatch));
        EXPECT_GT(data.numTriangles, static_cast<unsigned long>(kQ3SubdivisionMaxTrianglesPerPatch) / 2);
        Q3TriMesh_EmptyData(&data);
        Q3Object_Dispose(mesh);
    });
    Q3Object_Dispose(patch);
}

TEST_F(NURBPatchApiTest, ABoundingBoxHoldsTheControlPoints)
{
    PatchArrays arrays;
    TQ3GeometryObject patch = newPatch(arrays);
    Pixmap image(16, 16);
    TestView view(image.pixmap());
    TQ3BoundingBox box{};
    ASSERT_EQ(Q3View_StartBoundingBox(view.view(), kQ3ComputeBoundsExact), kQ3Success);
    TQ3ViewStatus status;
    do {
        EXPECT_EQ(Q3Geometry_Submit(patch, view.view()), kQ3Success);
        status = Q3View_EndBoundingBox(view.view(), &box);
    } while (status == kQ3ViewStatusRetraverse);
    EXPECT_EQ(status, kQ3ViewStatusDone);
    EXPECT_FLOAT_EQ(box.min.x, 0.0f);
    EXPECT_FLOAT_EQ(box.max.x, 3.0f);
    EXPECT_FLOAT_EQ(box.min.y, 0.0f);
    EXPECT_FLOAT_EQ(box.max.y, 1.0f);
    EXPECT_FLOAT_EQ(box.max.z, 0.5f);
    Q3Object_Dispose(patch);
}

} // namespace
