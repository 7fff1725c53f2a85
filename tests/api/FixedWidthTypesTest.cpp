// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Apple's fixed-width names are exactly their width (docs/porting.md,
// "Types") while Apple's unsigned long parameters stay unsigned long; and
// the case that needs it: Quesa's Geom Test lays out its pixmap marker's
// image as a TQ3Uns32 array, one ARGB32 pixel per element.

#include "RenderTestSupport.h"

#include "QD3DGeometry.h"
#include "QD3DIO.h"
#include "QD3DStorage.h"

#include <cstddef>
#include <cstring>
#include <cstdint>
#include <type_traits>

namespace {

using namespace q3test;

static_assert(sizeof(TQ3Uns8) == 1 && sizeof(TQ3Int8) == 1, "8-bit types");
static_assert(sizeof(TQ3Uns16) == 2 && sizeof(TQ3Int16) == 2, "16-bit types");
static_assert(sizeof(TQ3Uns32) == 4 && sizeof(TQ3Int32) == 4, "32-bit types");
static_assert(sizeof(TQ3Uns64) == 8 && sizeof(TQ3Int64) == 8, "64-bit types");
static_assert(sizeof(TQ3Float32) == 4 && sizeof(TQ3Float64) == 8, "float types");
static_assert(std::is_unsigned<TQ3Uns8>::value && std::is_unsigned<TQ3Uns16>::value &&
                  std::is_unsigned<TQ3Uns32>::value,
              "unsigned types");
static_assert(std::is_signed<TQ3Int8>::value && std::is_signed<TQ3Int16>::value && std::is_signed<TQ3Int32>::value,
              "signed types");
static_assert(std::is_same<TQ3Size, TQ3Uns32>::value, "TQ3Size is TQ3Uns32, as in QD3DIO.h");
// Apple's layout of the 64-bit structs: the low half first on a
// little-endian machine, so the struct's bytes are the 64-bit value's.
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
static_assert(offsetof(TQ3Uns64, lo) == 0 && offsetof(TQ3Uns64, hi) == 4, "TQ3Uns64 layout");
static_assert(offsetof(TQ3Int64, lo) == 0 && offsetof(TQ3Int64, hi) == 4, "TQ3Int64 layout");
#else
static_assert(offsetof(TQ3Uns64, hi) == 0 && offsetof(TQ3Uns64, lo) == 4, "TQ3Uns64 layout");
static_assert(offsetof(TQ3Int64, hi) == 0 && offsetof(TQ3Int64, lo) == 4, "TQ3Int64 layout");
#endif
// Apple's counts and indices stay unsigned long.
static_assert(std::is_same<decltype(TQ3Pixmap::width), unsigned long>::value, "struct fields stay unsigned long");
static_assert(std::is_same<decltype(&Q3Shared_GetEditIndex), unsigned long (*)(TQ3SharedObject)>::value,
              "results stay unsigned long");
static_assert(std::is_same<decltype(&Q3Storage_GetSize), TQ3Status (*)(TQ3StorageObject, unsigned long*)>::value,
              "parameters stay unsigned long");

using FixedWidthTypesTest = Q3ApiTest;

TEST_F(FixedWidthTypesTest, TheSixtyFourBitStructsHoldTheValueInMemoryOrder)
{
    TQ3Uns64 value{};
    value.hi = 0x01020304u;
    value.lo = 0x05060708u;
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    EXPECT_EQ(bits, 0x0102030405060708ull);
}

// 40 x 30 pixels under listing1OrthographicCamera: world x -0.5..3.5 and
// y 2..-1 across them, so pixel (px, py)'s centre is this world point.
TQ3Point3D centreOf(int px, int py)
{
    return TQ3Point3D{float(-0.5 + (px + 0.5) / 40 * 4.0), float(2.0 - (py + 0.5) / 30 * 3.0), 0.0f};
}

TEST_F(FixedWidthTypesTest, AGeomTestPixmapMarkerFromATQ3Uns32ArrayDrawsPixelForPixel)
{
    // 4 x 2 RGB32 pixels, one TQ3Uns32 each, in the machine's byte order, as
    // Geom Test writes them: rowBytes = width * sizeof(TQ3Uns32).
    const TQ3Uns32 image[2][4] = {{0x00FF0000u, 0x0000FF00u, 0x000000FFu, 0x00FFFFFFu},
                                  {0x00808000u, 0x00008080u, 0x00800080u, 0x00404040u}};
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    const TQ3Endian order = kQ3EndianLittle;
#else
    const TQ3Endian order = kQ3EndianBig;
#endif
    TQ3StorageObject storage =
        Q3MemoryStorage_New(reinterpret_cast<const unsigned char*>(image), sizeof image);
    const TQ3StoragePixmap pixmap{storage, 4, 2, 4 * sizeof(TQ3Uns32), 32, kQ3PixelTypeRGB32, kQ3EndianBig, order};
    const TQ3PixmapMarkerData data{centreOf(10, 10), 0, 0, pixmap, nullptr};
    Pixmap picture(40, 30);
    TestView view(picture.pixmap());
    EXPECT_EQ(view.render([&](TQ3ViewObject v) { EXPECT_EQ(Q3PixmapMarker_Submit(&data, v), kQ3Success); }),
              kQ3ViewStatusDone);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) {
            const Rgba got = picture.at(10 + x, 10 + y);
            const TQ3Uns32 want = image[y][x];
            EXPECT_EQ(got.r, int((want >> 16) & 0xFF)) << x << "," << y;
            EXPECT_EQ(got.g, int((want >> 8) & 0xFF)) << x << "," << y;
            EXPECT_EQ(got.b, int(want & 0xFF)) << x << "," << y;
        }
    Q3Object_Dispose(storage);
}

TEST_F(FixedWidthTypesTest, TheThirtyTwoBitPrimitivesReadAndWriteEveryValue)
{
    TQ3StorageObject storage = Q3MemoryStorage_New(nullptr, 0);
    TQ3FileObject file = Q3File_New();
    ASSERT_EQ(Q3File_SetStorage(file, storage), kQ3Success);
    ASSERT_EQ(Q3File_OpenWrite(file, kQ3FileModeNormal), kQ3Success);
    ASSERT_EQ(Q3Uns32_Write(Q3_OBJECT_TYPE('f', 'x', 'w', 'd'), file), kQ3Success);
    ASSERT_EQ(Q3Uns32_Write(16, file), kQ3Success);
    ASSERT_EQ(Q3Uns32_Write(0xFFFFFFFFu, file), kQ3Success);
    ASSERT_EQ(Q3Int32_Write(INT32_MIN, file), kQ3Success);
    TQ3Uns64 big{};
    big.hi = 0xFFFFFFFFu;
    big.lo = 1;
    ASSERT_EQ(Q3Uns64_Write(big, file), kQ3Success);
    ASSERT_EQ(Q3File_Close(file), kQ3Success);
    TQ3FileMode mode = 0;
    ASSERT_EQ(Q3File_OpenRead(file, &mode), kQ3Success);
    TQ3Uns32 u = 0;
    TQ3Int32 i = 0;
    TQ3Uns64 back{};
    ASSERT_EQ(Q3Uns32_Read(&u, file), kQ3Success);
    ASSERT_EQ(Q3Int32_Read(&i, file), kQ3Success);
    ASSERT_EQ(Q3Uns64_Read(&back, file), kQ3Success);
    EXPECT_EQ(u, 0xFFFFFFFFu);
    EXPECT_EQ(i, INT32_MIN);
    EXPECT_EQ(back.hi, 0xFFFFFFFFu);
    EXPECT_EQ(back.lo, 1u);
    ASSERT_EQ(Q3File_Close(file), kQ3Success);
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
}

} // namespace
