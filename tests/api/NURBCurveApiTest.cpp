// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "NURBCurveTestSupport.h"
#include "Q3ApiTest.h"
#include "ShapeTypeChain.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"

#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace {

using q3test::CurveArrays;
using q3test::expectShapeTypeChain;
using q3test::listing1;
using q3test::Q3ApiTest;
using q3test::sixPointQuadratic;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

class NURBCurveApiTest : public Q3ApiTest {
protected:
    // The whole state of a curve, to prove a failed call changed nothing.
    struct Snapshot {
        std::vector<float> values;
        unsigned long editIndex;
        bool operator==(const Snapshot& o) const { return values == o.values && editIndex == o.editIndex; }
    };

    Snapshot snapshot(TQ3GeometryObject curve)
    {
        TQ3NURBCurveData data{};
        EXPECT_EQ(Q3NURBCurve_GetData(curve, &data), kQ3Success);
        Snapshot s;
        s.values.push_back(static_cast<float>(data.order));
        s.values.push_back(static_cast<float>(data.numPoints));
        for (unsigned long i = 0; i < data.numPoints; ++i) {
            const TQ3RationalPoint4D& p = data.controlPoints[i];
            s.values.insert(s.values.end(), {p.x, p.y, p.z, p.w});
        }
        s.values.insert(s.values.end(), data.knots, data.knots + data.numPoints + data.order);
        s.values.push_back(data.curveAttributeSet == nullptr ? 0.0f : 1.0f);
        EXPECT_EQ(Q3NURBCurve_EmptyData(&data), kQ3Success);
        s.editIndex = Q3Shared_GetEditIndex(curve);
        return s;
    }

    TQ3GeometryObject newCurve(CurveArrays arrays)
    {
        TQ3NURBCurveData data = arrays.data();
        TQ3GeometryObject curve = Q3NURBCurve_New(&data);
        EXPECT_NE(curve, nullptr);
        return curve;
    }

    // New must reject the data with `code` and create nothing.
    void expectNewRejects(CurveArrays arrays, TQ3Error code)
    {
        TQ3NURBCurveData data = arrays.data();
        const unsigned long live = Q3Memory_CountLiveObjects();
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_New(&data), nullptr), code);
        EXPECT_STRNE(Q3Error_GetMessage(), "");
        EXPECT_EQ(Q3Memory_CountLiveObjects(), live);
    }

    // SetData must reject the data with the same code and leave the curve as it was.
    void expectSetDataRejects(CurveArrays arrays, TQ3Error code)
    {
        TQ3GeometryObject curve = newCurve(listing1());
        const Snapshot before = snapshot(curve);
        TQ3NURBCurveData data = arrays.data();
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_SetData(curve, &data), kQ3Failure), code);
        EXPECT_EQ(snapshot(curve), before);
        Q3Object_Dispose(curve);
    }

    void expectRejected(const CurveArrays& arrays, TQ3Error code)
    {
        expectNewRejects(arrays, code);
        expectSetDataRejects(arrays, code);
    }
};

TEST_F(NURBCurveApiTest, NewCopiesTheCallersArrays)
{
    CurveArrays arrays = listing1();
    TQ3GeometryObject curve = newCurve(arrays);
    arrays.points[1].y = 99.0f;
    arrays.knots[7] = 42.0f;
    TQ3RationalPoint4D point{};
    EXPECT_EQ(Q3NURBCurve_GetControlPoint(curve, 1, &point), kQ3Success);
    EXPECT_EQ(point.y, 1.0f);
    float knot = 0.0f;
    EXPECT_EQ(Q3NURBCurve_GetKnot(curve, 7, &knot), kQ3Success);
    EXPECT_EQ(knot, 1.0f);
    EXPECT_EQ(Q3Object_Dispose(curve), kQ3Success);
}

TEST_F(NURBCurveApiTest, ReportsQuickDraw3DTypesAtEveryLevel)
{
    TQ3GeometryObject curve = newCurve(listing1());
    expectShapeTypeChain(curve, kQ3ShapeTypeGeometry, kQ3GeometryTypeNURBCurve, kQ3True);
    EXPECT_EQ(Q3Geometry_GetType(curve), kQ3GeometryTypeNURBCurve);
    EXPECT_EQ(Q3Object_IsType(curve, kQ3SharedTypeSet), kQ3False);
    Q3Object_Dispose(curve);
}

TEST_F(NURBCurveApiTest, NewRejectsNullDataAndNullArrays)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    CurveArrays arrays = listing1();
    TQ3NURBCurveData data = arrays.data();
    data.controlPoints = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_New(&data), nullptr), kQ3ErrorNULLParameter);
    data = arrays.data();
    data.knots = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_New(&data), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(NURBCurveApiTest, RejectsOrderOutsideTwoToSixteen)
{
    for (unsigned long order : {0UL, 1UL, 17UL, 0xFFFFFFFFUL, ULONG_MAX}) {
        CurveArrays arrays = listing1();
        arrays.order = order;
        expectRejected(arrays, kQ3ErrorParameterOutOfRange);
    }
}

TEST_F(NURBCurveApiTest, AcceptsOrdersTwoAndSixteen)
{
    CurveArrays linear{{{0, 0, 0, 1}, {1, 1, 0, 1}}, {0, 0, 1, 1}, 2};
    Q3Object_Dispose(newCurve(linear));
    CurveArrays order16;
    order16.order = 16;
    for (int i = 0; i < 16; ++i)
        order16.points.push_back({float(i), float(i % 3), 0, 1});
    for (int i = 0; i < 32; ++i)
        order16.knots.push_back(i < 16 ? 0.0f : 1.0f);
    Q3Object_Dispose(newCurve(order16));
}

TEST_F(NURBCurveApiTest, RejectsFewerPointsThanTheOrder)
{
    CurveArrays arrays = listing1();
    arrays.order = 4;
    arrays.points.resize(3);
    arrays.knots = {0, 0, 0, 0, 1, 1, 1};
    expectRejected(arrays, kQ3ErrorGeometryInsufficientNumberOfPoints);
}

TEST_F(NURBCurveApiTest, RejectsDecreasingKnots)
{
    CurveArrays arrays = sixPointQuadratic();
    arrays.knots[4] = 0.5f; // 0 0 0 1 0.5 ...
    expectRejected(arrays, kQ3ErrorInvalidData);
}

TEST_F(NURBCurveApiTest, AcceptsInteriorRunOfOrderMinusOneAndRejectsOrder)
{
    CurveArrays ok = sixPointQuadratic();
    ok.knots = {0, 0, 0, 2, 2, 3, 4, 4, 4}; // interior run of k-1 = 2
    Q3Object_Dispose(newCurve(ok));
    CurveArrays bad = sixPointQuadratic();
    bad.knots = {0, 0, 0, 2, 2, 2, 4, 4, 4}; // interior run of k = 3
    expectRejected(bad, kQ3ErrorInvalidData);
}

TEST_F(NURBCurveApiTest, AcceptsEndRunsOfOrderAndRejectsOrderPlusOne)
{
    CurveArrays clamped = sixPointQuadratic(); // runs of k = 3 at both ends
    Q3Object_Dispose(newCurve(clamped));
    CurveArrays startTooLong = sixPointQuadratic();
    startTooLong.knots = {0, 0, 0, 0, 2, 3, 4, 4, 4};
    expectRejected(startTooLong, kQ3ErrorInvalidData);
    CurveArrays endTooLong = sixPointQuadratic();
    endTooLong.knots = {0, 0, 0, 1, 2, 4, 4, 4, 4};
    expectRejected(endTooLong, kQ3ErrorInvalidData);
}

TEST_F(NURBCurveApiTest, RejectsNonPositiveWeights)
{
    for (float w : {0.0f, -1.0f, -0.0f}) {
        CurveArrays arrays = listing1();
        arrays.points[2].w = w;
        expectRejected(arrays, kQ3ErrorInvalidData);
    }
}

TEST_F(NURBCurveApiTest, RejectsNonFiniteControlPointsAndKnots)
{
    for (float bad : {kNaN, kInf, -kInf}) {
        CurveArrays point = listing1();
        point.points[3].z = bad;
        expectRejected(point, kQ3ErrorInvalidData);
        CurveArrays weight = listing1();
        weight.points[0].w = bad;
        expectRejected(weight, kQ3ErrorInvalidData);
        CurveArrays knot = listing1();
        knot.knots[7] = bad;
        expectRejected(knot, kQ3ErrorInvalidData);
    }
}

TEST_F(NURBCurveApiTest, RejectsAnEmptyDomain)
{
    // Every run is allowed, but the domain [knots[2], knots[3]] = [1, 1] is empty.
    CurveArrays arrays{{{0, 0, 0, 1}, {1, 1, 0, 1}, {2, 0, 0, 1}}, {0, 0, 1, 1, 2, 2}, 3};
    expectRejected(arrays, kQ3ErrorInvalidData);
}

TEST_F(NURBCurveApiTest, RejectsAnAttributeSetHandleOfTheWrongClassOrDisposed)
{
    TQ3GeometryObject other = newCurve(listing1());
    CurveArrays arrays = listing1();
    arrays.attributes = other;
    expectRejected(arrays, kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(other);
    TQ3AttributeSet set = Q3AttributeSet_New();
    Q3Object_Dispose(set);
    arrays.attributes = set;
    expectRejected(arrays, kQ3ErrorInvalidObject);
}

TEST_F(NURBCurveApiTest, CurveHoldsAReferenceToItsAttributeSet)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB red{1, 0, 0};
    ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &red), kQ3Success);
    CurveArrays arrays = listing1();
    arrays.attributes = set;
    TQ3GeometryObject curve = newCurve(arrays);
    EXPECT_EQ(Q3Shared_IsReferenced(set), kQ3True);
    Q3Object_Dispose(set); // the curve's reference keeps it alive
    TQ3NURBCurveData data{};
    ASSERT_EQ(Q3NURBCurve_GetData(curve, &data), kQ3Success);
    ASSERT_EQ(data.curveAttributeSet, set);
    TQ3ColorRGB color{};
    EXPECT_EQ(Q3AttributeSet_Get(data.curveAttributeSet, kQ3AttributeTypeDiffuseColor, &color), kQ3Success);
    EXPECT_EQ(color.r, 1.0f);
    EXPECT_EQ(Q3Shared_IsReferenced(set), kQ3True); // curve + GetData's reference
    EXPECT_EQ(Q3NURBCurve_EmptyData(&data), kQ3Success);
    EXPECT_EQ(data.curveAttributeSet, nullptr);
    EXPECT_EQ(Q3Shared_IsReferenced(set), kQ3False); // only the curve's
    const unsigned long live = Q3Memory_CountLiveObjects();
    Q3Object_Dispose(curve);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live - 2); // curve and set
}

TEST_F(NURBCurveApiTest, GetDataHandsOutFreshCopiesThatEmptyDataReleases)
{
    CurveArrays arrays = sixPointQuadratic();
    TQ3GeometryObject curve = newCurve(arrays);
    TQ3NURBCurveData data{};
    ASSERT_EQ(Q3NURBCurve_GetData(curve, &data), kQ3Success);
    EXPECT_EQ(data.order, 3u);
    EXPECT_EQ(data.numPoints, 6u);
    EXPECT_NE(data.controlPoints, arrays.points.data());
    for (unsigned long i = 0; i < 6; ++i)
        EXPECT_EQ(data.controlPoints[i].y, arrays.points[i].y);
    for (unsigned long i = 0; i < 9; ++i)
        EXPECT_EQ(data.knots[i], arrays.knots[i]);
    EXPECT_EQ(data.curveAttributeSet, nullptr);
    data.controlPoints[0].x = 77.0f; // the copy is the caller's
    TQ3RationalPoint4D point{};
    Q3NURBCurve_GetControlPoint(curve, 0, &point);
    EXPECT_EQ(point.x, 0.0f);
    EXPECT_EQ(Q3NURBCurve_EmptyData(&data), kQ3Success);
    EXPECT_EQ(data.controlPoints, nullptr);
    EXPECT_EQ(data.knots, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_EmptyData(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_GetData(curve, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    Q3Object_Dispose(curve);
}

TEST_F(NURBCurveApiTest, SetDataReplacesEverythingAndBumpsTheEditIndex)
{
    TQ3GeometryObject curve = newCurve(listing1());
    const unsigned long before = Q3Shared_GetEditIndex(curve);
    CurveArrays arrays = sixPointQuadratic();
    TQ3NURBCurveData data = arrays.data();
    EXPECT_EQ(Q3NURBCurve_SetData(curve, &data), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(curve), before);
    float knot = 0;
    EXPECT_EQ(Q3NURBCurve_GetKnot(curve, 8, &knot), kQ3Success);
    EXPECT_EQ(knot, 4.0f);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_SetData(curve, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    Q3Object_Dispose(curve);
}

TEST_F(NURBCurveApiTest, ControlPointIndicesAreCheckedAtEveryBoundary)
{
    TQ3GeometryObject curve = newCurve(listing1());
    TQ3RationalPoint4D point{};
    EXPECT_EQ(Q3NURBCurve_GetControlPoint(curve, 0, &point), kQ3Success);
    EXPECT_EQ(point.x, 0.0f);
    EXPECT_EQ(Q3NURBCurve_GetControlPoint(curve, 3, &point), kQ3Success);
    EXPECT_EQ(point.x, 3.0f);
    const Snapshot before = snapshot(curve);
    const TQ3RationalPoint4D valid{5, 5, 5, 2};
    for (unsigned long index : {4UL, 0xFFFFFFFFUL, ULONG_MAX}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_GetControlPoint(curve, index, &point), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_SetControlPoint(curve, index, &valid), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_GetControlPoint(curve, 0, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_SetControlPoint(curve, 0, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_EQ(snapshot(curve), before);
    Q3Object_Dispose(curve);
}

TEST_F(NURBCurveApiTest, SetControlPointRejectsBadValuesAndKeepsTheCurve)
{
    TQ3GeometryObject curve = newCurve(listing1());
    const Snapshot before = snapshot(curve);
    for (TQ3RationalPoint4D bad : {TQ3RationalPoint4D{kNaN, 0, 0, 1}, TQ3RationalPoint4D{0, kInf, 0, 1},
                                   TQ3RationalPoint4D{0, 0, -kInf, 1}, TQ3RationalPoint4D{0, 0, 0, kNaN},
                                   TQ3RationalPoint4D{0, 0, 0, 0}, TQ3RationalPoint4D{0, 0, 0, -2}}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_SetControlPoint(curve, 3, &bad), kQ3Failure),
                        kQ3ErrorInvalidParameter);
    }
    EXPECT_EQ(snapshot(curve), before);
    const TQ3RationalPoint4D good{6, 2, 0, 2};
    EXPECT_EQ(Q3NURBCurve_SetControlPoint(curve, 3, &good), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(curve), before.editIndex);
    TQ3RationalPoint4D point{};
    Q3NURBCurve_GetControlPoint(curve, 3, &point);
    EXPECT_EQ(point.x, 6.0f);
    EXPECT_EQ(point.w, 2.0f);
    Q3Object_Dispose(curve);
}

TEST_F(NURBCurveApiTest, KnotIndicesAreCheckedAtEveryBoundary)
{
    TQ3GeometryObject curve = newCurve(listing1());
    float knot = -1;
    EXPECT_EQ(Q3NURBCurve_GetKnot(curve, 0, &knot), kQ3Success);
    EXPECT_EQ(knot, 0.0f);
    EXPECT_EQ(Q3NURBCurve_GetKnot(curve, 7, &knot), kQ3Success);
    EXPECT_EQ(knot, 1.0f);
    const Snapshot before = snapshot(curve);
    for (unsigned long index : {8UL, 0xFFFFFFFFUL, ULONG_MAX}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_GetKnot(curve, index, &knot), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_SetKnot(curve, index, 1.0f), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_GetKnot(curve, 0, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_EQ(snapshot(curve), before);
    Q3Object_Dispose(curve);
}

TEST_F(NURBCurveApiTest, SetKnotRejectsValuesThatBreakARule)
{
    TQ3GeometryObject curve = newCurve(sixPointQuadratic()); // 0 0 0 1 2 3 4 4 4
    const Snapshot before = snapshot(curve);
    struct Case {
        unsigned long index;
        float value;
    };
    // Decreasing; a start run of k + 1; non-finite.
    for (Case c : {Case{4, 0.5f}, Case{5, 1.5f}, Case{3, 0.0f}, Case{4, kNaN}, Case{8, kInf},
                   Case{0, -kInf}}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_SetKnot(curve, c.index, c.value), kQ3Failure),
                        kQ3ErrorInvalidParameter);
    }
    EXPECT_EQ(snapshot(curve), before);
    EXPECT_EQ(Q3NURBCurve_SetKnot(curve, 4, 2.5f), kQ3Success); // 0 0 0 1 2.5 3 4 4 4
    EXPECT_EQ(Q3NURBCurve_SetKnot(curve, 0, -1.0f), kQ3Success); // unclamped start
    EXPECT_NE(Q3Shared_GetEditIndex(curve), before.editIndex);
    float knot = 0;
    Q3NURBCurve_GetKnot(curve, 4, &knot);
    EXPECT_EQ(knot, 2.5f);
    // 0 0 0 1 3 3 4 4 4 is fine (an interior run of k - 1); then 0 0 0 3 3 3 ...
    // would be an interior run of k.
    EXPECT_EQ(Q3NURBCurve_SetKnot(curve, 4, 3.0f), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_SetKnot(curve, 3, 3.0f), kQ3Failure), kQ3ErrorInvalidParameter);
    // Lowering knots[3] to knots[2] would empty the domain [knots[2], knots[3]]
    // while breaking no other rule.
    CurveArrays narrow{{{0, 0, 0, 1}, {1, 1, 0, 1}, {2, 0, 0, 1}}, {0, 0, 1, 2, 3, 3}, 3};
    TQ3GeometryObject quadratic = newCurve(narrow);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_SetKnot(quadratic, 3, 1.0f), kQ3Failure), kQ3ErrorInvalidParameter);
    Q3Object_Dispose(quadratic);
    Q3Object_Dispose(curve);
}

TEST_F(NURBCurveApiTest, DuplicateIsDeepAndIndependent)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB blue{0, 0, 1};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &blue);
    CurveArrays arrays = listing1();
    arrays.attributes = set;
    TQ3GeometryObject curve = newCurve(arrays);
    TQ3GeometryObject copy = Q3Object_Duplicate(curve);
    ASSERT_NE(copy, nullptr);
    ASSERT_NE(copy, curve);
    EXPECT_EQ(Q3Object_GetLeafType(copy), kQ3GeometryTypeNURBCurve);
    EXPECT_EQ(snapshot(copy).values, snapshot(curve).values);
    const TQ3RationalPoint4D moved{9, 9, 9, 1};
    Q3NURBCurve_SetControlPoint(copy, 0, &moved);
    TQ3RationalPoint4D point{};
    Q3NURBCurve_GetControlPoint(curve, 0, &point);
    EXPECT_EQ(point.x, 0.0f);
    TQ3NURBCurveData data{};
    Q3NURBCurve_GetData(copy, &data);
    EXPECT_NE(data.curveAttributeSet, set); // the attribute set was duplicated too
    TQ3ColorRGB color{};
    EXPECT_EQ(Q3AttributeSet_Get(data.curveAttributeSet, kQ3AttributeTypeDiffuseColor, &color), kQ3Success);
    EXPECT_EQ(color.b, 1.0f);
    Q3NURBCurve_EmptyData(&data);
    Q3Object_Dispose(copy);
    Q3Object_Dispose(curve);
    Q3Object_Dispose(set);
}

TEST_F(NURBCurveApiTest, HandlesOfTheWrongClassOrDisposedAreRejected)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    float knot = 0;
    TQ3RationalPoint4D point{0, 0, 0, 1};
    TQ3NURBCurveData data{};
    EXPECT_Q3_ERROR(Q3NURBCurve_GetKnot(set, 0, &knot), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3NURBCurve_SetKnot(set, 0, 0), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3NURBCurve_GetControlPoint(set, 0, &point), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3NURBCurve_SetControlPoint(set, 0, &point), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3NURBCurve_GetData(set, &data), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3NURBCurve_SetData(set, &data), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Geometry_GetType(set), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(set);
    TQ3GeometryObject curve = newCurve(listing1());
    EXPECT_EQ(Q3Object_Dispose(curve), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Dispose(curve), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3NURBCurve_GetKnot(curve, 0, &knot), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3NURBCurve_GetKnot(nullptr, 0, &knot), kQ3ErrorNULLParameter);
    int stray = 0;
    EXPECT_Q3_ERROR(Q3NURBCurve_GetKnot(reinterpret_cast<TQ3GeometryObject>(&stray), 0, &knot),
                    kQ3ErrorInvalidObject);
}

TEST_F(NURBCurveApiTest, SharedReferencesCountAsQuickDraw3DDoes)
{
    TQ3GeometryObject curve = newCurve(listing1());
    EXPECT_EQ(Q3Shared_IsReferenced(curve), kQ3False);
    TQ3SharedObject second = Q3Shared_GetReference(curve);
    EXPECT_EQ(second, curve);
    EXPECT_EQ(Q3Shared_IsReferenced(curve), kQ3True);
    const unsigned long index = Q3Shared_GetEditIndex(curve);
    EXPECT_NE(index, 0u);
    EXPECT_EQ(Q3Shared_Edited(curve), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(curve), index);
    EXPECT_EQ(Q3Object_Dispose(curve), kQ3Success);
    EXPECT_EQ(Q3Object_GetLeafType(second), kQ3GeometryTypeNURBCurve); // still alive
    EXPECT_EQ(Q3Object_Dispose(second), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shared_GetReference(curve), nullptr), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shared_GetEditIndex(curve), 0u), kQ3ErrorInvalidObject);
}

TEST(NURBCurveApiUninitialized, EveryCallFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    CurveArrays arrays = listing1();
    TQ3NURBCurveData data = arrays.data();
    float knot = 0;
    TQ3RationalPoint4D point{};
    EXPECT_EQ(Q3NURBCurve_New(&data), nullptr);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3NURBCurve_GetKnot(nullptr, 0, &knot), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3NURBCurve_SetKnot(nullptr, 0, 0), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3NURBCurve_GetControlPoint(nullptr, 0, &point), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3NURBCurve_SetControlPoint(nullptr, 0, &point), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3NURBCurve_GetData(nullptr, &data), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3NURBCurve_SetData(nullptr, &data), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3NURBCurve_EmptyData(&data), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3NURBCurve_Submit(&data, nullptr), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3Geometry_GetType(nullptr), kQ3ObjectTypeInvalid);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3Object_Dispose(nullptr), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
}

} // namespace
