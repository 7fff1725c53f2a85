// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Values and comparisons the QD3DMath.h tests share. Expected values in the
// tests are written out by hand or computed here from the textbook formula,
// never by calling Q3.

#include "QD3D.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <initializer_list>
#include <limits>

namespace q3test {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kPi = 3.14159265358979323846;

/// Every byte equal (tells -0 from 0 and compares NaNs).
template <class T>
bool sameBits(const T& a, const T& b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

/// A value filled with one float, to see that a failed call left it alone.
template <class T>
T filledWith(float value)
{
    static_assert(sizeof(T) % sizeof(float) == 0, "a struct of floats");
    T result;
    for (std::size_t i = 0; i < sizeof(T) / sizeof(float); ++i)
        std::memcpy(reinterpret_cast<unsigned char*>(&result) + i * sizeof(float), &value, sizeof(float));
    return result;
}

/// An N x N matrix from its entries row by row.
template <class Matrix, int N>
Matrix matrixOfRows(std::initializer_list<float> rowMajor)
{
    Matrix m{};
    int k = 0;
    for (float v : rowMajor) {
        m.value[k / N][k % N] = v;
        ++k;
    }
    return m;
}

inline TQ3Matrix4x4 matrix4x4Of(std::initializer_list<float> rowMajor)
{
    return matrixOfRows<TQ3Matrix4x4, 4>(rowMajor);
}

inline TQ3Matrix3x3 matrix3x3Of(std::initializer_list<float> rowMajor)
{
    return matrixOfRows<TQ3Matrix3x3, 3>(rowMajor);
}

inline const TQ3Matrix4x4 kIdentity4x4 = matrix4x4Of({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
inline const TQ3Matrix3x3 kIdentity3x3 = matrix3x3Of({1, 0, 0, 0, 1, 0, 0, 0, 1});

/// Row-vector products written out: (x, y, z, w) * M.
inline void rowTimes(const double in[4], const TQ3Matrix4x4& m, double out[4])
{
    for (int j = 0; j < 4; ++j) {
        out[j] = 0.0;
        for (int i = 0; i < 4; ++i)
            out[j] += in[i] * m.value[i][j];
    }
}

inline void rowTimes(const double in[3], const TQ3Matrix3x3& m, double out[3])
{
    for (int j = 0; j < 3; ++j) {
        out[j] = 0.0;
        for (int i = 0; i < 3; ++i)
            out[j] += in[i] * m.value[i][j];
    }
}

template <class M>
void expectMatrixNear(const M& actual, const M& expected, float tolerance, const char* what)
{
    constexpr int n = sizeof(M::value) / sizeof(M::value[0]);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            EXPECT_NEAR(actual.value[i][j], expected.value[i][j], tolerance)
                << what << ": value[" << i << "][" << j << "]";
}

} // namespace q3test
