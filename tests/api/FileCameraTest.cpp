// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Cameras in 3DMF files: the three kinds written and read back in every
// encoding and mode, compared field by field; files written by hand (text,
// big- and little-endian binary); the reference's defaults for a camera
// without subobjects; malformed cameras as errors; and a writing loop that
// writes what is submitted, not the view's camera.

#include "FileTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DCamera.h"
#include "QD3DGeometry.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

using namespace q3test;

namespace {

class FileCameraTest : public Q3ApiTest {};

const TQ3FileMode kModes[] = {kQ3FileModeNormal, kQ3FileModeText, kQ3FileModeStream | kQ3FileModeText,
                              kQ3FileModeDatabase, kQ3FileModeStream};

std::vector<unsigned char> dataFile(const char* name)
{
    std::ifstream in(std::string(Q3_TEST_DATA_DIR) + "/" + name, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Values no default or neighbour shares, so a field read into the wrong
// place shows.
TQ3CameraData commonData()
{
    TQ3CameraData data;
    data.placement = {{1.5f, -2.25f, 7}, {0.125f, 0.5f, -1}, {0.25f, 1, 0.0625f}};
    data.range = {0.75f, 123.5f};
    data.viewPort = {{-0.75f, 0.5f}, 1.25f, 1.375f};
    return data;
}

TQ3OrthographicCameraData orthographicData()
{
    TQ3OrthographicCameraData data;
    data.cameraData = commonData();
    data.left = -3.5f;
    data.top = 2.25f;
    data.right = 4.75f;
    data.bottom = -1.125f;
    return data;
}

TQ3ViewPlaneCameraData viewPlaneData()
{
    TQ3ViewPlaneCameraData data;
    data.cameraData = commonData();
    data.viewPlane = 6.5f;
    data.halfWidthAtViewPlane = 2.75f;
    data.halfHeightAtViewPlane = 1.625f;
    data.centerXOnViewPlane = -0.375f;
    data.centerYOnViewPlane = 0.8125f;
    return data;
}

TQ3ViewAngleAspectCameraData viewAngleData()
{
    TQ3ViewAngleAspectCameraData data;
    data.cameraData = commonData();
    data.fov = 0.9f;
    data.aspectRatioXToY = 1.7f;
    return data;
}

bool sameCommon(const TQ3CameraData& a, const TQ3CameraData& b)
{
    return samePoint(a.placement.cameraLocation, b.placement.cameraLocation) &&
           samePoint(a.placement.pointOfInterest, b.placement.pointOfInterest) &&
           a.placement.upVector.x == b.placement.upVector.x && a.placement.upVector.y == b.placement.upVector.y &&
           a.placement.upVector.z == b.placement.upVector.z && a.range.hither == b.range.hither &&
           a.range.yon == b.range.yon && a.viewPort.origin.x == b.viewPort.origin.x &&
           a.viewPort.origin.y == b.viewPort.origin.y && a.viewPort.width == b.viewPort.width &&
           a.viewPort.height == b.viewPort.height;
}

// Checks that `camera` is a shared shape object, a camera of `type`, and
// reads its data into `got` with `get`, checking the fields every camera has.
template <class Data>
void expectCameraOfType(TQ3Object camera, TQ3ObjectType type, TQ3Status (*get)(TQ3CameraObject, Data*),
                        const Data& expected, Data& got)
{
    ASSERT_NE(camera, nullptr);
    EXPECT_EQ(Q3Object_IsType(camera, kQ3ShapeTypeCamera), kQ3True);
    EXPECT_EQ(Q3Object_GetType(camera), kQ3ObjectTypeShared);
    EXPECT_EQ(Q3Shared_GetType(camera), kQ3SharedTypeShape);
    EXPECT_EQ(Q3Shape_GetType(camera), kQ3ShapeTypeCamera);
    EXPECT_EQ(Q3Object_GetLeafType(camera), type);
    EXPECT_EQ(Q3Camera_GetType(camera), type);
    ASSERT_EQ(get(camera, &got), kQ3Success);
    EXPECT_TRUE(sameCommon(got.cameraData, expected.cameraData));
}

void expectOrthographic(TQ3Object camera, const TQ3OrthographicCameraData& expected)
{
    TQ3OrthographicCameraData got{};
    expectCameraOfType(camera, kQ3CameraTypeOrthographic, Q3OrthographicCamera_GetData, expected, got);
    if (::testing::Test::HasFatalFailure())
        return;
    EXPECT_EQ(got.left, expected.left);
    EXPECT_EQ(got.top, expected.top);
    EXPECT_EQ(got.right, expected.right);
    EXPECT_EQ(got.bottom, expected.bottom);
}

void expectViewPlane(TQ3Object camera, const TQ3ViewPlaneCameraData& expected)
{
    TQ3ViewPlaneCameraData got{};
    expectCameraOfType(camera, kQ3CameraTypeViewPlane, Q3ViewPlaneCamera_GetData, expected, got);
    if (::testing::Test::HasFatalFailure())
        return;
    EXPECT_EQ(got.viewPlane, expected.viewPlane);
    EXPECT_EQ(got.halfWidthAtViewPlane, expected.halfWidthAtViewPlane);
    EXPECT_EQ(got.halfHeightAtViewPlane, expected.halfHeightAtViewPlane);
    EXPECT_EQ(got.centerXOnViewPlane, expected.centerXOnViewPlane);
    EXPECT_EQ(got.centerYOnViewPlane, expected.centerYOnViewPlane);
}

void expectViewAngle(TQ3Object camera, const TQ3ViewAngleAspectCameraData& expected)
{
    TQ3ViewAngleAspectCameraData got{};
    expectCameraOfType(camera, kQ3CameraTypeViewAngleAspect, Q3ViewAngleAspectCamera_GetData, expected, got);
    if (::testing::Test::HasFatalFailure())
        return;
    EXPECT_EQ(got.fov, expected.fov);
    EXPECT_EQ(got.aspectRatioXToY, expected.aspectRatioXToY);
}

TQ3CameraData handCommon(TQ3Point3D location, TQ3Point3D target, TQ3Vector3D up, float hither, float yon,
                         TQ3CameraViewPort viewPort)
{
    TQ3CameraData data;
    data.placement = {location, target, up};
    data.range = {hither, yon};
    data.viewPort = viewPort;
    return data;
}

// What cameras.3dmf and its binary twins (make_camera_binary.py) hold.
void expectHandWrittenCameras(const std::vector<TQ3Object>& objects)
{
    ASSERT_EQ(objects.size(), 4u);
    TQ3ViewAngleAspectCameraData first;
    first.cameraData = handCommon({2, 3, 10}, {0, 0.5f, 0}, {0, 1, 0}, 0.5f, 50, {{-1, 1}, 2, 2});
    first.fov = 0.5235988f;
    first.aspectRatioXToY = 1.5f;
    expectViewAngle(objects[0], first);
    TQ3OrthographicCameraData second;
    second.cameraData = handCommon({0, 0, 8}, {0, 0, 0}, {0, 1, 0}, 0, 20, {{-0.5f, 0.5f}, 1, 1});
    second.left = -4;
    second.top = 3;
    second.right = 4;
    second.bottom = -3;
    expectOrthographic(objects[1], second);
    TQ3ViewPlaneCameraData third;
    third.cameraData = handCommon({0, 5, 5}, {0, 0, 0}, {0, 0, -1}, 1, 100, {{-1, 1}, 2, 2});
    third.viewPlane = 5;
    third.halfWidthAtViewPlane = 2;
    third.halfHeightAtViewPlane = 1.5f;
    third.centerXOnViewPlane = 0.25f;
    third.centerYOnViewPlane = -0.5f;
    expectViewPlane(objects[2], third);
    // Without subobjects: the reference's placement and view port, and
    // Q3's finite stand-in for its "epsilon to infinity" range.
    TQ3ViewAngleAspectCameraData fourth;
    fourth.cameraData = handCommon({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 0.001f, 1000000.0f, {{-1, 1}, 2, 2});
    fourth.fov = 1;
    fourth.aspectRatioXToY = 1;
    expectViewAngle(objects[3], fourth);
}

std::string textFile(const std::string& body)
{
    return "3DMetafile ( 1 6 Normal )\n" + body + "\n";
}

void putObject(std::vector<unsigned char>& out, const char* tag, const std::vector<unsigned char>& data)
{
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<unsigned char>(tag[i]));
    put32(out, static_cast<std::uint32_t>(data.size()));
    out.insert(out.end(), data.begin(), data.end());
}

std::vector<unsigned char> floatData(std::initializer_list<float> values)
{
    std::vector<unsigned char> out;
    for (float v : values)
        putFloat(out, v);
    return out;
}

std::vector<unsigned char> binaryFile(const std::vector<unsigned char>& objects)
{
    std::vector<unsigned char> out = binaryHeader();
    out.insert(out.end(), objects.begin(), objects.end());
    return out;
}

} // namespace

TEST_F(FileCameraTest, EveryKindReadsBackFieldByFieldInEveryMode)
{
    const TQ3OrthographicCameraData orthographic = orthographicData();
    const TQ3ViewPlaneCameraData viewPlane = viewPlaneData();
    const TQ3ViewAngleAspectCameraData viewAngle = viewAngleData();
    TQ3CameraObject cameras[3] = {Q3OrthographicCamera_New(&orthographic), Q3ViewPlaneCamera_New(&viewPlane),
                                  Q3ViewAngleAspectCamera_New(&viewAngle)};
    for (TQ3FileMode mode : kModes) {
        SCOPED_TRACE(mode);
        const auto objects = readAll(writeObjects({cameras[0], cameras[1], cameras[2]}, mode));
        ASSERT_EQ(objects.size(), 3u);
        expectOrthographic(objects[0], orthographic);
        expectViewPlane(objects[1], viewPlane);
        expectViewAngle(objects[2], viewAngle);
        disposeAll(objects);
    }
    for (TQ3CameraObject camera : cameras)
        Q3Object_Dispose(camera);
}

TEST_F(FileCameraTest, TextFilesLayTheSubobjectsOutAsTheReferenceNamesThem)
{
    const TQ3ViewAngleAspectCameraData viewAngle = viewAngleData();
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&viewAngle);
    const auto bytes = writeObjects({camera}, kQ3FileModeText);
    const std::string text(bytes.begin(), bytes.end());
    const std::size_t own = text.find("ViewAngleAspectCamera");
    const std::size_t placement = text.find("CameraPlacement");
    const std::size_t range = text.find("CameraRange");
    const std::size_t viewPort = text.find("CameraViewPort");
    ASSERT_NE(own, std::string::npos);
    EXPECT_LT(text.find("Container"), own);
    EXPECT_LT(own, placement);
    EXPECT_LT(placement, range);
    EXPECT_LT(range, viewPort);
    EXPECT_NE(viewPort, std::string::npos);
    Q3Object_Dispose(camera);
}

TEST_F(FileCameraTest, BinaryCamerasUseApplesTags)
{
    const TQ3OrthographicCameraData orthographic = orthographicData();
    TQ3CameraObject camera = Q3OrthographicCamera_New(&orthographic);
    const auto bytes = writeObjects({camera}, kQ3FileModeNormal);
    const std::string data(bytes.begin(), bytes.end());
    // cntr, then orth with 16 bytes, cmpl 36, cmrg 8, cmvp 16.
    EXPECT_NE(data.find(std::string("orth\0\0\0\x10", 8)), std::string::npos);
    EXPECT_NE(data.find(std::string("cmpl\0\0\0\x24", 8)), std::string::npos);
    EXPECT_NE(data.find(std::string("cmrg\0\0\0\x08", 8)), std::string::npos);
    EXPECT_NE(data.find(std::string("cmvp\0\0\0\x10", 8)), std::string::npos);
    Q3Object_Dispose(camera);
}

TEST_F(FileCameraTest, HandWrittenFilesReadInTextAndBothByteOrders)
{
    for (const char* name : {"cameras.3dmf", "cameras_be.3dmf", "cameras_le.3dmf"}) {
        SCOPED_TRACE(name);
        const auto bytes = dataFile(name);
        ASSERT_FALSE(bytes.empty());
        const auto objects = readAll(bytes);
        expectHandWrittenCameras(objects);
        disposeAll(objects);
    }
}

TEST_F(FileCameraTest, CamerasTheApiWouldRefuseAreMetafileErrors)
{
    // Zero field of view, hither >= yon, a zero view port, no viewing
    // direction, an up vector along it, an empty rectangle, a view plane
    // behind the eye: each breaks the camera's rules.
    const char* bodies[] = {
        "ViewAngleAspectCamera ( 0 1.5 )",
        "ViewAngleAspectCamera ( 3.2 1.5 )",
        "ViewAngleAspectCamera ( 0.5 0 )",
        "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraRange ( 10 5 ) )",
        "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraRange ( 5 5 ) )",
        "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraRange ( 0 5 ) )",
        "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraViewPort ( -1 1 0 2 ) )",
        "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraViewPort ( -1 1 2 -2 ) )",
        "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraPlacement ( 1 2 3  1 2 3  0 1 0 ) )",
        "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraPlacement ( 0 0 5  0 0 0  0 0 1 ) )",
        "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraPlacement ( 0 0 5  0 0 0  0 0 0 ) )",
        "OrthographicCamera ( 1 1 1 -1 )",
        "OrthographicCamera ( -1 1 1 1 )",
        "ViewPlaneCamera ( 0 1 1 0 0 )",
        "ViewPlaneCamera ( 5 0 1 0 0 )",
    };
    for (const char* body : bodies) {
        SCOPED_TRACE(body);
        EXPECT_READ_ERROR(bytesOf(textFile(body)), kQ3ErrorInvalidMetafileObject);
    }
}

TEST_F(FileCameraTest, MalformedCameraDataAreErrors)
{
    // Too few fields, a field that is not a number, a non-finite number.
    for (const char* body : {"OrthographicCamera ( -4 3 4 )", "ViewPlaneCamera ( 5 2 1.5 0.25 )",
                             "ViewAngleAspectCamera ( 0.5 )", "ViewAngleAspectCamera ( nan 1 )",
                             "ViewAngleAspectCamera ( 0.5 inf )",
                             "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraRange ( 1 ) )",
                             "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraViewPort ( -1 1 2 ) )",
                             "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraPlacement ( 0 0 5 0 0 0 0 1 ) )",
                             "Container ( OrthographicCamera ( -4 3 4 -3 ) CameraRange ( 0 x ) )"}) {
        SCOPED_TRACE(body);
        EXPECT_READ_ERROR(bytesOf(textFile(body)), kQ3ErrorInvalidMetafilePrimitive);
    }
    // Data left over after the fields, and the camera's parts on their own.
    for (const char* body : {"OrthographicCamera ( -4 3 4 -3 1 )", "ViewAngleAspectCamera ( 0.5 1 1 )",
                             "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraRange ( 1 5 9 ) )",
                             "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraViewPort ( -1 1 2 2 2 ) )",
                             "CameraPlacement ( 0 0 5  0 0 0  0 1 0 )", "CameraRange ( 1 5 )",
                             "CameraViewPort ( -1 1 2 2 )"}) {
        SCOPED_TRACE(body);
        EXPECT_READ_ERROR(bytesOf(textFile(body)), kQ3ErrorInvalidMetafileObject);
    }
}

TEST_F(FileCameraTest, MalformedBinaryCamerasAreErrors)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // A well-formed camera reads, so each variant below fails for its flaw.
    std::vector<unsigned char> good;
    {
        std::vector<unsigned char> container;
        putObject(container, "vana", floatData({0.5f, 1}));
        putObject(container, "cmrg", floatData({1, 10}));
        putObject(good, "cntr", container);
    }
    const auto goodObjects = readAll(binaryFile(good));
    ASSERT_EQ(goodObjects.size(), 1u);
    disposeAll(goodObjects);

    std::vector<unsigned char> truncated; // a size of 12 for four fields
    putObject(truncated, "orth", floatData({-4, 3, 4}));
    EXPECT_READ_ERROR(binaryFile(truncated), kQ3ErrorInvalidMetafilePrimitive);

    std::vector<unsigned char> notFinite;
    putObject(notFinite, "vana", floatData({nan, 1}));
    EXPECT_READ_ERROR(binaryFile(notFinite), kQ3ErrorInvalidMetafilePrimitive);

    std::vector<unsigned char> shortRange;
    {
        std::vector<unsigned char> container;
        putObject(container, "vana", floatData({0.5f, 1}));
        putObject(container, "cmrg", floatData({1}));
        putObject(shortRange, "cntr", container);
    }
    EXPECT_READ_ERROR(binaryFile(shortRange), kQ3ErrorInvalidMetafilePrimitive);

    std::vector<unsigned char> longViewPort;
    {
        std::vector<unsigned char> container;
        putObject(container, "vana", floatData({0.5f, 1}));
        putObject(container, "cmvp", floatData({-1, 1, 2, 2, 0}));
        putObject(longViewPort, "cntr", container);
    }
    EXPECT_READ_ERROR(binaryFile(longViewPort), kQ3ErrorInvalidMetafileObject);

    std::vector<unsigned char> zeroFov;
    putObject(zeroFov, "vana", floatData({0, 1}));
    EXPECT_READ_ERROR(binaryFile(zeroFov), kQ3ErrorInvalidMetafileObject);

    // A size running past the end of the file.
    std::vector<unsigned char> overrun;
    overrun.insert(overrun.end(), {'v', 'w', 'p', 'l'});
    put32(overrun, 400);
    const auto five = floatData({5, 2, 1.5f, 0, 0});
    overrun.insert(overrun.end(), five.begin(), five.end());
    EXPECT_READ_ERROR(binaryFile(overrun), kQ3ErrorInvalidMetafile);
}

TEST_F(FileCameraTest, AReferencedCameraIsOneObject)
{
    const TQ3ViewAngleAspectCameraData viewAngle = viewAngleData();
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&viewAngle);
    for (TQ3FileMode mode : {kQ3FileModeNormal, kQ3FileModeText}) {
        SCOPED_TRACE(mode);
        const auto objects = readAll(writeObjects({camera, camera}, mode));
        ASSERT_EQ(objects.size(), 2u);
        EXPECT_EQ(objects[0], objects[1]);
        expectViewAngle(objects[1], viewAngle);
        disposeAll(objects);
    }
    Q3Object_Dispose(camera);
}

TEST_F(FileCameraTest, AWritingLoopWritesWhatIsSubmittedNotTheViewsCamera)
{
    // QuickDraw 3D writes only the objects submitted in the loop; a view's
    // camera goes into a file only when the application submits it.
    const TQ3ViewAngleAspectCameraData viewAngle = viewAngleData();
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&viewAngle);
    TQ3PointData point = {{1, 2, 3}, nullptr};
    TQ3GeometryObject geometry = Q3Point_New(&point);
    TQ3ViewObject view = Q3View_New();
    ASSERT_EQ(Q3View_SetCamera(view, camera), kQ3Success);
    const auto objects = readAll(writeMemoryFileThrough(
        view, kQ3FileModeNormal, [&](TQ3ViewObject v) { EXPECT_EQ(Q3Object_Submit(geometry, v), kQ3Success); },
        [](bool ok, const char* what) { EXPECT_TRUE(ok) << what; }));
    ASSERT_EQ(objects.size(), 1u);
    EXPECT_EQ(Q3Object_GetLeafType(objects[0]), kQ3GeometryTypePoint);
    disposeAll(objects);
    Q3Object_Dispose(view);
    Q3Object_Dispose(geometry);
    Q3Object_Dispose(camera);
}
