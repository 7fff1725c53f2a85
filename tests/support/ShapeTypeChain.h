// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The type chain every shape object reports (object → shared → shape → its
// shape type → leaf), checked the same way for lights, shaders, styles,
// transforms and geometries.

#include "QD3D.h"

#include <gtest/gtest.h>

#include <string>

namespace q3test {

/// Checks that `object` is a shared shape object of `shapeType` whose leaf
/// type is `leafType`, and whether it is drawable; `what` names the case.
inline void expectShapeTypeChain(TQ3Object object, TQ3ObjectType shapeType, TQ3ObjectType leafType,
                                 TQ3Boolean drawable, const std::string& what = "")
{
    EXPECT_EQ(Q3Object_GetType(object), kQ3ObjectTypeShared) << what;
    EXPECT_EQ(Q3Shared_GetType(object), kQ3SharedTypeShape) << what;
    EXPECT_EQ(Q3Shape_GetType(object), shapeType) << what;
    EXPECT_EQ(Q3Object_GetLeafType(object), leafType) << what;
    EXPECT_EQ(Q3Object_IsType(object, shapeType), kQ3True) << what;
    EXPECT_EQ(Q3Object_IsDrawable(object), drawable) << what;
}

} // namespace q3test
