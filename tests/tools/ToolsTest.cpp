// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
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
    return std::string(::testing::TempDir()) + "q3tools_" + std::to_string(::getpid()) + "_" + name;
}

// Runs a command line; its exit status, and what it wrote to stderr.
int run(const std::string& command, std::string* errors = nullptr)
{
    const std::string log = scratch("stderr.txt");
    const int raw = std::system((command + " 2> " + log).c_str());
    if (errors != nullptr) {
        std::ifstream in(log);
        errors->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::remove(log.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

std::string slurp(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

const std::string kScene = std::string(Q3_TEST_DATA_DIR) + "/scene.3dmf";

} // namespace

TEST(Q3Render, DrawsTheSceneAsTheGoldenShows)
{
    const std::string png = scratch("scene.png");
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + kScene + " -o " + png + " --size 400x300"), 0);
    q3test::RgbaImage image;
    ASSERT_TRUE(q3test::readPng(png, &image));
    EXPECT_TRUE(q3test::matchesGolden("q3render_scene", image));
    std::remove(png.c_str());
}

TEST(Q3Render, TheBinaryFormOfTheSceneDrawsTheSameImage)
{
    const std::string binary = scratch("scene.bin.3dmf");
    const std::string fromText = scratch("text.png");
    const std::string fromBinary = scratch("binary.png");
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + kScene + " " + binary + " --binary"), 0);
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + kScene + " -o " + fromText + " --renderer wireframe"), 0);
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + binary + " -o " + fromBinary + " --renderer wireframe"), 0);
    q3test::RgbaImage a, b;
    ASSERT_TRUE(q3test::readPng(fromText, &a));
    ASSERT_TRUE(q3test::readPng(fromBinary, &b));
    EXPECT_EQ(q3test::countDifferingPixels(a, b), 0);
    for (const std::string& path : {binary, fromText, fromBinary})
        std::remove(path.c_str());
}

TEST(Q3Render, OptionsAreUsed)
{
    const std::string png = scratch("options.png");
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + kScene + " -o " + png +
                  " --size 64x48 --subdivision screen:4 --background 0,0,0"),
              0);
    q3test::RgbaImage image;
    ASSERT_TRUE(q3test::readPng(png, &image));
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 48);
    const unsigned char* corner = image.at(0, 0);
    EXPECT_EQ(corner[0], 0);
    EXPECT_EQ(corner[1], 0);
    EXPECT_EQ(corner[2], 0);
    std::remove(png.c_str());
}

TEST(Q3Render, AFileItCannotReadIsAClearMessageAndExitStatusTwo)
{
    std::string errors;
    EXPECT_EQ(run(std::string(Q3_RENDER_TOOL) + " /no/such/model.3dmf -o " + scratch("x.png"), &errors), 2);
    EXPECT_NE(errors.find("cannot open /no/such/model.3dmf"), std::string::npos) << errors;
    const std::string junk = scratch("junk.3dmf");
    std::ofstream(junk) << "this is not a metafile\n";
    EXPECT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + junk + " -o " + scratch("x.png"), &errors), 2);
    EXPECT_NE(errors.find("is not a 3DMF file"), std::string::npos) << errors;
    EXPECT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + kScene, &errors), 1);
    EXPECT_NE(errors.find("usage"), std::string::npos);
    std::remove(junk.c_str());
}

TEST(Q3Convert, TextToBinaryToTextGivesTheSameText)
{
    const std::string text1 = scratch("a.3dmf"), binary = scratch("b.3dmf"), text2 = scratch("c.3dmf");
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + kScene + " " + text1 + " --text"), 0);
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + text1 + " " + binary + " --binary"), 0);
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + binary + " " + text2 + " --text"), 0);
    EXPECT_EQ(slurp(binary).substr(0, 4), "3DMF");
    EXPECT_EQ(slurp(text1), slurp(text2));
    EXPECT_EQ(slurp(text1).rfind("3DMetafile ( 1 6 Normal", 0), 0u);
    std::string errors;
    EXPECT_EQ(run(std::string(Q3_CONVERT_TOOL) + " /no/such/file.3dmf " + text2, &errors), 2);
    EXPECT_NE(errors.find("cannot open"), std::string::npos);
    EXPECT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + kScene, &errors), 1);
    for (const std::string& path : {text1, binary, text2})
        std::remove(path.c_str());
}

TEST(Q3Convert, LittleEndianOptionWritesTheHandLaidLittleEndianFile)
{
    const std::string little = scratch("le.3dmf"), big = scratch("be.3dmf");
    const std::string data = std::string(Q3_TEST_DATA_DIR) + "/";
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + data + "references_be.3dmf " + little + " --little-endian"), 0);
    EXPECT_EQ(slurp(little), slurp(data + "references_le.3dmf"));
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + little + " " + big + " --binary"), 0);
    EXPECT_EQ(slurp(big), slurp(data + "references_be.3dmf"));
    for (const std::string& path : {little, big})
        std::remove(path.c_str());
}
