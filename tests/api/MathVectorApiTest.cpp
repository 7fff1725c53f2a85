// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DMath.h's vector calls that MathApiTest.cpp does not cover: 2-D
// vectors, and 3-D vector sums, scaling, negation, transforms and changes of
// dimension.

#include "MathTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DMath.h"

#include <cmath>

namespace {

using namespace q3test;
using MathVectorApiTest = Q3ApiTest;

// ---- Setting and converting --------------------------------------------------

TEST_F(MathVectorApiTest, Vector2DSetStoresComponentsAsGiven)
{
    TQ3Vector2D v{};
    EXPECT_EQ(Q3Vector2D_Set(&v, -1.5f, 2.25f), &v);
    EXPECT_EQ(v.x, -1.5f);
    EXPECT_EQ(v.y, 2.25f);
    EXPECT_EQ(Q3Vector2D_Set(&v, kNaN, -kInf), &v);
    EXPECT_TRUE(std::isnan(v.x));
    EXPECT_EQ(v.y, -kInf);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Vector2D_Set(nullptr, 1, 2), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(MathVectorApiTest, Vector2DTo3DAppendsOne)
{
    const TQ3Vector2D v{3, -4};
    TQ3Vector3D r{};
    EXPECT_EQ(Q3Vector2D_To3D(&v, &r), &r);
    EXPECT_TRUE(sameBits(r, TQ3Vector3D{3, -4, 1}));
    const TQ3Vector2D bad{kNaN, kInf};
    Q3Vector2D_To3D(&bad, &r);
    EXPECT_TRUE(std::isnan(r.x));
    EXPECT_EQ(r.y, kInf);
    EXPECT_EQ(r.z, 1.0f);
}

TEST_F(MathVectorApiTest, Vector3DTo2DDividesByZUnlessItIsZero)
{
    const TQ3Vector3D v{6, -9, 3}, flat{6, -9, 0}, far{1, 2, kInf}, nan{1, 2, kNaN};
    TQ3Vector2D r{};
    EXPECT_EQ(Q3Vector3D_To2D(&v, &r), &r);
    EXPECT_EQ(r.x, 2.0f);
    EXPECT_EQ(r.y, -3.0f);
    EXPECT_EQ(Q3Vector3D_To2D(&flat, &r), &r); // z = 0: undivided, no error
    EXPECT_EQ(r.x, 6.0f);
    EXPECT_EQ(r.y, -9.0f);
    Q3Vector3D_To2D(&far, &r);
    EXPECT_EQ(r.x, 0.0f);
    EXPECT_EQ(r.y, 0.0f);
    Q3Vector3D_To2D(&nan, &r);
    EXPECT_TRUE(std::isnan(r.x) && std::isnan(r.y));
}

TEST_F(MathVectorApiTest, ConversionsRejectNullAndLeaveTheResultAlone)
{
    const TQ3Vector2D v2{1, 2};
    const TQ3Vector3D v3{1, 2, 3};
    TQ3Vector2D r2 = filledWith<TQ3Vector2D>(7);
    TQ3Vector3D r3 = filledWith<TQ3Vector3D>(7);
    expectEachNullRejected("Q3Vector2D_To3D", Q3Vector2D_To3D, &v2, &r3);
    expectEachNullRejected("Q3Vector3D_To2D", Q3Vector3D_To2D, &v3, &r2);
    EXPECT_TRUE(sameBits(r2, filledWith<TQ3Vector2D>(7)));
    EXPECT_TRUE(sameBits(r3, filledWith<TQ3Vector3D>(7)));
}

// ---- Scaling, lengths, normalizing ---------------------------------------------

TEST_F(MathVectorApiTest, ScaleMultipliesEveryComponent)
{
    TQ3Vector2D v2{1.5f, -2};
    TQ3Vector3D v3{1.5f, -2, 0.25f};
    TQ3Vector2D r2{};
    EXPECT_EQ(Q3Vector2D_Scale(&v2, -4, &r2), &r2);
    EXPECT_EQ(r2.x, 1.5f * -4);
    EXPECT_EQ(r2.y, -2.0f * -4);
    EXPECT_EQ(Q3Vector3D_Scale(&v3, 3, &v3), &v3); // in place
    EXPECT_EQ(v3.x, 1.5f * 3);
    EXPECT_EQ(v3.y, -2.0f * 3);
    EXPECT_EQ(v3.z, 0.25f * 3);
    EXPECT_EQ(Q3Vector2D_Scale(&v2, 0.5f, &v2), &v2);
    EXPECT_EQ(v2.x, 0.75f);
    EXPECT_EQ(v2.y, -1.0f);
}

TEST_F(MathVectorApiTest, ScaleFollowsIEEEForNonFiniteValues)
{
    const TQ3Vector3D v{0, 1, -1};
    TQ3Vector3D r{};
    Q3Vector3D_Scale(&v, kInf, &r); // 0 * inf is NaN
    EXPECT_TRUE(std::isnan(r.x));
    EXPECT_EQ(r.y, kInf);
    EXPECT_EQ(r.z, -kInf);
    Q3Vector3D_Scale(&v, kNaN, &r);
    EXPECT_TRUE(std::isnan(r.y));
    const TQ3Vector2D big{3e38f, 1};
    TQ3Vector2D r2{};
    Q3Vector2D_Scale(&big, 10, &r2); // overflows to infinity, no error
    EXPECT_EQ(r2.x, kInf);
    EXPECT_EQ(r2.y, 10.0f);
}

TEST_F(MathVectorApiTest, Vector2DLengthIsEuclideanAndDoesNotOverflow)
{
    const TQ3Vector2D v{-5, 12}, zero{0, 0}, huge{3e30f, 4e30f};
    EXPECT_EQ(Q3Vector2D_Length(&v), 13.0f);
    EXPECT_EQ(Q3Vector2D_Length(&zero), 0.0f);
    EXPECT_FLOAT_EQ(Q3Vector2D_Length(&huge), 5e30f); // the square, 2.5e61, is beyond FLT_MAX
    const TQ3Vector2D nan{kNaN, 0}, inf{0, -kInf};
    EXPECT_TRUE(std::isnan(Q3Vector2D_Length(&nan)));
    EXPECT_EQ(Q3Vector2D_Length(&inf), kInf);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Vector2D_Length(nullptr), 0.0f), kQ3ErrorNULLParameter);
}

TEST_F(MathVectorApiTest, Vector2DNormalizeKeepsDirectionAtUnitLength)
{
    TQ3Vector2D v{3, -4};
    EXPECT_EQ(Q3Vector2D_Normalize(&v, &v), &v); // in place
    EXPECT_FLOAT_EQ(v.x, 0.6f);
    EXPECT_FLOAT_EQ(v.y, -0.8f);
    const TQ3Vector2D tiny{1e-40f, -1e-40f}, huge{3e38f, 3e38f};
    TQ3Vector2D r{};
    ASSERT_EQ(Q3Vector2D_Normalize(&tiny, &r), &r);
    EXPECT_FLOAT_EQ(r.x, float(1 / std::sqrt(2.0)));
    EXPECT_FLOAT_EQ(r.y, float(-1 / std::sqrt(2.0)));
    ASSERT_EQ(Q3Vector2D_Normalize(&huge, &r), &r);
    EXPECT_FLOAT_EQ(r.x, float(1 / std::sqrt(2.0)));
}

TEST_F(MathVectorApiTest, Vector2DNormalizeRejectsTheZeroVectorAndNull)
{
    const TQ3Vector2D zero{0, -0.0f}, v{1, 0};
    TQ3Vector2D r = filledWith<TQ3Vector2D>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Vector2D_Normalize(&zero, &r), nullptr), kQ3ErrorVector3DZeroLength);
    EXPECT_TRUE(sameBits(r, filledWith<TQ3Vector2D>(7)));
    expectEachNullRejected("Q3Vector2D_Normalize", Q3Vector2D_Normalize, &v, &r);
}

TEST_F(MathVectorApiTest, Vector2DNormalizePropagatesNonFiniteComponents)
{
    const TQ3Vector2D nan{kNaN, 1}, inf{kInf, 0};
    TQ3Vector2D r{};
    EXPECT_EQ(Q3Vector2D_Normalize(&nan, &r), &r);
    EXPECT_TRUE(std::isnan(r.x) && std::isnan(r.y));
    EXPECT_EQ(Q3Vector2D_Normalize(&inf, &r), &r); // inf / inf
    EXPECT_TRUE(std::isnan(r.x));
}

// ---- Sums, products, negation ---------------------------------------------------

TEST_F(MathVectorApiTest, AddAndSubtractWorkComponentwiseAndInPlace)
{
    TQ3Vector2D a{1.5f, -2}, b{0.25f, 8};
    TQ3Vector2D r{};
    EXPECT_EQ(Q3Vector2D_Add(&a, &b, &r), &r);
    EXPECT_EQ(r.x, 1.75f);
    EXPECT_EQ(r.y, 6.0f);
    EXPECT_EQ(Q3Vector2D_Subtract(&a, &b, &r), &r);
    EXPECT_EQ(r.x, 1.25f);
    EXPECT_EQ(r.y, -10.0f);
    EXPECT_EQ(Q3Vector2D_Subtract(&a, &b, &b), &b); // result is v2
    EXPECT_EQ(b.x, 1.25f);
    EXPECT_EQ(b.y, -10.0f);

    TQ3Vector3D c{1, 2, 3}, d{10, 20, 30};
    EXPECT_EQ(Q3Vector3D_Add(&c, &d, &c), &c); // result is v1
    EXPECT_EQ(c.x, 11.0f);
    EXPECT_EQ(c.y, 22.0f);
    EXPECT_EQ(c.z, 33.0f);
    EXPECT_EQ(Q3Vector3D_Subtract(&c, &c, &c), &c); // all three the same
    EXPECT_EQ(c.x, 0.0f);
    EXPECT_EQ(c.z, 0.0f);
    EXPECT_EQ(Q3Vector3D_Subtract(&d, &c, &c), &c);
    EXPECT_EQ(c.y, 20.0f);
}

TEST_F(MathVectorApiTest, AddAndSubtractFollowIEEEForNonFiniteValues)
{
    const TQ3Vector3D inf{kInf, kInf, kNaN}, one{1, kInf, 1};
    TQ3Vector3D r{};
    Q3Vector3D_Add(&inf, &one, &r);
    EXPECT_EQ(r.x, kInf);
    EXPECT_TRUE(std::isnan(r.z));
    Q3Vector3D_Subtract(&inf, &one, &r); // inf - inf
    EXPECT_TRUE(std::isnan(r.y));
    const TQ3Vector2D max{3e38f, -3e38f}, same{3e38f, 3e38f};
    TQ3Vector2D r2{};
    Q3Vector2D_Add(&max, &same, &r2);
    EXPECT_EQ(r2.x, kInf); // overflow, no error
    EXPECT_EQ(r2.y, 0.0f);
}

TEST_F(MathVectorApiTest, AddAndSubtractRejectNull)
{
    const TQ3Vector2D a{1, 2};
    const TQ3Vector3D b{1, 2, 3};
    TQ3Vector2D r2 = filledWith<TQ3Vector2D>(7);
    TQ3Vector3D r3 = filledWith<TQ3Vector3D>(7);
    expectEachNullRejected("Q3Vector2D_Add", Q3Vector2D_Add, &a, &a, &r2);
    expectEachNullRejected("Q3Vector2D_Subtract", Q3Vector2D_Subtract, &a, &a, &r2);
    expectEachNullRejected("Q3Vector3D_Add", Q3Vector3D_Add, &b, &b, &r3);
    expectEachNullRejected("Q3Vector3D_Subtract", Q3Vector3D_Subtract, &b, &b, &r3);
    EXPECT_TRUE(sameBits(r2, filledWith<TQ3Vector2D>(7)));
    EXPECT_TRUE(sameBits(r3, filledWith<TQ3Vector3D>(7)));
}

TEST_F(MathVectorApiTest, Vector2DCrossIsTheZOfTheThreeDimensionalCross)
{
    const TQ3Vector2D x{1, 0}, y{0, 1}, a{2, 3}, b{4, 5};
    EXPECT_EQ(Q3Vector2D_Cross(&x, &y), 1.0f); // y is counterclockwise from x
    EXPECT_EQ(Q3Vector2D_Cross(&y, &x), -1.0f);
    EXPECT_EQ(Q3Vector2D_Cross(&a, &b), 2.0f * 5 - 3.0f * 4);
    EXPECT_EQ(Q3Vector2D_Cross(&a, &a), 0.0f);
    const TQ3Vector2D nan{kNaN, 0}, inf{kInf, 0};
    EXPECT_TRUE(std::isnan(Q3Vector2D_Cross(&nan, &y)));
    EXPECT_EQ(Q3Vector2D_Cross(&inf, &y), kInf);
    expectEachNullRejected("Q3Vector2D_Cross", Q3Vector2D_Cross, &x, &y);
}

TEST_F(MathVectorApiTest, Vector2DDotMatchesHandComputation)
{
    const TQ3Vector2D a{1, 2}, b{3, -4};
    EXPECT_EQ(Q3Vector2D_Dot(&a, &b), 1.0f * 3 + 2.0f * -4);
    const TQ3Vector2D nan{kNaN, 0}, inf{-kInf, 0};
    EXPECT_TRUE(std::isnan(Q3Vector2D_Dot(&nan, &a)));
    EXPECT_EQ(Q3Vector2D_Dot(&inf, &a), -kInf);
    expectEachNullRejected("Q3Vector2D_Dot", Q3Vector2D_Dot, &a, &a);
}

TEST_F(MathVectorApiTest, NegateFlipsEverySignInPlaceToo)
{
    TQ3Vector2D v2{1.5f, 0.0f};
    EXPECT_EQ(Q3Vector2D_Negate(&v2, &v2), &v2);
    EXPECT_EQ(v2.x, -1.5f);
    EXPECT_TRUE(std::signbit(v2.y)); // 0 becomes -0
    TQ3Vector3D v3{-2, kInf, kNaN}, r{};
    EXPECT_EQ(Q3Vector3D_Negate(&v3, &r), &r);
    EXPECT_EQ(r.x, 2.0f);
    EXPECT_EQ(r.y, -kInf);
    EXPECT_TRUE(std::isnan(r.z));
    expectEachNullRejected("Q3Vector2D_Negate", Q3Vector2D_Negate, &v2, &v2);
    expectEachNullRejected("Q3Vector3D_Negate", Q3Vector3D_Negate, &v3, &r);
}

// ---- Transforms ----------------------------------------------------------------

TEST_F(MathVectorApiTest, Vector2DTransformUsesOnlyTheUpperLeftTwoByTwo)
{
    // Translation (row 2) and the projective column (column 2) do not touch
    // a direction.
    const TQ3Matrix3x3 m = matrix3x3Of({2, 1, 5, -1, 3, 7, 100, 200, 9});
    TQ3Vector2D v{1.5f, -2};
    const double in[3] = {1.5, -2, 0};
    double expected[3];
    rowTimes(in, m, expected);
    EXPECT_EQ(Q3Vector2D_Transform(&v, &m, &v), &v); // in place
    EXPECT_FLOAT_EQ(v.x, float(expected[0]));
    EXPECT_FLOAT_EQ(v.y, float(expected[1]));
}

TEST_F(MathVectorApiTest, Vector3DTransformUsesOnlyTheUpperLeftThreeByThree)
{
    const TQ3Matrix4x4 m = matrix4x4Of({0.5f, 1, 0, 3, -2, 0.25f, 1, 4, 0, 3, 2, 5, 70, -40, 15, 6});
    const TQ3Vector3D v{1, -2, 0.5f};
    const double in[4] = {1, -2, 0.5, 0};
    double expected[4];
    rowTimes(in, m, expected);
    TQ3Vector3D r{};
    EXPECT_EQ(Q3Vector3D_Transform(&v, &m, &r), &r);
    EXPECT_FLOAT_EQ(r.x, float(expected[0]));
    EXPECT_FLOAT_EQ(r.y, float(expected[1]));
    EXPECT_FLOAT_EQ(r.z, float(expected[2]));
    // A pure translation leaves a vector exactly as it was.
    TQ3Matrix4x4 t = kIdentity4x4;
    t.value[3][0] = 10;
    t.value[3][1] = -20;
    TQ3Vector3D same = v;
    EXPECT_EQ(Q3Vector3D_Transform(&same, &t, &same), &same);
    EXPECT_TRUE(sameBits(same, v));
}

TEST_F(MathVectorApiTest, TransformsFollowIEEEForNonFiniteValues)
{
    TQ3Matrix4x4 m = kIdentity4x4;
    m.value[0][1] = kInf;
    const TQ3Vector3D v{1, 0, 0}, nan{kNaN, 0, 0};
    TQ3Vector3D r{};
    Q3Vector3D_Transform(&v, &m, &r);
    EXPECT_EQ(r.y, kInf);
    Q3Vector3D_Transform(&nan, &kIdentity4x4, &r);
    EXPECT_TRUE(std::isnan(r.x));
    const TQ3Vector2D v2{0, 1};
    TQ3Matrix3x3 m3 = kIdentity3x3;
    m3.value[0][0] = kNaN; // 0 * NaN is NaN
    TQ3Vector2D r2{};
    Q3Vector2D_Transform(&v2, &m3, &r2);
    EXPECT_TRUE(std::isnan(r2.x));
    EXPECT_EQ(r2.y, 1.0f);
}

TEST_F(MathVectorApiTest, ScaleAndTransformsRejectNull)
{
    const TQ3Vector2D v2{1, 2};
    const TQ3Vector3D v3{1, 2, 3};
    TQ3Vector2D r2{};
    TQ3Vector3D r3{};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Vector2D_Scale(nullptr, 2, &r2), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Vector2D_Scale(&v2, 2, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Vector3D_Scale(nullptr, 2, &r3), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Vector3D_Scale(&v3, 2, nullptr), nullptr), kQ3ErrorNULLParameter);
    expectEachNullRejected("Q3Vector2D_Transform", Q3Vector2D_Transform, &v2, &kIdentity3x3, &r2);
    expectEachNullRejected("Q3Vector3D_Transform", Q3Vector3D_Transform, &v3, &kIdentity4x4, &r3);
}

// ---- Before Q3Initialize ----------------------------------------------------------

TEST(MathVectorApiUninitialized, EveryCallFailsWithNotInitializedAndChangesNothing)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    TQ3Vector2D a{1, 2}, r2 = filledWith<TQ3Vector2D>(7);
    TQ3Vector3D b{1, 2, 3}, r3 = filledWith<TQ3Vector3D>(7);
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    EXPECT_EQ(Q3Vector2D_Set(&r2, 0, 0), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector2D_To3D(&a, &r3), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector3D_To2D(&b, &r2), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector2D_Scale(&a, 2, &r2), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector3D_Scale(&b, 2, &r3), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector2D_Length(&a), 0.0f);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector2D_Normalize(&a, &r2), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector2D_Add(&a, &a, &r2), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector3D_Add(&b, &b, &r3), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector2D_Subtract(&a, &a, &r2), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector3D_Subtract(&b, &b, &r3), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector2D_Cross(&a, &a), 0.0f);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector2D_Dot(&a, &a), 0.0f);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector2D_Transform(&a, &kIdentity3x3, &r2), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector3D_Transform(&b, &kIdentity4x4, &r3), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector2D_Negate(&a, &r2), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector3D_Negate(&b, &r3), nullptr);
    EXPECT_TRUE(failed());
    const TQ3Quaternion q{1, 0, 0, 0};
    EXPECT_EQ(Q3Vector3D_TransformQuaternion(&b, &q, &r3), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_TRUE(sameBits(r2, filledWith<TQ3Vector2D>(7)));
    EXPECT_TRUE(sameBits(r3, filledWith<TQ3Vector3D>(7)));
}

} // namespace
