// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The pixmap draw context: data round trips, the TQ3DrawContextData and
// TQ3Pixmap rules in their order, and that failures change nothing.

#include "DrawContextTestSupport.h"
#include "GeometryTestSupport.h"
#include "RenderTestSupport.h"

#include "QD3DSet.h"

#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

using namespace q3test;

class DrawContextApiTest : public PixmapContextApiTest {
protected:
    // One broken TQ3Pixmap rule and the error it must give.
    struct BrokenPixmap {
        const char* name;
        std::function<void(TQ3Pixmap&)> breakIt;
        TQ3Error error;
    };
    static std::vector<BrokenPixmap> brokenPixmaps()
    {
        return {
            {"NULL image", [](TQ3Pixmap& p) { p.image = nullptr; }, kQ3ErrorNULLParameter},
            {"NULL image before a bad type",
             [](TQ3Pixmap& p) {
                 p.image = nullptr;
                 p.pixelType = TQ3PixelType(17);
             },
             kQ3ErrorNULLParameter},
            {"unknown pixel type", [](TQ3Pixmap& p) { p.pixelType = TQ3PixelType(6); }, kQ3ErrorInvalidData},
            {"negative pixel type", [](TQ3Pixmap& p) { p.pixelType = TQ3PixelType(-1); }, kQ3ErrorInvalidData},
            {"unknown byte order", [](TQ3Pixmap& p) { p.byteOrder = TQ3Endian(2); }, kQ3ErrorInvalidData},
            {"unknown bit order", [](TQ3Pixmap& p) { p.bitOrder = TQ3Endian(-3); }, kQ3ErrorInvalidData},
            {"bad type before bad size",
             [](TQ3Pixmap& p) {
                 p.pixelType = TQ3PixelType(9);
                 p.pixelSize = 8;
             },
             kQ3ErrorInvalidData},
            {"pixel size 16 for ARGB32", [](TQ3Pixmap& p) { p.pixelSize = 16; }, kQ3ErrorUnsupportedPixelDepth},
            {"pixel size 24 for RGB16",
             [](TQ3Pixmap& p) {
                 p.pixelType = kQ3PixelTypeRGB16;
                 p.pixelSize = 24;
             },
             kQ3ErrorUnsupportedPixelDepth},
            {"pixel size 32 for RGB24",
             [](TQ3Pixmap& p) { p.pixelType = kQ3PixelTypeRGB24; }, kQ3ErrorUnsupportedPixelDepth},
            {"bad size before zero width",
             [](TQ3Pixmap& p) {
                 p.pixelSize = 8;
                 p.width = 0;
             },
             kQ3ErrorUnsupportedPixelDepth},
            {"zero width", [](TQ3Pixmap& p) { p.width = 0; }, kQ3ErrorInvalidData},
            {"zero height", [](TQ3Pixmap& p) { p.height = 0; }, kQ3ErrorInvalidData},
            {"rowBytes one short", [](TQ3Pixmap& p) { p.rowBytes = p.width * 4 - 1; }, kQ3ErrorInvalidData},
            {"rowBytes zero", [](TQ3Pixmap& p) { p.rowBytes = 0; }, kQ3ErrorInvalidData},
            {"width beyond 32 bits", [](TQ3Pixmap& p) { p.width = ~0UL; }, kQ3ErrorInvalidData},
        };
    }
};

TEST_F(DrawContextApiTest, NewStoresTheDataAsGiven)
{
    Pixmap image(10, 4, kQ3PixelTypeRGB16_565, kQ3EndianLittle, 6);
    TQ3PixmapDrawContextData data = pixmapContextData(image.pixmap());
    data.drawContextData.clearImageColor = {0.5f, 2.0f, -1.0f, 0.25f}; // clamped only when used
    data.drawContextData.pane = {{1, 1}, {3, 3}};
    data.drawContextData.paneState = kQ3True;
    unsigned char maskBits[4] = {};
    data.drawContextData.mask = {maskBits, 2, 2, 2, kQ3EndianLittle};
    data.drawContextData.maskState = TQ3Boolean(5);
    data.drawContextData.doubleBufferState = TQ3Boolean(-1);
    TQ3DrawContextObject context = Q3PixmapDrawContext_New(&data);
    ASSERT_NE(context, nullptr);
    EXPECT_EQ(Q3DrawContext_GetType(context), kQ3DrawContextTypePixmap);
    EXPECT_EQ(Q3Shared_GetType(context), kQ3SharedTypeDrawContext);
    TQ3DrawContextData out{};
    ASSERT_EQ(Q3DrawContext_GetData(context, &out), kQ3Success);
    EXPECT_EQ(out.clearImageColor.r, 2.0f);
    EXPECT_EQ(out.pane.max.x, 3.0f);
    EXPECT_EQ(out.paneState, kQ3True);
    EXPECT_EQ(out.mask.image, maskBits);
    // Any non-false boolean is stored as kQ3True.
    EXPECT_EQ(out.maskState, kQ3True);
    EXPECT_EQ(out.doubleBufferState, kQ3True);
    TQ3Pixmap pixmap{};
    ASSERT_EQ(Q3PixmapDrawContext_GetPixmap(context, &pixmap), kQ3Success);
    EXPECT_EQ(std::memcmp(&pixmap, &image.pixmap(), sizeof pixmap), 0);
    Q3Object_Dispose(context);
}

TEST_F(DrawContextApiTest, NewChecksThePixmapRulesInOrder)
{
    for (const BrokenPixmap& broken : brokenPixmaps()) {
        SCOPED_TRACE(broken.name);
        TQ3PixmapDrawContextData data = pixmapContextData(m_image.pixmap());
        broken.breakIt(data.pixmap);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapDrawContext_New(&data), nullptr), broken.error);
    }
    EXPECT_Q3_ERROR(Q3PixmapDrawContext_New(nullptr), kQ3ErrorNULLParameter);
}

TEST_F(DrawContextApiTest, NewChecksTheCommonDataBeforeThePixmap)
{
    const std::vector<std::function<void(TQ3DrawContextData&)>> cases = {
        [](TQ3DrawContextData& d) { d.clearImageMethod = TQ3DrawContextClearImageMethod(2); },
        [](TQ3DrawContextData& d) { d.clearImageColor.g = kNaN; },
        [](TQ3DrawContextData& d) { d.clearImageColor.a = kInf; },
        [](TQ3DrawContextData& d) {
            d.paneState = kQ3True;
            d.pane = {{5, 5}, {5, 9}};
        },
        [](TQ3DrawContextData& d) {
            d.paneState = TQ3Boolean(2);
            d.pane = {{5, 9}, {8, 2}};
        },
        [](TQ3DrawContextData& d) {
            d.paneState = kQ3True;
            d.pane = {{0, 0}, {kInf, 4}};
        },
    };
    for (std::size_t i = 0; i < cases.size(); ++i) {
        SCOPED_TRACE("case " + std::to_string(i));
        TQ3PixmapDrawContextData data = pixmapContextData(m_image.pixmap());
        cases[i](data.drawContextData);
        data.pixmap.image = nullptr; // also broken, but checked later
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapDrawContext_New(&data), nullptr), kQ3ErrorInvalidData);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetData(m_context, &data.drawContextData), kQ3Failure),
                        kQ3ErrorInvalidData);
    }
    // With the pane off, the pane may hold anything.
    TQ3PixmapDrawContextData data = pixmapContextData(m_image.pixmap());
    data.drawContextData.pane = {{kNaN, 3}, {-kInf, 0}};
    TQ3DrawContextObject context = Q3PixmapDrawContext_New(&data);
    EXPECT_NE(context, nullptr);
    // ... until the pane is turned on.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetPaneState(context, kQ3True), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    TQ3Boolean state = kQ3True;
    Q3DrawContext_GetPaneState(context, &state);
    EXPECT_EQ(state, kQ3False);
    Q3Object_Dispose(context);
}

TEST_F(DrawContextApiTest, SetPixmapChecksTheSameRulesAndChangesNothingOnFailure)
{
    const Snapshot before = snapshot();
    for (const BrokenPixmap& broken : brokenPixmaps()) {
        SCOPED_TRACE(broken.name);
        TQ3Pixmap pixmap = m_image.pixmap();
        broken.breakIt(pixmap);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapDrawContext_SetPixmap(m_context, &pixmap), kQ3Failure), broken.error);
    }
    expectUnchanged(before);
    Pixmap other(3, 3, kQ3PixelTypeRGB24, kQ3EndianLittle);
    EXPECT_EQ(Q3PixmapDrawContext_SetPixmap(m_context, &other.pixmap()), kQ3Success);
    TQ3Pixmap out{};
    Q3PixmapDrawContext_GetPixmap(m_context, &out);
    EXPECT_EQ(std::memcmp(&out, &other.pixmap(), sizeof out), 0);
    EXPECT_NE(Q3Shared_GetEditIndex(m_context), before.editIndex);
}

TEST_F(DrawContextApiTest, SetDataReplacesTheCommonState)
{
    TQ3DrawContextData data{};
    data.clearImageMethod = kQ3ClearMethodNone;
    data.clearImageColor = {1, 0.25f, 0.5f, 0.75f};
    data.pane = {{2, 3}, {4, 5}};
    data.paneState = TQ3Boolean(9);
    EXPECT_EQ(Q3DrawContext_SetData(m_context, &data), kQ3Success);
    TQ3DrawContextData out{};
    Q3DrawContext_GetData(m_context, &out);
    EXPECT_EQ(out.clearImageMethod, kQ3ClearMethodNone);
    EXPECT_EQ(out.clearImageColor.b, 0.75f);
    EXPECT_EQ(out.pane.min.y, 3.0f);
    EXPECT_EQ(out.paneState, kQ3True);
    // The pixmap is not part of the common state.
    TQ3Pixmap pixmap{};
    Q3PixmapDrawContext_GetPixmap(m_context, &pixmap);
    EXPECT_EQ(pixmap.image, m_image.pixmap().image);
}

TEST_F(DrawContextApiTest, ClearColorPaneAndMethodSettersRoundTripAndValidate)
{
    const TQ3ColorARGB color = {0.5f, 1.5f, 0, 1};
    EXPECT_EQ(Q3DrawContext_SetClearImageColor(m_context, &color), kQ3Success);
    TQ3ColorARGB colorOut{};
    EXPECT_EQ(Q3DrawContext_GetClearImageColor(m_context, &colorOut), kQ3Success);
    EXPECT_EQ(std::memcmp(&colorOut, &color, sizeof color), 0);

    const TQ3Area pane = {{1.5f, 2}, {10, 7}};
    EXPECT_EQ(Q3DrawContext_SetPane(m_context, &pane), kQ3Success);
    TQ3Area paneOut{};
    EXPECT_EQ(Q3DrawContext_GetPane(m_context, &paneOut), kQ3Success);
    EXPECT_EQ(std::memcmp(&paneOut, &pane, sizeof pane), 0);

    EXPECT_EQ(Q3DrawContext_SetPaneState(m_context, TQ3Boolean(3)), kQ3Success);
    TQ3Boolean state = kQ3False;
    EXPECT_EQ(Q3DrawContext_GetPaneState(m_context, &state), kQ3Success);
    EXPECT_EQ(state, kQ3True);
    EXPECT_EQ(Q3DrawContext_SetPaneState(m_context, kQ3False), kQ3Success);
    Q3DrawContext_GetPaneState(m_context, &state);
    EXPECT_EQ(state, kQ3False);

    EXPECT_EQ(Q3DrawContext_SetClearImageMethod(m_context, kQ3ClearMethodNone), kQ3Success);
    TQ3DrawContextClearImageMethod method = kQ3ClearMethodWithColor;
    EXPECT_EQ(Q3DrawContext_GetClearImageMethod(m_context, &method), kQ3Success);
    EXPECT_EQ(method, kQ3ClearMethodNone);

    const Snapshot before = snapshot();
    for (float bad : {kNaN, kInf, -kInf})
        for (int field = 0; field < 4; ++field) {
            SCOPED_TRACE("field " + std::to_string(field) + " = " + std::to_string(bad));
            TQ3ColorARGB badColor = color;
            (&badColor.a)[field] = bad;
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetClearImageColor(m_context, &badColor), kQ3Failure),
                            kQ3ErrorInvalidParameter);
            TQ3Area badPane = pane;
            (&badPane.min.x)[field] = bad;
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetPane(m_context, &badPane), kQ3Failure),
                            kQ3ErrorInvalidParameter);
            // The same values inside a whole TQ3DrawContextData.
            TQ3DrawContextData data = before.data;
            data.clearImageColor = badColor;
            EXPECT_Q3_ERROR(Q3DrawContext_SetData(m_context, &data), kQ3ErrorInvalidData);
            data = before.data;
            data.pane = badPane;
            data.paneState = kQ3True;
            EXPECT_Q3_ERROR(Q3DrawContext_SetData(m_context, &data), kQ3ErrorInvalidData);
        }
    const TQ3Area empty = {{4, 4}, {4, 8}};
    const TQ3Area inverted = {{4, 8}, {8, 4}};
    EXPECT_Q3_ERROR(Q3DrawContext_SetPane(m_context, &empty), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3DrawContext_SetPane(m_context, &inverted), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3DrawContext_SetClearImageMethod(m_context, TQ3DrawContextClearImageMethod(2)),
                    kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3DrawContext_SetClearImageMethod(m_context, TQ3DrawContextClearImageMethod(-1)),
                    kQ3ErrorInvalidParameter);
    expectUnchanged(before);
}

TEST_F(DrawContextApiTest, EveryCallRejectsBadHandlesAndPointers)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3PixmapDrawContextData good = pixmapContextData(m_image.pixmap());
    TQ3DrawContextObject dead = Q3PixmapDrawContext_New(&good);
    Q3Object_Dispose(dead);
    TQ3DrawContextData data = good.drawContextData;
    TQ3ColorARGB color{};
    TQ3Area pane = {{0, 0}, {1, 1}};
    TQ3Boolean state;
    TQ3DrawContextClearImageMethod method;
    TQ3Pixmap pixmap = m_image.pixmap();
    const std::vector<std::function<TQ3Status(TQ3DrawContextObject, bool)>> calls = {
        [&](TQ3DrawContextObject c, bool p) { return Q3DrawContext_SetData(c, p ? &data : nullptr); },
        [&](TQ3DrawContextObject c, bool p) { return Q3DrawContext_GetData(c, p ? &data : nullptr); },
        [&](TQ3DrawContextObject c, bool p) { return Q3DrawContext_SetClearImageColor(c, p ? &color : nullptr); },
        [&](TQ3DrawContextObject c, bool p) { return Q3DrawContext_GetClearImageColor(c, p ? &color : nullptr); },
        [&](TQ3DrawContextObject c, bool p) { return Q3DrawContext_SetPane(c, p ? &pane : nullptr); },
        [&](TQ3DrawContextObject c, bool p) { return Q3DrawContext_GetPane(c, p ? &pane : nullptr); },
        [&](TQ3DrawContextObject c, bool p) { return Q3DrawContext_GetPaneState(c, p ? &state : nullptr); },
        [&](TQ3DrawContextObject c, bool p) { return Q3DrawContext_GetClearImageMethod(c, p ? &method : nullptr); },
        [&](TQ3DrawContextObject c, bool p) { return Q3PixmapDrawContext_SetPixmap(c, p ? &pixmap : nullptr); },
        [&](TQ3DrawContextObject c, bool p) { return Q3PixmapDrawContext_GetPixmap(c, p ? &pixmap : nullptr); },
    };
    for (std::size_t i = 0; i < calls.size(); ++i) {
        SCOPED_TRACE("call " + std::to_string(i));
        EXPECT_Q3_ERROR(EXPECT_EQ(calls[i](nullptr, true), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(calls[i](dead, true), kQ3ErrorInvalidObject);
        EXPECT_Q3_ERROR(calls[i](set, true), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(calls[i](m_context, false), kQ3ErrorNULLParameter);
        EXPECT_EQ(calls[i](m_context, true), kQ3Success);
    }
    for (TQ3DrawContextObject bad : {TQ3DrawContextObject(nullptr), dead, set}) {
        const TQ3Error expected = bad == nullptr ? kQ3ErrorNULLParameter
                                  : bad == dead  ? kQ3ErrorInvalidObject
                                                 : kQ3ErrorInvalidObjectType;
        EXPECT_Q3_ERROR(Q3DrawContext_SetPaneState(bad, kQ3False), expected);
        EXPECT_Q3_ERROR(Q3DrawContext_SetClearImageMethod(bad, kQ3ClearMethodNone), expected);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_GetType(bad), kQ3ObjectTypeInvalid), expected);
    }
    Q3Object_Dispose(set);
}

TEST_F(DrawContextApiTest, DuplicateCopiesTheStateButSharesTheImageMemory)
{
    TQ3DrawContextObject copy = Q3Object_Duplicate(m_context);
    ASSERT_NE(copy, nullptr);
    TQ3Pixmap pixmap{};
    Q3PixmapDrawContext_GetPixmap(copy, &pixmap);
    EXPECT_EQ(pixmap.image, m_image.pixmap().image);
    Q3DrawContext_SetClearImageMethod(copy, kQ3ClearMethodNone);
    TQ3DrawContextClearImageMethod method;
    Q3DrawContext_GetClearImageMethod(m_context, &method);
    EXPECT_EQ(method, kQ3ClearMethodWithColor);
    Q3Object_Dispose(copy);
}

TEST_F(DrawContextApiTest, ClearColorComponentsAreClampedWhenUsed)
{
    Pixmap image(8, 8, kQ3PixelTypeARGB32);
    TestView view(image.pixmap());
    const TQ3ColorARGB color = {3.0f, -2.0f, 0.5f, 7.0f};
    ASSERT_EQ(Q3DrawContext_SetClearImageColor(view.context(), &color), kQ3Success);
    EXPECT_EQ(view.render([](TQ3ViewObject) {}), kQ3ViewStatusDone);
    const Rgba c = image.at(3, 3);
    EXPECT_EQ(c.a, 255);
    EXPECT_EQ(c.r, 0);
    EXPECT_NEAR(c.g, 128, 1);
    EXPECT_EQ(c.b, 255);
}

} // namespace
