// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Camera data the API, render and regression tests set up alike.

#include "QD3DCamera.h"

namespace q3test {

/// An orthographic camera looking down -z from (x, y, 10) at (x, y, 0), y
/// up, range 1 to 100, showing halfWidth either side of x and halfHeight
/// above and below y.
inline TQ3OrthographicCameraData orthographicCameraAt(float x, float y, float halfWidth, float halfHeight)
{
    TQ3OrthographicCameraData data{};
    data.cameraData.placement = {{x, y, 10.0f}, {x, y, 0.0f}, {0.0f, 1.0f, 0.0f}};
    data.cameraData.range = {1.0f, 100.0f};
    data.cameraData.viewPort = {{-1.0f, 1.0f}, 2.0f, 2.0f};
    data.left = -halfWidth;
    data.right = halfWidth;
    data.top = halfHeight;
    data.bottom = -halfHeight;
    return data;
}

/// The world coordinate at the centre of pixel i of `size` pixels across an
/// orthographic view showing -half..half, counted from the -half side.
inline double pixelCentre(unsigned long i, unsigned long size, double half)
{
    return -half + (double(i) + 0.5) * (2 * half / double(size));
}

} // namespace q3test
