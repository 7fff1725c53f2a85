// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// View hints (QD3DIO.h): every call with good and bad input, the references
// Set keeps and Get hands out, hints made from a view's configuration, and
// that a failing call changes nothing. (A clear method that is no
// enumerator is tried from C, in tests/c/AllHeaders.c.)

#include "RenderTestSupport.h"
#include "ViewHintsTestSupport.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGroup.h"
#include "QD3DIO.h"
#include "QD3DLight.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace {

using namespace q3test;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TQ3CameraObject newCamera()
{
    TQ3ViewAngleAspectCameraData data{};
    data.cameraData.placement = {{0, 0, 5}, {0, 0, 0}, {0, 1, 0}};
    data.cameraData.range = {1, 10};
    data.cameraData.viewPort = {{-1, 1}, 2, 2};
    data.fov = 0.7f;
    data.aspectRatioXToY = 1.5f;
    return Q3ViewAngleAspectCamera_New(&data);
}

class ViewHintsApiTest : public Q3ApiTest {
protected:
    // `get` hands back `expected`, the object the hints hold, with a new
    // reference (given back here).
    // `get` refuses a NULL result pointer on the hints, and a handle of
    // another type.
    template <class T>
    void expectGetRefuses(TQ3Status (*get)(TQ3ViewHintsObject, T*), TQ3Object wrongType)
    {
        EXPECT_Q3_ERROR(get(m_hints, nullptr), kQ3ErrorNULLParameter);
        T out{};
        EXPECT_Q3_ERROR(get(wrongType, &out), kQ3ErrorInvalidObjectType);
    }

    static void expectHintsHold(TQ3Status (*get)(TQ3ViewHintsObject, TQ3Object*), TQ3ViewHintsObject hints,
                                TQ3Object expected)
    {
        TQ3Object got = nullptr;
        EXPECT_EQ(get(hints, &got), kQ3Success);
        EXPECT_EQ(got, expected);
        if (got != nullptr)
            Q3Object_Dispose(got);
    }

    void SetUp() override
    {
        Q3ApiTest::SetUp();
        m_view = Q3View_New();
        ASSERT_NE(m_view, nullptr);
        m_hints = Q3ViewHints_New(m_view);
        ASSERT_NE(m_hints, nullptr);
    }
    void TearDown() override
    {
        Q3Object_Dispose(m_hints);
        Q3Object_Dispose(m_view);
        Q3ApiTest::TearDown();
    }

    // Everything a view hints object shows through its Get calls.
    struct Snapshot {
        TQ3Object renderer, camera, lights, set;
        TQ3Boolean dimensionsState, maskState;
        unsigned long width, height;
        TQ3Bitmap mask;
        std::vector<unsigned char> maskBits;
        TQ3DrawContextClearImageMethod method;
        TQ3ColorARGB color;
        unsigned long editIndex;
    };
    Snapshot snapshot()
    {
        Snapshot s{};
        EXPECT_EQ(Q3ViewHints_GetRenderer(m_hints, &s.renderer), kQ3Success);
        EXPECT_EQ(Q3ViewHints_GetCamera(m_hints, &s.camera), kQ3Success);
        EXPECT_EQ(Q3ViewHints_GetLightGroup(m_hints, &s.lights), kQ3Success);
        EXPECT_EQ(Q3ViewHints_GetAttributeSet(m_hints, &s.set), kQ3Success);
        for (TQ3Object held : {s.renderer, s.camera, s.lights, s.set})
            if (held != nullptr)
                Q3Object_Dispose(held);
        EXPECT_EQ(Q3ViewHints_GetDimensionsState(m_hints, &s.dimensionsState), kQ3Success);
        EXPECT_EQ(Q3ViewHints_GetDimensions(m_hints, &s.width, &s.height), kQ3Success);
        EXPECT_EQ(Q3ViewHints_GetMaskState(m_hints, &s.maskState), kQ3Success);
        EXPECT_EQ(Q3ViewHints_GetMask(m_hints, &s.mask), kQ3Success);
        if (s.mask.image != nullptr)
            s.maskBits.assign(s.mask.image, s.mask.image + s.mask.rowBytes * s.mask.height);
        EXPECT_EQ(Q3Bitmap_Empty(&s.mask), kQ3Success);
        EXPECT_EQ(Q3ViewHints_GetClearImageMethod(m_hints, &s.method), kQ3Success);
        EXPECT_EQ(Q3ViewHints_GetClearImageColor(m_hints, &s.color), kQ3Success);
        s.editIndex = Q3Shared_GetEditIndex(m_hints);
        return s;
    }
    void expectUnchanged(const Snapshot& before)
    {
        const Snapshot now = snapshot();
        EXPECT_EQ(now.renderer, before.renderer);
        EXPECT_EQ(now.camera, before.camera);
        EXPECT_EQ(now.lights, before.lights);
        EXPECT_EQ(now.set, before.set);
        EXPECT_EQ(now.dimensionsState, before.dimensionsState);
        EXPECT_EQ(now.width, before.width);
        EXPECT_EQ(now.height, before.height);
        EXPECT_EQ(now.maskState, before.maskState);
        EXPECT_EQ(now.mask.width, before.mask.width);
        EXPECT_EQ(now.mask.height, before.mask.height);
        EXPECT_EQ(now.mask.rowBytes, before.mask.rowBytes);
        EXPECT_EQ(now.maskBits, before.maskBits);
        EXPECT_EQ(now.method, before.method);
        EXPECT_EQ(std::memcmp(&now.color, &before.color, sizeof now.color), 0);
        EXPECT_EQ(now.editIndex, before.editIndex);
    }

    TQ3ViewObject m_view = nullptr;
    TQ3ViewHintsObject m_hints = nullptr;
};

TEST_F(ViewHintsApiTest, HintsOfABareViewHoldNothing)
{
    EXPECT_EQ(Q3Object_IsType(m_hints, kQ3SharedTypeViewHints), kQ3True);
    EXPECT_EQ(Q3Shared_GetType(m_hints), kQ3SharedTypeViewHints);
    const Snapshot s = snapshot();
    EXPECT_EQ(s.renderer, nullptr);
    EXPECT_EQ(s.camera, nullptr);
    EXPECT_EQ(s.lights, nullptr);
    // Q3View_GetDefaultAttributeSet always gives a set: QuickDraw 3D's
    // defaults, diffuse colour white among them.
    ASSERT_NE(s.set, nullptr);
    EXPECT_EQ(s.dimensionsState, kQ3False);
    EXPECT_EQ(s.width, 0ul);
    EXPECT_EQ(s.height, 0ul);
    EXPECT_EQ(s.maskState, kQ3False);
    EXPECT_EQ(s.mask.image, nullptr);
    EXPECT_EQ(s.mask.width, 0ul);
    EXPECT_EQ(s.method, kQ3ClearMethodNone);
    EXPECT_EQ(s.color.a, 1.0f);
    EXPECT_EQ(s.color.r, 0.0f);
}

TEST_F(ViewHintsApiTest, NewCopiesTheViewsConfiguration)
{
    Pixmap image(40, 30);
    TQ3PixmapDrawContextData contextData = pixmapContextData(image.pixmap());
    contextData.drawContextData.clearImageColor = {1.0f, 0.25f, 0.5f, 0.75f};
    unsigned char maskBits[6] = {0xFF, 0x00, 0xF0, 0x0F, 0xAA, 0x55};
    contextData.drawContextData.mask = {maskBits, 16, 3, 2, kQ3EndianLittle};
    contextData.drawContextData.maskState = kQ3True;
    TQ3DrawContextObject context = Q3PixmapDrawContext_New(&contextData);
    TQ3CameraObject camera = newCamera();
    TQ3RendererObject renderer = Q3Renderer_NewFromType(kQ3RendererTypeWireFrame);
    TQ3GroupObject lights = Q3LightGroup_New();
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB diffuse{0.1f, 0.2f, 0.3f};
    ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &diffuse), kQ3Success);
    ASSERT_EQ(Q3View_SetDrawContext(m_view, context), kQ3Success);
    ASSERT_EQ(Q3View_SetCamera(m_view, camera), kQ3Success);
    ASSERT_EQ(Q3View_SetRenderer(m_view, renderer), kQ3Success);
    ASSERT_EQ(Q3View_SetLightGroup(m_view, lights), kQ3Success);
    ASSERT_EQ(Q3View_SetDefaultAttributeSet(m_view, set), kQ3Success);

    TQ3ViewHintsObject hints = Q3ViewHints_New(m_view);
    ASSERT_NE(hints, nullptr);
    expectHintsHold(Q3ViewHints_GetCamera, hints, camera);
    expectHintsHold(Q3ViewHints_GetRenderer, hints, renderer);
    expectHintsHold(Q3ViewHints_GetLightGroup, hints, lights);
    expectHintsHold(Q3ViewHints_GetAttributeSet, hints, set);
    expectImageHints(hints, 40, 30, contextData.drawContextData.mask, contextData.drawContextData.clearImageColor);

    // A pane gives the dimensions instead of the pixmap.
    const TQ3Area pane{{4, 2}, {24.4f, 12}};
    ASSERT_EQ(Q3DrawContext_SetPane(context, &pane), kQ3Success);
    ASSERT_EQ(Q3DrawContext_SetPaneState(context, kQ3True), kQ3Success);
    TQ3ViewHintsObject paned = Q3ViewHints_New(m_view);
    unsigned long width = 0, height = 0;
    EXPECT_EQ(Q3ViewHints_GetDimensions(paned, &width, &height), kQ3Success);
    EXPECT_EQ(width, 20ul);
    EXPECT_EQ(height, 10ul);

    Q3Object_Dispose(paned);
    Q3Object_Dispose(hints);
    for (TQ3Object object : {context, camera, renderer, lights, set})
        Q3Object_Dispose(object);
}

TEST_F(ViewHintsApiTest, SetKeepsAReferenceAndGetHandsOutANewOne)
{
    TQ3CameraObject camera = newCamera();
    TQ3RendererObject renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    TQ3GroupObject lights = Q3LightGroup_New();
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3Object objects[] = {camera, renderer, lights, set};
    for (TQ3Object object : objects)
        EXPECT_EQ(Q3Shared_IsReferenced(object), kQ3False);
    ASSERT_EQ(Q3ViewHints_SetCamera(m_hints, camera), kQ3Success);
    ASSERT_EQ(Q3ViewHints_SetRenderer(m_hints, renderer), kQ3Success);
    ASSERT_EQ(Q3ViewHints_SetLightGroup(m_hints, lights), kQ3Success);
    ASSERT_EQ(Q3ViewHints_SetAttributeSet(m_hints, set), kQ3Success);
    for (TQ3Object object : objects)
        EXPECT_EQ(Q3Shared_IsReferenced(object), kQ3True);
    // The caller's references go: the hints' keep each object alive.
    for (TQ3Object object : objects)
        Q3Object_Dispose(object);
    TQ3Object got[4] = {};
    EXPECT_EQ(Q3ViewHints_GetCamera(m_hints, &got[0]), kQ3Success);
    EXPECT_EQ(Q3ViewHints_GetRenderer(m_hints, &got[1]), kQ3Success);
    EXPECT_EQ(Q3ViewHints_GetLightGroup(m_hints, &got[2]), kQ3Success);
    EXPECT_EQ(Q3ViewHints_GetAttributeSet(m_hints, &got[3]), kQ3Success);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(got[i], objects[i]);
        // The hints' reference and the one Get handed out.
        EXPECT_EQ(Q3Shared_IsReferenced(got[i]), kQ3True);
    }
    // NULL takes the light group and attribute set away.
    EXPECT_EQ(Q3ViewHints_SetLightGroup(m_hints, nullptr), kQ3Success);
    EXPECT_EQ(Q3ViewHints_SetAttributeSet(m_hints, nullptr), kQ3Success);
    EXPECT_EQ(Q3Shared_IsReferenced(got[2]), kQ3False);
    EXPECT_EQ(Q3Shared_IsReferenced(got[3]), kQ3False);
    TQ3Object none = got[2];
    EXPECT_EQ(Q3ViewHints_GetLightGroup(m_hints, &none), kQ3Success);
    EXPECT_EQ(none, nullptr);
    // Disposing of the hints drops their references.
    const unsigned long before = Q3Memory_CountLiveObjects();
    Q3Object_Dispose(m_hints);
    m_hints = Q3ViewHints_New(m_view);
    EXPECT_EQ(Q3Shared_IsReferenced(got[0]), kQ3False);
    EXPECT_EQ(Q3Shared_IsReferenced(got[1]), kQ3False);
    EXPECT_LE(Q3Memory_CountLiveObjects(), before + 1);
    for (TQ3Object object : got)
        Q3Object_Dispose(object);
}

TEST_F(ViewHintsApiTest, ValuesRoundTrip)
{
    EXPECT_EQ(Q3ViewHints_SetDimensionsState(m_hints, kQ3True), kQ3Success);
    EXPECT_EQ(Q3ViewHints_SetDimensions(m_hints, 1, 0xFFFFFFFFul), kQ3Success);
    EXPECT_EQ(Q3ViewHints_SetMaskState(m_hints, static_cast<TQ3Boolean>(1)), kQ3Success);
    unsigned char bits[4] = {0x80, 0x01, 0x7F, 0xFE};
    const TQ3Bitmap mask{bits, 9, 2, 2, kQ3EndianBig};
    EXPECT_EQ(Q3ViewHints_SetMask(m_hints, &mask), kQ3Success);
    bits[0] = 0; // the hints hold a copy
    EXPECT_EQ(Q3ViewHints_SetClearImageMethod(m_hints, kQ3ClearMethodWithColor), kQ3Success);
    const TQ3ColorARGB color{0.5f, -0.25f, 2.0f, 0.125f};
    EXPECT_EQ(Q3ViewHints_SetClearImageColor(m_hints, &color), kQ3Success);
    const Snapshot s = snapshot();
    EXPECT_EQ(s.dimensionsState, kQ3True);
    EXPECT_EQ(s.width, 1ul);
    EXPECT_EQ(s.height, 0xFFFFFFFFul);
    EXPECT_EQ(s.maskState, kQ3True);
    EXPECT_EQ(s.mask.width, 9ul);
    EXPECT_EQ(s.mask.height, 2ul);
    EXPECT_EQ(s.mask.rowBytes, 2ul);
    EXPECT_EQ(s.maskBits, (std::vector<unsigned char>{0x80, 0x01, 0x7F, 0xFE}));
    EXPECT_EQ(s.method, kQ3ClearMethodWithColor);
    EXPECT_EQ(std::memcmp(&s.color, &color, sizeof color), 0);
    // States switch off again, keeping the values.
    EXPECT_EQ(Q3ViewHints_SetDimensionsState(m_hints, kQ3False), kQ3Success);
    EXPECT_EQ(Q3ViewHints_SetMaskState(m_hints, kQ3False), kQ3Success);
    const Snapshot off = snapshot();
    EXPECT_EQ(off.dimensionsState, kQ3False);
    EXPECT_EQ(off.maskState, kQ3False);
    EXPECT_EQ(off.height, 0xFFFFFFFFul);
    EXPECT_EQ(off.maskBits, s.maskBits);
    // Each Set is an edit.
    EXPECT_NE(off.editIndex, s.editIndex);
}

TEST_F(ViewHintsApiTest, DuplicateSharesTheObjectsAndCopiesTheValues)
{
    TQ3CameraObject camera = newCamera();
    ASSERT_EQ(Q3ViewHints_SetCamera(m_hints, camera), kQ3Success);
    unsigned char bits[2] = {0x81, 0x18};
    const TQ3Bitmap mask{bits, 8, 2, 1, kQ3EndianBig};
    ASSERT_EQ(Q3ViewHints_SetMask(m_hints, &mask), kQ3Success);
    ASSERT_EQ(Q3ViewHints_SetDimensions(m_hints, 3, 4), kQ3Success);
    TQ3ViewHintsObject copy = Q3Object_Duplicate(m_hints);
    ASSERT_NE(copy, nullptr);
    EXPECT_NE(copy, m_hints);
    EXPECT_EQ(Q3Object_IsType(copy, kQ3SharedTypeViewHints), kQ3True);
    expectHintsHold(Q3ViewHints_GetCamera, copy, camera);
    unsigned long width = 0, height = 0;
    EXPECT_EQ(Q3ViewHints_GetDimensions(copy, &width, &height), kQ3Success);
    EXPECT_EQ(width, 3ul);
    EXPECT_EQ(height, 4ul);
    // The copy's mask is its own: changing the original's leaves it.
    unsigned char other[2] = {0xFF, 0xFF};
    const TQ3Bitmap full{other, 8, 2, 1, kQ3EndianBig};
    ASSERT_EQ(Q3ViewHints_SetMask(m_hints, &full), kQ3Success);
    TQ3Bitmap copied{};
    ASSERT_EQ(Q3ViewHints_GetMask(copy, &copied), kQ3Success);
    ASSERT_NE(copied.image, nullptr);
    EXPECT_EQ(copied.image[0], 0x81);
    EXPECT_EQ(copied.image[1], 0x18);
    Q3Bitmap_Empty(&copied);
    Q3Object_Dispose(copy);
    Q3Object_Dispose(camera);
}

TEST_F(ViewHintsApiTest, BadHandlesAreErrorsAndChangeNothing)
{
    TQ3CameraObject camera = newCamera();
    TQ3GroupObject display = Q3DisplayGroup_New();
    ASSERT_EQ(Q3ViewHints_SetCamera(m_hints, camera), kQ3Success);
    const Snapshot before = snapshot();
    TQ3Object out = nullptr;
    unsigned long w, h;
    TQ3ColorARGB color{1, 0, 0, 0};

    EXPECT_Q3_ERROR(Q3ViewHints_New(nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewHints_New(camera), kQ3ErrorInvalidObjectType);
    // A view hints object where a view belongs, and other objects where
    // view hints belong.
    EXPECT_Q3_ERROR(Q3ViewHints_New(m_hints), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewHints_SetCamera(camera, camera), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewHints_SetCamera(nullptr, camera), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewHints_SetCamera(m_hints, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewHints_SetCamera(m_hints, display), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewHints_SetRenderer(m_hints, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewHints_SetRenderer(m_hints, camera), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewHints_SetLightGroup(m_hints, display), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewHints_SetLightGroup(m_hints, camera), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewHints_SetAttributeSet(m_hints, camera), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewHints_SetDimensionsState(display, kQ3True), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewHints_SetDimensions(display, 1, 1), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewHints_SetMaskState(nullptr, kQ3True), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewHints_SetMask(m_hints, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewHints_SetClearImageMethod(camera, kQ3ClearMethodNone), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3ViewHints_SetClearImageColor(m_hints, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewHints_SetClearImageColor(camera, &color), kQ3ErrorInvalidObjectType);
    expectUnchanged(before);

    // Get calls: the handle, then the output pointer; nothing is written.
    out = camera;
    EXPECT_Q3_ERROR(Q3ViewHints_GetCamera(display, &out), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(out, camera);
    EXPECT_Q3_ERROR(Q3ViewHints_GetCamera(m_hints, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewHints_GetRenderer(m_hints, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewHints_GetRenderer(nullptr, &out), kQ3ErrorNULLParameter);
    expectGetRefuses(Q3ViewHints_GetLightGroup, camera);
    expectGetRefuses(Q3ViewHints_GetAttributeSet, camera);
    EXPECT_EQ(out, camera);
    expectGetRefuses(Q3ViewHints_GetDimensionsState, camera);
    EXPECT_Q3_ERROR(Q3ViewHints_GetDimensions(m_hints, nullptr, &h), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewHints_GetDimensions(m_hints, &w, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3ViewHints_GetDimensions(camera, &w, &h), kQ3ErrorInvalidObjectType);
    expectGetRefuses(Q3ViewHints_GetMaskState, display);
    expectGetRefuses(Q3ViewHints_GetMask, display);
    expectGetRefuses(Q3ViewHints_GetClearImageMethod, display);
    expectGetRefuses(Q3ViewHints_GetClearImageColor, display);
    expectUnchanged(before);
    Q3Object_Dispose(camera);
    Q3Object_Dispose(display);
}

TEST_F(ViewHintsApiTest, BadValuesAreErrorsAndChangeNothing)
{
    unsigned char bits[4] = {1, 2, 3, 4};
    const TQ3Bitmap good{bits, 8, 2, 1, kQ3EndianBig};
    ASSERT_EQ(Q3ViewHints_SetMask(m_hints, &good), kQ3Success);
    ASSERT_EQ(Q3ViewHints_SetDimensions(m_hints, 7, 9), kQ3Success);
    const Snapshot before = snapshot();

    EXPECT_Q3_ERROR(Q3ViewHints_SetDimensions(m_hints, 0, 10), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3ViewHints_SetDimensions(m_hints, 10, 0), kQ3ErrorInvalidParameter);
    if (sizeof(unsigned long) > 4) {
        const unsigned long tooWide = static_cast<unsigned long>(std::uint64_t{1} << 32);
        EXPECT_Q3_ERROR(Q3ViewHints_SetDimensions(m_hints, tooWide, 10), kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(Q3ViewHints_SetDimensions(m_hints, 10, tooWide), kQ3ErrorInvalidParameter);
    }
    for (float bad : {kNaN, kInf, -kInf}) {
        TQ3ColorARGB color{1, 0.5f, 0.5f, 0.5f};
        color.g = bad;
        EXPECT_Q3_ERROR(Q3ViewHints_SetClearImageColor(m_hints, &color), kQ3ErrorInvalidParameter);
        color = {bad, 0.5f, 0.5f, 0.5f};
        EXPECT_Q3_ERROR(Q3ViewHints_SetClearImageColor(m_hints, &color), kQ3ErrorInvalidParameter);
    }
    TQ3Bitmap bad = good;
    bad.image = nullptr;
    EXPECT_Q3_ERROR(Q3ViewHints_SetMask(m_hints, &bad), kQ3ErrorNULLParameter);
    bad = good;
    bad.width = 0;
    EXPECT_Q3_ERROR(Q3ViewHints_SetMask(m_hints, &bad), kQ3ErrorInvalidData);
    bad = good;
    bad.height = 0;
    EXPECT_Q3_ERROR(Q3ViewHints_SetMask(m_hints, &bad), kQ3ErrorInvalidData);
    bad = good;
    bad.width = 9; // 9 bits need 2 bytes a row
    EXPECT_Q3_ERROR(Q3ViewHints_SetMask(m_hints, &bad), kQ3ErrorInvalidData);
    bad = good;
    bad.rowBytes = 0x10000;
    bad.height = 0x10000; // 2^32 bytes: more than any array Q3 takes
    EXPECT_Q3_ERROR(Q3ViewHints_SetMask(m_hints, &bad), kQ3ErrorParameterOutOfRange);
    expectUnchanged(before);
}

} // namespace
