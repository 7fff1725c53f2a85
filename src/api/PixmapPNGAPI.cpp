// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "Q3PixmapPNG.h"
#include "api/Entry.h"
#include "image/PixmapPng.h"
#include "view/DrawContext.h"

using namespace q3;
using q3::api::guardStatus;

extern "C" {

TQ3Status Q3PixmapDrawContext_WritePNG(TQ3DrawContextObject drawContext, const char* path)
{
    return guardStatus(__func__, [&] {
        const PixmapDrawContext& source = lookup<PixmapDrawContext>(drawContext, "drawContext");
        requireNonNull(path, "path");
        writePixmapPng(source.pixmap(), path);
    });
}

TQ3Status Q3Pixmap_WritePNG(const TQ3Pixmap* pixmap, const char* path)
{
    return guardStatus(__func__, [&] {
        requireNonNull(pixmap, "pixmap");
        requireNonNull(path, "path");
        writePixmapPng(*pixmap, path);
    });
}

TQ3Status Q3Pixmap_ReadPNG(const char* path, TQ3PixelType pixelType, TQ3Endian byteOrder, TQ3Pixmap* pixmap)
{
    return guardStatus(__func__, [&] {
        requireNonNull(path, "path");
        requireNonNull(pixmap, "pixmap");
        *pixmap = readPixmapPng(path, pixelType, byteOrder);
    });
}

TQ3Status Q3Pixmap_EmptyData(TQ3Pixmap* pixmap)
{
    return guardStatus(__func__, [&] {
        requireNonNull(pixmap, "pixmap");
        freePixmapImage(*pixmap);
    });
}

} // extern "C"
