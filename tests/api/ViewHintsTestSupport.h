// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Checks shared by the view hints tests (ViewHintsApiTest, FileViewHintsTest).

#include "QD3DDrawContext.h"
#include "QD3DIO.h"

#include <gtest/gtest.h>

#include <cstring>

namespace q3test {

/// The image hints `hints` shows through its Get calls: dimensions on and
/// `width` x `height`, mask on and a copy of `mask` (its own bytes, not
/// mask.image), the clear method WithColor and `color`.
inline void expectImageHints(TQ3ViewHintsObject hints, unsigned long width, unsigned long height,
                             const TQ3Bitmap& mask, const TQ3ColorARGB& color)
{
    TQ3Boolean state = kQ3False;
    unsigned long gotWidth = 0, gotHeight = 0;
    EXPECT_EQ(Q3ViewHints_GetDimensionsState(hints, &state), kQ3Success);
    EXPECT_EQ(state, kQ3True);
    EXPECT_EQ(Q3ViewHints_GetDimensions(hints, &gotWidth, &gotHeight), kQ3Success);
    EXPECT_EQ(gotWidth, width);
    EXPECT_EQ(gotHeight, height);
    state = kQ3False;
    EXPECT_EQ(Q3ViewHints_GetMaskState(hints, &state), kQ3Success);
    EXPECT_EQ(state, kQ3True);
    TQ3Bitmap gotMask{};
    ASSERT_EQ(Q3ViewHints_GetMask(hints, &gotMask), kQ3Success);
    ASSERT_NE(gotMask.image, nullptr);
    EXPECT_NE(gotMask.image, mask.image);
    EXPECT_EQ(gotMask.width, mask.width);
    EXPECT_EQ(gotMask.height, mask.height);
    EXPECT_EQ(gotMask.rowBytes, mask.rowBytes);
    EXPECT_EQ(gotMask.bitOrder, mask.bitOrder);
    if (gotMask.height == mask.height && gotMask.rowBytes == mask.rowBytes)
        EXPECT_EQ(std::memcmp(gotMask.image, mask.image, mask.height * mask.rowBytes), 0);
    Q3Bitmap_Empty(&gotMask);
    TQ3DrawContextClearImageMethod method = kQ3ClearMethodNone;
    TQ3ColorARGB gotColor{};
    EXPECT_EQ(Q3ViewHints_GetClearImageMethod(hints, &method), kQ3Success);
    EXPECT_EQ(method, kQ3ClearMethodWithColor);
    EXPECT_EQ(Q3ViewHints_GetClearImageColor(hints, &gotColor), kQ3Success);
    EXPECT_EQ(gotColor.a, color.a);
    EXPECT_EQ(gotColor.r, color.r);
    EXPECT_EQ(gotColor.g, color.g);
    EXPECT_EQ(gotColor.b, color.b);
}

} // namespace q3test
