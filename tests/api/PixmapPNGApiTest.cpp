// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Q3PixmapPNG.h: every pixel type and byte order written and read back bit
// for bit, a draw context's rendered image written as drawn, deterministic
// files, and every error in the order the header lists them.

#include "RenderTestSupport.h"

#include "Q3PixmapPNG.h"
#include "q3png.h"

#include <zlib.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using namespace q3test;

const TQ3PixelType kPixelTypes[] = {kQ3PixelTypeRGB32, kQ3PixelTypeARGB32, kQ3PixelTypeRGB16,
                                    kQ3PixelTypeARGB16, kQ3PixelTypeRGB16_565, kQ3PixelTypeRGB24};
const TQ3Endian kByteOrders[] = {kQ3EndianBig, kQ3EndianLittle};

std::string scratch(const std::string& name)
{
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return ::testing::TempDir() + "q3pixmappng_" + std::to_string(getpid()) + "_" + info->name() + "_" + name;
}

std::string slurp(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool exists(const std::string& path)
{
    return access(path.c_str(), F_OK) == 0;
}

// The bits a type ignores, which Q3 draws as ones and a PNG cannot hold.
std::uint32_t ignoredBits(TQ3PixelType type)
{
    switch (type) {
    case kQ3PixelTypeRGB32:
        return 0xFF000000u;
    case kQ3PixelTypeRGB16:
        return 0x8000u;
    default:
        return 0;
    }
}

// Stores word at pixel (x, y) of a pixmap as its byte order says.
void storeWord(const TQ3Pixmap& pixmap, unsigned long x, unsigned long y, std::uint32_t word)
{
    const unsigned size = bitsOf(pixmap.pixelType) / 8;
    unsigned char* p = static_cast<unsigned char*>(pixmap.image) + y * pixmap.rowBytes + x * size;
    for (unsigned i = 0; i < size; ++i) {
        const unsigned shift = pixmap.byteOrder == kQ3EndianBig ? 8 * (size - 1 - i) : 8 * i;
        p[i] = static_cast<unsigned char>(word >> shift);
    }
}

std::uint32_t loadWord(const TQ3Pixmap& pixmap, unsigned long x, unsigned long y)
{
    const unsigned size = bitsOf(pixmap.pixelType) / 8;
    const unsigned char* p = static_cast<const unsigned char*>(pixmap.image) + y * pixmap.rowBytes + x * size;
    std::uint32_t word = 0;
    for (unsigned i = 0; i < size; ++i) {
        const unsigned shift = pixmap.byteOrder == kQ3EndianBig ? 8 * (size - 1 - i) : 8 * i;
        word |= std::uint32_t(p[i]) << shift;
    }
    return word;
}

// A big-endian PNG chunk: length, type, data, CRC of type and data.
void appendChunk(std::string* file, const char* type, const std::string& data)
{
    auto be32 = [](std::uint32_t v) {
        return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    };
    const std::string body = std::string(type, 4) + data;
    *file += be32(std::uint32_t(data.size())) + body;
    *file += be32(std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()))));
}

void writeFile(const std::string& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary) << bytes;
}

class PixmapPNGApiTest : public Q3ApiTest {};

TEST_F(PixmapPNGApiTest, EveryPixelTypeAndByteOrderRoundTripsBitExactly)
{
    std::mt19937 random(31);
    for (TQ3PixelType type : kPixelTypes)
        for (TQ3Endian order : kByteOrders) {
            SCOPED_TRACE(std::string(nameOf(type)) + (order == kQ3EndianBig ? " big" : " little"));
            // 37 x 11 pixels, 3 bytes of padding at each row's end: odd sizes
            // and a rowBytes that is not width times the pixel size.
            Pixmap source(37, 11, type, order, 3);
            const std::uint32_t mask = bitsOf(type) == 32 ? 0xFFFFFFFFu : (1u << bitsOf(type)) - 1u;
            std::vector<std::uint32_t> words;
            for (unsigned long y = 0; y < source.height(); ++y)
                for (unsigned long x = 0; x < source.width(); ++x) {
                    // Every channel value at its extremes too: all zeros, all ones.
                    std::uint32_t word = (x == 0) ? 0 : (x == 1) ? mask : std::uint32_t(random()) & mask;
                    word |= ignoredBits(type);
                    words.push_back(word);
                    storeWord(source.pixmap(), x, y, word);
                }
            const std::string path = scratch("roundtrip.png");
            ASSERT_EQ(Q3Pixmap_WritePNG(&source.pixmap(), path.c_str()), kQ3Success);

            TQ3Pixmap read{};
            ASSERT_EQ(Q3Pixmap_ReadPNG(path.c_str(), type, order, &read), kQ3Success);
            ASSERT_NE(read.image, nullptr);
            EXPECT_EQ(read.width, source.width());
            EXPECT_EQ(read.height, source.height());
            EXPECT_EQ(read.rowBytes, source.width() * bitsOf(type) / 8);
            EXPECT_EQ(read.pixelSize, bitsOf(type));
            EXPECT_EQ(read.pixelType, type);
            EXPECT_EQ(read.byteOrder, order);
            EXPECT_EQ(read.bitOrder, order);
            long differing = 0;
            for (unsigned long y = 0; y < read.height; ++y)
                for (unsigned long x = 0; x < read.width; ++x)
                    differing += loadWord(read, x, y) != words[y * source.width() + x];
            EXPECT_EQ(differing, 0);

            // What another PNG reader sees: 8-bit channels, 5- and 6-bit ones
            // widened by bit replication, alpha only for the types that have it.
            unsigned char* rgba = nullptr;
            int width = 0, height = 0;
            ASSERT_EQ(q3png_read_rgba8(path.c_str(), &rgba, &width, &height), Q3PNG_OK);
            const std::uint32_t word = words[5];
            const Rgba seen{rgba[20], rgba[21], rgba[22], rgba[23]};
            const Rgba drawn = source.at(5, 0);
            EXPECT_EQ(seen.a, type == kQ3PixelTypeARGB32 || type == kQ3PixelTypeARGB16 ? drawn.a : 255);
            if (bitsOf(type) != 16) {
                EXPECT_EQ(seen.r, drawn.r);
                EXPECT_EQ(seen.g, drawn.g);
                EXPECT_EQ(seen.b, drawn.b);
            } else {
                const unsigned blue = word & 31u;
                EXPECT_EQ(seen.b, int((blue << 3) | (blue >> 2))) << std::hex << word;
            }
            std::free(rgba);
            EXPECT_EQ(Q3Pixmap_EmptyData(&read), kQ3Success);
            EXPECT_EQ(read.image, nullptr);
            std::remove(path.c_str());
        }
}

TEST_F(PixmapPNGApiTest, ADrawContextsImageIsWrittenAsDrawn)
{
    Pixmap image(160, 120, kQ3PixelTypeARGB32, kQ3EndianLittle);
    TestView view(image.pixmap());
    Listing1 listing;
    const TQ3NURBCurveData curve = listing.data();
    ASSERT_EQ(view.render([&](TQ3ViewObject v) { Q3NURBCurve_Submit(&curve, v); }), kQ3ViewStatusDone);

    const std::string path = scratch("drawn.png");
    ASSERT_EQ(Q3PixmapDrawContext_WritePNG(view.context(), path.c_str()), kQ3Success);
    unsigned char* rgba = nullptr;
    int width = 0, height = 0;
    ASSERT_EQ(q3png_read_rgba8(path.c_str(), &rgba, &width, &height), Q3PNG_OK);
    ASSERT_EQ(width, 160);
    ASSERT_EQ(height, 120);
    long differing = 0, lit = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const unsigned char* p = rgba + (std::size_t(y) * width + x) * 4;
            const Rgba c = image.at(x, y);
            differing += p[0] != c.r || p[1] != c.g || p[2] != c.b || p[3] != c.a;
            lit += image.lit(x, y);
        }
    std::free(rgba);
    EXPECT_EQ(differing, 0);
    EXPECT_GT(lit, 100);
    std::remove(path.c_str());
}

TEST_F(PixmapPNGApiTest, TheSamePixelsGiveTheSameFileBytes)
{
    Pixmap image(64, 48, kQ3PixelTypeRGB16_565, kQ3EndianBig);
    const std::string first = scratch("first.png");
    const std::string second = scratch("second.png");
    ASSERT_EQ(Q3Pixmap_WritePNG(&image.pixmap(), first.c_str()), kQ3Success);
    ASSERT_EQ(Q3Pixmap_WritePNG(&image.pixmap(), second.c_str()), kQ3Success);
    EXPECT_EQ(slurp(first), slurp(second));
    EXPECT_FALSE(slurp(first).empty());
    std::remove(first.c_str());
    std::remove(second.c_str());
}

TEST_F(PixmapPNGApiTest, AnRgbFileReadsOpaqueIntoAPixelTypeWithAlpha)
{
    const unsigned char rgb[2 * 3] = {10, 20, 30, 250, 128, 0};
    const std::string path = scratch("rgb.png");
    ASSERT_EQ(q3png_write_rgb8(path.c_str(), rgb, 2, 1, 6), Q3PNG_OK);
    TQ3Pixmap read{};
    ASSERT_EQ(Q3Pixmap_ReadPNG(path.c_str(), kQ3PixelTypeARGB32, kQ3EndianBig, &read), kQ3Success);
    EXPECT_EQ(loadWord(read, 0, 0), 0xFF0A141Eu);
    EXPECT_EQ(loadWord(read, 1, 0), 0xFFFA8000u);
    EXPECT_EQ(Q3Pixmap_EmptyData(&read), kQ3Success);
    std::remove(path.c_str());
}

TEST_F(PixmapPNGApiTest, WritingChecksItsArgumentsAndThePixmapRulesInOrder)
{
    Pixmap image(4, 4);
    const std::string path = scratch("never.png");
    EXPECT_Q3_ERROR(Q3Pixmap_WritePNG(nullptr, path.c_str()), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pixmap_WritePNG(&image.pixmap(), nullptr), kQ3ErrorNULLParameter);
    TQ3Pixmap broken = image.pixmap();
    broken.image = nullptr;
    EXPECT_Q3_ERROR(Q3Pixmap_WritePNG(&broken, path.c_str()), kQ3ErrorNULLParameter);
    broken = image.pixmap();
    broken.pixelType = static_cast<TQ3PixelType>(6);
    EXPECT_Q3_ERROR(Q3Pixmap_WritePNG(&broken, path.c_str()), kQ3ErrorInvalidData);
    broken = image.pixmap();
    broken.byteOrder = static_cast<TQ3Endian>(2);
    EXPECT_Q3_ERROR(Q3Pixmap_WritePNG(&broken, path.c_str()), kQ3ErrorInvalidData);
    broken = image.pixmap();
    broken.pixelSize = 16;
    EXPECT_Q3_ERROR(Q3Pixmap_WritePNG(&broken, path.c_str()), kQ3ErrorUnsupportedPixelDepth);
    broken = image.pixmap();
    broken.width = 0;
    EXPECT_Q3_ERROR(Q3Pixmap_WritePNG(&broken, path.c_str()), kQ3ErrorInvalidData);
    broken = image.pixmap();
    broken.rowBytes = 15;
    EXPECT_Q3_ERROR(Q3Pixmap_WritePNG(&broken, path.c_str()), kQ3ErrorInvalidData);
    // A height PNG cannot hold (a width cannot be above 2^31 - 1 with a
    // 32-bit rowBytes): refused before any pixel is read.
    broken = image.pixmap();
    broken.width = 1;
    broken.height = 0x80000000ul;
    EXPECT_Q3_ERROR(Q3Pixmap_WritePNG(&broken, path.c_str()), kQ3ErrorValueExceedsMaximumSize);
    EXPECT_FALSE(exists(path));
}

TEST_F(PixmapPNGApiTest, AFileThatCannotBeWrittenIsAnErrorAndLeavesNothing)
{
    Pixmap image(300, 200);
    const std::string missingFolder = scratch("no_such_folder") + "/out.png";
    EXPECT_Q3_ERROR(Q3Pixmap_WritePNG(&image.pixmap(), missingFolder.c_str()), kQ3ErrorFileNotOpen);
    EXPECT_NE(std::string(Q3Error_GetMessage()).find("No such file"), std::string::npos) << Q3Error_GetMessage();
    EXPECT_FALSE(exists(missingFolder));
    if (exists("/dev/full"))
        EXPECT_Q3_ERROR(Q3Pixmap_WritePNG(&image.pixmap(), "/dev/full"), kQ3ErrorWroteLessThanSize);
}

TEST_F(PixmapPNGApiTest, TheDrawContextFormChecksItsHandle)
{
    Pixmap image(4, 4);
    const std::string path = scratch("never.png");
    EXPECT_Q3_ERROR(Q3PixmapDrawContext_WritePNG(nullptr, path.c_str()), kQ3ErrorNULLParameter);
    const TQ3OrthographicCameraData cameraData = listing1OrthographicCamera();
    TQ3CameraObject camera = Q3OrthographicCamera_New(&cameraData);
    EXPECT_Q3_ERROR(Q3PixmapDrawContext_WritePNG(camera, path.c_str()), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(camera);
    const TQ3PixmapDrawContextData data = pixmapContextData(image.pixmap());
    TQ3DrawContextObject context = Q3PixmapDrawContext_New(&data);
    EXPECT_Q3_ERROR(Q3PixmapDrawContext_WritePNG(context, nullptr), kQ3ErrorNULLParameter);
    Q3Object_Dispose(context);
    EXPECT_Q3_ERROR(Q3PixmapDrawContext_WritePNG(context, path.c_str()), kQ3ErrorInvalidObject);
    EXPECT_FALSE(exists(path));
}

TEST_F(PixmapPNGApiTest, ReadingChecksItsArgumentsInOrderAndLeavesThePixmapUnchanged)
{
    Pixmap image(4, 4);
    const std::string path = scratch("good.png");
    ASSERT_EQ(Q3Pixmap_WritePNG(&image.pixmap(), path.c_str()), kQ3Success);
    TQ3Pixmap read;
    std::memset(&read, 0x77, sizeof read);
    const TQ3Pixmap before = read;
    EXPECT_Q3_ERROR(Q3Pixmap_ReadPNG(nullptr, kQ3PixelTypeARGB32, kQ3EndianBig, &read), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pixmap_ReadPNG(path.c_str(), kQ3PixelTypeARGB32, kQ3EndianBig, nullptr),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pixmap_ReadPNG(path.c_str(), static_cast<TQ3PixelType>(6), kQ3EndianBig, &read),
                    kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3Pixmap_ReadPNG(path.c_str(), static_cast<TQ3PixelType>(-1), kQ3EndianBig, &read),
                    kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3Pixmap_ReadPNG(path.c_str(), kQ3PixelTypeARGB32, static_cast<TQ3Endian>(2), &read),
                    kQ3ErrorInvalidParameter);
    // The argument checks come before the file is opened.
    EXPECT_Q3_ERROR(Q3Pixmap_ReadPNG("/nonexistent/x.png", static_cast<TQ3PixelType>(6), kQ3EndianBig, &read),
                    kQ3ErrorInvalidParameter);
    EXPECT_EQ(std::memcmp(&read, &before, sizeof read), 0);
    std::remove(path.c_str());
}

TEST_F(PixmapPNGApiTest, UnreadableFilesAreErrors)
{
    TQ3Pixmap read;
    std::memset(&read, 0x77, sizeof read);
    const TQ3Pixmap before = read;

    EXPECT_Q3_ERROR(Q3Pixmap_ReadPNG(scratch("missing.png").c_str(), kQ3PixelTypeARGB32, kQ3EndianBig, &read),
                    kQ3ErrorFileNotOpen);
    EXPECT_NE(std::string(Q3Error_GetMessage()).find("No such file"), std::string::npos) << Q3Error_GetMessage();

    const std::string text = scratch("text.png");
    writeFile(text, "this is not a PNG file at all");
    EXPECT_Q3_ERROR(Q3Pixmap_ReadPNG(text.c_str(), kQ3PixelTypeARGB32, kQ3EndianBig, &read), kQ3ErrorInvalidData);
    const std::string empty = scratch("empty.png");
    writeFile(empty, "");
    EXPECT_Q3_ERROR(Q3Pixmap_ReadPNG(empty.c_str(), kQ3PixelTypeARGB32, kQ3EndianBig, &read), kQ3ErrorInvalidData);

    // A valid file cut short, at several places.
    Pixmap image(40, 30, kQ3PixelTypeARGB32);
    for (unsigned long y = 0; y < 30; ++y)
        for (unsigned long x = 0; x < 40; ++x)
            storeWord(image.pixmap(), x, y, std::uint32_t(x * 2654435761u + y * 40503u));
    const std::string whole = scratch("whole.png");
    ASSERT_EQ(Q3Pixmap_WritePNG(&image.pixmap(), whole.c_str()), kQ3Success);
    const std::string bytes = slurp(whole);
    const std::string cut = scratch("cut.png");
    for (std::size_t keep : {std::size_t(12), std::size_t(40), bytes.size() / 2, bytes.size() - 13}) {
        SCOPED_TRACE("kept " + std::to_string(keep) + " bytes");
        writeFile(cut, bytes.substr(0, keep));
        EXPECT_Q3_ERROR(Q3Pixmap_ReadPNG(cut.c_str(), kQ3PixelTypeARGB32, kQ3EndianBig, &read), kQ3ErrorInvalidData);
    }
    EXPECT_EQ(std::memcmp(&read, &before, sizeof read), 0);
    for (const std::string& path : {text, empty, whole, cut})
        std::remove(path.c_str());
}

TEST_F(PixmapPNGApiTest, AnImageAboveTheLimitIsRefusedBeforeAllocating)
{
    // A header saying 20000 x 20000 (4e8 pixels > 2^28) and no pixel data:
    // the size is refused before the missing pixel data is noticed.
    auto be32 = [](std::uint32_t v) {
        return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    };
    std::string file("\x89PNG\r\n\x1a\n", 8);
    appendChunk(&file, "IHDR", be32(20000) + be32(20000) + std::string("\x08\x02\x00\x00\x00", 5));
    appendChunk(&file, "IDAT", "");
    appendChunk(&file, "IEND", "");
    const std::string path = scratch("huge.png");
    writeFile(path, file);
    TQ3Pixmap read{};
    EXPECT_Q3_ERROR(Q3Pixmap_ReadPNG(path.c_str(), kQ3PixelTypeRGB24, kQ3EndianBig, &read),
                    kQ3ErrorValueExceedsMaximumSize);
    EXPECT_EQ(read.image, nullptr);

    // Exactly at the limit's side length (16384 x 16384 = 2^28 pixels) the
    // size passes and the missing data is what fails.
    file.assign("\x89PNG\r\n\x1a\n", 8);
    appendChunk(&file, "IHDR", be32(16384) + be32(16384) + std::string("\x08\x02\x00\x00\x00", 5));
    appendChunk(&file, "IDAT", "");
    appendChunk(&file, "IEND", "");
    writeFile(path, file);
    EXPECT_Q3_ERROR(Q3Pixmap_ReadPNG(path.c_str(), kQ3PixelTypeRGB24, kQ3EndianBig, &read), kQ3ErrorInvalidData);
    std::remove(path.c_str());
}

TEST_F(PixmapPNGApiTest, EmptyDataFreesTheImageOnce)
{
    EXPECT_Q3_ERROR(Q3Pixmap_EmptyData(nullptr), kQ3ErrorNULLParameter);
    TQ3Pixmap empty{};
    EXPECT_EQ(Q3Pixmap_EmptyData(&empty), kQ3Success);
    EXPECT_EQ(empty.image, nullptr);
}

} // namespace
