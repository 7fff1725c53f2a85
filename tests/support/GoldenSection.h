// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Golden-section search, the minimiser the tests' independent oracles
// (closest point on a curve, distance to a trim curve) refine a sampled
// minimum with: each step keeps the part of [lo, hi] that holds the smaller
// of two probes placed at the golden ratio.

#include <algorithm>
#include <cmath>

namespace q3test {

/// The smaller of the two last probes of `steps` golden-section steps for
/// f on [lo, hi] (f taken to have one minimum there).
template <class Real, class F>
Real goldenSectionMinimum(F&& f, Real lo, Real hi, int steps)
{
    const Real g = Real((std::sqrt(5.0L) - 1) / 2);
    Real c = hi - g * (hi - lo), d = lo + g * (hi - lo);
    Real fc = f(c), fd = f(d);
    for (int step = 0; step < steps; ++step) {
        if (fc < fd) {
            hi = d;
            d = c;
            fd = fc;
            c = hi - g * (hi - lo);
            fc = f(c);
        } else {
            lo = c;
            c = d;
            fc = fd;
            d = lo + g * (hi - lo);
            fd = f(d);
        }
    }
    return std::min(fc, fd);
}

} // namespace q3test
