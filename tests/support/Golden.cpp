// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "Golden.h"

#include "q3png.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <system_error>

#ifndef Q3_GOLDEN_DIR
#error "Q3_GOLDEN_DIR must name tests/golden"
#endif
#ifndef Q3_GOLDEN_FAILURE_DIR
#error "Q3_GOLDEN_FAILURE_DIR must name the folder for mismatch images"
#endif

namespace q3test {

namespace {

void setRgb(unsigned char* pixel, unsigned char r, unsigned char g, unsigned char b)
{
    pixel[0] = r;
    pixel[1] = g;
    pixel[2] = b;
}

/// Differing pixels in red over the expected image faded towards white; where
/// only one image has pixels (sizes differ), magenta.
RgbaImage diffImage(const RgbaImage& actual, const RgbaImage& expected)
{
    RgbaImage diff(std::max(actual.width, expected.width), std::max(actual.height, expected.height));
    for (int y = 0; y < diff.height; ++y) {
        for (int x = 0; x < diff.width; ++x) {
            unsigned char* out = diff.at(x, y);
            const bool inActual = x < actual.width && y < actual.height;
            const bool inExpected = x < expected.width && y < expected.height;
            out[3] = 255;
            if (!inActual || !inExpected) {
                setRgb(out, 255, 0, 255);
                continue;
            }
            const unsigned char* a = actual.at(x, y);
            const unsigned char* e = expected.at(x, y);
            if (std::memcmp(a, e, 4) != 0) {
                setRgb(out, 255, 0, 0);
            } else {
                const int gray = (e[0] * 3 + e[1] * 6 + e[2]) / 10;
                const auto faded = static_cast<unsigned char>(192 + gray / 4);
                setRgb(out, faded, faded, faded);
            }
        }
    }
    return diff;
}

std::string joinPath(const std::string& dir, const std::string& file)
{
    return (std::filesystem::path(dir) / file).string();
}

/// Removes the images an earlier mismatch of this name left behind.
void removeStaleFailure(const GoldenSettings& settings, const std::string& name)
{
    std::error_code ignored;
    for (const char* suffix : {".actual.png", ".expected.png", ".diff.png"})
        std::filesystem::remove(joinPath(settings.failureDir, name + suffix), ignored);
}

} // namespace

GoldenSettings goldenSettings()
{
    GoldenSettings settings;
    settings.goldenDir = Q3_GOLDEN_DIR;
    settings.failureDir = Q3_GOLDEN_FAILURE_DIR;
    const char* update = std::getenv("UPDATE_GOLDENS");
    settings.update = update != nullptr && std::strcmp(update, "1") == 0;
    return settings;
}

long countDifferingPixels(const RgbaImage& a, const RgbaImage& b)
{
    if (a.width != b.width || a.height != b.height)
        return -1;
    long count = 0;
    for (std::size_t i = 0; i < a.pixels.size(); i += 4) {
        if (std::memcmp(&a.pixels[i], &b.pixels[i], 4) != 0)
            ++count;
    }
    return count;
}

bool readPng(const std::string& path, RgbaImage* image)
{
    unsigned char* rgba = nullptr;
    int width = 0, height = 0;
    if (q3png_read_rgba8(path.c_str(), &rgba, &width, &height) != Q3PNG_OK)
        return false;
    image->width = width;
    image->height = height;
    image->pixels.assign(rgba, rgba + std::size_t(width) * std::size_t(height) * 4);
    std::free(rgba);
    return true;
}

bool writePng(const std::string& path, const RgbaImage& image)
{
    return q3png_write_rgba8(path.c_str(), image.pixels.data(), image.width, image.height,
                             image.width * 4) == Q3PNG_OK;
}

::testing::AssertionResult matchesGolden(const std::string& name, const RgbaImage& image,
                                         const GoldenSettings& settings)
{
    const std::string goldenPath = joinPath(settings.goldenDir, name + ".png");
    RgbaImage expected;
    const bool haveGolden = std::filesystem::exists(goldenPath) && readPng(goldenPath, &expected);
    const long differing = haveGolden ? countDifferingPixels(image, expected) : -1;

    if (settings.update) {
        removeStaleFailure(settings, name);
        if (haveGolden && differing == 0)
            return ::testing::AssertionSuccess() << name << ": golden unchanged";
        std::error_code ignored;
        std::filesystem::create_directories(settings.goldenDir, ignored);
        if (!writePng(goldenPath, image))
            return ::testing::AssertionFailure() << "UPDATE_GOLDENS: cannot write " << goldenPath;
        std::cout << "[ GOLDEN   ] " << (haveGolden ? "updated " : "created ") << goldenPath << "\n";
        return ::testing::AssertionSuccess() << name << ": golden written";
    }

    if (haveGolden && differing >= 0 && differing <= settings.maxDifferingPixels) {
        removeStaleFailure(settings, name);
        return ::testing::AssertionSuccess() << name << ": " << differing << " pixels differ";
    }

    std::error_code error;
    std::filesystem::create_directories(settings.failureDir, error);
    const std::string actualPath = joinPath(settings.failureDir, name + ".actual.png");
    std::ostringstream message;
    bool wrote = writePng(actualPath, image);
    if (!haveGolden) {
        message << "golden image " << goldenPath
                << " is missing or unreadable (run the test with UPDATE_GOLDENS=1 to create it"
                << " after checking the image); actual image: " << actualPath;
    } else {
        const std::string expectedPath = joinPath(settings.failureDir, name + ".expected.png");
        const std::string diffPath = joinPath(settings.failureDir, name + ".diff.png");
        wrote = writePng(expectedPath, expected) && wrote;
        wrote = writePng(diffPath, diffImage(image, expected)) && wrote;
        if (differing < 0) {
            message << name << ": size " << image.width << "x" << image.height << " but golden "
                    << goldenPath << " is " << expected.width << "x" << expected.height;
        } else {
            message << name << ": " << differing << " pixels differ from golden " << goldenPath
                    << " (at most " << settings.maxDifferingPixels << " may)";
        }
        message << "; see " << actualPath << ", " << expectedPath << " and " << diffPath;
    }
    if (!wrote)
        message << " (writing some of those images into " << settings.failureDir << " failed)";
    return ::testing::AssertionFailure() << message.str();
}

} // namespace q3test
