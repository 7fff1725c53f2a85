// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "MathTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DMath.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace {

using q3test::Q3ApiTest;
using MathApiTest = Q3ApiTest;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
// Results go through float rounding of sines, cosines and products of small
// values; 1e-6 is a few float ulps at magnitude 1-10.
constexpr float kTolerance = 1e-6f;

TQ3Matrix4x4 matrixOf(std::initializer_list<float> rowMajor)
{
    return q3test::matrix4x4Of(rowMajor);
}

TQ3Matrix4x4 filled(float value)
{
    TQ3Matrix4x4 m;
    for (auto& row : m.value)
        for (float& entry : row)
            entry = value;
    return m;
}

bool sameBits(const TQ3Matrix4x4& a, const TQ3Matrix4x4& b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

void expectMatrixNear(const TQ3Matrix4x4& actual, const TQ3Matrix4x4& expected, float tolerance,
                      const char* what)
{
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            EXPECT_NEAR(actual.value[i][j], expected.value[i][j], tolerance)
                << what << ": value[" << i << "][" << j << "]";
}

void expectPointNear(const TQ3Point3D& p, float x, float y, float z, float tolerance = kTolerance)
{
    EXPECT_NEAR(p.x, x, tolerance);
    EXPECT_NEAR(p.y, y, tolerance);
    EXPECT_NEAR(p.z, z, tolerance);
}

TQ3Point3D transformed(float x, float y, float z, const TQ3Matrix4x4& m)
{
    const TQ3Point3D p{x, y, z};
    TQ3Point3D r{};
    Q3Point3D_Transform(&p, &m, &r);
    return r;
}

const TQ3Matrix4x4 kIdentity = matrixOf({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});

// ---- Setting points and vectors -------------------------------------------

TEST_F(MathApiTest, Point3DSetStoresCoordinatesAndReturnsItsArgument)
{
    TQ3Point3D p{};
    EXPECT_EQ(Q3Point3D_Set(&p, 1.5f, -2.0f, 3.25f), &p);
    EXPECT_EQ(p.x, 1.5f);
    EXPECT_EQ(p.y, -2.0f);
    EXPECT_EQ(p.z, 3.25f);
}

TEST_F(MathApiTest, Point3DSetStoresNonFiniteValuesUnchecked)
{
    TQ3Point3D p{};
    EXPECT_EQ(Q3Point3D_Set(&p, kNaN, kInf, -kInf), &p);
    EXPECT_TRUE(std::isnan(p.x));
    EXPECT_EQ(p.y, kInf);
    EXPECT_EQ(p.z, -kInf);
}

TEST_F(MathApiTest, Point3DSetRejectsNull)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_Set(nullptr, 1, 2, 3), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(MathApiTest, Vector3DSetStoresComponentsAndReturnsItsArgument)
{
    TQ3Vector3D v{};
    EXPECT_EQ(Q3Vector3D_Set(&v, -1.0f, 0.5f, 8.0f), &v);
    EXPECT_EQ(v.x, -1.0f);
    EXPECT_EQ(v.y, 0.5f);
    EXPECT_EQ(v.z, 8.0f);
    EXPECT_EQ(Q3Vector3D_Set(&v, kInf, kNaN, -kInf), &v);
    EXPECT_EQ(v.x, kInf);
    EXPECT_TRUE(std::isnan(v.y));
    EXPECT_EQ(v.z, -kInf);
}

TEST_F(MathApiTest, Vector3DSetRejectsNull)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Vector3D_Set(nullptr, 1, 2, 3), nullptr), kQ3ErrorNULLParameter);
}

// Each coordinate of p is exactly the value given.
void expectRationalPoint(const TQ3RationalPoint4D& p, float x, float y, float z, float w)
{
    EXPECT_EQ(p.x, x);
    EXPECT_EQ(p.y, y);
    EXPECT_EQ(p.z, z);
    EXPECT_EQ(p.w, w);
}

TEST_F(MathApiTest, RationalPoint4DSetStoresCoordinatesAndWeight)
{
    TQ3RationalPoint4D p{};
    EXPECT_EQ(Q3RationalPoint4D_Set(&p, 1, 2, 3, 0.5f), &p);
    expectRationalPoint(p, 1, 2, 3, 0.5f);
    EXPECT_EQ(Q3RationalPoint4D_Set(&p, kNaN, kInf, -kInf, kNaN), &p);
    EXPECT_TRUE(std::isnan(p.x));
    EXPECT_EQ(p.y, kInf);
    EXPECT_EQ(p.z, -kInf);
    EXPECT_TRUE(std::isnan(p.w));
}

TEST_F(MathApiTest, RationalPoint4DSetRejectsNull)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RationalPoint4D_Set(nullptr, 1, 2, 3, 1), nullptr),
                    kQ3ErrorNULLParameter);
}

TEST_F(MathApiTest, ArticleAliasTQ3RationalPoint4DSetIsQ3RationalPoint4DSet)
{
    // The develop article's Listing 3 spells it this way.
    TQ3RationalPoint4D p{};
    EXPECT_EQ(TQ3RationalPoint4D_Set(&p, 4, 5, 6, 1.0), &p);
    expectRationalPoint(p, 4, 5, 6, 1);
}

// ---- Lengths, distances and products --------------------------------------

TEST_F(MathApiTest, Point3DDistanceIsEuclidean)
{
    const TQ3Point3D a{1, 2, 3}, b{4, 6, 3};
    EXPECT_FLOAT_EQ(Q3Point3D_Distance(&a, &b), 5.0f);
    EXPECT_FLOAT_EQ(Q3Point3D_Distance(&b, &a), 5.0f);
    EXPECT_EQ(Q3Point3D_Distance(&a, &a), 0.0f);
}

TEST_F(MathApiTest, Point3DDistanceDoesNotOverflowForLargeFiniteCoordinates)
{
    // The squared distance, 2.5e61, is beyond FLT_MAX; the distance is not.
    const TQ3Point3D a{0, 0, 0}, b{3e30f, 4e30f, 0};
    EXPECT_FLOAT_EQ(Q3Point3D_Distance(&a, &b), 5e30f);
}

TEST_F(MathApiTest, Point3DDistancePropagatesNonFiniteCoordinates)
{
    const TQ3Point3D a{0, 0, 0}, nan{kNaN, 0, 0}, inf{kInf, 0, 0}, minusInf{0, -kInf, 0};
    EXPECT_TRUE(std::isnan(Q3Point3D_Distance(&a, &nan)));
    EXPECT_EQ(Q3Point3D_Distance(&a, &inf), kInf);
    EXPECT_EQ(Q3Point3D_Distance(&minusInf, &a), kInf);
}

TEST_F(MathApiTest, Point3DDistanceRejectsNullAndReturnsZero)
{
    const TQ3Point3D a{1, 2, 3};
    expectEachNullRejected("Q3Point3D_Distance", Q3Point3D_Distance, &a, &a);
}

TEST_F(MathApiTest, Vector3DLengthIsEuclidean)
{
    const TQ3Vector3D v{3, 4, 12}, zero{0, 0, 0}, negative{-2, 0, 0};
    EXPECT_FLOAT_EQ(Q3Vector3D_Length(&v), 13.0f);
    EXPECT_EQ(Q3Vector3D_Length(&zero), 0.0f);
    EXPECT_FLOAT_EQ(Q3Vector3D_Length(&negative), 2.0f);
}

TEST_F(MathApiTest, Vector3DLengthDoesNotOverflowForLargeFiniteComponents)
{
    const TQ3Vector3D v{3e20f, 4e20f, 0};
    EXPECT_FLOAT_EQ(Q3Vector3D_Length(&v), 5e20f);
}

TEST_F(MathApiTest, Vector3DLengthPropagatesNonFiniteComponents)
{
    const TQ3Vector3D nan{1, kNaN, 0}, inf{0, 0, kInf}, minusInf{-kInf, 0, 0};
    EXPECT_TRUE(std::isnan(Q3Vector3D_Length(&nan)));
    EXPECT_EQ(Q3Vector3D_Length(&inf), kInf);
    EXPECT_EQ(Q3Vector3D_Length(&minusInf), kInf);
}

TEST_F(MathApiTest, Vector3DLengthRejectsNull)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Vector3D_Length(nullptr), 0.0f), kQ3ErrorNULLParameter);
}

TEST_F(MathApiTest, Vector3DNormalizeKeepsDirectionAtUnitLength)
{
    const TQ3Vector3D v{3, 0, -4};
    TQ3Vector3D unit{};
    EXPECT_EQ(Q3Vector3D_Normalize(&v, &unit), &unit);
    EXPECT_FLOAT_EQ(unit.x, 0.6f);
    EXPECT_EQ(unit.y, 0.0f);
    EXPECT_FLOAT_EQ(unit.z, -0.8f);
}

TEST_F(MathApiTest, Vector3DNormalizeWorksInPlace)
{
    TQ3Vector3D v{0, 0, 7};
    EXPECT_EQ(Q3Vector3D_Normalize(&v, &v), &v);
    EXPECT_EQ(v.x, 0.0f);
    EXPECT_EQ(v.y, 0.0f);
    EXPECT_EQ(v.z, 1.0f);
}

TEST_F(MathApiTest, Vector3DNormalizeHandlesSubnormalAndHugeComponents)
{
    const TQ3Vector3D tiny{1e-40f, 0, 0}, huge{0, 3e38f, 3e38f};
    TQ3Vector3D unit{};
    ASSERT_EQ(Q3Vector3D_Normalize(&tiny, &unit), &unit);
    EXPECT_FLOAT_EQ(unit.x, 1.0f);
    ASSERT_EQ(Q3Vector3D_Normalize(&huge, &unit), &unit);
    EXPECT_FLOAT_EQ(unit.y, std::sqrt(0.5f));
    EXPECT_FLOAT_EQ(unit.z, std::sqrt(0.5f));
}

TEST_F(MathApiTest, Vector3DNormalizeRejectsTheZeroVectorAndLeavesResultAlone)
{
    const TQ3Vector3D zero{0, 0, 0}, negativeZero{-0.0f, 0, -0.0f};
    TQ3Vector3D result{9, 9, 9};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Vector3D_Normalize(&zero, &result), nullptr), kQ3ErrorVector3DZeroLength);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Vector3D_Normalize(&negativeZero, &result), nullptr),
                    kQ3ErrorVector3DZeroLength);
    EXPECT_EQ(result.x, 9.0f);
    EXPECT_EQ(result.y, 9.0f);
    EXPECT_EQ(result.z, 9.0f);
}

TEST_F(MathApiTest, Vector3DNormalizePropagatesNonFiniteComponents)
{
    const TQ3Vector3D nan{kNaN, 1, 0}, inf{kInf, 0, 0}, minusInf{0, -kInf, 0};
    TQ3Vector3D result{};
    EXPECT_EQ(Q3Vector3D_Normalize(&nan, &result), &result);
    EXPECT_TRUE(std::isnan(result.x));
    // inf / inf is not a number: IEEE arithmetic, not an error.
    EXPECT_EQ(Q3Vector3D_Normalize(&inf, &result), &result);
    EXPECT_TRUE(std::isnan(result.x));
    EXPECT_EQ(Q3Vector3D_Normalize(&minusInf, &result), &result);
    EXPECT_TRUE(std::isnan(result.y));
}

TEST_F(MathApiTest, Vector3DNormalizeRejectsNull)
{
    const TQ3Vector3D v{1, 0, 0};
    TQ3Vector3D result{};
    expectEachNullRejected("Q3Vector3D_Normalize", Q3Vector3D_Normalize, &v, &result);
}

TEST_F(MathApiTest, Vector3DCrossIsRightHanded)
{
    const TQ3Vector3D x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    TQ3Vector3D r{};
    EXPECT_EQ(Q3Vector3D_Cross(&x, &y, &r), &r);
    EXPECT_EQ(r.x, 0.0f);
    EXPECT_EQ(r.y, 0.0f);
    EXPECT_EQ(r.z, 1.0f);
    Q3Vector3D_Cross(&y, &z, &r);
    EXPECT_EQ(r.x, 1.0f);
    Q3Vector3D_Cross(&z, &x, &r);
    EXPECT_EQ(r.y, 1.0f);
    Q3Vector3D_Cross(&y, &x, &r);
    EXPECT_EQ(r.z, -1.0f);
}

TEST_F(MathApiTest, Vector3DCrossOfGeneralVectorsMatchesHandComputation)
{
    // (1,2,3) x (4,5,6) = (2*6-3*5, 3*4-1*6, 1*5-2*4) = (-3, 6, -3)
    TQ3Vector3D a{1, 2, 3};
    const TQ3Vector3D b{4, 5, 6};
    EXPECT_EQ(Q3Vector3D_Cross(&a, &b, &a), &a); // result aliases an input
    EXPECT_EQ(a.x, -3.0f);
    EXPECT_EQ(a.y, 6.0f);
    EXPECT_EQ(a.z, -3.0f);
}

TEST_F(MathApiTest, Vector3DCrossPropagatesNonFiniteComponents)
{
    const TQ3Vector3D nan{kNaN, 0, 0}, inf{0, kInf, 0}, z{0, 0, 1};
    TQ3Vector3D r{};
    Q3Vector3D_Cross(&nan, &z, &r);
    EXPECT_TRUE(std::isnan(r.y));
    Q3Vector3D_Cross(&inf, &z, &r); // (inf*1 - 0*0, 0*0 - 0*1, 0*0 - inf*0)
    EXPECT_EQ(r.x, kInf);
    EXPECT_TRUE(std::isnan(r.z));
}

TEST_F(MathApiTest, Vector3DCrossRejectsNull)
{
    const TQ3Vector3D v{1, 0, 0};
    TQ3Vector3D r{};
    expectEachNullRejected("Q3Vector3D_Cross", Q3Vector3D_Cross, &v, &v, &r);
}

TEST_F(MathApiTest, Vector3DDotMatchesHandComputation)
{
    const TQ3Vector3D a{1, 2, 3}, b{4, -5, 6}, x{1, 0, 0}, y{0, 1, 0};
    EXPECT_EQ(Q3Vector3D_Dot(&a, &b), 12.0f); // 4 - 10 + 18
    EXPECT_EQ(Q3Vector3D_Dot(&x, &y), 0.0f);
}

TEST_F(MathApiTest, Vector3DDotPropagatesNonFiniteComponents)
{
    const TQ3Vector3D nan{kNaN, 0, 0}, inf{kInf, 0, 0}, minusInf{-kInf, 0, 0}, x{1, 0, 0};
    EXPECT_TRUE(std::isnan(Q3Vector3D_Dot(&nan, &x)));
    EXPECT_EQ(Q3Vector3D_Dot(&inf, &x), kInf);
    EXPECT_EQ(Q3Vector3D_Dot(&minusInf, &x), -kInf);
}

TEST_F(MathApiTest, Vector3DDotRejectsNull)
{
    const TQ3Vector3D v{1, 0, 0};
    expectEachNullRejected("Q3Vector3D_Dot", Q3Vector3D_Dot, &v, &v);
}

// ---- Transforming points ----------------------------------------------------

TEST_F(MathApiTest, Point3DTransformAppliesTheRowVectorConvention)
{
    // Translation in the bottom row: p * M adds it.
    const TQ3Matrix4x4 m = matrixOf({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 20, 30, 1});
    expectPointNear(transformed(1, 2, 3, m), 11, 22, 33);
}

TEST_F(MathApiTest, Point3DTransformDividesByW)
{
    // (1,2,3,1) * M: x' = 1*2 = 2, y' = 2*2 = 4, z' = 3*2 = 6, w' = 1*1 + 3 = 4.
    const TQ3Matrix4x4 m = matrixOf({2, 0, 0, 1, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 3});
    expectPointNear(transformed(1, 2, 3, m), 0.5f, 1.0f, 1.5f);
}

TEST_F(MathApiTest, Point3DTransformLeavesThePointUndividedWhenWIsZero)
{
    const TQ3Matrix4x4 m = matrixOf({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 0});
    expectPointNear(transformed(1, 2, 3, m), 6, 2, 3);
}

TEST_F(MathApiTest, Point3DTransformWorksInPlace)
{
    const TQ3Matrix4x4 m = matrixOf({0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
    TQ3Point3D p{1, 2, 3};
    EXPECT_EQ(Q3Point3D_Transform(&p, &m, &p), &p);
    expectPointNear(p, -2, 1, 3);
}

TEST_F(MathApiTest, Point3DTransformPropagatesNonFiniteValues)
{
    const TQ3Point3D nan{kNaN, 0, 0};
    TQ3Point3D r{};
    EXPECT_EQ(Q3Point3D_Transform(&nan, &kIdentity, &r), &r);
    EXPECT_TRUE(std::isnan(r.x));
    const TQ3Matrix4x4 inf = matrixOf({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, kInf, 0, 0, 1});
    const TQ3Matrix4x4 minusInf = matrixOf({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -kInf, 0, 1});
    EXPECT_EQ(transformed(1, 1, 1, inf).x, kInf);
    EXPECT_EQ(transformed(1, 1, 1, minusInf).y, -kInf);
}

TEST_F(MathApiTest, Point3DTransformRejectsNull)
{
    const TQ3Point3D p{1, 2, 3};
    TQ3Point3D r{};
    expectEachNullRejected("Q3Point3D_Transform", Q3Point3D_Transform, &p, &kIdentity, &r);
}

TEST_F(MathApiTest, RationalPoint4DTransformMultipliesWithoutDividing)
{
    // (1,2,3,2) * M, M as below:
    //   x' = 1*1 + 2*0 + 3*0 + 2*10 = 21
    //   y' = 1*0 + 2*2 + 3*0 + 2*20 = 44
    //   z' = 1*0 + 2*0 + 3*1 + 2*30 = 63
    //   w' = 1*1 + 2*0 + 3*0 + 2*1  = 3
    const TQ3Matrix4x4 m = matrixOf({1, 0, 0, 1, 0, 2, 0, 0, 0, 0, 1, 0, 10, 20, 30, 1});
    TQ3RationalPoint4D p{1, 2, 3, 2};
    EXPECT_EQ(Q3RationalPoint4D_Transform(&p, &m, &p), &p);
    expectRationalPoint(p, 21, 44, 63, 3);
}

TEST_F(MathApiTest, RationalPoint4DTransformKeepsAZeroWeight)
{
    const TQ3Matrix4x4 m = matrixOf({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 20, 30, 1});
    const TQ3RationalPoint4D direction{1, 2, 3, 0};
    TQ3RationalPoint4D r{};
    ASSERT_EQ(Q3RationalPoint4D_Transform(&direction, &m, &r), &r);
    expectRationalPoint(r, 1, 2, 3, 0);
}

TEST_F(MathApiTest, RationalPoint4DTransformPropagatesNonFiniteValues)
{
    const TQ3RationalPoint4D nan{0, 0, 0, kNaN}, inf{kInf, 0, 0, 1}, minusInf{0, 0, -kInf, 1};
    TQ3RationalPoint4D r{};
    Q3RationalPoint4D_Transform(&nan, &kIdentity, &r);
    EXPECT_TRUE(std::isnan(r.w));
    Q3RationalPoint4D_Transform(&inf, &kIdentity, &r);
    EXPECT_EQ(r.x, kInf);
    Q3RationalPoint4D_Transform(&minusInf, &kIdentity, &r);
    EXPECT_EQ(r.z, -kInf);
}

TEST_F(MathApiTest, RationalPoint4DTransformRejectsNull)
{
    const TQ3RationalPoint4D p{1, 2, 3, 1};
    TQ3RationalPoint4D r{};
    expectEachNullRejected("Q3RationalPoint4D_Transform", Q3RationalPoint4D_Transform, &p, &kIdentity, &r);
}

// ---- Building matrices ------------------------------------------------------

TEST_F(MathApiTest, SetIdentityWritesExactlyTheIdentity)
{
    TQ3Matrix4x4 m = filled(7.0f);
    EXPECT_EQ(Q3Matrix4x4_SetIdentity(&m), &m);
    EXPECT_TRUE(sameBits(m, kIdentity));
}

TEST_F(MathApiTest, SetTranslatePutsTheOffsetInTheBottomRow)
{
    TQ3Matrix4x4 m = filled(7.0f);
    EXPECT_EQ(Q3Matrix4x4_SetTranslate(&m, 1, -2, 3), &m);
    EXPECT_TRUE(sameBits(m, matrixOf({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, -2, 3, 1})));
    expectPointNear(transformed(10, 10, 10, m), 11, 8, 13);
}

TEST_F(MathApiTest, SetScaleWritesTheDiagonal)
{
    TQ3Matrix4x4 m = filled(7.0f);
    EXPECT_EQ(Q3Matrix4x4_SetScale(&m, 2, 0, -0.5f), &m);
    EXPECT_TRUE(sameBits(m, matrixOf({2, 0, 0, 0, 0, 0, 0, 0, 0, 0, -0.5f, 0, 0, 0, 0, 1})));
}

TEST_F(MathApiTest, SetTranslateAndScaleStoreNonFiniteValuesUnchecked)
{
    TQ3Matrix4x4 m{};
    EXPECT_EQ(Q3Matrix4x4_SetTranslate(&m, kNaN, kInf, -kInf), &m);
    EXPECT_TRUE(std::isnan(m.value[3][0]));
    EXPECT_EQ(m.value[3][1], kInf);
    EXPECT_EQ(m.value[3][2], -kInf);
    EXPECT_EQ(Q3Matrix4x4_SetScale(&m, kNaN, kInf, -kInf), &m);
    EXPECT_TRUE(std::isnan(m.value[0][0]));
    EXPECT_EQ(m.value[1][1], kInf);
    EXPECT_EQ(m.value[2][2], -kInf);
}

TEST_F(MathApiTest, SetRotateXQuarterTurnTakesYToZ)
{
    TQ3Matrix4x4 m = filled(7.0f);
    EXPECT_EQ(Q3Matrix4x4_SetRotate_X(&m, kQ3PiOver2), &m);
    expectPointNear(transformed(0, 1, 0, m), 0, 0, 1);
    expectPointNear(transformed(0, 0, 1, m), 0, -1, 0);
    // The x row and column and the homogeneous part are exact.
    EXPECT_EQ(m.value[0][0], 1.0f);
    EXPECT_EQ(m.value[0][1], 0.0f);
    EXPECT_EQ(m.value[1][0], 0.0f);
    EXPECT_EQ(m.value[3][3], 1.0f);
    EXPECT_EQ(m.value[3][1], 0.0f);
}

TEST_F(MathApiTest, SetRotateYQuarterTurnTakesZToX)
{
    TQ3Matrix4x4 m{};
    EXPECT_EQ(Q3Matrix4x4_SetRotate_Y(&m, kQ3PiOver2), &m);
    expectPointNear(transformed(0, 0, 1, m), 1, 0, 0);
    expectPointNear(transformed(1, 0, 0, m), 0, 0, -1);
    EXPECT_EQ(m.value[1][1], 1.0f);
}

TEST_F(MathApiTest, SetRotateZQuarterTurnTakesXToY)
{
    TQ3Matrix4x4 m{};
    EXPECT_EQ(Q3Matrix4x4_SetRotate_Z(&m, kQ3PiOver2), &m);
    expectPointNear(transformed(1, 0, 0, m), 0, 1, 0);
    expectPointNear(transformed(0, 1, 0, m), -1, 0, 0);
    EXPECT_EQ(m.value[2][2], 1.0f);
}

TEST_F(MathApiTest, SetRotateZMatchesCosineAndSine)
{
    // Row-vector layout of a rotation by a: [c s; -s c] in the top-left.
    const float a = 0.3f;
    TQ3Matrix4x4 m{};
    Q3Matrix4x4_SetRotate_Z(&m, a);
    const TQ3Matrix4x4 expected = matrixOf({std::cos(a), std::sin(a), 0, 0, -std::sin(a), std::cos(a), 0, 0,
                                            0, 0, 1, 0, 0, 0, 0, 1});
    expectMatrixNear(m, expected, kTolerance, "SetRotate_Z(0.3)");
}

TEST_F(MathApiTest, SetRotatePropagatesNonFiniteAngles)
{
    TQ3Matrix4x4 m{};
    for (float angle : {kNaN, kInf, -kInf}) {
        EXPECT_EQ(Q3Matrix4x4_SetRotate_X(&m, angle), &m);
        EXPECT_TRUE(std::isnan(m.value[1][1]));
        EXPECT_EQ(m.value[0][0], 1.0f);
        EXPECT_EQ(Q3Matrix4x4_SetRotate_Y(&m, angle), &m);
        EXPECT_TRUE(std::isnan(m.value[0][0]));
        EXPECT_EQ(Q3Matrix4x4_SetRotate_Z(&m, angle), &m);
        EXPECT_TRUE(std::isnan(m.value[1][1]));
    }
}

TEST_F(MathApiTest, SetBuildersRejectNull)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetIdentity(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetTranslate(nullptr, 1, 2, 3), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetScale(nullptr, 1, 2, 3), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetRotate_X(nullptr, 1), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetRotate_Y(nullptr, 1), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetRotate_Z(nullptr, 1), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(MathApiTest, SetRotateAboutAxisTurnsAboutAnOffsetLine)
{
    // Axis: the line x = 1, y = 0 along +z (given with length 2). A quarter
    // turn takes (2,0,0), one unit along +x from the axis, to one unit along
    // +y from it: (1,1,0). Points on the axis stay put.
    const TQ3Point3D origin{1, 0, 0};
    const TQ3Vector3D orientation{0, 0, 2};
    TQ3Matrix4x4 m = filled(7.0f);
    EXPECT_EQ(Q3Matrix4x4_SetRotateAboutAxis(&m, &origin, &orientation, kQ3PiOver2), &m);
    expectPointNear(transformed(2, 0, 0, m), 1, 1, 0);
    expectPointNear(transformed(1, 0, 5, m), 1, 0, 5);
    expectPointNear(transformed(0, 0, -3, m), 1, -1, -3);
}

TEST_F(MathApiTest, SetRotateAboutAxisThroughTheOriginMatchesTheAxisRotations)
{
    const TQ3Point3D origin{0, 0, 0};
    const TQ3Vector3D x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    const float angle = 1.1f;
    TQ3Matrix4x4 general{}, axis{};
    Q3Matrix4x4_SetRotateAboutAxis(&general, &origin, &x, angle);
    Q3Matrix4x4_SetRotate_X(&axis, angle);
    expectMatrixNear(general, axis, kTolerance, "about x");
    Q3Matrix4x4_SetRotateAboutAxis(&general, &origin, &y, angle);
    Q3Matrix4x4_SetRotate_Y(&axis, angle);
    expectMatrixNear(general, axis, kTolerance, "about y");
    Q3Matrix4x4_SetRotateAboutAxis(&general, &origin, &z, angle);
    Q3Matrix4x4_SetRotate_Z(&axis, angle);
    expectMatrixNear(general, axis, kTolerance, "about z");
}

TEST_F(MathApiTest, SetRotateAboutAxisRejectsAZeroAxisAndLeavesTheMatrixAlone)
{
    const TQ3Point3D origin{1, 2, 3};
    const TQ3Vector3D zero{0, 0, 0};
    TQ3Matrix4x4 m = filled(7.0f);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetRotateAboutAxis(&m, &origin, &zero, 1.0f), nullptr),
                    kQ3ErrorVector3DZeroLength);
    EXPECT_TRUE(sameBits(m, filled(7.0f)));
}

TEST_F(MathApiTest, SetRotateAboutAxisPropagatesNonFiniteValues)
{
    const TQ3Point3D origin{0, 0, 0}, nanOrigin{kNaN, 0, 0};
    const TQ3Vector3D z{0, 0, 1}, infAxis{0, 0, kInf};
    TQ3Matrix4x4 m{};
    EXPECT_EQ(Q3Matrix4x4_SetRotateAboutAxis(&m, &origin, &z, kNaN), &m);
    EXPECT_TRUE(std::isnan(m.value[0][0]));
    EXPECT_EQ(Q3Matrix4x4_SetRotateAboutAxis(&m, &nanOrigin, &z, 1.0f), &m);
    EXPECT_TRUE(std::isnan(m.value[3][0]));
    EXPECT_EQ(Q3Matrix4x4_SetRotateAboutAxis(&m, &origin, &infAxis, 1.0f), &m);
    EXPECT_TRUE(std::isnan(m.value[2][2]));
    EXPECT_EQ(Q3Matrix4x4_SetRotateAboutAxis(&m, &origin, &z, -kInf), &m);
    EXPECT_TRUE(std::isnan(m.value[0][0]));
}

TEST_F(MathApiTest, SetRotateAboutAxisRejectsNull)
{
    const TQ3Point3D origin{0, 0, 0};
    const TQ3Vector3D z{0, 0, 1};
    TQ3Matrix4x4 m{};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetRotateAboutAxis(nullptr, &origin, &z, 1), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetRotateAboutAxis(&m, nullptr, &z, 1), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetRotateAboutAxis(&m, &origin, nullptr, 1), nullptr),
                    kQ3ErrorNULLParameter);
}

// ---- Matrix operations ------------------------------------------------------

TEST_F(MathApiTest, MultiplyAppliesTheLeftFactorFirst)
{
    // Translate by +1 along x, then scale by 2: (1,0,0) -> (2,0,0) -> (4,0,0).
    TQ3Matrix4x4 t{}, s{}, ts{}, st{};
    Q3Matrix4x4_SetTranslate(&t, 1, 0, 0);
    Q3Matrix4x4_SetScale(&s, 2, 2, 2);
    EXPECT_EQ(Q3Matrix4x4_Multiply(&t, &s, &ts), &ts);
    EXPECT_EQ(Q3Matrix4x4_Multiply(&s, &t, &st), &st);
    expectPointNear(transformed(1, 0, 0, ts), 4, 0, 0);
    expectPointNear(transformed(1, 0, 0, st), 3, 0, 0);
}

TEST_F(MathApiTest, MultiplyMatchesHandComputedProduct)
{
    // Small integers, so every product is exact.
    const TQ3Matrix4x4 a = matrixOf({1, 2, 0, 0, 0, 1, 3, 0, 0, 0, 1, 0, 4, 0, 0, 1});
    const TQ3Matrix4x4 b = matrixOf({2, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 5, 0, 0, 0, 1});
    // Row i of a * b = sum_k a[i][k] * row k of b.
    const TQ3Matrix4x4 expected = matrixOf({4, 2, 0, 0, 1, 1, 3, 15, 0, 0, 1, 5, 8, 0, 0, 1});
    TQ3Matrix4x4 r{};
    Q3Matrix4x4_Multiply(&a, &b, &r);
    EXPECT_TRUE(sameBits(r, expected));
}

TEST_F(MathApiTest, MultiplyAllowsTheResultToBeEitherFactor)
{
    const TQ3Matrix4x4 a = matrixOf({1, 2, 0, 0, 0, 1, 3, 0, 0, 0, 1, 0, 4, 0, 0, 1});
    const TQ3Matrix4x4 b = matrixOf({2, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 5, 0, 0, 0, 1});
    TQ3Matrix4x4 expected{};
    Q3Matrix4x4_Multiply(&a, &b, &expected);
    TQ3Matrix4x4 left = a, right = b;
    EXPECT_EQ(Q3Matrix4x4_Multiply(&left, &b, &left), &left);
    EXPECT_EQ(Q3Matrix4x4_Multiply(&a, &right, &right), &right);
    EXPECT_TRUE(sameBits(left, expected));
    EXPECT_TRUE(sameBits(right, expected));
    TQ3Matrix4x4 square = a, squared{};
    Q3Matrix4x4_Multiply(&a, &a, &squared);
    EXPECT_EQ(Q3Matrix4x4_Multiply(&square, &square, &square), &square);
    EXPECT_TRUE(sameBits(square, squared));
}

TEST_F(MathApiTest, MultiplyPropagatesNonFiniteEntries)
{
    TQ3Matrix4x4 nan = kIdentity, r{};
    nan.value[0][0] = kNaN;
    EXPECT_EQ(Q3Matrix4x4_Multiply(&nan, &kIdentity, &r), &r);
    EXPECT_TRUE(std::isnan(r.value[0][0]));
    TQ3Matrix4x4 inf = kIdentity;
    inf.value[3][0] = kInf;
    EXPECT_EQ(Q3Matrix4x4_Multiply(&kIdentity, &inf, &r), &r);
    EXPECT_EQ(r.value[3][0], kInf);
}

TEST_F(MathApiTest, MultiplyRejectsNull)
{
    TQ3Matrix4x4 r{};
    expectEachNullRejected("Q3Matrix4x4_Multiply", Q3Matrix4x4_Multiply, &kIdentity, &kIdentity, &r);
}

TEST_F(MathApiTest, InvertTimesTheMatrixIsTheIdentity)
{
    // A rotation, non-uniform scale, translation and perspective term together.
    const TQ3Matrix4x4 m = matrixOf({0.5f, 1.0f, 0.0f, 0.1f, -2.0f, 0.25f, 1.0f, 0.0f, 0.0f, 3.0f, 2.0f,
                                     -0.2f, 7.0f, -4.0f, 1.5f, 1.0f});
    TQ3Matrix4x4 inverse{}, product{};
    EXPECT_EQ(Q3Matrix4x4_Invert(&m, &inverse), &inverse);
    Q3Matrix4x4_Multiply(&inverse, &m, &product);
    expectMatrixNear(product, kIdentity, 1e-5f, "Invert(M) * M");
    Q3Matrix4x4_Multiply(&m, &inverse, &product);
    expectMatrixNear(product, kIdentity, 1e-5f, "M * Invert(M)");
}

TEST_F(MathApiTest, InvertOfASimpleTransformMatchesHandComputation)
{
    // scale 2 then translate (4,6,8): inverse translates by (-4,-6,-8), scales by 1/2.
    const TQ3Matrix4x4 m = matrixOf({2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 4, 6, 8, 1});
    const TQ3Matrix4x4 expected = matrixOf({0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 0.5f, 0, -2, -3, -4, 1});
    TQ3Matrix4x4 inverse{};
    Q3Matrix4x4_Invert(&m, &inverse);
    expectMatrixNear(inverse, expected, 0.0f, "inverse");
}

TEST_F(MathApiTest, InvertWorksInPlace)
{
    TQ3Matrix4x4 m{};
    Q3Matrix4x4_SetRotate_Z(&m, 0.7f);
    TQ3Matrix4x4 expected{};
    Q3Matrix4x4_SetRotate_Z(&expected, -0.7f);
    EXPECT_EQ(Q3Matrix4x4_Invert(&m, &m), &m);
    expectMatrixNear(m, expected, kTolerance, "inverse rotation");
}

TEST_F(MathApiTest, InvertRejectsSingularMatricesAndLeavesTheResultAlone)
{
    TQ3Matrix4x4 equalRows = matrixOf({1, 2, 3, 4, 1, 2, 3, 4, 0, 0, 1, 0, 0, 0, 0, 1});
    TQ3Matrix4x4 flat{};
    Q3Matrix4x4_SetScale(&flat, 1, 0, 1);
    for (const TQ3Matrix4x4& singular : {filled(0.0f), flat, equalRows}) {
        TQ3Matrix4x4 result = filled(7.0f);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_Invert(&singular, &result), nullptr),
                        kQ3ErrorNonInvertibleMatrix);
        EXPECT_TRUE(sameBits(result, filled(7.0f)));
    }
    // In place, the input is not touched either.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_Invert(&equalRows, &equalRows), nullptr),
                    kQ3ErrorNonInvertibleMatrix);
    EXPECT_EQ(equalRows.value[1][3], 4.0f);
}

TEST_F(MathApiTest, InvertRejectsAnInverseTooLargeForAFloat)
{
    // Determinant 1e-117 is not 0, but the inverse's 1e39 exceeds FLT_MAX.
    TQ3Matrix4x4 tiny{}, result = filled(7.0f);
    Q3Matrix4x4_SetScale(&tiny, 1e-39f, 1e-39f, 1e-39f);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_Invert(&tiny, &result), nullptr), kQ3ErrorNonInvertibleMatrix);
    EXPECT_TRUE(sameBits(result, filled(7.0f)));
    // A small but representable inverse is fine.
    Q3Matrix4x4_SetScale(&tiny, 1e-30f, 1e-30f, 1e-30f);
    ASSERT_EQ(Q3Matrix4x4_Invert(&tiny, &result), &result);
    EXPECT_FLOAT_EQ(result.value[0][0], 1e30f);
}

TEST_F(MathApiTest, InvertRejectsNonFiniteMatrices)
{
    for (float bad : {kNaN, kInf, -kInf}) {
        TQ3Matrix4x4 m = kIdentity, result = filled(7.0f);
        m.value[2][1] = bad;
        m.value[0][0] = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_Invert(&m, &result), nullptr), kQ3ErrorNonInvertibleMatrix);
        EXPECT_TRUE(sameBits(result, filled(7.0f)));
    }
}

TEST_F(MathApiTest, InvertRejectsNull)
{
    TQ3Matrix4x4 r{};
    expectEachNullRejected("Q3Matrix4x4_Invert", Q3Matrix4x4_Invert, &kIdentity, &r);
}

TEST_F(MathApiTest, TransposeSwapsRowsAndColumns)
{
    const TQ3Matrix4x4 m = matrixOf({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16});
    const TQ3Matrix4x4 expected = matrixOf({1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15, 4, 8, 12, 16});
    TQ3Matrix4x4 r{};
    EXPECT_EQ(Q3Matrix4x4_Transpose(&m, &r), &r);
    EXPECT_TRUE(sameBits(r, expected));
    EXPECT_EQ(Q3Matrix4x4_Transpose(&r, &r), &r);
    EXPECT_TRUE(sameBits(r, m));
}

TEST_F(MathApiTest, TransposeCarriesNonFiniteEntries)
{
    TQ3Matrix4x4 m = kIdentity, r{};
    m.value[0][3] = kNaN;
    m.value[1][2] = kInf;
    m.value[3][2] = -kInf;
    Q3Matrix4x4_Transpose(&m, &r);
    EXPECT_TRUE(std::isnan(r.value[3][0]));
    EXPECT_EQ(r.value[2][1], kInf);
    EXPECT_EQ(r.value[2][3], -kInf);
}

TEST_F(MathApiTest, TransposeRejectsNull)
{
    TQ3Matrix4x4 r{};
    expectEachNullRejected("Q3Matrix4x4_Transpose", Q3Matrix4x4_Transpose, &kIdentity, &r);
}

TEST_F(MathApiTest, CopyCopiesEveryBit)
{
    TQ3Matrix4x4 m = matrixOf({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16});
    m.value[1][1] = kNaN;
    m.value[2][2] = -kInf;
    TQ3Matrix4x4 r = filled(0.0f);
    EXPECT_EQ(Q3Matrix4x4_Copy(&m, &r), &r);
    EXPECT_TRUE(sameBits(r, m));
    EXPECT_EQ(Q3Matrix4x4_Copy(&r, &r), &r);
    EXPECT_TRUE(sameBits(r, m));
}

TEST_F(MathApiTest, CopyRejectsNull)
{
    TQ3Matrix4x4 r{};
    expectEachNullRejected("Q3Matrix4x4_Copy", Q3Matrix4x4_Copy, &kIdentity, &r);
}

// ---- Before Q3Initialize ------------------------------------------------------

TEST(MathApiUninitialized, EveryFunctionFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    TQ3Point3D p{1, 2, 3};
    TQ3Vector3D v{1, 0, 0};
    TQ3RationalPoint4D p4{1, 2, 3, 1};
    TQ3Matrix4x4 m = kIdentity, r = kIdentity;
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };

    EXPECT_EQ(Q3Point3D_Set(&p, 0, 0, 0), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(p.x, 1.0f);
    EXPECT_EQ(Q3Vector3D_Set(&v, 0, 0, 0), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3RationalPoint4D_Set(&p4, 0, 0, 0, 0), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Point3D_Distance(&p, &p), 0.0f);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector3D_Length(&v), 0.0f);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector3D_Normalize(&v, &v), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector3D_Cross(&v, &v, &v), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Vector3D_Dot(&v, &v), 0.0f);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Point3D_Transform(&p, &m, &p), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3RationalPoint4D_Transform(&p4, &m, &p4), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Matrix4x4_SetIdentity(&r), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Matrix4x4_SetTranslate(&r, 1, 2, 3), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Matrix4x4_SetScale(&r, 1, 2, 3), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Matrix4x4_SetRotate_X(&r, 1), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Matrix4x4_SetRotate_Y(&r, 1), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Matrix4x4_SetRotate_Z(&r, 1), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Matrix4x4_SetRotateAboutAxis(&r, &p, &v, 1), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Matrix4x4_Multiply(&m, &m, &r), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Matrix4x4_Invert(&m, &r), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Matrix4x4_Transpose(&m, &r), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Matrix4x4_Copy(&m, &r), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_TRUE(sameBits(r, kIdentity));
}

} // namespace
