// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "render/OffscreenRenderer.h"
#include "base/PixelConvert.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace q3 {
namespace {

const PixelType kAllTypes[] = {PixelType::kRGB32,  PixelType::kARGB32,    PixelType::kRGB16,
                               PixelType::kARGB16, PixelType::kRGB16_565, PixelType::kRGB24};
const ByteOrder kAllOrders[] = {ByteOrder::kBig, ByteOrder::kLittle};

std::string name(PixelType type, ByteOrder order)
{
    return "type " + std::to_string(std::uint32_t(type)) + (order == ByteOrder::kBig ? " big" : " little");
}

// A pixmap layout of `type` and `order`, width x height, each row padded
// by `pad` bytes.
PixmapLayout layoutOf(PixelType type, ByteOrder order, std::uint32_t width, std::uint32_t height, std::uint32_t pad)
{
    PixmapLayout layout;
    layout.width = width;
    layout.height = height;
    layout.rowBytes = width * bytesPerPixel(type) + pad;
    layout.pixelType = type;
    layout.byteOrder = order;
    return layout;
}

std::vector<std::uint8_t> bytesOfPixel(PixelType type, ByteOrder order, Rgba8 color)
{
    const PixmapLayout layout = layoutOf(type, order, 1, 1, 0);
    const std::uint8_t rgba[4] = {color.r, color.g, color.b, color.a};
    std::vector<std::uint8_t> bytes(layout.rowBytes, 0);
    EXPECT_TRUE(writeRgba8ToPixmap(Rgba8ImageView{rgba, 1, 1, 4}, PixelRect{0, 0, 1, 1}, bytes.data(), layout, 0, 0));
    return bytes;
}

// A test image whose channels run through all byte values.
std::vector<std::uint8_t> makeImage(std::uint32_t width, std::uint32_t height)
{
    std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i)
        rgba[i] = std::uint8_t(i * 37 + (i >> 2) * 11);
    return rgba;
}

TEST(RenderPixelConvert, BytesPerPixelMatchesQuickDraw3D)
{
    EXPECT_EQ(bytesPerPixel(PixelType::kRGB32), 4u);
    EXPECT_EQ(bytesPerPixel(PixelType::kARGB32), 4u);
    EXPECT_EQ(bytesPerPixel(PixelType::kRGB16), 2u);
    EXPECT_EQ(bytesPerPixel(PixelType::kARGB16), 2u);
    EXPECT_EQ(bytesPerPixel(PixelType::kRGB16_565), 2u);
    EXPECT_EQ(bytesPerPixel(PixelType::kRGB24), 3u);
    EXPECT_EQ(bytesPerPixel(static_cast<PixelType>(6)), 0u);
    EXPECT_EQ(std::uint32_t(PixelType::kRGB32), 0u);
    EXPECT_EQ(std::uint32_t(PixelType::kRGB24), 5u);
    EXPECT_EQ(std::uint32_t(ByteOrder::kBig), 0u);
    EXPECT_EQ(std::uint32_t(ByteOrder::kLittle), 1u);
}

TEST(RenderPixelConvert, StoredBytesFollowDocumentedLayout)
{
    using Bytes = std::vector<std::uint8_t>;
    const Rgba8 c{0x11, 0x22, 0x33, 0x44};
    EXPECT_EQ(bytesOfPixel(PixelType::kARGB32, ByteOrder::kBig, c), (Bytes{0x44, 0x11, 0x22, 0x33}));
    EXPECT_EQ(bytesOfPixel(PixelType::kARGB32, ByteOrder::kLittle, c), (Bytes{0x33, 0x22, 0x11, 0x44}));
    EXPECT_EQ(bytesOfPixel(PixelType::kRGB32, ByteOrder::kBig, c), (Bytes{0xFF, 0x11, 0x22, 0x33}));
    EXPECT_EQ(bytesOfPixel(PixelType::kRGB32, ByteOrder::kLittle, c), (Bytes{0x33, 0x22, 0x11, 0xFF}));
    EXPECT_EQ(bytesOfPixel(PixelType::kRGB24, ByteOrder::kBig, c), (Bytes{0x11, 0x22, 0x33}));
    EXPECT_EQ(bytesOfPixel(PixelType::kRGB24, ByteOrder::kLittle, c), (Bytes{0x33, 0x22, 0x11}));

    const Rgba8 red{255, 0, 0, 0};
    const Rgba8 green{0, 255, 0, 255};
    const Rgba8 blue{0, 0, 255, 200};
    // x/A RRRRR GGGGG BBBBB
    EXPECT_EQ(bytesOfPixel(PixelType::kRGB16, ByteOrder::kBig, red), (Bytes{0xFC, 0x00}));
    EXPECT_EQ(bytesOfPixel(PixelType::kRGB16, ByteOrder::kLittle, red), (Bytes{0x00, 0xFC}));
    EXPECT_EQ(bytesOfPixel(PixelType::kARGB16, ByteOrder::kBig, red), (Bytes{0x7C, 0x00}));
    EXPECT_EQ(bytesOfPixel(PixelType::kARGB16, ByteOrder::kBig, green), (Bytes{0x83, 0xE0}));
    EXPECT_EQ(bytesOfPixel(PixelType::kARGB16, ByteOrder::kLittle, blue), (Bytes{0x1F, 0x80}));
    // RRRRR GGGGGG BBBBB
    EXPECT_EQ(bytesOfPixel(PixelType::kRGB16_565, ByteOrder::kBig, red), (Bytes{0xF8, 0x00}));
    EXPECT_EQ(bytesOfPixel(PixelType::kRGB16_565, ByteOrder::kBig, green), (Bytes{0x07, 0xE0}));
    EXPECT_EQ(bytesOfPixel(PixelType::kRGB16_565, ByteOrder::kLittle, blue), (Bytes{0x1F, 0x00}));
}

TEST(RenderPixelConvert, NarrowChannelsRoundToNearest)
{
    for (int c = 0; c < 256; ++c) {
        const Rgba8 color{std::uint8_t(c), std::uint8_t(c), std::uint8_t(c), 255};
        const std::uint32_t w555 = packPixel(PixelType::kRGB16, color);
        const std::uint32_t w565 = packPixel(PixelType::kRGB16_565, color);
        EXPECT_EQ((w555 >> 10) & 31, std::uint32_t(std::lround(c * 31.0 / 255.0))) << c;
        EXPECT_EQ((w565 >> 5) & 63, std::uint32_t(std::lround(c * 63.0 / 255.0))) << c;
        // Widening back is within half a step of the narrow channel.
        EXPECT_LE(std::abs(int(unpackPixel(PixelType::kRGB16, w555).r) - c), 4) << c;
        EXPECT_LE(std::abs(int(unpackPixel(PixelType::kRGB16_565, w565).g) - c), 2) << c;
    }
    EXPECT_EQ(unpackPixel(PixelType::kRGB16, 0xFFFF), (Rgba8{255, 255, 255, 255}));
    EXPECT_EQ(unpackPixel(PixelType::kRGB16_565, 0x0000), (Rgba8{0, 0, 0, 255}));
    EXPECT_EQ(unpackPixel(PixelType::kARGB16, 0x7FFF), (Rgba8{255, 255, 255, 0}));
}

TEST(RenderPixelConvert, UnpackThenPackIsIdentityForEveryWord)
{
    for (std::uint32_t w = 0; w < 0x10000; ++w) {
        EXPECT_EQ(packPixel(PixelType::kARGB16, unpackPixel(PixelType::kARGB16, w)), w);
        EXPECT_EQ(packPixel(PixelType::kRGB16_565, unpackPixel(PixelType::kRGB16_565, w)), w);
        const std::uint32_t withX = w | 0x8000u;
        ASSERT_EQ(packPixel(PixelType::kRGB16, unpackPixel(PixelType::kRGB16, withX)), withX);
    }
    for (std::uint32_t i = 0; i < 100000; ++i) {
        const std::uint32_t w = i * 2654435761u;
        ASSERT_EQ(packPixel(PixelType::kARGB32, unpackPixel(PixelType::kARGB32, w)), w);
        ASSERT_EQ(packPixel(PixelType::kRGB32, unpackPixel(PixelType::kRGB32, w | 0xFF000000u)), w | 0xFF000000u);
        ASSERT_EQ(packPixel(PixelType::kRGB24, unpackPixel(PixelType::kRGB24, w & 0xFFFFFFu)), w & 0xFFFFFFu);
    }
}

TEST(RenderPixelConvert, EveryTypeAndByteOrderRoundTrips)
{
    const std::uint32_t width = 13;
    const std::uint32_t height = 7;
    const std::vector<std::uint8_t> source = makeImage(width, height);
    const Rgba8ImageView view{source.data(), width, height, width * 4};
    for (PixelType type : kAllTypes) {
        for (ByteOrder order : kAllOrders) {
            SCOPED_TRACE(name(type, order));
            const PixmapLayout layout = layoutOf(type, order, width, height, 5); // padded rows
            std::vector<std::uint8_t> pixmap(std::size_t(layout.rowBytes) * height, 0);
            ASSERT_TRUE(writeRgba8ToPixmap(view, PixelRect{0, 0, int(width), int(height)}, pixmap.data(), layout,
                                           0, 0));

            std::vector<std::uint8_t> back(std::size_t(width) * height * 4, 0);
            ASSERT_TRUE(readPixmapToRgba8(pixmap.data(), layout, PixelRect{0, 0, int(width), int(height)},
                                          back.data(), width * 4));
            for (std::uint32_t y = 0; y < height; ++y) {
                for (std::uint32_t x = 0; x < width; ++x) {
                    const std::uint8_t* s = &source[(std::size_t(y) * width + x) * 4];
                    const Rgba8 original{s[0], s[1], s[2], s[3]};
                    const Rgba8 expected = unpackPixel(type, packPixel(type, original));
                    const std::uint8_t* b = &back[(std::size_t(y) * width + x) * 4];
                    ASSERT_EQ((Rgba8{b[0], b[1], b[2], b[3]}), expected) << x << "," << y;
                    ASSERT_EQ(readPixmapPixel(pixmap.data(), layout, x, y), expected);
                    if (bytesPerPixel(type) >= 3) {
                        EXPECT_EQ(expected.r, original.r);
                        EXPECT_EQ(expected.g, original.g);
                        EXPECT_EQ(expected.b, original.b);
                    }
                    EXPECT_EQ(expected.a, type == PixelType::kARGB32 ? original.a
                                          : type == PixelType::kARGB16 ? (original.a >= 128 ? 255 : 0)
                                                                        : 255);
                }
            }
        }
    }
}

TEST(RenderPixelConvert, WritesOnlyTheDestinationRectangle)
{
    const std::vector<std::uint8_t> source = makeImage(20, 10);
    const Rgba8ImageView view{source.data(), 20, 10, 80};
    for (PixelType type : kAllTypes) {
        for (ByteOrder order : kAllOrders) {
            SCOPED_TRACE(name(type, order));
            const PixmapLayout layout = layoutOf(type, order, 16, 12, 3);
            const std::uint32_t bpp = bytesPerPixel(type);
            std::vector<std::uint8_t> pixmap(std::size_t(layout.rowBytes) * layout.height, 0xAB);
            const PixelRect from{4, 2, 6, 5};
            const int toX = 9;
            const int toY = 6;
            ASSERT_TRUE(writeRgba8ToPixmap(view, from, pixmap.data(), layout, toX, toY));
            for (std::uint32_t y = 0; y < layout.height; ++y) {
                for (std::uint32_t byte = 0; byte < layout.rowBytes; ++byte) {
                    const std::uint32_t x = byte / bpp;
                    const bool inRect = byte < layout.width * bpp && int(x) >= toX && int(x) < toX + from.width &&
                                        int(y) >= toY && int(y) < toY + from.height;
                    if (!inRect) {
                        ASSERT_EQ(pixmap[std::size_t(y) * layout.rowBytes + byte], 0xAB) << byte << "," << y;
                    }
                }
            }
            for (int y = 0; y < from.height; ++y) {
                for (int x = 0; x < from.width; ++x) {
                    const std::uint8_t* s = &source[(std::size_t(from.y + y) * 20 + std::size_t(from.x + x)) * 4];
                    const Rgba8 expected = unpackPixel(type, packPixel(type, Rgba8{s[0], s[1], s[2], s[3]}));
                    ASSERT_EQ(readPixmapPixel(pixmap.data(), layout, std::uint32_t(toX + x), std::uint32_t(toY + y)),
                              expected);
                }
            }
        }
    }
}

TEST(RenderPixelConvert, InvalidArgumentsAreRejectedWithoutWriting)
{
    const std::vector<std::uint8_t> source = makeImage(4, 4);
    const Rgba8ImageView view{source.data(), 4, 4, 16};
    PixmapLayout good;
    good.width = 4;
    good.height = 4;
    good.rowBytes = 16;
    good.pixelType = PixelType::kARGB32;
    good.byteOrder = ByteOrder::kLittle;
    std::vector<std::uint8_t> pixmap(64, 0x5A);
    const PixelRect all{0, 0, 4, 4};
    auto expectRejected = [&](RenderResult result) {
        EXPECT_EQ(result.status, RenderStatus::kInvalidArgument);
        EXPECT_FALSE(result.message.empty());
        for (std::uint8_t b : pixmap)
            ASSERT_EQ(b, 0x5A);
    };

    PixmapLayout layout = good;
    layout.pixelType = static_cast<PixelType>(6);
    expectRejected(writeRgba8ToPixmap(view, all, pixmap.data(), layout, 0, 0));
    layout.pixelType = static_cast<PixelType>(UINT32_MAX);
    expectRejected(writeRgba8ToPixmap(view, all, pixmap.data(), layout, 0, 0));
    layout = good;
    layout.byteOrder = static_cast<ByteOrder>(2);
    expectRejected(writeRgba8ToPixmap(view, all, pixmap.data(), layout, 0, 0));
    layout = good;
    layout.rowBytes = 15;
    expectRejected(writeRgba8ToPixmap(view, all, pixmap.data(), layout, 0, 0));
    layout = good;
    layout.width = 0;
    expectRejected(writeRgba8ToPixmap(view, all, pixmap.data(), layout, 0, 0));

    expectRejected(writeRgba8ToPixmap(view, all, nullptr, good, 0, 0));
    expectRejected(writeRgba8ToPixmap(Rgba8ImageView{nullptr, 4, 4, 16}, all, pixmap.data(), good, 0, 0));
    expectRejected(writeRgba8ToPixmap(Rgba8ImageView{source.data(), 4, 4, 15}, all, pixmap.data(), good, 0, 0));
    expectRejected(writeRgba8ToPixmap(view, PixelRect{1, 0, 4, 4}, pixmap.data(), good, 0, 0));
    expectRejected(writeRgba8ToPixmap(view, PixelRect{-1, 0, 2, 2}, pixmap.data(), good, 0, 0));
    expectRejected(writeRgba8ToPixmap(view, PixelRect{0, 0, -2, 2}, pixmap.data(), good, 0, 0));
    expectRejected(writeRgba8ToPixmap(view, PixelRect{0, 0, 2, 2}, pixmap.data(), good, 3, 0));
    expectRejected(writeRgba8ToPixmap(view, PixelRect{0, 0, 2, 2}, pixmap.data(), good, 0, -1));
    expectRejected(writeRgba8ToPixmap(view, PixelRect{0, 0, 2, 2}, pixmap.data(), good, INT32_MAX, 0));

    std::uint8_t out[64];
    EXPECT_EQ(readPixmapToRgba8(pixmap.data(), good, PixelRect{0, 0, 5, 1}, out, 64).status,
              RenderStatus::kInvalidArgument);
    EXPECT_EQ(readPixmapToRgba8(pixmap.data(), good, all, out, 15).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(readPixmapToRgba8(nullptr, good, all, out, 16).status, RenderStatus::kInvalidArgument);
    EXPECT_EQ(readPixmapPixel(pixmap.data(), good, 4, 0), Rgba8{});
    EXPECT_EQ(readPixmapPixel(pixmap.data(), good, 0, UINT32_MAX), Rgba8{});
    EXPECT_EQ(readPixmapPixel(nullptr, good, 0, 0), Rgba8{});

    // An empty rectangle is valid and writes nothing.
    EXPECT_TRUE(writeRgba8ToPixmap(view, PixelRect{2, 2, 0, 0}, pixmap.data(), good, 4, 4));
    for (std::uint8_t b : pixmap)
        ASSERT_EQ(b, 0x5A);
}

TEST(RenderPixelConvert, RenderedPaneLandsInEveryPixmapFormat)
{
    OffscreenRenderer renderer;
    const PixelRect pane{3, 2, 12, 8};
    ASSERT_TRUE(renderer.beginFrame(20, 14, RgbaColor{0.0f, 0.0f, 1.0f, 1.0f}, pane));
    const float pixelOrtho[16] = {2.0f / 12, 0, 0, 0, 0, -2.0f / 8, 0, 0, 0, 0, 1, 0, -1, 1, 0, 1};
    ASSERT_TRUE(renderer.setMatrix(pixelOrtho));
    const float line[] = {1.5f, 4.5f, 0.0f, 9.5f, 4.5f, 0.0f};
    ASSERT_TRUE(renderer.drawLineStrip(line, 2, RgbColor{1.0f, 1.0f, 0.0f}));
    ASSERT_TRUE(renderer.endFrame());
    const Rgba8ImageView image{renderer.pixels(), renderer.width(), renderer.height(), renderer.rowBytes()};

    for (PixelType type : kAllTypes) {
        for (ByteOrder order : kAllOrders) {
            SCOPED_TRACE(name(type, order));
            const PixmapLayout layout = layoutOf(type, order, 20, 14, 2);
            std::vector<std::uint8_t> pixmap(std::size_t(layout.rowBytes) * layout.height, 0);
            ASSERT_TRUE(writeRgba8ToPixmap(image, pane, pixmap.data(), layout, pane.x, pane.y));
            const Rgba8 yellow = readPixmapPixel(pixmap.data(), layout, 3 + 4, 2 + 4);
            const Rgba8 blue = readPixmapPixel(pixmap.data(), layout, 3 + 4, 2 + 5);
            EXPECT_EQ(yellow.r, 255);
            EXPECT_EQ(yellow.g, 255);
            EXPECT_EQ(yellow.b, 0);
            EXPECT_EQ(blue.r, 0);
            EXPECT_EQ(blue.g, 0);
            EXPECT_EQ(blue.b, 255);
            // Outside the pane the pixmap was not touched.
            EXPECT_EQ(pixmap[0], 0);
        }
    }
}

} // namespace
} // namespace q3
