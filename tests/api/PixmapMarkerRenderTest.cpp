// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Pixmap markers drawn: every pixel type in both byte orders lands pixel for
// pixel at the projected position plus the offsets, in its own colour
// (decoded here from QD3DDrawContext.h's table, independently of Q3),
// transparent where an ARGB alpha is 0, clipped at the pane's edges, read
// from the storage at each drawing.

#include "GeometryTestSupport.h"
#include "RenderTestSupport.h"

#include "QD3DSet.h"
#include "QD3DStorage.h"

#include <climits>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using namespace q3test;

// 40 x 30 pixels under listing1OrthographicCamera: world x -0.5..3.5 and
// y 2..-1 across them, so pixel (px, py)'s centre is this world point.
constexpr int kWidth = 40, kHeight = 30;
TQ3Point3D centreOf(int px, int py)
{
    return TQ3Point3D{float(-0.5 + (px + 0.5) / kWidth * 4.0), float(2.0 - (py + 0.5) / kHeight * 3.0), 0.0f};
}

// One test pixmap: 3 x 2 pixels of a type in a byte order, two spare bytes
// a row, its words written here from QD3DDrawContext.h's table and the
// colour each should show as 8-bit RGB (alpha 0: not drawn).
struct TestPixmap {
    std::vector<unsigned char> bytes;
    TQ3StoragePixmap pixmap{};
    Rgba expected[2][3];
};

TestPixmap makePixmap(TQ3PixelType type, TQ3Endian order)
{
    TestPixmap t;
    const unsigned bits = bitsOf(type), size = bits / 8;
    const unsigned long rowBytes = 3 * size + 2;
    t.bytes.assign(rowBytes * 2, 0xEE);
    for (unsigned y = 0; y < 2; ++y)
        for (unsigned x = 0; x < 3; ++x) {
            const unsigned i = 3 * y + x;
            // Distinct, non-black channel values at each type's precision.
            const unsigned r8 = 40 + 30 * i, g8 = 250 - 35 * i, b8 = 17 + 41 * i;
            const unsigned r5 = 3 + 5 * i, g5 = 30 - 4 * i, b5 = 1 + 6 * i, g6 = 60 - 9 * i;
            std::uint32_t word = 0;
            Rgba c{};
            switch (type) {
            case kQ3PixelTypeARGB32:
            case kQ3PixelTypeRGB32: {
                // ARGB: pixel 4 fully transparent, pixel 1 half (drawn).
                const unsigned alpha = type == kQ3PixelTypeRGB32 ? 0 : i == 4 ? 0 : i == 1 ? 0x80 : 0xFF;
                word = (alpha << 24) | (r8 << 16) | (g8 << 8) | b8;
                c = {int(r8), int(g8), int(b8), type == kQ3PixelTypeARGB32 && i == 4 ? 0 : 255};
                break;
            }
            case kQ3PixelTypeRGB24:
                word = (r8 << 16) | (g8 << 8) | b8;
                c = {int(r8), int(g8), int(b8), 255};
                break;
            case kQ3PixelTypeARGB16:
            case kQ3PixelTypeRGB16: {
                const unsigned alpha = type == kQ3PixelTypeRGB16 ? 0 : i == 4 ? 0 : 1;
                word = (alpha << 15) | (r5 << 10) | (g5 << 5) | b5;
                c = {widen(r5, 5), widen(g5, 5), widen(b5, 5), type == kQ3PixelTypeARGB16 && i == 4 ? 0 : 255};
                break;
            }
            default:
                word = (r5 << 11) | (g6 << 5) | b5;
                c = {widen(r5, 5), widen(g6, 6), widen(b5, 5), 255};
                break;
            }
            unsigned char* p = t.bytes.data() + y * rowBytes + x * size;
            for (unsigned k = 0; k < size; ++k)
                p[k] = static_cast<unsigned char>(word >> (order == kQ3EndianBig ? 8 * (size - 1 - k) : 8 * k));
            t.expected[y][x] = c;
        }
    t.pixmap = TQ3StoragePixmap{nullptr, 3, 2, rowBytes, bits, type, kQ3EndianBig, order};
    return t;
}

class PixmapMarkerRenderTest : public Q3ApiTest {
protected:
    // Renders `submit` into a fresh kWidth x kHeight ARGB32 image (cleared
    // to opaque black) with the interactive renderer.
    Pixmap render(const std::function<void(TQ3ViewObject)>& submit)
    {
        Pixmap image(kWidth, kHeight);
        TestView view(image.pixmap(), kQ3RendererTypeInteractive);
        EXPECT_EQ(view.render(submit), kQ3ViewStatusDone);
        return image;
    }

    static bool isBlack(const Rgba& c) { return c.r == 0 && c.g == 0 && c.b == 0; }

    // Every image pixel is black except those `drawn` names, which show
    // their colours exactly.
    static void expectOnly(const Pixmap& image, const std::vector<std::pair<std::pair<int, int>, Rgba>>& drawn,
                           const std::string& what)
    {
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                Rgba want{0, 0, 0, 255};
                for (const auto& d : drawn)
                    if (d.first.first == x && d.first.second == y)
                        want = d.second;
                const Rgba got = image.at(x, y);
                EXPECT_TRUE(got.r == want.r && got.g == want.g && got.b == want.b)
                    << what << ": pixel (" << x << ", " << y << ") is " << got.r << " " << got.g << " " << got.b
                    << ", expected " << want.r << " " << want.g << " " << want.b;
            }
    }
};

TEST_F(PixmapMarkerRenderTest, EveryPixelTypeInBothByteOrdersLandsPixelForPixel)
{
    const TQ3PixelType types[] = {kQ3PixelTypeRGB32, kQ3PixelTypeARGB32, kQ3PixelTypeRGB16,
                                  kQ3PixelTypeARGB16, kQ3PixelTypeRGB16_565, kQ3PixelTypeRGB24};
    // A diffuse colour on the marker changes nothing: the pixels are unlit.
    TQ3AttributeSet green = colorSet(0, 1, 0);
    for (TQ3PixelType type : types)
        for (TQ3Endian order : {kQ3EndianBig, kQ3EndianLittle}) {
            TestPixmap t = makePixmap(type, order);
            TQ3StorageObject storage =
                Q3MemoryStorage_New(t.bytes.data(), static_cast<unsigned long>(t.bytes.size()));
            t.pixmap.image = storage;
            // Anchored at pixel (20, 15), offset 7 left and 5 down.
            const TQ3PixmapMarkerData data{centreOf(20, 15), -7, 5, t.pixmap, green};
            TQ3GeometryObject marker = Q3PixmapMarker_New(&data);
            ASSERT_NE(marker, nullptr);
            const std::string what = std::string(nameOf(type)) + (order == kQ3EndianBig ? " big" : " little");
            std::vector<std::pair<std::pair<int, int>, Rgba>> drawn;
            for (int y = 0; y < 2; ++y)
                for (int x = 0; x < 3; ++x)
                    if (t.expected[y][x].a != 0)
                        drawn.push_back({{13 + x, 20 + y}, t.expected[y][x]});
            const bool alpha = type == kQ3PixelTypeARGB32 || type == kQ3PixelTypeARGB16;
            EXPECT_EQ(drawn.size(), alpha ? 5u : 6u) << what;
            expectOnly(render([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(marker, v), kQ3Success); }), drawn,
                       what + " retained");
            expectOnly(render([&](TQ3ViewObject v) { EXPECT_EQ(Q3PixmapMarker_Submit(&data, v), kQ3Success); }),
                       drawn, what + " immediate");
            Q3Object_Dispose(marker);
            Q3Object_Dispose(storage);
        }
    Q3Object_Dispose(green);
}

TEST_F(PixmapMarkerRenderTest, PixelsOutsideThePaneAreClipped)
{
    TestPixmap t = makePixmap(kQ3PixelTypeRGB24, kQ3EndianBig);
    TQ3StorageObject storage = Q3MemoryStorage_New(t.bytes.data(), static_cast<unsigned long>(t.bytes.size()));
    t.pixmap.image = storage;
    TQ3PixmapMarkerData data{centreOf(0, 0), -1, -1, t.pixmap, nullptr};
    // Top left corner: only the bottom row's last two pixels are inside.
    expectOnly(render([&](TQ3ViewObject v) { EXPECT_EQ(Q3PixmapMarker_Submit(&data, v), kQ3Success); }),
               {{{0, 0}, t.expected[1][1]}, {{1, 0}, t.expected[1][2]}}, "top left");
    // Bottom right corner: only the first pixel.
    data.position = centreOf(kWidth - 1, kHeight - 1);
    data.xOffset = 0;
    data.yOffset = 0;
    expectOnly(render([&](TQ3ViewObject v) { EXPECT_EQ(Q3PixmapMarker_Submit(&data, v), kQ3Success); }),
               {{{kWidth - 1, kHeight - 1}, t.expected[0][0]}}, "bottom right");
    // Wholly outside, however far.
    for (long offset : {LONG_MIN, long(-kWidth), long(kWidth), LONG_MAX}) {
        data.xOffset = offset;
        data.yOffset = offset / -2;
        expectOnly(render([&](TQ3ViewObject v) { EXPECT_EQ(Q3PixmapMarker_Submit(&data, v), kQ3Success); }), {},
                   "outside " + std::to_string(offset));
    }
    // Behind the camera (which sits at z = 10, looking down -z).
    data.position = centreOf(20, 15);
    data.position.z = 20.0f;
    data.xOffset = data.yOffset = 0;
    expectOnly(render([&](TQ3ViewObject v) { EXPECT_EQ(Q3PixmapMarker_Submit(&data, v), kQ3Success); }), {},
               "behind the camera");
    Q3Object_Dispose(storage);
}

TEST_F(PixmapMarkerRenderTest, TheStorageIsReadAtEachDrawing)
{
    TestPixmap t = makePixmap(kQ3PixelTypeARGB32, kQ3EndianBig);
    TQ3StorageObject storage = Q3MemoryStorage_New(t.bytes.data(), static_cast<unsigned long>(t.bytes.size()));
    t.pixmap.image = storage;
    t.pixmap.width = 1;
    t.pixmap.height = 1;
    const TQ3PixmapMarkerData data{centreOf(5, 6), 0, 0, t.pixmap, nullptr};
    TQ3GeometryObject marker = Q3PixmapMarker_New(&data);
    ASSERT_NE(marker, nullptr);
    expectOnly(render([&](TQ3ViewObject v) { Q3Geometry_Submit(marker, v); }), {{{5, 6}, t.expected[0][0]}},
               "before");
    const unsigned char white[4] = {0xFF, 0xFF, 0xFF, 0xFF};
    unsigned long written = 0;
    ASSERT_EQ(Q3Storage_SetData(storage, 0, 4, white, &written), kQ3Success);
    expectOnly(render([&](TQ3ViewObject v) { Q3Geometry_Submit(marker, v); }), {{{5, 6}, Rgba{255, 255, 255, 255}}},
               "after");
    // A storage emptied behind the marker's back: drawing it fails, clearly.
    ASSERT_EQ(Q3MemoryStorage_Set(storage, nullptr, 0), kQ3Success);
    expectOnly(render([&](TQ3ViewObject v) {
                   EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_Submit(marker, v), kQ3Failure), kQ3ErrorInvalidData);
               }),
               {}, "emptied");
    Q3Object_Dispose(marker);
    Q3Object_Dispose(storage);
}

} // namespace
