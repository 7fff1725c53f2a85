// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DMath.h's 3x3 matrix calls, determinants, and the 4x4 rotations
// MathApiTest.cpp does not cover (XYZ, about a point, vector to vector).
// Expected matrices are built in the test from the textbook rotation
// matrices in QuickDraw 3D's row-vector convention.

#include "MathTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DMath.h"

#include <array>
#include <cmath>

namespace {

using namespace q3test;
using MathMatrixApiTest = Q3ApiTest;

// Float rounding of sines, cosines and a few products of magnitude 1-10.
constexpr float kTolerance = 2e-6f;

using Rows = std::array<std::array<double, 4>, 4>;

Rows identityRows()
{
    Rows m{};
    for (int i = 0; i < 4; ++i)
        m[i][i] = 1;
    return m;
}

Rows times(const Rows& a, const Rows& b)
{
    Rows r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k)
                r[i][j] += a[i][k] * b[k][j];
    return r;
}

// Counterclockwise about an axis, as a row-vector matrix: the row of
// `from` turns towards `to`.
Rows turn(int from, int to, double angle)
{
    Rows m = identityRows();
    m[from][from] = std::cos(angle);
    m[from][to] = std::sin(angle);
    m[to][from] = -std::sin(angle);
    m[to][to] = std::cos(angle);
    return m;
}

Rows rotX(double a) { return turn(1, 2, a); }
Rows rotY(double a) { return turn(2, 0, a); }
Rows rotZ(double a) { return turn(0, 1, a); }

Rows shift(double x, double y, double z)
{
    Rows m = identityRows();
    m[3][0] = x;
    m[3][1] = y;
    m[3][2] = z;
    return m;
}

TQ3Matrix4x4 toMatrix(const Rows& m)
{
    TQ3Matrix4x4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            r.value[i][j] = float(m[i][j]);
    return r;
}

// v * M for a direction (w = 0).
std::array<double, 3> turned(const std::array<double, 3>& v, const TQ3Matrix4x4& m)
{
    const double in[4] = {v[0], v[1], v[2], 0};
    double out[4];
    rowTimes(in, m, out);
    return {out[0], out[1], out[2]};
}

double det3(const TQ3Matrix3x3& m)
{
    const auto& a = m.value;
    return double(a[0][0]) * (double(a[1][1]) * a[2][2] - double(a[1][2]) * a[2][1]) -
           double(a[0][1]) * (double(a[1][0]) * a[2][2] - double(a[1][2]) * a[2][0]) +
           double(a[0][2]) * (double(a[1][0]) * a[2][1] - double(a[1][1]) * a[2][0]);
}

// Laplace expansion along the first row.
double det4(const TQ3Matrix4x4& m)
{
    double sum = 0;
    for (int col = 0; col < 4; ++col) {
        TQ3Matrix3x3 minor{};
        for (int i = 1; i < 4; ++i)
            for (int j = 0, k = 0; j < 4; ++j)
                if (j != col)
                    minor.value[i - 1][k++] = m.value[i][j];
        sum += (col % 2 ? -1.0 : 1.0) * m.value[0][col] * det3(minor);
    }
    return sum;
}

const TQ3Matrix3x3 kGeneral3x3 = matrix3x3Of({2, -1, 0.5f, 1, 3, -2, 0.25f, 4, 1});

// ---- 3x3: copy, identity, transpose, multiply ---------------------------------------

TEST_F(MathMatrixApiTest, Matrix3x3CopyCopiesEveryBitAndSetIdentityIsExact)
{
    TQ3Matrix3x3 m = matrix3x3Of({1, 2, 3, 4, 5, 6, 7, 8, 9});
    m.value[1][1] = kNaN;
    m.value[2][0] = -0.0f;
    TQ3Matrix3x3 r = filledWith<TQ3Matrix3x3>(0);
    EXPECT_EQ(Q3Matrix3x3_Copy(&m, &r), &r);
    EXPECT_TRUE(sameBits(r, m));
    EXPECT_EQ(Q3Matrix3x3_Copy(&r, &r), &r);
    EXPECT_TRUE(sameBits(r, m));
    EXPECT_EQ(Q3Matrix3x3_SetIdentity(&r), &r);
    EXPECT_TRUE(sameBits(r, kIdentity3x3));
}

TEST_F(MathMatrixApiTest, Matrix3x3TransposeSwapsRowsAndColumnsInPlaceToo)
{
    const TQ3Matrix3x3 m = matrix3x3Of({1, 2, 3, 4, 5, 6, 7, 8, kNaN});
    TQ3Matrix3x3 r{};
    EXPECT_EQ(Q3Matrix3x3_Transpose(&m, &r), &r);
    EXPECT_EQ(r.value[0][1], 4.0f);
    EXPECT_EQ(r.value[1][0], 2.0f);
    EXPECT_EQ(r.value[2][0], 3.0f);
    EXPECT_EQ(r.value[1][2], 8.0f);
    EXPECT_TRUE(std::isnan(r.value[2][2]));
    EXPECT_EQ(Q3Matrix3x3_Transpose(&r, &r), &r);
    EXPECT_TRUE(sameBits(r, m));
}

TEST_F(MathMatrixApiTest, Matrix3x3MultiplyMatchesHandComputationAndAllowsAliasing)
{
    const TQ3Matrix3x3 a = matrix3x3Of({1, 2, 0, 0, 1, 3, 4, 0, 1});
    const TQ3Matrix3x3 b = matrix3x3Of({2, 0, 1, 1, 1, 0, 0, 5, 1});
    // Row i of a * b is sum_k a[i][k] * row k of b.
    const TQ3Matrix3x3 expected = matrix3x3Of({4, 2, 1, 1, 16, 3, 8, 5, 5});
    TQ3Matrix3x3 r{};
    EXPECT_EQ(Q3Matrix3x3_Multiply(&a, &b, &r), &r);
    EXPECT_TRUE(sameBits(r, expected));
    TQ3Matrix3x3 left = a, right = b;
    EXPECT_EQ(Q3Matrix3x3_Multiply(&left, &b, &left), &left);
    EXPECT_EQ(Q3Matrix3x3_Multiply(&a, &right, &right), &right);
    EXPECT_TRUE(sameBits(left, expected));
    EXPECT_TRUE(sameBits(right, expected));
    TQ3Matrix3x3 square = a, squared{};
    Q3Matrix3x3_Multiply(&a, &a, &squared);
    EXPECT_EQ(Q3Matrix3x3_Multiply(&square, &square, &square), &square);
    EXPECT_TRUE(sameBits(square, squared));
}

TEST_F(MathMatrixApiTest, Matrix3x3MultiplyAppliesTheLeftFactorFirst)
{
    // Translate by (1, 0) then scale by 2: (1, 0) -> (2, 0) -> (4, 0).
    TQ3Matrix3x3 t{}, s{}, ts{};
    Q3Matrix3x3_SetTranslate(&t, 1, 0);
    Q3Matrix3x3_SetScale(&s, 2, 2);
    Q3Matrix3x3_Multiply(&t, &s, &ts);
    const TQ3Point2D p{1, 0};
    TQ3Point2D r{};
    Q3Point2D_Transform(&p, &ts, &r);
    EXPECT_EQ(r.x, 4.0f);
    EXPECT_EQ(r.y, 0.0f);
    TQ3Matrix3x3 nan = kIdentity3x3, out{};
    nan.value[0][0] = kNaN;
    Q3Matrix3x3_Multiply(&nan, &kIdentity3x3, &out);
    EXPECT_TRUE(std::isnan(out.value[0][0]));
}

// ---- 3x3: building transforms ------------------------------------------------------------

TEST_F(MathMatrixApiTest, Matrix3x3SetTranslateAndSetScaleStoreExactlyWhatTheyAreGiven)
{
    TQ3Matrix3x3 m = filledWith<TQ3Matrix3x3>(7);
    EXPECT_EQ(Q3Matrix3x3_SetTranslate(&m, 3, -4), &m);
    EXPECT_TRUE(sameBits(m, matrix3x3Of({1, 0, 0, 0, 1, 0, 3, -4, 1})));
    EXPECT_EQ(Q3Matrix3x3_SetScale(&m, -2, 0.5f), &m);
    EXPECT_TRUE(sameBits(m, matrix3x3Of({-2, 0, 0, 0, 0.5f, 0, 0, 0, 1}))); // no -0 appears
    EXPECT_EQ(Q3Matrix3x3_SetScale(&m, kInf, kNaN), &m);
    EXPECT_EQ(m.value[0][0], kInf);
    EXPECT_TRUE(std::isnan(m.value[1][1]));
    EXPECT_EQ(m.value[0][1], 0.0f); // not inf * 0
    EXPECT_EQ(Q3Matrix3x3_SetTranslate(&m, kNaN, -kInf), &m);
    EXPECT_TRUE(std::isnan(m.value[2][0]));
    EXPECT_EQ(m.value[2][1], -kInf);
    EXPECT_EQ(m.value[2][2], 1.0f);
}

TEST_F(MathMatrixApiTest, Matrix3x3SetRotateAboutPointTurnsCounterclockwiseAboutTheOrigin)
{
    const TQ3Point2D zero{0, 0}, centre{1, 1};
    TQ3Matrix3x3 m{};
    EXPECT_EQ(Q3Matrix3x3_SetRotateAboutPoint(&m, &zero, float(kPi / 2)), &m);
    const TQ3Point2D x{1, 0};
    TQ3Point2D r{};
    Q3Point2D_Transform(&x, &m, &r);
    EXPECT_NEAR(r.x, 0.0f, kTolerance);
    EXPECT_NEAR(r.y, 1.0f, kTolerance);
    // About (1, 1) by 0.7: p' = o + R (p - o), and o itself stays put.
    const double a = 0.7f;
    Q3Matrix3x3_SetRotateAboutPoint(&m, &centre, float(a));
    const TQ3Point2D p{3, -2};
    Q3Point2D_Transform(&p, &m, &r);
    EXPECT_NEAR(r.x, 1 + 2 * std::cos(a) + 3 * std::sin(a), kTolerance * 4);
    EXPECT_NEAR(r.y, 1 + 2 * std::sin(a) - 3 * std::cos(a), kTolerance * 4);
    Q3Point2D_Transform(&centre, &m, &r);
    EXPECT_NEAR(r.x, 1.0f, kTolerance);
    EXPECT_NEAR(r.y, 1.0f, kTolerance);
    EXPECT_EQ(m.value[0][2], 0.0f);
    EXPECT_EQ(m.value[2][2], 1.0f);
}

TEST_F(MathMatrixApiTest, Matrix3x3BuildersPropagateNonFiniteValuesAndRejectNull)
{
    const TQ3Point2D zero{0, 0};
    TQ3Matrix3x3 m{};
    EXPECT_EQ(Q3Matrix3x3_SetRotateAboutPoint(&m, &zero, kInf), &m);
    EXPECT_TRUE(std::isnan(m.value[0][0]));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix3x3_SetIdentity(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix3x3_SetTranslate(nullptr, 1, 2), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix3x3_SetScale(nullptr, 1, 2), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix3x3_SetRotateAboutPoint(nullptr, &zero, 1), nullptr), kQ3ErrorNULLParameter);
    m = filledWith<TQ3Matrix3x3>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix3x3_SetRotateAboutPoint(&m, nullptr, 1), nullptr), kQ3ErrorNULLParameter);
    EXPECT_TRUE(sameBits(m, filledWith<TQ3Matrix3x3>(7)));
}

// ---- 3x3: inverse, adjoint, determinant --------------------------------------------------

TEST_F(MathMatrixApiTest, Matrix3x3InvertTimesTheMatrixIsTheIdentity)
{
    TQ3Matrix3x3 inverse{}, product{};
    EXPECT_EQ(Q3Matrix3x3_Invert(&kGeneral3x3, &inverse), &inverse);
    Q3Matrix3x3_Multiply(&inverse, &kGeneral3x3, &product);
    expectMatrixNear(product, kIdentity3x3, 1e-6f, "Invert(M) * M");
    Q3Matrix3x3_Multiply(&kGeneral3x3, &inverse, &product);
    expectMatrixNear(product, kIdentity3x3, 1e-6f, "M * Invert(M)");
    // Scale 2 then translate (4, 6): the inverse translates back and halves.
    TQ3Matrix3x3 m = matrix3x3Of({2, 0, 0, 0, 2, 0, 4, 6, 1});
    EXPECT_EQ(Q3Matrix3x3_Invert(&m, &m), &m); // in place
    expectMatrixNear(m, matrix3x3Of({0.5f, 0, 0, 0, 0.5f, 0, -2, -3, 1}), 0.0f, "inverse");
}

TEST_F(MathMatrixApiTest, Matrix3x3InvertRejectsSingularTooLargeAndNonFiniteMatrices)
{
    TQ3Matrix3x3 equalRows = matrix3x3Of({1, 2, 3, 1, 2, 3, 0, 0, 1});
    const TQ3Matrix3x3 tiny = matrix3x3Of({1e-39f, 0, 0, 0, 1e-39f, 0, 0, 0, 1});
    TQ3Matrix3x3 nan = kIdentity3x3, inf = kIdentity3x3;
    nan.value[1][2] = kNaN;
    inf.value[0][0] = kInf;
    for (const TQ3Matrix3x3& bad : {filledWith<TQ3Matrix3x3>(0), equalRows, tiny, nan, inf}) {
        TQ3Matrix3x3 r = filledWith<TQ3Matrix3x3>(7);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix3x3_Invert(&bad, &r), nullptr), kQ3ErrorNonInvertibleMatrix);
        EXPECT_TRUE(sameBits(r, filledWith<TQ3Matrix3x3>(7)));
    }
    const TQ3Matrix3x3 before = equalRows;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix3x3_Invert(&equalRows, &equalRows), nullptr), kQ3ErrorNonInvertibleMatrix);
    EXPECT_TRUE(sameBits(equalRows, before));
}

TEST_F(MathMatrixApiTest, Matrix3x3AdjointIsTheTransposedCofactorMatrix)
{
    // A textbook matrix with determinant 1, so its adjoint is its inverse.
    const TQ3Matrix3x3 a = matrix3x3Of({1, 2, 3, 0, 1, 4, 5, 6, 0});
    const TQ3Matrix3x3 expected = matrix3x3Of({-24, 18, 5, 20, -15, -4, -5, 4, 1});
    TQ3Matrix3x3 r{};
    EXPECT_EQ(Q3Matrix3x3_Adjoint(&a, &r), &r);
    EXPECT_TRUE(sameBits(r, expected));
    TQ3Matrix3x3 inPlace = a;
    EXPECT_EQ(Q3Matrix3x3_Adjoint(&inPlace, &inPlace), &inPlace);
    EXPECT_TRUE(sameBits(inPlace, expected));
}

TEST_F(MathMatrixApiTest, Matrix3x3AdjointTimesTheMatrixIsTheDeterminantEvenWhenSingular)
{
    for (const TQ3Matrix3x3& m : {kGeneral3x3, matrix3x3Of({1, 2, 3, 2, 4, 6, 1, 0, 1})}) {
        TQ3Matrix3x3 adj{}, product{};
        Q3Matrix3x3_Adjoint(&m, &adj);
        Q3Matrix3x3_Multiply(&adj, &m, &product);
        const float det = float(det3(m));
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                EXPECT_NEAR(product.value[i][j], i == j ? det : 0.0f, 1e-5f) << i << ", " << j;
    }
    TQ3Matrix3x3 nan = kIdentity3x3, adj{};
    nan.value[0][0] = kNaN;
    EXPECT_EQ(Q3Matrix3x3_Adjoint(&nan, &adj), &adj); // no error: the adjoint always exists
    EXPECT_TRUE(std::isnan(adj.value[1][1]));
    EXPECT_EQ(adj.value[0][0], 1.0f); // the cofactor of (0, 0) does not involve it
}

TEST_F(MathMatrixApiTest, DeterminantsMatchTheExpansionFormulas)
{
    EXPECT_FLOAT_EQ(Q3Matrix3x3_Determinant(&kGeneral3x3), float(det3(kGeneral3x3)));
    EXPECT_EQ(Q3Matrix3x3_Determinant(&kIdentity3x3), 1.0f);
    const TQ3Matrix3x3 singular = matrix3x3Of({1, 2, 3, 2, 4, 6, 1, 0, 1});
    EXPECT_EQ(Q3Matrix3x3_Determinant(&singular), 0.0f);
    const TQ3Matrix4x4 m = matrix4x4Of({0.5f, 1, 0, 0.1f, -2, 0.25f, 1, 0, 0, 3, 2, -0.2f, 7, -4, 1.5f, 1});
    EXPECT_FLOAT_EQ(Q3Matrix4x4_Determinant(&m), float(det4(m)));
    EXPECT_EQ(Q3Matrix4x4_Determinant(&kIdentity4x4), 1.0f);
    // Triangular: the product of the diagonal; swapping two rows flips the sign.
    TQ3Matrix4x4 t = matrix4x4Of({2, 5, 7, 1, 0, 3, 8, 2, 0, 0, -1, 4, 0, 0, 0, 0.5f});
    EXPECT_EQ(Q3Matrix4x4_Determinant(&t), -3.0f);
    std::swap(t.value[0], t.value[2]);
    EXPECT_EQ(Q3Matrix4x4_Determinant(&t), 3.0f);
}

TEST_F(MathMatrixApiTest, DeterminantsFollowIEEEAndRejectNull)
{
    TQ3Matrix3x3 nan = kIdentity3x3;
    nan.value[2][1] = kNaN;
    EXPECT_TRUE(std::isnan(Q3Matrix3x3_Determinant(&nan)));
    TQ3Matrix4x4 huge{};
    Q3Matrix4x4_SetScale(&huge, 1e20f, 1e20f, 1e20f);
    EXPECT_EQ(Q3Matrix4x4_Determinant(&huge), kInf); // 1e60 does not fit a float
    // An infinite entry meets zeros in the expansion: infinity or NaN, no error.
    TQ3Matrix4x4 inf = kIdentity4x4;
    inf.value[3][3] = -kInf;
    EXPECT_FALSE(std::isfinite(Q3Matrix4x4_Determinant(&inf)));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix3x3_Determinant(nullptr), 0.0f), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_Determinant(nullptr), 0.0f), kQ3ErrorNULLParameter);
}

TEST_F(MathMatrixApiTest, Matrix3x3CallsRejectNullAndLeaveTheResultAlone)
{
    TQ3Matrix3x3 r = filledWith<TQ3Matrix3x3>(7);
    const TQ3Matrix3x3& m = kGeneral3x3;
    expectEachNullRejected("Q3Matrix3x3_Copy", Q3Matrix3x3_Copy, &m, &r);
    expectEachNullRejected("Q3Matrix3x3_Transpose", Q3Matrix3x3_Transpose, &m, &r);
    expectEachNullRejected("Q3Matrix3x3_Invert", Q3Matrix3x3_Invert, &m, &r);
    expectEachNullRejected("Q3Matrix3x3_Adjoint", Q3Matrix3x3_Adjoint, &m, &r);
    expectEachNullRejected("Q3Matrix3x3_Multiply", Q3Matrix3x3_Multiply, &m, &m, &r);
    EXPECT_TRUE(sameBits(r, filledWith<TQ3Matrix3x3>(7)));
}

// ---- 4x4 rotations -----------------------------------------------------------------------------

TEST_F(MathMatrixApiTest, SetRotateXYZRotatesAboutXThenYThenZ)
{
    const double x = 0.3f, y = -1.1f, z = 2.5f;
    TQ3Matrix4x4 m = filledWith<TQ3Matrix4x4>(7);
    EXPECT_EQ(Q3Matrix4x4_SetRotate_XYZ(&m, float(x), float(y), float(z)), &m);
    expectMatrixNear(m, toMatrix(times(times(rotX(x), rotY(y)), rotZ(z))), kTolerance, "Rx * Ry * Rz");
    // The first row of Rx Ry Rz, written out: (cos y cos z, cos y sin z, -sin y).
    EXPECT_NEAR(m.value[0][2], -std::sin(y), kTolerance);
    EXPECT_NEAR(m.value[0][0], std::cos(y) * std::cos(z), kTolerance);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(m.value[i][3], 0.0f);
        EXPECT_EQ(m.value[3][i], 0.0f);
    }
    EXPECT_EQ(m.value[3][3], 1.0f);
    // Single angles give the single-axis rotations.
    TQ3Matrix4x4 single{}, expected{};
    Q3Matrix4x4_SetRotate_XYZ(&single, 0, 0.6f, 0);
    Q3Matrix4x4_SetRotate_Y(&expected, 0.6f);
    expectMatrixNear(single, expected, kTolerance, "Y alone");
    Q3Matrix4x4_SetRotate_XYZ(&single, 0, 0, 0);
    EXPECT_TRUE(sameBits(single, kIdentity4x4));
}

TEST_F(MathMatrixApiTest, SetRotateAboutPointKeepsThePointFixed)
{
    const TQ3Point3D origin{1, -2, 3};
    const double x = 0.4f, y = 0.9f, z = -0.2f;
    TQ3Matrix4x4 m{};
    EXPECT_EQ(Q3Matrix4x4_SetRotateAboutPoint(&m, &origin, float(x), float(y), float(z)), &m);
    const Rows expected = times(times(shift(-1, 2, -3), times(times(rotX(x), rotY(y)), rotZ(z))), shift(1, -2, 3));
    expectMatrixNear(m, toMatrix(expected), kTolerance * 4, "T(-o) * Rxyz * T(o)");
    TQ3Point3D fixed{};
    Q3Point3D_Transform(&origin, &m, &fixed);
    EXPECT_NEAR(fixed.x, 1.0f, kTolerance * 4);
    EXPECT_NEAR(fixed.y, -2.0f, kTolerance * 4);
    EXPECT_NEAR(fixed.z, 3.0f, kTolerance * 4);
    // About the origin it is SetRotate_XYZ.
    const TQ3Point3D zero{0, 0, 0};
    TQ3Matrix4x4 atZero{}, xyz{};
    Q3Matrix4x4_SetRotateAboutPoint(&atZero, &zero, 0.4f, 0.9f, -0.2f);
    Q3Matrix4x4_SetRotate_XYZ(&xyz, 0.4f, 0.9f, -0.2f);
    EXPECT_TRUE(sameBits(atZero, xyz));
}

TEST_F(MathMatrixApiTest, SetRotateVectorToVectorTakesOneDirectionToTheOther)
{
    const TQ3Vector3D v1{1, 2, 2}, v2{-3, 0, 4}; // lengths 3 and 5: need not be unit
    TQ3Matrix4x4 m = filledWith<TQ3Matrix4x4>(7);
    EXPECT_EQ(Q3Matrix4x4_SetRotateVectorToVector(&m, &v1, &v2), &m);
    const auto image = turned({1.0 / 3, 2.0 / 3, 2.0 / 3}, m);
    EXPECT_NEAR(image[0], -0.6, kTolerance);
    EXPECT_NEAR(image[1], 0.0, kTolerance);
    EXPECT_NEAR(image[2], 0.8, kTolerance);
    // The common normal v1 x v2 = (8, -10, 6) does not move.
    const auto axis = turned({8, -10, 6}, m);
    EXPECT_NEAR(axis[0], 8, 1e-5);
    EXPECT_NEAR(axis[1], -10, 1e-5);
    EXPECT_NEAR(axis[2], 6, 1e-5);
    // A rotation: orthonormal rows, determinant 1, no translation.
    EXPECT_NEAR(det4(m), 1.0, 1e-6);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double dot = 0;
            for (int k = 0; k < 3; ++k)
                dot += double(m.value[i][k]) * m.value[j][k];
            EXPECT_NEAR(dot, i == j ? 1.0 : 0.0, 1e-6) << i << ", " << j;
        }
    EXPECT_EQ(m.value[3][0], 0.0f);
    EXPECT_EQ(m.value[3][3], 1.0f);
}

TEST_F(MathMatrixApiTest, SetRotateVectorToVectorHandlesParallelAndOppositeDirections)
{
    const TQ3Vector3D v{1, 2, 3}, twice{2, 4, 6}, opposite{-0.5f, -1, -1.5f};
    TQ3Matrix4x4 m{};
    EXPECT_EQ(Q3Matrix4x4_SetRotateVectorToVector(&m, &v, &twice), &m);
    EXPECT_TRUE(sameBits(m, kIdentity4x4));
    // Opposite: a half turn about v x e_x (x is v's smallest component),
    // (1, 2, 3) x (1, 0, 0) = (0, 3, -2).
    EXPECT_EQ(Q3Matrix4x4_SetRotateVectorToVector(&m, &v, &opposite), &m);
    const auto image = turned({1, 2, 3}, m);
    EXPECT_NEAR(image[0], -1, 1e-5);
    EXPECT_NEAR(image[1], -2, 1e-5);
    EXPECT_NEAR(image[2], -3, 1e-5);
    const auto axis = turned({0, 3, -2}, m);
    EXPECT_NEAR(axis[0], 0, 1e-5);
    EXPECT_NEAR(axis[1], 3, 1e-5);
    EXPECT_NEAR(axis[2], -2, 1e-5);
}

TEST_F(MathMatrixApiTest, SetRotateVectorToVectorRejectsZeroVectorsAndNull)
{
    const TQ3Vector3D zero{0, -0.0f, 0}, v{1, 0, 0};
    TQ3Matrix4x4 m = filledWith<TQ3Matrix4x4>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetRotateVectorToVector(&m, &zero, &v), nullptr),
                    kQ3ErrorVector3DZeroLength);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetRotateVectorToVector(&m, &v, &zero), nullptr),
                    kQ3ErrorVector3DZeroLength);
    expectEachNullRejected("Q3Matrix4x4_SetRotateVectorToVector", Q3Matrix4x4_SetRotateVectorToVector, &m, &v, &v);
    EXPECT_TRUE(sameBits(m, filledWith<TQ3Matrix4x4>(7)));
}

TEST_F(MathMatrixApiTest, FourByFourRotationsPropagateNonFiniteValues)
{
    TQ3Matrix4x4 m{};
    EXPECT_EQ(Q3Matrix4x4_SetRotate_XYZ(&m, kNaN, 0, 0), &m);
    EXPECT_TRUE(std::isnan(m.value[1][1]));
    const TQ3Point3D infOrigin{kInf, 0, 0};
    EXPECT_EQ(Q3Matrix4x4_SetRotateAboutPoint(&m, &infOrigin, 0.5f, 0, 0), &m);
    EXPECT_FALSE(std::isfinite(m.value[3][0]));
    const TQ3Vector3D nan{kNaN, 0, 0}, v{0, 1, 0};
    EXPECT_EQ(Q3Matrix4x4_SetRotateVectorToVector(&m, &nan, &v), &m); // NaN is not a zero length
    EXPECT_TRUE(std::isnan(m.value[0][0]));
    const TQ3Vector3D inf{kInf, 1, 0};
    EXPECT_EQ(Q3Matrix4x4_SetRotateVectorToVector(&m, &inf, &v), &m); // inf / inf
    EXPECT_TRUE(std::isnan(m.value[0][0]));
}

TEST_F(MathMatrixApiTest, FourByFourRotationsRejectNull)
{
    const TQ3Point3D origin{0, 0, 0};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetRotate_XYZ(nullptr, 1, 2, 3), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetRotateAboutPoint(nullptr, &origin, 1, 2, 3), nullptr),
                    kQ3ErrorNULLParameter);
    TQ3Matrix4x4 m = filledWith<TQ3Matrix4x4>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Matrix4x4_SetRotateAboutPoint(&m, nullptr, 1, 2, 3), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_TRUE(sameBits(m, filledWith<TQ3Matrix4x4>(7)));
}

// ---- Before Q3Initialize ----------------------------------------------------------------------------

TEST(MathMatrixApiUninitialized, EveryCallFailsWithNotInitializedAndChangesNothing)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    TQ3Matrix3x3 r3 = filledWith<TQ3Matrix3x3>(7);
    TQ3Matrix4x4 r4 = filledWith<TQ3Matrix4x4>(7);
    const TQ3Point2D p2{0, 0};
    const TQ3Point3D p3{0, 0, 0};
    const TQ3Vector3D v{1, 0, 0};
    const TQ3Quaternion q{1, 0, 0, 0};
    int calls = 0, failures = 0;
    auto check = [&](bool failedValue) {
        ++calls;
        if (failedValue && Q3Error_Get(nullptr) == kQ3ErrorNotInitialized)
            ++failures;
    };
    check(Q3Matrix3x3_Copy(&kIdentity3x3, &r3) == nullptr);
    check(Q3Matrix3x3_SetIdentity(&r3) == nullptr);
    check(Q3Matrix3x3_Transpose(&kIdentity3x3, &r3) == nullptr);
    check(Q3Matrix3x3_Invert(&kIdentity3x3, &r3) == nullptr);
    check(Q3Matrix3x3_Adjoint(&kIdentity3x3, &r3) == nullptr);
    check(Q3Matrix3x3_Multiply(&kIdentity3x3, &kIdentity3x3, &r3) == nullptr);
    check(Q3Matrix3x3_SetTranslate(&r3, 1, 2) == nullptr);
    check(Q3Matrix3x3_SetScale(&r3, 1, 2) == nullptr);
    check(Q3Matrix3x3_SetRotateAboutPoint(&r3, &p2, 1) == nullptr);
    check(Q3Matrix4x4_SetRotateAboutPoint(&r4, &p3, 1, 2, 3) == nullptr);
    check(Q3Matrix4x4_SetRotate_XYZ(&r4, 1, 2, 3) == nullptr);
    check(Q3Matrix4x4_SetRotateVectorToVector(&r4, &v, &v) == nullptr);
    check(Q3Matrix4x4_SetQuaternion(&r4, &q) == nullptr);
    check(Q3Matrix3x3_Determinant(&kIdentity3x3) == 0.0f);
    check(Q3Matrix4x4_Determinant(&kIdentity4x4) == 0.0f);
    EXPECT_EQ(calls, 15);
    EXPECT_EQ(failures, calls);
    EXPECT_TRUE(sameBits(r3, filledWith<TQ3Matrix3x3>(7)));
    EXPECT_TRUE(sameBits(r4, filledWith<TQ3Matrix4x4>(7)));
}

} // namespace
