// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Picking (QD3DPick.h, Q3View_StartPicking / EndPicking): every call and
// every error it documents; the details of hits (pick ID, path through
// nested groups, object, matrix, point, distance, normal, part, uv),
// sorting and numHitsToReturn; tolerances in world units and in pixels;
// world-ray hits against an evaluator written here (plane intersection and
// Cramer's rule); and window picks against what the interactive renderer
// draws at the same pixels.

#include "RenderTestSupport.h"

#include "QD3DGroup.h"
#include "QD3DPick.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace {

using namespace q3test;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kWidth = 80;
constexpr int kHeight = 60;

TQ3PickData pickData(TQ3PickSort sort = kQ3PickSortNearToFar, TQ3PickDetail mask = 0x3FF,
                     unsigned long numHits = kQ3ReturnAllHits)
{
    TQ3PickData data;
    data.sort = sort;
    data.mask = mask;
    data.numHitsToReturn = numHits;
    return data;
}

TQ3WorldRayPickData rayData(TQ3Point3D origin, TQ3Vector3D direction, TQ3PickData data = pickData())
{
    TQ3WorldRayPickData ray;
    ray.data = data;
    ray.ray.origin = origin;
    ray.ray.direction = direction;
    ray.vertexTolerance = 0.1f;
    ray.edgeTolerance = 0.1f;
    return ray;
}

TQ3WindowPointPickData pointData(float x, float y, TQ3PickData data = pickData())
{
    TQ3WindowPointPickData point;
    point.data = data;
    point.point = TQ3Point2D{x, y};
    point.vertexTolerance = 2.0f;
    point.edgeTolerance = 2.0f;
    return point;
}

TQ3WindowPointPickData pointData2(float x, float y, float tolerance)
{
    TQ3WindowPointPickData point = pointData(x, y, pickData(kQ3PickSortNearToFar, kQ3PickDetailMaskObject));
    point.vertexTolerance = tolerance;
    point.edgeTolerance = tolerance;
    return point;
}

TQ3WindowRectPickData rectData(float x0, float y0, float x1, float y1, TQ3PickData data = pickData())
{
    TQ3WindowRectPickData rect;
    rect.data = data;
    rect.rect = TQ3Area{{x0, y0}, {x1, y1}};
    return rect;
}

TQ3TriangleData triangleData(TQ3Point3D a, TQ3Point3D b, TQ3Point3D c)
{
    TQ3TriangleData data{};
    data.vertices[0].point = a;
    data.vertices[1].point = b;
    data.vertices[2].point = c;
    return data;
}

class PickApiTest : public Q3ApiTest {
protected:
    void TearDown() override
    {
        for (auto it = m_owned.rbegin(); it != m_owned.rend(); ++it)
            Q3Object_Dispose(*it);
        m_owned.clear();
        Q3ApiTest::TearDown();
    }

    template <class T>
    T own(T object)
    {
        EXPECT_NE(object, nullptr);
        m_owned.push_back(object);
        return object;
    }

    /// A triangle in the plane z = z covering x, y in [x0, x0 + size].
    TQ3GeometryObject square(float x0, float y0, float z, float size = 1.0f)
    {
        const TQ3TriangleData data = triangleData({x0, y0, z}, {x0 + 2 * size, y0, z}, {x0, y0 + 2 * size, z});
        return own(Q3Triangle_New(&data));
    }

    /// Squares at z = 0, -1 and -2 under x, y in [-1, 1], with pick IDs 1, 2
    /// and 3 (nearest to farthest from +z), submitted middle, nearest,
    /// farthest.
    std::function<void(TQ3ViewObject)> threeSquares()
    {
        const TQ3GeometryObject nearest = square(-1, -1, 0);
        const TQ3GeometryObject middle = square(-1, -1, -1);
        const TQ3GeometryObject farthest = square(-1, -1, -2);
        return [=](TQ3ViewObject v) {
            Q3PickIDStyle_Submit(2, v);
            Q3Object_Submit(middle, v);
            Q3PickIDStyle_Submit(1, v);
            Q3Object_Submit(nearest, v);
            Q3PickIDStyle_Submit(3, v);
            Q3Object_Submit(farthest, v);
        };
    }

    /// Runs a picking loop (the legacy do/while shape) around submit.
    TQ3ViewStatus pick(TQ3ViewObject view, TQ3PickObject pickObject, const std::function<void(TQ3ViewObject)>& submit)
    {
        TQ3ViewStatus status = kQ3ViewStatusError;
        if (Q3View_StartPicking(view, pickObject) != kQ3Success)
            return status;
        do {
            submit(view);
            status = Q3View_EndPicking(view);
        } while (status == kQ3ViewStatusRetraverse);
        return status;
    }

    unsigned long hits(TQ3PickObject pickObject)
    {
        unsigned long n = 0;
        EXPECT_EQ(Q3Pick_GetNumHits(pickObject, &n), kQ3Success);
        return n;
    }

    template <class T>
    T detail(TQ3PickObject pickObject, unsigned long index, TQ3PickDetail which)
    {
        T value{};
        EXPECT_EQ(Q3Pick_GetPickDetailData(pickObject, index, which, &value), kQ3Success);
        return value;
    }

    std::vector<TQ3Object> m_owned;
};

// ---- Objects and their data -------------------------------------------------

TEST_F(PickApiTest, EachKindKeepsItsDataAndType)
{
    const TQ3WindowPointPickData point = pointData(3.5f, 4.5f, pickData(kQ3PickSortNone, 5, 7));
    TQ3PickObject p = own(Q3WindowPointPick_New(&point));
    EXPECT_EQ(Q3Pick_GetType(p), kQ3PickTypeWindowPoint);
    EXPECT_EQ(Q3Object_GetType(p), kQ3ObjectTypePick);
    TQ3WindowPointPickData gotPoint{};
    ASSERT_EQ(Q3WindowPointPick_GetData(p, &gotPoint), kQ3Success);
    EXPECT_EQ(gotPoint.data.sort, kQ3PickSortNone);
    EXPECT_EQ(gotPoint.data.mask, 5u);
    EXPECT_EQ(gotPoint.data.numHitsToReturn, 7u);
    EXPECT_EQ(gotPoint.point.x, 3.5f);
    EXPECT_EQ(gotPoint.point.y, 4.5f);
    EXPECT_EQ(gotPoint.vertexTolerance, 2.0f);
    TQ3Point2D xy{};
    ASSERT_EQ(Q3WindowPointPick_GetPoint(p, &xy), kQ3Success);
    EXPECT_EQ(xy.x, 3.5f);
    const TQ3Point2D moved{9.0f, 8.0f};
    ASSERT_EQ(Q3WindowPointPick_SetPoint(p, &moved), kQ3Success);
    ASSERT_EQ(Q3WindowPointPick_GetPoint(p, &xy), kQ3Success);
    EXPECT_EQ(xy.y, 8.0f);
    gotPoint.edgeTolerance = 6.0f;
    ASSERT_EQ(Q3WindowPointPick_SetData(p, &gotPoint), kQ3Success);
    float tolerance = 0.0f;
    ASSERT_EQ(Q3Pick_GetEdgeTolerance(p, &tolerance), kQ3Success);
    EXPECT_EQ(tolerance, 6.0f);
    ASSERT_EQ(Q3Pick_SetVertexTolerance(p, 1.25f), kQ3Success);
    ASSERT_EQ(Q3Pick_GetVertexTolerance(p, &tolerance), kQ3Success);
    EXPECT_EQ(tolerance, 1.25f);
    ASSERT_EQ(Q3Pick_SetEdgeTolerance(p, 0.0f), kQ3Success);
    ASSERT_EQ(Q3Pick_GetEdgeTolerance(p, &tolerance), kQ3Success);
    EXPECT_EQ(tolerance, 0.0f);
    const TQ3PickData common = pickData(kQ3PickSortFarToNear, kQ3PickDetailMaskXYZ, 2);
    ASSERT_EQ(Q3Pick_SetData(p, &common), kQ3Success);
    TQ3PickData gotCommon{};
    ASSERT_EQ(Q3Pick_GetData(p, &gotCommon), kQ3Success);
    EXPECT_EQ(gotCommon.sort, kQ3PickSortFarToNear);
    EXPECT_EQ(gotCommon.mask, TQ3PickDetail(kQ3PickDetailMaskXYZ));
    EXPECT_EQ(gotCommon.numHitsToReturn, 2u);
    ASSERT_EQ(Q3WindowPointPick_GetData(p, &gotPoint), kQ3Success);
    EXPECT_EQ(gotPoint.data.sort, kQ3PickSortFarToNear);

    const TQ3WindowRectPickData rect = rectData(1, 2, 3, 4);
    TQ3PickObject r = own(Q3WindowRectPick_New(&rect));
    EXPECT_EQ(Q3Pick_GetType(r), kQ3PickTypeWindowRect);
    TQ3Area area{};
    ASSERT_EQ(Q3WindowRectPick_GetRect(r, &area), kQ3Success);
    EXPECT_EQ(area.max.y, 4.0f);
    const TQ3Area bigger{{0, 0}, {10, 10}};
    ASSERT_EQ(Q3WindowRectPick_SetRect(r, &bigger), kQ3Success);
    TQ3WindowRectPickData gotRect{};
    ASSERT_EQ(Q3WindowRectPick_GetData(r, &gotRect), kQ3Success);
    EXPECT_EQ(gotRect.rect.max.x, 10.0f);
    gotRect.rect.min.x = 5;
    ASSERT_EQ(Q3WindowRectPick_SetData(r, &gotRect), kQ3Success);
    ASSERT_EQ(Q3WindowRectPick_GetRect(r, &area), kQ3Success);
    EXPECT_EQ(area.min.x, 5.0f);

    const TQ3WorldRayPickData ray = rayData({1, 2, 3}, {0, 0, -2});
    TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
    EXPECT_EQ(Q3Pick_GetType(w), kQ3PickTypeWorldRay);
    TQ3Ray3D gotRay{};
    ASSERT_EQ(Q3WorldRayPick_GetRay(w, &gotRay), kQ3Success);
    EXPECT_EQ(gotRay.direction.z, -2.0f);
    const TQ3Ray3D other{{0, 0, 0}, {1, 0, 0}};
    ASSERT_EQ(Q3WorldRayPick_SetRay(w, &other), kQ3Success);
    TQ3WorldRayPickData gotRayData{};
    ASSERT_EQ(Q3WorldRayPick_GetData(w, &gotRayData), kQ3Success);
    EXPECT_EQ(gotRayData.ray.direction.x, 1.0f);
    gotRayData.vertexTolerance = 3.0f;
    ASSERT_EQ(Q3WorldRayPick_SetData(w, &gotRayData), kQ3Success);
    ASSERT_EQ(Q3Pick_GetVertexTolerance(w, &tolerance), kQ3Success);
    EXPECT_EQ(tolerance, 3.0f);
    unsigned long n = 99;
    ASSERT_EQ(Q3Pick_GetNumHits(w, &n), kQ3Success);
    EXPECT_EQ(n, 0u);
    EXPECT_EQ(Q3Pick_EmptyHitList(w), kQ3Success);
}

TEST_F(PickApiTest, NewRefusesBadData)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowPointPick_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowRectPick_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WorldRayPick_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    for (float bad : {kNaN, kInf, -kInf}) {
        TQ3WindowPointPickData point = pointData(bad, 1);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowPointPick_New(&point), nullptr), kQ3ErrorInvalidParameter);
        point = pointData(1, bad);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowPointPick_New(&point), nullptr), kQ3ErrorInvalidParameter);
        point = pointData(1, 1);
        point.vertexTolerance = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowPointPick_New(&point), nullptr), kQ3ErrorInvalidParameter);
        point = pointData(1, 1);
        point.edgeTolerance = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowPointPick_New(&point), nullptr), kQ3ErrorInvalidParameter);
        TQ3WindowRectPickData rect = rectData(0, 0, bad, 1);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowRectPick_New(&rect), nullptr), kQ3ErrorInvalidParameter);
        TQ3WorldRayPickData ray = rayData({bad, 0, 0}, {0, 0, 1});
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3WorldRayPick_New(&ray), nullptr), kQ3ErrorInvalidParameter);
        ray = rayData({0, 0, 0}, {0, bad, 1});
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3WorldRayPick_New(&ray), nullptr), kQ3ErrorInvalidParameter);
        ray = rayData({0, 0, 0}, {0, 0, 1});
        ray.edgeTolerance = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3WorldRayPick_New(&ray), nullptr), kQ3ErrorInvalidParameter);
    }
    TQ3WindowPointPickData negative = pointData(1, 1);
    negative.vertexTolerance = -0.5f;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowPointPick_New(&negative), nullptr), kQ3ErrorInvalidParameter);
    TQ3WindowRectPickData inverted = rectData(5, 0, 4, 1);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowRectPick_New(&inverted), nullptr), kQ3ErrorInvalidParameter);
    inverted = rectData(0, 5, 1, 4);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowRectPick_New(&inverted), nullptr), kQ3ErrorInvalidParameter);
    TQ3WorldRayPickData zero = rayData({0, 0, 0}, {0, 0, 0});
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WorldRayPick_New(&zero), nullptr), kQ3ErrorInvalidParameter);
    TQ3WorldRayPickData badSort = rayData({0, 0, 0}, {0, 0, 1});
    reinterpret_cast<int&>(badSort.data.sort) = 3;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WorldRayPick_New(&badSort), nullptr), kQ3ErrorInvalidParameter);
    reinterpret_cast<int&>(badSort.data.sort) = -1;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WorldRayPick_New(&badSort), nullptr), kQ3ErrorInvalidParameter);
    TQ3WorldRayPickData badMask = rayData({0, 0, 0}, {0, 0, 1});
    badMask.data.mask = kQ3PickDetailMaskUV << 1;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WorldRayPick_New(&badMask), nullptr), kQ3ErrorInvalidParameter);
}

TEST_F(PickApiTest, FailedSettersLeaveThePickAsItWas)
{
    const TQ3WindowPointPickData point = pointData(3, 4);
    TQ3PickObject p = own(Q3WindowPointPick_New(&point));
    const TQ3WorldRayPickData ray = rayData({1, 2, 3}, {0, 0, -1});
    TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
    const TQ3WindowRectPickData rect = rectData(1, 2, 3, 4);
    TQ3PickObject r = own(Q3WindowRectPick_New(&rect));

    for (float bad : {kNaN, kInf, -kInf, -1.0f}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Pick_SetVertexTolerance(p, bad), kQ3Failure), kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Pick_SetEdgeTolerance(w, bad), kQ3Failure), kQ3ErrorInvalidParameter);
        if (bad == -1.0f)
            continue;
        const TQ3Point2D badPoint{bad, 0};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowPointPick_SetPoint(p, &badPoint), kQ3Failure), kQ3ErrorInvalidParameter);
        const TQ3Area badArea{{0, 0}, {1, bad}};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowRectPick_SetRect(r, &badArea), kQ3Failure), kQ3ErrorInvalidParameter);
        const TQ3Ray3D badRay{{0, 0, bad}, {0, 0, 1}};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3WorldRayPick_SetRay(w, &badRay), kQ3Failure), kQ3ErrorInvalidParameter);
    }
    const TQ3Ray3D zero{{0, 0, 0}, {0, 0, 0}};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WorldRayPick_SetRay(w, &zero), kQ3Failure), kQ3ErrorInvalidParameter);
    const TQ3Area inverted{{3, 0}, {1, 1}};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowRectPick_SetRect(r, &inverted), kQ3Failure), kQ3ErrorInvalidParameter);
    TQ3PickData badMask = pickData();
    badMask.mask = 1u << 12;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Pick_SetData(p, &badMask), kQ3Failure), kQ3ErrorInvalidParameter);
    TQ3WindowPointPickData badPoint = pointData(kNaN, 0, pickData(kQ3PickSortNone, 0, 1));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowPointPick_SetData(p, &badPoint), kQ3Failure), kQ3ErrorInvalidParameter);
    TQ3WindowRectPickData badRect = rectData(0, 0, kInf, 1, pickData(kQ3PickSortNone, 0, 1));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WindowRectPick_SetData(r, &badRect), kQ3Failure), kQ3ErrorInvalidParameter);
    TQ3WorldRayPickData badRayData = rayData({0, 0, 0}, {0, 0, 1}, pickData(kQ3PickSortNone, 0, 1));
    badRayData.vertexTolerance = -2.0f;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3WorldRayPick_SetData(w, &badRayData), kQ3Failure), kQ3ErrorInvalidParameter);

    TQ3WindowPointPickData gotPoint{};
    ASSERT_EQ(Q3WindowPointPick_GetData(p, &gotPoint), kQ3Success);
    EXPECT_EQ(std::memcmp(&gotPoint, &point, sizeof point), 0);
    TQ3WindowRectPickData gotRect{};
    ASSERT_EQ(Q3WindowRectPick_GetData(r, &gotRect), kQ3Success);
    EXPECT_EQ(std::memcmp(&gotRect, &rect, sizeof rect), 0);
    TQ3WorldRayPickData gotRay{};
    ASSERT_EQ(Q3WorldRayPick_GetData(w, &gotRay), kQ3Success);
    EXPECT_EQ(std::memcmp(&gotRay, &ray, sizeof ray), 0);
}

TEST_F(PickApiTest, CallsRefuseHandlesOfTheWrongKind)
{
    const TQ3WindowPointPickData point = pointData(3, 4);
    TQ3PickObject p = own(Q3WindowPointPick_New(&point));
    const TQ3WindowRectPickData rect = rectData(1, 2, 3, 4);
    TQ3PickObject r = own(Q3WindowRectPick_New(&rect));
    const TQ3WorldRayPickData ray = rayData({1, 2, 3}, {0, 0, -1});
    TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
    TQ3Object notPick = own(Q3View_New());

    TQ3Point2D xy{};
    TQ3Area area{};
    TQ3Ray3D gotRay{};
    float tolerance = 0.0f;
    TQ3PickData data{};
    EXPECT_Q3_ERROR(Q3WindowPointPick_GetPoint(r, &xy), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3WindowPointPick_SetPoint(w, &xy), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3WindowRectPick_GetRect(p, &area), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3WindowRectPick_SetRect(w, &area), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3WorldRayPick_GetRay(p, &gotRay), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3WorldRayPick_SetRay(r, &gotRay), kQ3ErrorInvalidObjectType);
    TQ3WindowPointPickData pd{};
    TQ3WindowRectPickData rd{};
    TQ3WorldRayPickData wd{};
    EXPECT_Q3_ERROR(Q3WindowPointPick_GetData(w, &pd), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3WindowPointPick_SetData(r, &point), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3WindowRectPick_GetData(p, &rd), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3WindowRectPick_SetData(w, &rect), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3WorldRayPick_GetData(r, &wd), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3WorldRayPick_SetData(p, &ray), kQ3ErrorInvalidObjectType);
    // A window-rect pick has no tolerances.
    EXPECT_Q3_ERROR(Q3Pick_GetVertexTolerance(r, &tolerance), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Pick_GetEdgeTolerance(r, &tolerance), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Pick_SetVertexTolerance(r, 1.0f), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Pick_SetEdgeTolerance(r, 1.0f), kQ3ErrorInvalidObjectType);
    // Not a pick, NULL, NULL outputs.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Pick_GetType(notPick), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Pick_GetType(nullptr), kQ3ObjectTypeInvalid), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pick_GetData(notPick, &data), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Pick_GetData(p, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pick_SetData(p, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pick_SetData(nullptr, &data), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pick_GetVertexTolerance(p, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pick_GetEdgeTolerance(nullptr, &tolerance), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pick_SetVertexTolerance(nullptr, 1.0f), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pick_SetEdgeTolerance(notPick, 1.0f), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Pick_GetNumHits(p, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pick_GetNumHits(notPick, nullptr), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Pick_EmptyHitList(nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pick_EmptyHitList(notPick), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3WindowPointPick_GetPoint(p, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3WindowPointPick_SetPoint(p, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3WindowPointPick_GetData(p, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3WindowPointPick_SetData(p, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3WindowRectPick_GetRect(r, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3WindowRectPick_SetRect(r, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3WindowRectPick_GetData(r, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3WindowRectPick_SetData(r, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3WorldRayPick_GetRay(w, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3WorldRayPick_SetRay(w, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3WorldRayPick_GetData(w, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3WorldRayPick_SetData(w, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3WorldRayPick_GetRay(nullptr, &gotRay), kQ3ErrorNULLParameter);
    // A disposed pick is no longer a live object.
    TQ3PickObject gone = Q3WorldRayPick_New(&ray);
    ASSERT_EQ(Q3Object_Dispose(gone), kQ3Success);
    EXPECT_Q3_ERROR(Q3Pick_GetType(gone), kQ3ErrorInvalidObject);
}

// ---- The picking loop ---------------------------------------------------------

TEST_F(PickApiTest, LoopErrors)
{
    TQ3ViewObject bare = own(Q3View_New());
    const TQ3WorldRayPickData ray = rayData({0, 0, 5}, {0, 0, -1});
    TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
    const TQ3WindowPointPickData point = pointData(3, 4);
    TQ3PickObject p = own(Q3WindowPointPick_New(&point));

    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_EndPicking(bare), kQ3ViewStatusError), kQ3ErrorPickingNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_EndPicking(nullptr), kQ3ViewStatusError), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_StartPicking(nullptr, w), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_StartPicking(bare, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_StartPicking(bare, bare), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_StartPicking(w, w), kQ3ErrorInvalidObjectType);
    // Window picks need a draw context, then a camera.
    EXPECT_Q3_ERROR(Q3View_StartPicking(bare, p), kQ3ErrorDrawContextNotSet);
    Pixmap image(kWidth, kHeight);
    const TQ3PixmapDrawContextData contextData = pixmapContextData(image.pixmap());
    TQ3DrawContextObject context = own(Q3PixmapDrawContext_New(&contextData));
    ASSERT_EQ(Q3View_SetDrawContext(bare, context), kQ3Success);
    EXPECT_Q3_ERROR(Q3View_StartPicking(bare, p), kQ3ErrorCameraNotSet);

    // A world ray needs neither; a second start and other loops are refused.
    ASSERT_EQ(Q3View_StartPicking(bare, w), kQ3Success);
    EXPECT_Q3_ERROR(Q3View_StartPicking(bare, w), kQ3ErrorViewIsStarted);
    EXPECT_Q3_ERROR(Q3View_StartRendering(bare), kQ3ErrorViewIsStarted);
    EXPECT_Q3_ERROR(Q3View_EndRendering(bare), kQ3ErrorRenderingNotStarted);
    EXPECT_EQ(Q3View_EndPicking(bare), kQ3ViewStatusDone);
    EXPECT_Q3_ERROR(Q3View_EndPicking(bare), kQ3ErrorPickingNotStarted);
    // Outside the loop shapes cannot be submitted.
    const TQ3TriangleData tri = triangleData({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    EXPECT_Q3_ERROR(Q3Triangle_Submit(&tri, bare), kQ3ErrorViewNotStarted);
}

TEST_F(PickApiTest, CancelledLoopLeavesNoHitsAndDisposedPickFailsTheLoop)
{
    TQ3ViewObject view = own(Q3View_New());
    TQ3GeometryObject tri = square(-1, -1, 0);
    const TQ3WorldRayPickData ray = rayData({-0.5f, -0.5f, 5}, {0, 0, -1});
    TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
    ASSERT_EQ(pick(view, w, [&](TQ3ViewObject v) { Q3Object_Submit(tri, v); }), kQ3ViewStatusDone);
    EXPECT_EQ(hits(w), 1u);
    // Starting a loop empties the list; a cancelled loop leaves it empty.
    ASSERT_EQ(Q3View_StartPicking(view, w), kQ3Success);
    EXPECT_EQ(hits(w), 0u);
    ASSERT_EQ(Q3Object_Submit(tri, view), kQ3Success);
    ASSERT_EQ(Q3View_Cancel(view), kQ3Success);
    EXPECT_EQ(Q3View_EndPicking(view), kQ3ViewStatusCancelled);
    EXPECT_EQ(hits(w), 0u);

    TQ3PickObject doomed = Q3WorldRayPick_New(&ray);
    ASSERT_EQ(Q3View_StartPicking(view, doomed), kQ3Success);
    ASSERT_EQ(Q3Object_Submit(tri, view), kQ3Success);
    ASSERT_EQ(Q3Object_Dispose(doomed), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_EndPicking(view), kQ3ViewStatusError), kQ3ErrorPickingLoopFailed);
    // The loop is over: a new one starts.
    ASSERT_EQ(pick(view, w, [&](TQ3ViewObject v) { Q3Object_Submit(tri, v); }), kQ3ViewStatusDone);
    EXPECT_EQ(hits(w), 1u);
    EXPECT_EQ(Q3Pick_EmptyHitList(w), kQ3Success);
    EXPECT_EQ(hits(w), 0u);
}

// ---- Hits ---------------------------------------------------------------------

TEST_F(PickApiTest, HitIndexAndDetailErrors)
{
    TQ3ViewObject view = own(Q3View_New());
    const TQ3WorldRayPickData ray = rayData({-0.5f, -0.5f, 5}, {0, 0, -1},
                                        pickData(kQ3PickSortNearToFar, kQ3PickDetailMaskPickID | kQ3PickDetailMaskShapePart));
    TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
    TQ3GeometryObject a = square(-1, -1, 0);
    TQ3GeometryObject b = square(-1, -1, -1);
    TQ3GeometryObject c = square(-1, -1, -2);
    ASSERT_EQ(pick(view, w, [&](TQ3ViewObject v) {
                  Q3Object_Submit(a, v);
                  Q3Object_Submit(b, v);
                  Q3Object_Submit(c, v);
              }),
              kQ3ViewStatusDone);
    ASSERT_EQ(hits(w), 3u);
    TQ3PickDetail valid = 0;
    for (unsigned long i : {0ul, 2ul}) {
        ASSERT_EQ(Q3Pick_GetPickDetailValidMask(w, i, &valid), kQ3Success);
        // Triangles have no shape parts; what was not asked for is not valid either.
        EXPECT_EQ(valid, TQ3PickDetail(kQ3PickDetailMaskPickID));
    }
    unsigned long id = 0;
    for (unsigned long bad : {3ul, 4ul, (unsigned long)UINT32_MAX}) {
        EXPECT_Q3_ERROR(Q3Pick_GetPickDetailValidMask(w, bad, &valid), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(Q3Pick_GetPickDetailData(w, bad, kQ3PickDetailMaskPickID, &id), kQ3ErrorParameterOutOfRange);
    }
    EXPECT_Q3_ERROR(Q3Pick_GetPickDetailValidMask(w, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pick_GetPickDetailValidMask(nullptr, 0, &valid), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pick_GetPickDetailData(w, 0, kQ3PickDetailMaskPickID, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pick_GetPickDetailData(view, 0, kQ3PickDetailMaskPickID, &id), kQ3ErrorInvalidObjectType);
    for (TQ3PickDetail bad : {TQ3PickDetail(0), TQ3PickDetail(3), TQ3PickDetail(kQ3PickDetailMaskUV << 1),
                              TQ3PickDetail(~0ul)})
        EXPECT_Q3_ERROR(Q3Pick_GetPickDetailData(w, 0, bad, &id), kQ3ErrorInvalidParameter);
    id = 77;
    EXPECT_Q3_ERROR(Q3Pick_GetPickDetailData(w, 2, kQ3PickDetailMaskShapePart, &id), kQ3ErrorDataNotAvailable);
    EXPECT_Q3_ERROR(Q3Pick_GetPickDetailData(w, 2, kQ3PickDetailMaskXYZ, &id), kQ3ErrorDataNotAvailable);
    EXPECT_EQ(id, 77u);
    EXPECT_EQ(Q3Pick_GetPickDetailData(w, 2, kQ3PickDetailMaskPickID, &id), kQ3Success);
    EXPECT_EQ(id, 0u);
}

TEST_F(PickApiTest, HitsAreSortedAndCut)
{
    TQ3ViewObject view = own(Q3View_New());
    const auto scene = threeSquares();
    auto ids = [&](TQ3PickObject p) {
        std::vector<unsigned long> out;
        for (unsigned long i = 0; i < hits(p); ++i)
            out.push_back(detail<unsigned long>(p, i, kQ3PickDetailMaskPickID));
        return out;
    };
    struct Case {
        TQ3PickSort sort;
        unsigned long keep;
        std::vector<unsigned long> want;
    } cases[] = {{kQ3PickSortNearToFar, 0, {1, 2, 3}}, {kQ3PickSortFarToNear, 0, {3, 2, 1}},
                 {kQ3PickSortNone, 0, {2, 1, 3}},      {kQ3PickSortNearToFar, 2, {1, 2}},
                 {kQ3PickSortFarToNear, 1, {3}},       {kQ3PickSortNone, 2, {2, 1}},
                 {kQ3PickSortNearToFar, 9, {1, 2, 3}}};
    for (const Case& c : cases) {
        const TQ3WorldRayPickData ray = rayData({-0.5f, -0.5f, 5}, {0, 0, -2}, pickData(c.sort, 0x3FF, c.keep));
        TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
        ASSERT_EQ(pick(view, w, scene), kQ3ViewStatusDone);
        EXPECT_EQ(ids(w), c.want) << "sort " << c.sort << " keep " << c.keep;
    }
    // Distances and points: the ray from z = 5 meets z = 0, -1, -2.
    const TQ3WorldRayPickData ray = rayData({-0.5f, -0.5f, 5}, {0, 0, -2});
    TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
    ASSERT_EQ(pick(view, w, scene), kQ3ViewStatusDone);
    for (unsigned long i = 0; i < 3; ++i) {
        EXPECT_FLOAT_EQ(detail<float>(w, i, kQ3PickDetailMaskDistance), 5.0f + i);
        const TQ3Point3D xyz = detail<TQ3Point3D>(w, i, kQ3PickDetailMaskXYZ);
        EXPECT_FLOAT_EQ(xyz.x, -0.5f);
        EXPECT_FLOAT_EQ(xyz.y, -0.5f);
        EXPECT_FLOAT_EQ(xyz.z, -float(i));
    }
}

TEST_F(PickApiTest, DetailsOfAHit)
{
    TQ3ViewObject view = own(Q3View_New());
    // A triangle with uvs at its corners, moved by a transform.
    TQ3TriangleData data = triangleData({0, 0, 0}, {2, 0, 0}, {0, 2, 0});
    const TQ3Param2D uvs[3] = {{0, 0}, {1, 0}, {0, 1}};
    TQ3AttributeSet sets[3];
    for (int k = 0; k < 3; ++k) {
        sets[k] = own(Q3AttributeSet_New());
        Q3AttributeSet_Add(sets[k], kQ3AttributeTypeSurfaceUV, &uvs[k]);
        data.vertices[k].attributeSet = sets[k];
    }
    TQ3GeometryObject tri = own(Q3Triangle_New(&data));
    const TQ3Vector3D shift{10, 0, 0};
    const TQ3WorldRayPickData ray = rayData({10.5f, 0.5f, 3}, {0, 0, -1});
    TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
    ASSERT_EQ(pick(view, w,
                   [&](TQ3ViewObject v) {
                       Q3PickIDStyle_Submit(42, v);
                       Q3TranslateTransform_Submit(&shift, v);
                       Q3Object_Submit(tri, v);
                   }),
              kQ3ViewStatusDone);
    ASSERT_EQ(hits(w), 1u);
    TQ3PickDetail valid = 0;
    ASSERT_EQ(Q3Pick_GetPickDetailValidMask(w, 0, &valid), kQ3Success);
    // Everything but the path (no group) and the shape part (a triangle has no parts).
    EXPECT_EQ(valid, TQ3PickDetail(0x3FF & ~kQ3PickDetailMaskPath & ~kQ3PickDetailMaskShapePart));
    EXPECT_EQ(detail<unsigned long>(w, 0, kQ3PickDetailMaskPickID), 42u);
    TQ3Object object = detail<TQ3Object>(w, 0, kQ3PickDetailMaskObject);
    EXPECT_EQ(object, tri);
    EXPECT_EQ(Q3Object_Dispose(object), kQ3Success); // the reference it returned
    const TQ3Matrix4x4 m = detail<TQ3Matrix4x4>(w, 0, kQ3PickDetailMaskLocalToWorldMatrix);
    EXPECT_EQ(m.value[3][0], 10.0f);
    EXPECT_EQ(m.value[0][0], 1.0f);
    const TQ3Vector3D n = detail<TQ3Vector3D>(w, 0, kQ3PickDetailMaskNormal);
    EXPECT_FLOAT_EQ(n.z, 1.0f);
    const TQ3Param2D uv = detail<TQ3Param2D>(w, 0, kQ3PickDetailMaskUV);
    EXPECT_FLOAT_EQ(uv.u, 0.25f);
    EXPECT_FLOAT_EQ(uv.v, 0.25f);
    EXPECT_EQ(detail<TQ3PickParts>(w, 0, kQ3PickDetailMaskPickPart), TQ3PickParts(kQ3PickPartsObject));

    // Clockwise front faces turn the normal; immediate mode has no object
    // and, without uvs, no uv.
    const TQ3TriangleData plain = triangleData({0, 0, 0}, {2, 0, 0}, {0, 2, 0});
    const TQ3WorldRayPickData ray2 = rayData({0.5f, 0.5f, 3}, {0, 0, -1});
    TQ3PickObject w2 = own(Q3WorldRayPick_New(&ray2));
    ASSERT_EQ(pick(view, w2,
                   [&](TQ3ViewObject v) {
                       Q3OrientationStyle_Submit(kQ3OrientationStyleClockwise, v);
                       Q3Triangle_Submit(&plain, v);
                   }),
              kQ3ViewStatusDone);
    ASSERT_EQ(hits(w2), 1u);
    ASSERT_EQ(Q3Pick_GetPickDetailValidMask(w2, 0, &valid), kQ3Success);
    EXPECT_EQ(valid & (kQ3PickDetailMaskObject | kQ3PickDetailMaskUV), 0u);
    EXPECT_FLOAT_EQ(detail<TQ3Vector3D>(w2, 0, kQ3PickDetailMaskNormal).z, -1.0f);
}

// Found by the fuzzer: a Q3Pick_SetData during the picking loop changes the
// details the hits report, as it changes their sort and count: a hit
// reports only the details the pick asks for when the loop ends.
TEST_F(PickApiTest, DataSetDuringTheLoopRulesTheHitsDetails)
{
    TQ3ViewObject view = own(Q3View_New());
    TQ3GeometryObject tri = square(0, 0, 0);
    TQ3WorldRayPickData ray = rayData({0.5f, 0.5f, 3}, {0, 0, -1});
    ray.data.mask = kQ3PickDetailMaskPickID | kQ3PickDetailMaskLocalToWorldMatrix | kQ3PickDetailMaskObject;
    TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
    TQ3PickData narrower = ray.data;
    narrower.mask = kQ3PickDetailMaskObject | kQ3PickDetailMaskDistance;
    ASSERT_EQ(pick(view, w,
                   [&](TQ3ViewObject v) {
                       EXPECT_EQ(Q3Pick_SetData(w, &narrower), kQ3Success);
                       Q3Object_Submit(tri, v);
                   }),
              kQ3ViewStatusDone);
    ASSERT_EQ(hits(w), 1u);
    TQ3PickDetail valid = 0;
    ASSERT_EQ(Q3Pick_GetPickDetailValidMask(w, 0, &valid), kQ3Success);
    // Asked at the start and still asked; never a detail no longer asked.
    EXPECT_EQ(valid, TQ3PickDetail(kQ3PickDetailMaskObject));
    unsigned long id = 0;
    EXPECT_Q3_ERROR(Q3Pick_GetPickDetailData(w, 0, kQ3PickDetailMaskPickID, &id), kQ3ErrorDataNotAvailable);
}

// Found by the fuzzer: a Q3Pick_SetData after the loop that asks for fewer
// hits left the list longer than numHitsToReturn. The new data rules the list
// at once, as it would have at the loop's end: sorted, cut and masked.
TEST_F(PickApiTest, DataSetAfterTheLoopRulesTheHitList)
{
    TQ3ViewObject view = own(Q3View_New());
    const auto scene = threeSquares();
    for (int setter = 0; setter < 2; ++setter) {
        const TQ3WorldRayPickData ray = rayData({-0.5f, -0.5f, 5}, {0, 0, -2});
        TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
        ASSERT_EQ(pick(view, w, scene), kQ3ViewStatusDone);
        ASSERT_EQ(hits(w), 3u);
        const TQ3PickData fewer = pickData(kQ3PickSortFarToNear, kQ3PickDetailMaskPickID, 2);
        if (setter == 0) {
            ASSERT_EQ(Q3Pick_SetData(w, &fewer), kQ3Success);
        } else {
            TQ3WorldRayPickData changed = ray;
            changed.data = fewer;
            ASSERT_EQ(Q3WorldRayPick_SetData(w, &changed), kQ3Success);
        }
        ASSERT_EQ(hits(w), 2u) << "setter " << setter;
        EXPECT_EQ(detail<unsigned long>(w, 0, kQ3PickDetailMaskPickID), 3u);
        EXPECT_EQ(detail<unsigned long>(w, 1, kQ3PickDetailMaskPickID), 2u);
        TQ3PickDetail valid = 0;
        ASSERT_EQ(Q3Pick_GetPickDetailValidMask(w, 0, &valid), kQ3Success);
        EXPECT_EQ(valid, TQ3PickDetail(kQ3PickDetailMaskPickID));
        // Asking for all hits again does not bring the cut one back.
        ASSERT_EQ(Q3Pick_SetData(w, &ray.data), kQ3Success);
        EXPECT_EQ(hits(w), 2u);
    }
}

TEST_F(PickApiTest, HitPathThroughNestedGroups)
{
    TQ3ViewObject view = own(Q3View_New());
    TQ3GeometryObject decoy = square(5, 5, 0);
    TQ3GeometryObject tri = square(-1, -1, 0);
    TQ3GroupObject inner = own(Q3DisplayGroup_New());
    TQ3GroupObject outer = own(Q3DisplayGroup_New());
    TQ3GroupPosition decoyPosition = Q3Group_AddObject(inner, decoy);
    TQ3GroupPosition triPosition = Q3Group_AddObject(inner, tri);
    const TQ3Vector3D none{0, 0, 0};
    TQ3TransformObject move = own(Q3TranslateTransform_New(&none));
    Q3Group_AddObject(outer, move);
    TQ3GroupPosition innerPosition = Q3Group_AddObject(outer, inner);
    ASSERT_NE(decoyPosition, nullptr);

    const TQ3WorldRayPickData ray = rayData({-0.5f, -0.5f, 5}, {0, 0, -1});
    TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
    ASSERT_EQ(pick(view, w, [&](TQ3ViewObject v) { Q3Object_Submit(outer, v); }), kQ3ViewStatusDone);
    ASSERT_EQ(hits(w), 1u);
    TQ3HitPath path = detail<TQ3HitPath>(w, 0, kQ3PickDetailMaskPath);
    EXPECT_EQ(path.rootGroup, outer);
    ASSERT_EQ(path.depth, 2u);
    EXPECT_EQ(path.positions[0], innerPosition);
    EXPECT_EQ(path.positions[1], triPosition);
    TQ3Object object = nullptr;
    ASSERT_EQ(Q3Group_GetPositionObject(inner, path.positions[1], &object), kQ3Success);
    EXPECT_EQ(object, tri);
    Q3Object_Dispose(object);
    ASSERT_EQ(Q3HitPath_EmptyData(&path), kQ3Success);
    EXPECT_EQ(path.rootGroup, nullptr);
    EXPECT_EQ(path.depth, 0u);
    EXPECT_EQ(path.positions, nullptr);
    ASSERT_EQ(Q3HitPath_EmptyData(&path), kQ3Success); // emptied twice is fine

    // A group that is not picked hides what it holds.
    ASSERT_EQ(Q3DisplayGroup_SetState(inner, kQ3DisplayGroupStateMaskIsDrawn), kQ3Success);
    ASSERT_EQ(pick(view, w, [&](TQ3ViewObject v) { Q3Object_Submit(outer, v); }), kQ3ViewStatusDone);
    EXPECT_EQ(hits(w), 0u);

    EXPECT_Q3_ERROR(Q3HitPath_EmptyData(nullptr), kQ3ErrorNULLParameter);
    TQ3HitPath bad{tri, 0, nullptr};
    EXPECT_Q3_ERROR(Q3HitPath_EmptyData(&bad), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(bad.rootGroup, tri);
    TQ3HitPath noPositions{nullptr, 1, nullptr};
    EXPECT_Q3_ERROR(Q3HitPath_EmptyData(&noPositions), kQ3ErrorInvalidParameter);
    EXPECT_EQ(noPositions.depth, 1u);
}

TEST_F(PickApiTest, PickPartsReportFaceEdgeAndVertex)
{
    TQ3ViewObject view = own(Q3View_New());
    TQ3GeometryObject tri = square(0, 0, 0); // corners (0,0) (2,0) (0,2)
    // The ray passes inside the triangle, 0.05 from its corner (0, 0) on
    // both axes: within 0.1 of the corner and of two edges.
    const TQ3WorldRayPickData ray = rayData({0.05f, 0.05f, 4}, {0, 0, -1});
    TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
    auto partsOf = [&](TQ3PickParts parts) {
        EXPECT_EQ(pick(view, w,
                       [&](TQ3ViewObject v) {
                           Q3PickPartsStyle_Submit(parts, v);
                           Q3Object_Submit(tri, v);
                       }),
                  kQ3ViewStatusDone);
        std::multiset<TQ3PickParts> found;
        for (unsigned long i = 0; i < hits(w); ++i)
            found.insert(detail<TQ3PickParts>(w, i, kQ3PickDetailMaskPickPart));
        return found;
    };
    EXPECT_EQ(partsOf(kQ3PickPartsObject), (std::multiset<TQ3PickParts>{kQ3PickPartsObject}));
    EXPECT_EQ(partsOf(kQ3PickPartsMaskFace), (std::multiset<TQ3PickParts>{kQ3PickPartsMaskFace}));
    EXPECT_EQ(partsOf(kQ3PickPartsMaskFace | kQ3PickPartsMaskEdge | kQ3PickPartsMaskVertex),
              (std::multiset<TQ3PickParts>{kQ3PickPartsMaskFace, kQ3PickPartsMaskEdge, kQ3PickPartsMaskVertex}));
    // The vertex hit is the corner itself.
    ASSERT_EQ(hits(w), 3u);
    for (unsigned long i = 0; i < 3; ++i)
        if (detail<TQ3PickParts>(w, i, kQ3PickDetailMaskPickPart) == kQ3PickPartsMaskVertex) {
            const TQ3Point3D at = detail<TQ3Point3D>(w, i, kQ3PickDetailMaskXYZ);
            EXPECT_EQ(at.x, 0.0f);
            EXPECT_EQ(at.y, 0.0f);
            EXPECT_FLOAT_EQ(detail<float>(w, i, kQ3PickDetailMaskDistance), std::sqrt(16.0f + 0.005f));
        }
    // Tighter than 0.05, only the face is left.
    ASSERT_EQ(Q3Pick_SetVertexTolerance(w, 0.04f), kQ3Success);
    ASSERT_EQ(Q3Pick_SetEdgeTolerance(w, 0.04f), kQ3Success);
    EXPECT_EQ(partsOf(kQ3PickPartsMaskFace | kQ3PickPartsMaskEdge | kQ3PickPartsMaskVertex),
              (std::multiset<TQ3PickParts>{kQ3PickPartsMaskFace}));
}

TEST_F(PickApiTest, PointsAndLinesWithinWorldTolerances)
{
    TQ3ViewObject view = own(Q3View_New());
    const TQ3PointData pointData{{0.3f, 0, 0}, nullptr};
    TQ3GeometryObject point = own(Q3Point_New(&pointData));
    TQ3LineData lineData{};
    lineData.vertices[0].point = {-1, 0.3f, -2};
    lineData.vertices[1].point = {1, 0.3f, -2};
    TQ3GeometryObject line = own(Q3Line_New(&lineData));
    const TQ3WorldRayPickData ray = rayData({0, 0, 5}, {0, 0, -1});
    TQ3PickObject w = own(Q3WorldRayPick_New(&ray));
    auto scene = [&](TQ3ViewObject v) {
        Q3Object_Submit(point, v);
        Q3Object_Submit(line, v);
    };
    for (float tolerance : {0.2f, 0.35f}) {
        ASSERT_EQ(Q3Pick_SetVertexTolerance(w, tolerance), kQ3Success);
        ASSERT_EQ(Q3Pick_SetEdgeTolerance(w, tolerance), kQ3Success);
        ASSERT_EQ(pick(view, w, scene), kQ3ViewStatusDone);
        if (tolerance < 0.3f) {
            EXPECT_EQ(hits(w), 0u);
            continue;
        }
        ASSERT_EQ(hits(w), 2u);
        // Near to far: the point (distance from the origin 5.009), then the
        // line's closest point (0, 0.3, -2).
        EXPECT_EQ(detail<TQ3Object>(w, 0, kQ3PickDetailMaskObject), point);
        Q3Object_Dispose(point);
        EXPECT_FLOAT_EQ(detail<float>(w, 0, kQ3PickDetailMaskDistance), std::sqrt(25.0f + 0.09f));
        const TQ3Point3D onLine = detail<TQ3Point3D>(w, 1, kQ3PickDetailMaskXYZ);
        EXPECT_NEAR(onLine.x, 0.0f, 1e-6);
        EXPECT_FLOAT_EQ(onLine.y, 0.3f);
        EXPECT_FLOAT_EQ(onLine.z, -2.0f);
    }
}

// The world-ray picking of a triangle, against the plane intersection and
// Cramer's rule computed here.
TEST_F(PickApiTest, WorldRayHitsMatchAnIndependentEvaluator)
{
    TQ3ViewObject view = own(Q3View_New());
    std::mt19937 rng(2026);
    std::uniform_real_distribution<float> coord(-2.0f, 2.0f);
    int hitCount = 0, missCount = 0;
    for (int i = 0; i < 400; ++i) {
        const TQ3Point3D a{coord(rng), coord(rng), coord(rng)};
        const TQ3Point3D b{coord(rng), coord(rng), coord(rng)};
        const TQ3Point3D c{coord(rng), coord(rng), coord(rng)};
        // Half the rays start above the triangle's centre, so both outcomes
        // are common.
        const float cx = (a.x + b.x + c.x) / 3, cy = (a.y + b.y + c.y) / 3;
        const TQ3Point3D o = i % 2 == 0 ? TQ3Point3D{coord(rng), coord(rng), 5.0f + coord(rng)}
                                        : TQ3Point3D{cx + 0.3f * coord(rng), cy + 0.3f * coord(rng), 5.0f};
        const float slope = i % 2 == 0 ? 0.3f : 0.02f;
        const TQ3Vector3D d{slope * coord(rng), slope * coord(rng), -1.0f};
        // Reference, in double.
        const double e1[3] = {b.x - a.x, b.y - a.y, b.z - a.z};
        const double e2[3] = {c.x - a.x, c.y - a.y, c.z - a.z};
        const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                             e1[0] * e2[1] - e1[1] * e2[0]};
        const double nd = n[0] * d.x + n[1] * d.y + n[2] * d.z;
        const double area = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (area < 0.05 || std::abs(nd) < 0.05 * area)
            continue;
        const double t = (n[0] * (a.x - o.x) + n[1] * (a.y - o.y) + n[2] * (a.z - o.z)) / nd;
        const double p[3] = {o.x + t * d.x - a.x, o.y + t * d.y - a.y, o.z + t * d.z - a.z};
        auto dot = [](const double* x, const double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
        const double d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2), d20 = dot(p, e1), d21 = dot(p, e2);
        const double det = d00 * d11 - d01 * d01;
        const double u = (d11 * d20 - d01 * d21) / det;
        const double v = (d00 * d21 - d01 * d20) / det;
        const double margin = std::min({u, v, 1.0 - u - v});
        if (std::abs(margin) < 1e-3 || std::abs(t) < 1e-3)
            continue;
        const bool want = margin > 0.0 && t > 0.0;

        const TQ3TriangleData tri = triangleData(a, b, c);
        const TQ3WorldRayPickData ray = rayData(o, d);
        TQ3PickObject w = Q3WorldRayPick_New(&ray);
        ASSERT_EQ(pick(view, w, [&](TQ3ViewObject vw) { Q3Triangle_Submit(&tri, vw); }), kQ3ViewStatusDone);
        ASSERT_EQ(hits(w), want ? 1u : 0u) << "case " << i;
        if (want) {
            ++hitCount;
            const double length = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
            EXPECT_NEAR(detail<float>(w, 0, kQ3PickDetailMaskDistance), t * length, 1e-4) << "case " << i;
        } else {
            ++missCount;
        }
        Q3Object_Dispose(w);
    }
    EXPECT_GT(hitCount, 60);
    EXPECT_GT(missCount, 60);
}

// ---- Window picks against the rendered image ------------------------------------

struct Colored {
    unsigned long id;
    TQ3ColorRGB color;
};

const Colored kColors[] = {{1, {1, 0, 0}}, {2, {0, 1, 0}}, {3, {0, 0, 1}}, {4, {1, 1, 0}}, {5, {1, 0, 1}}};

class PickRenderTest : public PickApiTest {
protected:
    /// Triangle `k` of a scene: under kColors[k]'s pick ID, in its colour.
    static void submitColoredTriangle(TQ3ViewObject v, int k, const TQ3Point3D (&corners)[3])
    {
        Q3PickIDStyle_Submit(kColors[k].id, v);
        TQ3AttributeSet set = Q3AttributeSet_New();
        Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &kColors[k].color);
        TQ3TriangleData data = triangleData(corners[0], corners[1], corners[2]);
        data.triangleAttributeSet = set;
        Q3Triangle_Submit(&data, v);
        Q3Object_Dispose(set);
    }

    /// Overlapping triangles at different depths, each in its own colour
    /// under its own pick ID; unlit, so each pixel shows one colour exactly.
    void submitScene(TQ3ViewObject v)
    {
        const TQ3Point3D corners[][3] = {{{-0.5f, -1.0f, 0.0f}, {2.5f, -0.8f, 0.0f}, {0.5f, 1.8f, 0.0f}},
                                         {{0.5f, -0.5f, 1.0f}, {3.4f, 0.0f, -1.0f}, {2.0f, 1.9f, 0.5f}},
                                         {{-0.4f, 1.9f, -0.5f}, {1.5f, 0.2f, 2.0f}, {3.0f, 1.5f, -0.5f}},
                                         {{1.0f, -0.9f, 3.0f}, {1.6f, -0.9f, 3.0f}, {1.3f, 0.4f, 3.0f}},
                                         {{2.6f, -0.9f, -3.0f}, {3.4f, -0.9f, -3.0f}, {3.4f, 1.9f, -3.0f}}};
        for (int k = 0; k < 5; ++k)
            submitColoredTriangle(v, k, corners[k]);
    }

    static unsigned long idOf(const Rgba& c)
    {
        for (const Colored& k : kColors)
            if (c.r == int(k.color.r * 255) && c.g == int(k.color.g * 255) && c.b == int(k.color.b * 255))
                return k.id;
        return 0;
    }

    /// Every pixel of the scene's image against a window-point pick at its
    /// centre, skipping pixels next to a change of colour (where the
    /// rasterizer's edge rule, not geometry, decides).
    void compareEveryPixel(TQ3CameraObject camera)
    {
        Pixmap image(kWidth, kHeight);
        TestView tv(image.pixmap(), kQ3RendererTypeInteractive, camera);
        ASSERT_EQ(tv.render([&](TQ3ViewObject v) { submitScene(v); }), kQ3ViewStatusDone);
        const TQ3WindowPointPickData data = pointData(0, 0, pickData(kQ3PickSortNearToFar, kQ3PickDetailMaskPickID, 1));
        TQ3PickObject p = own(Q3WindowPointPick_New(&data));
        int compared = 0;
        std::set<unsigned long> seen;
        for (int y = 1; y + 1 < kHeight; ++y)
            for (int x = 1; x + 1 < kWidth; ++x) {
                const unsigned long id = idOf(image.at(x, y));
                bool uniform = true;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        uniform = uniform && idOf(image.at(x + dx, y + dy)) == id;
                if (!uniform)
                    continue;
                const TQ3Point2D at{x + 0.5f, y + 0.5f};
                ASSERT_EQ(Q3WindowPointPick_SetPoint(p, &at), kQ3Success);
                ASSERT_EQ(pick(tv.view(), p, [&](TQ3ViewObject v) { submitScene(v); }), kQ3ViewStatusDone);
                const unsigned long picked = hits(p) == 0 ? 0 : detail<unsigned long>(p, 0, kQ3PickDetailMaskPickID);
                ASSERT_EQ(picked, id) << "pixel " << x << ", " << y;
                seen.insert(id);
                ++compared;
            }
        EXPECT_GT(compared, kWidth * kHeight / 2);
        // Every triangle and the background were seen somewhere.
        EXPECT_EQ(seen.size(), 6u);
    }
};

TEST_F(PickRenderTest, WindowPointPickFindsWhatIsDrawnAtEachPixelOrthographic)
{
    compareEveryPixel(nullptr);
}

TEST_F(PickRenderTest, WindowPointPickFindsWhatIsDrawnAtEachPixelPerspective)
{
    const TQ3ViewAngleAspectCameraData data =
        viewAngleCamera({1.5, 0.5, 6.0}, {1.5, 0.5, 0.0}, {0, 1, 0}, 0.7, double(kWidth) / kHeight);
    TQ3CameraObject camera = own(Q3ViewAngleAspectCamera_New(&data));
    compareEveryPixel(camera);
}

TEST_F(PickRenderTest, WindowRectPickFindsWhatIsDrawnInTheRectangle)
{
    Pixmap image(kWidth, kHeight);
    TestView tv(image.pixmap());
    // Side by side, no overlap: everything in the rectangle is visible.
    auto scene = [&](TQ3ViewObject v) {
        const TQ3Point3D corners[][3] = {{{-0.4f, -0.9f, 0}, {0.6f, -0.9f, 0}, {0.1f, 1.9f, 0}},
                                         {{0.8f, -0.9f, 0}, {1.8f, -0.9f, 0}, {1.3f, 1.9f, 0}},
                                         {{2.0f, -0.9f, 0}, {3.4f, -0.9f, 0}, {2.7f, 1.9f, 0}}};
        for (int k = 0; k < 3; ++k)
            submitColoredTriangle(v, k, corners[k]);
    };
    ASSERT_EQ(tv.render(scene), kQ3ViewStatusDone);
    auto colorsIn = [&](int x0, int y0, int x1, int y1) {
        std::set<unsigned long> ids;
        for (int y = std::max(y0, 0); y < std::min(y1, kHeight); ++y)
            for (int x = std::max(x0, 0); x < std::min(x1, kWidth); ++x)
                if (unsigned long id = idOf(image.at(x, y)))
                    ids.insert(id);
        return ids;
    };
    const TQ3WindowRectPickData data = rectData(0, 0, 1, 1, pickData(kQ3PickSortNearToFar, kQ3PickDetailMaskPickID));
    TQ3PickObject r = own(Q3WindowRectPick_New(&data));
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> xs(0, kWidth - 4), ys(0, kHeight - 4), size(1, 30);
    int nonEmpty = 0;
    for (int i = 0; i < 60; ++i) {
        const int x0 = xs(rng), y0 = ys(rng);
        const int x1 = std::min(kWidth, x0 + size(rng)), y1 = std::min(kHeight, y0 + size(rng));
        const TQ3Area area{{float(x0), float(y0)}, {float(x1), float(y1)}};
        ASSERT_EQ(Q3WindowRectPick_SetRect(r, &area), kQ3Success);
        ASSERT_EQ(pick(tv.view(), r, scene), kQ3ViewStatusDone);
        std::set<unsigned long> picked;
        for (unsigned long k = 0; k < hits(r); ++k)
            picked.insert(detail<unsigned long>(r, k, kQ3PickDetailMaskPickID));
        // What the pixels inside show was picked; nothing was picked that
        // shows nowhere within one pixel of the rectangle.
        const std::set<unsigned long> inside = colorsIn(x0, y0, x1, y1);
        const std::set<unsigned long> around = colorsIn(x0 - 1, y0 - 1, x1 + 1, y1 + 1);
        for (unsigned long id : inside)
            EXPECT_EQ(picked.count(id), 1u) << "rect " << i << " id " << id;
        for (unsigned long id : picked)
            EXPECT_EQ(around.count(id), 1u) << "rect " << i << " id " << id;
        nonEmpty += !picked.empty();
        // Window-rect hits have no distance or point.
        if (hits(r) != 0) {
            TQ3PickDetail valid = 0;
            ASSERT_EQ(Q3Pick_GetPickDetailValidMask(r, 0, &valid), kQ3Success);
            EXPECT_EQ(valid, TQ3PickDetail(kQ3PickDetailMaskPickID));
        }
    }
    EXPECT_GT(nonEmpty, 30);
}

TEST_F(PickRenderTest, WindowPointTolerancesAreInPixels)
{
    Pixmap image(kWidth, kHeight);
    TestView tv(image.pixmap());
    const Projection project = orthographicProjection(0, 0, kWidth, kHeight);
    // A point at (1.5, 0.5) and a horizontal line at y = 1 from x = 0 to 3.
    const TQ3PointData pointData{{1.5f, 0.5f, 0}, nullptr};
    TQ3GeometryObject point = own(Q3Point_New(&pointData));
    TQ3LineData lineData{};
    lineData.vertices[0].point = {0, 1, 0};
    lineData.vertices[1].point = {3, 1, 0};
    TQ3GeometryObject line = own(Q3Line_New(&lineData));
    const Point3 at = project({1.5, 0.5, 0});
    const Point3 lineAt = project({1.0, 1.0, 0});
    struct Case {
        double x, y;
        float tolerance;
        TQ3Object want;
    } cases[] = {{at.x + 3, at.y, 2.0f, nullptr},       {at.x + 3, at.y, 4.0f, point},
                 {at.x, at.y - 2.5, 2.0f, nullptr},     {at.x, at.y - 2.5, 3.0f, point},
                 {lineAt.x, lineAt.y + 3, 2.5f, nullptr}, {lineAt.x, lineAt.y + 3, 3.5f, line}};
    for (const Case& c : cases) {
        TQ3WindowPointPickData data = pointData2(float(c.x), float(c.y), c.tolerance);
        TQ3PickObject p = Q3WindowPointPick_New(&data);
        ASSERT_EQ(pick(tv.view(), p,
                       [&](TQ3ViewObject v) {
                           Q3Object_Submit(point, v);
                           Q3Object_Submit(line, v);
                       }),
                  kQ3ViewStatusDone);
        if (c.want == nullptr) {
            EXPECT_EQ(hits(p), 0u) << c.x << ", " << c.y;
        } else {
            ASSERT_EQ(hits(p), 1u) << c.x << ", " << c.y;
            TQ3Object got = detail<TQ3Object>(p, 0, kQ3PickDetailMaskObject);
            EXPECT_EQ(got, c.want);
            Q3Object_Dispose(got);
        }
        Q3Object_Dispose(p);
    }
}

// Shapes of other kinds (a box, an ellipsoid, the article's curve, a
// polyline), each drawn alone: every pixel it covers is picked as it, every
// pixel two pixels clear of it picks nothing.
TEST_F(PickRenderTest, EveryKindOfShapeIsPickedWhereItIsDrawn)
{
    TQ3BoxData box{{0.0f, -0.8f, -0.5f}, {0, 0, 1}, {1.2f, 0.3f, 0}, {-0.3f, 1.2f, 0}, nullptr, nullptr};
    TQ3EllipsoidData ellipsoid{{2.0f, 0.6f, 0.0f}, {0, 0, 0.8f}, {0.9f, 0, 0}, {0, 0.7f, 0}, 0, 1, 0, 1,
                               kQ3EndCapNone, nullptr, nullptr};
    Listing1 listing1;
    const TQ3NURBCurveData curve = listing1.data();
    TQ3Vertex3D zigzag[4] = {{{-0.3f, 1.8f, 0}, nullptr}, {{0.5f, 1.2f, 0}, nullptr}, {{1.4f, 1.9f, 0}, nullptr},
                             {{3.2f, -0.9f, 0}, nullptr}};
    const TQ3PolyLineData polyLine{4, zigzag, nullptr, nullptr};
    const TQ3GeometryObject shapes[] = {own(Q3Box_New(&box)), own(Q3Ellipsoid_New(&ellipsoid)),
                                        own(Q3NURBCurve_New(&curve)), own(Q3PolyLine_New(&polyLine))};
    for (TQ3GeometryObject shape : shapes) {
        Pixmap image(kWidth, kHeight);
        TestView tv(image.pixmap());
        auto scene = [&](TQ3ViewObject v) { Q3Object_Submit(shape, v); };
        ASSERT_EQ(tv.render(scene), kQ3ViewStatusDone);
        TQ3WindowPointPickData data = pointData2(0, 0, 1.5f);
        TQ3PickObject p = own(Q3WindowPointPick_New(&data));
        auto lit = [&](int x, int y) {
            const Rgba c = image.at(x, y);
            return c.r + c.g + c.b > 0;
        };
        int inside = 0, outside = 0;
        for (int y = 2; y + 2 < kHeight; y += 2)
            for (int x = 2; x + 2 < kWidth; x += 2) {
                bool clear = true;
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx)
                        clear = clear && !lit(x + dx, y + dy);
                if (!lit(x, y) && !clear)
                    continue;
                const TQ3Point2D at{x + 0.5f, y + 0.5f};
                ASSERT_EQ(Q3WindowPointPick_SetPoint(p, &at), kQ3Success);
                ASSERT_EQ(pick(tv.view(), p, scene), kQ3ViewStatusDone);
                if (clear) {
                    EXPECT_EQ(hits(p), 0u) << "type " << Q3Object_GetLeafType(shape) << " pixel " << x << ", " << y;
                    ++outside;
                    continue;
                }
                ASSERT_EQ(hits(p), 1u) << "type " << Q3Object_GetLeafType(shape) << " pixel " << x << ", " << y;
                TQ3Object got = detail<TQ3Object>(p, 0, kQ3PickDetailMaskObject);
                EXPECT_EQ(got, shape);
                Q3Object_Dispose(got);
                ++inside;
            }
        EXPECT_GT(inside, 10) << Q3Object_GetLeafType(shape);
        EXPECT_GT(outside, 100) << Q3Object_GetLeafType(shape);
    }
}

} // namespace
