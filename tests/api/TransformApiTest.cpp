// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "Q3ApiTest.h"

#include "QD3DMath.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <climits>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

namespace {

using q3test::Q3ApiTest;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
const float kNonFinite[] = {kNaN, kInf, -kInf};

TQ3Matrix4x4 identity()
{
    TQ3Matrix4x4 m{};
    Q3Matrix4x4_SetIdentity(&m);
    return m;
}

TQ3Matrix4x4 translation(float x, float y, float z)
{
    TQ3Matrix4x4 m{};
    Q3Matrix4x4_SetTranslate(&m, x, y, z);
    return m;
}

// What a C caller can store in the enum field: any int. Converting such an
// int to TQ3Axis in C++ would be undefined, so the bits are copied in.
TQ3RotateTransformData rotateWithRawAxis(int axis, float radians)
{
    TQ3RotateTransformData data{kQ3AxisX, radians};
    static_assert(sizeof data.axis == sizeof axis, "TQ3Axis is int-sized");
    std::memcpy(&data.axis, &axis, sizeof axis);
    return data;
}

void expectMatrixNear(const TQ3Matrix4x4& actual, const TQ3Matrix4x4& expected, const char* what)
{
    // The view composes in double and rounds once; a float ulp or two.
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            EXPECT_NEAR(actual.value[i][j], expected.value[i][j], 1e-6f)
                << what << ": value[" << i << "][" << j << "]";
}

class TransformApiTest : public Q3ApiTest {
protected:
    void TearDown() override
    {
        if (m_view != nullptr)
            Q3Object_Dispose(m_view);
        Q3ApiTest::TearDown();
    }

    TQ3ViewObject view()
    {
        if (m_view == nullptr)
            m_view = Q3View_New();
        return m_view;
    }

    /// Runs one bounding loop, calling `scene` in every traversal, and
    /// returns the local-to-world matrix it leaves.
    TQ3Matrix4x4 stateAfter(const std::function<void(TQ3ViewObject)>& scene)
    {
        TQ3Matrix4x4 state = identity();
        TQ3BoundingBox box{};
        EXPECT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
        do {
            scene(view());
            EXPECT_EQ(Q3View_GetLocalToWorldMatrixState(view(), &state), kQ3Success);
        } while (Q3View_EndBoundingBox(view(), &box) == kQ3ViewStatusRetraverse);
        return state;
    }

    /// Every check a _New makes on its object: type chain, drawable,
    /// duplicable. Disposes it.
    void expectTransformOfType(TQ3TransformObject transform, TQ3ObjectType leafType)
    {
        ASSERT_NE(transform, nullptr);
        EXPECT_EQ(Q3Object_GetType(transform), kQ3ObjectTypeShared);
        EXPECT_EQ(Q3Shared_GetType(transform), kQ3SharedTypeShape);
        EXPECT_EQ(Q3Shape_GetType(transform), kQ3ShapeTypeTransform);
        EXPECT_EQ(Q3Object_GetLeafType(transform), leafType);
        EXPECT_EQ(Q3Object_IsType(transform, kQ3ShapeTypeTransform), kQ3True);
        EXPECT_EQ(Q3Object_IsDrawable(transform), kQ3True);
        TQ3Object copy = Q3Object_Duplicate(transform);
        ASSERT_NE(copy, nullptr);
        EXPECT_NE(copy, transform);
        EXPECT_EQ(Q3Object_GetLeafType(copy), leafType);
        Q3Object_Dispose(copy);
        Q3Object_Dispose(transform);
    }

private:
    TQ3ViewObject m_view = nullptr;
};

// ---- Creating transforms ----------------------------------------------------

TEST_F(TransformApiTest, MatrixTransformNewMakesAMatrixTransform)
{
    const TQ3Matrix4x4 m = translation(1, 2, 3);
    expectTransformOfType(Q3MatrixTransform_New(&m), kQ3TransformTypeMatrix);
}

TEST_F(TransformApiTest, MatrixTransformNewAcceptsASingularMatrix)
{
    TQ3Matrix4x4 zero{};
    expectTransformOfType(Q3MatrixTransform_New(&zero), kQ3TransformTypeMatrix);
}

TEST_F(TransformApiTest, MatrixTransformNewRejectsNull)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MatrixTransform_New(nullptr), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(TransformApiTest, MatrixTransformNewRejectsEveryNonFiniteEntry)
{
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (float bad : kNonFinite) {
                TQ3Matrix4x4 m = identity();
                m.value[i][j] = bad;
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3MatrixTransform_New(&m), nullptr), kQ3ErrorInvalidParameter);
            }
}

TEST_F(TransformApiTest, TranslateTransformNewMakesATranslateTransform)
{
    const TQ3Vector3D offset{1, -2, 3};
    expectTransformOfType(Q3TranslateTransform_New(&offset), kQ3TransformTypeTranslate);
}

TEST_F(TransformApiTest, TranslateTransformNewRejectsNullAndNonFiniteComponents)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TranslateTransform_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    for (float bad : kNonFinite) {
        const TQ3Vector3D vectors[] = {{bad, 0, 0}, {0, bad, 0}, {0, 0, bad}};
        for (const TQ3Vector3D& v : vectors)
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3TranslateTransform_New(&v), nullptr), kQ3ErrorInvalidParameter);
    }
}

TEST_F(TransformApiTest, ScaleTransformNewMakesAScaleTransform)
{
    const TQ3Vector3D scale{2, 3, 4};
    expectTransformOfType(Q3ScaleTransform_New(&scale), kQ3TransformTypeScale);
}

TEST_F(TransformApiTest, ScaleTransformNewAcceptsZeroAndNegativeFactorsSilently)
{
    // QuickDraw 3D allows them ("when two or three of the scale factors are
    // 0, nothing is drawn"); the fixture fails on any post.
    const TQ3Vector3D zeros{0, 0, 0}, oneZero{1, 0, 1}, negative{-1, 2, -3};
    expectTransformOfType(Q3ScaleTransform_New(&zeros), kQ3TransformTypeScale);
    expectTransformOfType(Q3ScaleTransform_New(&oneZero), kQ3TransformTypeScale);
    expectTransformOfType(Q3ScaleTransform_New(&negative), kQ3TransformTypeScale);
}

TEST_F(TransformApiTest, ScaleTransformNewRejectsNullAndNonFiniteFactors)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ScaleTransform_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    for (float bad : kNonFinite) {
        const TQ3Vector3D vectors[] = {{bad, 1, 1}, {1, bad, 1}, {1, 1, bad}};
        for (const TQ3Vector3D& v : vectors)
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3ScaleTransform_New(&v), nullptr), kQ3ErrorInvalidParameter);
    }
}

TEST_F(TransformApiTest, RotateTransformNewAcceptsEachAxis)
{
    for (TQ3Axis axis : {kQ3AxisX, kQ3AxisY, kQ3AxisZ}) {
        const TQ3RotateTransformData data{axis, 1.0f};
        expectTransformOfType(Q3RotateTransform_New(&data), kQ3TransformTypeRotate);
    }
}

TEST_F(TransformApiTest, RotateTransformNewRejectsAxesOutsideTheEnum)
{
    for (int axis : {-1, 3, INT_MAX, INT_MIN}) {
        const TQ3RotateTransformData data = rotateWithRawAxis(axis, 1.0f);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateTransform_New(&data), nullptr), kQ3ErrorInvalidData);
    }
}

TEST_F(TransformApiTest, RotateTransformNewRejectsNullAndNonFiniteAngles)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateTransform_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    for (float bad : kNonFinite) {
        const TQ3RotateTransformData data{kQ3AxisY, bad};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateTransform_New(&data), nullptr), kQ3ErrorInvalidData);
    }
}

TEST_F(TransformApiTest, ResetTransformNewMakesAResetTransform)
{
    expectTransformOfType(Q3ResetTransform_New(), kQ3TransformTypeReset);
}

TEST(TransformApiUninitialized, EveryFunctionFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    const TQ3Matrix4x4 m{};
    const TQ3Vector3D v{1, 1, 1};
    const TQ3RotateTransformData r{kQ3AxisX, 1.0f};
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    EXPECT_EQ(Q3MatrixTransform_New(&m), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3TranslateTransform_New(&v), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3ScaleTransform_New(&v), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3RotateTransform_New(&r), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3ResetTransform_New(), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3MatrixTransform_Submit(&m, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3TranslateTransform_Submit(&v, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3ScaleTransform_Submit(&v, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3RotateTransform_Submit(&r, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3ResetTransform_Submit(nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
}

// ---- Submitting: argument checks -------------------------------------------

TEST_F(TransformApiTest, SubmitOutsideALoopFailsWithViewNotStarted)
{
    const TQ3Matrix4x4 m = identity();
    const TQ3Vector3D v{1, 2, 3};
    const TQ3RotateTransformData r{kQ3AxisZ, 0.5f};
    ASSERT_NE(view(), nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MatrixTransform_Submit(&m, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TranslateTransform_Submit(&v, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ScaleTransform_Submit(&v, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateTransform_Submit(&r, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ResetTransform_Submit(view()), kQ3Failure), kQ3ErrorViewNotStarted);
}

TEST_F(TransformApiTest, SubmitChecksTheDataPointerBeforeTheView)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MatrixTransform_Submit(nullptr, view()), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TranslateTransform_Submit(nullptr, view()), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ScaleTransform_Submit(nullptr, view()), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateTransform_Submit(nullptr, view()), kQ3Failure), kQ3ErrorNULLParameter);
}

TEST_F(TransformApiTest, SubmitRejectsANullView)
{
    const TQ3Matrix4x4 m = identity();
    const TQ3Vector3D v{1, 2, 3};
    const TQ3RotateTransformData r{kQ3AxisZ, 0.5f};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MatrixTransform_Submit(&m, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TranslateTransform_Submit(&v, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ScaleTransform_Submit(&v, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateTransform_Submit(&r, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ResetTransform_Submit(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
}

TEST_F(TransformApiTest, SubmitRejectsAViewThatIsNotAView)
{
    const TQ3Vector3D v{1, 2, 3};
    TQ3TransformObject notAView = Q3TranslateTransform_New(&v);
    ASSERT_NE(notAView, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TranslateTransform_Submit(&v, notAView), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ResetTransform_Submit(notAView), kQ3Failure), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(notAView);
    int notAnObject = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ResetTransform_Submit(reinterpret_cast<TQ3ViewObject>(&notAnObject)),
                              kQ3Failure),
                    kQ3ErrorInvalidObject);
}

TEST_F(TransformApiTest, SubmitOutsideALoopReportsViewNotStartedBeforeBadData)
{
    // The view's condition comes before the data rules (QD3DView.h order).
    TQ3Matrix4x4 m = identity();
    m.value[0][0] = kNaN;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MatrixTransform_Submit(&m, view()), kQ3Failure), kQ3ErrorViewNotStarted);
}

// ---- Submitting: effect on the view ------------------------------------------

TEST_F(TransformApiTest, SubmittedMatrixBecomesTheLocalToWorldMatrix)
{
    TQ3Matrix4x4 m{};
    Q3Matrix4x4_SetRotate_Z(&m, 0.25f);
    m.value[3][0] = 5;
    const TQ3Matrix4x4 state = stateAfter([&](TQ3ViewObject v) {
        EXPECT_EQ(Q3MatrixTransform_Submit(&m, v), kQ3Success);
    });
    expectMatrixNear(state, m, "after one matrix");
}

TEST_F(TransformApiTest, LaterTransformsApplyBeforeEarlierOnes)
{
    // Submitting T then S gives local-to-world S * T: S acts on the
    // geometry first. Translate by (1,0,0), then scale by 2: a point at the
    // local origin is scaled (no change) and then translated to (1,0,0).
    const TQ3Vector3D offset{1, 0, 0}, factors{2, 2, 2};
    const TQ3Matrix4x4 state = stateAfter([&](TQ3ViewObject v) {
        EXPECT_EQ(Q3TranslateTransform_Submit(&offset, v), kQ3Success);
        EXPECT_EQ(Q3ScaleTransform_Submit(&factors, v), kQ3Success);
    });
    const TQ3Point3D origin{0, 0, 0}, x{1, 0, 0};
    TQ3Point3D p{};
    Q3Point3D_Transform(&origin, &state, &p);
    EXPECT_FLOAT_EQ(p.x, 1.0f);
    Q3Point3D_Transform(&x, &state, &p);
    EXPECT_FLOAT_EQ(p.x, 3.0f);
}

TEST_F(TransformApiTest, EachImmediateTransformHasTheMatrixOfItsMathFunction)
{
    const TQ3Vector3D offset{1, -2, 3}, factors{2, 0, -1};
    TQ3Matrix4x4 expected{};
    Q3Matrix4x4_SetTranslate(&expected, 1, -2, 3);
    expectMatrixNear(stateAfter([&](TQ3ViewObject v) { Q3TranslateTransform_Submit(&offset, v); }),
                     expected, "translate");
    Q3Matrix4x4_SetScale(&expected, 2, 0, -1);
    expectMatrixNear(stateAfter([&](TQ3ViewObject v) { Q3ScaleTransform_Submit(&factors, v); }), expected,
                     "scale");
    using SetRotate = TQ3Matrix4x4* (*)(TQ3Matrix4x4*, float);
    const SetRotate setters[] = {Q3Matrix4x4_SetRotate_X, Q3Matrix4x4_SetRotate_Y, Q3Matrix4x4_SetRotate_Z};
    for (TQ3Axis axis : {kQ3AxisX, kQ3AxisY, kQ3AxisZ}) {
        const TQ3RotateTransformData data{axis, 0.75f};
        setters[axis](&expected, 0.75f);
        expectMatrixNear(stateAfter([&](TQ3ViewObject v) { Q3RotateTransform_Submit(&data, v); }), expected,
                         "rotate");
    }
}

TEST_F(TransformApiTest, RotateTransformQuarterTurnAboutZTakesXToY)
{
    const TQ3RotateTransformData data{kQ3AxisZ, kQ3PiOver2};
    const TQ3Matrix4x4 state =
        stateAfter([&](TQ3ViewObject v) { EXPECT_EQ(Q3RotateTransform_Submit(&data, v), kQ3Success); });
    const TQ3Point3D x{1, 0, 0};
    TQ3Point3D p{};
    Q3Point3D_Transform(&x, &state, &p);
    EXPECT_NEAR(p.x, 0.0f, 1e-6f);
    EXPECT_NEAR(p.y, 1.0f, 1e-6f);
    EXPECT_NEAR(p.z, 0.0f, 1e-6f);
}

TEST_F(TransformApiTest, ResetTransformRestoresTheIdentity)
{
    const TQ3Vector3D offset{4, 5, 6};
    const TQ3Matrix4x4 afterReset = stateAfter([&](TQ3ViewObject v) {
        Q3TranslateTransform_Submit(&offset, v);
        EXPECT_EQ(Q3ResetTransform_Submit(v), kQ3Success);
    });
    expectMatrixNear(afterReset, identity(), "after reset");
    const TQ3Matrix4x4 afterMore = stateAfter([&](TQ3ViewObject v) {
        Q3TranslateTransform_Submit(&offset, v);
        Q3ResetTransform_Submit(v);
        Q3TranslateTransform_Submit(&offset, v);
    });
    expectMatrixNear(afterMore, translation(4, 5, 6), "translate after reset");
}

TEST_F(TransformApiTest, RetainedTransformsSubmitLikeImmediateOnes)
{
    const TQ3Vector3D offset{1, 2, 3};
    TQ3TransformObject translate = Q3TranslateTransform_New(&offset);
    TQ3TransformObject reset = Q3ResetTransform_New();
    ASSERT_NE(translate, nullptr);
    ASSERT_NE(reset, nullptr);
    expectMatrixNear(
        stateAfter([&](TQ3ViewObject v) { EXPECT_EQ(Q3Object_Submit(translate, v), kQ3Success); }),
        translation(1, 2, 3), "retained translate");
    expectMatrixNear(stateAfter([&](TQ3ViewObject v) {
                         Q3Object_Submit(translate, v);
                         EXPECT_EQ(Q3Object_Submit(reset, v), kQ3Success);
                     }),
                     identity(), "retained reset");
    Q3Object_Dispose(translate);
    Q3Object_Dispose(reset);
}

TEST_F(TransformApiTest, InvalidDataInsideALoopFailsAndLeavesTheStateAlone)
{
    const TQ3Vector3D offset{1, 2, 3}, badOffset{kInf, 0, 0};
    const TQ3RotateTransformData badRotate = rotateWithRawAxis(3, 1.0f);
    TQ3Matrix4x4 badMatrix = identity();
    badMatrix.value[3][3] = kNaN;
    const TQ3Matrix4x4 state = stateAfter([&](TQ3ViewObject v) {
        Q3TranslateTransform_Submit(&offset, v);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TranslateTransform_Submit(&badOffset, v), kQ3Failure),
                        kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3ScaleTransform_Submit(&badOffset, v), kQ3Failure),
                        kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3MatrixTransform_Submit(&badMatrix, v), kQ3Failure),
                        kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateTransform_Submit(&badRotate, v), kQ3Failure), kQ3ErrorInvalidData);
    });
    expectMatrixNear(state, translation(1, 2, 3), "after rejected submits");
}

} // namespace
