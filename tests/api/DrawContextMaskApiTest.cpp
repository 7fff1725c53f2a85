// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The draw context's mask and double-buffer calls: round trips, bad input
// (a failed Set leaves the draw context and its edit index unchanged), and
// the mask deciding which pixmap pixels Q3View_EndRendering writes.

#include "DrawContextTestSupport.h"
#include "RenderTestSupport.h"

#include "QD3DGeometry.h"

#include <climits>
#include <cstring>
#include <vector>

namespace {

using namespace q3test;

class DrawContextMaskApiTest : public PixmapContextApiTest {
protected:
    void SetUp() override
    {
        PixmapContextApiTest::SetUp();
        m_renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    }
    void TearDown() override
    {
        Q3Object_Dispose(m_renderer);
        PixmapContextApiTest::TearDown();
    }

    // A 16 x 8 mask, 2 bytes a row: the left half of every row selected
    // (big-endian bits: the first byte's bits are pixels 0-7).
    unsigned char m_bits[16] = {0xFF, 0x00, 0xFF, 0x00, 0xFF, 0x00, 0xFF, 0x00,
                                0xFF, 0x00, 0xFF, 0x00, 0xFF, 0x00, 0xFF, 0x00};
    TQ3Bitmap m_mask{m_bits, 16, 8, 2, kQ3EndianBig};
    TQ3RendererObject m_renderer = nullptr;
};

TEST_F(DrawContextMaskApiTest, MaskAndStatesStartOffAndRoundTrip)
{
    TQ3Bitmap mask{};
    TQ3Boolean state = kQ3True;
    ASSERT_EQ(Q3DrawContext_GetMask(m_context, &mask), kQ3Success);
    EXPECT_EQ(mask.image, nullptr);
    ASSERT_EQ(Q3DrawContext_GetMaskState(m_context, &state), kQ3Success);
    EXPECT_EQ(state, kQ3False);
    state = kQ3True;
    ASSERT_EQ(Q3DrawContext_GetDoubleBufferState(m_context, &state), kQ3Success);
    EXPECT_EQ(state, kQ3False);

    const unsigned long before = Q3Shared_GetEditIndex(m_context);
    ASSERT_EQ(Q3DrawContext_SetMask(m_context, &m_mask), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(m_context), before);
    ASSERT_EQ(Q3DrawContext_GetMask(m_context, &mask), kQ3Success);
    EXPECT_EQ(std::memcmp(&mask, &m_mask, sizeof mask), 0); // the caller's bits, not a copy

    ASSERT_EQ(Q3DrawContext_SetMaskState(m_context, TQ3Boolean(7)), kQ3Success);
    ASSERT_EQ(Q3DrawContext_GetMaskState(m_context, &state), kQ3Success);
    EXPECT_EQ(state, kQ3True);
    ASSERT_EQ(Q3DrawContext_SetMaskState(m_context, kQ3False), kQ3Success);
    ASSERT_EQ(Q3DrawContext_GetMaskState(m_context, &state), kQ3Success);
    EXPECT_EQ(state, kQ3False);

    ASSERT_EQ(Q3DrawContext_SetDoubleBufferState(m_context, TQ3Boolean(-1)), kQ3Success);
    ASSERT_EQ(Q3DrawContext_GetDoubleBufferState(m_context, &state), kQ3Success);
    EXPECT_EQ(state, kQ3True);
    ASSERT_EQ(Q3DrawContext_SetDoubleBufferState(m_context, kQ3False), kQ3Success);
    ASSERT_EQ(Q3DrawContext_GetDoubleBufferState(m_context, &state), kQ3Success);
    EXPECT_EQ(state, kQ3False);

    TQ3DrawContextData data{};
    ASSERT_EQ(Q3DrawContext_GetData(m_context, &data), kQ3Success);
    EXPECT_EQ(data.mask.image, m_bits);
}

TEST_F(DrawContextMaskApiTest, BadHandlesAndNullPointersFailAndChangeNothing)
{
    ASSERT_EQ(Q3DrawContext_SetMask(m_context, &m_mask), kQ3Success);
    TQ3Bitmap mask{};
    TQ3Boolean state = kQ3False;
    const Snapshot before = snapshot();
    for (TQ3Object bad : {TQ3Object(nullptr), TQ3Object(m_renderer)}) {
        const TQ3Error code = bad == nullptr ? kQ3ErrorNULLParameter : kQ3ErrorInvalidObjectType;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetMask(bad, &m_mask), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_GetMask(bad, &mask), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetMaskState(bad, kQ3True), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_GetMaskState(bad, &state), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetDoubleBufferState(bad, kQ3True), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_GetDoubleBufferState(bad, &state), kQ3Failure), code);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetMask(m_context, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_GetMask(m_context, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_GetMaskState(m_context, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_GetDoubleBufferState(m_context, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    expectUnchanged(before);
    EXPECT_EQ(mask.image, nullptr);
    EXPECT_EQ(state, kQ3False);

    // A disposed draw context is no longer a Q3 object.
    const TQ3PixmapDrawContextData data = pixmapContextData(m_image.pixmap());
    TQ3DrawContextObject dead = Q3PixmapDrawContext_New(&data);
    ASSERT_EQ(Q3Object_Dispose(dead), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetMask(dead, &m_mask), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_GetMaskState(dead, &state), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetDoubleBufferState(dead, kQ3True), kQ3Failure),
                    kQ3ErrorInvalidObject);
}

TEST_F(DrawContextMaskApiTest, SetMaskRejectsEachBrokenRuleAndChangesNothing)
{
    ASSERT_EQ(Q3DrawContext_SetMask(m_context, &m_mask), kQ3Success);
    ASSERT_EQ(Q3DrawContext_SetMaskState(m_context, kQ3True), kQ3Success);
    const Snapshot before = snapshot();
    const TQ3Bitmap broken[] = {
        {nullptr, 16, 8, 2, kQ3EndianBig},            // no bits
        {m_bits, 0, 8, 2, kQ3EndianBig},              // zero width
        {m_bits, 16, 0, 2, kQ3EndianBig},             // zero height
        {m_bits, 17, 8, 2, kQ3EndianBig},             // 17 bits need 3 bytes a row
        {m_bits, ULONG_MAX, 8, 2, kQ3EndianBig},      // width far too big for the rows
        {m_bits, 16, 8, 2, TQ3Endian(2)},             // not a bit order
        {m_bits, 16, 8, 2, TQ3Endian(-1)},            // not a bit order
    };
    for (const TQ3Bitmap& mask : broken)
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetMask(m_context, &mask), kQ3Failure), kQ3ErrorInvalidParameter);
    expectUnchanged(before);
}

TEST_F(DrawContextMaskApiTest, TurningTheMaskOnNeedsAMask)
{
    const Snapshot before = snapshot();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetMaskState(m_context, kQ3True), kQ3Failure), kQ3ErrorInvalidParameter);
    expectUnchanged(before);

    // SetData applies the same rules while the mask is on.
    TQ3DrawContextData data = before.data;
    data.maskState = kQ3True;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetData(m_context, &data), kQ3Failure), kQ3ErrorInvalidData);
    expectUnchanged(before);
    data.mask = m_mask;
    data.mask.rowBytes = 1;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DrawContext_SetData(m_context, &data), kQ3Failure), kQ3ErrorInvalidData);
    expectUnchanged(before);
    data.mask.rowBytes = 2;
    EXPECT_EQ(Q3DrawContext_SetData(m_context, &data), kQ3Success);
    // With the mask off, any mask is stored as given.
    data.maskState = kQ3False;
    data.mask = TQ3Bitmap{};
    EXPECT_EQ(Q3DrawContext_SetData(m_context, &data), kQ3Success);
}

class MaskRenderTest : public Q3ApiTest {
protected:
    // Renders a triangle covering the whole view into a fresh image through
    // a draw context set up by `configure`.
    void render(Pixmap& image, const std::function<void(TQ3DrawContextObject)>& configure)
    {
        TestView view(image.pixmap());
        configure(view.context());
        const TQ3TriangleData triangle{{{{-20.0f, -20.0f, 0.0f}, nullptr},
                                        {{20.0f, -20.0f, 0.0f}, nullptr},
                                        {{0.0f, 20.0f, 0.0f}, nullptr}},
                                       nullptr};
        EXPECT_EQ(view.render([&](TQ3ViewObject v) { Q3Triangle_Submit(&triangle, v); }), kQ3ViewStatusDone);
    }
    bool untouched(const Pixmap& image, unsigned long x, unsigned long y)
    {
        return image.word(x, y) == 0x5A5A5A5Au;
    }
};

TEST_F(MaskRenderTest, OnlyPixelsWhoseMaskBitIsSetAreWritten)
{
    // Bits in both orders and a mask smaller than the image: a diagonal-ish
    // pattern, rows 3 bytes apart (one padding byte), 12 x 6 pixels.
    for (TQ3Endian order : {kQ3EndianBig, kQ3EndianLittle}) {
        std::vector<unsigned char> bits(3 * 6, 0);
        auto select = [&](unsigned x, unsigned y) {
            bits[y * 3 + x / 8] |= order == kQ3EndianBig ? (0x80 >> (x % 8)) : (1 << (x % 8));
        };
        for (unsigned y = 0; y < 6; ++y)
            for (unsigned x = 0; x < 12; ++x)
                if ((x + y) % 3 == 0)
                    select(x, y);
        const TQ3Bitmap mask{bits.data(), 12, 6, 3, order};
        for (TQ3DrawContextClearImageMethod clear : {kQ3ClearMethodWithColor, kQ3ClearMethodNone}) {
            Pixmap image(16, 8);
            render(image, [&](TQ3DrawContextObject context) {
                ASSERT_EQ(Q3DrawContext_SetClearImageMethod(context, clear), kQ3Success);
                ASSERT_EQ(Q3DrawContext_SetMask(context, &mask), kQ3Success);
                ASSERT_EQ(Q3DrawContext_SetMaskState(context, kQ3True), kQ3Success);
            });
            for (unsigned long y = 0; y < 8; ++y)
                for (unsigned long x = 0; x < 16; ++x) {
                    const bool selected = x < 12 && y < 6 && (x + y) % 3 == 0;
                    EXPECT_EQ(untouched(image, x, y), !selected)
                        << "pixel " << x << "," << y << " order " << order << " clear " << clear;
                }
        }
    }
}

TEST_F(MaskRenderTest, AMaskTurnedOffOrDoubleBufferingChangeNothing)
{
    Pixmap plain(16, 8), masked(16, 8), doubled(16, 8);
    unsigned char bits[16] = {};
    const TQ3Bitmap mask{bits, 16, 8, 2, kQ3EndianBig}; // selects nothing
    render(plain, [](TQ3DrawContextObject) {});
    render(masked, [&](TQ3DrawContextObject context) {
        ASSERT_EQ(Q3DrawContext_SetMask(context, &mask), kQ3Success);
        ASSERT_EQ(Q3DrawContext_SetMaskState(context, kQ3True), kQ3Success);
        ASSERT_EQ(Q3DrawContext_SetMaskState(context, kQ3False), kQ3Success);
    });
    render(doubled, [](TQ3DrawContextObject context) {
        ASSERT_EQ(Q3DrawContext_SetDoubleBufferState(context, kQ3True), kQ3Success);
    });
    EXPECT_EQ(plain.bytes(), masked.bytes());
    EXPECT_EQ(plain.bytes(), doubled.bytes());
    for (unsigned long y = 0; y < 8; ++y)
        for (unsigned long x = 0; x < 16; ++x)
            EXPECT_FALSE(untouched(plain, x, y));

    // The same mask on: nothing is written.
    Pixmap none(16, 8);
    render(none, [&](TQ3DrawContextObject context) {
        ASSERT_EQ(Q3DrawContext_SetMask(context, &mask), kQ3Success);
        ASSERT_EQ(Q3DrawContext_SetMaskState(context, kQ3True), kQ3Success);
    });
    for (unsigned char byte : none.bytes())
        EXPECT_EQ(byte, Pixmap::kSentinel);
}

} // namespace
