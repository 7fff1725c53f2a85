// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DMath.h's three transform-array calls: every element as the single-
// point call gives it, at any stride, and the array rules at the top of
// QD3DMath.h (NULL only with no points, negative and huge counts, strides
// smaller than a point) checked before anything is read or written.

#include "MathTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DMath.h"

#include <climits>
#include <cmath>
#include <cstring>
#include <vector>

namespace {

using namespace q3test;

// Rotation, scale, translation and a perspective column together.
const TQ3Matrix4x4 kMatrix = matrix4x4Of({0.5f, 1, 0, 0.1f, -2, 0.25f, 1, 0, 0, 3, 2, -0.2f, 7, -4, 1.5f, 1});

class MathTransformArrayApiTest : public Q3ApiTest {
protected:
    // Each of the three array calls on one point (in to out, in to out4, in4 to
    // out4) refuses `count` as out of range.
    void expectCountRejected(long count, const TQ3Point3D& in, const TQ3RationalPoint4D& in4, TQ3Point3D& out,
                             TQ3RationalPoint4D& out4)
    {
        EXPECT_Q3_ERROR(
            EXPECT_EQ(Q3Point3D_To3DTransformArray(&in, &kMatrix, &out, count, sizeof in, sizeof out), kQ3Failure),
            kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(
            EXPECT_EQ(Q3Point3D_To4DTransformArray(&in, &kMatrix, &out4, count, sizeof in, sizeof out4), kQ3Failure),
            kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RationalPoint4D_To4DTransformArray(&in4, &kMatrix, &out4, count, sizeof in4,
                                                                       sizeof out4),
                                  kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
    }
};

// The points sit inside a larger vertex, as in legacy vertex arrays.
struct Vertex {
    float before;
    TQ3Point3D point;
    int after;
};

struct RationalVertex {
    TQ3RationalPoint4D point;
    double extra;
};

// (p, 1) * M, divided by w unless w is 0.
TQ3Point3D expectedPoint(const TQ3Point3D& p, const TQ3Matrix4x4& m)
{
    const double in[4] = {p.x, p.y, p.z, 1};
    double out[4];
    rowTimes(in, m, out);
    const double w = out[3] == 0 ? 1 : out[3];
    return TQ3Point3D{float(out[0] / w), float(out[1] / w), float(out[2] / w)};
}

TQ3RationalPoint4D expectedRational(const TQ3RationalPoint4D& p, const TQ3Matrix4x4& m)
{
    const double in[4] = {p.x, p.y, p.z, p.w};
    double out[4];
    rowTimes(in, m, out);
    return TQ3RationalPoint4D{float(out[0]), float(out[1]), float(out[2]), float(out[3])};
}

void expectNear(const TQ3Point3D& actual, const TQ3Point3D& expected, int index)
{
    EXPECT_FLOAT_EQ(actual.x, expected.x) << "point " << index;
    EXPECT_FLOAT_EQ(actual.y, expected.y) << "point " << index;
    EXPECT_FLOAT_EQ(actual.z, expected.z) << "point " << index;
}

void expectNear(const TQ3RationalPoint4D& actual, const TQ3RationalPoint4D& expected, int index)
{
    EXPECT_FLOAT_EQ(actual.x, expected.x) << "point " << index;
    EXPECT_FLOAT_EQ(actual.y, expected.y) << "point " << index;
    EXPECT_FLOAT_EQ(actual.z, expected.z) << "point " << index;
    EXPECT_FLOAT_EQ(actual.w, expected.w) << "point " << index;
}

std::vector<TQ3Point3D> somePoints()
{
    return {{1, 2, 3}, {-4, 0.5f, 2}, {0, 0, 0}, {10, -10, 0.25f}, {3, 3, -3}};
}

TEST_F(MathTransformArrayApiTest, To3DTransformsEachPointAsPoint3DTransformAtStridesLargerThanAPoint)
{
    const std::vector<TQ3Point3D> points = somePoints();
    std::vector<Vertex> in, out(points.size(), Vertex{-1, {7, 7, 7}, 42});
    for (const TQ3Point3D& p : points)
        in.push_back(Vertex{-1, p, 42});
    ASSERT_EQ(Q3Point3D_To3DTransformArray(&in[0].point, &kMatrix, &out[0].point, long(points.size()),
                                           sizeof(Vertex), sizeof(Vertex)),
              kQ3Success);
    for (std::size_t i = 0; i < points.size(); ++i) {
        expectNear(out[i].point, expectedPoint(points[i], kMatrix), int(i));
        EXPECT_EQ(out[i].before, -1.0f); // the bytes between points are not touched
        EXPECT_EQ(out[i].after, 42);
    }
}

TEST_F(MathTransformArrayApiTest, To3DWorksInPlaceAndMatchesTheSinglePointCall)
{
    std::vector<TQ3Point3D> points = somePoints();
    const std::vector<TQ3Point3D> original = points;
    ASSERT_EQ(Q3Point3D_To3DTransformArray(points.data(), &kMatrix, points.data(), long(points.size()),
                                           sizeof(TQ3Point3D), sizeof(TQ3Point3D)),
              kQ3Success);
    for (std::size_t i = 0; i < points.size(); ++i) {
        TQ3Point3D single{};
        Q3Point3D_Transform(&original[i], &kMatrix, &single);
        EXPECT_TRUE(sameBits(points[i], single)) << "point " << i;
    }
}

TEST_F(MathTransformArrayApiTest, To3DLeavesPointsAtInfinityUndivided)
{
    // w' = x * 0 + ... + 1 * 0 = 0: the point maps to infinity.
    const TQ3Matrix4x4 m = matrix4x4Of({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 0});
    const TQ3Point3D in[] = {{1, 2, 3}, {kNaN, 0, 0}};
    TQ3Point3D out[2];
    ASSERT_EQ(Q3Point3D_To3DTransformArray(in, &m, out, 2, sizeof(TQ3Point3D), sizeof(TQ3Point3D)), kQ3Success);
    EXPECT_EQ(out[0].x, 6.0f);
    EXPECT_EQ(out[0].y, 2.0f);
    EXPECT_EQ(out[0].z, 3.0f);
    EXPECT_TRUE(std::isnan(out[1].x));
}

TEST_F(MathTransformArrayApiTest, To4DKeepsTheHomogeneousResultUndivided)
{
    const std::vector<TQ3Point3D> points = somePoints();
    std::vector<RationalVertex> out(points.size(), RationalVertex{{7, 7, 7, 7}, 0.5});
    ASSERT_EQ(Q3Point3D_To4DTransformArray(points.data(), &kMatrix, &out[0].point, long(points.size()),
                                           sizeof(TQ3Point3D), sizeof(RationalVertex)),
              kQ3Success);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const TQ3RationalPoint4D p{points[i].x, points[i].y, points[i].z, 1};
        expectNear(out[i].point, expectedRational(p, kMatrix), int(i));
        EXPECT_EQ(out[i].extra, 0.5);
    }
}

TEST_F(MathTransformArrayApiTest, RationalTo4DTransformsEachPointAndWorksInPlace)
{
    std::vector<RationalVertex> vertices = {
        {{1, 2, 3, 1}, 1}, {{2, 4, 6, 2}, 2}, {{1, 0, 0, 0}, 3}, {{-1, 5, 2, 0.5f}, 4}};
    const std::vector<RationalVertex> original = vertices;
    ASSERT_EQ(Q3RationalPoint4D_To4DTransformArray(&vertices[0].point, &kMatrix, &vertices[0].point,
                                                   long(vertices.size()), sizeof(RationalVertex),
                                                   sizeof(RationalVertex)),
              kQ3Success);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        expectNear(vertices[i].point, expectedRational(original[i].point, kMatrix), int(i));
        EXPECT_EQ(vertices[i].extra, original[i].extra);
    }
}

TEST_F(MathTransformArrayApiTest, ElementsNeedNotBeAligned)
{
    // A stride of 13 bytes puts every point but the first off a float boundary.
    constexpr unsigned long kStride = sizeof(TQ3Point3D) + 1;
    const std::vector<TQ3Point3D> points = somePoints();
    std::vector<unsigned char> in(1 + kStride * points.size()), out(in.size(), 0xAB);
    for (std::size_t i = 0; i < points.size(); ++i)
        std::memcpy(&in[1 + kStride * i], &points[i], sizeof(TQ3Point3D));
    ASSERT_EQ(Q3Point3D_To3DTransformArray(reinterpret_cast<const TQ3Point3D*>(&in[1]), &kMatrix,
                                           reinterpret_cast<TQ3Point3D*>(&out[1]), long(points.size()), kStride,
                                           kStride),
              kQ3Success);
    for (std::size_t i = 0; i < points.size(); ++i) {
        TQ3Point3D got;
        std::memcpy(&got, &out[1 + kStride * i], sizeof got);
        expectNear(got, expectedPoint(points[i], kMatrix), int(i));
        EXPECT_EQ(out[kStride * (i + 1)], 0xAB); // the byte after each point
    }
    EXPECT_EQ(out[0], 0xAB);
}

TEST_F(MathTransformArrayApiTest, ZeroPointsDoNothingAndAllowNullArrays)
{
    TQ3Point3D in{1, 2, 3}, out = filledWith<TQ3Point3D>(7);
    TQ3RationalPoint4D in4{1, 2, 3, 1}, out4 = filledWith<TQ3RationalPoint4D>(7);
    EXPECT_EQ(Q3Point3D_To3DTransformArray(nullptr, &kMatrix, nullptr, 0, sizeof in, sizeof out), kQ3Success);
    EXPECT_EQ(Q3Point3D_To4DTransformArray(nullptr, &kMatrix, nullptr, 0, sizeof in, sizeof out4), kQ3Success);
    EXPECT_EQ(Q3RationalPoint4D_To4DTransformArray(nullptr, &kMatrix, nullptr, 0, sizeof in4, sizeof out4),
              kQ3Success);
    EXPECT_EQ(Q3Point3D_To3DTransformArray(&in, &kMatrix, &out, 0, sizeof in, sizeof out), kQ3Success);
    EXPECT_EQ(Q3RationalPoint4D_To4DTransformArray(&in4, &kMatrix, &out4, 0, sizeof in4, sizeof out4), kQ3Success);
    EXPECT_TRUE(sameBits(out, filledWith<TQ3Point3D>(7)));
    EXPECT_TRUE(sameBits(out4, filledWith<TQ3RationalPoint4D>(7)));
}

TEST_F(MathTransformArrayApiTest, OnePointIsTransformed)
{
    const TQ3Point3D in{1, 2, 3};
    TQ3Point3D out{};
    ASSERT_EQ(Q3Point3D_To3DTransformArray(&in, &kMatrix, &out, 1, sizeof in, sizeof out), kQ3Success);
    expectNear(out, expectedPoint(in, kMatrix), 0);
    // With one point the strides only need to cover one point.
    TQ3RationalPoint4D out4{};
    ASSERT_EQ(Q3Point3D_To4DTransformArray(&in, &kMatrix, &out4, 1, sizeof in, sizeof out4), kQ3Success);
    expectNear(out4, expectedRational(TQ3RationalPoint4D{1, 2, 3, 1}, kMatrix), 0);
}

TEST_F(MathTransformArrayApiTest, NullMatrixOrNullArraysWithPointsAreRejected)
{
    const TQ3Point3D in[2] = {{1, 2, 3}, {4, 5, 6}};
    const TQ3RationalPoint4D in4[2] = {{1, 2, 3, 1}, {4, 5, 6, 1}};
    TQ3Point3D out[2] = {filledWith<TQ3Point3D>(7), filledWith<TQ3Point3D>(7)};
    TQ3RationalPoint4D out4[2] = {filledWith<TQ3RationalPoint4D>(7), filledWith<TQ3RationalPoint4D>(7)};
    const unsigned long s3 = sizeof(TQ3Point3D), s4 = sizeof(TQ3RationalPoint4D);
    for (long count : {0L, 1L, 2L, LONG_MAX}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_To3DTransformArray(in, nullptr, out, count, s3, s3), kQ3Failure),
                        kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_To4DTransformArray(in, nullptr, out4, count, s3, s4), kQ3Failure),
                        kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(
            EXPECT_EQ(Q3RationalPoint4D_To4DTransformArray(in4, nullptr, out4, count, s4, s4), kQ3Failure),
            kQ3ErrorNULLParameter);
        if (count == 0)
            continue;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_To3DTransformArray(nullptr, &kMatrix, out, count, s3, s3), kQ3Failure),
                        kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_To3DTransformArray(in, &kMatrix, nullptr, count, s3, s3), kQ3Failure),
                        kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_To4DTransformArray(nullptr, &kMatrix, out4, count, s3, s4), kQ3Failure),
                        kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_To4DTransformArray(in, &kMatrix, nullptr, count, s3, s4), kQ3Failure),
                        kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(
            EXPECT_EQ(Q3RationalPoint4D_To4DTransformArray(nullptr, &kMatrix, out4, count, s4, s4), kQ3Failure),
            kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(
            EXPECT_EQ(Q3RationalPoint4D_To4DTransformArray(in4, &kMatrix, nullptr, count, s4, s4), kQ3Failure),
            kQ3ErrorNULLParameter);
    }
    // A negative count is not 0 either: NULL arrays are reported first.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_To3DTransformArray(nullptr, &kMatrix, out, -1, s3, s3), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_TRUE(sameBits(out[0], filledWith<TQ3Point3D>(7)));
    EXPECT_TRUE(sameBits(out4[1], filledWith<TQ3RationalPoint4D>(7)));
}

TEST_F(MathTransformArrayApiTest, NegativeCountsAreRejected)
{
    const TQ3Point3D in{1, 2, 3};
    const TQ3RationalPoint4D in4{1, 2, 3, 1};
    TQ3Point3D out = filledWith<TQ3Point3D>(7);
    TQ3RationalPoint4D out4 = filledWith<TQ3RationalPoint4D>(7);
    for (long count : {-1L, -2L, LONG_MIN})
        expectCountRejected(count, in, in4, out, out4);
    EXPECT_TRUE(sameBits(out, filledWith<TQ3Point3D>(7)));
    EXPECT_TRUE(sameBits(out4, filledWith<TQ3RationalPoint4D>(7)));
}

// The arrays hold one point each: counts beyond what any array could hold
// must fail before the first read or write (AddressSanitizer watches).
TEST_F(MathTransformArrayApiTest, CountsNoArrayCouldHoldAreRejectedBeforeAnythingIsRead)
{
    const TQ3Point3D in{1, 2, 3};
    const TQ3RationalPoint4D in4{1, 2, 3, 1};
    TQ3Point3D out = filledWith<TQ3Point3D>(7);
    TQ3RationalPoint4D out4 = filledWith<TQ3RationalPoint4D>(7);
    for (long count : {LONG_MAX, LONG_MAX / 12 + 1, 1L << 62, 1L << 60})
        expectCountRejected(count, in, in4, out, out4);
    // Two points at a stride that reaches past the end of the address space.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_To3DTransformArray(&in, &kMatrix, &out, 2, ULONG_MAX, sizeof out), kQ3Failure),
                    kQ3ErrorParameterOutOfRange);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_To3DTransformArray(&in, &kMatrix, &out, 2, sizeof in, ULONG_MAX / 2),
                              kQ3Failure),
                    kQ3ErrorParameterOutOfRange);
    EXPECT_TRUE(sameBits(out, filledWith<TQ3Point3D>(7)));
    EXPECT_TRUE(sameBits(out4, filledWith<TQ3RationalPoint4D>(7)));
}

TEST_F(MathTransformArrayApiTest, StridesSmallerThanAPointAreRejectedEvenForZeroPoints)
{
    const TQ3Point3D in[2] = {{1, 2, 3}, {4, 5, 6}};
    const TQ3RationalPoint4D in4[2] = {{1, 2, 3, 1}, {4, 5, 6, 1}};
    TQ3Point3D out[2] = {filledWith<TQ3Point3D>(7), filledWith<TQ3Point3D>(7)};
    TQ3RationalPoint4D out4[2] = {filledWith<TQ3RationalPoint4D>(7), filledWith<TQ3RationalPoint4D>(7)};
    const unsigned long s3 = sizeof(TQ3Point3D), s4 = sizeof(TQ3RationalPoint4D);
    for (long count : {0L, 1L, 2L}) {
        for (unsigned long small : {0UL, 1UL, s3 - 1}) {
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_To3DTransformArray(in, &kMatrix, out, count, small, s3), kQ3Failure),
                            kQ3ErrorParameterOutOfRange);
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_To3DTransformArray(in, &kMatrix, out, count, s3, small), kQ3Failure),
                            kQ3ErrorParameterOutOfRange);
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_To4DTransformArray(in, &kMatrix, out4, count, small, s4), kQ3Failure),
                            kQ3ErrorParameterOutOfRange);
        }
        // s3 is enough for a TQ3Point3D but not for the TQ3RationalPoint4D out.
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Point3D_To4DTransformArray(in, &kMatrix, out4, count, s3, s3), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RationalPoint4D_To4DTransformArray(in4, &kMatrix, out4, count, s3, s4), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RationalPoint4D_To4DTransformArray(in4, &kMatrix, out4, count, s4, s4 - 1),
                                  kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
    }
    EXPECT_TRUE(sameBits(out[1], filledWith<TQ3Point3D>(7)));
    EXPECT_TRUE(sameBits(out4[0], filledWith<TQ3RationalPoint4D>(7)));
}

TEST_F(MathTransformArrayApiTest, NonFiniteValuesGoThroughTheArithmetic)
{
    TQ3Matrix4x4 m = kIdentity4x4;
    m.value[3][0] = kInf;
    const TQ3RationalPoint4D in[] = {{1, 1, 1, 1}, {1, 1, 1, 0}, {kNaN, 1, 1, 1}};
    TQ3RationalPoint4D out[3];
    ASSERT_EQ(Q3RationalPoint4D_To4DTransformArray(in, &m, out, 3, sizeof in[0], sizeof out[0]), kQ3Success);
    EXPECT_EQ(out[0].x, kInf);
    EXPECT_TRUE(std::isnan(out[1].x)); // 0 * inf
    EXPECT_TRUE(std::isnan(out[2].x));
    EXPECT_TRUE(std::isnan(out[2].y)); // NaN * 0 is NaN: one NaN spreads through the row product
}

TEST(MathTransformArrayApiUninitialized, EveryCallFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    const TQ3Point3D in{1, 2, 3};
    const TQ3RationalPoint4D in4{1, 2, 3, 1};
    TQ3Point3D out = filledWith<TQ3Point3D>(7);
    TQ3RationalPoint4D out4 = filledWith<TQ3RationalPoint4D>(7);
    EXPECT_EQ(Q3Point3D_To3DTransformArray(&in, &kIdentity4x4, &out, 1, sizeof in, sizeof out), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3Point3D_To4DTransformArray(&in, &kIdentity4x4, &out4, 1, sizeof in, sizeof out4), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3RationalPoint4D_To4DTransformArray(&in4, &kIdentity4x4, &out4, 1, sizeof in4, sizeof out4),
              kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_TRUE(sameBits(out, filledWith<TQ3Point3D>(7)));
    EXPECT_TRUE(sameBits(out4, filledWith<TQ3RationalPoint4D>(7)));
}

} // namespace
