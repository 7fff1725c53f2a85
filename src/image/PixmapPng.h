// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Pixmaps to and from PNG files (Q3PixmapPNG.h): the pixel conversions of
// base/PixelConvert over the files of image/PngFile.

#include "QD3D.h"

namespace q3 {

/// Writes a pixmap that obeys the TQ3Pixmap rules (checked first, as
/// validatePixmap does) to a PNG file. Throws the errors Q3Pixmap_WritePNG
/// documents.
void writePixmapPng(const TQ3Pixmap& pixmap, const char* path);

/// Reads a PNG file into a new pixmap of the given type and byte order, its
/// image allocated with std::malloc (freePixmapImage releases it). Throws the
/// errors Q3Pixmap_ReadPNG documents after the argument checks.
TQ3Pixmap readPixmapPng(const char* path, const TQ3PixelType& pixelType, const TQ3Endian& byteOrder);

/// Releases an image readPixmapPng allocated and sets it to NULL.
void freePixmapImage(TQ3Pixmap& pixmap);

} // namespace q3
