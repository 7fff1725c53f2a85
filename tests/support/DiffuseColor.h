// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Reading the diffuse colour back from an attribute set, the check many API
// and file tests end with.

#include "QD3D.h"
#include "QD3DSet.h"

#include <gtest/gtest.h>

namespace q3test {

/// The diffuse colour `set` holds; a failure, and (-1, -1, -1), when
/// Q3AttributeSet_Get cannot read one.
inline TQ3ColorRGB expectDiffuseColor(TQ3AttributeSet set)
{
    TQ3ColorRGB color{-1, -1, -1};
    EXPECT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, &color), kQ3Success);
    return color;
}

} // namespace q3test
