// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "q3png.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

// A path in the test temp directory, unique per process and test.
std::string tempPath(const std::string& stem)
{
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return ::testing::TempDir() + "q3png_" + std::to_string(getpid()) + "_" + info->name() + "_" + stem;
}

std::vector<unsigned char> fileBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool fileExists(const std::string& path)
{
    return access(path.c_str(), F_OK) == 0;
}

// width x height RGBA with padding bytes between rows, filled with a pattern.
std::vector<unsigned char> makeRgba(int width, int height, int rowBytes)
{
    std::vector<unsigned char> pixels(std::size_t(rowBytes) * height, 0xEE);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width * 4; ++x)
            pixels[std::size_t(y) * rowBytes + x] = static_cast<unsigned char>(x * 7 + y * 31 + (x >> 2));
    return pixels;
}

class ScopedFile {
public:
    explicit ScopedFile(std::string path) : m_path(std::move(path)) {}
    ~ScopedFile() { std::remove(m_path.c_str()); }
    const char* c_str() const { return m_path.c_str(); }
    const std::string& path() const { return m_path; }

private:
    std::string m_path;
};

// The file read with q3png_read_rgba8, which must succeed with a width x
// height image: its width * height * 4 bytes, or none when it fails.
std::vector<unsigned char> readRgba(const ScopedFile& file, int width, int height)
{
    unsigned char* read = nullptr;
    int readWidth = 0;
    int readHeight = 0;
    EXPECT_EQ(q3png_read_rgba8(file.c_str(), &read, &readWidth, &readHeight), Q3PNG_OK);
    EXPECT_NE(read, nullptr);
    EXPECT_EQ(readWidth, width);
    EXPECT_EQ(readHeight, height);
    std::vector<unsigned char> pixels;
    if (read != nullptr && readWidth == width && readHeight == height)
        pixels.assign(read, read + std::size_t(width) * height * 4);
    std::free(read);
    return pixels;
}

TEST(PngFile, RgbaWriteThenReadRoundTrips)
{
    const int width = 17;
    const int height = 9;
    const int rowBytes = width * 4 + 6;
    const std::vector<unsigned char> pixels = makeRgba(width, height, rowBytes);
    ScopedFile file(tempPath("rgba.png"));
    ASSERT_EQ(q3png_write_rgba8(file.c_str(), pixels.data(), width, height, rowBytes), Q3PNG_OK);

    const std::vector<unsigned char> read = readRgba(file, width, height);
    ASSERT_EQ(read.size(), std::size_t(width) * height * 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width * 4; ++x)
            ASSERT_EQ(read[y * width * 4 + x], pixels[std::size_t(y) * rowBytes + x]) << x << "," << y;
}

TEST(PngFile, RgbWriteReadsBackOpaque)
{
    const int width = 5;
    const int height = 3;
    std::vector<unsigned char> rgb(width * height * 3);
    for (std::size_t i = 0; i < rgb.size(); ++i)
        rgb[i] = static_cast<unsigned char>(i * 13);
    ScopedFile file(tempPath("rgb.png"));
    ASSERT_EQ(q3png_write_rgb8(file.c_str(), rgb.data(), width, height, width * 3), Q3PNG_OK);

    const std::vector<unsigned char> read = readRgba(file, width, height);
    ASSERT_EQ(read.size(), std::size_t(width) * height * 4);
    for (int i = 0; i < width * height; ++i) {
        EXPECT_EQ(read[i * 4 + 0], rgb[i * 3 + 0]);
        EXPECT_EQ(read[i * 4 + 1], rgb[i * 3 + 1]);
        EXPECT_EQ(read[i * 4 + 2], rgb[i * 3 + 2]);
        EXPECT_EQ(read[i * 4 + 3], 255);
    }
}

TEST(PngFile, RewritingIdenticalPixelsIsByteIdentical)
{
    const std::vector<unsigned char> pixels = makeRgba(31, 23, 31 * 4);
    ScopedFile first(tempPath("a.png"));
    ScopedFile second(tempPath("b.png"));
    ASSERT_EQ(q3png_write_rgba8(first.c_str(), pixels.data(), 31, 23, 31 * 4), Q3PNG_OK);
    ASSERT_EQ(q3png_write_rgba8(second.c_str(), pixels.data(), 31, 23, 31 * 4), Q3PNG_OK);
    const std::vector<unsigned char> a = fileBytes(first.path());
    const std::vector<unsigned char> b = fileBytes(second.path());
    ASSERT_FALSE(a.empty());
    EXPECT_EQ(a, b);
    // Only IHDR, IDAT and IEND: in particular no tIME chunk.
    const std::string text(a.begin(), a.end());
    EXPECT_EQ(text.find("tIME"), std::string::npos);
    EXPECT_EQ(text.find("tEXt"), std::string::npos);
    EXPECT_EQ(text.find("gAMA"), std::string::npos);
}

// Writes a PNG of one row, `width` pixels of `bitDepth` and `colorType`,
// directly with libpng; `chunks` adds what the type needs before the row.
template <class Chunks>
bool writeOneRowPng(const char* path, png_uint_32 width, int bitDepth, int colorType, unsigned char* row, Chunks chunks)
{
    FILE* out = std::fopen(path, "wb");
    if (out == nullptr)
        return false;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, out);
    png_set_IHDR(png, info, width, 1, bitDepth, colorType, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    chunks(png, info);
    png_write_info(png, info);
    png_write_row(png, row);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(out);
    return true;
}

TEST(PngFile, ReadsGrayAndPalettePngsAsRgba)
{
    ScopedFile gray(tempPath("gray.png"));
    ScopedFile palette(tempPath("palette.png"));
    // 16-bit gray written directly with libpng: read keeps the high byte.
    unsigned char grayRow[4] = {0x12, 0x34, 0xFE, 0xDC};
    ASSERT_TRUE(writeOneRowPng(gray.c_str(), 2, 16, PNG_COLOR_TYPE_GRAY, grayRow, [](png_structp, png_infop) {}));
    // 2-bit palette with a transparent entry.
    unsigned char paletteRow[1] = {static_cast<unsigned char>((2 << 6) | (1 << 4) | (0 << 2))};
    ASSERT_TRUE(writeOneRowPng(palette.c_str(), 3, 2, PNG_COLOR_TYPE_PALETTE, paletteRow,
                               [](png_structp png, png_infop info) {
                                   png_color colors[3] = {{10, 20, 30}, {40, 50, 60}, {70, 80, 90}};
                                   png_set_PLTE(png, info, colors, 3);
                                   png_byte alpha[2] = {255, 0};
                                   png_set_tRNS(png, info, alpha, 2, nullptr);
                               }));

    unsigned char* read = nullptr;
    int width = 0;
    int height = 0;
    ASSERT_EQ(q3png_read_rgba8(gray.c_str(), &read, &width, &height), Q3PNG_OK);
    ASSERT_EQ(width, 2);
    ASSERT_EQ(height, 1);
    const std::vector<unsigned char> grayExpected{0x12, 0x12, 0x12, 255, 0xFE, 0xFE, 0xFE, 255};
    EXPECT_EQ(std::vector<unsigned char>(read, read + 8), grayExpected);
    std::free(read);

    ASSERT_EQ(q3png_read_rgba8(palette.c_str(), &read, &width, &height), Q3PNG_OK);
    ASSERT_EQ(width, 3);
    const std::vector<unsigned char> paletteExpected{70, 80, 90, 255, 40, 50, 60, 0, 10, 20, 30, 255};
    EXPECT_EQ(std::vector<unsigned char>(read, read + 12), paletteExpected);
    std::free(read);
}

TEST(PngFile, WriteToUnwritablePathFails)
{
    const std::vector<unsigned char> pixels = makeRgba(2, 2, 8);
    const char* path = "/nonexistent-q3-directory/out.png";
    EXPECT_EQ(q3png_write_rgba8(path, pixels.data(), 2, 2, 8), Q3PNG_ERROR_OPEN);
    EXPECT_EQ(q3png_write_rgb8(path, pixels.data(), 2, 2, 6), Q3PNG_ERROR_OPEN);
    EXPECT_FALSE(fileExists(path));
}

TEST(PngFile, WriteFailureReportsErrorAndKeepsDeviceFiles)
{
    // /dev/full accepts open() and fails every write with ENOSPC. The failed
    // write must be reported, and the device node must not be "cleaned up".
    const char* path = "/dev/full";
    if (!fileExists(path))
        GTEST_SKIP() << "no /dev/full here";
    const std::vector<unsigned char> small = makeRgba(2, 2, 8);
    EXPECT_EQ(q3png_write_rgba8(path, small.data(), 2, 2, 8), Q3PNG_ERROR_WRITE);
    const std::vector<unsigned char> large = makeRgba(300, 200, 1200);
    EXPECT_EQ(q3png_write_rgba8(path, large.data(), 300, 200, 1200), Q3PNG_ERROR_WRITE);
    EXPECT_TRUE(fileExists(path));
}

TEST(PngFile, ReadMissingFileFailsWithoutTouchingOutputs)
{
    unsigned char sentinel = 0;
    unsigned char* read = &sentinel;
    int width = -7;
    int height = -7;
    EXPECT_EQ(q3png_read_rgba8(tempPath("missing.png").c_str(), &read, &width, &height), Q3PNG_ERROR_OPEN);
    EXPECT_EQ(read, &sentinel);
    EXPECT_EQ(width, -7);
    EXPECT_EQ(height, -7);
}

TEST(PngFile, ReadNonPngFileFails)
{
    ScopedFile file(tempPath("text.png"));
    {
        std::ofstream out(file.path(), std::ios::binary);
        out << "this is not a PNG file, just some text";
    }
    unsigned char* read = nullptr;
    int width = 0;
    int height = 0;
    EXPECT_EQ(q3png_read_rgba8(file.c_str(), &read, &width, &height), Q3PNG_ERROR_NOT_PNG);
    EXPECT_EQ(read, nullptr);

    ScopedFile empty(tempPath("empty.png"));
    { std::ofstream out(empty.path(), std::ios::binary); }
    EXPECT_EQ(q3png_read_rgba8(empty.c_str(), &read, &width, &height), Q3PNG_ERROR_NOT_PNG);
    EXPECT_EQ(read, nullptr);
}

TEST(PngFile, ReadTruncatedPngFails)
{
    const std::vector<unsigned char> pixels = makeRgba(40, 30, 160);
    ScopedFile file(tempPath("whole.png"));
    ASSERT_EQ(q3png_write_rgba8(file.c_str(), pixels.data(), 40, 30, 160), Q3PNG_OK);
    std::vector<unsigned char> bytes = fileBytes(file.path());
    ASSERT_GT(bytes.size(), 60u);
    for (std::size_t keep : {std::size_t(12), std::size_t(40), bytes.size() / 2, bytes.size() - 13}) {
        ScopedFile cut(tempPath("cut.png"));
        {
            std::ofstream out(cut.path(), std::ios::binary);
            out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(keep));
        }
        unsigned char* read = nullptr;
        int width = 0;
        int height = 0;
        EXPECT_EQ(q3png_read_rgba8(cut.c_str(), &read, &width, &height), Q3PNG_ERROR_FORMAT) << keep;
        EXPECT_EQ(read, nullptr);
    }
}

TEST(PngFile, InvalidArgumentsAreRejected)
{
    const std::vector<unsigned char> pixels = makeRgba(4, 4, 16);
    const std::string path = tempPath("never.png");
    EXPECT_EQ(q3png_write_rgba8(nullptr, pixels.data(), 4, 4, 16), Q3PNG_ERROR_ARGUMENT);
    EXPECT_EQ(q3png_write_rgba8(path.c_str(), nullptr, 4, 4, 16), Q3PNG_ERROR_ARGUMENT);
    EXPECT_EQ(q3png_write_rgba8(path.c_str(), pixels.data(), 0, 4, 16), Q3PNG_ERROR_ARGUMENT);
    EXPECT_EQ(q3png_write_rgba8(path.c_str(), pixels.data(), 4, -1, 16), Q3PNG_ERROR_ARGUMENT);
    EXPECT_EQ(q3png_write_rgba8(path.c_str(), pixels.data(), 4, 4, 15), Q3PNG_ERROR_ARGUMENT);
    EXPECT_EQ(q3png_write_rgb8(path.c_str(), pixels.data(), 4, 4, 11), Q3PNG_ERROR_ARGUMENT);
    EXPECT_FALSE(fileExists(path));

    unsigned char* read = nullptr;
    int width = 0;
    int height = 0;
    EXPECT_EQ(q3png_read_rgba8(nullptr, &read, &width, &height), Q3PNG_ERROR_ARGUMENT);
    EXPECT_EQ(q3png_read_rgba8(path.c_str(), nullptr, &width, &height), Q3PNG_ERROR_ARGUMENT);
    EXPECT_EQ(q3png_read_rgba8(path.c_str(), &read, nullptr, &height), Q3PNG_ERROR_ARGUMENT);
    EXPECT_EQ(q3png_read_rgba8(path.c_str(), &read, &width, nullptr), Q3PNG_ERROR_ARGUMENT);

    EXPECT_STREQ(q3png_error_string(Q3PNG_OK), "success");
    EXPECT_STREQ(q3png_error_string(Q3PNG_ERROR_NOT_PNG), "not a PNG file");
    EXPECT_STREQ(q3png_error_string(99), "unknown error");
}

} // namespace
