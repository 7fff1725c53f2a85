// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3D.h"
#include "api/Entry.h"

#include <cstdlib>
#include <limits>

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3Status Q3Bitmap_Empty(TQ3Bitmap* bitmap)
{
    return guardStatus(__func__, [&] {
        requireNonNull(bitmap, "bitmap");
        std::free(bitmap->image);
        bitmap->image = nullptr;
    });
}

unsigned long Q3Bitmap_GetImageSize(unsigned long width, unsigned long height)
{
    return guard(__func__, 0ul, [&]() -> unsigned long {
        const unsigned long rowBytes = width / 8 + (width % 8 != 0 ? 1 : 0);
        if (height != 0 && rowBytes > std::numeric_limits<unsigned long>::max() / height)
            return 0;
        return rowBytes * height;
    });
}

} // extern "C"
