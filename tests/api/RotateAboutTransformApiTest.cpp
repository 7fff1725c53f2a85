// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The quaternion, rotate-about-point and rotate-about-axis transforms: data
// round trips, field calls, the matrix each composes into the view (the
// matrix of its QD3DMath.h function), bounds, and bad input (a failed Set
// leaves the data and the edit index unchanged). Their 3DMF forms are in
// FileStateRoundTripTest.

#include "Q3ApiTest.h"
#include "TransformTestSupport.h"

#include "QD3DGeometry.h"
#include "QD3DMath.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

using q3test::Q3ApiTest;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
const float kNonFinite[] = {kNaN, kInf, -kInf};

void expectMatrixNear(const TQ3Matrix4x4& actual, const TQ3Matrix4x4& expected, const char* what)
{
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            EXPECT_NEAR(actual.value[i][j], expected.value[i][j], 1e-5f) << what << ": value[" << i << "][" << j << "]";
}

// Stores any int in an axis field, as C code may (reading it back as a
// TQ3Axis would be undefined in C++: only Q3 reads it, as bytes).
void setRawAxis(TQ3Axis& field, int value)
{
    static_assert(sizeof field == sizeof value, "TQ3Axis is int-sized, as in C");
    std::memcpy(&field, &value, sizeof value);
}

class RotateAboutTransformApiTest : public q3test::TransformStateTest {};

const TQ3Quaternion kQuaternion{0.5f, -0.5f, 0.25f, 2.0f};
const TQ3RotateAboutPointTransformData kAboutPoint{kQ3AxisY, 0.75f, {1.0f, 2.0f, -3.0f}};
const TQ3RotateAboutAxisTransformData kAboutAxis{{0.5f, 0.0f, 1.0f}, {0.0f, 3.0f, 4.0f}, -1.25f};

TEST_F(RotateAboutTransformApiTest, NewMakesEachKindAndKeepsItsData)
{
    TQ3TransformObject q = Q3QuaternionTransform_New(&kQuaternion);
    TQ3TransformObject p = Q3RotateAboutPointTransform_New(&kAboutPoint);
    TQ3TransformObject a = Q3RotateAboutAxisTransform_New(&kAboutAxis);
    ASSERT_NE(q, nullptr);
    ASSERT_NE(p, nullptr);
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(Q3Transform_GetType(q), kQ3TransformTypeQuaternion);
    EXPECT_EQ(Q3Transform_GetType(p), kQ3TransformTypeRotateAboutPoint);
    EXPECT_EQ(Q3Transform_GetType(a), kQ3TransformTypeRotateAboutAxis);
    for (TQ3Object t : {q, p, a}) {
        EXPECT_EQ(Q3Shape_GetType(t), kQ3ShapeTypeTransform);
        EXPECT_EQ(Q3Object_IsDrawable(t), kQ3True);
    }

    TQ3TransformObject copies[] = {Q3Object_Duplicate(q), Q3Object_Duplicate(p), Q3Object_Duplicate(a)};
    TQ3Quaternion gotQ{};
    TQ3RotateAboutPointTransformData gotP{};
    TQ3RotateAboutAxisTransformData gotA{};
    ASSERT_EQ(Q3QuaternionTransform_Get(copies[0], &gotQ), kQ3Success);
    ASSERT_EQ(Q3RotateAboutPointTransform_GetData(copies[1], &gotP), kQ3Success);
    ASSERT_EQ(Q3RotateAboutAxisTransform_GetData(copies[2], &gotA), kQ3Success);
    EXPECT_EQ(std::memcmp(&gotQ, &kQuaternion, sizeof gotQ), 0); // as given, not normalized
    EXPECT_EQ(std::memcmp(&gotP, &kAboutPoint, sizeof gotP), 0);
    EXPECT_EQ(std::memcmp(&gotA, &kAboutAxis, sizeof gotA), 0);

    TQ3Axis axis = kQ3AxisX;
    float radians = 0;
    TQ3Point3D point{};
    TQ3Vector3D vector{};
    ASSERT_EQ(Q3RotateAboutPointTransform_GetAxis(p, &axis), kQ3Success);
    EXPECT_EQ(axis, kQ3AxisY);
    ASSERT_EQ(Q3RotateAboutPointTransform_GetAngle(p, &radians), kQ3Success);
    EXPECT_EQ(radians, 0.75f);
    ASSERT_EQ(Q3RotateAboutPointTransform_GetAboutPoint(p, &point), kQ3Success);
    EXPECT_EQ(point.z, -3.0f);
    ASSERT_EQ(Q3RotateAboutAxisTransform_GetOrigin(a, &point), kQ3Success);
    EXPECT_EQ(point.x, 0.5f);
    ASSERT_EQ(Q3RotateAboutAxisTransform_GetOrientation(a, &vector), kQ3Success);
    EXPECT_EQ(vector.z, 4.0f);
    ASSERT_EQ(Q3RotateAboutAxisTransform_GetAngle(a, &radians), kQ3Success);
    EXPECT_EQ(radians, -1.25f);
    for (TQ3Object t : {q, p, a, copies[0], copies[1], copies[2]})
        Q3Object_Dispose(t);
}

TEST_F(RotateAboutTransformApiTest, FieldSettersChangeOneFieldAndBumpTheEditIndex)
{
    TQ3TransformObject p = Q3RotateAboutPointTransform_New(&kAboutPoint);
    TQ3TransformObject a = Q3RotateAboutAxisTransform_New(&kAboutAxis);
    TQ3TransformObject q = Q3QuaternionTransform_New(&kQuaternion);
    unsigned long index = Q3Shared_GetEditIndex(p);
    ASSERT_EQ(Q3RotateAboutPointTransform_SetAxis(p, kQ3AxisZ), kQ3Success);
    ASSERT_EQ(Q3RotateAboutPointTransform_SetAngle(p, 2.0f), kQ3Success);
    const TQ3Point3D about{7, 8, 9};
    ASSERT_EQ(Q3RotateAboutPointTransform_SetAboutPoint(p, &about), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(p), index);
    TQ3RotateAboutPointTransformData gotP{};
    ASSERT_EQ(Q3RotateAboutPointTransform_GetData(p, &gotP), kQ3Success);
    EXPECT_EQ(gotP.axis, kQ3AxisZ);
    EXPECT_EQ(gotP.radians, 2.0f);
    EXPECT_EQ(gotP.about.y, 8.0f);

    index = Q3Shared_GetEditIndex(a);
    const TQ3Point3D origin{-1, -2, -3};
    const TQ3Vector3D orientation{1, 0, 0};
    ASSERT_EQ(Q3RotateAboutAxisTransform_SetOrigin(a, &origin), kQ3Success);
    ASSERT_EQ(Q3RotateAboutAxisTransform_SetOrientation(a, &orientation), kQ3Success);
    ASSERT_EQ(Q3RotateAboutAxisTransform_SetAngle(a, 0.5f), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(a), index);
    TQ3RotateAboutAxisTransformData gotA{};
    ASSERT_EQ(Q3RotateAboutAxisTransform_GetData(a, &gotA), kQ3Success);
    EXPECT_EQ(gotA.origin.z, -3.0f);
    EXPECT_EQ(gotA.orientation.x, 1.0f);
    EXPECT_EQ(gotA.radians, 0.5f);
    ASSERT_EQ(Q3RotateAboutAxisTransform_SetData(a, &kAboutAxis), kQ3Success);
    ASSERT_EQ(Q3RotateAboutPointTransform_SetData(p, &kAboutPoint), kQ3Success);

    index = Q3Shared_GetEditIndex(q);
    const TQ3Quaternion other{1, 0, 0, 0};
    ASSERT_EQ(Q3QuaternionTransform_Set(q, &other), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(q), index);
    TQ3Quaternion gotQ{};
    ASSERT_EQ(Q3QuaternionTransform_Get(q, &gotQ), kQ3Success);
    EXPECT_EQ(gotQ.w, 1.0f);
    for (TQ3Object t : {p, a, q})
        Q3Object_Dispose(t);
}

TEST_F(RotateAboutTransformApiTest, EachComposesTheMatrixOfItsMathFunction)
{
    TQ3Quaternion unit = kQuaternion;
    Q3Quaternion_Normalize(&unit, &unit);
    TQ3Matrix4x4 expected{};
    Q3Matrix4x4_SetQuaternion(&expected, &unit);
    expectMatrixNear(stateAfter([&](TQ3ViewObject v) { EXPECT_EQ(Q3QuaternionTransform_Submit(&kQuaternion, v), kQ3Success); }),
                     expected, "quaternion");
    TQ3TransformObject q = Q3QuaternionTransform_New(&kQuaternion);
    TQ3Matrix4x4 got{};
    ASSERT_EQ(Q3Transform_GetMatrix(q, &got), &got);
    expectMatrixNear(got, expected, "quaternion GetMatrix");
    expectMatrixNear(stateAfter([&](TQ3ViewObject v) { EXPECT_EQ(Q3Transform_Submit(q, v), kQ3Success); }), expected,
                     "quaternion retained");

    Q3Matrix4x4_SetRotateAboutPoint(&expected, &kAboutPoint.about, 0.0f, 0.75f, 0.0f);
    expectMatrixNear(
        stateAfter([&](TQ3ViewObject v) { EXPECT_EQ(Q3RotateAboutPointTransform_Submit(&kAboutPoint, v), kQ3Success); }),
        expected, "about point");
    TQ3TransformObject p = Q3RotateAboutPointTransform_New(&kAboutPoint);
    ASSERT_EQ(Q3Transform_GetMatrix(p, &got), &got);
    expectMatrixNear(got, expected, "about point GetMatrix");

    Q3Matrix4x4_SetRotateAboutAxis(&expected, &kAboutAxis.origin, &kAboutAxis.orientation, kAboutAxis.radians);
    expectMatrixNear(
        stateAfter([&](TQ3ViewObject v) { EXPECT_EQ(Q3RotateAboutAxisTransform_Submit(&kAboutAxis, v), kQ3Success); }),
        expected, "about axis");
    TQ3TransformObject a = Q3RotateAboutAxisTransform_New(&kAboutAxis);
    ASSERT_EQ(Q3Transform_GetMatrix(a, &got), &got);
    expectMatrixNear(got, expected, "about axis GetMatrix");
    for (TQ3Object t : {q, p, a})
        Q3Object_Dispose(t);
}

TEST_F(RotateAboutTransformApiTest, GeometryAfterThemIsBoundedWhereTheyMoveIt)
{
    // A quarter turn about z through (1, 1, 0) takes (2, 1, 0) to (1, 2, 0);
    // about the z axis through the origin, a quaternion takes (1, 0, 0) to
    // (0, 1, 0); about the line x = 1 along z, (0, 0, 0) goes to (1, -1, 0).
    const TQ3PointData point{{2, 1, 0}, nullptr};
    const TQ3RotateAboutPointTransformData turn{kQ3AxisZ, kQ3PiOver2, {1, 1, 0}};
    TQ3BoundingBox box{};
    stateAfter(
        [&](TQ3ViewObject v) {
            Q3RotateAboutPointTransform_Submit(&turn, v);
            Q3Point_Submit(&point, v);
        },
        &box);
    EXPECT_NEAR(box.min.x, 1.0f, 1e-5f);
    EXPECT_NEAR(box.min.y, 2.0f, 1e-5f);

    const float half = std::sqrt(0.5f);
    const TQ3Quaternion quarter{half, 0, 0, half};
    const TQ3PointData x{{1, 0, 0}, nullptr};
    stateAfter(
        [&](TQ3ViewObject v) {
            Q3QuaternionTransform_Submit(&quarter, v);
            Q3Point_Submit(&x, v);
        },
        &box);
    EXPECT_NEAR(box.min.x, 0.0f, 1e-5f);
    EXPECT_NEAR(box.min.y, 1.0f, 1e-5f);

    const TQ3RotateAboutAxisTransformData line{{1, 0, 0}, {0, 0, 2}, kQ3PiOver2};
    const TQ3PointData origin{{0, 0, 0}, nullptr};
    stateAfter(
        [&](TQ3ViewObject v) {
            Q3RotateAboutAxisTransform_Submit(&line, v);
            Q3Point_Submit(&origin, v);
        },
        &box);
    EXPECT_NEAR(box.min.x, 1.0f, 1e-5f);
    EXPECT_NEAR(box.min.y, -1.0f, 1e-5f);
}

TEST_F(RotateAboutTransformApiTest, NewAndSubmitRejectBadData)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3QuaternionTransform_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutPointTransform_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutAxisTransform_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    const TQ3Quaternion zero{0, 0, 0, 0};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3QuaternionTransform_New(&zero), nullptr), kQ3ErrorInvalidParameter);
    for (float bad : kNonFinite) {
        for (int i = 0; i < 4; ++i) {
            TQ3Quaternion q = kQuaternion;
            (&q.w)[i] = bad;
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3QuaternionTransform_New(&q), nullptr), kQ3ErrorInvalidParameter);
        }
        TQ3RotateAboutPointTransformData p = kAboutPoint;
        p.radians = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutPointTransform_New(&p), nullptr), kQ3ErrorInvalidData);
        p = kAboutPoint;
        p.about.y = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutPointTransform_New(&p), nullptr), kQ3ErrorInvalidData);
        TQ3RotateAboutAxisTransformData a = kAboutAxis;
        a.radians = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutAxisTransform_New(&a), nullptr), kQ3ErrorInvalidData);
        a = kAboutAxis;
        a.origin.x = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutAxisTransform_New(&a), nullptr), kQ3ErrorInvalidData);
        a = kAboutAxis;
        a.orientation.z = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutAxisTransform_New(&a), nullptr), kQ3ErrorInvalidData);
    }
    for (int axis : {-1, 3, 1000}) {
        TQ3RotateAboutPointTransformData p = kAboutPoint;
        setRawAxis(p.axis, axis);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutPointTransform_New(&p), nullptr), kQ3ErrorInvalidData);
    }
    TQ3RotateAboutAxisTransformData a = kAboutAxis;
    a.orientation = {0, 0, 0};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutAxisTransform_New(&a), nullptr), kQ3ErrorInvalidData);

    // Immediate mode: the same checks inside a loop, which the state survives.
    TQ3Matrix4x4 identity{};
    Q3Matrix4x4_SetIdentity(&identity);
    expectMatrixNear(stateAfter([&](TQ3ViewObject v) {
                         EXPECT_Q3_ERROR(EXPECT_EQ(Q3QuaternionTransform_Submit(&zero, v), kQ3Failure),
                                         kQ3ErrorInvalidParameter);
                         EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutAxisTransform_Submit(&a, v), kQ3Failure),
                                         kQ3ErrorInvalidData);
                         EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutPointTransform_Submit(nullptr, v), kQ3Failure),
                                         kQ3ErrorNULLParameter);
                     }),
                     identity, "after refused submits");
    // Outside a loop, and with bad views.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3QuaternionTransform_Submit(&kQuaternion, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutPointTransform_Submit(&kAboutPoint, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    TQ3TransformObject notAView = Q3QuaternionTransform_New(&kQuaternion);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutAxisTransform_Submit(&kAboutAxis, notAView), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(notAView);
}

TEST_F(RotateAboutTransformApiTest, CallsRejectBadHandlesAndNullPointers)
{
    TQ3TransformObject q = Q3QuaternionTransform_New(&kQuaternion);
    TQ3TransformObject p = Q3RotateAboutPointTransform_New(&kAboutPoint);
    TQ3TransformObject a = Q3RotateAboutAxisTransform_New(&kAboutAxis);
    TQ3TransformObject dead = Q3QuaternionTransform_New(&kQuaternion);
    Q3Object_Dispose(dead);
    TQ3Quaternion quaternion{};
    TQ3RotateAboutPointTransformData pointData{};
    TQ3RotateAboutAxisTransformData axisData{};
    TQ3Axis axis{};
    float radians = 0;
    TQ3Point3D point{};
    TQ3Vector3D vector{1, 0, 0};
    // Each call, given a handle, with its pointer present or NULL.
    using Call = std::function<TQ3Status(TQ3TransformObject, bool)>;
    const std::vector<std::pair<TQ3TransformObject, Call>> calls = {
        {q, [&](TQ3TransformObject t, bool ok) { return Q3QuaternionTransform_Set(t, ok ? &kQuaternion : nullptr); }},
        {q, [&](TQ3TransformObject t, bool ok) { return Q3QuaternionTransform_Get(t, ok ? &quaternion : nullptr); }},
        {p, [&](TQ3TransformObject t, bool ok) { return Q3RotateAboutPointTransform_SetData(t, ok ? &kAboutPoint : nullptr); }},
        {p, [&](TQ3TransformObject t, bool ok) { return Q3RotateAboutPointTransform_GetData(t, ok ? &pointData : nullptr); }},
        {p, [&](TQ3TransformObject t, bool) { return Q3RotateAboutPointTransform_SetAxis(t, kQ3AxisX); }},
        {p, [&](TQ3TransformObject t, bool ok) { return Q3RotateAboutPointTransform_GetAxis(t, ok ? &axis : nullptr); }},
        {p, [&](TQ3TransformObject t, bool) { return Q3RotateAboutPointTransform_SetAngle(t, 1.0f); }},
        {p, [&](TQ3TransformObject t, bool ok) { return Q3RotateAboutPointTransform_GetAngle(t, ok ? &radians : nullptr); }},
        {p, [&](TQ3TransformObject t, bool ok) { return Q3RotateAboutPointTransform_SetAboutPoint(t, ok ? &point : nullptr); }},
        {p, [&](TQ3TransformObject t, bool ok) { return Q3RotateAboutPointTransform_GetAboutPoint(t, ok ? &point : nullptr); }},
        {a, [&](TQ3TransformObject t, bool ok) { return Q3RotateAboutAxisTransform_SetData(t, ok ? &kAboutAxis : nullptr); }},
        {a, [&](TQ3TransformObject t, bool ok) { return Q3RotateAboutAxisTransform_GetData(t, ok ? &axisData : nullptr); }},
        {a, [&](TQ3TransformObject t, bool ok) { return Q3RotateAboutAxisTransform_SetOrientation(t, ok ? &vector : nullptr); }},
        {a, [&](TQ3TransformObject t, bool ok) { return Q3RotateAboutAxisTransform_GetOrientation(t, ok ? &vector : nullptr); }},
        {a, [&](TQ3TransformObject t, bool) { return Q3RotateAboutAxisTransform_SetAngle(t, 1.0f); }},
        {a, [&](TQ3TransformObject t, bool ok) { return Q3RotateAboutAxisTransform_GetAngle(t, ok ? &radians : nullptr); }},
        {a, [&](TQ3TransformObject t, bool ok) { return Q3RotateAboutAxisTransform_SetOrigin(t, ok ? &point : nullptr); }},
        {a, [&](TQ3TransformObject t, bool ok) { return Q3RotateAboutAxisTransform_GetOrigin(t, ok ? &point : nullptr); }},
    };
    const bool takesPointer[] = {true, true, true, true, false, true, false, true, true, true,
                                 true, true, true, true, false, true, true, true};
    for (std::size_t i = 0; i < calls.size(); ++i) {
        SCOPED_TRACE("call " + std::to_string(i));
        const TQ3TransformObject right = calls[i].first;
        const TQ3TransformObject wrong = right == q ? p : q;
        EXPECT_Q3_ERROR(EXPECT_EQ(calls[i].second(nullptr, true), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(calls[i].second(dead, true), kQ3Failure), kQ3ErrorInvalidObject);
        EXPECT_Q3_ERROR(EXPECT_EQ(calls[i].second(wrong, true), kQ3Failure), kQ3ErrorInvalidObjectType);
        if (takesPointer[i])
            EXPECT_Q3_ERROR(EXPECT_EQ(calls[i].second(right, false), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_EQ(calls[i].second(right, true), kQ3Success);
    }
    for (TQ3Object t : {q, p, a})
        Q3Object_Dispose(t);
}

TEST_F(RotateAboutTransformApiTest, AFailedSetLeavesTheDataAndTheEditIndex)
{
    TQ3TransformObject q = Q3QuaternionTransform_New(&kQuaternion);
    TQ3TransformObject p = Q3RotateAboutPointTransform_New(&kAboutPoint);
    TQ3TransformObject a = Q3RotateAboutAxisTransform_New(&kAboutAxis);
    const unsigned long indexQ = Q3Shared_GetEditIndex(q), indexP = Q3Shared_GetEditIndex(p),
                        indexA = Q3Shared_GetEditIndex(a);
    const TQ3Quaternion zero{0, 0, 0, 0};
    const TQ3Quaternion nan{kNaN, 0, 0, 1};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3QuaternionTransform_Set(q, &zero), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3QuaternionTransform_Set(q, &nan), kQ3Failure), kQ3ErrorInvalidParameter);
    for (int bad : {-1, 3}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutPointTransform_SetAxis(p, static_cast<TQ3Axis>(bad)), kQ3Failure),
                        kQ3ErrorInvalidData);
    }
    const TQ3Point3D farAway{kInf, 0, 0};
    const TQ3Vector3D none{0, 0, 0}, nanVector{0, kNaN, 1};
    for (float bad : kNonFinite) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutPointTransform_SetAngle(p, bad), kQ3Failure), kQ3ErrorInvalidData);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutAxisTransform_SetAngle(a, bad), kQ3Failure), kQ3ErrorInvalidData);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutPointTransform_SetAboutPoint(p, &farAway), kQ3Failure),
                    kQ3ErrorInvalidData);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutAxisTransform_SetOrigin(a, &farAway), kQ3Failure), kQ3ErrorInvalidData);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutAxisTransform_SetOrientation(a, &none), kQ3Failure), kQ3ErrorInvalidData);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutAxisTransform_SetOrientation(a, &nanVector), kQ3Failure),
                    kQ3ErrorInvalidData);
    TQ3RotateAboutPointTransformData badP = kAboutPoint;
    badP.radians = kNaN;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutPointTransform_SetData(p, &badP), kQ3Failure), kQ3ErrorInvalidData);
    TQ3RotateAboutAxisTransformData badA = kAboutAxis;
    badA.orientation = none;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateAboutAxisTransform_SetData(a, &badA), kQ3Failure), kQ3ErrorInvalidData);

    EXPECT_EQ(Q3Shared_GetEditIndex(q), indexQ);
    EXPECT_EQ(Q3Shared_GetEditIndex(p), indexP);
    EXPECT_EQ(Q3Shared_GetEditIndex(a), indexA);
    TQ3Quaternion gotQ{};
    TQ3RotateAboutPointTransformData gotP{};
    TQ3RotateAboutAxisTransformData gotA{};
    ASSERT_EQ(Q3QuaternionTransform_Get(q, &gotQ), kQ3Success);
    ASSERT_EQ(Q3RotateAboutPointTransform_GetData(p, &gotP), kQ3Success);
    ASSERT_EQ(Q3RotateAboutAxisTransform_GetData(a, &gotA), kQ3Success);
    EXPECT_EQ(std::memcmp(&gotQ, &kQuaternion, sizeof gotQ), 0);
    EXPECT_EQ(std::memcmp(&gotP, &kAboutPoint, sizeof gotP), 0);
    EXPECT_EQ(std::memcmp(&gotA, &kAboutAxis, sizeof gotA), 0);
    for (TQ3Object t : {q, p, a})
        Q3Object_Dispose(t);
}

} // namespace
