// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The golden-image comparison itself (tests/support/Golden.h), on images
// made here, in a scratch folder of the build tree.

#include "Golden.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

using q3test::GoldenSettings;
using q3test::RgbaImage;

namespace fs = std::filesystem;

/// A white image with a dark diagonal line, like a figure.
RgbaImage sample(int shift = 0)
{
    RgbaImage image(40, 30);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            unsigned char* p = image.at(x, y);
            const bool ink = x == y + shift + 5;
            p[0] = p[1] = p[2] = ink ? 20 : 255;
            p[3] = 255;
        }
    }
    return image;
}

std::string readBytes(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

class Golden : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_root = fs::path(Q3_TEST_SCRATCH_DIR) / info->name();
        fs::remove_all(m_root);
        fs::create_directories(m_root / "golden");
        m_settings.goldenDir = (m_root / "golden").string();
        m_settings.failureDir = (m_root / "failures").string();
        m_settings.update = false;
    }

    fs::path m_root;
    GoldenSettings m_settings;
};

TEST_F(Golden, IdenticalImageMatches)
{
    ASSERT_TRUE(q3test::writePng(m_settings.goldenDir + "/line.png", sample()));
    EXPECT_TRUE(q3test::matchesGolden("line", sample(), m_settings));
    EXPECT_FALSE(fs::exists(m_settings.failureDir));
}

TEST_F(Golden, UpToFourDifferingPixelsAreTolerated)
{
    ASSERT_TRUE(q3test::writePng(m_settings.goldenDir + "/line.png", sample()));
    RgbaImage image = sample();
    for (int i = 0; i < q3test::kGoldenMaxDifferingPixels; ++i)
        image.at(30 + i, 2)[1] ^= 1;  // one step in one channel
    EXPECT_TRUE(q3test::matchesGolden("line", image, m_settings));
}

TEST_F(Golden, FiveDifferingPixelsFailAndLeaveActualExpectedAndDiff)
{
    ASSERT_TRUE(q3test::writePng(m_settings.goldenDir + "/line.png", sample()));
    RgbaImage image = sample();
    for (int i = 0; i <= q3test::kGoldenMaxDifferingPixels; ++i)
        image.at(30 + i, 2)[3] = 254;  // alpha counts too
    const ::testing::AssertionResult result = q3test::matchesGolden("line", image, m_settings);
    EXPECT_FALSE(result);
    const std::string message = result.message();
    for (const char* suffix : {".actual.png", ".expected.png", ".diff.png"}) {
        const fs::path path = fs::path(m_settings.failureDir) / (std::string("line") + suffix);
        EXPECT_TRUE(fs::exists(path)) << path;
        EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    }
    RgbaImage diff;
    ASSERT_TRUE(q3test::readPng(m_settings.failureDir + "/line.diff.png", &diff));
    const unsigned char* marked = diff.at(30, 2);
    EXPECT_EQ(marked[0], 255);
    EXPECT_EQ(marked[1], 0);
    EXPECT_EQ(marked[2], 0);
}

TEST_F(Golden, AMatchRemovesTheImagesOfAnEarlierMismatch)
{
    ASSERT_TRUE(q3test::writePng(m_settings.goldenDir + "/line.png", sample()));
    EXPECT_FALSE(q3test::matchesGolden("line", sample(1), m_settings));
    ASSERT_TRUE(fs::exists(fs::path(m_settings.failureDir) / "line.diff.png"));
    EXPECT_TRUE(q3test::matchesGolden("line", sample(), m_settings));
    EXPECT_FALSE(fs::exists(fs::path(m_settings.failureDir) / "line.actual.png"));
    EXPECT_FALSE(fs::exists(fs::path(m_settings.failureDir) / "line.expected.png"));
    EXPECT_FALSE(fs::exists(fs::path(m_settings.failureDir) / "line.diff.png"));
}

TEST_F(Golden, OnePixelShiftFails)
{
    ASSERT_TRUE(q3test::writePng(m_settings.goldenDir + "/line.png", sample()));
    EXPECT_FALSE(q3test::matchesGolden("line", sample(1), m_settings));
}

TEST_F(Golden, SizeMismatchFails)
{
    ASSERT_TRUE(q3test::writePng(m_settings.goldenDir + "/line.png", sample()));
    EXPECT_FALSE(q3test::matchesGolden("line", RgbaImage(40, 31), m_settings));
}

TEST_F(Golden, MissingGoldenFailsAndLeavesTheActualImage)
{
    const ::testing::AssertionResult result = q3test::matchesGolden("absent", sample(), m_settings);
    EXPECT_FALSE(result);
    EXPECT_NE(std::string(result.message()).find("missing"), std::string::npos);
    EXPECT_TRUE(fs::exists(fs::path(m_settings.failureDir) / "absent.actual.png"));
    EXPECT_FALSE(fs::exists(fs::path(m_settings.goldenDir) / "absent.png"));
}

TEST_F(Golden, UpdateCreatesMissingAndRewritesOnlyChangedGoldens)
{
    m_settings.update = true;
    EXPECT_TRUE(q3test::matchesGolden("created", sample(), m_settings));
    RgbaImage created;
    ASSERT_TRUE(q3test::readPng(m_settings.goldenDir + "/created.png", &created));
    EXPECT_EQ(q3test::countDifferingPixels(created, sample()), 0);

    // Unchanged pixels: the file is not touched at all.
    const fs::path unchanged = fs::path(m_settings.goldenDir) / "created.png";
    const auto stamp = fs::last_write_time(unchanged);
    fs::last_write_time(unchanged, stamp - std::chrono::hours(1));
    const auto older = fs::last_write_time(unchanged);
    const std::string bytes = readBytes(unchanged);
    EXPECT_TRUE(q3test::matchesGolden("created", sample(), m_settings));
    EXPECT_EQ(fs::last_write_time(unchanged), older);
    EXPECT_EQ(readBytes(unchanged), bytes);

    // Changed pixels (even one, within the tolerance): rewritten.
    RgbaImage changed = sample();
    changed.at(0, 0)[0] = 0;
    EXPECT_TRUE(q3test::matchesGolden("created", changed, m_settings));
    RgbaImage rewritten;
    ASSERT_TRUE(q3test::readPng(unchanged.string(), &rewritten));
    EXPECT_EQ(q3test::countDifferingPixels(rewritten, changed), 0);

    // Writing the same pixels twice gives the same bytes (q3png is
    // deterministic), so a rewrite never churns a golden.
    ASSERT_TRUE(q3test::writePng((m_root / "again.png").string(), changed));
    EXPECT_EQ(readBytes(m_root / "again.png"), readBytes(unchanged));
}

} // namespace
