// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "Q3ApiTest.h"
#include "SetThenGet.h"
#include "ShapeTypeChain.h"
#include "TransformTestSupport.h"

#include "QD3DGeometry.h"
#include "QD3DMath.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <climits>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace {

using q3test::expectShapeTypeChain;
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

class TransformApiTest : public q3test::TransformStateTest {
protected:
    /// Every check a _New makes on its object: type chain, drawable,
    /// duplicable. Disposes it.
    void expectTransformOfType(TQ3TransformObject transform, TQ3ObjectType leafType)
    {
        ASSERT_NE(transform, nullptr);
        expectShapeTypeChain(transform, kQ3ShapeTypeTransform, leafType, kQ3True);
        TQ3Object copy = Q3Object_Duplicate(transform);
        ASSERT_NE(copy, nullptr);
        EXPECT_NE(copy, transform);
        EXPECT_EQ(Q3Object_GetLeafType(copy), leafType);
        Q3Object_Dispose(copy);
        Q3Object_Dispose(transform);
    }

    /// A quarter turn about z: the state takes (1, 0, 0) to (0, 1, 0).
    static void expectTakesXToY(const TQ3Matrix4x4& state)
    {
        const TQ3Point3D x{1, 0, 0};
        TQ3Point3D p{};
        Q3Point3D_Transform(&x, &state, &p);
        EXPECT_NEAR(p.x, 0.0f, 1e-6f);
        EXPECT_NEAR(p.y, 1.0f, 1e-6f);
        EXPECT_NEAR(p.z, 0.0f, 1e-6f);
    }
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
    TQ3Matrix4x4 mOut{};
    TQ3Vector3D vOut{};
    TQ3RotateTransformData rOut{};
    TQ3Axis axis = kQ3AxisX;
    float radians = 0;
    EXPECT_EQ(Q3Transform_GetType(nullptr), kQ3ObjectTypeInvalid);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Transform_GetMatrix(nullptr, &mOut), nullptr);
    EXPECT_TRUE(failed());
    const std::vector<std::function<TQ3Status()>> accessors = {
        [&] { return Q3Transform_Submit(nullptr, nullptr); },
        [&] { return Q3MatrixTransform_Set(nullptr, &m); },
        [&] { return Q3MatrixTransform_Get(nullptr, &mOut); },
        [&] { return Q3TranslateTransform_Set(nullptr, &v); },
        [&] { return Q3TranslateTransform_Get(nullptr, &vOut); },
        [&] { return Q3ScaleTransform_Set(nullptr, &v); },
        [&] { return Q3ScaleTransform_Get(nullptr, &vOut); },
        [&] { return Q3RotateTransform_SetData(nullptr, &r); },
        [&] { return Q3RotateTransform_GetData(nullptr, &rOut); },
        [&] { return Q3RotateTransform_SetAxis(nullptr, kQ3AxisY); },
        [&] { return Q3RotateTransform_GetAxis(nullptr, &axis); },
        [&] { return Q3RotateTransform_SetAngle(nullptr, 1.0f); },
        [&] { return Q3RotateTransform_GetAngle(nullptr, &radians); },
    };
    for (std::size_t i = 0; i < accessors.size(); ++i) {
        EXPECT_EQ(accessors[i](), kQ3Failure) << "accessor " << i;
        EXPECT_TRUE(failed()) << "accessor " << i;
    }
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
    expectTakesXToY(state);
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

// ---- Any transform: type and matrix -----------------------------------------

TEST_F(TransformApiTest, TransformGetTypeReportsEachKind)
{
    const TQ3Matrix4x4 m = translation(1, 2, 3);
    const TQ3Vector3D v{1, 2, 3};
    const TQ3RotateTransformData r{kQ3AxisY, 0.5f};
    const std::pair<TQ3TransformObject, TQ3ObjectType> cases[] = {
        {Q3MatrixTransform_New(&m), kQ3TransformTypeMatrix},
        {Q3TranslateTransform_New(&v), kQ3TransformTypeTranslate},
        {Q3ScaleTransform_New(&v), kQ3TransformTypeScale},
        {Q3RotateTransform_New(&r), kQ3TransformTypeRotate},
        {Q3ResetTransform_New(), kQ3TransformTypeReset},
    };
    for (const auto& c : cases) {
        EXPECT_EQ(Q3Transform_GetType(c.first), c.second);
        Q3Object_Dispose(c.first);
    }
}

TEST_F(TransformApiTest, TransformGetMatrixIsWhatASubmitApplies)
{
    TQ3Matrix4x4 m{};
    Q3Matrix4x4_SetRotate_X(&m, 0.3f);
    m.value[3][1] = -2;
    const TQ3Vector3D offset{1, -2, 3}, factors{2, 0, -1};
    const TQ3RotateTransformData r{kQ3AxisZ, 1.25f};
    TQ3TransformObject transforms[] = {Q3MatrixTransform_New(&m), Q3TranslateTransform_New(&offset),
                                       Q3ScaleTransform_New(&factors), Q3RotateTransform_New(&r),
                                       Q3ResetTransform_New()};
    const TQ3Vector3D before{7, 8, 9};
    for (TQ3TransformObject transform : transforms) {
        ASSERT_NE(transform, nullptr);
        TQ3Matrix4x4 got{};
        EXPECT_EQ(Q3Transform_GetMatrix(transform, &got), &got);
        // What the view holds after the transform, starting from identity
        // (a reset transform after a translation gives the identity too).
        const TQ3Matrix4x4 state = stateAfter([&](TQ3ViewObject v) {
            Q3TranslateTransform_Submit(&before, v);
            Q3ResetTransform_Submit(v);
            EXPECT_EQ(Q3Object_Submit(transform, v), kQ3Success);
        });
        expectMatrixNear(got, state, "Q3Transform_GetMatrix");
        Q3Object_Dispose(transform);
    }
}

// ---- Retained transforms: set and get ---------------------------------------

TEST_F(TransformApiTest, MatrixTransformSetReplacesTheMatrixAndBumpsTheEditIndex)
{
    const TQ3Matrix4x4 first = translation(1, 2, 3);
    TQ3Matrix4x4 second{};
    Q3Matrix4x4_SetScale(&second, 2, 3, 4);
    second.value[0][3] = 0.5f; // not affine: the matrix is kept as given
    TQ3TransformObject transform = Q3MatrixTransform_New(&first);
    TQ3Matrix4x4 out{};
    EXPECT_EQ(Q3MatrixTransform_Get(transform, &out), kQ3Success);
    EXPECT_EQ(std::memcmp(&out, &first, sizeof out), 0);
    const unsigned long edit = Q3Shared_GetEditIndex(transform);
    EXPECT_EQ(Q3MatrixTransform_Set(transform, &second), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(transform), edit);
    EXPECT_EQ(Q3MatrixTransform_Get(transform, &out), kQ3Success);
    EXPECT_EQ(std::memcmp(&out, &second, sizeof out), 0);
    expectMatrixNear(stateAfter([&](TQ3ViewObject v) { Q3Object_Submit(transform, v); }), second,
                     "after Set");
    Q3Object_Dispose(transform);
}

TEST_F(TransformApiTest, MatrixTransformSetRejectsEveryNonFiniteEntryAndChangesNothing)
{
    const TQ3Matrix4x4 good = translation(1, 2, 3);
    TQ3TransformObject transform = Q3MatrixTransform_New(&good);
    const unsigned long edit = Q3Shared_GetEditIndex(transform);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (float bad : kNonFinite) {
                TQ3Matrix4x4 m = identity();
                m.value[i][j] = bad;
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3MatrixTransform_Set(transform, &m), kQ3Failure),
                                kQ3ErrorInvalidParameter);
            }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MatrixTransform_Set(transform, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    TQ3Matrix4x4 out{};
    Q3MatrixTransform_Get(transform, &out);
    EXPECT_EQ(std::memcmp(&out, &good, sizeof out), 0);
    EXPECT_EQ(Q3Shared_GetEditIndex(transform), edit);
    Q3Object_Dispose(transform);
}

TEST_F(TransformApiTest, TranslateTransformSetMovesTheBoundsOfLaterGeometry)
{
    // A segment from (0,0,0) to (3,1,0) as an order-2 NURB curve, bounded
    // after the retained translation.
    TQ3RationalPoint4D points[2] = {{0, 0, 0, 1}, {3, 1, 0, 1}};
    float knots[4] = {0, 0, 1, 1};
    const TQ3NURBCurveData curve = {2, 2, points, knots, nullptr};
    const TQ3Vector3D first{10, 20, 30}, second{-1, 0, 5};
    TQ3TransformObject transform = Q3TranslateTransform_New(&first);
    auto bounds = [&] {
        TQ3BoundingBox box{};
        EXPECT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
        do {
            Q3Object_Submit(transform, view());
            Q3NURBCurve_Submit(&curve, view());
        } while (Q3View_EndBoundingBox(view(), &box) == kQ3ViewStatusRetraverse);
        return box;
    };
    TQ3BoundingBox box = bounds();
    EXPECT_FLOAT_EQ(box.min.x, 10);
    EXPECT_FLOAT_EQ(box.max.y, 21);
    ASSERT_EQ(Q3TranslateTransform_Set(transform, &second), kQ3Success);
    TQ3Vector3D out{};
    EXPECT_EQ(Q3TranslateTransform_Get(transform, &out), kQ3Success);
    EXPECT_EQ(std::memcmp(&out, &second, sizeof out), 0);
    box = bounds();
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_FLOAT_EQ(box.min.x, -1);
    EXPECT_FLOAT_EQ(box.min.y, 0);
    EXPECT_FLOAT_EQ(box.min.z, 5);
    EXPECT_FLOAT_EQ(box.max.x, 2);
    EXPECT_FLOAT_EQ(box.max.y, 1);
    EXPECT_FLOAT_EQ(box.max.z, 5);
    Q3Object_Dispose(transform);
}

TEST_F(TransformApiTest, TransformSubmitAppliesAnyKindAndChecksItsArguments)
{
    TQ3RationalPoint4D points[2] = {{0, 0, 0, 1}, {3, 1, 0, 1}};
    float knots[4] = {0, 0, 1, 1};
    const TQ3NURBCurveData curve = {2, 2, points, knots, nullptr};
    const TQ3Vector3D move{10, 20, 30}, grow{2, 2, 2};
    TQ3TransformObject translate = Q3TranslateTransform_New(&move);
    TQ3TransformObject scale = Q3ScaleTransform_New(&grow);
    TQ3BoundingBox box{};
    ASSERT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
    do {
        EXPECT_EQ(Q3Transform_Submit(translate, view()), kQ3Success);
        EXPECT_EQ(Q3Transform_Submit(scale, view()), kQ3Success);
        Q3NURBCurve_Submit(&curve, view());
    } while (Q3View_EndBoundingBox(view(), &box) == kQ3ViewStatusRetraverse);
    // Row vectors: the later transform applies to the geometry first.
    EXPECT_FLOAT_EQ(box.min.x, 10);
    EXPECT_FLOAT_EQ(box.min.y, 20);
    EXPECT_FLOAT_EQ(box.max.x, 16);
    EXPECT_FLOAT_EQ(box.max.y, 22);
    EXPECT_FLOAT_EQ(box.max.z, 30);

    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Transform_Submit(translate, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Transform_Submit(nullptr, view()), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Transform_Submit(translate, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Transform_Submit(view(), view()), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Transform_Submit(translate, scale), kQ3Failure), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(translate);
    Q3Object_Dispose(scale);
}

TEST_F(TransformApiTest, TranslateAndScaleSetRejectNullAndNonFiniteComponentsAndChangeNothing)
{
    const TQ3Vector3D good{1, 2, 3};
    TQ3TransformObject translate = Q3TranslateTransform_New(&good);
    TQ3TransformObject scale = Q3ScaleTransform_New(&good);
    const unsigned long translateEdit = Q3Shared_GetEditIndex(translate);
    const unsigned long scaleEdit = Q3Shared_GetEditIndex(scale);
    for (float bad : kNonFinite) {
        const TQ3Vector3D vectors[] = {{bad, 1, 1}, {1, bad, 1}, {1, 1, bad}};
        for (const TQ3Vector3D& v : vectors) {
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3TranslateTransform_Set(translate, &v), kQ3Failure),
                            kQ3ErrorInvalidParameter);
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3ScaleTransform_Set(scale, &v), kQ3Failure),
                            kQ3ErrorInvalidParameter);
        }
    }
    EXPECT_Q3_ERROR(Q3TranslateTransform_Set(translate, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ScaleTransform_Set(scale, nullptr), kQ3ErrorNULLParameter);
    TQ3Vector3D out{};
    Q3TranslateTransform_Get(translate, &out);
    EXPECT_EQ(std::memcmp(&out, &good, sizeof out), 0);
    Q3ScaleTransform_Get(scale, &out);
    EXPECT_EQ(std::memcmp(&out, &good, sizeof out), 0);
    EXPECT_EQ(Q3Shared_GetEditIndex(translate), translateEdit);
    EXPECT_EQ(Q3Shared_GetEditIndex(scale), scaleEdit);
    Q3Object_Dispose(translate);
    Q3Object_Dispose(scale);
}

TEST_F(TransformApiTest, ScaleTransformSetAcceptsZeroAndNegativeFactorsAndTakesEffect)
{
    const TQ3Vector3D first{2, 2, 2}, second{0, -1, 3};
    TQ3TransformObject transform = Q3ScaleTransform_New(&first);
    q3test::expectSetThenGet(transform, Q3ScaleTransform_Set, Q3ScaleTransform_Get, second);
    TQ3Matrix4x4 expected{};
    Q3Matrix4x4_SetScale(&expected, 0, -1, 3);
    expectMatrixNear(stateAfter([&](TQ3ViewObject v) { Q3Object_Submit(transform, v); }), expected,
                     "after Set");
    Q3Object_Dispose(transform);
}

TEST_F(TransformApiTest, RotateTransformSettersReplaceDataAxisAndAngle)
{
    const TQ3RotateTransformData first{kQ3AxisX, 0.5f};
    TQ3TransformObject transform = Q3RotateTransform_New(&first);
    TQ3RotateTransformData data{};
    EXPECT_EQ(Q3RotateTransform_GetData(transform, &data), kQ3Success);
    EXPECT_EQ(data.axis, kQ3AxisX);
    EXPECT_EQ(data.radians, 0.5f);

    unsigned long edit = Q3Shared_GetEditIndex(transform);
    const TQ3RotateTransformData second{kQ3AxisY, -2.0f};
    EXPECT_EQ(Q3RotateTransform_SetData(transform, &second), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(transform), edit);
    TQ3Axis axis = kQ3AxisX;
    float radians = 0;
    EXPECT_EQ(Q3RotateTransform_GetAxis(transform, &axis), kQ3Success);
    EXPECT_EQ(Q3RotateTransform_GetAngle(transform, &radians), kQ3Success);
    EXPECT_EQ(axis, kQ3AxisY);
    EXPECT_EQ(radians, -2.0f);

    edit = Q3Shared_GetEditIndex(transform);
    EXPECT_EQ(Q3RotateTransform_SetAxis(transform, kQ3AxisZ), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(transform), edit);
    edit = Q3Shared_GetEditIndex(transform);
    EXPECT_EQ(Q3RotateTransform_SetAngle(transform, kQ3PiOver2), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(transform), edit);
    EXPECT_EQ(Q3RotateTransform_GetData(transform, &data), kQ3Success);
    EXPECT_EQ(data.axis, kQ3AxisZ);
    EXPECT_EQ(data.radians, kQ3PiOver2);

    // The view applies the new rotation: a quarter turn about z takes x to y.
    const TQ3Matrix4x4 state =
        stateAfter([&](TQ3ViewObject v) { EXPECT_EQ(Q3Object_Submit(transform, v), kQ3Success); });
    expectTakesXToY(state);
    Q3Object_Dispose(transform);
}

TEST_F(TransformApiTest, RotateTransformSettersRejectWhatNewRejectsAndChangeNothing)
{
    const TQ3RotateTransformData good{kQ3AxisY, 0.75f};
    TQ3TransformObject transform = Q3RotateTransform_New(&good);
    const unsigned long edit = Q3Shared_GetEditIndex(transform);
    for (int axis : {-1, 3, INT_MAX, INT_MIN}) {
        const TQ3RotateTransformData data = rotateWithRawAxis(axis, 1.0f);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateTransform_SetData(transform, &data), kQ3Failure),
                        kQ3ErrorInvalidData);
        // Converted, not loaded from memory, as ViewBoundsTest passes bad
        // enum arguments: what a C caller's int argument becomes.
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateTransform_SetAxis(transform, static_cast<TQ3Axis>(axis)),
                                  kQ3Failure),
                        kQ3ErrorInvalidData);
    }
    for (float bad : kNonFinite) {
        const TQ3RotateTransformData data{kQ3AxisZ, bad};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateTransform_SetData(transform, &data), kQ3Failure),
                        kQ3ErrorInvalidData);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RotateTransform_SetAngle(transform, bad), kQ3Failure),
                        kQ3ErrorInvalidData);
    }
    EXPECT_Q3_ERROR(Q3RotateTransform_SetData(transform, nullptr), kQ3ErrorNULLParameter);
    TQ3RotateTransformData out{};
    Q3RotateTransform_GetData(transform, &out);
    EXPECT_EQ(out.axis, good.axis);
    EXPECT_EQ(out.radians, good.radians);
    EXPECT_EQ(Q3Shared_GetEditIndex(transform), edit);
    Q3Object_Dispose(transform);
}

TEST_F(TransformApiTest, SettingADuplicateLeavesTheOriginalAlone)
{
    const TQ3Vector3D first{1, 2, 3}, second{4, 5, 6};
    TQ3TransformObject original = Q3TranslateTransform_New(&first);
    TQ3TransformObject copy = Q3Object_Duplicate(original);
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(Q3TranslateTransform_Set(copy, &second), kQ3Success);
    TQ3Vector3D out{};
    Q3TranslateTransform_Get(original, &out);
    EXPECT_EQ(std::memcmp(&out, &first, sizeof out), 0);
    Q3TranslateTransform_Get(copy, &out);
    EXPECT_EQ(std::memcmp(&out, &second, sizeof out), 0);
    Q3Object_Dispose(copy);
    Q3Object_Dispose(original);
}

TEST_F(TransformApiTest, AccessorsRejectBadHandlesWrongKindsAndNullPointers)
{
    const TQ3Matrix4x4 m = translation(1, 2, 3);
    const TQ3Vector3D v{1, 2, 3};
    const TQ3RotateTransformData r{kQ3AxisX, 1.0f};
    TQ3TransformObject matrix = Q3MatrixTransform_New(&m);
    TQ3TransformObject translate = Q3TranslateTransform_New(&v);
    TQ3TransformObject scale = Q3ScaleTransform_New(&v);
    TQ3TransformObject rotate = Q3RotateTransform_New(&r);
    TQ3TransformObject reset = Q3ResetTransform_New();
    TQ3TransformObject dead = Q3TranslateTransform_New(&v);
    Q3Object_Dispose(dead);
    TQ3Matrix4x4 mOut = m;
    TQ3Vector3D vOut = v;
    TQ3RotateTransformData rOut = r;
    TQ3Axis axisOut = kQ3AxisX;
    float angleOut = 1.0f;
    struct Call {
        const char* name;
        TQ3TransformObject right; // a transform the call accepts
        TQ3Object wrong;          // a live object of another kind
        bool takesPointer;        // run(_, false) passes a NULL pointer
        std::function<TQ3Status(TQ3Object, bool)> run;
    };
    const std::vector<Call> calls = {
        {"MatrixTransform_Set", matrix, translate, true,
         [&](TQ3Object t, bool p) { return Q3MatrixTransform_Set(t, p ? &m : nullptr); }},
        {"MatrixTransform_Get", matrix, reset, true,
         [&](TQ3Object t, bool p) { return Q3MatrixTransform_Get(t, p ? &mOut : nullptr); }},
        {"TranslateTransform_Set", translate, scale, true,
         [&](TQ3Object t, bool p) { return Q3TranslateTransform_Set(t, p ? &v : nullptr); }},
        {"TranslateTransform_Get", translate, matrix, true,
         [&](TQ3Object t, bool p) { return Q3TranslateTransform_Get(t, p ? &vOut : nullptr); }},
        {"ScaleTransform_Set", scale, translate, true,
         [&](TQ3Object t, bool p) { return Q3ScaleTransform_Set(t, p ? &v : nullptr); }},
        {"ScaleTransform_Get", scale, rotate, true,
         [&](TQ3Object t, bool p) { return Q3ScaleTransform_Get(t, p ? &vOut : nullptr); }},
        {"RotateTransform_SetData", rotate, matrix, true,
         [&](TQ3Object t, bool p) { return Q3RotateTransform_SetData(t, p ? &r : nullptr); }},
        {"RotateTransform_GetData", rotate, scale, true,
         [&](TQ3Object t, bool p) { return Q3RotateTransform_GetData(t, p ? &rOut : nullptr); }},
        {"RotateTransform_SetAxis", rotate, translate, false,
         [&](TQ3Object t, bool) { return Q3RotateTransform_SetAxis(t, kQ3AxisX); }},
        {"RotateTransform_GetAxis", rotate, reset, true,
         [&](TQ3Object t, bool p) { return Q3RotateTransform_GetAxis(t, p ? &axisOut : nullptr); }},
        {"RotateTransform_SetAngle", rotate, matrix, false,
         [&](TQ3Object t, bool) { return Q3RotateTransform_SetAngle(t, 1.0f); }},
        {"RotateTransform_GetAngle", rotate, view(), true,
         [&](TQ3Object t, bool p) { return Q3RotateTransform_GetAngle(t, p ? &angleOut : nullptr); }},
    };
    for (const Call& call : calls) {
        SCOPED_TRACE(call.name);
        EXPECT_Q3_ERROR(EXPECT_EQ(call.run(nullptr, true), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(call.run(dead, true), kQ3Failure), kQ3ErrorInvalidObject);
        EXPECT_Q3_ERROR(EXPECT_EQ(call.run(call.wrong, true), kQ3Failure), kQ3ErrorInvalidObjectType);
        if (call.takesPointer)
            EXPECT_Q3_ERROR(EXPECT_EQ(call.run(call.right, false), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_EQ(call.run(call.right, true), kQ3Success);
    }
    // Failed Gets left their outputs alone; the successful ones read back what was set.
    EXPECT_EQ(std::memcmp(&mOut, &m, sizeof m), 0);
    EXPECT_EQ(std::memcmp(&vOut, &v, sizeof v), 0);
    EXPECT_EQ(axisOut, kQ3AxisX);
    EXPECT_EQ(angleOut, 1.0f);

    TQ3Matrix4x4 untouched = m;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Transform_GetMatrix(nullptr, &untouched), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Transform_GetMatrix(dead, &untouched), nullptr), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Transform_GetMatrix(view(), &untouched), nullptr),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Transform_GetMatrix(reset, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_EQ(std::memcmp(&untouched, &m, sizeof m), 0);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Transform_GetType(nullptr), kQ3ObjectTypeInvalid), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Transform_GetType(dead), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Transform_GetType(view()), kQ3ObjectTypeInvalid),
                    kQ3ErrorInvalidObjectType);
    for (TQ3Object t : {matrix, translate, scale, rotate, reset})
        Q3Object_Dispose(t);
}

} // namespace
