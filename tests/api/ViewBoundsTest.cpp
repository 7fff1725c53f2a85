// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Bounding-box and bounding-sphere loops. A NURB curve is bounded by its
// control points projected to 3D (x/w, y/w, z/w), as the article says
// QuickDraw 3D does; transforms apply; exact mode transforms every point,
// approximate mode the corners of the local box.

#include "RenderTestSupport.h"

#include "QD3DTransform.h"

#include <cmath>

namespace {

using namespace q3test;

class ViewBoundsTest : public Q3ApiTest {
protected:
    void SetUp() override
    {
        Q3ApiTest::SetUp();
        m_view = Q3View_New();
    }
    void TearDown() override
    {
        Q3Object_Dispose(m_view);
        Q3ApiTest::TearDown();
    }

    TQ3BoundingBox box(TQ3ComputeBounds mode, const std::function<void(TQ3ViewObject)>& submit)
    {
        TQ3BoundingBox result{};
        EXPECT_EQ(Q3View_StartBoundingBox(m_view, mode), kQ3Success);
        submit(m_view);
        EXPECT_EQ(Q3View_EndBoundingBox(m_view, &result), kQ3ViewStatusDone);
        return result;
    }

    TQ3BoundingSphere sphere(TQ3ComputeBounds mode, const std::function<void(TQ3ViewObject)>& submit)
    {
        TQ3BoundingSphere result{};
        EXPECT_EQ(Q3View_StartBoundingSphere(m_view, mode), kQ3Success);
        submit(m_view);
        EXPECT_EQ(Q3View_EndBoundingSphere(m_view, &result), kQ3ViewStatusDone);
        return result;
    }

    static void expectBox(const TQ3BoundingBox& box, TQ3Point3D min, TQ3Point3D max)
    {
        EXPECT_EQ(box.isEmpty, kQ3False);
        EXPECT_NEAR(box.min.x, min.x, 1e-5);
        EXPECT_NEAR(box.min.y, min.y, 1e-5);
        EXPECT_NEAR(box.min.z, min.z, 1e-5);
        EXPECT_NEAR(box.max.x, max.x, 1e-5);
        EXPECT_NEAR(box.max.y, max.y, 1e-5);
        EXPECT_NEAR(box.max.z, max.z, 1e-5);
    }

    TQ3ViewObject m_view = nullptr;
};

TEST_F(ViewBoundsTest, ABoundingLoopNeedsNoCameraRendererOrDrawContext)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    expectBox(box(kQ3ComputeBoundsExact, [&](TQ3ViewObject v) { Q3NURBCurve_Submit(&data, v); }),
              {0, 0, 0}, {3, 1, 0});
}

TEST_F(ViewBoundsTest, ACurveIsBoundedByItsControlPointsNotItsPath)
{
    // The curve itself stays within y 0..1 but its control points reach 4.
    TQ3RationalPoint4D points[4] = {{0, 0, 0, 1}, {1, 4, -2, 1}, {2, -3, 1, 1}, {3, 1, 0, 1}};
    float knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    const TQ3NURBCurveData data = {4, 4, points, knots, nullptr};
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    expectBox(box(kQ3ComputeBoundsExact, [&](TQ3ViewObject v) { Q3Geometry_Submit(curve, v); }),
              {0, -3, -2}, {3, 4, 1});
    Q3Object_Dispose(curve);
}

TEST_F(ViewBoundsTest, RationalControlPointsAreProjectedToThreeD)
{
    TQ3RationalPoint4D points[3] = {{0, 0, 0, 1}, {4, 4, 2, 2}, {6, 0, 0, 2}};
    float knots[6] = {0, 0, 0, 1, 1, 1};
    const TQ3NURBCurveData data = {3, 3, points, knots, nullptr};
    expectBox(box(kQ3ComputeBoundsExact, [&](TQ3ViewObject v) { Q3NURBCurve_Submit(&data, v); }),
              {0, 0, 0}, {3, 2, 1});
}

TEST_F(ViewBoundsTest, TransformsMoveTheBounds)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    const TQ3Vector3D offset = {10, 20, 30};
    const TQ3Vector3D scale = {2, 3, 1};
    expectBox(box(kQ3ComputeBoundsExact,
                  [&](TQ3ViewObject v) {
                      Q3TranslateTransform_Submit(&offset, v);
                      Q3ScaleTransform_Submit(&scale, v);
                      Q3NURBCurve_Submit(&data, v);
                  }),
              {10, 20, 30}, {16, 23, 30});
}

TEST_F(ViewBoundsTest, ApproximateModeTransformsTheLocalBoxCorners)
{
    // Rotated by 45 degrees about z, the exact box holds the rotated control
    // points; the approximate one holds the rotated corners of the local box
    // (0..3 x 0..1), which reach further.
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    const TQ3RotateTransformData rotate = {kQ3AxisZ, float(M_PI / 4)};
    auto submit = [&](TQ3ViewObject v) {
        Q3RotateTransform_Submit(&rotate, v);
        Q3NURBCurve_Submit(&data, v);
    };
    const double c = std::cos(M_PI / 4), s = std::sin(M_PI / 4);
    auto rotated = [&](double x, double y) { return TQ3Point3D{float(x * c - y * s), float(x * s + y * c), 0}; };
    // Control points (0,0), (1,1), (2,0), (3,1).
    const TQ3Point3D p[4] = {rotated(0, 0), rotated(1, 1), rotated(2, 0), rotated(3, 1)};
    TQ3Point3D low = p[0], high = p[0];
    for (const TQ3Point3D& q : p) {
        low = {std::min(low.x, q.x), std::min(low.y, q.y), 0};
        high = {std::max(high.x, q.x), std::max(high.y, q.y), 0};
    }
    expectBox(box(kQ3ComputeBoundsExact, submit), low, high);
    // Corners (0,0), (3,0), (0,1), (3,1).
    const TQ3Point3D k[4] = {rotated(0, 0), rotated(3, 0), rotated(0, 1), rotated(3, 1)};
    low = k[0];
    high = k[0];
    for (const TQ3Point3D& q : k) {
        low = {std::min(low.x, q.x), std::min(low.y, q.y), 0};
        high = {std::max(high.x, q.x), std::max(high.y, q.y), 0};
    }
    const TQ3BoundingBox approximate = box(kQ3ComputeBoundsApproximate, submit);
    expectBox(approximate, low, high);
    EXPECT_LT(approximate.min.x, float(rotated(0, 1).x) + 1e-5f);
}

TEST_F(ViewBoundsTest, ShapesAccumulateAndPushPopScopesTransforms)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    const TQ3Vector3D offset = {0, 0, -5};
    expectBox(box(kQ3ComputeBoundsExact,
                  [&](TQ3ViewObject v) {
                      Q3Push_Submit(v);
                      Q3TranslateTransform_Submit(&offset, v);
                      Q3NURBCurve_Submit(&data, v);
                      Q3Pop_Submit(v);
                      Q3NURBCurve_Submit(&data, v);
                  }),
              {0, 0, -5}, {3, 1, 0});
}

TEST_F(ViewBoundsTest, AnEmptyLoopGivesAnEmptyBoxAndSphere)
{
    const TQ3BoundingBox empty = box(kQ3ComputeBoundsExact, [](TQ3ViewObject) {});
    EXPECT_EQ(empty.isEmpty, kQ3True);
    EXPECT_EQ(empty.min.x, 0.0f);
    EXPECT_EQ(empty.max.z, 0.0f);
    const TQ3BoundingSphere none = sphere(kQ3ComputeBoundsApproximate, [](TQ3ViewObject) {});
    EXPECT_EQ(none.isEmpty, kQ3True);
    EXPECT_EQ(none.radius, 0.0f);
    EXPECT_EQ(none.origin.y, 0.0f);
}

TEST_F(ViewBoundsTest, TheSphereHoldsEveryControlPointOfEveryShape)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    const TQ3Vector3D offset = {5, -2, 4};
    for (TQ3ComputeBounds mode : {kQ3ComputeBoundsExact, kQ3ComputeBoundsApproximate}) {
        const TQ3BoundingSphere result = sphere(mode, [&](TQ3ViewObject v) {
            Q3NURBCurve_Submit(&data, v);
            Q3TranslateTransform_Submit(&offset, v);
            Q3NURBCurve_Submit(&data, v);
        });
        EXPECT_EQ(result.isEmpty, kQ3False);
        for (int copy = 0; copy < 2; ++copy)
            for (const TQ3RationalPoint4D& p : listing.points) {
                const double x = p.x + copy * offset.x - result.origin.x;
                const double y = p.y + copy * offset.y - result.origin.y;
                const double z = p.z + copy * offset.z - result.origin.z;
                EXPECT_LE(std::sqrt(x * x + y * y + z * z), result.radius);
            }
        // Not wastefully large: at most the sum of the two spheres' sizes.
        EXPECT_LT(result.radius, 6.0f);
    }
}

TEST_F(ViewBoundsTest, OneCurveSphereIsCentredOnItsBox)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    const TQ3BoundingSphere result =
        sphere(kQ3ComputeBoundsExact, [&](TQ3ViewObject v) { Q3NURBCurve_Submit(&data, v); });
    EXPECT_NEAR(result.origin.x, 1.5, 1e-6);
    EXPECT_NEAR(result.origin.y, 0.5, 1e-6);
    EXPECT_NEAR(result.radius, std::sqrt(1.5 * 1.5 + 0.5 * 0.5), 1e-5);
}

TEST_F(ViewBoundsTest, EndBoundingReportsItsErrors)
{
    TQ3BoundingBox box{};
    TQ3BoundingSphere sphere{};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_EndBoundingBox(m_view, &box), kQ3ViewStatusError), kQ3ErrorBoundsNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_EndBoundingSphere(m_view, &sphere), kQ3ViewStatusError),
                    kQ3ErrorBoundsNotStarted);
    ASSERT_EQ(Q3View_StartBoundingBox(m_view, kQ3ComputeBoundsExact), kQ3Success);
    EXPECT_Q3_ERROR(Q3View_EndBoundingSphere(m_view, &sphere), kQ3ErrorBoundsNotStarted);
    EXPECT_Q3_ERROR(Q3View_EndBoundingBox(m_view, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_EndBoundingBox(nullptr, &box), kQ3ErrorNULLParameter);
    // Made before the dead handle, so that it cannot take its address.
    TQ3Object set = Q3AttributeSet_New();
    TQ3Object dead = Q3AttributeSet_New();
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(Q3View_EndBoundingBox(dead, &box), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3View_EndBoundingBox(set, &box), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_EndBoundingSphere(set, &sphere), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_EndBoundingSphere(nullptr, &sphere), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_EndBoundingSphere(dead, &sphere), kQ3ErrorInvalidObject);
    // The loop survived every failed end.
    EXPECT_EQ(Q3View_EndBoundingBox(m_view, &box), kQ3ViewStatusDone);
    ASSERT_EQ(Q3View_StartBoundingSphere(m_view, kQ3ComputeBoundsExact), kQ3Success);
    EXPECT_Q3_ERROR(Q3View_EndBoundingBox(m_view, &box), kQ3ErrorBoundsNotStarted);
    EXPECT_Q3_ERROR(Q3View_EndBoundingSphere(m_view, nullptr), kQ3ErrorNULLParameter);
    EXPECT_EQ(Q3View_EndBoundingSphere(m_view, &sphere), kQ3ViewStatusDone);
    Q3Object_Dispose(set);
}

TEST_F(ViewBoundsTest, StartBoundingReportsItsErrors)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_StartBoundingBox(m_view, TQ3ComputeBounds(2)), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3View_StartBoundingSphere(m_view, TQ3ComputeBounds(-1)), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3View_StartBoundingBox(nullptr, kQ3ComputeBoundsExact), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_StartBoundingSphere(nullptr, kQ3ComputeBoundsExact), kQ3ErrorNULLParameter);
    TQ3Object set = Q3AttributeSet_New();
    EXPECT_Q3_ERROR(Q3View_StartBoundingBox(set, kQ3ComputeBoundsExact), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_StartBoundingSphere(set, kQ3ComputeBoundsExact), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(set);
    EXPECT_Q3_ERROR(Q3View_StartBoundingBox(set, kQ3ComputeBoundsExact), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3View_StartBoundingSphere(set, kQ3ComputeBoundsExact), kQ3ErrorInvalidObject);
    // Nothing was started by the failures.
    TQ3BoundingBox box;
    EXPECT_Q3_ERROR(Q3View_EndBoundingBox(m_view, &box), kQ3ErrorBoundsNotStarted);
    // Inside a loop the loop is reported before a bad computeBounds.
    ASSERT_EQ(Q3View_StartBoundingSphere(m_view, kQ3ComputeBoundsExact), kQ3Success);
    EXPECT_Q3_ERROR(Q3View_StartBoundingBox(m_view, TQ3ComputeBounds(7)), kQ3ErrorViewIsStarted);
    EXPECT_Q3_ERROR(Q3View_StartBoundingSphere(m_view, kQ3ComputeBoundsExact), kQ3ErrorViewIsStarted);
    TQ3BoundingSphere sphere;
    EXPECT_EQ(Q3View_EndBoundingSphere(m_view, &sphere), kQ3ViewStatusDone);
}

TEST_F(ViewBoundsTest, CancelEndsABoundingLoopWithoutAResult)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    TQ3BoundingBox box{};
    box.min.x = 42;
    ASSERT_EQ(Q3View_StartBoundingBox(m_view, kQ3ComputeBoundsExact), kQ3Success);
    Q3NURBCurve_Submit(&data, m_view);
    EXPECT_EQ(Q3View_Cancel(m_view), kQ3Success);
    EXPECT_EQ(Q3View_EndBoundingBox(m_view, &box), kQ3ViewStatusCancelled);
    EXPECT_EQ(box.min.x, 42.0f);
    TQ3BoundingSphere sphere{};
    sphere.radius = 42;
    ASSERT_EQ(Q3View_StartBoundingSphere(m_view, kQ3ComputeBoundsExact), kQ3Success);
    Q3View_Cancel(m_view);
    EXPECT_EQ(Q3View_EndBoundingSphere(m_view, &sphere), kQ3ViewStatusCancelled);
    EXPECT_EQ(sphere.radius, 42.0f);
}

} // namespace
