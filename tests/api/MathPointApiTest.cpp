// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DMath.h's point calls that MathApiTest.cpp does not cover: 2-D,
// parametric, rational, polar and spherical points; differences, distances,
// relative ratios, affine combinations and 2-D transforms.

#include "MathTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DMath.h"

#include <climits>
#include <cmath>
#include <vector>

namespace {

using namespace q3test;
using MathPointApiTest = Q3ApiTest;

// One point of each kind the affine combinations take, each with weight 1,
// and a zeroed result of each kind.
struct OnePointOfEachKind {
    TQ3Point2D p2[1] = {{1, 2}};
    TQ3Param2D u[1] = {{1, 2}};
    TQ3RationalPoint3D r3[1] = {{1, 2, 1}};
    TQ3Point3D p3[1] = {{1, 2, 3}};
    TQ3RationalPoint4D r4[1] = {{1, 2, 3, 1}};
    float w[1] = {1};
    TQ3Point2D o2{};
    TQ3Param2D ou{};
    TQ3RationalPoint3D o3{};
    TQ3Point3D op3{};
    TQ3RationalPoint4D o4{};

    /// Calls check(affineComb, points, result) for each kind's
    /// Q3*_AffineComb with its one point and its result.
    template <class Check>
    void forEachAffineComb(Check&& check)
    {
        check(Q3Point2D_AffineComb, p2, o2);
        check(Q3Param2D_AffineComb, u, ou);
        check(Q3RationalPoint3D_AffineComb, r3, o3);
        check(Q3Point3D_AffineComb, p3, op3);
        check(Q3RationalPoint4D_AffineComb, r4, o4);
    }
};

// Angles come from sines and cosines rounded to float: a few ulps at 2 pi.
constexpr float kAngleTolerance = 2e-6f;

// ---- Setting ----------------------------------------------------------------------

TEST_F(MathPointApiTest, SettersStoreTheirValuesAsGiven)
{
    TQ3Point2D p2{};
    EXPECT_EQ(Q3Point2D_Set(&p2, 1.5f, kNaN), &p2);
    EXPECT_EQ(p2.x, 1.5f);
    EXPECT_TRUE(std::isnan(p2.y));
    TQ3Param2D uv{};
    EXPECT_EQ(Q3Param2D_Set(&uv, 0.25f, -kInf), &uv);
    EXPECT_EQ(uv.u, 0.25f);
    EXPECT_EQ(uv.v, -kInf);
    TQ3RationalPoint3D r3{};
    EXPECT_EQ(Q3RationalPoint3D_Set(&r3, 1, 2, 0.5f), &r3);
    EXPECT_EQ(r3.x, 1.0f);
    EXPECT_EQ(r3.y, 2.0f);
    EXPECT_EQ(r3.w, 0.5f);
    TQ3PolarPoint polar{};
    EXPECT_EQ(Q3PolarPoint_Set(&polar, -2, 7.5f), &polar); // any values: no range check
    EXPECT_EQ(polar.r, -2.0f);
    EXPECT_EQ(polar.theta, 7.5f);
    TQ3SphericalPoint sphere{};
    EXPECT_EQ(Q3SphericalPoint_Set(&sphere, 3, kInf, kNaN), &sphere);
    EXPECT_EQ(sphere.rho, 3.0f);
    EXPECT_EQ(sphere.theta, kInf);
    EXPECT_TRUE(std::isnan(sphere.phi));
}

TEST_F(MathPointApiTest, SettersRejectNull)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point2D_Set(nullptr, 1, 2), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Param2D_Set(nullptr, 1, 2), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RationalPoint3D_Set(nullptr, 1, 2, 1), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PolarPoint_Set(nullptr, 1, 2), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3SphericalPoint_Set(nullptr, 1, 2, 3), nullptr), kQ3ErrorNULLParameter);
}

// ---- Converting dimensions ----------------------------------------------------------

TEST_F(MathPointApiTest, GoingUpAppendsOne)
{
    const TQ3Point2D p2{3, -4};
    TQ3Point3D r3{};
    EXPECT_EQ(Q3Point2D_To3D(&p2, &r3), &r3);
    EXPECT_TRUE(sameBits(r3, TQ3Point3D{3, -4, 1}));
    const TQ3Point3D p3{kNaN, kInf, 5};
    TQ3RationalPoint4D r4{};
    EXPECT_EQ(Q3Point3D_To4D(&p3, &r4), &r4);
    EXPECT_TRUE(std::isnan(r4.x));
    EXPECT_EQ(r4.y, kInf);
    EXPECT_EQ(r4.z, 5.0f);
    EXPECT_EQ(r4.w, 1.0f);
}

TEST_F(MathPointApiTest, GoingDownDividesByTheLastCoordinateUnlessItIsZero)
{
    const TQ3RationalPoint3D a{6, -9, 3}, atInfinity{6, -9, 0}, negativeZero{6, -9, -0.0f};
    TQ3Point2D r2{};
    EXPECT_EQ(Q3RationalPoint3D_To2D(&a, &r2), &r2);
    EXPECT_EQ(r2.x, 2.0f);
    EXPECT_EQ(r2.y, -3.0f);
    EXPECT_EQ(Q3RationalPoint3D_To2D(&atInfinity, &r2), &r2);
    EXPECT_EQ(r2.x, 6.0f);
    EXPECT_EQ(r2.y, -9.0f);
    EXPECT_EQ(Q3RationalPoint3D_To2D(&negativeZero, &r2), &r2);
    EXPECT_EQ(r2.x, 6.0f);

    const TQ3RationalPoint4D b{2, 4, -6, 2}, flat{2, 4, -6, 0}, nan{1, 1, 1, kNaN}, inf{1, 1, 1, kInf};
    TQ3Point3D r3{};
    EXPECT_EQ(Q3RationalPoint4D_To3D(&b, &r3), &r3);
    EXPECT_EQ(r3.x, 1.0f);
    EXPECT_EQ(r3.y, 2.0f);
    EXPECT_EQ(r3.z, -3.0f);
    EXPECT_EQ(Q3RationalPoint4D_To3D(&flat, &r3), &r3);
    EXPECT_EQ(r3.z, -6.0f);
    Q3RationalPoint4D_To3D(&nan, &r3);
    EXPECT_TRUE(std::isnan(r3.x));
    Q3RationalPoint4D_To3D(&inf, &r3);
    EXPECT_EQ(r3.y, 0.0f);
}

TEST_F(MathPointApiTest, ConversionsRejectNullAndLeaveTheResultAlone)
{
    const TQ3Point2D p2{1, 2};
    const TQ3Point3D p3{1, 2, 3};
    const TQ3RationalPoint3D r3{1, 2, 1};
    const TQ3RationalPoint4D r4{1, 2, 3, 1};
    TQ3Point2D out2 = filledWith<TQ3Point2D>(7);
    TQ3Point3D out3 = filledWith<TQ3Point3D>(7);
    TQ3RationalPoint4D out4 = filledWith<TQ3RationalPoint4D>(7);
    expectEachNullRejected("Q3Point2D_To3D", Q3Point2D_To3D, &p2, &out3);
    expectEachNullRejected("Q3RationalPoint3D_To2D", Q3RationalPoint3D_To2D, &r3, &out2);
    expectEachNullRejected("Q3Point3D_To4D", Q3Point3D_To4D, &p3, &out4);
    expectEachNullRejected("Q3RationalPoint4D_To3D", Q3RationalPoint4D_To3D, &r4, &out3);
    EXPECT_TRUE(sameBits(out2, filledWith<TQ3Point2D>(7)));
    EXPECT_TRUE(sameBits(out3, filledWith<TQ3Point3D>(7)));
    EXPECT_TRUE(sameBits(out4, filledWith<TQ3RationalPoint4D>(7)));
}

// ---- Differences and moves --------------------------------------------------------------

TEST_F(MathPointApiTest, SubtractingPointsGivesTheVectorFromTheSecondToTheFirst)
{
    const TQ3Point2D a{5, 1}, b{2, 3};
    TQ3Vector2D v{};
    EXPECT_EQ(Q3Point2D_Subtract(&a, &b, &v), &v);
    EXPECT_EQ(v.x, 3.0f);
    EXPECT_EQ(v.y, -2.0f);
    const TQ3Param2D u1{0.75f, 0.5f}, u2{0.25f, 1};
    EXPECT_EQ(Q3Param2D_Subtract(&u1, &u2, &v), &v);
    EXPECT_EQ(v.x, 0.5f);
    EXPECT_EQ(v.y, -0.5f);
    const TQ3Point3D c{1, 2, 3}, d{kInf, 2, kNaN};
    TQ3Vector3D w{};
    EXPECT_EQ(Q3Point3D_Subtract(&c, &d, &w), &w);
    EXPECT_EQ(w.x, -kInf);
    EXPECT_EQ(w.y, 0.0f);
    EXPECT_TRUE(std::isnan(w.z));
}

TEST_F(MathPointApiTest, MovingAPointByAVectorWorksInPlace)
{
    TQ3Point2D p{1, 2};
    const TQ3Vector2D v{0.5f, -4};
    EXPECT_EQ(Q3Point2D_Vector2D_Add(&p, &v, &p), &p);
    EXPECT_EQ(p.x, 1.5f);
    EXPECT_EQ(p.y, -2.0f);
    EXPECT_EQ(Q3Point2D_Vector2D_Subtract(&p, &v, &p), &p);
    EXPECT_EQ(p.x, 1.0f);
    EXPECT_EQ(p.y, 2.0f);
    TQ3Param2D uv{0.25f, 0.75f};
    EXPECT_EQ(Q3Param2D_Vector2D_Add(&uv, &v, &uv), &uv);
    EXPECT_EQ(uv.u, 0.75f);
    EXPECT_EQ(uv.v, -3.25f);
    EXPECT_EQ(Q3Param2D_Vector2D_Subtract(&uv, &v, &uv), &uv);
    EXPECT_EQ(uv.u, 0.25f);
    EXPECT_EQ(uv.v, 0.75f);
    TQ3Point3D q{1, 2, 3};
    const TQ3Vector3D w{10, kInf, kNaN};
    TQ3Point3D r{};
    EXPECT_EQ(Q3Point3D_Vector3D_Add(&q, &w, &r), &r);
    EXPECT_EQ(r.x, 11.0f);
    EXPECT_EQ(r.y, kInf);
    EXPECT_TRUE(std::isnan(r.z));
    EXPECT_EQ(Q3Point3D_Vector3D_Subtract(&q, &w, &q), &q);
    EXPECT_EQ(q.x, -9.0f);
    EXPECT_EQ(q.y, -kInf);
}

TEST_F(MathPointApiTest, DifferencesAndMovesRejectNull)
{
    const TQ3Point2D p2{1, 2};
    const TQ3Param2D u{1, 2};
    const TQ3Point3D p3{1, 2, 3};
    const TQ3Vector2D v2{1, 2};
    const TQ3Vector3D v3{1, 2, 3};
    TQ3Vector2D rv2{};
    TQ3Vector3D rv3{};
    TQ3Point2D rp2{};
    TQ3Param2D ru{};
    TQ3Point3D rp3{};
    expectEachNullRejected("Q3Point2D_Subtract", Q3Point2D_Subtract, &p2, &p2, &rv2);
    expectEachNullRejected("Q3Param2D_Subtract", Q3Param2D_Subtract, &u, &u, &rv2);
    expectEachNullRejected("Q3Point3D_Subtract", Q3Point3D_Subtract, &p3, &p3, &rv3);
    expectEachNullRejected("Q3Point2D_Vector2D_Add", Q3Point2D_Vector2D_Add, &p2, &v2, &rp2);
    expectEachNullRejected("Q3Param2D_Vector2D_Add", Q3Param2D_Vector2D_Add, &u, &v2, &ru);
    expectEachNullRejected("Q3Point3D_Vector3D_Add", Q3Point3D_Vector3D_Add, &p3, &v3, &rp3);
    expectEachNullRejected("Q3Point2D_Vector2D_Subtract", Q3Point2D_Vector2D_Subtract, &p2, &v2, &rp2);
    expectEachNullRejected("Q3Param2D_Vector2D_Subtract", Q3Param2D_Vector2D_Subtract, &u, &v2, &ru);
    expectEachNullRejected("Q3Point3D_Vector3D_Subtract", Q3Point3D_Vector3D_Subtract, &p3, &v3, &rp3);
}

TEST_F(MathPointApiTest, CrossProductTriIsTheTriangleNormal)
{
    const TQ3Point3D o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0};
    TQ3Vector3D n{};
    EXPECT_EQ(Q3Point3D_CrossProductTri(&o, &x, &y, &n), &n); // counterclockwise seen from +z
    EXPECT_EQ(n.x, 0.0f);
    EXPECT_EQ(n.y, 0.0f);
    EXPECT_EQ(n.z, 1.0f);
    // (p2 - p1) x (p3 - p1) = (3, 4, 2) x (1, 3, 4) = (4*4 - 2*3, 2*1 - 3*4, 3*3 - 4*1).
    const TQ3Point3D p1{1, 2, 3}, p2{4, 6, 5}, p3{2, 5, 7};
    EXPECT_EQ(Q3Point3D_CrossProductTri(&p1, &p2, &p3, &n), &n);
    EXPECT_EQ(n.x, 10.0f);
    EXPECT_EQ(n.y, -10.0f);
    EXPECT_EQ(n.z, 5.0f);
    EXPECT_EQ(Q3Point3D_CrossProductTri(&p1, &p1, &p3, &n), &n); // degenerate: zero, no error
    EXPECT_EQ(n.x, 0.0f);
    const TQ3Point3D nan{kNaN, 0, 0};
    Q3Point3D_CrossProductTri(&o, &nan, &y, &n);
    EXPECT_TRUE(std::isnan(n.z));
    expectEachNullRejected("Q3Point3D_CrossProductTri", Q3Point3D_CrossProductTri, &o, &x, &y, &n);
}

// ---- Distances ------------------------------------------------------------------------------

TEST_F(MathPointApiTest, TwoDimensionalDistancesAreEuclidean)
{
    const TQ3Point2D a{1, 1}, b{4, 5};
    EXPECT_EQ(Q3Point2D_Distance(&a, &b), 5.0f);
    EXPECT_EQ(Q3Point2D_DistanceSquared(&a, &b), 25.0f);
    const TQ3Param2D u{0.5f, 0}, v{0.5f, 0.25f};
    EXPECT_EQ(Q3Param2D_Distance(&u, &v), 0.25f);
    EXPECT_EQ(Q3Param2D_DistanceSquared(&u, &v), 0.0625f);
    const TQ3Point2D far{3e30f, 4e30f}, origin{0, 0};
    EXPECT_FLOAT_EQ(Q3Point2D_Distance(&origin, &far), 5e30f);  // no overflow
    EXPECT_EQ(Q3Point2D_DistanceSquared(&origin, &far), kInf);  // 2.5e61 is not a float
}

TEST_F(MathPointApiTest, RationalDistancesMeasureThePointsTheyStandFor)
{
    // (2, 4, 2) is (1, 2); (9, 12, 3) is (3, 4): sqrt(2^2 + 2^2).
    const TQ3RationalPoint3D a{2, 4, 2}, b{9, 12, 3}, atInfinity{3, 4, 0};
    EXPECT_FLOAT_EQ(Q3RationalPoint3D_Distance(&a, &b), float(std::sqrt(8.0)));
    EXPECT_EQ(Q3RationalPoint3D_DistanceSquared(&a, &b), 8.0f);
    EXPECT_EQ(Q3RationalPoint3D_Distance(&a, &atInfinity), float(std::sqrt(2.0 * 2 + 2 * 2))); // undivided (3, 4)
    // (2, 4, 6, 2) is (1, 2, 3); (2, 4, 6, 1) is itself: sqrt(1 + 4 + 9).
    const TQ3RationalPoint4D c{2, 4, 6, 2}, d{2, 4, 6, 1};
    EXPECT_FLOAT_EQ(Q3RationalPoint4D_Distance(&c, &d), float(std::sqrt(14.0)));
    EXPECT_EQ(Q3RationalPoint4D_DistanceSquared(&c, &d), 14.0f);
    const TQ3Point3D p{1, 2, 3}, q{4, 6, 3};
    EXPECT_EQ(Q3Point3D_DistanceSquared(&p, &q), 25.0f);
}

TEST_F(MathPointApiTest, DistancesPropagateNonFiniteCoordinates)
{
    const TQ3Point2D a{0, 0}, nan{kNaN, 0}, inf{0, kInf};
    EXPECT_TRUE(std::isnan(Q3Point2D_Distance(&a, &nan)));
    EXPECT_EQ(Q3Point2D_DistanceSquared(&a, &inf), kInf);
    const TQ3RationalPoint4D w{1, 1, 1, kNaN}, one{1, 1, 1, 1};
    EXPECT_TRUE(std::isnan(Q3RationalPoint4D_Distance(&w, &one)));
    const TQ3RationalPoint3D infW{1, 1, kInf}, r{0, 0, 1};
    EXPECT_EQ(Q3RationalPoint3D_Distance(&infW, &r), 0.0f); // 1 / inf = 0
    const TQ3Point3D p{0, 0, 0}, minusInf{0, -kInf, 0};
    EXPECT_EQ(Q3Point3D_DistanceSquared(&p, &minusInf), kInf);
}

TEST_F(MathPointApiTest, DistancesRejectNullAndReturnZero)
{
    const TQ3Point2D p2{1, 2};
    const TQ3Param2D u{1, 2};
    const TQ3RationalPoint3D r3{1, 2, 1};
    const TQ3Point3D p3{1, 2, 3};
    const TQ3RationalPoint4D r4{1, 2, 3, 1};
    expectEachNullRejected("Q3Point2D_Distance", Q3Point2D_Distance, &p2, &p2);
    expectEachNullRejected("Q3Point2D_DistanceSquared", Q3Point2D_DistanceSquared, &p2, &p2);
    expectEachNullRejected("Q3Param2D_Distance", Q3Param2D_Distance, &u, &u);
    expectEachNullRejected("Q3Param2D_DistanceSquared", Q3Param2D_DistanceSquared, &u, &u);
    expectEachNullRejected("Q3RationalPoint3D_Distance", Q3RationalPoint3D_Distance, &r3, &r3);
    expectEachNullRejected("Q3RationalPoint3D_DistanceSquared", Q3RationalPoint3D_DistanceSquared, &r3, &r3);
    expectEachNullRejected("Q3Point3D_DistanceSquared", Q3Point3D_DistanceSquared, &p3, &p3);
    expectEachNullRejected("Q3RationalPoint4D_Distance", Q3RationalPoint4D_Distance, &r4, &r4);
    expectEachNullRejected("Q3RationalPoint4D_DistanceSquared", Q3RationalPoint4D_DistanceSquared, &r4, &r4);
}

// ---- Relative ratios ----------------------------------------------------------------------------

TEST_F(MathPointApiTest, RRatioGoesTheFractionR2OverR1PlusR2FromP1)
{
    // r1 = 1, r2 = 3: three quarters of the way, as the QuickDraw 3D 1.6
    // library does it (its book says r1 / (r1 + r2)).
    const TQ3Point2D a{0, 0}, b{4, 8};
    TQ3Point2D r{};
    EXPECT_EQ(Q3Point2D_RRatio(&a, &b, 1, 3, &r), &r);
    EXPECT_EQ(r.x, 3.0f);
    EXPECT_EQ(r.y, 6.0f);
    const TQ3Param2D u{1, 0}, v{0, 1};
    TQ3Param2D ru{};
    EXPECT_EQ(Q3Param2D_RRatio(&u, &v, 3, 1, &ru), &ru);
    EXPECT_EQ(ru.u, 0.75f);
    EXPECT_EQ(ru.v, 0.25f);
    TQ3Point3D p{1, 2, 3};
    const TQ3Point3D q{5, 10, -1};
    EXPECT_EQ(Q3Point3D_RRatio(&p, &q, 2, 2, &p), &p); // the midpoint, in place
    EXPECT_EQ(p.x, 3.0f);
    EXPECT_EQ(p.y, 6.0f);
    EXPECT_EQ(p.z, 1.0f);
    // Extrapolation: r1 = -1, r2 = 2 is 2 / 1 of the way.
    TQ3Point3D e{0, 0, 0};
    const TQ3Point3D f{1, 2, 3};
    EXPECT_EQ(Q3Point3D_RRatio(&e, &f, -1, 2, &e), &e);
    EXPECT_EQ(e.x, 2.0f);
    EXPECT_EQ(e.z, 6.0f);
}

TEST_F(MathPointApiTest, RationalRRatioInterpolatesTheWeightToo)
{
    const TQ3RationalPoint4D a{0, 0, 0, 1};
    TQ3RationalPoint4D b{4, 8, 12, 3};
    EXPECT_EQ(Q3RationalPoint4D_RRatio(&a, &b, 1, 1, &b), &b); // result is p2
    EXPECT_EQ(b.x, 2.0f);
    EXPECT_EQ(b.y, 4.0f);
    EXPECT_EQ(b.z, 6.0f);
    EXPECT_EQ(b.w, 2.0f);
}

TEST_F(MathPointApiTest, RRatioRejectsRatiosThatSumToZeroAndNull)
{
    const TQ3Point2D a{0, 0}, b{1, 1};
    TQ3Point2D r = filledWith<TQ3Point2D>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point2D_RRatio(&a, &b, 0, 0, &r), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point2D_RRatio(&a, &b, 2, -2, &r), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_TRUE(sameBits(r, filledWith<TQ3Point2D>(7)));
    const TQ3Param2D u{0, 0};
    TQ3Param2D ru = filledWith<TQ3Param2D>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Param2D_RRatio(&u, &u, -0.5f, 0.5f, &ru), nullptr), kQ3ErrorInvalidParameter);
    const TQ3Point3D p{0, 0, 0};
    TQ3Point3D rp = filledWith<TQ3Point3D>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_RRatio(&p, &p, 0, -0.0f, &rp), nullptr), kQ3ErrorInvalidParameter);
    const TQ3RationalPoint4D w{0, 0, 0, 1};
    TQ3RationalPoint4D rw = filledWith<TQ3RationalPoint4D>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RationalPoint4D_RRatio(&w, &w, 1, -1, &rw), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_TRUE(sameBits(ru, filledWith<TQ3Param2D>(7)));
    EXPECT_TRUE(sameBits(rp, filledWith<TQ3Point3D>(7)));
    EXPECT_TRUE(sameBits(rw, filledWith<TQ3RationalPoint4D>(7)));

    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point2D_RRatio(nullptr, &b, 1, 1, &r), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point2D_RRatio(&a, nullptr, 1, 1, &r), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point2D_RRatio(&a, &b, 1, 1, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Param2D_RRatio(nullptr, &u, 1, 1, &ru), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Param2D_RRatio(&u, nullptr, 1, 1, &ru), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Param2D_RRatio(&u, &u, 1, 1, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_RRatio(nullptr, &p, 1, 1, &rp), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_RRatio(&p, nullptr, 1, 1, &rp), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_RRatio(&p, &p, 1, 1, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RationalPoint4D_RRatio(nullptr, &w, 1, 1, &rw), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RationalPoint4D_RRatio(&w, nullptr, 1, 1, &rw), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RationalPoint4D_RRatio(&w, &w, 1, 1, nullptr), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(MathPointApiTest, RRatioPropagatesNonFiniteRatiosAndCoordinates)
{
    const TQ3Point3D a{0, 0, 0}, b{1, 1, 1}, nan{kNaN, 0, 0};
    TQ3Point3D r{};
    EXPECT_EQ(Q3Point3D_RRatio(&a, &b, kNaN, 1, &r), &r); // NaN passes the zero test
    EXPECT_TRUE(std::isnan(r.x));
    EXPECT_EQ(Q3Point3D_RRatio(&a, &b, kInf, 1, &r), &r); // 1 / inf of the way: p1
    EXPECT_EQ(r.x, 0.0f);
    EXPECT_EQ(Q3Point3D_RRatio(&a, &b, kInf, kInf, &r), &r); // inf / inf
    EXPECT_TRUE(std::isnan(r.y));
    EXPECT_EQ(Q3Point3D_RRatio(&nan, &b, 1, 1, &r), &r);
    EXPECT_TRUE(std::isnan(r.x));
    EXPECT_EQ(r.y, 0.5f);
}

// ---- Transforming 2-D points ------------------------------------------------------------------------

TEST_F(MathPointApiTest, Point2DTransformMultipliesThenDividesByW)
{
    const TQ3Matrix3x3 m = matrix3x3Of({2, 1, 0.5f, -1, 3, 0.25f, 4, -2, 1});
    TQ3Point2D p{1.5f, -2};
    const double in[3] = {1.5, -2, 1};
    double h[3];
    rowTimes(in, m, h);
    EXPECT_EQ(Q3Point2D_Transform(&p, &m, &p), &p); // in place
    EXPECT_FLOAT_EQ(p.x, float(h[0] / h[2]));
    EXPECT_FLOAT_EQ(p.y, float(h[1] / h[2]));
    TQ3Param2D uv{1.5f, -2};
    EXPECT_EQ(Q3Param2D_Transform(&uv, &m, &uv), &uv);
    EXPECT_FLOAT_EQ(uv.u, float(h[0] / h[2]));
    EXPECT_FLOAT_EQ(uv.v, float(h[1] / h[2]));
}

TEST_F(MathPointApiTest, Point2DTransformTranslatesAndLeavesAPointAtInfinityUndivided)
{
    const TQ3Matrix3x3 shift = matrix3x3Of({1, 0, 0, 0, 1, 0, 10, -20, 1});
    const TQ3Point2D p{1, 2};
    TQ3Point2D r{};
    Q3Point2D_Transform(&p, &shift, &r);
    EXPECT_EQ(r.x, 11.0f);
    EXPECT_EQ(r.y, -18.0f);
    // w' = x * 1 + y * 0 + 1 * -1 = 0 for x = 1.
    const TQ3Matrix3x3 project = matrix3x3Of({1, 0, 1, 0, 1, 0, 0, 0, -1});
    Q3Point2D_Transform(&p, &project, &r);
    EXPECT_EQ(r.x, 1.0f);
    EXPECT_EQ(r.y, 2.0f);
    const TQ3Point2D nan{kNaN, 0};
    Q3Point2D_Transform(&nan, &kIdentity3x3, &r);
    EXPECT_TRUE(std::isnan(r.x));
}

TEST_F(MathPointApiTest, Point2DTransformsRejectNull)
{
    const TQ3Point2D p{1, 2};
    const TQ3Param2D u{1, 2};
    TQ3Point2D r{};
    TQ3Param2D ru{};
    expectEachNullRejected("Q3Point2D_Transform", Q3Point2D_Transform, &p, &kIdentity3x3, &r);
    expectEachNullRejected("Q3Param2D_Transform", Q3Param2D_Transform, &u, &kIdentity3x3, &ru);
}

// ---- Polar and spherical coordinates -------------------------------------------------------------------

TEST_F(MathPointApiTest, ToPolarMeasuresTheAngleCounterclockwiseFromPlusXInZeroToTwoPi)
{
    struct Case {
        TQ3Point2D point;
        double r, theta;
    };
    const double root2 = std::sqrt(2.0);
    for (const Case& c : {Case{{1, 1}, root2, kPi / 4}, Case{{-1, 0}, 1, kPi}, Case{{0, -2}, 2, 3 * kPi / 2},
                          Case{{1, -1}, root2, 7 * kPi / 4}, Case{{3, 0}, 3, 0},
                          Case{{-3, 4}, 5, kPi - std::atan(4.0 / 3)}}) {
        TQ3PolarPoint polar{};
        ASSERT_EQ(Q3Point2D_ToPolar(&c.point, &polar), &polar);
        EXPECT_FLOAT_EQ(polar.r, float(c.r)) << c.point.x << ", " << c.point.y;
        EXPECT_NEAR(polar.theta, c.theta, kAngleTolerance) << c.point.x << ", " << c.point.y;
        EXPECT_GE(polar.theta, 0.0f);
    }
    const TQ3Point2D origin{0, 0}, negativeZero{-0.0f, 0};
    TQ3PolarPoint polar{};
    Q3Point2D_ToPolar(&origin, &polar);
    EXPECT_TRUE(sameBits(polar, TQ3PolarPoint{0, 0}));
    Q3Point2D_ToPolar(&negativeZero, &polar);
    EXPECT_TRUE(sameBits(polar, TQ3PolarPoint{0, 0}));
}

TEST_F(MathPointApiTest, PolarToPointAndBackRoundTrips)
{
    const TQ3PolarPoint polar{2, float(5 * kPi / 6)};
    TQ3Point2D p{};
    EXPECT_EQ(Q3PolarPoint_ToPoint2D(&polar, &p), &p);
    EXPECT_NEAR(p.x, 2 * std::cos(5 * kPi / 6), 1e-6);
    EXPECT_NEAR(p.y, 2 * std::sin(5 * kPi / 6), 1e-6);
    TQ3PolarPoint back{};
    Q3Point2D_ToPolar(&p, &back);
    EXPECT_FLOAT_EQ(back.r, 2.0f);
    EXPECT_NEAR(back.theta, polar.theta, kAngleTolerance);
    // Any r and theta: a negative radius points the other way.
    const TQ3PolarPoint odd{-1, float(4 * kPi)};
    Q3PolarPoint_ToPoint2D(&odd, &p);
    EXPECT_NEAR(p.x, -1.0f, 1e-6);
    EXPECT_NEAR(p.y, 0.0f, 1e-6);
    const TQ3PolarPoint nan{1, kNaN};
    Q3PolarPoint_ToPoint2D(&nan, &p);
    EXPECT_TRUE(std::isnan(p.x) && std::isnan(p.y));
    const TQ3Point2D inf{kInf, 0};
    Q3Point2D_ToPolar(&inf, &back);
    EXPECT_EQ(back.r, kInf);
    EXPECT_EQ(back.theta, 0.0f);
}

TEST_F(MathPointApiTest, ToSphericalMeasuresPhiFromPlusZ)
{
    struct Case {
        TQ3Point3D point;
        double rho, theta, phi;
    };
    const double root2 = std::sqrt(2.0);
    for (const Case& c :
         {Case{{0, 0, 5}, 5, 0, 0}, Case{{0, 0, -5}, 5, 0, kPi}, Case{{1, 0, 0}, 1, 0, kPi / 2},
          Case{{0, 2, 0}, 2, kPi / 2, kPi / 2}, Case{{1, 1, float(root2)}, 2, kPi / 4, kPi / 4},
          Case{{0, -3, -3}, 3 * root2, 3 * kPi / 2, 3 * kPi / 4}}) {
        TQ3SphericalPoint s{};
        ASSERT_EQ(Q3Point3D_ToSpherical(&c.point, &s), &s);
        EXPECT_FLOAT_EQ(s.rho, float(c.rho)) << c.point.x << ", " << c.point.y << ", " << c.point.z;
        EXPECT_NEAR(s.theta, c.theta, kAngleTolerance) << c.point.x << ", " << c.point.y << ", " << c.point.z;
        EXPECT_NEAR(s.phi, c.phi, kAngleTolerance) << c.point.x << ", " << c.point.y << ", " << c.point.z;
    }
    const TQ3Point3D origin{0, -0.0f, 0};
    TQ3SphericalPoint s{};
    Q3Point3D_ToSpherical(&origin, &s);
    EXPECT_TRUE(sameBits(s, TQ3SphericalPoint{0, 0, 0}));
}

TEST_F(MathPointApiTest, SphericalToPointAndBackRoundTrips)
{
    const TQ3SphericalPoint s{3, float(2 * kPi / 3), float(kPi / 3)};
    TQ3Point3D p{};
    EXPECT_EQ(Q3SphericalPoint_ToPoint3D(&s, &p), &p);
    EXPECT_NEAR(p.x, 3 * std::sin(kPi / 3) * std::cos(2 * kPi / 3), 1e-6);
    EXPECT_NEAR(p.y, 3 * std::sin(kPi / 3) * std::sin(2 * kPi / 3), 1e-6);
    EXPECT_NEAR(p.z, 3 * std::cos(kPi / 3), 1e-6);
    TQ3SphericalPoint back{};
    Q3Point3D_ToSpherical(&p, &back);
    EXPECT_FLOAT_EQ(back.rho, 3.0f);
    EXPECT_NEAR(back.theta, s.theta, kAngleTolerance);
    EXPECT_NEAR(back.phi, s.phi, kAngleTolerance);
    const TQ3SphericalPoint nan{kNaN, 0, 0};
    Q3SphericalPoint_ToPoint3D(&nan, &p);
    EXPECT_TRUE(std::isnan(p.z));
    const TQ3Point3D inf{0, 0, -kInf};
    Q3Point3D_ToSpherical(&inf, &back);
    EXPECT_EQ(back.rho, kInf);
    EXPECT_NEAR(back.phi, kPi, kAngleTolerance);
    const TQ3Point3D nanPoint{kNaN, 1, 1};
    Q3Point3D_ToSpherical(&nanPoint, &back);
    EXPECT_TRUE(std::isnan(back.rho) && std::isnan(back.theta) && std::isnan(back.phi));
}

TEST_F(MathPointApiTest, PolarAndSphericalConversionsRejectNull)
{
    const TQ3Point2D p2{1, 2};
    const TQ3Point3D p3{1, 2, 3};
    const TQ3PolarPoint polar{1, 1};
    const TQ3SphericalPoint sphere{1, 1, 1};
    TQ3PolarPoint rPolar = filledWith<TQ3PolarPoint>(7);
    TQ3SphericalPoint rSphere = filledWith<TQ3SphericalPoint>(7);
    TQ3Point2D r2 = filledWith<TQ3Point2D>(7);
    TQ3Point3D r3 = filledWith<TQ3Point3D>(7);
    expectEachNullRejected("Q3Point2D_ToPolar", Q3Point2D_ToPolar, &p2, &rPolar);
    expectEachNullRejected("Q3PolarPoint_ToPoint2D", Q3PolarPoint_ToPoint2D, &polar, &r2);
    expectEachNullRejected("Q3Point3D_ToSpherical", Q3Point3D_ToSpherical, &p3, &rSphere);
    expectEachNullRejected("Q3SphericalPoint_ToPoint3D", Q3SphericalPoint_ToPoint3D, &sphere, &r3);
    EXPECT_TRUE(sameBits(rPolar, filledWith<TQ3PolarPoint>(7)));
    EXPECT_TRUE(sameBits(rSphere, filledWith<TQ3SphericalPoint>(7)));
    EXPECT_TRUE(sameBits(r2, filledWith<TQ3Point2D>(7)));
    EXPECT_TRUE(sameBits(r3, filledWith<TQ3Point3D>(7)));
}

// ---- Affine combinations ---------------------------------------------------------------------------------

TEST_F(MathPointApiTest, AffineCombinationsWithWeightsSummingToOne)
{
    // 0.25 (0, 0) + 0.25 (4, 0) + 0.5 (0, 8) = (1, 4).
    const TQ3Point2D p2[] = {{0, 0}, {4, 0}, {0, 8}};
    const float w[] = {0.25f, 0.25f, 0.5f};
    TQ3Point2D r2{};
    EXPECT_EQ(Q3Point2D_AffineComb(p2, w, 3, &r2), &r2);
    EXPECT_EQ(r2.x, 1.0f);
    EXPECT_EQ(r2.y, 4.0f);
    const TQ3Param2D u[] = {{0, 0}, {1, 0}, {0, 1}};
    TQ3Param2D ru{};
    EXPECT_EQ(Q3Param2D_AffineComb(u, w, 3, &ru), &ru);
    EXPECT_EQ(ru.u, 0.25f);
    EXPECT_EQ(ru.v, 0.5f);
    TQ3Point3D p3[] = {{1, 2, 3}, {3, 2, 1}};
    const float half[] = {0.5f, 0.5f};
    EXPECT_EQ(Q3Point3D_AffineComb(p3, half, 2, &p3[0]), &p3[0]); // result is one of the points
    EXPECT_EQ(p3[0].x, 2.0f);
    EXPECT_EQ(p3[0].y, 2.0f);
    EXPECT_EQ(p3[0].z, 2.0f);
    // Rational points combine in homogeneous coordinates, w too.
    const TQ3RationalPoint3D r3[] = {{2, 0, 2}, {0, 6, 3}};
    TQ3RationalPoint3D rr3{};
    EXPECT_EQ(Q3RationalPoint3D_AffineComb(r3, half, 2, &rr3), &rr3);
    EXPECT_EQ(rr3.x, 1.0f);
    EXPECT_EQ(rr3.y, 3.0f);
    EXPECT_EQ(rr3.w, 2.5f);
    const TQ3RationalPoint4D r4[] = {{2, 0, 4, 2}, {0, 6, 0, 1}};
    const float w4[] = {0.75f, 0.25f};
    TQ3RationalPoint4D rr4{};
    EXPECT_EQ(Q3RationalPoint4D_AffineComb(r4, w4, 2, &rr4), &rr4);
    EXPECT_EQ(rr4.x, 1.5f);
    EXPECT_EQ(rr4.y, 1.5f);
    EXPECT_EQ(rr4.z, 3.0f);
    EXPECT_EQ(rr4.w, 1.75f);
}

TEST_F(MathPointApiTest, AffineCombinationsDivideByTheWeightsSum)
{
    // Weights 1, 1, 2 give the mean 0.25, 0.25, 0.5 give; negative weights
    // too as long as the sum is not 0.
    const TQ3Point2D p[] = {{0, 0}, {4, 0}, {0, 8}};
    const float w[] = {1, 1, 2};
    TQ3Point2D r{};
    EXPECT_EQ(Q3Point2D_AffineComb(p, w, 3, &r), &r);
    EXPECT_EQ(r.x, 1.0f);
    EXPECT_EQ(r.y, 4.0f);
    const TQ3Point3D line[] = {{0, 0, 0}, {1, 1, 1}};
    const float outside[] = {-1, 2}; // -1 * a + 2 * b: beyond b
    TQ3Point3D q{};
    EXPECT_EQ(Q3Point3D_AffineComb(line, outside, 2, &q), &q);
    EXPECT_EQ(q.x, 2.0f);
    // One point with a nonzero weight is that point.
    const float three = 3;
    EXPECT_EQ(Q3Point3D_AffineComb(&line[1], &three, 1, &q), &q);
    EXPECT_EQ(q.y, 1.0f);
}

TEST_F(MathPointApiTest, AffineCombinationsRejectWeightsSummingToZeroAndNoPoints)
{
    const TQ3Point3D p[] = {{1, 2, 3}, {4, 5, 6}};
    const float cancel[] = {1, -1}, zero[] = {0, 0};
    TQ3Point3D r = filledWith<TQ3Point3D>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_AffineComb(p, cancel, 2, &r), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_AffineComb(p, zero, 2, &r), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_AffineComb(p, cancel, 0, &r), nullptr), kQ3ErrorParameterOutOfRange);
    // With no points the arrays may be NULL, but there is still nothing to combine.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_AffineComb(nullptr, nullptr, 0, &r), nullptr), kQ3ErrorParameterOutOfRange);
    EXPECT_TRUE(sameBits(r, filledWith<TQ3Point3D>(7)));
    OnePointOfEachKind().forEachAffineComb([&](auto comb, auto, auto& out) {
        EXPECT_Q3_ERROR(EXPECT_EQ(comb(nullptr, nullptr, 0, &out), nullptr), kQ3ErrorParameterOutOfRange);
    });
}

TEST_F(MathPointApiTest, AffineCombinationsRejectNullArraysForOneOrMorePointsAndNullResults)
{
    OnePointOfEachKind kinds;
    kinds.forEachAffineComb([&](auto comb, auto points, auto& out) {
        for (unsigned long count : {1UL, ULONG_MAX}) {
            EXPECT_Q3_ERROR(EXPECT_EQ(comb(nullptr, kinds.w, count, &out), nullptr), kQ3ErrorNULLParameter);
            EXPECT_Q3_ERROR(EXPECT_EQ(comb(points, nullptr, count, &out), nullptr), kQ3ErrorNULLParameter);
        }
        EXPECT_Q3_ERROR(EXPECT_EQ(comb(points, kinds.w, 1, nullptr), nullptr), kQ3ErrorNULLParameter);
    });
}

// The arrays hold one point: a count beyond what any array could hold must
// fail before anything is read (AddressSanitizer would see a read past them).
TEST_F(MathPointApiTest, AffineCombinationsRejectCountsNoArrayCouldHoldBeforeReading)
{
    OnePointOfEachKind kinds;
    kinds.op3 = filledWith<TQ3Point3D>(7);
    for (unsigned long count : {ULONG_MAX, ULONG_MAX / 4 + 1, 1UL << 62, (unsigned long)LONG_MAX})
        kinds.forEachAffineComb([&](auto comb, auto points, auto& out) {
            EXPECT_Q3_ERROR(EXPECT_EQ(comb(points, kinds.w, count, &out), nullptr), kQ3ErrorParameterOutOfRange);
        });
    EXPECT_TRUE(sameBits(kinds.op3, filledWith<TQ3Point3D>(7)));
}

TEST_F(MathPointApiTest, AffineCombinationsPropagateNonFiniteValues)
{
    const TQ3Point3D p[] = {{0, 0, 0}, {1, kInf, kNaN}};
    const float w[] = {0.5f, 0.5f};
    TQ3Point3D r{};
    EXPECT_EQ(Q3Point3D_AffineComb(p, w, 2, &r), &r);
    EXPECT_EQ(r.x, 0.5f);
    EXPECT_EQ(r.y, kInf);
    EXPECT_TRUE(std::isnan(r.z));
    const float nanWeight[] = {kNaN, 1};
    EXPECT_EQ(Q3Point3D_AffineComb(p, nanWeight, 2, &r), &r); // NaN passes the zero test
    EXPECT_TRUE(std::isnan(r.x));
    const float infWeight[] = {kInf, 1};
    EXPECT_EQ(Q3Point3D_AffineComb(p, infWeight, 2, &r), &r); // (inf * 0 + 1) / inf
    EXPECT_TRUE(std::isnan(r.x));
}

// ---- Before Q3Initialize ------------------------------------------------------------------------------------

TEST(MathPointApiUninitialized, EveryCallFailsWithNotInitializedAndChangesNothing)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    const TQ3Point2D p2{1, 2};
    const TQ3Param2D u{1, 2};
    const TQ3Point3D p3{1, 2, 3};
    const TQ3RationalPoint3D r3{1, 2, 1};
    const TQ3RationalPoint4D r4{1, 2, 3, 1};
    const TQ3Vector2D v2{1, 2};
    const TQ3Vector3D v3{1, 2, 3};
    const TQ3PolarPoint polar{1, 1};
    const TQ3SphericalPoint sphere{1, 1, 1};
    const TQ3Quaternion q{1, 0, 0, 0};
    const float w[] = {1};
    TQ3Point2D o2 = filledWith<TQ3Point2D>(7);
    TQ3Param2D ou = filledWith<TQ3Param2D>(7);
    TQ3Point3D o3 = filledWith<TQ3Point3D>(7);
    TQ3RationalPoint3D or3 = filledWith<TQ3RationalPoint3D>(7);
    TQ3RationalPoint4D or4 = filledWith<TQ3RationalPoint4D>(7);
    TQ3Vector2D ov2 = filledWith<TQ3Vector2D>(7);
    TQ3Vector3D ov3 = filledWith<TQ3Vector3D>(7);
    TQ3PolarPoint oPolar = filledWith<TQ3PolarPoint>(7);
    TQ3SphericalPoint oSphere = filledWith<TQ3SphericalPoint>(7);
    int calls = 0, failures = 0;
    auto check = [&](bool failedValue) {
        ++calls;
        if (failedValue && Q3Error_Get(nullptr) == kQ3ErrorNotInitialized)
            ++failures;
    };
    check(Q3Point2D_Set(&o2, 0, 0) == nullptr);
    check(Q3Param2D_Set(&ou, 0, 0) == nullptr);
    check(Q3RationalPoint3D_Set(&or3, 0, 0, 0) == nullptr);
    check(Q3PolarPoint_Set(&oPolar, 0, 0) == nullptr);
    check(Q3SphericalPoint_Set(&oSphere, 0, 0, 0) == nullptr);
    check(Q3Point2D_To3D(&p2, &o3) == nullptr);
    check(Q3RationalPoint3D_To2D(&r3, &o2) == nullptr);
    check(Q3Point3D_To4D(&p3, &or4) == nullptr);
    check(Q3RationalPoint4D_To3D(&r4, &o3) == nullptr);
    check(Q3Point2D_Subtract(&p2, &p2, &ov2) == nullptr);
    check(Q3Param2D_Subtract(&u, &u, &ov2) == nullptr);
    check(Q3Point3D_Subtract(&p3, &p3, &ov3) == nullptr);
    check(Q3Point2D_Distance(&p2, &p2) == 0.0f);
    check(Q3Point2D_DistanceSquared(&p2, &p2) == 0.0f);
    check(Q3Param2D_Distance(&u, &u) == 0.0f);
    check(Q3Param2D_DistanceSquared(&u, &u) == 0.0f);
    check(Q3RationalPoint3D_Distance(&r3, &r3) == 0.0f);
    check(Q3RationalPoint3D_DistanceSquared(&r3, &r3) == 0.0f);
    check(Q3Point3D_DistanceSquared(&p3, &p3) == 0.0f);
    check(Q3RationalPoint4D_Distance(&r4, &r4) == 0.0f);
    check(Q3RationalPoint4D_DistanceSquared(&r4, &r4) == 0.0f);
    check(Q3Point2D_RRatio(&p2, &p2, 1, 1, &o2) == nullptr);
    check(Q3Param2D_RRatio(&u, &u, 1, 1, &ou) == nullptr);
    check(Q3Point3D_RRatio(&p3, &p3, 1, 1, &o3) == nullptr);
    check(Q3RationalPoint4D_RRatio(&r4, &r4, 1, 1, &or4) == nullptr);
    check(Q3Point2D_Vector2D_Add(&p2, &v2, &o2) == nullptr);
    check(Q3Param2D_Vector2D_Add(&u, &v2, &ou) == nullptr);
    check(Q3Point3D_Vector3D_Add(&p3, &v3, &o3) == nullptr);
    check(Q3Point2D_Vector2D_Subtract(&p2, &v2, &o2) == nullptr);
    check(Q3Param2D_Vector2D_Subtract(&u, &v2, &ou) == nullptr);
    check(Q3Point3D_Vector3D_Subtract(&p3, &v3, &o3) == nullptr);
    check(Q3Point3D_CrossProductTri(&p3, &p3, &p3, &ov3) == nullptr);
    check(Q3Point2D_Transform(&p2, &kIdentity3x3, &o2) == nullptr);
    check(Q3Param2D_Transform(&u, &kIdentity3x3, &ou) == nullptr);
    check(Q3Point2D_ToPolar(&p2, &oPolar) == nullptr);
    check(Q3PolarPoint_ToPoint2D(&polar, &o2) == nullptr);
    check(Q3Point3D_ToSpherical(&p3, &oSphere) == nullptr);
    check(Q3SphericalPoint_ToPoint3D(&sphere, &o3) == nullptr);
    check(Q3Point2D_AffineComb(&p2, w, 1, &o2) == nullptr);
    check(Q3Param2D_AffineComb(&u, w, 1, &ou) == nullptr);
    check(Q3RationalPoint3D_AffineComb(&r3, w, 1, &or3) == nullptr);
    check(Q3Point3D_AffineComb(&p3, w, 1, &o3) == nullptr);
    check(Q3RationalPoint4D_AffineComb(&r4, w, 1, &or4) == nullptr);
    check(Q3Point3D_TransformQuaternion(&p3, &q, &o3) == nullptr);
    check(Q3Point3D_To3DTransformArray(&p3, &kIdentity4x4, &o3, 1, sizeof p3, sizeof o3) == kQ3Failure);
    check(Q3Point3D_To4DTransformArray(&p3, &kIdentity4x4, &or4, 1, sizeof p3, sizeof or4) == kQ3Failure);
    check(Q3RationalPoint4D_To4DTransformArray(&r4, &kIdentity4x4, &or4, 1, sizeof r4, sizeof or4) == kQ3Failure);
    EXPECT_EQ(failures, calls);
    EXPECT_EQ(calls, 47);
    EXPECT_TRUE(sameBits(o2, filledWith<TQ3Point2D>(7)));
    EXPECT_TRUE(sameBits(ou, filledWith<TQ3Param2D>(7)));
    EXPECT_TRUE(sameBits(o3, filledWith<TQ3Point3D>(7)));
    EXPECT_TRUE(sameBits(or3, filledWith<TQ3RationalPoint3D>(7)));
    EXPECT_TRUE(sameBits(or4, filledWith<TQ3RationalPoint4D>(7)));
    EXPECT_TRUE(sameBits(ov2, filledWith<TQ3Vector2D>(7)));
    EXPECT_TRUE(sameBits(ov3, filledWith<TQ3Vector3D>(7)));
    EXPECT_TRUE(sameBits(oPolar, filledWith<TQ3PolarPoint>(7)));
    EXPECT_TRUE(sameBits(oSphere, filledWith<TQ3SphericalPoint>(7)));
}

} // namespace
