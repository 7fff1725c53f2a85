// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// q3compare run as a golden-image test runs it: each exit status, the
// tolerance and pixel-count edges (exactly at the limit and one past), the
// summary line, the diff picture, different sizes and unreadable files.

#include "Golden.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

std::string scratch(const std::string& name)
{
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return std::string(::testing::TempDir()) + "q3compare_" + std::to_string(::getpid()) + "_" + info->name() +
           "_" + name;
}

std::string slurp(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct Outcome {
    int status = -1;
    std::string out;
    std::string err;
};

// Runs q3compare with the arguments; its exit status, standard output and
// standard error.
Outcome compare(const std::string& arguments)
{
    const std::string out = scratch("stdout.txt"), err = scratch("stderr.txt");
    const int raw = std::system((std::string(Q3_COMPARE_TOOL) + " " + arguments + " > " + out + " 2> " + err).c_str());
    Outcome outcome;
    outcome.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    outcome.out = slurp(out);
    outcome.err = slurp(err);
    std::remove(out.c_str());
    std::remove(err.c_str());
    return outcome;
}

// A 4 x 3 image of distinct opaque colours.
q3test::RgbaImage golden()
{
    q3test::RgbaImage image(4, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) {
            unsigned char* p = image.at(x, y);
            p[0] = static_cast<unsigned char>(40 * x + 10);
            p[1] = static_cast<unsigned char>(60 * y + 20);
            p[2] = 200;
            p[3] = 255;
        }
    return image;
}

class Q3Compare : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_golden = scratch("golden.png");
        m_actual = scratch("actual.png");
        ASSERT_TRUE(q3test::writePng(m_golden, golden()));
    }
    void TearDown() override
    {
        std::remove(m_golden.c_str());
        std::remove(m_actual.c_str());
    }
    // Writes the golden with green raised by `by` in the first `pixels`
    // pixels of the bottom row, from (0, 2).
    void writeActual(int by, int pixels = 1)
    {
        q3test::RgbaImage image = golden();
        for (int x = 0; x < pixels; ++x)
            image.at(x, 2)[1] = static_cast<unsigned char>(image.at(x, 2)[1] + by);
        ASSERT_TRUE(q3test::writePng(m_actual, image));
    }
    std::string files() const { return m_actual + " " + m_golden; }

    std::string m_golden, m_actual;
};

TEST_F(Q3Compare, IdenticalImagesMatchWithExitStatusZeroAndNoOutput)
{
    writeActual(0);
    const Outcome outcome = compare(files());
    EXPECT_EQ(outcome.status, 0) << outcome.out << outcome.err;
    EXPECT_EQ(outcome.out, "");
    EXPECT_EQ(outcome.err, "");
}

TEST_F(Q3Compare, OneChannelOffByOneIsAMismatchWithAOneLineSummary)
{
    writeActual(1);
    const Outcome outcome = compare(files());
    EXPECT_EQ(outcome.status, 1);
    EXPECT_EQ(outcome.out, "q3compare: " + m_actual + " differs from " + m_golden +
                               ": 1 of 12 pixels differ by more than 0 (0 allowed); largest difference 1 in G at "
                               "(0, 2)\n");
    EXPECT_EQ(outcome.err, "");
}

TEST_F(Q3Compare, AChannelDifferenceExactlyAtTheToleranceMatchesAndOnePastDoesNot)
{
    writeActual(7);
    EXPECT_EQ(compare(files() + " --tolerance 7").status, 0);
    const Outcome past = compare(files() + " --tolerance 6");
    EXPECT_EQ(past.status, 1);
    EXPECT_NE(past.out.find("1 of 12 pixels differ by more than 6"), std::string::npos) << past.out;
    EXPECT_NE(past.out.find("largest difference 7 in G at (0, 2)"), std::string::npos) << past.out;
    EXPECT_EQ(compare(files() + " --tolerance 255").status, 0);
}

TEST_F(Q3Compare, ExactlyMaxPixelsDifferingMatchesAndOneMoreDoesNot)
{
    writeActual(3, 3);
    EXPECT_EQ(compare(files() + " --max-pixels 3").status, 0);
    const Outcome past = compare(files() + " --max-pixels 2");
    EXPECT_EQ(past.status, 1);
    EXPECT_NE(past.out.find("3 of 12 pixels differ by more than 0 (2 allowed)"), std::string::npos) << past.out;
    // Both limits together: within the tolerance, no pixel counts.
    EXPECT_EQ(compare(files() + " --tolerance 3 --max-pixels 0").status, 0);
    EXPECT_EQ(compare(files() + " --tolerance 2 --max-pixels 2").status, 1);
}

TEST_F(Q3Compare, TheDiffShowsTheGoldenDimmedAndMarksDifferingPixels)
{
    writeActual(5, 2); // (0, 2) and (1, 2) differ by 5
    const std::string diffPath = scratch("diff.png");
    // Tolerance 4 and two pixels allowed: a match, and the diff is written all the same.
    EXPECT_EQ(compare(files() + " --tolerance 4 --max-pixels 2 --diff " + diffPath).status, 0);
    q3test::RgbaImage diff;
    ASSERT_TRUE(q3test::readPng(diffPath, &diff));
    ASSERT_EQ(diff.width, 4);
    ASSERT_EQ(diff.height, 3);
    const unsigned char* red = diff.at(0, 2);
    EXPECT_EQ(int(red[0]), 255);
    EXPECT_EQ(int(red[1]), 0);
    EXPECT_EQ(int(red[2]), 0);
    const unsigned char* same = diff.at(3, 0);
    const q3test::RgbaImage original = golden();
    const unsigned char* source = original.at(3, 0);
    EXPECT_EQ(int(same[0]), 96 + source[0] / 4);
    EXPECT_EQ(int(same[1]), 96 + source[1] / 4);
    EXPECT_EQ(int(same[2]), 96 + source[2] / 4);
    EXPECT_EQ(int(same[3]), 255);

    // Within a larger tolerance, a changed pixel is yellow rather than red.
    EXPECT_EQ(compare(files() + " --tolerance 5 --diff " + diffPath).status, 0);
    ASSERT_TRUE(q3test::readPng(diffPath, &diff));
    EXPECT_EQ(int(diff.at(1, 2)[0]), 255);
    EXPECT_EQ(int(diff.at(1, 2)[1]), 255);
    EXPECT_EQ(int(diff.at(1, 2)[2]), 0);
    std::remove(diffPath.c_str());
}

TEST_F(Q3Compare, ImagesOfDifferentSizesAreAnErrorWithExitStatusTwo)
{
    ASSERT_TRUE(q3test::writePng(m_actual, q3test::RgbaImage(4, 4)));
    const std::string diffPath = scratch("diff.png");
    const Outcome outcome = compare(files() + " --diff " + diffPath);
    EXPECT_EQ(outcome.status, 2);
    EXPECT_NE(outcome.err.find("different sizes: " + m_actual + " is 4 x 4, " + m_golden + " is 4 x 3"),
              std::string::npos)
        << outcome.err;
    EXPECT_EQ(outcome.out, "");
    EXPECT_NE(access(diffPath.c_str(), F_OK), 0) << "no diff is written when the images cannot be compared";
}

TEST_F(Q3Compare, AFileThatCannotBeReadIsAnErrorWithExitStatusTwo)
{
    const Outcome missing = compare(scratch("missing.png") + " " + m_golden);
    EXPECT_EQ(missing.status, 2);
    EXPECT_NE(missing.err.find("No such file"), std::string::npos) << missing.err;
    const Outcome missingGolden = compare(m_golden + " " + scratch("missing_golden.png"));
    EXPECT_EQ(missingGolden.status, 2);

    std::ofstream(m_actual) << "not a PNG file";
    const Outcome text = compare(files());
    EXPECT_EQ(text.status, 2);
    EXPECT_NE(text.err.find("not a PNG file"), std::string::npos) << text.err;

    // A diff that cannot be written is an error too.
    writeActual(0);
    EXPECT_EQ(compare(files() + " --diff " + scratch("no_such_folder") + "/diff.png").status, 2);
}

TEST_F(Q3Compare, BadArgumentsAreAnErrorWithExitStatusTwo)
{
    writeActual(0);
    for (const std::string& arguments :
         {m_actual, files() + " third.png", files() + " --tolerance", files() + " --tolerance 256",
          files() + " --tolerance -1", files() + " --tolerance 1.5", files() + " --max-pixels x",
          files() + " --diff", files() + " --frobnicate"}) {
        const Outcome outcome = compare(arguments);
        EXPECT_EQ(outcome.status, 2) << arguments;
        EXPECT_NE(outcome.err.find("usage: q3compare"), std::string::npos) << arguments;
    }
}

TEST_F(Q3Compare, HelpNamesEveryOptionAndTheExitStatusesOnStandardOutput)
{
    const Outcome outcome = compare("--help");
    EXPECT_EQ(outcome.status, 0);
    for (const char* text : {"--tolerance", "--max-pixels", "--diff", "--help", "0 match", "1 mismatch", "2 error"})
        EXPECT_NE(outcome.out.find(text), std::string::npos) << text;
}

} // namespace
