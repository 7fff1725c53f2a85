// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// View hints in 3DMF files: hints written and read back in every encoding
// and mode, compared field by field; the hand-laid files (text, big- and
// little-endian binary, make_view_hints_binary.py); a renderer the file names
// kept as an unknown object and written back; malformed hints as errors; and
// a writing loop writing hints made from a view.

#include "FileTestSupport.h"
#include "Q3ApiTest.h"
#include "ViewHintsTestSupport.h"

#include "QD3DCamera.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DSet.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

using namespace q3test;

namespace {

class FileViewHintsTest : public Q3ApiTest {};

// The hints' mask has `order` and its first two bytes are `first`, `second`.
void expectMaskBytes(TQ3ViewHintsObject hints, TQ3Endian order, unsigned char first, unsigned char second)
{
    TQ3Bitmap mask{};
    ASSERT_EQ(Q3ViewHints_GetMask(hints, &mask), kQ3Success);
    ASSERT_NE(mask.image, nullptr);
    EXPECT_EQ(mask.bitOrder, order);
    EXPECT_EQ(mask.image[0], first);
    EXPECT_EQ(mask.image[1], second);
    Q3Bitmap_Empty(&mask);
}

const TQ3FileMode kModes[] = {kQ3FileModeNormal,   kQ3FileModeText,   kQ3FileModeStream | kQ3FileModeText,
                              kQ3FileModeDatabase, kQ3FileModeStream, kQ3FileModeSwap};

std::vector<unsigned char> dataFile(const char* name)
{
    std::ifstream in(std::string(Q3_TEST_DATA_DIR) + "/" + name, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string textFile(const std::string& body)
{
    return "3DMetafile ( 1 6 Normal )\n" + body + "\n";
}

void putObject(std::vector<unsigned char>& out, const char* tag, const std::vector<unsigned char>& data)
{
    putTag(out, tag);
    put32(out, static_cast<std::uint32_t>(data.size()));
    out.insert(out.end(), data.begin(), data.end());
}

std::vector<unsigned char> words(std::initializer_list<std::uint32_t> values)
{
    std::vector<unsigned char> out;
    for (std::uint32_t v : values)
        put32(out, v);
    return out;
}

std::vector<unsigned char> binaryFile(const std::vector<unsigned char>& objects)
{
    std::vector<unsigned char> out = binaryHeader();
    out.insert(out.end(), objects.begin(), objects.end());
    return out;
}

// A ViewHints container of the given children, binary.
std::vector<unsigned char> hintsContainer(const std::vector<unsigned char>& children)
{
    std::vector<unsigned char> container;
    putObject(container, "vwhn", {});
    container.insert(container.end(), children.begin(), children.end());
    std::vector<unsigned char> out;
    putObject(out, "cntr", container);
    return out;
}

TQ3ViewAngleAspectCameraData cameraData(float fov, float aspect, TQ3Point3D location, float hither, float yon)
{
    TQ3ViewAngleAspectCameraData data{};
    data.cameraData.placement = {location, {0, 0, 0}, {0, 1, 0}};
    data.cameraData.range = {hither, yon};
    data.cameraData.viewPort = {{-1, 1}, 2, 2};
    data.fov = fov;
    data.aspectRatioXToY = aspect;
    return data;
}

void expectCamera(TQ3ViewHintsObject hints, const TQ3ViewAngleAspectCameraData& expected)
{
    TQ3CameraObject camera = nullptr;
    ASSERT_EQ(Q3ViewHints_GetCamera(hints, &camera), kQ3Success);
    ASSERT_NE(camera, nullptr);
    TQ3ViewAngleAspectCameraData got{};
    EXPECT_EQ(Q3ViewAngleAspectCamera_GetData(camera, &got), kQ3Success);
    EXPECT_EQ(got.fov, expected.fov);
    EXPECT_EQ(got.aspectRatioXToY, expected.aspectRatioXToY);
    EXPECT_TRUE(samePoint(got.cameraData.placement.cameraLocation, expected.cameraData.placement.cameraLocation));
    EXPECT_TRUE(samePoint(got.cameraData.placement.pointOfInterest, expected.cameraData.placement.pointOfInterest));
    EXPECT_EQ(got.cameraData.range.hither, expected.cameraData.range.hither);
    EXPECT_EQ(got.cameraData.range.yon, expected.cameraData.range.yon);
    EXPECT_EQ(got.cameraData.viewPort.width, expected.cameraData.viewPort.width);
    Q3Object_Dispose(camera);
}

// The lights of the hints' group: their types and light data, in order.
struct LightSeen {
    TQ3ObjectType type;
    TQ3LightData data;
};
std::vector<LightSeen> lightsOf(TQ3ViewHintsObject hints)
{
    std::vector<LightSeen> seen;
    TQ3GroupObject group = nullptr;
    EXPECT_EQ(Q3ViewHints_GetLightGroup(hints, &group), kQ3Success);
    if (group == nullptr)
        return seen;
    EXPECT_EQ(Q3Object_GetLeafType(group), kQ3GroupTypeLight);
    TQ3GroupPosition position = nullptr;
    Q3Group_GetFirstPosition(group, &position);
    while (position != nullptr) {
        TQ3Object light = nullptr;
        Q3Group_GetPositionObject(group, position, &light);
        LightSeen one{Q3Object_GetLeafType(light), {}};
        Q3Light_GetData(light, &one.data);
        seen.push_back(one);
        Q3Object_Dispose(light);
        Q3Group_GetNextPosition(group, &position);
    }
    Q3Object_Dispose(group);
    return seen;
}

TQ3ColorRGB diffuseOf(TQ3ViewHintsObject hints)
{
    TQ3ColorRGB color{-1, -1, -1};
    TQ3AttributeSet set = nullptr;
    EXPECT_EQ(Q3ViewHints_GetAttributeSet(hints, &set), kQ3Success);
    if (set != nullptr) {
        EXPECT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, &color), kQ3Success);
        Q3Object_Dispose(set);
    }
    return color;
}

// What view_hints.3dmf and its binary twins hold.
void expectHandWritten(const std::vector<TQ3Object>& objects)
{
    ASSERT_EQ(objects.size(), 2u);
    TQ3ViewHintsObject hints = objects[0];
    ASSERT_EQ(Q3Object_IsType(hints, kQ3SharedTypeViewHints), kQ3True);
    expectCamera(hints, cameraData(0.6f, 1.25f, {0, 1, 6}, 0.5f, 40));
    const auto lights = lightsOf(hints);
    ASSERT_EQ(lights.size(), 2u);
    EXPECT_EQ(lights[0].type, kQ3LightTypeAmbient);
    EXPECT_EQ(lights[0].data.brightness, 0.25f);
    EXPECT_EQ(lights[1].type, kQ3LightTypeDirectional);
    EXPECT_EQ(lights[1].data.brightness, 0.75f);
    EXPECT_EQ(lights[1].data.color.g, 0.5f);
    EXPECT_EQ(lights[1].data.color.b, 0.25f);
    const TQ3ColorRGB diffuse = diffuseOf(hints);
    EXPECT_EQ(diffuse.r, 0.25f);
    EXPECT_EQ(diffuse.g, 0.5f);
    EXPECT_EQ(diffuse.b, 0.75f);
    const unsigned char bits[4] = {0xF0, 0x0F, 0xA5, 0xA0};
    expectImageHints(hints, 320, 200, TQ3Bitmap{const_cast<unsigned char*>(bits), 12, 2, 2, kQ3EndianBig},
                     TQ3ColorARGB{1.0f, 0.125f, 0.375f, 0.625f});
    TQ3Boolean state = kQ3False;
    TQ3DrawContextClearImageMethod method = kQ3ClearMethodNone;

    // The empty one holds nothing.
    TQ3ViewHintsObject empty = objects[1];
    ASSERT_EQ(Q3Object_IsType(empty, kQ3SharedTypeViewHints), kQ3True);
    TQ3Object none = empty;
    EXPECT_EQ(Q3ViewHints_GetCamera(empty, &none), kQ3Success);
    EXPECT_EQ(none, nullptr);
    EXPECT_TRUE(lightsOf(empty).empty());
    EXPECT_EQ(Q3ViewHints_GetDimensionsState(empty, &state), kQ3Success);
    EXPECT_EQ(state, kQ3False);
    EXPECT_EQ(Q3ViewHints_GetMaskState(empty, &state), kQ3Success);
    EXPECT_EQ(state, kQ3False);
    EXPECT_EQ(Q3ViewHints_GetClearImageMethod(empty, &method), kQ3Success);
    EXPECT_EQ(method, kQ3ClearMethodNone);
}

TEST_F(FileViewHintsTest, HandWrittenFilesReadInTextAndBothByteOrders)
{
    for (const char* name : {"view_hints.3dmf", "view_hints_be.3dmf", "view_hints_le.3dmf"}) {
        SCOPED_TRACE(name);
        const auto bytes = dataFile(name);
        ASSERT_FALSE(bytes.empty());
        const auto objects = readAll(bytes);
        expectHandWritten(objects);
        disposeAll(objects);
    }
}

TEST_F(FileViewHintsTest, HintsReadBackFieldByFieldInEveryMode)
{
    const TQ3ViewAngleAspectCameraData viewAngle = cameraData(0.9f, 1.7f, {1.5f, -2.25f, 7}, 0.75f, 123.5f);
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&viewAngle);
    TQ3GroupObject lights = Q3LightGroup_New();
    const TQ3LightData pointData{kQ3True, 0.625f, {0.5f, 0.25f, 1}};
    TQ3LightObject ambient = Q3AmbientLight_New(&pointData);
    const TQ3DirectionalLightData directionalData{{kQ3False, 0.375f, {1, 0.75f, 0.125f}}, kQ3False, {0, -1, 0}};
    TQ3LightObject directional = Q3DirectionalLight_New(&directionalData);
    Q3Group_AddObject(lights, ambient);
    Q3Group_AddObject(lights, directional);
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB diffuse{0.125f, 0.875f, 0.5f};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &diffuse);
    TQ3ViewObject view = Q3View_New();
    TQ3ViewHintsObject hints = Q3ViewHints_New(view);
    ASSERT_EQ(Q3ViewHints_SetCamera(hints, camera), kQ3Success);
    ASSERT_EQ(Q3ViewHints_SetLightGroup(hints, lights), kQ3Success);
    ASSERT_EQ(Q3ViewHints_SetAttributeSet(hints, set), kQ3Success);
    ASSERT_EQ(Q3ViewHints_SetDimensions(hints, 1024, 0xFFFFFFFFul), kQ3Success);
    ASSERT_EQ(Q3ViewHints_SetDimensionsState(hints, kQ3True), kQ3Success);
    unsigned char bits[6] = {0x80, 0x01, 0xFF, 0x00, 0x3C, 0xC3};
    const TQ3Bitmap mask{bits, 11, 3, 2, kQ3EndianBig};
    ASSERT_EQ(Q3ViewHints_SetMask(hints, &mask), kQ3Success);
    ASSERT_EQ(Q3ViewHints_SetMaskState(hints, kQ3True), kQ3Success);
    ASSERT_EQ(Q3ViewHints_SetClearImageMethod(hints, kQ3ClearMethodWithColor), kQ3Success);
    const TQ3ColorARGB color{1, 0.0625f, 0.5625f, 0.9375f};
    ASSERT_EQ(Q3ViewHints_SetClearImageColor(hints, &color), kQ3Success);

    for (TQ3FileMode mode : kModes) {
        SCOPED_TRACE(mode);
        const auto objects = readAll(writeObjects({hints}, mode));
        ASSERT_EQ(objects.size(), 1u);
        TQ3ViewHintsObject got = objects[0];
        ASSERT_EQ(Q3Object_IsType(got, kQ3SharedTypeViewHints), kQ3True);
        expectCamera(got, viewAngle);
        const auto seen = lightsOf(got);
        ASSERT_EQ(seen.size(), 2u);
        EXPECT_EQ(seen[0].type, kQ3LightTypeAmbient);
        EXPECT_EQ(seen[0].data.brightness, 0.625f);
        EXPECT_EQ(seen[0].data.color.b, 1.0f);
        EXPECT_EQ(seen[1].type, kQ3LightTypeDirectional);
        EXPECT_EQ(seen[1].data.isOn, kQ3False);
        EXPECT_EQ(seen[1].data.brightness, 0.375f);
        EXPECT_EQ(seen[1].data.color.b, 0.125f);
        const TQ3ColorRGB gotDiffuse = diffuseOf(got);
        EXPECT_EQ(gotDiffuse.g, 0.875f);
        expectImageHints(got, 1024, 0xFFFFFFFFul, mask, color);
        disposeAll(objects);
    }
    for (TQ3Object object : {TQ3Object(hints), view, camera, lights, ambient, directional, set})
        Q3Object_Dispose(object);
}

TEST_F(FileViewHintsTest, WhatTheFileCannotHoldIsLeftOutAndLittleEndianMasksTurnBigEndian)
{
    // The file keeps no states apart from the objects, no clear-colour alpha
    // and no bit order (docs/3dmf.md): hints whose states are off read back
    // without dimensions or mask; a little-endian mask reads back as the same
    // pixels, most significant bit first.
    TQ3ViewObject view = Q3View_New();
    TQ3ViewHintsObject hints = Q3ViewHints_New(view);
    unsigned char bits[2] = {0x01, 0x80}; // pixel 0 of row 0 and pixel 7 of row 1
    const TQ3Bitmap little{bits, 8, 2, 1, kQ3EndianLittle};
    ASSERT_EQ(Q3ViewHints_SetMask(hints, &little), kQ3Success);
    ASSERT_EQ(Q3ViewHints_SetDimensions(hints, 5, 6), kQ3Success);
    const TQ3ColorARGB color{0.5f, 1, 1, 1};
    ASSERT_EQ(Q3ViewHints_SetClearImageColor(hints, &color), kQ3Success);
    for (TQ3FileMode mode : {kQ3FileModeNormal, kQ3FileModeText}) {
        SCOPED_TRACE(mode);
        ASSERT_EQ(Q3ViewHints_SetMaskState(hints, kQ3False), kQ3Success);
        auto objects = readAll(writeObjects({hints}, mode));
        ASSERT_EQ(objects.size(), 1u);
        TQ3Boolean state = kQ3True;
        TQ3Bitmap mask{};
        EXPECT_EQ(Q3ViewHints_GetMaskState(objects[0], &state), kQ3Success);
        EXPECT_EQ(state, kQ3False);
        EXPECT_EQ(Q3ViewHints_GetMask(objects[0], &mask), kQ3Success);
        EXPECT_EQ(mask.image, nullptr);
        EXPECT_EQ(Q3ViewHints_GetDimensionsState(objects[0], &state), kQ3Success);
        EXPECT_EQ(state, kQ3False);
        TQ3DrawContextClearImageMethod method = kQ3ClearMethodWithColor;
        EXPECT_EQ(Q3ViewHints_GetClearImageMethod(objects[0], &method), kQ3Success);
        EXPECT_EQ(method, kQ3ClearMethodNone);
        disposeAll(objects);

        ASSERT_EQ(Q3ViewHints_SetMaskState(hints, kQ3True), kQ3Success);
        ASSERT_EQ(Q3ViewHints_SetClearImageMethod(hints, kQ3ClearMethodWithColor), kQ3Success);
        objects = readAll(writeObjects({hints}, mode));
        ASSERT_EQ(objects.size(), 1u);
        expectMaskBytes(objects[0], kQ3EndianBig, 0x80, 0x01);
        TQ3ColorARGB got{};
        EXPECT_EQ(Q3ViewHints_GetClearImageColor(objects[0], &got), kQ3Success);
        EXPECT_EQ(got.a, 1.0f);
        EXPECT_EQ(got.r, 1.0f);
        disposeAll(objects);
        ASSERT_EQ(Q3ViewHints_SetClearImageMethod(hints, kQ3ClearMethodNone), kQ3Success);
    }
    Q3Object_Dispose(hints);
    Q3Object_Dispose(view);
}

TEST_F(FileViewHintsTest, TextMaskWithTheExamplesBitOrderAndARendererKeptAsUnknown)
{
    // The reference's ImageMask example puts a bit order after rowBytes;
    // a renderer (no class in Q3) is no renderer of the hints.
    const auto objects = readAll(bytesOf(textFile("Container ( ViewHints ( ) InteractiveRenderer ( )\n"
                                                  "  ImageMask ( 8 2 1 LittleEndian 0x0180 ) )")));
    ASSERT_EQ(objects.size(), 1u);
    expectMaskBytes(objects[0], kQ3EndianLittle, 0x01, 0x80);
    TQ3Object renderer = objects[0];
    EXPECT_EQ(Q3ViewHints_GetRenderer(objects[0], &renderer), kQ3Success);
    EXPECT_EQ(renderer, nullptr);
    // The renderer is kept as an unknown object and written back unchanged
    // (to a text file: an unknown text object has no binary form, which a
    // binary file leaves out with a warning, as for any unknown text object).
    const auto bytes = writeObjects({objects[0]}, kQ3FileModeText);
    EXPECT_NE(std::string(bytes.begin(), bytes.end()).find("InteractiveRenderer ( )"), std::string::npos);
    const auto again = readAll(bytes);
    ASSERT_EQ(again.size(), 1u);
    const auto text = writeObjects({again[0]}, kQ3FileModeText);
    EXPECT_EQ(text, bytes);
    disposeAll(again);
    std::vector<unsigned char> binary;
    EXPECT_Q3_WARNING(binary = writeObjects({objects[0]}, kQ3FileModeNormal), kQ3WarningNoObjectSupportForWriteMethod);
    const auto fromBinary = readAll(binary);
    ASSERT_EQ(fromBinary.size(), 1u);
    TQ3Bitmap binaryMask{};
    ASSERT_EQ(Q3ViewHints_GetMask(fromBinary[0], &binaryMask), kQ3Success);
    EXPECT_EQ(binaryMask.image[0], 0x80); // written most significant bit first
    Q3Bitmap_Empty(&binaryMask);
    disposeAll(fromBinary);
    disposeAll(objects);
}

TEST_F(FileViewHintsTest, MalformedTextHintsAreErrors)
{
    // Too few fields, or a field that is not a number.
    for (const char* body : {"Container ( ViewHints ( ) ImageDimensions ( 320 ) )",
                             "Container ( ViewHints ( ) ImageDimensions ( 320 x ) )",
                             "Container ( ViewHints ( ) ImageClearColor ( 1 1 ) )",
                             "Container ( ViewHints ( ) ImageClearColor ( 1 nan 1 ) )",
                             "Container ( ViewHints ( ) ImageMask ( 8 2 ) )",
                             "Container ( ViewHints ( ) ImageMask ( 8 2 1 0x01 ) )",
                             "Container ( ViewHints ( ) ImageMask ( 8 2 1 0x000000 ) )"}) {
        SCOPED_TRACE(body);
        EXPECT_READ_ERROR(bytesOf(textFile(body)), kQ3ErrorInvalidMetafilePrimitive);
    }
    // Values the hints refuse, data left over, image objects on their own.
    for (const char* body : {"ViewHints ( 1 )", "Container ( ViewHints ( ) ImageDimensions ( 0 5 ) )",
                             "Container ( ViewHints ( ) ImageDimensions ( 5 6 7 ) )",
                             "Container ( ViewHints ( ) ImageClearColor ( 1 1 1 1 ) )",
                             "Container ( ViewHints ( ) ImageMask ( 0 2 1 0x0000 ) )",
                             "Container ( ViewHints ( ) ImageMask ( 9 2 1 0x0000 ) )",
                             "Container ( ViewHints ( ) ImageMask ( 8 65536 65536 0x00 ) )",
                             "ImageDimensions ( 1 1 )", "ImageClearColor ( 1 1 1 )", "ImageMask ( 8 1 1 0x00 )"}) {
        SCOPED_TRACE(body);
        EXPECT_READ_ERROR(bytesOf(textFile(body)), kQ3ErrorInvalidMetafileObject);
    }
    // Children the reference does not list, or given twice.
    for (const char* body :
         {"Container ( ViewHints ( ) Box ( ) )",
          "Container ( ViewHints ( ) ImageDimensions ( 1 1 ) ImageDimensions ( 2 2 ) )",
          "Container ( ViewHints ( ) ImageClearColor ( 1 1 1 ) ImageClearColor ( 1 1 1 ) )",
          "Container ( ViewHints ( ) ImageMask ( 8 1 1 0x00 ) ImageMask ( 8 1 1 0x00 ) )",
          "Container ( ViewHints ( ) ViewAngleAspectCamera ( 0.5 1 ) ViewAngleAspectCamera ( 0.5 1 ) )",
          "Container ( ViewHints ( ) Container ( AttributeSet ( ) ) Container ( AttributeSet ( ) ) )",
          "Container ( ViewHints ( ) BeginGroup ( DisplayGroup ( ) ) EndGroup ( ) )"}) {
        SCOPED_TRACE(body);
        EXPECT_READ_ERROR(bytesOf(textFile(body)), kQ3ErrorInvalidMetafileSubObject);
    }
    // A camera the camera rules refuse stays the camera's error.
    EXPECT_READ_ERROR(bytesOf(textFile("Container ( ViewHints ( ) ViewAngleAspectCamera ( 0 1 ) )")),
                      kQ3ErrorInvalidMetafileObject);
}

TEST_F(FileViewHintsTest, MalformedBinaryHintsAreErrors)
{
    // A well-formed one reads, so each variant below fails for its flaw.
    std::vector<unsigned char> children;
    putObject(children, "imdm", words({4, 3}));
    putObject(children, "immk", words({8, 1, 1, 0xA5000000}));
    const auto good = readAll(binaryFile(hintsContainer(children)));
    ASSERT_EQ(good.size(), 1u);
    disposeAll(good);

    std::vector<unsigned char> shortDimensions;
    putObject(shortDimensions, "imdm", words({4}));
    EXPECT_READ_ERROR(binaryFile(hintsContainer(shortDimensions)), kQ3ErrorInvalidMetafilePrimitive);

    std::vector<unsigned char> zeroDimensions;
    putObject(zeroDimensions, "imdm", words({0, 3}));
    EXPECT_READ_ERROR(binaryFile(hintsContainer(zeroDimensions)), kQ3ErrorInvalidMetafileObject);

    // A mask image the object's size cannot hold, and one claiming 2^32 bytes.
    std::vector<unsigned char> shortMask;
    putObject(shortMask, "immk", words({8, 8, 1, 0}));
    EXPECT_READ_ERROR(binaryFile(hintsContainer(shortMask)), kQ3ErrorInvalidMetafilePrimitive);
    std::vector<unsigned char> hugeMask;
    putObject(hugeMask, "immk", words({8, 0x10000, 0x10000, 0}));
    EXPECT_READ_ERROR(binaryFile(hintsContainer(hugeMask)), kQ3ErrorInvalidMetafileObject);

    std::vector<unsigned char> longColor;
    putObject(longColor, "imcc", words({0, 0, 0, 0}));
    EXPECT_READ_ERROR(binaryFile(hintsContainer(longColor)), kQ3ErrorInvalidMetafileObject);

    // A size running past the end of the file.
    std::vector<unsigned char> overrun;
    putTag(overrun, "cntr");
    put32(overrun, 400);
    putObject(overrun, "vwhn", {});
    EXPECT_READ_ERROR(binaryFile(overrun), kQ3ErrorInvalidMetafile);
}

TEST_F(FileViewHintsTest, AWritingLoopWritesHintsMadeFromAView)
{
    Pixmap image(64, 48);
    const TQ3PixmapDrawContextData contextData = pixmapContextData(image.pixmap());
    TQ3DrawContextObject context = Q3PixmapDrawContext_New(&contextData);
    const TQ3ViewAngleAspectCameraData viewAngle = cameraData(0.8f, 1.25f, {0, 0, 9}, 1, 30);
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&viewAngle);
    TQ3ViewObject view = Q3View_New();
    ASSERT_EQ(Q3View_SetDrawContext(view, context), kQ3Success);
    ASSERT_EQ(Q3View_SetCamera(view, camera), kQ3Success);
    TQ3ViewHintsObject hints = Q3ViewHints_New(view);
    const auto objects = readAll(writeObjects({hints}, kQ3FileModeText));
    ASSERT_EQ(objects.size(), 1u);
    expectCamera(objects[0], viewAngle);
    unsigned long width = 0, height = 0;
    EXPECT_EQ(Q3ViewHints_GetDimensions(objects[0], &width, &height), kQ3Success);
    EXPECT_EQ(width, 64ul);
    EXPECT_EQ(height, 48ul);
    disposeAll(objects);
    for (TQ3Object object : {TQ3Object(hints), view, camera, context})
        Q3Object_Dispose(object);
}

} // namespace
