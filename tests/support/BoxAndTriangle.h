// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The scene the window and application-context draw-context tests draw
// both into their window and into a pixmap: a box across the origin and a
// triangle in front of it with a colour per vertex, submitted in immediate
// mode.

#include "QD3D.h"
#include "QD3DGeometry.h"
#include "QD3DSet.h"

namespace q3test {

inline void submitBoxAndTriangle(TQ3ViewObject view)
{
    TQ3BoxData box{};
    box.origin = {-0.6f, -0.6f, -0.6f};
    box.orientation = {0.0f, 1.2f, 0.0f};
    box.majorAxis = {0.0f, 0.0f, 1.2f};
    box.minorAxis = {1.2f, 0.0f, 0.0f};
    Q3Box_Submit(&box, view);
    TQ3Vertex3D vertices[3] = {{{-1.5f, -1.0f, 0.8f}, nullptr}, {{1.5f, -1.0f, 0.8f}, nullptr},
                               {{0.0f, 1.4f, 0.8f}, nullptr}};
    const TQ3ColorRGB colours[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 3; ++i) {
        vertices[i].attributeSet = Q3AttributeSet_New();
        Q3AttributeSet_Add(vertices[i].attributeSet, kQ3AttributeTypeDiffuseColor, &colours[i]);
    }
    const TQ3TriangleData triangle{{vertices[0], vertices[1], vertices[2]}, nullptr};
    Q3Triangle_Submit(&triangle, view);
    for (TQ3Vertex3D& vertex : vertices)
        Q3Object_Dispose(vertex.attributeSet);
}

} // namespace q3test
