// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The view layer's matrix conventions, in one place.
//
// QuickDraw 3D multiplies row vectors, p' = p * R, and stores R row by row in
// TQ3Matrix4x4::value[row][column]. glm multiplies column vectors,
// p' = M * p, and stores M column by column. A glm::dmat4 whose m[i][j] holds
// R's value[i][j] is therefore exactly M = R^T, the same mapping: the two
// layouts coincide in memory and converting is a plain copy. Every matrix in
// src/view is such a dmat4 (double, so that composing camera, transform and
// window matrices loses nothing before the final rounding to float).
//
// Composition reads in QuickDraw 3D order with then(): then(a, b) applies a
// first and b second (R_a * R_b, which is M_b * M_a in glm).

#include "QD3D.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace q3 {

using Matrix = glm::dmat4;

/// The matrix doing `first`, then `second`.
inline Matrix then(const Matrix& first, const Matrix& second)
{
    return second * first;
}

/// A row-vector QuickDraw 3D matrix as a Matrix (exact: float to double).
inline Matrix fromQ3(const TQ3Matrix4x4& value)
{
    Matrix m(1.0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            m[i][j] = value.value[i][j];
    return m;
}

/// A Matrix as QuickDraw 3D stores it (each entry rounded to float).
inline TQ3Matrix4x4 toQ3(const Matrix& m)
{
    TQ3Matrix4x4 value;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            value.value[i][j] = static_cast<float>(m[i][j]);
    return value;
}

/// The homogeneous image of point p under m (w = 1 in).
inline glm::dvec4 transformPoint(const Matrix& m, const glm::dvec3& p)
{
    return m * glm::dvec4(p, 1.0);
}

} // namespace q3
