// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DMath.h's bounding box and bounding sphere calls: unions computed by
// hand, empty bounds (isEmpty any nonzero int), bounds of strided point
// arrays at 0, 1 and many points, counts no array could hold, strides
// smaller than a point, and bounds that hold their points exactly after
// rounding.

#include "MathTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DMath.h"

#include <climits>
#include <cmath>
#include <cstring>
#include <vector>

namespace {

using namespace q3test;
class MathBoundsApiTest : public Q3ApiTest {
protected:
    // Results filled with 7s, to see that a refused call leaves them alone.
    TQ3BoundingBox m_box = filledWith<TQ3BoundingBox>(7);
    TQ3BoundingSphere m_sphere = filledWith<TQ3BoundingSphere>(7);

    // Each of the four array calls, into the members (NULL with nullResult),
    // from `count` points of p or p4 at their own size, fails with `code`.
    void expectArrayCallsFail(bool nullResult, const TQ3Point3D* p, const TQ3RationalPoint4D* p4, unsigned long count,
                              TQ3Error code)
    {
        TQ3BoundingBox* b = nullResult ? nullptr : &m_box;
        TQ3BoundingSphere* s = nullResult ? nullptr : &m_sphere;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingBox_SetFromPoints3D(b, p, count, sizeof *p), nullptr), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingBox_SetFromRationalPoints4D(b, p4, count, sizeof *p4), nullptr), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingSphere_SetFromPoints3D(s, p, count, sizeof *p), nullptr), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingSphere_SetFromRationalPoints4D(s, p4, count, sizeof *p4), nullptr), code);
    }

    void expectResultsUntouched()
    {
        EXPECT_TRUE(sameBits(m_box, filledWith<TQ3BoundingBox>(7)));
        EXPECT_TRUE(sameBits(m_sphere, filledWith<TQ3BoundingSphere>(7)));
    }
};

TQ3BoundingBox box(TQ3Point3D min, TQ3Point3D max)
{
    return TQ3BoundingBox{min, max, kQ3False};
}

TQ3BoundingSphere sphere(TQ3Point3D origin, float radius)
{
    return TQ3BoundingSphere{origin, radius, kQ3False};
}

// A bound whose isEmpty holds an int outside TQ3Boolean, as C code may store.
template <class Bound>
Bound withRawIsEmpty(Bound bound, int raw)
{
    static_assert(sizeof(bound.isEmpty) == sizeof raw, "TQ3Boolean is int-sized");
    std::memcpy(&bound.isEmpty, &raw, sizeof raw);
    return bound;
}

template <class Bound>
int rawIsEmpty(const Bound& bound)
{
    int raw;
    std::memcpy(&raw, &bound.isEmpty, sizeof raw);
    return raw;
}

double distance(const TQ3Point3D& a, double x, double y, double z)
{
    return std::sqrt((a.x - x) * (a.x - x) + (a.y - y) * (a.y - y) + (a.z - z) * (a.z - z));
}

const TQ3BoundingBox kEmptyBox{{0, 0, 0}, {0, 0, 0}, kQ3True};
const TQ3BoundingSphere kEmptySphere{{0, 0, 0}, 0, kQ3True};

struct Vertex {
    int tag;
    TQ3Point3D point;
    float extra;
};

// ---- Boxes: copy and set -------------------------------------------------------------------

TEST_F(MathBoundsApiTest, BoxCopyCopiesEveryByte)
{
    TQ3BoundingBox src = withRawIsEmpty(box({1, kNaN, 3}, {-1, 5, kInf}), 5);
    TQ3BoundingBox dest{};
    EXPECT_EQ(Q3BoundingBox_Copy(&src, &dest), &dest);
    EXPECT_TRUE(sameBits(dest, src));
    EXPECT_EQ(Q3BoundingBox_Copy(&dest, &dest), &dest);
    EXPECT_TRUE(sameBits(dest, src));
    expectEachNullRejected("Q3BoundingBox_Copy", Q3BoundingBox_Copy, &src, &dest);
}

TEST_F(MathBoundsApiTest, BoxSetStoresItsFieldsAsGiven)
{
    const TQ3Point3D min{5, kNaN, 0}, max{-5, 2, kInf};
    TQ3BoundingBox b = filledWith<TQ3BoundingBox>(7);
    EXPECT_EQ(Q3BoundingBox_Set(&b, &min, &max, kQ3False), &b); // min above max is not checked
    EXPECT_TRUE(sameBits(b.min, min));
    EXPECT_TRUE(sameBits(b.max, max));
    EXPECT_EQ(b.isEmpty, kQ3False);
    EXPECT_EQ(Q3BoundingBox_Set(&b, &min, &max, TQ3Boolean(5)), &b);
    EXPECT_EQ(rawIsEmpty(b), int(kQ3True)); // any nonzero value is stored as kQ3True
    TQ3BoundingBox untouched = filledWith<TQ3BoundingBox>(7);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingBox_Set(nullptr, &min, &max, kQ3False), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingBox_Set(&untouched, nullptr, &max, kQ3False), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingBox_Set(&untouched, &min, nullptr, kQ3False), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_TRUE(sameBits(untouched, filledWith<TQ3BoundingBox>(7)));
}

// ---- Boxes: unions -------------------------------------------------------------------------------

TEST_F(MathBoundsApiTest, BoxUnionTakesTheLeastMinAndGreatestMax)
{
    TQ3BoundingBox a = box({0, -1, 2}, {1, 1, 3}), b = box({-2, 0, 2.5f}, {0.5f, 4, 10});
    TQ3BoundingBox r{};
    EXPECT_EQ(Q3BoundingBox_Union(&a, &b, &r), &r);
    EXPECT_TRUE(sameBits(r, box({-2, -1, 2}, {1, 4, 10})));
    EXPECT_EQ(Q3BoundingBox_Union(&a, &b, &a), &a); // result is v1
    EXPECT_TRUE(sameBits(a, r));
    TQ3BoundingBox c = box({100, 100, 100}, {101, 101, 101});
    EXPECT_EQ(Q3BoundingBox_Union(&b, &c, &c), &c); // result is v2
    EXPECT_TRUE(sameBits(c, box({-2, 0, 2.5f}, {101, 101, 101})));
}

TEST_F(MathBoundsApiTest, BoxUnionIgnoresEmptyBoxesWhateverTheirOtherFields)
{
    const TQ3BoundingBox a = box({0, 0, 0}, {1, 1, 1});
    const TQ3BoundingBox empty = withRawIsEmpty(box({-100, -100, -100}, {kNaN, 100, 100}), 1);
    const TQ3BoundingBox oddEmpty = withRawIsEmpty(box({-5, -5, -5}, {5, 5, 5}), -3);
    TQ3BoundingBox r{};
    EXPECT_EQ(Q3BoundingBox_Union(&a, &empty, &r), &r);
    EXPECT_TRUE(sameBits(r, a));
    EXPECT_EQ(Q3BoundingBox_Union(&oddEmpty, &a, &r), &r);
    EXPECT_TRUE(sameBits(r, a));
    EXPECT_EQ(Q3BoundingBox_Union(&empty, &oddEmpty, &r), &r);
    EXPECT_TRUE(sameBits(r, kEmptyBox));
    // A box with isEmpty 0 is not empty, whatever it holds.
    const TQ3BoundingBox point = box({2, 2, 2}, {2, 2, 2});
    Q3BoundingBox_Union(&point, &empty, &r);
    EXPECT_TRUE(sameBits(r, point));
}

TEST_F(MathBoundsApiTest, BoxUnionPropagatesNaNAndInfinities)
{
    const TQ3BoundingBox a = box({kNaN, 0, -kInf}, {1, 1, 1}), b = box({0, 0, 0}, {2, kInf, kNaN});
    TQ3BoundingBox r{};
    EXPECT_EQ(Q3BoundingBox_Union(&a, &b, &r), &r);
    EXPECT_TRUE(std::isnan(r.min.x));
    EXPECT_EQ(r.min.z, -kInf);
    EXPECT_EQ(r.max.y, kInf);
    EXPECT_TRUE(std::isnan(r.max.z));
    EXPECT_EQ(r.max.x, 2.0f);
}

TEST_F(MathBoundsApiTest, BoxUnionPointGrowsTheBoxToThePoint)
{
    TQ3BoundingBox b = box({0, 0, 0}, {1, 1, 1});
    const TQ3Point3D outside{-2, 0.5f, 3}, inside{0.5f, 0.5f, 0.5f};
    EXPECT_EQ(Q3BoundingBox_UnionPoint3D(&b, &outside, &b), &b); // in place
    EXPECT_TRUE(sameBits(b, box({-2, 0, 0}, {1, 1, 3})));
    TQ3BoundingBox r{};
    EXPECT_EQ(Q3BoundingBox_UnionPoint3D(&b, &inside, &r), &r);
    EXPECT_TRUE(sameBits(r, b));
    EXPECT_EQ(Q3BoundingBox_UnionPoint3D(&kEmptyBox, &outside, &r), &r);
    EXPECT_TRUE(sameBits(r, box(outside, outside)));
    const TQ3Point3D nan{kNaN, 0, 0};
    Q3BoundingBox_UnionPoint3D(&b, &nan, &r);
    EXPECT_TRUE(std::isnan(r.min.x) && std::isnan(r.max.x));
    EXPECT_EQ(r.max.z, 3.0f);
}

TEST_F(MathBoundsApiTest, BoxUnionRationalPointUsesThePointItStandsForRoundedOutwards)
{
    TQ3BoundingBox b = box({0, 0, 0}, {0, 0, 0});
    const TQ3RationalPoint4D p{2, -4, 6, 2}, third{1, 1, -1, 3}, atInfinity{5, 0, 0, 0};
    TQ3BoundingBox r{};
    EXPECT_EQ(Q3BoundingBox_UnionRationalPoint4D(&b, &p, &r), &r);
    EXPECT_TRUE(sameBits(r, box({0, -2, 0}, {1, 0, 3})));
    // 1/3 is no float: the box reaches the floats on either side of it.
    EXPECT_EQ(Q3BoundingBox_UnionRationalPoint4D(&kEmptyBox, &third, &r), &r);
    EXPECT_LE(double(r.min.x), 1.0 / 3);
    EXPECT_GE(double(r.max.x), 1.0 / 3);
    EXPECT_EQ(std::nextafter(r.min.x, 1.0f), r.max.x);
    EXPECT_LE(double(r.min.z), -1.0 / 3);
    EXPECT_GE(double(r.max.z), -1.0 / 3);
    EXPECT_EQ(Q3BoundingBox_UnionRationalPoint4D(&b, &atInfinity, &b), &b); // w = 0: undivided
    EXPECT_EQ(b.max.x, 5.0f);
}

TEST_F(MathBoundsApiTest, BoxUnionsRejectNullAndLeaveTheResultAlone)
{
    const TQ3BoundingBox a = box({0, 0, 0}, {1, 1, 1});
    const TQ3Point3D p{1, 2, 3};
    const TQ3RationalPoint4D p4{1, 2, 3, 1};
    TQ3BoundingBox r = filledWith<TQ3BoundingBox>(7);
    expectEachNullRejected("Q3BoundingBox_Union", Q3BoundingBox_Union, &a, &a, &r);
    expectEachNullRejected("Q3BoundingBox_UnionPoint3D", Q3BoundingBox_UnionPoint3D, &a, &p, &r);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingBox_UnionRationalPoint4D(nullptr, &p4, &r), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingBox_UnionRationalPoint4D(&a, nullptr, &r), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingBox_UnionRationalPoint4D(&a, &p4, nullptr), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_TRUE(sameBits(r, filledWith<TQ3BoundingBox>(7)));
}

// ---- Boxes from point arrays ----------------------------------------------------------------------

TEST_F(MathBoundsApiTest, BoxFromPointsHoldsExactlyThePointsAtAnyStride)
{
    const std::vector<Vertex> vertices = {
        {1, {1, 2, 3}, 0}, {2, {-4, 0.5f, 2}, 0}, {3, {0, 7, -1}, 0}, {4, {2, -3, 0.25f}, 0}};
    TQ3BoundingBox b = filledWith<TQ3BoundingBox>(7);
    EXPECT_EQ(Q3BoundingBox_SetFromPoints3D(&b, &vertices[0].point, vertices.size(), sizeof(Vertex)), &b);
    EXPECT_TRUE(sameBits(b, box({-4, -3, -1}, {2, 7, 3})));
    // One point: a box of no size.
    EXPECT_EQ(Q3BoundingBox_SetFromPoints3D(&b, &vertices[2].point, 1, sizeof(TQ3Point3D)), &b);
    EXPECT_TRUE(sameBits(b, box({0, 7, -1}, {0, 7, -1})));
    // Rational points, divided by w and rounded outwards.
    const TQ3RationalPoint4D r4[] = {{2, 4, 6, 2}, {1, 0, 0, 3}, {-9, 3, 3, 3}};
    EXPECT_EQ(Q3BoundingBox_SetFromRationalPoints4D(&b, r4, 3, sizeof r4[0]), &b);
    EXPECT_EQ(b.min.x, -3.0f);
    EXPECT_EQ(b.max.y, 2.0f);
    EXPECT_EQ(b.max.z, 3.0f);
    EXPECT_EQ(b.min.z, 0.0f);
    EXPECT_GE(double(b.max.x), 1.0 / 3);
    EXPECT_EQ(b.isEmpty, kQ3False);
}

TEST_F(MathBoundsApiTest, BoxOfNoPointsIsEmptyAndTheArrayMayBeNull)
{
    const TQ3Point3D p{1, 2, 3};
    TQ3BoundingBox b = filledWith<TQ3BoundingBox>(7);
    EXPECT_EQ(Q3BoundingBox_SetFromPoints3D(&b, nullptr, 0, sizeof(TQ3Point3D)), &b);
    EXPECT_TRUE(sameBits(b, kEmptyBox));
    b = filledWith<TQ3BoundingBox>(7);
    EXPECT_EQ(Q3BoundingBox_SetFromPoints3D(&b, &p, 0, sizeof p), &b);
    EXPECT_TRUE(sameBits(b, kEmptyBox));
    b = filledWith<TQ3BoundingBox>(7);
    EXPECT_EQ(Q3BoundingBox_SetFromRationalPoints4D(&b, nullptr, 0, sizeof(TQ3RationalPoint4D)), &b);
    EXPECT_TRUE(sameBits(b, kEmptyBox));
}

TEST_F(MathBoundsApiTest, BoxFromPointsPropagatesNaN)
{
    const TQ3Point3D p[] = {{0, 0, 0}, {kNaN, 1, kInf}, {2, 2, 2}};
    TQ3BoundingBox b{};
    EXPECT_EQ(Q3BoundingBox_SetFromPoints3D(&b, p, 3, sizeof p[0]), &b);
    EXPECT_TRUE(std::isnan(b.min.x) && std::isnan(b.max.x));
    EXPECT_EQ(b.max.z, kInf);
    EXPECT_EQ(b.max.y, 2.0f);
}

// ---- Spheres: copy, set, unions ------------------------------------------------------------------------

TEST_F(MathBoundsApiTest, SphereCopyAndSetStoreTheirFields)
{
    const TQ3BoundingSphere src = withRawIsEmpty(sphere({1, 2, kNaN}, -4), 9);
    TQ3BoundingSphere dest{};
    EXPECT_EQ(Q3BoundingSphere_Copy(&src, &dest), &dest);
    EXPECT_TRUE(sameBits(dest, src));
    EXPECT_EQ(Q3BoundingSphere_Copy(&dest, &dest), &dest);
    EXPECT_TRUE(sameBits(dest, src));
    const TQ3Point3D origin{3, -1, 0.5f};
    EXPECT_EQ(Q3BoundingSphere_Set(&dest, &origin, -2, kQ3False), &dest); // the radius is not checked
    EXPECT_TRUE(sameBits(dest, sphere(origin, -2)));
    EXPECT_EQ(Q3BoundingSphere_Set(&dest, &origin, kNaN, TQ3Boolean(2)), &dest);
    EXPECT_EQ(rawIsEmpty(dest), int(kQ3True));
    EXPECT_TRUE(std::isnan(dest.radius));
    TQ3BoundingSphere untouched = filledWith<TQ3BoundingSphere>(7);
    expectEachNullRejected("Q3BoundingSphere_Copy", Q3BoundingSphere_Copy, &src, &untouched);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingSphere_Set(nullptr, &origin, 1, kQ3False), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingSphere_Set(&untouched, nullptr, 1, kQ3False), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_TRUE(sameBits(untouched, filledWith<TQ3BoundingSphere>(7)));
}

TEST_F(MathBoundsApiTest, SphereUnionKeepsASphereThatHoldsTheOther)
{
    const TQ3BoundingSphere big = sphere({0, 0, 0}, 10), small = sphere({3, 4, 0}, 5); // touches from inside
    TQ3BoundingSphere r{};
    EXPECT_EQ(Q3BoundingSphere_Union(&big, &small, &r), &r);
    EXPECT_TRUE(sameBits(r, big));
    EXPECT_EQ(Q3BoundingSphere_Union(&small, &big, &r), &r);
    EXPECT_TRUE(sameBits(r, big));
}

TEST_F(MathBoundsApiTest, SphereUnionSpansBothAlongTheLineThroughTheCentres)
{
    // Apart: centres 10 apart, radii 1 and 1 -> radius 6 centred between.
    const TQ3BoundingSphere a = sphere({0, 0, 0}, 1), b = sphere({10, 0, 0}, 1);
    TQ3BoundingSphere r{};
    EXPECT_EQ(Q3BoundingSphere_Union(&a, &b, &r), &r);
    EXPECT_TRUE(sameBits(r, sphere({5, 0, 0}, 6)));
    // Overlapping: radii 2 and 2, centres 3 apart -> radius 3.5, centre 1.5
    // from the first, in place.
    TQ3BoundingSphere c = sphere({0, 0, 0}, 2);
    const TQ3BoundingSphere d = sphere({0, 3, 0}, 2);
    EXPECT_EQ(Q3BoundingSphere_Union(&c, &d, &c), &c);
    EXPECT_TRUE(sameBits(c, sphere({0, 1.5f, 0}, 3.5f)));
    // A general pair: the result holds both, exactly, after rounding.
    const TQ3BoundingSphere e = sphere({0.1f, -2.3f, 7.7f}, 1.3f), f = sphere({-4.9f, 3.3f, 0.2f}, 0.7f);
    EXPECT_EQ(Q3BoundingSphere_Union(&e, &f, &r), &r);
    for (const TQ3BoundingSphere& s : {e, f})
        EXPECT_LE(distance(r.origin, s.origin.x, s.origin.y, s.origin.z) + s.radius, double(r.radius));
    const double expected = (distance(e.origin, f.origin.x, f.origin.y, f.origin.z) + 1.3f + 0.7f) / 2;
    EXPECT_NEAR(r.radius, expected, 1e-5);
}

TEST_F(MathBoundsApiTest, SphereUnionIgnoresEmptySpheres)
{
    const TQ3BoundingSphere a = sphere({1, 2, 3}, 4);
    const TQ3BoundingSphere empty = withRawIsEmpty(sphere({100, 0, 0}, kNaN), 1);
    const TQ3BoundingSphere oddEmpty = withRawIsEmpty(sphere({-100, 0, 0}, 1), 77);
    TQ3BoundingSphere r{};
    EXPECT_EQ(Q3BoundingSphere_Union(&empty, &a, &r), &r);
    EXPECT_TRUE(sameBits(r, a));
    EXPECT_EQ(Q3BoundingSphere_Union(&a, &oddEmpty, &r), &r);
    EXPECT_TRUE(sameBits(r, a));
    EXPECT_EQ(Q3BoundingSphere_Union(&empty, &oddEmpty, &r), &r);
    EXPECT_TRUE(sameBits(r, kEmptySphere));
}

TEST_F(MathBoundsApiTest, SphereUnionPointGrowsTheSphereJustEnough)
{
    TQ3BoundingSphere s = sphere({0, 0, 0}, 1);
    const TQ3Point3D outside{3, 0, 0}, inside{0.5f, 0.5f, 0};
    TQ3BoundingSphere r{};
    EXPECT_EQ(Q3BoundingSphere_UnionPoint3D(&s, &inside, &r), &r);
    EXPECT_TRUE(sameBits(r, s));
    EXPECT_EQ(Q3BoundingSphere_UnionPoint3D(&s, &outside, &s), &s); // in place: from -1 to 3
    EXPECT_TRUE(sameBits(s, sphere({1, 0, 0}, 2)));
    EXPECT_EQ(Q3BoundingSphere_UnionPoint3D(&kEmptySphere, &outside, &r), &r);
    EXPECT_TRUE(sameBits(r, sphere(outside, 0)));
    const TQ3RationalPoint4D p4{-6, 0, 0, 2}; // (-3, 0, 0)
    EXPECT_EQ(Q3BoundingSphere_UnionRationalPoint4D(&s, &p4, &r), &r);
    EXPECT_TRUE(sameBits(r, sphere({0, 0, 0}, 3)));
    const TQ3RationalPoint4D atInfinity{0, 7, 0, 0}; // w = 0: (0, 7, 0) undivided
    EXPECT_EQ(Q3BoundingSphere_UnionRationalPoint4D(&kEmptySphere, &atInfinity, &r), &r);
    EXPECT_TRUE(sameBits(r, sphere({0, 7, 0}, 0)));
}

TEST_F(MathBoundsApiTest, SphereUnionsPropagateNaN)
{
    const TQ3BoundingSphere s = sphere({0, 0, 0}, 1), nanRadius = sphere({5, 0, 0}, kNaN);
    TQ3BoundingSphere r{};
    EXPECT_EQ(Q3BoundingSphere_Union(&s, &nanRadius, &r), &r);
    EXPECT_TRUE(std::isnan(r.radius));
    const TQ3Point3D nan{kNaN, 0, 0};
    EXPECT_EQ(Q3BoundingSphere_UnionPoint3D(&s, &nan, &r), &r);
    EXPECT_TRUE(std::isnan(r.radius));
    EXPECT_EQ(r.isEmpty, kQ3False);
}

TEST_F(MathBoundsApiTest, SphereUnionsRejectNullAndLeaveTheResultAlone)
{
    const TQ3BoundingSphere s = sphere({0, 0, 0}, 1);
    const TQ3Point3D p{1, 2, 3};
    const TQ3RationalPoint4D p4{1, 2, 3, 1};
    TQ3BoundingSphere r = filledWith<TQ3BoundingSphere>(7);
    expectEachNullRejected("Q3BoundingSphere_Union", Q3BoundingSphere_Union, &s, &s, &r);
    expectEachNullRejected("Q3BoundingSphere_UnionPoint3D", Q3BoundingSphere_UnionPoint3D, &s, &p, &r);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingSphere_UnionRationalPoint4D(nullptr, &p4, &r), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingSphere_UnionRationalPoint4D(&s, nullptr, &r), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingSphere_UnionRationalPoint4D(&s, &p4, nullptr), nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_TRUE(sameBits(r, filledWith<TQ3BoundingSphere>(7)));
}

// ---- Spheres from point arrays ---------------------------------------------------------------------------

TEST_F(MathBoundsApiTest, SphereFromPointsIsCentredOnTheirBoxAndReachesTheFarthest)
{
    const std::vector<Vertex> vertices = {
        {1, {1, 2, 3}, 0}, {2, {-4, 0.5f, 2}, 0}, {3, {0, 7, -1}, 0}, {4, {2, -3, 0.25f}, 0}};
    TQ3BoundingSphere s = filledWith<TQ3BoundingSphere>(7);
    EXPECT_EQ(Q3BoundingSphere_SetFromPoints3D(&s, &vertices[0].point, vertices.size(), sizeof(Vertex)), &s);
    // The box is (-4, -3, -1) to (2, 7, 3): centre (-1, 2, 1).
    EXPECT_TRUE(sameBits(s.origin, TQ3Point3D{-1, 2, 1}));
    double farthest = 0;
    for (const Vertex& v : vertices)
        farthest = std::max(farthest, distance(v.point, -1, 2, 1));
    EXPECT_FLOAT_EQ(s.radius, float(farthest));
    for (const Vertex& v : vertices)
        EXPECT_LE(distance(v.point, s.origin.x, s.origin.y, s.origin.z), double(s.radius));
    EXPECT_EQ(s.isEmpty, kQ3False);
    // One point: radius 0.
    EXPECT_EQ(Q3BoundingSphere_SetFromPoints3D(&s, &vertices[1].point, 1, sizeof(Vertex)), &s);
    EXPECT_TRUE(sameBits(s, sphere({-4, 0.5f, 2}, 0)));
}

TEST_F(MathBoundsApiTest, SphereFromRationalPointsHoldsThePointsTheyStandFor)
{
    const TQ3RationalPoint4D r4[] = {{1, 1, 1, 3}, {-2, 0.5f, 4, 7}, {10, -3, 2, 11}, {0, 0, 1, 0}};
    TQ3BoundingSphere s{};
    EXPECT_EQ(Q3BoundingSphere_SetFromRationalPoints4D(&s, r4, 4, sizeof r4[0]), &s);
    for (const TQ3RationalPoint4D& p : r4) {
        const double w = p.w == 0 ? 1 : p.w;
        EXPECT_LE(distance(s.origin, p.x / w, p.y / w, p.z / w), double(s.radius));
    }
    TQ3BoundingSphere empty = filledWith<TQ3BoundingSphere>(7);
    EXPECT_EQ(Q3BoundingSphere_SetFromRationalPoints4D(&empty, nullptr, 0, sizeof r4[0]), &empty);
    EXPECT_TRUE(sameBits(empty, kEmptySphere));
    empty = filledWith<TQ3BoundingSphere>(7);
    EXPECT_EQ(Q3BoundingSphere_SetFromPoints3D(&empty, nullptr, 0, sizeof(TQ3Point3D)), &empty);
    EXPECT_TRUE(sameBits(empty, kEmptySphere));
}

TEST_F(MathBoundsApiTest, SphereFromPointsPropagatesNaN)
{
    const TQ3Point3D p[] = {{0, 0, 0}, {1, kNaN, 0}, {2, 2, 2}};
    TQ3BoundingSphere s{};
    EXPECT_EQ(Q3BoundingSphere_SetFromPoints3D(&s, p, 3, sizeof p[0]), &s);
    EXPECT_TRUE(std::isnan(s.radius));
    EXPECT_TRUE(std::isnan(s.origin.y));
}

// ---- The array rules, for all four array calls ----------------------------------------------------------

TEST_F(MathBoundsApiTest, ArrayCallsRejectNullArraysWithPointsAndNullBounds)
{
    const TQ3Point3D p{1, 2, 3};
    const TQ3RationalPoint4D p4{1, 2, 3, 1};
    for (unsigned long count : {1UL, 2UL, ULONG_MAX})
        expectArrayCallsFail(false, nullptr, nullptr, count, kQ3ErrorNULLParameter);
    for (unsigned long count : {0UL, 1UL})
        expectArrayCallsFail(true, &p, &p4, count, kQ3ErrorNULLParameter);
    expectResultsUntouched();
}

// The arrays hold one point: counts beyond what any array could hold must
// fail before the first read (AddressSanitizer watches).
TEST_F(MathBoundsApiTest, ArrayCallsRejectCountsNoArrayCouldHoldBeforeReading)
{
    const TQ3Point3D p{1, 2, 3};
    const TQ3RationalPoint4D p4{1, 2, 3, 1};
    for (unsigned long count : {ULONG_MAX, ULONG_MAX / 12 + 1, 1UL << 62, (unsigned long)LONG_MAX})
        expectArrayCallsFail(false, &p, &p4, count, kQ3ErrorParameterOutOfRange);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingBox_SetFromPoints3D(&m_box, &p, 2, ULONG_MAX), nullptr),
                    kQ3ErrorParameterOutOfRange);
    expectResultsUntouched();
}

TEST_F(MathBoundsApiTest, ArrayCallsRejectStridesSmallerThanAPointEvenForNoPoints)
{
    const TQ3Point3D p[2] = {{1, 2, 3}, {4, 5, 6}};
    const TQ3RationalPoint4D p4[2] = {{1, 2, 3, 1}, {4, 5, 6, 1}};
    for (unsigned long count : {0UL, 1UL, 2UL}) {
        for (unsigned long stride : {0UL, 4UL, sizeof(TQ3Point3D) - 1}) {
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingBox_SetFromPoints3D(&m_box, p, count, stride), nullptr),
                            kQ3ErrorParameterOutOfRange);
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingSphere_SetFromPoints3D(&m_sphere, p, count, stride), nullptr),
                            kQ3ErrorParameterOutOfRange);
        }
        // A TQ3Point3D's size is too small for a TQ3RationalPoint4D.
        for (unsigned long stride : {0UL, sizeof(TQ3Point3D), sizeof(TQ3RationalPoint4D) - 1}) {
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingBox_SetFromRationalPoints4D(&m_box, p4, count, stride), nullptr),
                            kQ3ErrorParameterOutOfRange);
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3BoundingSphere_SetFromRationalPoints4D(&m_sphere, p4, count, stride), nullptr),
                            kQ3ErrorParameterOutOfRange);
        }
    }
    expectResultsUntouched();
}

TEST_F(MathBoundsApiTest, ArrayPointsNeedNotBeAligned)
{
    constexpr unsigned long kStride = sizeof(TQ3Point3D) + 2;
    const TQ3Point3D points[] = {{1, -1, 0}, {3, 5, -2}, {-1, 2, 4}};
    std::vector<unsigned char> bytes(3 + kStride * 3);
    for (int i = 0; i < 3; ++i)
        std::memcpy(&bytes[3 + kStride * i], &points[i], sizeof(TQ3Point3D));
    const auto* first = reinterpret_cast<const TQ3Point3D*>(&bytes[3]);
    TQ3BoundingBox b{};
    EXPECT_EQ(Q3BoundingBox_SetFromPoints3D(&b, first, 3, kStride), &b);
    EXPECT_TRUE(sameBits(b, box({-1, -1, -2}, {3, 5, 4})));
    TQ3BoundingSphere s{};
    EXPECT_EQ(Q3BoundingSphere_SetFromPoints3D(&s, first, 3, kStride), &s);
    EXPECT_TRUE(sameBits(s.origin, TQ3Point3D{1, 2, 1}));
}

// ---- Before Q3Initialize -------------------------------------------------------------------------------------

TEST(MathBoundsApiUninitialized, EveryCallFailsWithNotInitializedAndChangesNothing)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    const TQ3Point3D p{1, 2, 3};
    const TQ3RationalPoint4D p4{1, 2, 3, 1};
    const TQ3BoundingBox a = box({0, 0, 0}, {1, 1, 1});
    const TQ3BoundingSphere s = sphere({0, 0, 0}, 1);
    TQ3BoundingBox rb = filledWith<TQ3BoundingBox>(7);
    TQ3BoundingSphere rs = filledWith<TQ3BoundingSphere>(7);
    int calls = 0, failures = 0;
    auto check = [&](bool failedValue) {
        ++calls;
        if (failedValue && Q3Error_Get(nullptr) == kQ3ErrorNotInitialized)
            ++failures;
    };
    check(Q3BoundingBox_Copy(&a, &rb) == nullptr);
    check(Q3BoundingBox_Union(&a, &a, &rb) == nullptr);
    check(Q3BoundingBox_Set(&rb, &p, &p, kQ3False) == nullptr);
    check(Q3BoundingBox_UnionPoint3D(&a, &p, &rb) == nullptr);
    check(Q3BoundingBox_UnionRationalPoint4D(&a, &p4, &rb) == nullptr);
    check(Q3BoundingBox_SetFromPoints3D(&rb, &p, 1, sizeof p) == nullptr);
    check(Q3BoundingBox_SetFromRationalPoints4D(&rb, &p4, 1, sizeof p4) == nullptr);
    check(Q3BoundingSphere_Copy(&s, &rs) == nullptr);
    check(Q3BoundingSphere_Union(&s, &s, &rs) == nullptr);
    check(Q3BoundingSphere_Set(&rs, &p, 1, kQ3False) == nullptr);
    check(Q3BoundingSphere_UnionPoint3D(&s, &p, &rs) == nullptr);
    check(Q3BoundingSphere_UnionRationalPoint4D(&s, &p4, &rs) == nullptr);
    check(Q3BoundingSphere_SetFromPoints3D(&rs, &p, 1, sizeof p) == nullptr);
    check(Q3BoundingSphere_SetFromRationalPoints4D(&rs, &p4, 1, sizeof p4) == nullptr);
    EXPECT_EQ(calls, 14);
    EXPECT_EQ(failures, calls);
    EXPECT_TRUE(sameBits(rb, filledWith<TQ3BoundingBox>(7)));
    EXPECT_TRUE(sameBits(rs, filledWith<TQ3BoundingSphere>(7)));
}

} // namespace
