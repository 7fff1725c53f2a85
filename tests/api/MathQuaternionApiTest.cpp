// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DMath.h's quaternion calls, Q3Matrix4x4_SetQuaternion and the two
// TransformQuaternion calls. Expected values come from Hamilton's product
// and the half-angle formula written out here, and every quaternion
// rotation is checked against the matrix call for the same rotation.

#include "MathTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DMath.h"

#include <cfloat>
#include <cmath>

namespace {

using namespace q3test;
using MathQuaternionApiTest = Q3ApiTest;

// Products and sums of a few unit-sized floats, and sines rounded to float.
constexpr float kTolerance = 2e-6f;

// Hamilton's product a * b, written out.
TQ3Quaternion hamilton(const TQ3Quaternion& a, const TQ3Quaternion& b)
{
    return TQ3Quaternion{a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                         a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

// cos(a/2) + sin(a/2) * unit axis.
TQ3Quaternion halfAngle(double x, double y, double z, double angle)
{
    const double n = std::sqrt(x * x + y * y + z * z);
    const double s = std::sin(angle / 2) / n;
    return TQ3Quaternion{float(std::cos(angle / 2)), float(x * s), float(y * s), float(z * s)};
}

void expectQuaternionNear(const TQ3Quaternion& actual, const TQ3Quaternion& expected, float tolerance = kTolerance)
{
    EXPECT_NEAR(actual.w, expected.w, tolerance);
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// The same rotation: q or -q.
void expectSameRotation(const TQ3Quaternion& actual, const TQ3Quaternion& expected)
{
    const float sign = actual.w * expected.w + actual.x * expected.x + actual.y * expected.y +
                                   actual.z * expected.z <
                               0
                           ? -1.0f
                           : 1.0f;
    expectQuaternionNear(actual, TQ3Quaternion{sign * expected.w, sign * expected.x, sign * expected.y,
                                               sign * expected.z});
}

TQ3Matrix4x4 matrixOf(const TQ3Quaternion& q)
{
    TQ3Matrix4x4 m{};
    EXPECT_EQ(Q3Matrix4x4_SetQuaternion(&m, &q), &m);
    return m;
}

float lengthOf(const TQ3Quaternion& q)
{
    return float(std::sqrt(double(q.w) * q.w + double(q.x) * q.x + double(q.y) * q.y + double(q.z) * q.z));
}

const TQ3Quaternion kGeneral = halfAngle(1, -2, 0.5, 1.3);

// ---- Setting, copying, testing ------------------------------------------------------

TEST_F(MathQuaternionApiTest, SetSetIdentityAndCopyStoreTheirValues)
{
    TQ3Quaternion q{};
    EXPECT_EQ(Q3Quaternion_Set(&q, 0.5f, -1, kNaN, kInf), &q);
    EXPECT_EQ(q.w, 0.5f);
    EXPECT_EQ(q.x, -1.0f);
    EXPECT_TRUE(std::isnan(q.y));
    EXPECT_EQ(q.z, kInf);
    TQ3Quaternion copy = filledWith<TQ3Quaternion>(7);
    EXPECT_EQ(Q3Quaternion_Copy(&q, &copy), &copy);
    EXPECT_TRUE(sameBits(copy, q));
    EXPECT_EQ(Q3Quaternion_Copy(&copy, &copy), &copy);
    EXPECT_TRUE(sameBits(copy, q));
    EXPECT_EQ(Q3Quaternion_SetIdentity(&q), &q);
    EXPECT_TRUE(sameBits(q, TQ3Quaternion{1, 0, 0, 0}));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_Set(nullptr, 1, 0, 0, 0), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetIdentity(nullptr), nullptr), kQ3ErrorNULLParameter);
    expectEachNullRejected("Q3Quaternion_Copy", Q3Quaternion_Copy, &q, &q);
}

TEST_F(MathQuaternionApiTest, IsIdentityTestsXYZWithinRealZeroAndIgnoresW)
{
    struct Case {
        TQ3Quaternion q;
        TQ3Boolean identity;
    };
    for (const Case& c : {Case{{1, 0, 0, 0}, kQ3True}, Case{{-1, 0, 0, 0}, kQ3True}, Case{{0.5f, 0, 0, 0}, kQ3True},
                          Case{{1, FLT_EPSILON, -FLT_EPSILON, 0}, kQ3True}, Case{{kNaN, 0, 0, 0}, kQ3True},
                          Case{{1, 2 * FLT_EPSILON, 0, 0}, kQ3False}, Case{{1, 0, 0, -1e-6f}, kQ3False},
                          Case{{1, 0, kNaN, 0}, kQ3False}, Case{{1, kInf, 0, 0}, kQ3False}}) {
        EXPECT_EQ(Q3Quaternion_IsIdentity(&c.q), c.identity) << c.q.w << " " << c.q.x << " " << c.q.y << " " << c.q.z;
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_IsIdentity(nullptr), kQ3False), kQ3ErrorNULLParameter);
}

// ---- Invert, normalize, dot, multiply ------------------------------------------------------

TEST_F(MathQuaternionApiTest, InvertIsTheConjugateOverTheSquaredLength)
{
    TQ3Quaternion r{};
    EXPECT_EQ(Q3Quaternion_Invert(&kGeneral, &r), &r); // unit: the conjugate
    expectQuaternionNear(r, TQ3Quaternion{kGeneral.w, -kGeneral.x, -kGeneral.y, -kGeneral.z});
    TQ3Quaternion q{1, 1, 1, 1}; // |q|^2 = 4
    EXPECT_EQ(Q3Quaternion_Invert(&q, &q), &q);
    EXPECT_TRUE(sameBits(q, TQ3Quaternion{0.25f, -0.25f, -0.25f, -0.25f}));
    const TQ3Quaternion a{2, -1, 0.5f, 3};
    TQ3Quaternion inverse{};
    Q3Quaternion_Invert(&a, &inverse);
    expectQuaternionNear(hamilton(a, inverse), TQ3Quaternion{1, 0, 0, 0});
}

TEST_F(MathQuaternionApiTest, NormalizeScalesToUnitLengthWithoutOverflow)
{
    TQ3Quaternion q{1, 1, 1, 1};
    EXPECT_EQ(Q3Quaternion_Normalize(&q, &q), &q);
    EXPECT_TRUE(sameBits(q, TQ3Quaternion{0.5f, 0.5f, 0.5f, 0.5f}));
    const TQ3Quaternion huge{3e38f, 0, -3e38f, 0}, tiny{0, 1e-40f, 0, 0};
    TQ3Quaternion r{};
    ASSERT_EQ(Q3Quaternion_Normalize(&huge, &r), &r);
    EXPECT_FLOAT_EQ(r.w, float(1 / std::sqrt(2.0)));
    EXPECT_FLOAT_EQ(r.y, float(-1 / std::sqrt(2.0)));
    ASSERT_EQ(Q3Quaternion_Normalize(&tiny, &r), &r);
    EXPECT_EQ(r.x, 1.0f);
}

TEST_F(MathQuaternionApiTest, InvertAndNormalizeRejectTheZeroQuaternionAndNull)
{
    const TQ3Quaternion zero{0, -0.0f, 0, 0};
    TQ3Quaternion r = filledWith<TQ3Quaternion>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_Invert(&zero, &r), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_Normalize(&zero, &r), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_TRUE(sameBits(r, filledWith<TQ3Quaternion>(7)));
    expectEachNullRejected("Q3Quaternion_Invert", Q3Quaternion_Invert, &kGeneral, &r);
    expectEachNullRejected("Q3Quaternion_Normalize", Q3Quaternion_Normalize, &kGeneral, &r);
}

TEST_F(MathQuaternionApiTest, InvertAndNormalizePropagateNonFiniteComponents)
{
    const TQ3Quaternion nan{kNaN, 0, 0, 0}, inf{kInf, 1, 0, 0};
    TQ3Quaternion r{};
    EXPECT_EQ(Q3Quaternion_Normalize(&nan, &r), &r);
    EXPECT_TRUE(std::isnan(r.w));
    EXPECT_EQ(Q3Quaternion_Normalize(&inf, &r), &r); // inf / inf
    EXPECT_TRUE(std::isnan(r.w));
    EXPECT_EQ(r.x, 0.0f);
    EXPECT_EQ(Q3Quaternion_Invert(&nan, &r), &r);
    EXPECT_TRUE(std::isnan(r.w));
}

TEST_F(MathQuaternionApiTest, DotIsTheFourVectorDotProduct)
{
    const TQ3Quaternion a{1, 2, 3, 4}, b{-1, 0.5f, 2, -0.25f}, nan{kNaN, 0, 0, 0};
    EXPECT_EQ(Q3Quaternion_Dot(&a, &b), -1.0f + 1 + 6 - 1);
    EXPECT_TRUE(std::isnan(Q3Quaternion_Dot(&a, &nan)));
    expectEachNullRejected("Q3Quaternion_Dot", Q3Quaternion_Dot, &a, &a);
}

TEST_F(MathQuaternionApiTest, MultiplyAppliesTheFirstRotationFirst)
{
    // Small integers: every product is exact. Multiply(q1, q2) is q2 * q1.
    const TQ3Quaternion q1{1, 2, -1, 3}, q2{2, 0, 1, -1};
    TQ3Quaternion r{};
    EXPECT_EQ(Q3Quaternion_Multiply(&q1, &q2, &r), &r);
    EXPECT_TRUE(sameBits(r, hamilton(q2, q1)));
    const TQ3Quaternion i{0, 1, 0, 0}, j{0, 0, 1, 0};
    Q3Quaternion_Multiply(&i, &j, &r); // j * i = -k
    EXPECT_TRUE(sameBits(r, TQ3Quaternion{0, 0, 0, -1}));
    // As matrices: the matrix of the product is the product of the matrices.
    const TQ3Quaternion a = halfAngle(0, 0, 1, 0.8), b = halfAngle(1, 1, 0, -2.1);
    TQ3Quaternion ab{};
    Q3Quaternion_Multiply(&a, &b, &ab);
    TQ3Matrix4x4 ma = matrixOf(a), mb = matrixOf(b), product{};
    Q3Matrix4x4_Multiply(&ma, &mb, &product);
    expectMatrixNear(matrixOf(ab), product, kTolerance, "SetQuaternion(a then b)");
}

TEST_F(MathQuaternionApiTest, MultiplyAllowsTheResultToBeEitherFactor)
{
    const TQ3Quaternion q1{1, 2, -1, 3}, q2{2, 0, 1, -1};
    TQ3Quaternion left = q1, right = q2, square = q1;
    EXPECT_EQ(Q3Quaternion_Multiply(&left, &q2, &left), &left);
    EXPECT_TRUE(sameBits(left, hamilton(q2, q1)));
    EXPECT_EQ(Q3Quaternion_Multiply(&q1, &right, &right), &right);
    EXPECT_TRUE(sameBits(right, hamilton(q2, q1)));
    EXPECT_EQ(Q3Quaternion_Multiply(&square, &square, &square), &square);
    EXPECT_TRUE(sameBits(square, hamilton(q1, q1)));
    const TQ3Quaternion nan{kNaN, 0, 0, 0};
    TQ3Quaternion r{};
    Q3Quaternion_Multiply(&nan, &q1, &r);
    EXPECT_TRUE(std::isnan(r.w));
    expectEachNullRejected("Q3Quaternion_Multiply", Q3Quaternion_Multiply, &q1, &q1, &r);
}

// ---- Rotations ---------------------------------------------------------------------------------

TEST_F(MathQuaternionApiTest, SingleAxisRotationsAreTheHalfAngleQuaternionsOfTheMatrixRotations)
{
    const float a = 1.1f;
    TQ3Quaternion q{};
    TQ3Matrix4x4 m{};
    EXPECT_EQ(Q3Quaternion_SetRotate_X(&q, a), &q);
    expectQuaternionNear(q, TQ3Quaternion{float(std::cos(a / 2.0)), float(std::sin(a / 2.0)), 0, 0});
    Q3Matrix4x4_SetRotate_X(&m, a);
    expectMatrixNear(matrixOf(q), m, kTolerance, "X");
    EXPECT_EQ(Q3Quaternion_SetRotate_Y(&q, a), &q);
    expectQuaternionNear(q, TQ3Quaternion{float(std::cos(a / 2.0)), 0, float(std::sin(a / 2.0)), 0});
    Q3Matrix4x4_SetRotate_Y(&m, a);
    expectMatrixNear(matrixOf(q), m, kTolerance, "Y");
    EXPECT_EQ(Q3Quaternion_SetRotate_Z(&q, a), &q);
    expectQuaternionNear(q, TQ3Quaternion{float(std::cos(a / 2.0)), 0, 0, float(std::sin(a / 2.0))});
    Q3Matrix4x4_SetRotate_Z(&m, a);
    expectMatrixNear(matrixOf(q), m, kTolerance, "Z");
}

TEST_F(MathQuaternionApiTest, SetRotateXYZComposesXThenYThenZ)
{
    const float x = 0.3f, y = -1.1f, z = 2.5f;
    TQ3Quaternion q{};
    EXPECT_EQ(Q3Quaternion_SetRotate_XYZ(&q, x, y, z), &q);
    TQ3Matrix4x4 m{};
    Q3Matrix4x4_SetRotate_XYZ(&m, x, y, z);
    expectMatrixNear(matrixOf(q), m, kTolerance, "XYZ");
    const TQ3Quaternion qx = halfAngle(1, 0, 0, x), qy = halfAngle(0, 1, 0, y), qz = halfAngle(0, 0, 1, z);
    expectQuaternionNear(q, hamilton(qz, hamilton(qy, qx)));
    EXPECT_NEAR(lengthOf(q), 1.0f, kTolerance);
}

TEST_F(MathQuaternionApiTest, SetRotateAboutAxisMatchesTheMatrixAndNormalizesTheAxis)
{
    const TQ3Vector3D axis{2, -4, 4}; // length 6
    TQ3Quaternion q{};
    EXPECT_EQ(Q3Quaternion_SetRotateAboutAxis(&q, &axis, 0.9f), &q);
    expectQuaternionNear(q, halfAngle(2, -4, 4, 0.9f));
    const TQ3Point3D origin{0, 0, 0};
    TQ3Matrix4x4 m{};
    Q3Matrix4x4_SetRotateAboutAxis(&m, &origin, &axis, 0.9f);
    expectMatrixNear(matrixOf(q), m, kTolerance, "about axis");
    const TQ3Vector3D zero{0, 0, 0};
    TQ3Quaternion r = filledWith<TQ3Quaternion>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetRotateAboutAxis(&r, &zero, 1), nullptr), kQ3ErrorVector3DZeroLength);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetRotateAboutAxis(&r, nullptr, 1), nullptr), kQ3ErrorNULLParameter);
    EXPECT_TRUE(sameBits(r, filledWith<TQ3Quaternion>(7)));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetRotateAboutAxis(nullptr, &axis, 1), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(MathQuaternionApiTest, SetRotateVectorToVectorMatchesTheMatrixEvenForOppositeDirections)
{
    const TQ3Vector3D v1{1, 2, 2}, v2{-3, 0, 4}, opposite{-2, -4, -4}, same{0.5f, 1, 1};
    for (const TQ3Vector3D* to : {&v2, &opposite, &same}) {
        TQ3Quaternion q{};
        TQ3Matrix4x4 m{};
        EXPECT_EQ(Q3Quaternion_SetRotateVectorToVector(&q, &v1, to), &q);
        Q3Matrix4x4_SetRotateVectorToVector(&m, &v1, to);
        expectMatrixNear(matrixOf(q), m, kTolerance, "vector to vector");
        EXPECT_NEAR(lengthOf(q), 1.0f, kTolerance);
        TQ3Vector3D turned{};
        Q3Vector3D_TransformQuaternion(&v1, &q, &turned);
        const float scale = 3.0f / std::sqrt(to->x * to->x + to->y * to->y + to->z * to->z);
        EXPECT_NEAR(turned.x, to->x * scale, 1e-5f);
        EXPECT_NEAR(turned.y, to->y * scale, 1e-5f);
        EXPECT_NEAR(turned.z, to->z * scale, 1e-5f);
    }
    const TQ3Vector3D zero{0, 0, 0};
    TQ3Quaternion r = filledWith<TQ3Quaternion>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetRotateVectorToVector(&r, &zero, &v1), nullptr),
                    kQ3ErrorVector3DZeroLength);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetRotateVectorToVector(&r, &v1, &zero), nullptr),
                    kQ3ErrorVector3DZeroLength);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetRotateVectorToVector(nullptr, &v1, &v2), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetRotateVectorToVector(&r, nullptr, &v2), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetRotateVectorToVector(&r, &v1, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_TRUE(sameBits(r, filledWith<TQ3Quaternion>(7)));
}

TEST_F(MathQuaternionApiTest, RotationSettersPropagateNonFiniteAngles)
{
    TQ3Quaternion q{};
    EXPECT_EQ(Q3Quaternion_SetRotate_X(&q, kNaN), &q);
    EXPECT_TRUE(std::isnan(q.w) && std::isnan(q.x));
    EXPECT_EQ(Q3Quaternion_SetRotate_XYZ(&q, 0, kInf, 0), &q);
    EXPECT_TRUE(std::isnan(q.w));
    const TQ3Vector3D nanAxis{kNaN, 0, 0};
    EXPECT_EQ(Q3Quaternion_SetRotateAboutAxis(&q, &nanAxis, 1), &q); // NaN is not a zero length
    EXPECT_TRUE(std::isnan(q.x));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetRotate_X(nullptr, 1), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetRotate_Y(nullptr, 1), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetRotate_Z(nullptr, 1), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetRotate_XYZ(nullptr, 1, 2, 3), nullptr), kQ3ErrorNULLParameter);
}

// ---- Quaternions and matrices --------------------------------------------------------------------

TEST_F(MathQuaternionApiTest, SetQuaternionWritesTheRotationMatrixOfAnyNonzeroMultiple)
{
    // The row-vector rotation matrix of a unit (w, x, y, z), written out.
    const TQ3Quaternion q = kGeneral;
    const double w = q.w, x = q.x, y = q.y, z = q.z;
    const TQ3Matrix4x4 expected = matrix4x4Of(
        {float(1 - 2 * (y * y + z * z)), float(2 * (x * y + w * z)), float(2 * (x * z - w * y)), 0,
         float(2 * (x * y - w * z)), float(1 - 2 * (x * x + z * z)), float(2 * (y * z + w * x)), 0,
         float(2 * (x * z + w * y)), float(2 * (y * z - w * x)), float(1 - 2 * (x * x + y * y)), 0, 0, 0, 0, 1});
    TQ3Matrix4x4 m = filledWith<TQ3Matrix4x4>(7);
    EXPECT_EQ(Q3Matrix4x4_SetQuaternion(&m, &q), &m);
    expectMatrixNear(m, expected, kTolerance, "SetQuaternion");
    const TQ3Quaternion scaled{-3 * q.w, -3 * q.x, -3 * q.y, -3 * q.z};
    expectMatrixNear(matrixOf(scaled), expected, kTolerance, "SetQuaternion(-3 q)");
}

TEST_F(MathQuaternionApiTest, SetQuaternionRejectsTheZeroQuaternionAndNull)
{
    const TQ3Quaternion zero{0, 0, 0, 0};
    TQ3Matrix4x4 m = filledWith<TQ3Matrix4x4>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetQuaternion(&m, &zero), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetQuaternion(&m, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_TRUE(sameBits(m, filledWith<TQ3Matrix4x4>(7)));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetQuaternion(nullptr, &kGeneral), nullptr), kQ3ErrorNULLParameter);
    const TQ3Quaternion nan{kNaN, 0, 0, 0};
    EXPECT_EQ(Q3Matrix4x4_SetQuaternion(&m, &nan), &m);
    EXPECT_TRUE(std::isnan(m.value[0][0]));
}

TEST_F(MathQuaternionApiTest, SetMatrixInvertsSetQuaternionInEveryBranch)
{
    // A general rotation, and half turns about x, y and z, which make x, y
    // and z the largest component in turn.
    for (const TQ3Quaternion& q :
         {kGeneral, halfAngle(1, 0, 0, kPi), halfAngle(0, 1, 0, kPi), halfAngle(0, 0, 1, kPi), halfAngle(1, 1, 1, 3.0),
          TQ3Quaternion{1, 0, 0, 0}}) {
        TQ3Matrix4x4 m = matrixOf(q);
        m.value[3][0] = 5; // translation is ignored
        m.value[3][1] = -7;
        TQ3Quaternion back = filledWith<TQ3Quaternion>(7);
        EXPECT_EQ(Q3Quaternion_SetMatrix(&back, &m), &back);
        expectSameRotation(back, q);
        EXPECT_NEAR(lengthOf(back), 1.0f, kTolerance);
    }
}

TEST_F(MathQuaternionApiTest, SetMatrixReadsTheMatrixRotationsBack)
{
    TQ3Matrix4x4 m{};
    Q3Matrix4x4_SetRotate_Y(&m, 0.75f);
    TQ3Quaternion q{};
    Q3Quaternion_SetMatrix(&q, &m);
    expectSameRotation(q, halfAngle(0, 1, 0, 0.75f));
    TQ3Matrix4x4 nan = kIdentity4x4;
    nan.value[1][2] = kNaN;
    EXPECT_EQ(Q3Quaternion_SetMatrix(&q, &nan), &q);
    EXPECT_TRUE(std::isnan(q.x));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetMatrix(nullptr, &m), nullptr), kQ3ErrorNULLParameter);
    TQ3Quaternion r = filledWith<TQ3Quaternion>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_SetMatrix(&r, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_TRUE(sameBits(r, filledWith<TQ3Quaternion>(7)));
}

// ---- Reflection and interpolation ------------------------------------------------------------------

TEST_F(MathQuaternionApiTest, MatchReflectionPicksTheSignOnQ2sSide)
{
    const TQ3Quaternion q1{0.5f, 0.5f, -0.5f, 0.5f}, near{1, 0, 0, 0}, far{-1, 0, 0, 0}, square{0, 0, 0, 1};
    TQ3Quaternion r{};
    EXPECT_EQ(Q3Quaternion_MatchReflection(&q1, &near, &r), &r);
    EXPECT_TRUE(sameBits(r, q1));
    EXPECT_EQ(Q3Quaternion_MatchReflection(&q1, &far, &r), &r);
    EXPECT_TRUE(sameBits(r, TQ3Quaternion{-0.5f, -0.5f, 0.5f, -0.5f}));
    const TQ3Quaternion perpendicular{0, 1, 0, 0};
    EXPECT_EQ(Q3Quaternion_MatchReflection(&perpendicular, &square, &r), &r); // dot 0: -q1
    EXPECT_TRUE(sameBits(r, TQ3Quaternion{-0.0f, -1, -0.0f, -0.0f}));
    TQ3Quaternion inPlace = q1;
    EXPECT_EQ(Q3Quaternion_MatchReflection(&inPlace, &far, &inPlace), &inPlace);
    EXPECT_EQ(inPlace.w, -0.5f);
    const TQ3Quaternion nan{kNaN, 0, 0, 0};
    Q3Quaternion_MatchReflection(&q1, &nan, &r);
    EXPECT_EQ(r.w, -0.5f);
    expectEachNullRejected("Q3Quaternion_MatchReflection", Q3Quaternion_MatchReflection, &q1, &q1, &r);
}

TEST_F(MathQuaternionApiTest, InterpolateFastIsTheNormalizedStraightLine)
{
    const TQ3Quaternion q1 = halfAngle(0, 0, 1, 0), q2 = halfAngle(0, 0, 1, 2.0);
    TQ3Quaternion r{};
    EXPECT_EQ(Q3Quaternion_InterpolateFast(&q1, &q2, 0, &r), &r);
    expectQuaternionNear(r, q1);
    EXPECT_EQ(Q3Quaternion_InterpolateFast(&q1, &q2, 1, &r), &r);
    expectQuaternionNear(r, q2);
    // Halfway along the chord of an arc is halfway along the arc.
    EXPECT_EQ(Q3Quaternion_InterpolateFast(&q1, &q2, 0.5f, &r), &r);
    expectQuaternionNear(r, halfAngle(0, 0, 1, 1.0));
    // At t = 0.25: (0.75 q1 + 0.25 q2) / length, written out.
    const double w = 0.75 * q1.w + 0.25 * q2.w, z = 0.75 * q1.z + 0.25 * q2.z;
    const double n = std::sqrt(w * w + z * z);
    TQ3Quaternion quarter = q1;
    EXPECT_EQ(Q3Quaternion_InterpolateFast(&quarter, &q2, 0.25f, &quarter), &quarter); // result is q1
    expectQuaternionNear(quarter, TQ3Quaternion{float(w / n), 0, 0, float(z / n)});
    // No sign is changed: towards -q1 the line passes through 0.
    const TQ3Quaternion minus{-q1.w, -q1.x, -q1.y, -q1.z};
    r = filledWith<TQ3Quaternion>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_InterpolateFast(&q1, &minus, 0.5f, &r), nullptr),
                    kQ3ErrorInvalidParameter);
    EXPECT_TRUE(sameBits(r, filledWith<TQ3Quaternion>(7)));
}

TEST_F(MathQuaternionApiTest, InterpolateLinearTurnsAtConstantSpeed)
{
    // From no rotation to 2 radians about z: t turns 2t radians, and t
    // outside [0, 1] extrapolates.
    const TQ3Quaternion q1{1, 0, 0, 0}, q2 = halfAngle(0, 0, 1, 2.0);
    TQ3Quaternion r{};
    EXPECT_EQ(Q3Quaternion_InterpolateLinear(&q1, &q2, 0, &r), &r);
    EXPECT_TRUE(sameBits(r, q1));
    EXPECT_EQ(Q3Quaternion_InterpolateLinear(&q1, &q2, 1, &r), &r);
    EXPECT_TRUE(sameBits(r, q2));
    for (float t : {0.1f, 0.25f, 0.5f, 0.9f, 2.0f, -0.5f}) {
        EXPECT_EQ(Q3Quaternion_InterpolateLinear(&q1, &q2, t, &r), &r);
        expectQuaternionNear(r, halfAngle(0, 0, 1, 2.0 * t));
    }
    // Between two general rotations the angle from q1 grows linearly.
    const TQ3Quaternion a = halfAngle(1, 2, 3, 0.4), b = halfAngle(-1, 0, 2, 1.9);
    const double full = std::acos(double(a.w) * b.w + double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z);
    TQ3Quaternion mid = b;
    EXPECT_EQ(Q3Quaternion_InterpolateLinear(&a, &mid, 0.3f, &mid), &mid); // result is q2
    const double part =
        std::acos(double(a.w) * mid.w + double(a.x) * mid.x + double(a.y) * mid.y + double(a.z) * mid.z);
    EXPECT_NEAR(part, 0.3 * full, 1e-5);
    EXPECT_NEAR(lengthOf(mid), 1.0f, kTolerance);
}

TEST_F(MathQuaternionApiTest, InterpolateLinearHandlesNearlyEqualOppositeAndDegenerateQuaternions)
{
    const TQ3Quaternion q{0.5f, 0.5f, 0.5f, 0.5f};
    TQ3Quaternion r{};
    EXPECT_EQ(Q3Quaternion_InterpolateLinear(&q, &q, 0.3f, &r), &r); // equal: the straight line
    expectQuaternionNear(r, q);
    // Opposite: through (-x, w, -z, y), reaching -q at t = 1.
    const TQ3Quaternion minus{-0.5f, -0.5f, -0.5f, -0.5f};
    EXPECT_EQ(Q3Quaternion_InterpolateLinear(&q, &minus, 0.5f, &r), &r);
    expectQuaternionNear(r, TQ3Quaternion{-0.5f, 0.5f, -0.5f, 0.5f});
    EXPECT_EQ(Q3Quaternion_InterpolateLinear(&q, &minus, 1, &r), &r);
    expectQuaternionNear(r, minus);
    // A zero quaternion or a NaN: the straight line, no error.
    const TQ3Quaternion zero{0, 0, 0, 0}, nan{kNaN, 0, 0, 0};
    EXPECT_EQ(Q3Quaternion_InterpolateLinear(&zero, &q, 0.5f, &r), &r);
    expectQuaternionNear(r, TQ3Quaternion{0.25f, 0.25f, 0.25f, 0.25f});
    EXPECT_EQ(Q3Quaternion_InterpolateLinear(&nan, &q, 0.5f, &r), &r);
    EXPECT_TRUE(std::isnan(r.w));
    EXPECT_EQ(Q3Quaternion_InterpolateLinear(&q, &q, kNaN, &r), &r);
    EXPECT_TRUE(std::isnan(r.x));
}

TEST_F(MathQuaternionApiTest, InterpolationsRejectNull)
{
    const TQ3Quaternion q{1, 0, 0, 0};
    TQ3Quaternion r = filledWith<TQ3Quaternion>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_InterpolateFast(nullptr, &q, 0.5f, &r), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_InterpolateFast(&q, nullptr, 0.5f, &r), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_InterpolateFast(&q, &q, 0.5f, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_InterpolateLinear(nullptr, &q, 0.5f, &r), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_InterpolateLinear(&q, nullptr, 0.5f, &r), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Quaternion_InterpolateLinear(&q, &q, 0.5f, nullptr), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_TRUE(sameBits(r, filledWith<TQ3Quaternion>(7)));
}

// ---- Transforming by a quaternion ----------------------------------------------------------------------

TEST_F(MathQuaternionApiTest, TransformQuaternionRotatesAsTheMatrixDoes)
{
    const TQ3Quaternion quarterZ = halfAngle(0, 0, 1, kPi / 2);
    TQ3Vector3D v{1, 0, 0};
    EXPECT_EQ(Q3Vector3D_TransformQuaternion(&v, &quarterZ, &v), &v); // in place
    EXPECT_NEAR(v.x, 0.0f, kTolerance);
    EXPECT_NEAR(v.y, 1.0f, kTolerance);
    EXPECT_NEAR(v.z, 0.0f, kTolerance);
    const TQ3Point3D p{1.5f, -2, 0.25f};
    const TQ3Matrix4x4 m = matrixOf(kGeneral);
    TQ3Point3D byQuaternion{}, byMatrix{};
    EXPECT_EQ(Q3Point3D_TransformQuaternion(&p, &kGeneral, &byQuaternion), &byQuaternion);
    Q3Point3D_Transform(&p, &m, &byMatrix);
    EXPECT_NEAR(byQuaternion.x, byMatrix.x, 1e-5f);
    EXPECT_NEAR(byQuaternion.y, byMatrix.y, 1e-5f);
    EXPECT_NEAR(byQuaternion.z, byMatrix.z, 1e-5f);
    // Any nonzero multiple is the same rotation; lengths are kept.
    const TQ3Quaternion scaled{2 * kGeneral.w, 2 * kGeneral.x, 2 * kGeneral.y, 2 * kGeneral.z};
    TQ3Point3D byScaled = p;
    EXPECT_EQ(Q3Point3D_TransformQuaternion(&byScaled, &scaled, &byScaled), &byScaled);
    EXPECT_NEAR(byScaled.x, byQuaternion.x, 1e-5f);
    EXPECT_NEAR(byScaled.z, byQuaternion.z, 1e-5f);
    EXPECT_NEAR(std::sqrt(byScaled.x * byScaled.x + byScaled.y * byScaled.y + byScaled.z * byScaled.z),
                std::sqrt(1.5 * 1.5 + 4 + 0.0625), 1e-5);
}

TEST_F(MathQuaternionApiTest, TransformQuaternionRejectsTheZeroQuaternionAndNull)
{
    const TQ3Quaternion zero{0, 0, 0, 0}, q{1, 0, 0, 0};
    const TQ3Vector3D v{1, 2, 3};
    const TQ3Point3D p{1, 2, 3};
    TQ3Vector3D rv = filledWith<TQ3Vector3D>(7);
    TQ3Point3D rp = filledWith<TQ3Point3D>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Vector3D_TransformQuaternion(&v, &zero, &rv), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_TransformQuaternion(&p, &zero, &rp), nullptr), kQ3ErrorInvalidParameter);
    expectEachNullRejected("Q3Vector3D_TransformQuaternion", Q3Vector3D_TransformQuaternion, &v, &q, &rv);
    expectEachNullRejected("Q3Point3D_TransformQuaternion", Q3Point3D_TransformQuaternion, &p, &q, &rp);
    EXPECT_TRUE(sameBits(rv, filledWith<TQ3Vector3D>(7)));
    EXPECT_TRUE(sameBits(rp, filledWith<TQ3Point3D>(7)));
    const TQ3Quaternion nan{1, kNaN, 0, 0};
    EXPECT_EQ(Q3Vector3D_TransformQuaternion(&v, &nan, &rv), &rv);
    EXPECT_TRUE(std::isnan(rv.y));
}

// ---- Before Q3Initialize ----------------------------------------------------------------------------------

TEST(MathQuaternionApiUninitialized, EveryCallFailsWithNotInitializedAndChangesNothing)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    const TQ3Quaternion q{1, 0, 0, 0};
    const TQ3Vector3D v{1, 0, 0};
    TQ3Quaternion r = filledWith<TQ3Quaternion>(7);
    int calls = 0, failures = 0;
    auto check = [&](bool failedValue) {
        ++calls;
        if (failedValue && Q3Error_Get(nullptr) == kQ3ErrorNotInitialized)
            ++failures;
    };
    check(Q3Quaternion_Set(&r, 1, 0, 0, 0) == nullptr);
    check(Q3Quaternion_SetIdentity(&r) == nullptr);
    check(Q3Quaternion_Copy(&q, &r) == nullptr);
    check(Q3Quaternion_IsIdentity(&q) == kQ3False);
    check(Q3Quaternion_Invert(&q, &r) == nullptr);
    check(Q3Quaternion_Normalize(&q, &r) == nullptr);
    check(Q3Quaternion_Dot(&q, &q) == 0.0f);
    check(Q3Quaternion_Multiply(&q, &q, &r) == nullptr);
    check(Q3Quaternion_SetRotateAboutAxis(&r, &v, 1) == nullptr);
    check(Q3Quaternion_SetRotate_XYZ(&r, 1, 2, 3) == nullptr);
    check(Q3Quaternion_SetRotate_X(&r, 1) == nullptr);
    check(Q3Quaternion_SetRotate_Y(&r, 1) == nullptr);
    check(Q3Quaternion_SetRotate_Z(&r, 1) == nullptr);
    check(Q3Quaternion_SetMatrix(&r, &kIdentity4x4) == nullptr);
    check(Q3Quaternion_SetRotateVectorToVector(&r, &v, &v) == nullptr);
    check(Q3Quaternion_MatchReflection(&q, &q, &r) == nullptr);
    check(Q3Quaternion_InterpolateFast(&q, &q, 0.5f, &r) == nullptr);
    check(Q3Quaternion_InterpolateLinear(&q, &q, 0.5f, &r) == nullptr);
    EXPECT_EQ(calls, 18);
    EXPECT_EQ(failures, calls);
    EXPECT_TRUE(sameBits(r, filledWith<TQ3Quaternion>(7)));
}

} // namespace
