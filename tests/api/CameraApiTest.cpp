// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Cameras: data round trips, every TQ3CameraData rule, and the matrices with
// QuickDraw 3D's conventions (row vectors; view space looks down -z; frustum
// x, y in -1..1 across the view port, z from 0 at hither to -1 at yon). The
// expected values are worked out by hand in each test.

#include "Q3ApiTest.h"

#include "QD3DCamera.h"
#include "QD3DSet.h"

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

using q3test::Q3ApiTest;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kPi = 3.14159265358979323846;

TQ3CameraData commonData()
{
    TQ3CameraData data{};
    data.placement = {{0, 0, 5}, {0, 0, 0}, {0, 1, 0}};
    data.range = {1, 10};
    data.viewPort = {{-1, 1}, 2, 2};
    return data;
}

TQ3OrthographicCameraData orthographicData()
{
    return {commonData(), -2, 1, 2, -1};
}

TQ3ViewPlaneCameraData viewPlaneData()
{
    return {commonData(), 2, 1, 0.5f, 0, 0};
}

TQ3ViewAngleAspectCameraData viewAngleData()
{
    return {commonData(), float(kPi / 2), 2};
}

struct Homogeneous {
    double x, y, z, w;
};

// p * M for the row vector (x, y, z, 1).
Homogeneous apply(const TQ3Matrix4x4& m, double x, double y, double z)
{
    const double in[4] = {x, y, z, 1};
    double out[4] = {0, 0, 0, 0};
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
            out[j] += in[i] * m.value[i][j];
    return {out[0], out[1], out[2], out[3]};
}

// The frustum point of a view-space point (after the divide).
Homogeneous toFrustum(const TQ3Matrix4x4& m, double x, double y, double z)
{
    const Homogeneous h = apply(m, x, y, z);
    return {h.x / h.w, h.y / h.w, h.z / h.w, 1};
}

class CameraApiTest : public Q3ApiTest {
protected:
    TQ3Matrix4x4 worldToView(TQ3CameraObject camera)
    {
        TQ3Matrix4x4 m{};
        EXPECT_EQ(Q3Camera_GetWorldToView(camera, &m), kQ3Success);
        return m;
    }
    TQ3Matrix4x4 viewToFrustum(TQ3CameraObject camera)
    {
        TQ3Matrix4x4 m{};
        EXPECT_EQ(Q3Camera_GetViewToFrustum(camera, &m), kQ3Success);
        return m;
    }

    // Every rule of TQ3CameraData broken once, each applied to a copy of good data.
    std::vector<std::function<void(TQ3CameraData&)>> brokenCommonData(bool perspective)
    {
        std::vector<std::function<void(TQ3CameraData&)>> cases = {
            [](TQ3CameraData& d) { d.placement.cameraLocation.x = kNaN; },
            [](TQ3CameraData& d) { d.placement.cameraLocation.z = kInf; },
            [](TQ3CameraData& d) { d.placement.pointOfInterest.y = -kInf; },
            [](TQ3CameraData& d) { d.placement.upVector.z = kNaN; },
            [](TQ3CameraData& d) { d.placement.pointOfInterest = d.placement.cameraLocation; },
            [](TQ3CameraData& d) { d.placement.upVector = {0, 0, 0}; },
            [](TQ3CameraData& d) { d.placement.upVector = {0, 0, -3}; }, // parallel to the view direction
            [](TQ3CameraData& d) { d.range.hither = kNaN; },
            [](TQ3CameraData& d) { d.range.yon = kInf; },
            [](TQ3CameraData& d) { d.range = {5, 5}; },
            [](TQ3CameraData& d) { d.range = {6, 5}; },
            [](TQ3CameraData& d) { d.viewPort.origin.x = kNaN; },
            [](TQ3CameraData& d) { d.viewPort.width = 0; },
            [](TQ3CameraData& d) { d.viewPort.height = -1; },
            [](TQ3CameraData& d) { d.viewPort.height = kInf; },
        };
        if (perspective) {
            cases.push_back([](TQ3CameraData& d) { d.range.hither = 0; });
            cases.push_back([](TQ3CameraData& d) { d.range.hither = -1; });
        }
        return cases;
    }
};

TEST_F(CameraApiTest, EachKindIsCreatedAndReadBack)
{
    const TQ3OrthographicCameraData ortho = orthographicData();
    const TQ3ViewPlaneCameraData plane = viewPlaneData();
    const TQ3ViewAngleAspectCameraData angle = viewAngleData();
    TQ3CameraObject a = Q3OrthographicCamera_New(&ortho);
    TQ3CameraObject b = Q3ViewPlaneCamera_New(&plane);
    TQ3CameraObject c = Q3ViewAngleAspectCamera_New(&angle);
    ASSERT_TRUE(a && b && c);
    EXPECT_EQ(Q3Camera_GetType(a), kQ3CameraTypeOrthographic);
    EXPECT_EQ(Q3Camera_GetType(b), kQ3CameraTypeViewPlane);
    EXPECT_EQ(Q3Camera_GetType(c), kQ3CameraTypeViewAngleAspect);
    EXPECT_EQ(Q3Shape_GetType(a), kQ3ShapeTypeCamera);
    EXPECT_EQ(Q3Object_IsDrawable(a), kQ3False);

    TQ3OrthographicCameraData orthoOut{};
    EXPECT_EQ(Q3OrthographicCamera_GetData(a, &orthoOut), kQ3Success);
    EXPECT_EQ(std::memcmp(&orthoOut, &ortho, sizeof ortho), 0);
    TQ3ViewPlaneCameraData planeOut{};
    EXPECT_EQ(Q3ViewPlaneCamera_GetData(b, &planeOut), kQ3Success);
    EXPECT_EQ(std::memcmp(&planeOut, &plane, sizeof plane), 0);
    TQ3ViewAngleAspectCameraData angleOut{};
    EXPECT_EQ(Q3ViewAngleAspectCamera_GetData(c, &angleOut), kQ3Success);
    EXPECT_EQ(std::memcmp(&angleOut, &angle, sizeof angle), 0);

    // The orthographic camera accepts a hither at or behind the eye.
    TQ3OrthographicCameraData behind = ortho;
    behind.cameraData.range = {-5, 5};
    EXPECT_EQ(Q3OrthographicCamera_SetData(a, &behind), kQ3Success);
    for (TQ3Object camera : {a, b, c})
        Q3Object_Dispose(camera);
}

TEST_F(CameraApiTest, CommonDataAndItsPartsRoundTrip)
{
    const TQ3ViewAngleAspectCameraData angle = viewAngleData();
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&angle);
    TQ3CameraData data = commonData();
    data.placement = {{1, 2, 3}, {4, 5, 6}, {0, 0, 1}};
    data.range = {0.5f, 99};
    data.viewPort = {{-0.5f, 0.5f}, 1, 1};
    const unsigned long edit = Q3Shared_GetEditIndex(camera);
    EXPECT_EQ(Q3Camera_SetData(camera, &data), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(camera), edit);
    TQ3CameraData out{};
    EXPECT_EQ(Q3Camera_GetData(camera, &out), kQ3Success);
    EXPECT_EQ(std::memcmp(&out, &data, sizeof data), 0);

    const TQ3CameraPlacement placement = {{0, 3, 0}, {0, 0, 0}, {1, 0, 0}};
    EXPECT_EQ(Q3Camera_SetPlacement(camera, &placement), kQ3Success);
    TQ3CameraPlacement placementOut{};
    EXPECT_EQ(Q3Camera_GetPlacement(camera, &placementOut), kQ3Success);
    EXPECT_EQ(std::memcmp(&placementOut, &placement, sizeof placement), 0);

    const TQ3CameraRange range = {2, 20};
    EXPECT_EQ(Q3Camera_SetRange(camera, &range), kQ3Success);
    TQ3CameraRange rangeOut{};
    EXPECT_EQ(Q3Camera_GetRange(camera, &rangeOut), kQ3Success);
    EXPECT_EQ(rangeOut.hither, 2.0f);
    EXPECT_EQ(rangeOut.yon, 20.0f);

    const TQ3CameraViewPort port = {{0, 0}, 0.5f, 0.25f};
    EXPECT_EQ(Q3Camera_SetViewPort(camera, &port), kQ3Success);
    TQ3CameraViewPort portOut{};
    EXPECT_EQ(Q3Camera_GetViewPort(camera, &portOut), kQ3Success);
    EXPECT_EQ(std::memcmp(&portOut, &port, sizeof port), 0);

    // The kind-specific data see the same common part.
    TQ3ViewAngleAspectCameraData all{};
    Q3ViewAngleAspectCamera_GetData(camera, &all);
    EXPECT_EQ(std::memcmp(&all.cameraData.viewPort, &port, sizeof port), 0);
    EXPECT_EQ(all.fov, angle.fov);
    Q3Object_Dispose(camera);
}

TEST_F(CameraApiTest, EveryBrokenRuleIsRejectedAndChangesNothing)
{
    const TQ3OrthographicCameraData ortho = orthographicData();
    const TQ3ViewPlaneCameraData plane = viewPlaneData();
    const TQ3ViewAngleAspectCameraData angle = viewAngleData();
    TQ3CameraObject cameras[3] = {Q3OrthographicCamera_New(&ortho), Q3ViewPlaneCamera_New(&plane),
                                  Q3ViewAngleAspectCamera_New(&angle)};
    for (int kind = 0; kind < 3; ++kind) {
        TQ3CameraObject camera = cameras[kind];
        const unsigned long edit = Q3Shared_GetEditIndex(camera);
        TQ3CameraData before{};
        Q3Camera_GetData(camera, &before);
        int index = 0;
        for (const auto& breakIt : brokenCommonData(kind != 0)) {
            SCOPED_TRACE("kind " + std::to_string(kind) + " case " + std::to_string(index++));
            TQ3CameraData bad = commonData();
            breakIt(bad);
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Camera_SetData(camera, &bad), kQ3Failure), kQ3ErrorInvalidCameraValues);
            // The setter of the part that is broken fails too.
            if (std::memcmp(&bad.placement, &before.placement, sizeof bad.placement) != 0)
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3Camera_SetPlacement(camera, &bad.placement), kQ3Failure),
                                kQ3ErrorInvalidCameraValues);
            if (std::memcmp(&bad.range, &before.range, sizeof bad.range) != 0)
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3Camera_SetRange(camera, &bad.range), kQ3Failure),
                                kQ3ErrorInvalidCameraValues);
            if (std::memcmp(&bad.viewPort, &before.viewPort, sizeof bad.viewPort) != 0)
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3Camera_SetViewPort(camera, &bad.viewPort), kQ3Failure),
                                kQ3ErrorInvalidCameraValues);
            // New with the broken common data fails too.
            TQ3CameraObject made = nullptr;
            if (kind == 0) {
                TQ3OrthographicCameraData d = ortho;
                d.cameraData = bad;
                EXPECT_Q3_ERROR(made = Q3OrthographicCamera_New(&d), kQ3ErrorInvalidCameraValues);
            } else if (kind == 1) {
                TQ3ViewPlaneCameraData d = plane;
                d.cameraData = bad;
                EXPECT_Q3_ERROR(made = Q3ViewPlaneCamera_New(&d), kQ3ErrorInvalidCameraValues);
            } else {
                TQ3ViewAngleAspectCameraData d = angle;
                d.cameraData = bad;
                EXPECT_Q3_ERROR(made = Q3ViewAngleAspectCamera_New(&d), kQ3ErrorInvalidCameraValues);
            }
            EXPECT_EQ(made, nullptr);
        }
        TQ3CameraData after{};
        Q3Camera_GetData(camera, &after);
        EXPECT_EQ(std::memcmp(&after, &before, sizeof after), 0);
        EXPECT_EQ(Q3Shared_GetEditIndex(camera), edit);
    }
    for (TQ3Object camera : cameras)
        Q3Object_Dispose(camera);
}

TEST_F(CameraApiTest, KindSpecificRulesAreChecked)
{
    TQ3OrthographicCameraData ortho = orthographicData();
    TQ3CameraObject orthoCamera = Q3OrthographicCamera_New(&ortho);
    for (auto breakIt : std::vector<std::function<void(TQ3OrthographicCameraData&)>>{
             [](TQ3OrthographicCameraData& d) { d.left = d.right; },
             [](TQ3OrthographicCameraData& d) { d.top = d.bottom; },
             [](TQ3OrthographicCameraData& d) { d.left = kNaN; },
             [](TQ3OrthographicCameraData& d) { d.bottom = -kInf; }}) {
        TQ3OrthographicCameraData bad = orthographicData();
        breakIt(bad);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3OrthographicCamera_New(&bad), nullptr), kQ3ErrorInvalidCameraValues);
        EXPECT_Q3_ERROR(Q3OrthographicCamera_SetData(orthoCamera, &bad), kQ3ErrorInvalidCameraValues);
    }
    // Mirrored bounds are allowed.
    TQ3OrthographicCameraData mirrored = orthographicData();
    std::swap(mirrored.left, mirrored.right);
    EXPECT_EQ(Q3OrthographicCamera_SetData(orthoCamera, &mirrored), kQ3Success);

    TQ3ViewPlaneCameraData plane = viewPlaneData();
    TQ3CameraObject planeCamera = Q3ViewPlaneCamera_New(&plane);
    for (auto breakIt : std::vector<std::function<void(TQ3ViewPlaneCameraData&)>>{
             [](TQ3ViewPlaneCameraData& d) { d.viewPlane = 0; },
             [](TQ3ViewPlaneCameraData& d) { d.viewPlane = -1; },
             [](TQ3ViewPlaneCameraData& d) { d.halfWidthAtViewPlane = 0; },
             [](TQ3ViewPlaneCameraData& d) { d.halfHeightAtViewPlane = -2; },
             [](TQ3ViewPlaneCameraData& d) { d.centerXOnViewPlane = kNaN; },
             [](TQ3ViewPlaneCameraData& d) { d.centerYOnViewPlane = kInf; },
             [](TQ3ViewPlaneCameraData& d) { d.viewPlane = kInf; }}) {
        TQ3ViewPlaneCameraData bad = viewPlaneData();
        breakIt(bad);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3ViewPlaneCamera_New(&bad), nullptr), kQ3ErrorInvalidCameraValues);
        EXPECT_Q3_ERROR(Q3ViewPlaneCamera_SetData(planeCamera, &bad), kQ3ErrorInvalidCameraValues);
    }

    TQ3ViewAngleAspectCameraData angle = viewAngleData();
    TQ3CameraObject angleCamera = Q3ViewAngleAspectCamera_New(&angle);
    for (auto breakIt : std::vector<std::function<void(TQ3ViewAngleAspectCameraData&)>>{
             [](TQ3ViewAngleAspectCameraData& d) { d.fov = 0; },
             [](TQ3ViewAngleAspectCameraData& d) { d.fov = -0.5f; },
             [](TQ3ViewAngleAspectCameraData& d) { d.fov = float(kPi); },
             [](TQ3ViewAngleAspectCameraData& d) { d.fov = kNaN; },
             [](TQ3ViewAngleAspectCameraData& d) { d.aspectRatioXToY = 0; },
             [](TQ3ViewAngleAspectCameraData& d) { d.aspectRatioXToY = -1; },
             [](TQ3ViewAngleAspectCameraData& d) { d.aspectRatioXToY = kInf; },
             [](TQ3ViewAngleAspectCameraData& d) { d.aspectRatioXToY = kNaN; }}) {
        TQ3ViewAngleAspectCameraData bad = viewAngleData();
        breakIt(bad);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3ViewAngleAspectCamera_New(&bad), nullptr), kQ3ErrorInvalidCameraValues);
        EXPECT_Q3_ERROR(Q3ViewAngleAspectCamera_SetData(angleCamera, &bad), kQ3ErrorInvalidCameraValues);
    }
    TQ3ViewAngleAspectCameraData out{};
    Q3ViewAngleAspectCamera_GetData(angleCamera, &out);
    EXPECT_EQ(std::memcmp(&out, &angle, sizeof out), 0);
    for (TQ3Object camera : {orthoCamera, planeCamera, angleCamera})
        Q3Object_Dispose(camera);
}

// Every field of every camera structure is a float; each one at NaN, +Inf
// and -Inf must be refused by New and SetData.
template <class Data>
void forEachNonFiniteField(const Data& good, const std::function<void(const Data&, const std::string&)>& check)
{
    static_assert(sizeof(Data) % sizeof(float) == 0, "camera data is all floats");
    for (std::size_t field = 0; field < sizeof(Data) / sizeof(float); ++field)
        for (float bad : {kNaN, kInf, -kInf}) {
            Data data = good;
            std::memcpy(reinterpret_cast<unsigned char*>(&data) + field * sizeof(float), &bad, sizeof bad);
            check(data, "field " + std::to_string(field) + " = " + std::to_string(bad));
        }
}

TEST_F(CameraApiTest, EveryFloatFieldRejectsNaNAndInfinities)
{
    const TQ3OrthographicCameraData ortho = orthographicData();
    const TQ3ViewPlaneCameraData plane = viewPlaneData();
    const TQ3ViewAngleAspectCameraData angle = viewAngleData();
    TQ3CameraObject a = Q3OrthographicCamera_New(&ortho);
    TQ3CameraObject b = Q3ViewPlaneCamera_New(&plane);
    TQ3CameraObject c = Q3ViewAngleAspectCamera_New(&angle);
    forEachNonFiniteField<TQ3OrthographicCameraData>(ortho, [&](const TQ3OrthographicCameraData& d, const std::string& what) {
        SCOPED_TRACE(what);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3OrthographicCamera_New(&d), nullptr), kQ3ErrorInvalidCameraValues);
        EXPECT_Q3_ERROR(Q3OrthographicCamera_SetData(a, &d), kQ3ErrorInvalidCameraValues);
    });
    forEachNonFiniteField<TQ3ViewPlaneCameraData>(plane, [&](const TQ3ViewPlaneCameraData& d, const std::string& what) {
        SCOPED_TRACE(what);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3ViewPlaneCamera_New(&d), nullptr), kQ3ErrorInvalidCameraValues);
        EXPECT_Q3_ERROR(Q3ViewPlaneCamera_SetData(b, &d), kQ3ErrorInvalidCameraValues);
    });
    forEachNonFiniteField<TQ3ViewAngleAspectCameraData>(
        angle, [&](const TQ3ViewAngleAspectCameraData& d, const std::string& what) {
            SCOPED_TRACE(what);
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3ViewAngleAspectCamera_New(&d), nullptr), kQ3ErrorInvalidCameraValues);
            EXPECT_Q3_ERROR(Q3ViewAngleAspectCamera_SetData(c, &d), kQ3ErrorInvalidCameraValues);
        });
    forEachNonFiniteField<TQ3CameraData>(commonData(), [&](const TQ3CameraData& d, const std::string& what) {
        SCOPED_TRACE(what);
        EXPECT_Q3_ERROR(Q3Camera_SetData(c, &d), kQ3ErrorInvalidCameraValues);
    });
    forEachNonFiniteField<TQ3CameraPlacement>(commonData().placement,
                                              [&](const TQ3CameraPlacement& d, const std::string& what) {
                                                  SCOPED_TRACE(what);
                                                  EXPECT_Q3_ERROR(Q3Camera_SetPlacement(a, &d),
                                                                  kQ3ErrorInvalidCameraValues);
                                              });
    forEachNonFiniteField<TQ3CameraRange>(commonData().range, [&](const TQ3CameraRange& d, const std::string& what) {
        SCOPED_TRACE(what);
        EXPECT_Q3_ERROR(Q3Camera_SetRange(a, &d), kQ3ErrorInvalidCameraValues);
    });
    forEachNonFiniteField<TQ3CameraViewPort>(commonData().viewPort,
                                             [&](const TQ3CameraViewPort& d, const std::string& what) {
                                                 SCOPED_TRACE(what);
                                                 EXPECT_Q3_ERROR(Q3Camera_SetViewPort(b, &d),
                                                                 kQ3ErrorInvalidCameraValues);
                                             });
    TQ3OrthographicCameraData after{};
    Q3OrthographicCamera_GetData(a, &after);
    EXPECT_EQ(std::memcmp(&after, &ortho, sizeof after), 0);
    for (TQ3Object camera : {a, b, c})
        Q3Object_Dispose(camera);
}

TEST_F(CameraApiTest, KindSpecificCallsRejectOtherKindsAndBadPointers)
{
    const TQ3OrthographicCameraData ortho = orthographicData();
    const TQ3ViewPlaneCameraData plane = viewPlaneData();
    const TQ3ViewAngleAspectCameraData angle = viewAngleData();
    TQ3CameraObject a = Q3OrthographicCamera_New(&ortho);
    TQ3CameraObject b = Q3ViewPlaneCamera_New(&plane);
    TQ3CameraObject c = Q3ViewAngleAspectCamera_New(&angle);
    TQ3OrthographicCameraData orthoOut;
    TQ3ViewPlaneCameraData planeOut;
    TQ3ViewAngleAspectCameraData angleOut;
    EXPECT_Q3_ERROR(Q3OrthographicCamera_GetData(b, &orthoOut), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3OrthographicCamera_SetData(c, &ortho), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewPlaneCamera_GetData(a, &planeOut), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewPlaneCamera_SetData(c, &plane), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewAngleAspectCamera_GetData(a, &angleOut), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewAngleAspectCamera_SetData(b, &angle), kQ3ErrorInvalidObjectType);

    EXPECT_Q3_ERROR(Q3OrthographicCamera_New(nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewPlaneCamera_New(nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewAngleAspectCamera_New(nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3OrthographicCamera_GetData(a, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3OrthographicCamera_SetData(a, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewPlaneCamera_GetData(b, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewPlaneCamera_SetData(b, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewAngleAspectCamera_GetData(c, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewAngleAspectCamera_SetData(c, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3OrthographicCamera_GetData(nullptr, &orthoOut), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewPlaneCamera_SetData(nullptr, &plane), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewAngleAspectCamera_GetData(nullptr, &angleOut), kQ3ErrorNULLParameter);
    for (TQ3Object camera : {a, b, c})
        Q3Object_Dispose(camera);
    EXPECT_Q3_ERROR(Q3OrthographicCamera_GetData(a, &orthoOut), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3ViewPlaneCamera_SetData(b, &plane), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3ViewAngleAspectCamera_GetData(c, &angleOut), kQ3ErrorInvalidObject);
}

TEST_F(CameraApiTest, CommonCallsRejectBadHandlesAndPointers)
{
    const TQ3OrthographicCameraData ortho = orthographicData();
    TQ3CameraObject camera = Q3OrthographicCamera_New(&ortho);
    TQ3AttributeSet set = Q3AttributeSet_New();
    TQ3CameraObject dead = Q3OrthographicCamera_New(&ortho);
    Q3Object_Dispose(dead);
    TQ3CameraData data = commonData();
    TQ3Matrix4x4 m;
    // Each call: NULL handle, dead handle, wrong class, NULL pointer.
    const std::vector<std::function<TQ3Status(TQ3CameraObject, bool)>> calls = {
        [&](TQ3CameraObject c, bool p) { return Q3Camera_SetData(c, p ? &data : nullptr); },
        [&](TQ3CameraObject c, bool p) { return Q3Camera_GetData(c, p ? &data : nullptr); },
        [&](TQ3CameraObject c, bool p) { return Q3Camera_SetPlacement(c, p ? &data.placement : nullptr); },
        [&](TQ3CameraObject c, bool p) { return Q3Camera_GetPlacement(c, p ? &data.placement : nullptr); },
        [&](TQ3CameraObject c, bool p) { return Q3Camera_SetRange(c, p ? &data.range : nullptr); },
        [&](TQ3CameraObject c, bool p) { return Q3Camera_GetRange(c, p ? &data.range : nullptr); },
        [&](TQ3CameraObject c, bool p) { return Q3Camera_SetViewPort(c, p ? &data.viewPort : nullptr); },
        [&](TQ3CameraObject c, bool p) { return Q3Camera_GetViewPort(c, p ? &data.viewPort : nullptr); },
        [&](TQ3CameraObject c, bool p) { return Q3Camera_GetWorldToView(c, p ? &m : nullptr); },
        [&](TQ3CameraObject c, bool p) { return Q3Camera_GetViewToFrustum(c, p ? &m : nullptr); },
        [&](TQ3CameraObject c, bool p) { return Q3Camera_GetWorldToFrustum(c, p ? &m : nullptr); },
    };
    for (std::size_t i = 0; i < calls.size(); ++i) {
        SCOPED_TRACE("call " + std::to_string(i));
        EXPECT_Q3_ERROR(EXPECT_EQ(calls[i](nullptr, true), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(calls[i](dead, true), kQ3ErrorInvalidObject);
        EXPECT_Q3_ERROR(calls[i](set, true), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(calls[i](camera, false), kQ3ErrorNULLParameter);
        EXPECT_EQ(calls[i](camera, true), kQ3Success);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Camera_GetType(nullptr), kQ3ObjectTypeInvalid), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Camera_GetType(dead), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3Camera_GetType(set), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(camera);
    Q3Object_Dispose(set);
}

TEST_F(CameraApiTest, WorldToViewPutsTheEyeAtTheOriginLookingDownMinusZ)
{
    TQ3OrthographicCameraData data = orthographicData();
    // From (3, 4, 5) towards (3, 4, -1) with a tilted, non-unit up vector.
    data.cameraData.placement = {{3, 4, 5}, {3, 4, -1}, {0, 2, 2}};
    TQ3CameraObject camera = Q3OrthographicCamera_New(&data);
    const TQ3Matrix4x4 m = worldToView(camera);
    const Homogeneous eye = apply(m, 3, 4, 5);
    EXPECT_NEAR(eye.x, 0, 1e-6);
    EXPECT_NEAR(eye.y, 0, 1e-6);
    EXPECT_NEAR(eye.z, 0, 1e-6);
    const Homogeneous target = apply(m, 3, 4, -1);
    EXPECT_NEAR(target.x, 0, 1e-5);
    EXPECT_NEAR(target.y, 0, 1e-5);
    EXPECT_NEAR(target.z, -6, 1e-5);
    // Up (made perpendicular to the view direction: +y world) is +y; right is +x.
    const Homogeneous up = apply(m, 3, 5, 5);
    EXPECT_NEAR(up.x, 0, 1e-6);
    EXPECT_NEAR(up.y, 1, 1e-6);
    const Homogeneous right = apply(m, 4, 4, 5);
    EXPECT_NEAR(right.x, 1, 1e-6);
    EXPECT_NEAR(right.y, 0, 1e-6);
    // A rigid motion: the 3x3 part is orthonormal, the last column 0 0 0 1.
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double dot = 0;
            for (int k = 0; k < 3; ++k)
                dot += m.value[i][k] * m.value[j][k];
            EXPECT_NEAR(dot, i == j ? 1.0 : 0.0, 1e-6);
        }
        EXPECT_EQ(m.value[i][3], 0.0f);
    }
    EXPECT_EQ(m.value[3][3], 1.0f);
    Q3Object_Dispose(camera);
}

TEST_F(CameraApiTest, OrthographicFrustumMapsTheBoundsAndTheRange)
{
    const TQ3OrthographicCameraData data = orthographicData(); // x -2..2, y -1..1, hither 1, yon 10
    TQ3CameraObject camera = Q3OrthographicCamera_New(&data);
    const TQ3Matrix4x4 m = viewToFrustum(camera);
    const Homogeneous nearCorner = toFrustum(m, -2, -1, -1);
    EXPECT_NEAR(nearCorner.x, -1, 1e-6);
    EXPECT_NEAR(nearCorner.y, -1, 1e-6);
    EXPECT_NEAR(nearCorner.z, 0, 1e-6);
    const Homogeneous farCorner = toFrustum(m, 2, 1, -10);
    EXPECT_NEAR(farCorner.x, 1, 1e-6);
    EXPECT_NEAR(farCorner.y, 1, 1e-6);
    EXPECT_NEAR(farCorner.z, -1, 1e-6);
    EXPECT_NEAR(apply(m, 0.5, 0.5, -3).w, 1.0, 1e-7); // no perspective divide
    Q3Object_Dispose(camera);
}

TEST_F(CameraApiTest, ViewAngleFrustumSpansTheFieldOfViewAcrossTheNarrowerSide)
{
    // fov 90 degrees, aspect 2: vertical half-angle 45 degrees, horizontal
    // half-width twice the vertical at every depth.
    const TQ3ViewAngleAspectCameraData data = viewAngleData();
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&data);
    TQ3Matrix4x4 m = viewToFrustum(camera);
    const Homogeneous top = toFrustum(m, 0, 3, -3);
    EXPECT_NEAR(top.y, 1, 1e-6);
    const Homogeneous side = toFrustum(m, 6, 0, -3);
    EXPECT_NEAR(side.x, 1, 1e-6);
    EXPECT_NEAR(toFrustum(m, 0, 0, -1).z, 0, 1e-6);
    EXPECT_NEAR(toFrustum(m, 0, 0, -10).z, -1, 1e-6);
    EXPECT_NEAR(apply(m, 0, 0, -4).w, 4, 1e-6); // w is the distance in front of the eye
    // Aspect below 1: the angle spans the width instead.
    TQ3ViewAngleAspectCameraData tall = data;
    tall.aspectRatioXToY = 0.5f;
    Q3ViewAngleAspectCamera_SetData(camera, &tall);
    m = viewToFrustum(camera);
    EXPECT_NEAR(toFrustum(m, 3, 0, -3).x, 1, 1e-6);
    EXPECT_NEAR(toFrustum(m, 0, 6, -3).y, 1, 1e-6);
    Q3Object_Dispose(camera);
}

TEST_F(CameraApiTest, ViewPlaneFrustumMapsTheRectangleOnThePlane)
{
    // Rectangle centred at (1, -0.5) on the plane at distance 2, half sizes 1 and 0.5.
    TQ3ViewPlaneCameraData data = viewPlaneData();
    data.centerXOnViewPlane = 1;
    data.centerYOnViewPlane = -0.5f;
    TQ3CameraObject camera = Q3ViewPlaneCamera_New(&data);
    const TQ3Matrix4x4 m = viewToFrustum(camera);
    const Homogeneous low = toFrustum(m, 0, -1, -2);
    EXPECT_NEAR(low.x, -1, 1e-6);
    EXPECT_NEAR(low.y, -1, 1e-6);
    // The same corner ray, twice as far.
    const Homogeneous high = toFrustum(m, 4, 0, -4);
    EXPECT_NEAR(high.x, 1, 1e-6);
    EXPECT_NEAR(high.y, 1, 1e-6);
    EXPECT_NEAR(toFrustum(m, 1, -0.5, -2).x, 0, 1e-6);
    EXPECT_NEAR(toFrustum(m, 0, 0, -1).z, 0, 1e-6);
    EXPECT_NEAR(toFrustum(m, 0, 0, -10).z, -1, 1e-6);
    Q3Object_Dispose(camera);
}

TEST_F(CameraApiTest, TheViewPortSelectsPartOfTheViewPlane)
{
    // The top-right quarter: origin (0, 1), width 1, height 1.
    TQ3OrthographicCameraData data = orthographicData();
    data.cameraData.viewPort = {{0, 1}, 1, 1};
    TQ3CameraObject camera = Q3OrthographicCamera_New(&data);
    const TQ3Matrix4x4 m = viewToFrustum(camera);
    const Homogeneous centre = toFrustum(m, 1, 0.5, -2); // the quarter's centre
    EXPECT_NEAR(centre.x, 0, 1e-6);
    EXPECT_NEAR(centre.y, 0, 1e-6);
    const Homogeneous corner = toFrustum(m, 2, 1, -2); // the quarter's top-right corner
    EXPECT_NEAR(corner.x, 1, 1e-6);
    EXPECT_NEAR(corner.y, 1, 1e-6);
    const Homogeneous origin = toFrustum(m, 0, 0, -2);
    EXPECT_NEAR(origin.x, -1, 1e-6);
    EXPECT_NEAR(origin.y, -1, 1e-6);
    Q3Object_Dispose(camera);
}

TEST_F(CameraApiTest, WorldToFrustumIsWorldToViewThenViewToFrustum)
{
    TQ3ViewPlaneCameraData data = viewPlaneData();
    data.cameraData.placement = {{1, 2, 3}, {-1, 0, 0}, {0, 1, 0}};
    data.cameraData.viewPort = {{-0.5f, 0.8f}, 1.2f, 1.5f};
    TQ3CameraObject camera = Q3ViewPlaneCamera_New(&data);
    const TQ3Matrix4x4 a = worldToView(camera), b = viewToFrustum(camera);
    TQ3Matrix4x4 whole{};
    ASSERT_EQ(Q3Camera_GetWorldToFrustum(camera, &whole), kQ3Success);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double sum = 0;
            for (int k = 0; k < 4; ++k)
                sum += double(a.value[i][k]) * b.value[k][j];
            EXPECT_NEAR(whole.value[i][j], sum, 1e-5 * (1 + std::fabs(sum))) << i << ", " << j;
        }
    Q3Object_Dispose(camera);
}

TEST_F(CameraApiTest, DuplicateMakesAnIndependentCamera)
{
    const TQ3ViewAngleAspectCameraData data = viewAngleData();
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&data);
    TQ3CameraObject copy = Q3Object_Duplicate(camera);
    ASSERT_NE(copy, nullptr);
    EXPECT_NE(copy, camera);
    const TQ3CameraRange range = {3, 4};
    Q3Camera_SetRange(copy, &range);
    TQ3CameraRange original{};
    Q3Camera_GetRange(camera, &original);
    EXPECT_EQ(original.hither, data.cameraData.range.hither);
    TQ3ViewAngleAspectCameraData copied{};
    Q3ViewAngleAspectCamera_GetData(copy, &copied);
    EXPECT_EQ(copied.fov, data.fov);
    Q3Object_Dispose(copy);
    Q3Object_Dispose(camera);
}

} // namespace
