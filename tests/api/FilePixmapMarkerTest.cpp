// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Pixmap markers in 3DMF files ('mrkp', the layout Quesa reads): written and
// read back in every encoding and mode, compared field by field, image byte
// by byte and rendered; files written by hand in text and both byte orders;
// malformed images as errors.

#include "FileTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DStorage.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

using namespace q3test;

namespace {

class FilePixmapMarkerTest : public Q3ApiTest {};

const TQ3FileMode kModes[] = {kQ3FileModeNormal, kQ3FileModeText, kQ3FileModeStream | kQ3FileModeText,
                              kQ3FileModeDatabase};

std::vector<unsigned char> dataFile(const char* name)
{
    std::ifstream in(std::string(Q3_TEST_DATA_DIR) + "/" + name, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::vector<unsigned char> storageBytes(TQ3StorageObject storage)
{
    unsigned long size = 0;
    EXPECT_EQ(Q3Storage_GetSize(storage, &size), kQ3Success);
    std::vector<unsigned char> bytes(size);
    unsigned long read = 0;
    if (size > 0)
        EXPECT_EQ(Q3Storage_GetData(storage, 0, size, bytes.data(), &read), kQ3Success);
    EXPECT_EQ(read, size);
    return bytes;
}

// A marker of `image` (rowBytes * height bytes) with a diffuse colour.
TQ3GeometryObject makeMarker(const std::vector<unsigned char>& image, unsigned long width, unsigned long height,
                             unsigned long rowBytes, TQ3PixelType type, unsigned long pixelSize, TQ3Endian byteOrder)
{
    TQ3StorageObject storage = Q3MemoryStorage_New(image.data(), static_cast<unsigned long>(image.size()));
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB yellow = {1, 1, 0};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &yellow);
    TQ3PixmapMarkerData data;
    data.position = {0.25f, -0.5f, 0.125f};
    data.xOffset = -7;
    data.yOffset = 5;
    data.pixmap = {storage, width, height, rowBytes, pixelSize, type, kQ3EndianBig, byteOrder};
    data.pixmapMarkerAttributeSet = set;
    TQ3GeometryObject marker = Q3PixmapMarker_New(&data);
    Q3Object_Dispose(storage);
    Q3Object_Dispose(set);
    return marker;
}

// Everything of two storage pixmaps but their storage.
void expectSameLayout(const TQ3StoragePixmap& a, const TQ3StoragePixmap& b)
{
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.rowBytes, b.rowBytes);
    EXPECT_EQ(a.pixelSize, b.pixelSize);
    EXPECT_EQ(a.pixelType, b.pixelType);
    EXPECT_EQ(a.bitOrder, b.bitOrder);
    EXPECT_EQ(a.byteOrder, b.byteOrder);
}

void expectSameMarker(TQ3Object read, TQ3Object original)
{
    ASSERT_NE(read, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(read), kQ3GeometryTypePixmapMarker);
    TQ3PixmapMarkerData a, b;
    ASSERT_EQ(Q3PixmapMarker_GetData(read, &a), kQ3Success);
    ASSERT_EQ(Q3PixmapMarker_GetData(original, &b), kQ3Success);
    EXPECT_TRUE(samePoint(a.position, b.position));
    EXPECT_EQ(a.xOffset, b.xOffset);
    EXPECT_EQ(a.yOffset, b.yOffset);
    expectSameLayout(a.pixmap, b.pixmap);
    EXPECT_EQ(storageBytes(a.pixmap.image), storageBytes(b.pixmap.image));
    EXPECT_TRUE(sameSet(a.pixmapMarkerAttributeSet, b.pixmapMarkerAttributeSet));
    EXPECT_NE(a.pixmapMarkerAttributeSet, nullptr);
    Q3PixmapMarker_EmptyData(&a);
    Q3PixmapMarker_EmptyData(&b);
}

std::string textFile(const std::string& body)
{
    return "3DMetafile ( 1 6 Normal )\n" + body + "\n";
}

// A binary file of one 'mrkp' whose fields are given; `imageBytes` bytes of
// image follow (0x5A each).
std::vector<unsigned char> binaryMarker(std::uint32_t width, std::uint32_t height, std::uint32_t rowBytes,
                                        std::uint32_t pixelSize, std::uint32_t pixelType, std::size_t imageBytes)
{
    std::vector<unsigned char> data;
    putFloat(data, 0);
    putFloat(data, 0);
    putFloat(data, 0);
    put32(data, 0);
    put32(data, 0);
    for (std::uint32_t v : {width, height, rowBytes, pixelSize, pixelType, 0u, 0u})
        put32(data, v);
    data.insert(data.end(), imageBytes, 0x5A);
    std::vector<unsigned char> out = binaryHeader();
    putTag(out, "mrkp");
    put32(out, static_cast<std::uint32_t>(data.size()));
    out.insert(out.end(), data.begin(), data.end());
    return out;
}

} // namespace

TEST_F(FilePixmapMarkerTest, ReadsBackFieldByFieldAndDrawsTheSameInEveryMode)
{
    // 5 x 4 ARGB32 (little-endian words) with spare bytes in each row, and
    // 3 x 3 RGB24 whose 27 bytes need padding in binary files.
    std::vector<unsigned char> argb(4 * 23);
    for (std::size_t i = 0; i < argb.size(); ++i)
        argb[i] = static_cast<unsigned char>(i % 4 == 3 ? 0xFF : 37 * i + 11);
    std::vector<unsigned char> rgb(27);
    for (std::size_t i = 0; i < rgb.size(); ++i)
        rgb[i] = static_cast<unsigned char>(200 - 7 * i);
    TQ3GeometryObject markers[] = {makeMarker(argb, 5, 4, 23, kQ3PixelTypeARGB32, 32, kQ3EndianLittle),
                                   makeMarker(rgb, 3, 3, 9, kQ3PixelTypeRGB24, 24, kQ3EndianBig)};
    for (TQ3GeometryObject marker : markers) {
        ASSERT_NE(marker, nullptr);
        const std::vector<std::uint32_t> drawn = renderedWords(marker);
        // The marker shows: not every pixel is the background's.
        bool shows = false;
        for (std::uint32_t word : drawn)
            shows = shows || word != drawn.front();
        EXPECT_TRUE(shows);
        for (TQ3FileMode mode : kModes) {
            SCOPED_TRACE(mode);
            const auto objects = readAll(writeObjects({marker}, mode));
            ASSERT_EQ(objects.size(), 1u);
            expectSameMarker(objects[0], marker);
            EXPECT_EQ(renderedWords(objects[0]), drawn);
            disposeAll(objects);
        }
        Q3Object_Dispose(marker);
    }
}

TEST_F(FilePixmapMarkerTest, HandWrittenFilesReadInTextAndBothByteOrders)
{
    const std::vector<unsigned char> image = {255, 0,   0,   0,   255, 0, 0,   0,   255, 0, 0, 0,
                                              255, 255, 255, 0,   0,   0, 128, 128, 128, 0, 0, 0};
    for (const char* name : {"pixmap_marker.3dmf", "pixmap_marker_be.3dmf", "pixmap_marker_le.3dmf"}) {
        SCOPED_TRACE(name);
        const auto objects = readAll(dataFile(name));
        ASSERT_EQ(objects.size(), 1u);
        TQ3PixmapMarkerData data;
        ASSERT_EQ(Q3PixmapMarker_GetData(objects[0], &data), kQ3Success);
        EXPECT_TRUE(samePoint(data.position, TQ3Point3D{0.5f, -0.25f, 1}));
        EXPECT_EQ(data.xOffset, -2);
        EXPECT_EQ(data.yOffset, 3);
        expectSameLayout(data.pixmap, {nullptr, 3, 2, 12, 24, kQ3PixelTypeRGB24, kQ3EndianBig, kQ3EndianBig});
        EXPECT_EQ(storageBytes(data.pixmap.image), image);
        TQ3ColorRGB color = {};
        ASSERT_NE(data.pixmapMarkerAttributeSet, nullptr);
        EXPECT_EQ(Q3AttributeSet_Get(data.pixmapMarkerAttributeSet, kQ3AttributeTypeDiffuseColor, &color),
                  kQ3Success);
        EXPECT_EQ(color.r, 1);
        EXPECT_EQ(color.g, 1);
        EXPECT_EQ(color.b, 0);
        Q3PixmapMarker_EmptyData(&data);
        disposeAll(objects);
    }
}

TEST_F(FilePixmapMarkerTest, MalformedImagesAreErrors)
{
    // A well-formed 2 x 2 RGB32 marker reads, so each variant fails for its flaw.
    const auto good = readAll(binaryMarker(2, 2, 8, 32, kQ3PixelTypeRGB32, 16));
    ASSERT_EQ(good.size(), 1u);
    disposeAll(good);
    // The image runs past the object's data.
    EXPECT_READ_ERROR(binaryMarker(2, 2, 8, 32, kQ3PixelTypeRGB32, 12), kQ3ErrorInvalidMetafileObject);
    // Data left over after the (padded) image.
    EXPECT_READ_ERROR(binaryMarker(2, 2, 8, 32, kQ3PixelTypeRGB32, 20), kQ3ErrorInvalidMetafileObject);
    // Rows too short for their pixels: the marker's own rule.
    EXPECT_READ_ERROR(binaryMarker(3, 2, 8, 32, kQ3PixelTypeRGB32, 16), kQ3ErrorInvalidMetafileObject);
    // A pixel size that is not the type's, an empty image.
    EXPECT_READ_ERROR(binaryMarker(2, 2, 8, 24, kQ3PixelTypeRGB32, 16), kQ3ErrorInvalidMetafileObject);
    EXPECT_READ_ERROR(binaryMarker(0, 2, 8, 32, kQ3PixelTypeRGB32, 16), kQ3ErrorInvalidMetafileObject);
    // A huge width * height claimed with a few bytes: refused before any allocation.
    EXPECT_READ_ERROR(binaryMarker(0x40000000, 0x40000000, 0xFFFFFFFF, 32, kQ3PixelTypeRGB32, 16),
                      kQ3ErrorInvalidMetafileObject);
    EXPECT_READ_ERROR(binaryMarker(0x10000, 0x10000, 0x40000, 32, kQ3PixelTypeRGB32, 16),
                      kQ3ErrorInvalidMetafileObject);
    // A pixel type outside the enumeration.
    EXPECT_READ_ERROR(binaryMarker(2, 2, 8, 32, 9, 16), kQ3ErrorInvalidMetafilePrimitive);
    // Truncated before the image fields.
    auto truncated = binaryMarker(2, 2, 8, 32, kQ3PixelTypeRGB32, 0);
    truncated.resize(truncated.size() - 8);
    truncated[31] = static_cast<unsigned char>(truncated[31] - 8); // the low byte of the object's size
    EXPECT_READ_ERROR(truncated, kQ3ErrorInvalidMetafilePrimitive);

    const std::string fields = "PixmapMarker ( 0 0 0  0 0  2 1 8 32 ";
    EXPECT_EQ(readError(bytesOf(textFile(fields + "ARGB32 BigEndian BigEndian 0x0102030405060708 )"))), kQ3ErrorNone);
    EXPECT_READ_ERROR(bytesOf(textFile(fields + "ARGB32 BigEndian BigEndian 0x01020304 )")),
                      kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_READ_ERROR(bytesOf(textFile(fields + "RGB48 BigEndian BigEndian 0x0102030405060708 )")),
                      kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_READ_ERROR(bytesOf(textFile(fields + "ARGB32 Middle BigEndian 0x0102030405060708 )")),
                      kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_READ_ERROR(bytesOf(textFile(fields + "ARGB32 BigEndian BigEndian 0x01020304050607zz )")),
                      kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_READ_ERROR(bytesOf(textFile(fields + "ARGB32 BigEndian BigEndian 0x0102030405060708 7 )")),
                      kQ3ErrorInvalidMetafileObject);
}

TEST_F(FilePixmapMarkerTest, AnOffsetTheFileCannotHoldIsAnErrorAndWritesNothing)
{
    if (sizeof(long) < 8)
        GTEST_SKIP() << "every long fits the file's 32-bit offsets";
    const std::vector<unsigned char> image(8, 0x40);
    TQ3GeometryObject marker = makeMarker(image, 2, 1, 8, kQ3PixelTypeARGB32, 32, kQ3EndianBig);
    TQ3PointData pointData = {{1, 2, 3}, nullptr};
    TQ3GeometryObject point = Q3Point_New(&pointData);
    ASSERT_EQ(Q3PixmapMarker_SetXOffset(marker, 0x100000000L), kQ3Success);
    const auto objects = readAll(writeAfterRefusal(
        [&](TQ3ViewObject view) {
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Submit(marker, view), kQ3Failure), kQ3ErrorInvalidData);
        },
        point));
    ASSERT_EQ(objects.size(), 1u); // the point alone
    EXPECT_EQ(Q3Object_GetLeafType(objects[0]), kQ3GeometryTypePoint);
    disposeAll(objects);
    Q3Object_Dispose(point);
    Q3Object_Dispose(marker);
}
