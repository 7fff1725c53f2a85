// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "exchange/Scene.h"

#include <string>
#include <vector>

namespace q3::exchange {

/// The image as a PNG file's bytes: RGBA when it has alpha, RGB otherwise,
/// 8 bits per channel. Throws kQ3ErrorOutOfMemory, kQ3ErrorInternalError.
std::vector<unsigned char> encodePng(const Image& image);

/// A PNG file's first image as RGBA (palettes, grey and 16-bit channels
/// expanded). Throws kQ3ErrorInvalidData naming `what` when the bytes are
/// not a PNG image.
Image decodePng(const unsigned char* bytes, std::size_t size, const std::string& what);

} // namespace q3::exchange
