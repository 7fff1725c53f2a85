// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "FileCensus.h"
#include "Golden.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>
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

// The pixels of an image that are clearly one primary colour (the lit
// squares of camera_scene.3dmf) and their bounding box.
struct ColourArea {
    int count = 0, minX = 1 << 30, minY = 1 << 30, maxX = -1, maxY = -1;
};

ColourArea areaOf(const q3test::RgbaImage& image, int channel)
{
    ColourArea area;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const unsigned char* p = image.at(x, y);
            bool strong = p[channel] > 100;
            for (int c = 0; c < 3; ++c)
                strong = strong && (c == channel || p[c] < 60);
            if (!strong)
                continue;
            ++area.count;
            area.minX = std::min(area.minX, x);
            area.maxX = std::max(area.maxX, x);
            area.minY = std::min(area.minY, y);
            area.maxY = std::max(area.maxY, y);
        }
    return area;
}

TEST(Q3Render, AFilesCameraIsUsedWithTheImagesAspectUnlessFitCameraIsAsked)
{
    const std::string model = std::string(Q3_TEST_DATA_DIR) + "/camera_scene.3dmf";
    const std::string own = scratch("own_camera.png");
    const std::string fitted = scratch("fitted_camera.png");
    // --unlit: flat colours, so that a specular highlight cannot whiten part
    // of a square and move its measured edges.
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + model + " -o " + own + " --size 200x100 --unlit"), 0);
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + model + " -o " + fitted + " --size 200x100 --fit-camera --unlit"),
              0);
    q3test::RgbaImage a, b;
    ASSERT_TRUE(q3test::readPng(own, &a));
    ASSERT_TRUE(q3test::readPng(fitted, &b));
    // The file's camera, 4 units in front of the unit green square with a
    // vertical field of view of 0.5 radians, sees only that square, centred,
    // 100 * 0.5 / (4 tan 0.25) pixels high and, the aspect ratio matched to
    // the image's, as many wide (a camera left at aspect 1 would stretch it
    // to twice that width).
    const double side = 100 * 0.5 / (4 * std::tan(0.25));
    const ColourArea green = areaOf(a, 1);
    EXPECT_EQ(areaOf(a, 0).count, 0);
    ASSERT_GT(green.count, 0);
    EXPECT_NEAR(green.maxX - green.minX + 1, side, 2.0);
    EXPECT_NEAR(green.maxY - green.minY + 1, side, 2.0);
    EXPECT_NEAR((green.minX + green.maxX + 1) / 2.0, 100, 1.5);
    EXPECT_NEAR((green.minY + green.maxY + 1) / 2.0, 50, 1.5);
    // The fitted camera sees both squares, each far smaller.
    const ColourArea fittedGreen = areaOf(b, 1);
    EXPECT_GT(areaOf(b, 0).count, 0);
    EXPECT_GT(fittedGreen.count, 0);
    EXPECT_LT(fittedGreen.count * 4, green.count);
    for (const std::string& path : {own, fitted})
        std::remove(path.c_str());
}

TEST(Q3Render, AViewHintsCameraAndClearColourAreUsedWhenTheFileHasNoCamera)
{
    // hints_scene.3dmf is camera_scene.3dmf with the camera inside a
    // ViewHints that also gives a clear colour of (0.25, 0.5, 0.75).
    const std::string data = std::string(Q3_TEST_DATA_DIR) + "/";
    const std::string hinted = scratch("hinted.png"), white = scratch("hinted_white.png");
    const std::string own = scratch("own.png"), fitted = scratch("hinted_fitted.png");
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + data + "hints_scene.3dmf -o " + hinted + " --size 200x100"), 0);
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + data + "hints_scene.3dmf -o " + white +
                  " --size 200x100 --background 1,1,1"),
              0);
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + data + "camera_scene.3dmf -o " + own +
                  " --size 200x100 --background 1,1,1"),
              0);
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + data + "hints_scene.3dmf -o " + fitted +
                  " --size 200x100 --fit-camera"),
              0);
    q3test::RgbaImage a, b, c, d;
    ASSERT_TRUE(q3test::readPng(hinted, &a));
    ASSERT_TRUE(q3test::readPng(white, &b));
    ASSERT_TRUE(q3test::readPng(own, &c));
    ASSERT_TRUE(q3test::readPng(fitted, &d));
    // The hints' clear colour is the background unless --background is given.
    const unsigned char* corner = a.at(0, 0);
    EXPECT_NEAR(corner[0], 64, 1);
    EXPECT_NEAR(corner[1], 128, 1);
    EXPECT_NEAR(corner[2], 191, 1);
    EXPECT_EQ(b.at(0, 0)[0], 255);
    // Through the hints' camera, with the aspect handled as for a top-level
    // camera: the same image as camera_scene.3dmf's on the same background.
    EXPECT_EQ(q3test::countDifferingPixels(b, c), 0);
    EXPECT_EQ(areaOf(a, 0).count, 0);
    EXPECT_EQ(areaOf(a, 1).count, areaOf(c, 1).count);
    // --fit-camera still fits one to the whole model: both squares show.
    EXPECT_GT(areaOf(d, 0).count, 0);
    for (const std::string& path : {hinted, white, own, fitted})
        std::remove(path.c_str());
}

TEST(Q3Render, AFileWithNothingToDrawIsSaidSo)
{
    // A file holding a camera alone: the image is the background, and
    // stderr says why.
    const std::string model = scratch("camera_only.3dmf"), png = scratch("camera_only.png");
    std::ofstream(model) << "3DMetafile ( 1 6 Normal )\n"
                            "Container ( ViewAngleAspectCamera ( 0.5 1 ) CameraPlacement ( 0 0 4  0 0 0  0 1 0 )\n"
                            "  CameraRange ( 1 20 ) CameraViewPort ( -1 1 2 2 ) )\n";
    std::string errors;
    EXPECT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + model + " -o " + png + " --size 40x30", &errors), 0);
    EXPECT_NE(errors.find("nothing to draw"), std::string::npos) << errors;
    // A model with something to draw: nothing on stderr.
    EXPECT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + kScene + " -o " + png + " --size 40x30", &errors), 0);
    EXPECT_EQ(errors, "");
    for (const std::string& path : {model, png})
        std::remove(path.c_str());
}

TEST(Q3Render, HelpNamesEveryOptionOnStandardOutput)
{
    const std::string help = scratch("help.txt");
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " --help > " + help), 0);
    const std::string text = slurp(help);
    for (const char* option :
         {"-o", "--size", "--renderer", "--subdivision", "--background", "--fit-camera", "--unlit", "--help"})
        EXPECT_NE(text.find(option), std::string::npos) << option;
    for (const char* defaultNamed : {"ViewHints", "Phong", "0.5,0.5,0.5", "Exit status"})
        EXPECT_NE(text.find(defaultNamed), std::string::npos) << defaultNamed;
    std::remove(help.c_str());
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

TEST(Q3Convert, ToGlbAndGltfAndBackKeepsTheTexturedBox)
{
    const std::string model = std::string(Q3_TEST_DATA_DIR) + "/textured_box.3dmf";
    const std::string validator = std::string(Q3_TEST_DATA_DIR) + "/../../scripts/gltf-validate.js";
    for (const char* ext : {".glb", ".gltf", ".GLB"}) {
        const std::string gltf = scratch(std::string("box") + ext), back = scratch("box_back.3dmf");
        std::string errors;
        ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + model + " " + gltf + " --subdivision 4x", &errors), 0)
            << errors;
        EXPECT_EQ(run("node " + validator + " " + gltf + " > /dev/null", &errors), 0) << errors;
        ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + gltf + " " + back + " --text", &errors), 0) << errors;
        const std::string text = slurp(back);
        EXPECT_NE(text.find("TriMesh"), std::string::npos);
        EXPECT_NE(text.find("TextureShader"), std::string::npos);
        EXPECT_NE(text.find("MipmapTexture"), std::string::npos);
        // The box's 8 x 8 texels, orange E6B43C and blue 285AC8, opaque.
        EXPECT_NE(text.find("FFE6B43CFF285AC8"), std::string::npos);
        std::remove(gltf.c_str());
        std::remove(back.c_str());
    }
    // --format wins over the extension.
    const std::string forced = scratch("forced.bin");
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + model + " " + forced + " --format glb"), 0);
    EXPECT_EQ(slurp(forced).substr(0, 4), "glTF");
    std::remove(forced.c_str());
}

TEST(Q3Convert, ToObjAndStlAndBack)
{
    const std::string model = std::string(Q3_TEST_DATA_DIR) + "/textured_box.3dmf";
    const std::string obj = scratch("box.obj"), mtl = scratch("box.mtl"), png = scratch("box_0.png");
    const std::string stl = scratch("box.stl"), back = scratch("box_from.3dmf");
    std::string errors;
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + model + " " + obj + " --subdivision 2x", &errors), 0) << errors;
    EXPECT_NE(slurp(obj).find("mtllib"), std::string::npos);
    EXPECT_NE(slurp(mtl).find("map_Kd"), std::string::npos);
    EXPECT_EQ(slurp(png).substr(1, 3), "PNG");
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + obj + " " + back + " --text", &errors), 0) << errors;
    EXPECT_NE(slurp(back).find("MipmapTexture"), std::string::npos);
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + model + " " + stl + " --subdivision 2x", &errors), 0) << errors;
    // Binary STL: an 80-byte header, then the triangle count.
    EXPECT_GT(slurp(stl).size(), 84u);
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + stl + " " + back + " --text", &errors), 0) << errors;
    EXPECT_NE(slurp(back).find("TriMesh"), std::string::npos);
    // An OBJ without its material file is exit status 2, with the file named.
    std::remove(mtl.c_str());
    EXPECT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + obj + " " + back, &errors), 2);
    EXPECT_NE(errors.find("box.mtl"), std::string::npos) << errors;
    for (const std::string& path : {obj, png, stl, back})
        std::remove(path.c_str());
}

TEST(Q3Convert, ABrokenGltfIsExitStatusTwoAndAnUnwritableOutputThreeWithNothingLeft)
{
    const std::string broken = scratch("broken.gltf"), out = scratch("broken.3dmf");
    {
        std::ofstream file(broken);
        file << "{ \"asset\": { \"version\": \"2.0\" }, \"nodes\": [ { \"mesh\": 3 } ] ";
    }
    std::string errors;
    EXPECT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + broken + " " + out, &errors), 2);
    EXPECT_NE(errors.find("cannot be read"), std::string::npos) << errors;
    EXPECT_TRUE(slurp(out).empty());
    const std::string nowhere = scratch("no/such/dir/out.glb");
    EXPECT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + kScene + " " + nowhere, &errors), 3);
    EXPECT_NE(errors.find("cannot write"), std::string::npos) << errors;
    EXPECT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + kScene + " " + scratch("x.glb") + " --subdivision -1", &errors),
              1);
    EXPECT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + kScene + " " + scratch("x.glb") + " --format fbx", &errors), 1);
    std::remove(broken.c_str());
}

TEST(Q3Convert, AnObjectLeftOutIsNamedOnStandardError)
{
    // tests/data/unknown.3dmf holds an unknown text object, which has no
    // binary form.
    const std::string binary = scratch("unknown.bin.3dmf");
    std::string errors;
    EXPECT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + std::string(Q3_TEST_DATA_DIR) + "/unknown.3dmf " + binary +
                      " --binary",
                  &errors),
              0);
    EXPECT_NE(errors.find("warning"), std::string::npos) << errors;
    EXPECT_NE(errors.find("MyPrivateThing"), std::string::npos) << errors;
    EXPECT_NE(errors.find("left out"), std::string::npos) << errors;
    // Nothing to warn of: nothing on standard error.
    EXPECT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + kScene + " " + binary + " --binary", &errors), 0);
    EXPECT_EQ(errors, "");
    std::remove(binary.c_str());
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

namespace {

// Pixels whose colour is a scaled copy of (r, g, b): channel ratios within
// 0.08 of one another, between 0.2 and 1.2.
int pixelsLike(const q3test::RgbaImage& image, int r, int g, int b)
{
    int n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const unsigned char* p = image.at(x, y);
            const double ratios[3] = {p[0] / double(r), p[1] / double(g), p[2] / double(b)};
            const double lo = std::min({ratios[0], ratios[1], ratios[2]});
            const double hi = std::max({ratios[0], ratios[1], ratios[2]});
            if (hi - lo < 0.08 && lo > 0.2 && hi < 1.2)
                ++n;
        }
    return n;
}

} // namespace

TEST(Q3Render, ATexturedModelShowsItsTextureInsteadOfItsColour)
{
    // tests/data/textured_box.3dmf: a grey box under a texture shader with
    // an orange (230, 180, 60) and blue (40, 90, 200) checkerboard.
    const std::string model = std::string(Q3_TEST_DATA_DIR) + "/textured_box.3dmf";
    const std::string png = scratch("textured.png");
    // On white: the default mid-grey background would pass for the box's grey.
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + model + " -o " + png + " --size 200x150 --background 1,1,1"),
              0);
    q3test::RgbaImage image;
    ASSERT_TRUE(q3test::readPng(png, &image));
    EXPECT_GT(pixelsLike(image, 230, 180, 60), 1000);
    EXPECT_GT(pixelsLike(image, 40, 90, 200), 1000);
    EXPECT_EQ(pixelsLike(image, 128, 128, 128), 0) << "the box's grey shows through";
    std::remove(png.c_str());
}

namespace {

const std::string kLitSphere = std::string(Q3_TEST_DATA_DIR) + "/lit_sphere.3dmf";

// The grey of the default background, 0.5 in each channel.
bool isBackground(const unsigned char* p)
{
    return std::abs(p[0] - 128) <= 1 && std::abs(p[1] - 128) <= 1 && std::abs(p[2] - 128) <= 1;
}

double brightness(const unsigned char* p)
{
    return (p[0] + p[1] + p[2]) / 3.0;
}

// A pixel of the sphere's image and the normal there: tests/data/lit_sphere.3dmf's
// camera looks down -z at the unit sphere, so the image's x and y (y up) over the
// disc's radius are the normal's x and y, near enough for comparisons between
// pixels whose predicted brightness differs by a wide margin (the perspective of
// a camera 5 radii away moves the silhouette by a few percent of the radius).
struct SurfacePixel {
    double brightness;
    double nx, ny, nz;
};

std::vector<SurfacePixel> spherePixels(const q3test::RgbaImage& image)
{
    double sumX = 0, sumY = 0;
    int n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (!isBackground(image.at(x, y))) {
                sumX += x + 0.5;
                sumY += y + 0.5;
                ++n;
            }
    std::vector<SurfacePixel> pixels;
    if (n == 0)
        return pixels;
    const double cx = sumX / n, cy = sumY / n, radius = std::sqrt(n / 3.14159265358979);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double nx = (x + 0.5 - cx) / radius, ny = (cy - y - 0.5) / radius;
            const double r2 = nx * nx + ny * ny;
            if (r2 > 0.8 || isBackground(image.at(x, y)))
                continue; // the rim, where the estimate of the normal is poorest
            pixels.push_back({brightness(image.at(x, y)), nx, ny, std::sqrt(1 - r2)});
        }
    return pixels;
}

} // namespace

TEST(Q3Render, ByDefaultAModelWithoutLightsIsLitAndShadedOnMidGrey)
{
    const std::string png = scratch("lit_sphere.png");
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + kLitSphere + " -o " + png + " --size 200x200"), 0);
    q3test::RgbaImage image;
    ASSERT_TRUE(q3test::readPng(png, &image));
    EXPECT_TRUE(isBackground(image.at(0, 0)));
    EXPECT_TRUE(isBackground(image.at(199, 199)));
    const std::vector<SurfacePixel> pixels = spherePixels(image);
    ASSERT_GT(pixels.size(), 5000u);
    // q3render's default directional light travels along the view direction
    // (0, 0, -1) tilted by (-0.3, -0.5, 0): from over the viewer's right
    // shoulder. The Lambert term N.L (L towards the light) orders the pixels:
    // of two pixels whose N.L differ by more than 0.5, the one facing the
    // light more is the brighter (the Phong highlight only adds to the side
    // facing the light).
    const double len = std::sqrt(0.3 * 0.3 + 0.5 * 0.5 + 1.0);
    const double lx = 0.3 / len, ly = 0.5 / len, lz = 1.0 / len;
    auto facing = [&](const SurfacePixel& p) { return std::max(0.0, p.nx * lx + p.ny * ly + p.nz * lz); };
    int compared = 0, wrong = 0;
    for (size_t i = 0; i < pixels.size(); i += 37)
        for (size_t j = 0; j < pixels.size(); j += 41) {
            if (facing(pixels[i]) - facing(pixels[j]) <= 0.5)
                continue;
            ++compared;
            if (!(pixels[i].brightness > pixels[j].brightness + 10))
                ++wrong;
        }
    EXPECT_GT(compared, 1000);
    EXPECT_EQ(wrong, 0) << "of " << compared;
    // The brightest pixel is on the upper right (towards the light), the
    // darkest on the lower left; the spread is that of a lit surface.
    const auto [darkest, brightest] = std::minmax_element(
        pixels.begin(), pixels.end(),
        [](const SurfacePixel& a, const SurfacePixel& b) { return a.brightness < b.brightness; });
    EXPECT_GT(brightest->nx, 0);
    EXPECT_GT(brightest->ny, 0);
    EXPECT_LT(darkest->nx, 0);
    EXPECT_LT(darkest->ny, 0);
    EXPECT_GT(brightest->brightness - darkest->brightness, 80);
    std::remove(png.c_str());
}

TEST(Q3Render, UnlitGivesTheFlatDiffuseColourOnMidGrey)
{
    const std::string png = scratch("unlit_sphere.png");
    ASSERT_EQ(run(std::string(Q3_RENDER_TOOL) + " " + kLitSphere + " -o " + png + " --size 200x200 --unlit"), 0);
    q3test::RgbaImage image;
    ASSERT_TRUE(q3test::readPng(png, &image));
    // Every pixel is the background grey (0.5) or the sphere's diffuse grey
    // (0.6 -> 153), whatever way the surface faces.
    int sphere = 0, other = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const unsigned char* p = image.at(x, y);
            if (isBackground(p))
                continue;
            if (std::abs(p[0] - 153) <= 1 && std::abs(p[1] - 153) <= 1 && std::abs(p[2] - 153) <= 1)
                ++sphere;
            else
                ++other;
        }
    EXPECT_GT(sphere, 5000);
    EXPECT_EQ(other, 0);
    std::remove(png.c_str());
}

namespace {

// The options a program's --help names: every word that starts with one or
// two hyphens and a letter ("-o", "--size", "--help").
std::vector<std::string> optionsIn(const std::string& help)
{
    std::vector<std::string> options;
    for (size_t i = 0; i < help.size(); ++i) {
        const bool starts = help[i] == '-' && (i == 0 || std::string(" \t\n[|,").find(help[i - 1]) != std::string::npos);
        if (!starts)
            continue;
        size_t end = i;
        while (end < help.size() && (help[end] == '-' || std::isalnum(static_cast<unsigned char>(help[end]))))
            ++end;
        const std::string word = help.substr(i, end - i);
        const size_t hyphens = word.find_first_not_of('-');
        if (hyphens != std::string::npos && hyphens <= 2 && std::isalpha(static_cast<unsigned char>(word[hyphens])) &&
            std::find(options.begin(), options.end(), word) == options.end())
            options.push_back(word);
        i = end;
    }
    return options;
}

// A roff source with its escaped hyphens ("\-") plain.
std::string unescapedHyphens(std::string roff)
{
    for (size_t at = roff.find("\\-"); at != std::string::npos; at = roff.find("\\-", at))
        roff.erase(at, 1);
    return roff;
}

bool haveProgram(const std::string& name)
{
    return run("which " + name + " > /dev/null") == 0;
}

} // namespace

class ManPage : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(ManPage, ExistsFormatsWithoutWarningsAndNamesEveryOptionOfHelp)
{
    const std::string tool = GetParam().first, program = GetParam().second;
    const std::string page = std::string(Q3_MAN_DIR) + "/" + tool + ".1";
    const std::string roff = slurp(page);
    ASSERT_FALSE(roff.empty()) << page << " is missing";
    for (const char* section : {".TH", ".SH NAME", ".SH SYNOPSIS", ".SH DESCRIPTION", ".SH OPTIONS", ".SH EXIT STATUS",
                                ".SH EXAMPLES", ".SH SEE ALSO"})
        EXPECT_NE(roff.find(section), std::string::npos) << section;
    // Every option --help names is in the page.
    const std::string helpFile = scratch(tool + "_help.txt");
    ASSERT_EQ(run(program + " --help > " + helpFile), 0);
    const std::string help = slurp(helpFile);
    std::remove(helpFile.c_str());
    const std::vector<std::string> options = optionsIn(help);
    EXPECT_GE(options.size(), 4u) << help;
    const std::string text = unescapedHyphens(roff);
    for (const std::string& option : options)
        EXPECT_NE(text.find(option), std::string::npos) << option << " is in --help but not in " << page;
    // The exit statuses --help documents (those main returns), each in the page.
    const bool compare = tool == "q3compare";
    const std::vector<std::string> helpStatuses =
        compare ? std::vector<std::string>{"0 match", "1 mismatch", "2 error"}
                : std::vector<std::string>{"0 done", "1 bad arguments", "2 the", "3 "};
    for (const std::string& status : helpStatuses)
        EXPECT_NE(help.find(status), std::string::npos) << status;
    for (std::size_t status = 0; status < helpStatuses.size(); ++status)
        EXPECT_NE(roff.find(".B " + std::to_string(status) + "\n"), std::string::npos) << status;
    if (!haveProgram("groff")) {
        GTEST_SKIP() << "groff is not installed: the page's formatting is not checked";
    }
    // LC_ALL=C: the pages are ASCII, and man warns of a locale the machine
    // lacks before it reads the page.
    std::string warnings;
    EXPECT_EQ(run("LC_ALL=C groff -man -ww -z " + page, &warnings), 0);
    EXPECT_EQ(warnings, "");
    if (haveProgram("man")) {
        EXPECT_EQ(run("LC_ALL=C man --warnings -l " + page + " > /dev/null", &warnings), 0);
        EXPECT_EQ(warnings, "");
    }
}

INSTANTIATE_TEST_SUITE_P(Tools, ManPage,
                         ::testing::Values(std::make_pair("q3render", Q3_RENDER_TOOL),
                                           std::make_pair("q3convert", Q3_CONVERT_TOOL),
                                           std::make_pair("q3compare", Q3_COMPARE_TOOL)),
                         [](const auto& info) { return std::string(info.param.first); });

namespace {

// A test's name from its model's file name: the part before the dot, with
// every character GoogleTest does not allow made an underscore.
std::string modelTestName(const ::testing::TestParamInfo<const char*>& info)
{
    std::string name = info.param;
    name = name.substr(0, name.find('.'));
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch)))
            ch = '_';
    return name;
}

// Every text 3DMF file of tests/data, written by hand to hold one of each
// thing Q3 reads (unknown.3dmf aside: its unknown text object has no binary
// form, and a binary file leaves it out, docs/3dmf.md).
const char* const kTextModels[] = {"attributes.3dmf",     "camera_scene.3dmf",  "cameras.3dmf",
                                   "curves_quadrics.3dmf", "groups.3dmf",        "hints_scene.3dmf",
                                   "lights_styles.3dmf",  "lights_transforms_groups.3dmf", "lit_sphere.3dmf",
                                   "mesh.3dmf",           "nurbpatch.3dmf",     "part_sets.3dmf",
                                   "pixmap_marker.3dmf",  "polygons.3dmf",      "scene.3dmf",
                                   "styles_shaders.3dmf", "textured_box.3dmf",  "textures.3dmf",
                                   "view_hints.3dmf"};

} // namespace

class ConvertCensus : public ::testing::TestWithParam<const char*> {
protected:
    void SetUp() override { ASSERT_EQ(Q3Initialize(), kQ3Success); }
    void TearDown() override { Q3Exit(); }
};

TEST_P(ConvertCensus, TextToBinaryToTextLosesNothing)
{
    const std::string model = std::string(Q3_TEST_DATA_DIR) + "/" + GetParam();
    const std::string text1 = scratch("census_a.3dmf"), binary = scratch("census_b.3dmf");
    const std::string text2 = scratch("census_c.3dmf");
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + model + " " + text1 + " --text"), 0);
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + text1 + " " + binary + " --binary"), 0);
    ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + binary + " " + text2 + " --text"), 0);
    const q3test::Census original = q3test::censusOfFile(model);
    const q3test::Census a = q3test::censusOfFile(text1), b = q3test::censusOfFile(binary);
    const q3test::Census c = q3test::censusOfFile(text2);
    SCOPED_TRACE(q3test::censusText(original));
    EXPECT_EQ(original.failure, "");
    EXPECT_GT(original.topLevel, 0);
    EXPECT_TRUE(original == a) << "file -> text:\n" << q3test::censusDifference(original, a);
    EXPECT_TRUE(a == b) << "text -> binary:\n" << q3test::censusDifference(a, b);
    EXPECT_TRUE(b == c) << "binary -> text:\n" << q3test::censusDifference(b, c);
    for (const std::string& path : {text1, binary, text2})
        std::remove(path.c_str());
}

INSTANTIATE_TEST_SUITE_P(TestData, ConvertCensus, ::testing::ValuesIn(kTextModels), modelTestName);

// Every text 3DMF file of tests/data converts to .glb and .gltf that the
// Khronos validator passes with no errors, and reads back.
class ConvertGltf : public ::testing::TestWithParam<const char*> {};

TEST_P(ConvertGltf, EveryTestModelGivesAValidGlbAndGltf)
{
    const std::string model = std::string(Q3_TEST_DATA_DIR) + "/" + GetParam();
    const std::string validator = std::string(Q3_TEST_DATA_DIR) + "/../../scripts/gltf-validate.js";
    for (const char* ext : {".glb", ".gltf"}) {
        const std::string out = scratch(std::string("census") + ext), back = scratch("census_back.3dmf");
        std::string errors;
        ASSERT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + model + " " + out + " --subdivision 8x", &errors), 0)
            << errors;
        EXPECT_EQ(run("node " + validator + " " + out + " > " + scratch("report.txt"), &errors), 0)
            << slurp(scratch("report.txt")) << errors;
        EXPECT_EQ(run(std::string(Q3_CONVERT_TOOL) + " " + out + " " + back, &errors), 0) << errors;
        for (const std::string& path : {out, back, scratch("report.txt")})
            std::remove(path.c_str());
    }
}

INSTANTIATE_TEST_SUITE_P(TestData, ConvertGltf, ::testing::ValuesIn(kTextModels), modelTestName);
