// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// What the NURBS kernels (Bezier.cpp, SurfaceGrid.cpp) share to compute on
// several doubles at once: GCC/Clang vector types of 2 lanes (SSE2, every
// x86-64) and 4 lanes (AVX2, chosen at run time), the attribute that
// compiles a kernel for AVX2, and the pieces every kernel inlines. The pieces
// are always_inline so that each is compiled inside the function that uses
// it, with that function's instruction set; they take vectors by reference,
// never by value, so no function boundary depends on the vector ABI.

#include <cstring>

#if !defined(__GNUC__)
#error "Q3's NURBS kernels use GCC/Clang vector extensions"
#endif

#define Q3_LANES_INLINE inline __attribute__((always_inline))

#if defined(__x86_64__) || defined(__i386__)
#define Q3_LANES_AVX2 1
#define Q3_LANES_TARGET_AVX2 __attribute__((target("avx2")))
#else
#define Q3_LANES_AVX2 0
#endif

namespace q3::nurbs {

typedef double Double2 __attribute__((vector_size(16)));
typedef double Double4 __attribute__((vector_size(32)));

template <typename V>
constexpr unsigned kLanes = sizeof(V) / sizeof(double);

/// The kLanes<V> doubles from p.
template <typename V>
Q3_LANES_INLINE void loadLanes(V& v, const double* p)
{
    std::memcpy(&v, p, sizeof v);
}

} // namespace q3::nurbs
