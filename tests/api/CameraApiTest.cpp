// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Cameras: data round trips, every TQ3CameraData rule, and the matrices with
// QuickDraw 3D's conventions (row vectors; view space looks down -z; frustum
// x, y in -1..1 across the view port, z from 0 at hither to -1 at yon). The
// expected values are worked out by hand in each test.

#include "RenderTestSupport.h"
#include "SetThenGet.h"

#include "QD3DCamera.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

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

// One camera of each kind, made from the data above, with that data; the
// test disposes of the cameras.
struct OneOfEachKind {
    TQ3OrthographicCameraData ortho = orthographicData();
    TQ3ViewPlaneCameraData plane = viewPlaneData();
    TQ3ViewAngleAspectCameraData angle = viewAngleData();
    TQ3CameraObject a = Q3OrthographicCamera_New(&ortho);
    TQ3CameraObject b = Q3ViewPlaneCamera_New(&plane);
    TQ3CameraObject c = Q3ViewAngleAspectCamera_New(&angle);
};

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

// One float of a kind's data, with the accessors that reach it alone.
template <class Data>
struct Field {
    const char* name;
    float Data::*member;
    TQ3Status (*set)(TQ3CameraObject, float);
    TQ3Status (*get)(TQ3CameraObject, float*);
    std::vector<float> rejected; // besides NaN and the infinities
    float accepted;              // a new value the rules allow
};

std::vector<Field<TQ3OrthographicCameraData>> orthographicFields()
{
    // orthographicData(): left -2, top 1, right 2, bottom -1.
    using D = TQ3OrthographicCameraData;
    return {
        {"left", &D::left, Q3OrthographicCamera_SetLeft, Q3OrthographicCamera_GetLeft, {2}, -3},
        {"top", &D::top, Q3OrthographicCamera_SetTop, Q3OrthographicCamera_GetTop, {-1}, 1.5f},
        {"right", &D::right, Q3OrthographicCamera_SetRight, Q3OrthographicCamera_GetRight, {-2}, -2.5f},
        {"bottom", &D::bottom, Q3OrthographicCamera_SetBottom, Q3OrthographicCamera_GetBottom, {1}, -0.5f},
    };
}

std::vector<Field<TQ3ViewPlaneCameraData>> viewPlaneFields()
{
    using D = TQ3ViewPlaneCameraData;
    return {
        {"viewPlane", &D::viewPlane, Q3ViewPlaneCamera_SetViewPlane, Q3ViewPlaneCamera_GetViewPlane,
         {0, -0.0f, -1}, 3},
        {"halfWidthAtViewPlane", &D::halfWidthAtViewPlane, Q3ViewPlaneCamera_SetHalfWidth,
         Q3ViewPlaneCamera_GetHalfWidth, {0, -2}, 1.5f},
        {"halfHeightAtViewPlane", &D::halfHeightAtViewPlane, Q3ViewPlaneCamera_SetHalfHeight,
         Q3ViewPlaneCamera_GetHalfHeight, {0, -0.5f}, 0.75f},
        {"centerXOnViewPlane", &D::centerXOnViewPlane, Q3ViewPlaneCamera_SetCenterX,
         Q3ViewPlaneCamera_GetCenterX, {}, -1},
        {"centerYOnViewPlane", &D::centerYOnViewPlane, Q3ViewPlaneCamera_SetCenterY,
         Q3ViewPlaneCamera_GetCenterY, {}, 0.25f},
    };
}

std::vector<Field<TQ3ViewAngleAspectCameraData>> viewAngleFields()
{
    using D = TQ3ViewAngleAspectCameraData;
    return {
        {"fov", &D::fov, Q3ViewAngleAspectCamera_SetFOV, Q3ViewAngleAspectCamera_GetFOV,
         {0, -0.5f, float(kPi), 4}, 1},
        {"aspectRatioXToY", &D::aspectRatioXToY, Q3ViewAngleAspectCamera_SetAspectRatio,
         Q3ViewAngleAspectCamera_GetAspectRatio, {0, -1}, 0.5f},
    };
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

    // For each field: every value SetData rejects (with only that field
    // changed) the single-field setter rejects with the same error, leaving
    // the data and the edit index alone; an allowed value changes that field
    // only and bumps the edit index; the getter reads it back.
    template <class Data>
    void checkFields(const Data& good, TQ3CameraObject (*make)(const Data*),
                     TQ3Status (*getData)(TQ3CameraObject, Data*),
                     TQ3Status (*setData)(TQ3CameraObject, const Data*),
                     const std::vector<Field<Data>>& fields)
    {
        for (const Field<Data>& field : fields) {
            SCOPED_TRACE(field.name);
            TQ3CameraObject camera = make(&good);
            ASSERT_NE(camera, nullptr);
            const unsigned long edit = Q3Shared_GetEditIndex(camera);
            std::vector<float> bad = {kNaN, kInf, -kInf};
            bad.insert(bad.end(), field.rejected.begin(), field.rejected.end());
            for (float value : bad) {
                SCOPED_TRACE(std::to_string(value));
                Data viaSetData = good;
                viaSetData.*field.member = value;
                EXPECT_Q3_ERROR(EXPECT_EQ(setData(camera, &viaSetData), kQ3Failure),
                                kQ3ErrorInvalidCameraValues);
                EXPECT_Q3_ERROR(EXPECT_EQ(field.set(camera, value), kQ3Failure),
                                kQ3ErrorInvalidCameraValues);
            }
            Data after{};
            EXPECT_EQ(getData(camera, &after), kQ3Success);
            EXPECT_EQ(std::memcmp(&after, &good, sizeof after), 0);
            EXPECT_EQ(Q3Shared_GetEditIndex(camera), edit);
            float out = 0;
            EXPECT_EQ(field.get(camera, &out), kQ3Success);
            EXPECT_EQ(out, good.*field.member);

            EXPECT_EQ(field.set(camera, field.accepted), kQ3Success);
            EXPECT_NE(Q3Shared_GetEditIndex(camera), edit);
            EXPECT_EQ(field.get(camera, &out), kQ3Success);
            EXPECT_EQ(out, field.accepted);
            Data expected = good;
            expected.*field.member = field.accepted;
            EXPECT_EQ(getData(camera, &after), kQ3Success);
            EXPECT_EQ(std::memcmp(&after, &expected, sizeof after), 0);
            Q3Object_Dispose(camera);
        }
    }
};

TEST_F(CameraApiTest, EachKindIsCreatedAndReadBack)
{
    const auto [ortho, plane, angle, a, b, c] = OneOfEachKind();
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
    q3test::expectSetThenGet(camera, Q3Camera_SetData, Q3Camera_GetData, data);

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
    const OneOfEachKind kinds;
    const auto& [ortho, plane, angle, a, b, c] = kinds;
    forEachNonFiniteField<TQ3OrthographicCameraData>(ortho, [&](const TQ3OrthographicCameraData& d, const std::string& what) {
        SCOPED_TRACE(what);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3OrthographicCamera_New(&d), nullptr), kQ3ErrorInvalidCameraValues);
        EXPECT_Q3_ERROR(Q3OrthographicCamera_SetData(kinds.a, &d), kQ3ErrorInvalidCameraValues);
    });
    forEachNonFiniteField<TQ3ViewPlaneCameraData>(plane, [&](const TQ3ViewPlaneCameraData& d, const std::string& what) {
        SCOPED_TRACE(what);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3ViewPlaneCamera_New(&d), nullptr), kQ3ErrorInvalidCameraValues);
        EXPECT_Q3_ERROR(Q3ViewPlaneCamera_SetData(kinds.b, &d), kQ3ErrorInvalidCameraValues);
    });
    forEachNonFiniteField<TQ3ViewAngleAspectCameraData>(
        angle, [&](const TQ3ViewAngleAspectCameraData& d, const std::string& what) {
            SCOPED_TRACE(what);
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3ViewAngleAspectCamera_New(&d), nullptr), kQ3ErrorInvalidCameraValues);
            EXPECT_Q3_ERROR(Q3ViewAngleAspectCamera_SetData(kinds.c, &d), kQ3ErrorInvalidCameraValues);
        });
    forEachNonFiniteField<TQ3CameraData>(commonData(), [&](const TQ3CameraData& d, const std::string& what) {
        SCOPED_TRACE(what);
        EXPECT_Q3_ERROR(Q3Camera_SetData(kinds.c, &d), kQ3ErrorInvalidCameraValues);
    });
    forEachNonFiniteField<TQ3CameraPlacement>(commonData().placement,
                                              [&](const TQ3CameraPlacement& d, const std::string& what) {
                                                  SCOPED_TRACE(what);
                                                  EXPECT_Q3_ERROR(Q3Camera_SetPlacement(kinds.a, &d),
                                                                  kQ3ErrorInvalidCameraValues);
                                              });
    forEachNonFiniteField<TQ3CameraRange>(commonData().range, [&](const TQ3CameraRange& d, const std::string& what) {
        SCOPED_TRACE(what);
        EXPECT_Q3_ERROR(Q3Camera_SetRange(kinds.a, &d), kQ3ErrorInvalidCameraValues);
    });
    forEachNonFiniteField<TQ3CameraViewPort>(commonData().viewPort,
                                             [&](const TQ3CameraViewPort& d, const std::string& what) {
                                                 SCOPED_TRACE(what);
                                                 EXPECT_Q3_ERROR(Q3Camera_SetViewPort(kinds.b, &d),
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
    const auto [ortho, plane, angle, a, b, c] = OneOfEachKind();
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

// ---- Single-field accessors ---------------------------------------------------

TEST_F(CameraApiTest, OrthographicFieldSettersCheckWhatSetDataChecks)
{
    checkFields(orthographicData(), Q3OrthographicCamera_New, Q3OrthographicCamera_GetData,
                Q3OrthographicCamera_SetData, orthographicFields());
}

TEST_F(CameraApiTest, ViewPlaneFieldSettersCheckWhatSetDataChecks)
{
    checkFields(viewPlaneData(), Q3ViewPlaneCamera_New, Q3ViewPlaneCamera_GetData,
                Q3ViewPlaneCamera_SetData, viewPlaneFields());
}

TEST_F(CameraApiTest, ViewAngleAspectFieldSettersCheckWhatSetDataChecks)
{
    checkFields(viewAngleData(), Q3ViewAngleAspectCamera_New, Q3ViewAngleAspectCamera_GetData,
                Q3ViewAngleAspectCamera_SetData, viewAngleFields());
}

TEST_F(CameraApiTest, FieldAccessorsRejectBadHandlesOtherKindsAndNullPointers)
{
    const auto [ortho, plane, angle, a, b, c] = OneOfEachKind();
    TQ3CameraObject dead = Q3OrthographicCamera_New(&ortho);
    Q3Object_Dispose(dead);
    const TQ3Vector3D offset{1, 2, 3};
    TQ3TransformObject transform = Q3TranslateTransform_New(&offset);
    struct Family {
        TQ3CameraObject right, otherKind;
        std::vector<std::pair<TQ3Status (*)(TQ3CameraObject, float), TQ3Status (*)(TQ3CameraObject, float*)>>
            accessors;
    };
    std::vector<Family> kinds(3);
    kinds[0] = {a, c, {}};
    for (const auto& f : orthographicFields())
        kinds[0].accessors.push_back({f.set, f.get});
    kinds[1] = {b, a, {}};
    for (const auto& f : viewPlaneFields())
        kinds[1].accessors.push_back({f.set, f.get});
    kinds[2] = {c, b, {}};
    for (const auto& f : viewAngleFields())
        kinds[2].accessors.push_back({f.set, f.get});
    for (std::size_t k = 0; k < kinds.size(); ++k) {
        const TQ3CameraObject right = kinds[k].right;
        TQ3ViewAngleAspectCameraData angleBefore{};
        Q3ViewAngleAspectCamera_GetData(c, &angleBefore);
        const unsigned long edit = Q3Shared_GetEditIndex(right);
        for (std::size_t i = 0; i < kinds[k].accessors.size(); ++i) {
            SCOPED_TRACE("kind " + std::to_string(k) + " accessor " + std::to_string(i));
            const auto set = kinds[k].accessors[i].first;
            const auto get = kinds[k].accessors[i].second;
            float out = 42;
            for (TQ3Object wrong : {static_cast<TQ3Object>(kinds[k].otherKind), transform}) {
                EXPECT_Q3_ERROR(EXPECT_EQ(set(wrong, 0.5f), kQ3Failure), kQ3ErrorInvalidObjectType);
                EXPECT_Q3_ERROR(EXPECT_EQ(get(wrong, &out), kQ3Failure), kQ3ErrorInvalidObjectType);
            }
            EXPECT_Q3_ERROR(EXPECT_EQ(set(nullptr, 0.5f), kQ3Failure), kQ3ErrorNULLParameter);
            EXPECT_Q3_ERROR(EXPECT_EQ(get(nullptr, &out), kQ3Failure), kQ3ErrorNULLParameter);
            EXPECT_Q3_ERROR(EXPECT_EQ(set(dead, 0.5f), kQ3Failure), kQ3ErrorInvalidObject);
            EXPECT_Q3_ERROR(EXPECT_EQ(get(dead, &out), kQ3Failure), kQ3ErrorInvalidObject);
            EXPECT_Q3_ERROR(EXPECT_EQ(get(right, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
            EXPECT_EQ(out, 42.0f);
        }
        EXPECT_EQ(Q3Shared_GetEditIndex(right), edit);
        // A setter handed another kind of camera left that camera alone too.
        TQ3ViewAngleAspectCameraData angleAfter{};
        Q3ViewAngleAspectCamera_GetData(c, &angleAfter);
        EXPECT_EQ(std::memcmp(&angleAfter, &angleBefore, sizeof angleAfter), 0);
    }
    for (TQ3Object object : {a, b, c, transform})
        Q3Object_Dispose(object);
}

// ---- Single-field setters take effect ------------------------------------------

TEST_F(CameraApiTest, OrthographicBoundSettersMoveTheFrustum)
{
    const TQ3OrthographicCameraData data = orthographicData(); // x -2..2, y -1..1
    TQ3CameraObject camera = Q3OrthographicCamera_New(&data);
    ASSERT_EQ(Q3OrthographicCamera_SetLeft(camera, -6), kQ3Success);
    ASSERT_EQ(Q3OrthographicCamera_SetTop(camera, 3), kQ3Success);
    const TQ3Matrix4x4 m = viewToFrustum(camera);
    const Homogeneous topLeft = toFrustum(m, -6, 3, -2);
    EXPECT_NEAR(topLeft.x, -1, 1e-6);
    EXPECT_NEAR(topLeft.y, 1, 1e-6);
    const Homogeneous bottomRight = toFrustum(m, 2, -1, -2);
    EXPECT_NEAR(bottomRight.x, 1, 1e-6);
    EXPECT_NEAR(bottomRight.y, -1, 1e-6);
    ASSERT_EQ(Q3OrthographicCamera_SetRight(camera, 10), kQ3Success);
    ASSERT_EQ(Q3OrthographicCamera_SetBottom(camera, -5), kQ3Success);
    const Homogeneous centre = toFrustum(viewToFrustum(camera), 2, -1, -2);
    EXPECT_NEAR(centre.x, 0, 1e-6);
    EXPECT_NEAR(centre.y, 0, 1e-6);
    Q3Object_Dispose(camera);
}

TEST_F(CameraApiTest, ViewPlaneSettersMoveTheFrustum)
{
    const TQ3ViewPlaneCameraData data = viewPlaneData(); // plane 2, half sizes 1 x 0.5, centred
    TQ3CameraObject camera = Q3ViewPlaneCamera_New(&data);
    // Plane at 4 with half sizes 2 x 1, centred at (1, -0.5): the rectangle
    // spans x -1..3 and y -1.5..0.5 on the plane z = -4.
    ASSERT_EQ(Q3ViewPlaneCamera_SetViewPlane(camera, 4), kQ3Success);
    ASSERT_EQ(Q3ViewPlaneCamera_SetHalfWidth(camera, 2), kQ3Success);
    ASSERT_EQ(Q3ViewPlaneCamera_SetHalfHeight(camera, 1), kQ3Success);
    ASSERT_EQ(Q3ViewPlaneCamera_SetCenterX(camera, 1), kQ3Success);
    ASSERT_EQ(Q3ViewPlaneCamera_SetCenterY(camera, -0.5f), kQ3Success);
    const TQ3Matrix4x4 m = viewToFrustum(camera);
    const Homogeneous low = toFrustum(m, -1, -1.5, -4);
    EXPECT_NEAR(low.x, -1, 1e-6);
    EXPECT_NEAR(low.y, -1, 1e-6);
    const Homogeneous high = toFrustum(m, 6, 1, -8); // the other corner's ray, twice as far
    EXPECT_NEAR(high.x, 1, 1e-6);
    EXPECT_NEAR(high.y, 1, 1e-6);
    EXPECT_NEAR(toFrustum(m, 1, -0.5, -4).x, 0, 1e-6);
    Q3Object_Dispose(camera);
}

TEST_F(CameraApiTest, SetFOVAndSetAspectRatioChangeWhatTheCameraSees)
{
    const TQ3ViewAngleAspectCameraData data = viewAngleData(); // fov 90 degrees, aspect 2
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&data);
    TQ3Matrix4x4 before{};
    ASSERT_EQ(Q3Camera_GetWorldToFrustum(camera, &before), kQ3Success);
    // 60 degrees across y: at depth 3 the top edge is 3 tan(30 degrees) up.
    ASSERT_EQ(Q3ViewAngleAspectCamera_SetFOV(camera, float(kPi / 3)), kQ3Success);
    const double top = 3 * std::tan(double(float(kPi / 3)) / 2);
    TQ3Matrix4x4 m = viewToFrustum(camera);
    EXPECT_NEAR(toFrustum(m, 0, top, -3).y, 1, 1e-6);
    EXPECT_NEAR(toFrustum(m, 2 * top, 0, -3).x, 1, 1e-6);
    TQ3Matrix4x4 after{};
    ASSERT_EQ(Q3Camera_GetWorldToFrustum(camera, &after), kQ3Success);
    EXPECT_NE(std::memcmp(&after, &before, sizeof after), 0);
    // Aspect 4: the same height, twice the width.
    ASSERT_EQ(Q3ViewAngleAspectCamera_SetAspectRatio(camera, 4), kQ3Success);
    m = viewToFrustum(camera);
    EXPECT_NEAR(toFrustum(m, 0, top, -3).y, 1, 1e-6);
    EXPECT_NEAR(toFrustum(m, 4 * top, 0, -3).x, 1, 1e-6);
    Q3Object_Dispose(camera);
}

TEST_F(CameraApiTest, ARetainedCurveIsSubdividedAgainWhenTheFOVChanges)
{
    // Listing 1 seen from 6 units away with a view angle camera; screen-space
    // subdivision at 2 pixels, so the polyline's size follows the curve's
    // length in pixels. Halving the field of view roughly doubles it
    // (tan 0.5 / tan 0.25 = 2.14).
    q3test::Pixmap image{200, 150};
    const q3test::Point3 eye = {1.5, 0.5, 6}, target = {1.5, 0.5, 0}, up = {0, 1, 0};
    const TQ3ViewAngleAspectCameraData data = q3test::viewAngleCamera(eye, target, up, 1.0, 200.0 / 150.0);
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&data);
    q3test::TestView view(image.pixmap(), kQ3RendererTypeInteractive, camera);
    q3test::Listing1 listing;
    const TQ3NURBCurveData curveData = listing.data();
    TQ3GeometryObject curve = Q3NURBCurve_New(&curveData);
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodScreenSpace, 2, 2};
    auto vertexCount = [&]() -> unsigned long {
        TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(curve, view.view());
        TQ3PolyLineData out{};
        if (polyLine == nullptr || Q3PolyLine_GetData(polyLine, &out) != kQ3Success) {
            ADD_FAILURE() << "no polyline";
            if (polyLine != nullptr)
                Q3Object_Dispose(polyLine);
            return 0;
        }
        const unsigned long count = out.numVertices;
        Q3PolyLine_EmptyData(&out);
        Q3Object_Dispose(polyLine);
        return count;
    };
    auto inALoop = [&](const std::function<void()>& body) {
        TQ3BoundingBox box{};
        ASSERT_EQ(Q3View_StartBoundingBox(view.view(), kQ3ComputeBoundsExact), kQ3Success);
        Q3SubdivisionStyle_Submit(&style, view.view());
        body();
        EXPECT_EQ(Q3View_EndBoundingBox(view.view(), &box), kQ3ViewStatusDone);
    };
    unsigned long wide = 0, narrow = 0, again = 0;
    inALoop([&] { wide = vertexCount(); });
    ASSERT_EQ(Q3ViewAngleAspectCamera_SetFOV(camera, 0.5f), kQ3Success);
    inALoop([&] { narrow = vertexCount(); });
    EXPECT_GT(narrow, wide * 3 / 2);
    EXPECT_LT(narrow, wide * 3);
    // A loop keeps the camera it started with: a change in the middle of it
    // shows in the next loop, not in this one.
    inALoop([&] {
        EXPECT_EQ(Q3ViewAngleAspectCamera_SetFOV(camera, 1.0f), kQ3Success);
        again = vertexCount();
    });
    EXPECT_EQ(again, narrow);
    inALoop([&] { again = vertexCount(); });
    EXPECT_EQ(again, wide);
    Q3Object_Dispose(curve);
    Q3Object_Dispose(camera);
}

TEST(CameraApiUninitialized, FieldAccessorsFailWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    float out = 0;
    std::vector<std::pair<TQ3Status (*)(TQ3CameraObject, float), TQ3Status (*)(TQ3CameraObject, float*)>>
        accessors;
    for (const auto& f : orthographicFields())
        accessors.push_back({f.set, f.get});
    for (const auto& f : viewPlaneFields())
        accessors.push_back({f.set, f.get});
    for (const auto& f : viewAngleFields())
        accessors.push_back({f.set, f.get});
    ASSERT_EQ(accessors.size(), 11u);
    for (std::size_t i = 0; i < accessors.size(); ++i) {
        EXPECT_EQ(accessors[i].first(nullptr, 1.0f), kQ3Failure) << i;
        EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized) << i;
        EXPECT_EQ(accessors[i].second(nullptr, &out), kQ3Failure) << i;
        EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized) << i;
    }
}

} // namespace
