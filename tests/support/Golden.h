// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Golden-image comparison for the tests that render: an RGBA image is
// compared with tests/golden/NAME.png.
//
// Tolerance: at most kGoldenMaxDifferingPixels (4) pixels may differ, where
// a pixel differs when any of its R, G, B, A bytes differs at all. Rendering
// is aliased (no smoothing, no blending, 1-pixel lines) on the pinned
// llvmpipe rasterizer, so the same scene gives the same bytes; the few
// pixels allowed absorb a last-bit difference in a vertex (another compiler
// or CPU path rounding one coordinate differently) that moves the end pixel
// of a line. Anything visible fails: shifting a curve or polygon by one
// pixel changes every pixel along it, hundreds in any figure, and a colour
// change of one step in one channel fails too.
//
// On failure NAME.actual.png, NAME.expected.png and NAME.diff.png (differing
// pixels red over a faded copy of the expected image) are written to the
// failure directory and named in the message (a later match removes them).
// A missing golden fails.
//
// UPDATE_GOLDENS=1 in the environment rewrites a golden whose pixels differ
// in any way (or creates a missing one) and passes; a golden whose pixels are
// identical is left untouched, so its file stays byte-for-byte the same.

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace q3test {

constexpr int kGoldenMaxDifferingPixels = 4;

/// 8-bit RGBA pixels, top row first, rows packed (width * 4 bytes).
struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<unsigned char> pixels;

    RgbaImage() = default;
    RgbaImage(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h) * 4, 0) {}
    unsigned char* at(int x, int y) { return &pixels[offset(x, y)]; }
    const unsigned char* at(int x, int y) const { return &pixels[offset(x, y)]; }
    std::size_t offset(int x, int y) const
    {
        return (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
};

struct GoldenSettings {
    std::string goldenDir;   ///< where NAME.png lives
    std::string failureDir;  ///< where mismatches are written
    bool update = false;     ///< UPDATE_GOLDENS=1
    int maxDifferingPixels = kGoldenMaxDifferingPixels;
};

/// The build's settings: tests/golden, <build>/golden-failures, and
/// UPDATE_GOLDENS from the environment.
GoldenSettings goldenSettings();

/// Pixels that differ in any byte; -1 when the sizes differ.
long countDifferingPixels(const RgbaImage& a, const RgbaImage& b);

/// Reads a PNG; false (and *image untouched) if it cannot be read.
bool readPng(const std::string& path, RgbaImage* image);
/// Writes a PNG (q3png: deterministic bytes); false on failure.
bool writePng(const std::string& path, const RgbaImage& image);

/// Compares image with settings.goldenDir/NAME.png as described above.
::testing::AssertionResult matchesGolden(const std::string& name, const RgbaImage& image,
                                         const GoldenSettings& settings = goldenSettings());

} // namespace q3test
